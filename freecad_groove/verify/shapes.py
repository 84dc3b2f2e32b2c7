"""Regions of the half section without shapely: ``Shape`` (closed rings and
their Boolean combinations, evaluated on a column grid when needed),
``Section`` (a region on a column grid: what the check reports) and the
distances the check measures (to the edges of a shape's rings).

Points are (z, x), x the radius, as in the rest of verify.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import Optional

import numpy as np

from . import columns as col
from .columns import DIFFERENCE, INTERSECTION, UNION, Flat, Grid

SEGMENT_PIECE = 1.0  # mm: edges longer along Z are split (the nearest-edge search looks along Z)
AREA_STEP = 0.005  # mm: the columns a Shape's own area is taken on


class Shape:
    """A region of closed rings combined by union, difference, intersection."""

    def rows(self, centres: np.ndarray, transposed: bool = False) -> Flat:
        raise NotImplementedError

    def leaves(self) -> list[Rings]:
        raise NotImplementedError

    def clipped(self, zlo: float, zhi: float) -> Shape:
        """The same region on the lines z in [zlo, zhi], without the rings that lie wholly beside them."""
        raise NotImplementedError

    def vertices(self) -> np.ndarray:
        """(z, x) of every ring vertex."""
        parts = [np.concatenate(leaf.rings) for leaf in self.leaves() if leaf.rings]
        return np.concatenate(parts) if parts else np.empty((0, 2))

    @property
    def bounds(self) -> tuple[float, float, float, float]:
        v = self.vertices()
        if not len(v):
            return (0.0, 0.0, 0.0, 0.0)
        return float(v[:, 0].min()), float(v[:, 1].min()), float(v[:, 0].max()), float(v[:, 1].max())

    @property
    def is_empty(self) -> bool:
        return self.area == 0.0

    def z_range(self) -> Optional[tuple[float, float]]:
        """The Z range the region may reach (None: nowhere): an intersection
        reaches no farther than either side, a difference than its first."""
        v = self.vertices()
        return (float(v[:, 0].min()), float(v[:, 0].max())) if len(v) else None

    @property
    def area(self) -> float:
        """On columns AREA_STEP wide (and at every vertex) over its Z range: exact for straight edges."""
        reach = self.z_range()
        if reach is None or reach[1] <= reach[0]:
            return 0.0
        shape = self.clipped(*reach)
        z = shape.vertices()[:, 0]
        grid = col.make_grid(np.concatenate([z[(z >= reach[0]) & (z <= reach[1])], reach]), [reach], AREA_STEP, 0.0)
        return col.area(shape.rows(grid.centres), grid.widths)

    def __or__(self, other: Shape) -> Shape:
        return Combined(UNION, self, other)

    def __sub__(self, other: Shape) -> Shape:
        return Combined(DIFFERENCE, self, other)

    def __and__(self, other: Shape) -> Shape:
        return Combined(INTERSECTION, self, other)


@dataclass(frozen=True, eq=False)
class Rings(Shape):
    """The region closed (z, x) rings enclose, nested rings as holes (even-odd)."""

    rings: tuple = ()

    def rows(self, centres: np.ndarray, transposed: bool = False) -> Flat:
        rings = [r[:, ::-1] for r in self.rings] if transposed else list(self.rings)
        return col.ring_rows(rings, centres)

    def leaves(self) -> list[Rings]:
        return [self]

    def clipped(self, zlo: float, zhi: float) -> Shape:
        return Rings(tuple(r for r in self.rings if r[:, 0].max() >= zlo and r[:, 0].min() <= zhi))


@dataclass(frozen=True, eq=False)
class Combined(Shape):
    op: str
    a: Shape
    b: Shape

    def rows(self, centres: np.ndarray, transposed: bool = False) -> Flat:
        return col.combine(self.a.rows(centres, transposed), self.b.rows(centres, transposed), self.op)

    def leaves(self) -> list[Rings]:
        return self.a.leaves() + self.b.leaves()

    def clipped(self, zlo: float, zhi: float) -> Shape:
        return Combined(self.op, self.a.clipped(zlo, zhi), self.b.clipped(zlo, zhi))

    def z_range(self) -> Optional[tuple[float, float]]:
        a = self.a.z_range()
        if self.op == DIFFERENCE or a is None:
            return a
        b = self.b.z_range()
        if b is None:
            return None if self.op == INTERSECTION else a
        if self.op == INTERSECTION:
            return (max(a[0], b[0]), min(a[1], b[1])) if max(a[0], b[0]) <= min(a[1], b[1]) else None
        return (min(a[0], b[0]), max(a[1], b[1]))


@dataclass(frozen=True, eq=False)
class Union(Shape):
    """The union of many shapes at once (one sweep over all their intervals: no deep tree)."""

    parts: tuple = ()

    def rows(self, centres: np.ndarray, transposed: bool = False) -> Flat:
        rows = [p.rows(centres, transposed) for p in self.parts]
        if not rows:
            return col.empty_flat()
        return col.combine(tuple(np.concatenate([r[k] for r in rows]) for k in range(3)), col.empty_flat(), UNION)

    def leaves(self) -> list[Rings]:
        return [leaf for p in self.parts for leaf in p.leaves()]

    @cached_property
    def _by_start(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
        """The parts' Z ranges sorted by their low ends: (order, lows, highs, the longest range)."""
        ranges = np.array([[p.bounds[0], p.bounds[2]] for p in self.parts]).reshape(-1, 2)
        order = np.argsort(ranges[:, 0], kind="stable")
        longest = float(np.max(ranges[:, 1] - ranges[:, 0])) if len(ranges) else 0.0
        return order, ranges[order, 0], ranges[order, 1], longest

    def clipped(self, zlo: float, zhi: float) -> Shape:
        # only the parts starting within the longest range (and 1 mm) below zlo: the check clips a few
        # times an op, and a scan of every part (the air of 2000 CYCLE93 calls) grew with the program
        order, lows, highs, longest = self._by_start
        i0 = int(np.searchsorted(lows, zlo - longest - 1.0, "left"))
        i1 = int(np.searchsorted(lows, zhi, "right"))
        near = np.sort(order[i0:i1][highs[i0:i1] >= zlo])
        parts = [self.parts[k].clipped(zlo, zhi) for k in near]
        return Union(tuple(p for p in parts if not (isinstance(p, Rings) and not p.rings)))


