"""The command line's ``verify``: a whole program's moves (cycle expansions
and plain G0/G1/G2/G3 blocks) swept over the stock and judged against the
part the program declares, with turning.check_op doing the bookkeeping on
the column model (numpy only; program_check_shapely.py does the same on
shapely polygons, the tests' second oracle).

* The part the program declares: the stock less the grooves its cycle calls
  declare (program_record.declared_grooves). A feed cutting anything else is a
  gouge (a hand-written G1 as much as a cycle's), a rapid whose blade enters
  the standing stock a collision; either is a *finding* naming its line.
* Default stock (``default_stock``): a bar whose surface passes through the
  program's first approach point (its radius that point's X), lowered to the
  opening of the highest external groove a cycle declares (the cycles assume
  the contour turned); from CHUCK_MARGIN below the lowest Z the tool or a
  groove reaches (the chuck end) to the highest Z of the approach point, the
  feeds' end points and the declared grooves (rapids beyond run in air),
  lowered to the opening of the highest face groove. Internal grooves give it a bore
  at their lowest opening. ``--stock DIAMETER[xLENGTH]`` sets the diameter
  (and the length back from that face end).
* A piece cut free of the chuck end falls away: a rapid is checked only
  against the stock still connected to the chuck end (a cut-off's relief).
* Plain blocks cut with the blade of the tool in force (tool table, else
  --tool-width) held as the nearest cycle call of the program holds it (the
  one before, else the one after), else plunging -X (an external blade).
* Machining time: each feed at its own F in its feed mode (G94/G95) with the
  spindle in force (S, or G96 with its limit: none means no limit); rapids
  are timed only when a rapid rate is given (a program does not say it).
"""

from __future__ import annotations

import math
import operator
from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from freecad_groove.engine.errors import ProgramError
from freecad_groove.engine.moves import DWELL, FEED, MINUS_X, MINUS_Z, PLUS_X, RAPID
from freecad_groove.engine.tool_table import ToolTable, blade_for

from . import columns as col
from .column_figures import NOISE_AREA
from .column_sweep import Material, swept_rows
from .holder import Holder
from .machining_time import Feeds, MachiningTime, feed_seconds, rapid_seconds
from .program_record import RecordingTranslator, SpeedState, Step, mm_blade
from .shapes import EMPTY_SECTION, Measured, Section, Shape, union_all
from .turned_section import bar_section, groove_region
from .turning import DEFAULT_TOL, GrooveRun, JobCheck, OpCheck, OpInput, PartModel, check_op, layout

Point = tuple[float, float]
CHUCK_MARGIN = 10.0  # mm of bar below the lowest Z the program reaches (the chuck end)


@dataclass(frozen=True)
class StockSpec:
    """--stock: diameter (mm), length (mm, None: to the chuck end)."""

    diameter: float
    length: Optional[float] = None


@dataclass
class ProgramCheck:
    """The verdict on a program: the sections, each step's figures, the findings (line, text)."""

    name: str
    job: JobCheck
    steps: list[Step]
    stock_note: str
    times: list[MachiningTime] = field(default_factory=list)
    findings: list[tuple[int, str]] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        return not self.findings


# ---------------------------------------------------------------- the stock


@dataclass(frozen=True)
class StockBar:
    """The bar a program is checked on: radius, bore radius, Z from low to high, and the note saying so."""

    radius: float
    bore: float
    low: float
    high: float
    note: str


def _rings(steps: list[Step], plunge: str) -> list[list[Point]]:
    return [ring for step in steps if step.plunge == plunge for ring in step.grooves]


