"""Scripting entry point: make_groove()."""

import re

import FreeCAD

from . import groove_op

SETTABLE = tuple(n for n in groove_op.PROPERTY_NAMES if n not in groove_op.DERIVED) + ("CoolantMode", "Comment")


def snake_case(name):
    """Property name -> keyword: "EdgeCorner1Type" -> "edge_corner1_type"."""
    return re.sub(r"(?<!^)(?=[A-Z])", "_", name).lower()


KEYWORDS = {snake_case(n): n for n in SETTABLE}


def _faces(job, faces):
    """[(obj, [sub, ...])] from (obj, "Face3"), (obj, ["Face3", ...]) or a list of those."""
    if isinstance(faces, tuple) and len(faces) == 2 and not isinstance(faces[0], tuple):
        faces = [faces]
    out = []
    for obj, subs in faces:
        if isinstance(subs, str):
            subs = [subs]
        out.append((obj, list(subs)))
    return out


def _tool_controller(job):
    group = job.Tools.Group if job.Tools else []
    if group:
        return group[0]
    import Path.Tool.Controller as PathToolController

    tc = PathToolController.Create("TC: Grooving tool", toolNumber=job.Proxy.nextToolNumber(), assignViewProvider=False)
    job.Proxy.addToolController(tc)
    return tc


def make_groove(job, faces, name="Groove", tool_controller=None, recompute=True, **values):
    """Create a Groove operation in ``job`` and return it.

    ``faces``: (part, "Face3"), (part, ["Face3", "Face8"]) or a list of such
    pairs; ``part`` may be the object you modelled or the Job's clone of it
    (each face is taken from the Job's model clone, as the GUI does).
    ``tool_controller``: defaults to the job's first tool controller; a job
    without one gets a new "TC: Grooving tool" (FreeCAD's default bit: the
    blade's size then comes from tool_width/tool_corner_radius).
    ``recompute``: recompute the document at the end (an invalid groove then
    marks the op invalid with the engine's message instead of raising).

    Every other keyword is an op property in snake_case, in mm, degrees and
    seconds (or a FreeCAD quantity string such as "4 mm"):
    position, width, depth, flank_angle1, flank_angle2, edge_corner1,
    edge_corner1_type ("None"/"Radius"/"Chamfer"), edge_corner2,
    edge_corner2_type, base_corner1, base_corner1_type, base_corner2,
    base_corner2_type, chamfer_measure ("Chamfer length (CHF)"/"Leg length
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
    doc = job.Document
    if FreeCAD.ActiveDocument is None or FreeCAD.ActiveDocument.Name != doc.Name:
        FreeCAD.setActiveDocument(doc.Name)
    tc = tool_controller or _tool_controller(job)
    obj = groove_op.Create(name, parentJob=job, tool_controller=tc)
    obj.ToolController = tc
    for part, subs in _faces(job, faces):
        model = job.Proxy.resourceClone(job, part) or part
        for sub in subs:
            obj.Proxy.addBase(obj, model, sub)
    for key, value in values.items():
        setattr(obj, KEYWORDS[key], value)
    if recompute:
        doc.recompute()
    return obj
