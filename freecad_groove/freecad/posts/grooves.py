"""A Groove op's grooves in a program: native CYCLE93 calls, pecking-cycle
calls (plain grooves), or the engine's expanded moves (see the package notes)."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING, Any, Callable, List, Optional

from ...engine import DWELL, FEED, CycleError, ProgramError
from ...engine.moves import Move
from ...engine.numbers import format_decimal
from ..units import feed_mm_per_min
from .controls import NATIVE_CYCLE93, NATIVE_PECKING
from .errors import PostError
from .objects import label_of
from .pecking import NotNative, PeckingCall, PeckingCalls, plain_reason
from .reference_corner import corner_shift

if TYPE_CHECKING:
    from .program import Program

RETRACT_DECIMALS = 4  # of the peck retract named in a comment


def call_text(call: Any) -> str:
    """A CYCLE93 call for a comment (comments cannot hold parentheses)."""
    return call.emit().replace("(", "[").replace(")", "]")


def face_groups(plans: List[Any]) -> List[List[Any]]:
    """The plans in groups of one face each (a face's grooves are numbered from 0)."""
    groups: List[List[Any]] = []
    for plan in plans:
        if plan.index == 0 or not groups:
            groups.append([plan])
        else:
            groups[-1].append(plan)
    return groups


class GrooveOutput:
    """Writes one Groove op's grooves into a Program, native or expanded."""

    def __init__(self, program: Program, op: Any) -> None:
        self.program = program
        self.op = op
        self.label = label_of(op)
        self.feed = 0.0  # mm/min, from the op's tool controller

    def write(self) -> None:
        plans = self._plans()
        if not plans:
            self.program.note("%s: no groove (no face in Base)" % self.label)
            return
        self.feed = self._feed()
        write_group = self._group_writer()
        for group in face_groups(plans):
            write_group(group)

    def _plans(self) -> List[Any]:
        """The op's groove plans (kept by the op while it is up to date)."""
        try:
            return self.op.Proxy.current_plan(self.op)
        except CycleError:
            raise  # the program names the op property
        except ValueError as exc:
            raise PostError(str(exc), op=self.label) from None

    def _feed(self) -> float:
        """The grooves' feed, mm/min: the op's tool controller's HorizFeed."""
        tc = getattr(self.op, "ToolController", None)
        if tc is None:
            raise PostError("is not set: the grooves' feed comes from it", op=self.label, parameter="ToolController")
        feed = feed_mm_per_min(tc.HorizFeed.Value)
        if not feed > 0:
            raise PostError("is 0: the grooves need a feed", op=self.label, parameter="ToolController HorizFeed")
        return feed

    def _group_writer(self) -> Callable[[List[Any]], None]:
        """What writes a face's grooves: the control's native cycle or the expansion."""
        native = self.program.control.native if self.program.options.native else None
        writers = {NATIVE_CYCLE93: self._cycle93_group, NATIVE_PECKING: self.pecking}
        return writers.get(native, self._expanded_group)

    # -- positions in the output's reference corner
    def link(self, plan: Any, to_start: bool = True) -> None:
        """The op's link rapids to the plan's start point (``to_start`` False:
        without the last one when it is the start point, which the caller writes)."""
        shift = corner_shift(plan, self.program.options.reference)
        link = list(plan.link)
        if not to_start and link and link[-1] == (plan.start.x, plan.start.z):
            link = link[:-1]
        for x, z in link:
            self.program.rapid(None if x is None else x + shift.dx, None if z is None else z + shift.dz)

    def rapid_to(self, plan: Any, point: Any, force: bool = False) -> None:
        """A rapid to ``point`` (anything with x and z, model coordinates of the plan)."""
        shift = corner_shift(plan, self.program.options.reference)
        self.program.rapid(point.x + shift.dx, point.z + shift.dz, force=force)

    # -- expanded
    def _expanded_group(self, group: List[Any]) -> None:
        for plan in group:
            self.expanded(plan, None)

    def expanded(self, plan: Any, why: Optional[str]) -> None:
        """The plan's moves as G0/G1 (``why``: the reason it is not a native call, for a comment)."""
        program = self.program
        program.note("%s groove %d: %s" % (plan.face.name, plan.index + 1, call_text(plan.cycle)))
        if why:
            program.note("expanded: " + why)
        self.link(plan)
        shift = corner_shift(plan, program.options.reference)
        moves = [Move(m.kind, m.x + shift.dx, m.z + shift.dz, self.feed if m.kind == FEED else None, m.p)
                 for m in plan.moves]
        if program.x is None or program.z is None:  # the link always ends at the start point; this is a guard
            self.rapid_to(plan, plan.start, force=True)
        try:
            program.add(program.writer.write(moves))
        except ProgramError as exc:
            dwell = any(m.kind == DWELL for m in moves) and "dwell" in str(exc)
            raise PostError(str(exc), op=self.label, parameter="Dwell" if dwell else None) from None
        if moves:
            program.moved(moves[-1].x, moves[-1].z)

    # -- Siemens CYCLE93
    def _cycle93_group(self, group: List[Any]) -> None:
        for plan in group:
            self.cycle93(plan)

    def cycle93(self, plan: Any) -> None:
        """The plan's CYCLE93 call, after a rapid to its start point and its feed."""
        program = self.program
        call = plan.cycle
        if program.options.diameter_input:
            longitudinal = call.kind()[0]
            call = replace(
                call, axfa=2 * call.axfa,
                depg=2 * call.depg if longitudinal else call.depg,
                fal1=2 * call.value("FAL1") if longitudinal else call.fal1,
                fal2=call.fal2 if longitudinal else 2 * call.value("FAL2"),
            )
        program.note("%s groove %d" % (plan.face.name, plan.index + 1))
        self.link(plan, to_start=False)
        self.rapid_to(plan, plan.start, force=True)
        program.add(["F" + program.writer.f_word(self.feed)])  # CYCLE93 cuts at the feed in force
        program.add([call.emit()])
        # CYCLE93 ends at its start point; the motion mode it leaves is not documented
        program.writer.forget(position=False, motion=True, feed=True)

    # -- pecking cycles (Allen-Bradley G77/G76, Fanuc and Haas G75/G74)
    def pecking(self, group: List[Any]) -> None:
        """A face's grooves as pecking-cycle calls, or expanded with the reason when the cycle cannot cut them."""
        first = group[0]
        call = first.cycle
        geometry = call.geometry(first.settings)
        why = plain_reason(call, geometry)
        if why is None:
            try:
                calls = PeckingCalls(self.program, self.label, self.feed).calls(group, geometry)
            except NotNative as exc:
                why = str(exc)
        if why is not None:
            control = self.program.control
            cycle = control.longitudinal_cycle if call.kind()[0] else control.face_cycle
            for plan in group:
                self.expanded(plan, "%s cannot cut %s" % (cycle, why))
            return
        for pecking_call in calls:
            self.pecking_call(pecking_call)

    def pecking_call(self, call: PeckingCall) -> None:
        """One pecking call: comments, the rapids to its start point and back, the call."""
        program, control = self.program, self.program.control
        first = call.plans[0]
        if len(call.plans) > 1:
            what = "%s grooves %d-%d" % (first.face.name, first.index + 1, call.plans[-1].index + 1)
        else:
            what = "%s groove %d" % (first.face.name, first.index + 1)
        program.note("%s: %s as %s" % (what, call_text(first.cycle), call.model.NAME))
        if control.retract_setting:
            program.note("peck retract e = %s mm: %s"
                         % (format_decimal(call.retract, RETRACT_DECIMALS), control.retract_setting))
        self.link(first)
        for point in call.approach[1:-1]:
            self.rapid_to(first, point)
        self.rapid_to(first, call.approach[-1], force=True)
        program.add(call.model.emit().split("\n"))
        # the cycle ends at its start point; motion and feed after it: not relied on
        program.writer.forget(position=False, motion=True, feed=True)
        for point in reversed(call.approach[:-1]):
            self.rapid_to(first, point)
        for plan in call.plans[1:]:
            self.link(plan)
