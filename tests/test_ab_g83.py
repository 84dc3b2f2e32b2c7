"""Allen-Bradley 9/Series grinder G83 / G83.1 plunge surface grinding (seed 003).

Expected move lists are worked out by hand from the sequence in ab_g83's
notes: (G83.1: dress P first) plunge pick J at F; X strokes at E to X, to I,
...; at each reversal a cross pick K (at X) / R (at I) at F toward the
crossover end Z; at a reversal at I (the seed's step 4: "The plunge pick move
(Q) begins as the X axis decelerates to the secondary reversal point") where
the crossover end is reached, the plunge pick Q (clipped to Y) and the
crossover turns back; at X the crossover end only turns; after Y one crossover at
depth plus L spark-out crossovers; D dresses after plunges ceil(i n / D).
Tuples are (kind, x, y, z, f or program number).
"""

import pytest
from hypothesis import assume, given
from hypothesis import settings as hsettings
from hypothesis import strategies as st
from shapely.geometry import box
from shapely.ops import unary_union

from freecad_groove.engine.cycles.ab_g83 import G83, G83_1
from freecad_groove.engine.errors import CycleError
from freecad_groove.engine.moves import DRESS, FEED, MachineState
from freecad_groove.engine.registry import cycle_for, entry

G1, DR = FEED, DRESS


def start(x=0.0, y=0.0, z=0.0, feed=None, incremental=False):
    return MachineState(x=x, z=z, y=y, feed=feed, diameter_mode=False, incremental=incremental)


def moving(moves):
    """The moves that change the position or call a dress (as rs274 reports them)."""
    kept, where = [], None
    for move in moves:
        if move.kind == DRESS or (move.x, move.y, move.z) != where:
            kept.append(move)
        where = (move.x, move.y, move.z)
    return kept


def moves_of(moves):
    return [(m.kind, round(m.x, 6), round(m.y, 6), round(m.z, 6), m.p if m.kind == DRESS else m.f)
            for m in moves]


def test_registered_for_the_grinder_control():
    assert cycle_for("ab9grind", "G83") is G83
    assert cycle_for("ab9grind", "G83.1") is G83_1
    assert entry("ab-g83.1").cycle_class is G83_1


# ---------------------------------------------------------------- hand-derived expansions


def test_no_crossover_plunges_at_every_reversal_at_i_then_one_stroke_at_depth():
    # Z = start Z: every reversal is a crossover end; Q only at I (step 4). J 0.1, then Q 0.1 to Y-0.25.
    m = G83(X=50.0, Y=-0.25, J=0.1, Z=0.0, K=1.0, F=20.0, E=3000.0)
    assert moves_of(m.expand(start())) == [
        (G1, 0.0, -0.1, 0.0, 20.0),  # plunge pick at start J
        (G1, 50.0, -0.1, 0.0, 3000.0),  # stroke to the primary reversal X: it only turns
        (G1, 0.0, -0.1, 0.0, 3000.0),  # stroke to the secondary reversal: the start point (no I)
        (G1, 0.0, -0.2, 0.0, 20.0),  # plunge pick Q (= J) at I
        (G1, 50.0, -0.2, 0.0, 3000.0),
        (G1, 0.0, -0.2, 0.0, 3000.0),
        (G1, 0.0, -0.25, 0.0, 20.0),  # the last pick clipped to Y, at I
        (G1, 50.0, -0.25, 0.0, 3000.0),  # one stroke at the final depth, L = 0: the end
        (G1, 50.0, -0.25, 0.0, 20.0),  # F in force again (the last move was at E)
    ]


# the issue's call (issue 20, item 2): from X20 Y0 Z0, I0, crossover to Z10 by R4 at I and K5 at X
ISSUE = dict(X=50.0, I=0.0, Y=-0.1, J=0.05, Z=10.0, K=5.0, R=4.0, Q=0.03, F=10.0, E=2000.0)


