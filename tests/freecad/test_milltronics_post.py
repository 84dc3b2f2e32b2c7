"""The milltronics_mill post inside FreeCAD (1.1 and 1.0; run by tests/freecad/run_suite.py).

A block 100 x 60 x 20 (X, Y, Z) at the origin with a pocket 40 x 20 x 5
(X30..70, Y20..40, floor Z15) and a round pocket (diameter 12 at X15 Y30,
floor Z15); the Job's stock is 1 mm above the block, its tool a 5 mm end
mill. CAM's Face op on the top and Pocket Shape op on the rectangular floor
are posted as G33/G34: the blocks are read back with the engine's parser and
compared with words worked out here by hand from the ops; the engine's
expansion of each call sweeps (shapely) what the op's own Path sweeps, to
within the stepover's scallop; ops the cycles cannot reproduce are written
as moves with the reason.
"""

import importlib.util
import math
import os

import FreeCAD
import Part
import Path.Main.Job as PathJob
import Path.Op.MillFace as MillFace
import Path.Op.PocketShape as PocketShape
import pytest
from pylib import require_shapely

from freecad_groove.engine.cycles.milltronics import G33, G34
from freecad_groove.engine.mill_tool_table import MillToolTable
from freecad_groove.engine.moves import ARC_CCW, ARC_CW, FEED, MachineState
from freecad_groove.engine.settings import Settings
from freecad_groove.engine.translator import translate_program
from freecad_groove.freecad.posts.milltronics_ops import NativeOp, recognise
from freecad_groove.freecad.posts.post_error import PostError

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TOOL = 5.0
# By hand from the ops: the Face op from the stock top 21 (StepDown 0.5: 20.5, 20) over the top 100 x 60 centred at
# X50 Y30; the Pocket from 21 (StepDown 2: 19, 17, 15) over the floor 40 x 20 centred at X50 Y30; R = SafeHeight 24,
# P155 = StepOver 50 % x 5 mm, F = VertFeed 5 mm/s = 300 mm/min (the X-Y feed HorizFeed 10 mm/s = 600 mm/min).
# FreeCAD 1.0's Face op never cuts its last depth (its Path stops at 20.5): the G33 cuts what the Path cuts, and says so
FACE_FLOOR = 20.5 if FreeCAD.Version()[:2] == ["1", "0"] else 20.0
FACE_TITLE = "(Face: G33" + ("; Z is the lowest level the op's Path cuts, 20.5, not its FinalDepth 20)"
                             if FACE_FLOOR == 20.5 else ")")
FACING = G33(R=24.0, Z=FACE_FLOOR, V=20.5, Q=0.5, F=300.0, G99=True, compensation="G41", P151=100.0, P152=60.0,
             P155=2.5)
POCKET = G34(R=24.0, Z=15.0, V=19.0, Q=2.0, F=300.0, G99=True, compensation="G41", P150=0.0, P151=40.0, P152=20.0,
             P153=0.0, P154=0.0, P155=2.5)
PATTERN = "ClearingPattern" if FreeCAD.Version()[:2] != ["1", "0"] else "OffsetPattern"  # 1.1 renamed it
RAPID_Z = 1e9  # a rapid's point in the swept lists: it cuts nothing
START = MachineState(x=50.0, y=30.0, z=26.0, feed=600.0, metric=True, diameter_mode=False)


