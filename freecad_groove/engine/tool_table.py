"""Grooving blades by tool number: the tool table a program's cycles take their blade from.

    table = read_tool_table(text, "tools.tbl")       # ToolTable: {5: GroovingTool(3.0, 0.2, "minus"), ...}
    blade = blade_for(5, table, default=None)        # the blade tool 5 cuts with
    table.reach[5]                                   # its free reach, when the table gives one

The text format, one tool a line::

    # T  width  corner-radius  reference  [reach]
    5    3.0    0.2            minus      12
    7    2.5    0.1            plus

* four fields separated by spaces or tabs: the tool number T (a whole number,
  0 or more, once in the table), the blade width (greater than 0), the corner
  radius of both front corners (0 or more, less than half the width) and the
  reference corner the tool's offset was measured on (``minus`` or ``plus``,
  see moves.GroovingTool);
* an optional fifth field, the blade's free reach (greater than 0): how deep
  it cuts before its holder meets the part (FreeCAD's grooving blade tool
  bit: CuttingEdgeHeight). When given, a CYCLE93 deeper than it (DEPG, as a
  radius) is refused (reach_problem); without it the reach is not checked;
* anywhere after the first four, optionally, ``side=SIDE``: where the blade
  cuts, ``external`` (plunging toward -X), ``internal`` (toward +X, in a
  bore), ``face`` (toward -Z) or ``back-face`` (toward +Z). The cycles do not
  need it (a cycle's own words say where it cuts); a lathe tool table written
  for a control does (``tools --to linuxcnc``: the tool's orientation);
* anywhere after the first four, optionally, what the blade's holder allows
  (blade_limits.py; each one given is checked, one not given is not):
  ``dmin=D`` and ``dmax=D``, a face-grooving blade's first-cut diameter
  range (a face groove's first plunge must cut between them); ``bore=D``, an
  internal bar's smallest bore (an internal groove's bore must be at least
  D); ``holder=W``, the holder's width across the blade, centred on it,
  beginning at the reach (needs the reach field): ``verify`` draws it and
  reports it entering standing material (verify/holder.py);
* ``#`` starts a comment, to the end of the line; blank lines are skipped;
* lengths are in the program's units at the time the cycle runs (a table for
  an inch program holds inches), like ``--tool-width``.

Every line that breaks a rule raises ProgramError with its 1-based line
number in ``.line`` and a message naming the field, the value and the rule.

Which blade a cycle gets (``blade_for``; the translator asks for the cycles
whose class declares ``NEEDS_BLADE``): the table's entry for the tool in force;
else the default blade (``Settings.tool``, the command line's ``--tool-width``)
when there is one; else nothing, and the cycle is refused: a blade guessed is
a groove cut with the wrong width.
"""

import math
import re
from typing import Dict, Iterable, Optional, Tuple

from .blade_limits import BladeLimits
from .errors import ProgramError
from .moves import REFERENCE_MINUS, REFERENCE_PLUS, GroovingTool
from .numbers import MAX_WORD, format_value

__all__ = ["BLADE_UNKNOWN", "SIDES", "ToolTable", "blade_for", "reach_problem", "read_tool_table"]

BLADE_UNKNOWN = "the blade width is unknown"
FIELDS = ("T", "width", "corner radius", "reference")
OPTIONAL_FIELDS = ("reach",)
SIDES = ("external", "internal", "face", "back-face")  # where a blade cuts: plunging -X, +X, -Z, +Z
TOLERANCE = 1e-9
_WHOLE = re.compile(r"[0-9]+\Z")


class ToolTable(Dict[int, GroovingTool]):
    """Tool number -> blade, with the name of the table it was read from
    (``source``, named in the translator's messages)."""

    def __init__(self, tools: Iterable[Tuple[int, GroovingTool]] = (), source: str = "the tool table") -> None:
        super().__init__(tools)
        self.source = source
        self.reach: Dict[int, float] = {}  # tool number -> the blade's free reach, where the table gives one
        self.sides: Dict[int, str] = {}  # tool number -> its side= (SIDES), where the line gives one
        self.lines: Dict[int, int] = {}  # tool number -> the line that gives it (messages)
        self.limits: Dict[int, BladeLimits] = {}  # tool number -> dmin=, dmax=, bore= (where a line gives one)
        self.holders: Dict[int, float] = {}  # tool number -> holder= (the holder's width)


def _number(field: str, text: str, line: int) -> float:
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not -MAX_WORD < value < MAX_WORD:  # also refuses NaN and infinities
        raise ProgramError("%s=%s: must be a number" % (field, text), line)
    return value


NUMBER_OPTIONS = ("dmin", "dmax", "bore", "holder")  # lengths (diameters, the holder's width), greater than 0


def _options(fields: list, line: int) -> Dict[str, object]:
    """The ``name=value`` fields of a line (removed from ``fields``): side=, dmin=, dmax=, bore=, holder=."""
    options: Dict[str, object] = {}
    for field in [f for f in fields if "=" in f]:
        fields.remove(field)
        name, value = field.split("=", 1)
        if name != "side" and name not in NUMBER_OPTIONS:
            raise ProgramError("%s: unknown; the named fields are side=, %s" % (
                field, ", ".join(n + "=" for n in NUMBER_OPTIONS)), line)
        if name in options:
            raise ProgramError("%s: %s= is given twice" % (field, name), line)
        if name == "side":
            if value not in SIDES:
                raise ProgramError("side=%s: must be %s" % (value, ", ".join(SIDES[:-1]) + " or " + SIDES[-1]),
                                   line)
            options[name] = value
            continue
        number = _number(name, value, line)
        if not number > 0:
            raise ProgramError("%s=%s: must be greater than 0 (leave the field out when it is not known)"
                               % (name, value), line)
        options[name] = number
    if "dmin" in options and "dmax" in options and not options["dmin"] < options["dmax"]:
        raise ProgramError("dmin=%s: must be less than dmax=%s" % (
            format_value(options["dmin"]), format_value(options["dmax"])), line)
    return options


