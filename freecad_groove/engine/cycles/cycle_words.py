"""The words of a G-word cycle block, as the controls read and write them:
reading one block into its words (:func:`read_block`), checking a value the
control must read back exactly as held (:func:`check_number`), and writing a
word's value (:func:`word_value`, :func:`words_text`). The pecking cycles
(``pecking.py``), the 9/Series grinder's G83 and the Milltronics
autoroutines share them; pecking.py's module notes give the number format.
"""

import math
import re
from typing import Dict, Sequence

from ..errors import CycleError
from ..numbers import DIGITS_RULE, format_decimal, shortened, too_many_digits

__all__ = ["DECIMALS", "F_DECIMALS", "MAX_COUNT", "MAX_WORD", "TOLERANCE", "check_number", "decimals", "read_block",
           "word_value", "words_text"]

DECIMALS = 4
F_DECIMALS = 6
MAX_WORD = 100000.0
MAX_COUNT = 99999999  # Fanuc P/Q: 8 digits
TOLERANCE = 1e-7  # far below the 0.0001 word resolution, far above float noise

# ---------------------------------------------------------------- numbers, words


def decimals(letter: str) -> int:
    """How many decimals the word ``letter`` may have."""
    return F_DECIMALS if letter == "F" else DECIMALS


def word_value(value: float, letter: str = "") -> str:
    """A decimal word value as written: always a decimal point, no trailing zeros."""
    return format_decimal(value, decimals(letter))


def words_text(model: object, name: str, words: Sequence[str], counted: Sequence[str]) -> str:
    """A block: ``name``, then each word of ``words`` that ``model`` holds (not
    None), the ``counted`` ones as whole numbers, the others by word_value."""
    parts = [name]
    for letter in words:
        value = getattr(model, letter)
        if value is not None:
            parts.append(letter + (str(value) if letter in counted else word_value(value, letter)))
    return " ".join(parts)


def check_number(cycle: str, letter: str, value: object, counted: bool = False) -> None:
    """Refuse a word value the control cannot read back exactly as held."""
    if counted:
        if isinstance(value, bool) or not isinstance(value, int):
            raise CycleError(
                letter, value, "must be an integer in least input increments (P2000 = 2 mm or 0.2 in)", cycle=cycle
            )
        if abs(value) > MAX_COUNT:
            raise CycleError(letter, value, "must have at most 8 digits", cycle=cycle)
        return
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise CycleError(letter, value, "must be a number", cycle=cycle)
    if not math.isfinite(value):
        raise CycleError(letter, value, "must be a finite number", cycle=cycle)
    if not abs(value) < MAX_WORD:
        raise CycleError(letter, value, "must be less than %d in magnitude" % MAX_WORD, cycle=cycle)
    if round(value, decimals(letter)) != value:
        raise CycleError(letter, value, "must have at most %d decimal places" % decimals(letter), cycle=cycle)


_WORD = re.compile(r"([A-Z])([+-]?(?:\d+\.?\d*|\.\d+))")
_BLOCK_NUMBER = re.compile(r"N\d+")


def read_block(text: str, cycle: str, letters: Sequence[str], counted: Sequence[str] = ()) -> Dict[str, float]:
    """Read one block ``G77 X40. Z-30. ...`` into {letter: value}.

    ``cycle`` is the G word expected ("G77"); ``letters`` the words the block may
    hold; ``counted`` those that are integers in least input increments.
    """
    block = "".join(text.split()).upper()
    if block.endswith(";"):
        block = block[:-1]
    match = _BLOCK_NUMBER.match(block)
    pos = match.end() if match else 0
    code = float(cycle[1:])  # "G83.1": a code with a decimal is written with it
    words = {}
    seen_g = False
    while pos < len(block):
        match = _WORD.match(block, pos)
        if not match:
            raise CycleError(block[pos], None, "cannot read %r as a %s word" % (block[pos:], cycle), cycle=cycle)
        letter, number = match.groups()
        pos = match.end()
        if too_many_digits(number):
            raise CycleError(letter, shortened(number), DIGITS_RULE, cycle=cycle)
        if letter == "G":
            if seen_g or ("." in number) != ("." in cycle) or float(number) != code:
                raise CycleError("G", float(number), "only %s may be programmed in this block" % cycle, cycle=cycle)
            seen_g = True
            continue
        if letter not in letters:
            raise CycleError(
                letter, float(number), "is not a word of %s (words: %s)" % (cycle, " ".join(letters)), cycle=cycle
            )
        if letter in words:
            raise CycleError(letter, float(number), "is programmed twice", cycle=cycle)
        if letter in counted:
            if "." in number:
                raise CycleError(
                    letter,
                    float(number),
                    "must be an integer in least input increments, without a decimal point (P2000 = 2 mm or 0.2 in)",
                    cycle=cycle,
                )
            words[letter] = int(number)
        else:
            value = float(number)
            if "." not in number and value != 0:
                raise CycleError(
                    letter,
                    value,
                    "needs a decimal point: without one the control reads it in least input increments "
                    "or per its zero-suppression setting; write %s%s." % (letter, number),
                    cycle=cycle,
                )
            words[letter] = value
    if not seen_g:
        raise CycleError("G", None, "the block must hold %s" % cycle, cycle=cycle)
    return words
