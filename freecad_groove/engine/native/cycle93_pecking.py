"""Plain CYCLE93 grooves as the pecking cycles of a target (Allen-Bradley
G77/G76, Fanuc and GSK two-block G75/G74, Haas one-block G75/G74): the
decision the lathe posts and ``expand --native-cycles`` share.

A pecking cycle plunges straight, the full width of the blade, to a flat
bottom: it replaces a CYCLE93 groove only when the groove is *plain*
(:func:`plain_reason`: a paraxial contour, no flank angles, no edge or base
radii/chamfers, no allowances, no dwell). Then a groove exactly as wide as
the blade, repeated on a face (a group of grooves), is one call (the pitch as
the groove spacing, the last groove as the last position); a wider groove is
one call per groove stepping across it by the engine's own step, 95 % of
(blade width - 2 x corner radius). The peck depth is IDEP, the peck retract
e the given one, else VRT. The call starts where the engine's CYCLE93
expansion plunges from (VRT above the contour over the first plunge), reached
and left by the same rapids as the CYCLE93 approach.

A groove is anything with ``cycle`` (the Cycle93 model), ``settings`` (its
blade), ``start`` (x radius, z before the call) and ``moves`` (the
expansion from there): the posts' groove plans, the command line's
:class:`Groove`. The target names the cycles (its ``NativeCycles``: the
dialect whose registered cycles it writes, their codes, where e goes); each
cycle class names its own words (``PECK``, ``PITCH``, ``RELIEF``,
``COUNTED``), so nothing here depends on which control it is.
"""

import math
from dataclasses import replace
from typing import Any, Dict, List, NamedTuple, Optional, Sequence

from ..cycles.cycle93 import WIDTH_STEP_FACTOR
from ..moves import ARCS, FEED, RAPID, REFERENCE_PLUS, MachineState, Move
from ..numbers import format_decimal
from ..output.syntax import Target
from ..output.writer import Writer
from ..registry import cycle_for
from ..settings import Settings
from .result import NotNative, Point

__all__ = ["Groove", "GrooveSpan", "PeckingCall", "PeckingOutput", "Shift", "corner_settings", "corner_shift",
           "groove_span", "pecking_calls", "pecking_cycle", "plain_reason", "retract_note"]

SAME = 1e-9  # lengths closer than this are the same (blade width, start points)
EQUAL_SPACING = 1e-6  # how far a groove of a set may be off its pitch
FEED_DECIMALS = 6  # as the expanded moves' F: inch feeds per revolution need them
RETRACT_DECIMALS = 4  # of the peck retract named in a comment


class Groove(NamedTuple):
    """One CYCLE93 groove of a program: its call, the settings it runs with
    (the blade), where the tool stands before it and the expansion from there."""

    cycle: Any
    settings: Settings
    start: Point
    moves: List[Move]


class Shift(NamedTuple):
    """What to add to a groove's words for another reference corner: ``dx`` (radius) and ``dz``."""

    dx: float
    dz: float


def corner_shift(groove: Any, reference: Optional[str]) -> Shift:
    """The shift from the groove's reference corner to ``reference`` (None: its own): every word
    moves by the blade's width along the groove's axis (Z for longitudinal grooves, X for face grooves)."""
    tool = groove.settings.tool
    if reference is None or reference == tool.reference:
        return Shift(0.0, 0.0)
    d = (tool.width if reference == REFERENCE_PLUS else 0.0) - tool.reference_offset
    return Shift(0.0, d) if groove.cycle.kind()[0] else Shift(d, 0.0)


def shifted(move: Move, shift: Shift, f: Optional[float]) -> Move:
    """``move`` measured from the other corner: its end and an arc's centre shifted, its feed ``f``."""
    centre = None if move.centre is None else (move.centre[0] + shift.dx, move.centre[1] + shift.dz)
    return Move(move.kind, move.x + shift.dx, move.z + shift.dz, f, move.p, centre=centre, radius=move.radius)


