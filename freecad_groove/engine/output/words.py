"""Numbers and comments as a control reads them: the one number formatter of
every output word, and comments made safe (see writer.py's module notes)."""

import re

from ..errors import ProgramError
from ..numbers import MAX_WORD, format_decimal

__all__ = ["MAX_COMMENT", "MAX_LINE", "comment_text", "format_number"]

MAX_COMMENT = 140
MAX_LINE = 250  # LinuxCNC refuses blocks longer than 252 characters ("Command too long")


def format_number(value: float, digits: int) -> str:
    """``value`` with at most ``digits`` decimals, a decimal point always, no ``-0``;
    ProgramError for magnitudes of MAX_WORD and above and NaN."""
    if not -MAX_WORD < value < MAX_WORD:  # also refuses NaN
        raise ProgramError("value %r cannot be written (not a number below %g in magnitude)" % (value, MAX_WORD))
    return format_decimal(value, digits)


_ACTIVE_COMMENT = re.compile(r"(?i)\s*(?:[a-z_]+\s*,|logclose|logopen|logappend|probeopen|probeclose|py\b|abort\b)")
_NOT_PRINTABLE = re.compile(r"[^\x20-\x7e]")


def comment_text(text: str, limit: int = MAX_COMMENT) -> str:
    """The text of a comment made safe (see the module notes), cut to ``limit``
    characters (ending in ``...``)."""
    text = _NOT_PRINTABLE.sub("?", text.replace("(", "").replace(")", "")).strip()
    if _ACTIVE_COMMENT.match(text):
        text = "- " + text
    if len(text) > limit:
        text = text[: max(0, limit - 3)] + "..."
    return text
