"""Any other object's Path (a turning op, a custom Path, a dressup's Path, the
Job's fixture blocks) as the control's plain moves.

Each command is read (:class:`Command`), checked for axes a lathe post does
not write, and handed to the method the tables at the end of
:class:`PathCommands` name for it: G codes by their code (``"G59.1"``), then
by ranges of their number (G59.x work offsets, G73..G89 drilling cycles); M
codes by their number (a fraction is not read). Anything else is refused with
an error naming the op and the command.
"""

from __future__ import annotations

import math
import re
from typing import TYPE_CHECKING, Any, Callable, Dict, Iterable, NamedTuple, NoReturn, Optional, Tuple

from ...engine import FEED, RAPID
from ...engine.moves import ARC_CCW, ARC_CW, Move
from ...engine.numbers import ARC_IJK_TOLERANCE, format_decimal
from ...engine.output.program import Spindle, spindle_lines
from ...engine.output.syntax import ARC_CR
from ..units import feed_mm_per_min
from .post_error import PostError

if TYPE_CHECKING:
    from .program import Program

_CODE = re.compile(r"^([GMT])0*(\d+)(\.\d+)?$")
TOL = 1e-9
OTHER_AXES = ("A", "B", "C", "U", "V", "W")
PLANE_NAMES = {"G17": "XY", "G19": "YZ"}
# Codes the posts write themselves (absolute, no compensation, per minute, mm): dropped from Paths.
POST_MODES = ("G90", "G40", "G49", "G80", "G94", "G21", "G98", "G99", "G43")
REFUSED = {
    "G91": "incremental distances (G91) are not written; FreeCAD ops program absolute positions",
    "G41": "tool nose radius compensation is not written by these posts",
    "G42": "tool nose radius compensation is not written by these posts",
}


class Command(NamedTuple):
    """One Path command, read: ``letter`` G/M/T, ``number``, ``fraction`` (".1" or
    None), ``params`` (upper-case words, floats) and the FreeCAD command itself."""

    letter: str
    number: int
    fraction: Optional[str]
    params: Dict[str, float]
    source: Any

    @property
    def code(self) -> str:
        """The code without leading zeros, with its fraction: "G1", "G59.1"."""
        return "%s%d%s" % (self.letter, self.number, self.fraction or "")


Handler = Callable[["PathCommands", Command], None]


