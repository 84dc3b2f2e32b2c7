"""Tests of the simulation oracle itself (freecad_groove.verify), on
hand-made programs whose right answer is known, so that the cycle tests can
trust its verdicts: a gouge, a rapid into stock or material left behind must
be reported, a correct program must pass.

Geometry is (z, x) with x the radius; moves are (x, z) like moves.Move.
"""

import math
import os
import re
import subprocess
import sys

import pytest
import shapely
import shapely.affinity
from hypothesis import given
from hypothesis import strategies as st
from shapely.geometry import Point, box

from freecad_groove.engine.moves import (
    MINUS_X,
    MINUS_Z,
    PLUNGE_DIRECTIONS,
    PLUS_X,
    PLUS_Z,
    GroovingTool,
    Move,
    dwell,
    feed,
    rapid,
)
from freecad_groove.verify import (
    ARC_EXCESS,
    assert_clean,
    bar,
    check_groove,
    reachable_region,
    region,
    simulate,
    swept_area,
    tool_outline,
    unreachable_region,
)
from freecad_groove.verify import reach as reach_module

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# A bar of radius 20 from Z-50 to Z0, and a groove Z-10..-7, 5 deep.
STOCK = bar(20.0, -50.0, 0.0)
GROOVE = region(15.0, 20.0, -10.0, -7.0)
TOOL = GroovingTool(3.0, 0.4)
SHARP = GroovingTool(3.0, 0.0)
START = (25.0, -10.0)


def fillet_area(r):
    """Area a corner radius r leaves in one sharp 90 degree corner."""
    return (1 - math.pi / 4) * r * r


def plunge(z, bottom, top=21.0, f=0.1):
    """One plunge of an external groove at reference Z z, down to radius bottom."""
    return [rapid(top, z), feed(bottom, z, f), rapid(top, z)]


def run(moves, tool=TOOL, target=GROOVE, stock=STOCK, start=START, plunge_dir=MINUS_X):
    result = simulate(moves, tool, plunge_dir, start, stock)
    return result, check_groove(result, target, tool)


# --------------------------------------------------------------------------- (a) correct


def test_correct_plunge_passes():
    result, verdict = run(plunge(-10.0, 15.0))
    assert_clean(verdict)
    assert verdict.gouge == 0.0
    assert not verdict.incomplete
    assert not verdict.rapid_collisions
    # What is left in the groove is exactly the two corner fillets of r=0.4.
    left = GROOVE.intersection(result.remaining).area
    assert left == pytest.approx(2 * fillet_area(0.4), abs=2e-4)
    assert verdict.unreachable.area == pytest.approx(2 * fillet_area(0.4), abs=2e-4)
    # The groove went: removed is the groove minus its fillets.
    assert result.removed.area == pytest.approx(GROOVE.area - 2 * fillet_area(0.4), abs=2e-4)


def test_correct_wide_groove_with_floor_pass_passes():
    target = region(15.0, 20.0, -10.0, -2.0)  # 8 wide: three plunges and a floor pass
    moves = plunge(-10.0, 15.2) + plunge(-7.5, 15.2) + plunge(-5.0, 15.2)
    moves += [rapid(21.0, -10.0), feed(15.0, -10.0), feed(15.0, -5.0), feed(21.0, -5.0), rapid(25.0, -5.0)]
    _, verdict = run(moves, target=target)
    assert_clean(verdict)


def test_sharp_tool_leaves_nothing():
    result, verdict = run(plunge(-10.0, 15.0), tool=SHARP)
    assert_clean(verdict)
    assert GROOVE.intersection(result.remaining).area < 1e-9
    assert verdict.unreachable.is_empty


def test_reference_plus_corner_program_passes():
    tool = GroovingTool(3.0, 0.4, reference="plus")
    _, verdict = run(plunge(-7.0, 15.0), tool=tool, start=(25.0, -7.0))
    assert_clean(verdict)


# --------------------------------------------------------------------------- (b) gouge


@pytest.mark.parametrize("extra", [0.01, 0.002, 0.3])
def test_plunge_too_deep_is_a_gouge(extra):
    _, verdict = run(plunge(-10.0, 15.0 - extra))
    assert not verdict.ok
    assert verdict.gouge == pytest.approx(extra, abs=1e-4)
    assert "GOUGE" in verdict.describe()
    with pytest.raises(AssertionError, match="GOUGE"):
        assert_clean(verdict)


def test_gouge_within_tolerance_is_not_reported():
    _, verdict = run(plunge(-10.0, 15.0 - 0.0005))
    assert verdict.gouge == 0.0
    assert_clean(verdict)


def test_side_gouge_of_a_misplaced_plunge():
    # The plunge 0.02 too far toward -Z cuts into the groove's -Z wall.
    _, verdict = run(plunge(-10.02, 15.0), start=(25.0, -10.02))
    assert verdict.gouge == pytest.approx(0.02, abs=1e-4)
    assert not verdict.ok


def test_z_traverse_at_depth_with_too_wide_a_move_gouges_the_wall():
    # The reference (-Z) corner moves to Z-9.9: the blade then spans Z-9.9..-6.9.
    moves = plunge(-10.0, 15.0)[:2] + [feed(15.0, -9.9), rapid(21.0, -9.9)]
    _, verdict = run(moves)
    assert verdict.gouge == pytest.approx(0.1, abs=1e-4)


# --------------------------------------------------------------------------- (c) incomplete


@pytest.mark.parametrize("short", [0.05, 0.002, 1.0])
def test_plunge_stopping_short_is_incomplete(short):
    _, verdict = run(plunge(-10.0, 15.0 + short))
    assert not verdict.ok
    assert verdict.incomplete
    assert verdict.gouge == 0.0
    assert verdict.incomplete_depth == pytest.approx(short, abs=1e-4)
    # The strip left: width 3 minus what the fillet allowance excuses.
    assert verdict.incomplete_area == pytest.approx(3.0 * short, rel=0.1, abs=0.01)
    assert "INCOMPLETE" in verdict.describe()


