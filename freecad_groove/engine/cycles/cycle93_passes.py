"""Steps 3 and 4 of CYCLE93 fed only where material remains.

A contour or finishing pass follows the blade's envelope over a profile
(``Envelope.trace``), split at the plunge positions and at the path's
vertices. Most of it runs where the plunges have already cut. Each stretch
is decided whole: fed when the blade swept along it would cut more than
MATERIAL_MARGIN of what the plunges and the stretches fed before it left
(``MaterialTop.cuts``; a fed stretch adds the blade standing at its two
ends), skipped otherwise, or skipped without a test when the roughing passes
already ran it on the same envelope (``covered``: a finishing pass over a
stretch where the final profile is the roughing one). So a pass ends where
its last stretch that cuts ends (at the foot of a flank or a corner, not on
along a base the plunges have cut) and the blade goes straight up there. Between two fed runs the blade either
feeds on through the air of the gap or rapids out to the clearance VRT above
the contour, across, and down to a re-entry clearance above the material left
under the blade, whichever takes less time when a rapid runs RAPID_FEED_RATIO
times as fast as the feed (the machining-time benchmark's rates: 10,000 and
100 mm/min). A rapid never runs through material: out of a stretch the blade
rises through the columns it has just cut, across at the clearance, and down
only to REENTRY_CLEARANCE above the highest material the plunges left under
the blade (an upper bound of what stands), or to VRT over the contour where
that material is the contour itself (stock not cut yet).

The decisions are taken on the chorded trace, the moves written along the
exact path (``Envelope.path``, split at the same plunge positions): arcs
where the blade's corner rolls over a profile arc or round a vertex, between
the same stretch bounds the chorded trace has (``_Written``).
"""

import math
from bisect import bisect_left, bisect_right
from operator import itemgetter
from typing import TYPE_CHECKING, Callable, Dict, List, Optional, Tuple

from ..envelope import Envelope, PathPoint, on_circles, path_moves, writes_arcs
from .cycle93_constants import PATH_TOLERANCE, REENTRY_CLEARANCE_INCH, REENTRY_CLEARANCE_MM
from .cycle93_material import SIDE_EPS, MaterialTop
from .cycle93_profile import split_at

if TYPE_CHECKING:  # the geometry imports this module
    from .cycle93_geometry import GrooveGeometry

Point = Tuple[float, float]
Go = Callable[..., None]  # go(kind, u, v, turn=None): "r" rapid or "f" feed to (u, v), along a circle with turn

# Rapid rate over feed rate that decides between feeding through a gap and
# rapiding around it (the benchmark's 10,000 and 100 mm/min).
RAPID_FEED_RATIO = 100.0
# A trace point this close to a plunge position along u is at it (split_at puts them there exactly).
STEP_EPS = 1e-9
# The chorded trace's and the exact path's stretch bounds are the same when they
# lie this close along u (rounding apart, the same split points and walls).
BOUND_EPS = 1e-6


def _groups(pts: List[Point], steps: List[float]) -> List[Tuple[int, int]]:
    """(first, last) point indexes of the stretches between the plunge
    positions ``steps`` (ascending): the trace is split there (``split_at``),
    so each stretch takes at most one tooth. One point is one stretch."""
    inner = _at_steps(pts, steps) if len(pts) > 3 * len(steps) else None  # by step where the points outnumber them
    if inner is None:
        inner = []
        for k in range(1, len(pts) - 1):
            u = pts[k][0]
            i = bisect_left(steps, u - STEP_EPS)
            if i < len(steps) and steps[i] <= u + STEP_EPS:
                inner.append(k)
    bounds = [0] + inner + [len(pts) - 1]
    return list(zip(bounds, bounds[1:])) if len(pts) > 1 else [(0, 0)]


def _at_steps(pts: List[Point], steps: List[float]) -> Optional[List[int]]:
    """The inner point indexes (not the first, not the last) within STEP_EPS
    of one of ``steps``, ascending, for a trace whose u never turns back (a
    pass), found by step (a bisection each, then each point near it tested as
    ``_groups`` does); None for another trace."""
    us = list(map(itemgetter(0), pts))
    last = len(us) - 1
    if us == sorted(us):
        ordered, flip = us, False
    elif us == sorted(us, reverse=True):
        ordered, flip = us[::-1], True
    else:
        return None
    found = set()
    count = len(steps)
    for s in steps:
        near = 1e-6 + abs(s) * 1e-12  # far wider than STEP_EPS and its rounding: each point in it is tested
        for j in range(bisect_left(ordered, s - near), bisect_right(ordered, s + near)):
            k = last - j if flip else j
            if 0 < k < last and k not in found:
                u = us[k]
                i = bisect_left(steps, u - STEP_EPS)
                if i < count and steps[i] <= u + STEP_EPS:
                    found.add(k)
    return sorted(found)


