"""Reading a CYCLE93 call from a notch of a turned part's section.

``recognize(outline, picked)`` takes the part's section outline in the
(z, radius) half plane (``cycle93_outline``: segments and arcs) and the
element the user picked, finds the notch it belongs to and returns the
CYCLE93 call whose finished profile is that notch: AXFA, AXSA, WIDG, DEPG,
ANGC, ANG1, ANG2, RCO1, RCO2, RCI1, RCI2 and TYP (the machining parameters
FAL1, FAL2, IDEP, DWT and VRT are left empty).

How a notch is read (choices marked *):
- The contour line is the straight line the outline leaves and comes back
  to. Longitudinal grooves (plunged along X) are tried first on contours at
  most 45 degrees off the Z axis, face grooves (plunged along Z) first on
  steeper ones*; the other kind is tried when the first does not fit.
  External/internal: the side the material is on, as CYCLE93's TYP reads it.
- Between the contour line's two pieces: [corner] flank [corner] base
  [corner] flank [corner]. The base is the one segment parallel to the
  contour; a corner is a tangent arc (RCO/RCI > 0) or a chamfer with equal
  legs (< 0: its length, CHF, or with ``chr_chamfers`` its leg, CHR). When
  two segments stand between the contour and the base, the one that reads as
  a chamfer with equal legs is the chamfer; when both do, the first one
  (the edge's)*. A flank of zero length between two corners is not read*.
- ``right`` (default, as the Groove op does) puts the start point on the
  groove's +Z edge (longitudinal) or outer edge (face): TYP 5..8; otherwise
  on the -Z / inner edge: TYP 1..4.
- The call is rebuilt (``Cycle93.geometry``) and its finished profile must be
  the notch within SHAPE_TOLERANCE, element by element.
- Values are rounded to VALUE_DECIMALS decimals*.

Refused, with what does not fit: no straight contour line on both sides of
the picked element, more than seven elements in the notch, no base parallel
to the contour or more than one (a stepped groove), an undercut (a flank that
leans back over the base: the groove is wider at the bottom than at the top),
an arc that is not tangent to both its neighbours, a chamfer with unequal
legs, a base narrower than its corners, a flank of zero length.

Pure engine code: no FreeCAD.
"""

import math
from dataclasses import dataclass, replace
from typing import List, Optional, Sequence, Tuple

from ..errors import CycleError
from ..moves import GroovingTool
from ..settings import Settings
from .cycle93 import Cycle93
from .cycle93_outline import (
    SHAPE_TOLERANCE,
    ArcSegment,
    Element,
    Notch,
    NotchError,
    Point,
    Segment,
    find_notch,
    fmt_point,
    line_offset,
    tidy_outline,
)

VALUE_DECIMALS = 6  # mm and degrees: the recognised values are rounded to this
LONGITUDINAL_LIMIT = 45.0  # degrees off Z up to which longitudinal grooves are tried first
MAX_ELEMENTS = 7  # two flanks, a base and four corners


@dataclass(frozen=True)
class RecognisedGroove:
    """A notch read as a CYCLE93 call.

    call           the Cycle93 call (geometry parameters and TYP only)
    contour_start  (z, radius) where the contour line's piece before the notch starts
    contour_end    (z, radius) where the piece after it ends (outline order)
    notch          the notch as found in the tidied outline
    """

    call: Cycle93
    contour_start: Point
    contour_end: Point
    notch: Notch


@dataclass(frozen=True)
class _Frame:
    """The groove frame at ``origin``: u across the groove (su), v out of the material (sv)."""

    origin: Point
    longitudinal: bool
    su: float
    sv: float

    def uv(self, p: Point) -> Point:
        dz, dr = p[0] - self.origin[0], p[1] - self.origin[1]
        if self.longitudinal:
            return self.su * dz, self.sv * dr
        return self.su * dr, self.sv * dz

    def world(self, u: float, v: float) -> Point:
        if self.longitudinal:
            return self.origin[0] + self.su * u, self.origin[1] + self.sv * v
        return self.origin[0] + self.sv * v, self.origin[1] + self.su * u


def _cross(a: Point, b: Point) -> float:
    return a[0] * b[1] - a[1] * b[0]


def _round(value: float) -> float:
    return round(value, VALUE_DECIMALS) + 0.0


