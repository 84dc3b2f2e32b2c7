"""A Cylinder slot op (cylinder_slot_op.py) in a program: its X/Z/C moves, or
on a control with ``native_slot`` (GSK) its G7.1 region: with
``--native-cycles`` the Type II region as the op built it (engine/cycles/
gsk_g7_1.py ``GskG7_1.emit``); expanded, every pass written out: G1 X in, the
path as a Type I region (cylindrical interpolation at that X), G0 X out, G0 Z
C back. GSK programs feed C only inside a G7.1 region (the GSK reader's rule:
the manual documents no G1 with C outside it), so its expanded form keeps
the path in Type I regions; the moves are the same.

Both start the same way: G0 X to the op's safe radius, G0 Z C to the path's
start, G0 X to the cycle start (the cylinder + Retract), feed per minute
(the region's F is mm/min along the developed path; G98 on GSK). The region
ends where it started (at the cycle start); both end with G0 X back to the
safe radius. A post whose target has no C axis (``LathePost.c_feed`` None) refuses the
op with a PostError naming the posts that write C. The native region's words
are mm: with --inches the op is written expanded. Around it, the main spindle
stop, C axis mode and the live tool (live_tool.py: machine codes given as
post options, else a comment marking each missing switch).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from ...engine.cycles.gsk_g7_1 import GskG7_1
from ...engine.moves import FEED, RAPID, Move
from ...ops.slot.cutting import slot_cutting
from . import live_tool
from .lathe_posts import LATHE_POSTS
from .objects import label_of
from .post_error import PostError

if TYPE_CHECKING:
    from .program import Program


def is_slot_op(obj: Any) -> bool:
    """Whether ``obj`` is a Cylinder slot op (its proxy plans a G7.1 region)."""
    proxy = getattr(obj, "Proxy", None)
    return proxy is not None and hasattr(proxy, "current_plan") and hasattr(obj, "Region") and hasattr(obj, "Passes")


class SlotOutput:
    """Writes one Cylinder slot op into a Program."""

    def __init__(self, program: Program, op: Any) -> None:
        self.program = program
        self.op = op
        self.label = label_of(op)

    def write(self) -> None:
        program, post = self.program, self.program.post
        if post.c_feed is None:
            with_c = ", ".join(p.freecad_name for p in LATHE_POSTS.values() if p.c_feed)
            raise PostError("is a Cylinder slot: its moves turn the C axis, which the %s post does not write "
                            "(posts with C: %s)" % (post.freecad_name, with_c), op=self.label)
        error = getattr(self.op.Proxy, "error", None)
        if error:
            raise PostError(error, op=self.label)
        plan = self.op.Proxy.current_plan(self.op)
        live_tool.switch_on(program, slot_cutting(self.op), self.label)  # the tool controller's as it is now
        program.set_feed_mode(False)
        start = plan.start
        self._moves([Move(RAPID, plan.safe_radius, None),  # X first: Z and C move only at the safe radius
                     Move(RAPID, plan.safe_radius, start.z, c=start.c), Move(RAPID, start.x, start.z, c=start.c)])
        if post.native_slot and program.options.inches:
            raise PostError("--inches: the G7.1 region of a Cylinder slot is written in mm (write it in mm)",
                            op=self.label)
        if post.native_slot and program.options.native:
            self._region(plan.region, (start.x, start.z, start.c))
        elif post.native_slot:
            self._type_i_passes(plan)
        else:
            self._moves(plan.moves)
        self._moves([Move(RAPID, plan.safe_radius, start.z)])
        live_tool.switch_off(program, self.label)

    def _region(self, region: GskG7_1, end: tuple) -> None:
        """The region's blocks; the output then knows it stands at ``end`` (x, z, c) with no motion in force."""
        writer = self.program.writer
        self.program.add(region.emit().split("\n"))
        writer.forget(position=True, motion=True, feed=True)  # the control ran the region
        writer.write([Move(RAPID, end[0], end[1], c=end[2])])  # the written texts of where it ends, not a line
        writer.motion = None  # the region left G1 in force: the next rapid writes its G0
        self.program.moved(end[0], end[1])

    def _type_i_passes(self, plan: object) -> None:
        """Each pass of the Type II region written out, its path a Type I region."""
        region, start = plan.region, plan.start
        path = GskG7_1(C=region.C, path=region.path, code=region.code)
        end = plan.moves[-3]  # the last pass's last path move (then E and G rapids)
        infeed = start.feed
        for radius in region.pass_radii(start):
            self._moves([Move(FEED, radius, start.z, infeed)])
            self._region(path, (radius, end.z, end.c))
            self._moves([Move(RAPID, region.clearance_radius(), end.z, c=end.c),
                         Move(RAPID, region.clearance_radius(), start.z, c=start.c)])
            infeed = next((b.f for b in reversed(region.path) if b.f is not None), infeed)

    def _moves(self, moves: list) -> None:
        self.program.add(self.program.writer.write(moves))
        self.program.moved(moves[-1].x, moves[-1].z)
