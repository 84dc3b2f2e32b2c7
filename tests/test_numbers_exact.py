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
