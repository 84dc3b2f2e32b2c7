"""Allen-Bradley 9/Series G77 / G76 (seed 000), and invariants of the shared pecking loop.

Expected move lists are worked out by hand from the manual text:
per groove FEED I, RAPID back e, FEED I + e, ... last infeed lands on X; RAPID D along Z
(if D != 0); RAPID to the start X; RAPID along Z to the next groove; after the last
groove RAPID to the start Z. e = 0.5 mm (metric) / 0.02 in (inch) unless set.
Tuples are (kind, x radius, z, f).
"""

import math

import pytest
from hypothesis import given
from hypothesis import settings as hsettings
from hypothesis import strategies as st
from pecking_helpers import F, R, moves_of, raises, state

from freecad_groove.engine.cycles import ab_g77
from freecad_groove.engine.cycles.ab_g77 import G76, G77
from freecad_groove.engine.cycles.fanuc_g75 import FanucG74, FanucG75, HaasG74, HaasG75
from freecad_groove.engine.moves import FEED, MINUS_X, MINUS_Z, PLUS_X, PLUS_Z, MachineState
from freecad_groove.engine.settings import Settings

# ---------------------------------------------------------------- G77 expansions


def test_single_groove_several_pecks_d0_with_f():
    # start X50 (radius 25) Z-10; X40. = radius 20, depth 5 in pecks of 2, last shortened.
    m = G77(X=40.0, I=2.0, F=0.1, D=0.0)
    assert moves_of(m.expand(state(25.0, -10.0, feed=0.2))) == [
        (F, 23.0, -10.0, 0.1),
        (R, 23.5, -10.0, None),
        (F, 21.0, -10.0, 0.1),  # I + e from 23.5
        (R, 21.5, -10.0, None),
        (F, 20.0, -10.0, 0.1),  # shortened: lands on the bottom, not 19
        (R, 25.0, -10.0, None),  # D = 0: straight back to the start X
    ]
    assert m.plunge_direction(state(25.0, -10.0)) == MINUS_X


def test_grooves_last_gap_smaller_than_k_with_d_shift_without_f_radius_mode():
    # radius mode, start X15 Z0, bottom 12 (depth 3, I2), grooves at 0 -4 -8 and -11 (last gap 3 < K4).
    m = G77(X=12.0, Z=-11.0, I=2.0, K=4.0, D=1.0)
    got = moves_of(m.expand(state(15.0, 0.0, feed=0.08, diameter_mode=False)))
    expected = []
    for z, next_z in ((0.0, -4.0), (-4.0, -8.0), (-8.0, -11.0), (-11.0, 0.0)):
        expected += [
            (F, 13.0, z, None),
            (R, 13.5, z, None),
            (F, 12.0, z, None),
            (R, 12.0, z + 1.0, None),  # D1. at rapid along Z, at full depth
            (R, 15.0, z + 1.0, None),  # retract to the starting X
            (R, 15.0, next_z, None),  # next groove; after the last: back to the start Z
        ]
    assert got == expected


def test_return_to_start_z_is_a_constant(monkeypatch):
    m = G77(X=12.0, Z=-11.0, I=2.0, K=4.0, D=1.0)
    st_ = state(15.0, 0.0, diameter_mode=False)
    assert ab_g77.RETURN_TO_START_Z is True
    assert moves_of(m.expand(st_))[-2:] == [(R, 15.0, -10.0, None), (R, 15.0, 0.0, None)]
    monkeypatch.setattr(ab_g77, "RETURN_TO_START_Z", False)
    assert moves_of(m.expand(st_))[-2:] == [(R, 12.0, -10.0, None), (R, 15.0, -10.0, None)]


def test_cut_off_single_groove_d_nonzero_through_centre():
    # start X30 (r15) Z-30; X-1. = radius -0.5 (through the centre), I5, D-0.5, F0.05.
    m = G77(X=-1.0, I=5.0, F=0.05, D=-0.5)
    assert moves_of(m.expand(state(15.0, -30.0))) == [
        (F, 10.0, -30.0, 0.05),
        (R, 10.5, -30.0, None),
        (F, 5.0, -30.0, 0.05),
        (R, 5.5, -30.0, None),
        (F, 0.0, -30.0, 0.05),
        (R, 0.5, -30.0, None),
        (F, -0.5, -30.0, 0.05),
        (R, -0.5, -30.5, None),  # shift D
        (R, 15.0, -30.5, None),  # retract
        (R, 15.0, -30.0, None),  # back to the start Z
    ]


