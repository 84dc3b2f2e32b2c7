"""The tool's moves of the Milltronics autoroutines (``milltronics``): G33's
back-and-forth facing and G34's pocket laps, from a resolved ``Cut``. The
module notes of ``milltronics`` say how each is read.
"""

import math
from typing import List, NamedTuple, Optional, Tuple

from ..errors import CycleError
from ..moves import ARC_CCW, ARC_CW, FEED, RAPID, Move
from ..numbers import MAX_MOVES, MIN_ARC_CHORD

TOLERANCE = 1e-9
# G34's laps step out at most this many tool diameters even when P155 allows more: between two laps with
# sharp corners, a point on the corner's bisector is left uncut once the step exceeds (1 + 1/sqrt(2)) radii
LAP_STEP_LIMIT = 0.85
# A point of a lap (u, v about the rectangle's centre) and, for the end of a
# rounded corner, the arc that reaches it: (centre u, centre v, clockwise); None: straight.
LapPoint = Tuple[float, float, Optional[Tuple[float, float, bool]]]


class Cut(NamedTuple):
    """An autoroutine with every value resolved, in the program's units."""

    cx: float  # the rectangle's centre: the XY position before the call
    cy: float
    z0: Optional[float]  # Z before the call; None: not known (the first move is X Y at the height held)
    size_x: float  # P151
    size_y: float  # P152
    width: float  # P155
    radius: float  # the tool's radius
    clearance: float  # R
    depths: Tuple[float, ...]  # V .. Z
    lift: float
    xy_feed: float
    z_feed: float
    back_to: Optional[float]  # the Z at the end: G99 R, G98 z0; None: the lift above the last depth
    clockwise: bool  # G42 (G34 laps)


class _Tool:
    """The tool's position as the moves are made; points relative to the centre."""

    def __init__(self, cut: Cut, name: str) -> None:
        self.cut = cut
        self.name = name
        self.x, self.y, self.z = cut.cx, cut.cy, cut.z0
        self.moves: List[Move] = []

    def _add(self, kind: str, x: float, y: float, z: Optional[float], f: Optional[float],
             centre: Optional[Tuple[float, float]] = None) -> None:
        """A move to (x, y, z); z None only while the Z before the call is not known (the Z held)."""
        same_z = z == self.z if z is None or self.z is None else abs(z - self.z) <= TOLERANCE
        if abs(x - self.x) <= TOLERANCE and abs(y - self.y) <= TOLERANCE and same_z:
            return
        self.x, self.y, self.z = x, y, z
        self.moves.append(Move(kind, x, z, f, 0.0, y, centre=centre))
        if len(self.moves) > MAX_MOVES:
            raise CycleError("P155", self.cut.width, "the cycle would make more than %d moves" % MAX_MOVES,
                             cycle=self.name)

    def rapid_z(self, z: float) -> None:
        self._add(RAPID, self.x, self.y, z, None)

    def rapid_xy(self, u: float, v: float) -> None:
        self._add(RAPID, self.cut.cx + u, self.cut.cy + v, self.z, None)

    def feed_z(self, z: float) -> None:
        self._add(FEED, self.x, self.y, z, self.cut.z_feed)

    def feed_xy(self, u: float, v: float) -> None:
        self._add(FEED, self.cut.cx + u, self.cut.cy + v, self.z, self.cut.xy_feed)

    def feed_lap(self, point: LapPoint) -> None:
        """A feed to a lap's point: straight, or along the arc that reaches it."""
        u, v, arc = point
        if arc is None:
            self.feed_xy(u, v)
        else:
            cu, cv, clockwise = arc
            self._add(ARC_CW if clockwise else ARC_CCW, self.cut.cx + u, self.cut.cy + v, self.z, self.cut.xy_feed,
                      (self.cut.cx + cu, self.cut.cy + cv))

    def enter(self, u: float, v: float, depth: float, first: bool) -> None:
        """To the start (u, v) of a depth: over it at the clearance plane first, else by the lift."""
        if first:
            if self.z is not None:  # not known: X Y at the height held, then Z to R (the module notes)
                self.rapid_z(max(self.z, self.cut.clearance))
            self.rapid_xy(u, v)
            self.rapid_z(self.cut.clearance)
        else:
            self.rapid_z(self.z + self.cut.lift)
            self.rapid_xy(u, v)
        self.feed_z(depth)

    def leave(self) -> List[Move]:
        """G99: to the clearance plane; G98: to the Z before the call; else the lift above the last depth."""
        self.rapid_z(self.cut.back_to if self.cut.back_to is not None else self.z + self.cut.lift)
        return self.moves


def _even_steps(span: float, width: float, cycle: str) -> List[float]:
    """0, s, 2s, ... span with s the largest equal step at most ``width``."""
    if span <= TOLERANCE:
        return [0.0]
    count = max(1, math.ceil(span / width - 1e-9))
    if count > MAX_MOVES:  # before the list is made: the moves' own limit would come too late
        raise CycleError("P155", width, "the cut width is too small for the rectangle: more than %d passes"
                         % MAX_MOVES, cycle=cycle)
    return [span * index / count for index in range(count + 1)]


