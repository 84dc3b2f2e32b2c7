"""Where the blade can cut a target the way a grooving cycle does, and what of
the target it cannot reach: a morphological opening of the free space (the
target and the air) by the blade, built from exact Minkowski sums and
differences with segments.

Geometry is shapely (z, x), x the radius.
"""

from __future__ import annotations

import numpy as np
import shapely
import shapely.errors
from shapely import Geometry
from shapely.geometry import Polygon, box

from freecad_groove.engine.moves import MINUS_X, MINUS_Z, PLUS_X, PLUS_Z, GroovingTool

from .overlay import (
    EMPTY,
    NOISE_AREA,
    QUAD_SEGS,
    diagonal,
    difference,
    flat_parts,
    intersection,
    union,
    union_all,
)

# The reach computation narrows the blade by this much (mm), so that a groove
# exactly as wide as the blade (up to float rounding) still fits it.
FIT_SLACK = 1e-8

# Grid (mm) to which _sum_segment snaps its input and its union when the plain
# floating union fails or is implausible: far below every tolerance the checks
# use and far below FIT_SLACK, yet some hundred float ulps of the coordinates.
SUM_GRID = 1e-11


# Parts of a swept geometry thinner than this (mm, on average) are overlay
# debris (a polygon collapsed to a line, its sides a few ulps apart): swept, one
# would add a whole band of reach. Far below FIT_SLACK.
SLIVER_WIDTH = 1e-10

Vector = tuple[float, float] | np.ndarray  # (z, x)


# --------------------------------------------------------------------------- Minkowski sums with a segment


def _polygonal(geom: Geometry) -> Geometry:
    """geom as a valid (Multi)Polygon without slivers: invalid input is
    repaired, and lines, points and parts thinner than SLIVER_WIDTH (the
    debris of an overlay, zero-area spikes) are dropped."""
    if geom.is_empty:
        return EMPTY
    if not geom.is_valid:
        geom = shapely.make_valid(geom)
    parts = flat_parts(geom)
    polygons = parts[shapely.get_type_id(parts) == 3]
    keep = shapely.area(polygons) > 0.25 * SLIVER_WIDTH * shapely.length(polygons)
    if keep.all() and len(polygons) == len(parts) and geom.geom_type in ("Polygon", "MultiPolygon"):
        return geom
    polygons = polygons[keep]
    if len(polygons) == 0:
        return EMPTY
    if len(polygons) == 1:
        return polygons[0]
    return union_all(polygons)


def _sweep_quads(geom: Geometry, v: np.ndarray) -> np.ndarray:
    """The parallelograms swept by the edges of geom's rings that face v
    (outward normal . v > 0). geom's rings must be oriented (exteriors
    counter-clockwise, holes clockwise)."""
    quads = []
    for ring in shapely.get_rings(shapely.get_parts(geom)):
        c = shapely.get_coordinates(ring)
        a, b = c[:-1], c[1:]
        d = b - a
        # outward normal of an edge d of a counter-clockwise exterior (or a
        # clockwise hole) is (d_x, -d_z) in (z, x)
        facing = d[:, 1] * v[0] - d[:, 0] * v[1] > 0.0
        if facing.any():
            a, b = a[facing], b[facing]
            quads.append(np.stack([a, b, b + v, a + v, a], axis=1))
    if not quads:
        return np.empty(0, dtype=object)
    quads = shapely.polygons(np.concatenate(quads))
    bad = ~shapely.is_valid(quads)
    if bad.any():  # a sliver the translation's rounding turned into a bow tie
        quads[bad] = [_polygonal(q) for q in quads[bad]]
    return quads


def _plausible_union(result: Geometry, pieces: np.ndarray) -> bool:
    """Cheap sanity check of a union: valid, polygonal, and no smaller than
    its largest piece nor larger than all pieces together. (GEOS has been
    seen to return a wrong union of nearly degenerate input without any
    error.)"""
    if not result.is_valid or result.geom_type not in ("Polygon", "MultiPolygon"):
        return False
    areas = shapely.area(pieces)
    slack = 1e-9 * float(np.sum(areas)) + NOISE_AREA
    return float(np.max(areas)) - slack <= result.area <= float(np.sum(areas)) + slack


