"""One groove's plan: where the Groove op starts its CYCLE93 call, the
engine's expansion from there, and the link rapids that lead to it.

For each groove the op derives a Cycle93 call (op.py); here:

1. the finished groove must lie on the face (not past its ends, not below
   the axis);
2. a start point outside the part is picked on the safe envelope (links.py),
   the call is expanded there with the engine, and the approach and final
   retreat rapids are checked against the model's solids; when they would
   pass through the part the next candidate is tried:
   - longitudinal external: X = R + c, Z beside the groove (the blade over
     its first plunge position), where R is the model's largest radius and c
     the clearance (Retract, 0 = 1 mm);
   - longitudinal internal: Z = Zmax + c (the blade wholly beyond the part's
     +Z end), X at the clearance level the cycle itself would approach at
     (c inside the bore's contour line); then the same from the -Z end;
   - face grooves: X = R + c (the blade wholly outside the part), Z at the
     cycle's clearance level above the face; then a column approach: X over
     the first plunge position, Z = Zmax + c (external) / Zmin - c (internal);
3. the link rapids run along the envelope from the previous groove's start
   point (the first groove's: from wherever the tool is).

FreeCAD layer: the envelope needs Part; the rest is the engine's.
"""

from dataclasses import dataclass, field
from typing import Optional

from ...engine import CycleError, MachineState, Settings
from ...engine.cycles.cycle93 import Cycle93
from ...engine.cycles.cycle93_geometry import GrooveGeometry
from ...engine.cycles.cycle93_warnings import cycle93_warnings
from ...engine.moves import FEED, RAPID, Move
from ...engine.numbers import format_value
from ...engine.warnings import CycleWarning
from ...freecad.faces import GrooveFace
from .links import BOTTOM, SIDE, TOP, LinkMove, Point, SafeEnvelope
from .properties import GrooveInputError

ON_FACE_TOLERANCE = 1e-6  # mm a finished groove may stand past its face


@dataclass
class GroovePlan:
    """One groove the op cuts.

    face      the GrooveFace it is cut into
    index     0-based number of the groove on that face
    position  its Position (Position + index * Pitch)
    cycle     the Cycle93 call
    settings  the engine Settings (tool width, corner radius, reference corner)
    start     MachineState at the start point the call is expanded from
    start_on  where that start point is on the safe envelope: "side" (X = R + c),
              "top" (Z = Zmax + c) or "bottom" (Z = Zmin - c)
    link      G0 moves [LinkMove(x or None, z or None)] from the previous groove's
              start point (for the first groove: a G0 to the op's safe start point
              first, links.SafeEnvelope.safe_start) to ``start``
    moves     the engine's expansion of ``cycle`` from ``start``
    retreat   G0 moves [LinkMove] after the groove, back to the op's safe start
              point (links.SafeEnvelope.retreat): the op's last groove only
    geometry  ``cycle.geometry(settings)``: the groove's profile (the preview draws it)
    warnings  the call's CycleWarnings (what it cannot do as programmed: allowances
              that leave the blade no room); the op prints them on each recompute
    """

    face: GrooveFace
    index: int
    position: float
    cycle: Cycle93
    settings: Settings
    start: MachineState
    start_on: str
    link: list[LinkMove] = field(default_factory=list)
    moves: list[Move] = field(default_factory=list)
    retreat: list[LinkMove] = field(default_factory=list)
    geometry: Optional[GrooveGeometry] = None
    warnings: list[CycleWarning] = field(default_factory=list)

    @property
    def warning_texts(self) -> list[str]:
        """Each warning as one line naming the face and the groove."""
        return ["%s: groove %d: %s" % (self.face.name, self.index + 1, warning.text) for warning in self.warnings]

    @property
    def start_point(self) -> Point:
        """(x, z) of the start point."""
        return (self.start.x, self.start.z)


def _check_span(what: str, coordinate: str, values: list[float], low: float, high: float,
                properties: tuple[str, ...]) -> None:
    """GrooveInputError when the groove's ``values`` of ``coordinate`` ("Z",
    "radius") pass the face's extent low..high."""
    if min(values) < low - ON_FACE_TOLERANCE or max(values) > high + ON_FACE_TOLERANCE:
        raise GrooveInputError(
            "%s spans %s %s..%s, past the face (%s %s..%s)"
            % (what, coordinate, format_value(min(values)), format_value(max(values)), coordinate,
               format_value(low), format_value(high)),
            properties,
        )


def check_on_face(face: GrooveFace, geometry: GrooveGeometry, index: int, position: float) -> None:
    """The finished groove must lie on the face: not past its ends, not below
    the axis (GrooveInputError naming the properties to fix)."""
    region = geometry.region_world()
    xs = [x for x, _z in region]
    what = "%s: groove %d (Position %s mm)" % (face.name, index + 1, format_value(float(position)))
    placement = ("Position",) if index == 0 else ("Position", "Pitch", "GrooveCount")
    if face.longitudinal:
        _check_span(what, "Z", [z for _x, z in region], face.z_min, face.z_max, placement)
        if min(xs) < -ON_FACE_TOLERANCE:
            raise GrooveInputError("%s reaches X %s, past the axis" % (what, format_value(min(xs))), ("Depth",))
    else:
        _check_span(what, "radius", xs, face.r_min, face.r_max, placement)


def clearance_level(geometry: GrooveGeometry, u_start: float, u_first: float) -> float:
    """The clearance level (groove frame v) the cycle approaches at between
    the start point's u and its first plunge position u."""
    retract = geometry.params["VRT"]
    return max(geometry.clearance(u_first),
               max(geometry.contour_top(u_start), geometry.contour_top(u_first)) + retract)