def shifted_moves(moves: List[Move], shift: Shift, feed: float) -> List[Move]:
    """Every move as ``shifted`` gives it, a FEED move and an arc fed at ``feed``, the others with no F: a
    post's groove (500 of them in a Job). Without a shift a move that stays as it is is not copied."""
    if shift.dx != 0.0 or shift.dz != 0.0:
        return [shifted(m, shift, feed if m.kind == FEED or m.kind in ARCS else None) for m in moves]
    out = []
    for m in moves:
        kind = m.kind
        f = feed if kind == FEED or kind in ARCS else None
        out.append(m if m.f == f and m.y is None and m.c is None else
                   Move(kind, m.x, m.z, f, m.p, None, None, m.centre, m.radius))
    return out


def corner_settings(groove: Any, reference: Optional[str]) -> Settings:
    """The groove's settings with the tool measured from ``reference`` (None: its own)."""
    return groove.settings if reference is None else groove.settings.with_tool(reference=reference)


class PeckingOutput(NamedTuple):
    """How the calls are written. ``target``: its NativeCycles name the cycles;
    ``writer``: the output's writer (its units, X words as diameters or not;
    the start words are read back from it); ``scale``: output units per groove
    unit (1/25.4: grooves in mm written in inches); ``decimals``: of the cycle
    words; ``diameter``: X words are diameters; ``retract``: e, in groove
    units (None: the groove's VRT); ``setting_retract``: e where the target
    holds it as a machine setting, as the settings give it (None: as
    ``retract``); ``reference``: the blade corner the words measure (None:
    each groove's own); ``metric``: the grooves' lengths are mm."""

    target: Target
    writer: Writer
    scale: float = 1.0
    decimals: int = 4
    diameter: bool = True
    retract: Optional[float] = None
    setting_retract: Optional[float] = None
    reference: Optional[str] = None
    metric: bool = True

    @property
    def increment(self) -> float:
        """The least input increment of counted words (Fanuc P/Q), output units."""
        return 10.0 ** -self.target.digits(self.writer.metric)


class GrooveSpan(NamedTuple):
    """One groove as a pecking cycle cuts it, in the groove's coordinates:
    ``start`` the blade over the first plunge (VRT above the contour),
    ``approach`` the rapids of the expansion from the groove's start point to
    it, ``bottom`` the first plunge's bottom, ``far`` the blade over the last plunge."""

    plan: Any
    geometry: Any
    approach: List[Point]
    start: Point
    bottom: Point
    far: Point


class PeckingCall(NamedTuple):
    """One cycle call: the grooves it cuts, the rapids to its start point, the
    cycle model (validated), the peck retract e it was checked with (output
    units) and its moves from its start point (output units)."""

    plans: List[Any]
    approach: List[Point]
    model: Any
    retract: float
    moves: List[Move] = []


def pecking_cycle(target: Target, longitudinal: bool) -> type:
    """The cycle class ``target`` writes for a longitudinal or a face groove."""
    native = target.native
    return cycle_for(native.dialect, native.longitudinal if longitudinal else native.face)


def retract_note(target: Target, retract: float, metric: bool) -> Optional[str]:
    """The comment naming the peck retract a call relies on where the target
    holds it as a machine setting (None where the call writes it)."""
    if not target.native.retract_setting:
        return None
    return "peck retract e = %s %s: %s" % (format_decimal(retract, RETRACT_DECIMALS), "mm" if metric else "in",
                                           target.native.retract_setting)


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


def groove_span(plan: Any, metric: bool = True) -> GrooveSpan:
    """The groove as a pecking cycle cuts it; NotNative when the expansion's
    approach does not end at the cycle's start point."""
    geometry = plan.cycle.geometry(plan.settings, metric)
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


def pecking_calls(group: Sequence[Any], output: PeckingOutput, feed: float, per_rev: bool = False) -> List[PeckingCall]:
    """The calls that cut ``group`` (grooves of one face, in order; ``feed``
    their feed in output units per minute, or per revolution with
    ``per_rev``): one per groove, or one for the whole group when each groove
    is one plunge. NotNative (``G75 cannot cut flank angles``) when the
    target's cycle cannot cut them; CycleError when a call breaks its cycle's rules."""
    first = group[0]
    geometry = first.cycle.geometry(first.settings, output.metric)
    why = plain_reason(first.cycle, geometry)
    if why is None:
        try:
            return _Calls(output, feed, per_rev).calls(list(group), geometry)
        except NotNative as exc:
            why = str(exc)
    native = output.target.native
    raise NotNative("%s cannot cut %s" % (native.longitudinal if geometry.longitudinal else native.face, why))