def facing_moves(cut: Cut, name: str = "G33") -> List[Move]:
    """G33: from the upper right corner, back and forth along the long side."""
    tool = _Tool(cut, name)
    half_x, half_y = cut.size_x / 2.0 - cut.radius, cut.size_y / 2.0 - cut.radius
    along_x = cut.size_x >= cut.size_y
    short = 2.0 * (half_y if along_x else half_x)
    steps = _even_steps(short, cut.width, name)
    for index, depth in enumerate(cut.depths):
        tool.enter(half_x, half_y, depth, index == 0)
        for number, step in enumerate(steps):
            if along_x:
                v = half_y - step
                tool.feed_xy(tool.x - cut.cx, v)
                tool.feed_xy(-half_x if number % 2 == 0 else half_x, v)
            else:
                u = half_x - step
                tool.feed_xy(u, tool.y - cut.cy)
                tool.feed_xy(u, -half_y if number % 2 == 0 else half_y)
    return tool.leave()


def _corner(cx: float, cy: float, radius: float, start: float, clockwise: bool) -> List[LapPoint]:
    """The end of a quarter arc of ``radius`` about (cx, cy) from angle ``start``, reached along it; a
    sharp corner (radius 0) is its centre, an arc shorter than MIN_ARC_CHORD a chord (its end written
    to the output's resolution could fall behind its start and turn it the other way round)."""
    if radius <= TOLERANCE:
        return [(cx, cy, None)]
    end = start + (-1.0 if clockwise else 1.0) * math.pi / 2
    arc = (cx, cy, clockwise) if radius * math.sqrt(2.0) >= MIN_ARC_CHORD else None
    return [(cx + radius * math.cos(end), cy + radius * math.sin(end), arc)]


def lap_points(half_x: float, half_y: float, corner: float, clockwise: bool) -> List[LapPoint]:
    """A closed lap of a rectangle with rounded corners about (0, 0), from (half_x, 0) back to it."""
    corner = min(max(corner, 0.0), half_x, half_y)
    ix, iy = half_x - corner, half_y - corner
    # corner centres and the angle each arc starts at, counter-clockwise from the right side
    corners = [((ix, iy), 0.0), ((-ix, iy), math.pi / 2), ((-ix, -iy), math.pi), ((ix, -iy), 1.5 * math.pi)]
    points: List[LapPoint] = [(half_x, 0.0, None)]  # each lap starts and ends at the right side's middle
    if clockwise:
        for (x, y), start in reversed(corners):
            points.append((x + corner * math.cos(start + math.pi / 2), y + corner * math.sin(start + math.pi / 2),
                           None))
            points += _corner(x, y, corner, start + math.pi / 2, True)
    else:
        for (x, y), start in corners:
            points.append((x + corner * math.cos(start), y + corner * math.sin(start), None))
            points += _corner(x, y, corner, start, False)
    points.append((half_x, 0.0, None))
    return points


def pocket_laps(cut: Cut, stock: float, corner: float, name: str = "G34") -> List[List[LapPoint]]:
    """The tool centre's paths at one depth, from the centre outward (see the module notes)."""
    half_x = cut.size_x / 2.0 - cut.radius - stock
    half_y = cut.size_y / 2.0 - cut.radius - stock
    outer_corner = max(corner - cut.radius - stock, 0.0) if corner > 0 else 0.0
    inset = min(half_x, half_y)
    spine_x, spine_y = half_x - inset, half_y - inset
    paths = [[(0.0, 0.0, None), (-spine_x, -spine_y, None), (spine_x, spine_y, None)]]
    for offset in _even_steps(inset, min(cut.width, LAP_STEP_LIMIT * 2 * cut.radius), name)[1:]:
        rest = inset - offset
        paths.append(lap_points(half_x - rest, half_y - rest, max(outer_corner - rest, 0.0), cut.clockwise))
    return paths


def pocket_moves(cut: Cut, stock: float, corner: float, finish_depth: Optional[float], name: str = "G34") -> List[Move]:
    """G34: at each depth the centre line and the laps; the last depth and the finishing lap."""
    tool = _Tool(cut, name)
    depths = cut.depths + ((finish_depth,) if finish_depth is not None else ())
    laps = pocket_laps(cut, stock, corner, name)
    for index, depth in enumerate(depths):
        tool.enter(0.0, 0.0, depth, index == 0)
        for lap in laps:
            for point in lap:
                tool.feed_lap(point)
    if stock > 0:
        finish = pocket_laps(cut._replace(width=max(cut.size_x, cut.size_y)), 0.0, corner, name)[-1]
        for point in finish:
            tool.feed_lap(point)
    return tool.leave()


