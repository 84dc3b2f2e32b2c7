"""Shapely building blocks the other verify modules share: overlay operations
that survive GEOS's rare robustness failures, and small geometry measures.

Geometry is (z, x), x the radius (see the package docstring).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable

import numpy as np
import shapely
import shapely.errors
from shapely import Geometry
from shapely.geometry import Polygon

# Areas below this (mm^2) are numerical noise of the overlay operations.
NOISE_AREA = 1e-10
# Segments per quarter circle for the buffers used by the checks.
QUAD_SEGS = 64

EMPTY = Polygon()

# GEOS's floating overlay can, rarely, fail on nearly coincident edges
# ("Unable to determine overlay result geometry dimension"); the retry snaps
# to this grid (mm), far below any tolerance the checks use.
SNAP_GRID = 1e-9


def _overlay(op: Callable[..., Geometry], a: Geometry, b: Geometry) -> Geometry:
    try:
        return op(a, b)
    except shapely.errors.GEOSException:
        return op(a, b, grid_size=SNAP_GRID)


def difference(a: Geometry, b: Geometry) -> Geometry:
    return _overlay(shapely.difference, a, b)


def intersection(a: Geometry, b: Geometry) -> Geometry:
    return _overlay(shapely.intersection, a, b)


def union(a: Geometry, b: Geometry) -> Geometry:
    return _overlay(shapely.union, a, b)


def union_all(geoms: Iterable[Geometry] | np.ndarray) -> Geometry:
    try:
        return shapely.union_all(geoms)
    except shapely.errors.GEOSException:
        return shapely.union_all(geoms, grid_size=SNAP_GRID)


def area(geom: Geometry) -> float:
    return 0.0 if geom.is_empty else geom.area


def vertices(geom: Geometry) -> np.ndarray:
    if geom.is_empty:
        return np.empty((0, 2))
    return shapely.get_coordinates(geom)


def diagonal(geom: Geometry) -> float:
    zmin, xmin, zmax, xmax = geom.bounds
    return math.hypot(zmax - zmin, xmax - xmin)


def flat_parts(geom: Geometry) -> np.ndarray:
    """The points, lines and polygons in geom, however nested."""
    parts = shapely.get_parts(geom)
    while True:
        nested = shapely.get_type_id(parts) >= 4  # Multi* and collections
        if not nested.any():
            return parts
        parts = np.concatenate([parts[~nested], shapely.get_parts(parts[nested])])
