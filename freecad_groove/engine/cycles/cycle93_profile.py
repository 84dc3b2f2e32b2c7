"""The pieces a CYCLE93 groove is drawn with: its frame (the groove frame to
the world and blade positions to the reference corner, arcs included), the
rounded or chamfered corners of its profile, and the split of a pass at the
plunge positions.
"""

import math
from bisect import bisect_left, bisect_right
from operator import itemgetter
from typing import Dict, List, Optional, Sequence, Tuple

from ..envelope import Arc, PathPoint, arc_points
from ..envelope_curves import value
from .cycle93_constants import PATH_TOLERANCE

Point = Tuple[float, float]

FOLD_TOLERANCE = 1e-9  # a profile stepping back further than this folds over itself


class Frame:
    """Maps the groove frame (u across the groove from the start point, v out
    of the material) to world (x radius, z) and blade positions to the
    reference corner."""

    def __init__(
        self, x0: float, z0: float, longitudinal: bool, su: float, sv: float, width: float, ref_plus: bool
    ) -> None:
        self.x0, self.z0 = x0, z0
        self.longitudinal = longitudinal
        self.su, self.sv = su, sv
        self.width = width
        self.ref_shift = width if ref_plus else 0.0

    def point(self, u: float, v: float) -> Point:
        """World (x, z) of a groove-frame point."""
        if self.longitudinal:
            return self.x0 + self.sv * v, self.z0 + self.su * u
        return self.x0 + self.su * u, self.z0 + self.sv * v

    def blade(self, u: float, v: float) -> Point:
        """World reference corner (x, z) of the blade whose minus-u edge is at u."""
        lo = u if self.su > 0 else -(u + self.width)
        along = lo + self.ref_shift
        if self.longitudinal:
            return self.x0 + self.sv * v, self.z0 + along
        return self.x0 + along, self.z0 + self.sv * v

    def clockwise(self, counter_clockwise: bool) -> bool:
        """Whether a move turning counter-clockwise in the groove frame (u to
        the right, v up) turns clockwise in the world (Z to the right, X up:
        G2): the frame is a translation and reflections, and an odd number of
        reflections turns the other way."""
        # (z, x) = (su u, sv v) along a longitudinal groove, (sv v, su u) across a face: the sign of the map
        keeps = (self.su * self.sv > 0) == self.longitudinal
        return counter_clockwise != keeps

    def blade_of(self, x: float, z: float) -> Point:
        """Inverse of blade(): the blade position (u, v) for a reference corner."""
        if self.longitudinal:
            along, v = z - self.z0, self.sv * (x - self.x0)
        else:
            along, v = x - self.x0, self.sv * (z - self.z0)
        lo = along - self.ref_shift
        u = lo if self.su > 0 else -lo - self.width
        return u, v


def unit(du: float, dv: float) -> Point:
    n = math.hypot(du, dv)
    return du / n, dv / n


def intersect(p: Point, d: Point, q: Point, e: Point) -> Optional[Point]:
    """Intersection of lines p + t d and q + s e."""
    den = d[0] * e[1] - d[1] * e[0]
    if abs(den) < 1e-15:
        return None
    t = ((q[0] - p[0]) * e[1] - (q[1] - p[1]) * e[0]) / den
    return p[0] + t * d[0], p[1] + t * d[1]


def without_float_folds(pts: List[Point]) -> List[Point]:
    """The points with u never stepping back by rounding: an arc's end computed
    from a large radius may lie FOLD_TOLERANCE behind the next point."""
    us = list(map(itemgetter(0), pts))
    if us == sorted(us) and set(map(type, pts)) == {tuple}:
        return list(pts)  # u never steps back: the points as they are
    out = [pts[0]]
    for u, v in pts[1:]:
        back = out[-1][0]
        out.append((back, v) if back - FOLD_TOLERANCE <= u < back else (u, v))
    return out


def split_at(pts: Sequence[Point], positions: List[float]) -> List[Point]:
    """The trace with a point added wherever a move crosses one of
    ``positions`` (the plunges' u): on the move's straight line, or on its
    circle for a move of an exact path along one (a PathPoint's arc: both
    halves follow it). The Siemens manual's step 3: "Infeed along the groove
    width is carried out in several steps if the flank width is larger": the
    plunges across the opening are those steps (each stops on the flank,
    leaving a tooth at most one width step wide), and the pass takes the
    teeth one move per step, never more than a width step across."""
    positions = sorted(positions)
    # By position where the moves outnumber the positions (a pass over an arc's chords), else move by move.
    crossed = _crossed_monotone(pts, positions) if len(pts) > 2 * len(positions) else None
    if crossed is None:
        return _split_each(pts, positions)
    exact = isinstance(pts[0], PathPoint)
    out: List[Point] = []
    done = 0
    for i in sorted(crossed):
        out.extend(pts[done:i + 1])
        out.extend(_points_on(pts[i], pts[i + 1], crossed[i], exact))
        done = i + 1
    out.extend(pts[done:])
    return out