def _intersect(a: Segment, b: Segment) -> Point:
    """Where the lines through segments a and b cross."""
    d, e = a.direction(), b.direction()
    den = d[0] * e[1] - d[1] * e[0]
    if abs(den) < 1e-12:
        raise NotchError("the lines from %s and from %s are parallel: they make no corner"
                         % (fmt_point(a.start), fmt_point(b.start)))
    t = ((b.start[0] - a.start[0]) * e[1] - (b.start[1] - a.start[1]) * e[0]) / den
    return a.start[0] + t * d[0], a.start[1] + t * d[1]


def recognize(outline: Sequence[Element], picked: int, right: bool = True,
              chr_chamfers: bool = False) -> RecognisedGroove:
    """The CYCLE93 call of the notch that element ``picked`` of the closed
    ``outline`` belongs to; NotchError saying what does not fit."""
    elements, index = tidy_outline(outline, picked)
    notch = find_notch(elements, index)
    if len(notch.elements) > MAX_ELEMENTS:
        raise NotchError("the notch from %s to %s has %d elements: CYCLE93 cuts two flanks, a base and four corners"
                         % (fmt_point(notch.before.end), fmt_point(notch.after.start), len(notch.elements)))
    return read_notch(notch, right, chr_chamfers)


def read_notch(notch: Notch, right: bool = True, chr_chamfers: bool = False) -> RecognisedGroove:
    """The notch as a CYCLE93 call (see the module notes)."""
    c = notch.contour_direction()
    angc = math.degrees(math.atan2(c[1], c[0])) % 180.0
    if angc > 180.0 - 1e-9:
        angc = 0.0
    tilt = min(angc, 180.0 - angc)
    kinds = (True, False) if tilt <= LONGITUDINAL_LIMIT else (False, True)
    errors: List[NotchError] = []
    for longitudinal in kinds:
        try:
            call = _read_as(notch, longitudinal, right, chr_chamfers, angc)
            return RecognisedGroove(call, notch.before.start, notch.after.end, notch)
        except NotchError as e:
            errors.append(e)
    raise errors[0]


def _base_index(notch: Notch) -> int:
    """Index of the notch's base: its one segment parallel to the contour."""
    start, d = notch.before.start, notch.before.direction()
    found = [k for k, e in enumerate(notch.elements) if isinstance(e, Segment)
             and abs(line_offset(start, d, e.start) - line_offset(start, d, e.end)) <= SHAPE_TOLERANCE]
    where = "the notch from %s to %s" % (fmt_point(notch.before.end), fmt_point(notch.after.start))
    if not found:
        raise NotchError("%s has no base parallel to the contour: CYCLE93's base runs parallel to it" % where)
    if len(found) > 1:
        raise NotchError("%s has %d segments parallel to the contour (a stepped groove): CYCLE93 cuts one base"
                         % (where, len(found)))
    return found[0]


def _side_options(side: Sequence[Element], contour: Point) -> List[Tuple[Optional[Element], Segment,
                                                                         Optional[Element]]]:
    """The readings of the elements between the contour and the base as
    (edge corner, flank, base corner): first those whose flank stands most
    across the ``contour`` direction (a chamfer halves the turn from the
    contour to the flank), then the edge's chamfer first."""
    n = len(side)
    if n == 1 and isinstance(side[0], Segment):
        return [(None, side[0], None)]
    options = []
    if n == 2:
        if isinstance(side[1], Segment):
            options.append((side[0], side[1], None))
        if isinstance(side[0], Segment):
            options.append((None, side[0], side[1]))
    if n == 3 and isinstance(side[1], Segment):
        options.append((side[0], side[1], side[2]))
    return sorted(options, key=lambda option: -abs(_cross(contour, option[1].direction())))


