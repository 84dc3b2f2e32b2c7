"""A pecking cycle call (Allen-Bradley G77/G76, Fanuc and GSK two-block G75/G74,
Haas one-block G75/G74) written as another control's pecking cycle, or as
CYCLE93: the call is rebuilt from the layout it cuts (absolute positions,
X a diameter, lengths at the output's resolution), then both calls are
expanded and their moves compared (compare.py): it is written natively only
when the target's call cuts the same moves. Where they differ the reason says
why, for the differences known to matter:

* Allen-Bradley's D shifts the blade at the bottom of every groove, signed;
  Fanuc's R and Haas' D relieve it toward the grooves already cut, never at
  the first;
* a target that holds the peck retract e as a machine setting (the
  Allen-Bradley AMP parameter, Haas setting 22) retracts by the e the
  settings give (``--retract``), not by a Fanuc call's R(e);
* CYCLE93 cuts one groove a call, in equal infeeds each followed by a
  retract and a rapid back down, and places its plunge with the blade: only
  a one-groove, one-peck call is the same cut.
"""

from dataclasses import replace
from typing import Any, Dict, List, Optional

from ..cycles.cycle93 import DEFAULT_VRT_INCH, DEFAULT_VRT_MM, Cycle93
from ..cycles.cycle_words import F_DECIMALS
from ..cycles.pecking import PeckingLayout
from ..errors import CycleError
from ..moves import GroovingTool, MachineState, Move
from ..numbers import format_decimal
from ..output.syntax import Target
from ..settings import Settings
from .compare import difference, resolved
from .cycle93_pecking import pecking_cycle
from .result import NotNative

__all__ = ["Words", "cycle93_model", "pecking_model", "to_cycle93", "to_pecking"]


class Words:
    """Word values at the output's resolution: ``digits`` decimals, counted
    words in least input increments, X a diameter (``diameter``)."""

    def __init__(self, digits: int, feed_digits: int, diameter: bool = True) -> None:
        self.digits = digits
        self.feed_digits = min(feed_digits, F_DECIMALS)
        self.diameter = diameter

    def length(self, value: float) -> float:
        return round(value, self.digits) + 0.0

    def x(self, radius: float) -> float:
        return self.length(radius * (2.0 if self.diameter else 1.0))

    def counted(self, value: float) -> int:
        return int(round(value * 10 ** self.digits))

    def feed(self, value: Optional[float]) -> Optional[float]:
        return None if value is None else round(value, self.feed_digits) + 0.0


def pecking_model(target: Target, layout: PeckingLayout, words: Words) -> Any:
    """The target's pecking call cutting ``layout`` (its relief as near as the cycle has one)."""
    cycle = pecking_cycle(target, layout.longitudinal)
    values: Dict[str, Any] = {}

    def put(letter: str, length: float) -> None:
        values[letter] = words.counted(length) if letter in cycle.COUNTED else words.length(length)

    values[cycle.BOTTOM[0]] = words.x(layout.bottom) if cycle.BOTTOM[0] == "X" else words.length(layout.bottom)
    if len(layout.positions) > 1:
        last = layout.positions[-1]
        values[cycle.LAST[0]] = words.x(last) if cycle.LAST[0] == "X" else words.length(last)
        put(cycle.PITCH, layout.pitch)
    put(cycle.PECK, layout.peck)
    values["F"] = words.feed(layout.feed)
    relief = layout.relief if layout.relief_made else 0.0
    if cycle.SHIFT_D:
        values[cycle.RELIEF] = words.length(relief)
    elif relief:
        values[cycle.RELIEF] = words.length(abs(relief))
    if target.native.retract_word:
        values[target.native.retract_word] = words.length(layout.retract)
    return cycle(**values)


def _read(model: Any, start: MachineState, settings: Settings) -> List[Move]:
    """The moves of the rebuilt call; NotNative when it breaks its cycle's rules."""
    try:
        return model.validate(settings).expand(start, settings)
    except CycleError as exc:
        raise NotNative("%s cannot cut it: %s" % (model.NAME, exc.message)) from None


def _pecking_reason(source: Any, model: Any, layout: PeckingLayout, target: Target, settings: Settings,
                    metric: bool, tolerance: float) -> Optional[str]:
    """Why ``model`` cuts other moves than ``source``, where the reason is a known one."""
    if source.SHIFT_D != model.SHIFT_D and layout.relief_made:
        if source.SHIFT_D:
            return ("the D shift of %s is made at the bottom of every groove, the relief %s of %s never at the "
                    "first" % (source.NAME, model.RELIEF, model.NAME))
        return ("the relief %s of %s is not made at the first groove, the D shift of %s is made at every groove"
                % (source.RELIEF, source.NAME, model.NAME))
    held = settings.retract_e(metric)
    if target.native.retract_setting and layout.pecks > 1 and abs(layout.retract - held) > tolerance:
        unit = "mm" if metric else "in"
        return ("the peck retract e is %s %s, the %s %s reads is %s %s: give --retract %s"
                % (_number(layout.retract), unit, target.native.retract_setting, model.NAME, _number(held), unit,
                   _number(layout.retract)))
    return None