def test_the_plunge_pick_q_is_made_at_the_secondary_reversal_point_i_as_step_4_says():
    assert moves_of(G83(**ISSUE).expand(start(20.0))) == [
        (G1, 20.0, -0.05, 0.0, 10.0),  # J at the start
        (G1, 0.0, -0.05, 0.0, 2000.0),  # step 3: to I first
        (G1, 0.0, -0.05, 4.0, 10.0),  # R 4 at I
        (G1, 50.0, -0.05, 4.0, 2000.0),
        (G1, 50.0, -0.05, 9.0, 10.0),  # K 5 at X
        (G1, 0.0, -0.05, 9.0, 2000.0),
        (G1, 0.0, -0.05, 10.0, 10.0),  # R 4 clipped to Z10: the crossover end
        (G1, 50.0, -0.05, 10.0, 2000.0),  # at X the end only turns: Q waits for I
        (G1, 0.0, -0.05, 10.0, 2000.0),
        (G1, 0.0, -0.08, 10.0, 10.0),  # Q 0.03 at I; the crossover turns back
        (G1, 50.0, -0.08, 10.0, 2000.0),
        (G1, 50.0, -0.08, 5.0, 10.0),  # K 5
        (G1, 0.0, -0.08, 5.0, 2000.0),
        (G1, 0.0, -0.08, 1.0, 10.0),  # R 4
        (G1, 50.0, -0.08, 1.0, 2000.0),
        (G1, 50.0, -0.08, 0.0, 10.0),  # K 5 clipped to the start Z
        (G1, 0.0, -0.08, 0.0, 2000.0),
        (G1, 0.0, -0.1, 0.0, 10.0),  # Q at I, 0.03 clipped to Y-0.1
        (G1, 50.0, -0.1, 0.0, 2000.0),  # the crossover at depth
        (G1, 50.0, -0.1, 5.0, 10.0),
        (G1, 0.0, -0.1, 5.0, 2000.0),
        (G1, 0.0, -0.1, 9.0, 10.0),
        (G1, 50.0, -0.1, 9.0, 2000.0),
        (G1, 50.0, -0.1, 10.0, 10.0),
        (G1, 0.0, -0.1, 10.0, 2000.0),  # at the end: L0, the cycle ends at this reversal
        (G1, 0.0, -0.1, 10.0, 10.0),  # F in force again
    ]


def test_without_crossover_the_issue_call_picks_q_only_at_i():
    moves = G83(**dict(ISSUE, Z=0.0)).expand(start(20.0))
    assert moves_of(moves) == [
        (G1, 20.0, -0.05, 0.0, 10.0),
        (G1, 0.0, -0.05, 0.0, 2000.0),
        (G1, 0.0, -0.08, 0.0, 10.0),  # Q at I
        (G1, 50.0, -0.08, 0.0, 2000.0),  # X only turns
        (G1, 0.0, -0.08, 0.0, 2000.0),
        (G1, 0.0, -0.1, 0.0, 10.0),  # Q at I reaches Y
        (G1, 50.0, -0.1, 0.0, 2000.0),  # one stroke at depth
        (G1, 50.0, -0.1, 0.0, 10.0),
    ]
    picks = [(b.x, b.y) for a, b in zip(moves, moves[1:]) if b.y != a.y]
    assert [x for x, _ in picks] == [0.0, 0.0]  # every Q pick at I0, none at the primary X50


