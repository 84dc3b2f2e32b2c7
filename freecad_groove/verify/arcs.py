"""Arc moves (moves.ARC_CW / ARC_CCW) as the straight pieces the simulation
and the figures sweep.

Seen with Z to the right and X (the radius) up, G2 turns clockwise (the plane
G18 seen from +Y): the angle atan2(x - cx, z - cz) falls. An arc whose end is
not exactly at its start's distance from the centre (rounding) runs as the
controls run it: the distance changes evenly with the angle, so the pieces
end exactly at its end. An arc whose end is its start moves nothing, as the
writers write nothing for it (never a full circle).

The chords' ends lie on the arc: each chord is at most ``tol`` inside it. The
simulation's ``SWEEP_TOL`` (1e-5 mm) is a hundredth of the 0.001 mm the
gouge and leftover checks report from, half the blade outline's own excess
(blade.ARC_EXCESS): a chord can neither hide a gouge nor make one that the
check would report.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator

from freecad_groove.engine.moves import ARC_CW, ARCS, DWELL, FEED, Move

Point = tuple[float, float]  # (x, z), x the radius

SWEEP_TOL = 1e-5  # mm: the chords the simulation sweeps for an arc stay this close to it
TIME_TOL = 1e-3  # mm: the chords an arc's machining time is taken along (its length to a millionth)
# An arc whose end is farther than this from its circle (more than the 0.001 mm
# the checks report) is not one the engine or a control writes: refused.
ARC_END_TOL = 1e-3


def radius_centre(start: Point, end: Point, radius: float, clockwise: bool) -> Point:
    """The centre (x, z) of the arc of ``radius`` (at most half a turn) from start to end."""
    (x0, z0), (x1, z1) = start, end
    half = math.hypot(x1 - x0, z1 - z0) / 2.0
    height = math.sqrt(max(radius * radius - half * half, 0.0))
    mz, mx = (z0 + z1) / 2.0, (x0 + x1) / 2.0
    dz, dx = (z1 - z0) / (2 * half), (x1 - x0) / (2 * half)
    side = -1.0 if clockwise else 1.0  # (z, x) plane: a clockwise minor arc has its centre to the right
    return (mx + side * height * dz, mz - side * height * dx)


def arc_chords(start: Point, end: Point, centre: Point, clockwise: bool, tol: float) -> list[Point]:
    """Points (x, z) along the arc from start to end (end included), each
    chord within ``tol`` of it; none for an arc whose end is its start."""
    if start == end:
        return []
    cx, cz = centre
    radius = math.hypot(start[0] - cx, start[1] - cz)
    end_radius = math.hypot(end[0] - cx, end[1] - cz)
    a0 = math.atan2(start[0] - cx, start[1] - cz)  # angle in the (z, x) plane
    a1 = math.atan2(end[0] - cx, end[1] - cz)
    sweep = a1 - a0
    if clockwise:
        sweep = sweep - 2 * math.pi if sweep > 0 else sweep
    else:
        sweep = sweep + 2 * math.pi if sweep < 0 else sweep
    largest = max(radius, end_radius)
    if largest <= tol:
        return [end]
    step = 2.0 * math.acos(max(1.0 - tol / largest, -1.0))
    count = max(1, math.ceil(abs(sweep) / step))
    points = []
    for k in range(1, count):
        t = k / count
        r, a = radius + (end_radius - radius) * t, a0 + sweep * t
        points.append((cx + r * math.sin(a), cz + r * math.cos(a)))
    return points + [end]


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