def _read_as(notch: Notch, longitudinal: bool, right: bool, chr_chamfers: bool, angc: float) -> Cycle93:
    """The call of ``notch`` as a longitudinal or face groove."""
    into = (-notch.contour_direction()[1], notch.contour_direction()[0])  # left normal: into the material
    plunge = into[1] if longitudinal else into[0]
    if abs(plunge) < 1e-9:
        raise NotchError("a %s groove cannot be cut into a contour %s to its axis (ANGC %s)"
                         % ("longitudinal" if longitudinal else "face",
                            "square" if longitudinal else "parallel", _round(angc)))
    external = plunge < 0
    base = _base_index(notch)
    side_a, side_b = notch.elements[:base], [e.reversed() for e in reversed(notch.elements[base + 1:])]
    where = "the notch from %s to %s" % (fmt_point(notch.before.end), fmt_point(notch.after.start))
    contour = notch.contour_direction()
    options_a, options_b = _side_options(side_a, contour), _side_options(side_b, contour)
    for name, side, options in (("before", side_a, options_a), ("after", side_b, options_b)):
        if not options:
            raise NotchError("%s: the %d element(s) between the contour and the base %s it do not read as "
                             "[corner] flank [corner]" % (where, len(side), name))
    first_error = None
    for a in options_a:
        for b in options_b:
            try:
                return _call_from(notch, notch.elements[base], a, b, (longitudinal, external, right, chr_chamfers),
                                  angc)
            except NotchError as e:
                first_error = first_error or e
    raise first_error


def _call_from(notch: Notch, base: Segment, side_a: tuple, side_b: tuple, kind: tuple, angc: float) -> Cycle93:
    """The call for one reading of the notch's sides (side_b walked from the
    contour after the notch toward the base)."""
    longitudinal, external, right, chr_chamfers = kind
    reversed_contour = notch.after.reversed()
    p_a, b_a = _intersect(notch.before, side_a[1]), _intersect(side_a[1], base)
    p_b, b_b = _intersect(reversed_contour, side_b[1]), _intersect(side_b[1], base)
    su = -1.0 if right else 1.0
    sv = 1.0 if external else -1.0
    probe = _Frame(p_a, longitudinal, su, sv)
    a_first = probe.uv(p_b)[0] > 0
    (p1, b1, s1), (p2, b2, s2) = ((p_a, b_a, side_a), (p_b, b_b, side_b)) if a_first else (
        (p_b, b_b, side_b), (p_a, b_a, side_a))
    frame = _Frame(p1, longitudinal, su, sv)
    (u_b1, v_b1), (u_b2, v_b2), (u_p2, v_p2) = frame.uv(b1), frame.uv(b2), frame.uv(p2)
    slope = v_p2 / u_p2
    depth = slope * u_b1 - v_b1
    width = u_b2 - u_b1
    if not depth > SHAPE_TOLERANCE or not width > SHAPE_TOLERANCE:
        raise NotchError("the notch from %s to %s does not read as a %s groove"
                         % (fmt_point(notch.before.end), fmt_point(notch.after.start),
                            "longitudinal" if longitudinal else "face"))
    ang1 = _flank_angle("1", (u_b1, v_b1), (0.0, 0.0), b1, p1)
    ang2 = _flank_angle("2", (u_b2, v_b2), (u_p2, v_p2), b2, p2)
    rco1, rci1 = _corner_value(s1[0], p1, chr_chamfers), _corner_value(s1[2], b1, chr_chamfers)
    rco2, rci2 = _corner_value(s2[0], p2, chr_chamfers), _corner_value(s2[2], b2, chr_chamfers)
    typ = {(True, True): 1, (False, True): 2, (True, False): 3, (False, False): 4}[(longitudinal, external)]
    typ += (4 if right else 0) + (10 if chr_chamfers else 0)
    call = Cycle93(axfa=_round(p1[1]), axsa=_round(p1[0]), widg=_round(width), depg=_round(depth),
                   angc=_round(angc), ang1=ang1, ang2=ang2, rco1=rco1, rco2=rco2, rci1=rci1, rci2=rci2, typ=typ)
    _check_profile(call, notch, a_first)
    return call


def _flank_angle(name: str, bottom: Point, top: Point, bottom_world: Point, top_world: Point) -> float:
    """ANG1/ANG2: the flank's angle from the plunge direction, opening outward
    (flank 1 runs toward +u going down, flank 2 toward +u going up)."""
    du, dv = top[0] - bottom[0], top[1] - bottom[1]
    if dv <= SHAPE_TOLERANCE:
        raise NotchError("flank %s from %s to %s does not rise from the base to the contour"
                         % (name, fmt_point(bottom_world), fmt_point(top_world)))
    lean = math.degrees(math.atan2(du if name == "2" else -du, dv))
    if lean < 0 and abs(du) > SHAPE_TOLERANCE:
        raise NotchError("flank %s from %s to %s leans %s degrees back over the base (an undercut: the groove "
                         "is wider at the bottom than at the top); a blade plunging along the axis cannot cut it"
                         % (name, fmt_point(bottom_world), fmt_point(top_world), _round(-lean)))
    return _round(max(lean, 0.0))


