"""Whether each cycle call of a translated program is written as the target's
own cycle (``expand --native-cycles``), and as which call.

:class:`NativeOutput` decides call by call, for one program and one target:

* a call of the target's own family is written as the target writes it (the
  model's ``emit()``: Fanuc's ``G75 R(e)`` first block, the G7.1 region, the P
  assignment blocks), its words absolute, X a diameter, at the output's
  resolution; CYCLE93 to ``sinumerik``, G7.1 to ``gsk``, G83/G83.1 to
  ``ab9grind`` (every word written, none left to the control's memory),
  G31-G34 to ``milltronics``;
* CYCLE93 to a pecking target (``ab9``, ``fanuc``, ``fanuc-c``, ``haas``,
  ``gsk``): as the lathe posts decide (cycle93_pecking.py), plain grooves only;
* a pecking call to another pecking target or to CYCLE93 (pecking_convert.py);
* anything else: the moves, with the reason (``LinuxCNC has no grooving cycle``).

Except CYCLE93 to the pecking cycles (whose chip-breaking differs by design,
as in the posts), a call is written natively only when the engine's expansion
of the call as written, from the start as written, cuts the same moves as the
program's own call (compare.py): "the same" is proven, not assumed. What the
output's control remembers of the native calls (G83's words, the Milltronics
P parameters and clearance plane R) is kept here, so a call that reads the
control's memory (G31) is proven against what the output gave it.
"""

from dataclasses import asdict, replace
from typing import Any, Dict, List, Optional, Tuple

from ..cycles.ab_g83 import G83
from ..cycles.cycle93 import Cycle93
from ..cycles.gsk_g7_1 import GskG7_1
from ..cycles.milltronics import G31, G32, PARAMETERS, MilltronicsCycle
from ..cycles.pecking import PeckingCycle
from ..errors import CycleError
from ..moves import GroovingTool, MachineState, Move
from ..numbers import format_decimal
from ..output.syntax import Target
from ..output.writer import Writer
from ..settings import Settings
from .compare import difference, resolved
from .cycle93_pecking import Groove, PeckingOutput, pecking_calls, retract_note
from .pecking_convert import Words, to_cycle93, to_pecking
from .result import NativeCall, NotNative, Point

__all__ = ["FAMILIES", "NativeOutput", "family_of"]

GROOVES, SLOTS, GRINDS, MILL = "grooves", "slots", "grinds", "mill"
# a family of cycles: what a target without it lacks (for the reason)
FAMILIES = {GROOVES: "grooving cycle", SLOTS: "G7.1 cylinder slot cycle", GRINDS: "G83 plunge grinding cycle",
            MILL: "Milltronics autoroutine G31-G34"}


def family_of(model: Any) -> str:
    """The family of a cycle model (FAMILIES); ValueError for one no target writes natively."""
    for family, classes in ((GROOVES, (Cycle93, PeckingCycle)), (SLOTS, (GskG7_1,)), (GRINDS, (G83,)),
                            (MILL, (MilltronicsCycle,))):
        if isinstance(model, classes):
            return family
    raise ValueError("%s has no native form" % type(model).__name__)


def _has(target: Target, family: str) -> bool:
    native = target.native
    return bool(native.grooves if family == GROOVES else getattr(native, family))


