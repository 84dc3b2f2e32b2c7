"""Where a blade touches each element of a material top, as closed-form curves.

The blade spans [u, u + width] with its front edge at level v and both front
corners rounded by ``radius`` (corner centres at (u + r, v + r) and
(u + width - r, v + r)). Its lowest level over one element is reached where
the blade's outline touches it, in one of these ways (the maximum over the
blade of f(u + s) - bottom(s) is at an element's end or where the two are
tangent, the outline being smooth):
- a vertex (an element's end, a step's top, a bump's top) under a corner
  (a cap of radius r around the vertex, shifted by the corner) or under the
  flat front (a level line);
- a line under a corner, tangent to it (the line, shifted: the left corner
  for a falling line, the right one for a rising one, both for a level one);
- an arc bulging up (a bump) under a corner, tangent to it: the corner's
  centre runs on a circle of radius R + r (a cap);
- an arc hollowed down (a bowl) under a corner, tangent inside it: a circle of
  radius R - r (a cup); a bowl narrower than the corner (R < r) pins the
  blade at its two ends, which are vertices.

A contact at the blade's very side edge (s = 0 or s = width) with the top of
a wall (a vertical step falling away from the blade) is only a touch: the
curve's interval stops EDGE_EPS short of it, so that a blade beside a wall may
slide down along it. Where the top goes on from the point touched, the next
element takes over at the same level (the two overlap by OVERLAP).
"""

import math
from typing import Dict, FrozenSet, Iterable, List, NamedTuple, Tuple

from .envelope_curves import CAP, CUP, LINE, Curve

Point = Tuple[float, float]

EDGE_EPS = 1e-9  # a blade this close to a wall only touches it
# Curves that meet where one element of the top meets the next may miss each
# other by a rounding error, the level between them dropping to whatever lies
# below: each curve runs on this far past its ends (a negligible rise).
OVERLAP = 1e-10
HALF_PI = 0.5 * math.pi
TWO_PI = 2 * math.pi


class Arc(NamedTuple):
    """A circular element of a material top: a bump (centre below it) or a
    bowl (centre above it)."""

    center: Point
    radius: float
    bump: bool


class Blade(NamedTuple):
    """The blade, and the tops of the walls of the material top it runs over:
    ``walls_left`` those with the material on their minus-u side (the top
    falls after them), ``walls_right`` those with it on their plus-u side."""

    width: float
    radius: float
    walls_left: FrozenSet[Point] = frozenset()
    walls_right: FrozenSet[Point] = frozenset()


def _curve(out: List[Curve], blade: Blade, lo: float, hi: float, contact: Tuple[float, float],
           shape: Tuple[int, float, float, float], touched: Tuple[Point, Point]) -> None:
    """Add a curve over [lo, hi]; ``contact`` is where on the blade (s) it
    touches at lo and at hi, ``touched`` the point of the top it touches
    there: a wall's top at the blade's side edge is only a touch."""
    s_lo, s_hi = contact
    if s_lo >= blade.width - EDGE_EPS and touched[0] in blade.walls_right:
        lo += EDGE_EPS
    else:
        lo -= OVERLAP
    if s_hi <= EDGE_EPS and touched[1] in blade.walls_left:
        hi -= EDGE_EPS
    else:
        hi += OVERLAP
    if hi > lo + 2 * OVERLAP:
        out.append(Curve(lo, hi, *shape))


def vertex_curves(out: List[Curve], blade: Blade, point: Point, flat_only: bool = False) -> None:
    """A vertex under the right corner, the flat front and the left corner."""
    w, r = blade.width, blade.radius
    pu, pv = point
    touched = (point, point)
    if r > 0 and not flat_only:
        _curve(out, blade, pu - w, pu - w + r, (w, w - r), (CAP, pu - w + r, pv - r, r), touched)
        _curve(out, blade, pu - r, pu, (r, 0.0), (CAP, pu - r, pv - r, r), touched)
    _curve(out, blade, pu - w + r, pu - r, (w - r, r), (LINE, pu, pv, 0.0), touched)


def line_curves(out: List[Curve], blade: Blade, p: Point, q: Point) -> None:
    """A line from p to q (q further along u) under the corner it touches."""
    w, r = blade.width, blade.radius
    slope = (q[1] - p[1]) / (q[0] - p[0])
    k = 1.0 / math.sqrt(1.0 + slope * slope)
    lift = r - r * k  # the corner's outline above the front edge at the tangent point
    if slope == 0:
        _curve(out, blade, p[0] - w + r, q[0] - r, (w - r, r), (LINE, p[0], p[1], 0.0), (p, q))
        return
    s = r + r * slope * k if slope < 0 else w - r + r * slope * k  # tangent point on the blade
    _curve(out, blade, p[0] - s, q[0] - s, (s, s), (LINE, p[0] - s, p[1] - lift, slope), (p, q))


