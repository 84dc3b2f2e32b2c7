"""CYCLE93: the material a flat blade cannot reach is reported (issue 9 item 2,
engine/cycles/cycle93_reach.py), and it is exactly what the simulation of the
expanded moves leaves standing; on steep contours, held against an independent
model of the blade's reach (tests/blade_oracle.py, issue 20 item 4): nothing a
blade reaches is left, and the warning is what no placement of it reaches."""

import dataclasses

import pytest
from blade_oracle import blade_reach
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from shapely.geometry import LineString, Polygon
from test_cycle93_simulation import SEED_CALL, grooves, simulated

from freecad_groove import verify as sim
from freecad_groove.engine import CycleError, GroovingTool, MachineState, Settings
from freecad_groove.engine.cycles import cycle93
from freecad_groove.engine.cycles.cycle93 import Cycle93
from freecad_groove.engine.cycles.cycle93_reach import REACH_TOLERANCE_MM, unreachable_regions

SEED = Cycle93.parse(SEED_CALL)
START = MachineState(x=40.0, z=65.0, feed=0.2, feed_per_rev=True)


def texts(call, tool, state=START):
    return [w.text for w in call.warnings(state, Settings(tool=tool)) if w.parameter in ("RCI1", "RCI2")]


def test_seed_example_with_a_5_mm_blade_reports_the_wedge_at_base_corner_2():
    # The oblique base (ANGC 12) runs down into the chamfer RCI2 -2: the flat
    # blade rests on both and leaves the wedge between; the chamfer's own
    # corners leave the blade's r0.4 at base corner 1.
    assert texts(SEED, GroovingTool(5.0, 0.4)) == [
        "CYCLE93: 0.0023 mm² up to 0.03 mm deep at base corner 1 cannot be reached by a 5 mm flat blade (r0.4)",
        "CYCLE93: 1.49 mm² up to 0.68 mm deep at base corner 2 cannot be reached by a 5 mm flat blade (r0.4)",
    ]
    (warning,) = [w for w in SEED.warnings(START, Settings(tool=GroovingTool(5.0, 0.4))) if "corner 2" in w.text]
    assert (warning.cycle, warning.parameter) == ("CYCLE93", "RCI2")


def test_seed_example_with_a_3_mm_blade_leaves_a_smaller_wedge():
    assert texts(SEED, GroovingTool(3.0, 0.4))[1] == (
        "CYCLE93: 0.44 mm² up to 0.37 mm deep at base corner 2 cannot be reached by a 3 mm flat blade (r0.4)")
    (wedge,) = [r for r in unreachable_regions(SEED.geometry(Settings(tool=GroovingTool(3.0, 0.4))))
                if r.area > 0.1]
    assert wedge.corner == 2 and wedge.depth == pytest.approx(0.3694, abs=5e-4)


@pytest.mark.parametrize("call, tool", [
    ("CYCLE93(35, 60, 10, 4, 0, 0, 0, 0, 0, 0.4, 0.4, 0, 0, 2, 0, 5, 0)", GroovingTool(3.0, 0.4)),  # RCI = r
    ("CYCLE93(35, 60, 10, 4, 0, 0, 0, 0, 0, 1.5, 2, 0, 0, 2, 0, 5, 0)", GroovingTool(3.0, 0.4)),  # RCI > r
    ("CYCLE93(35, 60, 10, 4, 0, 10, 20, 1, -1, 0.5, 0.6, 0.1, 0.1, 2, 0, 1, 0)", GroovingTool(3.0, 0.4)),
    ("CYCLE93(35, 60, 10, 4, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 5, 0)", GroovingTool(3.0, 0.0)),  # sharp blade
    ("CYCLE93(35, 60, 10, 4, 90, 0, 0, 0, 0, 0.5, 0.5, 0, 0, 2, 0, 2, 0)", GroovingTool(3.0, 0.3)),  # face
])
def test_a_groove_whose_corners_the_blade_reaches_has_no_warning(call, tool):
    assert texts(Cycle93.parse(call), tool) == []


