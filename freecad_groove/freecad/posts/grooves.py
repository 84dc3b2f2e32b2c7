"""A Groove op's grooves in a program: native CYCLE93 calls, pecking-cycle
calls (plain grooves), or the engine's expanded moves (see the package notes).

The pecking-cycle calls (Allen-Bradley G77/G76, Fanuc, Haas and GSK G75/G74)
that cut a group of plain CYCLE93 grooves are decided and built by the engine
(``engine/native/cycle93_pecking.py``, shared with ``expand --native-cycles``);
here they get the post's output, and an error names the op property at fault
(``PECKING_PROPERTIES``)."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING, Any, Callable, List, Optional, Tuple

from ...engine import DWELL, CycleError, ProgramError
from ...engine.moves import RAPID, Move
from ...engine.native import NotNative
from ...engine.native.cycle93_pecking import (
    PeckingCall,
    PeckingOutput,
    corner_shift,
    pecking_calls,
    retract_note,
    shifted_moves,
)
from ...engine.numbers import MM_PER_INCH
from ...ops.groove.cutting import CuttingData, cutting_data
from ...ops.groove.properties import GrooveInputError
from .lathe_posts import NATIVE_CYCLE93, NATIVE_PECKING
from .objects import label_of
from .post_error import PostError, cycle_post_error

if TYPE_CHECKING:
    from .program import Program

CYCLE93_LENGTHS = ("axfa", "axsa", "widg", "depg", "rco1", "rco2", "rci1", "rci2", "fal1", "fal2", "idep", "vrt")
# pecking word -> what the op sets it from
PECKING_PROPERTIES = {"I": "Infeed", "K": "Infeed", "P": "Infeed", "Q": "Infeed", "X": "Depth", "Z": "Depth",
                      "F": "FeedPerRev (or the tool controller's HorizFeed)", "e": "Retract", "R(e)": "Retract"}


def groove_cutting(op: Any) -> CuttingData:
    """The Groove op's feeds and speeds (cutting.py; kept by the op with its plans while they are current);
    PostError naming the op property at fault."""
    current = getattr(getattr(op, "Proxy", None), "current_cutting", None)
    try:
        return current(op) if current is not None else cutting_data(op)
    except GrooveInputError as exc:
        raise PostError(str(exc), op=label_of(op)) from None


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
        self.feed = 0.0  # mm/min or mm/rev (per_rev), the op's (cutting.py)
        self.per_rev = False

    def write(self) -> None:
        plans = self._plans()
        if not plans:  # nothing to cut: never an op's frame without its grooves
            raise PostError("Base: no face picked: the op has no groove to cut", op=self.label)
        cutting = groove_cutting(self.op)
        self.feed, self.per_rev = cutting.feed, cutting.per_rev
        self.program.set_feed_mode(cutting.per_rev)
        write_group = self._group_writer()
        for group in face_groups(plans):
            write_group(group)
        self.retreat(plans[-1])

    def _plans(self) -> List[Any]:
        """The op's groove plans (kept by the op while it is up to date)."""
        try:
            return self.op.Proxy.current_plan(self.op)
        except CycleError:
            raise  # the program names the op property
        except ValueError as exc:
            raise PostError(str(exc), op=self.label) from None

    def _group_writer(self) -> Callable[[List[Any]], None]:
        """What writes a face's grooves: the target's native cycle or the expansion."""
        native = self.program.post.native if self.program.options.native else None
        writers = {NATIVE_CYCLE93: self._cycle93_group, NATIVE_PECKING: self.pecking}
        return writers.get(native, self._expanded_group)

    # -- positions in the output's reference corner
    def link(self, plan: Any, to_start: bool = True) -> None:
        """The op's link rapids to the plan's start point (``to_start`` False:
        without the last one when it reaches the start point, which the caller
        then writes in one block: the same motion, since an axis the step
        leaves out is known to be at the start point already)."""
        shift = corner_shift(plan, self.program.options.reference)
        moves = [(None if x is None else x + shift.dx, None if z is None else z + shift.dz) for x, z in plan.link]
        if moves and not to_start and self._reached(moves) == (plan.start.x + shift.dx, plan.start.z + shift.dz):
            moves.pop()
        self.rapids(moves)

    def _reached(self, points: List[Tuple[Optional[float], Optional[float]]]) -> Tuple[Any, Any]:
        """Where the tool is after rapids to ``points`` (x, z; None: that axis does not move)."""
        return (next((x for x, _z in reversed(points) if x is not None), self.program.x),
                next((z for _x, z in reversed(points) if z is not None), self.program.z))

    def retreat(self, plan: Any) -> None:
        """The op's rapids back to its safe start point after ``plan`` (its
        last groove, which every writer leaves at that groove's start point)."""
        shift = corner_shift(plan, self.program.options.reference)
        self.rapids([(x + shift.dx, z + shift.dz) for x, z in plan.retreat])

    def rapids(self, points: List[Tuple[Optional[float], Optional[float]]]) -> None:
        """Rapids to ``points`` (x, z; None: that axis does not move), written in one go: what a rapid at a
        time writes (the writer's modal words: test_writer.py, one go against one at a time), the tool where
        the last of each axis leaves it."""
        program = self.program
        program.add(program.writer.write([Move(RAPID, x, z) for x, z in points]))
        program.moved(*self._reached(points))

    def rapid_to(self, plan: Any, point: Any, force: bool = False) -> None:
        """A rapid to ``point`` (anything with x and z, model coordinates of the plan)."""
        shift = corner_shift(plan, self.program.options.reference)
        self.program.rapid(point.x + shift.dx, point.z + shift.dz, force=force)

    # -- expanded
    def _expanded_group(self, group: List[Any]) -> None:
        for plan in group:
            self.expanded(plan, None)

    def expanded(self, plan: Any, why: Optional[str]) -> None:
        """The plan's moves as G0/G1/G2/G3 (``why``: the reason it is not a native call, for a comment)."""
        program = self.program
        program.note("%s groove %d: %s" % (plan.face.name, plan.index + 1, call_text(plan.cycle)))
        if why:
            program.note("expanded: " + why)
        self.link(plan)
        shift = corner_shift(plan, program.options.reference)
        moves = shifted_moves(plan.moves, shift, self.feed)
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
        if program.options.inches:  # every length word in inches (G700); ANGC, ANG1/2, DWT, TYP stay
            call = replace(call, **{name: getattr(call, name) / MM_PER_INCH for name in CYCLE93_LENGTHS
                                    if getattr(call, name) is not None})
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
        try:
            calls = self.pecking_calls(group)
        except NotNative as exc:
            for plan in group:
                self.expanded(plan, str(exc))
            return
        for pecking_call in calls:
            self.pecking_call(pecking_call)

    def pecking_calls(self, group: List[Any]) -> List[PeckingCall]:
        """The calls that cut ``group``, their words in the output's units (the
        plans are in mm); NotNative (the whole reason: ``G75 cannot cut flank
        angles``) when the target's cycle cannot cut them."""
        options = self.program.options
        output = PeckingOutput(
            self.program.writer.target, self.program.writer, 1.0 / MM_PER_INCH if options.inches else 1.0,
            options.native_decimals, options.diameter, options.retract, None, options.reference)
        try:
            return pecking_calls(group, output, self.feed, self.per_rev)
        except CycleError as exc:
            raise cycle_post_error(self.label, exc, PECKING_PROPERTIES) from None

    def pecking_call(self, call: PeckingCall) -> None:
        """One pecking call: comments, the rapids to its start point and back, the call."""
        program, post = self.program, self.program.post
        first = call.plans[0]
        if len(call.plans) > 1:
            what = "%s grooves %d-%d" % (first.face.name, first.index + 1, call.plans[-1].index + 1)
        else:
            what = "%s groove %d" % (first.face.name, first.index + 1)
        program.note("%s: %s as %s" % (what, call_text(first.cycle), call.model.NAME))
        note = retract_note(post.target, call.retract, not program.options.inches)
        if note:
            program.note(note)
        # the call's start point in one block; when that is the plan's start point, the link's last step
        # (which would reach it) is left to that block
        self.link(first, to_start=call.approach[-1] != call.approach[0])
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
