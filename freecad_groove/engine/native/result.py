"""What deciding a cycle call's native form gives: the target's own call
(:class:`NativeCall`), or why it is written as moves (:class:`NotNative`)."""

from typing import Any, List, NamedTuple, Optional, Tuple

from ..moves import RAPID, Move

__all__ = ["NativeCall", "NotNative", "Point"]


class NotNative(Exception):
    """Why a cycle call (a groove, an op) is written as moves instead of the
    control's own cycle: the message, one line, fit for a comment (no
    parentheses)."""


class Point(NamedTuple):
    """A point in the XZ plane: ``x`` a radius."""

    x: float
    z: float


class NativeCall(NamedTuple):
    """A cycle call written as the target's own cycle.

    ``model``: the target's cycle model, validated; its ``emit()`` gives the
    blocks (Fanuc's two, the P assignments and the call, the G7.1 region).
    ``moves``: what the control makes of the call from where it starts (the
    engine's expansion of the call as written, read back). ``approach``: the
    rapids (x radius, z) before the call, the last one to the point the call
    starts from; ``retreat``: the rapids after it. ``notes``: comments written
    before the call, the machine settings it relies on. ``feed``: the feed in
    force the call cuts at when it has no F of its own (CYCLE93; the X-Y feed
    of G33/G34), written before it unless in force. ``register``: the
    diameter register D the call reads (Milltronics), written before it.
    Lengths are in the output's units."""

    model: Any
    moves: List[Move]
    approach: Tuple[Point, ...] = ()
    retreat: Tuple[Point, ...] = ()
    notes: Tuple[str, ...] = ()
    feed: Optional[float] = None
    register: Optional[int] = None

    def all_moves(self) -> List[Move]:
        """The output's moves: the approach rapids, the call's (those that cut at
        the feed in force with ``feed``, when it is given), the retreat rapids."""
        moves = list(self.moves)
        if self.feed is not None:
            moves = [m._replace(f=self.feed) if m.kind != RAPID and m.f is None else m for m in moves]
        return ([Move(RAPID, p.x, p.z) for p in self.approach] + moves
                + [Move(RAPID, p.x, p.z) for p in self.retreat])
