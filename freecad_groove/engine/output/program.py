"""The one program builder: a whole program's lines for one target, from its
items (the frame, tool changes, the spindle, the feed mode, coolant, notes,
moves and native cycle calls), keeping what is in force so that each is
written only when it changes.

The posts turn a FreeCAD Job's objects into these calls; the command line's
``emit --expand`` and the grinder program too. What each item looks like is
the writer's (``writer.py``), from the target's table.

Choices: a spindle start on a lathe is ``G97 S<rpm> M3`` (G97 cancels a
constant surface speed the machine may hold), on a mill ``S<rpm> M3``; a
spindle left on is stopped (M5) before the program's end; after a tool change
the position is unknown (the next move writes every axis), and on a target
whose tool change stops the spindle (LinuxCNC's M6) the spindle is off.
"""

from typing import Any, Iterable, List, NamedTuple, Optional, Sequence, Union

from ..errors import ProgramError
from ..moves import RAPID, MachineState, Move
from ..numbers import MAX_WORD
from .native import native_lines
from .syntax import LATHE, Target
from .writer import Writer

__all__ = ["ProgramBuilder", "Spindle", "spindle_lines", "write_moves", "write_program"]

class Spindle(NamedTuple):
    """A spindle command as written: ``speed`` rpm, or a surface speed with
    ``limit`` the rpm limit (constant surface speed); ``clockwise`` M3, else M4."""

    speed: float
    clockwise: bool = True
    limit: Optional[float] = None

    @property
    def css(self) -> bool:
        return self.limit is not None


def spindle_lines(writer: Writer, spindle: Spindle) -> List[str]:
    """The lines that start ``spindle``."""
    m_code = writer.m_code(3 if spindle.clockwise else 4)
    if spindle.css:
        alone, words = writer.surface_speed(spindle.speed, spindle.limit)
        return alone + [" ".join(words + [m_code])]
    if writer.target.machine == LATHE:
        return [" ".join(writer.rpm_words(spindle.speed) + [m_code])]
    return [" ".join([writer.speed_word(spindle.speed), m_code])]


class ProgramBuilder:
    """Builds one program's text in ``lines`` (see the module notes).

    ``tool``: the tool number in force (None: none yet, or unknown);
    ``spindle``: the Spindle in force as written (None: off or unknown);
    ``spindle_on``: the program may have the spindle turning; ``per_rev``:
    feed per revolution in force (the setup line selects per minute); ``x``,
    ``z``: where the tool is, in the caller's units, x a radius (None after a
    tool change, a work offset)."""

    def __init__(self, writer: Writer, comments: bool = True) -> None:
        self.writer = writer
        self.target = writer.target
        self.comments = comments
        self.lines: List[str] = []
        self.tool: Optional[int] = None
        self.spindle: Optional[Spindle] = None
        self.spindle_on = False
        self.per_rev = False
        self.x: Optional[float] = None
        self.z: Optional[float] = None

    # -- lines
    def add(self, lines: Iterable[str]) -> None:
        self.lines.extend(lines)

    def note(self, text: str) -> None:
        """A comment, unless the program is written without comments."""
        if self.comments:
            self.lines.append(self.writer.comment(text))

    def m_code(self, number: int) -> None:
        self.lines.append(self.writer.m_code(number))

    def text(self) -> str:
        return "\n".join(self.lines) + "\n"

    # -- frame
    def begin(self, title: Optional[str], program_number: Optional[int] = None, notes: Sequence[str] = ()) -> None:
        """The frame, the title and ``notes`` (comments) and the setup lines."""
        if not self.comments:
            title, notes = None, ()
        self.add(self.writer.header(title, program_number, notes))

    def finish(self) -> None:
        """The spindle stopped when it may turn, then the program's end."""
        if self.spindle_on:
            self.stop_spindle()
        self.add(self.writer.footer())

    # -- position
    def moved(self, x: Optional[float] = None, z: Optional[float] = None) -> None:
        """The tool is now at radius ``x`` / ``z`` (None: that axis did not move)."""
        if x is not None:
            self.x = x
        if z is not None:
            self.z = z

    def rapid(self, x: Optional[float] = None, z: Optional[float] = None, force: bool = False) -> None:
        self.add(self.writer.move(RAPID, x, z, force=force))
        self.moved(x, z)

    def write(self, moves: Sequence[Move], prefix: str = "") -> None:
        """Moves through the writer; the tool is where the last one ends."""
        self.add(self.writer.write(moves, prefix))
        if moves:
            self.moved(moves[-1].x, moves[-1].z)

    def unknown_position(self) -> None:
        self.x = self.z = None
        self.writer.forget(position=True, motion=True, feed=False)

    # -- tools, spindle, feed mode, coolant
    def change_tool(self, number: int, note: str, offset: Optional[int] = None, own: bool = True) -> None:
        """The tool change to tool ``number`` after the comment ``note``, with the
        length offset ``offset`` (None: the tool's own)."""
        self.note(note)
        self.lines.append(" ".join(self.writer.tool_change(number, number if offset is None else offset, own)))
        self.tool = number
        self.unknown_position()
        if self.target.tool_change_stops_spindle:
            self.spindle_on = False
            self.spindle = None

    def start_spindle(self, spindle: Spindle) -> None:
        """``spindle``, unless it is in force."""
        if spindle == self.spindle:
            return
        self.add(spindle_lines(self.writer, spindle))
        self.spindle = spindle
        self.spindle_on = True

    def stop_spindle(self) -> None:
        self.m_code(5)
        self.spindle_on = False
        self.spindle = None

    def set_feed_mode(self, per_rev: bool) -> None:
        """Feed per revolution or per minute from here on (the code only when it changes; F is written again)."""
        if per_rev != self.per_rev:
            self.lines.append(self.writer.set_feed_mode(per_rev))
            self.per_rev = per_rev


