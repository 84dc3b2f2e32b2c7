"""Scripting entry point: make_groove() (freecad_groove.make_groove)."""

import FreeCAD

from ...freecad.scripting import nothing_left_behind, picked_faces, set_keyword_values, snake_case
from .model import MODEL_VALUES
from .op import Create
from .properties import DERIVED, PROPERTY_NAMES

SETTABLE = tuple(n for n in PROPERTY_NAMES if n not in DERIVED) + ("CoolantMode", "Comment")
KEYWORDS = {snake_case(n): n for n in SETTABLE}
# The keywords that give the groove's size: without any, the groove is read from the model.
DIMENSIONS = tuple(snake_case(n) for n in MODEL_VALUES)


def _set_values(obj: object, values: dict) -> None:
    set_keyword_values("make_groove", obj, KEYWORDS, values)


def _tool_controller(job):
    group = job.Tools.Group if job.Tools else []
    if group:
        return group[0]
    import Path.Tool.Controller as PathToolController

    tc = PathToolController.Create("TC: Grooving tool", toolNumber=job.Proxy.nextToolNumber(), assignViewProvider=False)
    job.Proxy.addToolController(tc)
    return tc


def _create(job: object, faces: list, name: str, tool_controller: object, values: dict) -> object:
    """The op in ``job`` on the checked ``faces`` with ``values``; on any
    failure every object made here is removed before the error goes on."""
    with nothing_left_behind(job.Document):
        tc = tool_controller or _tool_controller(job)
        obj = Create(name, parentJob=job, tool_controller=tc)
        obj.ToolController = tc
        for model, subs in faces:
            for sub in subs:
                obj.Proxy.addBase(obj, model, sub)
        if "model_groove" in values:  # first: dimensions set after it override the model's
            _set_values(obj, {"model_groove": values["model_groove"]})
        _set_values(obj, values)
    return obj


def _with_model_groove(values: dict) -> dict:
    """``values`` with model_groove=True when they give no dimension of the groove."""
    if any(k in values for k in DIMENSIONS) or "model_groove" in values:
        return values
    return dict(values, model_groove=True)


def make_groove(job, faces, name="Groove", tool_controller=None, recompute=True, **values):
    """Create a Groove operation in ``job`` and return it.

    ``faces``: (part, "Face3"), (part, ["Face3", "Face8"]) or a list of such
    pairs; ``part`` may be the object you modelled or the Job's clone of it
    (each face is taken from the Job's model clone, as the GUI does).
    ``tool_controller``: defaults to the job's first tool controller; a job
    without one gets a new "TC: Grooving tool" (FreeCAD's default bit: the
    blade's size then comes from tool_width/tool_corner_radius).
    ``recompute``: recompute the document at the end (a groove that cannot
    be cut then reports the engine's message, see op.op_error,
    instead of raising).

    Raises TypeError (an unknown keyword) or ValueError (no faces, an object
    that is not in the Job's model, a name that is not one of its faces, a
    value the property refuses, a NaN or infinite number) with nothing left behind in the Job.

    No dimension (position, width, depth, flank angles, corners): the groove
    is read from the model (model_groove=True); with it, dimensions override.
    Every other keyword is an op property in snake_case, in mm, degrees and
    seconds (or a FreeCAD quantity string such as "4 mm"):
    position, width, depth, flank_angle1, flank_angle2, edge_corner1,
    edge_corner1_type ("None"/"Radius"/"Chamfer"), edge_corner2,
    edge_corner2_type, base_corner1, base_corner1_type, base_corner2,
    base_corner2_type, model_groove, model_overrides, chamfer_measure ("Chamfer length (CHF)"/"Leg length
    (CHR)"), base_allowance, flank_allowance, infeed, dwell, retract,
    groove_count, pitch, tool_width, tool_corner_radius, reference_corner
    ("minus"/"plus"), coolant_mode, comment.

    Example::

        import FreeCAD, Part
        import Path.Main.Job as PathJob
        from freecad_groove import make_groove

        doc = FreeCAD.newDocument()
        shaft = doc.addObject("Part::Feature", "Shaft")
        shaft.Shape = Part.makeCylinder(20, 50)          # turned about Z
        doc.recompute()
        job = PathJob.Create("Job", [shaft])
        op = make_groove(job, (shaft, "Face1"), position=10, width=4, depth=2,
                         infeed=1, tool_width=3, tool_corner_radius=0.2)
        op.TYP, op.AXFA, op.AXSA      # 5, 20 mm, 40 mm
        op.Path.Commands              # G18, then the expanded moves
    """
    unknown = sorted(k for k in values if k not in KEYWORDS)
    if unknown:
        raise TypeError(
            "make_groove() got unknown keyword(s) %s; valid: %s" % (", ".join(unknown), ", ".join(sorted(KEYWORDS)))
        )
    faces = picked_faces("make_groove", job, faces)
    values = _with_model_groove(values)
    doc = job.Document
    if FreeCAD.ActiveDocument is None or FreeCAD.ActiveDocument.Name != doc.Name:
        FreeCAD.setActiveDocument(doc.Name)
    obj = _create(job, faces, name, tool_controller, values)
    if recompute:
        doc.recompute()
    return obj
