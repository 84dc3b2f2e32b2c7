"""The Groove operation inside FreeCAD (1.1 and 1.0; run by tests/freecad/run_suite.py).

A stepped shaft turned about Z (a revolved profile) carries a face of every
kind: a cylinder, a cone growing toward +Z, a cone shrinking toward +Z, a
shoulder face looking +Z, the left end face looking -Z and a blind bore open
toward +Z. A Job and tool controller are built by script (parts.py, shared
with test_posts.py and benchmarks/bench_freecad.py) and a Groove op put on
each face.

The expected Paths are worked out here, not taken from the op: the CYCLE93
call and the start point of each groove by hand (CASES, STARTS), the moves
from the engine's own expansion of that call, written in the Path's form
spelled out in PATH_FORM.
"""

import math

import FreeCAD
import Part
import Path.Main.Job as PathJob
import Path.Main.Stock as PathStock
import pytest
from parts import FACES, FEED_MM_MIN, face_name, make_shop, shaft_shape  # noqa: F401 - shaft_shape: test_posts uses it

from freecad_groove import make_groove
from freecad_groove.engine import GroovingTool, MachineState, Settings
from freecad_groove.engine.cycles.cycle93 import Cycle93
from freecad_groove.engine.moves import ARC_CCW, ARC_CW, DWELL, FEED, RAPID
from freecad_groove.freecad import faces as faces_mod
from freecad_groove.ops.groove import op as groove_op
from freecad_groove.ops.groove.cutting import DEFAULT_FEED_PER_REV, DEFAULT_RPM
from freecad_groove.ops.groove.links import SafeEnvelope
from freecad_groove.ops.groove.op import op_error
from freecad_groove.ops.groove.plan import rapids_clear

V = FreeCAD.Vector

CONE_ANGLE = math.degrees(math.atan2(4, 10))  # both cones change radius by 4 over 10 in Z
TAN_30 = math.tan(math.radians(30))

# name -> (make_groove keywords, GrooveKind, AXFA, AXSA, ANGC, TYP)
CASES = {
    "cylinder": (dict(position=5), "longitudinal, external", 20.0, 25.0, 0.0, 5),
    "cone_up": (dict(position=3), "oblique (ANGC 21.801°), external", 18.8, 7.0, CONE_ANGLE, 5),
    "cone_down": (dict(position=2), "oblique (ANGC 158.199°), external", 10.8, 58.0, 180 - CONE_ANGLE, 5),
    "shoulder": (dict(position=1, width=3.5), "face, external", 19.0, 30.0, 90.0, 6),
    "left_end": (dict(position=2), "face, internal", 14.0, 0.0, 90.0, 8),
    "bore": (dict(position=10, depth=1.5), "longitudinal, internal", 6.0, 50.0, 0.0, 7),
}

# The shaft's safe envelope (Retract 0 = 1 mm clearance): its largest radius
# R20 and its Z extent 0..60, 1 mm out.
R_SAFE, Z_TOP, Z_BOTTOM = 21.0, 61.0, -1.0
BLADE = 3.0  # the blade's width (tool_width)
# name -> the first groove's start point (x, z), worked out by hand:
# - longitudinal external: on the safe cylinder, the blade (its minus corner
#   on the -Z side) over its first plunge at the groove's start edge AXSA;
# - face grooves: on the safe cylinder (the minus corner on the blade's -X
#   side: the blade wholly outside), 1 mm (the clearance) off the face;
# - the bore: beyond the part's +Z end, 1 mm inside the bore wall R6.
STARTS = {
    "cylinder": (R_SAFE, 25.0 - BLADE),
    "cone_up": (R_SAFE, 7.0 - BLADE),
    "cone_down": (R_SAFE, 58.0 - BLADE),
    "shoulder": (R_SAFE, 30.0 + 1.0),
    "left_end": (R_SAFE, 0.0 - 1.0),
    "bore": (6.0 - 1.0, Z_TOP),
}
# With the plus reference corner (and 0.1 mm flank allowance): the corner on
# the blade's +Z side stands the allowance off the start edge; on face grooves
# it is on the blade's +X side, the blade still wholly outside; in the bore
# the blade is wholly beyond the +Z end.
PLUS_STARTS = {
    "cylinder": (R_SAFE, 25.0 - 0.1),
    "cone_up": (R_SAFE, 7.0 - 0.1),
    "cone_down": (R_SAFE, 58.0 - 0.1),
    "shoulder": (R_SAFE + BLADE, 31.0),
    "left_end": (R_SAFE + BLADE, -1.0),
    "bore": (5.0, Z_TOP + BLADE),
}


@pytest.fixture
def doc():
    d = FreeCAD.newDocument("GrooveOpTest")
    name = d.Name
    FreeCAD.setActiveDocument(name)
    yield d
    if name in FreeCAD.listDocuments():
        FreeCAD.closeDocument(name)


@pytest.fixture
def shop(doc):
    """(doc, shaft, job, tc): the shaft in a Job with one tool controller."""
    return make_shop(doc)


def groove(shop, key, **extra):
    doc, shaft, job, tc = shop
    kw = dict(width=4, depth=2, infeed=1, tool_width=3, tool_corner_radius=0.2)
    kw.update(CASES[key][0])
    kw.update(extra)
    return make_groove(job, (shaft, face_name(shaft.Shape, key)), name="Groove_" + key, **kw)


def path_moves(op):
    """[(name, params)] of the op's Path without comments and G18."""
    return [(command.Name, dict(command.Parameters)) for command in op.Path.Commands
            if not command.Name.startswith("(") and command.Name != "G18"]


def cycle93(axfa, axsa, typ, angc=0.0, **words):
    """The CYCLE93 call an op must derive: a groove 4 wide, 2 deep, infeed 1,
    no flank angles, corners or allowances, unless ``words`` say otherwise."""
    values = dict(widg=4.0, depg=2.0, ang1=0.0, ang2=0.0, rco1=0.0, rco2=0.0, rci1=0.0, rci2=0.0,
                  fal1=0.0, fal2=0.0, idep=1.0, dwt=0.0, vrt=0.0)
    values.update(words)
    return Cycle93(axfa=axfa, axsa=axsa, angc=angc, typ=typ, **values)


