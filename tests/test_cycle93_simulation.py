"""CYCLE93 proven by material removal: sweep the blade along every expanded
move over the part and check no gouge, a complete groove and no rapid into
stock, for the seed example and for generated grooves of every TYP.

A flat-fronted blade cannot reach into every corner of every CYCLE93 profile
(a V where an oblique base meets a chamfer, a base radius smaller than the
blade's own): the oracle works out what the blade can reach and judges the
program on that (allow_infeasible), while gouges and rapids are judged
everywhere."""

from cycle93_helpers import PLUNGE_AXIS, assert_reentries, chip_breaks
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from rs274 import canonical_matches, require_rs274, run_rs274, written_moves
from shapely.geometry import Polygon

from freecad_groove import verify as sim
from freecad_groove.engine import CycleError, GroovingTool, MachineState, Settings
from freecad_groove.engine.cycles.cycle93 import Cycle93
from freecad_groove.engine.cycles.cycle93_constants import REENTRY_CLEARANCE_MM
from freecad_groove.engine.output.program import write_program

SEED_CALL = "CYCLE93(35, 60, 30, 25, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0)"


def run(call, tool, start=None, interpreter=True):
    """Expand, simulate and judge one groove; returns (verdict, moves).

    The moves are also written as a LinuxCNC program and read back by
    LinuxCNC's own interpreter: rs274 must accept it, and its canonical moves
    must be the moves the oracle simulates."""
    result, target, _geo, moves = simulated(call, tool, start, interpreter)
    return sim.check_groove(result, target, tool, tol=0.001, plunge=call.plunge_direction(), label=call.emit()), moves


def simulated(call, tool, start=None, interpreter=True):
    """Expand and simulate one groove: (SimulationResult, target, geometry, moves)."""
    settings = Settings(tool=tool)
    geo = call.geometry(settings)
    if start is None:
        # Outside the part beside the groove's start side, above the contour.
        lo, hi = geo.opening(geo.final_top)
        u = lo - tool.width - 4.0
        v = max(geo.contour_top(u), geo.contour_top(hi)) + 3.0
        start = geo.frame.blade(u, v)
    state = MachineState(x=start[0], z=start[1], feed=0.1, feed_per_rev=False)
    moves = call.expand(state, settings)
    if interpreter:
        require_rs274()
        canon = run_rs274(write_program(moves, "linuxcnc", state))
        problems = canonical_matches(written_moves(moves), canon, start=1, trailing=True)
        assert not problems, "\n".join(problems[:5])
    stock = Polygon([(z, x) for x, z in geo.stock_world()])
    target = Polygon([(z, x) for x, z in geo.region_world()]).buffer(0)
    result = sim.simulate(moves, tool, call.plunge_direction(), start, stock)
    return result, target, geo, moves


def test_seed_example_cuts_the_groove_exactly():
    verdict, moves = run(Cycle93.parse(SEED_CALL), GroovingTool(3.0, 0.4), start=(40.0, 65.0))
    sim.assert_clean(verdict, allow_infeasible=True)
    assert moves[-1].x == 40.0 and moves[-1].z == 65.0
    # Everything but the corners a flat blade cannot enter is cut.
    assert verdict.unreachable.area < 0.5


def reentries_checked(call, tool, moves):
    """The chip-break re-entries of a metric expansion, checked (see
    cycle93_helpers.assert_reentries); returns how many there were."""
    vrt = call.geometry(Settings(tool=tool)).params["VRT"]
    return assert_reentries(moves, call.plunge_direction(), vrt, min(vrt, REENTRY_CLEARANCE_MM))


def test_seed_example_reenters_after_each_chip_break_without_a_rapid_into_stock():
    # The seed's plunges break the chip 30 times (up to 3 infeeds of at most
    # IDEP 10 each): each re-entry rapid runs down the slot just cut, and
    # with no skin at all (rapid_skin 0) none touches standing stock.
    call, tool = Cycle93.parse(SEED_CALL), GroovingTool(3.0, 0.4)
    verdict, moves = run(call, tool, start=(40.0, 65.0))
    assert reentries_checked(call, tool, moves) == 30
    geo = call.geometry(Settings(tool=tool))
    stock = Polygon([(z, x) for x, z in geo.stock_world()])
    exact = sim.simulate(moves, tool, call.plunge_direction(), (40.0, 65.0), stock, rapid_skin=0.0)
    reentry = {i + 2 for i in chip_breaks(moves, call.plunge_direction(), 1.0)}
    assert not [c for c in exact.rapid_collisions if c.index in reentry]


def test_oracle_catches_a_reentry_rapid_below_the_depth_reached():
    # The proof must be able to fail: send every re-entry rapid 0.2 below the
    # depth reached instead of 0.1 above it, into stock the blade has not cut.
    call, tool = Cycle93.parse(SEED_CALL), GroovingTool(3.0, 0.4)
    settings_ = Settings(tool=tool)
    geo = call.geometry(settings_)
    moves = call.expand(MachineState(x=40.0, z=65.0), settings_)
    axis, sign = PLUNGE_AXIS[call.plunge_direction()]
    breaks = chip_breaks(moves, call.plunge_direction(), 1.0)
    deep = list(moves)
    for i in breaks:
        deep[i + 2] = deep[i + 2]._replace(**{axis: getattr(moves[i], axis) + sign * 0.2})
    stock = Polygon([(z, x) for x, z in geo.stock_world()])
    result = sim.simulate(deep, tool, call.plunge_direction(), (40.0, 65.0), stock)
    assert {c.index for c in result.rapid_collisions} == {i + 2 for i in breaks}


