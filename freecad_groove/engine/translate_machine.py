"""Machine functions of the translator: feed rate, tools, spindle speed and
constant surface speed, M codes, dwell."""

from typing import Callable, Dict, List, NamedTuple, Optional

from .dialects import (
    CSS,
    DIAMETER_REGISTER,
    DWELL_LENGTH_SECONDS,
    DWELL_MILLISECONDS,
    DWELL_POINT_SECONDS,
    DWELL_SECONDS,
    LENGTH_OFFSET,
    M_GROUPS,
    SPEED_LIMIT,
    TOOL_AND_EDGE,
    TOOL_AND_OFFSET,
    TOOL_AND_OFFSET_OR_M6,
)
from .numbers import MAX_DWELL_SECONDS, MAX_WORD, shortened
from .reader import Block, Word
from .translate_base import Groups, TranslatorBase

__all__ = ["MachineTranslation", "ToolSelection"]

_SPINDLE_CODES = (3, 4, 5)
_END_CODES = (2, 30)


class ToolSelection(NamedTuple):
    """A tool call as read: the tool (None: the one in the spindle), its offset,
    and whether the offset is the tool's own tool-table entry."""

    tool: Optional[int]
    offset: int
    own_entry: bool


class MachineTranslation(TranslatorBase):
    """F, T/D, S, G96/G97, G50 S/LIMS=, M codes and G4."""

    # -- feed -----------------------------------------------------------------------

    def _feed_word(self, block: Block) -> Optional[Word]:
        """Read the block's F word into the state; the word, or None."""
        feed_word = block.get("F")
        if feed_word is None:
            return None
        if self.state.siemens_g70:
            self._fail(
                "F%s in G70: Siemens G70 leaves the feed in the metric basic system; use G700 for an inch feed"
                % feed_word.text
            )
        feed = self._length(feed_word)
        if not 0 < feed < MAX_WORD:
            self._fail("F%s: the feed must be greater than 0" % feed_word.text)
        self.state.feed = feed
        self._defined.add("feed")
        return feed_word

    # -- tools ----------------------------------------------------------------------

    def _diameter_register(self, block: Block) -> Optional[str]:
        """Milltronics ``D1``: the register of the end mill's diameter the G33/G34 that follow cut with (the
        tool in force, for mill_tool_table.diameter_for); nothing is written for it but the note returned."""
        word = block.get("D")
        if word is None:
            return None
        self.state.tool = self._integer(word)
        self._defined.add("tool")
        return "D%d: the diameter register of the G33/G34 that follow" % self.state.tool

    def _tool(self, block: Block, output: List[str]) -> None:
        """T (and Siemens D): a tool change, written as T M6 G43 (Fanuc output: T0101)."""
        if self.dialect.tool_words == DIAMETER_REGISTER:
            self._mill_tool_change(block, output)  # D is read by _diameter_register
            return
        tool_word = block.get("T")
        edge_word = block.get("D")
        if tool_word is None and edge_word is None:
            return
        if 6 in self._m_numbers(block) and self.dialect.tool_words == TOOL_AND_OFFSET_OR_M6:
            selection = self._tool_m6(tool_word)
        elif 6 in self._m_numbers(block):
            self._fail("M6 is added by the translation; program the tool with T alone")
        else:
            readers: Dict[str, Callable[[Optional[Word], Optional[Word]], ToolSelection]] = {
                TOOL_AND_EDGE: self._tool_and_edge,
                TOOL_AND_OFFSET: self._tool_and_offset,
                TOOL_AND_OFFSET_OR_M6: self._tool_and_offset,
            }
            selection = readers[self.dialect.tool_words](tool_word, edge_word)
        state = self.state
        in_place = state.tool
        state.x = state.y = state.z = None
        self._defined |= {"x", "y", "z", "tool"}
        if selection.tool is not None:
            state.tool = selection.tool
        output.extend(self.writer.tool_change(selection.tool, selection.offset, selection.own_entry, in_place))
        self._tool_changed = selection.tool is not None

    def _mill_tool_change(self, block: Block, output: List[str]) -> None:
        """Milltronics ``T5 M6``: the change, written ``T5 M6`` (Fanuc ``T05 M06``); afterwards the position
        and the spindle (M6 stops it) are unknown. T without M6 and M6 without T are refused."""
        tool_word = block.get("T")
        m6 = 6 in self._m_numbers(block)
        if tool_word is None and not m6:
            return
        if tool_word is None:
            self._fail("M6 without T: program the tool change as T<n> M6 in one block")
        if not m6:
            self._fail("T%s without M6: a tool selected for a later change is not translated; program the tool "
                       "change as T%s M6 in one block" % (tool_word.text, tool_word.text))
        tool = self._integer(tool_word)
        if tool < 1:
            self._fail("T%s: the tool number must be 1 or more" % tool_word.text)
        output.extend(self.writer.tool_change(tool))
        state = self.state
        state.x = state.y = state.z = None
        state.spindle_dir = None
        self._defined |= {"x", "y", "z", "spindle_dir"}

    def _length_offset(self, block: Block, groups: Groups, output: List[str]) -> None:
        """Milltronics ``G43 H1`` written as it is (both targets), ``G49`` too; H without G43 is refused."""
        height_word = block.get("H")
        on = groups[LENGTH_OFFSET].value if LENGTH_OFFSET in groups else None
        if height_word is not None and on is not True:
            self._fail("H%s without G43: program the tool length offset as G43 H<n>" % height_word.text)
        if on is None:
            return
        if not on:
            output.extend(self.writer.length_offset(None))
            return
        if height_word is None:
            self._fail("G43 without H: program the tool length offset as G43 H<n>")
        output.extend(self.writer.length_offset(self._integer(height_word)))
        self.state.z = None  # the offset moves the Z the program's words mean
        self._defined.add("z")

    def _tool_and_edge(self, tool_word: Optional[Word], edge_word: Optional[Word]) -> ToolSelection:
        """Siemens ``T5 D1``; ``T5`` alone selects D1; D0 cancels the offset."""
        tool = offset = None
        if tool_word is not None:
            tool = self._integer(tool_word)
            offset = 1
        if edge_word is not None:
            offset = self._integer(edge_word)
            if offset > 1:
                self._fail("D%s: a second cutting edge has no LinuxCNC tool-table entry; only D0 and D1 are "
                           "translated outside CYCLE93" % edge_word.text)
        return ToolSelection(tool, offset, True)

    def _tool_and_offset(self, tool_word: Optional[Word], edge_word: Optional[Word]) -> ToolSelection:
        """Fanuc, Haas, Allen-Bradley ``T0512``: tool 5, offset 12."""
        digits = tool_word.text.lstrip("+")
        if "." in tool_word.text or not digits.isdigit() or len(digits) < 3:
            self._fail("T%s: write the tool and offset as T<tool><2-digit offset>, e.g. T0101" % tool_word.text)
        tool, offset = int(digits[:-2]), int(digits[-2:])
        return ToolSelection(tool, offset, offset == tool)

    def _tool_m6(self, tool_word: Optional[Word]) -> ToolSelection:
        """The 9/Series grinder's mill form ``T03 M06`` (what its posts write): tool 3 with its own offset, as
        ``T0303``; the wheel keeps its direction, as after its T word (docs/choices.md)."""
        if tool_word is None:
            self._fail("M6 without T: program the tool change as T<n> M6 in one block")
        digits = tool_word.text.lstrip("+")
        if "." in tool_word.text or not digits.isdigit() or int(digits) < 1:
            self._fail("T%s M6: the tool number must be a whole number of 1 or more" % tool_word.text)
        tool = int(digits)
        return ToolSelection(tool, tool, True)

    def _restart_spindle(self, block: Block, output: List[str]) -> None:
        """LinuxCNC's M6 stops the spindle; a lathe turret (and the 9/Series grinder's T) does not: start it
        again. Not after a Milltronics T M6: the program starts it itself (_mill_tool_change)."""
        state = self.state
        changed, self._tool_changed = self._tool_changed, False
        if not (changed and self.writer.target.tool_change_stops_spindle) or state.spindle_dir not in (3, 4):
            return
        if set(_SPINDLE_CODES) & self._m_numbers(block):
            return  # the block starts or stops it itself
        self._not_ambiguous("spindle_dir", why="restarting the spindle after the tool change")
        output.append(self.writer.m_code(state.spindle_dir))

    # -- spindle ----------------------------------------------------------------------

    def _spindle(self, block: Block, groups: Groups, output: List[str], early: List[str]) -> None:
        """S, G96/G97 and the speed limit (G50 S, LIMS=)."""
        speed_word = block.get("S")
        limit_word = block.get("LIMS")
        speed = None
        if speed_word is not None:
            speed = speed_word.value
            if not 0 <= speed < MAX_WORD:
                self._fail("S%s is out of range" % speed_word.text)
        if SPEED_LIMIT in groups:  # Fanuc/Haas G50 S: spindle speed limit
            self._g50_limit(block, speed, output, early)
            return
        if limit_word is not None:
            if not 0 < limit_word.value < MAX_WORD:
                self._fail("LIMS=%s is out of range" % limit_word.text)
            self.state.speed_limit = limit_word.value
            self._defined.add("speed_limit")
        if CSS in groups:
            self._css(groups[CSS].value, speed_word, output, early, limit_word is not None)
            return
        if speed_word is not None:
            self.state.spindle = speed
            self._defined.add("spindle")
        if limit_word is not None and self._limit(output, early, "LIMS="):
            return
        if speed_word is not None:
            output.append(self.writer.speed_word(speed))

    def _limit(self, output: List[str], early: List[str], what: str) -> bool:
        """Write the speed limit in force, the target's way; True when that wrote
        the spindle speed too (LinuxCNC: its G96 again, with the limit as D)."""
        state = self.state
        said = self.writer.limit_words(state.speed_limit)
        if said is not None:
            early.extend(said[0])
            output.extend(said[1])
            return False
        if not state.css:
            return False
        if state.spindle is None:
            self._fail("%s: the surface speed in force is not known" % what)
        output.extend(self._css_words(state.spindle, True, early))
        return True

    def _g50_limit(self, block: Block, speed: Optional[float], output: List[str], early: List[str]) -> None:
        if speed is None or block.letters() - {"G", "S"} or len(block.all("G")) > 1:
            self._fail("G50 is supported only as the spindle speed limit, G50 S.. alone in its block")
        self.state.speed_limit = speed
        self._defined.add("speed_limit")
        if not self._limit(output, early, "G50 S") and not (output or early):
            output.append(self.writer.comment("G50 S%s: spindle limit for G96" % self.writer.speed_text(speed)))

    def _css(self, on: bool, speed_word: Optional[Word], output: List[str], early: List[str],
             limit_changed: bool) -> None:
        """G96 (constant surface speed, S in the block) or G97."""
        state = self.state
        if on and speed_word is None:
            self._fail("G96 needs the surface speed S in the same block")
        if not on and state.css and speed_word is None:
            self._fail("G97 after G96 needs the spindle speed S in the same block")
        state.css = on
        self._defined.add("css")
        if speed_word is not None:
            state.spindle = speed_word.value
            self._defined.add("spindle")
        if on:
            output.extend(self._css_words(speed_word.value, limit_changed, early))
            return
        output.extend(self.writer.rpm_words(None if speed_word is None else speed_word.value))

    def _css_words(self, surface_speed: float, limit_changed: bool, early: List[str]) -> List[str]:
        """G96 with the surface speed and the limit in force, where the target writes it with G96 (or it changed)."""
        alone, words = self.writer.surface_speed(surface_speed, self.state.speed_limit, limit_changed)
        early.extend(alone)
        return words

    # -- M codes ------------------------------------------------------------------------

    def _m_codes(self, block: Block, output: List[str]) -> List[int]:
        """Write the spindle and coolant M codes; return the stops and ends, written after the motion."""
        after = []
        modal = []
        in_group: Dict[str, int] = {}
        for word in block.all("M"):
            code = self._integer(word)
            if code == 6 and self.dialect.tool_words in (DIAMETER_REGISTER, TOOL_AND_OFFSET_OR_M6):
                if self.dialect.tool_words == TOOL_AND_OFFSET_OR_M6 and block.get("T") is None:
                    self._fail("M6 without T: program the tool change as T<n> M6 in one block")
                continue  # written by the tool change
            group = M_GROUPS.get(code)
            if group is None:
                text = word.text if len(word.text) <= 20 else shortened(word.text)
                self._fail("M%s is not supported (machine-specific M codes are not translated)" % text)
            if group in in_group and not (group == "coolant" and {code, in_group[group]} == {7, 8}):
                self._fail("M%d and M%d are in the same modal group" % (in_group[group], code))
            in_group[group] = code
            (after if group in ("stop", "end") else modal).append(code)
        for code in modal:
            output.append(self.writer.m_code(code))
            if code in _SPINDLE_CODES:
                self.state.spindle_dir = code
                self._defined.add("spindle_dir")
        return after

    def _stops_and_ends(self, codes: List[int], output: List[str]) -> None:
        """M0/M1 as they are; M2/M30 as the target's program end."""
        state = self.state
        for code in codes:
            if code not in _END_CODES:
                output.append(self.writer.m_code(code))
                continue
            output.append(self.writer.target.end_code)
            state.ended = True
            state.spindle_dir = None
            state.x = state.y = state.z = None

    # -- dwell ----------------------------------------------------------------------------

    def _dwell_block(self, block: Block) -> None:
        """G4 with its time word, read as the dialect reads it."""
        dialect = self.dialect
        others = [word for word in block.words if word.letter != "G"]
        if len(block.all("G")) > 1 or block.keywords:
            self._fail("G4 must be alone in its block (with its time word)")
        if dialect.dwell_unsupported:
            self._fail(dialect.dwell_unsupported)
        if len(others) != 1:
            self._fail("G4 needs exactly one time word")
        word = others[0]
        if word.letter in dialect.dwell_refusals:
            self._fail(dialect.dwell_refusals[word.letter])
        reading = dialect.dwell_words.get(word.letter)
        if reading is None:
            self._fail("G4 %s%s: not a dwell word of this control" % (word.letter, word.text))
        seconds = self._dwell_seconds(reading, word)
        if not 0 <= seconds <= MAX_DWELL_SECONDS:
            self._fail("G4 %s%s: the dwell must be 0 to %g s" % (word.letter, word.text, MAX_DWELL_SECONDS))
        self._emit_line(block, [self.writer.dwell(seconds)])

    def _dwell_seconds(self, reading: str, word: Word) -> float:
        readers = {
            DWELL_SECONDS: lambda: word.value,
            DWELL_LENGTH_SECONDS: lambda: self._length(word),
            DWELL_MILLISECONDS: lambda: self._milliseconds(word),
            DWELL_POINT_SECONDS: lambda: word.value if "." in word.text else self._milliseconds(word),
        }
        return readers[reading]()

    def _milliseconds(self, word: Word) -> float:
        """A whole number of milliseconds, in seconds (from the float value: a
        huge count is out of range, not an overflow)."""
        self._integer(word)
        return word.value / 1000.0