def start_candidates(face: GrooveFace, geometry: GrooveGeometry, settings: Settings,
                     envelope: SafeEnvelope) -> list[tuple[Point, str]]:
    """Start points to try, best first: [((x, z), where on the envelope)]."""
    frame = geometry.frame
    tool = settings.tool
    u_first = geometry.plunge_positions()[0]
    candidates = []
    if face.longitudinal and face.external:
        candidates.append(((envelope.r_safe, frame.blade(u_first, 0.0)[1]), SIDE))
    elif face.longitudinal:
        ends = ((envelope.z_top + tool.reference_offset, TOP),
                (envelope.z_bottom - tool.width + tool.reference_offset, BOTTOM))
        for z_start, on in ends:
            u_start = frame.blade_of(frame.x0, z_start)[0]
            x_start = frame.blade(u_start, clearance_level(geometry, u_start, u_first))[0]
            if x_start >= 0:
                candidates.append(((x_start, z_start), on))
    else:
        x_start = envelope.r_safe + tool.reference_offset
        u_start = frame.blade_of(x_start, frame.z0)[0]
        candidates.append(((x_start, frame.blade(u_start, clearance_level(geometry, u_start, u_first))[1]), SIDE))
        x_column = frame.blade(u_first, 0.0)[0]
        if face.external:
            candidates.append(((x_column, envelope.z_top), TOP))
        else:
            candidates.append(((x_column, envelope.z_bottom), BOTTOM))
    return candidates


def rapids_clear(envelope: SafeEnvelope, start: Point, moves: list[Move]) -> bool:
    """The approach (rapids up to the first feed) and the final retreat (the
    rapids after the one that leaves the groove) stay out of the model. The
    one that leaves the groove moves along the plunge axis (the first feed's,
    a plunge): a rapid before it along the groove's bottom (CYCLE93's
    free-off) is still in the groove."""
    kinds = [move.kind for move in moves]
    if FEED not in kinds:
        return True
    first_feed = kinds.index(FEED)
    approach = [start] + [(move.x, move.z) for move in moves[:first_feed]]
    last_cut = len(kinds) - 1 - [kind != RAPID for kind in reversed(kinds)].index(True)
    along_x = abs(moves[first_feed].x - approach[-1][0]) > abs(moves[first_feed].z - approach[-1][1])
    out = last_cut + 1
    while out + 1 < len(moves) and (moves[out].x == moves[out - 1].x) == along_x:
        out += 1  # a rapid across the plunge axis, along the bottom: not yet out of the groove
    retreat = [(move.x, move.z) for move in moves[out:]]
    for points in (approach, retreat):
        for a, b in zip(points, points[1:]):
            if envelope.hits(a, b):
                return False
    return True


def choose_start(face: GrooveFace, geometry: GrooveGeometry, call: Cycle93, settings: Settings,
                 envelope: SafeEnvelope, feed: Optional[float], index: int) -> tuple[MachineState, str, list[Move]]:
    """(start state, where on the envelope, expanded moves) of the first
    candidate whose rapids stay out of the model. Raises the engine's
    CycleError when no candidate expands, ValueError when every one hits."""
    error = None
    tried = []
    for (x, z), on in start_candidates(face, geometry, settings, envelope):
        start = MachineState(x=x, z=z, feed=feed, feed_per_rev=False, metric=True)
        try:
            moves = call.expand(start, settings)
        except CycleError as e:
            error = e
            continue
        if rapids_clear(envelope, (x, z), moves):
            return start, on, moves
        tried.append("X%s Z%s" % (format_value(x), format_value(z)))
    if error is not None and not tried:
        raise error
    raise ValueError(
        "%s: groove %d: every approach passes through the part (tried from %s); "
        "the groove cannot be reached from outside the model"
        % (face.name, index + 1, ", ".join(tried) or "nowhere")
    )


def blade_origin(origin: Point, call: Cycle93, settings: Settings) -> Point:
    """The safe start point ``origin`` (where the blade's minus-side edge
    stands: the whole blade is then outside the stock) in the words of the
    op's reference corner: moved by the corner's offset along the groove's
    axis, Z for longitudinal grooves and X for face grooves (as a post's
    --reference-corner moves the words: engine/native/cycle93_pecking.py's corner_shift)."""
    offset = settings.tool.reference_offset
    return (origin[0], origin[1] + offset) if call.kind()[0] else (origin[0] + offset, origin[1])


def plan_groove(face: GrooveFace, index: int, position: float, call: Cycle93, settings: Settings,
                envelope: SafeEnvelope, feed: Optional[float], previous: Optional[GroovePlan],
                origin: Optional[Point] = None) -> GroovePlan:
    """The plan of groove ``index`` on ``face`` (cut by ``call``), linked from
    the ``previous`` groove's start point (None: the op's first groove, linked
    from ``origin``, the op's safe start point; None: from wherever the tool is)."""
    geometry = call.geometry(settings)
    check_on_face(face, geometry, index, position)
    start, start_on, moves = choose_start(face, geometry, call, settings, envelope, feed, index)
    if previous is None:
        first_origin = None if origin is None else blade_origin(origin, call, settings)
        link = envelope.link(None, None, (start.x, start.z), start_on, first_origin)
    else:
        link = envelope.link(previous.start_point, previous.start_on, (start.x, start.z), start_on)
    return GroovePlan(face, index, position, call, settings, start, start_on, link, moves, geometry=geometry,
                      warnings=cycle93_warnings(geometry))