def _corner_value(corner: Optional[Element], vertex: Point, chr_chamfers: bool) -> float:
    """RCO/RCI of a corner element at the sharp ``vertex`` of the lines it
    joins: the radius of a tangent arc, minus the chamfer's length (CHF) or
    leg (CHR) of a chamfer with equal legs, 0 for none."""
    if corner is None:
        return 0.0
    leg_in, leg_out = math.dist(vertex, corner.start), math.dist(vertex, corner.end)
    what = "%s from %s to %s" % ("arc" if isinstance(corner, ArcSegment) else "chamfer",
                                 fmt_point(corner.start), fmt_point(corner.end))
    if abs(leg_in - leg_out) > SHAPE_TOLERANCE:
        rule = ("is not tangent to both elements it joins: CYCLE93 rounds a corner with a tangent radius"
                if isinstance(corner, ArcSegment) else
                "has legs %s and %s: CYCLE93's chamfers have equal legs" % (_round(leg_in), _round(leg_out)))
        raise NotchError("the %s %s" % (what, rule))
    if isinstance(corner, ArcSegment):
        return _round(corner.radius)
    return -_round(leg_in if chr_chamfers else math.dist(corner.start, corner.end))


def profile_elements(call: Cycle93) -> List[Element]:
    """The finished profile of ``call`` as (z, radius) elements from the
    start point's side: its corners' arcs and chamfers and the straight
    pieces between them (zero-length ones left out)."""
    # A blade as wide as the groove and IDEP = DEPG: one plunge, nothing to count.
    settings = Settings(tool=GroovingTool(width=call.widg, corner_radius=0.0))
    geo = replace(call, idep=call.depg).geometry(settings)
    frame = geo.frame

    def world(p):
        x, z = frame.point(*p)
        return z, x

    out: List[Element] = []
    last = None
    for corner in geo.final_corners:
        ends, arc = corner.element()
        pts = [world(p) for p in ends]
        if last is not None and math.dist(last, pts[0]) > SHAPE_TOLERANCE:
            out.append(Segment(last, pts[0]))
        if len(pts) == 2:
            if arc is None:
                out.append(Segment(pts[0], pts[1]))
            else:
                center = world(arc.center)
                ccw = (pts[0][0] - center[0]) * (pts[1][1] - center[1]) - (pts[0][1] - center[1]) * (
                    pts[1][0] - center[0]) > 0
                out.append(ArcSegment(pts[0], pts[1], center, ccw))
        last = pts[-1]
    return out


def _check_profile(call: Cycle93, notch: Notch, a_first: bool) -> None:
    """NotchError unless the finished profile of ``call`` is the notch."""
    try:
        profile = profile_elements(call)
    except CycleError as e:
        raise NotchError("the notch from %s to %s does not make a CYCLE93 groove: %s"
                         % (fmt_point(notch.before.end), fmt_point(notch.after.start), e)) from None
    ours = list(notch.elements) if a_first else [e.reversed() for e in reversed(notch.elements)]
    mismatch = _first_difference(profile, ours)
    if mismatch is not None:
        raise NotchError("the notch differs from the nearest CYCLE93 groove (%s) at %s"
                         % (call.emit(), fmt_point(mismatch)))


def _first_difference(profile: Sequence[Element], notch: Sequence[Element]) -> Optional[Point]:
    """Where the two element lists first differ by more than SHAPE_TOLERANCE (None: nowhere)."""
    for ours, theirs in zip(profile, notch):
        if type(ours) is not type(theirs):
            return theirs.start
        for p, q in ((ours.start, theirs.start), (ours.end, theirs.end)):
            if math.dist(p, q) > SHAPE_TOLERANCE:
                return q
        if isinstance(ours, ArcSegment) and (math.dist(ours.center, theirs.center) > SHAPE_TOLERANCE
                                             or ours.ccw != theirs.ccw):
            return theirs.start
    if len(profile) != len(notch):
        return (notch[len(profile)] if len(notch) > len(profile) else notch[-1]).start
    return None