def safe_start(radius, z_max, clearance=1.0):
    """The op's safe start point for a body of revolution of ``radius`` up to
    ``z_max`` in a Job's default stock (its bounding box grown 1 mm: a square
    of half side radius + 1 up to z_max + 1): the clearance outside the
    square's corner radius and beyond its +Z face."""
    return (math.hypot(radius + 1.0, radius + 1.0) + clearance, z_max + 1.0 + clearance)


# The shaft's (R20, Z 0..60) in its default stock (X/Y -21..21, Z -1..61):
# (21 * sqrt(2) + 1, 62).
SAFE_START = safe_start(20.0, 60.0)


def first_link(start, on="side", safe=SAFE_START):
    """The first groove's link: to the safe start point (both axes), then
    along the stock's outside one axis at a time and in to ``start``: for
    "top" in X above the stock, then down in Z; else down in Z outside the
    stock's radius (for "bottom" to the start point's level below the part),
    then in X."""
    (x, z), (sx, sz) = start, safe
    return [(sx, sz), (x, sz), (x, z)] if on == "top" else [(sx, sz), (sx, z), (x, z)]


def way_back(start, on="side", safe=SAFE_START):
    """The rapids after the op's last groove, from its start point back to the
    safe start point: the first link's steps reversed ("top": up in Z above
    the stock, then out in X; else out in X beyond the stock's radius, then
    up in Z)."""
    (x, z), (sx, sz) = start, safe
    return [(x, sz), (sx, sz)] if on == "top" else [(sx, z), (sx, sz)]


TOOL = GroovingTool(BLADE, 0.2)  # tool_width 3, tool_corner_radius 0.2, the minus reference corner
FEED_MM_S = FEED_MM_MIN / 60.0  # the tool controller's feed as the Path holds it (FreeCAD's mm/s)
# A tool controller without feed or speed (a new Job's): the op's defaults, 0.05 mm/rev at 500 rpm, in mm/s
DEFAULT_FEED_MM_S = DEFAULT_FEED_PER_REV * DEFAULT_RPM / 60.0

# The Path's form of each kind of engine move from ``here`` (x, z), spelled out: (command, words); an
# arc's I and K its centre less its start.
PATH_FORM = {
    RAPID: lambda move, feed, here: ("G0", {"X": move.x, "Z": move.z}),
    FEED: lambda move, feed, here: ("G1", {"X": move.x, "Z": move.z, "F": feed}),
    DWELL: lambda move, feed, here: ("G4", {"P": move.p}),
    ARC_CW: lambda move, feed, here: ("G2", {"X": move.x, "Z": move.z, "I": move.centre[0] - here[0],
                                             "K": move.centre[1] - here[1], "F": feed}),
    ARC_CCW: lambda move, feed, here: ("G3", {"X": move.x, "Z": move.z, "I": move.centre[0] - here[0],
                                              "K": move.centre[1] - here[1], "F": feed}),
}


def groove_path(link, call, start, tool=TOOL, feed=FEED_MM_S, retreat=()):
    """The Path the op must write for one groove, after its comment: every
    link step a G0 with the axes it moves, then the engine's expansion of
    ``call`` from ``start`` (x, z) with ``tool`` in PATH_FORM (``feed`` in mm/s),
    then the ``retreat`` steps (the op's last groove) as G0."""
    def rapids(steps):
        return [("G0", {axis: value for axis, value in zip("XZ", step) if value is not None}) for step in steps]

    path, here = rapids(link), start
    for move in call.expand(MachineState(x=start[0], z=start[1]), Settings(tool=tool)):
        path.append(PATH_FORM[move.kind](move, feed, here))
        here = here if move.kind == DWELL else (move.x, move.z)
    return path + rapids(retreat)


def case_path(key, start=None, tool=TOOL, feed=FEED_MM_S, safe=SAFE_START, **words):
    """groove_path of the CASES groove ``key`` from its hand-worked start point
    (or ``start``) and the safe start point ``safe``; ``words`` change its
    CYCLE93 call."""
    kw, _kind, axfa, axsa, angc, typ = CASES[key]
    words = dict(dict(widg=kw.get("width", 4.0), depg=kw.get("depth", 2.0), typ=typ), **words)
    call = cycle93(axfa, axsa, angc=angc, **words)
    start = STARTS[key] if start is None else start
    on = "top" if key == "bore" else "side"
    return groove_path(first_link(start, on, safe), call, start, tool, feed, way_back(start, on, safe))


def assert_same_moves(actual, expected, tol=1e-6):
    assert len(actual) == len(expected)
    for i, ((an, ap), (en, ep)) in enumerate(zip(actual, expected)):
        assert an == en, (i, an, en)
        assert sorted(ap) == sorted(ep), (i, ap, ep)
        for k in ep:
            assert ap[k] == pytest.approx(ep[k], abs=tol), (i, k, ap, ep)


# -- deriving CYCLE93 from the faces --------------------------------------------


@pytest.mark.parametrize("key", sorted(CASES))
def test_derived_parameters_and_path(shop, key):
    op = groove(shop, key)
    _kw, kind, axfa, axsa, angc, typ = CASES[key]
    assert op_error(op) is None, op_error(op)
    assert op.GrooveKind == kind
    assert op.AXFA.Value == pytest.approx(axfa, abs=1e-9)
    assert op.AXSA.Value == pytest.approx(axsa, abs=1e-9)
    assert op.ANGC.Value == pytest.approx(angc, abs=1e-9)
    assert op.TYP == typ
    (call, settings, start), = op.Proxy.cycles(op)
    assert (call.axfa, call.axsa, call.typ) == (pytest.approx(axfa, abs=1e-9), pytest.approx(axsa, abs=1e-9), typ)
    assert (call.widg, call.depg, call.idep) == (op.Width.Value, op.Depth.Value, 1.0)
    assert (settings.tool.width, settings.tool.corner_radius, settings.tool.reference) == (3.0, 0.2, "minus")
    assert start.feed == pytest.approx(FEED_MM_MIN) and not start.feed_per_rev
    commands = op.Path.Commands
    assert commands[0].Name == "(%s)" % op.Label
    assert commands[1].Name == "G18"
    moves = path_moves(op)
    assert_same_moves(moves, case_path(key))
    assert any(name == "G1" for name, _p in moves)
    assert all("Y" not in p for _n, p in moves)
    assert all(p["F"] == pytest.approx(FEED_MM_MIN / 60.0) for n, p in moves if n == "G1")