def test_crossover_picks_k_and_r_then_plunge_q_at_the_crossover_end_and_turn_back():
    # I10. (abs), K 8 at X, R 5 at I, crossover to Z12., Q 0.2 to Y-0.3, J 0.1, L1; start X0 is not I:
    # X goes to I first (the seed's step 3).
    m = G83(X=60.0, I=10.0, Y=-0.3, J=0.1, Z=12.0, K=8.0, R=5.0, Q=0.2, L=1, F=30.0, E=2000.0)
    assert moves_of(m.expand(start(x=0.0, y=0.0, z=0.0))) == [
        (G1, 0.0, -0.1, 0.0, 30.0),  # J at the start
        (G1, 10.0, -0.1, 0.0, 2000.0),  # to the secondary reversal I first
        (G1, 10.0, -0.1, 5.0, 30.0),  # R at the secondary
        (G1, 60.0, -0.1, 5.0, 2000.0),
        (G1, 60.0, -0.1, 12.0, 30.0),  # K at the primary, 13 clipped to Z12
        (G1, 10.0, -0.1, 12.0, 2000.0),
        (G1, 10.0, -0.3, 12.0, 30.0),  # crossover end reached: Q 0.2 reaches Y-0.3
        (G1, 60.0, -0.3, 12.0, 2000.0),  # crossover back at the final depth
        (G1, 60.0, -0.3, 4.0, 30.0),  # K 8
        (G1, 10.0, -0.3, 4.0, 2000.0),
        (G1, 10.0, -0.3, 0.0, 30.0),  # R 5 clipped to the start Z
        (G1, 60.0, -0.3, 0.0, 2000.0),  # crossover at depth done: this reversal only turns
        (G1, 10.0, -0.3, 0.0, 2000.0),  # L1: one spark-out crossover, from the Z0 strip
        (G1, 10.0, -0.3, 5.0, 30.0),
        (G1, 60.0, -0.3, 5.0, 2000.0),
        (G1, 60.0, -0.3, 12.0, 30.0),
        (G1, 10.0, -0.3, 12.0, 2000.0),  # at Z12 again: the end, no return move
        (G1, 10.0, -0.3, 12.0, 30.0),  # F in force again
    ]


def test_incremental_words_are_distances_from_the_start_point():
    # G91 from X5 Y2 Z3: X+20 -> 25, I-5 -> 0, Y-0.2 -> 1.8, Z0 -> no crossover.
    m = G83(X=20.0, I=-5.0, Y=-0.2, J=0.1, Z=0.0, K=1.0, F=10.0, E=100.0)
    assert moves_of(m.expand(start(5.0, 2.0, 3.0, incremental=True))) == [
        (G1, 5.0, 1.9, 3.0, 10.0),
        (G1, 0.0, 1.9, 3.0, 100.0),  # to I first
        (G1, 0.0, 1.8, 3.0, 10.0),  # no crossover: Q at every reversal
        (G1, 25.0, 1.8, 3.0, 100.0),
        (G1, 25.0, 1.8, 3.0, 10.0),
    ]


def test_when_j_reaches_y_and_the_first_stroke_is_short_one_more_crossover_at_depth():
    # start X30 between I0 and X60: the stroke 30 -> 0 at Z0 leaves 30..60 of the Z0 strip, so two crossovers.
    m = G83(X=60.0, I=0.0, Y=-0.1, J=0.1, Z=4.0, K=4.0, F=10.0, E=100.0)
    assert moves_of(m.expand(start(30.0))) == [
        (G1, 30.0, -0.1, 0.0, 10.0),
        (G1, 0.0, -0.1, 0.0, 100.0),
        (G1, 0.0, -0.1, 4.0, 10.0),
        (G1, 60.0, -0.1, 4.0, 100.0),  # the first crossover ends here: it only turns
        (G1, 0.0, -0.1, 4.0, 100.0),
        (G1, 0.0, -0.1, 0.0, 10.0),
        (G1, 60.0, -0.1, 0.0, 100.0),  # the Z0 strip over 0..60: the second crossover ends
        (G1, 60.0, -0.1, 0.0, 10.0),
    ]
    # started beyond X (seen from I), the first stroke spans both reversal points: one crossover
    assert len(m.expand(start(70.0))) == 5


