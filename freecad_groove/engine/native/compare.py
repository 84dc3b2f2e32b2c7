"""Whether two move lists cut the same: the proof a converted call is written by.

Both lists are read as the control runs them: every axis a move leaves out
stays where it was, a feed move without F cuts at the feed in force, and a
straight move that goes nowhere (within the tolerance) is dropped (a cycle
may start with a rapid to where the tool stands). Then the lists must match
move for move: the same kinds, every position within the tolerance (the
output's resolution), the same feeds, dwells and dress calls, arcs about
the same centre.
"""

import math
from typing import List, NamedTuple, Optional, Sequence, Tuple

from ..moves import ARCS, FEED, RAPID, MachineState, Move
from ..numbers import format_decimal

__all__ = ["Step", "difference", "resolved"]

DESCRIBED_DECIMALS = 4


class Step(NamedTuple):
    """One move as the control makes it: every axis absolute (None: never
    known), the feed it cuts at (None for a rapid), the dwell or program."""

    kind: str
    x: Optional[float]
    z: Optional[float]
    y: Optional[float]
    c: Optional[float]
    f: Optional[float]
    p: float
    centre: Optional[Tuple[float, float]]
    radius: Optional[float]


def _near(a: Optional[float], b: Optional[float], tolerance: float) -> bool:
    if a is None or b is None:
        return a is b
    return abs(a - b) <= tolerance


def resolved(moves: Sequence[Move], start: MachineState, tolerance: float, feed: Optional[float] = None) -> List[Step]:
    """``moves`` from ``start`` as Steps (see the module notes); ``feed``: the
    feed in force at the start (default ``start.feed``)."""
    here = [start.x, start.z, start.y, start.c]
    feed = start.feed if feed is None else feed
    steps: List[Step] = []
    for move in moves:
        target = [here[k] if value is None else value for k, value in enumerate((move.x, move.z, move.y, move.c))]
        if move.f is not None:
            feed = move.f
        if move.kind in (RAPID, FEED) and all(_near(a, b, tolerance) for a, b in zip(target, here)):
            continue
        here = target
        cuts = move.kind == FEED or move.kind in ARCS
        steps.append(Step(move.kind, here[0], here[1], here[2], here[3], feed if cuts else None, move.p,
                          move.centre, move.radius))
    return steps


def _same(a: Step, b: Step, tolerance: float) -> bool:
    if a.kind != b.kind or not all(_near(u, v, tolerance) for u, v in zip(a[1:5], b[1:5])):
        return False
    if not _near(a.f, b.f, 1e-9 * max(1.0, abs(a.f or 0.0))) or abs(a.p - b.p) > 1e-9:
        return False
    if (a.centre is None) != (b.centre is None) or (a.radius is None) != (b.radius is None):
        return False
    if a.centre is not None and math.dist(a.centre, b.centre) > tolerance:
        return False
    return a.radius is None or abs(a.radius - b.radius) <= tolerance


def describe(step: Step, mill: bool = False) -> str:
    """A step as a block would say it (X a diameter on a lathe)."""
    words = [step.kind]
    for letter, value in (("X", step.x), ("Y", step.y), ("Z", step.z), ("C", step.c)):
        if value is not None:
            value = value if (mill or letter != "X") else 2.0 * value
            words.append(letter + format_decimal(value, DESCRIBED_DECIMALS))
    if step.f is not None:
        words.append("F" + format_decimal(step.f, 6))
    return " ".join(words)


def difference(expected: Sequence[Step], got: Sequence[Step], tolerance: float, mill: bool = False) -> Optional[str]:
    """None when the steps are the same within ``tolerance``, else where they
    first differ (one line): ``expected`` the program's own, ``got`` the call's."""
    for index, (a, b) in enumerate(zip(expected, got)):
        if not _same(a, b, tolerance):
            return "move %d is %s, not %s" % (index + 1, describe(b, mill), describe(a, mill))
    if len(expected) != len(got):
        return "%d moves, not %d" % (len(got), len(expected))
    return None