def write_moves(moves: Iterable[Move], target: Union[str, Target], state: MachineState,
                motion: Optional[str] = None) -> List[str]:
    """Lines for ``moves`` for ``target``, dropping the words ``state`` makes
    redundant: the output is at state.x (a radius), state.z with state.feed in
    force and state.metric units; ``motion`` the motion in force (None: unknown)."""
    return Writer.from_state(state, target, motion).write(moves)


def write_program(moves: List[Move], target: Union[str, Target], state: MachineState, title: Optional[str] = None,
                  program_number: Optional[int] = None, spindle: Optional[float] = None, call: Any = None,
                  note: Optional[str] = None) -> str:
    """A whole program: the header, the spindle, a rapid to the start point, ``moves``, the end.

    ``call`` (engine/native's NativeCall): written in place of the moves, the
    target's own cycle (output/native.py); ``note``: a comment before the moves.

    The start point is (state.x, state.z) (and state.y, mill style); the
    tool's position before the program is unknown, so the approach writes
    every axis. state.feed, if set, is written on the first feed move that has
    no F of its own. ``spindle`` (rpm, optional) starts the spindle clockwise
    after the header (LinuxCNC refuses feed-per-revolution moves with the
    spindle stopped); a program that feeds per revolution needs it."""
    writer = Writer(target, state.metric, state.feed_per_rev)
    writer.default_feed = state.feed
    program = ProgramBuilder(writer)
    program.add(writer.header(title, program_number))
    if state.feed_per_rev and spindle is None and any(m.kind != RAPID for m in moves):
        raise ProgramError("feed per revolution needs a spindle speed: the spindle would not turn")
    if spindle is not None:
        if not 0 < spindle < MAX_WORD:
            raise ProgramError("spindle speed %r cannot be written" % (spindle,))
        program.add(spindle_lines(writer, Spindle(spindle)))
    program.write([Move(RAPID, state.x, state.z, y=state.y)])
    if note:
        program.add([writer.comment(note)])
    if call is not None:
        program.add(native_lines(writer, call))
    else:
        program.write(moves)
    program.add(writer.footer())
    return program.text()
