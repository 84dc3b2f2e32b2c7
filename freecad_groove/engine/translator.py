"""Read lathe programs (Siemens, Allen-Bradley 9/Series, Fanuc, Haas), track their
modal state, and translate them with every grooving cycle expanded.

    translate_program(text, dialect, settings, target="linuxcnc", source_name="PROGRAM", start=None,
                      tools=None, warnings=None, native_cycles=False) -> str
    iter_translation(text or lines, dialect, ...) -> Iterator[str]   # the same text, chunk by chunk

``dialect`` is the input: "sinumerik" (CYCLE93), "ab9" (G77/G76), "ab9grind"
(the 9/Series grinder's G83/G83.1; mill-style: X/Y/Z), "fanuc" (two-block
G75/G74), "haas" (one-block G75/G74), "gsk" (the G7.1 region up to G7.1 C0,
read block by block, expanded at its cancel block; G75/G74). ``target`` is
"linuxcnc", "fanuc", or with a C axis "linuxcnc-c", "fanuc-c" (see
targets.py); a mill-style program is written on its mill twin. Anything the
reader cannot translate faithfully
raises errors.ProgramError with the 1-based line number in ``.line``; a cycle's
CycleError becomes a ProgramError on the cycle's line with the cycle's message.
What a cycle cannot do as programmed, but runs anyway, is a warning
(warnings.CycleWarning, from the cycle's ``warnings()``): collected with its
line in ``Translator.warnings``; it never changes the output.

How the output is made
----------------------
Lines are not copied: each block is read into words and written again by the
target's writer. The output is always absolute (G90) with X words as diameters
(G7), so incremental words (G91, Fanuc/Haas U and W), radius programming
(Siemens DIAMOF, the Allen-Bradley radius G code) and Siemens DIAM90 are
resolved by the reader and never reach the output: an incremental move needs
a known position (else ProgramError). N numbers, comments and the block delete
``/`` are kept. A cycle block becomes a comment naming the call, then the
expanded moves (no N numbers; each prefixed with ``/`` when the call was);
with ``native_cycles`` the target's own call where engine/native decides it
cuts the same (translate_native.py), else a comment with the reason and the
moves.

Choices where the manuals are silent (each has a test)
------------------------------------------------------
* Diameter programming at the start for every dialect (the Siemens manual's
  example: ``G00 X80 Z65`` before CYCLE93 with AXFA 35 as a radius); metric at the start;
  the feed mode at the start is *unknown*: a feed move or a cycle before the
  program sets G94/G95 (G98/G99) is refused, because reading mm/rev as mm/min
  or the reverse is a crash or a scrapped part. ``start`` (a MachineState) may
  set other starting modes, including the feed mode.
* The position at the start is unknown; so is it after a tool change (T, D),
  a work offset (G54..G59) or a program end. An incremental move, or a cycle,
  needs a known position: program an absolute X and Z first.
* The motion mode (G0/G1/G2/G3) at the start is unknown: an axis word before
  any motion code is refused. After a Siemens or Allen-Bradley cycle it is
  unknown again (the manuals do not say what the cycle leaves modal); after a
  Fanuc/Haas G75/G74 (group 00, non-modal) it is the one before the cycle.
* After a cycle the position is its last move's and the feed the last F it
  wrote (unchanged when it wrote none).
* A units change converts the known position and forgets the feed. A change
  of the feed mode forgets it too (the source controls do, and so does
  LinuxCNC). The feed-mode code repeated while it is active keeps the feed in
  the source controls, but LinuxCNC sets F to 0 on every G93/G94/G95: such a
  block is written with the feed again (``G95`` -> ``G95 F0.2``; Fanuc output
  ``G99 F0.2``, where F is kept anyway and writing it is harmless).
* Fanuc, Haas, Allen-Bradley: a non-zero length or feed word without a decimal
  point (``X80``) is refused: those controls read it in least input increments
  or per a zero-suppression parameter (X80 may be 0.080 mm). Write ``X80.``.
  Siemens reads ``X80`` as 80. (The cycle parsers apply the same rule.)
* Siemens G70 (inch lengths, feed still in the metric basic system) is read as
  inch for lengths and forgets the feed; an F word in G70 is refused (use
  G700, which LinuxCNC's G20 matches). The basic system is taken as metric.
* Arc centres I, K are incremental radius values in every dialect; Fanuc/Haas/AB
  R and Siemens CR= give the radius (negative = over 180 degrees is refused).
  An arc needs a known start point; one whose end is off its circle by more
  than ARC_IJK_TOLERANCE (I/K) or out of reach by ARC_R_TOLERANCE (R), computed
  on the numbers as written, is refused: tighter than LinuxCNC's own limits, so
  the output is never rejected there.
* Tools: Siemens ``T5 D1`` (and ``T5`` alone: D1 is active after a tool
  change) -> ``T5 M6 G43``; ``D0`` -> ``G49``; D2.. (a second edge) is refused
  outside CYCLE93. Fanuc/Haas/AB ``T0512`` -> tool 5, offset 12 ->
  ``T5 M6 G43 H12`` (``G43`` when the offset is the tool number, ``G49`` for
  offset 00); T with fewer than three digits is refused. Fanuc output writes
  ``T0512``. Milltronics ``T5 M6`` (one block) -> ``T5 M6`` (Fanuc ``T05 M06``),
  ``G43 H5`` and ``G49`` as they are, ``D5`` the diameter register of G33/G34.
* The blade of a cycle that needs one (NEEDS_BLADE: CYCLE93): the tool
  table's entry (``tools``) for the tool in force (the last T: 5 for Siemens
  ``T5 D1`` and Fanuc-style ``T0512``); else ``settings.tool`` (the blade of
  every tool the table does not list, of cycles before any T, and of every
  tool without a table); else the cycle is refused. With a table, a T from a
  block-delete '/' line is ambiguous and refused there. The blade's lengths
  are in the program's units when the cycle runs.
* LinuxCNC's M6 stops the spindle (a lathe turret's T does not): when the
  spindle was running, the translated tool change starts it again (M3/M4).
* A feed move or cycle in feed per revolution needs a spindle speed (S) and a
  running spindle (M3/M4) programmed before it: LinuxCNC refuses the first and
  waits for ever on the second.
* Blocks are kept within MAX_LINE characters (LinuxCNC: 252) by cutting comments;
  Fanuc output refuses N numbers above 99999.
* M codes carried: M0 M1 (stops), M3 M4 M5 (spindle), M7 M8 M9 (coolant);
  M2/M30 end the program and are written as the target's end (LinuxCNC M2,
  Fanuc M30). Anything after the end except comments and ``%`` is refused;
  comments after it are dropped. A program without an end gets one.
  Other M codes (machine specific) are refused.
* Constant surface speed: G96 needs S in its block; G97 after G96 needs S.
  The speed limit (Fanuc/Haas ``G50 S``, Siemens ``LIMS=``) becomes LinuxCNC's
  ``G96 ... D<limit>`` (Fanuc output: ``G50 S``).
* Dwell: Siemens ``G4 F<s>``; Fanuc ``G04 X<s>``/``U<s>``/``P<ms>``; Haas ``G04 P``
  (seconds with a decimal point, milliseconds without). The 9/Series dwell
  word is not documented in the manual's grooving chapter: G04 is refused for "ab9".
* Block delete: a ``/`` block whose effect changes a mode or the position makes
  that item *ambiguous* (it depends on the operator's switch). Using an
  ambiguous item (incremental move, X word under an ambiguous diameter mode,
  feed move without F, a cycle) is refused until a plain block sets it again.
* ``;`` starts a comment in every dialect (Siemens comment; end of block
  elsewhere). ``(...)`` is a comment in every dialect. ``%`` lines are skipped;
  an ``O`` number (Fanuc, Haas, AB) before the first block names the program;
  a second one (subprograms) is refused.
* A cycle block may also hold its N number, a comment and mode G codes (units,
  feed mode, G90/G91, diameter mode), which take effect before the cycle;
  anything else in the block is refused.

Where the parts are
-------------------
reader.py reads lines into words; dialects.py says what each dialect's
codes mean (a Dialect per --dialect); modal.py holds the
ModalState; this module reads a program block by block, with the handlers of
translate_motion.py (G0..G3, axis words, arcs), translate_machine.py (F,
tools, spindle, M codes, dwell) and translate_cycle.py (the registered cycles)
on translate_base.py's helpers.
"""