def _bounds(groups: List[Tuple[int, int]]) -> List[int]:
    """The point indexes where the stretches ``groups`` (``_groups``) begin and end."""
    return [first for first, _last in groups] + [groups[-1][1]]


class _Written:
    """What a pass writes between two stretch bounds of its chorded trace
    ``pts``: the moves along the exact path ``exact`` (split at ``steps``
    when first asked) between the same bounds (its arcs), or, where the two
    do not line up bound for bound or an arc of the path does not start and
    end on its circle (not seen; a guard), the chords themselves."""

    def __init__(self, pts: List[Point], groups: List[Tuple[int, int]], exact: Optional[List[PathPoint]],
                 steps: List[float], runs: Optional[List[List[int]]] = None) -> None:
        self.pts, self.groups, self.exact, self.steps = pts, groups, exact, steps
        self._index: Optional[Dict[int, int]] = None
        lo, hi = -math.inf, math.inf  # what is fed: the runs and, at most, the gaps between them (None: all)
        if runs:
            lo, hi = sorted((pts[runs[0][0]][0], pts[runs[-1][1]][0]))
        if not exact or runs == [] or not writes_arcs(exact, PATH_TOLERANCE, lo + BOUND_EPS, hi - BOUND_EPS):
            self.exact = None  # no arc to write there: the chords are what the exact path would write

    @property
    def index(self) -> Dict[int, int]:
        """The exact path's point index at each stretch bound of ``pts`` (empty: they do not line up)."""
        if self._index is None:
            self._index = {}
            if not self.exact:
                return self._index
            exact = self.exact = split_at(self.exact, self.steps)
            if on_circles(exact):
                chorded, along = _bounds(self.groups), _bounds(_groups(exact, self.steps))
                if len(chorded) == len(along) and all(abs(self.pts[i][0] - exact[j][0]) <= BOUND_EPS
                                                      for i, j in zip(chorded, along)):
                    self._index = dict(zip(chorded, along))
        return self._index

    def point(self, i: int) -> Point:
        """The point written at the chorded trace's bound ``i``."""
        return self.exact[self.index[i]] if self.index else self.pts[i]

    def feed(self, go: Go, i: int, j: int) -> None:
        """Feed from bound ``i`` to bound ``j``: along the exact path (path_moves), or its chords."""
        index = self.index
        if not index:
            for q in self.pts[i + 1:j + 1]:
                go("f", q[0], q[1])
            return
        a, b = index[i], index[j]
        for q, turn in path_moves(self.exact[a], self.exact[a + 1:b + 1], PATH_TOLERANCE):
            go("f", q[0], q[1], turn)


def _element(env: Envelope, x: float) -> Tuple[Point, Point, object]:
    """The element of the envelope's top over column x (not at a vertex)."""
    pts = env.points
    k = max(bisect_right(pts, (x, math.inf)) - 1, 0)
    return pts[k], pts[min(k + 1, len(pts) - 1)], env.arcs.get(k)


def _same_profile(a: Envelope, b: Envelope, lo: float, hi: float) -> bool:
    """Whether the two envelopes' tops are made of the same elements over the
    columns (lo, hi), vertices and vertical steps included."""
    xs = sorted({lo, hi}.union(u for u, _v in a.points + b.points if lo < u < hi))
    for x in xs[1:-1]:
        if [p for p in a.points if p[0] == x] != [p for p in b.points if p[0] == x]:
            return False
    return all(_element(a, 0.5 * (x0 + x1)) == _element(b, 0.5 * (x0 + x1)) for x0, x1 in zip(xs, xs[1:]))


def covered(material: MaterialTop, env: Envelope, lo: float, hi: float) -> bool:
    """Whether the roughing passes already ran the blade positions [lo, hi]
    on this same envelope: a pass on another envelope (the finishing one)
    whose top is the roughing top under the blade there would retrace them."""
    if material.passed is None or material.passed[0] is env:
        return False
    rough, a, b = material.passed
    w = env.width
    return a - STEP_EPS <= lo and hi <= b + STEP_EPS and _same_profile(env, rough, lo + SIDE_EPS, hi + w - SIDE_EPS)


