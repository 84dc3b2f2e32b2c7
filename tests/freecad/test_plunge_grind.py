"""The Plunge grind op inside FreeCAD (1.1 and 1.0; run by tests/freecad/run_suite.py).

A box 100 x 40 x 20 (X, Y, Z) at the origin: its top face (Face6, Z20) is
ground with a 10 mm wide wheel. The G83 words are worked out here by hand
from the face and the op's values; the Path's moves are compared with the
engine's own expansion of that call; shapely checks that the wheel's strokes
at the final depth cover the face and that no move goes below it.
"""

import FreeCAD
import Part
import Path
import Path.Main.Job as PathJob
import pytest
from pylib import require_shapely

from freecad_groove import make_plunge_grind
from freecad_groove.engine.cycles.ab_g83 import G83, G83_1
from freecad_groove.engine.moves import DRESS, FEED, MachineState
from freecad_groove.ops.grind.op import op_error

TOP = "Face6"  # Part.makeBox: Face5 z=0, Face6 z=height
WHEEL = 10.0
# the op's values (feeds in mm/min as quantity strings)
VALUES = dict(depth=0.1, start_clearance=0.05, plunge_pick=0.02, cross_pick=5, spark_out_passes=1,
              plunge_feed="60 mm/min", reciprocation_feed="6000 mm/min", wheel_width=WHEEL)
# By hand: reversals 5 mm (Overtravel) past the face's X ends 0 and 100: I-5 (the start) and X105;
# the crossover from the wheel flush with Y0 (its middle at Y5) to flush with Y40 (Z35); Y = the face Z20;
# the start 0.1 + 0.05 above it (Z20.15).
CALL = G83(X=105.0, I=-5.0, Y=20.0, J=0.02, Z=35.0, K=5.0, L=1, F=60.0, E=6000.0)
START = MachineState(x=-5.0, z=5.0, y=20.15, feed=60.0, diameter_mode=False)
WHEEL_RPM = 3000.0  # the Job's tool controller's SpindleSpeed


def make_box_job(size=(100, 40, 20)):
    doc = FreeCAD.newDocument("PlungeGrind")
    block = doc.addObject("Part::Feature", "Block")
    block.Shape = Part.makeBox(*size)
    doc.recompute()
    job = PathJob.Create("Job", [block])
    job.Tools.Group[0].SpindleSpeed = WHEEL_RPM  # the posts refuse a wheel that does not turn
    doc.recompute()
    return doc, block, job


@pytest.fixture
def shop():
    doc, block, job = make_box_job()
    yield doc, block, job
    FreeCAD.closeDocument(doc.Name)


def _moves_in_path(op):
    """(kind, x, y, z, feed mm/min or dress program) of the op's Path after the approach rapids."""
    out = []
    for command in op.Path.Commands:
        if command.Name == "G1":
            p = command.Parameters
            out.append((FEED, p["X"], p["Y"], p["Z"], round(p["F"] * 60, 9)))
        elif command.Name.startswith("(DRESS P"):
            out.append((DRESS, None, None, None, int(command.Name[len("(DRESS P"):-1])))
    return out


def _engine_moves(call, start):
    out = []
    last = None
    for move in call.expand(start):
        if move.kind == FEED:
            out.append((FEED, move.x, move.z, move.y, move.f))
        else:
            out.append((DRESS, None, None, None, move.p))
        last = move
    assert last is not None
    return out


def test_the_op_programs_the_hand_derived_g83(shop):
    doc, block, job = shop
    op = make_plunge_grind(job, (block, TOP), **VALUES)
    assert op_error(op) is None
    assert op.GrindCall == CALL.emit()
    assert op.Proxy.current_plan(op).start == START


def test_the_path_holds_the_engines_expansion_between_rapids_at_the_safe_height(shop):
    doc, block, job = shop
    op = make_plunge_grind(job, (block, TOP), **VALUES)
    assert _moves_in_path(op) == _engine_moves(CALL, START)
    commands = op.Path.Commands
    safe = max(job.Stock.Shape.BoundBox.ZMax, 20.0) + 5.0  # Retract 5 over the stock's top
    names = [c.Name for c in commands]
    assert names[:2] == ["(PlungeGrind)", "G17"]  # the base class's label comment first
    first_g1 = names.index("G1")
    assert [(c.Name, c.Parameters) for c in commands[first_g1 - 3:first_g1]] == [
        ("G0", {"Z": pytest.approx(safe)}), ("G0", {"X": -5.0, "Y": 5.0}), ("G0", {"Z": pytest.approx(20.15)})]
    assert (commands[-1].Name, commands[-1].Parameters) == ("G0", {"Z": pytest.approx(safe)})


