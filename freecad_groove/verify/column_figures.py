"""The distances the column model's check reports: how deep a gouge reaches
into the part (to the exact edges of the part's rings), the part of it deeper
than the tolerance, and whether material left standing is thicker than it.

Rows are flat intervals along X on a window's columns (columns.Flat).
"""

from __future__ import annotations

import numpy as np

from . import columns as col
from .columns import DIFFERENCE, INTERSECTION, UNION, Flat, Grid
from .shapes import Edges, capsule_rows, distances

NOISE_AREA = 1e-10  # mm^2, as overlay.NOISE_AREA
SUBLINES = 4  # lines per column the part of a gouge deeper than the tolerance is measured on
NARROW = 0.005  # mm: in columns narrower than this a gouge's depth is also measured at the column's sides


def _near(rows: Flat, grid: Grid, edges: Edges, margin: float) -> np.ndarray:
    cols = rows[0]
    return edges.near(float(grid.edges[cols.min()]) - margin, float(grid.edges[cols.max() + 1]) + margin)


def deepest(rows: Flat, grid: Grid, edges: Edges) -> tuple[float, tuple[float, float]]:
    """(the largest distance of a point of ``rows`` from the part's edges, that point (x, z))."""
    cols, lo, hi = rows
    zmin, zmax = grid.edges[cols.min()], grid.edges[cols.max() + 1]
    reach = (zmax - zmin) + float(np.max(hi) - np.min(lo)) + 1.0
    segments = _near(rows, grid, edges, reach)
    zs = [grid.centres[cols]]
    narrow = grid.widths[cols] <= NARROW
    if narrow.any():
        zs += [np.where(narrow, grid.edges[cols], np.nan), np.where(narrow, grid.edges[cols + 1], np.nan)]
    points = [np.column_stack([z, x]) for z in zs for x in (lo, 0.5 * (lo + hi), hi)]
    points = np.concatenate(points)
    points = points[np.isfinite(points[:, 0])]
    depth = distances(points, segments)
    best = int(np.argmax(depth))
    return float(depth[best]), (float(points[best, 1]), float(points[best, 0]))


def deeper_than(rows: Flat, grid: Grid, edges: Edges, tol: float) -> tuple[Flat, float]:
    """The part of ``rows`` farther than ``tol`` from the part's edges: (its
    rows, each column's union of SUBLINES lines; its area, the lines' mean)."""
    cols, lo, hi = rows
    line_col = np.repeat(cols, SUBLINES)
    offsets = (np.tile(np.arange(SUBLINES), len(cols)) + 0.5) / SUBLINES
    lines = grid.edges[line_col] + offsets * grid.widths[line_col]
    segments = _near(rows, grid, edges, tol)
    index = np.arange(len(lines))
    core = col.combine((index, np.repeat(lo, SUBLINES), np.repeat(hi, SUBLINES)),
                       capsule_rows(lines, segments, tol), DIFFERENCE)
    amount = float(np.sum(col.lengths(core) * grid.widths[line_col[core[0]]])) / SUBLINES
    merged = col.combine((line_col[core[0]], core[1], core[2]), col.empty_flat(), UNION)
    return merged, amount


def thicker_than(left: Flat, standing: Flat, widths: np.ndarray, tol: float) -> bool:
    """Does some of ``left`` lie farther than ``tol`` from everything not
    ``standing`` (the column model's depth_inside)? Along X exactly; across,
    a column's centre lies half its width from its sides, and a column
    narrower than 2 tol counts only what its neighbours hold as well."""
    cols, lo, hi = standing
    eroded = col.select((cols, lo + tol, hi - tol), lo + tol < hi - tol)
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
