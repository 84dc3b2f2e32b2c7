"""CYCLE93: the material a flat-fronted blade cannot reach.

A paraxial blade (width w, both front corners rounded by r) cannot enter
every concave corner of a CYCLE93 profile: a base chamfer meeting an oblique
base, a base radius smaller than the blade's own, a sharp base corner. The
material it leaves is reported as a warning, never silently.

Definition (the one the simulation checks), in the groove frame (u across,
v out of the material): the lowest level the blade reaches at column x is
``g(x) = min over s in [0, w] of lowest(x - s) + bottom(s)`` (``lowest`` the
final profile's envelope, ``bottom`` the blade's front outline); material is
left where g(x) > f(x), f the final profile's top. Its area is the integral of
g - f, its depth the largest g - f: measured along the plunge axis.

How it is computed exactly, without a grid over columns: a column x the
blade cannot touch is best approached by a blade *stuck* in a position where
it touches the profile on both sides of x (a convex kink of ``lowest``,
where two contacts meet, or a blade flush against a wall), and that blade's
outline is g there. Conversely, between two contacts of any one blade
placement, no other placement touches the profile where this one stays above
it (two translates of the convex outline differ monotonically). So the
unreachable material is the union, over the stuck positions, of the gaps
between consecutive contacts; each gap's area is the closed-form integral of
the outline (flat and circular pieces) minus the profile (straight pieces),
its depth the largest gap at a profile vertex (the gap is convex between
vertices). The stuck positions are found near the two base corners only (the
profile's only concave corners: the edges RCO1/RCO2 are convex), as the
places where the envelope's slope increases between samples (the envelope
is concave between kinks), each located exactly by intersecting the straight
pieces on either side, or by a golden-section search when they are curved.
"""

import math
from bisect import bisect_right
from dataclasses import dataclass
from typing import TYPE_CHECKING, Callable, List, Optional, Sequence, Tuple

from ..numbers import format_value
from ..warnings import CycleWarning
from .cycle93_constants import NAME, PATH_TOLERANCE

if TYPE_CHECKING:  # the geometry imports the warnings, which import this module
    from .cycle93_geometry import GrooveGeometry

Point = Tuple[float, float]

__all__ = ["Unreachable", "REACH_TOLERANCE_MM", "REACH_TOLERANCE_INCH", "unreachable_regions", "reach_warnings"]

# Material left shallower than this (along the plunge axis), or thinner than
# this on average (its area over the length of profile under it), is not
# reported: five times the chord tolerance of the profile's arcs, so that their
# chords never warn (measured along the plunge axis a chord's sliver beside a
# steep arc is deeper, never thicker), and the simulation's tolerance.
REACH_TOLERANCE_MM = 0.001
REACH_TOLERANCE_INCH = 0.00004
SAMPLES = 64  # envelope samples over the blade positions around a base corner
CONTACT = 1e-7  # the outline this close to the profile touches it
KINK_TOLERANCE = 1e-10  # a stuck position is located this closely (u)
SLOPE_NOISE = 1e-9
BOWL_TOLERANCE = 2 * PATH_TOLERANCE  # a chord's sagitta, and some
WALL_GAP = 1e-8  # a blade side this close to a vertical step stands flush against it


@dataclass(frozen=True)
class Unreachable:
    """Material the blade cannot reach: the columns ``u_from``..``u_to`` (groove
    frame) beside base corner ``corner`` (1: RCI1's side, 2: RCI2's), its
    ``area`` and largest ``depth`` along the plunge axis (program units),
    that depth at column ``at``."""

    corner: int
    u_from: float
    u_to: float
    area: float
    depth: float
    at: float


