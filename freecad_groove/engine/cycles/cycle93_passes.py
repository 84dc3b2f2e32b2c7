"""Steps 3 and 4 of CYCLE93 fed only where material remains.

A contour or finishing pass follows the blade's envelope over a profile
(``Envelope.trace``). Most of it runs where the plunges (and the passes
before it) have already cut: only the moves that would cut something
(``MaterialTop.cuts``) are fed. Between two such stretches the blade either
feeds on through the air of the gap or rapids out to the clearance VRT above
the contour, across, and down to a re-entry clearance above the material left
under the blade, whichever takes less time when a rapid runs RAPID_FEED_RATIO
times as fast as the feed (the machining-time benchmark's rates: 10,000 and
100 mm/min). A rapid never runs through material: out of a stretch the blade
rises through the columns it has just cut, across at the clearance, and down
only to REENTRY_CLEARANCE above the highest material the field still holds
under the blade.
"""

import math
from typing import TYPE_CHECKING, Callable, List, Tuple

from .cycle93_constants import REENTRY_CLEARANCE_INCH, REENTRY_CLEARANCE_MM
from .cycle93_material import MaterialTop

if TYPE_CHECKING:  # the geometry imports this module
    from .cycle93_geometry import GrooveGeometry

Point = Tuple[float, float]
Go = Callable[[str, float, float], None]

# Rapid rate over feed rate that decides between feeding through a gap and
# rapiding around it (the benchmark's 10,000 and 100 mm/min).
RAPID_FEED_RATIO = 100.0


def _stretches(pts: List[Point], material: MaterialTop, width: float, radius: float) -> List[List[int]]:
    """[first, last] point indexes of the runs of moves that cut something.
    A trace of one point (a blade as wide as the opening) is a plunge to it:
    [0, 0] when the blade's front there has material above it."""
    if len(pts) == 1:
        return [[0, 0]] if material.cuts(pts[0], pts[0], width, radius) else []
    runs: List[List[int]] = []
    for k, (p, q) in enumerate(zip(pts, pts[1:])):
        if material.cuts(p, q, width, radius):
            if runs and runs[-1][1] == k:
                runs[-1][1] = k + 1
            else:
                runs.append([k, k + 1])
    return runs


def _entry(geo: "GrooveGeometry", material: MaterialTop, at: Point) -> float:
    """Level the blade may rapid down to above ``at``: REENTRY_CLEARANCE (at
    most VRT) over the highest material under it, never below ``at``."""
    u, v = at
    w = geo.tool.width
    stand = max(material.excess([(u + 1e-7, v), (u + w - 1e-7, v)]), 0.0)
    gap = min(geo.params["VRT"], REENTRY_CLEARANCE_MM if geo.metric else REENTRY_CLEARANCE_INCH)
    return min(v + stand + gap, geo.clearance(u))


def _length(pts: List[Point]) -> float:
    return sum(math.dist(p, q) for p, q in zip(pts, pts[1:]))


def feed_where_material(geo: "GrooveGeometry", pts: List[Point], go: Go, material: MaterialTop) -> None:
    """Feed the stretches of the trace ``pts`` that cut, linked the cheaper
    way; the blade comes from and goes back to the clearance."""
    w, r = geo.tool.width, geo.tool.corner_radius
    runs = _stretches(pts, material, w, r)
    here = None  # the point the blade stands on, None at the clearance
    for first, last in runs:
        start = pts[first]
        if here is not None:
            gap = pts[here:first + 1]
            end = pts[here]
            entry = _entry(geo, material, start)
            around = (geo.clearance(end[0]) - end[1]) + math.dist(
                (end[0], geo.clearance(end[0])), (start[0], geo.clearance(start[0]))
            ) + (geo.clearance(start[0]) - entry)
            if around / RAPID_FEED_RATIO + (entry - start[1]) < _length(gap):
                go("r", end[0], geo.clearance(end[0]))
                here = None
            else:
                for q in gap[1:]:
                    go("f", *q)
        if here is None:
            entry = _entry(geo, material, start)
            go("r", start[0], geo.clearance(start[0]))
            go("r", start[0], entry)
            go("f", *start)
            if first == last:  # a plunge: what it cleared is the front at start
                material.clear_move(start, start, w, r)
        for p, q in zip(pts[first:last], pts[first + 1:last + 1]):
            go("f", *q)
            material.clear_move(p, q, w, r)
        here = last
    if here is not None:
        end = pts[here]
        go("r", end[0], geo.clearance(end[0]))