def test_the_wheel_covers_the_face_at_the_final_depth_and_never_goes_below(shop):
    require_shapely()
    from shapely.geometry import box
    from shapely.ops import unary_union

    doc, block, job = shop
    op = make_plunge_grind(job, (block, TOP), **dict(VALUES, cross_pick=7, secondary_cross_pick=4))
    assert op_error(op) is None
    points = [(c.Parameters["X"], c.Parameters["Y"], c.Parameters["Z"]) for c in op.Path.Commands if c.Name == "G1"]
    assert min(z for _x, _y, z in points) == pytest.approx(20.0)
    strokes = []
    for (x0, y0, z0), (x1, y1, z1) in zip(points, points[1:]):
        if abs(z0 - 20.0) < 1e-9 and abs(z1 - 20.0) < 1e-9 and x0 != x1:
            assert y0 == y1  # a stroke reciprocates along X only
            strokes.append(box(min(x0, x1), y0 - WHEEL / 2, max(x0, x1), y0 + WHEEL / 2))
    assert box(0, 0, 100, 40).difference(unary_union(strokes)).area == 0.0


def test_dresses_and_g83_1_come_from_the_properties(shop):
    doc, block, job = shop
    op = make_plunge_grind(job, (block, TOP), **dict(VALUES, dress_program=12, dress_count=2, dress_first=True,
                                                     crossover_plunge_pick=0.03))
    call = G83_1(X=105.0, I=-5.0, Y=20.0, J=0.02, Z=35.0, K=5.0, Q=0.03, L=1, F=60.0, E=6000.0, P=12, D=2)
    assert op.GrindCall == call.emit()
    moves = _moves_in_path(op)
    assert moves == _engine_moves(call, START)
    assert moves[0] == (DRESS, None, None, None, 12) and sum(m[0] == DRESS for m in moves) == 3


def test_a_face_narrower_than_the_wheel_gets_no_crossover():
    doc, block, job = make_box_job((60, 8, 10))
    try:
        op = make_plunge_grind(job, (block, TOP), **VALUES)
        call = G83(X=65.0, I=-5.0, Y=10.0, J=0.02, Z=4.0, K=5.0, L=1, F=60.0, E=6000.0)
        assert op.GrindCall == call.emit()
        assert {c.Parameters["Y"] for c in op.Path.Commands if c.Name == "G1"} == {4.0}
    finally:
        FreeCAD.closeDocument(doc.Name)


@pytest.mark.parametrize("face, values, message", [
    ("Face1", {}, "Block.Face1: its normal (-1, 0, 0) is not +Z"),
    (TOP, dict(plunge_pick=0), "PlungePick=0: must be greater than 0"),
    (TOP, dict(depth=0), "Allowance=0: must be greater than 0"),
    (TOP, dict(cross_pick=12), "CrossPick=12: must be at most the wheel's width 10"),
    (TOP, dict(wheel_width=0), "WheelWidth: the wheel's width is unknown"),
    (TOP, dict(spark_out_passes=1000), "SparkOutPasses: G83 L=1000: must be a whole number from 0 to 999"),
    (TOP, dict(dress_count=2), "DressProgram: G83 P: must be programmed (D=2 dresses"),
    (TOP, dict(dress_program=10000), "DressProgram: G83 P=10000: must be a program number from 1 to 9999"),
    (TOP, dict(plunge_feed=0), "PlungeFeed=0: no feed (the tool controller's VertFeed is 0.0): set PlungeFeed"),
    (TOP, dict(reciprocation_feed=-1), "ReciprocationFeed=-60 mm/min: must be 0 <= ReciprocationFeed < 100000 "
     "mm/min"),
    (TOP, dict(overtravel=1e308), "Overtravel=1e+308 mm: must be 0 <= Overtravel < 100000 mm"),
])
def test_bad_inputs_give_one_line_naming_the_property(shop, face, values, message):
    doc, block, job = shop
    op = make_plunge_grind(job, (block, face), **dict(VALUES, **values))
    error = op_error(op)
    assert error is not None and error.startswith(message), error
    assert "\n" not in error
    assert [c.Name for c in op.Path.Commands if c.Name in ("G0", "G1")] == []


# ---------------------------------------------------------------- the grinder posts