def test_a_base_radius_smaller_than_the_blades_leaves_material():
    call = Cycle93.parse("CYCLE93(35, 60, 10, 4, 0, 0, 0, 0, 0, 0.2, 0, 0, 0, 2, 0, 5, 0)")
    assert texts(call, GroovingTool(3.0, 0.4)) == [
        "CYCLE93: 0.03 mm² up to 0.20 mm deep at base corner 1 cannot be reached by a 3 mm flat blade (r0.4)",
        "CYCLE93: 0.03 mm² up to 0.40 mm deep at base corner 2 cannot be reached by a 3 mm flat blade (r0.4)",
    ]


def test_inch_program_says_square_inches_and_inches():
    call = Cycle93.parse("CYCLE93(1.4, 2.4, 1.2, 1, 12, 15, 16, 0, 0, -0.08, -0.08, 0.04, 0.04, 0.4, 0, 5, 0)")
    state = MachineState(x=1.6, z=2.6, feed=0.008, feed_per_rev=True, metric=False)
    (text,) = [t for t in texts(call, GroovingTool(0.2, 0.0), state)]
    # The seed at 1/25 scale with a 0.2 in (5.08 mm) sharp blade: 4 decimals in inches.
    assert text == ("CYCLE93: 0.0031 in² up to 0.0314 in deep at base corner 2 cannot be reached by a 0.2 in flat "
                    "blade (r0)")


@pytest.mark.parametrize("call, tool", [
    # ANGC 6.1 into a large edge radius RCO1 on the opening's lower edge: the passes used to start with the blade's
    # flat on the radius' top and left 1.4 um there (0.000047 mm², reported at edge corner 1).
    ("CYCLE93(29.02, 10.84, 11.11, 6.37, 6.1, 19, 0, 0.97, 0, 0, -1.12, 0.2, 0, 3.46, 0, 11, 0)",
     GroovingTool(2.39, 0.37)),
    # A steep face contour (ANGC 149.4) past an edge radius RCO1 0.19: 0.02 mm (0.00091 mm²) was left between the
    # contour line and the radius, that only a blade overhanging the edge reaches with its rounded corner.
    ("CYCLE93(30, 10, 5.55, 4.28, 149.4, 0, 9.1, 0.19, 0, -0.71, -0.31, 0, 0, 2, 0, 6, 0)", GroovingTool(3.7, 0.45)),
])
def test_an_edge_radius_on_the_lower_edge_of_an_oblique_contour_is_rolled_over(call, tool):
    # Overhanging the edge, the blade's corner rolls down the radius to the contour line: nothing is left there,
    # and no warning names the edge.
    call = Cycle93.parse(call)
    assert [w.parameter for w in call.warnings(START, Settings(tool=tool))] == ["RCI1", "RCI2"]
    assert_left_is_what_is_warned(call, tool)


def test_a_program_line_builds_its_groove_once_for_validation_moves_and_warnings(monkeypatch):
    # The translator validates, expands and asks for the warnings of each call: one geometry serves all three
    # (the reach warning works on the envelope the expansion traced), and the same call again builds none.
    from freecad_groove.engine.translator import translate_program
    built = []

    class Counted(cycle93.GrooveGeometry):
        def __init__(self, *args):
            built.append(args[0])
            super().__init__(*args)

    monkeypatch.setattr(cycle93, "GrooveGeometry", Counted)
    # A groove no other test has built.
    program = "S500 M3\nG95 G90 F0.2\nG0 X80 Z65\n%s\nM2\n" % SEED_CALL.replace("30, 25, 12,", "30, 25.25, 12,")
    settings_ = Settings(tool=GroovingTool(5.0, 0.4))
    warnings = []
    text = translate_program(program, "sinumerik", settings_, warnings=warnings)
    assert len(built) == 1 and [w.parameter for _line, w in warnings] == ["RCI1", "RCI2"]
    assert translate_program(program, "sinumerik", settings_) == text
    assert len(built) == 1


