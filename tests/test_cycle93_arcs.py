"""CYCLE93's contour and finishing passes write arcs: where the blade's rounded
(or sharp) corner rolls over a profile arc or round a vertex, its reference
corner runs on a circle, written as one G2/G3 instead of a run of chords.
The moves are otherwise those of the chorded passes: the same plunges, the
same stretches fed. LinuxCNC's rs274 reads the arcs as the engine means them,
and the material-removal simulation sweeps them without a gouge."""

import contextlib
import io
import math

import pytest
from hypothesis import HealthCheck, assume, example, given, settings
from rs274 import canonical_matches, require_rs274, run_rs274, written_moves
from shapely.geometry import LineString, Point, Polygon
from test_cycle93_simulation import grooves

from freecad_groove import cli
from freecad_groove import verify as sim
from freecad_groove.engine import CycleError, GroovingTool, MachineState, Settings
from freecad_groove.engine.cycles import cycle93_passes
from freecad_groove.engine.cycles.cycle93 import Cycle93, _cached_geometry
from freecad_groove.engine.cycles.cycle93_constants import PATH_TOLERANCE
from freecad_groove.engine.cycles.cycle93_profile import split_at
from freecad_groove.engine.envelope import on_circles, writes_arcs
from freecad_groove.engine.moves import ARC_CCW, ARC_CW, ARCS, FEED, RAPID
from freecad_groove.engine.output.program import write_program

# The four-R2-corner groove of issue 19 and the lines `emit --expand` wrote for
# it before the passes wrote arcs (measured at main 3d18f68: 412 lines, 338 of
# them chords about 0.1 mm long).
R2_ARGS = ["emit", "cycle93", "--tool-width", "3", "--tool-radius", "0.4", "--axfa", "20", "--axsa", "-10",
           "--widg", "12", "--depg", "5", "--angc", "0", "--ang1", "0", "--ang2", "0", "--rco1", "2", "--rco2", "2",
           "--rci1", "2", "--rci2", "2", "--fal1", "0.2", "--fal2", "0.2", "--idep", "2", "--dwt", "0", "--typ", "5",
           "--vrt", "0", "--expand", "--start-x", "60", "--start-z", "5", "--feed", "0.1", "--spindle", "500"]
R2_CALL = "CYCLE93(20, -10, 12, 5, 0, 0, 0, 2, 2, 2, 2, 0.2, 0.2, 2, 0, 5, 0)"
R2_LINES_CHORDED = 412


def emitted(argv):
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert cli.main(argv) in (0, None)
    return out.getvalue().splitlines()


