"""The blade's holder in the turning check: a holder entering standing material is a collision, reported like a
gouge, naming the op and the move.

The holder (``Holder``): beyond the blade's free reach (``reach``, mm from the cutting edge along the blade:
the tool bit's CuttingEdgeHeight, the tool table's reach field) a block ``width`` wide across the blade, centred
on it (the tool bit's HolderWidth, the tool table's ``holder=``), HOLDER_LENGTH long. Where the blade cuts, its
own body goes; the holder's sides stand beside it, and a groove deeper than the reach brings them into the
part's surface beside the groove.

Each move (feeds and rapids, arcs as their chords) sweeps the holder's box; the material it meets is the material
standing when the move runs: what stood before the op less what the blade swept in the op's feeds up to that
move (the blade cuts ahead of its holder). A sweep meeting more than AREA_TOL mm^2 is a hit. Only the moves whose
holder sweep meets the material standing before the op are followed move by move. A piece cut free is not
taken away here (the holder that reaches it has already met the part beside the cut).

numpy only, on the column model's public functions (columns.combine, column_sweep.swept_rows).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any, Optional

import numpy as np

from freecad_groove.engine.moves import MINUS_X, MINUS_Z, PLUS_X, PLUS_Z, GroovingTool

from . import columns as col
from .column_sweep import blade_box, straight_segments, swept_rows
from .columns import DIFFERENCE, INTERSECTION, UNION, Flat, Grid
from .shapes import EMPTY_SECTION, Section

Point = tuple[float, float]  # (x, z), x the radius
HOLDER_LENGTH = 100.0  # mm of holder drawn behind the reach
AREA_TOL = 1e-6  # mm^2 of standing material the holder's sweep may graze (rounding at a wall it slides along)


@dataclass(frozen=True)
class Holder:
    """The blade's holder: from ``reach`` (mm from the cutting edge) back, ``width`` mm across the blade, centred."""

    reach: float
    width: float
    length: float = HOLDER_LENGTH

    def describe(self) -> str:
        return "its holder (%.4g mm wide, from %.4g mm behind the cutting edge)" % (self.width, self.reach)


@dataclass(frozen=True)
class HolderHit:
    """The holder of a move (Path command or program line ``command``) over ``area`` mm^2 of standing material."""

    command: int
    start: Point
    end: Point
    rapid: bool
    area: float
    at: Point
    holder: Holder
    entered: Flat = field(default_factory=col.empty_flat, repr=False, compare=False)  # on the op's window
    outline: np.ndarray = field(default_factory=lambda: np.empty((0, 2)), repr=False, compare=False)  # (z, x)

    def describe(self) -> str:
        return ("%s (Path command %d) X%.3f Z%.3f -> X%.3f Z%.3f: %s enters %.4g mm^2 of standing material near "
                "X%.3f Z%.3f" % ("G0" if self.rapid else "G1", self.command, self.start[0], self.start[1],
                                  self.end[0], self.end[1], self.holder.describe(), self.area, self.at[0],
                                  self.at[1]))


def _mapped(u: float, v: float, plunge: str) -> tuple[float, float]:
    """(z, x) of the blade's local point u across from its minus side, v back from its cutting edge
    (outline.outline_at_origin's frame)."""
    if plunge == MINUS_X:
        return u, v
    if plunge == PLUS_X:
        return u, -v
    if plunge == MINUS_Z:
        return v, u
    if plunge == PLUS_Z:
        return -v, u
    raise ValueError("unknown plunge direction %r" % (plunge,))


def holder_box(tool: GroovingTool, plunge: str, holder: Holder) -> tuple[GroovingTool, np.ndarray]:
    """The holder as a square-cornered blade (swept like one) and the (z, x) offset of its reference corner
    from the blade's."""
    box = GroovingTool(float(holder.width), 0.0, length=float(holder.length))
    u = 0.5 * (float(tool.width) - float(holder.width)) - tool.reference_offset
    return box, np.array(_mapped(u, float(holder.reach), plunge))


def holder_z_extent(tool: GroovingTool, plunge: str, holder: Optional[Holder], outline: np.ndarray
                    ) -> tuple[float, float]:
    """The Z extent about the reference corner of the blade (its ``outline``, (z, x) points) with its holder."""
    below, above = float(outline[:, 0].min()), float(outline[:, 0].max())
    if holder is None:
        return below, above
    box, offset = holder_box(tool, plunge, holder)
    _corner_box, _r = blade_box(box, plunge)
    return min(below, offset[0] + _corner_box[0]), max(above, offset[0] + _corner_box[2])


@dataclass
class _Segment:
    command: int
    start: Point
    end: Point
    rapid: bool
    run: Any


def _segments(start: Point, runs: Sequence[Any]) -> list[_Segment]:
    position, out = start, []
    for run in runs:
        pieces, position = straight_segments(run.moves, position)
        out += [_Segment(run.commands[i], a, b, rapid, run) for i, a, b, rapid in pieces]
    return out


def _zx(points: Sequence[Point]) -> np.ndarray:
    return np.array([(z, x) for x, z in points], dtype=float).reshape(-1, 2)