def test_short_within_tolerance_is_complete():
    _, verdict = run(plunge(-10.0, 15.0005))
    assert not verdict.incomplete
    assert_clean(verdict)


def test_untouched_groove_is_incomplete_to_full_depth():
    _, verdict = run([rapid(25.0, -20.0)], start=(25.0, -20.0))
    assert verdict.incomplete
    assert verdict.incomplete_depth == pytest.approx(5.0, abs=1e-3)


def test_island_left_inside_the_groove_is_incomplete():
    # Wide groove: plunges at both ends, but the middle is skipped: a 2 wide
    # island stands in the groove, surrounded by cut space on three sides.
    target = region(15.0, 20.0, -12.0, -2.0)
    moves = plunge(-12.0, 15.0) + plunge(-9.0, 15.0) + plunge(-5.0, 15.0)
    _, verdict = run(moves, target=target, start=(25.0, -12.0))
    assert verdict.incomplete
    # Thickest at the island's foot, between the two plunges' corner arcs
    # (centres 0.4 from the island's sides and from the floor).
    assert verdict.incomplete_depth == pytest.approx(math.hypot(0.9, 0.4) - 0.4, abs=1e-3)
    result = simulate(moves, SHARP, MINUS_X, (25.0, -12.0), STOCK)
    assert check_groove(result, target, SHARP).incomplete_depth == pytest.approx(0.5, abs=1e-4)


def test_missing_floor_pass_is_incomplete():
    target = region(15.0, 20.0, -10.0, -2.0)
    moves = plunge(-10.0, 15.2) + plunge(-7.5, 15.2) + plunge(-5.0, 15.2)
    _, verdict = run(moves, target=target)
    assert verdict.incomplete
    # 0.2 along the floor, a little more where the plunges' corner arcs
    # stand higher than the excused fillets.
    assert 0.2 <= verdict.incomplete_depth < 0.25
    result = simulate(moves, SHARP, MINUS_X, START, STOCK)
    assert check_groove(result, target, SHARP).incomplete_depth == pytest.approx(0.2, abs=1e-4)


# --------------------------------------------------------------------------- (d) rapids


def test_rapid_through_stock_is_reported():
    moves = [rapid(15.0, -10.0)]  # rapid plunge: the whole groove is rapid
    result, verdict = run(moves)
    assert len(result.rapid_collisions) == 1
    c = result.rapid_collisions[0]
    assert c.index == 0 and c.move == moves[0] and c.start == START
    assert c.area == pytest.approx(GROOVE.area - 2 * fillet_area(0.4), abs=2e-3)
    assert not verdict.ok
    assert "RAPID" in verdict.describe()


def test_rapid_through_cut_space_is_not_reported():
    moves = plunge(-10.0, 15.0) + [rapid(15.0, -10.0), rapid(21.0, -10.0)]
    result, verdict = run(moves)
    assert result.rapid_collisions == []
    assert_clean(verdict)


def test_rapid_is_judged_against_the_stock_at_that_moment():
    # The same rapid in and out of the groove, once before and once after
    # cutting it (a rapid removes nothing: the way out collides too).
    moves = [rapid(15.5, -10.0), rapid(21.0, -10.0)] + plunge(-10.0, 15.0) + [rapid(15.5, -10.0), rapid(21.0, -10.0)]
    result, _ = run(moves)
    assert [c.index for c in result.rapid_collisions] == [0, 1]


def test_rapid_sideways_at_depth_into_stock_is_reported():
    moves = plunge(-10.0, 15.0)[:2] + [rapid(15.0, -20.0)]
    result, _ = run(moves)
    assert [c.index for c in result.rapid_collisions] == [2]
    # The blade's side sweeps 10 mm of Z at 5 mm depth.
    assert result.rapid_collisions[0].area == pytest.approx(50.0, abs=0.1)


def test_rapid_touching_the_stock_surface_is_not_a_collision():
    # Traverse in Z with the front edge exactly on the bar's surface.
    result, _ = run([rapid(20.0, -10.0), rapid(20.0, -40.0), rapid(25.0, -40.0)])
    assert result.rapid_collisions == []


def test_rapid_grazing_the_stock_is_a_collision():
    result, _ = run([rapid(19.999, -10.0), rapid(19.999, -40.0), rapid(25.0, -40.0)], tool=SHARP)
    # in 0.001, across 30 (the blade's 3 plus 30 of travel), and out again
    assert [c.index for c in result.rapid_collisions] == [0, 1, 2]
    assert result.rapid_collisions[0].area == pytest.approx(3.0 * 0.001, rel=0.05)
    assert result.rapid_collisions[1].area == pytest.approx(33.0 * 0.001, rel=0.05)


# --------------------------------------------------------------------------- (e) outline


@pytest.mark.parametrize(
    "plunge_dir, reference, bounds",
    [
        # bounds (zmin, xmin, zmax, xmax) for reference corner at X10 Z-5, width 3, length 60
        (MINUS_X, "minus", (-5.0, 10.0, -2.0, 70.0)),
        (MINUS_X, "plus", (-8.0, 10.0, -5.0, 70.0)),
        (PLUS_X, "minus", (-5.0, -50.0, -2.0, 10.0)),
        (PLUS_X, "plus", (-8.0, -50.0, -5.0, 10.0)),
        (MINUS_Z, "minus", (-5.0, 10.0, 55.0, 13.0)),
        (MINUS_Z, "plus", (-5.0, 7.0, 55.0, 10.0)),
        (PLUS_Z, "minus", (-65.0, 10.0, -5.0, 13.0)),
        (PLUS_Z, "plus", (-65.0, 7.0, -5.0, 10.0)),
    ],
)
@pytest.mark.parametrize("radius", [0.0, 0.4])
def test_tool_outline_orientation(plunge_dir, reference, bounds, radius):
    tool = GroovingTool(3.0, radius, reference=reference)
    outline = tool_outline(tool, plunge_dir, 10.0, -5.0)
    assert outline.is_valid
    assert outline.bounds == pytest.approx(bounds, abs=1e-12)
    # The front edge lies on the reference corner's line across the plunge.
    front = {MINUS_X: "x", PLUS_X: "x", MINUS_Z: "z", PLUS_Z: "z"}[plunge_dir]
    coords = shapely.get_coordinates(outline)
    on_front = coords[abs(coords[:, 1 if front == "x" else 0] - (10.0 if front == "x" else -5.0)) < 1e-12]
    across = on_front[:, 0 if front == "x" else 1]
    lo, hi = (bounds[0], bounds[2]) if front == "x" else (bounds[1], bounds[3])
    # (the circumscribed arcs put their first vertex on the front line a
    # little before the tangent point)
    assert lo + 0.98 * radius <= across.min() <= lo + radius + 1e-12
    assert hi - radius - 1e-12 <= across.max() <= hi - 0.98 * radius
    # The reference corner itself is the sharp corner: inside only when r == 0.
    corner = Point(-5.0, 10.0)
    assert outline.buffer(1e-9).contains(corner) == (radius == 0.0)
    assert outline.area == pytest.approx(3.0 * 60.0 - 2 * fillet_area(radius), abs=1e-4)


