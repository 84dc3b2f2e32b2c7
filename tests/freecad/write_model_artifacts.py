"""Write the modelled grooves' ops for tests/test_model_artifacts.py (the
shapely oracle exists only on the host).

Executed *by* freecadcmd inside FreeCAD 1.1 or 1.0, from ``-c`` like
write_post_artifacts.py. For every part of model_parts.CASES: a Groove op made
with make_groove from the groove's base face and no dimensions (read from the
model), and one JSON file in FREECAD_GROOVE_ARTIFACTS (relative to
FREECAD_GROOVE_SHARE) with the op's expanded moves from its start point, the
blade, the plunge direction, the part's section as FreeCAD's boolean common
of the solid and a half plane through Z makes it (its outline chorded to
CHORD mm), and the section of the bar before grooving (model_parts'
section with the notch replaced by its contour line), all (z, radius).

Environment: FREECAD_GROOVE_CHECKOUT, FREECAD_GROOVE_SHARE,
FREECAD_GROOVE_ARTIFACTS (default "model-artifacts"), FREECAD_GROOVE_RESULT
(default "model-artifacts.json"): {"freecad_version", "written", "error"}.
The process ends with os._exit (0, or 1 on an error).
"""

CHORD = 1e-4  # mm: deflection of the chorded section outline (a tenth of the oracle's tolerance)
BLADE = dict(tool_width=2.0, tool_corner_radius=0.1)


def _section_polygon(shape):
    """[(z, radius)] of the part's section: the solid's common with the half plane Y = 0, X >= 0."""
    import FreeCAD
    import Part

    v = FreeCAD.Vector
    box = shape.BoundBox
    reach = max(abs(box.XMin), abs(box.XMax), abs(box.YMin), abs(box.YMax)) + 1.0
    pts = [v(0, 0, box.ZMin - 1), v(reach, 0, box.ZMin - 1), v(reach, 0, box.ZMax + 1), v(0, 0, box.ZMax + 1)]
    plane = Part.Face(Part.makePolygon(pts + [pts[0]]))
    faces = shape.common(plane).Faces
    assert len(faces) == 1, len(faces)
    return [(p.z, p.x) for p in faces[0].OuterWire.discretize(Deflection=CHORD)]


def _bar_polygon(call):
    """[(z, radius)] of the section before grooving: the notch replaced by its contour line."""
    from model_parts import section

    elements = section(call)
    notch_end = len(elements) - 4  # section: contour piece, the notch, contour piece, three closing segments
    return [elements[0].start, elements[0].end, elements[notch_end].end] + [e.end for e in elements[notch_end + 1:]]


def _artifact(case, call, op, part):
    import FreeCAD

    from freecad_groove.ops.groove.op import op_error

    plan = op.Proxy.current_plan(op)[0]
    tool = plan.settings.tool
    return {
        "case": case, "freecad": ".".join(FreeCAD.Version()[:3]), "error": op_error(op),
        "modelled": call.emit(), "derived": plan.cycle.emit(),
        "tool": {"width": tool.width, "corner_radius": tool.corner_radius, "reference": tool.reference},
        "plunge": plan.cycle.plunge_direction(), "start": [plan.start.x, plan.start.z],
        "moves": [[m.kind, m.x, m.z, m.p, m.centre and list(m.centre)] for m in plan.moves],  # an arc's centre
        "part": [list(p) for p in _section_polygon(part.Shape)],
        "bar": [list(p) for p in _bar_polygon(call)],
    }


def _write_artifacts(folder):
    import json
    import os

    import FreeCAD
    from model_parts import CASES, part_shape
    from parts import make_shop

    from freecad_groove import make_groove

    os.makedirs(folder, exist_ok=True)
    written = []
    for case, call in sorted(CASES.items()):
        doc = FreeCAD.newDocument("ModelArtifacts")
        try:
            _doc, part, job, _tc = make_shop(doc, shape=part_shape(call))
            face = next(sub for sub in ("Face%d" % (i + 1) for i in range(len(part.Shape.Faces)))
                        if _in_groove(part.Shape, sub))  # any face of it: test_model_grooves picks each
            chamfers = {"chamfer_measure": "Leg length (CHR)"} if call.typ > 10 else {}
            op = make_groove(job, (part, face), infeed=1, **BLADE, **chamfers)
            name = "%s.json" % case
            with open(os.path.join(folder, name), "w") as f:
                json.dump(_artifact(case, call, op, part), f)
            written.append(name)
        finally:
            FreeCAD.closeDocument(doc.Name)
    return written


def _in_groove(shape, sub):
    from freecad_groove.ops.groove.model import read_model_groove

    try:
        read_model_groove(shape, sub, "Part")
    except ValueError:
        return False
    return True


def main():
    import json
    import os
    import sys
    import traceback

    import FreeCAD

    checkout = os.environ.get("FREECAD_GROOVE_CHECKOUT", "/mnt/freecad-groove")
    share = os.environ.get("FREECAD_GROOVE_SHARE", os.getcwd())
    for path in (checkout, os.path.join(checkout, "tests", "freecad")):
        if path not in sys.path:
            sys.path.insert(0, path)
    result = {"freecad_version": ".".join(FreeCAD.Version()[:3]), "written": [], "error": None}
    try:
        result["written"] = _write_artifacts(os.path.join(share, os.environ.get("FREECAD_GROOVE_ARTIFACTS",
                                                                                "model-artifacts")))
    except Exception:
        result["error"] = traceback.format_exc()
    target = os.path.join(share, os.environ.get("FREECAD_GROOVE_RESULT", "model-artifacts.json"))
    with open(target + ".tmp", "w") as f:
        json.dump(result, f)
    os.replace(target + ".tmp", target)
    os._exit(1 if result["error"] else 0)


main()