def _overlap(rows: Flat, lo: np.ndarray, hi: np.ndarray, widths: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per row of ``rows``: the area it shares with the padded set (lo, hi), and that per slot."""
    cols, a, b = rows
    each = np.clip(np.minimum(b[:, None], hi[cols]) - np.maximum(a[:, None], lo[cols]), 0.0, None)
    return each.sum(axis=1) * widths[cols], each


def _by_run(segments: Sequence[_Segment]) -> list[tuple[Any, list[int]]]:
    """The segments' numbers in runs of consecutive segments of one GrooveRun."""
    groups: list[tuple[Any, list[int]]] = []
    for k, seg in enumerate(segments):
        if groups and groups[-1][0] is seg.run:
            groups[-1][1].append(k)
        else:
            groups.append((seg.run, [k]))
    return groups


def _joined(parts: list[Flat]) -> Flat:
    return tuple(np.concatenate(p) for p in zip(*parts)) if parts else col.empty_flat()


def _holder_rows(window: Grid, segments: Sequence[_Segment]) -> tuple[Flat, np.ndarray]:
    """The holder swept along each segment (of runs with a holder): rows on the window, and the segment's number
    in ``segments`` of each row."""
    rows, which = [], []
    for run, ks in _by_run(segments):
        box, offset = holder_box(run.tool, run.plunge, run.holder)
        starts = _zx([segments[k].start for k in ks]) + offset
        ends = _zx([segments[k].end for k in ks]) + offset
        r, w = swept_rows(window.centres, box, run.plunge, starts, ends)
        rows.append(r)
        which.append(np.asarray(ks, dtype=np.int64)[w])
    if not rows:
        return col.empty_flat(), np.empty(0, dtype=np.int64)
    return _joined(rows), np.concatenate(which)


def _hit(seg: _Segment, rows: Flat, state: Flat, window: Grid) -> Optional[HolderHit]:
    lo, hi = col.pack(len(window), state)
    area, each = _overlap(rows, lo, hi, window.widths)
    if float(area.sum()) <= AREA_TOL:
        return None
    best = int(np.argmax(area))
    k = int(np.argmax(each[best]))
    cols, a, b = rows
    x = 0.5 * (max(a[best], lo[cols[best], k]) + min(b[best], hi[cols[best], k]))
    return HolderHit(seg.command, seg.start, seg.end, seg.rapid, float(area.sum()),
                     (float(x), float(window.centres[cols[best]])), seg.run.holder,
                     col.combine(rows, state, INTERSECTION), holder_outline(seg.run, seg.end))


def holder_outline(run: Any, at: Point) -> np.ndarray:
    """The holder's rectangle, (z, x) corners, with the blade's reference corner at ``at`` (x, z)."""
    box, offset = holder_box(run.tool, run.plunge, run.holder)
    z0, x0, z1, x1 = blade_box(box, run.plunge)[0]
    z, x = float(at[1]) + offset[0], float(at[0]) + offset[1]
    return np.array([(z + z0, x + x0), (z + z1, x + x0), (z + z1, x + x1), (z + z0, x + x1), (z + z0, x + x0)])


def holder_region(hits: Sequence[HolderHit], window: Grid) -> Any:
    """The standing material the hits' holders enter, a Section on ``window`` (the turning check draws it)."""
    if not hits:
        return EMPTY_SECTION
    rows = col.empty_flat()
    for hit in hits:
        rows = col.combine(rows, hit.entered, UNION)
    return Section(window, rows)


def holder_hits(start: Point, runs: Sequence[Any], before: Flat, window: Grid) -> list[HolderHit]:
    """The moves of ``runs`` (turning.GrooveRun: moves, commands, tool, plunge, holder) from ``start`` whose
    holder enters the material standing when they run; ``before``: the material at the op's start, rows on
    ``window`` (numbered from its first column)."""
    if all(run.holder is None for run in runs):  # (the usual case: nothing to do, nothing computed)
        return []
    segments = _segments(start, runs)
    checked = [k for k, seg in enumerate(segments) if seg.run.holder is not None]
    if not checked:
        return []
    rows, which = _holder_rows(window, [segments[k] for k in checked])
    which = np.asarray(checked, dtype=np.int64)[which]  # the segment's number in ``segments``
    lo, hi = col.pack(len(window), before)
    first_area, _each = _overlap(rows, lo, hi, window.widths)
    touching = {int(w) for w in np.unique(which[first_area > AREA_TOL])}
    if not touching:
        return []
    hits, state, pending = [], before, []
    for k, seg in enumerate(segments):
        if not seg.rapid:
            pending.append(k)
        if k not in touching:
            continue
        if pending:  # what the blade cut up to here is gone before its holder comes
            state = col.combine(state, _blade_rows(window, [segments[j] for j in pending]), DIFFERENCE)
            pending.clear()
        hit = _hit(seg, col.select(rows, which == k), state, window)
        if hit is not None:
            hits.append(hit)
    return hits


def _blade_rows(window: Grid, segments: Sequence[_Segment]) -> Flat:
    """What the blade sweeps along the feed ``segments`` (runs may hold different blades)."""
    parts = []
    for run, ks in _by_run(segments):
        starts, ends = _zx([segments[k].start for k in ks]), _zx([segments[k].end for k in ks])
        parts.append(swept_rows(window.centres, run.tool, run.plunge, starts, ends)[0])
    return col.union_per_column(_joined(parts))


SHOWN = 3  # holder hits an op's summary lists (the first ones), the rest counted


def holder_lines(hits: Sequence[HolderHit]) -> list[str]:
    """The summary lines of an op's holder hits."""
    lines = ["  HOLDER IN STOCK: " + hit.describe() for hit in hits[:SHOWN]]
    if len(hits) > SHOWN:
        lines.append("  HOLDER IN STOCK: %d more move(s)" % (len(hits) - SHOWN))
    return lines