@pytest.mark.parametrize("radius", [0.05, 0.4, 1.2, 2.9])
def test_corner_arcs_are_circumscribed_and_close(radius):
    w, length = 6.0, 20.0
    tool = GroovingTool(w, radius, length=length)
    outline = tool_outline(tool, MINUS_X, 0.0, 0.0)  # (z, x) = (across, back)
    # The true blade, built from two boxes and two (finely inscribed) disks.
    true = shapely.union_all(
        [
            box(0.0, radius, w, length),
            box(radius, 0.0, w - radius, length),
            Point(radius, radius).buffer(radius, quad_segs=4096),
            Point(w - radius, radius).buffer(radius, quad_segs=4096),
        ]
    )
    assert true.difference(outline).area < 1e-12  # never smaller than the true arc
    assert outline.buffer(-(ARC_EXCESS + 1e-7)).difference(true).is_empty  # nor more than ARC_EXCESS outside
    quarter = (len(shapely.get_coordinates(outline)) - 5) // 2
    assert quarter >= 32


def test_swept_area_of_a_straight_move_is_the_hull():
    tool = GroovingTool(3.0, 0.4)
    hull = swept_area(tool, MINUS_X, (21.0, -10.0), (15.0, -10.0))
    assert hull.bounds == pytest.approx((-10.0, 15.0, -7.0, 81.0))
    diagonal = swept_area(SHARP, MINUS_X, (0.0, 0.0), (1.0, 1.0))
    assert diagonal.area == pytest.approx(3.0 * 60.0 + 3.0 * 1.0 + 60.0 * 1.0)


# --------------------------------------------------------------------------- (f) corner allowance


def test_sharp_target_is_complete_with_a_radiused_tool():
    result, verdict = run(plunge(-10.0, 15.0))
    assert GROOVE.intersection(result.remaining).area > 0.06  # fillets really stand
    assert not verdict.incomplete


def test_target_wider_than_the_program_is_flagged():
    # Same program, but the target is 0.1 wider toward +Z: reachable, not cut.
    _, verdict = run(plunge(-10.0, 15.0), target=region(15.0, 20.0, -10.0, -6.9))
    assert verdict.incomplete
    assert verdict.incomplete_depth == pytest.approx(0.1, abs=1e-3)


def test_fillets_bigger_than_the_tools_radius_are_flagged():
    # Cut with r=0.8 corners but judged for a tool of r=0.4: the extra fillet
    # material is within reach of r=0.4 and must be reported.
    big = GroovingTool(3.0, 0.8)
    result = simulate(plunge(-10.0, 15.0), big, MINUS_X, START, STOCK)
    verdict = check_groove(result, GROOVE, TOOL)
    assert verdict.incomplete
    # thickest at the corner bisector: (r_big - r) * (sqrt 2 - 1) and more, minus tol
    assert 0.1 < verdict.incomplete_depth < 0.4
    assert check_groove(result, GROOVE, big).ok


def test_target_needing_material_beyond_the_tools_reach_is_flagged():
    # Same program; the target adds a 1 wide, 1 deep slot in the floor that
    # the 3 wide blade cannot enter. No program can make it, so the verdict is
    # "infeasible", never ok (a test must not pass on a target the tool
    # cannot make, nor blame the cycle for it).
    target = shapely.union(GROOVE, region(14.0, 15.0, -9.0, -8.0))
    _, verdict = run(plunge(-10.0, 15.0), target=target)
    assert verdict.infeasible and not verdict.ok
    assert verdict.unreachable_depth == pytest.approx(1.0, abs=1e-3)
    assert not verdict.incomplete and verdict.gouge == 0.0
    assert "INFEASIBLE" in verdict.describe()


def test_groove_narrower_than_the_blade_is_infeasible():
    target = region(15.0, 20.0, -10.0, -7.5)  # 2.5 wide, blade 3
    _, verdict = run([], target=target)
    assert verdict.infeasible and not verdict.ok


def test_groove_exactly_as_wide_as_the_blade_is_feasible():
    for tool in (TOOL, SHARP):
        target = region(15.0, 20.0, -10.0, -10.0 + tool.width * (1 - 1e-12))
        unreachable = unreachable_region(target, STOCK, tool, MINUS_X)
        assert unreachable.area == pytest.approx(2 * fillet_area(tool.corner_radius), abs=1e-4)


def test_shallow_groove_leaves_only_the_tools_fillets():
    # Depth 0.5 < corner radius 0.75: the blade's corners hang over the
    # groove's mouth. Plunging at the walls is all a cycle can do.
    tool = GroovingTool(3.0, 0.75)
    target = region(19.5, 20.0, -10.0, -7.0)
    result = simulate(plunge(-10.0, 19.5), tool, MINUS_X, START, STOCK)
    verdict = check_groove(result, target, tool)
    assert_clean(verdict)
    assert verdict.unreachable.area == pytest.approx(target.intersection(result.remaining).area, abs=1e-4)
    # A disk of r=0.75 pivots around the mouth corners and reaches more: the
    # disk model would flag this correct program.
    disk = check_groove(result, target, tool, reach="disk")
    assert disk.incomplete