def _holder_options(number: int, tool: GroovingTool, reach: Optional[float], options: dict, table: "ToolTable",
                    line: int) -> None:
    """A line's dmin=, dmax=, bore= and holder= into ``table`` (holder= needs the reach, at least the width)."""
    if any(name in options for name in ("dmin", "dmax", "bore")):
        table.limits[number] = BladeLimits(options.get("dmin"), options.get("dmax"), options.get("bore"))
    if "holder" in options:
        holder = options["holder"]
        if reach is None:
            raise ProgramError("holder=%s: needs the reach field (the holder begins at the blade's free reach)"
                               % format_value(holder), line)
        if holder < tool.width - TOLERANCE:
            raise ProgramError("holder=%s: must be at least the blade's width %s"
                               % (format_value(holder), format_value(tool.width)), line)
        table.holders[number] = holder


def _tool_line(fields: list, line: int) -> Tuple[int, GroovingTool, Optional[float]]:
    """One table line's tool number, blade and reach (None: not given; the rules in the module notes)."""
    if not len(FIELDS) <= len(fields) <= len(FIELDS) + len(OPTIONAL_FIELDS):
        raise ProgramError("%d fields: a tool line has %d: %s (and optionally %s)"
                           % (len(fields), len(FIELDS), ", ".join(FIELDS), ", ".join(OPTIONAL_FIELDS)), line)
    number_text, width_text, radius_text, reference = fields[:len(FIELDS)]
    reach = None
    if len(fields) > len(FIELDS):
        reach = _number("reach", fields[len(FIELDS)], line)
        if not reach > 0:
            raise ProgramError("reach=%s: must be greater than 0 (leave the field out when it is not known)"
                               % fields[len(FIELDS)], line)
    if not _WHOLE.match(number_text):
        raise ProgramError("T=%s: must be a whole number, 0 or more" % number_text, line)
    width = _number("width", width_text, line)
    if not width > 0:
        raise ProgramError("width=%s: must be greater than 0" % width_text, line)
    radius = _number("corner radius", radius_text, line)
    if not 0 <= radius < width / 2:
        raise ProgramError("corner radius=%s: must be 0 or more and less than half the width %s"
                           % (radius_text, format_value(width)), line)
    if reference not in (REFERENCE_MINUS, REFERENCE_PLUS):
        raise ProgramError("reference=%s: must be %s or %s" % (reference, REFERENCE_MINUS, REFERENCE_PLUS), line)
    return int(number_text), GroovingTool(width, radius, reference), reach


def read_tool_table(text: str, source_name: str = "the tool table") -> ToolTable:
    """The tools of a tool table text (format in the module notes); ProgramError
    with ``.line`` on the first line that breaks a rule. ``source_name`` names
    the table in later messages (``ToolTable.source``)."""
    table = ToolTable(source=source_name)
    lines = table.lines
    for line, raw in enumerate(text.splitlines(), 1):
        fields = raw.split("#", 1)[0].split()
        if not fields:
            continue
        options = _options(fields, line)
        number, tool, reach = _tool_line(fields, line)
        if number in table:
            raise ProgramError("T=%d: must be unique; line %d gives it already" % (number, lines[number]), line)
        table[number] = tool
        if reach is not None:
            table.reach[number] = reach
        if "side" in options:
            table.sides[number] = options["side"]
        _holder_options(number, tool, reach, options, table, line)
        lines[number] = line
    return table


def blade_for(tool: Optional[int], table: Optional[ToolTable], default: Optional[GroovingTool]) -> GroovingTool:
    """The blade a cycle that needs one cuts with, tool ``tool`` in force (None:
    no T yet): the ``table``'s entry, else ``default``. ProgramError (without a
    line) saying what to give when neither has it."""
    if table is not None and tool is not None and tool in table:
        return table[tool]
    if default is not None:
        return default
    if table is None:
        raise ProgramError(BLADE_UNKNOWN + ": give --tool-width or a tool table")
    if tool is None:
        raise ProgramError("%s: no tool (T) is selected before it, so the tool table %s cannot give the blade; "
                           "program T first or give --tool-width for it" % (BLADE_UNKNOWN, table.source))
    raise ProgramError("%s: T%d is not in the tool table %s; add it there, or give --tool-width for the tools "
                       "the table does not list" % (BLADE_UNKNOWN, tool, table.source))


def reach_problem(depth: float, tool: Optional[int], table: Optional[ToolTable], what: str) -> Optional[str]:
    """Why a groove ``depth`` deep (``what``: the word that gives it, "CYCLE93 DEPG=15") cannot be cut by the
    blade of tool ``tool`` in ``table``: deeper than the reach the table gives it; None when it can, or when
    the table gives no reach for it (not checked)."""
    reach = table.reach.get(tool) if table is not None and tool is not None else None
    if reach is None or not depth > reach + TOLERANCE:
        return None
    return ("%s: deeper than the free reach %s of T%d's blade (%s): its holder would hit the part; use a blade "
            "that reaches %s or groove less deep" % (what, format_value(reach), tool, table.source,
                                                     format_value(depth)))
