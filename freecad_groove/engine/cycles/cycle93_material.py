"""What material the CYCLE93 plunges leave, exactly, so that the contour and
finishing passes (steps 3 and 4) feed only where there is something to cut.

The blade only moves paraxially and the profile is a function of u, so what
stands after the plunges is everything below a height field over u: the
lowest level the plunges cleared in each column, the contour line where they
did not reach. Each plunge (with its free-off along the bottom) clears a slot
whose floor is the blade's front outline at the plunge's bottom: a circular
arc of the corner radius at each end and the flat front between them. The
field is the lower envelope of those outlines and the contour line, built
once per call from closed-form curves (``envelope_curves``: arcs stay arcs),
no polygons and no grid.

A pass is tested a stretch at a time (``cuts``): the blade swept along a
convex chain of front positions (the lower hull of the stretch's points,
which lies below the stretch, so its sweep holds the stretch's) has a lower
outline made of the blade's arcs, its flat front and the chain's segments.
Between the breakpoints of the field and of that outline their difference is
monotone, convex, or concave with its peak where a field line has an arc's
slope, so its highest value is found at a handful of points, exactly. Where
the hull dips below the stretch (over a bump the blade rolls around), the
outline is raised to the profile the blade's envelope keeps it on (the
``floor``): the real blade never goes below it. Both only lower the outline
under the real sweep, so a stretch found not to cut leaves at most
MATERIAL_MARGIN (and the floor's chord tolerance) of material.

The passes' cuts are added only as the blade standing at both ends of each
stretch they feed (``cycle93_passes``: ``clear_slot`` at one position), less
than they cut, so the field stays an upper bound of what stands; a finishing
pass also skips the stretches the roughing passes already ran on the same
envelope (``note_pass``).
"""

import math
from bisect import bisect_left, bisect_right
from operator import itemgetter
from typing import List, Optional, Set, Tuple

from ..envelope import Envelope
from ..envelope_curves import CAP, CUP, LINE, Curve, crossings, upper_envelope, value
from .cycle93_witness import (  # noqa: F401 - the margins stay importable from here
    FLOOR_TOL,
    MATERIAL_MARGIN,
    SIDE_EPS,
    VERDICT_EPS,
    WITNESS_INSET,
    _axis,
    _by_ends,
    _in_end_corners,
    _over_blade,
    _under_floor,
)

Point = Tuple[float, float]
Piece = Tuple[float, float, Curve]  # x from, x to, the curve (real levels, not negated)

_LEVEL = itemgetter(1)