def test_small_noise_is_not_reported():
    # The arcs of a large base radius are chords in the profile: the blade's
    # corner resting on them must not warn.
    call = Cycle93.parse("CYCLE93(35, 60, 30, 10, 0, 0, 0, 0, 0, 2, 2, 0, 0, 5, 0, 5, 0)")
    assert unreachable_regions(call.geometry(Settings(tool=GroovingTool(5.0, 0.4)))) == []
    assert REACH_TOLERANCE_MM == 0.001


# ---------------------------------------------------------------- against the simulation


def _band(geo, u_from, u_to):
    """The columns u_from..u_to of the groove frame, as a shapely (z, x) polygon."""
    vs = [v for _u, v in geo.final_top]
    lo, hi = min(vs) - 5.0, max(vs) + 5.0
    return Polygon([(z, x) for x, z in (geo.frame.point(u, v) for u, v in
                                         ((u_from, lo), (u_to, lo), (u_to, hi), (u_from, hi)))])


def _thickness(geo, left, u):
    """Length of the plunge-axis line at column u through ``left`` (shapely (z, x))."""
    vs = [v for _u, v in geo.final_top]
    a, b = geo.frame.point(u, min(vs) - 5.0), geo.frame.point(u, max(vs) + 5.0)
    return left.intersection(LineString([(a[1], a[0]), (b[1], b[0])])).length


def _off_steps(geo, u):
    """u, or 1e-6 beside it on the low side of a vertical step of the final profile there."""
    points = geo.final_env.points
    for (u1, v1), (u2, v2) in zip(points, points[1:]):
        if u1 == u2 and abs(u - u1) < 1e-9:
            return u1 + (1e-6 if v2 < v1 else -1e-6)
    return u


def assert_left_is_what_is_warned(call, tool, tol=0.001):
    """The material the simulated moves leave in the finished groove is the
    reported regions, area for area and depth for depth, and nothing else
    thicker than tol."""
    result, target, geo, _moves = simulated(call, tool)
    left = result.remaining.intersection(target)
    regions = unreachable_regions(geo)
    label = (call.emit(), tool)
    for region in regions:
        band = _band(geo, region.u_from, region.u_to)
        assert left.intersection(band).area == pytest.approx(region.area, abs=0.005 + 0.02 * region.area), (
            region, label)
        # Just inside: at a wall's own column the line would run along the wall (at the region's ends, or a
        # vertical step inside it: then on the step's low side, where the depth is).
        at = min(max(_off_steps(geo, region.at), region.u_from + 1e-6), region.u_to - 1e-6)
        # Deepest at a wall, under the blade's corner: there the gap falls with the square root of the distance
        # from the wall, which the simulated blade's polygon (chords of its corners) does not resolve.
        slack = 0.003 if at == region.at else 0.01
        assert _thickness(geo, left, at) == pytest.approx(region.depth, abs=slack), (region, label)
    rest = left
    for region in regions:
        rest = rest.difference(_band(geo, region.u_from - tol, region.u_to + tol))
    thick = rest.buffer(-tol / 2)
    assert thick.is_empty or thick.area < 1e-9, (call.emit(), tool, thick.bounds)


@pytest.mark.parametrize("tool", [GroovingTool(5.0, 0.4), GroovingTool(3.0, 0.4), GroovingTool(3.0, 0.0)])
def test_seed_example_leaves_exactly_what_is_reported(tool):
    assert_left_is_what_is_warned(SEED, tool)


def test_face_groove_at_angc_45_leaves_exactly_what_is_reported():
    call = Cycle93.parse(SEED_CALL.replace("30, 25, 12,", "30, 25, 45,").replace(", 5, 0)", ", 2, 0)"))
    (wedge,) = [r for r in unreachable_regions(call.geometry(Settings(tool=GroovingTool(5.0, 0.4))))
                if r.area > 1]
    assert (wedge.corner, round(wedge.depth, 2), round(wedge.area, 2)) == (1, 2.27, 6.9)
    assert_left_is_what_is_warned(call, GroovingTool(5.0, 0.4))


