"""Material-removal simulation: run expanded moves through the stock.

FEED moves remove the area the blade sweeps, arcs (G2/G3) too, as chords
within arcs.SWEEP_TOL of them; a RAPID is checked against the
stock still standing at that moment; a DWELL removes nothing and must be where
the tool is. Tool positions are (x, z) like ``moves.Move``, x the radius; the
stock and everything derived from it are shapely (z, x).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Optional

import numpy as np
import shapely
from shapely import Geometry

from freecad_groove.engine.moves import ARCS, DWELL, FEED, RAPID, GroovingTool, Move

from .arcs import straightened
from .blade import ARC_EXCESS, outline_at_origin
from .overlay import difference, intersection, union_all

# A rapid is a collision when its swept area, shrunk by RAPID_SKIN (mm: the
# arcs' excess plus rounding), overlaps standing stock by more than
# RAPID_AREA_TOL mm^2. A rapid may touch the stock, not enter it.
RAPID_SKIN = ARC_EXCESS + 1e-5
RAPID_AREA_TOL = 1e-9

Point = tuple[float, float]  # (x, z), x the radius
Segment = tuple[int, Point, Point, bool]  # (index of the move, start, end, a rapid); an arc is several


@dataclass
class RapidCollision:
    index: int  # position of the move in the move list
    move: Move
    start: Point  # (x, z) before the move
    area: float  # mm^2 of standing stock inside the swept area
    region: Geometry | None = None  # the overlap (shapely, (z, x))

    def describe(self) -> str:
        zmin, xmin, zmax, xmax = self.region.bounds
        text = (
            "rapid #%d %s X(radius)%.4f Z%.4f -> X%.4f Z%.4f hits stock:"
            " %.6g mm^2 in Z[%.4f, %.4f] X[%.4f, %.4f]"
        )
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
    position: Point  # (x, z) the tool is actually at

    def describe(self) -> str:
        return "dwell #%d says X%.4f Z%.4f but the tool is at X%.4f Z%.4f" % (
            self.index,
            self.move.x,
            self.move.z,
            self.position[0],
            self.position[1],
        )


@dataclass
class SimulationResult:
    stock: Geometry  # the original stock
    remaining: Geometry  # stock still standing after the program
    removed: Geometry  # stock minus remaining
    rapid_collisions: list[RapidCollision]
    dwell_mismatches: list[DwellMismatch]
    final: Point  # (x, z) tool position after the last move
    tool: GroovingTool | None = None
    plunge: str | None = None


def _check_coords(i: int, move: Move) -> None:
    values = (move.x, move.z) + (tuple(move.centre) if move.kind in ARCS and move.centre is not None else ())
    if not all(math.isfinite(value) for value in values):
        raise ValueError("move #%d %r has a non-finite coordinate" % (i, move))


def _walk(moves: list[Move], start: Point) -> tuple[list[Segment], list[DwellMismatch], Point]:
    """Follow the moves from ``start``: the segments the tool sweeps (rapids,
    feeds, the chords of arcs), the dwells that are not where the tool is (by
    more than 1e-9), and the final position."""
    pos = (float(start[0]), float(start[1]))
    segments = []
    dwell_mismatches = []
    for i, m in enumerate(moves):
        _check_coords(i, m)
        if m.kind not in (RAPID, FEED, DWELL) and m.kind not in ARCS:
            raise ValueError("move #%d has unknown kind %r" % (i, m.kind))
    for i, m in straightened(moves, pos):
        if m.kind in (RAPID, FEED):
            end = (float(m.x), float(m.z))
            segments.append((i, pos, end, m.kind == RAPID))
            pos = end
        elif abs(m.x - pos[0]) > 1e-9 or abs(m.z - pos[1]) > 1e-9:
            dwell_mismatches.append(DwellMismatch(i, m, pos))
    return segments, dwell_mismatches, pos


def _swept_hulls(segments: list[Segment], base: np.ndarray) -> list[Geometry]:
    """The area each segment sweeps: the convex hull of the outline ``base``
    at both ends, all segments in one vectorised call."""
    if not segments:
        return []
    nb = len(base)
    ends = np.empty((len(segments), 2 * nb, 2))
    for k, (_, a, b, _rapid) in enumerate(segments):
        ends[k, :nb] = base + (a[1], a[0])
        ends[k, nb:] = base + (b[1], b[0])
    indices = np.repeat(np.arange(len(segments)), 2 * nb)
    points = shapely.multipoints(ends.reshape(-1, 2), indices=indices)
    return list(shapely.convex_hull(points))


def _flush(remaining: Geometry, pending: list[Geometry]) -> Geometry:
    """remaining less the feeds' swept areas collected since the last rapid."""
    if pending:
        cut = union_all(pending)
        remaining = difference(remaining, cut)
    return remaining


