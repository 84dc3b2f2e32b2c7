"""Scripting entry point: make_plunge_grind() (freecad_groove.make_plunge_grind)."""

import FreeCAD

from ...freecad.scripting import nothing_left_behind, picked_faces, set_keyword_values, snake_case
from .op import Create
from .properties import DERIVED, PROPERTY_NAMES

SETTABLE = tuple(n for n in PROPERTY_NAMES if n not in DERIVED) + ("CoolantMode", "Comment")
KEYWORDS = {snake_case(n): n for n in SETTABLE}
KEYWORDS["depth"] = "Allowance"  # the name for it: the stock the plunge grinds off


def _tool_controller(job: object) -> object:
    group = job.Tools.Group if job.Tools else []
    if group:
        return group[0]
    import Path.Tool.Controller as PathToolController

    tc = PathToolController.Create("TC: Grinding wheel", toolNumber=job.Proxy.nextToolNumber(),
                                   assignViewProvider=False)
    job.Proxy.addToolController(tc)
    return tc


def make_plunge_grind(job, face, name="PlungeGrind", tool_controller=None, recompute=True, **values):
    """Create a Plunge grind operation in ``job`` on ``face`` and return it.

    ``face``: (part, "FaceN"), one flat face looking up (+Z), a rectangle
    with edges along X (its length: the reciprocation) and Y (its width: the
    crossover). ``tool_controller``: default the job's first (a job without
    one gets "TC: Grinding wheel"). ``recompute``: recompute at the end (a
    grind that cannot be made then reports its error, see
    op.op_error, instead of raising).

    Keywords (op properties in snake_case; lengths in mm or quantity strings,
    feeds as quantity strings such as "300 mm/min" or numbers in mm/s):
    depth (= allowance: the stock left on the face), start_clearance,
    plunge_pick (J), crossover_plunge_pick (Q), cross_pick (K),
    secondary_cross_pick (R), overtravel, spark_out_passes (L), plunge_feed
    (F), reciprocation_feed (E), dress_program (P), dress_count (D),
    dress_first (G83.1), wheel_width, retract, coolant_mode, comment.

    Raises TypeError (an unknown keyword) or ValueError (a face that is not
    in the Job's model, a value a property refuses, a NaN or infinite number) with nothing left behind.

    Example::

        op = make_plunge_grind(job, (block, "Face6"), depth=0.1, plunge_pick=0.02,
                               cross_pick=5, wheel_width=10)
        op.GrindCall   # "G83 X... I... Y... J0.02 Z... K5 ..."
    """
    unknown = sorted(k for k in values if k not in KEYWORDS)
    if unknown:
        raise TypeError("make_plunge_grind() got unknown keyword(s) %s; valid: %s"
                        % (", ".join(unknown), ", ".join(sorted(KEYWORDS))))
    faces = picked_faces("make_plunge_grind", job, face)
    if sum(len(subs) for _model, subs in faces) != 1:
        raise ValueError("make_plunge_grind(): face=%r: give one (part, \"FaceN\")" % (face,))
    doc = job.Document
    if FreeCAD.ActiveDocument is None or FreeCAD.ActiveDocument.Name != doc.Name:
        FreeCAD.setActiveDocument(doc.Name)
    with nothing_left_behind(doc):
        tc = tool_controller or _tool_controller(job)
        obj = Create(name, parentJob=job, tool_controller=tc)
        obj.ToolController = tc
        for model, subs in faces:
            for sub in subs:
                obj.Proxy.addBase(obj, model, sub)
        set_keyword_values("make_plunge_grind", obj, KEYWORDS, values)
    if recompute:
        doc.recompute()
    return obj