EMPTY_SHAPE = Rings(())


def rings(points: Sequence[Sequence[tuple[float, float]]]) -> Shape:
    """Closed rings of (z, x) points (even-odd); rings of fewer than 3 points are left out."""
    return Rings(tuple(np.asarray(r, dtype=float) for r in points if len(r) >= 3))


def box(zmin: float, xmin: float, zmax: float, xmax: float) -> Shape:
    z0, z1, x0, x1 = min(zmin, zmax), max(zmin, zmax), min(xmin, xmax), max(xmin, xmax)
    if z1 <= z0 or x1 <= x0:
        return EMPTY_SHAPE
    return rings([[(z0, x0), (z1, x0), (z1, x1), (z0, x1)]])


def union_all(shapes: Sequence[Shape]) -> Shape:
    """The union of ``shapes``."""
    shapes = [s for s in shapes if not (isinstance(s, Rings) and not s.rings)]
    if not shapes:
        return EMPTY_SHAPE
    return shapes[0] if len(shapes) == 1 else Union(tuple(shapes))


# ---------------------------------------------------------------- regions on columns


@dataclass(eq=False)
class Section:
    """A region on a column grid (what the check reports): ``rows`` flat
    intervals along X in the columns of ``grid``."""

    grid: Optional[Grid] = None
    rows: Flat = field(default_factory=col.empty_flat)

    @property
    def area(self) -> float:
        return 0.0 if self.grid is None else col.area(self.rows, self.grid.widths)

    @property
    def is_empty(self) -> bool:
        return self.grid is None or not len(self.rows[0])

    @property
    def bounds(self) -> tuple[float, float, float, float]:
        if self.is_empty:
            return (0.0, 0.0, 0.0, 0.0)
        cols, lo, hi = self.rows
        return (float(self.grid.edges[cols.min()]), float(lo.min()), float(self.grid.edges[cols.max() + 1]),
                float(hi.max()))

    def outlines(self) -> list[np.ndarray]:
        """Closed (z, x) outlines of the region, one per run of neighbouring
        columns that hold one interval each in the same place (for a picture)."""
        if self.is_empty:
            return []
        cols, lo, hi = self.rows
        rank = np.arange(len(cols)) - np.searchsorted(cols, cols, "left")
        out = []
        for k in np.unique(rank):
            pick = rank == k
            c, a, b = cols[pick], lo[pick], hi[pick]
            breaks = np.nonzero((np.diff(c) != 1) | (a[1:] > b[:-1]) | (b[1:] < a[:-1]))[0] + 1
            for run in np.split(np.arange(len(c)), breaks):
                left, right = self.grid.edges[c[run]], self.grid.edges[c[run] + 1]
                z = np.column_stack([left, right]).ravel()
                bottom = np.column_stack([z, np.repeat(a[run], 2)])
                top = np.column_stack([z, np.repeat(b[run], 2)])[::-1]
                out.append(np.vstack([bottom, top]))
        return out