class PathCommands:
    """Writes one object's Path commands into a Program as plain moves.

    ``plane``: the arc plane in force (FreeCAD's default G17 until the Path
    selects another)."""

    def __init__(self, program: Program, label: str) -> None:
        self.program = program
        self.label = label
        self.plane = "G17"

    def write(self, commands: Iterable[Any]) -> None:
        for cmd in commands:
            name = cmd.Name.strip()
            if name.startswith("("):
                self.program.note(name[1:-1] if name.endswith(")") else name[1:])
                continue
            command = self._read(cmd, name.upper())
            self._check_axes(command)
            self._handler(command)(self, command)

    def _read(self, cmd: Any, name: str) -> Command:
        params = {k.upper(): float(v) for k, v in cmd.Parameters.items()}
        match = _CODE.match(name)
        if not match:
            raise PostError("command %s cannot be written by a lathe post" % cmd.toGCode(), op=self.label)
        return Command(match.group(1), int(match.group(2)), match.group(3), params, cmd)

    def refuse(self, command: Command, why: str) -> NoReturn:
        raise PostError("%s: %s" % (command.source.toGCode().strip(), why), op=self.label)

    def _check_axes(self, command: Command) -> None:
        for axis in OTHER_AXES:
            if axis in command.params:
                self.refuse(command, "axis %s: a lathe post writes X and Z only" % axis)
        if abs(command.params.get("Y", 0.0)) > TOL:
            self.refuse(command, "Y%s: a Y move; a lathe post writes moves in the XZ plane (X radius, Z) only"
                        % format_decimal(command.params["Y"], 4))

    def _handler(self, command: Command) -> Handler:
        handler: Optional[Handler] = None
        if command.letter == "G":
            handler = self.G_CODES.get(command.code)
            if handler is None:
                handler = next((h for numbers, h in self.G_NUMBERS if command.number in numbers), None)
        elif command.letter == "M":
            handler = self.M_NUMBERS.get(command.number)
        return handler or PathCommands._unknown

    # -- G codes
    def _straight(self, command: Command) -> None:
        """G0, G1: a move to the given axes."""
        params = command.params
        kind = RAPID if command.code == "G0" else FEED
        f = feed_mm_per_min(params["F"]) if (kind == FEED and "F" in params) else None
        if kind == FEED and f is not None and not f > 0:
            self.refuse(command, "feed F%s: must be greater than 0" % format_decimal(params["F"], 6))
        x, z = params.get("X"), params.get("Z")
        if kind == FEED:
            self.program.set_feed_mode(False)  # a Path's F is per minute
        self.program.add(self.program.writer.move(kind, x, z, f))
        self.program.moved(x, z)

    def _arc(self, command: Command) -> None:
        """G2, G3: an arc in the XZ plane with its centre I/K from the start (written the target's way:
        I/K from the start as written, Siemens CR=)."""
        params, program = command.params, self.program
        if self.plane != "G18":
            self.refuse(command, "an arc in the %s plane; a lathe post writes arcs in the XZ plane (G18) only"
                        % PLANE_NAMES[self.plane])
        if abs(params.get("J", 0.0)) > TOL:
            self.refuse(command, "J%s: an arc centre off the XZ plane" % format_decimal(params["J"], 4))
        if "R" in params:
            self.refuse(command, "R-form arcs are not written; give the centre with I and K")
        if program.x is None or program.z is None:
            self.refuse(command, "an arc from an unknown position: program X and Z before it")
        start = (program.x, program.z)
        end = (params.get("X", program.x), params.get("Z", program.z))
        centre = (start[0] + params.get("I", 0.0), start[1] + params.get("K", 0.0))
        radius, end_radius = math.dist(start, centre), math.dist(end, centre)
        if radius < TOL or abs(radius - end_radius) > ARC_IJK_TOLERANCE:
            self.refuse(command, "the arc's end is not on its circle (radius %.4f at the start, %.4f at the end)"
                        % (radius, end_radius))
        if program.target.arc_form == ARC_CR and math.dist(start, end) < TOL:
            self.refuse(command, "a full circle cannot be written with CR=")
        f = feed_mm_per_min(params["F"]) if "F" in params else None
        program.set_feed_mode(False)
        program.add(program.writer.programmed_line(Move(ARC_CW if command.code == "G2" else ARC_CCW, end[0], end[1], f,
                                                        centre=centre), "arc"))
        program.moved(*end)

    def _dwell(self, command: Command) -> None:
        params = command.params
        seconds = params.get("P", params.get("S", params.get("X", 0.0)))
        self.program.add([self.program.writer.dwell(seconds)])

    def _plane(self, command: Command) -> None:
        self.plane = command.code

    def _work_offset(self, command: Command) -> None:
        last = self.program.target.last_work_offset
        if command.number > last:
            self.refuse(command, "work offset %s: the %s output's settable offsets are G54..G%d here"
                        % (command.code, self.program.target.maker, last))
        self.program.add([command.code])
        self.program.unknown_position()

    def _dropped(self, command: Command) -> None:
        """A mode the post writes itself, or a program end (the post ends the program)."""

    def _refused(self, command: Command) -> None:
        self.refuse(command, REFUSED[command.code])

    def _drilling(self, command: Command) -> None:
        self.refuse(command, "a canned drilling cycle; lathe posts do not translate FreeCAD's XY drilling cycles")

    def _unknown(self, command: Command) -> None:
        self.refuse(command, "not a command these lathe posts write")

    # -- M codes
    def _spindle(self, command: Command) -> None:
        """M3, M4, with the speed S when the command has one."""
        program = self.program
        if "S" in command.params:
            spindle = Spindle(int(round(command.params["S"])), command.number == 3)
            program.add(spindle_lines(program.writer, spindle))
            program.spindle = spindle
        else:
            program.m_code(command.number)
            program.spindle = None  # running, at a speed the post did not write
        program.spindle_on = True

    def _spindle_stop(self, command: Command) -> None:
        self.program.stop_spindle()

    def _m_code(self, command: Command) -> None:
        """An M code written as it is: program stops, coolant."""
        self.program.m_code(command.number)

    def _tool_change(self, command: Command) -> None:
        """M6 T..: the control's tool change; the tool controller in force is forgotten."""
        if "T" not in command.params:
            self.refuse(command, "M6 without T")
        number = int(command.params["T"])
        self.program.change_tool(number, "tool %d" % number)
        self.program.tool_state = None

    # -- the tables: what each command is written by
    G_CODES: Dict[str, Handler] = {
        "G0": _straight, "G1": _straight, "G2": _arc, "G3": _arc, "G4": _dwell,
        "G17": _plane, "G18": _plane, "G19": _plane,
        **dict.fromkeys(["G%d" % number for number in range(54, 60)], _work_offset),
        **dict.fromkeys(POST_MODES, _dropped),
        **dict.fromkeys(REFUSED, _refused),
    }
    G_NUMBERS: Tuple[Tuple[range, Handler], ...] = (
        (range(59, 60), _work_offset),  # G59.1, G59.2, ...
        (range(73, 90), _drilling),
    )
    M_NUMBERS: Dict[int, Handler] = {
        3: _spindle, 4: _spindle, 5: _spindle_stop, 0: _m_code, 1: _m_code, 7: _m_code, 8: _m_code, 9: _m_code,
        6: _tool_change, 2: _dropped, 30: _dropped,
    }
