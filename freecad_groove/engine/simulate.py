"""Material-removal simulation: the test oracle for expanded grooving moves.

VERIFICATION ONLY. This module needs shapely (>= 2.0), which FreeCAD does not
bundle: no other engine module may import it. Tests import it directly.

Geometry lives in the lathe's half plane. A shapely point is ``(z, x)`` with
``x`` the *radius*, so a plot reads like a lathe drawing: Z horizontal, X up.
Functions that take a tool position take ``(x, z)`` like ``moves.Move`` does;
only the shapely geometry is ``(z, x)``.

What the oracle checks (see ``check_groove``):

* gouge: material removed that had to stay (stock minus target) deeper than
  ``tol`` below its surface (the target or the air); reported as the deepest
  such point (mm).
* incomplete: target material still standing farther than ``tol`` from every
  cut surface and the air, not counting what the blade cannot reach
  (``unreachable_region``, grown by ``tol``): the corner-radius fillets.
* infeasible: the target holds material farther than corner radius + ``tol``
  from every place the blade can reach (narrower than the blade, undercut,
  acute corner): no program can make it, the verdict is not ok.
* rapid collision: a RAPID whose swept tool area (less a RAPID_SKIN of
  3e-5 mm) overlaps the stock still standing at that moment by more than
  ``RAPID_AREA_TOL`` mm^2.
"""

import math
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Optional

import numpy as np
import shapely
import shapely.errors
from shapely.geometry import Polygon, box
from shapely.geometry.polygon import orient

from .moves import DWELL, FEED, MINUS_X, MINUS_Z, PLUS_X, PLUS_Z, RAPID, Move

# Largest amount (mm) by which the polygonal corner arcs may exceed the true arc.
ARC_EXCESS = 2e-5
# A rapid is a collision when its swept area, shrunk by RAPID_SKIN (mm: the
# arcs' excess plus rounding), overlaps standing stock by more than
# RAPID_AREA_TOL mm^2. A rapid may touch the stock, not enter it.
RAPID_SKIN = ARC_EXCESS + 1e-5
RAPID_AREA_TOL = 1e-9
# Areas below this (mm^2) are numerical noise of the overlay operations.
NOISE_AREA = 1e-10
# Segments per quarter circle for the buffers used by the checks.
QUAD_SEGS = 64
# The reach computation narrows the blade by this much (mm), so that a groove
# exactly as wide as the blade (up to float rounding) still fits it.
FIT_SLACK = 1e-8
# Precision (mm) of the reported gouge and incomplete depths.
DEPTH_PRECISION = 1e-5

_EMPTY = Polygon()


# --------------------------------------------------------------------------- robust overlay

# GEOS's floating overlay can, rarely, fail on nearly coincident edges
# ("Unable to determine overlay result geometry dimension"); the retry snaps
# to this grid (mm), far below any tolerance the checks use.
SNAP_GRID = 1e-9


def _overlay(op, a, b):
    try:
        return op(a, b)
    except shapely.errors.GEOSException:
        return op(a, b, grid_size=SNAP_GRID)


def _difference(a, b):
    return _overlay(shapely.difference, a, b)


def _intersection(a, b):
    return _overlay(shapely.intersection, a, b)


def _union(a, b):
    return _overlay(shapely.union, a, b)


def _union_all(geoms):
    try:
        return shapely.union_all(geoms)
    except shapely.errors.GEOSException:
        return shapely.union_all(geoms, grid_size=SNAP_GRID)



# --------------------------------------------------------------------------- tool


def _arc_segments(radius):
    """Segments per quarter arc so that the circumscribed polygon exceeds the
    true arc by at most ARC_EXCESS (and never fewer than 32)."""
    if radius <= 0:
        return 0
    # excess of a circumscribed polygon = r * (1 / cos(step / 2) - 1) ~ r * step^2 / 8
    step = math.sqrt(8.0 * ARC_EXCESS / radius)
    return int(min(512, max(32, math.ceil((math.pi / 2) / step))))


def _corner(cu, cv, radius, start_angle, n):
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
def _local_outline(width, radius, length):
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
def _outline_at_origin(tool, plunge):
    """(z, x) outline vertices of the tool with its reference corner at (0, 0)."""
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


