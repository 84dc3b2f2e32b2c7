"""Where CYCLE93's stretch shortcut (``MaterialTop._verdict``) looks: the
margins the field is judged by, the blades standing on a stretch over a
column (``_over_blade``: material over them is material the swept blade
cuts), and the places where what stands over a stretch is no material to
cut (``_under_floor``: no higher than the profile under it;
``_in_end_corners``: the corner arcs of a blade that stood at the
stretch's end). Each answers only where the exact sweep
(``MaterialTop.exceeds``) answers the same, by VERDICT_EPS.
"""

import math
from bisect import bisect_left, bisect_right
from operator import itemgetter
from typing import List, Optional, Tuple

from ..envelope_curves import CAP, LINE, Curve, value
from .cycle93_constants import PATH_TOLERANCE

Point = Tuple[float, float]
Piece = Tuple[float, float, Curve]  # x from, x to, the curve

# Material thinner than this (mm or in) under a stretch of a pass counts as
# already cut: a little over the passes' own path tolerance (PATH_TOLERANCE)
# and half the 0.001 a program writes; it also absorbs the float noise
# between the plunges' bottoms and the passes' points (different computations).
MATERIAL_MARGIN = 0.0005
# How far the profile's polyline (its arcs chorded toward more material) may
# stand above the profile the envelope keeps the blade on.
FLOOR_TOL = PATH_TOLERANCE
# A blade side within this of a wall only slides along it.
SIDE_EPS = 1e-7
# cuts' shortcut (MaterialTop._verdict) answers only this clear of MATERIAL_MARGIN: far over the rounding of
# exceeds' evaluation (about 1e-13 at these sizes), so the two never part.
VERDICT_EPS = 1e-9
# How far in from a field piece's ends the shortcut looks for material standing over the blade.
WITNESS_INSET = 1e-6
_INF = math.inf


def _blade_level(x: float, u: float, v: float, w: float, r: float) -> float:
    """Level of the front outline of the blade at (u, v) over column x (inf beside it)."""
    if x < u or x > u + w:
        return math.inf
    d = u + r - x if x < u + r else x - (u + w - r) if x > u + w - r else 0.0
    return v + r - math.sqrt(max(r * r - d * d, 0.0)) if d > 0 else v


def _over_blade(level: float, x: float, chain: List[Point], w: float, r: float, floor: List[Point],
                margin: float, axis: Optional[Tuple[List[float], bool]] = None) -> bool:
    """Whether ``level`` (the field's at column x) stands more than ``margin``
    over the floor less FLOOR_TOL there and over a blade standing on
    ``chain`` (at a point, or on a segment where its flat front covers x:
    at the ends of those places, where a segment is lowest; all on or above
    the chain's lower hull, so at least the outline swept along it). Never
    where x is not strictly inside a floor piece: exceeds does not look
    there. ``axis``: the chain's u ascending (``_axis``), to find the
    segments and the points over x by bisection."""
    i = bisect_right(floor, (x, _INF)) - 1
    if i < 0 or i + 1 >= len(floor):
        return False
    (u0, v0), (u1, v1) = floor[i], floor[i + 1]
    if not u0 < x < u1 or level - (v0 - FLOOR_TOL + (v1 - v0) / (u1 - u0) * (x - u0)) <= margin:
        return False
    flat = (x - w + r, x - r)  # the blade positions whose flat front covers x
    if axis is not None:
        return _over_blade_by_axis(level, x, flat, chain, axis, w, r, margin)
    p0, q0 = chain[0]
    for p1, q1 in chain[1:]:
        for c in flat:
            if (p0 < c < p1 or p1 < c < p0) and level - (q0 + (q1 - q0) * (c - p0) / (p1 - p0)) > margin:
                return True
        p0, q0 = p1, q1
    left = x - w
    for u, v in chain:
        if left <= u <= x and level - _blade_level(x, u, v, w, r) > margin:  # a blade over x
            return True
    return False


def _axis(chain: List[Point]) -> Optional[Tuple[List[float], bool]]:
    """For a long chain whose u never turns back (a stretch over an arc's
    chords): its u ascending, and whether the chain runs by decreasing u;
    None for a short chain (looked through whole) or one that turns back."""
    if len(chain) <= 8:
        return None
    us = list(map(itemgetter(0), chain))
    if us == sorted(us):
        return us, False
    if us == sorted(us, reverse=True):
        return us[::-1], True
    return None


