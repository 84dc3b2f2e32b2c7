"""Milltronics G33 facing and G34 rectangular pocket autoroutines (seed 004): the
engine's model, its rules, hand-derived moves, and the tool's swept area with shapely."""

import math

import pytest
from hypothesis import given
from hypothesis import settings as hsettings
from hypothesis import strategies as st
from shapely.geometry import LineString, Point, box
from shapely.ops import unary_union

from freecad_groove.engine.cycles.milltronics import G33, G34
from freecad_groove.engine.errors import CycleError
from freecad_groove.engine.moves import ARC_CCW, ARC_CW, FEED, RAPID, MachineState
from freecad_groove.engine.registry import cycle_for, entry
from freecad_groove.engine.settings import Settings

SEED = "P151=1\nP152=3\nP155=.1\nG33 G99 G41 R.1 Z-.5 V-.3 Q.1 F5"
QUARTER = Settings(mill_tool_diameter=0.25)


def start(x=1.0, y=2.0, z=1.0, feed=20.0, metric=False):
    return MachineState(x=x, z=z, y=y, feed=feed, diameter_mode=False, metric=metric)


def moves_of(moves):
    return [(m.kind, round(m.x, 6), round(m.y, 6), round(m.z, 6), m.f) for m in moves]


ARC_STEP = 1e-5  # the chords the helpers follow an arc move along stay this close to it


def along(moves):
    """The moves as (x, y, z) points, each arc (G2 clockwise, G3 counter-clockwise, X right and Y
    up, about its centre) as points within ARC_STEP of it."""
    points, here = [], None
    for move in moves:
        end = (move.x, move.y, move.z)
        if move.kind in (ARC_CW, ARC_CCW):
            (cx, cy), (x0, y0) = move.centre, here[:2]
            radius = math.hypot(x0 - cx, y0 - cy)
            assert radius == pytest.approx(math.hypot(move.x - cx, move.y - cy), abs=1e-9)
            a0, a1 = math.atan2(y0 - cy, x0 - cx), math.atan2(move.y - cy, move.x - cx)
            turn = (a1 - a0) % (2 * math.pi)
            turn = turn - 2 * math.pi if move.kind == ARC_CW else turn
            count = max(1, math.ceil(abs(turn) / (2 * math.acos(1 - ARC_STEP / radius))))
            points += [(cx + radius * math.cos(a0 + turn * k / count), cy + radius * math.sin(a0 + turn * k / count),
                        move.z) for k in range(1, count)]
        points.append(end)
        here = end
    return points


def swept(moves, depth, radius):
    """The area the tool's disc sweeps while feeding at ``depth``."""
    shapes, previous = [], None
    for point in along(moves):
        here = point[:2]
        if point[2] == depth:
            shapes.append(Point(here).buffer(radius, quad_segs=64))
            if previous is not None and previous[2] == depth and previous[:2] != here:
                shapes.append(LineString([previous[:2], here]).buffer(radius, quad_segs=64))
        previous = point
    return unary_union(shapes)


def inside(moves, cx, cy, half_x, half_y, corner, radius):
    """Every tool centre (and so, the region being convex, every segment) lies where the tool's disc
    stays inside the rectangle with rounded corners: exactly, not on shapely's polygons."""
    corner = max(corner, radius)
    for x, y, _z in along(moves):
        dx = max(abs(x - cx) - (half_x - corner), 0.0)
        dy = max(abs(y - cy) - (half_y - corner), 0.0)
        if (dx * dx + dy * dy) ** 0.5 > corner - radius + 1e-9:
            return False
    return True


def test_registered_for_milltronics_programs():
    assert cycle_for("milltronics", "G33") is G33 and cycle_for("milltronics", "G34") is G34
    assert entry("g33").cycle_class is G33 and entry("milltronics-g34").cycle_class is G34


