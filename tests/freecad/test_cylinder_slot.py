"""The Cylinder slot op inside FreeCAD (1.1 and 1.0; run by tests/freecad/run_suite.py).

An R20 cylinder (Z 0..50) turned about Z, with the slot's centre line a
separate model object: a helix of one turn (pitch 20) from Z10, or a keyway
line along Z at C90. The expected Paths are derived here by hand from the
G7.1 Type II rules (gsk_g7_1's module notes): the rough passes at radius
20 - (Depth - Allowance) * n / max(L, 2), the finish at 20 - Depth, the
cycle start at 20 + Retract; each pass: G1 X in, G1 along the developed
path, G0 X out, G0 Z C back.
"""

import math

import FreeCAD
import Part
import Path.Main.Job as PathJob
import pytest

from freecad_groove import make_cylinder_slot
from freecad_groove.ops.slot.op import op_error

V = FreeCAD.Vector
FEED = 120.0  # mm/min, the tool controller's HorizFeed
LIVE_RPM = 1000  # the tool controller's SpindleSpeed: the live tool's


def _shop(edge_shape, cylinder=None):
    doc = FreeCAD.newDocument("slot")
    shaft = doc.addObject("Part::Feature", "Shaft")
    shaft.Shape = cylinder if cylinder is not None else Part.makeCylinder(20, 50)
    line = doc.addObject("Part::Feature", "SlotLine")
    line.Shape = edge_shape
    doc.recompute()
    job = PathJob.Create("Job", [shaft, line])
    tc = job.Tools.Group[0]
    tc.HorizFeed = "%g mm/min" % FEED
    tc.SpindleSpeed = LIVE_RPM
    doc.recompute()
    return doc, shaft, line, job


def _helix():
    helix = Part.makeHelix(20.0, 20.0, 20.0)  # pitch, height, radius: one turn from (20, 0, 0)
    helix.translate(V(0, 0, 10))
    return helix


def _safe_radius(job, retract):
    radius = 20.0
    for shape in [m.Shape for m in job.Model.Group] + [job.Stock.Shape]:
        box = shape.BoundBox
        radius = max(radius, math.hypot(max(abs(box.XMin), abs(box.XMax)), max(abs(box.YMin), abs(box.YMax))))
    return radius + retract


def _words(op):
    """(name, {axis: value}) of the op's Path after its label comment."""
    return [(c.Name, dict(c.Parameters)) for c in op.Path.Commands[1:]]


def _expected(safe, start, end, radii, clear, feed_along):
    z0, c0 = start
    z1, c1 = end
    out = [("G18", {}), ("G0", {"X": safe}), ("G0", {"Z": z0, "C": c0})]
    if safe != clear:
        out.append(("G0", {"X": clear}))
    for radius in radii:
        out += [("G1", {"X": radius, "Z": z0, "C": c0, "F": FEED / 60}),
                ("G1", {"X": radius, "Z": z1, "C": c1, "F": feed_along / 60}),
                ("G0", {"X": clear, "Z": z1, "C": c1}),
                ("G0", {"X": clear, "Z": z0, "C": c0})]
    return out + [("G0", {"X": safe})]


def _same(got, want):
    assert [name for name, _ in got[1:]] == [name for name, _ in want], got
    for (name, words), (_n, expected) in zip(got[1:], want):
        assert set(words) == set(expected), (name, words, expected)
        for axis, value in expected.items():
            assert words[axis] == pytest.approx(value, abs=1e-6), (name, axis, words, expected)


def test_helical_groove_moves_by_hand(closing):
    doc, shaft, line, job = _shop(_helix())
    closing.append(doc)
    op = make_cylinder_slot(job, (shaft, "Face1"), [(line, "Edge1")], depth=2, passes=2, allowance=0.2, retract=1)
    assert op_error(op) is None
    assert op.Region == "G7.1 C20. J-4. R2. K0.4 L2"
    # developed: Z 10 -> 30 while C turns 0 -> 360, i.e. s = 20 * 2pi along the surface
    along = FEED * 20.0 / math.hypot(20.0, 40.0 * math.pi)  # F is along Z when Z moves (LinuxCNC's rule)
    want = _expected(_safe_radius(job, 1.0), (10.0, 0.0), (30.0, 360.0), [19.1, 18.2, 18.0], 21.0, along)
    assert op.Path.Commands[1].Name.startswith("(Face1") or "Face1" in op.Path.Commands[1].Name
    _same(_words(op), want)