def test_picks_go_toward_y_and_z_whichever_side_they_are():
    # Y above the start and Z below it: the unsigned picks take their direction from the targets.
    m = G83(X=10.0, Y=0.15, J=0.1, Z=-4.0, K=4.0, F=5.0, E=50.0)
    assert moves_of(m.expand(start())) == [
        (G1, 0.0, 0.1, 0.0, 5.0),
        (G1, 10.0, 0.1, 0.0, 50.0),
        (G1, 10.0, 0.1, -4.0, 5.0),
        (G1, 0.0, 0.1, -4.0, 50.0),
        (G1, 0.0, 0.15, -4.0, 5.0),  # Q = J 0.1 clipped to Y0.15
        (G1, 10.0, 0.15, -4.0, 50.0),
        (G1, 10.0, 0.15, 0.0, 5.0),
        (G1, 0.0, 0.15, 0.0, 50.0),
        (G1, 0.0, 0.15, 0.0, 5.0),
    ]


def test_f_and_e_default_to_the_feed_in_force():
    m = G83(X=10.0, Y=-0.1, J=0.1, Z=0.0, K=1.0)
    assert moves_of(m.expand(start(feed=40.0))) == [
        (G1, 0.0, -0.1, 0.0, 40.0),
        (G1, 10.0, -0.1, 0.0, 40.0),
    ]


def test_dresses_follow_the_plunges_spread_evenly_and_g83_1_dresses_first():
    # 4 Q plunges (0.1 .. 0.5 by 0.1 after J); D2: after plunges ceil(1*4/2)=2 and ceil(2*4/2)=4.
    m = G83_1(X=10.0, Y=-0.5, J=0.1, Z=0.0, K=1.0, F=5.0, E=50.0, P=77, D=2)
    got = moves_of(m.expand(start()))
    assert got[0] == (DR, 0.0, 0.0, 0.0, 77)  # G83.1: dress before anything moves
    plunges = [i for i in range(2, len(got)) if got[i][0] == G1 and got[i][2] != got[i - 1][2]]  # after J
    assert len(plunges) == 4
    dresses = [i for i, move in enumerate(got) if move[0] == DR][1:]
    assert dresses == [plunges[1] + 1, plunges[3] + 1]  # right after plunge 2 and 4, at that reversal
    assert got[plunges[1] + 1][1:4] == got[plunges[1]][1:4]


def test_more_dresses_than_plunges_call_p_several_times_after_a_plunge():
    m = G83(X=10.0, Y=-0.2, J=0.1, Z=0.0, K=1.0, F=5.0, P=3, D=3)  # one Q plunge
    kinds = [move[0] for move in moves_of(m.expand(start()))]
    assert kinds == [G1, G1, G1, G1, DR, DR, DR, G1]  # J, to X, to I, Q at I, the dresses; E = F: no F move


# ---------------------------------------------------------------- the program's memory


def test_omitted_words_come_from_the_previous_cycle_as_absolute_positions():
    first = G83(X=60.0, I=10.0, Y=-0.3, J=0.1, Z=12.0, K=8.0, E=900.0, F=3.0, P=5)
    memory = first.remembered(start())
    assert memory == {"X": 60.0, "I": 10.0, "Y": -0.3, "Z": 12.0, "J": 0.1, "K": 8.0, "E": 900.0, "P": 5}
    # in G91 from X10 Y-0.3 Z12 the same face is X+50, I0, Y0, Z0
    again = G83(Y=-0.1, Q=0.05).with_earlier(memory, start(10.0, -0.3, 12.0, feed=3.0, incremental=True))
    assert (again.X, again.I, again.Y, again.Z, again.J, again.K, again.E, again.P) == (
        50.0, 0.0, -0.1, 0.0, 0.1, 8.0, 900.0, 5)
    assert again.R is None and again.L is None and again.D is None  # R = K, L and D not modal


def test_a_class_2_word_never_programmed_is_refused():
    with pytest.raises(CycleError, match="G83 K: must be programmed"):
        G83(X=10.0, Y=-0.1, J=0.1, Z=0.0, F=1.0).expand(start())


def test_i_never_programmed_is_not_remembered():
    memory = G83(X=10.0, Y=-0.1, J=0.1, Z=0.0, K=1.0, F=1.0).remembered(start())
    assert "I" not in memory