def test_the_seed_block_reads_with_its_assignments_and_writes_back():
    model = G33.parse(SEED)
    assert (model.P151, model.P152, model.P155) == (1.0, 3.0, 0.1)
    assert (model.R, model.Z, model.V, model.Q, model.F, model.G99, model.compensation) == (
        0.1, -0.5, -0.3, 0.1, 5.0, True, "G41")
    assert model.emit() == "P151=1.\nP152=3.\nP155=0.1\nG33 G99 G41 R0.1 Z-0.5 V-0.3 Q0.1 F5."
    assert G33.parse(model.emit()) == model


def test_a_small_facing_by_hand():
    # 1 x 0.5 centred on X0 Y0, tool 0.25: centre inset 0.125 -> X +-0.375, Y +-0.125; long side X; one
    # step-over of 0.25 (= P155); one depth; G99 back to R.
    model = G33.parse("P151=1\nP152=.5\nP155=.25\nG33 G99 R.1 Z-.1 V-.1 F5")
    assert moves_of(model.expand(start(x=0.0, y=0.0), QUARTER)) == [
        (RAPID, 0.375, 0.125, 1.0, None),  # over the upper right corner (above R already)
        (RAPID, 0.375, 0.125, 0.1, None),  # down to R
        (FEED, 0.375, 0.125, -0.1, 5.0),  # Z feed
        (FEED, -0.375, 0.125, -0.1, 20.0),  # along the long side at the X-Y feed in force
        (FEED, -0.375, -0.125, -0.1, 20.0),  # step over
        (FEED, 0.375, -0.125, -0.1, 20.0),  # back
        (RAPID, 0.375, -0.125, 0.1, None),  # G99
    ]


def test_the_seed_facing_starts_upper_right_and_cuts_v_then_by_q_to_z_rising_0_1_between():
    moves = G33.parse(SEED).expand(start(), QUARTER)
    # Y is the long side (3 > 1): the first pass runs down Y from the upper right corner.
    assert moves_of(moves[:4]) == [(RAPID, 1.375, 3.375, 1.0, None), (RAPID, 1.375, 3.375, 0.1, None),
                                   (FEED, 1.375, 3.375, -0.3, 5.0), (FEED, 1.375, 0.625, -0.3, 20.0)]
    plunges = [m.z for m in moves if m.kind == FEED and m.f == 5.0]
    assert plunges == [-0.3, -0.4, -0.5]
    lifts = [(a.z, b.z) for a, b in zip(moves, moves[1:]) if b.kind == RAPID and b.z > a.z]
    assert [(round(a, 6), round(b, 6)) for a, b in lifts] == [(-0.3, -0.2), (-0.4, -0.3), (-0.5, 0.1)]
    for index, move in enumerate(moves):
        if move.kind == FEED and move.f == 5.0:
            assert (round(move.x, 6), round(move.y, 6)) == (1.375, 3.375)  # each depth from the top right
            assert moves[index - 1].kind == RAPID


@pytest.mark.parametrize("text", [SEED, "P151=2.5\nP152=1.2\nP155=.2\nG33 G42 R.1 Z-.2 Q.1",
                                  "P151=.25\nP152=.25\nP155=.25\nG33 R.1 Z-.1 V-.1"])
def test_the_facing_covers_the_rectangle_but_its_corners_at_every_depth_and_never_leaves_it(text):
    model = G33.parse(text)
    moves = model.expand(start(), QUARTER)
    rectangle = box(1 - model.P151 / 2, 2 - model.P152 / 2, 1 + model.P151 / 2, 2 + model.P152 / 2)
    rounded = rectangle.buffer(-0.125).buffer(0.125, quad_segs=64) if model.P151 > 0.25 else Point(1, 2).buffer(0.12)
    depths = sorted({m.z for m in moves if m.kind == FEED}, reverse=True)
    assert depths[-1] == model.Z
    for depth in depths:
        area = swept(moves, depth, 0.125)
        # all of it but the corners, which a round tool inside the rectangle leaves at its radius
        # at the short sides, between two passes not joined there, the round tool leaves a scallop
        scallop = 0.125 - (0.125 ** 2 - (model.P155 / 2) ** 2) ** 0.5
        assert rounded.buffer(-scallop - 1e-4).difference(area).area < 1e-7
    assert inside(moves, 1, 2, model.P151 / 2, model.P152 / 2, 0.0, 0.125)