def test_a_small_groove_with_base_radii_by_hand():
    # TYP 1 (longitudinal, external, left) at radius 20 from z 0 toward +Z: 6 wide, 3 deep, both
    # base corners R1, VRT 1, one infeed (IDEP 5); a sharp 2 mm blade, reference corner at its -Z
    # edge. Groove frame: u = z, v = x - 20. Plunges across the opening [0, 6] for the blade's
    # -Z edge from 0 to 4, at most 0.95 * 2 = 1.9 apart: 4 of them, 4/3 apart. The one at 0 stops
    # where the base radius starts on the flank (x 18), at 4 too (its +Z edge at the other flank),
    # the two between reach the base (x 17); the third and fourth free off 1 mm toward the one
    # before (the second has the first's shallower slot beside it). The contour pass from each edge
    # (no allowance: the roughing profile is the final one, one pass each way): the blade's sharp
    # corner runs down the base radius, a quarter circle of radius 1 about (x 18, z 1) on the left
    # (from angle 180 to 270 degrees about it, Z right and X up: counter-clockwise, G3) and about
    # (x 18, z 3) on the right for the blade's -Z corner (its +Z corner on the radius about z 5),
    # from 0 to -90 degrees: clockwise, G2. There the blade (z 1 to 3 on the left, 3 to 5 on the right) stands
    # on the base with the plunges' slots beside it: going on along the base to the next plunge
    # position (4/3, 8/3) would cut nothing, so each pass goes back up from the arc's end. Every
    # plunge feeds from VRT above the surface (x 21); the fourth one's
    # free-off is a rapid (the third's slot beside it is cut deeper, to x 17). Each pass comes down
    # from VRT above the contour to 0.1 above the level the first plunge left (x 18.1).
    moves = Cycle93.parse("CYCLE93(20, 0, 6, 3, 0, 0, 0, 0, 0, 1, 1, 0, 0, 5, 0, 1, 1)").expand(
        MachineState(x=25.0, z=5.0, feed=0.1), Settings(tool=GroovingTool(2.0, 0.0)))
    third, two_thirds = 4.0 / 3.0, 8.0 / 3.0
    expected = [
        (RAPID, 25.0, 0.0), (RAPID, 21.0, 0.0),  # along Z first (an external groove), down to VRT above
        (FEED, 18.0, 0.0), (RAPID, 21.0, 0.0),
        (RAPID, 21.0, third), (FEED, 17.0, third), (RAPID, 21.0, third),
        (RAPID, 21.0, two_thirds), (FEED, 17.0, two_thirds),
        (RAPID, 17.0, two_thirds - 1.0), (RAPID, 21.0, two_thirds - 1.0),
        (RAPID, 21.0, 4.0), (FEED, 18.0, 4.0), (RAPID, 18.0, 3.0), (RAPID, 21.0, 3.0),
        (RAPID, 21.0, 0.0), (RAPID, 18.1, 0.0), (FEED, 18.0, 0.0),
        (ARC_CCW, 17.0, 1.0, (18.0, 1.0)), (RAPID, 21.0, 1.0),
        (RAPID, 21.0, 4.0), (RAPID, 18.1, 4.0), (FEED, 18.0, 4.0),
        (ARC_CW, 17.0, 3.0, (18.0, 3.0)), (RAPID, 21.0, 3.0),
        (RAPID, 25.0, 3.0), (RAPID, 25.0, 5.0),  # back the way the approach came
    ]
    assert len(moves) == len(expected)
    for move, (kind, x, z, *centre) in zip(moves, expected):
        assert (move.kind, move.x, move.z) == (kind, pytest.approx(x, abs=1e-4), pytest.approx(z, abs=1e-4))
        assert move.centre == (pytest.approx(centre[0], abs=1e-9) if centre else None)


def test_the_four_r2_corner_groove_writes_at_most_two_fifths_of_its_chorded_lines():
    lines = emitted(R2_ARGS)
    assert len(lines) <= 0.4 * R2_LINES_CHORDED, len(lines)
    # The finishing passes over each outer corner, the roughing and the finishing passes over each base corner.
    assert sum(" I" in line and " K" in line for line in lines) >= 6


def test_no_chords_are_left_on_the_four_r2_corner_grooves_arcs():
    # Square flanks, a level base and contour: every straight piece of the passes' path is
    # paraxial (plunges, flanks and base); every other piece is an arc of a corner. A feed that
    # moves in X and Z at once would be a chord.
    moves = Cycle93.parse(R2_CALL).expand(MachineState(x=30.0, z=5.0), Settings(tool=GroovingTool(3.0, 0.4)))
    position = (30.0, 5.0)
    for move in moves:
        if move.kind == FEED:
            assert abs(move.x - position[0]) < 1e-9 or abs(move.z - position[1]) < 1e-9, (position, move)
        position = (move.x, move.z)
    assert {move.kind for move in moves} >= set(ARCS)


