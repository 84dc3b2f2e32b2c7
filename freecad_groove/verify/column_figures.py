"""The distances the column model's check reports: how deep a gouge reaches
into the part (to the exact edges of the part's rings), the part of it deeper
than the tolerance, and whether material left standing is thicker than it.
A gouge is measured on exact lines, not on the model's columns: the columns
find where to look (a column holds one interval across its width, and on a
steep wall that interval is off at the column's sides by the slope times
half the width), the lines measure.

Rows are flat intervals along X on a window's columns (columns.Flat).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Optional

import numpy as np

from . import columns as col
from .column_sweep import FeedPath, swept_rows
from .columns import DIFFERENCE, INTERSECTION, UNION, Flat, Grid
from .shapes import Edges, Shape, capsule_rows, distances

NOISE_AREA = 1e-10  # mm^2, as overlay.NOISE_AREA
SUBLINES = 4  # lines per column the part of a gouge deeper than the tolerance is measured on
NARROW = 0.005  # mm: a column narrower than this is measured on its sides too, whatever its centre shows
# mm: a row at a narrow column's centre thinner than this (a millionth of the tolerance) is the rounding of
# two edges that coincide (the blade finishing the part's wall, 1e-13 to 1e-11 thick as far as 65 m
# from the origin), not a cut whose sides to look at: in 2000 CYCLE93 calls along a bar, a fourth of the
# ops sent such a residue to the exact measure (1.4 ms each), as many as their rounding fell that way
RESIDUE = 1e-9


@dataclass
class Gouge:
    """A gouge: the area of it deeper than the tolerance, its depth, its deepest point (x, z), where it is."""

    area: float
    depth: float
    at: tuple[float, float]
    rows: Flat  # on the window's columns


def hinted(cut: Flat, grid: Grid, edges: Edges, tol: float) -> Flat:
    """The rows of ``cut`` whose column may hold a gouge deeper than tol:
    some of it farther than tol from the part's edges on the column's centre
    line (where the model is exact), or, in a column narrower than NARROW (a
    sliver beside a wall, deepest at the column's side), on a side line
    (there only the rows thicker than RESIDUE)."""
    cols = np.unique(cut[0])
    segments = edges.near(float(grid.edges[cols[0]]) - tol, float(grid.edges[cols[-1] + 1]) + tol)
    deep = np.zeros(len(grid), dtype=bool)
    narrow = grid.widths < NARROW
    sides = col.select(cut, narrow[cut[0]] & (col.lengths(cut) > RESIDUE))
    side_cols = np.unique(sides[0])
    # the capsules on the lines of the rows' own columns only
    for lines, rows, used in ((grid.centres, cut, cols), (grid.edges[:-1], sides, side_cols),
                              (grid.edges[1:], sides, side_cols)):
        if len(rows[0]):
            near, lo, hi = capsule_rows(lines[used], segments, tol)
            core = col.combine(rows, (used[near], lo, hi), DIFFERENCE)
            deep[core[0][col.lengths(core) > 0]] = True
    return col.select(cut, deep[cut[0]])


def _lines(cols: np.ndarray, grid: Grid) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The lines a gouge is measured on: SUBLINES across each column (each
    weighing a SUBLINES-th of its width) and the column's two sides (weighing
    nothing: where a wall bounds a sliver its deepest point lies): (z, the
    column of each, weight), sorted by z."""
    offsets = (np.arange(SUBLINES) + 0.5) / SUBLINES
    sub = grid.edges[cols][:, None] + offsets[None, :] * grid.widths[cols][:, None]
    z = np.concatenate([sub.ravel(), grid.edges[cols], grid.edges[cols + 1]])
    owner = np.concatenate([np.repeat(cols, SUBLINES), cols, cols])
    weight = np.concatenate([np.repeat(grid.widths[cols] / SUBLINES, SUBLINES), np.zeros(2 * len(cols))])
    order = np.argsort(z, kind="stable")
    return z[order], owner[order], weight[order]


def measure_gouge(cut: Flat, before: Flat, feeds: Sequence[FeedPath], part: Shape, edges: Edges, grid: Grid,
                  tol: float) -> Optional[Gouge]:
    """The gouge ``cut`` (the model's removed part, rows on ``grid``) hints
    at, measured exactly on lines across its columns: what the feeds sweep
    there (in closed form), inside the part (its rings) and the material
    standing before; its part farther than ``tol`` from the part's edges
    (capsules about them), its deepest point. None when no part of it is
    deeper than tol (the model's columns only hinted)."""
    cols = np.unique(cut[0])
    z, owner, weight = _lines(cols, grid)
    swept = [swept_rows(z, f.tool, f.plunge, f.starts, f.ends)[0] for f in feeds if len(f.starts)]
    if not swept:
        return None
    removed = col.combine((np.concatenate([r[0] for r in swept]), np.concatenate([r[1] for r in swept]),
                           np.concatenate([r[2] for r in swept])), col.empty_flat(), UNION)
    lo, hi = col.pack(len(grid), before)
    standing = col.flat(lo[owner], hi[owner])
    local = part.clipped(float(z[0]) - 1.0, float(z[-1]) + 1.0)
    inside = col.combine(col.combine(removed, local.rows(z), INTERSECTION), standing, INTERSECTION)
    if not len(inside[0]):
        return None
    segments = edges.near(float(z[0]) - tol, float(z[-1]) + tol)
    core = col.combine(inside, capsule_rows(z, segments, tol), DIFFERENCE)
    amount = float(np.sum(col.lengths(core) * weight[core[0]]))
    if amount <= NOISE_AREA:
        return None
    line, a, b = inside
    points = np.concatenate([np.column_stack([z[line], x]) for x in (a, 0.5 * (a + b), b)])
    reach = float(z[-1] - z[0]) + float(np.max(b) - np.min(a)) + 1.0
    depth = distances(points, edges.near(float(z[0]) - reach, float(z[-1]) + reach))
    best = int(np.argmax(depth))
    rows = col.combine((owner[core[0]], core[1], core[2]), col.empty_flat(), UNION)
    return Gouge(amount, float(depth[best]), (float(points[best, 1]), float(points[best, 0])), rows)


def _slopes(rows: Flat, centres: np.ndarray, end: int) -> np.ndarray:
    """At each row's end ``end`` (1: lo, 2: hi), how steeply that end runs to
    the same end of the nearest interval in the columns beside it (|dx/dz|,
    the steeper side; 0 where a neighbour holds nothing)."""
    lo, hi = col.pack(len(centres), rows)
    ends = lo if end == 1 else hi
    cols, value = rows[0], rows[end]
    steepest = np.zeros(len(cols))
    for offset in (-1, 1):
        other = cols + offset
        inside = (other >= 0) & (other < len(centres))
        other = np.clip(other, 0, len(centres) - 1)
        near = ends[other]
        gap = np.where(np.isfinite(near), np.abs(near - value[:, None]), np.inf)
        k = np.argmin(gap, axis=1)
        found = inside & np.isfinite(gap[np.arange(len(cols)), k])
        run = np.abs(centres[other] - centres[cols])
        slope = np.where(found, gap[np.arange(len(cols)), k] / np.where(run > 0, run, 1.0), 0.0)
        steepest = np.maximum(steepest, slope)
    return steepest


def thicker_than(left: Flat, standing: Flat, grid: Grid, tol: float) -> bool:
    """Does some of ``left`` lie farther than ``tol`` from everything not
    ``standing`` (the column model's depth_inside)? Along X, each end of a
    standing interval is taken in by tol measured square to the edge it lies
    on (its slope from the columns beside it); across, a column's centre lies
    half its width from its sides, and a column narrower than 2 tol counts
    only what its neighbours hold as well."""
    widths = grid.widths
    cols, lo, hi = standing
    lo_in = lo + tol * np.sqrt(1.0 + _slopes(standing, grid.centres, 1) ** 2)
    hi_in = hi - tol * np.sqrt(1.0 + _slopes(standing, grid.centres, 2) ** 2)
    eroded = col.select((cols, lo_in, hi_in), lo_in < hi_in)
    narrow = widths < 2 * tol
    if narrow.any():
        n = len(widths)
        keep = narrow[eroded[0]]
        wide, thin = col.select(eroded, ~keep), col.select(eroded, keep)
        for offset in (1, -1):
            moved = col.shifted(eroded, offset)
            inside = (moved[0] >= 0) & (moved[0] < n)
            moved = col.select(moved, inside)
            thin = col.combine(thin, col.select(moved, narrow[moved[0]]), INTERSECTION)
        eroded = col.combine(wide, thin, UNION)
    return col.area(col.combine(left, eroded, INTERSECTION), widths) > NOISE_AREA