def test_path_in_model_coordinates(shop):
    """X is the radius: the 2 mm deep groove in the R20 cylinder bottoms at X18,
    between Z21 and Z25 (the minus reference corner, blade 3 wide)."""
    op = groove(shop, "cylinder")
    feeds = [p for n, p in path_moves(op) if n == "G1"]
    assert min(p["X"] for p in feeds) == pytest.approx(18.0, abs=1e-9)
    assert max(p["X"] for p in feeds) <= 20.0 + 1e-9
    assert min(p["Z"] for p in feeds) == pytest.approx(21.0, abs=1e-9)
    assert max(p["Z"] + 3.0 for p in feeds) == pytest.approx(25.0, abs=1e-9)
    plan, = op.Proxy.plan(op)
    # start point: 1 mm (Retract 0 = 1 mm) outside the model's largest radius, beside the groove
    assert (plan.start.x, plan.start.z, plan.start_on) == (pytest.approx(21.0), pytest.approx(22.0), "side")
    # from the safe start point down in Z outside the stock, then in X to the start point
    assert plan.link == [SAFE_START, (SAFE_START[0], 22.0), (21.0, 22.0)]


def test_internal_groove_enters_the_bore_from_its_open_end(shop):
    op = groove(shop, "bore")
    plan, = op.Proxy.plan(op)
    assert plan.start_on == "top"
    assert plan.start.z == pytest.approx(61.0)  # 1 mm beyond the part's +Z end
    assert plan.start.x == pytest.approx(5.0)  # 1 mm inside the bore wall
    # from the safe start point in X above the stock, then down in Z to the start point
    assert plan.link == [SAFE_START, (5.0, 62.0), (5.0, 61.0)]
    feeds = [p for n, p in path_moves(op) if n == "G1"]
    assert max(p["X"] for p in feeds) == pytest.approx(7.5, abs=1e-9)


def test_chr_chamfers_add_ten_to_typ(shop):
    op = groove(shop, "cylinder", chamfer_measure="Leg length (CHR)", edge_corner1=0.5, edge_corner1_type="Chamfer",
                base_corner2=0.3, base_corner2_type="Radius")
    assert op_error(op) is None, op_error(op)
    assert op.TYP == 15
    (call, _s, _st), = op.Proxy.cycles(op)
    assert (call.rco1, call.rco2, call.rci1, call.rci2) == (-0.5, 0.0, 0.0, 0.3)
    assert_same_moves(path_moves(op), case_path("cylinder", typ=15, rco1=-0.5, rci2=0.3))


def test_several_grooves_pitch_toward_minus_z(shop):
    op = groove(shop, "cylinder", position=2, groove_count=3, pitch=6, dwell=0.5)
    assert op_error(op) is None, op_error(op)
    plans = op.Proxy.plan(op)
    assert [p.cycle.axsa for p in plans] == [28.0, 22.0, 16.0]
    assert [c.Name for c in op.Path.Commands].count("G18") == 1
    assert sum(1 for c in op.Path.Commands if "groove" in c.Name) == 3
    assert plans[1].link == [(21.0, plans[1].start.z)]  # along Z on the safe cylinder
    moves = path_moves(op)
    # the blade 3 wide over each groove's +Z edge, from one to the next along Z on the safe cylinder
    expected = []
    for axsa, link, back in ((28.0, first_link((R_SAFE, 25.0)), ()), (22.0, [(R_SAFE, 19.0)], ()),
                             (16.0, [(R_SAFE, 13.0)], way_back((R_SAFE, 13.0)))):
        expected += groove_path(link, cycle93(20.0, axsa, 5, dwt=0.5), (R_SAFE, axsa - BLADE), retreat=back)
    assert_same_moves(moves, expected)
    assert any(n == "G4" and p["P"] == pytest.approx(0.5) for n, p in moves)


def test_tool_size_comes_from_the_bit_when_it_has_one(shop):
    doc, shaft, job, tc = shop
    bit = tc.Tool
    bit.addProperty("App::PropertyLength", "Width", "Groove test")
    bit.addProperty("App::PropertyLength", "CornerRadius", "Groove test")
    bit.Width = 2.5
    bit.CornerRadius = 0.1
    op = groove(shop, "cylinder", tool_width=3, tool_corner_radius=0.2)
    (_c, settings, _st), = op.Proxy.cycles(op)
    assert (settings.tool.width, settings.tool.corner_radius) == (2.5, 0.1)
    # the 2.5 wide blade over the groove's +Z edge Z25
    assert_same_moves(path_moves(op), case_path("cylinder", start=(R_SAFE, 25.0 - 2.5), tool=GroovingTool(2.5, 0.1)))


# -- errors -----------------------------------------------------------------------


def test_engine_error_is_reported_on_the_op_and_a_fix_recovers(shop):
    doc, shaft, job, tc = shop
    other = groove(shop, "shoulder")
    op = groove(shop, "cylinder")
    assert op_error(op) is None
    op.Width = 2  # narrower than the 3 mm tool
    doc.recompute()
    status = op_error(op)
    assert "WIDG=2" in status and "narrower than the tool width 3" in status and "(alarm 61602)" in status
    # the stale moves are gone: the Path ends with a comment repeating the message, no moves
    assert path_moves(op) == []
    assert op.Path.Commands[-1].Name == "(%s: %s)" % (op.Label, status.replace("(", "[").replace(")", "]"))
    for o in (shaft, job, tc, other):
        assert o.isValid(), o.Name
    assert other.Path.Commands and op_error(other) is None
    op.Width = 4
    doc.recompute()
    assert op_error(op) is None
    assert "Invalid" not in op.State
    assert_same_moves(path_moves(op), case_path("cylinder"))


