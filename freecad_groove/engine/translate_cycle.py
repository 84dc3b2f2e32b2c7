"""Cycle blocks of the translator: a registered cycle's call read, checked
against the modal state, expanded and written in place.

How a call is written over blocks is the cycle's block form (``BLOCKS``,
block_forms.py): the block naming the cycle goes to the form, which runs the
call here (``run_cycle``), keeps the block for a later call, or opens the
blocks that follow (``open_blocks``: the translator hands them to it). A
program memory (program_memory.py) and parameter blocks (parameter_blocks.py)
are declared by the cycle beside its form."""

from dataclasses import replace
from typing import List, Optional, Sequence

from .blade_limits import limits_problem
from .block_forms import CycleCall, OpenBlocks
from .cycle import Cycle
from .dialects import CYCLE, CYCLE_OPTIONS, MODE_GROUPS
from .errors import CycleError, ProgramError
from .mill_tool_table import MillToolTable, diameter_for
from .moves import MachineState, Move
from .parameter_blocks import read_parameter_block
from .program_memory import with_memory
from .reader import Block
from .registry import CycleEntry
from .settings import Settings
from .tool_table import ToolTable, blade_for, reach_problem
from .translate_base import Groups, TranslatorBase
from .warnings import cycle_warnings

__all__ = ["CycleCall", "CycleTranslation"]