def test_keyway_along_z_moves_by_hand(closing):
    doc, shaft, line, job = _shop(Part.makeLine(V(0, 20, 5), V(0, 20, 45)))
    closing.append(doc)
    op = make_cylinder_slot(job, (shaft, "Face1"), (line, "Edge1"), depth=1.5, passes=1, allowance=0.1, retract=2)
    assert op_error(op) is None
    assert op.Region == "G7.1 C20. J-3. R4. K0.2 L1"
    # L1 runs as 2 rough passes of (1.5 - 0.1) / 2 each, then the finish at 18.5
    want = _expected(_safe_radius(job, 2.0), (5.0, 90.0), (45.0, 90.0), [19.3, 18.6, 18.5], 22.0, FEED)
    _same(_words(op), want)


@pytest.mark.parametrize("case, prefix", [
    ("plane", "Base: Shaft.Face2 is not a cylindrical face"),
    ("off_face", "Base: SlotLine.Edge1 does not lie on Shaft.Face1"),
    ("depth", "Depth=0.0: must be greater than 0"),
    ("not_z", "Base: Shaft.Face1 is a cylinder about (1, 0, 0)"),
])
def test_bad_inputs_give_one_line_naming_the_property(closing, case, prefix):
    edge = Part.makeLine(V(25, 0, 5), V(25, 0, 45)) if case == "off_face" else Part.makeLine(V(20, 0, 5),
                                                                                            V(20, 0, 45))
    cylinder = Part.makeCylinder(20, 50, V(0, 0, 0), V(1, 0, 0)) if case == "not_z" else None
    doc, shaft, line, job = _shop(edge, cylinder)
    closing.append(doc)
    face = "Face2" if case == "plane" else "Face1"
    op = make_cylinder_slot(job, (shaft, face), [(line, "Edge1")], depth=0 if case == "depth" else 1)
    message = op_error(op)
    assert message is not None and message.startswith(prefix), message
    assert "\n" not in message
    shown = message.replace("(", "[").replace(")", "]")  # a Path comment has no inner parentheses
    assert len(op.Path.Commands) == 2 and shown in op.Path.Commands[1].Name  # label, then the error


# ----------------------------------------------------------------------------- posts

