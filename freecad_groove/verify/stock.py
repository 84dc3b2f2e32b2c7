"""Stock and target shapes in the lathe's half plane: shapely (z, x), x the
radius, built from radius and Z limits."""

from __future__ import annotations

from shapely.geometry import Polygon, box


def region(xmin: float, xmax: float, zmin: float, zmax: float) -> Polygon:
    """Axis-aligned (z, x) rectangle from radius and Z limits."""
    return box(min(zmin, zmax), min(xmin, xmax), max(zmin, zmax), max(xmin, xmax))


def bar(radius: float, zmin: float, zmax: float, bore: float = 0.0) -> Polygon:
    """Stock of a bar (or tube with a bore radius) between zmin and zmax."""
    return region(bore, radius, zmin, zmax)
