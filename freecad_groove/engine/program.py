"""Read lathe programs (Siemens, Allen-Bradley 9/Series, Fanuc, Haas), track their
modal state, and translate them with every grooving cycle expanded.

    translate_program(text, dialect, settings, target="linuxcnc", source_name="PROGRAM") -> str

``dialect`` is the input: "sinumerik" (CYCLE93), "ab9" (G77/G76), "fanuc"
(two-block G75/G74), "haas" (one-block G75/G74). ``target`` is "linuxcnc" or
"fanuc" (see targets.py). Anything the reader cannot translate faithfully
raises errors.ProgramError with the 1-based line number in ``.line``; a cycle's
CycleError becomes a ProgramError on the cycle's line with the cycle's message.

How the output is made
----------------------
Lines are not copied: each block is read into words and written again by the
target's writer. The output is always absolute (G90) with X words as diameters
(G7), so incremental words (G91, Fanuc/Haas U and W), radius programming
(Siemens DIAMOF, the Allen-Bradley radius G code) and Siemens DIAM90 are
resolved by the reader and never reach the output: an incremental move needs
a known position (else ProgramError). N numbers, comments and the block delete
``/`` are kept. A cycle block becomes a comment naming the call, then the
expanded moves (no N numbers; each prefixed with ``/`` when the call was).

Choices where the manuals are silent (each has a test)
------------------------------------------------------
* Diameter programming at the start for every dialect (the seed example:
  ``G00 X80 Z65`` before CYCLE93 with AXFA 35 as a radius); metric at the start;
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
* A units change converts the known position and forgets the feed (LinuxCNC
  resets F to 0 on a feed-mode change too, so a feed-mode change also forgets
  it unless the block has F).
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
  ``T0512``.
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
  word is not documented in the seed: G04 is refused for "ab9".
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
"""

import math
import re
from dataclasses import dataclass, field
from typing import NamedTuple, Optional

from .targets import MAX_LINE, Writer, comment, target_spec
from .errors import CycleError, ProgramError
from .numbers import ARC_IJK_TOLERANCE, ARC_R_TOLERANCE, MAX_DWELL_SECONDS, MAX_WORD, MM_PER_INCH
from .registry import cycle_for
from .moves import FEED, RAPID, MachineState
from .settings import DEFAULT_SETTINGS

__all__ = [
    "DIALECTS",
    "Word",
    "Block",
    "ModalState",
    "Translator",
    "parse_block",
    "translate_program",
]

DIALECTS = ("sinumerik", "ab9", "fanuc", "haas")

# ---------------------------------------------------------------- tokenizer


class Word(NamedTuple):
    letter: str  # upper case; "CR", "LIMS" for Siemens assignments
    text: str  # the number as written
    value: float


class Block:
    """One line of an input program, read into words."""

    __slots__ = ("line", "text", "delete", "number", "words", "keywords", "call", "comments", "percent")

    def __init__(self, line, text):
        self.line = line
        self.text = text
        self.delete = False
        self.number = None  # N value (int)
        self.words = []  # Word, in order, without N
        self.keywords = []  # Siemens DIAMON, DIAMOF, DIAM90
        self.call = None  # Siemens "CYCLE93(...)" as written, name upper case
        self.comments = []
        self.percent = False

    def get(self, letter):
        for w in self.words:
            if w.letter == letter:
                return w
        return None

    def all(self, letter):
        return [w for w in self.words if w.letter == letter]

    def letters(self):
        return {w.letter for w in self.words}

    def is_empty(self):
        return not (self.words or self.keywords or self.call or self.number is not None)

    def __repr__(self):
        return "Block(%d, %r)" % (self.line, self.text)


_NUMBER = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)")
_SPACE = re.compile(r"[ \t]*")
_LETTERS = re.compile(r"[A-Za-z]+")
_IDENT_TAIL = re.compile(r"[A-Za-z0-9_]*")
_SIEMENS_KEYWORDS = ("DIAMON", "DIAMOF", "DIAM90")
_SIEMENS_ASSIGN = ("CR", "LIMS")
_SIEMENS_CALLS = ("CYCLE93",)