def test_an_error_does_not_escape_execute(shop):
    """An exception escaping execute makes FreeCAD print a Python traceback
    before the message (the property editor's recompute): the op reports
    one clean line instead."""
    doc, shaft, job, tc = shop
    op = groove(shop, "cylinder")
    op.Width = 2
    op.Proxy.execute(op)  # raised the CycleError before
    assert "(alarm 61602)" in op_error(op)
    assert path_moves(op) == []


# (FreeCAD itself clips an infinite length to the largest float or to 0)
@pytest.mark.parametrize("name, value", [("Dwell", float("nan")), ("Dwell", float("inf")), ("Width", float("nan")),
                                         ("Depth", float("nan")), ("Position", float("nan")),
                                         ("FlankAngle1", float("nan"))])
def test_nan_and_infinite_values_are_refused_naming_the_property(shop, name, value):
    doc, shaft, job, tc = shop
    op = groove(shop, "cylinder")
    assert path_moves(op)
    setattr(op, name, value)
    doc.recompute()
    assert op_error(op) == "%s=%s: must be a finite number" % (name, float(value))
    assert path_moves(op) == []  # no stale toolpath in the 3D view
    with pytest.raises(ValueError, match="^%s=" % name):  # nor from a post
        op.Proxy.cycles(op)


def test_groove_past_the_face_is_refused(shop):
    doc, shaft, job, tc = shop
    op = groove(shop, "cylinder", position=18)  # 18 + 4 > the 20 mm long face
    assert "past the face" in op_error(op) and "Shaft.Face" in op_error(op)
    op.Position = 15
    doc.recompute()
    assert op_error(op) is None


def test_pitch_is_required_for_several_grooves(shop):
    op = groove(shop, "cylinder", groove_count=2)
    assert "Pitch" in op_error(op)


@pytest.mark.parametrize("faces, values, message", [
    ("cylinder", dict(width="abc"), r"^make_groove\(\): width='abc': not a value for Width"),
    ("cylinder", dict(width="4 s"), r"^make_groove\(\): width='4 s': not a value for Width"),
    (("notanobject", "Face1"), {}, r"'notanobject' is not a FreeCAD object with a shape"),
    ((None, "Face1"), {}, r"None is not a FreeCAD object with a shape"),
    ([], {}, r"^make_groove\(\): faces=\[\]: give \(part, "),
    ("outsider", {}, r"^make_groove\(\): Outsider is not in the model of the Job Job$"),
    ("no_face", {}, r"^make_groove\(\): Shaft has no Face99$"),
])
def test_make_groove_refuses_bad_input_leaving_nothing_behind(shop, faces, values, message):
    doc, shaft, job, tc = shop
    if faces == "outsider":
        outsider = doc.addObject("Part::Feature", "Outsider")
        outsider.Shape = Part.makeCylinder(5, 5)
        faces = (outsider, "Face1")
    elif faces == "no_face":
        faces = (shaft, "Face99")
    elif faces == "cylinder":
        faces = (shaft, face_name(shaft.Shape, "cylinder"))
    names = sorted(o.Name for o in doc.Objects)
    with pytest.raises(ValueError, match=message):
        make_groove(job, faces, **values)
    assert sorted(o.Name for o in doc.Objects) == names
    assert job.Operations.Group == [] and job.Tools.Group == [tc]


def test_make_groove_in_a_job_without_tool_controller_leaves_none_behind_on_failure(shop):
    doc, shaft, job, tc = shop
    job.Tools.Group = []  # make_groove then makes "TC: Grooving tool" (and its tool bit)
    names = sorted(o.Name for o in doc.Objects)
    with pytest.raises(ValueError, match="^make_groove\\(\\): dwell='long': not a value for Dwell"):
        make_groove(job, (shaft, face_name(shaft.Shape, "cylinder")), dwell="long")
    assert sorted(o.Name for o in doc.Objects) == names and job.Tools.Group == []


def ball_ended_shaft():
    """A shaft R20 from Z0 to Z50 with a ball end (a sphere R20 at Z50) and a
    torus-shaped bead at Z10: faces no groove can be cut into, with the
    sphere's degenerated edge at its pole."""
    shape = Part.makeCylinder(20, 50).fuse(Part.makeSphere(20, V(0, 0, 50)))
    return shape.fuse(Part.makeTorus(20, 2, V(0, 0, 10))).removeSplitter()


def test_spherical_and_toroidal_faces_do_not_break_grooves_elsewhere(doc):
    shape = ball_ended_shaft()
    cylinders = [i + 1 for i, f in enumerate(shape.Faces) if isinstance(f.Surface, Part.Cylinder)]
    _doc, shaft, job, tc = make_shop(doc, shape=shape)
    op = make_groove(job, (shaft, "Face%d" % max(cylinders, key=lambda i: shape.Faces[i - 1].BoundBox.ZMax)),
                     position=5, width=4, depth=2, infeed=1, tool_width=3, tool_corner_radius=0.2)
    assert op_error(op) is None
    assert path_moves(op)
    # the ball's top is Z70: the op starts 1 mm beyond the default stock (the model's bounding box, which
    # OCC makes loose around the torus, grown 1 mm), outside the radius of its corner, stays out of the ball and
    # goes back there at the end
    stock = job.Stock.Shape.BoundBox
    assert stock.ZMax == pytest.approx(71.0) and min(stock.XMax, stock.YMax) >= 22.0 + 1.0
    first, *rest, last = path_moves(op)
    safe = ("G0", {"X": pytest.approx(math.hypot(stock.XMax, stock.YMax) + 1.0), "Z": pytest.approx(72.0)})
    assert first == safe and last == safe  # it ends where it started
    assert max(words["Z"] for _n, words in rest if "Z" in words) < 71.0 + 1e-9
    sphere = next(i + 1 for i, f in enumerate(shape.Faces) if isinstance(f.Surface, Part.Sphere))
    bad = make_groove(job, (shaft, "Face%d" % sphere), width=4)  # a size: not read from the model
    assert op_error(bad) == "Shaft.Face%d: a sphere face; grooves go on a cylinder, a cone or a plane square " \
                            "to the Z axis" % sphere


