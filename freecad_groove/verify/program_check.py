"""The command line's ``verify``: a whole program's moves (cycle expansions
and plain G0/G1/G2/G3 blocks) swept over the stock and judged against the
part the program declares, with turning.check_ops doing the bookkeeping.

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
from dataclasses import dataclass, field
from typing import Optional

from shapely import Geometry
from shapely.geometry import MultiPolygon, Polygon, box

from freecad_groove.engine.errors import ProgramError
from freecad_groove.engine.moves import FEED, MINUS_X, MINUS_Z, PLUS_X, RAPID
from freecad_groove.engine.tool_table import blade_for

from .blade import outline_at_origin, swept_area
from .machining_time import Feeds, MachiningTime, feed_seconds, rapid_seconds
from .overlay import NOISE_AREA, area, difference, intersection, union, union_all
from .program_record import RecordingTranslator, SpeedState, Step, mm_blade
from .section import bar_section, groove_region
from .turning import DEFAULT_TOL, GrooveRun, JobCheck, OpCheck, OpInput, check_op

Point = tuple[float, float]
CHUCK_MARGIN = 10.0  # mm of bar below the lowest Z the program reaches (the chuck end)
WINDOW_MARGIN = 1.0  # mm around what a step's blade sweeps: the window its check works in


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


def _rings(steps: list[Step], plunge: str) -> list[list[Point]]:
    return [ring for step in steps if step.plunge == plunge for ring in step.grooves]


def default_stock(steps: list[Step], approach: Optional[Point], spec: Optional[StockSpec]) -> tuple[Geometry, str]:
    """The stock (shapely (z, x)) and how it was derived (see the module)."""
    if approach is None:
        raise ProgramError("no approach point (a G0 to a known X and Z) to derive the stock from: give --stock", 0)
    points = [(m.x, m.z) for step in steps for m in step.moves] + [p for s in steps for r in s.grooves for p in r]
    low = min(z for _x, z in points) - CHUCK_MARGIN
    feeds = [m.z for step in steps for m in step.moves if m.kind == FEED]
    high = max([approach[1]] + feeds + [z for step in steps for ring in step.grooves for _x, z in ring])
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
    stock = difference(bar_section(radius, low, high), bar_section(bore, low, high)) if bore > 0 else \
        bar_section(radius, low, high)
    air = [groove_region(ring) for step in steps for ring in step.air]
    if air:
        stock = difference(stock, union_all(air))
    note = "stock: bar D%.3f%s from Z%.3f to Z%.3f (diameter %s)" % (
        2 * radius, " bore D%.3f" % (2 * bore) if bore > 0 else "", low, high, how)
    return stock, note


def held_by_chuck(chuck_z: float):
    """The standing stock still connected to the chuck end ``chuck_z`` (pieces cut free fall away)."""
    def attached(standing: Geometry) -> Geometry:
        if not isinstance(standing, MultiPolygon):
            return standing
        held = [piece for piece in standing.geoms if piece.bounds[0] <= chuck_z + 1e-6]
        return union_all(held) if held else Polygon()
    return attached


# ---------------------------------------------------------------- steps to ops


def _fill_blades(steps: list[Step], tools, default_blade) -> None:
    """Plain steps: the blade of their tool, held as the nearest cycle holds it."""
    for index, step in enumerate(steps):
        if step.cycle:
            continue
        try:
            step.blade = mm_blade(blade_for(step.tool, tools, default_blade), step.scale)
        except ProgramError as exc:
            raise ProgramError("verify needs the blade cutting these moves: %s" % exc, step.line) from None
        before = [s for s in steps[:index] if s.cycle]
        after = [s for s in steps[index + 1:] if s.cycle]
        nearest = before[-1] if before else after[0] if after else None
        step.plunge = nearest.plunge if nearest is not None else MINUS_X


def _op(step: Step) -> OpInput:
    rings = step.grooves or [[]]
    runs = [GrooveRun(step.moves if k == 0 else [], step.lines if k == 0 else [], step.blade, step.plunge, ring)
            for k, ring in enumerate(rings)]
    return OpInput(step.label, step.start, runs)


def _feeds(speed: SpeedState, rapid_rate: float) -> Feeds:
    max_rpm = speed.max_rpm if speed.max_rpm else math.inf
    return Feeds(speed.feed or 0.0, speed.per_rev, speed.rpm, speed.surface_speed, max_rpm, rapid_rate, rapid_rate)


def step_time(step: Step, rapid_rate: float) -> MachiningTime:
    """The step's time, each move at the feed and speeds in force for it."""
    position, cut, dwell, rapid = step.start, 0.0, 0.0, 0.0
    for move, speed in zip(step.moves, step.speeds):
        end = (move.x, move.z)
        feeds = _feeds(speed, rapid_rate)
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
    position = step.start
    for move, line in zip(step.moves, step.lines):
        end = (move.x, move.z)
        if move.kind == FEED and area(intersection(swept_area(step.blade, step.plunge, position, end),
                                                   check.gouge_region)) > NOISE_AREA:
            return line
        if move.kind != "G4":
            position = end
    return step.line


def _what(step: Step) -> str:
    """How the report names a step."""
    if step.cycle:
        return step.label
    first, last = step.lines[0], step.lines[-1]
    return "the moves of line %d" % first if first == last else "the moves of lines %d-%d" % (first, last)