class NativeOutput:
    """The native calls of one program written for ``target`` by ``writer``
    (see the module notes); ``memory`` what the output's control remembers of
    the native calls written so far (cycle MEMORY key -> words)."""

    def __init__(self, target: Target, writer: Writer) -> None:
        self.target = target
        self.writer = writer
        self.memory: Dict[str, Dict[str, float]] = {}

    @property
    def tolerance(self) -> float:
        """The output's resolution: how far two moves may differ and be the same."""
        return 10.0 ** -self.writer.digits

    def words(self) -> Words:
        return Words(self.writer.digits, self.target.feed_digits, self.writer.x_diameter)

    def written(self, start: MachineState) -> MachineState:
        """``start`` as the control reads it back from the written words (absolute, X as the output writes it)."""
        writer = self.writer
        return MachineState(
            x=None if start.x is None else writer.written_x(start.x),
            z=None if start.z is None else float(writer.z_word(start.z)), feed=start.feed,
            diameter_mode=writer.x_diameter, incremental=False, metric=start.metric,
            feed_per_rev=start.feed_per_rev, c=None if start.c is None else round(start.c, writer.digits),
            y=None if start.y is None else float(writer.y_word(start.y)))

    def call(self, model: Any, start: MachineState, settings: Settings, moves: List[Move],
             blade: Optional[GroovingTool] = None, register: Optional[int] = None) -> NativeCall:
        """The target's call for the validated ``model`` (memory words filled in)
        run from ``start`` with ``settings`` (its expansion: ``moves``);
        ``blade``: the blade of the tool in force, for a CYCLE93 written in
        place of another call; ``register``: the diameter register D in force
        (Milltronics). NotNative with the reason when it is written as moves."""
        family = family_of(model)
        if not _has(self.target, family):
            raise NotNative("%s has no %s" % (self.target.maker, FAMILIES[family]))
        if family == GROOVES:
            return self._groove(model, start, settings, moves, blade)
        if family == MILL:
            return self._mill(model, start, settings, moves, register)
        if family == GRINDS:
            model = grind_model(model, start, self.words())
        return self._proved(model, start, settings, moves)

    # -- grooves ------------------------------------------------------------------------

    def _groove(self, model: Any, start: MachineState, settings: Settings, moves: List[Move],
                blade: Optional[GroovingTool]) -> NativeCall:
        kind = self.target.native.grooves
        cycle93 = isinstance(model, Cycle93)
        if cycle93 and start.feed is None:
            raise NotNative("no feed is in force for CYCLE93 to cut at")
        if cycle93 and kind == "cycle93":
            return self._proved(model, start, settings, moves, feed=start.feed, notes=_cycle93_notes(settings))
        if cycle93:
            return self._cycle93_pecking(model, start, settings, moves)
        tstart = self.written(start)
        if kind == "cycle93":
            call, got, feed = to_cycle93(model, start, settings, moves, blade, tstart, self.writer.digits,
                                         self.tolerance)
            return NativeCall(call, got, feed=feed, notes=_cycle93_notes(settings))
        call, got = to_pecking(model, start, settings, moves, self.target, tstart, self.words(), self.tolerance)
        note = retract_note(self.target, settings.retract_e(start.metric), start.metric)
        return NativeCall(call, got, notes=(note,) if note else ())

    def _cycle93_pecking(self, model: Cycle93, start: MachineState, settings: Settings,
                         moves: List[Move]) -> NativeCall:
        """CYCLE93 as the target's pecking call, as the lathe posts decide (cycle93_pecking.py)."""
        writer = self.writer
        output = PeckingOutput(self.target, writer, 1.0, min(writer.digits, 4), writer.x_diameter,
                               settings.peck_retract, settings.retract_e(start.metric), None, start.metric)
        groove = Groove(model, settings, Point(start.x, start.z), moves)
        try:
            call, = pecking_calls([groove], output, start.feed, bool(start.feed_per_rev))
        except CycleError as exc:
            native = self.target.native
            code = native.longitudinal if model.kind()[0] else native.face
            raise NotNative("%s cannot cut it: %s" % (code, exc.message)) from None
        note = retract_note(self.target, call.retract, start.metric)
        approach = tuple(call.approach)
        return NativeCall(call.model, call.moves, approach[1:], tuple(reversed(approach[:-1])),
                          (note,) if note else ())

    # -- the same family -----------------------------------------------------------------

    def _proved(self, model: Any, start: MachineState, settings: Settings, moves: List[Move],
                feed: Optional[float] = None, notes: Tuple[str, ...] = (), register: Optional[int] = None,
                why: str = "") -> NativeCall:
        """``model`` written as it is, when its expansion from the start as
        written (with what the output's control remembers) cuts ``moves``;
        else NotNative (``why``, or where the moves differ)."""
        tstart = replace(self.written(start), feed=start.feed if feed is None else feed)
        key = model.MEMORY
        read = model.with_earlier(self.memory.get(key, {}), tstart) if key else model
        try:
            got = read.expand(tstart, settings)
        except CycleError as exc:
            raise NotNative("%s as written: %s" % (model.NAME, exc.message)) from None
        tolerance = self.tolerance
        diff = difference(resolved(moves, start, tolerance), resolved(got, tstart, tolerance), tolerance,
                          self.writer.target.mill)
        if diff is not None:
            raise NotNative(why or "%s as written cuts other moves: %s" % (model.NAME, diff))
        if key:
            self.memory[key] = read.remembered(tstart)
        return NativeCall(model, got, notes=notes, feed=feed, register=register)

    def _mill(self, model: MilltronicsCycle, start: MachineState, settings: Settings, moves: List[Move],
              register: Optional[int]) -> NativeCall:
        """G33/G34 with every word and P parameter written; G31/G32 as they are."""
        writer = self.writer
        if isinstance(model, G31):  # G32 too: Z alone, to a height the control holds
            call = type(model)()
            read = call.with_earlier(self.memory.get(call.MEMORY, {}), start)
            height = format_decimal(read.height(start, settings), writer.digits)
            if isinstance(model, G32):
                note = "tool change position Z%s: a machine setting, milltronics_tool_change_inch" % height
            elif read.R is None:
                note = "clearance Z%s: parameter 140, milltronics_clearance_inch" % height
            else:
                note = ""
            why = "" if read.R == model.R else ("G31 rises to the last R the output's control was given, not the "
                                                "program's: an autoroutine before it is written as moves")
            return self._proved(call, start, settings, moves, notes=(note,) if note else (), why=why)
        if start.feed is None:
            raise NotNative("no X-Y feed is in force for %s to cut at" % model.NAME)
        if register is None:
            raise NotNative("%s reads the end mill's diameter from the D register in force, which the program "
                            "does not select with D<n>" % model.NAME)
        return self._proved(mill_model(model, self.words()), start, settings, moves, feed=start.feed,
                            register=register)