EMPTY_SECTION = Section()


@dataclass(frozen=True)
class Measured:
    """A region of which only the area is kept (verify's report: no picture to draw)."""

    area: float

    @property
    def is_empty(self) -> bool:
        return not self.area


def padded_area(lo: np.ndarray, hi: np.ndarray, widths: np.ndarray, chunk: int = 1 << 16) -> float:
    """The area of a padded set on columns ``widths`` wide (``chunk`` columns at a time)."""
    total = 0.0
    for i0 in range(0, len(lo), chunk):
        a, b = lo[i0:i0 + chunk], hi[i0:i0 + chunk]
        length = np.subtract(b, a, out=np.zeros(a.shape), where=a < b)
        total += float(np.sum(length.sum(axis=1) * widths[i0:i0 + chunk]))
    return total


def padded_rows(grid: Grid, shape: Shape, chunk: int = 1 << 16) -> tuple[np.ndarray, np.ndarray]:
    """``shape`` on the columns of ``grid`` as a padded set, taken ``chunk``
    columns at a time (only the rings that reach them): no whole-grid array
    but the result."""
    n = len(grid)
    lo, hi = col.empty_padded(n)
    for i0 in range(0, n, chunk):
        i1 = min(n, i0 + chunk)
        local = shape.clipped(float(grid.edges[i0]), float(grid.edges[i1]))
        a, b = col.pack(i1 - i0, local.rows(grid.centres[i0:i1]))
        k = a.shape[1]
        if k > lo.shape[1]:
            grow = np.full((n, k - lo.shape[1]), col.EMPTY_SLOT)
            lo, hi = np.hstack([lo, grow]), np.hstack([hi, grow])
        lo[i0:i1, :k], hi[i0:i1, :k] = a, b
    return lo, hi


# ---------------------------------------------------------------- distances to a shape's edges


class Edges:
    """The edges of a shape's rings, split into pieces at most SEGMENT_PIECE
    long along Z (an edge across Z stays whole: a CYCLE93's air reaches 1000 mm
    up) and sorted along Z, for the distance from points to the shape's
    boundary: for a point inside a difference or an intersection of rings the
    nearest point outside lies on one of them."""

    def __init__(self, shape: Shape) -> None:
        pieces = []
        for leaf in shape.leaves():
            for ring in leaf.rings:
                closed = ring if np.all(ring[0] == ring[-1]) else np.vstack([ring, ring[:1]])
                pieces.append(_split(closed[:-1], closed[1:]))
        seg = np.concatenate(pieces) if pieces else np.empty((0, 4))
        order = np.argsort(np.minimum(seg[:, 0], seg[:, 2]), kind="stable")
        self.segments = seg[order]
        self.zmin = np.minimum(self.segments[:, 0], self.segments[:, 2])

    def near(self, zlo: float, zhi: float) -> np.ndarray:
        """The pieces that reach into Z [zlo, zhi]."""
        i0 = int(np.searchsorted(self.zmin, zlo - SEGMENT_PIECE, "left"))
        i1 = int(np.searchsorted(self.zmin, zhi, "right"))
        seg = self.segments[i0:i1]
        return seg[np.maximum(seg[:, 0], seg[:, 2]) >= zlo]


def corners(shape: Shape, turn: float = 0.05) -> np.ndarray:
    """(z, x) of the vertices where a ring of ``shape`` turns by more than
    ``turn`` radians (not the chords' ends along an arc)."""
    out = []
    for leaf in shape.leaves():
        for ring in leaf.rings:
            closed = ring[:-1] if len(ring) > 3 and np.all(ring[0] == ring[-1]) else ring
            d_in = closed - np.roll(closed, 1, axis=0)
            d_out = np.roll(closed, -1, axis=0) - closed
            angle = np.abs(np.arctan2(d_in[:, 0] * d_out[:, 1] - d_in[:, 1] * d_out[:, 0],
                                      np.sum(d_in * d_out, axis=1)))
            out.append(closed[angle > turn])
    return np.concatenate(out) if out else np.empty((0, 2))