def _snapped(geom: Geometry) -> Geometry:
    """geom on the SUM_GRID, valid, without the features thinner than that
    grid (a spike whose two sides lie 1e-15 apart: GEOS keeps it as valid)."""
    try:
        return _polygonal(shapely.set_precision(geom, SUM_GRID))
    except shapely.errors.GEOSException:
        return geom


def _sum_segment(geom: Geometry, v: Vector) -> Geometry:
    """Minkowski sum of a polygonal geometry with the segment from 0 to v.

    A point q is in the sum when the path from q - v to q meets geom; if q is
    not in geom that path leaves geom through an edge facing v, so the sum
    is geom united with the parallelograms swept by the edges that face v.
    (The translated copy of geom is not needed, it is covered too; and it
    need not even be valid: the rounding of the translation can make a
    zero-width spike cross itself, on which GEOS failed with "unable to
    assign free hole to a shell" or, worse, returned a wrong union.)

    The plain floating union is tried first: it keeps the coordinates of
    edges along v exact, so that the reach of a blade that fits a groove
    exactly does not fall short of the groove's walls by a rounding error.
    When GEOS fails on it or returns something implausible, geom is snapped
    to SUM_GRID (which also drops zero-width spikes) and the union done with
    snap rounding on that grid; as a last resort in small batches.
    """
    if geom.is_empty or (v[0] == 0 and v[1] == 0):
        return geom
    v = np.asarray(v, dtype=float)
    geom = _polygonal(geom)
    if geom.is_empty:
        return geom
    geom = shapely.orient_polygons(geom)
    pieces = np.concatenate([[geom], _sweep_quads(geom, v)])
    try:
        result = shapely.union_all(pieces)
        if _plausible_union(result, pieces):
            return result
    except shapely.errors.GEOSException:
        pass
    geom = shapely.orient_polygons(_snapped(geom))
    pieces = np.concatenate([[geom], _sweep_quads(geom, v)])
    try:
        result = shapely.union_all(pieces, grid_size=SUM_GRID)
        if _plausible_union(result, pieces):
            return result
    except shapely.errors.GEOSException:
        pass
    result = pieces[0]
    for k in range(1, len(pieces), 16):
        batch = shapely.union_all(pieces[k : k + 16], grid_size=SUM_GRID)
        result = shapely.union(result, batch, grid_size=SUM_GRID)
    if not _plausible_union(result, pieces):
        raise shapely.errors.GEOSException(
            "Minkowski sum with a segment failed: %s by %r" % (geom.wkt[:200], v.tolist())
        )
    return result


def _erode_segment(geom: Geometry, v: Vector, frame: Polygon) -> Geometry:
    """Minkowski difference: points p with p + [0, v] inside geom (frame: a box
    around geom, larger by more than |v|)."""
    outside = difference(frame, geom)
    return difference(frame, _sum_segment(outside, (-v[0], -v[1])))


# --------------------------------------------------------------------------- free space and reach

# Gaps (mm) narrower than twice this between the target and the air are closed
# (see _free_space).
JOIN_GAP = 1e-9


def _free_space(target: Geometry, air: Geometry) -> Geometry:
    """target united with the air, with the cracks between them closed.

    The target's edges that run along the stock's surface lie on it only up
    to float rounding: the plain union can leave a zero-width wall of stock
    between the target and the air, which eroding by the corner radius turns
    into a wall 2r thick across the groove's mouth (and the whole groove
    unreachable). A closing by JOIN_GAP removes walls thinner than 2 JOIN_GAP;
    it is added to the plain union, not put in its place, so that the edges
    keep their exact coordinates (the closing recomputes them, off by
    rounding, and a reach that falls short of the target's wall by 1e-15
    leaves a sliver of "unreachable" target that the check would then excuse
    a tol-wide band around)."""
    free = union(target, air)
    closed = free.buffer(JOIN_GAP, join_style="mitre").buffer(-JOIN_GAP, join_style="mitre")
    return union(free, closed)


def _air(stock: Geometry, target: Geometry, margin: float) -> tuple[Polygon, Geometry]:
    zmin, xmin, zmax, xmax = union(stock, target).bounds
    frame = box(zmin - margin, xmin - margin, zmax + margin, xmax + margin)
    return frame, difference(frame, stock)


