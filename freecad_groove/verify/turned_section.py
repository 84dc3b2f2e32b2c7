"""The turned section of a Job as Shapes (no shapely): stock and part in the
lathe's half plane ((z, x), x the radius) and the part the grooving ops must
leave; section.py has the same in shapely (the tests' second oracle).

The FreeCAD layer (ops/turning_check/check.py) hands in the model's section
as closed rings of (z, x) points (a cut through the axis, both halves: x may
be negative) and the stock's bounds.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from .shapes import EMPTY_SHAPE, Shape, box, rings, union_all

Point = tuple[float, float]

# A planned groove counts as modelled (the model already shows it: it is
# judged against the model) when less than this share of its area is solid
# in the model; otherwise the op cuts it into the modelled part.
MODELLED_SHARE = 0.5


def rings_section(ring_list: Sequence[Sequence[tuple[float, float]]]) -> Shape:
    """The region enclosed by closed (z, x) rings, nested rings as holes
    (even-odd), in the half plane x >= 0."""
    region = rings(ring_list)
    if not region.rings:
        return EMPTY_SHAPE
    zmin, _xmin, zmax, xmax = region.bounds
    return region & box(zmin - 1.0, 0.0, zmax + 1.0, max(xmax, 0.0) + 1.0)


def bar_section(radius: float, zmin: float, zmax: float) -> Shape:
    """A bar of ``radius`` between zmin and zmax."""
    return box(zmin, 0.0, zmax, radius)


def groove_region(points: Sequence[Point]) -> Shape:
    """A planned finished groove, given as world (x, z) points."""
    return rings([[(z, x) for x, z in points]]) if len(points) >= 3 else EMPTY_SHAPE


def is_modelled(groove: Shape, model: Shape) -> bool:
    """Does the model already show ``groove`` (less than MODELLED_SHARE of it is solid in the model)?"""
    whole = groove.area
    return whole > 0 and (groove & model).area < MODELLED_SHARE * whole


def part_to_leave(model: Shape, grooves: Sequence[Shape]) -> Shape:
    """What the ops must leave standing: the model's section less the
    planned grooves it does not show (those the ops cut into the part as
    programmed); a groove the model shows is judged against the model."""
    cut_in = [g for g in grooves if not g.is_empty and not is_modelled(g, model)]
    return model - union_all(cut_in) if cut_in else model


def vertices_z(shapes: Sequence[Shape]) -> np.ndarray:
    parts = [s.vertices()[:, 0] for s in shapes]
    return np.concatenate(parts) if parts else np.empty(0)
