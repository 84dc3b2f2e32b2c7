"""Judging a simulation against the groove it should have cut: gouge,
material left within the blade's reach, a target the blade cannot make,
rapid collisions and dwell mismatches (see the package docstring).

Geometry is shapely (z, x), x the radius.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from shapely import Geometry

from freecad_groove.engine.moves import GroovingTool

from .depth import depth_inside, farthest_from
from .overlay import EMPTY, NOISE_AREA, QUAD_SEGS, area, difference, intersection
from .reach import reachable_region
from .sweep import DwellMismatch, RapidCollision, SimulationResult


def _bounds_text(geom: Geometry) -> str:
    zmin, xmin, zmax, xmax = geom.bounds
    return "Z[%.4f, %.4f] X(radius)[%.4f, %.4f]" % (zmin, zmax, xmin, xmax)


@dataclass
class Verdict:
    tol: float
    gouge: float  # mm of removed material beyond the target (0.0 if none)
    gouge_region: Geometry  # removed material deeper than tol inside stock minus target
    incomplete_area: float  # mm^2 of target left standing outside the reach allowance
    incomplete_depth: float  # mm: its thickest part, measured to the nearest cut/air
    incomplete_region: Geometry  # the part of it thicker than tol (empty when complete)
    unreachable: Geometry  # part of the target the tool cannot reach (the allowance)
    unreachable_depth: float  # mm: farthest point of it from where the tool can reach
    corner_radius: float
    rapid_collisions: list[RapidCollision] = field(default_factory=list)
    dwell_mismatches: list[DwellMismatch] = field(default_factory=list)
    label: str | None = None

    @property
    def gouged(self) -> bool:
        return self.gouge > 0.0

    @property
    def incomplete(self) -> bool:
        return self.incomplete_depth > self.tol

    @property
    def infeasible(self) -> bool:
        """The target has material no placement of the tool reaches, beyond
        what a corner radius leaves in a right-angled (or wider) corner: a
        groove narrower than the blade, an undercut, an acute corner. The
        program cannot be judged complete against it: fix the target (or the
        cycle should have refused)."""
        return self.unreachable_depth > self.corner_radius + self.tol

    @property
    def ok_within_reach(self) -> bool:
        """ok, except that the target may be infeasible for the blade."""
        return not (self.gouged or self.incomplete or self.rapid_collisions or self.dwell_mismatches)

    @property
    def ok(self) -> bool:
        return self.ok_within_reach and not self.infeasible

    def describe(self) -> str:
        head = (self.label + ": ") if self.label else ""
        if self.ok:
            return head + "ok (tol %g mm)" % self.tol
        if self.ok_within_reach:
            lines = [head + "program ok within the blade's reach, but the target is not (tol %g mm):" % self.tol]
        else:
            lines = [head + "program fails the groove check (tol %g mm):" % self.tol]
        if self.gouged:
            lines.append(
                "  GOUGE %.4f mm deep into material outside the target, %.6g mm^2 of it deeper than tol, in %s"
                % (self.gouge, area(self.gouge_region), _bounds_text(self.gouge_region))
            )
        if self.incomplete:
            lines.append(
                "  INCOMPLETE: %.6g mm^2 of reachable target left standing, up to %.4f mm thick, in %s"
                % (self.incomplete_area, self.incomplete_depth, _bounds_text(self.incomplete_region))
            )
        if self.infeasible:
            lines.append(
                "  TARGET INFEASIBLE for this tool: %.6g mm^2 of it is out of the tool's reach, up to %.4f mm"
                " from anywhere the tool can be (corner radius %g), in %s"
                % (area(self.unreachable), self.unreachable_depth, self.corner_radius, _bounds_text(self.unreachable))
            )
        for c in self.rapid_collisions:
            lines.append("  RAPID COLLISION: " + c.describe())
        for d in self.dwell_mismatches:
            lines.append("  DWELL: " + d.describe())
        return "\n".join(lines)

    __str__ = describe


def _gouge(stock: Geometry, target: Geometry, removed: Geometry, tol: float) -> tuple[float, Geometry]:
    """Removed material that had to stay, measured as depth into it (a skim
    along the stock's surface far from the groove is as deep as the skim, not
    as far as the groove). Returns (depth, the part deeper than tol); the
    depth is 0.0 when no part is deeper than tol."""
    keep = difference(stock, target)
    cut_keep = intersection(removed, keep)
    if area(cut_keep) > NOISE_AREA:
        gouge, excess = depth_inside(cut_keep, keep, tol)
        if excess.is_empty:
            gouge = 0.0
    else:
        gouge, excess = 0.0, EMPTY
    return gouge, excess


def _unreachable(
    target: Geometry, stock: Geometry, tool: GroovingTool, plunge: str, tol: float, reach: str
) -> tuple[Geometry, float]:
    """The part of the target the tool cannot reach, and how far it lies from
    where the tool can reach."""
    reachable = reachable_region(target, stock, tool, plunge, tol, reach)
    unreachable = difference(target, reachable)
    if area(unreachable) > NOISE_AREA:
        unreachable_depth = farthest_from(unreachable, reachable)
    else:
        unreachable_depth = 0.0
    return unreachable, unreachable_depth


def _leftover(
    target: Geometry, remaining: Geometry, unreachable: Geometry, tol: float
) -> tuple[Geometry, float, Geometry]:
    """Target still standing less the reach allowance (unreachable grown by
    tol): (it, its depth inside the remaining stock, its part deeper than tol)."""
    left = intersection(target, remaining)
    if not unreachable.is_empty:
        left = difference(left, unreachable.buffer(tol, quad_segs=QUAD_SEGS))
    if area(left) > NOISE_AREA:
        depth, core = depth_inside(left, remaining, tol)
    else:
        depth, core = 0.0, EMPTY
    return left, depth, core


def check_groove(
    result: SimulationResult,
    target: Geometry,
    tool: GroovingTool | None = None,
    tol: float = 0.001,
    label: str | None = None,
    plunge: str | None = None,
    reach: str = "blade",
) -> Verdict:
    """Judge a simulation against ``target``: the region (shapely (z, x)) the
    program must remove. Target area outside the stock is simply air.

    gouge       removed material of (stock - target) farther than tol from
                both the target and the air: the largest such depth (mm),
                i.e. max over removed points of the distance to the nearest
                point of target or air; 0.0 when none is deeper than tol.
    incomplete  target material still standing, minus the reach allowance
                unreachable_region(...).buffer(tol); flagged when some of it
                lies more than tol from every cut surface and the air.
    infeasible  the unreachable part of the target reaches farther than
                corner_radius + tol from where the tool can be.
    rapid       the simulation's rapid collisions; dwell mismatches too.
    """
    tool = tool if tool is not None else result.tool
    plunge = plunge if plunge is not None else result.plunge
    if tool is None or plunge is None:
        raise ValueError("check_groove needs the tool and plunge direction")
    gouge, excess = _gouge(result.stock, target, result.removed, tol)
    unreachable, unreachable_depth = _unreachable(target, result.stock, tool, plunge, tol, reach)
    left, depth, core = _leftover(target, result.remaining, unreachable, tol)
    return Verdict(
        tol=tol,
        gouge=gouge,
        gouge_region=excess,
        incomplete_area=area(left),
        incomplete_depth=depth,
        incomplete_region=core,
        unreachable=unreachable,
        unreachable_depth=unreachable_depth,
        corner_radius=float(tool.corner_radius),
        rapid_collisions=list(result.rapid_collisions),
        dwell_mismatches=list(result.dwell_mismatches),
        label=label,
    )


def assert_clean(verdict: Verdict, allow_infeasible: bool = False) -> Verdict:
    """Raise AssertionError with the verdict's description unless it is ok.

    allow_infeasible: accept a target the blade cannot fully reach (judge the
    program only on gouge, leftover within reach, rapids and dwells), for
    cycles whose own definition leaves such material (e.g. a flat blade in a
    V-shaped floor)."""
    good = verdict.ok_within_reach if allow_infeasible else verdict.ok
    if not good:
        raise AssertionError(verdict.describe())
    return verdict