# Direction the blade body extends from its front edge (= the retract direction), (z, x).
_BACK = {MINUS_X: (0.0, 1.0), PLUS_X: (0.0, -1.0), MINUS_Z: (1.0, 0.0), PLUS_Z: (-1.0, 0.0)}


def _disk_reach(target: Geometry, stock: Geometry, r: float) -> Geometry:
    """The "disk" model of reachable_region."""
    frame, air = _air(stock, target, 2 * r + 1.0)
    free = _free_space(target, air)
    if r == 0.0:
        return free
    return free.buffer(-r, quad_segs=QUAD_SEGS).buffer(r, quad_segs=QUAD_SEGS)


def _blade_reach(target: Geometry, stock: Geometry, tool: GroovingTool, plunge: str, r: float) -> Geometry:
    """The "blade" model of reachable_region (r: the corner radius, 0.0 when
    not above FIT_SLACK)."""
    width, length = float(tool.width), float(tool.length)
    across = max(width - 2 * r - FIT_SLACK, 0.0)
    along = max(length - 2 * r - FIT_SLACK, 0.0)
    back = _BACK[plunge]
    if plunge in (MINUS_X, PLUS_X):
        va, vb = (across, 0.0), (0.0, along)  # (z, x): across Z, along X
    else:
        va, vb = (0.0, across), (along, 0.0)
    reach = length + width + diagonal(target) + 1.0
    frame, air = _air(stock, target, reach + 1.0)
    column = _sum_segment(target, (back[0] * reach, back[1] * reach))
    free = intersection(column, _free_space(target, air))
    zmin, xmin, zmax, xmax = frame.bounds
    big = box(zmin - reach, xmin - reach, zmax + reach, xmax + reach)
    core = free.buffer(-r, quad_segs=QUAD_SEGS) if r > 0 else free
    core = _erode_segment(_erode_segment(core, va, big), vb, big)
    opened = _sum_segment(_sum_segment(core, vb), va)
    return opened.buffer(r, quad_segs=QUAD_SEGS) if r > 0 else opened


def reachable_region(
    target: Geometry,
    stock: Geometry,
    tool: GroovingTool,
    plunge: str,
    tol: float = 0.001,
    model: str = "blade",
) -> Geometry:
    """Where the tool can cut the target the way a grooving cycle does: the
    union of all placements of the tool that stay inside the target and the
    air straight behind it (the target swept in the retract direction, minus
    other stock). This is a morphological opening.

    model "blade" (default): the blade as a ``width`` x ``length`` rectangle
    with all four corners rounded by ``corner_radius``, translated only (the
    tool never turns), narrowed by FIT_SLACK so that a groove exactly as wide
    as the blade counts as reachable despite rounding. (Not by more: a blade
    narrowed by d reaches sqrt(2 R d) deeper past a wall that ends in a
    radius R.) What it leaves in a
    rectangular groove is the two floor fillets, also when the groove is
    shallower than the corner radius.
    model "disk": the opening of (target + all air around the stock) by a
    disk of ``corner_radius``; it reaches more than a blade (a disk pivots
    around the groove's mouth and fits where the blade does not).
    """
    r = float(tool.corner_radius)
    if r <= FIT_SLACK:
        r = 0.0
    if model == "disk":
        return _disk_reach(target, stock, r)
    if model != "blade":
        raise ValueError("unknown reach model %r" % (model,))
    if plunge not in _BACK:
        raise ValueError("unknown plunge direction %r" % (plunge,))
    return _blade_reach(target, stock, tool, plunge, r)


def unreachable_region(
    target: Geometry,
    stock: Geometry,
    tool: GroovingTool,
    plunge: str = MINUS_X,
    tol: float = 0.001,
    model: str = "blade",
) -> Geometry:
    """Part of ``target`` the tool cannot reach without cutting stock outside
    the target (see reachable_region): the corner fillets, and whatever is
    narrower than the blade."""
    if target.is_empty:
        return EMPTY
    return difference(target, reachable_region(target, stock, tool, plunge, tol, model))
