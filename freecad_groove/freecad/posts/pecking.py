"""The pecking-cycle calls (Allen-Bradley G77/G76, Fanuc and Haas G75/G74) that
cut a group of plain CYCLE93 grooves, in the output's words.

The control names the cycles (``PeckingControl.pecking_cycle``, from the
engine's registry); each cycle class names its own words (``PECK``,
``PITCH``, ``RELIEF``, ``COUNTED``), so nothing here depends on which control
it is. When a group cannot be one of these calls, :class:`NotNative` says why
and the groove output expands the grooves instead (see the package notes).
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import TYPE_CHECKING, Any, Dict, List, NamedTuple, Optional

from ...engine import CycleError, MachineState
from ...engine.cycles.cycle93 import WIDTH_STEP_FACTOR
from ...engine.moves import RAPID
from ...engine.numbers import MM_PER_INCH, format_decimal
from .errors import cycle_post_error
from .reference_corner import corner_settings, corner_shift

if TYPE_CHECKING:
    from .program import Program

# pecking word -> what the op sets it from
PECKING_PROPERTIES = {"I": "Infeed", "K": "Infeed", "P": "Infeed", "Q": "Infeed", "X": "Depth", "Z": "Depth",
                      "F": "FeedPerRev (or the tool controller's HorizFeed)", "e": "Retract", "R(e)": "Retract"}
SAME = 1e-9  # lengths closer than this are the same (blade width, start points)
EQUAL_SPACING = 1e-6  # how far a groove of a set may be off its pitch
FEED_DECIMALS = 6  # as the expanded moves' F (targets.py): inch feeds per revolution need them


class NotNative(Exception):
    """A pecking cycle cannot cut the grooves; the message says why."""


class Point(NamedTuple):
    """A point in the XZ plane: ``x`` a radius."""

    x: float
    z: float


class GrooveSpan(NamedTuple):
    """One groove as a pecking cycle cuts it, in model coordinates: ``start`` the
    blade over the first plunge (VRT above the contour), ``approach`` the
    rapids of the engine's expansion from the plan's start point to it,
    ``bottom`` the first plunge's bottom, ``far`` the blade over the last plunge."""

    plan: Any
    geometry: Any
    approach: List[Point]
    start: Point
    bottom: Point
    far: Point


class PeckingCall(NamedTuple):
    """One cycle call: the grooves it cuts, the rapids to its start point, the
    engine's cycle model (validated) and the peck retract e it was checked with."""

    plans: List[Any]
    approach: List[Point]
    model: Any
    retract: float


def plain_reason(call: Any, geometry: Any) -> Optional[str]:
    """None when a pecking cycle can cut this CYCLE93 groove, else why not."""
    reasons = []
    if geometry.slope != 0.0:
        reasons.append("an oblique contour (ANGC %s)" % format_decimal(call.value("ANGC"), 3))
    if call.value("ANG1") or call.value("ANG2"):
        reasons.append("flank angles")
    if any(call.value(n) for n in ("RCO1", "RCO2", "RCI1", "RCI2")):
        reasons.append("edge or base radii/chamfers")
    if call.value("FAL1") or call.value("FAL2"):
        reasons.append("finishing allowances")
    if call.value("DWT"):
        reasons.append("a dwell at the bottom")
    return ", ".join(reasons) or None


def groove_span(plan: Any) -> GrooveSpan:
    """The plan's groove as a pecking cycle cuts it; NotNative when the
    expansion's approach does not end at the cycle's start point."""
    geometry = plan.cycle.geometry(plan.settings)
    frame = geometry.frame
    positions = geometry.plunge_positions()
    first, last = positions[0], positions[-1]
    start = Point(*frame.blade(first, geometry.clearance(first)))
    approach = [Point(plan.start.x, plan.start.z)]
    for move in plan.moves:
        if move.kind != RAPID:
            break
        approach.append(Point(move.x, move.z))
    if math.dist(approach[-1], start) > SAME:
        raise NotNative("its start point (the approach of the expansion ends elsewhere)")
    bottom = Point(*frame.blade(first, -geometry.params["DEPG"]))
    far = Point(*frame.blade(last, geometry.clearance(last)))
    return GrooveSpan(plan, geometry, approach, start, bottom, far)


