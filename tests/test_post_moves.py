"""A post's groove moves in the output's reference corner (engine/native/cycle93_pecking.py): shifted_moves,
which the FreeCAD posts write for each groove, gives every move as ``shifted`` gives it, one move at a time
(its end and an arc's centre moved by the shift, the op's feed on feed moves and arcs, no F on the others)."""

from hypothesis import given
from hypothesis import strategies as st

from freecad_groove.engine.moves import ARC_CCW, ARC_CW, DWELL, FEED, RAPID, Move
from freecad_groove.engine.native.cycle93_pecking import Shift, shifted, shifted_moves

_VALUE = st.integers(-80, 80).map(lambda k: k / 4.0)
_MOVE = st.builds(
    lambda kind, x, z, f, p, centre: Move(kind, x, z, f, p, centre=centre if kind in (ARC_CW, ARC_CCW) else None),
    st.sampled_from([RAPID, FEED, ARC_CW, ARC_CCW, DWELL]), _VALUE, _VALUE,
    st.sampled_from([None, 0.1, 0.15, 0.2]), st.sampled_from([0, 1.5]), st.tuples(_VALUE, _VALUE))


@given(st.lists(_MOVE, max_size=15), st.sampled_from([Shift(0.0, 0.0), Shift(0.0, 3.0), Shift(-2.5, 0.0)]),
       st.sampled_from([0.1, 0.15]))
def test_a_grooves_moves_are_each_move_shifted_and_fed_at_the_ops_feed(moves, shift, feed):
    expected = [shifted(m, shift, feed if m.kind in (FEED, ARC_CW, ARC_CCW) else None) for m in moves]
    got = shifted_moves(moves, shift, feed)
    assert got == expected
    assert [m.f for m in got] == [feed if m.kind in (FEED, ARC_CW, ARC_CCW) else None for m in moves]


def test_a_move_with_a_y_or_c_word_loses_it_as_shifted_drops_it():
    move = Move(FEED, 10.0, -2.0, 0.1, 0, y=1.0, c=None)
    assert shifted_moves([move], Shift(0.0, 0.0), 0.1) == [Move(FEED, 10.0, -2.0, 0.1, 0)]
