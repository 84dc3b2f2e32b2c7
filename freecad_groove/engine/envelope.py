"""Where a grooving blade may go without cutting into a given material top.

Everything here works in a *groove frame* (u, v): u runs across the groove,
v points out of the material, the blade's front edge faces -v and its body
extends to +v. The material is described by its top ``f(u)``: a polyline
sorted by u (vertical steps allowed, as two points with the same u).

``lowest(u)`` is the exact lowest level v of the blade's front edge when its
minus-u edge is at u, the blade spanning [u, u + width] with both front corners
rounded by ``radius``: the configuration-space boundary. Following it touches
the material everywhere and never enters it, so it gives both the plunge depth
of a roughing cut and the path of a contour-parallel finishing cut.
"""

import math
from bisect import bisect_left
from typing import Iterable, List, Optional, Set, Tuple

Point = Tuple[float, float]

EDGE_EPS = 1e-9  # a blade this close to a wall only touches it
JUMP_PROBE = 1e-7


class Envelope:
    """The lowest levels of one blade (width, corner radius) over one material top."""

    def __init__(
        self, points: List[Point], width: float, radius: float, corners: Optional[Iterable[float]] = None
    ) -> None:
        if radius < 0 or width <= 2 * radius:
            raise ValueError("blade width must exceed twice its corner radius")
        self.width = width
        self.radius = radius
        self.points = points
        # Where the top changes from one element to the next (the polyline's
        # other points only approximate arcs): the trace starts from these.
        self.corners = sorted(set(p[0] for p in points)) if corners is None else sorted(corners)
        segs = []
        for (u1, v1), (u2, v2) in zip(points, points[1:]):
            if u2 < u1 - 1e-12:
                raise ValueError("material top must be sorted by u")
            segs.append((u1, v1, u2, v2, (v2 - v1) / (u2 - u1) if u2 - u1 > 1e-12 else None))
        self.segments = segs
        self._ends = [s[2] for s in segs]
        # Tool parts over the blade's width: (s_from, s_to, kind)
        r, w = radius, width
        if r > 0:
            self.parts = ((0.0, r, -1), (r, w - r, 0), (w - r, w, 1))
        else:
            self.parts = ((0.0, w, 0),)

    def bottom(self, s: float) -> float:
        """Height of the blade's outline above its front edge, s from the minus edge."""
        r = self.radius
        if r <= 0:
            return 0.0
        if s < r:
            d = r - s
        elif s > self.width - r:
            d = s - (self.width - r)
        else:
            return 0.0
        return r - math.sqrt(max(r * r - d * d, 0.0))

    def lowest(self, u: float) -> float:
        """Lowest front-edge level at blade position u (minus edge at u)."""
        hi = u + self.width
        best = -math.inf
        segments = self.segments
        for index in range(bisect_left(self._ends, u), len(segments)):
            segment = segments[index]
            if segment[0] > hi:
                break
            if segment[4] is None:
                level = self._step_level(segment, u)
            else:
                level = self._slope_level(segment, u, hi)
            if level > best:
                best = level
        return best

    def _step_level(self, segment: tuple, u: float) -> float:
        """The blade's lowest level over a vertical step of the top. The material
        stands on the step's high side; when that side lies just outside the
        blade's span, the blade only slides along the wall and the elements
        beside it count instead (-inf)."""
        u1, v1, _u2, v2, _slope = segment
        s = u1 - u
        if v1 > v2:  # stepping down: material to the left
            if s <= EDGE_EPS:
                return -math.inf  # the wall stands just outside the blade
            top = v1
        else:  # stepping up: material to the right
            if s >= self.width - EDGE_EPS:
                return -math.inf
            top = v2
        return top - self.bottom(s)

    def _slope_level(self, segment: tuple, u: float, hi: float) -> float:
        """The blade's lowest level over a sloping (or flat) segment of the top."""
        r, w = self.radius, self.width
        u1, v1, u2, _v2, q = segment
        a = (u1 if u1 > u else u) - u
        b = (u2 if u2 < hi else hi) - u
        best = -math.inf
        if a > b or (b - a <= EDGE_EPS and (a <= EDGE_EPS or b >= w - EDGE_EPS)):
            return best  # outside the blade, or only touching its side edge
        for s_from, s_to, kind in self.parts:
            ta = a if a > s_from else s_from
            tb = b if b < s_to else s_to
            if ta > tb:
                continue
            candidates = [ta, tb]
            # A sloping segment touches a rounded corner at one tangent point.
            if kind < 0 and q < 0:
                candidates.append(r - r * (-q) / math.sqrt(1 + q * q))
            elif kind > 0 and q > 0:
                candidates.append(w - r + r * q / math.sqrt(1 + q * q))
            for s in candidates:
                if ta <= s <= tb:
                    level = v1 + q * (u + s - u1) - self.bottom(s)
                    if level > best:
                        best = level
        return best

    def walls(self, lo: float, hi: float) -> Set[float]:
        """Blade positions in (lo, hi) where a side edge passes a vertical step."""
        out = set()
        for u1, _v1, _u2, _v2, q in self.segments:
            if q is None:
                for c in (u1, u1 - self.width):
                    if lo < c < hi:
                        out.add(c)
        return out

    def breakpoints(self, lo: float, hi: float) -> List[float]:
        """Blade positions in [lo, hi] where ``lowest`` may change its formula."""
        r, w = self.radius, self.width
        offsets = (0.0, r, w - r, w) if r > 0 else (0.0, w)
        cands = {lo, hi}
        corners = self.corners
        for pu in corners:
            for off in offsets:
                c = pu - off
                if lo < c < hi:
                    cands.add(c)
        if r > 0:
            keys = set(corners)
            for u1, _v1, u2, _v2, q in self.segments:
                if q is None or q == 0 or u1 not in keys or u2 not in keys:
                    continue  # arc chords: the refinement follows them
                if q < 0:
                    s = r - r * (-q) / math.sqrt(1 + q * q)
                else:
                    s = w - r + r * q / math.sqrt(1 + q * q)
                for c in (u1 - s, u2 - s):
                    if lo < c < hi:
                        cands.add(c)
        return sorted(cands)

    def trace(self, lo: float, hi: float, tol: float = 0.0002) -> List[Point]:
        """Points (u, lowest(u)) from lo to hi, close enough that the straight
        moves between them stay within ``tol`` of the true boundary."""
        if hi < lo:
            return [(u, v) for u, v in reversed(self.trace(hi, lo, tol))]
        f = self.lowest
        us = self.breakpoints(lo, hi)
        walls = self.walls(lo, hi)
        out = []
        prev = (us[0], f(us[0]))
        out.append(prev)
        for u in us[1:]:
            # The boundary jumps where the blade passes a wall: move straight along it.
            cur = (u, f(u))
            if u in walls:
                # Passing a wall the boundary may jump, or dip at just this u
                # (a groove exactly as wide as the blade): go straight along it.
                seq = [(u, f(u - JUMP_PROBE)), cur, (u, f(u + JUMP_PROBE))]
                seq = [p for i, p in enumerate(seq) if i == 0 or abs(p[1] - seq[i - 1][1]) > tol / 10]
            else:
                seq = [cur]
            self._refine(prev, seq[0], tol, out, 0)
            out.extend(seq)
            prev = seq[-1]
        return _drop_collinear(out)

    def _refine(self, p, q, tol, out, depth):
        if q[0] - p[0] < 1e-6 or depth > 24:
            return
        # Between breakpoints the boundary is a maximum of lines and arcs of the
        # corner radius: the chord's error is largest near its middle, and at
        # most twice the middle's for a kink elsewhere.
        um = 0.5 * (p[0] + q[0])
        m = (um, self.lowest(um))
        if abs(m[1] - 0.5 * (p[1] + q[1])) > tol:
            self._refine(p, m, tol, out, depth + 1)
            out.append(m)
            self._refine(m, q, tol, out, depth + 1)


def _drop_collinear(pts, eps=1e-9):
    if len(pts) < 3:
        return pts
    out = [pts[0]]
    for i in range(1, len(pts) - 1):
        (u0, v0), (u1, v1), (u2, v2) = out[-1], pts[i], pts[i + 1]
        cross = (u1 - u0) * (v2 - v0) - (v1 - v0) * (u2 - u0)
        turns_back = (u1 - u0) * (u2 - u1) + (v1 - v0) * (v2 - v1) < 0
        if turns_back or abs(cross) > eps * max(1.0, abs(u2 - u0) + abs(v2 - v0)):
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