def _rapid_overlap(hull: Geometry, remaining: Geometry, rapid_skin: float) -> Geometry | None:
    """The standing stock inside a rapid's swept area shrunk by rapid_skin
    (None when they do not meet)."""
    hull = hull.buffer(-rapid_skin, join_style="mitre") if rapid_skin > 0 else hull
    if hull.intersects(remaining):
        return intersection(hull, remaining)
    return None


def _cut(
    moves: list[Move],
    segments: list[Segment],
    hulls: list[Geometry],
    stock: Geometry,
    rapid_area_tol: float,
    rapid_skin: float,
    attached: Optional[Callable[[Geometry], Geometry]] = None,
) -> tuple[Geometry, list[RapidCollision]]:
    """Remove the feeds' swept areas from ``stock`` in program order, checking
    each rapid against the stock standing when it runs (``attached`` of it:
    see simulate). Returns the stock left and the rapid collisions."""
    remaining = stock
    pending = []
    collisions = []
    for (i, start, _end, is_rapid), hull in zip(segments, hulls):
        if not is_rapid:
            pending.append(hull)
            continue
        remaining = _flush(remaining, pending)
        pending = []
        standing = remaining if attached is None else attached(remaining)
        hit = _rapid_overlap(hull, standing, rapid_skin)
        if hit is not None and hit.area > rapid_area_tol:
            collisions.append(RapidCollision(i, moves[i], start, hit.area, hit))
    return _flush(remaining, pending), collisions


def simulate(
    moves: Iterable[Move],
    tool: GroovingTool,
    plunge: str,
    start: Point,
    stock: Geometry,
    rapid_area_tol: float = RAPID_AREA_TOL,
    rapid_skin: float = RAPID_SKIN,
    attached: Optional[Callable[[Geometry], Geometry]] = None,
) -> SimulationResult:
    """Run ``moves`` (moves.Move, x radius) with ``tool`` plunging in ``plunge``
    from ``start`` = (x, z) through ``stock`` (shapely (z, x) Polygon/MultiPolygon).

    FEED moves remove the area the tool sweeps (the convex hull of the tool
    outline at both ends: exact for a straight move of a convex tool), arcs
    ARC_CW/ARC_CCW the areas of their chords (arcs.straightened). A
    RAPID whose swept area, shrunk by ``rapid_skin`` mm, overlaps the stock
    still standing at that moment by more than ``rapid_area_tol`` mm^2 is
    recorded. DWELL removes nothing; a dwell whose x, z differ from the tool
    position by more than 1e-9 is recorded as a dwell mismatch.
    ``attached`` (optional) gives the part of the standing stock a rapid is
    checked against: what is still held (a piece cut off has fallen away).
    """
    moves = list(moves)
    base = outline_at_origin(tool, plunge)
    segments, dwell_mismatches, final = _walk(moves, start)
    hulls = _swept_hulls(segments, base)
    remaining, collisions = _cut(moves, segments, hulls, stock, rapid_area_tol, rapid_skin, attached)
    removed = difference(stock, remaining)
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
