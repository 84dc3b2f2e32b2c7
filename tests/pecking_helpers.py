"""Helpers shared by the tests of the pecking cycles (test_ab_g77.py,
test_fanuc_g75.py): exact move lists, start states, expected errors."""

import pytest

from freecad_groove.engine.errors import CycleError
from freecad_groove.engine.moves import FEED, RAPID, MachineState

R, F = RAPID, FEED


def moves_of(moves):
    """Moves as (kind, x, z, f) with float noise rounded off, for exact comparison."""
    assert all(m.p == 0 for m in moves)
    return [(m.kind, round(m.x, 9), round(m.z, 9), m.f) for m in moves]


def state(x, z, feed=0.1, **kw):
    return MachineState(x=x, z=z, feed=feed, **kw)


def raises(call, *fragments):
    """The CycleError call() raises; its message holds every fragment."""
    with pytest.raises(CycleError) as info:
        call()
    text = str(info.value)
    for fragment in fragments:
        assert fragment in text, text
    return info.value