class CycleTranslation(TranslatorBase):
    """Siemens calls and G-word cycles (G77/G76, G75/G74, the G7.1 region), from the cycle registry."""

    _open: Optional[OpenBlocks] = None  # the blocks a call is reading (a region), else None

    def _cycle_block(self, block: Block, groups: Groups) -> None:
        """A block with a cycle call: its mode codes, then the call to its block form."""
        call = self._cycle_call(block, groups)
        early: List[str] = []
        output: List[str] = []
        self._modes(block, groups, output, early)
        self._emit_early(block, early, True)
        if output:
            self._emit(" ".join(output))
            self._sync_writer()
        entry = self.dialect.cycle(call.name)
        entry.cycle_class.BLOCKS.read_call(self, block, entry, call)

    def run_cycle(self, block: Block, entry: CycleEntry, call: CycleCall, label: str) -> None:
        """Parse, check, expand and write a cycle call (``label``: its text for the comment)."""
        cycle = entry.cycle_class
        try:  # the call itself first: its own errors are the most useful
            model = cycle.parse(call.text)
            settings = self._cycle_settings(entry)
            model.validate(settings)
        except CycleError as exc:
            self._fail(exc.message)
        self._check_reach(entry, model, settings)
        self._check_cycle_start(call.name, cycle.Z_ONLY, cycle.FROM_UNKNOWN_Z)
        start = self.state.machine_state()
        if cycle.FROM_UNKNOWN_Z and "z" in self.state.ambiguous - self._defined:
            start.z = None  # a Z a block-delete line may have changed is not known: the cycle needs none
        try:
            if cycle.MEMORY:
                model = with_memory(self, model, start)
            moves = model.expand(start, settings)
            self._check_blade_limits(model, start, settings, moves)
            note = model.note(start, settings)  # what the call did that its words do not say (G32: the Z used)
            if note is not None:
                label = "%s: %s" % (label, note)
            elif isinstance(self.tools, MillToolTable) and self.state.tool in self.tools:
                label = "%s: tool diameter %s, D%d of %s" % (label, settings.mill_tool_diameter, self.state.tool,
                                                             self.tools.source)
            self._collect_warnings(entry, model, start, settings)
        except CycleError as exc:
            self._fail(exc.message)
        self._emit_line(block, [], label.replace("(", " ").replace(")", ""))
        try:
            lines, moves = self._cycle_output(model, start, settings, moves)  # translate_native.py
        except ProgramError as exc:
            self._fail("%s: %s" % (call.name, exc))
        self.body.extend(lines)
        self._after_cycle(moves)

    # -- the blocks a call reads after its own (block_forms.OpenBlocks) -------------------

    def open_blocks(self, reading: Optional[OpenBlocks]) -> None:
        """Hand the blocks that follow to ``reading`` (a region's start); None: read them as usual again."""
        self._open = reading

    def _open_block(self, block: Block) -> None:
        """A block while a call reads the blocks after its own."""
        self._open.read(self, block)

    def check_blocks_closed(self) -> None:
        """At the end of the program: blocks a call still reads (a region without its cancel block) are refused."""
        if self._open is not None:
            reading, self._open = self._open, None
            reading.close(self)

    def _parameter_block(self, block: Block) -> None:
        """``P151=1``: see parameter_blocks.py."""
        read_parameter_block(self, block)

    def _cycle_call(self, block: Block, groups: Groups) -> CycleCall:
        """The cycle's name, text and words; refuses what may not share its block."""
        for group, code in groups.items():
            if group not in MODE_GROUPS + CYCLE_OPTIONS and group != CYCLE:
                self._fail("G%s shares the block with the cycle call: only N, a comment and mode codes may"
                           % code.word.text + " share it")
        others = [word for word in block.words if word.letter != "G"]
        if block.call is not None:
            name = block.call.split("(")[0]
            if others:
                self._fail("%s%s shares the block with %s: a cycle call takes only N, a comment and mode codes"
                           % (others[0].letter, others[0].text, name))
            return CycleCall(name, block.call, [])
        name = groups[CYCLE].value
        for word in others:
            if word.letter in ("M", "S", "T", "N"):
                self._fail("%s%s shares the block with %s: program it in its own block"
                           % (word.letter, word.text, name))
        if block.keywords:
            self._fail("%s shares the block with %s" % (block.keywords[0], name))
        written = "G" + groups[CYCLE].word.text  # the spelling read (GSK G07.1, G107)
        for group in CYCLE_OPTIONS:  # Milltronics G99, G41/G42: read by the cycle
            if group in groups:
                written += " G" + groups[group].word.text
        return CycleCall(name, " ".join([written] + ["%s%s" % (word.letter, word.text) for word in others]), others)

    def _cycle_settings(self, entry: CycleEntry) -> Settings:
        """The settings the cycle runs with: one that NEEDS_BLADE gets the blade of
        the tool in force (tool_table.blade_for), or is refused; a Milltronics G33/G34
        with a mill tool table the diameter of the D in force (mill_tool_table.diameter_for)."""
        if isinstance(self.tools, MillToolTable) and entry.cycle_class.PARAMETERS:
            self._not_ambiguous("tool", why="the tool diameter of %s" % entry.name)
            try:
                diameter = diameter_for(self.state.tool, self.tools, self.settings.mill_tool_diameter)
            except ProgramError as exc:
                self._fail("%s: %s" % (entry.name, exc))
            return replace(self.settings, mill_tool_diameter=diameter)
        if not entry.needs_blade:
            return self.settings
        if self.tools is not None:
            self._not_ambiguous("tool", why="the blade of %s" % entry.name)
        try:
            blade = blade_for(self.state.tool, self.tools, self.settings.tool)
        except ProgramError as exc:
            self._fail("%s: %s" % (entry.name, exc))
        return replace(self.settings, tool=blade)

    def _check_reach(self, entry: CycleEntry, model: Cycle, settings: Settings) -> None:
        """A call deeper than the free reach the tool table gives the blade of the tool in force is refused
        (tool_table.reach_problem; the depth the call says: Cycle.blade_depth)."""
        said = model.blade_depth(settings)
        if said is None or not isinstance(self.tools, ToolTable) or self.state.tool not in self.tools:
            return
        problem = reach_problem(said[0], self.state.tool, self.tools, said[1])
        if problem is not None:
            self._fail(problem)

    def _check_blade_limits(self, model: Cycle, start: MachineState, settings: Settings, moves: List[Move]) -> None:
        """A call the holder of the tool in force cannot cut (the tool table's dmin=, dmax=, bore=) is refused
        (blade_limits.limits_problem; where the blade cuts: Cycle.blade_entry)."""
        if not isinstance(self.tools, ToolTable) or self.state.tool not in self.tools.limits:
            return
        problem = limits_problem(model.blade_entry(start, settings, moves), self.tools.limits[self.state.tool],
                                 "T%d's blade (%s)" % (self.state.tool, self.tools.source))
        if problem is not None:
            self._fail(problem)

    def _collect_warnings(self, entry: CycleEntry, model: Cycle, start: MachineState, settings: Settings) -> None:
        """The cycle's warnings, on this line. A cycle that needs no blade still
        gets the tool table's blade of the tool in force where there is one, for
        its warnings (a Fanuc relief is checked against the blade's width)."""
        if not entry.needs_blade and isinstance(self.tools, ToolTable) and "tool" not in self.state.ambiguous:
            try:
                settings = replace(settings, tool=blade_for(self.state.tool, self.tools, settings.tool))
            except ProgramError:
                pass  # no blade: the warnings that need one are not given
        self.warnings.extend((self._line, warning) for warning in cycle_warnings(model, start, settings))

    # -- state before and after ------------------------------------------------------------

    def _check_cycle_start(self, name: str, z_only: bool = False, unknown_z: bool = False) -> None:
        """A cycle needs a known start point, feed mode and (per revolution) spindle; a cycle that is one
        rapid of Z alone (``Z_ONLY``: Milltronics G31/G32) needs only the units its height is in, one that
        runs from an unknown Z (``FROM_UNKNOWN_Z``: G33/G34) only X and Y of its start point."""
        state = self.state
        if z_only:
            self._not_ambiguous("metric", why=name)
            return
        if state.x is None or (state.z is None and not unknown_z) or (self.dialect.mill and state.y is None):
            axes = ("X and Y" if unknown_z else "X, Y and Z") if self.dialect.mill else "X and Z"
            self._fail("%s needs its start point: program an absolute %s before the call" % (name, axes))
        self._not_ambiguous("x", "y", *(() if unknown_z else ("z",)), "feed", "feed_per_rev", "metric", "diameter",
                            "diam90", "incremental", why=name)
        if state.feed_per_rev is None:
            self._fail("%s before the feed mode is programmed (%s)" % (name, self.dialect.feed_mode_codes))
        if state.siemens_g70:
            self._fail("%s in Siemens G70 (feed in the basic system): use G700" % name)
        self._check_spindle_for_feed(name)

    def _after_cycle(self, moves: Sequence[Move]) -> None:
        """The position of the last move, the last feed written; the motion mode
        the one before the cycle or unknown (Dialect.cycle_keeps_motion)."""
        state = self.state
        feeds = [move.f for move in moves if move.f is not None]
        if moves:
            state.z = float(moves[-1].z)
            if moves[-1].x is not None:  # None: a Z-only move, X (and Y) held
                state.x = float(moves[-1].x)
            if moves[-1].c is not None:
                state.c = float(moves[-1].c)
                self._defined.add("c")
            if moves[-1].y is not None:
                state.y = float(moves[-1].y)
                self._defined.add("y")
        if feeds:
            state.feed = float(feeds[-1])
            self._defined.add("feed")
        self._defined |= {"x", "z"}
        if not self.dialect.cycle_keeps_motion:
            state.motion = None
            self._defined.add("motion")
