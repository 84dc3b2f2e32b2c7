"""Scripting entry point: make_groove()."""

import contextlib
import re
from typing import Iterator

import FreeCAD

from . import groove_op

SETTABLE = tuple(n for n in groove_op.PROPERTY_NAMES if n not in groove_op.DERIVED) + ("CoolantMode", "Comment")


def snake_case(name):
    """Property name -> keyword: "EdgeCorner1Type" -> "edge_corner1_type"."""
    return re.sub(r"(?<!^)(?=[A-Z])", "_", name).lower()


KEYWORDS = {snake_case(n): n for n in SETTABLE}
# The keywords that give the groove's size: without any, the groove is read from the model.
DIMENSIONS = tuple(snake_case(n) for n in groove_op.MODEL_VALUES)


def _pairs(faces: object) -> list:
    """The (part, subs) pairs of make_groove's ``faces`` argument."""
    if isinstance(faces, tuple) and len(faces) == 2 and not isinstance(faces[0], (tuple, list)):
        return [faces]
    if not isinstance(faces, (list, tuple)) or not faces:
        raise ValueError("make_groove(): faces=%r: give (part, \"Face3\"), (part, [\"Face3\", ...]) "
                         "or a list of those" % (faces,))
    return list(faces)


def _model(job: object, part: object) -> object:
    """The Job's model clone of ``part`` (``part`` itself when it is one);
    ValueError when ``part`` is no object of the Job's model."""
    if not (hasattr(part, "Shape") and hasattr(part, "Document") and hasattr(part, "Name")):
        raise ValueError("make_groove(): faces: %r is not a FreeCAD object with a shape" % (part,))
    model = job.Proxy.resourceClone(job, part)
    if model is None and part in job.Model.Group:
        model = part
    if model is None:
        raise ValueError("make_groove(): %s is not in the model of the Job %s" % (part.Label, job.Label))
    return model


def _faces(job: object, faces: object) -> list:
    """[(model clone, [sub, ...])] from (obj, "Face3"), (obj, ["Face3", ...]) or a
    list of those, every face checked: ValueError before anything is made."""
    out = []
    for pair in _pairs(faces):
        if not isinstance(pair, (tuple, list)) or len(pair) != 2:
            raise ValueError("make_groove(): faces: %r is not a (part, \"FaceN\") pair" % (pair,))
        part, subs = pair
        model = _model(job, part)
        subs = [subs] if isinstance(subs, str) else list(subs or [])
        if not subs:
            raise ValueError("make_groove(): faces: no face named for %s" % part.Label)
        for sub in subs:
            if not isinstance(sub, str) or not sub.startswith("Face"):
                raise ValueError("make_groove(): faces: %s.%s is not a face name (\"FaceN\")" % (part.Label, sub))
            try:
                model.Shape.getElement(sub)
            except Exception:
                raise ValueError("make_groove(): %s has no %s" % (part.Label, sub)) from None
        out.append((model, subs))
    return out


@contextlib.contextmanager
def nothing_left_behind(doc: object) -> Iterator[None]:
    """The objects made in ``doc`` inside the block are removed again (newest
    first) when it raises: a make_* call makes a complete op or nothing."""
    before = {o.Name for o in doc.Objects}
    try:
        yield
    except BaseException:
        new = [o.Name for o in doc.Objects if o.Name not in before]
        for name in reversed(new):  # removing a tool controller removes its tool bit too
            if doc.getObject(name) is not None:
                doc.removeObject(name)
        raise


def set_keyword_values(call: str, obj: object, keywords: dict, values: dict) -> None:
    """The op's properties from the keywords of the make_* ``call`` ({keyword: property} ``keywords``);
    ValueError naming the keyword whose value FreeCAD refuses."""
    for key, value in values.items():
        try:
            setattr(obj, keywords[key], value)
        except Exception as e:
            raise ValueError("%s(): %s=%r: not a value for %s (%s: %s)"
                             % (call, key, value, keywords[key], type(e).__name__, e)) from None


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
        obj = groove_op.Create(name, parentJob=job, tool_controller=tc)
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
    be cut then reports the engine's message, see groove_op.op_error,
    instead of raising).

    Raises TypeError (an unknown keyword) or ValueError (no faces, an object
    that is not in the Job's model, a name that is not one of its faces, a
    value the property refuses) with nothing left behind in the Job.

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
    faces = _faces(job, faces)
    values = _with_model_groove(values)
    doc = job.Document
    if FreeCAD.ActiveDocument is None or FreeCAD.ActiveDocument.Name != doc.Name:
        FreeCAD.setActiveDocument(doc.Name)
    obj = _create(job, faces, name, tool_controller, values)
    if recompute:
        doc.recompute()
    return obj