@pytest.mark.parametrize("radius", [0.0, 0.4, 1.2])
@pytest.mark.parametrize("plunge_dir", PLUNGE_DIRECTIONS)
def test_unreachable_region_of_a_rectangular_groove_is_its_floor_fillets(plunge_dir, radius):
    tool = GroovingTool(3.0, radius)
    target = groove_target(plunge_dir, 15.0, 19.0, 4.0)
    unreachable = unreachable_region(target, TUBE, tool, plunge_dir)
    # (buffers are inscribed polygons: the arcs lose up to r * 7.5e-5 mm)
    assert unreachable.area == pytest.approx(2 * fillet_area(radius), abs=1e-4, rel=1e-3)
    if radius:
        # the fillets sit in the floor corners
        (x0, z0), (x1, z1) = FRAMES[plunge_dir](15.0, 4.0), FRAMES[plunge_dir](19.0, 4.0)
        for corner in (Point(z0, x0), Point(z1, x1)):
            assert unreachable.distance(corner) < 1e-9


def test_disk_model_reaches_a_cap_into_a_slot_narrower_than_its_diameter():
    # A 0.6 wide slot: a disk of r=0.4 dips 0.4 - sqrt(0.4^2 - 0.3^2) into it.
    target = shapely.union(GROOVE, region(14.0, 15.0, -8.8, -8.2))
    reach = reachable_region(target, STOCK, TOOL, MINUS_X, model="disk")
    cap = 0.4 - math.sqrt(0.4**2 - 0.3**2)
    assert reach.intersection(region(14.0, 15.0 - cap - 1e-3, -9.0, -8.0)).area < 1e-9
    assert reach.intersection(region(15.0 - cap + 1e-3, 15.0, -8.5 - 1e-3, -8.5 + 1e-3)).area > 0


# --------------------------------------------------------------------------- bookkeeping


def test_removed_is_stock_minus_remaining_and_dwell_removes_nothing():
    moves = plunge(-10.0, 15.0)
    with_dwell = moves[:2] + [dwell(15.0, -10.0, 0.5)] + moves[2:]
    a, _ = run(moves)
    b, verdict = run(with_dwell)
    assert a.removed.symmetric_difference(b.removed).area < 1e-12
    assert abs(a.removed.area + a.remaining.area - STOCK.area) < 1e-9
    assert verdict.dwell_mismatches == []
    assert b.final == (21.0, -10.0)


def test_dwell_away_from_the_tool_position_is_reported():
    moves = plunge(-10.0, 15.0)
    moves = moves[:2] + [dwell(16.0, -10.0, 0.5)] + moves[2:]
    _, verdict = run(moves)
    assert len(verdict.dwell_mismatches) == 1 and not verdict.ok
    assert "DWELL" in verdict.describe()


def test_unknown_move_kind_is_an_error():
    with pytest.raises(ValueError):
        simulate([Move("G5", 1.0, 2.0)], TOOL, MINUS_X, START, STOCK)
    with pytest.raises(ValueError):
        simulate([feed(float("nan"), 0.0)], TOOL, MINUS_X, START, STOCK)


def test_multipolygon_stock_and_parting_off():
    stock = shapely.union(bar(20.0, -50.0, -30.0), bar(20.0, -20.0, 0.0))
    target = region(0.0, 20.0, -13.0, -10.0)  # part off at Z-13..-10
    moves = [rapid(21.0, -13.0), feed(0.0, -13.0), rapid(21.0, -13.0)]
    result = simulate(moves, SHARP, MINUS_X, (25.0, -13.0), stock)
    assert result.remaining.geom_type == "MultiPolygon" and len(result.remaining.geoms) == 3
    assert_clean(check_groove(result, target, SHARP))


def test_a_long_program_of_pecks_cuts_clean():
    # 20 plunges of 15 pecks (300+ moves). Its speed is a benchmark's (benchmarks/run), not a timed test's.
    moves = []
    for k in range(20):
        z = -40.0 + 1.5 * k
        moves.append(rapid(21.0, z))
        depth = 20.0
        for _ in range(15):
            depth -= 0.33
            moves += [feed(depth, z), rapid(depth + 0.5, z)]
        moves.append(rapid(21.0, z))
    target = region(20.0 - 15 * 0.33, 20.0, -40.0, -40.0 + 1.5 * 19 + 3.0)
    result = simulate(moves, TOOL, MINUS_X, (21.0, -40.0), STOCK)
    verdict = check_groove(result, target, TOOL)
    assert len(moves) > 300
    assert verdict.gouge == 0.0 and not verdict.rapid_collisions


def test_simulate_is_not_imported_by_the_engine():
    # shapely is not bundled with FreeCAD: only verify/ imports it, and the
    # turning check (verify_job) loads it on demand, inside its functions.
    importing = re.compile(r"^\s*(from|import)\s[^#\n]*\b(simulate|shapely)\b", re.M)
    at_import = re.compile(r"^(from|import)\s[^#\n]*\b(simulate|shapely|verify)\b", re.M)
    engine = os.path.join(ROOT, "freecad_groove")
    verify = os.path.join(engine, "verify")
    on_demand = os.path.join(engine, "ops", "turning_check", "check.py")
    for folder, _, files in os.walk(engine):
        if folder == verify or folder.startswith(verify + os.sep):
            continue
        for name in files:
            if name.endswith(".py"):
                path = os.path.join(folder, name)
                text = open(path, encoding="utf-8").read()
                assert not (at_import if path == on_demand else importing).search(text), path
    code = "import sys, freecad_groove.engine; assert 'shapely' not in sys.modules"
    subprocess.run([sys.executable, "-c", code], cwd=ROOT, check=True)


# --------------------------------------------------------------------------- properties