def stock_bar(steps: list[Step], approach: Optional[Point], spec: Optional[StockSpec]) -> StockBar:
    """The bar the program is checked on (see the module)."""
    if approach is None:
        raise ProgramError("no approach point (a G0 to a known X and Z) to derive the stock from: give --stock", 0)
    # step by step: a list of every move's Z would hold as much as the moves again
    grooves = [z for step in steps for ring in step.grooves for _x, z in ring]
    low = min([min(m.z for m in step.moves) for step in steps] + grooves) - CHUCK_MARGIN
    feeds = [max((m.z for m in step.moves if m.kind == FEED), default=-math.inf) for step in steps]
    high = max([approach[1]] + feeds + grooves)
    external, faces, internal = (_rings(steps, plunge) for plunge in (MINUS_X, MINUS_Z, PLUS_X))
    radius = approach[0]
    how = "through the first approach point X%.3f Z%.3f" % (2 * approach[0], approach[1])
    if external and max(x for ring in external for x, _z in ring) < radius:
        radius = max(x for ring in external for x, _z in ring)
        how = "to the opening of the highest external groove"
    if faces:
        high = min(high, max(z for ring in faces for _x, z in ring))
    bore = min((x for ring in internal for x, _z in ring), default=0.0)
    if internal:
        radius = max(radius, max(x for ring in internal for x, _z in ring) + CHUCK_MARGIN)
    if spec is not None:
        radius, how = spec.diameter / 2.0, "as given (--stock)"
        if spec.length is not None:
            low = high - spec.length
    note = "stock: bar D%.3f%s from Z%.3f to Z%.3f (diameter %s)" % (
        2 * radius, " bore D%.3f" % (2 * bore) if bore > 0 else "", low, high, how)
    return StockBar(radius, bore, low, high, note)


def default_stock(steps: list[Step], approach: Optional[Point], spec: Optional[StockSpec], bar_region=bar_section,
                  groove=groove_region, union=union_all, minus=operator.sub) -> tuple[Shape, str]:
    """The stock and how it was derived (see the module): a Shape, or with
    the region functions of another model (program_check_shapely's) its region."""
    bar = stock_bar(steps, approach, spec)
    stock = bar_region(bar.radius, bar.low, bar.high)
    if bar.bore > 0:
        stock = minus(stock, bar_region(bar.bore, bar.low, bar.high))
    air = [groove(ring) for step in steps for ring in step.air]
    if air:
        stock = minus(stock, union(air))
    return stock, bar.note


# ---------------------------------------------------------------- steps to ops


def _nearest_cycles(steps: list[Step]) -> list[Optional[Step]]:
    """For each step, the last cycle step before it (None: none)."""
    out, last = [], None
    for step in steps:
        out.append(last)
        last = step if step.cycle else last
    return out


def _fill_blades(steps: list[Step], tools, default_blade) -> None:
    """Plain steps: the blade of their tool, held as the nearest cycle holds it."""
    before, after = _nearest_cycles(steps), _nearest_cycles(steps[::-1])[::-1]
    for index, step in enumerate(steps):
        if step.cycle:
            continue
        try:
            step.blade = mm_blade(blade_for(step.tool, tools, default_blade), step.scale)
        except ProgramError as exc:
            raise ProgramError("verify needs the blade cutting these moves: %s" % exc, step.line) from None
        nearest = before[index] if before[index] is not None else after[index]
        step.plunge = nearest.plunge if nearest is not None else MINUS_X


def _holder(step: Step, tools) -> Optional[Holder]:
    """The holder of the step's tool where the tool table gives its reach and ``holder=`` (mm), else None."""
    if not isinstance(tools, ToolTable) or step.tool not in tools.holders or step.tool not in tools.reach:
        return None
    return Holder(tools.reach[step.tool] * step.scale, tools.holders[step.tool] * step.scale)


def _op(step: Step, holder: Optional[Holder] = None) -> OpInput:
    rings = step.grooves or [[]]
    runs = [GrooveRun(step.moves if k == 0 else [], step.lines if k == 0 else [], step.blade, step.plunge, ring,
                      holder=holder) for k, ring in enumerate(rings)]
    return OpInput(step.label, step.start, runs)


