"""A turned part's section outline and the notches in it.

The outline is the part's section in the (z, radius) half plane: a closed
loop of straight segments and circular arcs (``Segment``, ``ArcSegment``),
each ending where the next starts. ``find_notch`` finds the notch an element
belongs to: the run of elements where the outline leaves a straight contour
line (the surrounding cylinder, cone or face) and comes back to the same
line, dipping into the material. ``cycle93_recognize`` reads a CYCLE93 call
from it.

Pure engine code: no FreeCAD.
"""

import math
from dataclasses import dataclass
from typing import List, Optional, Sequence, Tuple, Union

Point = Tuple[float, float]  # (z, radius)

SHAPE_TOLERANCE = 1e-4  # mm: how far a point may stand off the line or arc it should lie on
# How far from the picked element a notch's ends are looked for: beyond CYCLE93's seven elements (two flanks,
# a base, four corners), so that a longer notch is refused for what it is, not as "no notch".
NOTCH_SEARCH = 15


class NotchError(ValueError):
    """A notch that is not there or that CYCLE93 cannot describe; the
    message says what does not fit."""


@dataclass(frozen=True)
class Segment:
    """A straight element from ``start`` to ``end``, (z, radius) points."""

    start: Point
    end: Point

    def reversed(self) -> "Segment":
        return Segment(self.end, self.start)

    def direction(self) -> Point:
        """Unit direction from start to end."""
        return _unit(self.end[0] - self.start[0], self.end[1] - self.start[1])


@dataclass(frozen=True)
class ArcSegment:
    """A circular arc from ``start`` to ``end`` about ``center``,
    counter-clockwise in the (z, radius) plane (z to the right, radius up)
    when ``ccw``."""

    start: Point
    end: Point
    center: Point
    ccw: bool

    @property
    def radius(self) -> float:
        return math.dist(self.start, self.center)

    def reversed(self) -> "ArcSegment":
        return ArcSegment(self.end, self.start, self.center, not self.ccw)

    def sweep(self) -> float:
        """Signed angle from start to end (positive counter-clockwise), in (-2 pi, 2 pi)."""
        a0 = math.atan2(self.start[1] - self.center[1], self.start[0] - self.center[0])
        a1 = math.atan2(self.end[1] - self.center[1], self.end[0] - self.center[0])
        sweep = a1 - a0
        if self.ccw and sweep <= 0:
            sweep += 2 * math.pi
        elif not self.ccw and sweep >= 0:
            sweep -= 2 * math.pi
        return sweep

    def points(self, count: int = 16) -> List[Point]:
        """``count`` + 1 points along the arc, start and end included."""
        a0 = math.atan2(self.start[1] - self.center[1], self.start[0] - self.center[0])
        sweep, r = self.sweep(), self.radius
        return [(self.center[0] + r * math.cos(a0 + sweep * k / count),
                 self.center[1] + r * math.sin(a0 + sweep * k / count)) for k in range(count + 1)]


Element = Union[Segment, ArcSegment]


@dataclass(frozen=True)
class Notch:
    """A notch of an outline oriented with the material on its left.

    before, after  the contour line's elements on either side (segments on one line)
    elements       the notch's elements in outline order, from ``before`` to ``after``
    """

    before: Segment
    after: Segment
    elements: Tuple[Element, ...]

    def contour_direction(self) -> Point:
        return _unit(self.after.end[0] - self.before.start[0], self.after.end[1] - self.before.start[1])


def _unit(dz: float, dr: float) -> Point:
    n = math.hypot(dz, dr)
    return (dz / n, dr / n) if n > 0 else (0.0, 0.0)


def _cross(a: Point, b: Point) -> float:
    return a[0] * b[1] - a[1] * b[0]


def fmt_point(p: Point) -> str:
    """"Z12.5 X20" (radius X) for messages."""
    return "Z%s X%s" % (_short(p[0]), _short(p[1]))


def _short(value: float) -> str:
    text = "%.4f" % value
    text = text.rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def line_offset(start: Point, direction: Point, p: Point) -> float:
    """Signed distance of ``p`` from the line through ``start`` along the unit
    ``direction``: positive on its left."""
    return _cross(direction, (p[0] - start[0], p[1] - start[1]))


def _length(element: Element) -> float:
    if isinstance(element, Segment):
        return math.dist(element.start, element.end)
    return abs(element.sweep()) * element.radius


