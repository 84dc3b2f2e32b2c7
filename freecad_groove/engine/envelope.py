"""Where a grooving blade may go without cutting into a given material top.

Everything here works in a *groove frame* (u, v): u runs across the groove,
v points out of the material, the blade's front edge faces -v and its body
extends to +v. The material is described by its top ``f(u)``: vertices sorted
by u (vertical steps allowed, as two points with the same u) joined by lines
or by circular arcs (``Arc``), arcs staying arcs.

``lowest(u)`` is the exact lowest level v of the blade's front edge when its
minus-u edge is at u, the blade spanning [u, u + width] with both front corners
rounded by ``radius``: the configuration-space boundary. Following it touches
the material everywhere and never enters it, so it gives both the plunge depth
of a roughing cut and the path of a contour-parallel finishing cut.

It is built once per envelope from closed-form contact curves
(``envelope_contacts``) as their upper envelope (``envelope_curves``): lines
and circles, each chorded directly to the tolerance when traced.
"""

import math
from bisect import bisect_right
from typing import Dict, List, Optional, Set, Tuple

from .envelope_contacts import EDGE_EPS, Arc, top_curves
from .envelope_curves import Curve, chords, slope, upper_envelope, value

Point = Tuple[float, float]

__all__ = ["EDGE_EPS", "Arc", "Envelope", "arc_points"]

JUMP = 1e-9  # a change of level this large where two pieces meet is a wall: move straight along it
SAME_U = 1e-7  # points closer than this along u are at the same u (no sliver moves)
KINK = 1e-9  # two pieces whose slopes differ more than this where they meet make a kink


class Envelope:
    """The lowest levels of one blade (width, corner radius) over one material top."""

    def __init__(self, points: List[Point], width: float, radius: float,
                 arcs: Optional[Dict[int, Arc]] = None) -> None:
        if radius < 0 or width <= 2 * radius:
            raise ValueError("blade width must exceed twice its corner radius")
        self.width = width
        self.radius = radius
        self.points = points
        self.arcs = dict(arcs or {})
        self._curves = top_curves(points, self.arcs, width, radius)
        self._starts: List[float] = []
        self._pieces: List[Optional[Curve]] = []
        self._span = (min(p[0] for p in points) - width, max(p[0] for p in points))

    def _built(self) -> Tuple[List[float], List[Optional[Curve]]]:
        if not self._starts:
            self._starts, self._pieces = upper_envelope(self._curves, *self._span)
        return self._starts, self._pieces

    def lowest(self, u: float) -> float:
        """Lowest front-edge level at blade position u (minus edge at u)."""
        lo, hi = self._span
        if not lo <= u <= hi:
            return -math.inf
        starts, pieces = self._built()
        index = max(bisect_right(starts, u) - 1, 0)
        level = value(pieces[index], u)
        if u == starts[index] and index > 0:
            level = max(level, value(pieces[index - 1], u))  # where two pieces meet, the higher
        return level

    def trace(self, lo: float, hi: float, tol: float = 0.0002) -> List[Point]:
        """Points (u, lowest(u)) from lo to hi, close enough that the straight
        moves between them stay within ``tol`` of the true boundary and never
        below it; straight along u where the boundary jumps (a wall)."""
        if hi < lo:
            return [(u, v) for u, v in reversed(self.trace(hi, lo, tol))]
        starts, pieces = self._built()
        out = [(lo, self.lowest(lo))]
        index = max(bisect_right(starts, lo) - 1, 0)
        span_hi = self._span[1]
        while index < len(pieces):
            a = max(starts[index], lo)
            b = min(starts[index + 1] if index + 1 < len(starts) else span_hi, hi)
            piece = pieces[index]
            if b > a and piece is not None:
                level = value(piece, a)
                if abs(level - out[-1][1]) > JUMP:
                    out.append((a, level))
                out.extend(chords(piece, a, b, tol))
            if b >= hi:
                break
            index += 1
        end = self.lowest(hi)
        if abs(end - out[-1][1]) > JUMP:
            out.append((hi, end))
        return _drop_collinear(_without_slivers(out))

    def walls(self, lo: float, hi: float) -> Set[float]:
        """Blade positions in (lo, hi) where a side edge passes a vertical step of the top."""
        out = set()
        for (u1, _v1), (u2, _v2) in zip(self.points, self.points[1:]):
            if u2 - u1 <= 1e-12:
                out.update(c for c in (u1, u1 - self.width) if lo < c < hi)
        return out

    def kinks(self, lo: float, hi: float) -> List[float]:
        """Blade positions in (lo, hi) where two pieces of the lowest level meet
        at an angle or a step: where the blade touches the top at two places
        (a smooth hand-over from one piece to the next, one contact rolling
        on, is left out)."""
        starts, pieces = self._built()
        out = []
        for index in range(bisect_right(starts, lo), len(starts)):
            u = starts[index]
            if u >= hi:
                break
            before, after = pieces[index - 1], pieces[index]
            if before is None or after is None:
                continue
            jump = abs(value(before, u) - value(after, u)) > JUMP
            turn = slope(before, u) - slope(after, u)
            if jump or not abs(turn) <= KINK:  # an infinite or NaN turn (a vertical tangent) counts
                out.append(u)
        return out