import re
from typing import Iterable, Iterator, List, Optional, Tuple, Union

from .dialects import (
    COMPENSATION,
    CYCLE,
    CYCLE_OPTIONS,
    DIAMETER_REGISTER,
    DWELL,
    OFFSET,
    PLANE,
    REFUSED,
    dialect_named,
    g_code_key,
)
from .errors import CycleError, ProgramError
from .modal import TRACKED, ModalState
from .moves import MachineState
from .native import NativeOutput
from .output.targets import program_target, with_g07_meaning
from .output.writer import MAX_LINE, Writer
from .reader import Block, parse_block
from .settings import DEFAULT_SETTINGS, Settings
from .translate_base import ActiveCode, Groups, Tools
from .translate_cycle import CycleTranslation
from .translate_machine import MachineTranslation
from .translate_motion import MotionTranslation
from .translate_native import NativeCycleTranslation
from .warnings import CycleWarning

__all__ = ["Translator", "iter_translation", "program_lines", "translate_program"]


class Translator(MotionTranslation, MachineTranslation, CycleTranslation, NativeCycleTranslation):
    """Reads a program block by block and writes the translation.

    ``line(text, number)`` reads one line; ``state`` is the ModalState after it;
    ``result()`` is the translated program text; ``translate(lines)`` reads
    every line and yields the text as it is made; ``warnings`` the (line,
    CycleWarning) of the cycles read so far, in line order. ``native_cycles``:
    each cycle call written as the target's own cycle where it cuts the same
    (engine/native), else expanded after a comment saying why.
    """

    def __init__(self, dialect: str, settings: Settings = DEFAULT_SETTINGS, target: str = "linuxcnc",
                 source_name: str = "PROGRAM", start: Optional[MachineState] = None,
                 tools: Optional[Tools] = None, native_cycles: bool = False) -> None:
        self.dialect = dialect_named(dialect)  # raises on an unknown dialect
        # a mill-style program (X/Y/Z) on a mill target or a lathe target's mill twin; raises when there is none
        output_target = with_g07_meaning(program_target(target, self.dialect.mill), settings.ab_g07_is_diameter)
        self.settings = settings
        self.tools = tools
        self.target = output_target.name
        self.source_name = source_name
        self.codes = self.dialect.code_table()
        state = ModalState()
        if start is not None:
            state.diameter = bool(start.diameter_mode)
            state.incremental = bool(start.incremental)
            state.metric = bool(start.metric)
            state.feed_per_rev = start.feed_per_rev
        if self.dialect.mill:
            state.diameter = False  # X is a plain coordinate
        if self.dialect.feed_per_minute and state.feed_per_rev is None:
            state.feed_per_rev = False  # a mill feeds per minute (Milltronics: no G94 in its programs)
        self.state = state
        self.start_metric = state.metric
        self.start_feed_per_rev = state.feed_per_rev
        self.writer = Writer(output_target, state.metric, state.feed_per_rev)
        self.native = NativeOutput(output_target, self.writer) if native_cycles else None
        self.body: List[str] = []
        self.warnings: List[Tuple[int, CycleWarning]] = []
        self.program_number: Optional[int] = None
        self.started = False  # a block other than %, O, comments was read
        self.last_line = 0

    # -- reading ------------------------------------------------------------

    def line(self, text: str, number: int) -> None:
        """Read one line (``number`` is its 1-based line number)."""
        self._line = number
        self.last_line = number
        block = parse_block(text, self.dialect.name, number)
        limit = self.writer.target.max_block_number
        if block.number is not None and limit is not None and block.number > limit:
            self._fail("N%d: a %s block number has at most %d digits" % (block.number, self.writer.target.maker,
                                                                         len(str(limit))))
        self._prefix = "/" if block.delete else ""
        before = {name: getattr(self.state, name) for name in TRACKED} if block.delete else {}
        self._defined = set()
        try:
            self._block(block)
        except ProgramError as exc:
            if exc.line is None:  # raised by the writer: this line's words
                exc.line = number
            raise
        except CycleError as exc:
            raise ProgramError(exc.message, number) from exc
        except MemoryError:  # the run's, not this line's: the caller says it (the command line's out-of-memory line)
            raise
        except Exception as exc:  # a bug, reported on the line that triggered it
            raise ProgramError("internal error (%s: %s)" % (type(exc).__name__, exc), number) from exc
        self._track_block_delete(block, before)

    def _track_block_delete(self, block: Block, before: dict) -> None:
        """What a '/' line changed becomes ambiguous; what a plain line sets is known again."""
        state = self.state
        if block.delete:
            changed = {name for name in TRACKED if getattr(state, name) != before[name]}
            if "metric" in changed:
                changed |= {"x", "y", "z", "feed"}
            state.ambiguous |= changed
            self.writer.motion = None  # the output's motion depends on the switch too
        else:
            state.ambiguous -= self._defined
        if state.ambiguous:
            self._sync_writer()

    def _block(self, block: Block) -> None:
        if block.percent:
            return
        if self._open is not None and not block.is_empty():  # the blocks of a call over several (a region)
            self._open_block(block)
            return
        if self.state.ended:
            if block.words or block.keywords or block.call or block.number is not None:
                self._fail("text after the program end (M2/M30): subprograms and a second program are not supported")
            return
        if block.is_empty():
            for text in block.comments:
                self._emit(self.writer.comment(text, MAX_LINE - 3))
            return
        letters = [word.letter for word in block.words]
        if "O" in letters:
            self._program_number(block)
            return
        self.started = True
        for letter in set(letters):
            if letter not in ("G", "M") and letters.count(letter) > 1:
                self._fail("%s is programmed twice in the block" % letter)
        if block.parameters:
            self._parameter_block(block)
            return
        groups = self._g_codes(block)
        if block.call is not None or CYCLE in groups:
            self._cycle_block(block, groups)
        elif DWELL in groups:
            self._dwell_block(block)
        else:
            self._plain_block(block, groups)

    def _g_codes(self, block: Block) -> Groups:
        """The block's G codes by modal group, from the dialect's table."""
        groups: Groups = {}
        for word in block.all("G"):
            key = g_code_key(word.text)
            if key is None:
                self._fail("G%s is not a G code: a G word is a whole number, or one with a decimal such as G7.1"
                           % word.text)
            code = self.codes.get(key)
            if code is None:
                self._fail("G%s is not supported in a %s program" % (word.text, self.dialect.name))
            if code.group == REFUSED:
                self._fail("G%s: %s" % (word.text, code.value))
            if code.group in groups:
                self._fail("G%s and G%s are in the same modal group" % (groups[code.group].word.text, word.text))
            groups[code.group] = ActiveCode(code.value, word)
        return groups

    def _program_number(self, block: Block) -> None:
        if not self.dialect.program_numbers:
            self._fail("O is not a %s word" % self.dialect.maker)
        if len(block.words) > 1 or block.keywords or block.call or block.number is not None:
            self._fail("the O program number must be alone in its block")
        if self.started or self.program_number is not None:
            self._fail("a second O program number: subprograms and several programs in a file are not supported")
        self.program_number = self._integer(block.words[0])
        for text in block.comments:
            self._emit(self.writer.comment(text, MAX_LINE - 3))

    def _plain_block(self, block: Block, groups: Groups) -> None:
        """A block without a cycle or dwell: modes, tool, spindle, M codes, motion."""
        state = self.state
        self._check_plain_letters(block)
        for group in CYCLE_OPTIONS:
            if group in groups:
                self._fail("G%s: only a cycle's block (%s) may hold it" % (
                    groups[group].word.text, "/".join(entry.name for entry in self.dialect.cycles())))
        early: List[str] = []  # Fanuc output: blocks that must stand alone before this one
        output: List[str] = []
        self._modes(block, groups, output, early)
        target = self.writer.target
        if PLANE in groups and target.plane_code:  # Fanuc: G18 implied (plane selection is an option)
            output.append(target.plane_code)
        if OFFSET in groups:
            self._work_offset(groups[OFFSET], output)
        if COMPENSATION in groups:
            output.append(target.compensation_off)
        feed_word = self._feed_word(block)
        self._tool(block, output)  # tool, then spindle speed / CSS / limit
        self._length_offset(block, groups, output)
        self._restart_spindle(block, output)
        self._spindle(block, groups, output, early)
        stops_and_ends = self._m_codes(block, output)  # written after the motion
        self._motion(block, groups, output)
        if feed_word is not None:
            output.append(self.writer.feed_word(state.feed))
        self._stops_and_ends(stops_and_ends, output)
        note = self._diameter_register(block) if self.dialect.tool_words == DIAMETER_REGISTER else None
        self._emit_early(block, early, output or block.comments or note)
        if output or block.comments or note:
            self._emit_line(block, output, note)
        self._sync_writer()

    def _work_offset(self, code: ActiveCode, output: List[str]) -> None:
        """G54..G59: written as they are where the target has them; the position is unknown after."""
        target = self.writer.target
        number = int(code.value[1:])
        if number > target.last_work_offset:
            self._fail("%s: the %s output's settable work offsets are G54..G%d" % (code.value, target.name,
                                                                                 target.last_work_offset))
        output.append(code.value)
        self.state.x = self.state.y = self.state.z = None
        self._defined |= {"x", "y", "z"}

    def _check_plain_letters(self, block: Block) -> None:
        for word in block.words:
            if word.letter in self.dialect.plain_letters:
                continue
            if word.letter in self.dialect.letter_refusals:
                self._fail("%s%s: %s" % (word.letter, word.text, self.dialect.letter_refusals[word.letter]))
            self._fail("%s%s is not supported here" % (word.letter, word.text))

    # -- result -------------------------------------------------------------

    def header_known(self) -> bool:
        """Whether the header is settled: it names the O number, which may only
        come before the first block (or never, for a control without one)."""
        return self.started or self.program_number is not None or not self.dialect.program_numbers

    def header(self) -> List[str]:
        """The lines that open the translation (modes at the start, the title)."""
        header_writer = Writer(self.writer.target, self.start_metric, self.start_feed_per_rev)
        title = "%s: %s program%s, cycles %s for %s by freecad-groove" % (
            self.source_name,
            self.dialect.name,
            " O%d" % self.program_number if self.program_number is not None else "",
            "native or expanded" if self.native is not None else "expanded",
            self.target,
        )
        return header_writer.header(title, self.program_number)

    def footer(self) -> List[str]:
        """The lines that close the translation (the end when the program has none)."""
        self.check_blocks_closed()
        lines = self.writer.footer()
        return lines[1:] if self.state.ended else lines

    def result(self) -> str:
        """The translated program text (after ``line`` was called for every line)."""
        return "\n".join(self.header() + self.body + self.footer()) + "\n"

    def translate(self, lines: Iterable[str]) -> Iterator[str]:
        """Read ``lines`` (without their ends of line) one by one and yield the
        translation as it is made: the header once it is settled, then the
        output of each line as soon as it is read (one chunk of whole lines,
        each ending in a newline), then the footer. ``"".join`` of the chunks is
        ``result()``; the output of the lines read is not kept."""
        pending = True  # the header is not written yet
        for number, text in enumerate(lines, 1):
            self.line(text, number)
            if pending and self.header_known():
                pending = False
                yield _chunk(self.header())
            if not pending and self.body:
                body, self.body = self.body, []
                yield _chunk(body)
        if pending:
            yield _chunk(self.header())
        yield _chunk(self.body + self.footer())
        self.body = []