def post_module():
    spec = importlib.util.spec_from_file_location("milltronics_mill_post",
                                                  os.path.join(ROOT, "postprocessors", "milltronics_mill_post.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _floor_face(shape, z, x_range):
    for index, face in enumerate(shape.Faces):
        box = face.BoundBox
        if abs(box.ZMin - z) < 1e-6 and abs(box.ZMax - z) < 1e-6 and x_range[0] <= box.Center.x <= x_range[1]:
            return "Face%d" % (index + 1)
    raise AssertionError("no face at Z%g" % z)


def make_shop(corner=0.0, turned=0.0):
    """The block, its Job and the two ops; ``corner``: the pocket's corner radius, ``turned``: degrees it is
    turned about Z."""
    doc = FreeCAD.newDocument("Milltronics")
    pocket = Part.makeBox(40, 20, 5, FreeCAD.Vector(30, 20, 15))
    if corner:
        pocket = pocket.makeFillet(corner, [e for e in pocket.Edges if abs(e.BoundBox.ZLength - 5) < 1e-6])
    pocket.rotate(FreeCAD.Vector(50, 30, 15), FreeCAD.Vector(0, 0, 1), turned)
    round_pocket = Part.makeCylinder(6, 5, FreeCAD.Vector(15, 30, 15))
    block = doc.addObject("Part::Feature", "Block")
    block.Shape = Part.makeBox(100, 60, 20).cut(pocket).cut(round_pocket)
    doc.recompute()
    job = PathJob.Create("Job", [block])
    doc.recompute()
    model = job.Model.Group[0]
    controller = job.Tools.Group[0]
    controller.HorizFeed, controller.VertFeed, controller.SpindleSpeed = 10.0, 5.0, 3000.0
    face = MillFace.Create("Face")
    face.Base = [(model, [_floor_face(model.Shape, 20.0, (0, 100))])]
    face.ZigZagAngle = 0.0
    pocket_op = PocketShape.Create("Pocket")
    pocket_op.Base = [(model, [_floor_face(model.Shape, 15.0, (25, 75))])]
    setattr(pocket_op, PATTERN, "Offset")  # 1.1's default; 1.0's is ZigZag
    pocket_op.StepOver = 50  # 1.1's default; 1.0's is 100
    for op, step in ((face, 0.5), (pocket_op, 2.0)):
        op.setExpression("StepDown", None)  # CAM's default: the tool's diameter
        op.StepDown = step
    doc.recompute()
    return doc, job, face, pocket_op, model


@pytest.fixture
def shop():
    doc, job, face, pocket, model = make_shop()
    yield doc, job, face, pocket, model
    FreeCAD.closeDocument(doc.Name)


def _section(lines, title):
    """The P blocks and the call after the comment ``title``, and the 3 lines that position the tool."""
    at = lines.index(title)
    end = lines.index("G31", at)
    return lines[at + 1:at + 4], "\n".join(lines[at + 4:end])


def test_the_face_and_pocket_ops_post_as_g33_and_g34_with_the_ops_values(shop):
    doc, job, face, pocket, model = shop
    text = post_module().export([job], "-", "")
    lines = text.splitlines()
    assert lines[:7] == ["(Job: milltronics_mill_post of freecad-groove)", "G21 G90 G40", "G32", "T1 M6",
                         "S3000 M3", "D1 G43 H1", FACE_TITLE]
    position, block = _section(lines, FACE_TITLE)
    assert position == ["G0 Z26.", "G0 X50. Y30.", "F600."]
    assert G33.parse(block) == FACING
    position, block = _section(lines, "(Pocket: G34)")
    assert position == ["G0 Z26.", "G0 X50. Y30.", "F600."]
    assert G34.parse(block) == POCKET
    assert lines[-2:] == ["M5", "M30"] and "moves" not in text
    assert "G33 G99 G41 R24. Z%s V20.5 Q0.5 F300." % ("20.5" if FACE_FLOOR == 20.5 else "20.") in lines


def _swept(moves, radius):
    """{depth: the area the tool sweeps feeding across X-Y at that depth}, moves as (x, y, z) points."""
    from shapely.geometry import LineString, Point
    from shapely.ops import unary_union

    areas = {}
    for (x0, y0, z0), (x1, y1, z1) in zip(moves, moves[1:]):
        if z1 >= RAPID_Z:
            continue
        if abs(z0 - z1) < 1e-6 and (abs(x0 - x1) > 1e-9 or abs(y0 - y1) > 1e-9):
            piece = LineString([(x0, y0), (x1, y1)]).buffer(radius, 32)
            areas.setdefault(round(z0, 3), []).append(piece)
        elif z1 < z0:
            areas.setdefault(round(z1, 3), []).append(Point(x1, y1).buffer(radius, 32))
    return {z: unary_union(pieces) for z, pieces in areas.items()}


def _arc_points(start, end, params, clockwise):
    """Points along an arc of the X-Y plane (I, J from its start), 1 degree apart."""
    cx, cy = start[0] + params.get("I", 0.0), start[1] + params.get("J", 0.0)
    a0 = math.atan2(start[1] - cy, start[0] - cx)
    a1 = math.atan2(end[1] - cy, end[0] - cx)
    sweep = (a1 - a0) % (2 * math.pi)
    if clockwise:
        sweep -= 2 * math.pi
    if abs(sweep) < 1e-12:
        sweep = -2 * math.pi if clockwise else 2 * math.pi
    radius = math.hypot(start[0] - cx, start[1] - cy)
    count = max(2, int(abs(math.degrees(sweep))))
    return [(cx + radius * math.cos(a0 + sweep * k / count), cy + radius * math.sin(a0 + sweep * k / count),
             start[2] + (end[2] - start[2]) * k / count) for k in range(1, count + 1)]


def _path_points(op):
    """The op's Path as (x, y, z) points, arcs in short chords, a rapid's point at RAPID_Z."""
    where = {"X": None, "Y": None, "Z": None}
    points = []
    for command in op.Path.Commands:
        before = (where["X"], where["Y"], where["Z"])
        where.update({a: command.Parameters[a] for a in "XYZ" if a in command.Parameters})
        if None in where.values():
            continue
        end = (where["X"], where["Y"], where["Z"])
        if command.Name in ("G2", "G3"):
            points += _arc_points(before, end, command.Parameters, command.Name == "G2")
        elif command.Name == "G1":
            points.append(end)
        elif command.Name == "G0":
            points.append((where["X"], where["Y"], RAPID_Z))
    return points


def _engine_points(moves):
    """The engine's moves as (x, y, z) points like _path_points: arcs (G2, G3 about their centres) in
    short chords, a rapid's point at RAPID_Z."""
    points, here = [], (START.x, START.y, START.z)
    for m in moves:
        end = (m.x, m.y, m.z)
        if m.kind in (ARC_CW, ARC_CCW):
            offsets = {"I": m.centre[0] - here[0], "J": m.centre[1] - here[1]}
            points += _arc_points(here, end, offsets, m.kind == ARC_CW)
        else:
            points.append(end if m.kind == FEED else (m.x, m.y, RAPID_Z))
        here = end
    return points


@pytest.mark.parametrize("corner", [0.0, 4.0])
def test_the_cycles_sweep_what_the_ops_own_paths_sweep(corner):
    require_shapely()
    from shapely.geometry import box

    doc, job, face, pocket, model = make_shop(corner)
    try:
        lines = post_module().export([job], "-", "").splitlines()
        calls = [G33.parse(_section(lines, FACE_TITLE)[1]), G34.parse(_section(lines, "(Pocket: G34)")[1])]
        assert calls[1].P150 == corner
        outlines = [box(0, 0, 100, 60), box(30, 20, 70, 40)]
        if corner:
            outlines[1] = box(30 + corner, 20 + corner, 70 - corner, 40 - corner).buffer(corner, 64)
        for op, call, outline in zip((face, pocket), calls, outlines):
            engine = _engine_points(call.expand(START, Settings(mill_tool_diameter=TOOL)))
            cycle, own = _swept(engine, TOOL / 2), _swept(_path_points(op), TOOL / 2)
            assert sorted(cycle) == sorted(own), op.Label
            for depth in cycle:
                # the same area within the scallop; both inside the outline; the outline cleared
                assert cycle[depth].symmetric_difference(own[depth]).area < 0.001 * outline.area, (op.Label, depth)
                assert cycle[depth].difference(outline.buffer(1e-3)).area < 1e-6
                reachable = outline.buffer(-TOOL / 2, 64).buffer(TOOL / 2, 64)  # a sharp corner keeps its radius
                assert reachable.difference(cycle[depth]).area < 0.002 * outline.area
    finally:
        FreeCAD.closeDocument(doc.Name)


def test_ops_the_cycles_cannot_reproduce_are_written_as_moves_with_the_reason(shop):
    doc, job, face, pocket, model = shop
    face.ZigZagAngle = 45.0
    pocket.FinishDepth = 0.5
    round_pocket = PocketShape.Create("RoundPocket")
    round_pocket.Base = [(model, [_floor_face(model.Shape, 15.0, (0, 30))])]
    doc.recompute()
    lines = post_module().export([job], "-", "").splitlines()
    assert ("(Face written as moves: the op clears ZigZag at 45 degrees: G33 goes back and forth along the long "
            "side [%s ZigZag, ZigZagAngle 0])" % PATTERN) in lines
    assert any(line.startswith("(Pocket written as moves: the op's Path cuts at Z 19, 17, 15.5, 15, the cycle")
               for line in lines)
    assert "(RoundPocket written as moves: the area is not a rectangle: an edge is a Circle)" in lines
    assert not any(line.startswith(("G33", "G34", "G31")) for line in lines)
    face.ZigZagAngle = 0.0
    pocket.FinishDepth = 0.0
    doc.recompute()
    assert isinstance(recognise(face, False), NativeOp) and isinstance(recognise(pocket, False), NativeOp)


TABLE = MillToolTable([(1, TOOL)], "the Job's tools")


def test_expand_cycles_writes_the_ops_paths_which_the_engine_reads_back(shop):
    doc, job, face, pocket, model = shop
    text = post_module().export([job], "-", "--expand-cycles")
    lines = text.splitlines()
    assert "(Face written as moves: --expand-cycles)" in lines and "(Pocket written as moves: --expand-cycles)" in lines
    assert not any(line.startswith(("G33", "G34", "P15")) for line in lines)
    out = translate_program(text, "milltronics", Settings(), target="linuxcnc", tools=TABLE).splitlines()
    feeds = [line for line in out if line.startswith("G1")]
    assert len(feeds) > 10
    # read back as written: the G32 at the start (Z alone), the tool change and the length offset
    assert out[4:8] == ["(G32: Z101.6, setting milltronics_tool_change_inch)", "G0 Z101.6", "T1 M6", "S3000 M3"]
    assert "G43 H1 (D1: the diameter register of the G33/G34 that follow)" in out


def test_native_program_read_back_by_the_engine_is_the_cycles_expansion(shop):
    doc, job, face, pocket, model = shop
    text = post_module().export([job], "-", "")
    out = translate_program(text, "milltronics", Settings(), target="linuxcnc", tools=TABLE)
    out_lines = out.splitlines()
    for call in (FACING, POCKET):
        assert "(%s: tool diameter 5.0, D1 of the Job's tools)" % call.emit().split("\n")[-1] in out_lines
    assert out_lines.count("(G31: Z24., the last R)") == 2


def test_inch_output_and_option_errors(shop):
    doc, job, face, pocket, model = shop
    lines = post_module().export([job], "-", "--inches").splitlines()
    assert lines[1] == "G20 G90 G40"
    position, block = _section(lines, FACE_TITLE)
    assert position == ["G0 Z1.0236", "G0 X1.9685 Y1.1811", "F23.622"]
    call = G33.parse(block)
    assert (call.P151, call.P152, call.P155, call.R, call.Z, call.V, call.Q) == (
        3.937, 2.3622, 0.0984, 0.9449, round(FACE_FLOOR / 25.4, 4), 0.8071, 0.0197)
    with pytest.raises(PostError, match="^milltronics_mill_post: unrecognized arguments: --bogus$"):
        post_module().export([job], "-", "--bogus")


def test_a_path_command_the_post_cannot_write_is_refused_naming_the_op(shop, tmp_path):
    doc, job, face, pocket, model = shop
    import Path

    drill = doc.addObject("Path::Feature", "Drill")
    drill.Path = Path.Path([Path.Command("G81", {"X": 1, "Y": 2, "Z": -3, "R": 1})])
    doc.recompute()
    target = tmp_path / "out.nc"
    with pytest.raises(PostError, match=r"^Drill: G81 \(command 1\) cannot be written by milltronics_mill_post"):
        post_module().export([job, drill], str(target), "")
    assert not target.exists()


def test_cam_post_process_writes_the_program_or_reports_a_failed_post_in_one_line(shop, console):
    from Path.Post.Processor import PostProcessorFactory

    doc, job, face, pocket, model = shop
    job.PostProcessor = "milltronics_mill"
    found = PostProcessorFactory.get_post_processor(job, "milltronics_mill")
    assert type(found).__name__ == "Milltronics_Mill"
    ((_part, text),) = found.export()
    assert text == post_module().export([job], "-", "")
    job.PostProcessorArgs = "--bogus"
    assert found.export() is None  # CAM_Post: no file, no traceback
    assert console["PrintError"] == ["milltronics_mill_post: unrecognized arguments: --bogus (no file written)\n"]
    job.PostProcessorArgs = "--help"
    assert found.export() is None and "--expand-cycles" in "".join(console["PrintMessage"])


def _set(obj, **values):
    for name, value in values.items():
        if name in obj.PropertiesList and obj.getTypeIdOfProperty(name) == "App::PropertyEnumeration":
            setattr(obj, name, str(value))
        else:
            setattr(obj, name, value)


@pytest.mark.parametrize("op_name, values, controller, reason", [
    ("Face", dict(UseStartPoint=True), {}, "UseStartPoint is set: the cycle starts at the upper right corner"),
    ("Face", dict(ExtraOffset=1.0), {}, "ExtraOffset is not 0: the cycle cuts to the area's edges"),
    ("Pocket", dict(StartAt="Edge"), {}, "the op clears Offset from the edge: G34 laps from the centre outward "
                                         "[%s Offset, StartAt Center]" % PATTERN),
    ("Pocket", {}, dict(SpindleDir="Reverse"), "the spindle turns Reverse: G41 climbs and G42 cuts conventional "
                                               "with M3"),
    ("Face", {}, dict(HorizFeed=0.0), "the tool controller's HorizFeed is 0: the cycle needs its feed"),
    ("Pocket", {}, dict(VertFeed=0.0), "the tool controller's VertFeed is 0: the cycle needs its feed"),
])
def test_each_reason_to_write_an_op_as_moves(shop, op_name, values, controller, reason):
    doc, job, face, pocket, model = shop
    op = face if op_name == "Face" else pocket
    _set(op, **values)
    _set(op.ToolController, **controller)
    doc.recompute()
    lines = post_module().export([job], "-", "").splitlines()
    assert "(%s written as moves: %s)" % (op_name, reason) in lines


@pytest.mark.parametrize("corner, turned, reason", [
    (2.0, 0.0, "G34 P150=2: the corner radius is smaller than the tool radius 2.5 [0 cuts the corners at the "
               "tool radius]"),
    (0.0, 10.0, "an edge of the area is not along X or Y"),
])
def test_a_pocket_the_cycle_cannot_cut_is_written_as_moves(corner, turned, reason):
    doc, job, face, pocket, model = make_shop(corner, turned)
    try:
        lines = post_module().export([job], "-", "").splitlines()
        assert "(Pocket written as moves: %s)" % reason in lines
    finally:
        FreeCAD.closeDocument(doc.Name)


def test_another_op_is_written_as_its_moves_and_a_new_tool_after_g32(shop):
    import Path
    import Path.Tool.Controller as Controller

    doc, job, face, pocket, model = shop
    second = Controller.Create("TC2", tool=job.Tools.Group[0].Tool, toolNumber=2, assignViewProvider=False)
    second.SpindleSpeed, second.HorizFeed, second.VertFeed = 2000.0, 10.0, 5.0
    job.Proxy.addToolController(second)
    pocket.ToolController = second
    pocket.CoolantMode = "Flood"
    custom = doc.addObject("Path::Feature", "Custom")
    custom.Path = Path.Path([Path.Command("G0", {"X": 1, "Y": 2, "Z": 30}), Path.Command("G1", {"Z": 25, "F": 2}),
                             Path.Command("G2", {"X": 3, "Y": 2, "I": 1, "J": 0, "F": 2})])
    doc.recompute()
    lines = post_module().export([job, custom], "-", "").splitlines()
    at = lines.index("(Pocket: G34)")
    assert lines[at - 5:at] == ["G32", "T2 M6", "S2000 M3", "D2 G43 H2", "M8"]
    assert lines[lines.index("G31", at) + 1] == "M9"
    assert lines[-6:] == ["(Custom written as moves: only CAM's Face and Pocket Shape ops have autoroutines here)",
                          "G0 X1. Y2. Z30.", "G1 Z25. F120.", "G2 X3. Y2. I1. J0.", "M5", "M30"]


@pytest.mark.parametrize("mode, code", [("Climb", "G41"), ("Conventional", "G42")])
def test_cut_mode_gives_the_laps_direction_of_the_ops_path(shop, mode, code):
    doc, job, face, pocket, model = shop
    pocket.CutMode = mode
    doc.recompute()
    lines = post_module().export([job], "-", "").splitlines()
    call = G34.parse(_section(lines, "(Pocket: G34)")[1])
    assert call.compensation == code

    def turning(points):  # the sum of the cross products of the X-Y feed segments at the lowest depth
        low = min(z for _x, _y, z in points)
        flat = [(x, y) for x, y, z in points if abs(z - low) < 1e-6]
        return sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(flat, flat[1:]))

    engine = [(m.x, m.y, m.z) for m in call.expand(START, Settings(mill_tool_diameter=TOOL)) if m.kind == FEED]
    own = [point for point in _path_points(pocket) if point[2] < RAPID_Z]
    assert (turning(engine) > 0) == (turning(own) > 0) == (mode == "Climb")  # counter-clockwise climbs with M3


def test_a_path_that_does_not_reach_the_walls_as_the_cycle_would_is_written_as_moves(shop):
    import Path

    doc, job, face, pocket, model = shop
    assert isinstance(recognise(pocket, False), NativeOp)
    commands = []
    for command in pocket.Path.Commands:  # the outer lap's right side (X67.5) 1 mm short of it
        params = dict(command.Parameters)
        if abs(params.get("X", 0.0) - 67.5) < 1e-6:
            params["X"] = 66.5
        commands.append(Path.Command(command.Name, params))
    pocket.Path = Path.Path(commands)
    assert recognise(pocket, False) == ("the op's Path reaches X32.5..66.5 Y22.5..37.5, the cycle's tool centre "
                                        "X32.5..67.5 Y22.5..37.5")


def test_a_facing_that_does_not_start_at_the_upper_right_corner_is_written_as_moves(shop):
    import Path

    doc, job, face, pocket, model = shop
    assert isinstance(recognise(face, False), NativeOp)
    commands = []
    for command in face.Path.Commands:  # the same passes mirrored in Y: from the lower right corner
        params = dict(command.Parameters)
        if "Y" in params:
            params["Y"] = 60.0 - params["Y"]
        commands.append(Path.Command(command.Name, params))
    face.Path = Path.Path(commands)
    assert recognise(face, False) == "the op's Path starts at X97.5 Y2.5, G33 at the upper right corner X97.5 Y57.5"