class _Profile:
    """The final profile's top as straight pieces (x0, v0, x1, v1), vertical steps left out."""

    def __init__(self, top: Sequence[Point]) -> None:
        self.pieces = [(u1, v1, u2, v2) for (u1, v1), (u2, v2) in zip(top, top[1:]) if u2 > u1]
        self._ends = [piece[2] for piece in self.pieces]
        # Vertical steps: (u, their top).
        self.steps = [(u1, max(v1, v2)) for (u1, v1), (u2, v2) in zip(top, top[1:]) if u2 == u1]

    def under(self, lo: float, hi: float) -> List[Tuple[float, float, float, float]]:
        """The pieces clipped to [lo, hi]."""
        out = []
        for index in range(bisect_right(self._ends, lo), len(self.pieces)):
            u1, v1, u2, v2 = self.pieces[index]
            if u1 >= hi:
                break
            q = (v2 - v1) / (u2 - u1)
            a, b = max(u1, lo), min(u2, hi)
            out.append((a, v1 + q * (a - u1), b, v1 + q * (b - u1)))
        return out


class _Blade:
    """One blade placement: minus edge at ``u``, front edge at ``level``."""

    def __init__(self, u: float, level: float, width: float, radius: float) -> None:
        self.u, self.level, self.width, self.radius = u, level, width, radius

    def parts(self) -> List[Tuple[float, float, int]]:
        """(x from, x to, kind) of the outline: -1 left arc, 0 flat, 1 right arc."""
        u, w, r = self.u, self.width, self.radius
        if r <= 0:
            return [(u, u + w, 0)]
        return [(u, u + r, -1), (u + r, u + w - r, 0), (u + w - r, u + w, 1)]

    def outline(self, x: float) -> float:
        r, s = self.radius, x - self.u
        if s < r:
            d = r - s
        elif s > self.width - r:
            d = s - (self.width - r)
        else:
            return self.level
        return self.level + r - math.sqrt(max(r * r - d * d, 0.0))

    def tangent(self, kind: int, q: float) -> Optional[float]:
        """Column where the outline part ``kind`` has slope q, None if nowhere."""
        r = self.radius
        if kind < 0 < -q:
            return self.u + r - r * (-q) / math.sqrt(1 + q * q)
        if kind > 0 < q:
            return self.u + self.width - r + r * q / math.sqrt(1 + q * q)
        return None

    def integral(self, x0: float, x1: float, kind: int) -> float:
        """Integral of the outline over [x0, x1], all in part ``kind``."""
        area = self.level * (x1 - x0)
        if kind == 0:
            return area
        r = self.radius
        centre = self.u + r if kind < 0 else self.u + self.width - r
        return area + r * (x1 - x0) - (_circle_integral(x1 - centre, r) - _circle_integral(x0 - centre, r))


def _circle_integral(t: float, r: float) -> float:
    """Antiderivative of sqrt(r^2 - t^2)."""
    t = max(-r, min(r, t))
    return 0.5 * (t * math.sqrt(max(r * r - t * t, 0.0)) + r * r * math.asin(t / r))


def _gaps(blade: _Blade, profile: _Profile) -> List[Tuple[float, ...]]:
    """(from, to, area, depth, column of that depth, length of profile) of each gap between consecutive contacts of
    the blade with the profile (or a wall flush with its side)."""
    pieces = []  # (x0, x1, kind, f0, q): profile straight and outline one part
    for px0, pv0, px1, pv1 in profile.under(blade.u, blade.u + blade.width):
        q = (pv1 - pv0) / (px1 - px0)
        for a, b, kind in blade.parts():
            x0, x1 = max(a, px0), min(b, px1)
            if x1 > x0:
                pieces.append((x0, x1, kind, pv0 + q * (x0 - px0), q))
    if not pieces:
        return []
    contacts = _contacts(blade, pieces, profile.steps)
    gaps = []
    for a, b in zip(contacts, contacts[1:]):
        if b - a > 1e-9:
            gaps.append(_gap(blade, pieces, a, b))
    return gaps


def _contacts(blade: _Blade, pieces: list, steps: List[Point]) -> List[float]:
    """Sorted columns where the outline touches the profile, with the blade's
    sides when a wall stands flush against them."""
    out = []
    for x0, x1, kind, f0, q in pieces:
        xs = [x0, x1]
        t = blade.tangent(kind, q)
        if t is not None and x0 < t < x1:
            xs.append(t)
        out += [x for x in xs if blade.outline(x) - (f0 + q * (x - x0)) <= CONTACT]
    # A wall flush with a side: a vertical step at the edge rises past the outline.
    for edge in (blade.u, blade.u + blade.width):
        if any(abs(u - edge) <= WALL_GAP and top > blade.outline(edge) + CONTACT for u, top in steps):
            out.append(edge)
    return sorted(set(out))


