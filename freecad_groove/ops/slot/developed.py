"""The slot of a Cylinder slot op on the developed surface of its cylinder.

FreeCAD layer: Part only. A picked face must be a cylinder about the Job's Z
axis (the global Z axis through the origin); the slot's path is a chain of
edges lying on that face. Each edge is developed: a point (x, y, z) of it
becomes (z, C), C = atan2(y, x) in degrees, unwrapped along the chain so C
runs on past +-180 (a helix of two turns ends at C 720). The developed curve
is sampled (SAMPLES_PER_EDGE points, then halved where a chord leaves the
curve by more than the tolerance) and simplified (Douglas-Peucker) to
straight pieces within ``numbers.ARC_CHORD_TOLERANCE`` of it on the
developed surface (the arc length s = radius * C in radians): a helix and a
line along Z are each one straight piece.

Choices (docs/cylinder-slot.md, its table): the path starts where the first
edge starts (its direction as modelled, or reversed when only its start
meets the second edge); C of the start in (-180, 180]; a sketch of the
developed surface (its own x = Z, y = the developed length R*C, C = 0 at
y = 0) gives C as drawn, its edges chained by Part's edge sort, and may leave
the face's Z range by the end mill's radius (reach.py); an edge "lies on the
face" when every sample is within ON_FACE_TOLERANCE of the cylinder and of
the face (its Z range and its angular span).
"""

import math
from typing import List, NamedTuple, Tuple

import Part

from ...engine.numbers import ARC_CHORD_TOLERANCE
from .properties import SlotInputError

SAMPLES_PER_EDGE = 16  # first samples of an edge: under 180 degrees apart for unwrapping C
MAX_SPLITS = 12  # halvings of one sampled piece
ON_FACE_TOLERANCE = 1e-4  # mm
AXIS_TOLERANCE = 1e-6
DEVELOPED_TOLERANCE = ARC_CHORD_TOLERANCE / 2.0  # half for sampling, half for simplifying


class SlotCylinder(NamedTuple):
    """The picked cylindrical face: its radius and Z range; ``name`` "Label.FaceN"."""

    radius: float
    z_min: float
    z_max: float
    name: str


def read_cylinder(face: object, name: str) -> SlotCylinder:
    """The cylinder of ``face``; SlotInputError naming Base when it is no cylinder about Z."""
    surface = getattr(face, "Surface", None)
    if not isinstance(surface, Part.Cylinder):
        raise SlotInputError("Base: %s is not a cylindrical face (a %s): pick the cylinder the slot is cut in"
                               % (name, type(surface).__name__), ("Base",))
    axis, centre = surface.Axis, surface.Center
    if abs(axis.x) > AXIS_TOLERANCE or abs(axis.y) > AXIS_TOLERANCE or math.hypot(centre.x, centre.y) > 1e-6:
        raise SlotInputError("Base: %s is a cylinder about (%g, %g, %g) through (%g, %g): it must turn about the "
                               "Job's Z axis" % (name, axis.x, axis.y, axis.z, centre.x, centre.y), ("Base",))
    box = face.BoundBox
    return SlotCylinder(surface.Radius, box.ZMin, box.ZMax, name)


def _oriented(edges: List[Tuple[object, str]]) -> List[Tuple[object, str, bool]]:
    """(edge, name, reversed) in chain order; SlotInputError when they do not join end to end."""
    if len(edges) == 1:
        return [(edges[0][0], edges[0][1], False)]
    out = []
    first, second = edges[0][0], edges[1][0]
    ends = [v.Point for v in second.Vertexes]
    starts_reversed = min(first.Vertexes[0].Point.distanceToPoint(p) for p in ends) < \
        min(first.Vertexes[-1].Point.distanceToPoint(p) for p in ends)
    out.append((first, edges[0][1], starts_reversed))
    here = first.Vertexes[0].Point if starts_reversed else first.Vertexes[-1].Point
    for edge, name in edges[1:]:
        start, end = edge.Vertexes[0].Point, edge.Vertexes[-1].Point
        if here.distanceToPoint(start) <= ON_FACE_TOLERANCE:
            out.append((edge, name, False))
            here = end
        elif here.distanceToPoint(end) <= ON_FACE_TOLERANCE:
            out.append((edge, name, True))
            here = start
        else:
            raise SlotInputError("Base: %s does not join the edge before it: the slot's path must be one chain "
                                   "of edges, in order" % name, ("Base",))
    return out


def _angle(point: object, last: float) -> float:
    """C (degrees) of ``point``, the turn nearest ``last``."""
    c = math.degrees(math.atan2(point.y, point.x))
    return c + 360.0 * round((last - c) / 360.0)