def tool_outline(tool, plunge, x, z):
    """Polygon (z, x) of the blade with its reference corner at radius x, Z z.

    The front edge is flat, ``tool.width`` wide, both front corners rounded by
    ``tool.corner_radius`` (circumscribed polygon: never inside the true arc,
    at most ARC_EXCESS outside it), the sides run ``tool.length`` back.
    """
    coords = _outline_at_origin(tool, plunge) + (float(z), float(x))
    return orient(Polygon(coords))


def swept_area(tool, plunge, start, end):
    """Area swept by the tool moving straight from start (x, z) to end (x, z)."""
    base = _outline_at_origin(tool, plunge)
    a = base + (float(start[1]), float(start[0]))
    b = base + (float(end[1]), float(end[0]))
    return shapely.MultiPoint(np.vstack([a, b])).convex_hull


# --------------------------------------------------------------------------- simulation


@dataclass
class RapidCollision:
    index: int  # position of the move in the move list
    move: Move
    start: tuple  # (x, z) before the move
    area: float  # mm^2 of standing stock inside the swept area
    region: object = None  # the overlap (shapely, (z, x))

    def describe(self):
        zmin, xmin, zmax, xmax = self.region.bounds
        text = "rapid #%d %s X(radius)%.4f Z%.4f -> X%.4f Z%.4f hits stock: %.6g mm^2 in Z[%.4f, %.4f] X[%.4f, %.4f]"
        return text % (
            self.index,
            self.move.kind,
            self.start[0],
            self.start[1],
            self.move.x,
            self.move.z,
            self.area,
            zmin,
            zmax,
            xmin,
            xmax,
        )


@dataclass
class DwellMismatch:
    index: int
    move: Move
    position: tuple  # (x, z) the tool is actually at

    def describe(self):
        return "dwell #%d says X%.4f Z%.4f but the tool is at X%.4f Z%.4f" % (
            self.index,
            self.move.x,
            self.move.z,
            self.position[0],
            self.position[1],
        )


@dataclass
class SimulationResult:
    stock: object  # the original stock
    remaining: object  # stock still standing after the program
    removed: object  # stock minus remaining
    rapid_collisions: list
    dwell_mismatches: list
    final: tuple  # (x, z) tool position after the last move
    tool: object = None
    plunge: str = None


def _check_coords(i, move):
    if not (math.isfinite(move.x) and math.isfinite(move.z)):
        raise ValueError("move #%d %r has a non-finite coordinate" % (i, move))


def simulate(moves, tool, plunge, start, stock, rapid_area_tol=RAPID_AREA_TOL, rapid_skin=RAPID_SKIN):
    """Run ``moves`` (moves.Move, x radius) with ``tool`` plunging in ``plunge``
    from ``start`` = (x, z) through ``stock`` (shapely (z, x) Polygon/MultiPolygon).

    FEED moves remove the area the tool sweeps (the convex hull of the tool
    outline at both ends: exact for a straight move of a convex tool). A
    RAPID whose swept area, shrunk by ``rapid_skin`` mm, overlaps the stock
    still standing at that moment by more than ``rapid_area_tol`` mm^2 is
    recorded. DWELL removes nothing; a dwell whose x, z differ from the tool
    position by more than 1e-9 is recorded as a dwell mismatch.
    """
    moves = list(moves)
    base = _outline_at_origin(tool, plunge)
    nb = len(base)

    # Positions and the indices of moves that sweep (rapids and feeds).
    pos = (float(start[0]), float(start[1]))
    segments = []  # (index, start (x, z), end (x, z))
    dwell_mismatches = []
    for i, m in enumerate(moves):
        _check_coords(i, m)
        if m.kind in (RAPID, FEED):
            end = (float(m.x), float(m.z))
            segments.append((i, pos, end))
            pos = end
        elif m.kind == DWELL:
            if abs(m.x - pos[0]) > 1e-9 or abs(m.z - pos[1]) > 1e-9:
                dwell_mismatches.append(DwellMismatch(i, m, pos))
        else:
            raise ValueError("move #%d has unknown kind %r" % (i, m.kind))
    final = pos

    hulls = {}
    if segments:
        ends = np.empty((len(segments), 2 * nb, 2))
        for k, (_, a, b) in enumerate(segments):
            ends[k, :nb] = base + (a[1], a[0])
            ends[k, nb:] = base + (b[1], b[0])
        indices = np.repeat(np.arange(len(segments)), 2 * nb)
        points = shapely.multipoints(ends.reshape(-1, 2), indices=indices)
        for (i, _, _), hull in zip(segments, shapely.convex_hull(points)):
            hulls[i] = hull
    starts = {i: a for i, a, _ in segments}

    remaining = stock
    pending = []
    collisions = []

    def flush(remaining, pending):
        if pending:
            cut = _union_all(pending)
            remaining = _difference(remaining, cut)
        return remaining

    for i, m in enumerate(moves):
        if m.kind == FEED:
            pending.append(hulls[i])
        elif m.kind == RAPID:
            remaining = flush(remaining, pending)
            pending = []
            hull = hulls[i].buffer(-rapid_skin, join_style="mitre") if rapid_skin > 0 else hulls[i]
            if hull.intersects(remaining):
                hit = _intersection(hull, remaining)
                if hit.area > rapid_area_tol:
                    collisions.append(RapidCollision(i, m, starts[i], hit.area, hit))
    remaining = flush(remaining, pending)
    removed = _difference(stock, remaining)
    return SimulationResult(
        stock=stock,
        remaining=remaining,
        removed=removed,
        rapid_collisions=collisions,
        dwell_mismatches=dwell_mismatches,
        final=final,
        tool=tool,
        plunge=plunge,
    )