def _findings(steps: list[Step], checks: list[OpCheck]) -> list[tuple[int, str]]:
    found = []
    for step, check in zip(steps, checks):
        if check.gouge_depth:
            found.append((_gouge_line(step, check),
                          "gouge: %s cut %.4f mm^2 of the part outside the declared grooves, %.4f mm deep at "
                          "X%.3f Z%.3f (X a diameter)" % (_what(step), check.gouge_area, check.gouge_depth,
                                                          2 * check.gouge_at[0], check.gouge_at[1])))
        for hit in check.rapid_hits:
            found.append((hit.command, "collision: G0 X%.3f Z%.3f -> X%.3f Z%.3f passes through %.4g mm^2 of "
                          "standing stock near X%.3f Z%.3f (X diameters)" % (
                              2 * hit.start[0], hit.start[1], 2 * hit.end[0], hit.end[1], hit.area,
                              2 * hit.at[0], hit.at[1])))
    return sorted(found)


def _window(step: Step) -> Geometry:
    """A box (z, x) holding everything the step's blade sweeps and its grooves (WINDOW_MARGIN more)."""
    base = outline_at_origin(step.blade, step.plunge)
    points = [step.start] + [(m.x, m.z) for m in step.moves] + [p for ring in step.grooves for p in ring]
    xs, zs = [x for x, _z in points], [z for _x, z in points]
    return box(min(zs) + base[:, 0].min() - WINDOW_MARGIN, min(xs) + base[:, 1].min() - WINDOW_MARGIN,
               max(zs) + base[:, 0].max() + WINDOW_MARGIN, max(xs) + base[:, 1].max() + WINDOW_MARGIN)


def _held_in_window(rest: Geometry, window: Geometry, held):
    """``held`` for the stock inside ``window``, the stock outside it being ``rest``:
    a connected piece inside is held (the pieces that fell are gone already)."""
    def attached(local: Geometry) -> Geometry:
        if not isinstance(local, MultiPolygon):
            return local
        return intersection(held(union(rest, local)), window)
    return attached


def _sweep_steps(steps: list[Step], stock: Geometry, part: Geometry, tol: float) -> tuple[list[OpCheck], Geometry]:
    """turning.check_op on each step in turn, inside the step's window (so
    that a step's work does not grow with the grooves already cut); pieces
    cut free of the chuck end are dropped after each step."""
    held = held_by_chuck(stock.bounds[0])
    standing, checks = stock, []
    for step in steps:
        window = _window(step)
        local, rest = intersection(standing, window), difference(standing, window)
        # the part around the window by as much again: a gouge's depth is measured to its true surface
        zmin, xmin, zmax, xmax = window.bounds
        grow = (zmax - zmin) + (xmax - xmin)
        near = intersection(part, box(zmin - grow, xmin - grow, zmax + grow, xmax + grow))
        check, after = check_op(_op(step), local, near, tol, _held_in_window(rest, window, held))
        standing = held(union(rest, after))
        checks.append(check)
    return checks, standing


def check_program(name: str, record: RecordingTranslator, stock_spec: Optional[StockSpec] = None,
                  rapid_rate: float = 0.0, tol: float = DEFAULT_TOL) -> ProgramCheck:
    """Sweep the recorded program over its stock and judge it (see the module)."""
    steps = [step for step in record.steps if step.moves]
    if not steps:
        raise ProgramError("the program makes no moves: nothing to verify", 0)
    _fill_blades(steps, record.tools, record.settings.tool)
    stock, note = default_stock(steps, record.first_approach, stock_spec)
    grooves = union_all([groove_region(ring) for step in steps for ring in step.grooves] or [Polygon()])
    part = difference(stock, grooves)
    checks, remaining = _sweep_steps(steps, stock, part, tol)
    result = ProgramCheck(name, JobCheck(stock, part, remaining, checks, [note]), steps, note,
                          [step_time(step, rapid_rate) for step in steps])
    result.findings = _findings(steps, checks)
    return result


# ---------------------------------------------------------------- the report


def _step_line(name: str, step: Step, check: OpCheck, time: MachiningTime) -> str:
    what = _what(step)
    gouge = "GOUGE %.4f mm^2" % check.gouge_area if check.gouge_depth else "gouge 0"
    rapids = ", %d RAPID(S) THROUGH STOCK" % len(check.rapid_hits) if check.rapid_hits else ""
    return "%s:%d: %s: removed %.4f mm^2, %s, leftover %.4f mm^2, unreachable %.4f mm^2%s, time %s" % (
        name, step.line, what, check.removed, gouge, check.leftover, check.unreachable, rapids, time.describe())


def report(result: ProgramCheck) -> str:
    """The text verify prints: the stock, one line per step, the total, the findings."""
    job = result.job
    lines = ["%s: %s" % (result.name, result.stock_note),
             "%s: stock %.4f mm^2, part %.4f mm^2 (half section, X the radius)"
             % (result.name, area(job.stock), area(job.part))]
    lines += [_step_line(result.name, step, check, time)
              for step, check, time in zip(result.steps, job.ops, result.times)]
    total = MachiningTime(*(sum(getattr(t, key) for t in result.times) for key in ("feed", "dwell", "rapid")),
                          any(t.rapids_timed for t in result.times))
    lines.append("%s: total: removed %.4f mm^2, gouge %.4f mm^2, leftover %.4f mm^2, unreachable %.4f mm^2, "
                 "time %s: %s" % (result.name, sum(c.removed for c in job.ops), sum(c.gouge_area for c in job.ops),
                                  sum(c.leftover for c in job.ops), sum(c.unreachable for c in job.ops),
                                  total.describe(), "ok" if result.ok else "%d PROBLEM(S)" % len(result.findings)))
    return "\n".join(lines) + "\n"
