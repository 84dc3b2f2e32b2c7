"""The command line's ``verify`` on shapely polygons: the tests' second
oracle for program_check.py (the column model), with turning_shapely doing
the bookkeeping; the stock, the report and the findings are program_check's.
"""

from __future__ import annotations

from typing import Optional

from shapely import Geometry
from shapely.geometry import MultiPolygon, Polygon, box

from freecad_groove.engine.moves import FEED

from .blade import outline_at_origin, swept_area
from .overlay import NOISE_AREA, area, difference, intersection, union, union_all
from .program_check import ProgramCheck, StockSpec, _op, checked_steps, default_stock, findings, step_time
from .program_record import RecordingTranslator, Step
from .section import bar_section, groove_region
from .turning import DEFAULT_TOL, JobCheck, OpCheck
from .turning_shapely import check_op

Point = tuple[float, float]
WINDOW_MARGIN = 1.0  # mm around what a step's blade sweeps: the window its check works in


def held_by_chuck(chuck_z: float):
    """The standing stock still connected to the chuck end ``chuck_z`` (pieces cut free fall away)."""
    def attached(standing: Geometry) -> Geometry:
        if not isinstance(standing, MultiPolygon):
            return standing
        held = [piece for piece in standing.geoms if piece.bounds[0] <= chuck_z + 1e-6]
        return union_all(held) if held else Polygon()
    return attached


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
    steps = checked_steps(record)
    stock, note = default_stock(steps, record.first_approach, stock_spec, bar_section, groove_region, union_all,
                                difference)
    grooves = union_all([groove_region(ring) for step in steps for ring in step.grooves] or [Polygon()])
    part = difference(stock, grooves)
    checks, remaining = _sweep_steps(steps, stock, part, tol)
    result = ProgramCheck(name, JobCheck(stock, part, remaining, checks, [note]), steps, note,
                          [step_time(step, rapid_rate) for step in steps])
    result.findings = findings(steps, checks, _gouge_line)
    return result


