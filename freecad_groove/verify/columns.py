"""The column model of the half section: material as radial intervals per
axial column, exact along the radius (numpy only: FreeCAD ships it).

A ``Grid`` parts the Z axis into columns (edges increasing, widths free: fine
where a blade cuts, a column edge at every Z where a wall stands: a blade's
side at each move's end, a vertex of the stock, the part or a groove, so that a
vertical wall never lies inside a column). In each column the material is a
set of disjoint intervals along the other axis, sampled at the column's centre:
exact for every edge that is straight across the column (the midpoint rule
integrates a linear edge exactly), within h^2 of a curved one.

Interval sets are held two ways: *padded* (arrays lo, hi of shape (columns,
K), empty slots +inf in both; the stock, updated in place one slice at a
time) and *flat* (cols, lo, hi: one row per interval, sorted by column then
lo; what the Boolean operations take and give). ``combine`` is the one
Boolean operation: a sweep over the intervals' ends, all columns at once.
The same code runs on a transposed grid (columns along X, intervals along Z)
for a face groove's reach.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from functools import cached_property

import numpy as np

EMPTY_SLOT = np.inf
EDGE_MERGE = 1e-9  # mm: column edges closer than this are one edge
UNION, INTERSECTION, DIFFERENCE = "union", "intersection", "difference"

Flat = tuple[np.ndarray, np.ndarray, np.ndarray]  # (cols, lo, hi)


@dataclass(frozen=True)
class Grid:
    """Columns between consecutive ``edges`` (increasing)."""

    edges: np.ndarray

    @cached_property
    def centres(self) -> np.ndarray:
        return 0.5 * (self.edges[1:] + self.edges[:-1])

    @cached_property
    def widths(self) -> np.ndarray:
        return np.diff(self.edges)

    def __len__(self) -> int:
        return len(self.edges) - 1

    def span(self, lo: float, hi: float) -> tuple[int, int]:
        """[i0, i1): the columns whose centres lie in [lo, hi]."""
        return int(np.searchsorted(self.centres, lo, "left")), int(np.searchsorted(self.centres, hi, "right"))

    def part(self, i0: int, i1: int) -> Grid:
        return Grid(self.edges[i0:i1 + 1])


def graded(at: Iterable[float], reach: float, steps: int) -> np.ndarray:
    """Edges on both sides of each value of ``at``, ever closer to it (a
    square law): the columns beside a wall where a corner arc meets it."""
    at = np.asarray(list(at), dtype=float)
    if reach <= 0 or not len(at):
        return np.empty(0)
    offsets = reach * (np.arange(1, steps + 1) / steps) ** 2
    return (at[:, None] + np.concatenate([offsets, -offsets])[None, :]).ravel()


def make_grid(breaks: Iterable[float], fine: Sequence[tuple[float, float]], step: float,
              coarse: float) -> Grid:
    """Edges at ``breaks``, every ``step`` within the ``fine`` ranges, every
    ``coarse`` elsewhere between the outermost of them."""
    pieces = [np.asarray(list(breaks), dtype=float)]
    for lo, hi in _merged(fine):
        count = int(np.ceil((hi - lo) / step)) + 1
        pieces.append(lo + step * np.arange(count + 1))
    edges = np.concatenate(pieces)
    edges = edges[np.isfinite(edges)]
    lo, hi = float(edges.min()), float(edges.max())
    if coarse > 0 and hi > lo:
        pieces.append(lo + coarse * np.arange(int(np.ceil((hi - lo) / coarse)) + 1))
        edges = np.concatenate(pieces)
    edges = np.unique(edges[np.isfinite(edges)])
    keep = np.ones(len(edges), dtype=bool)
    keep[1:] = np.diff(edges) > EDGE_MERGE
    return Grid(edges[keep])


def _merged(ranges: Sequence[tuple[float, float]]) -> list[tuple[float, float]]:
    out: list[list[float]] = []
    for lo, hi in sorted((min(a, b), max(a, b)) for a, b in ranges):
        if out and lo <= out[-1][1]:
            out[-1][1] = max(out[-1][1], hi)
        else:
            out.append([lo, hi])
    return [(a, b) for a, b in out]


# ---------------------------------------------------------------- padded and flat interval sets


def empty_padded(n: int, k: int = 1) -> tuple[np.ndarray, np.ndarray]:
    return np.full((n, k), EMPTY_SLOT), np.full((n, k), EMPTY_SLOT)


def flat(lo: np.ndarray, hi: np.ndarray) -> Flat:
    """The padded set as flat rows (sorted by column, then lo)."""
    cols, slots = np.nonzero(lo < hi)
    return cols, lo[cols, slots], hi[cols, slots]


def empty_flat() -> Flat:
    return np.empty(0, dtype=np.int64), np.empty(0), np.empty(0)


def pack(n: int, rows: Flat) -> tuple[np.ndarray, np.ndarray]:
    """Flat rows (sorted by column, then lo) as a padded set of n columns."""
    cols, lo, hi = rows
    if not len(cols):
        return empty_padded(n)
    counts = np.bincount(cols, minlength=n)
    first = np.cumsum(counts) - counts
    slot = np.arange(len(cols)) - first[cols]
    out_lo, out_hi = empty_padded(n, max(1, int(counts.max())))
    out_lo[cols, slot] = lo
    out_hi[cols, slot] = hi
    return out_lo, out_hi


def combine(a: Flat, b: Flat, op: str) -> Flat:
    """a op b (UNION, INTERSECTION, DIFFERENCE), column by column, as flat
    rows sorted by column then lo; touching intervals are merged, empty ones
    dropped. a and b need not be sorted, and their intervals may overlap."""
    ca, la, ha = a
    cb, lb, hb = b
    keep_a, keep_b = la < ha, lb < hb
    ca, la, ha, cb, lb, hb = ca[keep_a], la[keep_a], ha[keep_a], cb[keep_b], lb[keep_b], hb[keep_b]
    na, nb = len(ca), len(cb)
    if na + nb == 0:
        return empty_flat()
    cols = np.concatenate([ca, ca, cb, cb])
    xs = np.concatenate([la, ha, lb, hb])
    da = np.concatenate([np.ones(na, np.int64), -np.ones(na, np.int64), np.zeros(2 * nb, np.int64)])
    db = np.concatenate([np.zeros(2 * na, np.int64), np.ones(nb, np.int64), -np.ones(nb, np.int64)])
    order = np.lexsort((xs, cols))
    cols, xs = cols[order], xs[order]
    in_a, in_b = np.cumsum(da[order]) > 0, np.cumsum(db[order]) > 0
    last = np.ones(len(cols), dtype=bool)  # the state after all the events at one (column, x)
    last[:-1] = (cols[1:] != cols[:-1]) | (xs[1:] != xs[:-1])
    cols, xs, in_a, in_b = cols[last], xs[last], in_a[last], in_b[last]
    if op == UNION:
        inside = in_a | in_b
    elif op == INTERSECTION:
        inside = in_a & in_b
    elif op == DIFFERENCE:
        inside = in_a & ~in_b
    else:
        raise ValueError("unknown operation %r" % (op,))
    before = np.zeros(len(inside), dtype=bool)
    before[1:] = inside[:-1] & (cols[1:] == cols[:-1])
    starts, stops = inside & ~before, ~inside & before
    return cols[starts], xs[starts], xs[stops]


def union_per_column(rows: Flat) -> Flat:
    """The union of many rows per column (sorted), fast where a column's
    intervals share a point (its union is then one interval: the smallest lo
    to the largest hi); the other columns through ``combine``."""
    cols, lo, hi = rows
    if not len(cols):
        return rows
    base = int(cols.min())
    c = cols - base
    n = int(c.max()) + 1
    lo_min, lo_max = np.full(n, np.inf), np.full(n, -np.inf)
    hi_min, hi_max = np.full(n, np.inf), np.full(n, -np.inf)
    np.minimum.at(lo_min, c, lo)
    np.maximum.at(lo_max, c, lo)
    np.minimum.at(hi_min, c, hi)
    np.maximum.at(hi_max, c, hi)
    simple = np.isfinite(lo_min) & (lo_max <= hi_min)
    one = np.nonzero(simple)[0]
    out = (one + base, lo_min[one], hi_max[one])
    rest = select(rows, ~simple[c])
    return combine(out, rest, UNION) if len(rest[0]) else out


def lengths(rows: Flat) -> np.ndarray:
    return rows[2] - rows[1]


def area(rows: Flat, widths: np.ndarray) -> float:
    return float(np.sum((rows[2] - rows[1]) * widths[rows[0]])) if len(rows[0]) else 0.0


def shifted(rows: Flat, offset: int) -> Flat:
    return rows[0] + offset, rows[1], rows[2]


def select(rows: Flat, keep: np.ndarray) -> Flat:
    return rows[0][keep], rows[1][keep], rows[2][keep]


def grown(rows: Flat, by: float) -> Flat:
    """Each interval longer by ``by`` at both ends (merged)."""
    return combine((rows[0], rows[1] - by, rows[2] + by), empty_flat(), UNION)


# ---------------------------------------------------------------- shapes on columns


def ring_rows(rings: Sequence[np.ndarray], centres: np.ndarray) -> Flat:
    """The region the closed rings of (column axis, interval axis) points
    enclose (even-odd) on the columns at ``centres``: each column's
    crossings with the edges, paired."""
    rings_closed = [np.vstack([r, r[:1]]) if np.any(r[0] != r[-1]) else r
                    for r in (np.asarray(ring, dtype=float) for ring in rings) if len(r) >= 3]
    if not rings_closed or not len(centres):
        return empty_flat()
    p0 = np.concatenate([r[:-1] for r in rings_closed])
    p1 = np.concatenate([r[1:] for r in rings_closed])
    slanted = p0[:, 0] != p1[:, 0]
    p0, p1 = p0[slanted], p1[slanted]
    zlo, zhi = np.minimum(p0[:, 0], p1[:, 0]), np.maximum(p0[:, 0], p1[:, 0])
    i0 = np.searchsorted(centres, zlo, "left")  # a column counts an edge when zlo <= centre < zhi
    i1 = np.searchsorted(centres, zhi, "left")
    counts = i1 - i0
    total = int(counts.sum())
    if not total:
        return empty_flat()
    edge = np.repeat(np.arange(len(p0)), counts)
    cols = i0[edge] + (np.arange(total) - (np.cumsum(counts) - counts)[edge])
    t = (centres[cols] - p0[edge, 0]) / (p1[edge, 0] - p0[edge, 0])
    xs = p0[edge, 1] + t * (p1[edge, 1] - p0[edge, 1])
    order = np.lexsort((xs, cols))
    cols, xs = cols[order], xs[order]
    base = int(cols[0])  # (counted over the columns the rings cross only: a ring's cost is its own)
    odd = np.bincount(cols - base) % 2 == 1  # a crossing lost to rounding at a vertex: the column is dropped
    if odd.any():
        keep = ~odd[cols - base]
        cols, xs = cols[keep], xs[keep]
    return _joined(cols[0::2], xs[0::2], xs[1::2])


def _joined(cols: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> Flat:
    """Sorted disjoint rows with the touching ones joined and the empty ones dropped (the crossings of
    rings, paired: an interval may end where the next begins, at a vertex on a column's line)."""
    keep = lo < hi
    cols, lo, hi = cols[keep], lo[keep], hi[keep]
    if not len(cols):
        return empty_flat()
    first = np.ones(len(cols), dtype=bool)
    first[1:] = (cols[1:] != cols[:-1]) | (lo[1:] > hi[:-1])
    last = np.ones(len(cols), dtype=bool)
    last[:-1] = first[1:]
    return cols[first], lo[first], hi[last]


def convex_rows(normals: np.ndarray, support: np.ndarray, centres: np.ndarray,
                which: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """(lo, hi) of a convex region given by half-planes (normals (m, 2) in
    (column axis, interval axis), support (m,): n . p <= s) on the columns at
    ``centres``; lo >= hi where it misses a column. With ``which`` (an index
    per centre), normals (k, m, 2) and support (k, m) hold k regions and
    centre i meets region which[i]."""
    if which is None:
        normals, support, which = normals[None], support[None], np.zeros(len(centres), dtype=np.int64)
    nz, nx = normals[which, :, 0], normals[which, :, 1]
    rhs = support[which] - centres[:, None] * nz
    up, down = nx > 1e-12, nx < -1e-12
    with np.errstate(divide="ignore", invalid="ignore"):
        bound = rhs / nx
    hi = np.min(np.where(up, bound, np.inf), axis=1)
    lo = np.max(np.where(down, bound, -np.inf), axis=1)
    outside = np.any(~(up | down) & (rhs < 0), axis=1)
    lo[outside], hi[outside] = np.inf, np.inf
    return lo, hi