def _chunk(lines: List[str]) -> str:
    return "".join(line + "\n" for line in lines)


_LINES = re.compile(r"\r\n|\r|\n")
_END_OF_LINE = ("\r\n", "\n", "\r")


def program_lines(program: Union[str, Iterable[str]]) -> Iterator[str]:
    """The lines of a program without their ends of line, read lazily from an
    iterable of lines as a text file yields them (each with its ``\n``,
    ``\r\n`` or ``\r``), or split from a whole text. Either way the same lines
    as ``re.split(r"\r\n|\r|\n", text)``: a text ending in a newline has an
    empty last line."""
    if isinstance(program, str):
        yield from _LINES.split(program)
        return
    ended = True  # an empty program is one empty line
    for line in program:
        ended = line.endswith(_END_OF_LINE)
        yield line[:-2] if line.endswith("\r\n") else line[:-1] if ended else line
    if ended:
        yield ""


def iter_translation(program: Union[str, Iterable[str]], dialect: str, settings: Settings = DEFAULT_SETTINGS,
                     target: str = "linuxcnc", source_name: str = "PROGRAM", start: Optional[MachineState] = None,
                     tools: Optional[Tools] = None,
                     warnings: Optional[List[Tuple[int, CycleWarning]]] = None,
                     native_cycles: bool = False) -> Iterator[str]:
    """translate_program, block by block: yields the translated text in chunks
    of whole lines as ``program`` is read (a text, or lines read lazily, e.g. a
    text file object: see program_lines), so neither the input nor the output
    need be held whole. ``"".join(iter_translation(...))`` is translate_program's
    result; a line that cannot be translated raises ProgramError when the
    translation reaches it, after the chunks of the lines before it.
    ``warnings``: as for translate_program, appended to as the lines are read."""
    translator = Translator(dialect, settings, target=target, source_name=source_name, start=start, tools=tools,
                            native_cycles=native_cycles)
    if warnings is not None:
        translator.warnings = warnings  # appended to as the lines are read
    return translator.translate(program_lines(program))