# A generic groove in "groove coordinates": across (a, along the groove's
# width) and depth (d, into the material from the surface). Each plunge
# direction maps them onto (x, z) of a tube with radii 10..30, Z-50..0.
TUBE = bar(30.0, -50.0, 0.0, bore=10.0)
FRAMES = {
    # plunge: (surface, depth sign, across axis), moves map (a, d) -> (x, z)
    MINUS_X: lambda a, d: (30.0 - d, a),  # OD groove, across = Z
    PLUS_X: lambda a, d: (10.0 + d, a),  # bore groove, across = Z
    MINUS_Z: lambda a, d: (a, 0.0 - d),  # face groove in Z0, across = X
    PLUS_Z: lambda a, d: (a, -50.0 + d),  # face groove in Z-50, across = X
}
ACROSS_RANGE = {MINUS_X: (-45.0, -5.0), PLUS_X: (-45.0, -5.0), MINUS_Z: (12.0, 28.0), PLUS_Z: (12.0, 28.0)}


def groove_target(plunge_dir, a0, a1, depth):
    (x0, z0), (x1, z1) = FRAMES[plunge_dir](a0, -5.0), FRAMES[plunge_dir](a1, depth)
    return region(x0, x1, z0, z1)


def groove_program(plunge_dir, tool, a0, a1, depth, extra=0.0, short=0.0):
    """Plunges every <= width across [a0, a1], then a floor pass at depth."""
    at = FRAMES[plunge_dir]
    w = tool.width
    ref = tool.reference_offset  # reference across-coordinate = left edge + ref
    n = max(1, math.ceil((a1 - a0 - w) / (0.8 * w) - 1e-9))
    lefts = [a0 + (a1 - a0 - w) * k / n for k in range(n + 1)] if a1 - a0 > w else [a0]
    moves = []
    for left in lefts:
        moves += [rapid(*at(left + ref, -1.0)), feed(*at(left + ref, depth - 0.1)), rapid(*at(left + ref, -1.0))]
    first, last = lefts[0] + ref, lefts[-1] + ref
    moves += [rapid(*at(first, -1.0)), feed(*at(first, depth + extra - short))]
    moves += [feed(*at(last, depth + extra - short)), feed(*at(last, -1.0)), rapid(*at(last, -3.0))]
    start = at(lefts[0] + ref, -3.0)
    return moves, start


grooves = st.builds(
    lambda plunge_dir, width, rfrac, reference, afrac, wfrac, depth: (
        plunge_dir,
        GroovingTool(width, rfrac * width / 2, reference=reference),
        afrac,
        wfrac,
        depth,
    ),
    st.sampled_from(PLUNGE_DIRECTIONS),
    st.floats(1.0, 6.0),
    st.floats(0.0, 0.8),
    st.sampled_from(["minus", "plus"]),
    st.floats(0.0, 1.0),
    st.floats(0.0, 1.0),
    st.floats(0.5, 8.0),
)


def place(case):
    plunge_dir, tool, afrac, wfrac, depth = case
    lo, hi = ACROSS_RANGE[plunge_dir]
    width = tool.width + wfrac * min(2.5 * tool.width, hi - lo - tool.width)
    a0 = lo + afrac * (hi - lo - width)
    return plunge_dir, tool, a0, a0 + width, depth


def verdict_of_groove(case, **program_options):
    """The oracle's verdict on ``groove_program(case, **program_options)`` in TUBE."""
    plunge_dir, tool, a0, a1, depth = place(case)
    moves, start = groove_program(plunge_dir, tool, a0, a1, depth, **program_options)
    result = simulate(moves, tool, plunge_dir, start, TUBE)
    return check_groove(result, groove_target(plunge_dir, a0, a1, depth), tool)


@given(grooves)
def test_property_correct_groove_programs_pass(case):
    assert_clean(verdict_of_groove(case))


@given(grooves, st.floats(0.003, 0.5))
def test_property_too_deep_floor_is_a_gouge_of_that_size(case, extra):
    verdict = verdict_of_groove(case, extra=extra)
    assert verdict.gouge == pytest.approx(extra, abs=1e-4), verdict.describe()
    assert not verdict.incomplete and not verdict.rapid_collisions, verdict.describe()


@given(grooves, st.floats(0.003, 0.09))
def test_property_short_floor_is_incomplete_by_that_much(case, short):
    verdict = verdict_of_groove(case, short=short)
    assert verdict.incomplete, verdict.describe()
    assert verdict.incomplete_depth == pytest.approx(short, abs=1e-3), verdict.describe()
    assert verdict.gouge == 0.0, verdict.describe()


@given(grooves, st.floats(0.0, 1.0))
def test_property_rapid_plunge_into_the_groove_is_a_collision(case, where):
    plunge_dir, tool, a0, a1, depth = place(case)
    moves, start = groove_program(plunge_dir, tool, a0, a1, depth)
    # Replace the first plunge's feed by a rapid.
    moves[1] = rapid(moves[1].x, moves[1].z)
    result = simulate(moves, tool, plunge_dir, start, TUBE)
    assert [c.index for c in result.rapid_collisions][:1] == [1]


# --------------------------------------------------------------------------- surfaces


SLANTED = shapely.Polygon([(-50.0, 0.0), (0.0, 0.0), (0.0, 20.0), (-50.0, 10.0)])  # top rises 1 in 5 toward +Z


def _on_slant(z):
    return 10.0 + (z + 50.0) / 5.0


def test_skimming_a_slanted_surface_is_neither_gouge_nor_collision():
    # The corner arc rides exactly on a 1:5 slope (tangent): the polygonal
    # arc pokes up to ARC_EXCESS into the stock, which must not count.
    # The +Z front corner rides the slope (the blade reaches down-slope from
    # it, so nothing else touches).
    tool = GroovingTool(3.0, 0.8, reference="plus")
    r = 0.8
    # The arc centre sits r from the contact point along the slope's normal.
    n = (-1.0 / math.hypot(1, 5), 5.0 / math.hypot(1, 5))  # (z, x) unit normal of the slope

    def ref(zc):
        cz, cx = zc + r * n[0], _on_slant(zc) + r * n[1]  # arc centre
        return (cx - r, cz + r)  # (x, z) of the reference corner
    a, b = ref(-40.0), ref(-20.0)
    moves = [rapid(*a), rapid(*b), feed(*a), feed(*b), rapid(30.0, b[1])]
    target = region(5.0, 6.0, -5.0, -2.0)  # elsewhere; nothing of it is cut
    result = simulate(moves, tool, MINUS_X, (30.0, a[1]), SLANTED)
    assert result.rapid_collisions == []
    verdict = check_groove(result, target, tool)
    assert verdict.gouge == 0.0
    assert 0 < result.removed.area < 20.0 * 3 * ARC_EXCESS