def _mergeable(a: Element, b: Element) -> bool:
    """Two consecutive elements that are one line or one arc."""
    if isinstance(a, Segment) and isinstance(b, Segment):
        d = a.direction()
        return abs(line_offset(a.start, d, b.end)) <= SHAPE_TOLERANCE and (
            (b.end[0] - a.start[0]) * d[0] + (b.end[1] - a.start[1]) * d[1] > 0)
    if isinstance(a, ArcSegment) and isinstance(b, ArcSegment):
        return a.ccw == b.ccw and math.dist(a.center, b.center) <= SHAPE_TOLERANCE and (
            abs(a.radius - b.radius) <= SHAPE_TOLERANCE)
    return False


def _joined(a: Element, b: Element) -> Element:
    if isinstance(a, Segment):
        return Segment(a.start, b.end)
    return ArcSegment(a.start, b.end, a.center, a.ccw)


def tidy_outline(outline: Sequence[Element], picked: int) -> Tuple[List[Element], int]:
    """The outline closed-checked, without zero-length elements, with the
    pieces of one line or one arc joined, oriented with the material on its
    left (counter-clockwise); and the index of the element holding ``picked``."""
    if not outline:
        raise NotchError("the section outline is empty")
    if not 0 <= picked < len(outline):
        raise NotchError("picked element %d: the outline has %d elements" % (picked, len(outline)))
    for a, b in zip(outline, list(outline[1:]) + [outline[0]]):
        if math.dist(a.end, b.start) > SHAPE_TOLERANCE:
            raise NotchError("the section outline is not closed: a gap at %s" % fmt_point(a.end))
    items = [(e, i == picked) for i, e in enumerate(outline) if _length(e) > SHAPE_TOLERANCE or i == picked]
    merged: List[Tuple[Element, bool]] = []
    for element, is_picked in items:
        if merged and _mergeable(merged[-1][0], element):
            merged[-1] = (_joined(merged[-1][0], element), merged[-1][1] or is_picked)
        else:
            merged.append((element, is_picked))
    if len(merged) > 1 and _mergeable(merged[-1][0], merged[0][0]):
        last = merged.pop()
        merged[0] = (_joined(last[0], merged[0][0]), last[1] or merged[0][1])
    if _signed_area([e for e, _p in merged]) < 0:
        merged = [(e.reversed(), p) for e, p in reversed(merged)]
    elements = [e for e, _p in merged]
    return elements, next(i for i, (_e, p) in enumerate(merged) if p)


def _signed_area(elements: Sequence[Element]) -> float:
    """Twice the signed area enclosed (positive: counter-clockwise)."""
    pts: List[Point] = []
    for e in elements:
        pts.extend(e.points() if isinstance(e, ArcSegment) else [e.start])
    return sum(_cross(a, b) for a, b in zip(pts, pts[1:] + pts[:1]))


def _contour_pair(elements: Sequence[Element], i: int, j: int) -> Optional[Notch]:
    """The notch between elements i and j (indices mod the count) when both
    are segments of one line and everything between dips into the material."""
    n = len(elements)
    before, after = elements[i % n], elements[j % n]
    if not (isinstance(before, Segment) and isinstance(after, Segment)):
        return None
    d = before.direction()
    if abs(line_offset(before.start, d, after.start)) > SHAPE_TOLERANCE or (
            abs(line_offset(before.start, d, after.end)) > SHAPE_TOLERANCE):
        return None
    if (after.start[0] - before.end[0]) * d[0] + (after.start[1] - before.end[1]) * d[1] < -SHAPE_TOLERANCE:
        return None  # the line comes back behind where it left
    inner = [elements[k % n] for k in range(i + 1, j)]
    for e in inner[1:]:
        if line_offset(before.start, d, e.start) <= SHAPE_TOLERANCE:
            return None
    for e in inner:
        if isinstance(e, ArcSegment) and min(line_offset(before.start, d, p) for p in e.points()) < -SHAPE_TOLERANCE:
            return None
    return Notch(before, after, tuple(inner))


def find_notch(outline: Sequence[Element], picked: int) -> Notch:
    """The notch of the (tidied) ``outline`` that element ``picked`` belongs
    to: the nearest contour segments of one line before and after it with at
    most NOTCH_SEARCH elements between them, all in the material.
    NotchError when there is none."""
    n = len(outline)
    best = None
    for span in range(2, min(NOTCH_SEARCH + 1, n - 1) + 1):
        for back in range(1, span):
            notch = _contour_pair(outline, picked - back, picked - back + span)
            if notch is not None:
                best = notch
                break
        if best is not None:
            return best
    what = outline[picked]
    raise NotchError(
        "the picked %s from %s to %s is in no notch: within %d elements on each side the outline does not "
        "leave a straight contour line into the material and come back to it"
        % ("arc" if isinstance(what, ArcSegment) else "line", fmt_point(what.start), fmt_point(what.end),
           NOTCH_SEARCH))
