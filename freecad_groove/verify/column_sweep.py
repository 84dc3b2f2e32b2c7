"""Material removal on the column model: a blade's moves swept over the
material, feeds taking away what the blade sweeps, rapids checked against
the material standing when they run.

Each straight move (an arc as its chords: arcs.straightened) sweeps the
Minkowski sum of the blade and the move, cut by each column's centre line
in closed form (swept_rows). The feeds between two rapids are
taken away together (the order of feeds does not change what they leave);
a rapid whose sweep, shrunk by sweep.RAPID_SKIN, overlaps standing material by
more than sweep.RAPID_AREA_TOL mm^2 is a hit. The work of a move is the
columns it crosses: linear in the moves.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from freecad_groove.engine.moves import ARCS, DWELL, FEED, RAPID, GroovingTool, Move

from . import columns as col
from .arcs import straightened
from .columns import DIFFERENCE, Flat, Grid
from .outline import outline_at_origin
from .shapes import Shape, padded_area, padded_rows

# As sweep.RAPID_SKIN and sweep.RAPID_AREA_TOL (that module needs shapely).
RAPID_SKIN = 2e-5 + 1e-5
RAPID_AREA_TOL = 1e-9
# The chords an arc is swept along stay this close to it (mm): a tenth of the
# 0.001 mm the check reports from, so that a chord can neither hide a gouge
# nor make one (arcs.SWEEP_TOL, 1e-5, ten times finer, is the shapely oracle's).
CHORD_TOL = 1e-4

Point = tuple[float, float]  # (x, z), x the radius


@dataclass
class FeedPath:
    """The straight feeds of a blade (arcs as chords): starts and ends, (z, x) rows."""

    tool: GroovingTool
    plunge: str
    starts: np.ndarray
    ends: np.ndarray


@dataclass
class Hit:
    """A rapid (move ``index`` of its list, from ``start``) over ``area`` mm^2 of standing material, ``at`` (x, z)."""

    index: int
    start: Point
    end: Point
    area: float
    at: Point


class Material:
    """The standing material on a grid: padded intervals per column, updated
    in place. With ``falls``, a piece cut free of the chuck end (the first
    column holding material) falls away: the columns from the first one left
    empty after it on (``held_end``) hold nothing."""

    def __init__(self, grid: Grid, shape: Shape, falls: bool = False) -> None:
        self.grid = grid
        self.lo, self.hi = padded_rows(grid, shape)
        self.stock_area = self.area()
        self.falls = falls
        self.held_end = len(grid)
        if falls:
            full = np.nonzero(self.lo[:, 0] < self.hi[:, 0])[0]
            if len(full):
                self.drop_after(int(full[0]), len(grid))

    def area(self) -> float:
        """The area standing (mm^2)."""
        return padded_area(self.lo, self.hi, self.grid.widths)

    def rows(self, i0: int, i1: int) -> Flat:
        """The columns i0:i1, numbered from i0."""
        return col.flat(self.lo[i0:i1], self.hi[i0:i1])

    def put(self, i0: int, i1: int, rows: Flat) -> None:
        lo, hi = col.pack(i1 - i0, rows)
        k = lo.shape[1]
        if k > self.lo.shape[1]:
            grow = np.full((len(self.lo), k - self.lo.shape[1]), col.EMPTY_SLOT)
            self.lo, self.hi = np.hstack([self.lo, grow]), np.hstack([self.hi, grow.copy()])
        self.lo[i0:i1, :k], self.hi[i0:i1, :k] = lo, hi
        self.lo[i0:i1, k:], self.hi[i0:i1, k:] = col.EMPTY_SLOT, col.EMPTY_SLOT

    def subtract(self, rows: Flat) -> None:
        """Take away ``rows`` (global column numbers, any order)."""
        if not len(rows[0]):
            return
        i0, i1 = int(rows[0].min()), int(rows[0].max()) + 1
        self.put(i0, i1, col.combine(self.rows(i0, i1), col.shifted(rows, -i0), DIFFERENCE))

    def first_empty(self, i0: int, i1: int) -> int:
        """The first column in [i0, i1) holding nothing, else i1."""
        empty = np.nonzero(~np.any(self.lo[i0:i1] < self.hi[i0:i1], axis=1))[0]
        return i0 + int(empty[0]) if len(empty) else i1

    def drop_after(self, i0: int, i1: int) -> None:
        """Columns from the first empty one in [i0, held_end) on have fallen away."""
        if not self.falls:
            return
        end = self.first_empty(i0, min(i1, self.held_end))
        if end < self.held_end:
            self.lo[end:self.held_end], self.hi[end:self.held_end] = col.EMPTY_SLOT, col.EMPTY_SLOT
            self.held_end = end


def straight_segments(moves: Sequence[Move], start: Point) -> tuple[list[tuple[int, Point, Point, bool]], Point]:
    """(index of the move, start, end, a rapid) of each straight piece the
    tool runs (arcs as chords), and the final position."""
    pos = (float(start[0]), float(start[1]))
    segments = []
    for i, m in enumerate(moves):
        if m.kind not in (RAPID, FEED, DWELL) and m.kind not in ARCS:
            raise ValueError("move #%d has unknown kind %r" % (i, m.kind))
    for i, m in straightened(moves, pos, CHORD_TOL):
        if m.kind in (RAPID, FEED):
            end = (pos[0] if m.x is None else float(m.x), float(m.z))
            segments.append((i, pos, end, m.kind == RAPID))
            pos = end
    return segments, pos


def _envelope(w: np.ndarray, dz: np.ndarray, dx: np.ndarray, r: float, sign: float) -> np.ndarray:
    """The lower (sign -1) or upper (sign 1) side of the capsule of radius r
    around the segment (0, 0) -> (dz, dx) at z = w (inside its Z range): the
    end disks and the two long edges of its band (the band's short edges lie
    in the disks)."""
    best = np.full(len(w), np.inf * -sign)
    pick = np.minimum if sign < 0 else np.maximum
    for pz, px in ((0.0, 0.0), (dz, dx)):
        dw = w - pz
        near = np.abs(dw) <= r
        best = np.where(near, pick(best, px + sign * np.sqrt(np.maximum(r * r - dw * dw, 0.0))), best)
    length = np.hypot(dz, dx)
    slanted = np.abs(dz) > 1e-15
    safe_len, safe_dz = np.where(length > 0, length, 1.0), np.where(slanted, dz, 1.0)
    nz, nx = -dx / safe_len, dz / safe_len
    for side in (r, -r):
        t = (w - side * nz) / safe_dz
        on = slanted & (t >= 0.0) & (t <= 1.0)
        best = np.where(on, pick(best, side * nx + t * dx), best)
    return best


def _extreme(w0: np.ndarray, w1: np.ndarray, dz: np.ndarray, dx: np.ndarray, r: float, sign: float) -> np.ndarray:
    """The lowest (sign -1) or highest (sign 1) level of the capsule over z in [w0, w1] (within its range)."""
    # where the capsule is lowest (highest): at the end lower (higher) in X, along all of it when level
    towards = dx * sign
    m0 = np.where(towards > 0, dz, np.where(towards < 0, 0.0, np.minimum(dz, 0.0)))
    m1 = np.where(towards > 0, dz, np.where(towards < 0, 0.0, np.maximum(dz, 0.0)))
    overall = (np.maximum(dx, 0.0) + r) if sign > 0 else (np.minimum(dx, 0.0) - r)
    pick = np.minimum if sign < 0 else np.maximum
    ends = pick(_envelope(w0, dz, dx, r, sign), _envelope(w1, dz, dx, r, sign))
    return np.where((w0 <= m1) & (w1 >= m0), overall, ends)


@lru_cache(maxsize=64)
def blade_box(tool: GroovingTool, plunge: str) -> tuple[np.ndarray, float]:
    """The blade as a box (z0, x0, z1, x1) about its reference corner grown
    by a disk of its corner radius (all four corners rounded: the back ones,
    far behind the cutting edge, are sharp on the real blade), and the radius
    (cached: read-only)."""
    points = np.asarray(outline_at_origin(tool, plunge))
    r = float(tool.corner_radius) if float(tool.corner_radius) > 1e-7 else 0.0
    lo, hi = points.min(axis=0) + r, points.max(axis=0) - r
    box = np.array([lo[0], lo[1], hi[0], hi[1]])
    box.setflags(write=False)
    return box, r


def swept_rows(centres: np.ndarray, tool: GroovingTool, plunge: str, starts: np.ndarray, ends: np.ndarray,
               skin: float = 0.0, limit: int | None = None) -> tuple[Flat, np.ndarray]:
    """What the blade sweeps along each move starts[i] -> ends[i] ((z, x)
    rows) on the lines z = ``centres`` (increasing; shrunk by ``skin``; only
    lines before ``limit``): rows (line numbers) and the move of each. The blade is blade_box's box
    B grown by a disk; swept along d it is B + capsule(0 -> d, r), and a
    column's line z = c meets it from the lowest to the highest level of the
    capsule over c - B's Z extent, B's X extent added: exact, arcs and all."""
    if not len(starts):
        return col.empty_flat(), np.empty(0, dtype=np.int64)
    box, r = blade_box(tool, plunge)
    if skin > r:
        box, r = box + np.array([skin - r, skin - r, r - skin, r - skin]), 0.0
    else:
        r -= skin
    dz, dx = ends[:, 0] - starts[:, 0], ends[:, 1] - starts[:, 1]
    kz0, kz1 = np.minimum(dz, 0.0) - r, np.maximum(dz, 0.0) + r  # the capsule's Z extent
    i0 = np.searchsorted(centres, starts[:, 0] + box[0] + kz0, "left")
    i1 = np.searchsorted(centres, starts[:, 0] + box[2] + kz1, "right")
    # the middle: lines whose strip holds the whole capsule, its lowest and highest level
    m0 = np.searchsorted(centres, starts[:, 0] + box[0] + kz1, "left")
    m1 = np.searchsorted(centres, starts[:, 0] + box[2] + kz0, "right")
    if limit is not None:
        i1, m1 = np.minimum(i1, limit), np.minimum(m1, limit)
    m0, m1 = np.clip(m0, i0, np.maximum(i0, i1)), np.clip(m1, i0, np.maximum(i0, i1))
    m1 = np.maximum(m1, m0)
    if box[2] < box[0] or box[3] < box[1]:
        return col.empty_flat(), np.empty(0, dtype=np.int64)
    middle_which, middle_cols = _ranges(m0, m1)
    lo = starts[middle_which, 1] + box[1] + np.minimum(dx[middle_which], 0.0) - r
    hi = starts[middle_which, 1] + box[3] + np.maximum(dx[middle_which], 0.0) + r
    side_which, side_cols = _ranges(np.concatenate([i0, m1]), np.concatenate([m0, np.maximum(i1, m1)]))
    side_which = side_which % len(starts)
    c = centres[side_cols] - starts[side_which, 0]
    mz, mx = dz[side_which], dx[side_which]
    w0 = np.maximum(c - box[2], kz0[side_which])
    w1 = np.minimum(c - box[0], kz1[side_which])
    side_lo = starts[side_which, 1] + box[1] + _extreme(w0, w1, mz, mx, r, -1.0)
    side_hi = starts[side_which, 1] + box[3] + _extreme(w0, w1, mz, mx, r, 1.0)
    cols = np.concatenate([middle_cols, side_cols])
    lo, hi = np.concatenate([lo, side_lo]), np.concatenate([hi, side_hi])
    which = np.concatenate([middle_which, side_which])
    keep = np.concatenate([np.ones(len(middle_cols), dtype=bool), w0 <= w1]) & (lo < hi)
    return (cols[keep], lo[keep], hi[keep]), which[keep]


def _ranges(start: np.ndarray, stop: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(which range, index) of every index in the ranges start[k]:stop[k]."""
    counts = np.maximum(stop - start, 0)
    which = np.repeat(np.arange(len(start)), counts)
    return which, start[which] + (np.arange(len(which)) - (np.cumsum(counts) - counts)[which])