def test_an_arc_mapped_to_the_world_is_on_the_circle_of_its_centre():
    moves = Cycle93.parse(R2_CALL).expand(MachineState(x=30.0, z=5.0), Settings(tool=GroovingTool(3.0, 0.4)))
    arcs = [(before, move) for before, move in zip(moves, moves[1:]) if move.kind in ARCS]
    assert arcs
    for before, move in arcs:
        start, end = math.dist((before.x, before.z), move.centre), math.dist((move.x, move.z), move.centre)
        assert start == pytest.approx(end, abs=1e-6)
        assert start in (pytest.approx(2.4, abs=1e-6), pytest.approx(1.6, abs=1e-6), pytest.approx(0.4, abs=1e-6))


# TYP 1..8: longitudinal (1, 3, 5, 7) and face (2, 4, 6, 8), external and internal, left and right:
# X plunging down (external longitudinal) and up (internal), Z plunging down and up (face grooves).
# Radii and chamfers on every corner, allowances and angled flanks, so the passes have arcs of
# every kind (a bump's R + r, a bowl's R - r, a vertex's r).
TYP_CASES = [(typ, reference) for typ in range(1, 9) for reference in ("minus", "plus")]


def typ_case(typ, reference):
    longitudinal = typ % 2 == 1
    call = Cycle93(axfa=30.0 if typ in (1, 2, 5, 6) else 15.0, axsa=10.0, widg=7.0, depg=4.0,
                   angc=0.0 if longitudinal else 90.0, ang1=5.0, ang2=10.0, rco1=1.0, rco2=-0.5, rci1=1.2,
                   rci2=0.8, fal1=0.2, fal2=0.15, idep=1.5, dwt=0.0, typ=typ, vrt=1.0)
    return call, GroovingTool(2.5, 0.4, reference=reference)


def expanded(call, tool):
    settings_ = Settings(tool=tool)
    geo = call.geometry(settings_)
    lo, hi = geo.opening(geo.final_top)
    u = lo - tool.width - 4.0
    start = geo.frame.blade(u, max(geo.contour_top(u), geo.contour_top(hi)) + 3.0)
    state = MachineState(x=start[0], z=start[1], feed=0.1, feed_per_rev=False)
    return geo, state, call.expand(state, settings_)


@pytest.mark.parametrize("typ, reference", TYP_CASES)
def test_rs274_reads_the_arcs_of_every_typ_as_the_engine_means_them(typ, reference):
    require_rs274()
    call, tool = typ_case(typ, reference)
    _geo, state, moves = expanded(call, tool)
    canon = run_rs274(write_program(moves, "linuxcnc", state))
    problems = canonical_matches(written_moves(moves), canon, start=1, trailing=True)
    assert not problems, "\n".join(problems[:5])
    assert {c[0] for c in canon} >= {"G2", "G3"}


@pytest.mark.parametrize("typ, reference", TYP_CASES)
def test_the_arcs_of_every_typ_cut_the_groove_without_a_gouge(typ, reference):
    call, tool = typ_case(typ, reference)
    geo, state, moves = expanded(call, tool)
    assert any(m.kind in ARCS for m in moves)
    stock = Polygon([(z, x) for x, z in geo.stock_world()])
    target = Polygon([(z, x) for x, z in geo.region_world()]).buffer(0)
    result = sim.simulate(moves, tool, call.plunge_direction(), (state.x, state.z), stock)
    verdict = sim.check_groove(result, target, tool, tol=0.001, plunge=call.plunge_direction(), label=call.emit())
    sim.assert_clean(verdict, allow_infeasible=True)


def test_the_oracle_catches_an_arc_turned_the_wrong_way():
    # The proof must be able to fail: the same arcs the other way round (G2 for G3) sweep the
    # rest of their circles, through the part.
    call, tool = typ_case(1, "minus")
    geo, state, moves = expanded(call, tool)
    turned = [m._replace(kind=ARC_CW if m.kind == ARC_CCW else ARC_CCW) if m.kind in ARCS else m for m in moves]
    stock = Polygon([(z, x) for x, z in geo.stock_world()])
    target = Polygon([(z, x) for x, z in geo.region_world()]).buffer(0)
    result = sim.simulate(turned, tool, call.plunge_direction(), (state.x, state.z), stock)
    verdict = sim.check_groove(result, target, tool, tol=0.001, plunge=call.plunge_direction())
    assert verdict.gouge > 0.1


