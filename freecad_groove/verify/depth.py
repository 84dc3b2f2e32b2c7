"""How far one region reaches from another: the distances the verdict reports
(the depth of a gouge, the thickness of material left standing, how far the
unreachable part of a target lies from the blade's reach).

Each starts from a cheap lower bound (vertex distances) and bisects with
buffers down to DEPTH_PRECISION.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import shapely
from shapely import Geometry
from shapely.geometry import box

from .overlay import EMPTY, NOISE_AREA, QUAD_SEGS, area, diagonal, difference, flat_parts, intersection, vertices

# Precision (mm) of the reported gouge and incomplete depths.
DEPTH_PRECISION = 1e-5


def _bisect(lo: float, hi: float, outside: Callable[[float], bool]) -> float:
    """Smallest d in [lo, hi] with outside(d) False (outside is monotone)."""
    while hi - lo > DEPTH_PRECISION:
        mid = 0.5 * (lo + hi)
        if outside(mid):
            lo = mid
        else:
            hi = mid
    return hi


def _densified_vertices(geom: Geometry, step: float) -> np.ndarray:
    """Vertices of geom with extra ones on every edge, at most step apart.

    The rings are densified, not the polygons: GEOS repairs a densified
    polygon with buffer(0), which can turn a valid but thin sliver into
    nothing at all."""
    parts = flat_parts(geom)
    polygons = shapely.get_type_id(parts) == 3
    lines = np.concatenate([shapely.get_rings(parts[polygons]), parts[~polygons]])
    return shapely.get_coordinates(shapely.segmentize(lines, step))


def farthest_from(excess: Geometry, target: Geometry) -> float:
    """Largest distance of a point of ``excess`` from ``target`` (inf when
    target is empty)."""
    if target.is_empty:
        return math.inf
    pts = shapely.points(_densified_vertices(excess, max(0.01, excess.length / 20000.0)))
    lo = float(np.max(shapely.distance(target, pts)))

    def outside(d: float) -> bool:
        rest = difference(excess, target.buffer(d, quad_segs=QUAD_SEGS))
        return area(rest) > NOISE_AREA

    # Buffers are inscribed polygons: allow for their chord error.
    if not outside(lo * (1 + 1e-4) + DEPTH_PRECISION):
        return lo
    return _bisect(lo, lo + diagonal(excess) + DEPTH_PRECISION, outside)


def depth_inside(region: Geometry, remaining: Geometry, tol: float) -> tuple[float, Geometry]:
    """How deep inside ``remaining`` does ``region`` (a part of it) reach: the
    largest distance from a point of region to the nearest point not in
    remaining. Returns (depth, core), core being the part of region deeper
    than tol (empty, and depth <= tol, when there is none)."""
    pts = shapely.points(vertices(region))
    lo = float(np.max(shapely.distance(remaining.boundary, pts))) if len(pts) else 0.0
    hi = lo + diagonal(region) + DEPTH_PRECISION
    zmin, xmin, zmax, xmax = region.bounds
    margin = hi + 1.0
    # Only the stock near the region matters; the clip edge is farther from
    # the region than any depth tested.
    local = intersection(remaining, box(zmin - margin, xmin - margin, zmax + margin, xmax + margin))

    def core_at(d: float) -> Geometry:
        return intersection(region, local.buffer(-d, quad_segs=QUAD_SEGS))

    def outside(d: float) -> bool:
        return area(core_at(d)) > NOISE_AREA

    core = core_at(tol)
    if area(core) <= NOISE_AREA:
        return min(lo, tol), EMPTY
    return _bisect(max(lo, tol), hi, outside), core