def _crossed_monotone(pts: Sequence[Point], positions: List[float]) -> Optional[Dict[int, List[float]]]:
    """For a trace whose u never turns back (a pass: the usual case), the
    positions (ascending) each move i (pts[i] to pts[i + 1]) crosses, as
    ``_split_each`` finds them (strictly inside the move by 1e-9), found by
    position, not by move: one bisection each. None for another trace."""
    us = list(map(itemgetter(0), pts))
    if us == sorted(us):
        ascending = True
    elif us == sorted(us, reverse=True):
        ascending, us = False, us[::-1]
    else:
        return None
    crossed: Dict[int, List[float]] = {}
    last = len(us) - 1
    for c in positions:
        j = bisect_left(us, c)  # us[j - 1] < c <= us[j]: only that move may hold c strictly inside
        if 0 < j <= last and us[j] > c and us[j - 1] + 1e-9 < c < us[j] - 1e-9:
            crossed.setdefault(j - 1 if ascending else last - j, []).append(c)
    if not ascending:
        for inside in crossed.values():
            inside.reverse()
    return crossed


def _points_on(start: Point, end: Point, inside: List[float], exact: bool) -> List[Point]:
    """The points at u in ``inside`` on the move from start to end (its line, or with ``exact`` its circle:
    end.arc), PathPoints with ``exact``."""
    (u0, v0), (u1, v1) = start, end
    if not exact:
        return [(c, v0 + (v1 - v0) * (c - u0) / (u1 - u0)) for c in inside]
    arc = end.arc
    return [PathPoint(c, v0 + (v1 - v0) * (c - u0) / (u1 - u0) if arc is None else value(arc, c), arc)
            for c in inside]


def _split_each(pts: Sequence[Point], positions: List[float]) -> List[Point]:
    """split_at move by move (any trace; ``positions`` ascending)."""
    exact = isinstance(pts[0], PathPoint)
    out = [pts[0]]
    for (u0, v0), end in zip(pts, pts[1:]):
        u1, v1 = end
        lo, hi = (u0, u1) if u0 <= u1 else (u1, u0)
        first, last = bisect_right(positions, lo + 1e-9), bisect_left(positions, hi - 1e-9)
        if first < last:
            inside = positions[first:last]
            arc = end.arc if exact else None
            for c in (reversed(inside) if u1 < u0 else inside):
                v = v0 + (v1 - v0) * (c - u0) / (u1 - u0) if arc is None else value(arc, c)
                out.append(PathPoint(c, v, arc) if exact else (c, v))
        out.append(end)
    return out


class Corner:
    """A rounded (value > 0) or chamfered (value < 0) corner between the
    incoming direction a and the outgoing direction b at vertex V."""

    def __init__(self, vertex: Point, a: Point, b: Point, value: float, chr_mode: bool) -> None:
        self.vertex = vertex
        self.value = value
        a, b = unit(*a), unit(*b)
        self.a, self.b = a, b
        cos_t = max(-1.0, min(1.0, a[0] * b[0] + a[1] * b[1]))
        self.turn = math.acos(cos_t)  # deflection angle
        self.left = a[0] * b[1] - a[1] * b[0] > 0
        half = self.turn / 2
        if value > 0:
            self.length = value * math.tan(half)
        elif value < 0:
            self.length = -value if chr_mode else -value / (2 * math.cos(half))
        else:
            self.length = 0.0

    def _arc_start(self) -> Tuple[Point, Point, Point]:
        """Where the corner's rounding or chamfer starts and ends (t_in, t_out),
        and the centre of its arc."""
        v, a, b, length = self.vertex, self.a, self.b, self.length
        t_in = (v[0] - length * a[0], v[1] - length * a[1])
        t_out = (v[0] + length * b[0], v[1] + length * b[1])
        n = (-a[1], a[0]) if self.left else (a[1], -a[0])
        r = self.value
        return t_in, t_out, (t_in[0] + r * n[0], t_in[1] + r * n[1])

    def points(self, tol: float = PATH_TOLERANCE) -> List[Point]:
        """The corner as a polyline, its arc chorded to ``tol``."""
        if self.length <= 0:
            return [self.vertex]
        t_in, t_out, c = self._arc_start()
        if self.value < 0:
            return [t_in, t_out]
        r = self.value
        a0 = math.atan2(t_in[1] - c[1], t_in[0] - c[0])
        sweep = self.turn if self.left else -self.turn
        # Material-side bumps (right turns) get a tangent polygon outside the
        # arc, bowls get chords inside it: both err toward more material.
        return arc_points(c, r, a0, a0 + sweep, outside=not self.left, tol=tol)

    def element(self) -> Tuple[List[Point], Optional[Arc]]:
        """The corner exactly: its vertex alone, or the two ends of its chamfer
        or arc, and the arc (None for a vertex or a chamfer)."""
        if self.length <= 0:
            return [self.vertex], None
        t_in, t_out, c = self._arc_start()
        if self.value < 0:
            return [t_in, t_out], None
        return [t_in, t_out], Arc(c, self.value, not self.left)