def _feeds(speed: SpeedState, rapid_rate: float) -> Feeds:
    max_rpm = speed.max_rpm if speed.max_rpm else math.inf
    return Feeds(speed.feed or 0.0, speed.per_rev, speed.rpm, speed.surface_speed, max_rpm, rapid_rate, rapid_rate)


def step_time(step: Step, rapid_rate: float) -> MachiningTime:
    """The step's time, each move at the feed and speeds in force for it."""
    position, cut, dwell, rapid = step.start, 0.0, 0.0, 0.0
    known: dict[SpeedState, Feeds] = {}  # the moves of a step share a few states
    for move, speed in zip(step.moves, step.speeds):
        end = (move.x, move.z)
        feeds = known.get(speed)
        if feeds is None:
            feeds = known[speed] = _feeds(speed, rapid_rate)
        if move.kind == FEED:
            cut += feed_seconds(position, end, feeds) if feeds.feed else 0.0
        elif move.kind == RAPID:
            rapid += rapid_seconds(position, end, feeds)
        else:
            dwell += move.p
            continue
        position = end
    return MachiningTime(cut, dwell, rapid, rapid_rate > 0)


# ---------------------------------------------------------------- findings


def _gouge_line(step: Step, check: OpCheck) -> int:
    """The line of the first feed of the step that cuts into the gouge."""
    region = check.gouge_region
    lo, hi = col.pack(len(region.grid), region.rows)
    position, starts, ends, lines = step.start, [], [], []
    for move, line in zip(step.moves, step.lines):
        end = (move.x, move.z)
        if move.kind == FEED:
            starts.append((position[1], position[0]))
            ends.append((end[1], end[0]))
            lines.append(line)
        if move.kind != DWELL:
            position = end
    if not lines:
        return step.line
    rows, which = swept_rows(region.grid.centres, step.blade, step.plunge, np.array(starts), np.array(ends))
    cols, a, b = rows
    overlap = np.clip(np.minimum(b[:, None], hi[cols]) - np.maximum(a[:, None], lo[cols]), 0.0, None).sum(axis=1)
    meets = which[overlap * region.grid.widths[cols] > NOISE_AREA]
    return lines[int(meets.min())] if len(meets) else step.line


def _what(step: Step) -> str:
    """How the report names a step."""
    if step.cycle:
        return step.label
    first, last = step.lines[0], step.lines[-1]
    return "the moves of line %d" % first if first == last else "the moves of lines %d-%d" % (first, last)


def findings(steps: list[Step], checks: list[OpCheck], gouge_line=_gouge_line) -> list[tuple[int, str]]:
    found = []
    for step, check in zip(steps, checks):
        if check.gouge_depth:
            found.append((gouge_line(step, check),
                          "gouge: %s cut %.4f mm^2 of the part outside the declared grooves, %.4f mm deep at "
                          "X%.3f Z%.3f (X a diameter)" % (_what(step), check.gouge_area, check.gouge_depth,
                                                          2 * check.gouge_at[0], check.gouge_at[1])))
        for hit in check.rapid_hits:
            found.append((hit.command, "collision: G0 X%.3f Z%.3f -> X%.3f Z%.3f passes through %.4g mm^2 of "
                          "standing stock near X%.3f Z%.3f (X diameters)" % (
                              2 * hit.start[0], hit.start[1], 2 * hit.end[0], hit.end[1], hit.area,
                              2 * hit.at[0], hit.at[1])))
        for hit in check.holder_hits:
            found.append((hit.command, "holder: %s X%.3f Z%.3f -> X%.3f Z%.3f: the blade's holder (%.4g wide, from "
                          "%.4g behind the cutting edge) enters %.4g mm^2 of standing material near X%.3f Z%.3f "
                          "(X diameters, mm)" % ("G0" if hit.rapid else "G1", 2 * hit.start[0], hit.start[1],
                                                 2 * hit.end[0], hit.end[1], hit.holder.width, hit.holder.reach,
                                                 hit.area, 2 * hit.at[0], hit.at[1])))
    return sorted(found)