def test_a_skim_far_from_the_groove_reports_its_depth_not_its_distance():
    # Feed along the bar's surface 0.01 deep, 20 mm away from the groove.
    moves = plunge(-10.0, 15.0) + [rapid(21.0, -40.0), feed(19.99, -40.0), feed(19.99, -30.0), rapid(21.0, -30.0)]
    _, verdict = run(moves)
    assert verdict.gouge == pytest.approx(0.01, abs=1e-4)
    assert "GOUGE" in verdict.describe()


def test_allow_infeasible_judges_the_program_within_reach():
    target = shapely.union(GROOVE, region(14.0, 15.0, -9.0, -8.0))  # slot the blade cannot enter
    _, verdict = run(plunge(-10.0, 15.0), target=target)
    assert not verdict.ok and verdict.ok_within_reach
    assert_clean(verdict, allow_infeasible=True)
    _, deep = run(plunge(-10.0, 14.99), target=target)  # gouges beside the slot
    with pytest.raises(AssertionError, match="GOUGE"):
        assert_clean(deep, allow_infeasible=True)


@given(grooves)
def test_property_replaying_a_program_at_rapid_through_its_own_cut_is_clean(case):
    # Every FEED of a second pass runs through space the first pass cut.
    plunge_dir, tool, a0, a1, depth = place(case)
    moves, start = groove_program(plunge_dir, tool, a0, a1, depth)
    replay = [rapid(m.x, m.z) for m in moves]
    result = simulate(moves + replay, tool, plunge_dir, start, TUBE)
    assert result.rapid_collisions == []
    assert_clean(check_groove(result, groove_target(plunge_dir, a0, a1, depth), tool))


def test_blade_as_wide_as_a_groove_with_a_rounded_floor_corner():
    # The groove's +Z floor corner is rounded (R0.1, material stays), the
    # blade is as wide as the groove: it can only go down until its sharp
    # corner meets the wall's end, 0.1 above the floor. The rest is out of
    # reach (infeasible), and stopping there is not "incomplete" (the reach
    # model must not let a blade narrowed by float slack slip down the arc).
    corner = shapely.difference(region(15.0, 15.1, -7.1, -7.0), Point(-7.1, 15.1).buffer(0.1, quad_segs=256))
    target = shapely.difference(GROOVE, corner)
    _, verdict = run(plunge(-10.0, 15.1), tool=SHARP, target=target)
    assert verdict.ok_within_reach and verdict.infeasible, verdict.describe()
    assert verdict.unreachable_depth == pytest.approx(0.1, abs=1e-3)
    _, short = run(plunge(-10.0, 15.102), tool=SHARP, target=target)
    assert short.incomplete


# --------------------------------------------------------------------------- robustness
#
# Shapes of generated CYCLE93 grooves (tests/test_cycle93_simulation.py) on
# which the oracle broke, copied here so that the tests do not depend on the
# engine or on hypothesis finding them again. (z, x) as everywhere here.

# CYCLE93(15, 0, 1.5, 0.8, 60, 0, 0.1, 0, 0.16, 0, 0, 0, 0, 0.3, 0, 2, 0), blade
# 1.5 sharp, -Z: a face groove at 60 degrees. The last segment of the R0.16
# arc lies on the flank (1e-15 from it) and the ring runs back along it: a
# zero-width spike. Sweeping it raised "TopologyException: unable to assign
# free hole to a shell" (also when snapped to 1e-9).
SPIKE_STOCK = shapely.Polygon(
    [(-2.0207259421636907, 11.5), (2.933653277111674, 20.081236527748356), (-6.020725942163691, 20.081236527748356),
     (-6.020725942163691, 11.5)]
)
SPIKE_TARGET = shapely.Polygon(
    [(0.0, 15.0), (-0.8, 15.0), (0.06602540378443889, 16.5), (0.7746425228810166, 16.50123677144223),
     (0.78225152861023, 16.501250051675992), (0.7973983405269923, 16.502720652561845),
     (0.8123372375424327, 16.50562202019958), (0.8269333809400229, 16.509927966799832),
     (0.8410550257027134, 16.515599626821697), (0.8545747096455047, 16.52258580777371),
     (0.8673704038911089, 16.53082345227807), (0.8793266143044912, 16.54023820722752),
     (0.890335423944728, 16.55074509489763), (0.9002974671249906, 16.56224927995707),
     (0.9091228262887798, 16.574646925452782), (0.9129273349479831, 16.581236527748356)]
)


def test_reach_past_a_zero_width_spike_in_the_target():
    tool = GroovingTool(1.5, 0.0)
    unreachable = unreachable_region(SPIKE_TARGET, SPIKE_STOCK, tool, MINUS_Z)
    # The blade (as wide as the groove across X) goes down -Z until its front
    # meets the 60 degree flank's upper end at Z0.066: the part of the groove
    # beyond that is out of reach, nothing else.
    beyond = shapely.intersection(SPIKE_TARGET, box(-1.0, 14.0, 0.06602540378443889, 17.0))
    assert shapely.symmetric_difference(unreachable, beyond).area < 1e-6
    assert beyond.area == pytest.approx(0.5 * 1.5 * 0.8660254 - 0.5 * 0.0660254 * 0.0660254 * math.sqrt(3), abs=1e-6)