@settings(suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])
@given(grooves())
def test_the_exact_path_lines_up_with_the_chorded_trace_stretch_by_stretch(case):
    # The passes decide on the chorded trace and write the exact path between the same stretch
    # bounds; where the two did not line up they would write the chords (a guard): they always do.
    call, tool = case
    try:
        geo = call.geometry(Settings(tool=tool))
    except CycleError:
        assume(False)
    steps = geo.plunge_positions()
    r, w = tool.corner_radius, tool.width
    for env, top in ((geo.rough_env, geo.rough_top), (geo.final_env, geo.final_top)):
        left, right = geo.opening(top)
        ua, ub = left - r, right - w + r
        for start in (ua, ub):
            end = 0.5 * (ua + ub)
            pts, exact = split_at(env.trace(start, end, PATH_TOLERANCE), steps), env.path(start, end)
            assert on_circles(split_at(exact, steps))
            written = cycle93_passes._Written(pts, cycle93_passes._groups(pts, steps), exact, steps)
            assert written.index or not writes_arcs(exact, PATH_TOLERANCE), (start, end)


def _runs(moves):
    """The fed runs between rapids: the end points of each run's moves."""
    runs, run = [], []
    for move in moves:
        if move.kind == RAPID:
            if run:
                runs.append(run)
            run = []
        elif move.kind != "G4":
            run.append((move.x, move.z))
    return runs + ([run] if run else [])


@settings(suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])
@given(grooves())
@example((Cycle93.parse("CYCLE93(15, 0, 1.51, 0.8, 6, 0, 0, 0.1, 0, 0, 0.74, 0, 0, 0.3, 0, 1, 0)"),
          GroovingTool(1.5, 0.0)))  # a run starting where a grazing line meets the path (a random case)
def test_arcs_change_only_the_feeds_between_the_bounds_the_chorded_passes_feed(case):
    # The same expansion with the passes writing their chords (as before arcs: the guard's way): the
    # same rapids and dwells, the same fed runs starting and ending at the same points (the exact
    # path's points there lie on the circle, the chords' up to the path tolerance above it).
    call, tool = case
    try:
        geo, state, moves = expanded(call, tool)
    except CycleError:
        assume(False)
    original = cycle93_passes._Written.index
    try:
        cycle93_passes._Written.index = property(lambda self: {})
        _cached_geometry.cache_clear()  # a geometry expands once per call and settings: expand afresh
        before = call.expand(state, Settings(tool=tool))
    finally:
        cycle93_passes._Written.index = original
        _cached_geometry.cache_clear()
    assert not any(m.kind in ARCS for m in before)
    assert [m for m in moves if m.kind in (RAPID, "G4")] == [m for m in before if m.kind in (RAPID, "G4")]
    runs, runs_before = _runs(moves), _runs(before)
    assert len(runs) == len(runs_before)
    for run, run_before in zip(runs, runs_before):
        # Each end lies on the chorded run's path (its chords are within the tolerance of the exact path),
        # and close to the chorded run's own end: where a run's end is found by meeting a line at a grazing
        # angle (a pass starting where its material starts), the chords' tolerance across the path moves the
        # meeting point along it by up to the tolerance over the angle's sine (0.00047 mm in the example).
        path = LineString(run_before) if len(run_before) > 1 else Point(run_before[0])
        for end, end_before in ((run[0], run_before[0]), (run[-1], run_before[-1])):
            assert path.distance(Point(end)) <= 2 * PATH_TOLERANCE, (end, end_before)
            assert math.dist(end, end_before) <= 10 * PATH_TOLERANCE, (end, end_before)