def _over_blade_by_axis(level: float, x: float, flat: Tuple[float, float], chain: List[Point],
                        axis: Tuple[List[float], bool], w: float, r: float, margin: float) -> bool:
    """_over_blade's blades on the chain, found by bisection of its u: the
    segment strictly about each end of ``flat`` (u never turns back: one),
    and the points over x; the same tests on them."""
    us, flip = axis
    last = len(us) - 1
    for c in flat:
        j = bisect_right(us, c)  # us[j - 1] <= c < us[j]
        if 0 < j <= last and us[j - 1] < c:
            (p0, q0), (p1, q1) = (chain[j - 1], chain[j]) if not flip else (chain[last - j], chain[last - j + 1])
            if level - (q0 + (q1 - q0) * (c - p0) / (p1 - p0)) > margin:
                return True
    for k in range(bisect_left(us, x - w), bisect_right(us, x)):
        u, v = chain[last - k] if flip else chain[k]
        if level - _blade_level(x, u, v, w, r) > margin:  # a blade over x
            return True
    return False


def _by_ends(spans: List[Piece], chain: List[Point], w: float, r: float, floor: List[Point],
             axis: Optional[Tuple[List[float], bool]], bounds: Tuple[float, float, float, float]) -> Optional[bool]:
    """_verdict's True near the ends of the pieces standing higher than the
    chain (``spans``), else None: ``bounds`` are its (inside_a, inside_b,
    high, witness)."""
    inside_a, inside_b, high, witness = bounds
    for lo, hi, piece in spans:
        for x in (lo + WITNESS_INSET, hi - WITNESS_INSET):
            if lo < x < hi and inside_a < x < inside_b:
                level = -value(piece, x)
                if level > high and _over_blade(level, x, chain, w, r, floor, witness, axis):
                    return True
    return None


def _in_end_corners(spans: List[Piece], hull: List[Point], w: float, r: float) -> bool:
    """Whether every piece of ``spans`` is the corner arc of the blade at an
    end of the ``hull`` (the slot a blade stood in there), within the
    columns of that corner, where the swept outline is that blade's own
    front: left of the first point's corner end when the hull does not fall
    from it (a blade further on stands no lower and its corner higher), the
    mirror at the last point; the field minus the outline is 0 there."""
    (u0, v0), (u1, v1) = hull[0], hull[-1]
    first = len(hull) == 1 or hull[1][1] >= v0
    last = len(hull) == 1 or hull[-2][1] >= v1
    for lo, hi, piece in spans:
        if not (first and _same_circle(piece, u0 + r, v0 + r, r) and u0 <= lo and hi <= u0 + r
                or last and _same_circle(piece, u1 + w - r, v1 + r, r) and u1 + w - r <= lo and hi <= u1 + w):
            return False
    return True


def _same_circle(piece: Curve, cu: float, cv: float, r: float) -> bool:
    """Whether the field piece is the lower half circle of centre (cu, cv) and radius r (stored negated),
    but for float noise far below MATERIAL_MARGIN even where the circle stands vertical."""
    return piece.kind == CAP and abs(piece.cu - cu) <= 1e-12 and abs(piece.cv + cv) <= 1e-12 \
        and abs(piece.size - r) <= 1e-12


def _under_floor(piece: Curve, lo: float, hi: float, floor: List[Point]) -> bool:
    """Whether the field ``piece`` stands nowhere over [lo, hi] more than
    MATERIAL_MARGIN less VERDICT_EPS above the floor less FLOOR_TOL, the
    floor straight between its points there (no vertical step inside): the
    field's real level is a line or a cup, so its height over a straight
    piece of floor peaks at one of that piece's ends (exceeds raises the
    outline to that floor: no material there)."""
    if piece.kind not in (LINE, CAP):
        return False
    limit = MATERIAL_MARGIN - VERDICT_EPS
    i = bisect_right(floor, (lo, _INF)) - 1
    while 0 <= i < len(floor) - 1:
        (u0, v0), (u1, v1) = floor[i], floor[i + 1]
        if not u0 < u1:
            return False
        rate = (v1 - v0) / (u1 - u0)
        for y in (u0 if u0 > lo else lo, u1 if u1 < hi else hi):
            if -value(piece, y) - (v0 - FLOOR_TOL + rate * (y - u0)) > limit:
                return False
        if u1 >= hi:
            return True
        i += 1
    return False