def _number(value: float) -> str:
    return format_decimal(value, 4, point=False)


def to_pecking(source: Any, start: MachineState, settings: Settings, moves: List[Move], target: Target,
               tstart: MachineState, words: Words, tolerance: float) -> Any:
    """The target's pecking call for ``source`` (from ``start``, its ``moves``),
    read from ``tstart`` (the start as written); NotNative with the reason when
    it cuts other moves: (the model, its moves)."""
    layout = source.layout(start, settings)
    model = pecking_model(target, layout, words)
    got = _read(model, tstart, settings)
    diff = difference(resolved(moves, start, tolerance), resolved(got, tstart, tolerance), tolerance)
    if diff is None:
        return model, got
    why = _pecking_reason(source, model, layout, target, settings, start.metric, tolerance)
    raise NotNative(why or "%s cuts other moves: %s" % (model.NAME, diff))


def _cycle93_reason(source: Any, layout: PeckingLayout, blade: Optional[GroovingTool]) -> Optional[str]:
    """Why CYCLE93 cannot cut what ``source`` cuts, known before building it."""
    if len(layout.positions) > 1:
        return "CYCLE93 cuts one groove a call, %s cuts %d" % (source.NAME, len(layout.positions))
    if layout.pecks > 1:
        return ("CYCLE93 cuts in equal infeeds, each followed by a retract and a rapid back down, not %s's %d "
                "pecks" % (source.NAME, layout.pecks))
    if layout.relief_made:
        return "CYCLE93 has no shift at the groove bottom as %s's %s" % (source.NAME, source.RELIEF)
    if blade is None:
        return "CYCLE93 places its plunge with the blade, which is not known: give --tool-width or --tool-table"
    return None


def cycle93_model(layout: PeckingLayout, tstart: MachineState, blade: GroovingTool, settings: Settings,
                  digits: int) -> Cycle93:
    """The CYCLE93 call whose one plunge is the layout's one peck from ``tstart``:
    a groove as wide as the blade, its contour (ANGC 90 for a face groove) VRT
    below the start (VRT at most half the plunge), its start edge where the
    blade's reference corner stands."""
    longitudinal = layout.longitudinal
    here = tstart.x if longitudinal else tstart.z
    across = tstart.z if longitudinal else tstart.x
    external = layout.bottom < here
    sv = 1.0 if external else -1.0
    plunge = abs(here - layout.bottom)
    default = DEFAULT_VRT_MM if tstart.metric else DEFAULT_VRT_INCH
    vrt = round(min(default, plunge / 2.0), digits)
    fine = digits + 1  # a radius read from a diameter word has one more decimal
    contour = round(here - sv * vrt, fine)
    depth = round(abs(contour - layout.bottom), fine)
    edge = round(across - blade.reference_offset, fine)
    axfa, axsa = (contour, edge) if longitudinal else (edge, contour)
    if settings.cycle93_diameter_input:
        axfa, depth = 2.0 * axfa, 2.0 * depth if longitudinal else depth
    typ = (1 if external else 3) if longitudinal else (2 if external else 4)
    idep = round(max(layout.peck, depth), fine)
    return Cycle93(axfa=axfa, axsa=axsa, widg=blade.width, depg=depth, angc=None if longitudinal else 90.0,
                   idep=idep, typ=typ, vrt=vrt)


def to_cycle93(source: Any, start: MachineState, settings: Settings, moves: List[Move], blade: Optional[GroovingTool],
               tstart: MachineState, digits: int, tolerance: float) -> Any:
    """CYCLE93 for the pecking call ``source`` (from ``start``, its ``moves``),
    read from ``tstart`` with ``blade``: (the model, its moves, the feed in
    force it cuts at); NotNative with the reason when it cuts other moves."""
    layout = source.layout(start, settings)
    why = _cycle93_reason(source, layout, blade)
    if why:
        raise NotNative(why)
    tstart = replace(tstart, feed=layout.feed if layout.feed is not None else start.feed)
    with_blade = replace(settings, tool=blade)
    model = cycle93_model(layout, tstart, blade, with_blade, digits)
    got = _read(model, tstart, with_blade)
    diff = difference(resolved(moves, start, tolerance), resolved(got, tstart, tolerance), tolerance)
    if diff is not None:
        raise NotNative("CYCLE93 cuts other moves: %s" % diff)
    return model, got, tstart.feed