# CYCLE93(15, 0, 2.56, 0.8, 0, 0, 0, 0, 0.52, 0.6, 0, 0, 0, 0.3, 0, 1, 0), blade
# 2.56 sharp, -X: the floor's -Z corner is rounded R0.6 (material stays), the
# mouth's +Z corner R0.52. What the blade cannot reach is a thin sliver at one
# end, and shapely.segmentize of it (used to find its farthest point) came
# back empty.
SLIVER_STOCK = region(8.08, 15.0, -4.5600000000000005, 7.640000000000001)
SLIVER_TARGET = shapely.Polygon(
    [(0.0, 15.0), (0.0, 14.8)]
    + [(0.6 - 0.6 * math.cos(a), 14.8 - 0.6 * math.sin(a)) for a in [k * math.pi / 64 for k in range(1, 32)]]
    + [(0.6, 14.2), (2.56, 14.2), (2.56, 14.48)]
    + [(3.08 - 0.52 * math.cos(a), 14.48 + 0.52 * math.sin(a)) for a in [k * math.pi / 64 for k in range(1, 32)]]
    + [(3.08, 15.0)]
)
SLIVER_TARGET_GENERATED = shapely.Polygon(
    [(0.0, 15.0), (0.0, 14.8), (0.0007700956973683004, 14.769610498696773), (0.0030784059648628626, 14.73929900680754),
     (0.006919005403133172, 14.709143333497254), (0.012282035248503353, 14.679220887946803),
     (0.019153728680277426, 14.649608480644767), (0.02751644615997062, 14.620382126215985),
     (0.03734872071175177, 14.591616848293107), (0.04862531302786155, 14.563386486932009),
     (0.06131727625755501, 14.535763509065418), (0.0753920303132507, 14.508818822481352),
     (0.0908134455031494, 14.482621593803822), (0.1075419352756341, 14.457239070943125),
     (0.12553455783738082, 14.432736410471403), (0.14474512638432535, 14.409176510366667),
     (0.165124327662528, 14.386619848554588), (0.18661984855458796, 14.365124327662528),
     (0.20917651036666646, 14.344745126384325), (0.23273641047140237, 14.325534557837381),
     (0.2572390709431246, 14.307541935275633), (0.28262159380382235, 14.290813445503149),
     (0.30881882248135156, 14.27539203031325), (0.33576350906541946, 14.261317276257556),
     (0.3633864869320088, 14.248625313027862), (0.3916168482931076, 14.237348720711752),
     (0.4203821262159849, 14.22751644615997), (0.44960848064476766, 14.219153728680277),
     (0.47922088794680384, 14.212282035248503), (0.5091433334972537, 14.206919005403133),
     (0.5392990068075408, 14.203078405964863), (0.5696104986967724, 14.200770095697369),
     (0.5999999999999999, 14.2), (2.56, 14.2), (2.56, 14.48), (2.56, 14.494086445725303),
     (2.5615252495948315, 14.522218019203532), (2.564571274964635, 14.550225759957367),
     (2.569129141592178, 14.578027516457508), (2.575185480469332, 14.605541741361957),
     (2.5827225273106764, 14.632687730708433), (2.591718174659209, 14.659385860632987),
     (2.6021460367313276, 14.685557820920524), (2.613975526810877, 14.711126844702152),
     (2.6271719469652592, 14.73601793362563), (2.641696589820448, 14.760158077838472),
     (2.657506852096386, 14.783476470138407), (2.6745563595697446, 14.80590471366311),
     (2.6927951030975135, 14.82737702250999), (2.712169585302431, 14.847830414697569),
     (2.7326229774900095, 14.867204896902487), (2.75409528633689, 14.885443640430255),
     (2.7765235298615942, 14.902493147903614), (2.7998419221615283, 14.918303410179552),
     (2.8239820663743695, 14.932828053034742), (2.848873155297849, 14.946024473189123),
     (2.874442179079476, 14.957853963268672), (2.900614139367013, 14.96828182534079),
     (2.927312269291568, 14.977277472689323), (2.954458258638043, 14.984814519530667),
     (2.9819724835424926, 14.990870858407822), (3.0097742400426326, 14.995428725035366),
     (3.0377819807964683, 14.998474750405169), (3.065913554274698, 15.0), (3.08, 15.0)]
)


def _lowest_blade_between_two_arcs():
    """Lowest radius the bottom of a 2.56 sharp blade reaches in SLIVER_TARGET:
    its -Z corner must clear the R0.6 floor fillet centred (0.6, 14.8), its
    +Z corner stay inside the R0.52 mouth rounding centred (3.08, 14.48)."""
    def gap(x):  # room for the blade's Z position at bottom radius x
        s_min = 0.6 - math.sqrt(0.36 - (14.8 - x) ** 2)
        s_max = 0.52 - math.sqrt(0.2704 - (x - 14.48) ** 2)
        return s_max - s_min
    lo, hi = 14.49, 14.79  # gap(lo) < 0 < gap(hi)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if gap(mid) < 0 else (lo, mid)
    return hi


@pytest.mark.parametrize("target", [SLIVER_TARGET_GENERATED, SLIVER_TARGET], ids=["generated", "rebuilt"])
def test_farthest_point_of_a_thin_unreachable_sliver(target):
    tool = GroovingTool(2.56, 0.0)
    result = simulate([], tool, MINUS_X, (20.0, 0.0), SLIVER_STOCK)
    verdict = check_groove(result, target, tool)
    assert verdict.incomplete and verdict.infeasible
    # The farthest unreachable point is on the floor (R14.2) under the
    # lowest the blade gets (up to the arcs' chords, 2e-4 inside the circles).
    assert verdict.unreachable_depth == pytest.approx(_lowest_blade_between_two_arcs() - 14.2, abs=1e-3)


