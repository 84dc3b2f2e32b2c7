"""A grinder program from plunge grinds (the FreeCAD Plunge grind op's plans)
and plain moves: for the Allen-Bradley 9/Series grinder with native
G83/G83.1 calls, or with the cycles expanded for a mill-style target.

Pure Python (no FreeCAD): the FreeCAD posts (freecad/posts/grind.py) gather
the items, this writes them. Every position is in the grinder's axes: x the
reciprocation (X words), y the plunge (Y words), z the crossover (Z words).

Per grind: a comment (the op and face), G0 Y to the safe plunge position, G0
X Z over the start point, G0 Y down to it; then the native G83/G83.1 block
(the cycle starts where the wheel stands) or the engine's expansion (a dress
is the target's subprogram call; the 9/Series' own call is not in the
manuals this follows: an expanded dress for it is refused); then G0 Y back
to the safe position. An item's coolant: its M code after the comment, M9
(``M09`` for the 9/Series) after its last move. After a native cycle the output forgets the position
(every axis of the next move is written).

The wheel (WheelChange items, one before the ops of each tool controller):
a tool change when the tool number differs from the one in force (9/Series
``T<nn> M06``, LinuxCNC ``T<n> M6 G43``), the output then forgetting the
position; its spindle (``S<rpm> M03``/``M04``; LinuxCNC ``M3``/``M4``)
written after every tool change (LinuxCNC's M6 stops the spindle) and
whenever the speed or the direction changes; rpm 0 stops it (M05/M5). A
spindle left on is stopped before the program's end. The 9/Series' S is a
whole number of rpm (refused otherwise); tool numbers 1..99 (9/Series) or
1..99999 (LinuxCNC).

Targets: "ab9grind" (native or expanded; "%", O number, G90 G94 G21 ... M30,
read back by the engine's ab9grind reader) and "linuxcnc" (expanded only:
the linuxcnc-mill writer, dress calls ``o<dressN> call``).
"""

from typing import List, NamedTuple, Optional, Sequence, Union

from .cycles.ab_g83 import G83
from .errors import ProgramError
from .moves import DRESS, RAPID, MachineState, Move
from .output.program import ProgramBuilder, Spindle
from .output.targets import program_target
from .output.writer import Writer

TARGETS = ("ab9grind", "linuxcnc")  # the grinder posts' targets (linuxcnc: its mill twin)


class GrindItem(NamedTuple):
    """One plunge grind: its call, the start point, the safe plunge position, the expansion."""

    label: str
    call: G83
    start: MachineState
    safe: float
    moves: List[Move]
    coolant: Optional[int] = None  # the coolant M code (8 flood, 7 mist) on before the op, M9 after


class PlainMoves(NamedTuple):
    """Another op's moves (RAPID/FEED, grinder axes), written as they are."""

    label: str
    moves: List[Move]
    coolant: Optional[int] = None


class WheelChange(NamedTuple):
    """The wheel of the items that follow: tool ``tool`` turning at ``rpm`` (0: stopped), clockwise (M3) or not."""

    label: str
    tool: int
    rpm: float
    clockwise: bool = True


MAX_RPM = 99999
Item = Union[GrindItem, PlainMoves, WheelChange]


def _retract(writer: Writer, safe: float) -> List[str]:
    """G0 Y to the safe plunge position, the other axes where they are (known to the output or not)."""
    line = "%s Y%s" % (writer.code(RAPID), writer.y_word(safe))
    writer.sync(None, None, None, RAPID, safe)  # X and Z: the next move writes them
    return [line]


def _grind_lines(writer: Writer, item: GrindItem, native: bool) -> List[str]:
    start = item.start
    lines = [writer.comment(item.label)] + _retract(writer, item.safe)
    lines += writer.write([Move(RAPID, start.x, start.z, y=item.safe), Move(RAPID, start.x, start.z, y=start.y)])
    if native:
        return lines + [item.call.emit()] + _retract(writer, item.safe)  # the cycle moved the wheel
    if not writer.target.dress_call and any(m.kind == DRESS for m in item.moves):
        raise ProgramError("%s: a dress (P%d) cannot be written expanded for the 9/Series: its subprogram call "
                           "is not in the manuals this post follows (write the cycle native, or DressCount 0 and "
                           "no G83.1)" % (item.label, item.call.P))
    lines.append(writer.comment(item.call.emit()))
    lines += writer.write(item.moves)
    return lines + _retract(writer, item.safe)


class _Wheel:
    """The tool in force in the program being written (the builder keeps the spindle)."""

    def __init__(self, program: ProgramBuilder):
        self.program = program
        self.tool: Optional[int] = None

    def change(self, item: WheelChange) -> None:
        """The tool change if needed, then the spindle if not in force."""
        program, target = self.program, self.program.target
        if not (isinstance(item.tool, int) and 1 <= item.tool <= target.max_tool):
            raise ProgramError("%s: tool number %r cannot be written (1..%d)" % (item.label, item.tool,
                                                                                  target.max_tool))
        if item.tool != self.tool:
            program.add([program.writer.comment("tool %d: %s" % (item.tool, item.label)),
                         " ".join(program.writer.tool_change(item.tool, item.tool))])
            self.tool = item.tool
            program.spindle = None
            program.spindle_on = True  # unknown after a change: a stop is written
            program.writer.forget(motion=False, feed=False)  # the change may move the axes: write them all
        if not item.rpm > 0:
            if program.spindle_on:
                program.stop_spindle()
            return
        if not item.rpm <= MAX_RPM:
            raise ProgramError("%s: spindle speed %r cannot be written" % (item.label, item.rpm))
        try:
            program.start_spindle(Spindle(item.rpm, item.clockwise))
        except ProgramError as exc:
            raise ProgramError("%s: %s" % (item.label, exc)) from None


def grind_program(items: Sequence[Item], target: str, native: bool, title: str, number: int = 1) -> str:
    """The whole program for ``items`` (see the module notes); ProgramError on what cannot be written."""
    if target not in TARGETS:
        raise ProgramError("unknown grinder target %r (known: %s)" % (target, ", ".join(TARGETS)))
    writer = Writer(program_target(target, True), True, False)
    if native and not writer.target.native.grinds:
        raise ProgramError("%s has no G83 cycle: the cycles are expanded for it" % target)
    program = ProgramBuilder(writer)
    program.begin(title, number)
    wheel = _Wheel(program)
    for item in items:
        if isinstance(item, WheelChange):
            wheel.change(item)
            continue
        if isinstance(item, GrindItem):
            body = _grind_lines(writer, item, native)
        else:
            body = [writer.comment(item.label)] + writer.write(item.moves)
        if item.coolant:
            body = body[:1] + [writer.m_code(item.coolant)] + body[1:] + [writer.m_code(9)]
        program.add(body)
    program.finish()
    return program.text()