def test_incremental_words():
    # G91: X-10. = -5 on the radius from X50 (bottom r20); Z-6. from Z-5 = last groove at Z-11.
    m = G77(X=-10.0, Z=-6.0, I=3.0, K=3.0, D=0.0)
    got = moves_of(m.expand(state(25.0, -5.0, incremental=True)))
    assert got == [
        (F, 22.0, -5.0, None),
        (R, 22.5, -5.0, None),
        (F, 20.0, -5.0, None),
        (R, 25.0, -5.0, None),
        (R, 25.0, -8.0, None),
        (F, 22.0, -8.0, None),
        (R, 22.5, -8.0, None),
        (F, 20.0, -8.0, None),
        (R, 25.0, -8.0, None),
        (R, 25.0, -11.0, None),
        (F, 22.0, -11.0, None),
        (R, 22.5, -11.0, None),
        (F, 20.0, -11.0, None),
        (R, 25.0, -11.0, None),
        (R, 25.0, -5.0, None),
    ]


def test_diameter_versus_radius_mode():
    m = G77(X=30.0, I=4.0, D=0.0)
    # diameter: bottom radius 15, depth 10 from 25.
    assert moves_of(m.expand(state(25.0, 0.0, diameter_mode=True))) == [
        (F, 21.0, 0.0, None),
        (R, 21.5, 0.0, None),
        (F, 17.0, 0.0, None),
        (R, 17.5, 0.0, None),
        (F, 15.0, 0.0, None),
        (R, 25.0, 0.0, None),
    ]
    # radius: bottom 30 above the start 25: an internal groove, plunging +X, retract toward -X.
    assert moves_of(m.expand(state(25.0, 0.0, diameter_mode=False))) == [
        (F, 29.0, 0.0, None),
        (R, 28.5, 0.0, None),
        (F, 30.0, 0.0, None),
        (R, 25.0, 0.0, None),
    ]
    assert m.plunge_direction(state(25.0, 0.0, diameter_mode=True)) == MINUS_X
    assert m.plunge_direction(state(25.0, 0.0, diameter_mode=False)) == PLUS_X


def test_internal_groove_diameter_mode():
    # bore radius 10, X26. = radius 13, I1.5: 11.5, back to 11, then 13.
    m = G77(X=26.0, I=1.5, D=0.0)
    assert moves_of(m.expand(state(10.0, -20.0))) == [
        (F, 11.5, -20.0, None),
        (R, 11.0, -20.0, None),
        (F, 13.0, -20.0, None),
        (R, 10.0, -20.0, None),
    ]


def test_inch_default_retract_and_set_retract():
    m = G77(X=1.6, I=0.1, D=0.0)
    assert moves_of(m.expand(state(1.0, 0.0, feed=0.004, metric=False))) == [
        (F, 0.9, 0.0, None),
        (R, 0.92, 0.0, None),  # e = 0.02 in
        (F, 0.8, 0.0, None),
        (R, 1.0, 0.0, None),
    ]
    m = G77(X=40.0, I=2.0, D=0.0)
    assert moves_of(m.expand(state(25.0, 0.0), Settings(peck_retract=0.2))) == [
        (F, 23.0, 0.0, None),
        (R, 23.2, 0.0, None),
        (F, 21.0, 0.0, None),
        (R, 21.2, 0.0, None),
        (F, 20.0, 0.0, None),
        (R, 25.0, 0.0, None),
    ]


def test_zero_retract_writes_no_empty_rapids():
    m = G77(X=40.0, I=2.0, D=0.0)
    assert moves_of(m.expand(state(25.0, 0.0), Settings(peck_retract=0.0))) == [
        (F, 23.0, 0.0, None),
        (F, 21.0, 0.0, None),
        (F, 20.0, 0.0, None),
        (R, 25.0, 0.0, None),
    ]


def test_retract_larger_than_peck_is_not_clipped():
    # r10 -> bottom 9.5 with I0.3, e0.5: the first retract goes 0.2 beyond the start (away from the part).
    m = G77(X=19.0, I=0.3, D=0.0)
    assert moves_of(m.expand(state(10.0, 0.0))) == [
        (F, 9.7, 0.0, None),
        (R, 10.2, 0.0, None),
        (F, 9.5, 0.0, None),
        (R, 10.0, 0.0, None),
    ]


def test_z_equal_to_start_is_one_groove_without_k():
    m = G77(X=40.0, Z=-10.0, I=5.0, D=0.0)
    assert moves_of(m.expand(state(25.0, -10.0))) == [(F, 20.0, -10.0, None), (R, 25.0, -10.0, None)]


