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

The blade positions are every one over the opening, from its left edge - w
to its right edge: a paraxial blade goes wherever it does not cut the part,
also overhanging an edge of the opening (where an oblique contour falls away
beyond it, lower than the flanks let it go: the passes run out there,
``GrooveGeometry.pass_range``). Material counts only below the contour line
(the stock's top).

How it is computed exactly, without a grid over columns: a column x the
blade cannot touch is best approached by a blade *stuck* in a position where
it touches the profile on both sides of x (a kink of ``lowest``, where two
contacts meet, a blade flush against a wall, or a blade at an end of the
passes' range, whose side bounds it), and that blade's outline is g there.
Conversely, between two contacts of any one blade placement, no other
placement touches the profile where this one stays above it (two translates
of the convex outline differ monotonically). So the unreachable material is
the union, over the stuck positions, of the gaps between consecutive
contacts. Everything is closed-form on the exact profile (lines and arcs, as
the envelope has them): the kinks are where the envelope's pieces meet at an
angle (``Envelope.kinks``); a contact is a profile vertex or a point where
the outline and the profile have the same slope; each gap's area is the
integral of the outline (flat and circular pieces, cut by the contour line)
minus the profile's, its depth the largest difference at a vertex, a
crossing or a point of equal slopes. Where a wall makes ``lowest`` jump, a gap
that another stuck blade reaches below is not counted.
"""

import math
from bisect import bisect_right
from collections import OrderedDict
from dataclasses import dataclass
from typing import TYPE_CHECKING, Dict, List, Optional, Sequence, Tuple

from ..envelope import Arc
from ..numbers import format_value
from ..warnings import CycleWarning
from .cycle93_constants import NAME

if TYPE_CHECKING:  # the geometry imports the warnings, which import this module
    from .cycle93_geometry import GrooveGeometry

Point = Tuple[float, float]
# One piece of the profile under the blade, clipped to one part of its outline:
# (x0, x1, outline part -1/0/1, the profile's level at x0, its slope, its arc or None).
Piece = Tuple[float, float, int, float, float, Optional[Arc]]

__all__ = ["Unreachable", "REACH_TOLERANCE_MM", "REACH_TOLERANCE_INCH", "unreachable_regions", "reach_warnings"]

# Material left shallower than this (along the plunge axis) is not reported:
# the simulation's tolerance. The computation is exact (no chords), so no
# other threshold is needed: every sliver deeper than this is named.
REACH_TOLERANCE_MM = 0.001
REACH_TOLERANCE_INCH = 0.00004
CONTACT = 1e-7  # the outline this close to the profile touches it
STEP = 1e-12  # a profile element this narrow is a vertical step (as in the envelope)
WALL_GAP = 1e-8  # a blade side this close to a vertical step stands flush against it


# The profile's corners in order along it: the parameter and the words of the warning.
CORNER_NAMES = (("RCO1", "edge corner 1"), ("RCI1", "base corner 1"), ("RCI2", "base corner 2"),
                ("RCO2", "edge corner 2"))


@dataclass(frozen=True)
class Unreachable:
    """Material the blade cannot reach: the columns ``u_from``..``u_to`` (groove
    frame) beside the corner named by ``parameter`` (RCO1, RCI1, RCI2, RCO2:
    the one whose element lies nearest) on side ``corner`` (1: the start
    point's, 2: the other), its ``area`` and largest ``depth`` along the
    plunge axis (program units), that depth at column ``at``."""

    corner: int
    u_from: float
    u_to: float
    area: float
    depth: float
    at: float
    parameter: str = "RCI1"


class _Profile:
    """The final profile's top exactly: straight pieces and arcs (u1, v1, u2,
    v2, arc or None), vertical steps apart, as the envelope has them."""

    def __init__(self, points: Sequence[Point], arcs: Dict[int, Arc], slope: float) -> None:
        self.slope = slope  # the contour line v = slope * u
        self.pieces = []
        self.steps = []  # vertical steps: (u, their top)
        for index, ((u1, v1), (u2, v2)) in enumerate(zip(points, points[1:])):
            if u2 - u1 <= STEP:
                self.steps.append((u1, max(v1, v2)))
            else:
                self.pieces.append((u1, v1, u2, v2, arcs.get(index)))
        self._ends = [piece[2] for piece in self.pieces]

    def under(self, lo: float, hi: float) -> List[Tuple[float, float, float, float, Optional[Arc]]]:
        """The pieces clipped to [lo, hi]: (x0, x1, level at x0, slope of a straight piece, arc)."""
        out = []
        for index in range(bisect_right(self._ends, lo), len(self.pieces)):
            u1, v1, u2, v2, arc = self.pieces[index]
            if u1 >= hi:
                break
            a, b = max(u1, lo), min(u2, hi)
            if arc is None:
                q = (v2 - v1) / (u2 - u1)
                out.append((a, b, v1 + q * (a - u1), q, None))
            else:
                out.append((a, b, 0.0, 0.0, arc))
        return out


def _level(piece: Piece, x: float) -> float:
    """The profile's level at column x of the piece."""
    x0, _x1, _kind, f0, q, arc = piece
    if arc is None:
        return f0 + q * (x - x0)
    (cu, cv), big = arc.center, arc.radius
    root = math.sqrt(max(big * big - (x - cu) ** 2, 0.0))
    return cv + root if arc.bump else cv - root


def _profile_integral(piece: Piece, a: float, b: float) -> float:
    """Integral of the profile over [a, b] within the piece."""
    x0, _x1, _kind, f0, q, arc = piece
    if arc is None:
        return (f0 + q * (0.5 * (a + b) - x0)) * (b - a)
    (cu, cv), big = arc.center, arc.radius
    bulge = _circle_integral(b - cu, big) - _circle_integral(a - cu, big)
    return cv * (b - a) + (bulge if arc.bump else -bulge)


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

    def centre(self, kind: int) -> float:
        """Column of the centre of the corner ``kind`` (-1 left, 1 right)."""
        return self.u + self.radius if kind < 0 else self.u + self.width - self.radius

    def tangent(self, kind: int, q: float) -> Optional[float]:
        """Column where the outline part ``kind`` has slope q, None if nowhere."""
        r = self.radius
        if kind < 0 < -q:
            return self.u + r - r * (-q) / math.sqrt(1 + q * q)
        if kind > 0 < q:
            return self.u + self.width - r + r * q / math.sqrt(1 + q * q)
        return None

    def same_slope(self, kind: int, piece: Piece) -> Optional[float]:
        """A column where outline part ``kind`` and the profile piece have the
        same slope (where their difference may be least or greatest), None if none."""
        _x0, _x1, _kind, _f0, q, arc = piece
        if arc is None:
            return self.tangent(kind, q)
        (cu, _cv), big = arc.center, arc.radius
        if kind == 0:
            return cu  # the top of a bump, the bottom of a bowl
        r, c = self.radius, self.centre(kind)
        span = r + big if arc.bump else r - big
        if abs(span) < 1e-15 or abs(cu - c) > abs(span):
            return None
        return c + r * (cu - c) / span

    def crossings(self, kind: int, slope: float) -> List[float]:
        """Columns where outline part ``kind`` may meet the line v = slope * u."""
        if kind == 0:
            return [self.level / slope] if slope else []
        r, c0 = self.radius, self.level + self.radius
        centre = self.centre(kind)
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
        r, centre = self.radius, self.centre(kind)
        return area + r * (x1 - x0) - (_circle_integral(x1 - centre, r) - _circle_integral(x0 - centre, r))


def _circle_integral(t: float, r: float) -> float:
    """Antiderivative of sqrt(r^2 - t^2)."""
    t = max(-r, min(r, t))
    return 0.5 * (t * math.sqrt(max(r * r - t * t, 0.0)) + r * r * math.asin(t / r))


def _gaps(blade: _Blade, profile: _Profile, edges: List[float], columns: Point) -> List[Tuple[float, ...]]:
    """(from, to, area, depth, column of that depth) of each gap between consecutive contacts of
    the blade with the profile (or a wall flush with its side, or one of ``edges``), within ``columns``."""
    pieces: List[Piece] = []
    for px0, px1, f0, q, arc in profile.under(blade.u, blade.u + blade.width):
        for a, b, kind in blade.parts():
            x0, x1 = max(a, px0), min(b, px1)
            if x1 > x0:
                pieces.append((x0, x1, kind, f0 + q * (x0 - px0), q, arc))
    if not pieces:
        return []
    contacts = sorted(set(_contacts(blade, pieces, profile.steps) + edges))
    gaps = []
    for a, b in zip(contacts, contacts[1:]):
        a, b = max(a, columns[0]), min(b, columns[1])
        if b - a > 1e-9:
            gaps.append(_gap(blade, pieces, a, b, profile.slope))
    return gaps


def _contacts(blade: _Blade, pieces: List[Piece], steps: List[Point]) -> List[float]:
    """Sorted columns where the outline touches the profile, with the blade's
    sides when a wall stands flush against them."""
    out = []
    for piece in pieces:
        x0, x1, kind = piece[:3]
        xs = [x0, x1]
        t = blade.same_slope(kind, piece)
        if t is not None and x0 < t < x1:
            xs.append(t)
        out += [x for x in xs if blade.outline(x) - _level(piece, x) <= CONTACT]
    # A wall flush with a side: a vertical step at the edge rises past the outline.
    for edge in (blade.u, blade.u + blade.width):
        if any(abs(u - edge) <= WALL_GAP and top > blade.outline(edge) + CONTACT for u, top in steps):
            out.append(edge)
    return sorted(set(out))


def _gap(blade: _Blade, pieces: List[Piece], a: float, b: float, slope: float) -> Tuple[float, ...]:
    """The gap between the outline and the profile over a..b, below the
    contour line v = slope * u (the stock's top: above it there is nothing to cut)."""
    area = depth = 0.0
    at = a
    for piece in pieces:
        x0, x1, kind = piece[:3]
        lo, hi = max(x0, a), min(x1, b)
        if hi <= lo:
            continue
        cuts = [lo] + sorted(x for x in blade.crossings(kind, slope) if lo < x < hi) + [hi]
        for c0, c1 in zip(cuts, cuts[1:]):
            mid = 0.5 * (c0 + c1)
            if blade.outline(mid) <= slope * mid:
                area += blade.integral(c0, c1, kind)
            else:
                area += 0.5 * slope * (c1 * c1 - c0 * c0)
            area -= _profile_integral(piece, c0, c1)
        # Elsewhere the gap is monotonic: deepest at an end, a crossing or where the slopes match.
        for x in cuts + _turning(blade, kind, piece, slope):
            if lo <= x <= hi:
                gap = min(blade.outline(x), slope * x) - _level(piece, x)
                if gap > depth:
                    depth, at = gap, x
    return a, b, area, depth, at


def _turning(blade: _Blade, kind: int, piece: Piece, slope: float) -> List[float]:
    """Columns where the gap over the piece may turn: the outline's or the
    contour line's slope matching the profile's (a bowl under the contour line)."""
    out = []
    t = blade.same_slope(kind, piece)
    if t is not None:
        out.append(t)
    arc = piece[5]
    if arc is not None and not arc.bump:
        out.append(arc.center[0] + arc.radius * slope / math.sqrt(1 + slope * slope))
    return out


def unreachable_regions(geometry: "GrooveGeometry", tolerance: Optional[float] = None) -> List[Unreachable]:
    """The material the blade leaves in the groove, deeper than ``tolerance``
    (default REACH_TOLERANCE_MM or _INCH by the program's units)."""
    if tolerance is None:
        tolerance = REACH_TOLERANCE_MM if geometry.metric else REACH_TOLERANCE_INCH
    tool = geometry.tool
    width, radius = tool.width, tool.corner_radius
    left, right = geometry.opening(geometry.final_top)
    # Every blade position over the opening, also overhanging an edge (the finishing passes run out past the
    # lower one).
    lo, hi = left - width, right
    env = geometry.final_env
    profile = _Profile(env.points, env.arcs, geometry.slope)
    spans = [(min(p[0] for p in ends), max(p[0] for p in ends))
             for ends in (corner.element()[0] for corner in geometry.final_corners)]
    stuck = {lo, hi} | env.walls(lo, hi) | set(env.kinks(lo, hi))
    blades = [_Blade(u, env.lowest(u), width, radius) for u in sorted(stuck)]
    regions: List[Unreachable] = []
    for blade in blades:
        # At the ends of the passes' range the blade goes no further: its side bounds what it reaches.
        edges = [edge for edge, end in ((blade.u, lo), (blade.u + width, hi + width)) if abs(edge - end) <= WALL_GAP]
        for a, b, area, depth, at in _gaps(blade, profile, edges, (left, right)):
            if depth > tolerance and not _lower(blades, blade, at) and not any(
                    r.u_from < b and a < r.u_to for r in regions):
                nearest = _nearest(spans, a, b)
                regions.append(Unreachable(1 if nearest < 2 else 2, a, b, area, depth, at,
                                           CORNER_NAMES[nearest][0]))
    return sorted(regions, key=lambda r: r.u_from)


def _lower(blades: List[_Blade], blade: _Blade, x: float) -> bool:
    """True when another stuck blade reaches below ``blade`` at column x: where
    a wall makes ``lowest`` jump, only the blade flush with it goes deep."""
    mine = blade.outline(x) - CONTACT
    return any(other.u <= x <= other.u + other.width and other.outline(x) < mine for other in blades)


def _nearest(spans: List[Point], a: float, b: float) -> int:
    """The corner (0..3: RCO1, RCI1, RCI2, RCO2) whose element lies nearest the
    columns a..b, a base corner before an edge at the same distance."""
    def key(index: int) -> Tuple[float, int]:
        first, last = spans[index]
        distance = max(first - b, a - last, 0.0)
        return (distance if distance > WALL_GAP else 0.0, index in (0, 3))
    return min(range(4), key=key)


def _amount(value: float, decimals: int) -> str:
    """value to ``decimals`` places, or to two significant digits when that rounds to 0 (no exponent)."""
    text = "%.*f" % (decimals, value)
    if float(text) == 0 and value > 0:
        text = "%.*f" % (1 - math.floor(math.log10(value)), value)
    return text


# The warnings of the last few groove shapes. A groove's geometry is built in its own frame (u, v from its start
# point AXFA/AXSA), from the other parameters, the settings and the units alone: the same groove elsewhere in a
# program leaves the same material, figure for figure, and its warnings are not computed again.
REACH_CACHE_SIZE = 32
_REACH_CACHE: "OrderedDict[tuple, Tuple[CycleWarning, ...]]" = OrderedDict()
_PLACE = ("axfa", "axsa")  # the call's parameters that only place the groove


def reach_warnings(geometry: "GrooveGeometry") -> List[CycleWarning]:
    """One warning per corner (base corners, and the edges where the passes
    start and end) where the blade leaves material."""
    key = (repr(tuple(value for name, value in vars(geometry.call).items() if name not in _PLACE)),
           geometry.settings, geometry.metric)  # the values' repr: -0.0 is not 0.0
    found = _REACH_CACHE.get(key)
    if found is None:
        found = _REACH_CACHE[key] = tuple(_reach_warnings(geometry))
        if len(_REACH_CACHE) > REACH_CACHE_SIZE:
            _REACH_CACHE.popitem(last=False)
    else:
        _REACH_CACHE.move_to_end(key)
    return list(found)


def _reach_warnings(geometry: "GrooveGeometry") -> List[CycleWarning]:
    regions = unreachable_regions(geometry)
    tool = geometry.tool
    units = "mm" if geometry.metric else "in"
    decimals = 2 if geometry.metric else 4
    out = []
    for parameter, where in CORNER_NAMES:
        mine = [r for r in regions if r.parameter == parameter]
        if not mine:
            continue
        area = sum(r.area for r in mine)
        depth = max(r.depth for r in mine)
        message = "%s %s² up to %s %s deep at %s cannot be reached by a %s %s flat blade (r%s)" % (
            _amount(area, decimals), units, _amount(depth, decimals), units, where, format_value(tool.width), units,
            format_value(tool.corner_radius))
        out.append(CycleWarning(NAME, parameter, message))
    return out
