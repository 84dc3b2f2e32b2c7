"""The blade's outline in the lathe's half plane and the area it sweeps.

Tool positions are (x, z) like ``moves.Move``; the outlines are shapely (z, x).
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
import shapely
from shapely.geometry import Polygon
from shapely.geometry.polygon import orient

from freecad_groove.engine.moves import MINUS_X, MINUS_Z, PLUS_X, PLUS_Z, GroovingTool

# Largest amount (mm) by which the polygonal corner arcs may exceed the true arc.
ARC_EXCESS = 2e-5


def _arc_segments(radius: float) -> int:
    """Segments per quarter arc so that the circumscribed polygon exceeds the
    true arc by at most ARC_EXCESS (and never fewer than 32)."""
    if radius <= 0:
        return 0
    # excess of a circumscribed polygon = r * (1 / cos(step / 2) - 1) ~ r * step^2 / 8
    step = math.sqrt(8.0 * ARC_EXCESS / radius)
    return int(min(512, max(32, math.ceil((math.pi / 2) / step))))


def _corner(cu: float, cv: float, radius: float, start_angle: float, n: int) -> list[tuple[float, float]]:
    """Circumscribed polygonal quarter arc around centre (cu, cv), counter-
    clockwise from start_angle: both tangent points (exactly on the arc) plus
    the intersections of n+1 evenly spaced tangent lines."""
    step = (math.pi / 2) / n
    far = radius / math.cos(step / 2)
    pts = [(cu + radius * math.cos(start_angle), cv + radius * math.sin(start_angle))]
    for k in range(n):
        a = start_angle + (k + 0.5) * step
        pts.append((cu + far * math.cos(a), cv + far * math.sin(a)))
    end = start_angle + math.pi / 2
    pts.append((cu + radius * math.cos(end), cv + radius * math.sin(end)))
    return pts


@lru_cache(maxsize=256)
def _local_outline(width: float, radius: float, length: float) -> np.ndarray:
    """Blade outline in its own frame: u across the front edge (0..width),
    v from the front edge (v=0) back along the blade (v=length)."""
    pts = [(0.0, length)]
    if radius > 1e-7:  # (below that: sharp, for the geometry's sake)
        n = _arc_segments(radius)
        pts += _corner(radius, radius, radius, math.pi, n)  # front corner at u=0
        pts += _corner(width - radius, radius, radius, 1.5 * math.pi, n)  # front corner at u=width
    else:
        pts += [(0.0, 0.0), (width, 0.0)]
    pts.append((width, length))
    return np.array(pts, dtype=float)


@lru_cache(maxsize=256)
def outline_at_origin(tool: GroovingTool, plunge: str) -> np.ndarray:
    """(z, x) outline vertices of the tool with its reference corner at (0, 0)
    (read-only: the array is cached)."""
    local = _local_outline(float(tool.width), float(tool.corner_radius), float(tool.length))
    u = local[:, 0] - tool.reference_offset
    v = local[:, 1]
    if plunge == MINUS_X:  # front faces -X, body toward +X
        z, x = u, v
    elif plunge == PLUS_X:  # front faces +X, body toward -X
        z, x = u, -v
    elif plunge == MINUS_Z:  # front faces -Z, body toward +Z
        z, x = v, u
    elif plunge == PLUS_Z:  # front faces +Z, body toward -Z
        z, x = -v, u
    else:
        raise ValueError("unknown plunge direction %r" % (plunge,))
    coords = np.column_stack([z, x])
    coords.setflags(write=False)
    return coords


def tool_outline(tool: GroovingTool, plunge: str, x: float, z: float) -> Polygon:
    """Polygon (z, x) of the blade with its reference corner at radius x, Z z.

    The front edge is flat, ``tool.width`` wide, both front corners rounded by
    ``tool.corner_radius`` (circumscribed polygon: never inside the true arc,
    at most ARC_EXCESS outside it), the sides run ``tool.length`` back.
    """
    coords = outline_at_origin(tool, plunge) + (float(z), float(x))
    return orient(Polygon(coords))


def swept_area(
    tool: GroovingTool, plunge: str, start: tuple[float, float], end: tuple[float, float]
) -> shapely.Geometry:
    """Area swept by the tool moving straight from start (x, z) to end (x, z)."""
    base = outline_at_origin(tool, plunge)
    a = base + (float(start[1]), float(start[0]))
    b = base + (float(end[1]), float(end[0]))
    return shapely.MultiPoint(np.vstack([a, b])).convex_hull