POCKETS = [
    "P151=2\nP152=1\nP155=.2\nP150=.25\nG34 G99 R.1 Z-.2 Q.1 F5",
    "P151=1\nP152=1.5\nP155=.1\nG34 G42 R.1 Z-.1 V-.1",  # corner radius 0: the tool's radius
    "P151=1.2\nP152=.8\nP155=.15\nP150=.2\nP153=.02\nP154=.01\nG34 G99 G41 R.1 Z-.2 V-.05 Q.1",
    "P151=.25\nP152=.6\nP155=.2\nG34 R.1 Z-.1 V-.1",  # exactly the tool's width: the centre line only
]


@pytest.mark.parametrize("text", POCKETS)
def test_the_pocket_is_cleared_at_every_depth_and_the_tool_never_leaves_it(text):
    model = G34.parse(text)
    moves = model.expand(start(), QUARTER)
    corner = model.P150 or 0.125
    half_x, half_y = model.P151 / 2, model.P152 / 2
    inner = box(1 - half_x + corner, 2 - half_y + corner, 1 + half_x - corner, 2 + half_y - corner)
    pocket = inner.buffer(corner, quad_segs=64)  # the walls with their corner radius
    stock = model.P153 or 0.0
    rough = box(1 - half_x + stock, 2 - half_y + stock, 1 + half_x - stock, 2 + half_y - stock)
    rough = rough.intersection(pocket.buffer(-stock, quad_segs=64)) if stock else pocket
    depths = sorted({m.z for m in moves if m.kind == FEED}, reverse=True)
    assert depths[-1] == model.Z
    assert moves[0].x == 1.0 and moves[0].y == 2.0  # the plunge is at the centre
    for depth in depths:
        area = swept(moves, depth, 0.125)
        # cleared, its corners too (arcs)
        assert rough.buffer(-1e-4).difference(area).area < 1e-7
    assert inside(moves, 1, 2, half_x, half_y, corner, 0.125)  # never beyond the walls
    final = swept(moves, model.Z, 0.125)
    # the finishing lap cuts the walls at Z
    assert pocket.buffer(-1e-4).difference(final).area < 1e-7


def test_a_small_square_pocket_by_hand():
    # 0.5 x 0.5, tool 0.25: the centre runs a square of half side 0.125 (0.25 from the wall... less the
    # radius), one lap counter-clockwise (G41 or none: climb with M3), from the right side's middle.
    model = G34.parse("P151=.5\nP152=.5\nP155=.125\nG34 G99 R.1 Z-.1 V-.1 F5")
    assert moves_of(model.expand(start(x=0.0, y=0.0, z=0.1), QUARTER)) == [
        (FEED, 0.0, 0.0, -0.1, 5.0),
        (FEED, 0.125, 0.0, -0.1, 20.0),  # out to the lap's start, the right side's middle
        (FEED, 0.125, 0.125, -0.1, 20.0),
        (FEED, -0.125, 0.125, -0.1, 20.0),
        (FEED, -0.125, -0.125, -0.1, 20.0),
        (FEED, 0.125, -0.125, -0.1, 20.0),
        (FEED, 0.125, 0.0, -0.1, 20.0),
        (RAPID, 0.125, 0.0, 0.1, None),
    ]
    g42 = G34.parse("P151=.5\nP152=.5\nP155=.125\nG34 G42 R.1 Z-.1 V-.1 F5")
    assert [(x, y) for _, x, y, _, _ in moves_of(g42.expand(start(x=0.0, y=0.0, z=0.1), QUARTER))[2:7]] == [
        (0.125, -0.125), (-0.125, -0.125), (-0.125, 0.125), (0.125, 0.125), (0.125, 0.0)]
    # without G99 the tool rises the lift (0.1") above the last depth
    assert g42.expand(start(x=0.0, y=0.0, z=0.1), QUARTER)[-1].z == pytest.approx(0.0)