# ---------------------------------------------------------------- G76 expansions


def test_g76_face_grooves_stepping_along_x():
    # start r30 Z2; Z-3. bottom (depth 5, K2 pecks), X50. = last groove at r25, I2.5 per side.
    m = G76(X=50.0, Z=-3.0, I=2.5, K=2.0, D=0.0)
    got = moves_of(m.expand(state(30.0, 2.0)))
    expected = []
    for x, next_x in ((30.0, 27.5), (27.5, 25.0), (25.0, 30.0)):
        expected += [
            (F, x, 0.0, None),
            (R, x, 0.5, None),
            (F, x, -2.0, None),
            (R, x, -1.5, None),
            (F, x, -3.0, None),
            (R, x, 2.0, None),
            (R, next_x, 2.0, None),
        ]
    assert got == expected
    assert m.plunge_direction(state(30.0, 2.0)) == MINUS_Z


def test_g76_single_groove_plus_z_with_d_shift_along_x():
    m = G76(Z=-6.0, K=3.0, D=-1.0, F=0.2)
    assert moves_of(m.expand(state(20.0, -10.0))) == [
        (F, 20.0, -7.0, 0.2),
        (R, 20.0, -7.5, None),
        (F, 20.0, -6.0, 0.2),
        (R, 19.0, -6.0, None),  # D along X, per side
        (R, 19.0, -10.0, None),
        (R, 20.0, -10.0, None),
    ]
    assert m.plunge_direction(state(20.0, -10.0)) == PLUS_Z


def test_g76_incremental_radius_mode():
    # G91, radius mode: Z-4. from Z0, X-6. from r20: grooves at 20, 17, 14 (I3).
    m = G76(X=-6.0, Z=-4.0, I=3.0, K=4.0, D=0.0)
    got = moves_of(m.expand(state(20.0, 0.0, incremental=True, diameter_mode=False)))
    assert got == [
        (F, 20.0, -4.0, None),
        (R, 20.0, 0.0, None),
        (R, 17.0, 0.0, None),
        (F, 17.0, -4.0, None),
        (R, 17.0, 0.0, None),
        (R, 14.0, 0.0, None),
        (F, 14.0, -4.0, None),
        (R, 14.0, 0.0, None),
        (R, 20.0, 0.0, None),
    ]


# ---------------------------------------------------------------- validation



@pytest.mark.parametrize(
    "model, fragments",
    [
        (G77(I=2.0, D=0.0), ("G77", "X:", "must be programmed")),
        (G77(X=40.0, D=0.0), ("I:", "must be programmed")),
        (G77(X=40.0, I=-1.0, D=0.0), ("I=-1", "peck depth must be greater than 0")),
        (G77(X=40.0, I=0.0, D=0.0), ("I=0", "greater than 0")),
        (G77(X=40.0, I=2.0), ("D:", "must be programmed (0 when not cutting off)")),
        (G77(X=40.0, Z=-20.0, I=2.0, K=-4.0, D=0.0), ("K=-4", "must not be negative")),
        (G77(X=40.0, I=2.0, F=0.0, D=0.0), ("F=0", "greater than 0")),
        (G77(X=40.0, I=2.0, F=-0.1, D=0.0), ("F=-0.1", "greater than 0")),
        (G77(X=40.12345, I=2.0, D=0.0), ("X=40.12345", "at most 4 decimal places")),
        (G77(X=100000.0, I=2.0, D=0.0), ("X=100000", "less than 100000")),
        (G77(X=40.0, I=float("nan"), D=0.0), ("I=nan", "finite")),
        (G77(X=40.0, I=2.0, D="1"), ("D=1", "must be a number")),
        (G76(X=40.0, K=2.0, D=0.0), ("G76", "Z:", "must be programmed")),
        (G76(Z=-3.0, D=0.0), ("K:", "must be programmed")),
        (G76(Z=-3.0, X=20.0, I=-2.5, K=2.0, D=0.0), ("I=-2.5", "must not be negative")),
    ],
)
def test_validation_rules(model, fragments):
    raises(model.validate, *fragments)
    raises(lambda: model.expand(state(25.0, 0.0)), *fragments)


def test_negative_retract_setting_is_refused():
    raises(lambda: G77(X=40.0, I=2.0, D=0.0).validate(Settings(peck_retract=-0.1)), "e=-0.1", "not less than 0")