# ---------------------------------------------------------------- validation, one rule a test


@pytest.mark.parametrize("words, message", [
    ("L1000", "L=1000: must be a whole number from 0 to 999"),
    ("D1000", "D=1000: must be a whole number from 0 to 999"),
    ("P0", "P=0: must be a program number from 1 to 9999"),
    ("J-0.1", "J=-0.1: is incremental only"),
    ("Q-0.1", "Q=-0.1: is incremental only"),
    ("K-1.", "K=-1: is incremental only"),
    ("R-1.", "R=-1: is incremental only"),
    ("Q0", "Q=0: must be greater than 0"),
    ("K0", "K=0: must be greater than 0"),
    ("R0", "R=0: must be greater than 0"),
    ("F0", "F=0: must be greater than 0"),
    ("E0", "E=0: must be greater than 0"),
    ("L1.", "L=1: must be an integer"),
    ("X10", "X=10: needs a decimal point"),
    ("W1.", "W=1: is not a word of G83"),
])
def test_word_rules(words, message):
    with pytest.raises(CycleError, match="G83 " + message.replace(".", r"\.")):
        G83.parse("G83 " + words)


@pytest.mark.parametrize("model, state, message", [
    (G83(X=10.0, Y=-0.1, J=0.1, Z=0.0, K=1.0, F=1.0), start(x=10.0), "X=10: the secondary reversal point equals"),
    (G83(X=10.0, I=10.0, Y=-0.1, J=0.1, Z=0.0, K=1.0, F=1.0), start(), "I=10: the secondary reversal point equals"),
    (G83(X=10.0, Y=-0.1, J=0.1, Z=0.0, K=1.0), start(), "F: must be programmed"),
    (G83_1(X=10.0, Y=-0.1, J=0.1, Z=0.0, K=1.0, F=1.0), start(), "P: must be programmed .G83.1 dresses first"),
    (G83(X=10.0, Y=-0.1, J=0.1, Z=0.0, K=1.0, F=1.0, D=1), start(), "P: must be programmed .D=1 dresses"),
    (G83(X=10.0, Y=-0.1, J=0.1, Z=0.0, K=1.0, F=1.0, D=1, P=4), start(), "D=1: the cycle has no plunge"),
    (G83(X=10.0, Y=-0.5, J=0.0, Z=0.0, K=1.0, F=1.0), start(), "Q=0: must be greater than 0"),
    (G83(X=10.0, Y=-0.5, J=0.1, Z=0.0, K=1.0, F=1.0), MachineState(x=0.0, z=0.0), "Y: the start position"),
    (G83(Y=-0.5), MachineState(x=0.0, z=0.0), "Y: the start position"),  # before the words it lacks
])
def test_plan_rules(model, state, message):
    with pytest.raises(CycleError, match="G83(.1)? " + message):
        model.expand(state)


def test_a_cycle_of_too_many_moves_is_refused():
    with pytest.raises(CycleError, match=r"G83.1 Q=0.0001: the cycle would make more than 1000000 moves"):
        G83_1(X=10.0, Y=-100.0, J=0.0001, Z=0.0, K=1.0, F=1.0, P=1).expand(start())