def test_a_metric_program_lifts_2_54_mm_between_depths():
    model = G33.parse("P151=20\nP152=10\nP155=5\nG33 R2 Z-2 V-1 Q1 F100")
    moves = model.expand(start(x=0.0, y=0.0, z=5.0, feed=500.0, metric=True), Settings(mill_tool_diameter=6.0))
    lift = [b.z - a.z for a, b in zip(moves, moves[1:]) if b.kind == RAPID and b.z > a.z]
    assert lift[0] == pytest.approx(2.54)


@pytest.mark.parametrize("cycle, text, message", [
    (G33, "P152=3\nP155=.1\nG33 R.1 Z-.5 Q.1", r"G33 P151: must be given \(the X size"),
    (G33, "P151=1\nP155=.1\nG33 R.1 Z-.5 Q.1", r"G33 P152: must be given \(the Y size"),
    (G33, "P151=1\nP152=3\nG33 R.1 Z-.5 Q.1", r"G33 P155: must be given \(the cut width"),
    (G33, "P151=1\nP152=3\nP155=.3\nG33 R.1 Z-.5 Q.1", r"G33 P155=0.3: the cut width is larger than the tool"),
    (G33, "P151=1\nP152=3\nP155=.1\nG33 R.1 Z-.5 Q.1", None),
    (G33, "P151=1\nP152=3\nP155=.1\nG33 R.1 Z-.5", r"G33 Q: must be given \(the first depth without V"),
    (G33, "P151=1\nP152=3\nP155=.1\nG33 R.1 Z-.5 V-.2", r"G33 Q: must be given \(more than one depth"),
    (G33, "P151=1\nP152=3\nP155=.1\nG33 Z-.5 Q.1", r"G33 R: must be given \(the clearance plane"),
    (G33, "P151=1\nP152=3\nP155=.1\nG33 R.1 Q.1", r"G33 Z: must be given \(the final depth"),
    (G33, "P151=1\nP152=3\nP155=.1\nG33 R.1 Z.2 Q.1", r"G33 Z=0.2: the final depth must be below"),
    (G33, "P151=1\nP152=3\nP155=.1\nG33 R.1 Z-.5 V.2 Q.1", r"G33 V=0.2: the first depth is above"),
    (G33, "P151=.2\nP152=3\nP155=.1\nG33 R.1 Z-.5 Q.1", r"G33 P151=0.2: the rectangle is smaller than the tool"),
    (G34, "P151=1\nP152=.2\nP155=.1\nG34 R.1 Z-.5 Q.1", r"G34 P152=0.2: the rectangle is smaller than the tool"),
    (G34, "P151=1\nP152=1\nP155=.1\nP150=.1\nG34 R.1 Z-.5 Q.1",
     r"G34 P150=0.1: the corner radius is smaller than the tool radius 0.125"),
    (G34, "P151=1\nP152=1\nP155=.1\nP150=.6\nG34 R.1 Z-.5 Q.1", r"G34 P150=0.6: the corner radius is more than half"),
    (G34, "P151=1\nP152=.4\nP155=.1\nP153=.1\nG34 R.1 Z-.5 Q.1",
     r"G34 P153=0.1: the pocket less the finish stock on both walls \(P152 = 0.4\) is smaller than the tool"),
    (G34, "P151=1\nP152=1\nP155=.1\nP154=.5\nG34 R.1 Z-.5 V-.1 Q.1", r"G34 V=-0.1: the first depth -0.1 is below"),
    (G34, "P151=9000\nP152=9000\nP155=.0001\nG34 R.1 Z-.1 V-.1",
     r"G34 P155=0.0001: the cut width is too small for the rectangle: more than 1000000 passes"),
    (G33, "P151=9000\nP152=900\nP155=.0001\nG33 R.1 Z-.1 V-.1", r"G33 P155=0.0001: the cut width is too small"),
    (G33, "P151=2\nP152=1\nP155=.1\nG33 R.1 Z-900 Q.0001", r"G33 Q=0.0001: too small for the depth"),
])
def test_every_rule_that_needs_the_start_or_the_tool(cycle, text, message):
    model = cycle.parse(text)
    if message is None:
        assert model.expand(start(), QUARTER)
        with pytest.raises(CycleError, match=r"G33 tool diameter: is not known"):
            model.expand(start(), Settings())
        with pytest.raises(CycleError, match=r"G33 F: no X-Y feed in force"):
            model.expand(start(feed=None), QUARTER)
        return
    with pytest.raises(CycleError, match=message):
        model.expand(start(), QUARTER)