class MaterialTop:
    """The plunges' field over the columns [lo, hi]: the contour line (slope
    ``slope``) lowered by each slot. Stored negated, as the upper envelope of
    the negated curves (``envelope_curves`` builds upper envelopes)."""

    def __init__(self, lo: float, hi: float, slope: float) -> None:
        self.lo, self.hi = lo, hi
        self._curves: Optional[List[Curve]] = [Curve(lo, hi, LINE, 0.0, 0.0, -slope)]
        self._starts: List[float] = []
        self._pieces: List[Optional[Curve]] = []
        self.passed: Optional[Tuple[Envelope, float, float]] = None  # see note_pass
        self._placed: Set[Point] = set()  # the blade positions cleared so far (stand_blade)

    def clear_slot(self, u_from: float, u_to: float, bottom: float, width: float, radius: float) -> None:
        """A plunge to ``bottom`` at u_from, freed off along the bottom to u_to."""
        a, b = min(u_from, u_to), max(u_from, u_to)
        self._placed.update(((u_from, bottom), (u_to, bottom)))
        r, top = radius, -(bottom + radius)
        new, slot = tuple.__new__, []  # Curve(...) without its __new__'s frame: a slot per plunge and blade stood
        if a + r > a:
            slot.append(new(Curve, (a, a + r, CAP, a + r, top, r)))
        if b + width - r > a + r:
            slot.append(new(Curve, (a + r, b + width - r, LINE, a, -bottom, 0.0)))
        if b + width > b + width - r:
            slot.append(new(Curve, (b + width - r, b + width, CAP, b + width - r, top, r)))
        if self._starts:
            self._lower(slot, max(a, self.lo), min(b + width, self.hi))
        else:
            self._curve_list().extend(slot)

    def stand_blade(self, u: float, v: float, width: float, radius: float) -> None:
        """The blade has stood at (u, v): a slot there, unless one was cleared
        at that very place already (a plunge's bottom the pass ends on)."""
        if (u, v) not in self._placed:
            self._placed.add((u, v))
            self.clear_slot(u, u, v, width, radius)

    def _lower(self, slot: List[Curve], a: float, b: float) -> None:
        """The field built, lowered by the ``slot``'s curves over [a, b] only:
        there the new field is the upper envelope of the old one's pieces and
        the slot's (each old piece is a curve at or under the old field)."""
        if not b > a:
            return
        starts, pieces = self._starts, self._pieces
        k0 = max(bisect_right(starts, a) - 1, 0)
        kb = max(bisect_right(starts, b) - 1, 0)
        local = list({id(c): c for c in pieces[k0:kb + 1] if c is not None}.values()) + slot
        sub_starts, sub_pieces = upper_envelope(local, a, b)
        head = k0 + 1 if starts[k0] < a else k0
        tail_starts, tail_pieces = ([b] + starts[kb + 1:], [pieces[kb]] + pieces[kb + 1:]) if b < self.hi else ([], [])
        # No piece follows itself in any of the three parts: only where they join may one run on.
        new_starts, new_pieces = _joined(starts[:head], pieces[:head], sub_starts, sub_pieces)
        self._starts, self._pieces = _joined(new_starts, new_pieces, tail_starts, tail_pieces)
        self._curves = None  # the pieces' curves, taken from them only if ever needed (_field)

    def note_pass(self, env: Envelope, lo: float, hi: float) -> None:
        """The roughing contour passes ran over blade positions [lo, hi] on
        ``env`` (``cycle93_passes.covered`` reads it)."""
        self.passed = (env, lo, hi)

    def _curve_list(self) -> List[Curve]:
        """The curves the field is the envelope of (after a lowering: its pieces' curves, taken when needed)."""
        if self._curves is None:
            self._curves = list({id(c): c for c in self._pieces if c is not None}.values())
        return self._curves

    def _field(self) -> Tuple[List[float], List[Optional[Curve]]]:
        if not self._starts:
            self._starts, self._pieces = upper_envelope(self._curve_list(), self.lo, self.hi)
            # A curve below the field everywhere stays so (slots only lower the material): drop it, so that
            # the next field is built from what stands, not from every slot and pass position so far.
            self._curves = list({id(c): c for c in self._pieces if c is not None}.values())
        return self._starts, self._pieces

    def cuts(self, points: List[Point], width: float, radius: float, floor: List[Point]) -> bool:
        """Whether the blade swept along the lower hull of the front positions
        ``points`` (a stretch of a pass), never below the material top
        ``floor`` (the profile its envelope keeps it on), stands under more
        than MATERIAL_MARGIN of the field."""
        verdict = self._verdict(points, width, radius, floor)
        if verdict is not None:
            return verdict
        return self.exceeds(_sweep(lower_hull(points), width, radius), floor, MATERIAL_MARGIN)

    def _verdict(self, chain: List[Point], width: float, radius: float, floor: List[Point]) -> Optional[bool]:
        """``cuts``' answer where it is plain without the sweep, else None
        (``chain``: the stretch's points, the hull's or any above it).
        True: at a piece of the field (its middle, or by its ends) it stands
        more than MATERIAL_MARGIN over the floor and over the blade standing
        on the chain there (``_over_blade``: at least the outline), so exceeds,
        exact, finds it too. False: wherever the field stands more than
        MATERIAL_MARGIN over the chain's lowest point (the outline is nowhere
        lower) over the swept columns, it stands no more than that over the
        floor (``_under_floor``). Both by VERDICT_EPS: their rounding and
        exceeds' own never part them."""
        starts, pieces = self._field()
        a, b = min(chain)[0] + SIDE_EPS, max(chain)[0] + width - SIDE_EPS  # the hull's first and last u
        inside_a, inside_b = a + WITNESS_INSET, b - WITNESS_INSET
        lowest = min(chain, key=_LEVEL)[1]
        witness, high = MATERIAL_MARGIN + VERDICT_EPS, lowest + MATERIAL_MARGIN + VERDICT_EPS
        k, fall = max(bisect_right(starts, a) - 1, 0), lowest + MATERIAL_MARGIN - VERDICT_EPS
        count, spans, tall = len(pieces), [], []  # pieces standing over high; over fall, not high
        sqrt, axis = math.sqrt, _axis(chain)
        while k < count:
            # lo, hi: max(starts[k], a), min(starts[k + 1], b), written out (this loop runs for every stretch)
            lo = starts[k]
            lo = a if a > lo else lo
            if lo >= b:
                break
            hi = starts[k + 1] if k + 1 < count else b
            hi = b if b < hi else hi
            piece = pieces[k]
            k += 1
            if piece is None:
                continue
            _plo, _phi, kind, cu, cv, size = piece  # stored negated: a line or a cap (its ends hold the real tops)
            if kind == LINE:
                peak, other = -cv - size * (lo - cu), -cv - size * (hi - cu)
            else:
                d, other = abs(lo - cu), abs(hi - cu)
                d = other if other > d else d
                h = size * size - d * d
                peak, other = -cv - sqrt(0.0 if 0.0 > h else h), -math.inf
            peak = other if other > peak else peak
            # The blade and the floor stand at least ``lowest``: only where the field stands higher is looked at.
            if peak <= high:
                if peak > fall:
                    tall.append((lo, hi, piece))
                continue
            spans.append((lo, hi, piece))
            x = 0.5 * (lo + hi)
            if inside_a < x < inside_b:
                level = -value(piece, x)
                if level > high and _over_blade(level, x, chain, width, radius, floor, witness, axis):
                    return True
        left = [(lo, hi, piece) for lo, hi, piece in spans + tall if not _under_floor(piece, lo, hi, floor)]
        if not left or (radius > 0 and _in_end_corners(left, lower_hull(chain), width, radius)):
            return False
        return _by_ends(spans, chain, width, radius, floor, axis, (inside_a, inside_b, high, witness))

    def stand(self, u: float, v: float, width: float) -> float:
        """Highest stand of the field above level v over the columns (u, u + w),
        SIDE_EPS in from both ends (its pieces are lines and cups: their ends
        hold their tops)."""
        starts, pieces = self._field()
        a, b = u + SIDE_EPS, u + width - SIDE_EPS
        k = max(bisect_right(starts, a) - 1, 0)
        best = -math.inf
        while k < len(pieces):
            lo = max(starts[k], a)
            if lo >= b:
                break
            hi = min(starts[k + 1], b) if k + 1 < len(starts) else b
            if pieces[k] is not None:
                best = max(best, -value(pieces[k], lo), -value(pieces[k], hi))
            k += 1
        return best - v

    def exceeds(self, outline: List[Piece], floor: List[Point], limit: float) -> bool:
        """Whether the field stands more than ``limit`` above the piecewise
        ``outline`` raised to ``floor`` less FLOOR_TOL, strictly inside the
        outline's columns (SIDE_EPS in from its ends). Between breakpoints of
        field and outline the difference is monotone, convex, or concave with
        its peak where a field line has an outline arc's slope; only where it
        exceeds the limit is the floor brought in, piece by piece."""
        starts, pieces = self._field()
        a, b = outline[0][0] + SIDE_EPS, outline[-1][1] - SIDE_EPS
        cuts = {x for piece in outline for x in piece[:2] if a < x < b}
        cuts.update(x for x in starts[bisect_right(starts, a):bisect_right(starts, b)] if x < b)
        xs = sorted(cuts.union((a, b)))
        j, last = 0, len(outline) - 1
        k, count = max(bisect_right(starts, a) - 1, 0), len(starts)  # the field's piece over a: the walk starts there
        for x0, x1 in zip(xs, xs[1:]):
            mid = 0.5 * (x0 + x1)
            while outline[j][1] <= mid and j < last:
                j += 1
            while k + 1 < count and starts[k + 1] <= mid:  # the field's piece over mid (mid only grows)
                k += 1
            field = pieces[k]
            if field is not None and _stands_over(field, outline[j][2], x0, x1, limit) \
                    and _floored(field, outline[j][2], floor, x0, x1, limit):
                return True
        return False


