"""The blade's outline in the lathe's half plane as numpy points (z, x), and
the convex shapes the column model sweeps: the outline moved along a straight
segment as half-planes, a convex hull, a convex polygon clipped to a box.
numpy only (FreeCAD ships it): the column model and the command line's record
use it without shapely.

Tool positions are (x, z) like ``moves.Move``; outlines are (z, x).
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from freecad_groove.engine.moves import MINUS_X, MINUS_Z, PLUS_X, PLUS_Z, GroovingTool

# Largest amount (mm) by which the polygonal corner arcs may exceed the true arc.
ARC_EXCESS = 2e-5


def _arc_segments(radius: float) -> int:
    """Segments per quarter arc so that the circumscribed polygon exceeds the
    true arc by at most ARC_EXCESS (and never fewer than 32)."""
    if radius <= 0:
        return 0
    # excess of a circumscribed polygon = r * (1 / cos(step / 2) - 1) ~ r * step^2 / 8
    step = math.sqrt(8.0 * ARC_EXCESS / radius)
    return int(min(512, max(32, math.ceil((math.pi / 2) / step))))


def _corner(cu: float, cv: float, radius: float, start_angle: float, n: int) -> list[tuple[float, float]]:
    """Circumscribed polygonal quarter arc around centre (cu, cv), counter-
    clockwise from start_angle: both tangent points (exactly on the arc) plus
    the intersections of n+1 evenly spaced tangent lines."""
    step = (math.pi / 2) / n
    far = radius / math.cos(step / 2)
    pts = [(cu + radius * math.cos(start_angle), cv + radius * math.sin(start_angle))]
    for k in range(n):
        a = start_angle + (k + 0.5) * step
        pts.append((cu + far * math.cos(a), cv + far * math.sin(a)))
    end = start_angle + math.pi / 2
    pts.append((cu + radius * math.cos(end), cv + radius * math.sin(end)))
    return pts


@lru_cache(maxsize=256)
def _local_outline(width: float, radius: float, length: float) -> np.ndarray:
    """Blade outline in its own frame: u across the front edge (0..width),
    v from the front edge (v=0) back along the blade (v=length)."""
    pts = [(0.0, length)]
    if radius > 1e-7:  # (below that: sharp, for the geometry's sake)
        n = _arc_segments(radius)
        pts += _corner(radius, radius, radius, math.pi, n)  # front corner at u=0
        pts += _corner(width - radius, radius, radius, 1.5 * math.pi, n)  # front corner at u=width
    else:
        pts += [(0.0, 0.0), (width, 0.0)]
    pts.append((width, length))
    return np.array(pts, dtype=float)


@lru_cache(maxsize=256)
def outline_at_origin(tool: GroovingTool, plunge: str) -> np.ndarray:
    """(z, x) outline vertices of the tool with its reference corner at (0, 0)
    (read-only: the array is cached)."""
    local = _local_outline(float(tool.width), float(tool.corner_radius), float(tool.length))
    u = local[:, 0] - tool.reference_offset
    v = local[:, 1]
    if plunge == MINUS_X:  # front faces -X, body toward +X
        z, x = u, v
    elif plunge == PLUS_X:  # front faces +X, body toward -X
        z, x = u, -v
    elif plunge == MINUS_Z:  # front faces -Z, body toward +Z
        z, x = v, u
    elif plunge == PLUS_Z:  # front faces +Z, body toward -Z
        z, x = -v, u
    else:
        raise ValueError("unknown plunge direction %r" % (plunge,))
    coords = np.column_stack([z, x])
    coords.setflags(write=False)
    return coords



def _ccw(points: np.ndarray) -> np.ndarray:
    """``points`` of a convex polygon, counter-clockwise."""
    z, x = points[:, 0], points[:, 1]
    signed = float(np.sum(z * np.roll(x, -1) - np.roll(z, -1) * x))
    return points if signed > 0 else points[::-1]


@lru_cache(maxsize=256)
def outline_planes(tool: GroovingTool, plunge: str) -> tuple[np.ndarray, np.ndarray]:
    """The blade's outline at the origin as half-planes: (unit outward normals
    (m, 2) in (z, x), their support values (m,)); a point p is inside when
    normals @ p <= support for every plane (read-only, cached)."""
    points = _ccw(np.asarray(outline_at_origin(tool, plunge)))
    edges = np.roll(points, -1, axis=0) - points
    lengths = np.hypot(edges[:, 0], edges[:, 1])
    keep = lengths > 1e-12
    normals = np.column_stack([edges[keep, 1], -edges[keep, 0]]) / lengths[keep, None]
    support = np.max(normals @ points.T, axis=1)
    normals.setflags(write=False)
    support.setflags(write=False)
    return normals, support


def swept_planes(tool: GroovingTool, plunge: str, start: tuple[float, float],
                 end: tuple[float, float]) -> tuple[np.ndarray, np.ndarray]:
    """The area the blade sweeps moving straight from start (x, z) to end (x, z)
    as half-planes (normals (m, 2) (z, x), support (m,)): the Minkowski sum of
    the outline and the segment, exact (the support of a sum is the sum of
    the supports), the segment's own two sides added."""
    normals, support = outline_planes(tool, plunge)
    a = np.array([start[1], start[0]], dtype=float)
    d = np.array([end[1] - start[1], end[0] - start[0]], dtype=float)
    shift = normals @ d
    planes, values = [normals], [support + np.maximum(shift, 0.0) + normals @ a]
    length = math.hypot(d[0], d[1])
    if length > 1e-12:
        side = np.array([[d[1], -d[0]], [-d[1], d[0]]]) / length
        points = np.asarray(outline_at_origin(tool, plunge))
        planes.append(side)
        values.append(np.max(side @ points.T, axis=1) + side @ a)
    return np.concatenate(planes), np.concatenate(values)


