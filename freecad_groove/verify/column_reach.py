"""Where a blade can cut a target the way a grooving cycle does, on columns
along its plunge axis (numpy only): the column model's reach.

The blade never turns and comes from behind its front edge (the retract
direction); in the *frame* of a plunge the columns run across the blade and
the values grow toward the blade's back, so the blade comes from above. A
column is open from level F up when nothing but target and air lies above F
and the target reaches down to F (the air straight behind the target is the
only way in: reach.reachable_region's column); a column without target is
open above the part in it (a blade may overhang the groove's opening where
the contour falls away beside it, as tests/blade_oracle.py and
cycle93_reach let it; a column of air holds it nowhere). A blade placed
with its reference corner at column position p sits no lower than
y(p) = max over the columns it covers of F - L (L the lower side of its
outline there); the lowest level it reaches in a column is
g = min over the placements covering it of y(p) + L. The target below g is
what no placement reaches (cycle93_reach defines the same on the exact
profile). Placements stand with a side on every column edge: flush with
every wall, as the grid has an edge at every wall.
"""

from __future__ import annotations

import numpy as np

from freecad_groove.engine.moves import MINUS_X, MINUS_Z, PLUS_X, PLUS_Z, GroovingTool

from . import columns as col
from .columns import DIFFERENCE, UNION, Flat, Grid
from .outline import lower_chain, outline_at_origin
from .shapes import Shape

SEAM = 1e-6  # mm: part thinner than this along a column is rounding, not a wall

# plunge: (columns along X (transposed), the sign that makes the blade's back "up")
FRAMES = {MINUS_X: (False, 1.0), PLUS_X: (False, -1.0), MINUS_Z: (True, 1.0), PLUS_Z: (True, -1.0)}


def _signed(rows: Flat, sign: float) -> Flat:
    if sign > 0:
        return rows
    return col.combine((rows[0], -rows[2], -rows[1]), col.empty_flat(), UNION)


def frame_unreachable(grid: Grid, target: Flat, solid: Flat, outline: np.ndarray) -> Flat:
    """The target (frame rows on ``grid``) that no placement of the blade
    (``outline``: frame points) reaches without entering ``solid``."""
    if not len(target[0]):
        return col.empty_flat()
    width = float(np.ptp(np.asarray(outline)[:, 0]))
    a = max(0, int(np.searchsorted(grid.edges, grid.edges[target[0].min()] - width, "right")) - 2)
    b = min(len(grid), int(np.searchsorted(grid.edges, grid.edges[target[0].max() + 1] + width, "left")) + 2)
    if a > 0 or b < len(grid):  # only the columns a blade over the target covers
        inside = (solid[0] >= a) & (solid[0] < b)
        local = frame_unreachable(grid.part(a, b), col.shifted(target, -a),
                                  col.shifted(col.select(solid, inside), -a), outline)
        return col.shifted(local, a)
    n = len(grid)
    c, edges = grid.centres, grid.edges
    # where the target's top runs along the part's surface the two agree only to rounding: the sliver of
    # part left above the target would close its column (blade_oracle grows the target by a seam likewise)
    solid = col.select(solid, solid[2] - solid[1] > SEAM)
    top = np.full(n, -np.inf)
    np.maximum.at(top, solid[0], solid[2])
    floor = np.full(n, np.inf)
    np.minimum.at(floor, target[0], target[1])
    level = np.where(np.isfinite(floor), np.maximum(top, floor), top)
    chain = lower_chain(outline)
    omin, omax = chain[0, 0], chain[-1, 0]
    pos = np.concatenate([edges - omin, edges - omax])
    pos = pos[(pos + omin >= edges[0] - 1e-12) & (pos + omax <= edges[-1] + 1e-12)]
    j0 = np.searchsorted(c, pos + omin, "left")
    j1 = np.searchsorted(c, pos + omax, "right")
    if not len(pos) or int(np.max(j1 - j0)) <= 0:
        return target
    cover = j0[:, None] + np.arange(int(np.max(j1 - j0)))[None, :]
    inside = cover < j1[:, None]
    cover = np.minimum(cover, n - 1)
    under = np.interp(c[cover] - pos[:, None], chain[:, 0], chain[:, 1])
    lowest = np.max(np.where(inside, level[cover] - under, -np.inf), axis=1)
    usable = inside & (np.isfinite(lowest) & (j1 > j0))[:, None]
    reach = np.full(n, np.inf)
    np.minimum.at(reach, cover[usable], (lowest[:, None] + under)[usable])
    open_cols = np.nonzero(np.isfinite(reach))[0]
    return col.combine(target, (open_cols, reach[open_cols], np.full(len(open_cols), np.inf)), DIFFERENCE)


def unreachable_across(grid: Grid, target: Flat, solid: Flat, tool: GroovingTool, plunge: str) -> Flat:
    """An X plunge's unreachable target on the main grid (rows along X)."""
    _transposed, sign = FRAMES[plunge]
    outline = np.asarray(outline_at_origin(tool, plunge)) * (1.0, sign)
    return _signed(frame_unreachable(grid, _signed(target, sign), _signed(solid, sign), outline), sign)


def unreachable_along(grid: Grid, target: Shape, part: Shape, tool: GroovingTool, plunge: str,
                      step: float) -> Flat:
    """A Z plunge's unreachable target, found on a grid of columns along X
    over the target (``step`` apart, an edge at every vertex) and returned
    on the main ``grid`` (columns along Z): each of its rows a rectangle (grown by its width along X)."""
    _transposed, sign = FRAMES[plunge]
    outline = np.asarray(outline_at_origin(tool, plunge))[:, ::-1] * (1.0, sign)
    verts = target.vertices()
    if not len(verts):
        return col.empty_flat()
    width = float(np.ptp(outline[:, 0]))
    r = float(tool.corner_radius)
    xlo, xhi = verts[:, 1].min() - width - step, verts[:, 1].max() + width + step
    across = col.make_grid(np.concatenate([verts[:, 1], verts[:, 1] - width, verts[:, 1] + width,
                                           col.graded(verts[:, 1], r, 12), [xlo, xhi]]), [(xlo, xhi)], step / 2, 0.0)
    t = target.rows(across.centres, transposed=True)
    s = col.combine(part.rows(across.centres, transposed=True), t, DIFFERENCE)
    rows = _signed(frame_unreachable(across, _signed(t, sign), _signed(s, sign), outline), sign)
    if not len(rows[0]):
        return rows
    i0 = np.searchsorted(grid.centres, rows[1], "left")
    i1 = np.searchsorted(grid.centres, rows[2], "right")
    counts = np.maximum(i1 - i0, 0)
    which = np.repeat(np.arange(len(i0)), counts)
    cols = i0[which] + (np.arange(int(counts.sum())) - (np.cumsum(counts) - counts)[which])
    row_cols = rows[0][which]
    # each row a rectangle a row wider on both sides: the rows step along X, and the unreachable
    # part excuses what the blade leaves; a staircase inside the true edge would not excuse all of it
    grow = across.widths[row_cols]
    return col.combine((cols, across.edges[row_cols] - grow, across.edges[row_cols + 1] + grow), col.empty_flat(),
                       UNION)
