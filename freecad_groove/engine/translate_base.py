"""What every block handler of the translator shares: the state it keeps, the
word checks, the output helpers, and the mode G codes (units, feed mode,
G90/G91, diameter mode) that plain and cycle blocks both apply.

The handlers themselves are mixins on :class:`TranslatorBase`: motion
(translate_motion.py), machine functions (translate_machine.py), cycles
(translate_cycle.py); translator.py puts them together.
"""

from typing import Dict, List, NamedTuple, NoReturn, Optional, Set, Tuple, Union

from .dialects import CYCLE, DIAMETER, DISTANCE, FEED_MODE, UNITS, Dialect, Units
from .errors import ProgramError
from .mill_tool_table import MillToolTable
from .modal import ModalState
from .numbers import MAX_WORD, MM_PER_INCH
from .output.writer import Writer
from .reader import Block, Word
from .settings import Settings
from .tool_table import ToolTable
from .warnings import CycleWarning

Tools = Union[ToolTable, MillToolTable]  # the blades by T (lathes), the end mill diameters by D (Milltronics)

__all__ = ["ActiveCode", "TranslatorBase"]


class ActiveCode(NamedTuple):
    """A G code of the block being read: its table value and the word as written."""

    value: object
    word: Word


Groups = Dict[str, ActiveCode]  # modal group -> the block's G code in it