@hsettings(max_examples=200, deadline=None)
@given(st.data())
def test_generated_cycles_stay_between_their_limits_and_cover_the_face(data):
    # any valid call from (x0, 0, 0): X between the start and the reversal points, Z between the start and
    # the crossover end, Y never past the depth, every pick at most its amount, and with picks no wider
    # than the wheel the strokes at the final depth cover the face between the reversal points and
    # across the crossover (and 4 of the wheel's half width 5 beyond it).
    draw = data.draw
    primary = draw(st.sampled_from([-1, 1])) * draw(st.integers(1, 50)) * 2.0
    secondary = draw(st.one_of(st.none(), st.integers(-20, 20).map(float)))
    x0 = draw(st.integers(-60, 60).map(float))
    assume(primary != (x0 if secondary is None else secondary))
    depth = -draw(st.integers(0, 40)) / 100.0
    cross = draw(st.integers(-30, 30)) * 1.0
    k, r = draw(st.integers(1, 10)) * 1.0, draw(st.integers(1, 10)) * 1.0
    j, q = draw(st.integers(0, 15)) / 100.0, draw(st.integers(1, 15)) / 100.0
    model = G83(X=primary, I=secondary, Y=depth, J=j, Z=cross, K=k, R=r, Q=q, L=draw(st.integers(0, 3)), F=10.0,
                E=500.0)
    moves = model.expand(start(x0))
    reversals = (primary, x0 if secondary is None else secondary)
    assert all(min(x0, *reversals) <= m.x <= max(x0, *reversals) for m in moves)
    assert all(min(0.0, cross) <= m.z <= max(0.0, cross) for m in moves)
    assert all(m.y >= depth for m in moves) and moves[-1].y == depth
    previous = before = start(x0)
    for m in moves:
        assert abs(m.y - before.y) <= max(j, q) + 1e-9
        assert abs(m.z - before.z) <= max(k, r) + 1e-9
        before = m
    strokes = [box(min(a.x, b.x), b.z - WHEEL_WIDTH / 2, max(a.x, b.x), b.z + WHEEL_WIDTH / 2)
               for a, b in zip([previous] + moves, moves) if a.y == b.y == depth and a.x != b.x]
    face = box(min(reversals), min(0.0, cross) - 4.0, max(reversals), max(0.0, cross) + 4.0)
    assert face.difference(unary_union(strokes)).area < 1e-9


# ---------------------------------------------------------------- emit and parse


_values = st.integers(-99999, 99999).map(lambda n: n / 100.0)
_amounts = st.integers(1, 99999).map(lambda n: n / 1000.0)


@hsettings(max_examples=200, deadline=None)
@given(st.sampled_from([G83, G83_1]), st.fixed_dictionaries({}, optional={
    "X": _values, "I": _values, "Y": _values, "Z": _values, "J": _amounts, "Q": _amounts, "K": _amounts,
    "R": _amounts, "F": _amounts, "E": _amounts, "L": st.integers(0, 999), "P": st.integers(1, 9999),
    "D": st.integers(0, 999)}))
def test_parse_of_emit_is_the_model(cls, words):
    model = cls(**words)
    assert cls.parse(model.emit()) == model


def test_emit_writes_the_seed_order():
    model = G83_1(D=2, P=10, X=1.5, I=0.0, Y=-0.2, J=0.01, Z=30.0, K=5.0, R=4.0, Q=0.02, L=2, F=100.0, E=8000.0)
    assert model.emit() == "G83.1 X1.5 I0. Y-0.2 J0.01 Z30. K5. R4. Q0.02 L2 F100. E8000. P10 D2"


# ---------------------------------------------------------------- the wheel covers the face


WHEEL_WIDTH = 10.0  # along the crossover axis Z, centred on the programmed Z


@pytest.mark.parametrize("k, r, spark", [(8.0, 8.0, 0), (10.0, 6.0, 2), (3.0, 9.5, 1)])
def test_the_wheel_covers_the_face_at_the_final_depth_and_never_goes_below(k, r, spark):
    # face: X 10..90, Z -4..34 (the wheel's half width beyond the crossover 0..30 is 5); the
    # reversals 0 and 100 overtravel it; final depth Y-0.35.
    model = G83(X=100.0, Y=-0.35, J=0.05, Z=30.0, K=k, R=r, Q=0.1, L=spark, F=50.0, E=5000.0)
    moves = model.expand(start(x=0.0, y=0.0, z=0.0))
    assert min(move.y for move in moves) == -0.35
    strokes, previous = [], moves[0]
    for move in moves[1:]:
        if move.y == -0.35 and previous.y == -0.35 and move.x != previous.x:  # a stroke at the final depth
            strokes.append(box(min(move.x, previous.x), move.z - WHEEL_WIDTH / 2,
                               max(move.x, previous.x), move.z + WHEEL_WIDTH / 2))
        previous = move
    face = box(10.0, -4.0, 90.0, 34.0)
    assert face.difference(unary_union(strokes)).area == 0.0


