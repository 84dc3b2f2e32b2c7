"""An independent model of what a paraxial grooving blade reaches, for the
tests: no code of the cycles, only the finished part and the blade.

The blade (width w, both front corners rounded by r) is translated, never
turned: it moves along the plunge axis and across it, and its body runs back
from its front edge out of the part, so a placement is possible exactly when
the blade's outline does not enter the part that must stay (the stock less
the target). Such a placement is reached by a straight plunge from outside,
wherever it stands: over the opening or overhanging an edge of it. What the
blade reaches of the target is the union of the possible placements.

Computed on a grid along the axis across the plunge (``STEP`` mm apart): the
part's top in each column (shapely: each column's line cut with the part),
the lowest front level of each placement (the top less the front's outline,
its maximum under the blade), and the lowest level any placement reaches in
each column (the minimum over the placements covering it). Geometry is
shapely (z, x), x the radius, as in ``freecad_groove.verify``.
"""

import numpy as np
import shapely
from shapely import affinity
from shapely.geometry import Polygon

from freecad_groove.engine.moves import MINUS_X, MINUS_Z, PLUS_X, PLUS_Z

STEP = 0.002  # mm between the grid's columns
CHUNK = 256
SEAM = 1e-7  # placements a numpy window holds at once

# (z, x) -> (a across the plunge, d out of the part) as an affine map [a, b, d, e, 0, 0]: a = a*z + b*x, d = d*z + e*x.
_TO_FRAME = {
    MINUS_X: (1, 0, 0, 1, 0, 0),
    PLUS_X: (1, 0, 0, -1, 0, 0),
    MINUS_Z: (0, 1, 1, 0, 0, 0),
    PLUS_Z: (0, 1, -1, 0, 0, 0),
}


def _outline(width, radius, n):
    """The front's height above its lowest level at n + 1 columns across the blade."""
    s = np.linspace(0.0, width, n + 1)
    d = np.maximum(radius - s, 0.0) + np.maximum(s - (width - radius), 0.0)
    return radius - np.sqrt(np.maximum(radius * radius - d * d, 0.0)) if radius > 0 else np.zeros(n + 1)


def _tops(part, columns, low, high):
    """The part's highest level in each column (-inf where there is none)."""
    lines = shapely.linestrings([[(a, low), (a, high)] for a in columns])
    cut = shapely.intersection(lines, part)
    tops = shapely.bounds(cut)[:, 3]
    return np.where(np.isnan(tops), -np.inf, tops)


def _windowed(values, outline, reduce):
    """reduce(values[i:i + n + 1] + outline) for each i, CHUNK rows at a time."""
    n = len(outline) - 1
    windows = np.lib.stride_tricks.sliding_window_view(values, n + 1)
    return np.concatenate([reduce(windows[i:i + CHUNK] + outline, axis=1) for i in range(0, len(windows), CHUNK)])


def _walls(shape, a_from, a_to):
    """The columns of the shape's walls (edges along the plunge axis) from a_from to a_to."""
    out = []
    for ring in shapely.get_rings(shapely.get_parts(shape)):
        c = shapely.get_coordinates(ring)
        wall = (np.abs(np.diff(c[:, 0])) < 1e-12) & (np.abs(np.diff(c[:, 1])) > 1e-6)
        out.extend(a for a in c[:-1][wall, 0] if a_from - 1e-6 <= a <= a_to + 1e-6)
    return sorted(out)


def lowest_reached(part, goal, width, radius, step=STEP):
    """(columns, level): the lowest level a placement of the blade reaches in
    each column of the goal, part and goal in the plunge frame (a, d). The grid
    runs through the goal's first wall (and, w being a whole number of steps, through
    a wall w from it: a blade as wide as a slot fits it)."""
    a_from, _low, a_to, _high = goal.bounds
    n = max(int(np.ceil(width / step)), 1)
    step = width / n
    anchor = (_walls(goal, a_from, a_to) or [a_from])[0]
    first = anchor - width - step * np.ceil((anchor - a_from) / step)
    columns = first + step * np.arange(int(np.ceil((a_to + width - first) / step)) + 1)
    _a0, low, _a1, high = part.bounds
    outline = _outline(width, radius, n)
    tops = _tops(part, columns, low - 1.0, high + 1.0)
    placements = _windowed(tops, -outline, np.max)  # front level of the blade whose minus edge is at each column
    padded = np.concatenate([np.full(n, np.inf), placements, np.full(n, np.inf)])
    level = _windowed(padded, outline[::-1], np.min)[:len(columns)]
    return columns, level


def blade_reach(stock, target, width, radius, plunge, step=STEP):
    """(reachable, unreachable): the parts of ``target`` a paraxial blade
    reaches without entering ``stock`` less ``target``, and the rest."""
    forward = _TO_FRAME[plunge]
    # The target grown by SEAM: where its top runs along the stock's surface the two agree only to rounding,
    # and the bare difference would leave a seam of part along the groove's mouth, closing it.
    part = affinity.affine_transform(stock.difference(target.buffer(SEAM, join_style="mitre")), forward)
    goal = affinity.affine_transform(target, forward)
    a_from, low, a_to, high = goal.bounds
    columns, level = lowest_reached(part, goal, width, radius, step)
    level = np.clip(level, low - 1.0, high + 1.0)
    above = Polygon(list(zip(columns, level)) + [(columns[-1], high + 2.0), (columns[0], high + 2.0)]).buffer(0)
    reachable = goal.intersection(above)
    back = _inverse(forward)
    return affinity.affine_transform(reachable, back), affinity.affine_transform(goal.difference(above), back)


def _inverse(matrix):
    a, b, d, e, _x, _y = matrix
    det = a * e - b * d
    return (e / det, -b / det, -d / det, a / det, 0, 0)