def test_seed_example_with_a_sharp_tool_and_the_other_reference_corner():
    tool = GroovingTool(4.0, 0.0, reference="plus")
    verdict, _ = run(Cycle93.parse(SEED_CALL), tool, start=(40.0, 69.0))
    sim.assert_clean(verdict, allow_infeasible=True)


def test_oracle_catches_a_program_that_stops_short():
    # The proof must be able to fail: drop the finishing passes' deepest
    # moves and the oracle reports the groove incomplete.
    call = Cycle93.parse(SEED_CALL)
    tool = GroovingTool(3.0, 0.4)
    settings = Settings(tool=tool)
    geo = call.geometry(settings)
    moves = call.expand(MachineState(x=40.0, z=65.0), settings)
    lowest = min(m.x for m in moves)
    lifted = [m._replace(x=max(m.x, lowest + 0.05)) for m in moves]
    stock = Polygon([(z, x) for x, z in geo.stock_world()])
    target = Polygon([(z, x) for x, z in geo.region_world()]).buffer(0)
    verdict = sim.check_groove(sim.simulate(lifted, tool, call.plunge_direction(), (40.0, 65.0), stock), target, tool)
    assert verdict.incomplete and not verdict.ok


corner = st.one_of(
    st.just(0.0), st.decimals("0.1", "1.2", places=2).map(float), st.decimals("-1.2", "-0.1", places=2).map(float)
)


@st.composite
def grooves(draw):
    typ = draw(st.sampled_from(list(range(1, 9)) + list(range(11, 19))))
    longitudinal = typ % 10 in (1, 3, 5, 7)
    width = draw(st.decimals("1.5", "4", places=2).map(float))
    radius = draw(st.one_of(st.just(0.0), st.decimals("0.05", "0.6", places=2).map(float)))
    assume(radius < width / 2 - 0.1)
    tool = GroovingTool(width, radius, reference=draw(st.sampled_from(["minus", "plus"])))
    # The seed's whole ANGC range (a contour square to the groove's axis is refused: assume() skips it).
    angc = draw(st.one_of(st.just(0.0 if longitudinal else 90.0), st.decimals("0", "180", places=1).map(float)))
    depg = draw(st.decimals("0.8", "8", places=2).map(float))
    call = Cycle93(
        axfa=draw(st.decimals("15", "40", places=2).map(float)),
        axsa=draw(st.decimals("-20", "20", places=2).map(float)),
        widg=width + draw(st.decimals("0", "10", places=2).map(float)),
        depg=depg,
        angc=angc,
        ang1=draw(st.one_of(st.just(0.0), st.decimals("0", "30", places=1).map(float))),
        ang2=draw(st.one_of(st.just(0.0), st.decimals("0", "30", places=1).map(float))),
        rco1=draw(corner), rco2=draw(corner), rci1=draw(corner), rci2=draw(corner),
        fal1=draw(st.one_of(st.just(0.0), st.decimals("0.05", "0.5", places=2).map(float))),
        fal2=draw(st.one_of(st.just(0.0), st.decimals("0.05", "0.5", places=2).map(float))),
        idep=draw(st.decimals("0.3", "4", places=2).map(float)),
        dwt=draw(st.sampled_from([0.0, 0.5])),
        typ=typ,
        vrt=draw(st.sampled_from([0.0, 0.3, 2.0])),
    )
    return call, tool


@settings(suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])
@given(grooves())
def test_generated_grooves_are_cut_without_gouge_leftover_or_rapid_into_stock(case):
    call, tool = case
    try:
        call.validate(Settings(tool=tool))
    except CycleError:
        assume(False)  # validation's own tests cover refusals
    verdict, moves = run(call, tool)
    sim.assert_clean(verdict, allow_infeasible=True)
    reentries_checked(call, tool, moves)


@settings(suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])
@given(grooves())
def test_the_counted_size_bounds_every_expansion(case):
    # The move limit is checked on counts made before expanding: they must
    # never fall short of the moves the expansion really writes.
    call, tool = case
    settings_ = Settings(tool=tool)
    try:
        geo = call.geometry(settings_)
    except CycleError:
        assume(False)
    lo, hi = geo.opening(geo.final_top)
    u = lo - tool.width - 4.0
    start = geo.frame.blade(u, max(geo.contour_top(u), geo.contour_top(hi)) + 3.0)
    moves = call.expand(MachineState(x=start[0], z=start[1]), settings_)
    assert len(moves) <= geo.size.moves


def test_plain_grooves_are_cut_completely():
    # Paraxial flanks on a straight contour: everything but the blade's own
    # corner radius at the base is reachable, and nothing may be excused.
    for typ in (1, 3, 5, 7, 2, 4, 6, 8):
        angc = 0.0 if typ % 2 else 90.0
        call = Cycle93(axfa=20.0, axsa=0.0, widg=7.0, depg=4.0, angc=angc, fal1=0.2, fal2=0.1, idep=1.5, typ=typ)
        verdict, _ = run(call, GroovingTool(3.0, 0.3))
        sim.assert_clean(verdict)
