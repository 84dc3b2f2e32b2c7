"""The turning check: a Job's grooving ops swept, in order, over the turned
section of its stock, and the figures per op (no FreeCAD: the FreeCAD layer,
ops/turning_check/check.py, reads the Job into OpInput; no shapely: the
column model, numpy only; turning_shapely.py computes the same on shapely
polygons, the tests' second oracle).

Per op:

* removed      stock standing before the op less stock standing after (mm^2
               of the half section);
* gouge        removed material inside the part the ops must leave
               (turned_section.part_to_leave) deeper than ``tol`` below its
               surface: its area, its depth and the deepest point;
* leftover     material of the op's planned grooves still standing that the
               blade could reach (farther than ``tol`` from the unreachable
               part);
* unreachable  material of the planned grooves no placement of the blade
               reaches (the corner fillets and whatever is narrower than the
               blade), beside the area the engine's reach warnings report;
* rapids       rapids whose swept blade meets standing stock;
* time         machining_time from the op's feeds and speeds.

The material lives on one column grid (columns.py) laid out before the
sweep: an edge at every vertex of the sections and grooves and at the
blade's sides at every move's end, columns STEP wide where a blade works.
Each op works on the columns of its own window: the check is linear in the
moves. Regions (``Section``) are (z, x), x the radius; positions are (x, z).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any, Optional

import numpy as np

from freecad_groove.engine.moves import ARCS, DWELL, MINUS_X, PLUS_X, GroovingTool, Move

from . import columns as col
from .column_figures import NOISE_AREA, hinted, measure_gouge, thicker_than
from .column_reach import unreachable_across, unreachable_along
from .column_sweep import FeedPath, Material, sweep
from .columns import DIFFERENCE, INTERSECTION, UNION, Flat, Grid
from .holder import Holder, HolderHit, holder_hits, holder_lines, holder_region, holder_z_extent
from .machining_time import Feeds, MachiningTime, machining_time
from .outline import outline_at_origin
from .shapes import EMPTY_SECTION, Edges, Section, Shape, box, corners
from .turned_section import groove_region, part_to_leave

Point = tuple[float, float]
Region = Any  # a Section (the column model) or a shapely geometry (turning_shapely)
DEFAULT_TOL = 0.001  # mm: gouges and leftovers thinner than this are not reported
WINDOW_MARGIN = 1.0  # mm around what an op's blade sweeps: the columns its check works on
COARSE = 1.0  # mm: the columns where no blade works
STEP = 0.05  # mm: the widest column where a blade works (straight edges are exact whatever the width)
GRADING = 12  # columns ever narrower toward a groove's wall, over a corner radius, on each side


def _area(region: Region) -> float:
    return 0.0 if region.is_empty else region.area


def step_for(tools: Sequence[GroovingTool]) -> float:
    """The column width where a blade works: STEP, narrower for a small corner radius (an eighth of it)."""
    radii = [float(t.corner_radius) for t in tools if float(t.corner_radius) > 0]
    return max(0.002, min([STEP] + [r / 8 for r in radii]))


@dataclass(frozen=True)
class GrooveRun:
    """One planned groove of an op and the moves of the op's Path that cut it
    (its link rapids included): x radius, z. ``commands``: the Path command
    number (1-based) of each move; ``region``: the planned finished groove,
    world (x, z); ``reach_warning``: mm^2 the engine's reach warnings say
    the blade leaves in it; ``programmed``: the groove is the design's though
    the model may not show it (programmed by its values on a plain face of
    the part); False: the model alone says what the op must leave (a groove
    in a face of a modelled groove is never the design's)."""

    moves: list[Move]
    commands: list[int]
    tool: GroovingTool
    plunge: str
    region: list[Point]
    reach_warning: float = 0.0
    programmed: bool = True
    holder: Optional[Holder] = None  # the blade's holder (holder.py); None: not drawn


@dataclass(frozen=True)
class OpInput:
    """A grooving op as its Path runs it: ``start`` (x, z) is where the tool
    stands before its first move; ``error``: why the op cannot be checked
    (then nothing else is used)."""

    label: str
    start: Point = (0.0, 0.0)
    grooves: list[GrooveRun] = field(default_factory=list)
    feeds: Optional[Feeds] = None
    error: Optional[str] = None


@dataclass(frozen=True)
class RapidHit:
    """A rapid through standing stock: Path command ``command`` from start to end (x, z)."""

    command: int
    start: Point
    end: Point
    area: float
    at: Point  # (x, z) inside the stock it meets

    def describe(self) -> str:
        return ("G0 (Path command %d) X%.3f Z%.3f -> X%.3f Z%.3f passes through %.4g mm^2 of standing stock"
                " near X%.3f Z%.3f" % (self.command, self.start[0], self.start[1], self.end[0], self.end[1],
                                       self.area, self.at[0], self.at[1]))


@dataclass
class OpCheck:
    """The figures of one op (areas in mm^2 of the half section, depths in mm)."""

    label: str
    error: Optional[str] = None
    removed: float = 0.0
    gouge_area: float = 0.0
    gouge_depth: float = 0.0
    gouge_at: Optional[Point] = None  # (x, z) of the deepest gouge
    leftover: float = 0.0
    unreachable: float = 0.0
    reach_warning: float = 0.0
    rapid_hits: list[RapidHit] = field(default_factory=list)
    holder_hits: list[HolderHit] = field(default_factory=list)  # moves whose holder enters standing material
    time: Optional[MachiningTime] = None
    removed_region: Region = EMPTY_SECTION
    gouge_region: Region = EMPTY_SECTION
    leftover_region: Region = EMPTY_SECTION
    unreachable_region: Region = EMPTY_SECTION
    holder_region: Region = EMPTY_SECTION  # the standing material the blade's holder enters

    @property
    def ok(self) -> bool:
        return (self.error is None and not self.gouge_depth and not self.leftover and not self.rapid_hits
                and not self.holder_hits)

    def summary(self) -> str:
        if self.error:
            return "%s: not checked: %s" % (self.label, self.error)
        lines = ["%s: %s" % (self.label, "ok" if self.ok else "PROBLEMS"),
                 "  removed %.4f mm^2" % self.removed]
        if self.gouge_depth:
            lines.append("  GOUGE %.4f mm^2 into the part, %.4f mm deep at X%.3f Z%.3f"
                         % (self.gouge_area, self.gouge_depth, self.gouge_at[0], self.gouge_at[1]))
        else:
            lines.append("  no gouge")
        lines.append("  %s %.4f mm^2 left in the grooves that the blade could reach"
                     % ("LEFTOVER:" if self.leftover else "leftover", self.leftover))
        lines.append("  unreachable %.4f mm^2 (the cycle's reach warnings: %.4f mm^2)"
                     % (self.unreachable, self.reach_warning))
        lines += ["  RAPID THROUGH STOCK: " + hit.describe() for hit in self.rapid_hits]
        lines += holder_lines(self.holder_hits)
        if self.time is not None:
            lines.append("  machining time " + self.time.describe())
        return "\n".join(lines)


@dataclass
class JobCheck:
    """The whole check: the sections (stock before, part to leave, stock after) and each op's figures."""

    stock: Region
    part: Region
    remaining: Region
    ops: list[OpCheck]
    notes: list[str] = field(default_factory=list)  # where the sections came from, ops not checked

    @property
    def ok(self) -> bool:
        return all(op.ok for op in self.ops)

    def summary(self) -> str:
        head = "Turning check: stock %.4f mm^2, part %.4f mm^2, %d op(s): %s" % (
            _area(self.stock), _area(self.part), len(self.ops), "ok" if self.ok else "PROBLEMS")
        return "\n".join([head] + ["  " + note for note in self.notes] + [op.summary() for op in self.ops])

    __str__ = summary


# ---------------------------------------------------------------- the column model's check


class PartModel:
    """The part the ops must leave on the material's grid, and its edges (for
    depths): taken on the columns an op asks for when it asks (only the rings
    that reach them), nothing kept per column."""

    CHUNK = 1 << 16  # columns measured at once for the area

    def __init__(self, grid: Grid, shape: Shape) -> None:
        self.grid = grid
        self.shape = shape
        self.edges = Edges(shape)
        self._last: Optional[tuple[tuple[int, int], Flat]] = None

    def rows(self, i0: int, i1: int) -> Flat:
        """The columns i0:i1, numbered from i0 (the last span's kept: an op asks for its own several times)."""
        if i1 <= i0:
            return col.empty_flat()
        if self._last is not None and self._last[0] == (i0, i1):
            return self._last[1]
        local = self.shape.clipped(float(self.grid.edges[i0]), float(self.grid.edges[i1]))
        rows = local.rows(self.grid.centres[i0:i1])
        self._last = ((i0, i1), rows)
        return rows

    @property
    def area(self) -> float:
        n, step = len(self.grid), self.CHUNK
        return sum(col.area(self.rows(i0, min(n, i0 + step)), self.grid.widths[i0:]) for i0 in range(0, n, step))


def _arc_reach(move: Move) -> float:
    """How far (Z) an arc may bulge beyond its end."""
    if move.centre is not None:
        return abs(float(move.z) - float(move.centre[1])) + abs(float(move.x) - float(move.centre[0]))
    return 2.0 * abs(float(move.radius or 0.0))


def op_range(op: OpInput) -> tuple[float, float]:
    """The Z range an op's blades (their holders too) and grooves reach (WINDOW_MARGIN more)."""
    lo = hi = float(op.start[1])
    for run in op.grooves:
        below, above = holder_z_extent(run.tool, run.plunge, run.holder, outline_at_origin(run.tool, run.plunge))
        zs = [float(m.z) for m in run.moves] + [float(z) for _x, z in run.region]
        bulge = max([_arc_reach(m) for m in run.moves if m.kind in ARCS] or [0.0])
        if zs:
            lo = min(lo, min(zs) - bulge + below)
            hi = max(hi, max(zs) + bulge + above)
    return lo - WINDOW_MARGIN, hi + WINDOW_MARGIN


def _wall_ends(moves: Sequence[Move], start: Point) -> np.ndarray:
    """The Z of the move ends where the blade's sides may stand as walls: the
    ends of moves along an axis and where the path turns back along Z (not
    the ends of an arc's chords: the blade's corner arcs bound what they cut)."""
    points = [(float(start[0]), float(start[1]))] + [
        (float(start[0]) if m.x is None else float(m.x), float(m.z)) for m in moves if m.kind != DWELL]
    xz = np.array(points)
    if len(xz) < 2:
        return xz[:, 1]
    d = np.diff(xz, axis=0)
    straight = (np.abs(d[:, 0]) < 1e-9) | (np.abs(d[:, 1]) < 1e-9)
    turn = np.zeros(len(d), dtype=bool)
    turn[:-1] = d[:-1, 1] * d[1:, 1] <= 0
    keep = straight | turn
    return np.concatenate([xz[:1, 1], xz[1:, 1][keep], xz[:-1, 1][straight]])


def _walls(region: Sequence[Point]) -> np.ndarray:
    """The Z of a groove's walls across Z (edges of constant Z): where its fillets meet them."""
    zs = [float(z) for _x, z in region]
    return np.unique([a for a, b in zip(zs, zs[1:] + zs[:1]) if abs(a - b) < 1e-9])


def layout(shapes: Sequence[Shape], ops: Sequence[OpInput]) -> tuple[Grid, float]:
    """The column grid of a check (see the module) and its step."""
    runs = [run for op in ops if not op.error for run in op.grooves]
    step = step_for([run.tool for run in runs])
    breaks = [corners(s)[:, 0] for s in shapes]
    for op in ops:
        if op.error:
            continue
        position = op.start
        for run in op.grooves:
            base = outline_at_origin(run.tool, run.plunge)
            ends = _wall_ends(run.moves, position)
            breaks += [ends + base[:, 0].min(), ends + base[:, 0].max()]
            moves = [m for m in run.moves if m.kind != DWELL]
            position = (moves[-1].x, moves[-1].z) if moves else position
        groove = corners(groove_region(run.region))[:, 0]
        breaks += [groove, col.graded(_walls(run.region), float(run.tool.corner_radius), GRADING)]
    fine = [op_range(op) for op in ops if not op.error and op.grooves]
    return col.make_grid(np.concatenate(breaks), fine, step, COARSE), step


def _gouge(check: OpCheck, removed: Flat, before: Flat, feeds: list[FeedPath], part: PartModel, window: Grid,
           span: tuple[int, int], tol: float) -> None:
    cut = col.combine(removed, part.rows(*span), INTERSECTION)
    if col.area(cut, window.widths) <= NOISE_AREA:
        return
    cut = hinted(cut, window, part.edges, tol)
    if not len(cut[0]):
        return
    gouge = measure_gouge(cut, before, feeds, part.shape, part.edges, window, tol)
    if gouge is not None:
        check.gouge_area, check.gouge_depth, check.gouge_at = gouge.area, gouge.depth, gouge.at
        check.gouge_region = Section(window, gouge.rows)


def _missed(run: GrooveRun, groove: Shape, target: Flat, part: PartModel, window: Grid, span: tuple[int, int],
            step: float) -> Flat:
    """The target of ``run`` (rows on the window) that no placement of its blade reaches."""
    if run.plunge in (MINUS_X, PLUS_X):
        solid = col.combine(part.rows(*span), target, DIFFERENCE)
        return unreachable_across(window, target, solid, run.tool, run.plunge)
    zmin, xmin, zmax, xmax = groove.bounds
    reach = float(run.tool.width) + float(run.tool.length) + 1.0
    local = part.shape & box(zmin - reach, xmin - reach, zmax + reach, xmax + reach)
    missed = unreachable_along(window, groove, local, run.tool, run.plunge, step)
    return col.combine(missed, target, INTERSECTION)


def _groove_figures(check: OpCheck, op: OpInput, part: PartModel, window: Grid, span: tuple[int, int],
                    before: Flat, after: Flat, tol: float, step: float) -> None:
    """Unreachable and leftover material of the op's planned grooves."""
    unreachable, leftover = col.empty_flat(), col.empty_flat()
    widths = window.widths
    for run in op.grooves:
        groove = groove_region(run.region)
        target = col.combine(groove.rows(window.centres), before, INTERSECTION)
        if col.area(target, widths) <= NOISE_AREA:
            continue
        missed = _missed(run, groove, target, part, window, span, step)
        left = col.combine(target, after, INTERSECTION)
        if len(missed[0]):
            left = col.combine(left, col.grown(missed, tol), DIFFERENCE)
        if col.area(left, widths) > NOISE_AREA and thicker_than(left, after, window, tol):
            leftover = col.combine(leftover, left, UNION)
        unreachable = col.combine(unreachable, missed, UNION)
        check.reach_warning += run.reach_warning
    check.unreachable_region, check.leftover_region = Section(window, unreachable), Section(window, leftover)
    check.unreachable, check.leftover = col.area(unreachable, widths), col.area(leftover, widths)


def check_op(op: OpInput, material: Material, part: PartModel, tol: float = DEFAULT_TOL,
             step: float = 0.02) -> OpCheck:
    """One op's figures over ``material`` (the stock standing when it starts; updated)."""
    check = OpCheck(op.label, op.error)
    if op.error:
        return check
    grid = material.grid
    span = grid.span(*op_range(op))
    window = grid.part(*span)
    before = material.rows(*span)
    position, feeds = op.start, []
    check.holder_hits = holder_hits(op.start, op.grooves, before, window)
    check.holder_region = holder_region(check.holder_hits, window)
    for run in op.grooves:
        hits, position, run_feeds = sweep(material, run.moves, run.tool, run.plunge, position, span)
        check.rapid_hits += [RapidHit(run.commands[h.index], h.start, h.end, h.area, h.at) for h in hits]
        feeds.append(run_feeds)
    after = material.rows(*span)
    removed = col.combine(before, after, DIFFERENCE)
    check.removed_region, check.removed = Section(window, removed), col.area(removed, window.widths)
    _gouge(check, removed, before, feeds, part, window, span, tol)
    _groove_figures(check, op, part, window, span, before, after, tol, step)
    material.drop_after(*span)
    if op.feeds is not None:
        moves = [move for run in op.grooves for move in run.moves]
        check.time = machining_time(op.start, moves, op.feeds)
    return check


def check_ops(ops: list[OpInput], stock: Shape, model: Shape, tol: float = DEFAULT_TOL,
              notes: Optional[list[str]] = None, falls: bool = False) -> JobCheck:
    """Sweep ``ops`` in order over ``stock`` (each op starts from what the
    previous ones left) and judge them against ``model``, the part's section;
    ``falls``: a piece cut free of the chuck end (the lowest Z) falls away.
    Only grooves ``programmed`` on plain faces join the part's design
    (part_to_leave): no op's own planned groove excuses what it cuts into the model elsewhere."""
    grooves = [groove_region(run.region) for op in ops if not op.error for run in op.grooves if run.programmed]
    part = part_to_leave(model, grooves)
    grid, step = layout([stock, part], ops)
    material = Material(grid, stock, falls)
    part_model = PartModel(grid, part)
    checks = [check_op(op, material, part_model, tol, step) for op in ops]
    remaining = Section(grid, material.rows(0, len(grid)))
    return JobCheck(Section(grid, stock.rows(grid.centres)), Section(grid, part_model.rows(0, len(grid))), remaining,
                    checks, list(notes or []))