# ---------------------------------------------------------------- reading 9/Series grinder programs

import subprocess  # noqa: E402
import sys  # noqa: E402
from pathlib import Path  # noqa: E402

from rs274 import require_rs274, run_rs274  # noqa: E402

from freecad_groove.engine.errors import ProgramError  # noqa: E402
from freecad_groove.engine.translator import translate_program  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "ab9_g83.nc"
SMALL = """G90 G94 G21
G0 X0. Y1. Z0.
G83.1 X50. Y0.8 J0.1 Z0. K1. F20. E3000. P7 D1
M30
"""


def test_a_grinder_program_becomes_a_mill_program_for_linuxcnc():
    # Y1 -> 0.8: J 0.1 at the start, to X50 (it only turns), back to I (the start X0), Q (= J) 0.1 there
    # reaching Y0.8, then one stroke at depth.
    assert translate_program(SMALL, "ab9grind", target="linuxcnc").splitlines() == [
        "(PROGRAM: ab9grind program, cycles expanded for linuxcnc-mill by freecad-groove)",
        "G17 G21 G90 G91.1 G40",
        "G21 G94",
        "G0 X0. Y1. Z0.",
        "(G83.1 X50. Y0.8 J0.1 Z0. K1. F20. E3000. P7 D1)",
        "o<dress7> call",  # G83.1: the dress first
        "G1 X0. Y0.9 Z0. F20.",  # after the call every axis, G1 and F again
        "X50. F3000.",
        "X0.",
        "Y0.8 F20.",
        "o<dress7> call",  # D1: after the one plunge at a reversal
        "G1 X50. Y0.8 Z0. F3000.",
        "F20.",  # the plunge feed in force again after the cycle
        "M2",
    ]


def test_a_grinder_program_for_fanuc_writes_g17_g94_and_m98():
    lines = translate_program(SMALL, "ab9grind", target="fanuc").splitlines()
    assert lines[:3] == ["%", "(PROGRAM: ab9grind program, cycles expanded for fanuc-mill by freecad-groove)", "G21"]
    assert lines[3] == "G17 G90 G40" and "G94" in lines and lines.count("M98 P7") == 2 and "G98" not in lines


def test_the_second_cycle_of_a_program_takes_the_omitted_words_from_the_first():
    text = SMALL.replace("M30\n", "G0 X0. Y1.\nG91 G83 Y-0.2 P8\nM30\n")
    lines = translate_program(text, "ab9grind").splitlines()
    second = lines[lines.index("(G83 Y-0.2 P8)"):]
    # X50 (absolute, remembered), J 0.1 (remembered), K; F the feed in force (F20: the first cycle ends
    # with it), E 3000 (remembered)
    assert second == ["(G83 Y-0.2 P8)", "G1 Y0.9", "X50. F3000.", "X0.", "Y0.8 F20.", "X50. F3000.", "F20.", "M2"]


def test_a_cycle_whose_memory_depends_on_a_block_delete_line_is_refused():
    text = SMALL.replace("G83.1", "/G83.1").replace("M30\n", "G0 X0. Y1.\nG83 Y0.8\nM30\n")
    with pytest.raises(ProgramError, match="G83 depends on a block-delete|the words G83 takes from the cycle before"):
        translate_program(text, "ab9grind")