def test_unsupported_faces_name_the_face(doc):
    box = doc.addObject("Part::Box", "Block")
    box.Length = box.Width = box.Height = 10
    ball = doc.addObject("Part::Sphere", "Ball")
    off = doc.addObject("Part::Cylinder", "OffAxis")
    off.Placement.Base = V(30, 0, 0)
    tilted = doc.addObject("Part::Cylinder", "Tilted")
    tilted.Placement.Rotation = FreeCAD.Rotation(V(1, 0, 0), 90)
    doc.recompute()
    with pytest.raises(ValueError, match=r"^Ball\.Face1: a sphere face"):
        faces_mod.analyse_face(ball.Shape.Face1, "Ball.Face1")
    with pytest.raises(ValueError, match=r"^Block\.Face1: a plane whose normal .* is not along Z"):
        faces_mod.analyse_face(box.Shape.Face1, "Block.Face1")
    with pytest.raises(ValueError, match=r"^OffAxis\.Face1: the cylinder's axis passes through X30 Y0"):
        faces_mod.analyse_face(off.Shape.Face1, "OffAxis.Face1")
    with pytest.raises(ValueError, match=r"^Tilted\.Face1: the cylinder's axis .* is not the Z axis"):
        faces_mod.analyse_face(tilted.Shape.Face1, "Tilted.Face1")
    # in an op: the recompute fails with the message naming the face
    job = PathJob.Create("Job", [box])
    doc.recompute()
    op = make_groove(job, (box, "Face1"), width=4)  # a size: not read from the model
    assert op_error(op).startswith("Block.Face1: a plane whose normal")
    assert job.isValid()


def test_face_analysis_directions():
    shape = shaft_shape()
    by_key = {k: faces_mod.analyse_face(shape.getElement(face_name(shape, k)), k) for k in FACES}
    assert (by_key["cylinder"].kind, by_key["cylinder"].external) == ("longitudinal", True)
    assert (by_key["bore"].kind, by_key["bore"].external) == ("longitudinal", False)
    assert (by_key["shoulder"].kind, by_key["shoulder"].external, by_key["shoulder"].r_min) == ("face", True, 14.0)
    assert (by_key["left_end"].kind, by_key["left_end"].external, by_key["left_end"].r_min) == ("face", False, 0.0)
    assert 0 < by_key["cone_up"].angc < 90 < by_key["cone_down"].angc < 180
    # a steep cone (60 degrees off Z) takes face grooves; its Z normal decides external/internal
    steep = Part.makeCone(20, 10, 10 * math.tan(math.radians(30)))  # radius 20 -> 10 over 5.77 in Z
    cone = [f for f in steep.Faces if isinstance(f.Surface, Part.Cone)][0]
    steep_face = faces_mod.analyse_face(cone, "Steep")
    assert (steep_face.kind, steep_face.external) == ("face", True)
    assert steep_face.angc == pytest.approx(180 - 60)
    assert steep_face.describe() == "oblique face (ANGC 120°), external"


def test_rapids_through_the_part_are_detected():
    envelope = SafeEnvelope([shaft_shape()], 1.0)
    assert (envelope.r_safe, envelope.z_top, envelope.z_bottom) == (21.0, 61.0, -1.0)
    assert envelope.hits((21.0, 20.0), (5.0, 20.0))  # radially into the R20 cylinder
    assert not envelope.hits((21.0, 20.0), (21.0, 65.0))
    assert not envelope.hits((5.0, 61.0), (5.0, 30.0))  # down the bore
    assert envelope.hits((5.0, 61.0), (5.0, 20.0))  # through the bore's bottom


# -- approaching the groove ------------------------------------------------------


def _revolved(doc, name, profile):
    obj = doc.addObject("Part::Feature", name)
    obj.Shape = Part.Face(Part.makePolygon([V(r, 0, z) for r, z in profile])).revolve(V(0, 0, 0), V(0, 0, 1), 360)
    doc.recompute()
    return obj


def _find(obj, predicate):
    """The name of the one face of ``obj`` that ``predicate`` accepts."""
    return face_name(obj.Shape, "wanted", {"wanted": predicate})


def _rapids_outside(op, part):
    """Every rapid of the approach and of the final retreat stays out of the part."""
    envelope = SafeEnvelope([part.Shape], 1.0)
    for plan in op.Proxy.plan(op):
        assert rapids_clear(envelope, (plan.start.x, plan.start.z), plan.moves)


def test_bore_open_toward_minus_z_is_entered_from_below(doc):
    # blind bore R6 from the -Z end (z 0..35) in an R20 x 50 body
    part = _revolved(doc, "Sleeve", [(6, 0), (20, 0), (20, 50), (0, 50), (0, 35), (6, 35), (6, 0)])
    job = PathJob.Create("Job", [part])
    doc.recompute()
    op = make_groove(job, (part, _find(part, lambda f: f.surface == "cylinder" and not f.external)),
                     position=5, width=4, depth=1, tool_width=3, tool_corner_radius=0.2)
    assert op_error(op) is None, op_error(op)
    assert (op.TYP, op.AXFA.Value, op.AXSA.Value) == (7, 6.0, 30.0)
    plan, = op.Proxy.plan(op)
    assert plan.start_on == "bottom"
    assert plan.start.z == pytest.approx(-4.0)  # the 3 mm blade wholly 1 mm below the part
    assert plan.start.x == pytest.approx(5.0)
    _rapids_outside(op, part)
    # from the safe start point (the R20 x 50 body's default stock) down outside the stock to the start point's
    # level below the part, in to the start point; the Job's own tool controller feeds at 0
    start = (5.0, -4.0)
    safe = safe_start(20.0, 50.0)
    expected = groove_path(first_link(start, "bottom", safe), cycle93(6.0, 30.0, 7, depg=1.0),
                           start, feed=DEFAULT_FEED_MM_S, retreat=way_back(start, "bottom", safe))
    assert_same_moves(path_moves(op), expected)


