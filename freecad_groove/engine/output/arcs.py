"""An arc's circle from its end points, as the writer needs it: the centre of
an arc given by its radius, and Siemens' signed radius CR= of an arc given by
its centre. Points are in the plane's coordinates: (x, z) on a lathe (x a
radius), (x, y) mill-style."""

import math

from ..errors import ProgramError
from ..moves import ARC_CCW, Move

__all__ = ["centre_of", "signed_radius"]


def _view(point: tuple, mill: bool) -> tuple:
    """A point of the arc's plane as (horizontal, vertical) seen from the plane's
    normal, where G3 turns counter-clockwise: G18 (z, x) from +Y, G17 (x, y) from +Z."""
    return point if mill else (point[1], point[0])


def centre_of(move: Move, start: tuple, end: tuple, mill: bool) -> tuple:
    """The centre (the plane's coordinates) of an arc given by its radius
    (negative: more than 180 degrees): left of the chord for G3 with a
    positive radius, right for G2."""
    radius = move.radius
    (h0, v0), (h1, v1) = _view(start, mill), _view(end, mill)
    half = math.hypot(h1 - h0, v1 - v0) / 2.0
    if half == 0 or half - abs(radius) > 1e-9 * max(1.0, abs(radius)):
        raise ProgramError("%s R%s: the radius does not reach the end point" % (move.kind, radius))
    height = math.sqrt(max(radius * radius - half * half, 0.0))
    side = height if (move.kind == ARC_CCW) == (radius > 0) else -height
    left = (-(v1 - v0) / (2 * half), (h1 - h0) / (2 * half))
    centre = ((h0 + h1) / 2.0 + side * left[0], (v0 + v1) / 2.0 + side * left[1])
    return _view(centre, mill)


def signed_radius(move: Move, start: tuple, end: tuple, centre: tuple, mill: bool) -> float:
    """Siemens CR= of an arc: its radius, negative above 180 degrees."""
    (h0, v0), (h1, v1), (hc, vc) = _view(start, mill), _view(end, mill), _view(centre, mill)
    ccw = (math.atan2(v1 - vc, h1 - hc) - math.atan2(v0 - vc, h0 - hc)) % (2 * math.pi)
    sweep = ccw if move.kind == ARC_CCW else 2 * math.pi - ccw
    radius = math.hypot(h0 - hc, v0 - vc)
    return radius if sweep <= math.pi + 1e-12 else -radius
