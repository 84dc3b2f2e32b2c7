"""The turning check on shapely regions: the oracle the tests hold the
column model (turning.py) to. The same figures per op (see turning.py) from
shapely overlays: exact polygons, slower, and growing faster than the moves.

Geometry is shapely (z, x), x the radius; positions are (x, z).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Optional

from shapely import Geometry

from .depth import depth_inside
from .machining_time import machining_time
from .overlay import EMPTY, NOISE_AREA, QUAD_SEGS, area, difference, intersection, union, union_all
from .reach import reachable_region
from .section import groove_region, part_to_leave
from .sweep import simulate
from .turning import DEFAULT_TOL, JobCheck, OpCheck, OpInput, RapidHit

Point = tuple[float, float]


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
