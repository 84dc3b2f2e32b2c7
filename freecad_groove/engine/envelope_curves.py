"""The closed-form curves a blade's lowest level is made of, their upper
envelope, and their chords.

Every way the blade can touch one element of a material top (``envelope_contacts``)
gives the blade's level v as a function of its position u over an interval:
a line, or the upper (cap) or lower (cup) half of a circle. The lowest level
the blade may stand at is the maximum of those curves (``upper_envelope``):
a sequence of pieces of them, each followed exactly and chorded directly to a
tolerance (``chords``), caps by a polygon outside them and cups by chords
inside them, so that no chord dips below the boundary.
"""

import math
from math import sqrt as _sqrt
from typing import List, NamedTuple, Optional, Sequence, Tuple

Point = Tuple[float, float]

LINE, CAP, CUP = 0, 1, -1

TIE = 1e-9  # two curves this close at a point are tied there: the one rising above the other wins
TIE_PROBE = 1e-7  # how far after a point where two curves meet they are compared


class Curve(NamedTuple):
    """One candidate piece of the blade's lowest level over u in [lo, hi].

    LINE: v = cv + size * (u - cu). CAP / CUP: the upper / lower half of the
    circle of centre (cu, cv) and radius size."""

    lo: float
    hi: float
    kind: int
    cu: float
    cv: float
    size: float


def value(curve: Optional[Curve], u: float) -> float:
    """The curve's level at u (-inf for no curve: no material under the blade)."""
    if curve is None:
        return -math.inf
    _lo, _hi, kind, cu, cv, size = curve  # one unpacking: this runs for every point of every envelope
    if kind == LINE:
        return cv + size * (u - cu)
    d = u - cu
    h = size * size - d * d
    root = _sqrt(h) if h > 0 else 0.0
    return cv + root if kind == CAP else cv - root


def _line_line(p: Curve, q: Curve) -> List[float]:
    _plo, _phi, _pk, pu, pv, ps = p
    _qlo, _qhi, _qk, qu, qv, qs = q
    den = ps - qs
    if den == 0:
        return []
    return [(qv - pv + ps * pu - qs * qu) / den]


def _line_circle(line: Curve, circle: Curve) -> List[float]:
    """u where the line meets the whole circle (a tangency counts once)."""
    _llo, _lhi, _lk, lu, lv, s = line
    _clo, _chi, _ck, cu, cv, r = circle
    k = lv + s * (cu - lu) - cv  # line's height over the centre
    a = 1 + s * s
    disc = a * r * r - k * k
    if disc < -1e-12 * a * r * r:
        return []
    root = _sqrt(disc) if disc > 0 else 0.0
    return [cu + (-s * k - root) / a, cu + (-s * k + root) / a]


def _circle_circle(p: Curve, q: Curve) -> List[float]:
    _plo, _phi, _pk, pu, pv, pr = p
    _qlo, _qhi, _qk, qu, qv, qr = q
    du, dv = qu - pu, qv - pv
    d2 = du * du + dv * dv
    if d2 < 1e-24:
        return []
    d = _sqrt(d2)
    a = (d2 + pr * pr - qr * qr) / (2 * d)
    h2 = pr * pr - a * a
    if h2 < -1e-12 * max(pr, qr) ** 2:
        return []
    h = _sqrt(h2) if h2 > 0 else 0.0
    eu, ev = du / d, dv / d
    mid = pu + a * eu
    return [mid - h * ev, mid + h * ev]


def crossings(p: Curve, q: Curve) -> List[float]:
    """u where the two curves may meet: where their lines or whole circles
    do (a superset of where the half circles do)."""
    if p[2] == LINE:  # p.kind
        return _line_line(p, q) if q[2] == LINE else _line_circle(p, q)
    if q[2] == LINE:
        return _line_circle(q, p)
    return _circle_circle(p, q)


def slope(curve: Curve, u: float) -> float:
    """dv/du of the curve at u (infinite where a circle stands vertical)."""
    _lo, _hi, kind, cu, _cv, size = curve
    if kind == LINE:
        return size
    d = u - cu
    h = size * size - d * d
    if h <= 0:
        return -math.inf * d * kind if d else 0.0
    return -d / _sqrt(h) * kind


def _rises(p: Curve, q: Curve, u: float) -> bool:
    """True when p goes on above q just after u, where the two meet: judged
    TIE_PROBE after u, clear of the rounding of where they meet (two curves
    meeting tangentially have the same slope there)."""
    after = u + TIE_PROBE
    rate = slope(p, after) - slope(q, after)
    if rate == rate and abs(rate) > 1e-12:  # not NaN (two vertical tangents)
        return rate > 0
    return value(p, after) > value(q, after)