def convex_hull(points: np.ndarray) -> np.ndarray:
    """The convex hull of (z, x) points, counter-clockwise (Andrew's monotone chain)."""
    pts = sorted(set(map(tuple, np.asarray(points, dtype=float).tolist())))
    if len(pts) < 3:
        return np.array(pts, dtype=float)

    def half(seq):
        chain = []
        for p in seq:
            while len(chain) >= 2 and ((chain[-1][0] - chain[-2][0]) * (p[1] - chain[-2][1])
                                       - (chain[-1][1] - chain[-2][1]) * (p[0] - chain[-2][0])) <= 0:
                chain.pop()
            chain.append(p)
        return chain

    lower, upper = half(pts), half(reversed(pts))
    return np.array(lower[:-1] + upper[:-1], dtype=float)


def clip_to_box(polygon: np.ndarray, zmin: float, xmin: float, zmax: float, xmax: float) -> np.ndarray:
    """A convex (z, x) polygon clipped to a box (Sutherland-Hodgman)."""
    pts = [tuple(p) for p in np.asarray(polygon, dtype=float)]
    for axis, bound, keep_low in ((0, zmin, False), (0, zmax, True), (1, xmin, False), (1, xmax, True)):
        out = []
        for k, p in enumerate(pts):
            q = pts[k - 1]
            p_in = p[axis] <= bound if keep_low else p[axis] >= bound
            q_in = q[axis] <= bound if keep_low else q[axis] >= bound
            if p_in != q_in:
                t = (bound - q[axis]) / (p[axis] - q[axis])
                cut = [q[0] + t * (p[0] - q[0]), q[1] + t * (p[1] - q[1])]
                cut[axis] = bound
                out.append(tuple(cut))
            if p_in:
                out.append(p)
        pts = out
        if not pts:
            break
    return np.array(pts, dtype=float)


def swept_hull(tool: GroovingTool, plunge: str, start: tuple[float, float], end: tuple[float, float]) -> np.ndarray:
    """The (z, x) polygon the blade sweeps moving straight from start (x, z) to end (x, z)."""
    base = outline_at_origin(tool, plunge)
    a = base + (float(start[1]), float(start[0]))
    b = base + (float(end[1]), float(end[0]))
    return convex_hull(np.vstack([a, b]))


def lower_chain(points: np.ndarray) -> np.ndarray:
    """The lower side of the convex hull of (u, v) points, from the smallest u
    to the largest (the lowest v at each u: np.interp along it)."""
    pts = sorted(set(map(tuple, np.asarray(points, dtype=float).tolist())))
    chain: list = []
    for p in pts:
        while len(chain) >= 2 and ((chain[-1][0] - chain[-2][0]) * (p[1] - chain[-2][1])
                                   - (chain[-1][1] - chain[-2][1]) * (p[0] - chain[-2][0])) <= 0:
            chain.pop()
        chain.append(p)
    while len(chain) >= 2 and chain[-1][0] == chain[-2][0]:  # a vertical side at the largest u
        chain.pop()
    return np.array(chain, dtype=float)
