"""Numbers as a control reads them, and the limits every writer shares.

One formatter for every decimal the project writes (cycle words, output
coordinates, messages), so a value is never written two ways. The limits are
the ones each target or control puts on a written word.
"""

MM_PER_INCH = 25.4

# Magnitude from which a written coordinate, feed or speed is refused: far
# beyond any lathe, and below the point where "%.4f" stops being exact.
MAX_WORD = 1.0e6

# Longest dwell any output writes (Fanuc: P holds at most 8 digits of ms).
MAX_DWELL_SECONDS = 99999.0

# Arcs: an I/K arc's start and end radius may differ by this (mm per side;
# LinuxCNC refuses between 0.02 and 0.05), half the chord of an R arc may
# exceed R by this (mm; LinuxCNC: 0.00127). Tighter than LinuxCNC, so a
# translated arc is never refused there.
ARC_IJK_TOLERANCE = 0.01
ARC_R_TOLERANCE = 0.001

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
    """A parameter value the way a G-code programmer reads it back (messages,
    Siemens call parameters): floats with at most 6 decimals, others as str()."""
    if isinstance(value, float):
        return format_decimal(value, 6, point=False)
    return str(value)