def _angle(center: Point, point: Point, bump: bool) -> float:
    """The point's angle about the centre: in [0, pi] on a bump, [pi, 2 pi] in a bowl."""
    a = math.atan2(point[1] - center[1], point[0] - center[0])
    if bump:
        a = a + TWO_PI if a < -HALF_PI else a
        return min(max(a, 0.0), math.pi)
    a = a + TWO_PI if a < HALF_PI else a
    return min(max(a, math.pi), TWO_PI)


def arc_curves(out: List[Curve], blade: Blade, p: Point, q: Point, arc: Arc) -> None:
    """An arc from p to q (q further along u) under the corners tangent to it."""
    w, r = blade.width, blade.radius
    (cu, cv), big = arc.center, arc.radius
    a_p, a_q = _angle(arc.center, p, arc.bump), _angle(arc.center, q, arc.bump)
    if arc.bump:
        if a_q <= HALF_PI <= a_p:
            vertex_curves(out, blade, (cu, cv + big), flat_only=True)
        rho = big + r
        # Left corner: the arc's part right of its top; right corner: left of it.
        for f_lo, f_hi, shift, left in ((a_q, min(a_p, HALF_PI), r, True), (max(a_q, HALF_PI), a_p, w - r, False)):
            if f_hi - f_lo > 1e-15:
                ou = cu - shift  # centre of the corner's path, in blade positions
                c_lo, c_hi = math.cos(f_hi), math.cos(f_lo)
                contact = (r - r * c_lo, r - r * c_hi) if left else (w - r - r * c_lo, w - r - r * c_hi)
                _curve(out, blade, ou + rho * c_lo, ou + rho * c_hi, contact, (CAP, ou, cv - r, rho), (p, q))
        return
    rho = big - r
    if rho <= 1e-12:
        return  # narrower than the corner: pinned at its ends (vertices)
    three_quarters = 1.5 * math.pi
    for f_lo, f_hi, shift, left in ((a_p, min(a_q, three_quarters), r, True),
                                    (max(a_p, three_quarters), a_q, w - r, False)):
        if f_hi - f_lo > 1e-15:
            ou = cu - shift
            c_lo, c_hi = math.cos(f_lo), math.cos(f_hi)
            contact = (r + r * c_lo, r + r * c_hi) if left else (w - r + r * c_lo, w - r + r * c_hi)
            _curve(out, blade, ou + rho * c_lo, ou + rho * c_hi, contact, (CUP, ou, cv - r, rho), (p, q))


def _walls(points: List[Point]) -> Tuple[FrozenSet[Point], FrozenSet[Point]]:
    """The tops of the steps: those the top falls from going on along u
    (material on their minus-u side), and those it rises to."""
    left, right = set(), set()
    for p, q in zip(points, points[1:]):
        if abs(q[0] - p[0]) <= 1e-12:
            if q[1] < p[1]:
                left.add(p)
            elif q[1] > p[1]:
                right.add(q)
    return frozenset(left), frozenset(right)


def top_curves(points: List[Point], arcs: Dict[int, Arc], width: float, radius: float) -> List[Curve]:
    """Every contact curve of a material top: vertices ``points`` sorted by u
    (a vertical step as two points with the same u), element i from
    points[i] to points[i + 1] a line unless ``arcs`` holds it."""
    out: List[Curve] = []
    blade = Blade(width, radius, *_walls(points))
    for point in _unique(points):
        vertex_curves(out, blade, point)
    for index, (p, q) in enumerate(zip(points, points[1:])):
        if q[0] < p[0] - 1e-12:
            raise ValueError("material top must be sorted by u")
        if q[0] - p[0] <= 1e-12:
            continue  # a step: its top is a vertex
        arc = arcs.get(index)
        if arc is None:
            line_curves(out, blade, p, q)
        else:
            arc_curves(out, blade, p, q, arc)
    return out


def _unique(points: Iterable[Point]) -> List[Point]:
    seen = set()
    out = []
    for point in points:
        if point not in seen:
            seen.add(point)
            out.append(point)
    return out