def _stretches(pts: List[Point], groups: List[Tuple[int, int]], material: MaterialTop, width: float,
               radius: float, top: List[Point], env: Envelope, entry: Callable[[Point], float],
               corners: List[float]) -> Tuple[List[List[int]], List[float]]:
    """[first, last] point indexes of the runs of stretches that cut
    something, in pass order, and the level the blade may rapid down to over
    each run's first point (``entry``, taken before the run cuts). A stretch
    is tested whole (the blade swept along its lower hull, below it; MaterialTop.cuts) against
    what the plunges and the stretches fed before it left: the blade standing
    at the end of each fed stretch that ends at one of the path's vertices
    (u in ``corners``, sorted: the foot of a flank or a corner, where a pass
    may have cut all there is before the next plunge position) is added to
    ``material``. A trace of one
    point (a blade as wide as the opening) is a plunge to it: [0, 0] when
    material stands above the blade there."""
    runs: List[List[int]] = []
    entries: List[float] = []
    for first, last in groups:
        part = pts[first:last + 1]
        lo, hi = min(part)[0], max(part)[0]  # the least and greatest u (points compare by u first)
        if covered(material, env, lo, hi) or not material.cuts(part, width, radius, top):
            continue
        if runs and runs[-1][1] == first:
            runs[-1][1] = last
        else:
            entries.append(entry(part[0]))
            runs.append([first, last])
        u, v = part[-1]
        k = bisect_left(corners, u - STEP_EPS)
        if k < len(corners) and corners[k] <= u + STEP_EPS:
            material.stand_blade(u, v, width, radius)  # cut for the stretches after
    return runs, entries


def _entry(geo: "GrooveGeometry", material: MaterialTop, at: Point) -> float:
    """Level the blade may rapid down to above ``at``: REENTRY_CLEARANCE (at
    most VRT) over the highest material under it, never below ``at``; VRT
    over the contour where that material is the contour itself (stock not
    cut yet: VRT is the machinist's clearance over it, as the plunges enter)."""
    u, v = at
    w = geo.tool.width
    stand = max(material.stand(u, v, w), 0.0)
    gap = min(geo.params["VRT"], REENTRY_CLEARANCE_MM if geo.metric else REENTRY_CLEARANCE_INCH)
    clearance = geo.clearance(u)
    if v + stand >= geo.contour_top(u) - PATH_TOLERANCE:
        return clearance
    return min(v + stand + gap, clearance)


def _length(pts: List[Point]) -> float:
    return sum(math.dist(p, q) for p, q in zip(pts, pts[1:]))


def feed_where_material(geo: "GrooveGeometry", pts: List[Point], go: Go, material: MaterialTop,
                        steps: List[float], top: List[Point], env: Envelope, rough: bool,
                        exact: Optional[List[PathPoint]] = None, vertices: Optional[List[Point]] = None) -> None:
    """Feed the stretches of the trace ``pts`` on the envelope of ``top``
    that cut, linked the cheaper way; the blade comes from and goes back to
    the clearance. A roughing pass (``rough``) is noted in ``material``.
    ``exact``: the same pass as an exact path (arcs), not split: the moves
    follow it, split at ``steps`` too (``_Written``); None: the chords.
    ``vertices``: the path's vertices (None: ``exact``'s points, else ``pts``)."""
    w, r = geo.tool.width, geo.tool.corner_radius
    # Stretches also part at the path's vertices (where a flank, a corner or the base begins): the moves are
    # the same, but a stretch that runs on over what the ones before it cut is tested, and skipped, alone.
    corners = sorted({u for u, _v in (vertices or exact or pts)})
    steps = sorted(set(steps).union(corners))
    pts = split_at(pts, steps)
    groups = _groups(pts, steps)
    runs, entries = _stretches(pts, groups, material, w, r, top, env, lambda at: _entry(geo, material, at), corners)
    written = _Written(pts, groups, exact, steps, runs)
    if rough:
        us = [min(pts)[0], max(pts)[0]] + ([material.passed[1], material.passed[2]] if material.passed else [])
        material.note_pass(env, min(us), max(us))
    here = None  # the point the blade stands on, None at the clearance
    for (first, last), entry in zip(runs, entries):
        start = pts[first]
        if here is not None:
            gap = pts[here:first + 1]
            end = pts[here]
            around = (geo.clearance(end[0]) - end[1]) + math.dist(
                (end[0], geo.clearance(end[0])), (start[0], geo.clearance(start[0]))
            ) + (geo.clearance(start[0]) - entry)
            if around / RAPID_FEED_RATIO + (entry - start[1]) < _length(gap):
                go("r", end[0], geo.clearance(end[0]))
                here = None
            else:
                written.feed(go, here, first)
        if here is None:
            go("r", start[0], geo.clearance(start[0]))
            go("r", start[0], entry)
            go("f", *written.point(first))
        written.feed(go, first, last)
        here = last
    if here is not None:
        end = pts[here]
        go("r", end[0], geo.clearance(end[0]))