class _Developer:
    """Develops one edge into (z, C) samples, checking it lies on the cylinder."""

    def __init__(self, cylinder: SlotCylinder, face: object):
        self.cylinder, self.face = cylinder, face
        self.to_s = cylinder.radius * math.pi / 180.0

    def point(self, edge: object, name: str, t: float, last_c: float) -> Tuple[float, float]:
        p = edge.valueAt(t)
        r, cyl = math.hypot(p.x, p.y), self.cylinder
        if abs(r - cyl.radius) > ON_FACE_TOLERANCE or not cyl.z_min - ON_FACE_TOLERANCE <= p.z <= \
                cyl.z_max + ON_FACE_TOLERANCE:
            raise SlotInputError("Base: %s does not lie on %s (a point at radius %.4f, Z %.4f; the face: radius "
                                   "%.4f, Z %.4f to %.4f)" % (name, cyl.name, r, p.z, cyl.radius, cyl.z_min,
                                                              cyl.z_max), ("Base",))
        return p.z, _angle(p, last_c)

    def edge_points(self, edge: object, name: str, reverse: bool, last_c: float) -> List[Tuple[float, float]]:
        a, b = edge.ParameterRange
        if reverse:
            a, b = b, a
        params = [a + (b - a) * k / SAMPLES_PER_EDGE for k in range(SAMPLES_PER_EDGE + 1)]
        points, c = [], last_c
        for t in params:
            points.append(self.point(edge, name, t, c))
            c = points[-1][1]
        self._check_span(edge, name)
        out = [points[0]]
        for k in range(1, len(params)):
            out.extend(self._refine(edge, name, params[k - 1], params[k], out[-1], points[k], 0))
        return out

    def _check_span(self, edge: object, name: str) -> None:
        """The edge's middle on the face itself (not only on its cylinder: a face may span part of a turn)."""
        middle = edge.valueAt(sum(edge.ParameterRange) / 2.0)
        if self.face.distToShape(Part.Vertex(middle))[0] > ON_FACE_TOLERANCE:
            raise SlotInputError("Base: %s does not lie on %s (its middle is off the face)"
                                   % (name, self.cylinder.name), ("Base",))

    def _refine(self, edge, name, t0, t1, p0, p1, depth) -> List[Tuple[float, float]]:
        """The samples after p0 up to p1, halving where the chord is off the curve."""
        tm = (t0 + t1) / 2.0
        pm = self.point(edge, name, tm, p0[1])
        if depth >= MAX_SPLITS or _offset(p0, p1, pm, self.to_s) <= DEVELOPED_TOLERANCE:
            return [p1]
        return self._refine(edge, name, t0, tm, p0, pm, depth + 1) + \
            self._refine(edge, name, tm, t1, pm, p1, depth + 1)


class _SketchDeveloper(_Developer):
    """Develops an edge of a sketch of the developed surface, in the sketch's own
    coordinates: x is Z, y the developed length s (C = y / radius in radians)."""

    margin = 0.0  # mm the path may leave the face's Z range by (the end mill's radius)

    def point(self, edge: object, name: str, t: float, last_c: float) -> Tuple[float, float]:
        p, cyl, margin = edge.valueAt(t), self.cylinder, self.margin + ON_FACE_TOLERANCE
        if not cyl.z_min - margin <= p.x <= cyl.z_max + margin:
            raise SlotInputError("DevelopedSketch: %s leaves %s by more than the end mill's radius %g (a point at "
                                   "sketch x = Z %.4f; the face: Z %.4f to %.4f)" % (
                                       name, cyl.name, round(self.margin, 4), p.x, cyl.z_min, cyl.z_max),
                                   ("DevelopedSketch",))
        return p.x, p.y / self.to_s

    def _check_span(self, edge: object, name: str) -> None:
        pass  # a developed path wraps round the whole cylinder


def _offset(p0, p1, p, to_s: float) -> float:
    """Distance on the developed surface from ``p`` to the chord p0-p1 (points (z, C degrees))."""
    z0, s0, z1, s1, z, s = p0[0], p0[1] * to_s, p1[0], p1[1] * to_s, p[0], p[1] * to_s
    length = math.hypot(z1 - z0, s1 - s0)
    if length == 0.0:
        return math.hypot(z - z0, s - s0)
    return abs((z1 - z0) * (s0 - s) - (z0 - z) * (s1 - s0)) / length


def _simplify(points: List[Tuple[float, float]], to_s: float) -> List[Tuple[float, float]]:
    """Douglas-Peucker within DEVELOPED_TOLERANCE on the developed surface."""
    keep, stack = {0, len(points) - 1}, [(0, len(points) - 1)]
    while stack:
        i, j = stack.pop()
        worst, where = 0.0, None
        for k in range(i + 1, j):
            d = _offset(points[i], points[j], points[k], to_s)
            if d > worst:
                worst, where = d, k
        if where is not None and worst > DEVELOPED_TOLERANCE:
            keep.add(where)
            stack.extend([(i, where), (where, j)])
    return [points[k] for k in sorted(keep)]


def developed_path(cylinder: SlotCylinder, face: object, edges: List[Tuple[object, str]],
                   sketch: bool = False, margin: float = 0.0) -> List[Tuple[float, float]]:
    """The slot's path as (z, C degrees) corners of straight pieces on the developed surface, start first.
    ``sketch``: the edges are a sketch's, in its own coordinates (x = Z, y = the developed length), which may
    leave the face's Z range by ``margin`` mm (the end mill's radius: it still touches the face)."""
    if not edges:
        raise SlotInputError("Base: no edge of the slot's path: pick the edges it follows on %s"
                               % cylinder.name, ("Base",))
    developer = _SketchDeveloper(cylinder, face) if sketch else _Developer(cylinder, face)
    developer.margin = margin
    points: List[Tuple[float, float]] = []
    last_c = 0.0
    for edge, name, reverse in _oriented(edges):
        if not points:
            start = edge.valueAt(edge.ParameterRange[1] if reverse else edge.ParameterRange[0])
            last_c = math.degrees(math.atan2(start.y, start.x))
        sampled = developer.edge_points(edge, name, reverse, last_c)
        points.extend(sampled if not points else sampled[1:])
        last_c = points[-1][1]
    return _simplify(points, developer.to_s)
