"""A Milltronics mill program from its items: tool changes, ops written as the
G33/G34 autoroutines (native) and ops written as their moves.

Pure Python (no FreeCAD): the ``milltronics_mill`` post (freecad/posts/
milltronics_mill.py) turns a Job's objects into these items, this writes
them with the engine's writer for the ``milltronics`` target.

The program: the title as a comment, ``G21 G90 G40`` (``G20`` in inch), then
the items in order, then ``M5`` and ``M30``:

- a tool change: ``G32`` (Z to the tool change position), ``T<n> M6``,
  ``S<rpm> M3`` (M4 counter-clockwise), ``D<n> G43 H<n>`` (as the manual's
  example: the diameter register G41/G42 and the autoroutines read, and the
  length offset, both numbered as the tool);
- a native op: a comment (the op, the G code, a note), ``G0 Z`` to its
  clearance, ``G0 X Y`` over the rectangle's centre, ``F`` the X-Y feed (the
  call's F is the Z feed), the P assignment blocks and the call, then
  ``G31``; the feed in force afterwards is not relied on;
- an op written as moves: a comment with the reason, then its G0/G1/G2/G3
  blocks as programmed (every axis the op's Path names; arcs in XY with their
  centre from the start as written).
An op's coolant: M8 (flood) or M7 (mist) before it, M9 after it.
"""

from typing import List, NamedTuple, Optional, Sequence, Union

from .cycles.milltronics import G31, G32, MilltronicsCycle
from .moves import RAPID, Move
from .output.program import ProgramBuilder, Spindle
from .output.writer import MAX_LINE, Writer

__all__ = ["MillMoves", "MillNative", "MillToolChange", "milltronics_program"]


class MillToolChange(NamedTuple):
    """The end mill of the items that follow: tool ``tool`` at ``rpm``, clockwise (M3) or not."""

    label: str
    tool: int
    rpm: float
    clockwise: bool = True


class MillNative(NamedTuple):
    """An op as an autoroutine: the call, where it starts and its feeds, in the program's units."""

    label: str
    call: MilltronicsCycle
    note: Optional[str]
    x: float
    y: float
    clearance: float
    xy_feed: float
    coolant: Optional[int] = None


class MillMoves(NamedTuple):
    """An op as its moves (mm, feeds mm/min; x, y, z None where a block does not name the axis; arcs with
    their centre (x, y)), with the reason it is not an autoroutine."""

    label: str
    reason: str
    moves: List[Move]
    coolant: Optional[int] = None


Item = Union[MillToolChange, MillNative, MillMoves]


def _tool_change(program: ProgramBuilder, item: MillToolChange) -> None:
    writer = program.writer
    program.add([G32().emit(), " ".join(writer.tool_change(item.tool))])
    program.tool = item.tool
    program.spindle = None
    program.start_spindle(Spindle(item.rpm, item.clockwise))
    # the manual's D1 G43 H1: the autoroutines' G41/G42 read the diameter register, every Z the length offset
    program.add([" ".join(["D%d" % item.tool] + writer.length_offset(item.tool))])
    writer.forget()


def _native(program: ProgramBuilder, item: MillNative) -> None:
    writer = program.writer
    title = item.call.NAME + ("; " + item.note if item.note else "")
    program.add([writer.comment("%s: %s" % (item.label, title), MAX_LINE - 2),
                 writer.code(RAPID) + " Z" + writer.number(item.clearance, writer.digits),
                 "%s X%s Y%s" % (writer.code(RAPID), writer.number(item.x, writer.digits),
                                 writer.number(item.y, writer.digits)),
                 "F" + writer.number(item.xy_feed, writer.digits)])
    program.add(item.call.emit().split("\n") + [G31().emit()])
    writer.forget()  # the call's F is the Z feed: the next feed move writes its own


def _moves(program: ProgramBuilder, item: MillMoves) -> None:
    writer = program.writer
    program.add([writer.comment("%s written as moves: %s" % (item.label, item.reason), MAX_LINE - 2)])
    for move in item.moves:
        program.add(writer.programmed_line(move))


def milltronics_program(items: Sequence[Item], inches: bool, title: str) -> str:
    """The whole program for ``items`` (see the module notes); ProgramError on what cannot be written."""
    scale = 1.0 / 25.4 if inches else 1.0
    program = ProgramBuilder(Writer("milltronics", not inches, False, scale=scale))
    program.begin(title)
    for item in items:
        if isinstance(item, MillToolChange):
            _tool_change(program, item)
            continue
        if item.coolant:
            program.m_code(item.coolant)
        if isinstance(item, MillNative):
            _native(program, item)
        else:
            _moves(program, item)
        if item.coolant:
            program.m_code(9)
    program.add([program.writer.m_code(5)])
    program.add(program.writer.footer())
    return program.text()