def _gap(blade: _Blade, pieces: list, a: float, b: float) -> Tuple[float, ...]:
    area = depth = length = 0.0
    at = a
    for x0, x1, kind, f0, q in pieces:
        lo, hi = max(x0, a), min(x1, b)
        if hi <= lo:
            continue
        f_lo, f_hi = f0 + q * (lo - x0), f0 + q * (hi - x0)
        area += blade.integral(lo, hi, kind) - 0.5 * (f_lo + f_hi) * (hi - lo)
        length += math.hypot(hi - lo, f_hi - f_lo)
        # Between profile vertices the gap is convex: deepest at a piece's end.
        for x, gap in ((lo, blade.outline(lo) - f_lo), (hi, blade.outline(hi) - f_hi)):
            if gap > depth:
                depth, at = gap, x
    return a, b, area, depth, at, length


def _golden(fn: Callable[[float], float], a: float, b: float) -> float:
    """A local minimum of fn on [a, b] (golden-section search)."""
    k = (math.sqrt(5) - 1) / 2
    c, d = b - k * (b - a), a + k * (b - a)
    fc, fd = fn(c), fn(d)
    while b - a > KINK_TOLERANCE:
        if fc <= fd:
            b, d, fd = d, c, fc
            c = b - k * (b - a)
            fc = fn(c)
        else:
            a, c, fc = c, d, fd
            d = a + k * (b - a)
            fd = fn(d)
    return 0.5 * (a + b)


def _kink(lowest: Callable[[float], float], us: List[float], ls: List[float], i: int) -> float:
    """The stuck position between samples i-1 and i+1, where the slope of
    ``lowest`` increases: where the straight pieces on either side meet, when
    they are straight; else the minimum of lowest tilted by the mean slope."""
    if 2 <= i < len(us) - 2:
        s_left = (ls[i - 1] - ls[i - 2]) / (us[i - 1] - us[i - 2])
        s_right = (ls[i + 2] - ls[i + 1]) / (us[i + 2] - us[i + 1])
        if s_right > s_left:
            u = (ls[i + 1] - ls[i - 1] + s_left * us[i - 1] - s_right * us[i + 1]) / (s_left - s_right)
            if us[i - 1] <= u <= us[i + 1]:
                level = ls[i - 1] + s_left * (u - us[i - 1])
                if abs(lowest(u) - level) <= CONTACT / 10:
                    return u
    mean = 0.5 * ((ls[i] - ls[i - 1]) / (us[i] - us[i - 1]) + (ls[i + 1] - ls[i]) / (us[i + 1] - us[i]))
    return _golden(lambda u: lowest(u) - mean * u, us[i - 1], us[i + 1])


def _bowl(geometry: "GrooveGeometry", index: int) -> Optional[Callable[[float], bool]]:
    """For a base radius the blade's corners fit (RCI >= r): a test whether a
    blade at u with its front edge at a level rests in that bowl as it would on
    the true arc. The profile's arcs are chords, so such a blade has a kink at
    every chord: none of them leaves more than a chord's sagitta, and they need
    no search. None for other corners."""
    corner = geometry.final_corners[index]
    big, r, w = corner.value, geometry.tool.corner_radius, geometry.tool.width
    if big <= 0 or big < r:
        return None
    a = corner.a
    start = (corner.vertex[0] - corner.length * a[0], corner.vertex[1] - corner.length * a[1])
    cx, cy = start[0] - big * a[1], start[1] + big * a[0]  # base corners turn left: centre on the left
    fit = big - r

    def rests(u: float, level: float) -> bool:
        levels = [cy - big]
        for centre in (u + r, u + w - r):
            if abs(centre - cx) <= fit:
                levels.append(cy - r - math.sqrt(fit * fit - (centre - cx) ** 2))
        return any(abs(level - v) <= BOWL_TOLERANCE for v in levels)

    return rests