@pytest.mark.parametrize("line, message", [
    ("G17", "G17: plane selection"),
    ("G2 X1. Y1. R1.", "G2: arcs .G02/G03. in a grinder program are not translated"),
    ("G83 X50. Y0.8 J0.1 Z0. K1. F20. L1000", "G83 L=1000: must be a whole number from 0 to 999"),
    ("G83 X0. Y0.8 J0.1 Z0. K1. F20.", "G83 X=0: the secondary reversal point equals the primary one"),
])
def test_grinder_program_refusals_name_the_line(line, message):
    with pytest.raises(ProgramError, match=message) as info:
        translate_program("G90 G94 G21\nG0 X0. Y1. Z0.\n" + line + "\nM30\n", "ab9grind")
    assert info.value.line == 3


def test_a_lathe_program_has_no_y_word():
    with pytest.raises(ProgramError, match="Y1. is not supported"):
        translate_program("G90 G94 G21\nG0 X0. Y1. Z0.\nM30\n", "ab9")


def test_the_command_line_reports_a_bad_grinder_cycle_in_one_line(tmp_path):
    program = tmp_path / "bad.nc"
    program.write_text("G90 G94 G21\nG0 X0. Y1. Z0.\nG83.1 X50. Y0.8 J0.1 Z0. K1. F20.\nM30\n")
    proc = subprocess.run([sys.executable, "-m", "freecad_groove", "expand", str(program), "--dialect", "ab9grind",
                           "--to", "fanuc"], cwd=ROOT, capture_output=True, timeout=120)
    assert proc.returncode == 2 and proc.stdout == b""
    expected = "%s:3: G83.1 P: must be programmed (G83.1 dresses first; no earlier cycle gave P)\n" % program
    assert proc.stderr.decode() == expected


def test_rs274_runs_the_example_grinder_program_where_the_engine_moves():
    require_rs274()
    proc = subprocess.run([sys.executable, "-m", "freecad_groove", "expand", str(EXAMPLE), "--dialect", "ab9grind",
                           "--to", "linuxcnc"], cwd=ROOT, capture_output=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    dress = "o<dress12> sub\nG4 P0.5\no<dress12> endsub\nM2\n"
    canon = run_rs274(proc.stdout.decode(), files={"dress12.ngc": dress}, xyz=True)
    first = G83_1.parse("G83.1 X100. Y-0.2 J0.1 Z30. K8. Q0.1 F20. E3000. P12 D2 L1")
    moves = moving(first.expand(start(0.0, 0.1, 0.0, feed=200.0)))
    # canon: G0 to X0 Y5 Z0, G1 Y0.1, then the first cycle (a dress is rs274's G4)
    got = [(c[0], round(c[1], 4), round(c[2], 4), round(c[3], 4)) for c in canon[2:2 + len(moves)]]
    assert got == [("G4" if m.kind == DRESS else "G1", round(m.x, 4), round(m.y, 4), round(m.z, 4)) for m in moves]
    assert min(c[2] for c in canon) == pytest.approx(-0.25)  # the G91 cycle's depth: Y-0.2 - 0.05


def test_emit_expand_writes_a_mill_program_from_the_start_x_y_z():
    proc = subprocess.run([sys.executable, "-m", "freecad_groove", "emit", "ab-g83", "-X", "20", "-Y", "-0.1", "-J",
                           "0.1", "-Z", "0", "-K", "1", "-F", "5", "--expand", "--start-x", "4", "--start-y", "0",
                           "--start-z", "0", "--feed-mode", "min"], cwd=ROOT, capture_output=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    lines = proc.stdout.decode().splitlines()
    # X4 is a plain coordinate (not a diameter): the J pick at X4, one stroke to X20 at depth
    assert lines[1] == "G17 G21 G90 G91.1 G40 G94" and lines[2:] == ["G0 X4. Y0. Z0.", "G1 Y-0.1 F5.", "X20.", "M2"]


def test_a_units_change_converts_the_y_position():
    # Y25.4 mm is Y1. in inch: G91 Y-1. then reaches Y0.
    text = "G90 G94 G21\nG0 X0. Y25.4 Z0.\nG20\nG91 G1 Y-1. F1.\nM30\n"
    assert translate_program(text, "ab9grind").splitlines()[-2] == "G1 Y0. F1."