def test_face_groove_inside_a_recess_is_approached_along_z(doc):
    # R20 x 30 body with an annular recess R10..R15, 5 deep, in its +Z end:
    # the recess floor (Z25, looking +Z) cannot be reached radially at Z26
    part = _revolved(doc, "Ring", [(0, 0), (20, 0), (20, 30), (15, 30), (15, 25), (10, 25), (10, 30), (0, 30), (0, 0)])
    job = PathJob.Create("Job", [part])
    doc.recompute()
    floor = _find(part, lambda f: f.surface == "plane" and abs(f.z_min - 25) < 1e-9)
    op = make_groove(job, (part, floor), position=0.5, width=3.5, depth=2, tool_width=3, tool_corner_radius=0.2)
    assert op_error(op) is None, op_error(op)
    assert (op.TYP, op.AXFA.Value, op.AXSA.Value, op.GrooveKind) == (6, 14.5, 25.0, "face, external")
    plan, = op.Proxy.plan(op)
    assert plan.start_on == "top" and plan.start.z == pytest.approx(31.0)
    _rapids_outside(op, part)
    # a column over the first plunge (the blade's minus corner 3 inside the groove's outer edge R14.5)
    start = (14.5 - BLADE, 31.0)
    safe = safe_start(20.0, 30.0)
    expected = groove_path(first_link(start, "top", safe), cycle93(14.5, 25.0, 6, 90.0, widg=3.5),
                           start, feed=DEFAULT_FEED_MM_S, retreat=way_back(start, "top", safe))
    assert_same_moves(path_moves(op), expected)
    # the shoulder-like outer end face (R15..R20 at Z30) is reached radially
    rim = _find(part, lambda f: f.surface == "plane" and abs(f.z_min - 30) < 1e-9 and f.r_min > 14)
    op2 = make_groove(job, (part, rim), position=0.5, width=3.2, depth=1, tool_width=3, tool_corner_radius=0.2)
    assert op_error(op2) is None, op_error(op2)
    assert op2.Proxy.plan(op2)[0].start_on == "side"


def test_steep_cone_takes_a_face_groove(doc):
    # a 60 degree (off Z) cone R30 -> R10 over 11.547 in Z on top of an R30 cylinder
    h = 20 * math.tan(math.radians(30))
    part = _revolved(doc, "Cone", [(0, 0), (30, 0), (30, 10), (10, 10 + h), (0, 10 + h), (0, 0)])
    job = PathJob.Create("Job", [part])
    doc.recompute()
    cone = _find(part, lambda f: f.surface == "cone")
    op = make_groove(job, (part, cone), position=4, width=4, depth=2, tool_width=3, tool_corner_radius=0.2)
    assert op_error(op) is None, op_error(op)
    assert op.GrooveKind == "oblique face (ANGC 120°), external"
    assert op.TYP == 6
    assert op.ANGC.Value == pytest.approx(120.0)
    assert op.AXFA.Value == pytest.approx(26.0)
    assert op.AXSA.Value == pytest.approx(10 + 4 * TAN_30)
    _rapids_outside(op, part)
    # on the safe cylinder R31, 1 mm above the cone where the blade (R23..26) plunges first: at R23
    start = (31.0, 10 + (30 - 23) * TAN_30 + 1.0)
    safe = safe_start(30.0, 10 + h)
    expected = groove_path(first_link(start, safe=safe), cycle93(26.0, 10 + 4 * TAN_30, 6, 120.0),
                           start, feed=DEFAULT_FEED_MM_S, retreat=way_back(start, safe=safe))
    assert_same_moves(path_moves(op), expected)


def test_one_op_on_several_faces_links_along_the_envelope(shop):
    doc, shaft, job, tc = shop
    names = [face_name(shaft.Shape, k) for k in ("bore", "cylinder", "left_end")]
    op = make_groove(job, (shaft, names), position=5, width=4, depth=1, tool_width=3, tool_corner_radius=0.2,
                     comment="three faces")
    assert op_error(op) is None, op_error(op)
    assert op.GrooveKind == "longitudinal, internal; longitudinal, external; face, internal"
    assert (op.TYP, op.AXFA.Value, op.AXSA.Value) == (7, 6.0, 55.0)  # the first face's first groove
    plans = op.Proxy.plan(op)
    assert [p.start_on for p in plans] == ["top", "side", "side"]
    assert [c.Name for c in op.Path.Commands[:3]] == ["(%s)" % op.Label, "(three faces)", "G18"]
    # bore (from beyond the +Z end), cylinder (up, out and down the safe cylinder), left end (down it)
    bore_start, cylinder_start, end_start = (5.0, Z_TOP), (R_SAFE, 25.0 - BLADE), (R_SAFE, Z_BOTTOM)
    expected = groove_path(first_link(bore_start, "top"), cycle93(6.0, 55.0, 7, depg=1.0), bore_start)
    expected += groove_path([(R_SAFE, Z_TOP), cylinder_start], cycle93(20.0, 25.0, 5, depg=1.0), cylinder_start)
    expected += groove_path([end_start], cycle93(11.0, 0.0, 8, 90.0, depg=1.0), end_start, retreat=way_back(end_start))
    assert_same_moves(path_moves(op), expected)
    for plan in plans[1:]:
        prev = None
        for x, z in plan.link:  # one axis at a time, never inside R21 x Z-1..61
            assert not (x < 21 - 1e-9 and -1 + 1e-9 < z < 61 - 1e-9), (x, z)
            if prev is not None:
                assert (x == prev[0]) != (z == prev[1])
            prev = (x, z)
    assert plans[1].link == [(21.0, 61.0), (21.0, plans[1].start.z)]


def _replace_stock(shop, stock):
    """Put ``stock`` (a new Job stock object, or None: no stock) in the shop's Job in place of the default one."""
    doc, _shaft, job, _tc = shop
    old = job.Stock
    job.Stock = stock
    doc.removeObject(old.Name)
    doc.recompute()