def _cycle93_notes(settings: Settings) -> Tuple[str, ...]:
    """A CYCLE93 read with --diameter-input relies on the control reading its words so (840D with DIAMON)."""
    if settings.cycle93_diameter_input:
        return ("CYCLE93 reads AXFA, DEPG, FAL1 and FAL2 as diameters: the control must too, --diameter-input",)
    return ()


def grind_model(model: G83, start: MachineState, words: Words) -> G83:
    """The G83/G83.1 cutting what ``model`` cuts from ``start``, every word it
    may take from the control's memory written, absolute (the output is G90)."""
    plan = model.plan(start)
    length = words.length
    values: Dict[str, Any] = dict(X=length(plan.primary), I=length(plan.secondary), Y=length(plan.depth),
                                  Z=length(plan.cross_end), J=length(plan.j), K=length(plan.k),
                                  F=words.feed(plan.feed), E=words.feed(plan.recip_feed))
    if plan.q != plan.j:
        values["Q"] = length(plan.q)
    if plan.r != plan.k:
        values["R"] = length(plan.r)
    if plan.spark_out:
        values["L"] = plan.spark_out
    if plan.program is not None:
        values["P"] = plan.program
    if plan.dresses:
        values["D"] = plan.dresses
    return type(model)(**values)


def mill_model(model: MilltronicsCycle, words: Words) -> MilltronicsCycle:
    """G33/G34 with its words and P parameters at the output's resolution."""
    values = {key: words.length(value) for key, value in asdict(model).items()
              if key in ("R", "Z", "V", "Q") + PARAMETERS and value is not None}
    return replace(model, F=words.feed(model.F), **values)
