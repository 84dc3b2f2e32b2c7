"""Helpers shared by the CYCLE93 tests (test_cycle93.py,
test_cycle93_simulation.py, test_cycle93_air.py, test_cycle93_flank_steps.py):
the chip-breaking retracts of an expansion and the rule for what follows
them; the material standing when the contour passes begin."""

import pytest

from freecad_groove.engine.moves import FEED, MINUS_X, MINUS_Z, PLUS_X, PLUS_Z, RAPID

# The coordinate a plunge moves along and its sign going into the part.
PLUNGE_AXIS = {MINUS_X: ("x", -1), PLUS_X: ("x", 1), MINUS_Z: ("z", -1), PLUS_Z: ("z", 1)}


def _line(plunge):
    axis, sign = PLUNGE_AXIS[plunge]
    return axis, ("z" if axis == "x" else "x"), sign


def chip_breaks(moves, plunge, vrt):
    """Indexes of the feeds each followed by a chip-breaking retract: a FEED
    into the part along the plunge axis, then a RAPID exactly VRT back out
    along the same line. (A plunge's last retract rises by its depth plus
    VRT, a contour pass's by the groove's depth plus VRT: neither is VRT.)"""
    axis, other, sign = _line(plunge)
    found = []
    for i in range(1, len(moves) - 1):
        before, cut, back = moves[i - 1], moves[i], moves[i + 1]
        if cut.kind != FEED or back.kind != RAPID:
            continue
        if not getattr(before, other) == getattr(cut, other) == getattr(back, other):
            continue
        into = sign * (getattr(cut, axis) - getattr(before, axis)) > 0
        if into and -sign * (getattr(back, axis) - getattr(cut, axis)) == pytest.approx(vrt, abs=1e-9):
            found.append(i)
    return found


def assert_reentries(moves, plunge, vrt, clearance):
    """After every chip-breaking retract: a RAPID back down the same line to
    ``clearance`` above the depth reached (none when the clearance is VRT:
    the retract already stands there), then a FEED deeper than that depth.
    Returns the number of chip-breaking retracts."""
    axis, other, sign = _line(plunge)
    breaks = chip_breaks(moves, plunge, vrt)
    for i in breaks:
        depth, at = getattr(moves[i], axis), getattr(moves[i], other)
        k = i + 2
        if clearance < vrt:
            back_in = moves[k]
            assert back_in.kind == RAPID and getattr(back_in, other) == at, (i, back_in)
            assert getattr(back_in, axis) == pytest.approx(depth - sign * clearance, abs=1e-9), (i, back_in)
            k += 1
        on = moves[k]
        assert on.kind == FEED and getattr(on, other) == at, (i, on)
        assert sign * (getattr(on, axis) - depth) > 0, (i, on)  # the next infeed goes deeper
    return len(breaks)


def after_the_plunges(call, tool, start):
    """(moves, first, remaining): the expansion of ``call`` from ``start`` (x,
    z) with ``tool``, the index of its first contour-pass move (where it
    differs from the expansion without contour and finishing passes), and the
    material (shapely, from verify.simulate) standing before that move."""
    from shapely.geometry import Polygon

    from freecad_groove import verify as sim
    from freecad_groove.engine import MachineState, Settings
    from freecad_groove.engine.cycles.cycle93_geometry import GrooveGeometry

    settings = Settings(tool=tool)
    geo = call.geometry(settings)
    state = MachineState(x=start[0], z=start[1])
    moves = call.expand(state, settings)
    original = GrooveGeometry._profile_passes
    try:
        GrooveGeometry._profile_passes = lambda self, *a: None
        roughing = call.expand(state, settings)
    finally:
        GrooveGeometry._profile_passes = original
    first = next(i for i, (a, b) in enumerate(zip(moves, roughing)) if a != b)
    stock = Polygon([(z, x) for x, z in geo.stock_world()])
    remaining = sim.simulate(moves[:first], tool, call.plunge_direction(), start, stock).remaining
    return moves, first, remaining