# --------------------------------------------------------------------------- verdict


def _vertices(geom):
    if geom.is_empty:
        return np.empty((0, 2))
    return shapely.get_coordinates(geom)


def _diagonal(geom):
    zmin, xmin, zmax, xmax = geom.bounds
    return math.hypot(zmax - zmin, xmax - xmin)


def _area(geom):
    return 0.0 if geom.is_empty else geom.area


def _bisect(lo, hi, outside):
    """Smallest d in [lo, hi] with outside(d) False (outside is monotone)."""
    while hi - lo > DEPTH_PRECISION:
        mid = 0.5 * (lo + hi)
        if outside(mid):
            lo = mid
        else:
            hi = mid
    return hi


def _flat_parts(geom):
    """The points, lines and polygons in geom, however nested."""
    parts = shapely.get_parts(geom)
    while True:
        nested = shapely.get_type_id(parts) >= 4  # Multi* and collections
        if not nested.any():
            return parts
        parts = np.concatenate([parts[~nested], shapely.get_parts(parts[nested])])


def _densified_vertices(geom, step):
    """Vertices of geom with extra ones on every edge, at most step apart.

    The rings are densified, not the polygons: GEOS repairs a densified
    polygon with buffer(0), which can turn a valid but thin sliver into
    nothing at all."""
    parts = _flat_parts(geom)
    polygons = shapely.get_type_id(parts) == 3
    lines = np.concatenate([shapely.get_rings(parts[polygons]), parts[~polygons]])
    return shapely.get_coordinates(shapely.segmentize(lines, step))


def _farthest_from(excess, target):
    """Largest distance of a point of ``excess`` from ``target`` (inf when
    target is empty)."""
    if target.is_empty:
        return math.inf
    pts = shapely.points(_densified_vertices(excess, max(0.01, excess.length / 20000.0)))
    lo = float(np.max(shapely.distance(target, pts)))

    def outside(d):
        rest = _difference(excess, target.buffer(d, quad_segs=QUAD_SEGS))
        return _area(rest) > NOISE_AREA

    # Buffers are inscribed polygons: allow for their chord error.
    if not outside(lo * (1 + 1e-4) + DEPTH_PRECISION):
        return lo
    return _bisect(lo, lo + _diagonal(excess) + DEPTH_PRECISION, outside)


def _depth_inside(region, remaining, tol):
    """How deep inside ``remaining`` does ``region`` (a part of it) reach: the
    largest distance from a point of region to the nearest point not in
    remaining. Returns (depth, core), core being the part of region deeper
    than tol (empty, and depth <= tol, when there is none)."""
    pts = shapely.points(_vertices(region))
    lo = float(np.max(shapely.distance(remaining.boundary, pts))) if len(pts) else 0.0
    hi = lo + _diagonal(region) + DEPTH_PRECISION
    zmin, xmin, zmax, xmax = region.bounds
    margin = hi + 1.0
    # Only the stock near the region matters; the clip edge is farther from
    # the region than any depth tested.
    local = _intersection(remaining, box(zmin - margin, xmin - margin, zmax + margin, xmax + margin))

    def core_at(d):
        return _intersection(region, local.buffer(-d, quad_segs=QUAD_SEGS))

    def outside(d):
        return _area(core_at(d)) > NOISE_AREA

    core = core_at(tol)
    if _area(core) <= NOISE_AREA:
        return min(lo, tol), _EMPTY
    return _bisect(max(lo, tol), hi, outside), core


