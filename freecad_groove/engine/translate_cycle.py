"""Cycle blocks of the translator: a registered cycle's call read, checked
against the modal state, expanded and written in place."""

from dataclasses import replace
from typing import List, NamedTuple, Optional, Sequence

from .errors import CycleError, ProgramError
from .input_controls import CYCLE, CYCLE_OPTIONS, MODE_GROUPS
from .mill_tool_table import MillToolTable, diameter_for
from .moves import MachineState, Move
from .numbers import MAX_WORD
from .reader import Block, Word
from .registry import CycleEntry
from .settings import Settings
from .tool_table import ToolTable, blade_for
from .translate_base import Groups, TranslatorBase
from .warnings import cycle_warnings

__all__ = ["CycleCall", "CycleTranslation"]


class CycleCall(NamedTuple):
    """A cycle block as read: the cycle's name, its text for the cycle's parse(),
    and its words (G-word cycles; empty for a ``NAME(...)`` call)."""

    name: str
    text: str
    words: List[Word]


class Region(NamedTuple):
    """A cycle that spans blocks (GSK G7.1 up to G7.1 C0), while it is read: its
    start block, entry and call, the path blocks' texts, the cycle's context."""

    block: Block
    entry: CycleEntry
    call: CycleCall
    texts: List[str]
    context: object


