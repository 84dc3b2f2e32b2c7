"""What material a CYCLE93 expansion has left so far, so that the contour and
finishing passes (steps 3 and 4) feed only where there is something to cut.

The blade only moves paraxially and the profile is a function of u, so the
material still standing is exactly what lies below a height field: the lowest
level cleared in each column u of the groove frame. ``MaterialTop`` keeps an
upper bound of it as a piecewise-linear function of u (vertical steps as two
points at the same u), built from arithmetic on the moves, never a grid:

- it starts as the contour line;
- a plunge slot lowers it to the blade's outline at the slot's bottom: flat
  across the blade's front, each rounded corner as a polygon inscribed in its
  arc, no further than ``MATERIAL_MARGIN`` from it (the polygon lies inside
  the blade, so the bound stays an upper bound: more material is assumed,
  never less);
- a fed move of a contour pass lowers it to the lower hull of that outline
  at both ends of the move (the blade is convex: it sweeps their hull).

A pass move cuts something when the field reaches into the region that
outline sweeps. That region holds everything the real blade sweeps except a
skin at most MATERIAL_MARGIN thick along its corners, so a move found to cut
nothing would have taken at most that skin; and as the same outline clears
and tests, a blade passing again where it has already been finds nothing.
Everything is arithmetic on a few points per move, no grid.
"""

import math
from bisect import bisect_left, bisect_right
from functools import lru_cache
from typing import List, Tuple

Point = Tuple[float, float]

# Material thinner than this (mm or in) under a pass counts as already cut: the
# corner polygons' distance from the arcs, a little over the passes' own path
# tolerance (PATH_TOLERANCE) and half the 0.001 a program writes.
MATERIAL_MARGIN = 0.0005
# The field standing less than this into the swept region is float noise (the
# passes' points and the plunges' bottoms come from different computations).
CUT_NOISE = 1e-6
# A blade side within this of a wall only slides along it.
SIDE_EPS = 1e-7


def _interp(u0: float, v0: float, u1: float, v1: float, u: float) -> float:
    if u1 - u0 <= 0:
        return min(v0, v1)
    return v0 + (v1 - v0) * (u - u0) / (u1 - u0)


class MaterialTop:
    """An upper bound of the material's top over u, lowered as the blade cuts."""

    def __init__(self, lo: float, hi: float, slope: float) -> None:
        self.us: List[float] = [lo, hi]
        self.vs: List[float] = [slope * lo, slope * hi]

    def _values(self, u: float) -> Tuple[float, float]:
        """(value just left of u, value just right of u)."""
        us, vs = self.us, self.vs
        i, j = bisect_left(us, u), bisect_right(us, u)
        if i < j:  # breakpoints at u itself
            return vs[i], vs[j - 1]
        if i == 0 or i >= len(us):
            return math.inf, math.inf  # outside the field: assume material
        v = _interp(us[i - 1], vs[i - 1], us[i], vs[i], u)
        return v, v

    def _highest(self, a: float, b: float) -> float:
        """The field's highest value over [a, b]."""
        us, vs = self.us, self.vs
        i, j = bisect_right(us, a), bisect_left(us, b)
        inner = max(vs[i:j]) if j > i else -math.inf
        return max(inner, max(self._values(a)), max(self._values(b)))

    def _columns(self, blade: List[Point], i: int, j: int) -> List[Tuple[float, float, float, float]]:
        """(u, field just left of u, field just right of u, blade level at u)
        at every breakpoint us[i:j] of the field and every point of ``blade``
        (by increasing u, no two at the same u), in order of u: one walk along
        both, no search per column. The field's points us[i:j] lie within the
        blade's u-range."""
        us, vs = self.us, self.vs
        last = len(us)
        out = []
        fi, bi, nb = i, 0, len(blade)
        while fi < j or bi < nb:
            ub = blade[bi][0] if bi < nb else math.inf
            uf = us[fi] if fi < j else math.inf
            if uf <= ub:
                u, k = uf, fi
                while fi < j and us[fi] == u:
                    fi += 1
                left, right = vs[k], vs[fi - 1]
            else:
                u = ub
                if 0 < fi < last:
                    left = right = _interp(us[fi - 1], vs[fi - 1], us[fi], vs[fi], u)
                else:
                    left = right = math.inf  # outside the field: assume material
            if ub == u:
                g = blade[bi][1]
                bi += 1
            else:
                (u0, v0), (u1, v1) = blade[bi - 1], blade[bi]
                g = _interp(u0, v0, u1, v1, u)
            out.append((u, left, right, g))
        return out

    def excess(self, blade: List[Point], enough: float = math.inf) -> float:
        """Highest stand of the field above the piecewise-linear ``blade``
        level (points by increasing u) strictly inside the blade's u-range
        (SIDE_EPS in from its ends); the search stops once a stand above
        ``enough`` is found."""
        a, b = blade[0][0] + SIDE_EPS, blade[-1][0] - SIDE_EPS
        level = _Level(blade)
        best = max(self._values(a)[1] - level(a), self._values(b)[0] - level(b))
        if best > enough:
            return best
        us = self.us
        i, j = bisect_right(us, a), bisect_left(us, b)
        for u, left, right, g in self._columns(blade, i, j):
            if a < u < b:
                best = max(best, left - g, right - g)
                if best > enough:
                    return best
        return best

    def lower(self, blade: List[Point]) -> None:
        """The field becomes min(field, blade) over the blade's u-range."""
        a, b = blade[0][0], blade[-1][0]
        if b <= a:
            return
        us, vs = self.us, self.vs
        i, j = bisect_left(us, a), bisect_right(us, b)  # the points replaced
        a_left, b_right = self._values(a)[0], self._values(b)[1]
        new = [(a, a_left)]
        prev = None  # (u, field just right of u, blade at u)
        for u, left, right, g in self._columns(blade, i, j):
            if prev is not None:
                d0, d1 = prev[1] - prev[2], left - g
                if d0 * d1 < 0:  # field and blade cross between two columns
                    t = d0 / (d0 - d1)
                    new.append((prev[0] + t * (u - prev[0]), prev[1] + t * (left - prev[1])))
            new.append((u, min(left, g) if u > a else min(right, g)))
            if a < u < b and right != left:
                new.append((u, min(right, g)))
            prev = (u, right, g)
        new.append((b, b_right))
        new = _simplified(new)
        us[i:j] = [p[0] for p in new]
        vs[i:j] = [p[1] for p in new]

    # -- what the blade sweeps -------------------------------------------------
    def clear_slot(self, u_from: float, u_to: float, bottom: float, width: float, radius: float) -> None:
        """A plunge to ``bottom`` at u_from, freed off along the bottom to u_to."""
        self.clear_move((u_from, bottom), (u_to, bottom), width, radius)

    def cuts(self, p: Point, q: Point, width: float, radius: float) -> bool:
        """Whether a blade fed from p to q (front-edge positions (u, v)) cuts
        more than MATERIAL_MARGIN of material."""
        if self._highest(min(p[0], q[0]), max(p[0], q[0]) + width) <= min(p[1], q[1]) + CUT_NOISE:
            return False  # the field lies below the blade's front: nothing to work out
        return self.excess(_swept(p, q, width, radius), CUT_NOISE) > CUT_NOISE

    def clear_move(self, p: Point, q: Point, width: float, radius: float) -> None:
        """What a blade fed from p to q has cleared (at least)."""
        self.lower(_swept(p, q, width, radius))


