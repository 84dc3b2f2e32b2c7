"""A lathe tool table for LinuxCNC from the project's tool table.

    text = linuxcnc_tool_table(read_tool_table(source), "mm")

One line a tool, in LinuxCNC's tool table format (one format for mills and
lathes since LinuxCNC 2.4)::

    T5 P5 D0.4 I90 J0 Q2 ;T5: grooving blade 3 mm, corner radius 0.2, reference minus, external

* ``T`` and ``P``: the tool number, and the same pocket (a lathe turret's
  station; edit P where the turret differs);
* ``D``: the diameter of the blade's corner rounding, twice its corner radius
  (LinuxCNC's lathe "tip diameter");
* ``Q``: the orientation, LinuxCNC's 1..9: where the control point (the
  imaginary sharp corner the program drives, the blade's reference corner)
  sits on the tip's rounding. LinuxCNC's interpreter (interp_queue.cc,
  ``latheorigin_x``/``latheorigin_z``) puts it at low X for 1, 2, 6; high X
  for 3, 4, 8; low Z for 2, 3, 7; high Z for 1, 4, 5. A blade's front edge
  cuts at low X plunging toward -X (external), at high X toward +X
  (internal), at low Z toward -Z (face), at high Z toward +Z (back-face); its
  reference corner is on the -Z (X plunges) or -X (Z plunges) side for
  ``minus``, on the other for ``plus``;
* ``I`` and ``J``: the front and back angles LinuxCNC draws the tool with,
  degrees counter-clockwise from +Z with X up (the reading of LinuxCNC's own
  sample lathe table, configs/sim/axis/lathe.tbl: Q2 I85 J25, Q1 I95 J155,
  Q3 I275 J335, Q4 I265 J205): a blade's two edges leave the reference
  corner square, one along X (I: 90 or 270), one along Z (J: 0, 180 or 360);
* no ``X``/``Z`` offsets: they are measured on the machine (touch off); the
  table gives none rather than a guessed zero that would move every tool;
* a comment after ``;`` saying what the tool is.

LinuxCNC reads a tool table in the machine's units (the INI's
[TRAJ]LINEAR_UNITS); the lengths are written as the project's table gives
them, in ``units``, which the header names. The choices are in docs/tool-tables.md.
"""

from typing import Dict, NamedTuple, Optional, Sequence, Tuple

from ..errors import ProgramError
from ..moves import REFERENCE_MINUS, GroovingTool
from ..numbers import format_value
from ..tool_table import SIDES, ToolTable

__all__ = ["MAX_LINUXCNC_TOOL", "UNITS", "ToolLine", "blade_line", "linuxcnc_lines", "linuxcnc_tool_table",
           "orientation", "orientation_angles"]

UNITS = ("mm", "inch")
MAX_LINUXCNC_TOOL = 99999  # LinuxCNC's largest tool and pocket number (its lathe documentation); T0 is no tool

# side -> (the control point's X, Z on the tip for the minus reference corner, for the plus one)
_CORNERS: Dict[str, Tuple[Tuple[str, str], Tuple[str, str]]] = {
    "external": (("low", "low"), ("low", "high")),  # front edge at low X; minus at -Z
    "internal": (("high", "low"), ("high", "high")),  # front edge at high X
    "face": (("low", "low"), ("high", "low")),  # front edge at low Z; minus at -X
    "back-face": (("low", "high"), ("high", "high")),  # front edge at high Z
}
# (X, Z) of the control point -> LinuxCNC's orientation (interp_queue.cc's latheorigin_x/_z)
_ORIENTATION = {("low", "high"): 1, ("low", "low"): 2, ("high", "low"): 3, ("high", "high"): 4}
# orientation -> (I, J): the edges along X and along Z from the corner, into the blade
_ANGLES = {1: (90, 180), 2: (90, 0), 3: (270, 360), 4: (270, 180)}


def orientation(reference: str, side: str) -> int:
    """LinuxCNC's tool orientation Q of a blade whose reference corner is
    ``reference`` (minus/plus) cutting on ``side`` (tool_table.SIDES)."""
    minus, plus = _CORNERS[side]
    return _ORIENTATION[minus if reference == REFERENCE_MINUS else plus]


def orientation_angles(q: int) -> Tuple[int, int]:
    """(front angle I, back angle J) of a square-cornered blade of orientation ``q``."""
    return _ANGLES[q]


class ToolLine(NamedTuple):
    """One tool of a LinuxCNC tool table: its number, tip diameter D, and for a
    lathe blade its orientation Q with its angles (None: a round tool, an end
    mill or a wheel, written with D alone), a comment, and the line of the
    source that gave it (messages)."""

    number: int
    diameter: float
    orientation: Optional[int]
    comment: str
    line: Optional[int] = None


def blade_line(number: int, blade: GroovingTool, side: str, units: str, line: Optional[int] = None) -> ToolLine:
    """The tool line of a grooving blade cutting on ``side`` (tool_table.SIDES), lengths in ``units``."""
    return ToolLine(number, 2 * blade.corner_radius, orientation(blade.reference, side),
                    "grooving blade %s %s, corner radius %s, reference %s, %s"
                    % (format_value(blade.width), units, format_value(blade.corner_radius), blade.reference, side),
                    line)


def linuxcnc_lines(tools: Sequence[ToolLine], units: str, source: str) -> str:
    """The LinuxCNC tool table text of ``tools`` (format in the module notes),
    lengths in ``units``; ProgramError naming a tool number LinuxCNC cannot take."""
    if units not in UNITS:
        raise ProgramError("units=%s: must be mm or inch" % units)
    if not tools:
        raise ProgramError("%s lists no tool: nothing to write" % source)
    lines = [";LinuxCNC lathe tool table from %s, lengths in %s (the machine's units: the INI's "
             "[TRAJ]LINEAR_UNITS); X and Z offsets are touched off on the machine" % (source, units)]
    for tool in sorted(tools):
        if not 1 <= tool.number <= MAX_LINUXCNC_TOOL:
            raise ProgramError("T=%d: LinuxCNC's tool numbers are 1 to %d (T0 is no tool)"
                               % (tool.number, MAX_LINUXCNC_TOOL), tool.line)
        words = "T%d P%d D%s" % (tool.number, tool.number, format_value(tool.diameter))
        if tool.orientation is not None:
            words += " I%d J%d Q%d" % (orientation_angles(tool.orientation) + (tool.orientation,))
        lines.append("%s ;T%d: %s" % (words, tool.number, " ".join(tool.comment.split())))  # a label on one line
    return "\n".join(lines) + "\n"


def linuxcnc_tool_table(table: ToolTable, units: str) -> str:
    """The LinuxCNC tool table text of the project's ``table``. ProgramError
    naming the tool when a blade has no side= (its orientation would be a
    guess) or a number LinuxCNC cannot take."""
    tools = []
    for number in sorted(table):
        side, line = table.sides.get(number), table.lines.get(number)
        if side is None:
            raise ProgramError("T%d: its side is not given: add side=%s to its line (where the blade cuts decides "
                               "LinuxCNC's orientation Q)" % (number, "|".join(SIDES)), line)
        tools.append(blade_line(number, table[number], side, units, line))
    return linuxcnc_lines(tools, units, table.source)