class CycleTranslation(TranslatorBase):
    """Siemens calls and G-word cycles (G77/G76, G75/G74, the G7.1 region), from the cycle registry."""

    _region: Optional[Region] = None  # the region being read (REGION cycles), else None

    def _cycle_block(self, block: Block, groups: Groups) -> None:
        """A block with a cycle call: its mode codes, then the expanded moves."""
        call = self._cycle_call(block, groups)
        early: List[str] = []
        output: List[str] = []
        self._modes(block, groups, output, early)
        self._emit_early(block, early, True)
        if output:
            self._emit(" ".join(output))
            self._sync_writer()
        entry = self.control.cycle(call.name)
        if entry.retract_block:
            if self._is_retract_block(entry, call.words):
                self._retract_block(block, entry, call.words)
                return
            call = self._with_retract_block(entry, call)
        if getattr(entry.cycle_class, "REGION", False):
            self._start_region(block, entry, call)
            return
        self._run_cycle(block, entry, call, " / ".join(call.text.split("\n")))

    def _run_cycle(self, block: Block, entry: CycleEntry, call: CycleCall, label: str) -> None:
        """Parse, check, expand and write a cycle call (``label``: its text for the comment)."""
        try:  # the call itself first: its own errors are the most useful
            model = entry.cycle_class.parse(call.text)
            settings = self._cycle_settings(entry)
            model.validate(settings)
        except CycleError as exc:
            self._fail(exc.message)
        self._check_cycle_start(call.name, getattr(entry.cycle_class, "Z_ONLY", False))
        start = self.state.machine_state()
        memory_key = getattr(entry.cycle_class, "MEMORY", "")
        try:
            if memory_key:
                model = self._with_memory(memory_key, model, start)
            moves = model.expand(start, settings)
            if hasattr(model, "note"):  # what the call did that its words do not say (G32: the Z used)
                label = "%s: %s" % (label, model.note(start, settings))
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

    # -- parameter assignments (Milltronics "P151=1") ------------------------------------

    def _parameter_block(self, block: Block) -> None:
        """``P151=1``: a P parameter of the control's cycles (class PARAMETERS), kept
        in the program's memory (class MEMORY) for the calls that follow."""
        name, text = block.parameters[0]
        if block.words or block.keywords or block.call or len(block.parameters) > 1:
            self._fail("%s=%s: a parameter assignment stands alone in its block" % (name, text))
        cycle = next((e.cycle_class for e in self.control.cycles() if getattr(e.cycle_class, "PARAMETERS", ())), None)
        known = cycle.PARAMETERS if cycle is not None else ()
        key = "P%d" % int(name[1:]) if name[1:].isdigit() else name
        if key not in known:
            self._fail("%s=%s: not a parameter of the %s cycles (%s)" % (name, text, self.control.maker,
                                                                        ", ".join(known) or "none"))
        value = float(text)
        if not abs(value) < MAX_WORD:
            self._fail("%s=%s: must be less than %g in magnitude" % (name, text, MAX_WORD))
        self._not_ambiguous("cycle_memory", why="the parameters %s calls read" % cycle.NAME)
        memory = dict(self.state.cycle_memory.get(cycle.MEMORY, {}), **{key: value})
        self.state.cycle_memory = dict(self.state.cycle_memory, **{cycle.MEMORY: memory})
        self._defined.add("cycle_memory")
        self._emit_line(block, [], "%s=%s: for the %s that follow" % (
            key, text, "/".join(e.name for e in self.control.cycles() if getattr(e.cycle_class, "PARAMETERS", ()))))

    # -- a cycle over several blocks (GSK G7.1 ... G7.1 C0) ------------------------------

    def _start_region(self, block: Block, entry: CycleEntry, call: CycleCall) -> None:
        if block.delete:
            self._fail("%s on a block-delete '/' line: a region is not translated there" % call.name)
        try:
            if entry.cycle_class.region_ends(call.text):
                self._fail("%s cancels a region that was not started" % call.text)
        except CycleError as exc:
            self._fail(exc.message)
        self._region = Region(block, entry, call, [], None)

    def _region_block(self, block: Block) -> None:
        """A block inside a region: a path block, checked now, or the block that ends it."""
        region = self._region
        if block.delete:
            self._fail("a block-delete '/' line inside the %s region is not translated" % region.call.name)
        if block.keywords or block.call:  # (comments on a path block are not written)
            self._fail("%s inside the %s region: only its path blocks may be there"
                       % ((block.keywords or [block.call])[0], region.call.name))
        text = " ".join(word.letter + word.text for word in block.words)
        cycle = region.entry.cycle_class
        try:
            if cycle.region_ends(text):
                self._finish_region(text)
                return
            context = cycle.check_region_block(text, region.context)
        except CycleError as exc:
            self._fail(exc.message)
        region.texts.append(text)
        self._region = region._replace(context=context)

    def _finish_region(self, cancel: str) -> None:
        """The cancel block read: the whole region is one call, its errors on its first line."""
        region, self._region = self._region, None
        line, self._line = self._line, region.block.line
        self._not_ambiguous("c", why=region.call.name)
        text = "\n".join([region.call.text] + region.texts + [cancel])
        label = "%s ... %s, %d path blocks" % (region.call.text, cancel, len(region.texts))
        self._run_cycle(region.block, region.entry, region.call._replace(text=text), label)
        self._line = line
        self.state.motion = None  # the motion after the region is not the one before it
        self._defined.add("motion")

    def check_region_closed(self) -> None:
        """At the end of the program: a region without its cancel block is refused."""
        if self._region is not None:
            region, self._region = self._region, None
            raise ProgramError("the %s region is not closed: it ends with %s C0" % (region.call.text,
                                                                                  region.call.name),
                               region.block.line)

    # -- the separate retract block (Fanuc "G75 R(e)") ---------------------------------

    @staticmethod
    def _is_retract_block(entry: CycleEntry, words: Sequence[Word]) -> bool:
        """True when the block holds none of the cycle's words but the retract block's."""
        cycle_words = {word.name for word in entry.words} - {entry.retract_block}
        return not {word.letter for word in words} & cycle_words

    def _retract_block(self, block: Block, entry: CycleEntry, words: Sequence[Word]) -> None:
        """``G75 R(e)`` alone: it only stores e for the next cycle of its kind."""
        letter = entry.retract_block
        if len(words) != 1 or words[0].letter != letter:
            self._fail("%s: the first block is %s %s(e) (the peck retract) alone" % (entry.name, entry.name, letter))
        self._length(words[0])
        self.state.retract_e = words[0]
        self._defined.add("retract_e")
        kinds = "/".join(other.name for other in self.control.cycles() if other.retract_block)
        note = "%s %s%s: peck retract e for the next %s" % (entry.name, letter, words[0].text, kinds)
        self._emit_line(block, [], note)

    def _with_retract_block(self, entry: CycleEntry, call: CycleCall) -> CycleCall:
        """The call with the retract block read before it, when there was one."""
        retract = self.state.retract_e
        if retract is None:
            return call
        self._not_ambiguous("retract_e", why="%s %s(e)" % (entry.name, entry.retract_block))
        text = "%s %s%s\n%s" % (entry.name, retract.letter, retract.text, call.text)
        return call._replace(text=text)

    def _with_memory(self, key: str, model: object, start: MachineState) -> object:
        """A cycle with a program memory (class MEMORY, G83): the words it omits
        from the previous cycle of its kind; what it leaves for the next one."""
        why = getattr(model, "MEMORY_WHAT", "the words %s takes from the cycle before") % model.NAME
        self._not_ambiguous("cycle_memory", why=why)
        model = model.with_earlier(self.state.cycle_memory.get(key, {}), start)
        self.state.cycle_memory = dict(self.state.cycle_memory, **{key: model.remembered(start)})
        self._defined.add("cycle_memory")
        return model

    def _cycle_settings(self, entry: CycleEntry) -> Settings:
        """The settings the cycle runs with: one that NEEDS_BLADE gets the blade of
        the tool in force (tool_table.blade_for), or is refused; a Milltronics G33/G34
        with a mill tool table the diameter of the D in force (mill_tool_table.diameter_for)."""
        if isinstance(self.tools, MillToolTable) and getattr(entry.cycle_class, "PARAMETERS", ()):
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

    def _collect_warnings(self, entry: CycleEntry, model: object, start: MachineState, settings: Settings) -> None:
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

    def _check_cycle_start(self, name: str, z_only: bool = False) -> None:
        """A cycle needs a known start point, feed mode and (per revolution) spindle; a cycle that is one
        rapid of Z alone (``Z_ONLY``: Milltronics G31/G32) needs only the units its height is in."""
        state = self.state
        if z_only:
            self._not_ambiguous("metric", why=name)
            return
        if state.x is None or state.z is None or (self.control.mill and state.y is None):
            self._fail("%s needs its start point: program an absolute %s before the call"
                       % (name, "X, Y and Z" if self.control.mill else "X and Z"))
        self._not_ambiguous("x", "y", "z", "feed", "feed_per_rev", "metric", "diameter", "diam90", "incremental",
                            why=name)
        if state.feed_per_rev is None:
            self._fail("%s before the feed mode is programmed (%s)" % (name, self.control.feed_mode_codes))
        if state.siemens_g70:
            self._fail("%s in Siemens G70 (feed in the basic system): use G700" % name)
        self._check_spindle_for_feed(name)

    def _after_cycle(self, moves: Sequence[Move]) -> None:
        """The position of the last move, the last feed written; the motion mode
        the one before the cycle or unknown (InputControl.cycle_keeps_motion)."""
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
        if not self.control.cycle_keeps_motion:
            state.motion = None
            self._defined.add("motion")