def _zx(points: Sequence[Point]) -> np.ndarray:
    return np.array([(z, x) for x, z in points], dtype=float).reshape(-1, 2)


def _overlaps(material: Material, rows: Flat) -> np.ndarray:
    """The area each row (cols, lo, hi) shares with the standing material, per row and slot (rows, K)."""
    cols, a, b = rows
    each = np.minimum(b[:, None], material.hi[cols]) - np.maximum(a[:, None], material.lo[cols])
    return np.clip(each, 0.0, None) * material.grid.widths[cols][:, None]


def _rapid_hit(material: Material, rows: Flat, window: tuple[int, int]) -> tuple[float, Point] | None:
    """(area, (x, z) inside) of the held material a rapid's rows (its sweep, less RAPID_SKIN) overlap, or None."""
    if not len(rows[0]):
        return None
    each = _overlaps(material, rows)
    area = each.sum(axis=1)
    if float(area.sum()) <= RAPID_AREA_TOL:
        return None
    cols, a, b = rows
    if material.falls:  # what a cut in this step set free has fallen: only what is still held counts
        end = min(material.held_end, int(cols.max()) + 1)
        area = np.where(cols < material.first_empty(window[0], end), area, 0.0)
        if float(area.sum()) <= RAPID_AREA_TOL:
            return None
    best = int(np.argmax(area))
    k = int(np.argmax(each[best]))
    x = 0.5 * (max(a[best], material.lo[cols[best], k]) + min(b[best], material.hi[cols[best], k]))
    return float(area.sum()), (float(x), float(material.grid.centres[cols[best]]))