@pytest.mark.parametrize("call, tool", [
    # A chamfer at base corner 2 running straight into an edge radius: the blade's corner leaves a sliver.
    ("CYCLE93(15, 0, 3.42, 0.8, 0, 0, 19.9, 0, 1, 0, -0.1, 0, 0, 0.3, 0, 13, 0)", GroovingTool(3.42, 0.4)),
    # As wide as a sharp blade, with a base chamfer: the blade cannot get past it and leaves the whole floor.
    ("CYCLE93(15, 0, 1.5, 0.8, 0, 0, 0, 0.1, 0.7, -0.39, 0, 0, 0, 0.3, 0, 3, 0)", GroovingTool(1.5, 0.0)),
    # Steep contours (ANGC 152, 88.8): the corner's material stops at the contour line, the stock's top.
    ("CYCLE93(30.31, 9.26, 4.57, 2.12, 152, 0, 23.6, 0.1, 0.1, 1.15, 0, 0, 0.12, 0.34, 0, 12, 2)",
     GroovingTool(3.0, 0.0, reference="plus")),
    ("CYCLE93(23.55, 0.15, 2.3, 7.83, 88.8, 0, 0, 0.32, -0.1, 0, 0, 0, 0, 0.3, 0, 15, 0)",
     GroovingTool(1.8, 0.05, reference="plus")),
    # Exactly the blade's width between two walls: only the blade flush with both reaches the floor.
    ("CYCLE93(15, 0, 3.57, 0.8, 0, 0, 0, 0.1, 0, 0, 0, 0, 0, 0.3, 0, 11, 0)", GroovingTool(3.57, 0.05)),
    # Stuck positions the search over the arcs' chords missed (the exact envelope's kinks find them): a base
    # chamfer beside an edge radius; steep contours with large edge radii (RCO1) rolled over by the blade.
    ("CYCLE93(32.81, 5.74, 7.71, 6.91, 0, 0, 0, 0, 0.27, 0, -1.06, 0, 0.27, 2.8, 0, 13, 2)",
     GroovingTool(3.84, 0.26, reference="plus")),
    ("CYCLE93(32.91, 1.24, 6.33, 6.94, 146.2, 0, 11.7, 1.2, -0.92, 0, 0, 0.1, 0, 1.72, 0, 17, 0)",
     GroovingTool(3.68, 0.21, reference="plus")),
    ("CYCLE93(36.05, -3.69, 5.83, 7.44, 66.5, 9.9, 0, 0.44, 0, 0.51, 0.9, 0.22, 0.48, 3.53, 0, 15, 0)",
     GroovingTool(1.55, 0.18, reference="plus")),
    ("CYCLE93(21.96, -5.69, 12.36, 6.17, 56.3, 0, 0, 0.99, -0.8, 0.37, 0, 0, 0.35, 2.84, 0, 6, 0)",
     GroovingTool(3.89, 0.42, reference="plus")),
    ("CYCLE93(37.31, 3.46, 4.32, 4.58, 73.5, 0, 13.6, 0.54, 0, 0.33, -0.93, 0, 0.31, 2.38, 0, 3, 2)",
     GroovingTool(1.88, 0.48)),
    # Deepest at a paraxial flank inside the region (a steep contour cuts the flank short): measured beside it.
    ("CYCLE93(24.23, -7.02, 4.85, 4.23, 134, 0, 1.3, 1.07, 0, 0, 0, 0.41, 0.18, 3.16, 0, 13, 0.3)",
     GroovingTool(3.82, 0.69, reference="plus")),
])
def test_found_by_generated_grooves_leaves_exactly_what_is_reported(call, tool):
    assert_left_is_what_is_warned(Cycle93.parse(call), tool)


@settings(derandomize=True, database=None, max_examples=160, deadline=None,
          suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])
@given(grooves())
def test_generated_grooves_leave_exactly_what_is_warned(case):
    # Strict, over the whole generated range (every TYP, ANGC 0..180, radii, chamfers, allowances), with a fixed
    # seed: whatever the simulated moves leave thicker than the tolerance is a reported region, area for area and
    # depth for depth (the chord search this replaced missed slivers at edge radii and chamfers in 0-2 of 80).
    call, tool = case
    try:
        call.validate(Settings(tool=tool))
    except CycleError:
        assume(False)  # validation's own tests cover refusals
    assert_left_is_what_is_warned(call, tool)