def translate_program(
    text: str,
    dialect: str,
    settings: Settings = DEFAULT_SETTINGS,
    target: str = "linuxcnc",
    source_name: str = "PROGRAM",
    start: Optional[MachineState] = None,
    tools: Optional[Tools] = None,
    warnings: Optional[List[Tuple[int, CycleWarning]]] = None,
    native_cycles: bool = False,
) -> str:
    """Translate a ``dialect`` program for ``target`` with every cycle call expanded.

    ``start`` (moves.MachineState, optional) gives the modes at the start
    (diameter_mode, incremental, metric, feed_per_rev); the position is never
    taken from it. ``tools`` (tool_table.ToolTable, optional; for a Milltronics
    program a mill_tool_table.MillToolTable: G33/G34 cut with the diameter of
    the D in force, else settings.mill_tool_diameter) gives the blade
    of each tool number; a cycle that needs a blade (CYCLE93) cuts with the
    table's entry for the tool in force, else with ``settings.tool``, else it
    is refused. Raises ProgramError (``.line`` set) on the first line that
    cannot be translated. ``warnings`` (a list, optional) gets a (line,
    warnings.CycleWarning) appended for each warning of a cycle, as the lines
    are read (so also those before a line that raises); they never change the
    text returned. ``native_cycles``: each cycle call written as the target's
    own cycle where it cuts the same, else expanded after a comment saying why
    (engine/native; off: every call expanded). (iter_translation gives the
    same text in chunks.)
    """
    return "".join(iter_translation(text, dialect, settings, target, source_name, start, tools, warnings,
                                    native_cycles))