def _without_slivers(pts: List[Point]) -> List[Point]:
    """The points with those less than SAME_U along u from the one before
    moved to its u (a wall as wide as the blade is a dip EDGE_EPS wide), and
    those less than SAME_U from it both ways dropped; the trace still ends
    exactly where asked (the last run along a wall moves there)."""
    out = [pts[0]]
    for u, v in pts[1:]:
        pu, pv = out[-1]
        if abs(u - pu) < SAME_U:
            if abs(v - pv) < SAME_U:
                continue
            u = pu
        out.append((u, v))
    end = pts[-1]
    run = out[-1][0]
    if len(out) > 1 and run != end[0] and abs(run - end[0]) < SAME_U:
        k = len(out) - 1
        while k > 0 and out[k][0] == run:
            out[k] = (end[0], out[k][1])
            k -= 1
    out[-1] = end
    return out


def _drop_collinear(pts: List[Point], eps: float = 1e-9) -> List[Point]:
    """The points without those less than eps off the line through their
    neighbours (a distance, so that short chords keep their corners)."""
    if len(pts) < 3:
        return pts
    out = [pts[0]]
    for i in range(1, len(pts) - 1):
        (u0, v0), (u1, v1), (u2, v2) = out[-1], pts[i], pts[i + 1]
        cross = (u1 - u0) * (v2 - v0) - (v1 - v0) * (u2 - u0)
        turns_back = (u1 - u0) * (u2 - u1) + (v1 - v0) * (v2 - v1) < 0
        if turns_back or abs(cross) > eps * (abs(u2 - u0) + abs(v2 - v0)):
            out.append(pts[i])
    out.append(pts[-1])
    return out


def arc_points(center: Point, radius: float, a0: float, a1: float, outside: bool, tol: float = 0.0002) -> List[Point]:
    """Points from angle a0 to a1 (radians) on a circle; ``outside`` puts the
    chords outside the circle (tangent polygon) instead of inside it."""
    sweep = a1 - a0
    if radius <= 0 or abs(sweep) < 1e-12:
        return []
    step = 2 * math.acos(max(1 - tol / radius, -1.0))
    n = max(1, int(math.ceil(abs(sweep) / step)))
    d = sweep / n
    cx, cy = center
    pts = [(cx + radius * math.cos(a0), cy + radius * math.sin(a0))]
    if outside:
        rr = radius / math.cos(d / 2)
        for k in range(n):
            a = a0 + (k + 0.5) * d
            pts.append((cx + rr * math.cos(a), cy + rr * math.sin(a)))
    else:
        for k in range(1, n):
            a = a0 + k * d
            pts.append((cx + radius * math.cos(a), cy + radius * math.sin(a)))
    pts.append((cx + radius * math.cos(a1), cy + radius * math.sin(a1)))
    return pts