@pytest.mark.parametrize("key", ["cylinder", "shoulder", "left_end", "bore"])
def test_the_op_starts_and_ends_at_the_safe_point_outside_the_stock(shop, key):
    """A bar R25 from Z-1 to Z65 (5 mm over the R20 x Z0..60 shaft's radius and +Z end): the first move is a rapid
    to the safe start point 1 mm (the clearance) outside the bar and beyond its end, X26 Z66; the link rapids from
    there stay out of the bar but the last, which enters it straight at the first groove's start point. After the
    groove the op goes back to X26 Z66 the same way: out of the bar straight, then outside it."""
    doc, _shaft, job, _tc = shop
    placement = FreeCAD.Placement(V(0, 0, -1), FreeCAD.Rotation())
    _replace_stock(shop, PathStock.CreateCylinder(job, 25.0, 66.0, placement))
    op = groove(shop, key)
    assert op_error(op) is None, op_error(op)
    assert_same_moves(path_moves(op)[:1], [("G0", {"X": 26.0, "Z": 66.0})])
    plan = op.Proxy.plan(op)[0]
    link = [tuple(step) for step in plan.link]
    assert link == first_link(STARTS[key], "top" if key == "bore" else "side", (26.0, 66.0))
    bar = SafeEnvelope([job.Stock.Shape], 1.0)
    assert bar.model_radius == pytest.approx(25.0) and (bar.z_min, bar.z_max) == (pytest.approx(-1), pytest.approx(65))
    for a, b in zip(link, link[1:-1]):
        assert not bar.hits(a, b), (a, b)
    (x, z), on = STARTS[key], "top" if key == "bore" else "side"
    back = [(x, 66.0), (26.0, 66.0)] if on == "top" else [(26.0, z), (26.0, 66.0)]
    assert [tuple(step) for step in plan.retreat] == back
    assert_same_moves(path_moves(op)[-2:], [("G0", {"X": x, "Z": z}) for x, z in back])
    for a, b in zip(back, back[1:]):
        assert not bar.hits(a, b), (a, b)


def test_safe_start_point_from_the_stock_and_model():
    """1 mm (the clearance) outside the larger radius and beyond the higher +Z end of stock and model; without
    stock (CAM's ops need one, the envelope does not): the model's, the envelope's corner."""
    envelope = SafeEnvelope([shaft_shape()], 1.0)
    assert envelope.safe_start(None) == (pytest.approx(R_SAFE), pytest.approx(Z_TOP))
    assert envelope.safe_start(Part.Shape()) == (pytest.approx(R_SAFE), pytest.approx(Z_TOP))
    bar = Part.makeCylinder(25.0, 66.0, V(0, 0, -1))
    assert envelope.safe_start(bar) == (pytest.approx(26.0), pytest.approx(66.0))
    short = Part.makeCylinder(19.0, 50.0)  # thinner and shorter than the model: the model's corner
    assert envelope.safe_start(short) == (pytest.approx(R_SAFE), pytest.approx(Z_TOP))


@pytest.mark.parametrize("key", sorted(CASES))
def test_plus_reference_corner(shop, key):
    doc, shaft, job, tc = shop
    op = groove(shop, key, reference_corner="plus", flank_angle2=5, base_corner1=0.3, base_corner1_type="Radius",
                base_allowance=0.1, flank_allowance=0.1)
    assert op_error(op) is None, op_error(op)
    (_c, settings, _st), = op.Proxy.cycles(op)
    assert settings.tool.reference == "plus"
    # the blade's minus-side edge at the safe start point: the plus corner's words 3 (the blade) further along
    # the groove's axis, Z for longitudinal grooves, X for face grooves
    sx, sz = SAFE_START
    safe = (sx + BLADE, sz) if key in ("shoulder", "left_end") else (sx, sz + BLADE)
    expected = case_path(key, start=PLUS_STARTS[key], tool=GroovingTool(BLADE, 0.2, "plus"), safe=safe, ang2=5.0,
                         rci1=0.3, fal1=0.1, fal2=0.1)
    assert_same_moves(path_moves(op), expected)
    _rapids_outside(op, shaft)


def test_a_job_without_tool_controller_gets_one(shop):
    doc, shaft, job, tc = shop
    job.Tools.removeObject(tc)
    doc.removeObject(tc.Name)
    doc.recompute()
    assert not job.Tools.Group
    op = groove(shop, "cylinder")
    assert len(job.Tools.Group) == 1
    assert op.ToolController == job.Tools.Group[0]
    assert op.ToolController.Label == "TC: Grooving tool"
    assert op_error(op) is None, op_error(op)
    assert op.ToolController.HorizFeed.Value == 0.0  # a new tool controller's feed
    assert_same_moves(path_moves(op), case_path("cylinder", feed=DEFAULT_FEED_MM_S))


def test_make_groove_rejects_unknown_keywords(shop):
    doc, shaft, job, tc = shop
    with pytest.raises(TypeError, match="widht"):
        make_groove(job, (shaft, "Face3"), widht=4)


def test_posts_reuse_the_plan_only_while_the_op_is_up_to_date(shop):
    op = groove(shop, "cylinder")
    doc = shop[0]
    cached = op.Proxy.current_plan(op)
    assert cached is op.Proxy.current_plan(op)  # no replanning after a recompute
    op.Width = 5.0  # touched, not recomputed: a post must not write the old groove
    fresh = op.Proxy.current_plan(op)
    assert fresh is not cached
    assert fresh[0].cycle.widg == 5.0 and cached[0].cycle.widg == 4.0
    doc.recompute()
    assert op.Proxy.current_plan(op) is op.Proxy.current_plan(op)
    assert op.Proxy.current_plan(op)[0].cycle.widg == 5.0


# -- planning from the task panel's values --------------------------------------


def test_plan_with_values_leaves_the_op_alone(shop):
    op = groove(shop, "cylinder")
    path_before = op.Path.toGCode()
    plans = op.Proxy.plan_with(op, {"Width": 6.0, "Depth": 3.0, "GrooveCount": 2, "Pitch": 8.0,
                                    "EdgeCorner1Type": "Chamfer", "EdgeCorner1": 0.5})
    assert [(p.cycle.widg, p.cycle.depg, p.cycle.rco1) for p in plans] == [(6.0, 3.0, -0.5)] * 2
    assert [p.position for p in plans] == [5.0, 13.0]
    assert (op.Width.Value, op.Depth.Value, int(op.GrooveCount)) == (4.0, 2.0, 1)
    assert "Touched" not in op.State and op.Path.toGCode() == path_before
    # The same values on the op itself plan the same grooves.
    op.Width, op.Depth, op.GrooveCount, op.Pitch = 6.0, 3.0, 2, 8.0
    op.EdgeCorner1Type, op.EdgeCorner1 = "Chamfer", 0.5
    assert [(p.cycle, p.start, p.moves) for p in op.Proxy.plan(op)] == [(p.cycle, p.start, p.moves) for p in plans]