def checked_steps(record: RecordingTranslator) -> list[Step]:
    """The steps of ``record`` that make moves, plain ones with their blades
    (_fill_blades); ProgramError when there is none (both checks' start)."""
    steps = [step for step in record.steps if step.moves]
    if not steps:
        raise ProgramError("the program makes no moves: nothing to verify", 0)
    _fill_blades(steps, record.tools, record.settings.tool)
    return steps


def check_program(name: str, record: RecordingTranslator, stock_spec: Optional[StockSpec] = None,
                  rapid_rate: float = 0.0, tol: float = DEFAULT_TOL, regions: bool = True) -> ProgramCheck:
    """Sweep the recorded program over its stock and judge it (see the
    module). ``regions`` False (verify's report): the job's sections and
    each step's regions are not kept (only their areas; a gouge's region
    stays), so that memory does not grow with the steps; plot keeps them."""
    steps = checked_steps(record)
    stock, note = default_stock(steps, record.first_approach, stock_spec)
    part = stock - union_all([groove_region(ring) for step in steps for ring in step.grooves])
    ops = [_op(step, _holder(step, record.tools)) for step in steps]
    grid, step_width = layout([stock, part], ops)
    material = Material(grid, stock, falls=True)
    part_model = PartModel(grid, part)
    checks = []
    for op in ops:
        check = check_op(op, material, part_model, tol, step_width)
        if not regions:
            check.removed_region = check.leftover_region = check.unreachable_region = EMPTY_SECTION
        checks.append(check)
    if regions:
        whole = (0, len(grid))
        sections = (Section(grid, stock.rows(grid.centres)), Section(grid, part_model.rows(*whole)),
                    Section(grid, material.rows(*whole)))
    else:
        sections = (Measured(material.stock_area), Measured(part_model.area), Measured(material.area()))
    job = JobCheck(*sections, checks, [note])
    result = ProgramCheck(name, job, steps, note, [step_time(step, rapid_rate) for step in steps])
    result.findings = findings(steps, checks)
    return result


# ---------------------------------------------------------------- the report


def _step_line(name: str, step: Step, check: OpCheck, time: MachiningTime) -> str:
    what = _what(step)
    gouge = "GOUGE %.4f mm^2" % check.gouge_area if check.gouge_depth else "gouge 0"
    rapids = ", %d RAPID(S) THROUGH STOCK" % len(check.rapid_hits) if check.rapid_hits else ""
    rapids += ", HOLDER IN STOCK AT %d MOVE(S)" % len(check.holder_hits) if check.holder_hits else ""
    return "%s:%d: %s: removed %.4f mm^2, %s, leftover %.4f mm^2, unreachable %.4f mm^2%s, time %s" % (
        name, step.line, what, check.removed, gouge, check.leftover, check.unreachable, rapids, time.describe())


def report(result: ProgramCheck) -> str:
    """The text verify prints: the stock, one line per step, the total, the findings."""
    job = result.job
    lines = ["%s: %s" % (result.name, result.stock_note),
             "%s: stock %.4f mm^2, part %.4f mm^2 (half section, X the radius)"
             % (result.name, job.stock.area, job.part.area)]
    lines += [_step_line(result.name, step, check, time)
              for step, check, time in zip(result.steps, job.ops, result.times)]
    total = MachiningTime(*(sum(getattr(t, key) for t in result.times) for key in ("feed", "dwell", "rapid")),
                          any(t.rapids_timed for t in result.times))
    lines.append("%s: total: removed %.4f mm^2, gouge %.4f mm^2, leftover %.4f mm^2, unreachable %.4f mm^2, "
                 "time %s: %s" % (result.name, sum(c.removed for c in job.ops), sum(c.gouge_area for c in job.ops),
                                  sum(c.leftover for c in job.ops), sum(c.unreachable for c in job.ops),
                                  total.describe(), "ok" if result.ok else "%d PROBLEM(S)" % len(result.findings)))
    return "\n".join(lines) + "\n"
