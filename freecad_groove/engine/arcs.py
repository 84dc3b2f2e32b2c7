"""Arcs as points along them: the chords an arc move is drawn or swept as.

Seen with Z to the right and X (the radius) up, G2 turns clockwise (the plane
G18 seen from +Y): the angle atan2(x - cx, z - cz) falls. An arc whose end
is not exactly at its start's
distance from the centre (rounding) runs as the controls run it: the distance
changes evenly with the angle, so the points end exactly at its end. An arc
whose end is its start moves nothing, as the writers write nothing for it
(never a full circle). Pure Python: the GUI's preview draws with it.
"""

import math
from typing import List, Tuple

Point = Tuple[float, float]  # (x, z), x the radius


def radius_centre(start: Point, end: Point, radius: float, clockwise: bool) -> Point:
    """The centre (x, z) of the arc of ``radius`` (at most half a turn) from start to end."""
    (x0, z0), (x1, z1) = start, end
    half = math.hypot(x1 - x0, z1 - z0) / 2.0
    height = math.sqrt(max(radius * radius - half * half, 0.0))
    mz, mx = (z0 + z1) / 2.0, (x0 + x1) / 2.0
    dz, dx = (z1 - z0) / (2 * half), (x1 - x0) / (2 * half)
    side = -1.0 if clockwise else 1.0  # (z, x) plane: a clockwise minor arc has its centre to the right
    return (mx + side * height * dz, mz - side * height * dx)


def arc_chords(start: Point, end: Point, centre: Point, clockwise: bool, tol: float) -> List[Point]:
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