def parse_block(text, dialect, line=1):
    """Read one line of a ``dialect`` program into a Block (raises ProgramError)."""
    if dialect not in DIALECTS:
        raise ValueError("unknown dialect %r (known: %s)" % (dialect, ", ".join(DIALECTS)))
    siemens = dialect == "sinumerik"
    b = Block(line, text)

    def fail(message):
        raise ProgramError(message, line)

    n = len(text)
    pos = _SPACE.match(text, 0).end()
    if pos < n and text[pos] == "%":
        b.percent = True
        return b
    if pos < n and text[pos] == "/":
        b.delete = True
        pos += 1
        if pos < n and text[pos].isdigit():
            fail("block delete level /%s is not supported (only /)" % text[pos])
    first_word = True
    while True:
        pos = _SPACE.match(text, pos).end()
        if pos >= n:
            break
        c = text[pos]
        if c == "(":
            end = text.find(")", pos + 1)
            if end < 0:
                fail("comment opened with '(' is not closed")
            b.comments.append(text[pos + 1 : end])
            pos = end + 1
            continue
        if c == ";":
            b.comments.append(text[pos + 1 :])
            break
        m = _LETTERS.match(text, pos)
        if not m:
            fail("cannot read %r" % text[pos:pos + 12])
        name = m.group().upper()
        if len(name) > 1:
            if not siemens:
                fail("cannot read %r: a word is one letter and a number" % text[pos:pos + 12])
            tail = _IDENT_TAIL.match(text, m.end())
            name = (m.group() + tail.group()).upper()
            pos = tail.end()
            if name in _SIEMENS_KEYWORDS:
                b.keywords.append(name)
                first_word = False
                continue
            after = _SPACE.match(text, pos).end()
            if after < n and text[after] == "(":
                if name not in _SIEMENS_CALLS:
                    fail("%s(...) is not supported (only %s)" % (name, ", ".join(_SIEMENS_CALLS)))
                if b.call is not None:
                    fail("two cycle calls in one block")
                depth = 0
                end = after
                while end < n:
                    if text[end] == "(":
                        depth += 1
                    elif text[end] == ")":
                        depth -= 1
                        if depth == 0:
                            break
                    end += 1
                if end >= n:
                    fail("%s( is not closed with ')'" % name)
                b.call = name + text[after : end + 1]
                pos = end + 1
                first_word = False
                continue
            if name in _SIEMENS_ASSIGN:
                if after >= n or text[after] != "=":
                    fail("%s must be followed by '=' and a number" % name)
                pos = _SPACE.match(text, after + 1).end()
                num = _NUMBER.match(text, pos)
                if not num:
                    fail("%s= must be followed by a number (parameters and expressions are not evaluated)" % name)
                b.words.append(Word(name, num.group(), float(num.group())))
                pos = num.end()
                first_word = False
                continue
            fail("%s is not supported" % name)
        pos = _SPACE.match(text, m.end()).end()
        if siemens and pos < n and text[pos] == "=":
            pos = _SPACE.match(text, pos + 1).end()
        num = _NUMBER.match(text, pos)
        if not num:
            fail("%s must be followed by a number (parameters and expressions are not evaluated)" % name)
        pos = num.end()
        t = num.group()
        if name == "N":
            if not first_word:
                fail("N%s: the block number must be the first word" % t)
            if not t.isdigit():
                fail("N%s: the block number must be a whole number" % t)
            b.number = int(t)
        else:
            b.words.append(Word(name, t, float(t)))
        first_word = False
    return b


# ---------------------------------------------------------------- dialect tables

_MOTION, _DWELL, _PLANE, _COMP, _CSS, _OFFSET, _UNITS, _DISTANCE, _FEEDMODE, _DIAM, _CLAMP, _CYCLE, _BAD = range(13)
_MODE_GROUPS = (_UNITS, _DISTANCE, _FEEDMODE, _DIAM)

_COMMON = {
    "0": (_MOTION, RAPID),
    "1": (_MOTION, FEED),
    "2": (_MOTION, "G2"),
    "3": (_MOTION, "G3"),
    "4": (_DWELL, None),
    "18": (_PLANE, None),
    "17": (_BAD, "only the XZ plane (G18) is supported on a lathe"),
    "19": (_BAD, "only the XZ plane (G18) is supported on a lathe"),
    "40": (_COMP, None),
    "41": (_BAD, "tool nose radius compensation (G41/G42) is not translated"),
    "42": (_BAD, "tool nose radius compensation (G41/G42) is not translated"),
    "96": (_CSS, True),
    "97": (_CSS, False),
    "54": (_OFFSET, "G54"),
    "55": (_OFFSET, "G55"),
    "56": (_OFFSET, "G56"),
    "57": (_OFFSET, "G57"),
}

_FANUC_LIKE = dict(_COMMON)
_FANUC_LIKE.update(
    {
        "58": (_OFFSET, "G58"),
        "59": (_OFFSET, "G59"),
        "20": (_UNITS, False),
        "21": (_UNITS, True),
        "98": (_FEEDMODE, False),
        "99": (_FEEDMODE, True),
        "50": (_CLAMP, None),
        "75": (_CYCLE, "G75"),
        "74": (_CYCLE, "G74"),
        "28": (_BAD, "reference return G28 is not translated (LinuxCNC's G28 goes to a stored position)"),
        "90": (_BAD, "G90 is the turning cycle on this lathe control (G code system A): not supported"),
        "92": (_BAD, "G92 is the threading cycle on this lathe control: not supported"),
        "94": (_BAD, "G94 is the facing cycle on this lathe control (feed per minute is G98): not supported"),
        "70": (_BAD, "G70 (finishing cycle) is not supported"),
        "71": (_BAD, "G71 (turning stock removal cycle) is not supported"),
        "72": (_BAD, "G72 (facing stock removal cycle) is not supported"),
        "73": (_BAD, "G73 (pattern repeating cycle) is not supported"),
        "76": (_BAD, "G76 (threading cycle) is not supported"),
    }
)

_TABLES = {
    "sinumerik": dict(
        _COMMON,
        **{
            "70": (_UNITS, "G70"),
            "71": (_UNITS, "G71"),
            "700": (_UNITS, "G700"),
            "710": (_UNITS, "G710"),
            "90": (_DISTANCE, False),
            "91": (_DISTANCE, True),
            "94": (_FEEDMODE, False),
            "95": (_FEEDMODE, True),
        }
    ),
    "ab9": dict(
        _COMMON,
        **{
            "58": (_OFFSET, "G58"),
            "59": (_OFFSET, "G59"),
            "7": (_DIAM, "G07"),
            "8": (_DIAM, "G08"),
            "20": (_UNITS, False),
            "21": (_UNITS, True),
            "90": (_DISTANCE, False),
            "91": (_DISTANCE, True),
            "94": (_FEEDMODE, False),
            "95": (_FEEDMODE, True),
            "77": (_CYCLE, "G77"),
            "76": (_CYCLE, "G76"),
        }
    ),
    "fanuc": _FANUC_LIKE,
    "haas": _FANUC_LIKE,
}

