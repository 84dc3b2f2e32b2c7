"""End mills by diameter register: the tool table a Milltronics program's G33/G34 take the tool's diameter from.

    table = read_mill_tool_table(text, "mill.tbl")   # MillToolTable: {1: 0.25, 2: 0.5}
    diameter = diameter_for(1, table, default=None)  # the diameter D1 selects

The text format, one register a line::

    # D  diameter
    1    0.25
    2    0.5

* two fields separated by spaces or tabs: the register number (the program's
  ``D1``: a whole number, 0 or more, once in the table) and the end mill's
  diameter (greater than 0), in the program's units at the time the cycle
  runs, like ``--tool-diameter``;
* ``#`` starts a comment, to the end of the line; blank lines are skipped.

Every line that breaks a rule raises ProgramError with its 1-based line
number in ``.line`` and a message naming the field, the value and the rule.

Which diameter G33/G34 get (``diameter_for``; the translator asks for the
cycles that read the P parameters): the table's entry for the D in force;
else ``Settings.mill_tool_diameter`` (``--tool-diameter``) when given; else
nothing, and the cycle is refused: a diameter guessed is a rectangle cut
with the wrong inset.
"""

import math
import re
from typing import Dict, Iterable, Optional, Tuple

from .errors import ProgramError
from .numbers import MAX_WORD

__all__ = ["MillToolTable", "diameter_for", "read_mill_tool_table"]

_WHOLE = re.compile(r"[0-9]+\Z")


class MillToolTable(Dict[int, float]):
    """Register number -> end mill diameter, with the name of the table it was read from (``source``)."""

    def __init__(self, tools: Iterable[Tuple[int, float]] = (), source: str = "the tool table") -> None:
        super().__init__(tools)
        self.source = source


def _entry(fields: list, line: int) -> Tuple[int, float]:
    if len(fields) != 2:
        raise ProgramError("%d fields: a line holds D and diameter (e.g. '1 0.25')" % len(fields), line)
    if not _WHOLE.match(fields[0]) or len(fields[0]) > 9:
        raise ProgramError("D=%s: must be a whole number, 0 or more" % fields[0], line)
    try:
        diameter = float(fields[1])
    except ValueError:
        diameter = math.nan
    if not 0 < diameter < MAX_WORD:  # also refuses NaN and infinities
        raise ProgramError("diameter=%s: must be a number greater than 0" % fields[1], line)
    return int(fields[0]), diameter


def read_mill_tool_table(text: str, source: str = "the tool table") -> MillToolTable:
    """The table in ``text`` (see the module notes); ProgramError naming the line and the rule."""
    table = MillToolTable(source=source)
    for number, line in enumerate(text.splitlines(), 1):
        fields = line.split("#", 1)[0].split()
        if not fields:
            continue
        register, diameter = _entry(fields, number)
        if register in table:
            raise ProgramError("D=%d: is in the table twice" % register, number)
        table[register] = diameter
    return table


def diameter_for(register: Optional[int], table: MillToolTable, default: Optional[float]) -> float:
    """The end mill diameter for D ``register`` in force (None: no D yet): the table's entry, else ``default``.
    ProgramError (without a line) saying what to give when neither has it."""
    if register is not None and register in table:
        return table[register]
    if default is not None:
        return default
    if register is None:
        raise ProgramError("the tool diameter is unknown: no D is programmed before it, so the tool table %s "
                           "cannot give it; program D<n> first or give --tool-diameter" % table.source)
    raise ProgramError("the tool diameter is unknown: D%d is not in the tool table %s; add it there, or give "
                       "--tool-diameter for the registers the table does not list" % (register, table.source))
