"""The turning check: a Job's grooving ops swept, in order, over the turned
section of its stock, and the figures per op (no FreeCAD: the FreeCAD layer,
freecad/turning_check.py, reads the Job into OpInput and JobInput).

Per op:

* removed      stock standing before the op less stock standing after (mm^2
               of the half section);
* gouge        removed material inside the part the ops must leave
               (section.part_to_leave) deeper than ``tol`` below its surface:
               its area, its depth and the deepest point;
* leftover     material of the op's planned grooves still standing that the
               blade could reach (farther than ``tol`` from the unreachable
               part);
* unreachable  material of the planned grooves no placement of the blade
               reaches (the corner fillets and whatever is narrower than the
               blade), beside the area the engine's reach warnings report;
* rapids       rapids whose swept blade meets standing stock (sweep.simulate);
* time         machining_time from the op's feeds and speeds.

Geometry is shapely (z, x), x the radius; positions are (x, z).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Optional

from shapely import Geometry

from freecad_groove.engine.moves import GroovingTool, Move

from .depth import depth_inside
from .machining_time import Feeds, MachiningTime, machining_time
from .overlay import EMPTY, NOISE_AREA, QUAD_SEGS, area, difference, intersection, union, union_all
from .reach import reachable_region
from .section import groove_region, part_to_leave
from .sweep import simulate

Point = tuple[float, float]
DEFAULT_TOL = 0.001  # mm: gouges and leftovers thinner than this are not reported


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
    time: Optional[MachiningTime] = None
    removed_region: Geometry = EMPTY
    gouge_region: Geometry = EMPTY
    leftover_region: Geometry = EMPTY
    unreachable_region: Geometry = EMPTY

    @property
    def ok(self) -> bool:
        return self.error is None and not self.gouge_depth and not self.leftover and not self.rapid_hits

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
        if self.time is not None:
            lines.append("  machining time " + self.time.describe())
        return "\n".join(lines)


@dataclass
class JobCheck:
    """The whole check: the sections (stock before, part to leave, stock after) and each op's figures."""

    stock: Geometry
    part: Geometry
    remaining: Geometry
    ops: list[OpCheck]
    notes: list[str] = field(default_factory=list)  # where the sections came from, ops not checked

    @property
    def ok(self) -> bool:
        return all(op.ok for op in self.ops)

    def summary(self) -> str:
        head = "Turning check: stock %.4f mm^2, part %.4f mm^2, %d op(s): %s" % (
            area(self.stock), area(self.part), len(self.ops), "ok" if self.ok else "PROBLEMS")
        return "\n".join([head] + ["  " + note for note in self.notes] + [op.summary() for op in self.ops])

    __str__ = summary


def _deepest(core: Geometry, part: Geometry, depth: float, tol: float) -> Point:
    """(x, z) of a point of ``core`` about ``depth`` inside ``part``."""
    deep = intersection(core, part.buffer(-max(depth - 2 * tol, tol), quad_segs=QUAD_SEGS))
    point = (deep if area(deep) > NOISE_AREA else core).representative_point()
    return (point.y, point.x)


def _gouge(check: OpCheck, removed: Geometry, part: Geometry, tol: float) -> None:
    cut = intersection(removed, part)
    if area(cut) <= NOISE_AREA:
        return
    depth, core = depth_inside(cut, part, tol)
    if core.is_empty:
        return
    check.gouge_area, check.gouge_depth, check.gouge_region = area(core), depth, core
    check.gouge_at = _deepest(core, part, depth, tol)


def _groove_figures(check: OpCheck, op: OpInput, part: Geometry, before: Geometry, after: Geometry,
                    tol: float) -> None:
    """Unreachable and leftover material of the op's planned grooves."""
    unreachable, leftover = [], []
    for run in op.grooves:
        target = intersection(groove_region(run.region), before)
        if area(target) <= NOISE_AREA:
            continue
        # The grooving cycle assumes the part turned to its contour: air above the groove.
        reach = reachable_region(target, union(part, target), run.tool, run.plunge, tol)
        missed = difference(target, reach)
        left = intersection(target, after)
        if not missed.is_empty:
            left = difference(left, missed.buffer(tol, quad_segs=QUAD_SEGS))
        if area(left) > NOISE_AREA and not depth_inside(left, after, tol)[1].is_empty:
            leftover.append(left)
        unreachable.append(missed)
        check.reach_warning += run.reach_warning
    check.unreachable_region = union_all(unreachable) if unreachable else EMPTY
    check.leftover_region = union_all(leftover) if leftover else EMPTY
    check.unreachable, check.leftover = area(check.unreachable_region), area(check.leftover_region)


Attached = Optional[Callable[[Geometry], Geometry]]  # the standing stock still held (sweep.simulate)


def _sweep(op: OpInput, stock: Geometry, attached: Attached = None) -> tuple[Geometry, list[RapidHit]]:
    """The stock left after the op's moves, groove by groove, and its rapids through stock."""
    position, hits = op.start, []
    for run in op.grooves:
        result = simulate(run.moves, run.tool, run.plunge, position, stock, attached=attached)
        for collision in result.rapid_collisions:
            point = collision.region.representative_point()
            hits.append(RapidHit(run.commands[collision.index], collision.start, (collision.move.x, collision.move.z),
                                 collision.area, (point.y, point.x)))
        stock, position = result.remaining, result.final
    return stock, hits


def check_op(op: OpInput, stock: Geometry, part: Geometry, tol: float = DEFAULT_TOL,
             attached: Attached = None) -> tuple[OpCheck, Geometry]:
    """One op's figures over ``stock`` (the stock standing when it starts),
    and the stock it leaves; ``attached``: see sweep.simulate."""
    check = OpCheck(op.label, op.error)
    if op.error:
        return check, stock
    after, check.rapid_hits = _sweep(op, stock, attached)
    check.removed_region = difference(stock, after)
    check.removed = area(check.removed_region)
    _gouge(check, check.removed_region, part, tol)
    _groove_figures(check, op, part, stock, after, tol)
    if op.feeds is not None:
        moves = [move for run in op.grooves for move in run.moves]
        check.time = machining_time(op.start, moves, op.feeds)
    return check, after


def check_ops(ops: list[OpInput], stock: Geometry, model: Geometry, tol: float = DEFAULT_TOL,
              notes: Optional[list[str]] = None, attached: Attached = None) -> JobCheck:
    """Sweep ``ops`` in order over ``stock`` (each op starts from what the
    previous ones left) and judge them against ``model``, the part's section;
    ``attached``: see sweep.simulate. Only grooves ``programmed`` on plain faces join the part's design
    (part_to_leave): no op's own planned groove excuses what it cuts into the model elsewhere."""
    grooves = [groove_region(run.region) for op in ops if not op.error for run in op.grooves if run.programmed]
    part = part_to_leave(model, grooves)
    checks, standing = [], stock
    for op in ops:
        check, standing = check_op(op, standing, part, tol, attached)
        checks.append(check)
    return JobCheck(stock, part, standing, checks, list(notes or []))