_M_GROUPS = {0: "stop", 1: "stop", 2: "end", 30: "end", 3: "spindle", 4: "spindle", 5: "spindle", 7: "coolant",
             8: "coolant", 9: "coolant"}


# ---------------------------------------------------------------- modal state


@dataclass
class ModalState:
    """What the reader knows after each block. None = unknown.

    x is a radius, z absolute, in the program's current units.
    """

    x: Optional[float] = None
    z: Optional[float] = None
    motion: Optional[str] = None  # RAPID, FEED, "G2", "G3"
    incremental: bool = False  # G91 (Siemens, AB)
    diameter: bool = True  # X words are diameters
    diam90: bool = False  # Siemens DIAM90: diameters in G90, radii in G91
    metric: bool = True
    siemens_g70: bool = False  # Siemens G70: inch lengths, feed in the basic system
    feed_per_rev: Optional[bool] = None
    feed: Optional[float] = None
    spindle: Optional[float] = None  # the last S value
    spindle_dir: Optional[int] = None  # 3 / 4 running (M3/M4), 5 stopped, None not started in this program
    css: bool = False  # G96 active
    speed_limit: Optional[float] = None  # G50 S / LIMS=
    tool: Optional[int] = None
    retract_e: Optional[Word] = None  # Fanuc "G75 R(e)" / "G74 R(e)"
    ended: bool = False
    ambiguous: set = field(default_factory=set)

    def x_words_diameter(self):
        """True when the X words of the next block are diameters."""
        return self.diameter and not (self.diam90 and self.incremental)

    def machine_state(self):
        return MachineState(
            x=self.x,
            z=self.z,
            feed=self.feed,
            diameter_mode=self.x_words_diameter(),
            incremental=self.incremental,
            metric=self.metric,
            feed_per_rev=bool(self.feed_per_rev),
        )


_TRACKED = ("x", "z", "motion", "incremental", "diameter", "diam90", "metric", "siemens_g70", "feed_per_rev", "feed",
            "spindle", "spindle_dir", "css", "speed_limit", "tool", "retract_e")

# ---------------------------------------------------------------- the translator