import importlib.util  # noqa: E402
import os  # noqa: E402

from freecad_groove.engine.grind_program import GrindItem, PlainMoves, WheelChange, grind_program  # noqa: E402
from freecad_groove.engine.moves import RAPID, Move  # noqa: E402
from freecad_groove.freecad.posts.post_error import PostError  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def post_module(name):
    """postprocessors/<name>_post.py, loaded from its file as FreeCAD loads a script post."""
    spec = importlib.util.spec_from_file_location(name + "_post", os.path.join(ROOT, "postprocessors",
                                                                               name + "_post.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _wheel(job):
    """The wheel of the Job's tool controller (tool 1 at WHEEL_RPM, clockwise)."""
    tc = job.Tools.Group[0]
    return WheelChange(tc.Label, 1, WHEEL_RPM, True)


def _expected(call, job, target, native, extra=()):
    item = GrindItem("PlungeGrind: Block.Face6", call, START, max(job.Stock.Shape.BoundBox.ZMax, 20.0) + 5.0,
                     call.expand(START))
    return grind_program([_wheel(job), item, *extra], target, native, "Job")


def test_the_ab9_grind_post_writes_the_op_as_its_g83_block_or_expanded(shop):
    doc, block, job = shop
    op = make_plunge_grind(job, (block, TOP), **VALUES)
    post = post_module("ab9_grind")
    native = post.export([job], "-", "")
    assert native == _expected(CALL, job, "ab9grind", True)
    op.CoolantMode = "Flood"
    lines = post.export([job], "-", "").splitlines()
    assert lines[8] == "M08" and lines[-3:] == ["M09", "M05", "M30"]  # after the tool change, spindle, comment
    op.CoolantMode = "None"
    assert "G83 X105. I-5. Y20. J0.02 Z35. K5. L1 F60. E6000." in native.splitlines()
    assert post.export([job], "-", "--expand-cycles") == _expected(CALL, job, "ab9grind", False)


def test_the_linuxcnc_grind_post_expands_dresses_and_writes_other_paths_as_they_are(shop):
    doc, block, job = shop
    make_plunge_grind(job, (block, TOP), **dict(VALUES, dress_program=12, dress_count=2, dress_first=True))
    custom = doc.addObject("Path::Feature", "Custom")
    custom.Path = Path.Path([Path.Command("G0", {"X": 1, "Y": 2, "Z": 30}), Path.Command("G1", {"X": 4, "F": 2})])
    doc.recompute()
    call = G83_1(X=105.0, I=-5.0, Y=20.0, J=0.02, Z=35.0, K=5.0, L=1, F=60.0, E=6000.0, P=12, D=2)
    plain = PlainMoves("Custom", [Move(RAPID, 1.0, 2.0, y=30.0), Move(FEED, 4.0, 2.0, 120.0, y=30.0)])
    text = post_module("linuxcnc_grind").export([job, custom], "-", "")
    assert text == _expected(call, job, "linuxcnc", False, [plain])
    assert text.count("o<dress12> call") == 3
    with pytest.raises(PostError, match=r"a dress \(P12\) cannot be written expanded for the 9/Series"):
        post_module("ab9_grind").export([job], "-", "--expand-cycles")


def test_the_grind_posts_refuse_an_op_that_cannot_grind_and_commands_they_cannot_write(shop):
    doc, block, job = shop
    op = make_plunge_grind(job, (block, TOP), **dict(VALUES, plunge_pick=0))
    with pytest.raises(PostError, match="^PlungeGrind: PlungePick=0: must be greater than 0$"):
        post_module("ab9_grind").export([job], "-", "")
    op.PlungePick = 0.02
    arc = doc.addObject("Path::Feature", "Arc")
    arc.Path = Path.Path([Path.Command("G2", {"X": 1, "Y": 2, "Z": 3, "I": 1})])
    doc.recompute()
    with pytest.raises(PostError, match=r"^Arc: G2 \(command 1\) cannot be written by a grinder post"):
        post_module("ab9_grind").export([job, arc], "-", "")


def test_the_posts_start_the_wheel_from_the_tool_controller_and_refuse_a_still_wheel(shop):
    doc, block, job = shop
    op = make_plunge_grind(job, (block, TOP), **VALUES)
    tc = op.ToolController
    lines = post_module("ab9_grind").export([job], "-", "").splitlines()
    assert lines[4:7] == ["(tool 1: %s)" % tc.Label, "T01 M06", "S3000 M03"] and lines[-2:] == ["M05", "M30"]
    tc.SpindleDir = "Reverse"
    tc.ToolNumber = 7
    lines = post_module("linuxcnc_grind").export([job], "-", "").splitlines()
    assert lines[2:5] == ["(tool 7: %s)" % tc.Label, "T7 M6 G43", "S3000 M4"] and lines[-2:] == ["M5", "M2"]
    tc.SpindleSpeed = 0
    with pytest.raises(PostError, match=r"^PlungeGrind: the wheel does not turn: %s has SpindleSpeed 0, SpindleDir "
                                        r"Reverse \(set a speed above 0, Forward or Reverse\)$" % tc.Label):
        post_module("ab9_grind").export([job], "-", "")
    tc.SpindleSpeed, tc.SpindleDir = 3000, "None"
    with pytest.raises(PostError, match="^PlungeGrind: the wheel does not turn: .* SpindleDir None"):
        post_module("linuxcnc_grind").export([job], "-", "")


def test_a_wall_within_the_overtravel_is_refused_and_none_without_overtravel():
    doc = FreeCAD.newDocument("PlungeWall")
    try:
        block = doc.addObject("Part::Feature", "Stepped")
        # the 100 x 40 face at Z20, a wall X100..110 up to Z30 right at its +X end
        block.Shape = Part.makeBox(100, 40, 20).fuse(Part.makeBox(10, 40, 30, FreeCAD.Vector(100, 0, 0)))
        doc.recompute()
        job = PathJob.Create("Job", [block])
        doc.recompute()
        top = next("Face%d" % (i + 1) for i, f in enumerate(block.Shape.Faces)
                   if abs(f.BoundBox.ZMin - 20) < 1e-9 and abs(f.BoundBox.ZMax - 20) < 1e-9)
        op = make_plunge_grind(job, (block, top), **VALUES)
        assert op_error(op).startswith("Base: the wheel's path over Stepped.%s (X-5..105, Y0..40) meets "
                                       "Stepped above the face" % top)
        op.Overtravel = 0
        doc.recompute()
        assert op_error(op) is None and op.GrindCall.startswith("G83 X100. I0. Y20.")
    finally:
        FreeCAD.closeDocument(doc.Name)


# ---------------------------------------------------------------- the grinding wheel tool bit

from freecad_groove.freecad import wheel_toolbit  # noqa: E402


def _stepped_job(name):
    """The 100 x 40 face at Z20 in a step: beyond its +X end a 12 mm gap down to Z10, then a wall X112..122 up
    to Z30; along its +Y edge a wall Y40..50 up to Z30, flush with the wheel's side at the end of the crossover."""
    doc = FreeCAD.newDocument(name)
    block = doc.addObject("Part::Feature", "Stepped")
    block.Shape = Part.makeBox(100, 40, 20).fuse([
        Part.makeBox(22, 40, 10, FreeCAD.Vector(100, 0, 0)), Part.makeBox(10, 40, 30, FreeCAD.Vector(112, 0, 0)),
        Part.makeBox(100, 10, 30, FreeCAD.Vector(0, 40, 0))])
    doc.recompute()
    job = PathJob.Create("Job", [block])
    doc.recompute()
    top = next("Face%d" % (i + 1) for i, f in enumerate(block.Shape.Faces)
               if abs(f.BoundBox.ZMin - 20) < 1e-9 and abs(f.BoundBox.ZMax - 20) < 1e-9)
    return doc, block, job, top


@pytest.mark.parametrize("diameter, overtravel, refused", [
    (200, 5, True),  # at the reversal X105 the 100 mm radius reaches X112 0.25 mm above the face
    (16, 5, True),  # reaches X113 at 8 mm above the face, below the wall's top (10 mm above)
    (16, 0, False),  # from X100: X108
    (10, 5, False),  # from X105: X110, 2 mm short of the wall
])
def test_the_wheel_body_is_checked_against_a_wall_beside_the_face(diameter, overtravel, refused):
    doc, block, job, top = _stepped_job("PlungeBody")
    try:
        op = make_plunge_grind(job, (block, top), **dict(VALUES, wheel_diameter=diameter, overtravel=overtravel))
        if refused:
            assert op_error(op) == (
                "Base: the wheel's body (diameter %g) meets Stepped beside Stepped.%s: a wall within the wheel's "
                "radius of a reversal point (reduce Overtravel, grind with a smaller wheel, or grind another face)"
                % (diameter, top))
            assert op.GrindCall == "" and not [c for c in op.Path.Commands if c.Name in ("G0", "G1")]
        else:  # the lowest point alone passes in every case; the +Y wall touches the wheel's side only
            assert op_error(op) is None and op.Proxy.current_plan(op).warnings == []
    finally:
        FreeCAD.closeDocument(doc.Name)


def test_a_wheel_of_unknown_diameter_grinds_with_a_warning_and_the_wheel_bit_gives_its_diameter():
    doc, block, job, top = _stepped_job("PlungeBodyUnknown")
    try:
        op = make_plunge_grind(job, (block, top), **VALUES)  # the Job's end mill: no Width, WheelDiameter 0
        assert op_error(op) is None
        assert op.Proxy.current_plan(op).warnings == [
            "WheelDiameter: the wheel's diameter is unknown (the tool bit has no Width: not a grinding wheel bit; "
            "WheelDiameter is 0): its body above the lowest point is not checked against the part"]
        op.ToolController = wheel_toolbit.make_wheel_tool_controller(job, width=10, diameter=200)
        doc.recompute()
        assert op_error(op).startswith("Base: the wheel's body (diameter 200) meets Stepped")
    finally:
        FreeCAD.closeDocument(doc.Name)


def test_the_wheel_tool_bit_gives_the_op_its_width_and_survives_save_and_reopen(tmp_path):
    doc, block, job = make_box_job()
    tc = wheel_toolbit.make_wheel_tool_controller(job, width=10, diameter=200)
    bit = tc.Tool
    assert (bit.Width.Value, bit.Diameter.Value) == (10.0, 200.0)
    if wheel_toolbit.NEW_TOOLBITS:
        assert type(bit.Proxy).__name__ == "ToolBitGrindingWheel"
    values = {k: v for k, v in VALUES.items() if k != "wheel_width"}
    op = make_plunge_grind(job, (block, TOP), tool_controller=tc, **values)
    assert op_error(op) is None and op.GrindCall == CALL.emit()  # K5 .. Z35: the 10 mm wheel
    path, name = str(tmp_path / "wheel.FCStd"), op.Name
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        op = reopened.getObject(name)
        assert type(op.Proxy).__name__ == "ObjectPlungeGrind"
        op.touch()
        reopened.recompute()
        assert op_error(op) is None and op.GrindCall == CALL.emit()
        assert op.ToolController.Tool.Width.Value == 10.0
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_a_wheel_without_size_is_refused_in_one_line(shop):
    doc, block, job = shop
    with pytest.raises(ValueError, match=r"^make_wheel_bit\(\): width=0: must be greater than 0$"):
        wheel_toolbit.make_wheel_bit(doc, 0, 200)


def test_cam_post_process_writes_the_program_or_reports_a_failed_post_in_one_line(shop, console):
    from Path.Post.Processor import PostProcessorFactory

    doc, block, job = shop
    op = make_plunge_grind(job, (block, TOP), **VALUES)
    job.PostProcessor = "ab9_grind"
    found = PostProcessorFactory.get_post_processor(job, "ab9_grind")
    assert type(found).__name__ == "Ab9_Grind"
    ((_part, text),) = found.export()
    assert text == _expected(CALL, job, "ab9grind", True)
    op.PlungePick = 0
    doc.recompute()
    del console["PrintError"][:]
    assert found.export() is None  # CAM_Post: no file, no traceback
    assert console["PrintError"] == ["ab9_grind_post: PlungeGrind: PlungePick=0: must be greater than 0 "
                                     "(no file written)\n"]
    job.PostProcessorArgs = "--help"
    assert found.export() is None and "--expand-cycles" in "".join(console["PrintMessage"])


@pytest.mark.parametrize("face, values, error, message", [
    ((None, TOP), {}, ValueError, r"^make_plunge_grind\(\): faces: None is not a FreeCAD object"),
    (("block", "Face99"), {}, ValueError, r"^make_plunge_grind\(\): Block has no Face99$"),
    (("block", ["Face5", "Face6"]), {}, ValueError, r"^make_plunge_grind\(\): face=.*: give one \(part, \"FaceN\"\)$"),
    (("block", TOP), {"plunge_pik": 1}, TypeError, r"^make_plunge_grind\(\) got unknown keyword\(s\) plunge_pik;"),
])
def test_make_plunge_grind_refuses_bad_arguments_leaving_nothing_behind(shop, face, values, error, message):
    doc, block, job = shop
    before = {o.Name for o in doc.Objects}
    face = tuple(block if part == "block" else part for part in face[:1]) + face[1:]
    with pytest.raises(error, match=message):
        make_plunge_grind(job, face, **values)
    assert {o.Name for o in doc.Objects} == before


def test_reciprocation_along_y_and_the_posts_axes():
    doc, block, job = make_box_job((40, 100, 20))  # the face's length along Y
    try:
        op = make_plunge_grind(job, (block, TOP), reciprocation_axis="Y", **VALUES)
        assert op_error(op) is None and op.GrindCall == CALL.emit()  # the same call: the face turned by 90 degrees
        g1 = [c.Parameters for c in op.Path.Commands if c.Name == "G1"]
        assert [(p["Y"], p["X"], p["Z"]) for p in g1] == [(m.x, m.z, m.y) for m in CALL.expand(START)]
        post = post_module("ab9_grind")
        with pytest.raises(PostError, match=r"^PlungeGrind: ReciprocationAxis=Y grinds with the grinder's X, Y, Z "
                                            r"along FreeCAD YZX, the post's --axes is XZY"):
            post.export([job], "-", "")
        safe = max(job.Stock.Shape.BoundBox.ZMax, 20.0) + 5.0
        item = GrindItem("PlungeGrind: Block.Face6", CALL, START, safe, CALL.expand(START))
        custom = doc.addObject("Path::Feature", "Custom")
        custom.Path = Path.Path([Path.Command("G0", {"X": 1, "Y": 2, "Z": 30})])
        doc.recompute()
        plain = PlainMoves("Custom", [Move(RAPID, 2.0, 1.0, y=30.0)])  # grinder X = FreeCAD Y, Z = FreeCAD X
        assert post.export([op, custom], "-", "--axes YZX") == grind_program([_wheel(job), item, plain], "ab9grind",
                                                                              True, "Job")
    finally:
        FreeCAD.closeDocument(doc.Name)


# ---------------------------------------------------------------- the wheel in FreeCAD 1.1's shape chooser

from freecad_groove.freecad import shape_assets  # noqa: E402


@pytest.mark.skipif(not shape_assets.AVAILABLE, reason="FreeCAD 1.0 has no tool bit shape chooser: wheels come "
                    "from make_wheel_tool_controller")
def test_the_shape_chooser_lists_the_grinding_wheel_and_a_bit_from_it_grinds(shop):
    import Path.Tool.Controller as PathToolController
    from Path.Tool.shape import ToolBitShapeSvgIcon
    from test_toolbit import _bit_from_the_chooser, _chooser_shapes

    doc, block, job = shop
    assert shape_assets.installed(), "Init.py registered the shapes when CAM imported Path.Tool"
    shapes = _chooser_shapes()
    shape = shapes[shape_assets.WHEEL_SHAPE_ID]
    assert "endmill" in shapes and shape_assets.SHAPE_ID in shapes  # FreeCAD's and the grooving blade too
    assert isinstance(shape, wheel_toolbit.ToolBitShapeGrindingWheel) and shape.label == "Grinding wheel"
    assert shape.is_builtin
    params = shape.get_parameters()
    assert (params["Diameter"].Value, params["Width"].Value) == (pytest.approx(200), pytest.approx(20))
    icon = shape.get_icon()  # what the chooser's button draws
    assert isinstance(icon, ToolBitShapeSvgIcon) and icon.abbreviations == {"Diameter": "D", "Width": "W"}
    asset = _bit_from_the_chooser(shape)
    assert isinstance(asset, wheel_toolbit.ToolBitGrindingWheel)
    bit = asset.attach_to_doc(doc)  # the tool library's "Add to Job", then the user's values
    bit.Width, bit.Diameter = 10, 150
    tc = PathToolController.Create("TC: " + asset.label, bit, 5)
    tc.SpindleSpeed = WHEEL_RPM
    job.Proxy.addToolController(tc)
    op = make_plunge_grind(job, (block, TOP), tool_controller=tc, **{k: v for k, v in VALUES.items()
                                                                     if k != "wheel_width"})
    assert op_error(op) is None, op_error(op)
    assert op.GrindCall == CALL.emit()  # the wheel's width 10 from the bit
    assert op.Proxy.current_plan(op).warnings == []  # its diameter known: the body checked
    assert "T05 M06" in post_module("ab9_grind").export([job], "-", "").splitlines()
