"""Scripting entry point: make_cylinder_slot() (freecad_groove.make_cylinder_slot)."""

import FreeCAD

from ...freecad.scripting import model_of, nothing_left_behind, set_keyword_values
from .op import Create

KEYWORDS = {"depth": "Depth", "passes": "Passes", "allowance": "Allowance", "retract": "Retract",
            "coolant_mode": "CoolantMode", "comment": "Comment"}


def _pair(pair: object, prefix: str, what: str) -> tuple:
    if not isinstance(pair, (tuple, list)) or len(pair) != 2 or not isinstance(pair[1], str) \
            or not pair[1].startswith(prefix):
        raise ValueError("make_cylinder_slot(): %s: %r is not a (part, \"%sN\") pair" % (what, pair, prefix))
    return pair


def _elements(job: object, face: object, path: object) -> list:
    """[(model clone, "FaceN"), (model clone, "EdgeN"), ...], each checked."""
    pairs = [_pair(face, "Face", "face")]
    if is_sketch(path):  # the path is the op's DevelopedSketch
        return [_checked(job, *pairs[0])]
    if isinstance(path, tuple) and len(path) == 2 and isinstance(path[1], str):
        path = [path]  # one (part, "EdgeN") pair
    if not isinstance(path, (list, tuple)) or not path:
        raise ValueError("make_cylinder_slot(): path=%r: give a list of (part, \"EdgeN\")" % (path,))
    pairs += [_pair(p, "Edge", "path") for p in path]
    return [_checked(job, part, sub) for part, sub in pairs]


def is_sketch(path: object) -> bool:
    """Whether ``path`` is one object with a shape (a sketch of the developed surface), not (part, "EdgeN") pairs."""
    return hasattr(path, "Shape") and hasattr(path, "Placement") and hasattr(path, "Document")


def _checked(job: object, part: object, sub: str) -> tuple:
    """(the Job's model clone of ``part``, ``sub``); ValueError when it has no such element."""
    model = model_of("make_cylinder_slot", job, part)
    try:
        model.Shape.getElement(sub)
    except Exception:
        raise ValueError("make_cylinder_slot(): %s has no %s" % (part.Label, sub)) from None
    return model, sub


def make_cylinder_slot(job, face, path, name="CylinderSlot", tool_controller=None, recompute=True, **values):
    """Create a Cylinder slot operation in ``job`` and return it.

    ``face``: (part, "FaceN"), a cylindrical face about Z; ``path``: the slot's
    centre line on it, [(part, "EdgeN"), ...] in order (one pair alone is
    fine), or a sketch of the developed surface (its x = Z, its y = the
    developed length radius*C; the op's DevelopedSketch). Keywords (mm): depth, passes, allowance, retract (radial: see
    op.py), coolant_mode, comment. ``tool_controller`` defaults to
    the Job's first (an end mill: its diameter is the slot's width).
    ``recompute``: then a slot that cannot be cut reports its message
    (op.op_error) instead of raising.

    Raises TypeError (unknown keyword) or ValueError (a bad element or value, a NaN or infinite number)
    with nothing left behind in the Job.

    Example::

        op = make_cylinder_slot(job, (shaft, "Face1"), [(helix, "Edge1")], depth=2, passes=3,
                                allowance=0.2, retract=1)
        op.Path.Commands       # G18, G0 X Z C, the G7.1 passes as G1 X Z C
    """
    unknown = sorted(k for k in values if k not in KEYWORDS)
    if unknown:
        raise TypeError("make_cylinder_slot() got unknown keyword(s) %s; valid: %s"
                        % (", ".join(unknown), ", ".join(sorted(KEYWORDS))))
    elements = _elements(job, face, path)
    doc = job.Document
    if FreeCAD.ActiveDocument is None or FreeCAD.ActiveDocument.Name != doc.Name:
        FreeCAD.setActiveDocument(doc.Name)
    with nothing_left_behind(doc):
        tc = tool_controller or (job.Tools.Group[0] if job.Tools and job.Tools.Group else None)
        obj = Create(name, parentJob=job, tool_controller=tc)
        if tc is not None:
            obj.ToolController = tc
        for model, sub in elements:
            obj.Proxy.addBase(obj, model, sub)
        if is_sketch(path):
            obj.DevelopedSketch = path
        set_keyword_values("make_cylinder_slot", obj, KEYWORDS, values)
    if recompute:
        doc.recompute()
    return obj
