"""Numbers as a control reads them, and the limits every writer shares.

One formatter for every decimal the project writes (cycle words, output
coordinates, messages), so a value is never written two ways. The limits are
the ones each target or control puts on a written word, and the size of an
expansion.
"""

import math
from decimal import Decimal
from typing import Union

MM_PER_INCH = 25.4

# Magnitude from which a written coordinate, feed or speed is refused: far
# beyond any lathe, and below the point where "%.4f" stops being exact.
MAX_WORD = 1.0e6

# Longest dwell any output writes (Fanuc: P holds at most 8 digits of ms).
MAX_DWELL_SECONDS = 99999.0

# Most moves one cycle call may expand into: every cycle counts its moves from
# its parameters before expanding and refuses a call beyond this, naming the
# parameter (a typo such as an infeed of 0.000001 must not hang FreeCAD).
MAX_MOVES = 1_000_000

# Arcs: an I/K arc's start and end radius may differ by this (mm per side;
# LinuxCNC refuses between 0.02 and 0.05), half the chord of an R arc may
# exceed R by this (mm; LinuxCNC: 0.00127). Tighter than LinuxCNC, so a
# translated arc is never refused there.
ARC_IJK_TOLERANCE = 0.01
ARC_R_TOLERANCE = 0.001

# The shortest arc a cycle writes as one G2/G3 (its chord, in the program's
# units): a shorter one's end, rounded to the output's resolution, could fall
# behind its start and turn it the other way round the whole circle; it is
# written as chords instead.
MIN_ARC_CHORD = 0.002

# An arc expanded into straight segments (GSK G7.1's arcs in the developed
# plane of a cylinder): the largest distance between a segment and the arc it
# replaces, in mm on the developed surface (converted in inch programs). A tenth of
# the 0.01 mm LinuxCNC arc limit, below what a slot's width tolerance notices.
ARC_CHORD_TOLERANCE = 0.001

# Most digits a number in a program may have: Python's own limit for
# converting a string of digits to an integer (sys.int_info.default_max_str_digits);
# a longer number is refused by name before any conversion.
MAX_DIGITS = 4300


def too_many_digits(number: str) -> bool:
    """Whether the number as written has more than MAX_DIGITS digits."""
    return len(number) > MAX_DIGITS and sum(char.isdigit() for char in number) > MAX_DIGITS


def shortened(number: str) -> str:
    """The first digits of a number too long to quote whole: ``1234567890...``."""
    return number[:10] + "..."


DIGITS_RULE = "the number has more than %d digits" % MAX_DIGITS


def digits_message(name: str, number: str) -> str:
    """The message for a word whose number has too many digits, ``name`` its
    letter as written (``N``, ``CR=``): ``N1234567890...: the number has more
    than 4300 digits``."""
    return "%s%s: %s" % (name, shortened(number), DIGITS_RULE)


def format_decimal(value: float, digits: int, point: bool = True) -> str:
    """``value`` rounded to ``digits`` decimals, trailing zeros dropped, never ``-0``.

    ``point`` True keeps the decimal point of a whole number (``80.``: a Fanuc
    control without calculator-type input reads ``X80`` as 0.080 mm); False
    drops it (``80``: Siemens parameters, messages).
    """
    text = ("%.*f" % (digits, value)).rstrip("0")
    if point:
        return "0." if text == "-0." else text
    text = text.rstrip(".")
    return "0" if text in ("-0", "") else text


def format_value(value: object) -> str:
    """A value the way a G-code programmer reads it in a message: floats with
    at most 6 decimals, others as str()."""
    if isinstance(value, float):
        return format_decimal(value, 6, point=False)
    return str(value)


def format_exact(value: Union[int, float]) -> str:
    """The shortest decimal that reads back as exactly ``value`` (the digits of
    Python's repr), written without an exponent and without a trailing point:
    35.0 -> ``35``, 0.1 -> ``0.1``, 1e-07 -> ``0.0000001``, -0.0 -> ``0``;
    integers, ``nan`` and ``inf`` as Python writes them."""
    if isinstance(value, int):
        return str(value)
    if not math.isfinite(value):
        return repr(float(value))
    text = repr(float(value))
    if "e" in text:  # repr's exponent form (below 1e-4, from 1e16): the same digits written out
        text = format(Decimal(text), "f")
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


# A given value longer than this in format_exact is shown in exponent form.
GIVEN_DIGITS = 20


def format_given(value: object) -> str:
    """A value as it was given, for a message (``CYCLE93 WIDG=-0.0000001: ...``):
    floats exactly (format_exact), or as ``1e+300`` when that would take more
    than GIVEN_DIGITS characters; anything else as format_value writes it."""
    if isinstance(value, float):
        text = format_exact(value)
        return text if len(text) <= GIVEN_DIGITS else repr(value)
    return format_value(value)