@pytest.mark.parametrize("text, message", [
    ("P151=1\nG33 R.1 Z-.5 V-.6 Q.1", r"G33 V=-0.6: the first depth is below the final depth Z-0.5"),
    ("G33 R.1 Z-.5 Q0", r"G33 Q=0: must be greater than 0"),
    ("G33 R.1 Z-.5 Q-.1", r"G33 Q=-0.1: must be greater than 0"),
    ("P151=0\nG33 R.1 Z-.5 Q.1", r"G33 P151=0: must be greater than 0"),
    ("P155=-.1\nG33 R.1 Z-.5 Q.1", r"G33 P155=-0.1: must be greater than 0"),
    ("P153=-.1\nG33 R.1 Z-.5 Q.1", r"G33 P153=-0.1: must not be negative"),
    ("P149=1\nG33 R.1 Z-.5 Q.1", r"G33 P149: is not a parameter of the autoroutines"),
    ("G33 G41 G42 R.1 Z-.5 Q.1", r"G33 G42: G41 and G42 in one block"),
    ("G33 G0 R.1 Z-.5 Q.1", r"G33 G0: may not share the G33 block"),
    ("G33 R.1 Z-.5 Q.1 X1", r"G33 X=1: is not a word of G33"),
    ("G33 R.1 Z-.5 Z-.4", r"G33 Z=-0.4: is not a word of G33 \(or is given twice\)"),
    ("G33 R.1 Z-.5 F0", r"G33 F=0: must be greater than 0"),
    ("G34 R.1 Z-.5", r"G33 G34: may not share the G33 block"),
    ("G33 R.1\nP151=1", r"G33 block=G33R.1: only P assignments"),
])
def test_every_rule_on_the_block_as_written(text, message):
    with pytest.raises(CycleError, match=message):
        G33.parse(text)


_values = st.integers(-99999, 99999).map(lambda n: n / 1000.0)
_amounts = st.integers(1, 99999).map(lambda n: n / 1000.0)


@hsettings(max_examples=200, deadline=None)
@given(st.sampled_from([G33, G34]), st.fixed_dictionaries({}, optional={
    "R": _values, "Z": _values, "Q": _amounts, "F": _amounts, "G99": st.booleans(),
    "compensation": st.sampled_from([None, "G41", "G42"]), "P150": _amounts, "P151": _amounts, "P152": _amounts,
    "P153": _amounts, "P154": _amounts, "P155": _amounts}))
def test_parse_of_emit_is_the_model(cycle, words):
    model = cycle(**words)
    assert cycle.parse(model.emit()) == model


@hsettings(max_examples=60, deadline=None)
@given(st.data())
def test_generated_pockets_and_facings_cover_their_rectangle_and_stay_inside(data):
    draw = data.draw
    diameter = draw(st.integers(10, 50)) / 100.0
    radius = diameter / 2
    size_x = round(diameter + draw(st.integers(0, 300)) / 100.0, 2)
    size_y = round(diameter + draw(st.integers(0, 300)) / 100.0, 2)
    width = draw(st.integers(1, int(diameter * 100))) / 100.0
    pocket = draw(st.booleans())
    words = dict(R=0.1, Z=-0.2, V=-0.1, Q=0.1, P151=size_x, P152=size_y, P155=width,
                 compensation=draw(st.sampled_from([None, "G41", "G42"])))
    corner = 0.0
    if pocket:
        limit = min(size_x, size_y) / 2
        corner = draw(st.sampled_from([0.0, radius, (radius + limit) / 2, limit]))
        words["P150"] = round(corner, 3)
        corner = words["P150"]
        if 0 < corner < radius or corner > limit:
            return
    model = (G34 if pocket else G33)(**words)
    settings = Settings(mill_tool_diameter=diameter)
    moves = model.expand(start(), settings)
    assert inside(moves, 1, 2, size_x / 2, size_y / 2, corner, radius)
    area = swept(moves, -0.2, radius)
    target = box(1 - size_x / 2, 2 - size_y / 2, 1 + size_x / 2, 2 + size_y / 2)
    shown = max(corner, radius)
    target = target.buffer(-shown).buffer(shown, quad_segs=64) if min(size_x, size_y) > 2 * shown else area
    # the facing leaves the step-over's scallop at its short sides; the pocket nothing (arcs at its corners)
    margin = radius - (radius ** 2 - (width / 2) ** 2) ** 0.5 if not pocket else 0.0
    assert target.buffer(-margin - 1e-4).difference(area).area < 1e-7