def test_state_dependent_rules():
    raises(lambda: G77(X=50.0, I=2.0, D=0.0).expand(state(25.0, 0.0)), "X=50", "nothing to cut")
    raises(lambda: G77(X=0.0, I=2.0, D=0.0).expand(state(25.0, 0.0, incremental=True)), "X=0", "nothing to cut")
    raises(lambda: G77(X=40.0, I=2.0, D=0.0).plunge_direction(state(20.0, 0.0)), "X=40", "nothing to cut")
    raises(lambda: G76(Z=-2.0, K=2.0, D=0.0).expand(state(25.0, -2.0)), "G76 Z=-2", "nothing to cut")
    raises(
        lambda: G77(X=40.0, Z=-20.0, I=2.0, D=0.0).expand(state(25.0, 0.0)),
        "K:",
        "must be programmed and greater than 0",
    )
    raises(lambda: G77(X=40.0, Z=-20.0, I=2.0, K=0.0, D=0.0).expand(state(25.0, 0.0)), "K=0", "greater than 0")
    raises(lambda: G76(X=40.0, Z=-2.0, K=1.0, D=0.0).expand(state(25.0, 0.0)), "I:", "must be programmed")
    raises(lambda: G77(X=40.0, I=2.0, D=0.0).expand(state(25.0, 0.0, feed=None)), "F:", "no feed is active")
    # with F programmed no active feed is needed
    assert G77(X=40.0, I=5.0, F=0.1, D=0.0).expand(state(25.0, 0.0, feed=None))


def test_expansion_size_limit_names_the_word():
    raises(
        lambda: G77(X=40.0, Z=-90000.0, I=5.0, K=0.0001, D=0.0).expand(state(25.0, 0.0)), "K=0.0001", "moves"
    )
    raises(lambda: G77(X=-90000.0, I=0.0001, D=0.0).expand(state(25.0, 0.0)), "I=0.0001", "moves")


def test_ten_thousand_grooves_all_expand():
    # Speed is measured by benchmarks/bench_engine.py, not here.
    m = G77(X=40.0, Z=-9999.0, I=2.0, K=1.0, D=0.5)
    moves = m.expand(state(25.0, 0.0))
    assert len(moves) == 10000 * 7 + 9999 + 1  # 7 per groove, 9999 steps, the return


# ---------------------------------------------------------------- text


def test_emit_exact_text():
    assert G77(X=40.0, Z=-30.0, I=2.0, K=5.5, F=0.1, D=0.0).emit() == "G77 X40. Z-30. I2. K5.5 F0.1 D0."
    assert G77(X=-0.5, I=0.0001, D=-0.0).emit() == "G77 X-0.5 I0.0001 D0."
    assert G76(X=50.0, Z=-3.0, I=2.5, K=2.0, D=-1.0).emit() == "G76 X50. Z-3. I2.5 K2. D-1."


def test_parse_the_manual_form():
    expected = G77(X=40.0, Z=-30.0, I=2.0, K=5.5, F=0.1, D=0.0)
    assert G77.parse("G77X40.Z-30.I2.K5.5F.1D0;") == expected
    assert G77.parse("N120 g77 x40. z-30. i2. k5.5 f0.1 d0") == expected
    assert G76.parse("G76 X50. Z-3. I2.5 K2. D-1.") == G76(X=50.0, Z=-3.0, I=2.5, K=2.0, D=-1.0)


@pytest.mark.parametrize(
    "text, fragments",
    [
        ("G77 X40 I2. D0.", ("X=40", "decimal point", "X40.")),
        ("G77 X40. I2 D0.", ("I=2", "decimal point")),
        ("G77 X40. Y1. I2. D0.", ("Y=1", "is not a word of G77")),
        ("G77 X40. X41. I2. D0.", ("X=41", "programmed twice")),
        ("G76 X40. I2. D0.", ("G=76", "only G77")),
        ("G01 G77 X40. I2. D0.", ("G=1", "only G77")),
        ("X40. I2. D0.", ("G:", "must hold G77")),
        ("G77 X40. I2. D0. #1", ("#", "cannot read")),
        ("G77 X40. I2.", ("D:", "must be programmed")),
        ("G77 X40. I-2. D0.", ("I=-2", "greater than 0")),
    ],
)
def test_parse_errors_name_the_word(text, fragments):
    raises(lambda: G77.parse(text), *fragments)


value = st.integers(-999999999, 999999999).map(lambda n: n / 10000)
positive = st.integers(1, 999999999).map(lambda n: n / 10000)
optional = lambda s: st.none() | s  # noqa: E731