class Translator:
    """Reads a program block by block and writes the translation.

    ``line(text, number)`` reads one line; ``state`` is the ModalState after it;
    ``result()`` is the translated program text.
    """

    def __init__(self, dialect, settings=DEFAULT_SETTINGS, target="linuxcnc", source_name="PROGRAM", start=None):
        if dialect not in DIALECTS:
            raise ValueError("unknown dialect %r (known: %s)" % (dialect, ", ".join(DIALECTS)))
        target_spec(target)  # raises on an unknown target
        self.dialect = dialect
        self.settings = settings
        self.target = target
        self.fanuc_out = target == "fanuc"
        self.source_name = source_name
        self.table = _TABLES[dialect]
        s = ModalState()
        if start is not None:
            s.diameter = bool(start.diameter_mode)
            s.incremental = bool(start.incremental)
            s.metric = bool(start.metric)
            s.feed_per_rev = start.feed_per_rev
        self.state = s
        self.start_metric = s.metric
        self.start_feed_per_rev = s.feed_per_rev
        self.writer = Writer(target, s.metric, s.feed_per_rev)
        self.body = []
        self.program_number = None
        self.started = False  # a block other than %, O, comments was read
        self.last_line = 0

    # -- helpers ------------------------------------------------------------

    def _fail(self, message, line=None):
        raise ProgramError(message, self._line if line is None else line)

    def _emit(self, text):
        text = self._prefix + text
        if len(text) > MAX_LINE:
            self._fail("the translated block is longer than %d characters (LinuxCNC's limit)" % MAX_LINE)
        self.body.append(text)

    def _sync_writer(self):
        """Tell the writer what the output program has in force (the reader's state)."""
        s = self.state
        amb = s.ambiguous
        self.writer.sync(
            None if "x" in amb else s.x,
            None if "z" in amb else s.z,
            None if "feed" in amb else s.feed,
            self.writer.motion,
        )

    def _length(self, w, what=None):
        """The value of a length/feed word, refusing Fanuc-style integers."""
        if self.dialect != "sinumerik" and "." not in w.text and w.value != 0:
            self._fail(
                "%s%s needs a decimal point: without one the control reads it in least input increments "
                "or per its zero-suppression parameter; write %s%s." % (w.letter, w.text, w.letter, w.text)
            )
        return w.value

    def _integer(self, w):
        if "." in w.text or w.value < 0:
            self._fail("%s%s must be a whole number" % (w.letter, w.text))
        return int(w.text.lstrip("+"))

    def _check_finite(self, value, w):
        if not abs(value) < MAX_WORD:
            self._fail("%s%s is out of range" % (w.letter, w.text))

    def _not_ambiguous(self, *names, why):
        amb = (self.state.ambiguous - self._defined).intersection(names)
        if amb:
            self._fail(
                "%s depends on a block-delete '/' line: %s is not known for sure; program it again in a "
                "block without '/'" % (why, ", ".join(sorted(amb)))
            )

    # -- reading ------------------------------------------------------------

    def line(self, text, number):
        """Read one line (``number`` is its 1-based line number)."""
        self._line = number
        self.last_line = number
        block = parse_block(text, self.dialect, number)
        if self.fanuc_out and block.number is not None and block.number > 99999:
            self._fail("N%d: a Fanuc block number has at most 5 digits" % block.number)
        self._prefix = "/" if block.delete else ""
        s = self.state
        if block.delete:
            before = {name: getattr(s, name) for name in _TRACKED}
        self._defined = set()
        try:
            self._block(block)
        except ProgramError as exc:
            if exc.line is None:  # raised by the writer: this line's words
                exc.line = number
            raise
        except CycleError as exc:
            raise ProgramError(exc.message, number) from exc
        except Exception as exc:  # a bug, reported on the line that triggered it
            raise ProgramError("internal error (%s: %s)" % (type(exc).__name__, exc), number) from exc
        if block.delete:
            changed = {name for name in _TRACKED if getattr(s, name) != before[name]}
            if "metric" in changed:
                changed |= {"x", "z", "feed"}
            s.ambiguous |= changed
        else:
            s.ambiguous -= self._defined
        if block.delete:
            self.writer.motion = None  # the output's motion depends on the switch too
        if s.ambiguous:
            self._sync_writer()

    def _block(self, b):
        s = self.state
        if b.percent:
            return
        if s.ended:
            if b.words or b.keywords or b.call or b.number is not None:
                self._fail("text after the program end (M2/M30): subprograms and a second program are not supported")
            return
        if b.is_empty():
            for text in b.comments:
                self._emit(comment(text, MAX_LINE - 3))
            return
        letters = [w.letter for w in b.words]
        if "O" in letters:
            self._program_number(b)
            return
        self.started = True
        for letter in set(letters):
            if letter not in ("G", "M") and letters.count(letter) > 1:
                self._fail("%s is programmed twice in the block" % letter)

        # classify the G codes
        groups = {}
        for w in b.all("G"):
            key = w.text.lstrip("+")
            if "." not in key:
                key = str(int(key))
            entry = self.table.get(key)
            if entry is None:
                self._fail("G%s is not supported in a %s program" % (w.text, self.dialect))
            group, arg = entry
            if group == _BAD:
                self._fail("G%s: %s" % (w.text, arg))
            if group in groups:
                self._fail("G%s and G%s are in the same modal group" % (groups[group][1].text, w.text))
            groups[group] = (arg, w)

        if b.call is not None or _CYCLE in groups:
            self._cycle_block(b, groups)
        elif _DWELL in groups:
            self._dwell_block(b, groups)
        else:
            self._plain_block(b, groups)

    def _program_number(self, b):
        if self.dialect == "sinumerik":
            self._fail("O is not a Siemens word")
        if len(b.words) > 1 or b.keywords or b.call or b.number is not None:
            self._fail("the O program number must be alone in its block")
        if self.started or self.program_number is not None:
            self._fail("a second O program number: subprograms and several programs in a file are not supported")
        w = b.words[0]
        self.program_number = self._integer(w)
        for text in b.comments:
            self._emit(comment(text, MAX_LINE - 3))

    # -- mode G codes -------------------------------------------------------

    def _modes(self, b, groups, out, early):
        """Apply units, feed mode, distance and diameter codes; add output words."""
        s = self.state
        w = self.writer
        if _UNITS in groups:
            arg, word = groups[_UNITS]
            g70 = False
            if self.dialect == "sinumerik":
                g70 = arg == "G70"
                metric = arg in ("G71", "G710")
            else:
                metric = arg
            if metric != s.metric:
                factor = MM_PER_INCH if metric else 1.0 / MM_PER_INCH
                if s.x is not None:
                    s.x *= factor
                if s.z is not None:
                    s.z *= factor
                s.feed = None
                s.metric = metric
            self._defined |= {"metric", "siemens_g70"}
            s.siemens_g70 = g70
            w.set_units(metric)
            if self.fanuc_out:
                early.append(w.units_code(metric))
            else:
                out.append(w.units_code(metric))
        if _FEEDMODE in groups:
            per_rev = groups[_FEEDMODE][0]
            if per_rev != s.feed_per_rev:
                s.feed = None
            s.feed_per_rev = per_rev
            self._defined.add("feed_per_rev")
            out.append(w.feed_mode_code(per_rev))
        if _DISTANCE in groups:
            s.incremental = groups[_DISTANCE][0]
            self._defined.add("incremental")
        if _DIAM in groups:
            code = groups[_DIAM][0]
            g07 = code == "G07"
            s.diameter = g07 if self.settings.ab_g07_is_diameter else not g07
            self._defined.add("diameter")
        for k in b.keywords:
            s.diameter = k != "DIAMOF"
            s.diam90 = k == "DIAM90"
            self._defined |= {"diameter", "diam90"}

    # -- block kinds ----------------------------------------------------------

    def _words_line(self, b, words, note=None):
        """``N.. words (note ; comments)``, the comment cut to keep the block within MAX_LINE."""
        parts = []
        if b.number is not None:
            parts.append("N%d" % b.number)
        parts.extend(words)
        line = " ".join(parts)
        texts = ([note] if note else []) + [c.strip() for c in b.comments]
        if texts:
            room = MAX_LINE - len(self._prefix) - len(line) - 3
            line = (line + " " if line else "") + comment(" ; ".join(texts), room)
        return line

    def _plain_block(self, b, groups):
        s = self.state
        wr = self.writer
        allowed = set("XZFSTMGIK")
        if self.dialect in ("fanuc", "haas"):
            allowed |= set("UWR")
        elif self.dialect == "ab9":
            allowed |= set("R")
        else:
            allowed |= {"D", "CR", "LIMS"}
        for w in b.words:
            if w.letter not in allowed:
                if self.dialect == "sinumerik" and w.letter == "R":
                    self._fail("R%s: Siemens R parameters are not evaluated" % w.text)
                self._fail("%s%s is not supported here" % (w.letter, w.text))
        early = []  # Fanuc output: blocks that must stand alone before this one
        out = []
        self._modes(b, groups, out, early)
        if _PLANE in groups:
            if not self.fanuc_out:  # Fanuc: G18 implied (plane selection is an option)
                out.append("G18")
        if _OFFSET in groups:
            out.append(groups[_OFFSET][0])
            s.x = s.z = None
            self._defined |= {"x", "z"}
        if _COMP in groups:
            out.append("G40")

        # F
        fw = b.get("F")
        if fw is not None:
            if s.siemens_g70:
                self._fail(
                    "F%s in G70: Siemens G70 leaves the feed in the metric basic system; use G700 for an inch feed"
                    % fw.text
                )
            f = self._length(fw)
            if not 0 < f < MAX_WORD:
                self._fail("F%s: the feed must be greater than 0" % fw.text)
            s.feed = f
            self._defined.add("feed")
        # tool, then spindle speed / CSS / limit
        self._tool(b, out)
        if "M6" in out and s.spindle_dir in (3, 4) and not {3, 4, 5} & {int(w.value) for w in b.all("M")}:
            # LinuxCNC's M6 stops the spindle; a lathe turret does not: start it again
            self._not_ambiguous("spindle_dir", why="restarting the spindle after the tool change")
            out.append("M%d" % s.spindle_dir)
        self._spindle(b, groups, out, early)
        # M codes (stops and ends after the motion)
        after = []
        spindle_m = []
        groups_m = {}
        for w in b.all("M"):
            m = self._integer(w)
            g = _M_GROUPS.get(m)
            if g is None:
                self._fail("M%s is not supported (machine-specific M codes are not translated)" % w.text)
            if g in groups_m and not (g == "coolant" and {m, groups_m[g]} == {7, 8}):
                self._fail("M%d and M%d are in the same modal group" % (groups_m[g], m))
            groups_m[g] = m
            if g in ("stop", "end"):
                after.append(m)
            else:
                spindle_m.append(m)
        for m in spindle_m:
            out.append(("M%02d" if self.fanuc_out else "M%d") % m)
            if m in (3, 4, 5):
                s.spindle_dir = m
                self._defined.add("spindle_dir")

        # motion
        self._motion(b, groups, out)
        if fw is not None:
            out.append("F" + wr.f_word(s.feed))

        for m in after:
            if m in (2, 30):
                out.append(wr.spec.end)
                s.ended = True
                s.spindle_dir = None
                s.x = s.z = None
            else:
                out.append(("M%02d" if self.fanuc_out else "M%d") % m)
        self._emit_early(b, early, out or b.comments)
        if out or b.comments:
            self._emit(self._words_line(b, out))
        self._sync_writer()

    def _emit_early(self, b, early, more):
        """Blocks that must stand alone before the block (Fanuc G20/G21, G50 S): the
        block's N goes on the first of them when nothing else of the block is written."""
        for i, text in enumerate(early):
            if i == 0 and not more and b.number is not None:
                text = "N%d %s" % (b.number, text)
            self._emit(text)

    def _spindle(self, b, groups, out, early):
        s = self.state
        sw = b.get("S")
        lims = b.get("LIMS")
        speed = None
        if sw is not None:
            speed = sw.value
            if not 0 <= speed < MAX_WORD:
                self._fail("S%s is out of range" % sw.text)
        if _CLAMP in groups:  # Fanuc/Haas G50 S: spindle speed limit
            if sw is None or b.letters() - {"G", "S"} or len(b.all("G")) > 1:
                self._fail("G50 is supported only as the spindle speed limit, G50 S.. alone in its block")
            s.speed_limit = speed
            self._defined.add("speed_limit")
            if self.fanuc_out:
                out.append("G50 S" + self._s_text(speed))
            elif s.css:
                if s.spindle is None:
                    self._fail("G50 S: the surface speed in force is not known")
                out.extend(["G96", "S" + self._s_text(s.spindle), "D" + self._s_text(speed)])
            else:
                out.append(comment("G50 S%s: spindle limit for G96" % self._s_text(speed)))
            return
        if lims is not None:
            if not 0 < lims.value < MAX_WORD:
                self._fail("LIMS=%s is out of range" % lims.text)
            s.speed_limit = lims.value
            self._defined.add("speed_limit")
            if self.fanuc_out:
                early.append("G50 S" + self._s_text(lims.value))
        if _CSS in groups:
            on = groups[_CSS][0]
            if on and sw is None:
                self._fail("G96 needs the surface speed S in the same block")
            if not on and s.css and sw is None:
                self._fail("G97 after G96 needs the spindle speed S in the same block")
            s.css = on
            self._defined.add("css")
            if sw is not None:
                s.spindle = speed
                self._defined.add("spindle")
            if on:
                out.extend(["G96", "S" + self._s_text(speed)])
                if s.speed_limit is not None and not self.fanuc_out:
                    out.append("D" + self._s_text(s.speed_limit))
            else:
                out.append("G97")
                if sw is not None:
                    out.append("S" + self._s_text(speed))
            return
        if sw is not None:
            s.spindle = speed
            self._defined.add("spindle")
            if lims is not None and s.css and not self.fanuc_out:
                out.extend(["G96", "S" + self._s_text(speed), "D" + self._s_text(s.speed_limit)])
            else:
                out.append("S" + self._s_text(speed))
        elif lims is not None and s.css and not self.fanuc_out:
            if s.spindle is None:
                self._fail("LIMS=: the surface speed in force is not known")
            out.extend(["G96", "S" + self._s_text(s.spindle), "D" + self._s_text(s.speed_limit)])

    def _s_text(self, value):
        if value == int(value):
            return "%d" % value
        if self.fanuc_out:
            self._fail("S%s: a Fanuc S word is a whole number" % value)
        return self.writer.number(value, 4)

    def _tool(self, b, out):
        s = self.state
        tw = b.get("T")
        dw = b.get("D")
        if tw is None and dw is None:
            return
        if "M" in b.letters() and 6 in [int(w.value) for w in b.all("M")]:
            self._fail("M6 is added by the translation; program the tool with T alone")
        offset = None
        if self.dialect == "sinumerik":
            tool = None
            if tw is not None:
                tool = self._integer(tw)
                offset = 1
            if dw is not None:
                offset = self._integer(dw)
                if offset > 1:
                    self._fail("D%s: a second cutting edge has no LinuxCNC tool-table entry; only D0 and D1 are "
                               "translated outside CYCLE93" % dw.text)
        else:
            if "." in tw.text or not tw.text.lstrip("+").isdigit() or len(tw.text.lstrip("+")) < 3:
                self._fail("T%s: write the tool and offset as T<tool><2-digit offset>, e.g. T0101" % tw.text)
            digits = tw.text.lstrip("+")
            tool = int(digits[:-2])
            offset = int(digits[-2:])
        s.x = s.z = None
        self._defined |= {"x", "z", "tool"}
        if tool is not None:
            s.tool = tool
        if self.fanuc_out:
            current = s.tool
            if current is None:
                self._fail("D%s: no tool selected before" % dw.text)
            if current > 99 or offset > 99:
                self._fail("T%d offset %d does not fit Fanuc's T<2 digits><2 digits>" % (current, offset))
            out.append("T%02d%02d" % (current, offset))
            return
        if tool is not None:
            out.extend(["T%d" % tool, "M6"])
        if offset == 0:
            out.append("G49")
        elif self.dialect == "sinumerik" or offset == tool:
            out.append("G43")  # the tool's own tool-table entry
        else:
            out.extend(["G43", "H%d" % offset])

    def _axis_target(self, b):
        """(x, z, wrote_x, wrote_z): the block's end point from X/U/Z/W."""
        s = self.state
        xw, uw, zw, ww = b.get("X"), b.get("U"), b.get("Z"), b.get("W")
        if xw is not None and uw is not None:
            self._fail("X and U in one block")
        if zw is not None and ww is not None:
            self._fail("Z and W in one block")
        x, z = s.x, s.z
        if xw is not None or uw is not None:
            self._not_ambiguous("diameter", "diam90", "incremental", why="the X word")
            w = xw or uw
            v = self._length(w)
            self._check_finite(v, w)
            if s.x_words_diameter():
                v /= 2.0
            if uw is not None or s.incremental:
                if s.x is None:
                    self._fail("%s%s is incremental but the X position is not known: program an absolute X first"
                               % (w.letter, w.text))
                self._not_ambiguous("x", why="the incremental %s word" % w.letter)
                x = s.x + v
            else:
                x = v
                self._defined.add("x")
        if zw is not None or ww is not None:
            self._not_ambiguous("incremental", why="the Z word")
            w = zw or ww
            v = self._length(w)
            self._check_finite(v, w)
            if ww is not None or s.incremental:
                if s.z is None:
                    self._fail("%s%s is incremental but the Z position is not known: program an absolute Z first"
                               % (w.letter, w.text))
                self._not_ambiguous("z", why="the incremental %s word" % w.letter)
                z = s.z + v
            else:
                z = v
                self._defined.add("z")
        return x, z, (xw or uw) is not None, (zw or ww) is not None

    def _motion(self, b, groups, out):
        s = self.state
        wr = self.writer
        explicit = groups.get(_MOTION)
        if explicit is not None:
            s.motion = explicit[0]
            self._defined.add("motion")
        axes = b.letters() & {"X", "Z", "U", "W"}
        arc_words = b.letters() & {"I", "K", "R", "CR"}
        if not axes:
            if arc_words:
                self._fail("%s without an end point" % "/".join(sorted(arc_words)))
            return
        if s.motion is None:
            self._fail("axis words without a motion mode in force: program G0 or G1")
        self._not_ambiguous("motion", why="the motion mode")
        kind = s.motion
        if kind in (RAPID, FEED) and arc_words:
            self._fail("%s is only read with G2/G3" % "/".join(sorted(arc_words)))
        arc = []
        if kind in ("G2", "G3"):
            has_ik = bool(arc_words & {"I", "K"})
            has_r = bool(arc_words & {"R", "CR"})
            if has_ik == has_r:
                self._fail("G2/G3 needs either I/K (centre) or the radius (%s)"
                           % ("CR=" if self.dialect == "sinumerik" else "R"))
            for letter in ("I", "K"):
                w = b.get(letter)
                if w is not None:
                    v = self._length(w)
                    self._check_finite(v, w)
                    arc.append(letter + wr.length_word(v))
            w = b.get("R") or b.get("CR")
            if w is not None:
                v = self._length(w)
                self._check_finite(v, w)
                if not v > 0:
                    self._fail("%s%s: the arc radius must be positive (arcs over 180 degrees are not translated)"
                               % (w.letter, w.text))
                arc.append("R" + wr.length_word(v))
        if kind != RAPID:
            if s.feed_per_rev is None:
                self._fail("feed move before the feed mode is programmed (%s)"
                           % ("G98/G99" if self.dialect in ("fanuc", "haas") else "G94/G95"))
            self._not_ambiguous("feed_per_rev", why="the feed mode")
            if s.siemens_g70:
                self._fail("feed move in Siemens G70 (feed in the basic system): use G700")
            if s.feed is None:
                self._fail("feed move with no feed rate (F) in force")
            self._check_spindle_for_feed("feed move")
            if b.get("F") is None:
                self._not_ambiguous("feed", why="the feed rate")
        x, z, has_x, has_z = self._axis_target(b)
        if arc:
            if s.x is None or s.z is None:
                self._fail("G2/G3 needs a known start point: program an absolute X and Z before the arc")
            self._not_ambiguous("x", "z", why="the start of the arc")
            # checked on the numbers as written: what the output control will compute with
            self._check_arc(b, float(wr.x_word(s.x)) / 2.0, float(wr.z_word(s.z)), float(wr.x_word(x)) / 2.0,
                            float(wr.z_word(z)))
        words = []
        if explicit is not None or wr.motion != kind:
            words.append(wr.code(kind))
        if has_x:
            words.append("X" + wr.x_word(x))
        if has_z:
            words.append("Z" + wr.z_word(z))
        words.extend(arc)
        out.extend(words)
        s.x, s.z = x, z
        wr.motion = kind

    def _check_spindle_for_feed(self, what):
        """Feed per revolution needs a spindle speed and a running spindle (else LinuxCNC
        refuses the move or waits for ever)."""
        s = self.state
        if not s.feed_per_rev:
            return
        self._not_ambiguous("spindle", "spindle_dir", why="%s in feed per revolution" % what)
        if not s.spindle:
            self._fail("%s in feed per revolution with no spindle speed (S) programmed" % what)
        if s.spindle_dir not in (3, 4):
            self._fail("%s in feed per revolution with the spindle %s (M3/M4)"
                       % (what, "stopped" if s.spindle_dir == 5 else "not started"))

    def _check_arc(self, b, x0, z0, x1, z1):
        """Refuse an arc whose end point is not on its circle (LinuxCNC would refuse it too).

        Tolerances (per side): I/K centre, the two radii differ by at most
        ARC_IJK_TOLERANCE; R, the chord is at most 2 R + ARC_R_TOLERANCE."""
        scale = 1.0 if self.state.metric else 1.0 / MM_PER_INCH
        r_word = b.get("R") or b.get("CR")
        if r_word is not None:
            radius = float(self.writer.length_word(r_word.value))
            half = math.hypot(x1 - x0, z1 - z0) / 2.0
            if half == 0:
                self._fail("G2/G3 with %s: the end point is the start point (no circle is defined)" % r_word.letter)
            if half - radius > ARC_R_TOLERANCE * scale:
                self._fail("G2/G3: radius %s%s is too small to reach the end point (half the chord is %.4f)"
                           % (r_word.letter, r_word.text, half))
            return
        i = float(self.writer.length_word(b.get("I").value)) if b.get("I") is not None else 0.0
        k = float(self.writer.length_word(b.get("K").value)) if b.get("K") is not None else 0.0
        cx, cz = x0 + i, z0 + k
        r1 = math.hypot(i, k)
        r2 = math.hypot(x1 - cx, z1 - cz)
        if r1 < ARC_IJK_TOLERANCE * scale:
            self._fail("G2/G3: zero radius (I and K put the centre on the start point)")
        if abs(r1 - r2) > ARC_IJK_TOLERANCE * scale:
            self._fail("G2/G3: the end point is not on the circle: radius %.4f at the start, %.4f at the end "
                       "(I and K are radius values, incremental from the start)" % (r1, r2))

    def _dwell_block(self, b, groups):
        d = self.dialect
        others = [w for w in b.words if w.letter != "G"]
        if len(b.all("G")) > 1 or b.keywords:
            self._fail("G4 must be alone in its block (with its time word)")
        seconds = None
        if d == "ab9":
            self._fail("G04: the 9/Series dwell word is not documented here; not translated")
        if len(others) != 1:
            self._fail("G4 needs exactly one time word")
        w = others[0]
        if d == "sinumerik":
            if w.letter == "F":
                seconds = w.value
            elif w.letter == "S":
                self._fail("G4 S (dwell in spindle revolutions) is not translated: use G4 F<seconds>")
        elif d == "fanuc":
            if w.letter in ("X", "U"):
                seconds = self._length(w)
            elif w.letter == "P":
                seconds = self._integer(w) / 1000.0
        else:  # haas
            if w.letter == "P":
                seconds = w.value if "." in w.text else self._integer(w) / 1000.0
        if seconds is None:
            self._fail("G4 %s%s: not a dwell word of this control" % (w.letter, w.text))
        if not 0 <= seconds <= MAX_DWELL_SECONDS:
            self._fail("G4 %s%s: the dwell must be 0 to %g s" % (w.letter, w.text, MAX_DWELL_SECONDS))
        self._emit(self._words_line(b, [self.writer.dwell(seconds)]))

    def _cycle_block(self, b, groups):
        s = self.state
        d = self.dialect
        for group in groups:
            if group not in _MODE_GROUPS and group != _CYCLE:
                self._fail("G%s shares the block with the cycle call: only N, a comment and mode codes may"
                           % groups[group][1].text + " share it")
        if b.call is not None:
            if b.words and any(w.letter != "G" for w in b.words):
                w = next(w for w in b.words if w.letter != "G")
                self._fail("%s%s shares the block with %s: a cycle call takes only N, a comment and mode codes"
                           % (w.letter, w.text, b.call.split("(")[0]))
            name = b.call.split("(")[0]
            text = b.call
            params = []
        else:
            name = groups[_CYCLE][0]
            params = [w for w in b.words if w.letter != "G"]
            for w in params:
                if w.letter in ("M", "S", "T", "N"):
                    self._fail("%s%s shares the block with %s: program it in its own block"
                               % (w.letter, w.text, name))
            text = " ".join([name] + ["%s%s" % (w.letter, w.text) for w in params])
        if b.keywords and b.call is None:
            self._fail("%s shares the block with %s" % (b.keywords[0], name))

        early, out = [], []
        self._modes(b, groups, out, early)
        self._emit_early(b, early, True)
        if out:
            self._emit(" ".join(out))
            self._sync_writer()

        # Fanuc two-block form: the first block only stores e
        if d == "fanuc" and not {w.letter for w in params} & {"X", "Z", "U", "W", "P", "Q", "F"}:
            r = [w for w in params if w.letter == "R"]
            if len(params) != 1 or not r:
                self._fail("%s: the first block is %s R(e) (the peck retract) alone" % (name, name))
            self._length(r[0])
            s.retract_e = r[0]
            self._defined.add("retract_e")
            note = "%s R%s: peck retract e for the next G75/G74" % (name, r[0].text)
            self._emit(self._words_line(b, [], note))
            return
        if d == "fanuc" and s.retract_e is not None:
            self._not_ambiguous("retract_e", why="%s R(e)" % name)
            text = "%s R%s\n%s" % (name, s.retract_e.text, text)

        cls = cycle_for(d, name)
        try:  # the call itself first: its own errors are the most useful
            model = cls.parse(text)
            model.validate(self.settings)
        except CycleError as exc:
            self._fail(exc.message)

        if s.x is None or s.z is None:
            self._fail("%s needs its start point: program an absolute X and Z before the call" % name)
        self._not_ambiguous("x", "z", "feed", "feed_per_rev", "metric", "diameter", "diam90", "incremental",
                            why=name)
        if s.feed_per_rev is None:
            self._fail("%s before the feed mode is programmed (%s)"
                       % (name, "G98/G99" if d in ("fanuc", "haas") else "G94/G95"))
        if s.siemens_g70:
            self._fail("%s in Siemens G70 (feed in the basic system): use G700" % name)
        self._check_spindle_for_feed(name)

        try:
            moves = model.expand(s.machine_state(), self.settings)
        except CycleError as exc:
            self._fail(exc.message)

        label = " / ".join(text.split("\n")).replace("(", " ").replace(")", "")
        self._emit(self._words_line(b, [], label))
        wr = self.writer
        try:
            lines = wr.write(moves, self._prefix)
        except ProgramError as exc:
            self._fail("%s: %s" % (name, exc))
        self.body.extend(lines)
        motion_before = s.motion
        last_f = None
        for m in moves:
            if m[3] is not None:
                last_f = m[3]
        if moves:
            last = moves[-1]
            s.x, s.z = float(last[1]), float(last[2])
        if last_f is not None:
            s.feed = float(last_f)
        s.motion = motion_before if d in ("fanuc", "haas") else None
        self._defined |= {"x", "z"}
        if last_f is not None:
            self._defined.add("feed")
        if d not in ("fanuc", "haas"):
            self._defined.add("motion")

    # -- result -------------------------------------------------------------

    def result(self):
        """The translated program text."""
        header_writer = Writer(self.target, self.start_metric, self.start_feed_per_rev)
        title = "%s: %s program%s, cycles expanded for %s by freecad-groove" % (
            self.source_name,
            self.dialect,
            " O%d" % self.program_number if self.program_number is not None else "",
            self.target,
        )
        lines = header_writer.header(title, self.program_number if self.fanuc_out else None)
        lines.extend(self.body)
        if not self.state.ended:
            lines.append(self.writer.spec.end)
        if self.fanuc_out:
            lines.append("%")
        return "\n".join(lines) + "\n"


_LINES = re.compile(r"\r\n|\r|\n")


def translate_program(text, dialect, settings=DEFAULT_SETTINGS, target="linuxcnc", source_name="PROGRAM", start=None):
    """Translate a ``dialect`` program for ``target`` with every cycle call expanded.

    ``start`` (moves.MachineState, optional) gives the modes at the start
    (diameter_mode, incremental, metric, feed_per_rev); the position is never
    taken from it. Raises ProgramError (``.line`` set) on the first line that
    cannot be translated.
    """
    t = Translator(dialect, settings, target, source_name, start)
    for number, line in enumerate(_LINES.split(text), 1):
        t.line(line, number)
    return t.result()
