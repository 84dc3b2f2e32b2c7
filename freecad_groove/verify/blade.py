"""The blade's outline in the lathe's half plane and the area it sweeps.

Tool positions are (x, z) like ``moves.Move``; the outlines are shapely (z, x).
"""

from __future__ import annotations

import numpy as np
import shapely
from shapely.geometry import Polygon
from shapely.geometry.polygon import orient

from freecad_groove.engine.moves import GroovingTool

from .outline import ARC_EXCESS, outline_at_origin

__all__ = ["ARC_EXCESS", "outline_at_origin", "tool_outline", "swept_area"]


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