def _joined(starts: List[float], pieces: List[Optional[Curve]], more_starts: List[float],
            more_pieces: List[Optional[Curve]]) -> Tuple[List[float], List[Optional[Curve]]]:
    """Two runs of field pieces one after the other, the second's first piece
    dropped where it is the first's last (it runs on)."""
    if pieces and more_pieces and pieces[-1] is more_pieces[0]:
        more_starts, more_pieces = more_starts[1:], more_pieces[1:]
    return starts + more_starts, pieces + more_pieces


def _stands_over(field: Curve, low: Curve, x0: float, x1: float, limit: float) -> bool:
    """Whether the field stands more than ``limit`` above the outline ``low``
    at one of ``_candidates`` (where over (x0, x1) their difference peaks)."""
    for x in _candidates(field, low, x0, x1):
        if -value(field, x) - value(low, x) > limit:
            return True
    return False


def _candidates(field: Curve, low: Curve, x0: float, x1: float) -> List[float]:
    """The ends of (x0, x1) and, inside, where the field (a line) has the slope
    of the outline (an arc): field minus outline peaks at one of them."""
    out = [x0, x1]
    if field.kind == LINE and low.kind == CUP:
        m = -field.size  # the field is stored negated
        x = low.cu + low.size * m / math.sqrt(1.0 + m * m)
        if x0 < x < x1:
            out.append(x)
    return out