# Grid (mm) to which _sum_segment snaps its input and its union when the plain
# floating union fails or is implausible: far below every tolerance the checks
# use and far below FIT_SLACK, yet some hundred float ulps of the coordinates.
SUM_GRID = 1e-11


# Parts of a swept geometry thinner than this (mm, on average) are overlay
# debris (a polygon collapsed to a line, its sides a few ulps apart): swept, one
# would add a whole band of reach. Far below FIT_SLACK.
SLIVER_WIDTH = 1e-10


def _polygonal(geom):
    """geom as a valid (Multi)Polygon without slivers: invalid input is
    repaired, and lines, points and parts thinner than SLIVER_WIDTH (the
    debris of an overlay, zero-area spikes) are dropped."""
    if geom.is_empty:
        return _EMPTY
    if not geom.is_valid:
        geom = shapely.make_valid(geom)
    parts = _flat_parts(geom)
    polygons = parts[shapely.get_type_id(parts) == 3]
    keep = shapely.area(polygons) > 0.25 * SLIVER_WIDTH * shapely.length(polygons)
    if keep.all() and len(polygons) == len(parts) and geom.geom_type in ("Polygon", "MultiPolygon"):
        return geom
    polygons = polygons[keep]
    if len(polygons) == 0:
        return _EMPTY
    if len(polygons) == 1:
        return polygons[0]
    return _union_all(polygons)


def _sweep_quads(geom, v):
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


def _plausible_union(result, pieces):
    """Cheap sanity check of a union: valid, polygonal, and no smaller than
    its largest piece nor larger than all pieces together. (GEOS has been
    seen to return a wrong union of nearly degenerate input without any
    error.)"""
    if not result.is_valid or result.geom_type not in ("Polygon", "MultiPolygon"):
        return False
    areas = shapely.area(pieces)
    slack = 1e-9 * float(np.sum(areas)) + NOISE_AREA
    return float(np.max(areas)) - slack <= result.area <= float(np.sum(areas)) + slack


def _snapped(geom):
    """geom on the SUM_GRID, valid, without the features thinner than that
    grid (a spike whose two sides lie 1e-15 apart: GEOS keeps it as valid)."""
    try:
        return _polygonal(shapely.set_precision(geom, SUM_GRID))
    except shapely.errors.GEOSException:
        return geom


def _sum_segment(geom, v):
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
        raise shapely.errors.GEOSException("Minkowski sum with a segment failed: %s by %r" % (geom.wkt[:200], v.tolist()))
    return result


def _erode_segment(geom, v, frame):
    """Minkowski difference: points p with p + [0, v] inside geom (frame: a box
    around geom, larger by more than |v|)."""
    outside = _difference(frame, geom)
    return _difference(frame, _sum_segment(outside, (-v[0], -v[1])))


# Gaps (mm) narrower than twice this between the target and the air are closed
# (see _free_space).
JOIN_GAP = 1e-9


def _free_space(target, air):
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
    free = _union(target, air)
    closed = free.buffer(JOIN_GAP, join_style="mitre").buffer(-JOIN_GAP, join_style="mitre")
    return _union(free, closed)


def _air(stock, target, margin):
    zmin, xmin, zmax, xmax = _union(stock, target).bounds
    frame = box(zmin - margin, xmin - margin, zmax + margin, xmax + margin)
    return frame, _difference(frame, stock)


# Direction the blade body extends from its front edge (= the retract direction), (z, x).
_BACK = {MINUS_X: (0.0, 1.0), PLUS_X: (0.0, -1.0), MINUS_Z: (1.0, 0.0), PLUS_Z: (-1.0, 0.0)}


