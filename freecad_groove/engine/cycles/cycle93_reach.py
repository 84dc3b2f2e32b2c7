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

The blade positions are those the contour and finishing passes use (the
plunges lie between them): from the opening's left edge - r to its right edge
- w + r; material counts only below the contour line (the stock's top).

How it is computed exactly, without a grid over columns: a column x the
blade cannot touch is best approached by a blade *stuck* in a position where
it touches the profile on both sides of x (a convex kink of ``lowest``,
where two contacts meet, a blade flush against a wall, or a blade at an end
of the passes' range, whose side bounds it), and that blade's outline is g
there. Conversely, between two contacts of any one blade placement, no other
placement touches the profile where this one stays above it (two translates
of the convex outline differ monotonically). So the unreachable material is
the union, over the stuck positions, of the gaps between consecutive
contacts; each gap's area is the closed-form integral of the outline (flat
and circular pieces, cut by the contour line) minus the profile (straight
pieces), its depth the largest gap at a profile vertex or crossing. The kinks
are found exactly: the blade's level over one straight piece of the profile
is concave in its position, so ``lowest`` (their maximum) kinks only where
the piece holding the blade up changes; between the envelope's breakpoints
that change is located by bisection, to 1e-11. Chords of an arc the blade
rolls over (a convex edge, a base radius >= r) are not searched: their kinks
leave no more than a chord's sagitta. Where a wall makes ``lowest`` jump, a
gap that another stuck blade reaches below is not counted.
"""

import math
from bisect import bisect_left, bisect_right
from dataclasses import dataclass
from typing import TYPE_CHECKING, List, Optional, Sequence, Tuple

from ..numbers import format_value
from ..warnings import CycleWarning
from .cycle93_constants import NAME

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
CONTACT = 1e-7  # the outline this close to the profile touches it
KINK_TOLERANCE = 1e-11  # a stuck position is located this closely (u)
EDGE = 1e-9  # a piece this close to the blade's side only touches it (Envelope's EDGE_EPS)
HOLD = 1e-12  # a piece this close to the blade's level holds it up
MAX_SPLITS = 40  # pieces holding the blade up in turn between two breakpoints, at most
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

    def __init__(self, top: Sequence[Point], slope: float) -> None:
        self.slope = slope  # the contour line v = slope * u
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

    def crossings(self, kind: int, slope: float) -> List[float]:
        """Columns where outline part ``kind`` may meet the line v = slope * u."""
        if kind == 0:
            return [self.level / slope] if slope else []
        r, c0 = self.radius, self.level + self.radius
        centre = self.u + r if kind < 0 else self.u + self.width - r
        a, b, c = 1 + slope * slope, -2 * (centre + c0 * slope), centre * centre + c0 * c0 - r * r
        disc = b * b - 4 * a * c
        if disc < 0:
            return []
        root = math.sqrt(disc)
        return [(-b - root) / (2 * a), (-b + root) / (2 * a)]

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


def _gaps(blade: _Blade, profile: _Profile, edges: List[float], columns: Point) -> List[Tuple[float, ...]]:
    """(from, to, area, depth, column of that depth, length of profile) of each gap between consecutive contacts of
    the blade with the profile (or a wall flush with its side, or one of ``edges``), within ``columns``."""
    pieces = []  # (x0, x1, kind, f0, q): profile straight and outline one part
    for px0, pv0, px1, pv1 in profile.under(blade.u, blade.u + blade.width):
        q = (pv1 - pv0) / (px1 - px0)
        for a, b, kind in blade.parts():
            x0, x1 = max(a, px0), min(b, px1)
            if x1 > x0:
                pieces.append((x0, x1, kind, pv0 + q * (x0 - px0), q))
    if not pieces:
        return []
    contacts = sorted(set(_contacts(blade, pieces, profile.steps) + edges))
    gaps = []
    for a, b in zip(contacts, contacts[1:]):
        a, b = max(a, columns[0]), min(b, columns[1])
        if b - a > 1e-9:
            gaps.append(_gap(blade, pieces, a, b, profile.slope))
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


def _gap(blade: _Blade, pieces: list, a: float, b: float, slope: float) -> Tuple[float, ...]:
    """The gap between the outline and the profile over a..b, below the
    contour line v = slope * u (the stock's top: above it there is nothing to cut)."""
    area = depth = length = 0.0
    at = a
    for x0, x1, kind, f0, q in pieces:
        lo, hi = max(x0, a), min(x1, b)
        if hi <= lo:
            continue
        length += math.hypot(hi - lo, q * (hi - lo))
        cuts = [lo] + sorted(x for x in blade.crossings(kind, slope) if lo < x < hi) + [hi]
        for c0, c1 in zip(cuts, cuts[1:]):
            mid = 0.5 * (c0 + c1)
            if blade.outline(mid) <= slope * mid:
                area += blade.integral(c0, c1, kind)
            else:
                area += 0.5 * slope * (c1 * c1 - c0 * c0)
            area -= (f0 + q * (0.5 * (c0 + c1) - x0)) * (c1 - c0)
        # Between profile vertices and crossings the gap is convex or straight: deepest at an end.
        for x in cuts:
            gap = min(blade.outline(x), slope * x) - (f0 + q * (x - x0))
            if gap > depth:
                depth, at = gap, x
    return a, b, area, depth, at, length


class _Levels:
    """The blade's lowest level over each straight piece and vertical step of
    the final profile (the same formulas as ``Envelope.lowest``, one piece at
    a time), so that the piece holding the blade up is known at every
    position: its maximum over the pieces is ``lowest``."""

    def __init__(self, geometry: "GrooveGeometry") -> None:
        tool = geometry.tool
        self.width, self.radius = tool.width, tool.corner_radius
        top = geometry.final_top
        # (u1, v1, u2, v2, slope or None for a vertical step), in order along u.
        self.pieces = [(u1, v1, u2, v2, (v2 - v1) / (u2 - u1) if u2 > u1 else None)
                       for (u1, v1), (u2, v2) in zip(top, top[1:])]
        self._ends = [piece[2] for piece in self.pieces]
        self._tops = [max(piece[1], piece[3]) for piece in self.pieces]
        self.element = _elements(geometry, self.pieces)

    def bottom(self, s: float) -> float:
        r = self.radius
        d = r - s if s < r else s - (self.width - r)
        return r - math.sqrt(max(r * r - d * d, 0.0)) if d > 0 else 0.0

    def level(self, index: int, u: float) -> float:
        """The lowest level of the blade at u over piece ``index`` alone (-inf where it is not under the blade)."""
        u1, v1, u2, v2, q = self.pieces[index]
        r, w = self.radius, self.width
        if q is None:  # a wall: it counts on its high side only, not just outside the blade
            s = u1 - u
            if (s <= EDGE if v1 > v2 else s >= w - EDGE) or not -EDGE <= s <= w + EDGE:
                return -math.inf
            return max(v1, v2) - self.bottom(s)
        a, b = max(u1, u) - u, min(u2, u + w) - u
        if a > b or (b - a <= EDGE and (a <= EDGE or b >= w - EDGE)):
            return -math.inf
        best = -math.inf
        for s_from, s_to, kind in ((0.0, r, -1), (r, w - r, 0), (w - r, w, 1)) if r > 0 else ((0.0, w, 0),):
            ta, tb = max(a, s_from), min(b, s_to)
            if ta > tb:
                continue
            candidates = [ta, tb]
            if kind < 0 < -q:
                candidates.append(r - r * (-q) / math.sqrt(1 + q * q))
            elif kind > 0 < q:
                candidates.append(w - r + r * q / math.sqrt(1 + q * q))
            for s in candidates:
                if ta <= s <= tb:
                    best = max(best, v1 + q * (u + s - u1) - self.bottom(s))
        return best

    def highest(self, u: float) -> Tuple[float, int]:
        """``lowest(u)`` and the piece that sets it."""
        best, which = -math.inf, -1
        for index in range(bisect_left(self._ends, u - EDGE), len(self.pieces)):
            if self.pieces[index][0] > u + self.width + EDGE:
                break
            if self._tops[index] <= best:
                continue  # the blade never sits above a piece's top: it cannot raise it
            level = self.level(index, u)
            if level > best:
                best, which = level, index
        return best, which


def _elements(geometry: "GrooveGeometry", pieces: list) -> List[Optional[int]]:
    """For each piece, the corner (0..3: RCO1, RCI1, RCI2, RCO2) whose arc
    it is a chord of, when the blade rolls over that arc without a gap (a
    convex edge, or a base radius the blade's corners fit); else None."""
    out: List[Optional[int]] = [None] * len(pieces)
    r = geometry.tool.corner_radius
    for index, corner in enumerate(geometry.final_corners):
        if corner.value <= 0 or (corner.left and corner.value < r):
            continue
        points = corner.points()
        lo, hi = points[0][0], points[-1][0]
        for k, piece in enumerate(pieces):
            if lo <= piece[0] and piece[2] <= hi and piece[2] > piece[0]:
                out[k] = index
    return out


def _stuck_positions(levels: _Levels, lo: float, hi: float, walls: Sequence[float]) -> List[float]:
    """The blade positions in [lo, hi] where ``lowest`` has a convex kink: where
    the piece holding the blade up changes (the levels over single pieces
    are concave, so only a change makes a kink), located exactly by bisection
    between the breakpoints; the blades flush against a wall; the ends."""
    found = [lo, hi] + [u for u in walls if lo < u < hi]
    cuts = sorted(set(found) | set(u for u in levels.breakpoints if lo < u < hi))
    for a, b in zip(cuts, cuts[1:]):
        if b - a > 2 * KINK_TOLERANCE:
            nudge = min(KINK_TOLERANCE, (b - a) / 4)
            _split(levels, a + nudge, b - nudge, levels.highest(a + nudge)[1], levels.highest(b - nudge)[1], found, 0)
    return found


def _split(levels: _Levels, a: float, b: float, left: int, right: int, found: List[float], depth: int) -> None:
    """Between a (held by piece ``left``) and b (by ``right``): the kinks."""
    if left == right or left < 0 or right < 0 or depth > MAX_SPLITS:
        return
    same = levels.element[left]
    if same is not None and same == levels.element[right]:
        return  # two chords of an arc the blade rolls over: no gap beyond a chord's sagitta
    lo, hi = a, b
    while hi - lo > KINK_TOLERANCE:
        mid = 0.5 * (lo + hi)
        if levels.level(left, mid) >= levels.level(right, mid):
            lo = mid
        else:
            hi = mid
    # Which pieces really hold the blade on either side: another one may
    # hold it between, or ``right`` may only enter the blade's span here.
    top_lo, holds_lo = levels.highest(lo)
    top_hi, holds_hi = levels.highest(hi)
    if levels.level(left, lo) < top_lo - HOLD:
        _split(levels, a, lo, left, holds_lo, found, depth + 1)
    if levels.level(right, hi) < top_hi - HOLD:
        _split(levels, hi, b, holds_hi, right, found, depth + 1)
    if holds_lo != holds_hi:
        found.append(0.5 * (lo + hi))


def unreachable_regions(geometry: "GrooveGeometry", tolerance: Optional[float] = None) -> List[Unreachable]:
    """The material the blade leaves in the groove, deeper than ``tolerance``
    (default REACH_TOLERANCE_MM or _INCH by the program's units)."""
    if tolerance is None:
        tolerance = REACH_TOLERANCE_MM if geometry.metric else REACH_TOLERANCE_INCH
    tool = geometry.tool
    width, radius = tool.width, tool.corner_radius
    left, right = geometry.opening(geometry.final_top)
    # The blade positions the contour and finishing passes use (and the plunges, between them).
    lo, hi = left - radius, right - width + radius
    env = geometry.final_env
    levels = _Levels(geometry)
    levels.breakpoints = env.breakpoints(lo, hi)
    profile = _Profile(geometry.final_top, geometry.slope)
    spans = []
    for index in (1, 2):
        points = geometry.final_corners[index].points()
        spans.append((min(p[0] for p in points), max(p[0] for p in points)))
    blades = [_Blade(u, levels.highest(u)[0], width, radius)
              for u in sorted(set(_stuck_positions(levels, lo, hi, sorted(env.walls(lo, hi)))))]
    regions: List[Unreachable] = []
    for blade in blades:
        # At the ends of the passes' range the blade goes no further: its side bounds what it reaches.
        edges = [edge for edge, end in ((blade.u, lo), (blade.u + width, hi + width)) if abs(edge - end) <= WALL_GAP]
        for a, b, area, depth, at, length in _gaps(blade, profile, edges, (left, right)):
            # Thinner on average than the tolerance: chords' slivers along an arc.
            thick = depth > tolerance and area > tolerance * length
            if thick and not _lower(blades, blade, at) and not any(r.u_from < b and a < r.u_to for r in regions):
                regions.append(Unreachable(_nearest(spans, a, b), a, b, area, depth, at))
    return sorted(regions, key=lambda r: r.u_from)


def _lower(blades: List[_Blade], blade: _Blade, x: float) -> bool:
    """True when another stuck blade reaches below ``blade`` at column x: where
    a wall makes ``lowest`` jump, only the blade flush with it goes deep."""
    mine = blade.outline(x) - CONTACT
    return any(other.u <= x <= other.u + other.width and other.outline(x) < mine for other in blades)


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