@given(
    cls=st.sampled_from([G77, G76]),
    x=value,
    z=optional(value),
    i=positive,
    k=optional(positive | st.just(0.0)),
    f=optional(positive),
    d=value,
)
def test_parse_emit_round_trip(cls, x, z, i, k, f, d):
    if cls is G77:
        model = G77(X=x, Z=z, I=i, K=k, F=f, D=d)
    else:  # G76: Z is the bottom (required), X the last groove, K the peck
        model = G76(X=z, Z=x, I=k, K=i, F=f, D=d)
    model.validate()
    assert cls.parse(model.emit()) == model


# ---------------------------------------------------------------- the shared loop, all six cycles


def _geometry(draw):
    """A random valid cycle and state, with the geometry it must produce (radius, abs)."""
    cls = draw(st.sampled_from([G77, G76, FanucG75, FanucG74, HaasG75, HaasG74]))
    grid = lambda lo, hi: st.integers(lo, hi).map(lambda n: n / 1000)  # noqa: E731
    diameter = draw(st.booleans())
    metric = draw(st.booleans())
    x0, z0 = draw(grid(1000, 60000)), draw(grid(-50000, 5000))
    depth = draw(grid(1, 10000)) * draw(st.sampled_from([-1, 1]))
    span = draw(grid(0, 10000)) * draw(st.sampled_from([-1, 1]))
    peck_len, pitch_len = draw(grid(100, 6000)), draw(grid(100, 6000))
    relief = draw(grid(0, 1000))
    axis = cls.AXIS
    p0, s0 = (x0, z0) if axis == "X" else (z0, x0)
    bottom, last = p0 + depth, s0 + span
    xw = lambda r: r * 2 if diameter else r  # noqa: E731
    bottom_word, last_word = (xw(bottom), last) if axis == "X" else (bottom, xw(last))
    words = {cls.BOTTOM[0]: round(bottom_word, 4), cls.LAST[0]: round(last_word, 4)}
    if cls.COUNTED:  # Fanuc P/Q: integers in least input increments
        unit = 0.001 if metric else 0.0001
        words[cls.PECK], words[cls.PITCH] = round(peck_len / unit), round(pitch_len / unit)
        peck, pitch = words[cls.PECK] * unit, words[cls.PITCH] * unit
    else:
        words[cls.PECK], words[cls.PITCH] = peck, pitch = peck_len, pitch_len
    words[cls.RELIEF] = relief if not cls.SHIFT_D else relief * draw(st.sampled_from([-1, 1]))
    model = cls(**words)
    start = MachineState(x=x0, z=z0, feed=0.1, diameter_mode=diameter, metric=metric)
    return model, start, bottom, last, peck, pitch, words[cls.RELIEF]


@hsettings(max_examples=300, deadline=None)
@given(st.data())
def test_expansion_invariants(data):
    model, start, bottom, last, peck, pitch, relief = _geometry(data.draw)
    moves = model.expand(start)
    axis = model.AXIS
    e = Settings().retract_e(start.metric)
    p0, s0 = (start.x, start.z) if axis == "X" else (start.z, start.x)
    sign = 1 if bottom > p0 else -1
    tol = 1e-6
    p, s = p0, s0
    grooves = []
    for m in moves:
        np_, ns = (m.x, m.z) if axis == "X" else (m.z, m.x)
        assert abs(np_ - p) < tol or abs(ns - s) < tol, "no diagonal move: %r" % (m,)
        if m.kind == FEED:
            assert abs(ns - s) < tol, "feeds only plunge"
            assert sign * (np_ - p) > 0, "feeds only into the part"
            assert sign * (np_ - p) <= peck + e + tol, "no infeed deeper than a peck"
            assert sign * (np_ - bottom) <= tol, "never beyond the bottom"
            if abs(np_ - bottom) < tol:
                grooves.append(ns)
        elif abs(ns - s) > tol:  # a rapid along the stepping axis: at the start or a relief at the bottom
            assert abs(p - p0) < tol or (abs(p - bottom) < tol and abs(abs(ns - s) - abs(relief)) < tol)
        p, s = np_, ns
    assert (p, s) == pytest.approx((p0, s0), abs=tol), "the cycle ends at its start point"
    assert grooves[0] == pytest.approx(s0, abs=tol)
    assert grooves[-1] == pytest.approx(last, abs=tol), "the last groove is at the programmed position"
    gaps = [abs(b - a) for a, b in zip(grooves, grooves[1:])]
    assert all(0 < g <= pitch + tol for g in gaps)
    assert all(g == pytest.approx(pitch, abs=tol) for g in gaps[:-1])
    assert len(grooves) == (1 if abs(last - s0) < 1e-7 else math.ceil(abs(last - s0) / pitch - 1e-6) + 1)
