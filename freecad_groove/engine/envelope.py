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
and circles. ``trace`` chords each circle directly to a tolerance (the
stretches the passes decide on); ``path`` gives the same boundary exactly,
each point carrying the circle of the move that reaches it (``PathPoint``),
and ``path_moves`` the moves a program writes along it: arcs, and the chords
of those too flat to write as arcs.
"""

import math
from bisect import bisect_right
from typing import Dict, Iterator, List, Optional, Sequence, Set, Tuple

from .envelope_contacts import EDGE_EPS, Arc, top_curves
from .envelope_curves import CUP, LINE, Curve, chords, slope, upper_envelope, value
from .numbers import MIN_ARC_CHORD

Point = Tuple[float, float]
# A move along a circle of the groove frame: its centre (u, v) and whether it
# turns counter-clockwise (u to the right, v up); None for a straight move.
Turn = Optional[Tuple[float, float, bool]]

__all__ = ["EDGE_EPS", "Arc", "Envelope", "PathPoint", "arc_points", "on_circles", "path_moves", "reversed_path",
           "writes_arcs"]

JUMP = 1e-9  # a change of level this large where two pieces meet is a wall: move straight along it
SAME_U = 1e-7  # points closer than this along u are at the same u (no sliver moves)
KINK = 1e-9  # two pieces whose slopes differ more than this where they meet make a kink
# An arc's ends lie on its circle: moved at most SAME_U along u (slivers), or
# JUMP along v where a piece starts.
ON_CIRCLE = 1e-6


class PathPoint(tuple):
    """A point (u, v) of an exact path; ``arc`` is the circle the move that
    reaches it follows: the envelope's CAP or CUP curve (a half circle over
    u), None for a straight move. Unpacks and compares as (u, v)."""

    arc: Optional[Curve] = None  # a straight move's point holds no attribute of its own

    def __new__(cls, u: float, v: float, arc: Optional[Curve] = None) -> "PathPoint":
        point = tuple.__new__(cls, (u, v))
        if arc is not None:
            point.arc = arc
        return point

    def __repr__(self) -> str:
        return "PathPoint(%r, %r%s)" % (self[0], self[1], "" if self.arc is None else ", arc")


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

    def _runs(self, lo: float, hi: float) -> Iterator[Tuple[float, float, Curve]]:
        """(a, b, piece): the pieces of the lowest level over [lo, hi] in order, each over [a, b]."""
        starts, pieces = self._built()
        index = max(bisect_right(starts, lo) - 1, 0)
        span_hi = self._span[1]
        while index < len(pieces):
            a = max(starts[index], lo)
            b = min(starts[index + 1] if index + 1 < len(starts) else span_hi, hi)
            piece = pieces[index]
            if b > a and piece is not None:
                yield a, b, piece
            if b >= hi:
                break
            index += 1

    def trace(self, lo: float, hi: float, tol: float = 0.0002) -> List[Point]:
        """Points (u, lowest(u)) from lo to hi, close enough that the straight
        moves between them stay within ``tol`` of the true boundary and never
        below it; straight along u where the boundary jumps (a wall)."""
        return self.traces(lo, hi, tol)[0]

    def path(self, lo: float, hi: float) -> List[PathPoint]:
        """The boundary ``trace`` chords, exactly: from lo to hi, a point where
        one piece meets the next, each reached along its piece (PathPoint.arc:
        the circle of a CAP or CUP piece, None along a line or a wall)."""
        return self.traces(lo, hi, None)[1]

    def traces(self, lo: float, hi: float, tol: Optional[float]) -> Tuple[List[Point], Optional[List[PathPoint]]]:
        """(``trace`` with ``tol``, ``path``) from lo to hi, in one walk over
        the pieces: no chords for ``tol`` None; with ``tol``, the path None
        when none of its arcs is written as one (``path_moves``: all within
        ``tol`` of their chords or shorter than MIN_ARC_CHORD), the chords
        being what it writes."""
        chorded, exact, worth = self.trace_and_path(lo, hi, tol, keep=False)
        return chorded, exact if worth else None

    def trace_and_path(self, lo: float, hi: float, tol: Optional[float],
                       keep: bool = True) -> Tuple[List[Point], List[PathPoint], bool]:
        """(``trace``, ``path``, whether ``traces`` gives that path: one of its
        arcs is written as one, or ``tol`` is None), in one walk; without
        ``keep`` the path is left empty where ``traces`` would not give it."""
        if hi < lo:
            chorded, exact, worth = self.trace_and_path(hi, lo, tol, keep)
            return [(u, v) for u, v in reversed(chorded)], exact and reversed_path(exact), worth
        start = self.lowest(lo)
        chorded, ends = [(lo, start)], [(lo, start, None)]
        worth = tol is None
        for a, b, piece in self._runs(lo, hi):
            level = value(piece, a)
            if abs(level - ends[-1][1]) > JUMP:  # the last point of both: (a, the last piece's level there)
                chorded.append((a, level))
                ends.append((a, level, None))
            if tol is not None:
                chorded.extend(chords(piece, a, b, tol))
            arc = piece if piece.kind != LINE and piece.size > 0 else None
            end = value(piece, b)
            worth = worth or (arc is not None and _writable(arc, (a, level), (b, end), tol))
            ends.append((b, end, arc))
        end = self.lowest(hi)
        if abs(end - ends[-1][1]) > JUMP:
            chorded.append((hi, end))
            ends.append((hi, end, None))
        chorded = _drop_collinear(_without_slivers(chorded)) if tol is not None else []
        if not (worth or keep):
            return chorded, [], False
        return chorded, _drop_collinear(_without_slivers([PathPoint(*point) for point in ends])), worth

    def deepest(self, start: float, end: float, gain: float = 0.0) -> float:
        """The blade position between ``start`` and ``end`` (either way round)
        nearest ``start`` where the front stands lowest; ``start`` itself
        unless that is more than ``gain`` below ``lowest(start)``. A piece is
        lowest at an end or at the bottom of a cup."""
        found = []
        for a, b, piece in self._runs(min(start, end), max(start, end)):
            xs = [a, b] + ([piece.cu] if piece.kind == CUP and a < piece.cu < b else [])
            found.extend((value(piece, x), x) for x in xs)
        if not found:
            return start
        level = min(found)[0]
        if level >= self.lowest(start) - gain:
            return start
        return min((x for v, x in found if v <= level + JUMP), key=lambda x: abs(x - start))

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


def _moved(point: Point, u: float, v: float, arc: bool = False) -> Point:
    """``point`` moved less than SAME_U along u to (u, v): a point of an exact
    path is then reached straight (the move no longer spans its circle over
    u), or along its circle still with ``arc`` (the move keeps its span)."""
    if not isinstance(point, PathPoint):
        return (u, v)
    return PathPoint(u, v, point.arc if arc else None)


def _without_slivers(pts: List[Point]) -> List[Point]:
    """The points with those less than SAME_U along u from the one before
    moved to its u (a wall as wide as the blade is a dip EDGE_EPS wide), and
    those less than SAME_U from it both ways dropped; the trace still ends
    exactly where asked (the last run along a wall moves there)."""
    out = [pts[0]]
    pu, pv = pts[0]  # the last point kept
    for point in pts[1:]:
        u, v = point
        if abs(u - pu) < SAME_U:
            if abs(v - pv) < SAME_U:
                continue
            point = _moved(point, pu, v)
            u = pu
        out.append(point)
        pu, pv = u, v
    end = pts[-1]
    run = out[-1][0]
    if len(out) > 1 and run != end[0] and abs(run - end[0]) < SAME_U:
        k = len(out) - 1
        while k > 0 and out[k][0] == run:
            out[k] = _moved(out[k], end[0], out[k][1], arc=True)
            k -= 1
    if out[-1] is not end:  # the end dropped beside the last point, or the last run moved to it
        out[-1] = _moved(end, end[0], end[1]) if getattr(out[-1], "arc", None) is None else \
            PathPoint(end[0], end[1], out[-1].arc)
    return out


def _drop_collinear(pts: List[Point], eps: float = 1e-9) -> List[Point]:
    """The points without those less than eps off the line through their
    neighbours (a distance, so that short chords keep their corners); a
    point an arc reaches or leaves stays."""
    if len(pts) < 3:
        return pts
    if isinstance(pts[0], PathPoint):
        return _drop_collinear_path(pts, eps)
    out = [pts[0]]
    u0, v0 = pts[0]
    for point, after in zip(pts[1:-1], pts[2:]):  # the chorded trace: one pass, the kept point in locals
        u1, v1 = point
        u2, v2 = after
        du, dv = u1 - u0, v1 - v0
        if abs(du * (v2 - v0) - dv * (u2 - u0)) > eps * (abs(u2 - u0) + abs(v2 - v0)) \
                or du * (u2 - u1) + dv * (v2 - v1) < 0:  # off the line, or turning back
            out.append(point)
            u0, v0 = u1, v1
    out.append(pts[-1])
    return out


def _drop_collinear_path(pts: List[PathPoint], eps: float) -> List[PathPoint]:
    """_drop_collinear of an exact path."""
    out = [pts[0]]
    for i in range(1, len(pts) - 1):
        if pts[i].arc is not None or pts[i + 1].arc is not None:
            out.append(pts[i])
            continue
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


def on_circles(pts: Sequence[Point], tol: float = ON_CIRCLE) -> bool:
    """Whether every arc of the exact path ``pts`` starts and ends on its
    circle (within ``tol``): the path a program may write as it is."""
    for here, point in zip(pts, pts[1:]):
        arc = getattr(point, "arc", None)
        if arc is not None and not all(abs(math.dist(p, (arc.cu, arc.cv)) - arc.size) <= tol for p in (here, point)):
            return False
    return True


def reversed_path(pts: Sequence[PathPoint]) -> List[PathPoint]:
    """The exact path run the other way: each move follows the circle the
    move it retraces followed."""
    out = [PathPoint(*pts[-1])]
    for k in range(len(pts) - 2, -1, -1):
        out.append(PathPoint(*pts[k], getattr(pts[k + 1], "arc", None)))
    return out


def _arc_chords(arc: Curve, start: Point, end: Point, tol: float) -> List[Point]:
    """The moves ``trace`` makes along ``arc`` from start to end (end last)."""
    if end[0] >= start[0]:
        return chords(arc, start[0], end[0], tol)[:-1] + [end]
    back = chords(arc, end[0], start[0], tol)
    return list(reversed(back[:-1])) + [end]


def path_moves(start: Point, pts: Sequence[Point], tol: float) -> Iterator[Tuple[Point, Turn]]:
    """The moves from ``start`` through the points ``pts`` of an exact path
    (plain points: straight moves): (end, turn), ``turn`` (cu, cv,
    counter-clockwise) for a move along a circle, None for a straight one.
    An arc whose sagitta is within ``tol``, or shorter than MIN_ARC_CHORD,
    is its chords as ``trace`` makes them instead (outside a cap, inside a
    cup: never below the boundary)."""
    here = start
    for point in pts:
        arc = getattr(point, "arc", None)
        if arc is None:
            yield point, None
        elif not _writable(arc, here, point, tol):
            for chord_end in _arc_chords(arc, here, point, tol):
                yield chord_end, None
        else:
            # A cup (lower half circle) runs counter-clockwise toward +u, a cap clockwise.
            yield point, (arc.cu, arc.cv, (arc.kind == CUP) == (point[0] > here[0]))
        here = point


def _writable(arc: Curve, start: Point, end: Point, tol: float) -> bool:
    """Whether the move along ``arc`` from start to end is written as an arc:
    its sagitta over ``tol`` and its chord at least MIN_ARC_CHORD."""
    half = 0.5 * math.dist(start, end)
    sagitta = arc.size - math.sqrt(max(arc.size * arc.size - half * half, 0.0))
    return sagitta > tol and 2 * half >= MIN_ARC_CHORD


def writes_arcs(pts: Sequence[Point], tol: float, lo: float = -math.inf, hi: float = math.inf) -> bool:
    """Whether ``path_moves`` may write an arc along the exact path ``pts``
    over (lo, hi) along u: an arc whose whole move is written as one (split
    in pieces, it is no less flat, nor longer) reaching into (lo, hi)."""
    return any(point.arc is not None and min(here[0], point[0]) < hi and max(here[0], point[0]) > lo
               and _writable(point.arc, here, point, tol)
               for here, point in zip(pts, pts[1:]) if isinstance(point, PathPoint))