def _floored(field: Curve, low: Curve, floor: List[Point], x0: float, x1: float, limit: float) -> bool:
    """Whether the field stands more than ``limit`` over (x0, x1) above the
    outline ``low`` raised to the floor less FLOOR_TOL: per straight piece of
    the floor, at the candidates and where the outline crosses the floor."""
    i = max(bisect_right(floor, (x0, math.inf)) - 1, 0)
    while i + 1 < len(floor) and floor[i][0] < x1:
        (u0, v0), (u1, v1) = floor[i], floor[i + 1]
        i += 1
        y0, y1 = max(u0, x0), min(u1, x1)
        if u1 <= u0 or y1 <= y0:
            continue
        line = Curve(u0, u1, LINE, u0, v0 - FLOOR_TOL, (v1 - v0) / (u1 - u0))
        for y in _candidates(field, low, y0, y1) + [y for y in crossings(low, line) if y0 < y < y1]:
            if -value(field, y) - max(value(low, y), value(line, y)) > limit:
                return True
    return False


def top_at(top: List[Point], x: float) -> Point:
    """(level just left of x, just right of x) of a material top (points by
    increasing u, a vertical step as two points at one u)."""
    i = bisect_left(top, (x, -math.inf))
    j = bisect_right(top, (x, math.inf))
    if i < j:
        return top[i][1], top[j - 1][1]
    if i == 0 or i >= len(top):
        return -math.inf, -math.inf
    (u0, v0), (u1, v1) = top[i - 1], top[i]
    v = v0 + (v1 - v0) * (x - u0) / (u1 - u0)
    return v, v


def _tangent(s: float, r: float) -> Point:
    """Offset from a lower arc's centre to its point of slope s."""
    k = 1.0 / math.sqrt(1.0 + s * s)
    return r * s * k, -r * k


def _blade(out: List[Piece], u: float, v: float, w: float, r: float, a: float, b: float) -> None:
    """The part of the front outline of the blade at (u, v) whose slopes lie
    in [a, b): left arc (slopes below 0), flat (0), right arc (above 0)."""
    cl, cr, cv = u + r, u + w - r, v + r
    if a < 0:
        x0 = u if a == -math.inf else cl + _tangent(a, r)[0]
        x1 = cl if b >= 0 else cl + _tangent(b, r)[0]
        out.append((x0, x1, Curve(x0, x1, CUP, cl, cv, r)))
    if a <= 0 < b:
        out.append((cl, cr, Curve(cl, cr, LINE, cl, v, 0.0)))
    if b > 0:
        x0 = cr if a <= 0 else cr + _tangent(a, r)[0]
        x1 = u + w if b == math.inf else cr + _tangent(b, r)[0]
        out.append((x0, x1, Curve(x0, x1, CUP, cr, cv, r)))


def _sweep(chain: List[Point], w: float, r: float) -> List[Piece]:
    """Lower outline of the blade swept along the convex chain (front
    positions by increasing u, slopes increasing): the Minkowski sum of the
    front outline and the chain, taken in order of slope."""
    out: List[Piece] = []
    slope = -math.inf
    for (u0, v0), (u1, v1) in zip(chain, chain[1:]):
        s = (v1 - v0) / (u1 - u0)
        _blade(out, u0, v0, w, r, slope, s)
        if s < 0:
            du, dv = _tangent(s, r)
            du, dv = r + du, r + dv
        elif s > 0:
            du, dv = _tangent(s, r)
            du, dv = w - r + du, r + dv
        else:
            du, dv = r, 0.0
        out.append((u0 + du, u1 + du, Curve(u0 + du, u1 + du, LINE, u0 + du, v0 + dv, s)))
        slope = s
    _blade(out, chain[-1][0], chain[-1][1], w, r, slope, math.inf)
    return [piece for piece in out if piece[1] > piece[0]]


def lower_hull(pts: List[Point]) -> List[Point]:
    """The lower convex hull of the points (the lowest at each u): a convex
    chain below all of them, by increasing u."""
    lowest = {}
    for u, v in pts:
        if u not in lowest or v < lowest[u]:
            lowest[u] = v
    hull: List[Point] = []
    for p in sorted(lowest.items()):
        while len(hull) >= 2:
            (u0, v0), (u1, v1) = hull[-2], hull[-1]
            if (u1 - u0) * (p[1] - v0) - (v1 - v0) * (p[0] - u0) <= 0:  # hull[-1] on or above the chord
                hull.pop()
            else:
                break
        hull.append(p)
    return hull