def _split(p0: np.ndarray, p1: np.ndarray) -> np.ndarray:
    """The edges p0 -> p1 ((z, x) rows) in pieces at most SEGMENT_PIECE long along Z (z0, x0, z1, x1)."""
    count = np.maximum(1, np.ceil(np.abs(p1[:, 0] - p0[:, 0]) / SEGMENT_PIECE).astype(np.int64))
    edge = np.repeat(np.arange(len(p0)), count)
    k = np.arange(len(edge)) - (np.cumsum(count) - count)[edge]
    t0, t1 = (k / count[edge])[:, None], ((k + 1) / count[edge])[:, None]
    d = (p1 - p0)[edge]
    return np.hstack([p0[edge] + t0 * d, p0[edge] + t1 * d])


def distances(points: np.ndarray, segments: np.ndarray, chunk: int = 2_000_000) -> np.ndarray:
    """The distance of each (z, x) point to the nearest segment (inf: none)."""
    out = np.full(len(points), np.inf)
    if not len(segments) or not len(points):
        return out
    a, d = segments[:, :2], segments[:, 2:] - segments[:, :2]
    dd = np.maximum(np.sum(d * d, axis=1), 1e-300)
    step = max(1, chunk // len(segments))
    for s in range(0, len(points), step):
        p = points[s:s + step, None, :]
        t = np.clip(np.sum((p - a) * d, axis=2) / dd, 0.0, 1.0)
        q = a + t[..., None] * d
        out[s:s + step] = np.sqrt(np.min(np.sum((p - q) ** 2, axis=2), axis=1))
    return out


def capsule_rows(lines: np.ndarray, segments: np.ndarray, radius: float) -> Flat:
    """Where each vertical line z = lines[i] comes within ``radius`` of a
    segment: rows (line, lo, hi) along X, one per (line, segment) that meet."""
    if not len(lines) or not len(segments):
        return col.empty_flat()
    near = ((lines[:, None] >= np.minimum(segments[:, 0], segments[:, 2])[None, :] - radius)
            & (lines[:, None] <= np.maximum(segments[:, 0], segments[:, 2])[None, :] + radius))
    li, si = np.nonzero(near)
    z, s = lines[li], segments[si]
    lo, hi = np.full(len(li), np.inf), np.full(len(li), -np.inf)
    for pz, px in ((s[:, 0], s[:, 1]), (s[:, 2], s[:, 3])):  # the end disks
        dz = z - pz
        half = np.sqrt(np.maximum(radius * radius - dz * dz, 0.0))
        meet = np.abs(dz) <= radius
        lo = np.where(meet, np.minimum(lo, px - half), lo)
        hi = np.where(meet, np.maximum(hi, px + half), hi)
    dz, dx = s[:, 2] - s[:, 0], s[:, 3] - s[:, 1]
    length = np.hypot(dz, dx)
    ok = length > 0
    uz, ux = np.where(ok, dz / np.where(ok, length, 1), 0), np.where(ok, dx / np.where(ok, length, 1), 0)
    rz = z - s[:, 0]
    # along: 0 <= rz uz + (x - x0) ux <= length; across: -r <= -rz ux + (x - x0) uz <= r
    a_lo, a_hi = _linear(rz * uz, ux, 0.0, length)
    b_lo, b_hi = _linear(-rz * ux, uz, -radius, radius)
    band_lo, band_hi = s[:, 1] + np.maximum(a_lo, b_lo), s[:, 1] + np.minimum(a_hi, b_hi)
    band = ok & (band_lo <= band_hi)
    lo = np.where(band, np.minimum(lo, band_lo), lo)
    hi = np.where(band, np.maximum(hi, band_hi), hi)
    keep = lo < hi
    return li[keep], lo[keep], hi[keep]


def _linear(c: np.ndarray, k: np.ndarray, low: float, high: float) -> tuple[np.ndarray, np.ndarray]:
    """The t with low <= c + k t <= high (all t, or none, where k is 0)."""
    steep = np.abs(k) > 1e-15
    safe = np.where(steep, k, 1.0)
    t0, t1 = (low - c) / safe, (high - c) / safe
    inside = (c >= low) & (c <= high)
    lo = np.where(steep, np.minimum(t0, t1), np.where(inside, -np.inf, np.inf))
    hi = np.where(steep, np.maximum(t0, t1), np.where(inside, np.inf, -np.inf))
    return lo, hi