class PeckingCalls:
    """The pecking-cycle calls of one Groove op's groups of grooves, for a
    Program; ``feed`` the grooves' feed (mm/rev with ``per_rev``, else
    mm/min), ``label`` the op's. The calls' words are in the output's units
    (``scale``: output units per mm); the plans are in mm."""

    def __init__(self, program: Program, label: str, feed: float, per_rev: bool = False) -> None:
        self.control = program.control
        self.options = program.options
        self.writer = program.writer
        self.label = label
        self.feed = feed
        self.per_rev = per_rev
        self.scale = 1.0 / MM_PER_INCH if self.options.inches else 1.0
        self.increment = self.control.least_input_increment_inch if self.options.inches \
            else self.control.least_input_increment

    def calls(self, group: List[Any], geometry: Any) -> List[PeckingCall]:
        """One call per groove, or one for the whole group when each groove is
        one plunge (``geometry``: the first groove's); NotNative when the cycle
        cannot cut them."""
        tool = group[0].settings.tool
        single = abs(geometry.params["WIDG"] - tool.width) <= SAME
        spans = [groove_span(plan) for plan in group]
        if single and len(group) > 1:
            return [self._set_call(spans)]
        if single:
            return [self._call([span.plan], span, None, None) for span in spans]
        pitch = self._width_step(tool)
        return [self._call([span.plan], span, span.far, pitch) for span in spans]

    def _set_call(self, spans: List[GrooveSpan]) -> PeckingCall:
        """One call for equally spaced blade-wide grooves: the pitch as the
        groove spacing, the last groove as the last position."""
        longitudinal = spans[0].geometry.longitudinal

        def along(point: Point) -> float:
            """The stepping coordinate: Z for G77/G75, X for G76/G74."""
            return point.z if longitudinal else point.x

        steps = [along(span.start) - along(spans[0].start) for span in spans]
        pitch = abs(steps[1])
        for k, step in enumerate(steps):
            if abs(abs(step) - k * pitch) > EQUAL_SPACING:
                raise NotNative("grooves that are not equally spaced")
        return self._call([span.plan for span in spans], spans[0], spans[-1].start, pitch * self.scale)

    def _width_step(self, tool: Any) -> float:
        """The step across a groove wider than the blade: the engine's own,
        in the output's units, cut to the cycle words' decimals."""
        step = WIDTH_STEP_FACTOR * (tool.width - 2 * tool.corner_radius) * self.scale
        scale = 10 ** self.options.native_decimals
        pitch = math.floor(step * scale + 1e-9) / scale
        if not pitch > 0:
            raise NotNative("a groove wider than the blade with a step below the cycle's resolution")
        return pitch

    def _call(self, plans: List[Any], span: GrooveSpan, last: Optional[Point], pitch: Optional[float]) -> PeckingCall:
        """The call from ``span``'s start point, its last groove at ``last``
        (None: one groove; ``pitch`` in the output's units), validated and
        expanded by the engine in the output's units."""
        shift = corner_shift(span.plan, self.options.reference)
        start = Point(span.start.x + shift.dx, span.start.z + shift.dz)
        bottom = Point(span.bottom.x + shift.dx, span.bottom.z + shift.dz)
        last = None if last is None else Point(last.x + shift.dx, last.z + shift.dz)
        start_x, start_z = self._read_back(start.x, True), self._read_back(start.z, False)
        peck = self._length(span.geometry.params["IDEP"])
        if not peck > 0:
            raise NotNative("an Infeed below the cycle's resolution")
        feed = round(self.feed * self.scale, FEED_DECIMALS)
        if not feed > 0:
            raise NotNative("a feed below the cycle's resolution")
        retract = self._length(self.options.retract if self.options.retract is not None
                               else span.geometry.params["VRT"])
        cycle = self.control.pecking_cycle(span.geometry.longitudinal)
        words = self._position_words(span.geometry.longitudinal, bottom, last)
        words.update(self._cycle_words(cycle, peck, feed, retract, None if last is None else pitch))
        model = cycle(**words)
        state = MachineState(x=start_x, z=start_z, feed=feed, diameter_mode=self.options.diameter,
                             metric=not self.options.inches, feed_per_rev=self.per_rev)
        settings = corner_settings(span.plan, self.options.reference)
        tool = settings.tool
        settings = replace(settings.with_tool(width=tool.width * self.scale,
                                              corner_radius=tool.corner_radius * self.scale), peck_retract=retract)
        try:
            model.validate(settings)
            model.expand(state, settings)
        except CycleError as exc:
            raise cycle_post_error(self.label, exc, PECKING_PROPERTIES) from None
        return PeckingCall(plans, span.approach, model, retract)

    def _length(self, value: float) -> float:
        """A length word from a length in mm: in the output's units, rounded to the cycle words' decimals."""
        return round(value * self.scale, self.options.native_decimals) + 0.0

    def _x_word(self, radius: float) -> float:
        """An X word from a radius in mm: a diameter unless the output is in radius mode."""
        return self._length(radius * (2.0 if self.options.diameter else 1.0))

    def _read_back(self, value: float, x_axis: bool) -> float:
        """The value the control reads back from the written start word (a radius for X), in the output's units."""
        written = self.writer.x_word(value) if x_axis else self.writer.z_word(value)
        return float(written) / (2.0 if (x_axis and self.writer.x_diameter) else 1.0)

    def _position_words(self, longitudinal: bool, bottom: Point, last: Optional[Point]) -> Dict[str, float]:
        """The groove bottom and the last groove's position (X and Z)."""
        words = {}
        if longitudinal:
            words["X"] = self._x_word(bottom.x)
            if last is not None:
                words["Z"] = self._length(last.z)
        else:
            words["Z"] = self._length(bottom.z)
            if last is not None:
                words["X"] = self._x_word(last.x)
        return words

    def _cycle_words(self, cycle: type, peck: float, feed: float, retract: float,
                     pitch: Optional[float]) -> Dict[str, Any]:
        """The peck, the feed, the retract where the cycle holds it, a required
        shift (none) and the groove spacing (``pitch``, None: one groove)."""
        increment = self.increment
        words: Dict[str, Any] = {
            cycle.PECK: int(round(peck / increment)) if cycle.PECK in cycle.COUNTED else peck,
            "F": feed,
        }
        if self.control.retract_word:
            words[self.control.retract_word] = retract
        if cycle.SHIFT_D:  # Allen-Bradley's D: required, 0 = no shift at the bottom
            words[cycle.RELIEF] = 0.0
        if pitch is not None:
            words[cycle.PITCH] = int(round(pitch / increment)) if cycle.PITCH in cycle.COUNTED \
                else round(pitch, self.options.native_decimals) + 0.0
        return words