def _winner(active: Sequence[Curve], u: float) -> Optional[Curve]:
    """The highest curve just after u, of those whose interval goes on past u:
    of those tied at u, the one rising above the others."""
    best, level = None, -math.inf
    for curve in active:
        lo, hi, kind, cu, cv, size = curve
        if not lo <= u < hi:
            continue
        if kind == LINE:  # value(curve, u), written out
            v = cv + size * (u - cu)
        else:
            d = u - cu
            h = size * size - d * d
            root = _sqrt(h) if h > 0 else 0.0
            v = cv + root if kind == CAP else cv - root
        if v > level + TIE or (best is not None and v > level - TIE and _rises(curve, best, u)):
            best, level = curve, level if level > v else v  # max(v, level)
    return best


def _next_event(curves: Sequence[Curve], start: int, active: Sequence[Curve], top: Curve,
                u: float, stop: float) -> float:
    """The first u after ``u`` (at most ``stop``) where another curve may rise
    above ``top``: where it starts at or above it, or crosses it rising."""
    top_line = top[2] == LINE
    for curve in active:
        hi = curve[1]  # curve.hi
        if curve is top or hi <= u:
            continue
        if curve[2] == LINE:  # crossings(curve, top), its dispatch written out (this runs for every pair)
            xs = _line_line(curve, top) if top_line else _line_circle(curve, top)
        else:
            xs = _line_circle(top, curve) if top_line else _circle_circle(curve, top)
        for x in xs:
            if u < x < stop and x < hi and _rises(curve, top, x):
                stop = x
    for index in range(start, len(curves)):
        curve = curves[index]
        lo, hi = curve[0], curve[1]
        if lo >= stop:
            break
        if value(curve, lo) >= value(top, lo) - TIE:
            return lo  # the curves are sorted by start: none starts earlier
        for x in crossings(curve, top):
            if lo < x < stop and x < hi and _rises(curve, top, x):
                stop = x
    return stop


def upper_envelope(curves: List[Curve], lo: float, hi: float) -> Tuple[List[float], List[Optional[Curve]]]:
    """The maximum of the curves over [lo, hi] as pieces: starts[i] and
    the curve over [starts[i], starts[i + 1]] (the last up to hi); None where
    no curve is defined."""
    curves = sorted(curves)
    starts: List[float] = []
    pieces: List[Optional[Curve]] = []
    active: List[Curve] = []
    k, u = 0, lo
    count = len(curves)
    budget = 100 * (count + 10) ** 2  # each pair of curves crosses at most twice
    while u < hi:
        budget -= 1
        if budget < 0:
            raise RuntimeError("envelope: no progress at u=%r" % u)
        while k < count and curves[k][0] <= u:  # curves[k].lo
            active.append(curves[k])
            k += 1
        active = [c for c in active if c[1] > u]  # c.hi
        top = _winner(active, u)
        if top is None:
            nxt = curves[k][0] if k < count else hi
        else:
            end = top[1]
            nxt = _next_event(curves, k, active, top, u, hi if hi < end else end)  # min(top.hi, hi)
        if not pieces or pieces[-1] is not top:
            starts.append(u)
            pieces.append(top)
        u = hi if hi < nxt else nxt  # min(nxt, hi)
    return starts, pieces


def inside_step(radius: float, tol: float) -> float:
    """Angle of a chord inside a circle that stays within tol of it."""
    return 2 * math.acos(max(1 - tol / radius, -1.0))


def outside_step(radius: float, tol: float) -> float:
    """Angle between the tangent points of a polygon outside a circle that
    stays within tol of it (its corners at radius + tol)."""
    return 2 * math.acos(radius / (radius + tol))


def chords(curve: Curve, a: float, b: float, tol: float) -> List[Point]:
    """Points after (a, v(a)) up to (b, v(b)) whose straight moves follow the
    curve within tol without dipping below it."""
    end = (b, value(curve, b))
    if curve.kind == LINE or curve.size <= 0 or b <= a:
        return [end]
    r, cu, cv = curve.size, curve.cu, curve.cv
    ta = math.acos(max(-1.0, min(1.0, (a - cu) / r)))
    tb = math.acos(max(-1.0, min(1.0, (b - cu) / r)))
    if ta - tb < 1e-12:
        return [end]
    if curve.kind == CAP:  # angles from ta down to tb; corners outside the circle
        n = math.ceil((ta - tb) / outside_step(r, tol))
        d = (tb - ta) / n
        rr = r / math.cos(d / 2)
        out = [(cu + rr * math.cos(ta + (k + 0.5) * d), cv + rr * math.sin(ta + (k + 0.5) * d)) for k in range(n)]
    else:  # a cup: angles -ta to -tb, points on the circle
        n = math.ceil((ta - tb) / inside_step(r, tol))
        d = (ta - tb) / n
        out = [(cu + r * math.cos(k * d - ta), cv + r * math.sin(k * d - ta)) for k in range(1, n)]
    out.append(end)
    return out