def _post(name, objects, args):
    import importlib.util
    import os

    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    spec = importlib.util.spec_from_file_location(name + "_post", os.path.join(root, "postprocessors",
                                                                               name + "_post.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.export(objects, "-", args)


def _positions(words_list, scale_x):
    """[(kind, x radius, z, c, f)] of full positions from [(code, {axis: value})] (modal G0/G1; f None on G0)."""
    here, kind, out = {}, None, []
    for code, words in words_list:
        if code in ("G0", "G00", "G1", "G01"):
            kind = "G0" if code in ("G0", "G00") else "G1"
        if not any(a in words for a in "XZC") or kind is None:
            continue
        here.update({a: words[a] * (scale_x if a == "X" else 1.0) for a in "XZC" if a in words})
        out.append((kind, here.get("X"), here.get("Z"), here.get("C")))
    return out


def _read_text(text):
    """[(code, {axis: value})] of a LinuxCNC-style text (comments dropped)."""
    import re

    out = []
    for line in text.splitlines():
        line = re.sub(r"\([^)]*\)", "", line).strip()
        code = next(iter(re.findall(r"\bG0*[01]\b", line)), None)
        words = {a: float(v) for a, v in re.findall(r"([XZCF])([-+]?[\d.]+)", line)}
        out.append(({"G00": "G0", "G01": "G1"}.get(code, code), words))
    return out


def _op_positions(op):
    return _positions([(c.Name, dict(c.Parameters)) for c in op.Path.Commands], 1.0)


def _helix_op(closing):
    doc, shaft, line, job = _shop(_helix())
    closing.append(doc)
    op = make_cylinder_slot(job, (shaft, "Face1"), [(line, "Edge1")], depth=2, passes=2, allowance=0.2, retract=1)
    assert op_error(op) is None
    return job, op


@pytest.mark.parametrize("args", ["--native-cycles", "--expand-cycles"])
def test_gsk_post_read_back_equals_the_op(closing, args):
    from freecad_groove.engine.translator import translate_program

    job, op = _helix_op(closing)
    text = _post("gsk_lathe", [job], args + " --switches-by-hand")
    region = [line for line in text.splitlines() if line.startswith("G7.1") or line.startswith("G1 Z")]
    if args == "--native-cycles":
        assert region == ["G7.1 C20. J-4. R2. K0.4 L2", "G1 Z30. C360. F120.", "G7.1 C0"], text
    else:  # each of the 3 passes: its path as a Type I region at the pass's X
        assert region == ["G7.1 C20.", "G1 Z30. C360. F120.", "G7.1 C0"] * 3, text
    translated = translate_program(text, "gsk", target="linuxcnc-c")
    got = _positions(_read_text(translated), 0.5)
    want = _op_positions(op)
    assert len(got) >= len(want)
    tail = got[len(got) - len(want):]
    for a, b in zip(tail, want):
        assert a[0] == b[0] and a[1:] == pytest.approx(b[1:], abs=1e-3), (a, b, translated)


def test_linuxcnc_post_writes_the_c_moves(closing):
    job, op = _helix_op(closing)
    text = _post("linuxcnc_lathe", [job], "--switches-by-hand")
    got = _positions(_read_text(text), 0.5)
    want = _op_positions(op)
    assert got[len(got) - len(want):] == [(k, pytest.approx(x, abs=1e-4), pytest.approx(z, abs=1e-4),
                                           pytest.approx(c, abs=1e-4)) for k, x, z, c in want]
    assert "C360." in text


def test_a_post_without_c_refuses_the_slot(closing):
    from freecad_groove.freecad.posts import PostError

    job, op = _helix_op(closing)
    with pytest.raises(PostError, match="the C axis, which the fanuc_lathe post does not write"):
        _post("fanuc_lathe", [job], "")


def test_gsk_post_writes_grooves_as_fanuc_style_g75(closing):
    """A plain Groove op on the gsk post: the two-block G75 of the fanuc post, read back by the gsk reader."""
    from freecad_groove import make_groove
    from freecad_groove.engine.translator import translate_program

    doc, shaft, line, job = _shop(Part.makeLine(V(20, 0, 5), V(20, 0, 45)))
    closing.append(doc)
    make_groove(job, (shaft, "Face1"), position=10, width=3, depth=2, infeed=1, tool_width=3,
                tool_corner_radius=0)
    body = {name: [line for line in _post(name, [job], "--native-cycles --no-header").splitlines()
                   if not line.startswith("(")] for name in ("gsk_lathe", "fanuc_lathe")}
    assert body["gsk_lathe"] == body["fanuc_lathe"]
    calls = [line for line in body["gsk_lathe"] if line.startswith("G75")]
    assert len(calls) == 2, body["gsk_lathe"]
    text = "\n".join(body["gsk_lathe"]) + "\n"
    def moves(dialect):
        return [line for line in translate_program(text, dialect).splitlines() if not line.startswith("(")]

    assert moves("gsk") == moves("fanuc")


def test_a_chain_of_edges_is_one_path_whatever_their_direction(closing):
    """The keyway as two edges, the second modelled backwards (45 -> 25): the same Path as the one edge."""
    halves = Part.makeCompound([Part.makeLine(V(0, 20, 5), V(0, 20, 25)), Part.makeLine(V(0, 20, 45), V(0, 20, 25))])
    doc, shaft, line, job = _shop(halves)
    closing.append(doc)
    op = make_cylinder_slot(job, (shaft, "Face1"), [(line, "Edge1"), (line, "Edge2")], depth=1.5, passes=1,
                            allowance=0.1, retract=2)
    assert op_error(op) is None
    want = _expected(_safe_radius(job, 2.0), (5.0, 90.0), (45.0, 90.0), [19.3, 18.6, 18.5], 22.0, FEED)
    _same(_words(op), want)
    reversed_first = make_cylinder_slot(job, (shaft, "Face1"), [(line, "Edge2"), (line, "Edge1")], depth=1.5)
    assert reversed_first.Region.startswith("G7.1 C20.")
    assert [c.Parameters.get("Z") for c in reversed_first.Path.Commands if c.Name == "G0"][1] == 45.0  # from 45


def test_a_new_jobs_tool_controller_mills_the_slot_at_the_documented_defaults(closing):
    # a new Job's default tool controller: feed 0, speed 0 (ops/slot/cutting.py: 50 mm/min, live tool 1000 rpm)
    doc, shaft, line, job = _shop(_helix())
    closing.append(doc)
    tc = job.Tools.Group[0]
    tc.HorizFeed, tc.SpindleSpeed = 0, 0
    op = make_cylinder_slot(job, (shaft, "Face1"), [(line, "Edge1")], depth=1)
    assert op_error(op) is None, op_error(op)
    assert op.FeedsAndSpeeds == ("feed 50 mm/min (default: the tool controller's HorizFeed is 0); live tool 1000 rpm "
                                 "CW (default: the tool controller's SpindleSpeed is 0)")
    switches = "--c-axis-on M14 --c-axis-off M15 --live-tool-cw M13 --live-tool-stop M25"
    text = _post("gsk_lathe", [job], "--native-cycles " + switches)
    assert "M13 S1000" in text.splitlines() and "G1 Z30. C360. F50." in text, text
    defaulted = _words(op)
    tc.HorizFeed, tc.SpindleSpeed = "50 mm/min", 1000  # the same, given
    doc.recompute()
    assert _words(op) == defaulted
    tc.HorizFeed, tc.SpindleSpeed = "90 mm/min", 1500
    doc.recompute()
    assert op.FeedsAndSpeeds == ("feed 90 mm/min (the tool controller's HorizFeed); live tool 1500 rpm CW (the tool "
                                 "controller's SpindleSpeed)")


@pytest.mark.parametrize("name, value, message", [
    ("HorizFeed", -1, "HorizFeed=-60.0: the tool controller's HorizFeed must be a number, 0 or more (0: the "
     "default)"),
    ("SpindleSpeed", 1e6, "SpindleSpeed=1e+06: the live tool's speed must be at most 99999 rpm"),
])
def test_a_feed_below_zero_or_a_speed_too_high_is_an_error_naming_it(closing, name, value, message):
    doc, shaft, line, job = _shop(_helix())
    closing.append(doc)
    setattr(job.Tools.Group[0], name, value)
    op = make_cylinder_slot(job, (shaft, "Face1"), [(line, "Edge1")], depth=1)
    assert op_error(op) == message and op.FeedsAndSpeeds == ""


def test_gsk_refuses_inches(closing):
    from freecad_groove.freecad.posts import PostError

    job, op = _helix_op(closing)
    with pytest.raises(PostError, match="--inches: the G7.1 region of a Cylinder slot is written in mm"):
        _post("gsk_lathe", [job], "--inches --switches-by-hand")


def _developed_distance(point, polyline):
    """Distance on the developed surface (z, s) from ``point`` to the polyline."""
    best = float("inf")
    for (z0, s0), (z1, s1) in zip(polyline, polyline[1:]):
        dz, ds = z1 - z0, s1 - s0
        t = max(0.0, min(1.0, ((point[0] - z0) * dz + (point[1] - s0) * ds) / (dz * dz + ds * ds)))
        best = min(best, math.hypot(point[0] - z0 - t * dz, point[1] - s0 - t * ds))
    return best


def test_a_curved_track_is_followed_within_the_chord_tolerance(closing):
    """A barrel-cam bend: half an ellipse drawn in the cylinder's own (angle, z) parameters, an exact edge
    on the face. Every point of the edge is within 0.001 mm of the region's path on the developed surface."""
    cylinder = Part.makeCylinder(20, 50)
    surface = cylinder.Face1.Surface
    curve = Part.Geom2d.Circle2d(FreeCAD.Base.Vector2d(1.0, 25.0), 0.8)
    edge = curve.toShape(surface, 0.0, math.pi)  # u: angle in radians, v: z
    doc, shaft, line, job = _shop(edge, cylinder)
    closing.append(doc)
    op = make_cylinder_slot(job, (shaft, "Face1"), [(line, "Edge1")], depth=1)
    assert op_error(op) is None, op_error(op)
    region = op.Proxy.current_plan(op).region
    to_s = 20.0 * math.pi / 180.0
    start = op.Proxy.current_plan(op).start
    polyline, z, c = [(start.z, start.c * to_s)], start.z, start.c
    for block in region.path:
        z = block.z if block.z is not None else z
        c = block.c if block.c is not None else c
        polyline.append((z, c * to_s))
    assert 10 < len(polyline) < 400, len(polyline)  # straight pieces, not one per sample
    shape = line.Shape.Edges[0]
    a, b = shape.ParameterRange
    worst = 0.0
    for k in range(2001):
        p = shape.valueAt(a + (b - a) * k / 2000)
        worst = max(worst, _developed_distance((p.z, math.atan2(p.y, p.x) * 20.0), polyline))
    assert worst <= 0.001 + 1e-4, worst  # the chord tolerance (+ the 4-decimal rounding of C and Z)


def test_the_op_recomputes_after_reopening_the_saved_document(closing, tmp_path):
    doc, shaft, line, job = _shop(_helix())
    op = make_cylinder_slot(job, (shaft, "Face1"), [(line, "Edge1")], depth=2, passes=2, allowance=0.2, retract=1)
    before = [(c.Name, dict(c.Parameters)) for c in op.Path.Commands]
    path = str(tmp_path / "slot.FCStd")
    doc.saveAs(path)
    name = op.Name
    FreeCAD.closeDocument(doc.Name)
    doc = FreeCAD.openDocument(path)
    closing.append(doc)
    op = doc.getObject(name)
    assert type(op.Proxy).__module__ + "." + type(op.Proxy).__name__ == \
        "freecad_groove.ops.slot.op.ObjectCylinderSlot"
    op.touch()
    doc.recompute()
    assert op_error(op) is None
    assert [(c.Name, dict(c.Parameters)) for c in op.Path.Commands] == before


def test_a_sketch_of_the_developed_surface_is_the_path(closing):
    """The helix drawn flat: a line from (x=Z 10, y=0) to (30, 40*pi), i.e. C 0 -> 360 on R20, in a sketch
    placed anywhere (its own coordinates count): the same Path as the helix edge."""
    import Sketcher

    doc, shaft, line, job = _shop(_helix())
    closing.append(doc)
    sketch = doc.addObject("Sketcher::SketchObject", "Developed")
    sketch.Placement = FreeCAD.Placement(V(100, 0, 0), FreeCAD.Rotation(V(1, 0, 0), 90))
    sketch.addGeometry(Part.LineSegment(V(10, 0, 0), V(30, 40 * math.pi, 0)))
    assert Sketcher  # the workbench's module is loaded for the sketch type
    doc.recompute()
    op = make_cylinder_slot(job, (shaft, "Face1"), sketch, depth=2, passes=2, allowance=0.2, retract=1)
    assert op_error(op) is None, op_error(op)
    assert op.DevelopedSketch == sketch
    along = FEED * 20.0 / math.hypot(20.0, 40.0 * math.pi)
    want = _expected(_safe_radius(job, 1.0), (10.0, 0.0), (30.0, 360.0), [19.1, 18.2, 18.0], 21.0, along)
    _same(_words(op), want)
    sketch.delGeometry(0)
    sketch.addGeometry(Part.LineSegment(V(10, 0, 0), V(60, 40 * math.pi, 0)))  # off the face's Z range 0..50
    doc.recompute()
    assert op_error(op).startswith("DevelopedSketch: Developed.Edge1 leaves Shaft.Face1"), op_error(op)
