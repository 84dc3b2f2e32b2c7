"""Arc moves (moves.ARC_CW / ARC_CCW) as the straight pieces the simulation
and the figures sweep (their chords: engine/arcs.py).

The chords' ends lie on the arc: each chord is at most ``tol`` inside it. The
simulation's ``SWEEP_TOL`` (1e-5 mm) is a hundredth of the 0.001 mm the
gouge and leftover checks report from, half the blade outline's own excess
(blade.ARC_EXCESS): a chord can neither hide a gouge nor make one that the
check would report.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator

from freecad_groove.engine.arcs import arc_chords, radius_centre
from freecad_groove.engine.moves import ARC_CW, ARCS, DWELL, FEED, Move

__all__ = ["ARC_END_TOL", "SWEEP_TOL", "TIME_TOL", "arc_centre", "arc_chords", "radius_centre", "straight",
           "straightened"]

Point = tuple[float, float]  # (x, z), x the radius

SWEEP_TOL = 1e-5  # mm: the chords the simulation sweeps for an arc stay this close to it
TIME_TOL = 1e-3  # mm: the chords an arc's machining time is taken along (its length within 0.01 %)
# An arc whose end is farther than this from its circle (more than the 0.001 mm
# the checks report) is not one the engine or a control writes: refused.
ARC_END_TOL = 1e-3


def arc_centre(move: Move, start: Point) -> Point:
    """The centre of an arc move from ``start`` (given, or from its radius);
    ValueError for one whose end is off its circle by more than ARC_END_TOL."""
    end = (float(move.x), float(move.z))
    if move.centre is not None:
        centre = (float(move.centre[0]), float(move.centre[1]))
    elif move.radius is not None:
        centre = radius_centre(start, end, float(move.radius), move.kind == ARC_CW)
    else:
        raise ValueError("%s to X%.4f Z%.4f (radius X) has neither a centre nor a radius" % (move.kind, end[0], end[1]))
    off = abs(math.dist(start, centre) - math.dist(end, centre))
    if not off <= ARC_END_TOL:
        raise ValueError("%s to X%.4f Z%.4f (radius X): its end is %.4g mm off the circle through its start"
                         % (move.kind, end[0], end[1], off))
    return centre


def straightened(moves: Iterable[Move], start: Point, tol: float = SWEEP_TOL) -> Iterator[tuple[int, Move]]:
    """(index, move) of ``moves`` from ``start`` with each arc as FEED chords
    within ``tol`` of it (its feed on the first), each with the arc's index;
    the other moves as they are. A move without x (a Z-only rapid) keeps
    the position's x."""
    position = (float(start[0]), float(start[1]))
    for index, move in enumerate(moves):
        if move.kind in ARCS:
            chords = arc_chords(position, (float(move.x), float(move.z)), arc_centre(move, position),
                                move.kind == ARC_CW, tol)
            for k, (x, z) in enumerate(chords):
                yield index, Move(FEED, x, z, move.f if k == 0 else None)
        else:
            yield index, move
        if move.kind != DWELL:  # a dwell holds the position (one elsewhere is the simulation's finding)
            position = (position[0] if move.x is None else float(move.x), float(move.z))


def straight(moves: Iterable[Move], start: Point, tol: float = SWEEP_TOL) -> list[Move]:
    """The moves with each arc as FEED chords (``straightened`` without the indexes)."""
    return [move for _index, move in straightened(moves, start, tol)]
