"""The turned section of a Job: stock and part in the lathe's half plane
(shapely (z, x), x the radius), and the part the grooving ops must leave.

No FreeCAD: the FreeCAD layer (freecad/turning_check.py) hands in the
model's section as closed rings of (z, x) points (a cut through the axis,
both halves: x may be negative) and the stock's bounds.
"""

from __future__ import annotations

from collections.abc import Sequence

from shapely import Geometry
from shapely.geometry import Polygon, box

from .overlay import EMPTY, area, difference, intersection, union_all

Point = tuple[float, float]

# A planned groove counts as modelled (the model already shows it: it is
# judged against the model) when less than this share of its area is solid
# in the model; otherwise the op cuts it into the modelled part.
MODELLED_SHARE = 0.5


def rings_section(rings: Sequence[Sequence[tuple[float, float]]]) -> Geometry:
    """The region enclosed by closed (z, x) rings, nested rings as holes
    (even-odd), clipped to the half plane x >= 0."""
    region = EMPTY
    for ring in rings:
        if len(ring) < 3:
            continue
        polygon = Polygon(ring).buffer(0)
        if area(polygon) > 0:
            region = region.symmetric_difference(polygon)
    if region.is_empty:
        return EMPTY
    zmin, _xmin, zmax, xmax = region.bounds
    return intersection(region, box(zmin - 1.0, 0.0, zmax + 1.0, max(xmax, 0.0) + 1.0))


def bar_section(radius: float, zmin: float, zmax: float) -> Geometry:
    """A bar of ``radius`` between zmin and zmax, in (z, x)."""
    return box(min(zmin, zmax), 0.0, max(zmin, zmax), radius)


def groove_region(points: Sequence[Point]) -> Geometry:
    """A planned finished groove, given as world (x, z) points, in (z, x)."""
    polygon = Polygon([(z, x) for x, z in points]).buffer(0)
    return polygon if area(polygon) > 0 else EMPTY


def is_modelled(groove: Geometry, model: Geometry) -> bool:
    """Does the model already show ``groove`` (less than MODELLED_SHARE of
    it is solid in the model)?"""
    whole = area(groove)
    return whole > 0 and area(intersection(groove, model)) < MODELLED_SHARE * whole


def part_to_leave(model: Geometry, grooves: Sequence[Geometry]) -> Geometry:
    """What the ops must leave standing: the model's section less the
    planned grooves it does not show (those the ops cut into the part as
    programmed); a groove the model shows is judged against the model."""
    cut_in = [g for g in grooves if not g.is_empty and not is_modelled(g, model)]
    if not cut_in:
        return model
    return difference(model, union_all(cut_in))