def _stuck_positions(geometry: "GrooveGeometry", index: int, lo: float, hi: float) -> List[float]:
    """Blade positions in [lo, hi] where the blade is stuck: convex kinks of
    the envelope, and blades flush against a wall."""
    env = geometry.final_env
    walls = env.walls(lo, hi)
    us = sorted(set([lo + (hi - lo) * k / SAMPLES for k in range(SAMPLES + 1)]) | set(env.breakpoints(lo, hi))
                | walls)
    ls = [env.lowest(u) for u in us]
    rests = _bowl(geometry, index)
    found = list(walls)
    for i in range(1, len(us) - 1):
        before = (ls[i] - ls[i - 1]) / (us[i] - us[i - 1])
        after = (ls[i + 1] - ls[i]) / (us[i + 1] - us[i])
        if after <= before + SLOPE_NOISE * (1 + abs(before) + abs(after)) or us[i] in walls:
            continue  # concave, or a blade flush against a wall: already found
        if rests is not None and all(rests(us[k], ls[k]) for k in (i - 1, i, i + 1)):
            continue
        found.append(_kink(env.lowest, us, ls, i))
    return found


def unreachable_regions(geometry: "GrooveGeometry", tolerance: Optional[float] = None) -> List[Unreachable]:
    """The material the blade leaves beside the base corners, deeper than
    ``tolerance`` (default REACH_TOLERANCE_MM or _INCH by the program's units)."""
    if tolerance is None:
        tolerance = REACH_TOLERANCE_MM if geometry.metric else REACH_TOLERANCE_INCH
    tool = geometry.tool
    width, radius = tool.width, tool.corner_radius
    env = geometry.final_env
    profile = _Profile(geometry.final_top)
    spans = []
    for index in (1, 2):
        points = geometry.final_corners[index].points()
        spans.append((min(p[0] for p in points), max(p[0] for p in points)))
    regions: List[Unreachable] = []
    for index, (first, last) in enumerate(spans, 1):
        for u in _stuck_positions(geometry, index, first - width - 1e-6, last + 1e-6):
            blade = _Blade(u, env.lowest(u), width, radius)
            for a, b, area, depth, at, length in _gaps(blade, profile):
                # Thinner on average than the tolerance: chords' slivers along an arc.
                thick = depth > tolerance and area > tolerance * length
                if thick and not any(r.u_from < b and a < r.u_to for r in regions):
                    regions.append(Unreachable(_nearest(spans, a, b), a, b, area, depth, at))
    return sorted(regions, key=lambda r: r.u_from)


def _nearest(spans: List[Tuple[float, float]], a: float, b: float) -> int:
    """The base corner (1 or 2) whose element lies nearest the columns a..b."""
    distances = [max(first - b, a - last, 0.0) for first, last in spans]
    return 1 if distances[0] <= distances[1] else 2


def _amount(value: float, decimals: int) -> str:
    """value to ``decimals`` places, or to two significant digits when that rounds to 0."""
    text = "%.*f" % (decimals, value)
    if float(text) == 0:
        text = "%.2g" % value
    return text


def reach_warnings(geometry: "GrooveGeometry") -> List[CycleWarning]:
    """One warning per base corner where the blade leaves material."""
    regions = unreachable_regions(geometry)
    tool = geometry.tool
    units = "mm" if geometry.metric else "in"
    decimals = 2 if geometry.metric else 4
    out = []
    for corner in (1, 2):
        mine = [r for r in regions if r.corner == corner]
        if not mine:
            continue
        area = sum(r.area for r in mine)
        depth = max(r.depth for r in mine)
        message = "%s %s² up to %s %s deep at base corner %d cannot be reached by a %s %s flat blade (r%s)" % (
            _amount(area, decimals), units, _amount(depth, decimals), units, corner, format_value(tool.width), units,
            format_value(tool.corner_radius))
        out.append(CycleWarning(NAME, "RCI%d" % corner, message))
    return out