RAPID_SCAN = 32  # rapids whose overlap with the standing material is taken at once


class _Groups:
    """The rows the feeds sweep, by feed group (the feeds between two rapids), taken away group by group."""

    def __init__(self, material: Material, tool: GroovingTool, plunge: str, starts: np.ndarray, ends: np.ndarray,
                 group: np.ndarray) -> None:
        self.material = material
        rows, which = swept_rows(material.grid.centres, tool, plunge, starts, ends)
        order = np.argsort(group[which], kind="stable")
        self.rows, self.group = col.select(rows, order), group[which][order]
        self.done = 0  # the groups before this one are taken away

    def take_until(self, stop: int) -> None:
        """Take away the groups before ``stop``."""
        if stop <= self.done:
            return
        a, b = np.searchsorted(self.group, [self.done, stop], "left")
        if b > a:
            self.material.subtract(col.union_per_column(col.select(self.rows, slice(a, b))))
        self.done = stop


def sweep(material: Material, moves: Sequence[Move], tool: GroovingTool, plunge: str, start: Point,
          window: tuple[int, int]) -> tuple[list[Hit], Point, FeedPath]:
    """Run ``moves`` from ``start`` through ``material`` (updated): the
    rapids that meet standing material, where the tool ends, the feeds.
    All the moves are swept at once; a feed group is taken away before the
    first rapid after it that overlaps the standing material (material only
    shrinks: a rapid clear of it before is clear of it after)."""
    segments, final = straight_segments(moves, start)
    rapid = np.array([r for _i, _a, _b, r in segments], dtype=bool)
    starts, ends = _zx([a for _i, a, _b, _r in segments]), _zx([b for _i, _a, b, _r in segments])
    feeds = FeedPath(tool, plunge, starts[~rapid], ends[~rapid])
    groups = _Groups(material, tool, plunge, feeds.starts, feeds.ends, np.cumsum(rapid)[~rapid])
    rapids = np.nonzero(rapid)[0]
    rows, which = swept_rows(material.grid.centres, tool, plunge, starts[rapids], ends[rapids], RAPID_SKIN,
                             material.held_end)
    order = np.argsort(which, kind="stable")
    rows, which = col.select(rows, order), which[order]
    bounds = np.searchsorted(which, np.arange(len(rapids) + 1), "left")
    hits, k = [], 0
    while k < len(rapids):
        stop = min(k + RAPID_SCAN, len(rapids))
        a, b = bounds[k], bounds[stop]
        area = np.bincount(which[a:b] - k, _overlaps(material, col.select(rows, slice(a, b))).sum(axis=1),
                           minlength=stop - k)
        near = np.nonzero(area > RAPID_AREA_TOL)[0]
        if not len(near):
            k = stop
            continue
        j = k + int(near[0])
        groups.take_until(j + 1)
        hit = _rapid_hit(material, col.select(rows, slice(bounds[j], bounds[j + 1])), window)
        if hit is not None:
            index, a_point, b_point, _r = segments[rapids[j]]
            hits.append(Hit(index, a_point, b_point, hit[0], hit[1]))
        k = j + 1
    groups.take_until(len(rapids) + 1)
    return hits, final, feeds