def test_a_pocket_with_rounded_corners_by_hand():
    # 0.75 x 0.75, corner radius P150 0.25, tool 0.25 (radius 0.125): the centre runs inset 0.125 (half
    # side 0.25), the outer lap's corners the offset of the wall's, radius 0.25 - 0.125 = 0.125 about
    # (+-0.125, +-0.125). Out to it in laps at most 0.85 tool diameters (0.2125) apart: two, the first
    # half side 0.125 with sharp corners (the corner radius less the step is nothing). Counter-
    # clockwise (no G42): each rounded corner a quarter arc G3 (X right, Y up) about its centre.
    model = G34.parse("P151=.75\nP152=.75\nP155=.25\nP150=.25\nG34 G99 R.1 Z-.1 V-.1 F5")
    moves = model.expand(start(x=0.0, y=0.0, z=0.1), QUARTER)
    assert [(m.kind, round(m.x, 9), round(m.y, 9), m.z, m.f, m.centre) for m in moves] == [
        (FEED, 0.0, 0.0, -0.1, 5.0, None),
        (FEED, 0.125, 0.0, -0.1, 20.0, None),  # the first lap, square
        (FEED, 0.125, 0.125, -0.1, 20.0, None),
        (FEED, -0.125, 0.125, -0.1, 20.0, None),
        (FEED, -0.125, -0.125, -0.1, 20.0, None),
        (FEED, 0.125, -0.125, -0.1, 20.0, None),
        (FEED, 0.125, 0.0, -0.1, 20.0, None),
        (FEED, 0.25, 0.0, -0.1, 20.0, None),  # the outer lap, from its right side's middle
        (FEED, 0.25, 0.125, -0.1, 20.0, None),
        (ARC_CCW, 0.125, 0.25, -0.1, 20.0, (0.125, 0.125)),
        (FEED, -0.125, 0.25, -0.1, 20.0, None),
        (ARC_CCW, -0.25, 0.125, -0.1, 20.0, (-0.125, 0.125)),
        (FEED, -0.25, -0.125, -0.1, 20.0, None),
        (ARC_CCW, -0.125, -0.25, -0.1, 20.0, (-0.125, -0.125)),
        (FEED, 0.125, -0.25, -0.1, 20.0, None),
        (ARC_CCW, 0.25, -0.125, -0.1, 20.0, (0.125, -0.125)),
        (FEED, 0.25, 0.0, -0.1, 20.0, None),
        (RAPID, 0.25, 0.0, 0.1, None, None),  # G99: to the clearance plane
    ]
    g42 = G34.parse("P151=.75\nP152=.75\nP155=.25\nP150=.25\nG34 G42 R.1 Z-.1 V-.1 F5")
    outer = g42.expand(start(x=0.0, y=0.0, z=0.1), QUARTER)[8:10]  # G42 runs clockwise: G2, first corner lower right
    assert [(m.kind, round(m.x, 9), round(m.y, 9), m.centre) for m in outer] == [
        (FEED, 0.25, -0.125, None), (ARC_CW, 0.125, -0.25, (0.125, -0.125))]
