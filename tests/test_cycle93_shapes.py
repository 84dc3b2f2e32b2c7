"""CYCLE93: a groove's shape worked out once for every place a program cuts it
(engine/cycles/cycle93_shapes.py, issue 22): a groove of a shape met before,
at another place, has exactly the moves, warnings and errors of the same groove
worked out afresh there (GrooveGeometry built and expanded directly, the reach
warnings computed again)."""

import dataclasses

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from test_cycle93_simulation import grooves

from freecad_groove.engine import CycleError, GroovingTool, MachineState, Settings
from freecad_groove.engine.cycles import cycle93_reach
from freecad_groove.engine.cycles.cycle93 import Cycle93
from freecad_groove.engine.cycles.cycle93_geometry import GrooveGeometry
from freecad_groove.engine.cycles.cycle93_warnings import cycle93_warnings

PLAIN = Cycle93.parse("CYCLE93(35, 0, 10, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 5, 0)")
FEATURED = Cycle93.parse("CYCLE93(35, 0, 10, 6, 0, 10, 15, 0.5, 0.5, -1, -1, 0.3, 0.2, 2, 0.5, 5, 0)")
SETTINGS = Settings(tool=GroovingTool(3.0, 0.4))


def fresh(call, state, settings):
    """(moves, warning texts) of ``call`` worked out from nothing: no geometry, plan or warning kept."""
    geo = GrooveGeometry(call, settings, state.metric)
    cycle93_reach._REACH_CACHE.clear()
    return geo.expand(state.x, state.z), [w.text for w in cycle93_warnings(geo)]


def kept(call, state, settings):
    return call.expand(state, settings), [w.text for w in call.warnings(state, settings)]


def start_beside(call, settings, du, dv):
    """A start point outside the part beside the groove's start side, (du, dv) further in its frame."""
    geo = GrooveGeometry(call, settings, True)
    lo, hi = geo.opening(geo.final_top)
    u = lo - settings.tool.width - 4.0 + du
    v = max(geo.contour_top(u), geo.contour_top(hi)) + 3.0 + dv
    x, z = geo.frame.blade(u, v)
    return MachineState(x=x, z=z, feed=0.1, feed_per_rev=False)


@pytest.mark.parametrize("call", [PLAIN, FEATURED], ids=["plain", "featured"])
def test_a_groove_cut_again_along_the_shaft_has_the_moves_and_warnings_worked_out_there(call):
    for k in range(12):
        placed = dataclasses.replace(call, axsa=-k * 40.3, axfa=35.0 + 0.1 * (k % 3))
        state = MachineState(x=40.0 + 0.1 * (k % 3), z=placed.axsa + 5.0, feed=0.2, feed_per_rev=True)
        assert kept(placed, state, SETTINGS) == fresh(placed, state, SETTINGS)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])
@given(grooves(), st.decimals("-500", "500", places=3).map(float), st.decimals("-30", "30", places=3).map(float),
       st.sampled_from([0.0, 1.5]))
def test_generated_grooves_placed_elsewhere_have_the_moves_and_warnings_worked_out_there(case, dz, dx, du):
    call, tool = case
    settings_ = Settings(tool=tool)
    try:
        call.validate(settings_)
    except CycleError:
        assume(False)
    kept(call, start_beside(call, settings_, du, 0.0), settings_)  # the shape and a plan are kept
    moved = dataclasses.replace(call, axsa=call.axsa + dz, axfa=call.axfa + dx)
    for state in (start_beside(moved, settings_, du, 0.0), start_beside(moved, settings_, du + 0.25, 0.5)):
        assert kept(moved, state, settings_) == fresh(moved, state, settings_)


def test_a_start_inside_the_part_at_the_second_place_is_refused_in_world_coordinates():
    state = MachineState(x=40.0, z=5.0, feed=0.2, feed_per_rev=True)
    kept(PLAIN, state, SETTINGS)
    moved = dataclasses.replace(PLAIN, axsa=-80.0)
    inside = MachineState(x=30.0, z=-82.0, feed=0.2, feed_per_rev=True)
    with pytest.raises(CycleError) as got:
        moved.expand(inside, SETTINGS)
    with pytest.raises(CycleError) as expected:
        GrooveGeometry(moved, SETTINGS, True).expand(inside.x, inside.z)
    assert got.value.message == expected.value.message
    assert "X30 Z-82" in got.value.message


def test_a_start_point_too_large_to_write_is_refused_for_a_shape_met_before():
    PLAIN.validate(SETTINGS)
    with pytest.raises(CycleError) as got:
        dataclasses.replace(PLAIN, axsa=-2e6).validate(SETTINGS)
    assert "AXSA" in got.value.message and "less than" in got.value.message