class TranslatorBase:
    """The translator's state and shared helpers (see the module notes)."""

    dialect: Dialect  # what the program's codes mean (--dialect)
    settings: Settings
    tools: Optional[Tools]  # the blade of each tool number, or None
    state: ModalState
    writer: Writer
    body: List[str]  # the translated blocks
    warnings: List[Tuple[int, CycleWarning]]  # (line, warning) of the cycles read so far
    _line: int  # the line being read
    _prefix: str  # "/" when the line is a block-delete line
    _defined: Set[str]  # the ModalState items the line sets for sure
    _tool_changed: bool = False  # the line changed the tool (the spindle may need starting again)

    # -- errors and checks ------------------------------------------------------

    def _fail(self, message: str) -> NoReturn:
        raise ProgramError(message, self._line)

    def _length(self, word: Word) -> float:
        """The value of a length/feed word, refusing Fanuc-style integers."""
        if self.dialect.decimal_point and "." not in word.text and word.value != 0:
            self._fail(
                "%s%s needs a decimal point: without one the control reads it in least input increments "
                "or per its zero-suppression parameter; write %s%s." % (word.letter, word.text, word.letter, word.text)
            )
        return word.value

    def _integer(self, word: Word) -> int:
        if "." in word.text or word.value < 0:
            self._fail("%s%s must be a whole number" % (word.letter, word.text))
        return int(word.text.lstrip("+"))

    @staticmethod
    def _m_numbers(block: Block) -> Set[int]:
        """The numbers of the block's M words that are whole numbers (as written: a
        huge one is not a float's infinity); the others are refused where M codes are read."""
        texts = (word.text.lstrip("+") for word in block.all("M"))
        return {int(text) for text in texts if text.isdigit()}

    def _check_finite(self, value: float, word: Word) -> None:
        if not abs(value) < MAX_WORD:
            self._fail("%s%s is out of range" % (word.letter, word.text))

    def _not_ambiguous(self, *names: str, why: str) -> None:
        ambiguous = (self.state.ambiguous - self._defined).intersection(names)
        if ambiguous:
            self._fail(
                "%s depends on a block-delete '/' line: %s is not known for sure; program it again in a "
                "block without '/'" % (why, ", ".join(sorted(ambiguous)))
            )

    def _check_spindle_for_feed(self, what: str) -> None:
        """Feed per revolution needs a spindle speed and a running spindle (else LinuxCNC
        refuses the move or waits for ever)."""
        state = self.state
        if not state.feed_per_rev:
            return
        self._not_ambiguous("spindle", "spindle_dir", why="%s in feed per revolution" % what)
        if not state.spindle:
            self._fail("%s in feed per revolution with no spindle speed (S) programmed" % what)
        if state.spindle_dir not in (3, 4):
            self._fail("%s in feed per revolution with the spindle %s (M3/M4)"
                       % (what, "stopped" if state.spindle_dir == 5 else "not started"))

    # -- output -------------------------------------------------------------------

    def _emit(self, text: str) -> None:
        self.body.append(self.writer.line([text], prefix=self._prefix))

    def _emit_early(self, block: Block, early: List[str], more: object) -> None:
        """Blocks that must stand alone before the block (Fanuc G20/G21, G50 S): the
        block's N goes on the first of them when nothing else of the block is written."""
        for index, text in enumerate(early):
            number = block.number if index == 0 and not more else None
            self.body.append(self.writer.line([text], number, prefix=self._prefix))

    def _emit_line(self, block: Block, words: List[str], note: Optional[str] = None) -> None:
        """``N.. words (note ; comments)``, the comment cut to keep the block within MAX_LINE."""
        notes = ([note] if note else []) + [text.strip() for text in block.comments]
        self.body.append(self.writer.line(words, block.number, notes, self._prefix))

    def _sync_writer(self) -> None:
        """Tell the writer what the output program has in force (the reader's state)."""
        state = self.state
        ambiguous = state.ambiguous
        self.writer.sync(
            None if "x" in ambiguous else state.x,
            None if "z" in ambiguous else state.z,
            None if "feed" in ambiguous else state.feed,
            self.writer.motion,
            y=None if "y" in ambiguous else state.y,
            c=None if "c" in ambiguous else state.c,
        )

    # -- mode G codes -------------------------------------------------------------

    def _modes(self, block: Block, groups: Groups, output: List[str], early: List[str]) -> None:
        """Apply units, feed mode, distance and diameter codes; add output words."""
        if UNITS in groups:
            self._units(groups[UNITS].value, output, early)
        if FEED_MODE in groups:
            # a plain block's F is written by the block; a cycle block's F is the cycle's
            own_feed = block.get("F") is not None and block.call is None and CYCLE not in groups
            self._feed_mode(groups[FEED_MODE].value, output, own_feed)
        if DISTANCE in groups:
            self.state.incremental = groups[DISTANCE].value
            self._defined.add("incremental")
        if DIAMETER in groups:
            g07 = groups[DIAMETER].value == "G07"
            self.state.diameter = g07 if self.settings.ab_g07_is_diameter else not g07
            self._defined.add("diameter")
        for keyword in block.keywords:
            self.state.diameter = keyword != "DIAMOF"
            self.state.diam90 = keyword == "DIAM90"
            self._defined |= {"diameter", "diam90"}

    def _units(self, units: Units, output: List[str], early: List[str]) -> None:
        state = self.state
        if units.metric != state.metric:
            factor = MM_PER_INCH if units.metric else 1.0 / MM_PER_INCH
            if state.x is not None:
                state.x *= factor
            if state.z is not None:
                state.z *= factor
            if state.y is not None:
                state.y *= factor
            state.feed = None
            state.metric = units.metric
        self._defined |= {"metric", "siemens_g70"}
        state.siemens_g70 = units.feed_in_basic_system
        self.writer.set_units(units.metric)
        (early if self.writer.target.units_alone else output).append(self.writer.units_code(units.metric))

    def _feed_mode(self, per_rev: bool, output: List[str], own_feed: bool) -> None:
        """G94/G95 (G98/G99). A change forgets the feed, as the source controls do.
        The code repeated keeps it in the source, but LinuxCNC sets F to 0 on every
        feed-mode code: the block writes the feed in force again, unless it writes
        its own F (``own_feed``) or the feed depends on a block-delete line."""
        state = self.state
        if per_rev != state.feed_per_rev:
            state.feed = None
        state.feed_per_rev = per_rev
        self._defined.add("feed_per_rev")
        output.append(self.writer.set_feed_mode(per_rev))
        if own_feed or state.feed is None or "feed" in state.ambiguous - self._defined:
            return
        output.append(self.writer.feed_word(state.feed))
