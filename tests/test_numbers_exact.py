"""format_exact (engine/numbers.py) writes every double as the shortest
decimal that reads back as the same double, without an exponent: checked
against Python's Decimal, which writes repr's digits out in full, and by
reading the text back."""

import math
from decimal import Decimal

from hypothesis import example, given
from hypothesis import strategies as st

from freecad_groove.engine.numbers import format_exact


def written_out(value: float) -> str:
    """repr's digits written out by Decimal, trailing zeros and point dropped, never -0."""
    text = format(Decimal(repr(value)), "f")
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


@given(st.floats(allow_nan=False, allow_infinity=False))
@example(0.0001)  # repr's last plain form
@example(0.00009999999999999999)  # repr's exponent form begins below 1e-4
@example(1e16)  # and at 1e16
@example(9999999999999998.0)
@example(-0.0)
@example(5e-324)
@example(1.7976931348623157e308)
def test_every_double_is_written_out_as_its_shortest_exact_decimal(value):
    text = format_exact(value)
    assert text == written_out(value)
    assert "e" not in text and "E" not in text and not text.endswith(".")
    assert float(text) == value or (value == 0 and float(text) == 0)


def test_plain_values_as_a_programmer_writes_them():
    assert [format_exact(v) for v in (35.0, 0.1, 1e-07, -0.0, -2.5, 1e16, 3, math.inf)] == [
        "35", "0.1", "0.0000001", "0", "-2.5", "10000000000000000", "3", "inf"]


# A CYCLE93 call's text (Cycle93.emit) keeps the texts of the values it met: every parameter is still
# written out exactly, whatever was met before and when the kept texts are dropped.
_PARAMETER = st.floats(allow_nan=False, allow_infinity=False, min_value=-1e20, max_value=1e20) | st.sampled_from(
    [0.0, -0.0, 5.0, 0.1, 1e-07])


@given(st.lists(st.tuples(_PARAMETER, _PARAMETER, _PARAMETER), min_size=1, max_size=6), st.integers(1, 4))
def test_a_call_is_written_out_exactly_whatever_calls_came_before(calls, kept):
    from freecad_groove.engine.cycles import cycle93

    saved = cycle93.EXACT_TEXTS_KEPT
    cycle93.EXACT_TEXTS_KEPT = kept  # drop the kept texts often
    try:
        for axfa, axsa, rco1 in calls:
            call = cycle93.Cycle93(axfa=axfa, axsa=axsa, widg=10.0, depg=6.0, rco1=rco1, typ=5, vrt=1.0)
            # AXFA, AXSA, WIDG, DEPG, ANGC..ANG2 not given, RCO1, RCO2..DWT not given, TYP, VRT
            parameters = [written_out(axfa), written_out(axsa), "10", "6"] + [""] * 3 + [written_out(rco1)] + \
                [""] * 7 + ["5", "1"]
            assert call.emit() == "CYCLE93(%s)" % ", ".join(parameters)
    finally:
        cycle93.EXACT_TEXTS_KEPT = saved


def test_zero_and_minus_zero_and_whole_numbers_read_the_same_in_a_call():
    from freecad_groove.engine.cycles.cycle93 import Cycle93

    texts = [Cycle93(axfa=a, axsa=b, widg=w, depg=6, typ=5, vrt=1).emit()
             for a, b, w in ((0.0, 5, 10.0), (-0.0, 5.0, 10), (0, 5.5, 10.0))]
    unset = ", " * 12  # ANGC to DWT (11) not given
    assert texts == ["CYCLE93(0, 5, 10, 6" + unset + "5, 1)", "CYCLE93(0, 5, 10, 6" + unset + "5, 1)",
                     "CYCLE93(0, 5.5, 10, 6" + unset + "5, 1)"]