def reachable_region(target, stock, tool, plunge, tol=0.001, model="blade"):
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
        frame, air = _air(stock, target, 2 * r + 1.0)
        free = _free_space(target, air)
        if r == 0.0:
            return free
        return free.buffer(-r, quad_segs=QUAD_SEGS).buffer(r, quad_segs=QUAD_SEGS)
    if model != "blade":
        raise ValueError("unknown reach model %r" % (model,))
    if plunge not in _BACK:
        raise ValueError("unknown plunge direction %r" % (plunge,))
    width, length = float(tool.width), float(tool.length)
    across = max(width - 2 * r - FIT_SLACK, 0.0)
    along = max(length - 2 * r - FIT_SLACK, 0.0)
    back = _BACK[plunge]
    if plunge in (MINUS_X, PLUS_X):
        va, vb = (across, 0.0), (0.0, along)  # (z, x): across Z, along X
    else:
        va, vb = (0.0, across), (along, 0.0)
    reach = length + width + _diagonal(target) + 1.0
    frame, air = _air(stock, target, reach + 1.0)
    column = _sum_segment(target, (back[0] * reach, back[1] * reach))
    free = _intersection(column, _free_space(target, air))
    zmin, xmin, zmax, xmax = frame.bounds
    big = box(zmin - reach, xmin - reach, zmax + reach, xmax + reach)
    core = free.buffer(-r, quad_segs=QUAD_SEGS) if r > 0 else free
    core = _erode_segment(_erode_segment(core, va, big), vb, big)
    opened = _sum_segment(_sum_segment(core, vb), va)
    return opened.buffer(r, quad_segs=QUAD_SEGS) if r > 0 else opened


def unreachable_region(target, stock, tool, plunge=MINUS_X, tol=0.001, model="blade"):
    """Part of ``target`` the tool cannot reach without cutting stock outside
    the target (see reachable_region): the corner fillets, and whatever is
    narrower than the blade."""
    if target.is_empty:
        return _EMPTY
    return _difference(target, reachable_region(target, stock, tool, plunge, tol, model))


def _bounds_text(geom):
    zmin, xmin, zmax, xmax = geom.bounds
    return "Z[%.4f, %.4f] X(radius)[%.4f, %.4f]" % (zmin, zmax, xmin, xmax)


@dataclass
class Verdict:
    tol: float
    gouge: float  # mm of removed material beyond the target (0.0 if none)
    gouge_region: object  # removed material deeper than tol inside stock minus target
    incomplete_area: float  # mm^2 of target left standing outside the reach allowance
    incomplete_depth: float  # mm: its thickest part, measured to the nearest cut/air
    incomplete_region: object  # the part of it thicker than tol (empty when complete)
    unreachable: object  # part of the target the tool cannot reach (the allowance)
    unreachable_depth: float  # mm: farthest point of it from where the tool can reach
    corner_radius: float
    rapid_collisions: list = field(default_factory=list)
    dwell_mismatches: list = field(default_factory=list)
    label: Optional[str] = None

    @property
    def gouged(self):
        return self.gouge > 0.0

    @property
    def incomplete(self):
        return self.incomplete_depth > self.tol

    @property
    def infeasible(self):
        """The target has material no placement of the tool reaches, beyond
        what a corner radius leaves in a right-angled (or wider) corner: a
        groove narrower than the blade, an undercut, an acute corner. The
        program cannot be judged complete against it: fix the target (or the
        cycle should have refused)."""
        return self.unreachable_depth > self.corner_radius + self.tol

    @property
    def ok_within_reach(self):
        """ok, except that the target may be infeasible for the blade."""
        return not (self.gouged or self.incomplete or self.rapid_collisions or self.dwell_mismatches)

    @property
    def ok(self):
        return self.ok_within_reach and not self.infeasible

    def describe(self):
        head = (self.label + ": ") if self.label else ""
        if self.ok:
            return head + "ok (tol %g mm)" % self.tol
        if self.ok_within_reach:
            lines = [head + "program ok within the blade's reach, but the target is not (tol %g mm):" % self.tol]
        else:
            lines = [head + "program fails the groove check (tol %g mm):" % self.tol]
        if self.gouged:
            lines.append(
                "  GOUGE %.4f mm deep into material outside the target, %.6g mm^2 of it deeper than tol, in %s"
                % (self.gouge, _area(self.gouge_region), _bounds_text(self.gouge_region))
            )
        if self.incomplete:
            lines.append(
                "  INCOMPLETE: %.6g mm^2 of reachable target left standing, up to %.4f mm thick, in %s"
                % (self.incomplete_area, self.incomplete_depth, _bounds_text(self.incomplete_region))
            )
        if self.infeasible:
            lines.append(
                "  TARGET INFEASIBLE for this tool: %.6g mm^2 of it is out of the tool's reach, up to %.4f mm"
                " from anywhere the tool can be (corner radius %g), in %s"
                % (_area(self.unreachable), self.unreachable_depth, self.corner_radius, _bounds_text(self.unreachable))
            )
        for c in self.rapid_collisions:
            lines.append("  RAPID COLLISION: " + c.describe())
        for d in self.dwell_mismatches:
            lines.append("  DWELL: " + d.describe())
        return "\n".join(lines)

    __str__ = describe