# CYCLE93(18.13, 0.01, 2.36, 5.85, 70.7, 0, 0.1, 0, 0.1, 0, 0.46, 0, 0, 0.3, 0, 8,
# 0), blade 2.36 R0.23, +Z: a face groove into a slanted front face. The
# target's mouth edge lies on the stock's face only up to rounding, so the
# plain union of target and air kept a zero-width wall of stock across the
# mouth, which the corner radius's erosion made 0.46 thick: the whole groove
# came out unreachable ("infeasible"), and nothing in it was checked.
CRACK_STOCK = shapely.Polygon(
    [(1.5368502853406727, 22.49), (-2.3702899981809105, 11.332958736878906), (11.58, 11.332958736878906),
     (11.58, 22.49)]
)
CRACK_TARGET = shapely.Polygon(
    [(0.01, 18.13), (5.859999999999999, 18.13), (5.1411876816740385, 16.0773942285036),
     (5.13152469994402, 16.052196265489396), (5.1204006726636075, 16.027608329971255),
     (5.107853887859706, 16.003715051689184), (5.093927530578709, 15.980598669427643),
     (5.078669534246956, 15.958338747956084), (5.06213241568766, 15.937011904173296),
     (5.044373094362126, 15.916691543398048), (5.025452696457445, 15.897447606713776),
     (5.005436344494965, 15.879346330236858), (4.984392933183696, 15.862450017137116),
     (4.96239489229014, 15.846816823195212), (4.9395179373407325, 15.832500556635019),
     (4.915840809014955, 15.819550492919948), (4.89144500212611, 15.808011205150683),
     (4.8664144851225855, 15.797922410648068), (4.840835411075059, 15.789318834249217),
     (4.814795821144403, 15.782230088787355), (4.788385341550941, 15.776680573166777),
     (4.761694875088039, 15.772689388383734), (4.734816288241843, 15.77027027178231),
     (4.707842094994066, 15.769431549771568), (-0.7492341505185041, 15.75990714529891),
     (-0.7554029605746942, 15.759896378683338), (-0.7676443900598952, 15.75835860825954),
     (-0.7796039995424187, 15.755327919436352), (-0.7911004331730871, 15.750850269662969),
     (-0.8019593587141587, 15.744993558144468), (-0.8120161111182056, 15.737846596216407),
     (-0.8211181895134498, 15.729517760607255), (-0.829127569731204, 15.720133350010691),
     (-0.835922797308185, 15.709835669888719), (-0.8414008292253558, 15.698780874547694),
     (-0.8434397128402371, 15.692958736878905)]
)


@pytest.mark.parametrize("model", ["blade", "disk"])
def test_a_target_flush_with_a_slanted_face_is_reached_through_its_mouth(model):
    tool = GroovingTool(2.36, 0.23)
    unreachable = unreachable_region(CRACK_TARGET, CRACK_STOCK, tool, PLUS_Z, model=model)
    # The groove's body (the blade fits it: 2.3606..2.3701 wide) is reached...
    assert shapely.intersection(unreachable, box(-0.5, 15.0, 4.5, 19.0)).area < 1e-6
    if model == "blade":
        # ...and the flat front leaves the wedge of the 70.7 degree floor.
        wedge = shapely.intersection(unreachable, box(4.5, 15.0, 6.0, 19.0))
        assert 1.0 < wedge.area < 1.2
        assert unreachable.area == pytest.approx(wedge.area, abs=1e-3)


# --------------------------------------------------------------------------- Minkowski sum with a segment


def _slow_sum_segment(geom, v):
    """The sum as the union of many translated copies (exact to a step)."""
    n = 100
    return shapely.union_all([shapely.affinity.translate(geom, v[0] * k / n, v[1] * k / n) for k in range(n + 1)])


polygons_with_holes = st.builds(
    lambda radii, hole, clockwise, v: (radii, hole, clockwise, v),
    st.lists(st.floats(1.0, 3.0), min_size=5, max_size=14),
    st.booleans(),
    st.booleans(),
    st.sampled_from([(2.5, 0.0), (0.0, -4.0), (1.5, 1.0), (-0.3, 7.0), (1e-3, 0.0)]),
)


@given(polygons_with_holes)
def test_property_sum_with_a_segment_matches_the_swept_copies(case):
    radii, hole, clockwise, v = case
    n = len(radii)
    ring = [(r * math.cos(2 * math.pi * k / n), r * math.sin(2 * math.pi * k / n)) for k, r in enumerate(radii)]
    ring = ring[::-1] if clockwise else ring  # _sum_segment orients the rings itself
    holes = [[(0.3 * c, 0.3 * s) for c, s in [(math.cos(a), math.sin(a)) for a in (0, 2.1, 4.2)]]]
    geom = shapely.Polygon(ring, holes if hole else None)
    got = reach_module._sum_segment(geom, v)
    assert got.is_valid
    slow = _slow_sum_segment(geom, v)
    # Contains every copy; no larger than the copies by more than the
    # slivers between two steps (|v|/100 times the perimeter).
    assert shapely.difference(slow, got).area < 1e-9
    step = math.hypot(*v) / 100
    assert shapely.difference(got, slow).area <= step * 2 * 3.0 * n + 1e-9


@pytest.mark.parametrize(
    "target, v",
    [
        (SLIVER_TARGET_GENERATED, (0.0, 7.3)),
        (SLIVER_TARGET, (-3.1, 0.0)),
        (shapely.difference(TUBE, GROOVE), (0.7, -2.0)),
        (SPIKE_TARGET, (64.8, 0.0)),
    ],
)
def test_sum_with_a_segment_falls_back_to_a_snapped_union(monkeypatch, target, v):
    plain = reach_module._sum_segment(target, v)
    real = shapely.union_all

    def failing(geoms, grid_size=None, **kwargs):
        if grid_size is None:
            raise shapely.errors.GEOSException("TopologyException: unable to assign free hole to a shell")
        return real(geoms, grid_size=grid_size, **kwargs)

    monkeypatch.setattr(shapely, "union_all", failing)
    snapped = reach_module._sum_segment(target, v)
    assert snapped.is_valid
    if target is SPIKE_TARGET:
        # The plain sum sweeps the zero-width spike too (R16.5746..16.5812),
        # the snapped one drops it: both are the shape swept 64.8 along Z.
        assert plain.area == pytest.approx(target.area + 64.8 * (16.581236527748356 - 15.0), abs=1e-6)
        assert snapped.area == pytest.approx(target.area + 64.8 * (16.574646925452782 - 15.0), abs=1e-6)
        assert shapely.difference(snapped, plain).area < 1e-9
    else:
        assert shapely.symmetric_difference(plain, snapped).area < 1e-8
        assert shapely.hausdorff_distance(plain, snapped) < 1e-10