# ---------------------------------------------------------------- against an independent model of the reach


def assert_cuts_what_a_blade_reaches(call, tool, thick=0.01):
    """The simulated moves (rs274 reads them back the same) gouge nothing, rapid
    into no stock, leave nothing thicker than ``thick`` that a placement of the
    blade reaches (blade_oracle: over the opening or overhanging its edges), and
    the warned area is what no placement reaches (the oracle's grid, STEP mm
    across, misses a wall by up to a step: the slack)."""
    result, _target, geo, _moves = simulated(call, tool)
    stock = Polygon([(z, x) for x, z in geo.stock_world()])
    target = Polygon([(z, x) for x, z in geo.region_world(1e-5)]).buffer(0)
    verdict = sim.check_groove(result, target, tool, tol=0.001, plunge=call.plunge_direction(), label=call.emit())
    assert not verdict.gouged and not verdict.rapid_collisions, verdict.describe()
    _reachable, unreachable = blade_reach(stock, target, tool.width, tool.corner_radius, call.plunge_direction())
    left = result.remaining.intersection(target).difference(unreachable)
    core = left.buffer(-thick / 2)
    assert core.is_empty or core.area < 1e-9, (call.emit(), tool, core.bounds)
    warned = sum(region.area for region in unreachable_regions(geo))
    assert warned == pytest.approx(unreachable.area, abs=0.02 + 0.01 * unreachable.area), (call.emit(), tool)


def test_a_steep_contour_is_cut_where_the_blade_overhangs_the_lower_edge():
    # Issue 20 item 4: ANGC 60, a 3 mm r0.2 blade. The contour falls away past the opening's lower edge, so a
    # blade overhanging it reaches down to that edge's level: the warning was 5.55 mm² and 2.95 mm² (1.7 mm thick)
    # of it was left where the blade reaches. Now the plunges and passes run out over the edge, and the warning is
    # the wedge below the edge's level between the base and the flank.
    call = Cycle93.parse("CYCLE93(20, -10, 6, 3, 60, 0, 0, 0, 0, 0, 0, 0.2, 0.2, 2, 0, 5, 0)")
    tool = GroovingTool(3.0, 0.2)
    state = MachineState(x=80.0, z=10.0, feed=0.1)
    assert [w.text for w in call.warnings(state, Settings(tool=tool))][-1] == (
        "CYCLE93: 2.60 mm² up to 3.00 mm deep at base corner 2 cannot be reached by a 3 mm flat blade (r0.2)")
    assert call.geometry(Settings(tool=tool)).plunge_positions()[-1] > 3.0  # past the 6 - 3 the flanks allow
    assert_cuts_what_a_blade_reaches(call, tool)
    assert_left_is_what_is_warned(call, tool)


@st.composite
def steep_grooves(draw):
    """grooves() on a contour 45 to 80 degrees off the groove's own axis, either way: ANGC 45..135 for a
    longitudinal groove, 10..45 and 135..170 for a face groove (its contour runs along X)."""
    call, tool = draw(grooves())
    tilt = draw(st.decimals("45", "80", places=1).map(float))
    longitudinal = call.kind()[0]
    angc = draw(st.sampled_from([tilt, 180 - tilt] if longitudinal else [90 - tilt, 90 + tilt]))
    return dataclasses.replace(call, angc=angc, idep=max(call.idep, 1.0)), tool


@settings(derandomize=True, database=None, max_examples=40, deadline=None,
          suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])
@given(steep_grooves())
def test_generated_steep_grooves_leave_nothing_a_blade_reaches_and_warn_the_rest(case):
    call, tool = case
    try:
        call.validate(Settings(tool=tool))
    except CycleError:
        assume(False)  # validation's own tests cover refusals
    assert_cuts_what_a_blade_reaches(call, tool)
    assert_left_is_what_is_warned(call, tool)