class _Calls:
    """The calls of one group; the words in the output's units, the grooves in theirs."""

    def __init__(self, output: PeckingOutput, feed: float, per_rev: bool) -> None:
        self.output = output
        self.writer = output.writer
        self.feed = feed
        self.per_rev = per_rev
        self.scale = output.scale

    def calls(self, group: List[Any], geometry: Any) -> List[PeckingCall]:
        tool = group[0].settings.tool
        single = abs(geometry.params["WIDG"] - tool.width) <= SAME
        spans = [groove_span(plan, self.output.metric) for plan in group]
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
        scale = 10 ** self.output.decimals
        pitch = math.floor(step * scale + 1e-9) / scale
        if not pitch > 0:
            raise NotNative("a groove wider than the blade with a step below the cycle's resolution")
        return pitch

    def _retract(self, span: GrooveSpan) -> float:
        """e in the output's units: the machine setting's where the target holds it so, else the given one or VRT."""
        output = self.output
        if output.target.native.retract_setting and output.setting_retract is not None:
            return self._length(output.setting_retract)
        return self._length(output.retract if output.retract is not None else span.geometry.params["VRT"])

    def _call(self, plans: List[Any], span: GrooveSpan, last: Optional[Point], pitch: Optional[float]) -> PeckingCall:
        """The call from ``span``'s start point, its last groove at ``last``
        (None: one groove; ``pitch`` in the output's units), validated and
        expanded by the engine in the output's units."""
        shift = corner_shift(span.plan, self.output.reference)
        bottom = Point(span.bottom.x + shift.dx, span.bottom.z + shift.dz)
        last = None if last is None else Point(last.x + shift.dx, last.z + shift.dz)
        start_x = self._read_back(span.start.x + shift.dx, True)
        start_z = self._read_back(span.start.z + shift.dz, False)
        peck = self._length(span.geometry.params["IDEP"])
        if not peck > 0:
            raise NotNative("an Infeed below the cycle's resolution")
        feed = round(self.feed * self.scale, FEED_DECIMALS)
        if not feed > 0:
            raise NotNative("a feed below the cycle's resolution")
        retract = self._retract(span)
        cycle = pecking_cycle(self.output.target, span.geometry.longitudinal)
        words = self._position_words(span.geometry.longitudinal, bottom, last)
        words.update(self._cycle_words(cycle, peck, feed, retract, None if last is None else pitch))
        model = cycle(**words)
        state = MachineState(x=start_x, z=start_z, feed=feed, diameter_mode=self.output.diameter,
                             metric=self.writer.metric, feed_per_rev=self.per_rev)
        settings = corner_settings(span.plan, self.output.reference)
        tool = settings.tool
        settings = replace(settings.with_tool(width=tool.width * self.scale,
                                              corner_radius=tool.corner_radius * self.scale), peck_retract=retract)
        model.validate(settings)
        moves = model.expand(state, settings)
        return PeckingCall(plans, span.approach, model, retract, moves)

    def _length(self, value: float) -> float:
        """A length word from a groove length: in the output's units, rounded to the cycle words' decimals."""
        return round(value * self.scale, self.output.decimals) + 0.0

    def _x_word(self, radius: float) -> float:
        """An X word from a radius: a diameter unless the output is in radius mode."""
        return self._length(radius * (2.0 if self.output.diameter else 1.0))

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
        increment = self.output.increment
        words: Dict[str, Any] = {
            cycle.PECK: int(round(peck / increment)) if cycle.PECK in cycle.COUNTED else peck,
            "F": feed,
        }
        retract_word = self.output.target.native.retract_word
        if retract_word:
            words[retract_word] = retract
        if cycle.SHIFT_D:  # Allen-Bradley's D: required, 0 = no shift at the bottom
            words[cycle.RELIEF] = 0.0
        if pitch is not None:
            words[cycle.PITCH] = int(round(pitch / increment)) if cycle.PITCH in cycle.COUNTED \
                else round(pitch, self.output.decimals) + 0.0
        return words