def check_groove(result, target, tool=None, tol=0.001, label=None, plunge=None, reach="blade"):
    """Judge a simulation against ``target``: the region (shapely (z, x)) the
    program must remove. Target area outside the stock is simply air.

    gouge       removed material of (stock - target) farther than tol from
                both the target and the air: the largest such depth (mm),
                i.e. max over removed points of the distance to the nearest
                point of target or air; 0.0 when none is deeper than tol.
    incomplete  target material still standing, minus the reach allowance
                unreachable_region(...).buffer(tol); flagged when some of it
                lies more than tol from every cut surface and the air.
    infeasible  the unreachable part of the target reaches farther than
                corner_radius + tol from where the tool can be.
    rapid       the simulation's rapid collisions; dwell mismatches too.
    """
    tool = tool if tool is not None else result.tool
    plunge = plunge if plunge is not None else result.plunge
    if tool is None or plunge is None:
        raise ValueError("check_groove needs the tool and plunge direction")
    stock, remaining, removed = result.stock, result.remaining, result.removed

    # Gouge: removed material that had to stay, measured as depth into it
    # (a skim along the stock's surface far from the groove is as deep as
    # the skim, not as far as the groove).
    keep = _difference(stock, target)
    cut_keep = _intersection(removed, keep)
    if _area(cut_keep) > NOISE_AREA:
        gouge, excess = _depth_inside(cut_keep, keep, tol)
        if excess.is_empty:
            gouge = 0.0
    else:
        gouge, excess = 0.0, _EMPTY

    reachable = reachable_region(target, stock, tool, plunge, tol, reach)
    unreachable = _difference(target, reachable)
    if _area(unreachable) > NOISE_AREA:
        unreachable_depth = _farthest_from(unreachable, reachable)
    else:
        unreachable_depth = 0.0

    left = _intersection(target, remaining)
    if not unreachable.is_empty:
        left = _difference(left, unreachable.buffer(tol, quad_segs=QUAD_SEGS))
    if _area(left) > NOISE_AREA:
        depth, core = _depth_inside(left, remaining, tol)
    else:
        depth, core = 0.0, _EMPTY
    return Verdict(
        tol=tol,
        gouge=gouge,
        gouge_region=excess,
        incomplete_area=_area(left),
        incomplete_depth=depth,
        incomplete_region=core,
        unreachable=unreachable,
        unreachable_depth=unreachable_depth,
        corner_radius=float(tool.corner_radius),
        rapid_collisions=list(result.rapid_collisions),
        dwell_mismatches=list(result.dwell_mismatches),
        label=label,
    )


def assert_clean(verdict, allow_infeasible=False):
    """Raise AssertionError with the verdict's description unless it is ok.

    allow_infeasible: accept a target the blade cannot fully reach (judge the
    program only on gouge, leftover within reach, rapids and dwells), for
    cycles whose own definition leaves such material (e.g. a flat blade in a
    V-shaped floor)."""
    good = verdict.ok_within_reach if allow_infeasible else verdict.ok
    if not good:
        raise AssertionError(verdict.describe())
    return verdict


# --------------------------------------------------------------------------- helpers


def region(xmin, xmax, zmin, zmax):
    """Axis-aligned (z, x) rectangle from radius and Z limits."""
    return box(min(zmin, zmax), min(xmin, xmax), max(zmin, zmax), max(xmin, xmax))


def bar(radius, zmin, zmax, bore=0.0):
    """Stock of a bar (or tube with a bore radius) between zmin and zmax."""
    return region(bore, radius, zmin, zmax)


__all__ = [
    "tool_outline",
    "swept_area",
    "simulate",
    "check_groove",
    "assert_clean",
    "unreachable_region",
    "reachable_region",
    "region",
    "bar",
    "SimulationResult",
    "Verdict",
    "RapidCollision",
    "DwellMismatch",
    "RAPID_AREA_TOL",
]