@pytest.mark.parametrize("values, properties, text", [
    ({"Width": 2.0}, ("Width", "ToolWidth"), "alarm 61602"),
    ({"ToolWidth": 5.0}, ("Width", "ToolWidth"), "narrower than the tool width 5"),
    ({"BaseCorner1Type": "Radius", "BaseCorner1": 2.0, "BaseCorner2Type": "Radius", "BaseCorner2": 2.5},
     ("BaseCorner1", "BaseCorner2"), "alarm 61603"),
    ({"Infeed": 0.0}, ("Infeed",), "IDEP"),
    ({"GrooveCount": 3, "Pitch": 0.0}, ("Pitch",), "Pitch=0"),
    ({"Position": 18.0}, ("Position",), "past the face"),
    ({"GrooveCount": 3, "Pitch": 9.0}, ("Position", "Pitch", "GrooveCount"), "groove 3"),
    ({"Depth": 25.0}, ("Depth",), "past the axis"),
])
def test_plan_with_errors_name_the_properties_to_fix(shop, values, properties, text):
    op = groove(shop, "cylinder")
    with pytest.raises(ValueError) as info:
        op.Proxy.plan_with(op, values)
    assert text in str(info.value)
    assert groove_op.error_properties(info.value) == properties


def test_face_errors_point_at_the_base_geometry(doc):
    doc, shaft, job, tc = make_shop(doc, shape=Part.makeSphere(10))
    op = make_groove(job, (shaft, "Face1"), recompute=False)
    with pytest.raises(ValueError) as info:
        op.Proxy.plan(op)
    assert groove_op.error_properties(info.value) == ("Base",)


# -- warnings -------------------------------------------------------------------------


def test_a_recompute_reports_the_cycles_warnings_once(shop, monkeypatch):
    printed = []
    monkeypatch.setattr(FreeCAD.Console, "PrintWarning", printed.append)
    doc = shop[0]
    # width 4, the 3 mm r0.2 blade: room for it; base radii of the blade's own
    # radius, so that it reaches every corner (no unreachable-material warning)
    op = groove(shop, "cylinder", base_corner1=0.2, base_corner1_type="Radius", base_corner2=0.2,
                base_corner2_type="Radius")
    assert op_error(op) is None, op_error(op)
    assert not [m for m in printed if "CYCLE93" in m] and all(plan.warnings == [] for plan in op.Proxy.plan(op))
    op.FlankAllowance = 0.6  # 4 - 2 x 0.6 = 2.8 < 3: roughing runs on the final profile
    doc.recompute()
    assert op_error(op) is None, op_error(op)
    text = ("CYCLE93: the allowances FAL1=0 FAL2=0.6 leave no room for the 3 mm blade: FAL2 leaves a roughing base "
            "2.8 mm wide; roughing runs on the final profile, leaving nothing for the finishing pass")
    (plan,) = op.Proxy.current_plan(op)
    assert [m for m in printed if "CYCLE93" in m] == ["%s: %s: groove 1: %s\n" % (op.Label, plan.face.name, text)]
    assert [warning.text for warning in plan.warnings] == [text]
    assert plan.geometry.roughs_to_final


# The seed example, CYCLE93(35, 60, 30, 25, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0): a groove 30 wide and 25
# deep (radius) into a cone at ANGC 12 through X35 Z60 (radius), its +Z edge at Z60: the cone of a shaft from Z0
# to Z80, the groove's +Z edge at Position 20 from the face's +Z end.
TAN_12 = math.tan(math.radians(12))
SEED_CONE = [(0, 0), (35 - 60 * TAN_12, 0), (35 + 20 * TAN_12, 80), (0, 80), (0, 0)]
SEED_OP = dict(position=20, width=30, depth=25, flank_angle1=15, flank_angle2=16, base_corner1=2,
               base_corner1_type="Chamfer", base_corner2=2, base_corner2_type="Chamfer", base_allowance=1,
               flank_allowance=1, infeed=10, dwell=1)


def test_the_seed_example_op_reports_the_material_its_5_mm_blade_cannot_reach(doc, monkeypatch):
    # The oblique base runs down into the chamfer RCI2: a flat 5 mm blade rests on both and leaves the wedge
    # between (issue 9 item 2), which the user reads in the report view, with the op's and the face's names.
    printed = []
    monkeypatch.setattr(FreeCAD.Console, "PrintWarning", printed.append)
    doc, shaft, job, tc = make_shop(doc, shape=shaft_shape(SEED_CONE))
    cone = face_name(shaft.Shape, "cone", {"cone": lambda f: f.surface == "cone"})
    op = make_groove(job, (shaft, cone), tool_width=5, tool_corner_radius=0.4, **SEED_OP)
    assert op_error(op) is None, op_error(op)
    (plan,) = op.Proxy.current_plan(op)
    seed = Cycle93.parse("CYCLE93(35, 60, 30, 25, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0)")
    assert [getattr(plan.cycle, name) for name in ("axfa", "axsa", "widg", "depg", "angc", "rci1", "rci2", "typ")] \
        == pytest.approx([getattr(seed, name) for name in ("axfa", "axsa", "widg", "depg", "angc", "rci1", "rci2",
                                                            "typ")], abs=1e-9)
    wedge = "CYCLE93: 1.49 mm² up to 0.68 mm deep at base corner 2 cannot be reached by a 5 mm flat blade (r0.4)"
    assert "%s: %s: groove 1: %s\n" % (op.Label, plan.face.name, wedge) in printed
    assert [(warning.parameter, warning.text) for warning in plan.warnings if warning.parameter == "RCI2"] == [
        ("RCI2", wedge)]