class _Level:
    """A piecewise-linear level by increasing u, evaluated at any u."""

    def __init__(self, pts: List[Point]) -> None:
        self.pts = pts
        self.us = [p[0] for p in pts]

    def __call__(self, u: float) -> float:
        pts = self.pts
        k = bisect_left(self.us, u)
        if k < len(pts) and pts[k][0] == u:
            return pts[k][1]
        if k == 0 or k >= len(pts):
            return math.inf
        (u0, v0), (u1, v1) = pts[k - 1], pts[k]
        return _interp(u0, v0, u1, v1, u)


def _simplified(pts: List[Point]) -> List[Point]:
    """``pts`` without repeated points and without inner points on the straight
    line through their neighbours (the field stays small), ends kept."""
    out = [pts[0]]
    for k in range(1, len(pts)):
        p = pts[k]
        if p == out[-1]:
            continue
        if len(out) >= 2 and k < len(pts) - 1:
            (u0, v0), (u1, v1) = out[-2], out[-1]
            if u0 < u1 < p[0] and abs((v1 - v0) * (p[0] - u0) - (p[1] - v0) * (u1 - u0)) <= 1e-12 * (p[0] - u0):
                out.pop()
        out.append(p)
    return out


@lru_cache(maxsize=64)
def _corner(radius: float) -> Tuple[Point, ...]:
    """The blade's left rounded corner as (du, dv) from its front-left point
    (t, v): a polygon inscribed in the arc, from the side (0, r) to the front
    (r, 0), each side at most MATERIAL_MARGIN from the arc."""
    ratio = min(MATERIAL_MARGIN / radius, 1.0)
    sides = max(1, math.ceil(0.25 * math.pi / math.acos(1.0 - ratio)))
    step = 0.5 * math.pi / sides
    pts = [(radius - radius * math.cos(k * step), radius - radius * math.sin(k * step)) for k in range(sides + 1)]
    pts[0], pts[-1] = (0.0, radius), (radius, 0.0)
    return tuple(pts)


@lru_cache(maxsize=64)
def _front(width: float, radius: float) -> Tuple[Tuple[Point, ...], Tuple[float, ...]]:
    """The blade's front as (du, dv) from its front-left point, inside the
    real blade (corner polygons from ``_corner``), by increasing u, and the
    slopes of its edges (increasing: the front is convex)."""
    if radius <= 0:
        pts = [(0.0, 0.0), (width, 0.0)]
    else:
        corner = _corner(radius)
        pts = list(corner) + [(width - du, dv) for du, dv in reversed(corner)]
    pts = [pt for k, pt in enumerate(pts) if k == 0 or pt[0] > pts[k - 1][0]]  # corners meeting at a point
    slopes = [(v1 - v0) / (u1 - u0) for (u0, v0), (u1, v1) in zip(pts, pts[1:])]
    return tuple(pts), tuple(slopes)


def _swept(p: Point, q: Point, width: float, radius: float) -> List[Point]:
    """The lowest the (convex) blade front reaches over each column while it
    moves from p to q: the lower boundary of the front's Minkowski sum with
    the segment pq, i.e. the front's edges at p that fall more steeply than
    pq, the segment, then the rest of the front at q."""
    front, slopes = _front(width, radius)
    if q[0] < p[0]:
        p, q = q, p
    du, dv = q[0] - p[0], q[1] - p[1]
    if du <= 0:  # straight along v: the lower of the two fronts
        t, v = p[0], min(p[1], q[1])
        return [(t + a, v + b) for a, b in front]
    k = bisect_right(slopes, dv / du)  # the edges before the segment
    (tp, vp), (tq, vq) = p, q
    return [(tp + a, vp + b) for a, b in front[:k + 1]] + [(tq + a, vq + b) for a, b in front[k:]]
