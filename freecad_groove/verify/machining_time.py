"""Machining time of lathe moves from feeds and speeds (no geometry library).

Feeds per minute take length / feed. Feeds per revolution take
length / (feed x rpm); with constant surface speed V (m/min) the spindle
turns at rpm(x) = min(max_rpm, 1000 V / (2 pi x)) at radius x, so the time
of a straight move is its length times the mean of 1 / (feed x rpm) along it,
integrated in closed form; an arc (G2/G3) is timed along its chords
(arcs.TIME_TOL). Dwells take their seconds. Rapids take
max(|dx| / rapid_x, |dz| / rapid_z) (each axis at its own rapid rate) when
both rates are known, else they are not timed (``rapids_timed`` False).
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Optional

from freecad_groove.engine.moves import DWELL, FEED, RAPID, Move

from .arcs import TIME_TOL, straight

SECONDS_PER_MINUTE = 60.0


@dataclass(frozen=True)
class Feeds:
    """What the moves run at. feed: mm/rev (per_rev) or mm/min; rpm: fixed
    spindle speed, or None with surface_speed (m/min) capped at max_rpm;
    rapid_x, rapid_z: rapid rates in mm/min (0: unknown)."""

    feed: float
    per_rev: bool
    rpm: Optional[float] = None
    surface_speed: Optional[float] = None
    max_rpm: Optional[float] = None
    rapid_x: float = 0.0
    rapid_z: float = 0.0

    @property
    def rapids_timed(self) -> bool:
        return self.rapid_x > 0 and self.rapid_z > 0


@dataclass(frozen=True)
class MachiningTime:
    """Seconds spent feeding, dwelling and (when timed) at rapid."""

    feed: float
    dwell: float
    rapid: float
    rapids_timed: bool

    @property
    def total(self) -> float:
        return self.feed + self.dwell + self.rapid

    def describe(self) -> str:
        rapid = "rapids %.1f s" % self.rapid if self.rapids_timed else "rapids not timed: no rapid rates"
        return "%.1f s (feeds %.1f s, dwells %.1f s, %s)" % (self.total, self.feed, self.dwell, rapid)


def _minutes_per_rev_integral(x: float, feeds: Feeds) -> float:
    """Antiderivative over the radius of 1 / rpm(x) (minutes per revolution
    times mm), odd in x: rpm depends on |x|."""
    k = feeds.surface_speed * 1000.0 / (2.0 * math.pi)
    xc = k / feeds.max_rpm  # below this radius the spindle runs at its limit
    a = abs(x)
    value = a / feeds.max_rpm if a <= xc else xc / feeds.max_rpm + (a * a - xc * xc) / (2.0 * k)
    return math.copysign(value, x)


def _revolutions_per_mm(x0: float, x1: float, feeds: Feeds) -> float:
    """Mean of 1 / rpm (minutes per revolution) along a move from radius x0 to x1."""
    if feeds.surface_speed is None:
        return 1.0 / feeds.rpm
    if abs(x1 - x0) < 1e-12:
        k = feeds.surface_speed * 1000.0 / (2.0 * math.pi)
        return max(1.0 / feeds.max_rpm, abs(x0) / k)
    return (_minutes_per_rev_integral(x1, feeds) - _minutes_per_rev_integral(x0, feeds)) / (x1 - x0)


def feed_seconds(start: tuple[float, float], end: tuple[float, float], feeds: Feeds) -> float:
    """Seconds of a feed move from (x, z) start to end."""
    length = math.hypot(end[0] - start[0], end[1] - start[1])
    if length == 0:
        return 0.0
    if not feeds.per_rev:
        return length / feeds.feed * SECONDS_PER_MINUTE
    return length / feeds.feed * _revolutions_per_mm(start[0], end[0], feeds) * SECONDS_PER_MINUTE


def rapid_seconds(start: tuple[float, float], end: tuple[float, float], feeds: Feeds) -> float:
    if not feeds.rapids_timed:
        return 0.0
    return max(abs(end[0] - start[0]) / feeds.rapid_x, abs(end[1] - start[1]) / feeds.rapid_z) * SECONDS_PER_MINUTE


def machining_time(start: tuple[float, float], moves: Iterable[Move], feeds: Feeds) -> MachiningTime:
    """The time of ``moves`` (x radius, z) from ``start`` (x, z)."""
    pos = (float(start[0]), float(start[1]))
    cut = dwell = rapid = 0.0
    for move in straight(moves, pos, TIME_TOL):
        end = (float(move.x), float(move.z))
        if move.kind == FEED:
            cut += feed_seconds(pos, end, feeds)
        elif move.kind == RAPID:
            rapid += rapid_seconds(pos, end, feeds)
        elif move.kind == DWELL:
            dwell += float(move.p)
            continue
        pos = end
    return MachiningTime(cut, dwell, rapid, feeds.rapids_timed)


def clock_text(seconds: float) -> str:
    """HH:MM:SS, as FreeCAD's CAM ops write CycleTime (rounded to the nearest second)."""
    total = int(round(max(seconds, 0.0)))
    return "%02d:%02d:%02d" % (total // 3600, total % 3600 // 60, total % 60)
