"""A native cycle call in a program's lines (``engine/native``'s NativeCall):
the notes it relies on as comments, the rapids to where it starts (the last
one writing both axes: the call starts where the tool stands), the feed in
force it cuts at and the diameter register it reads (each only when the
output does not hold it already), the call's blocks as the cycle model
emits them, the rapids after it.

After the call the output knows where the tool is (the end of the call's
moves), and the feed in force (the last the call's moves feed at); the
motion mode it leaves is not relied on (the next move writes its code).
"""

from typing import Any, List

from ..moves import RAPID
from .writer import Writer

__all__ = ["native_lines"]


def native_lines(writer: Writer, call: Any, prefix: str = "") -> List[str]:
    """The lines of ``call`` (a NativeCall), each after ``prefix`` ("/" for block delete)."""
    lines = [writer.comment(note) for note in call.notes]
    for index, point in enumerate(call.approach):
        lines += writer.move(RAPID, point.x, point.z, force=index == len(call.approach) - 1)
    if call.feed is not None:
        text = writer.f_word(call.feed)
        if text != writer.f_text:
            lines.append("F" + text)
            writer.f_text = text
    if call.register is not None:
        lines.append("D%d" % call.register)
    lines += call.model.emit().split("\n")
    _after(writer, call.moves)
    for point in call.retreat:
        lines += writer.move(RAPID, point.x, point.z)
    return [prefix + line for line in lines]


def _after(writer: Writer, moves: List[Any]) -> None:
    """The output at the end of the call's ``moves``: each axis where the last
    move that sets it put it, the feed the last one fed at, no motion known."""
    for axis, word in (("x", writer.x_word), ("z", writer.z_word), ("y", writer.y_word)):
        values = [getattr(move, axis) for move in moves if getattr(move, axis) is not None]
        if values:
            setattr(writer, axis + "_text", word(values[-1]))
    turns = [move.c for move in moves if move.c is not None]
    if turns and writer.target.c_feed:
        writer.c_text = writer.number(turns[-1], writer.digits)
    feeds = [move.f for move in moves if move.f is not None]
    if feeds:
        writer.f_text = writer.f_word(feeds[-1])
    writer.motion = None
