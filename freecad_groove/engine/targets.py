"""Output targets: the writers of expanded output, moves.Move lists to G-code text.

(A *target* is the control the output is written for; the *input control* a
program is read from is the reader's business.) Two targets:

``"linuxcnc"``  LinuxCNC in lathe use. Header ``G18 G7 G21 G90 G91.1 G40 G94``
                (G20 for inch, G95 for feed per revolution): XZ plane, X words
                are diameters (G7), absolute coordinates, incremental arc
                centres, no nose-radius compensation. ``G0``/``G1``, dwell
                ``G4 P<seconds>``, end ``M2``.
``"fanuc"``     Plain Fanuc-style lathe code (G code system A): G18 implied (not
                written: the plane selection is an option on many Fanuc lathes),
                X words are diameters (parameter 1006#3 set), X/Z always absolute
                (system A has no G90/G91). ``G00``/``G01``, dwell ``G04 P<ms>``
                (P is an integer in milliseconds; parameter 3405#1 DWL off, so the
                dwell is a time even in G99), ``G21``/``G20`` alone in their own
                block, ``G98``/``G99`` feed per minute / per revolution, ``%`` at
                both ends, optional ``O`` number, end ``M30``.

Mill style: ``"linuxcnc-mill"`` and ``"fanuc-mill"``, the twins of the two
targets for mill-style programs (a grinder's X/Y/Z, ``InputControl.mill``;
chosen by the translator, not by ``--to``): ``G17`` instead of ``G18 G7``
(Fanuc: ``G17 G90 G40`` after the units block), X written as is (not a
diameter), Y words, Fanuc feed modes ``G94``/``G95``; a ``DRESS`` move is the
dress program's call: ``o<dressN> call`` (LinuxCNC: a named subroutine file
``dressN.ngc``), ``M98 PN`` (Fanuc). After the call the output's position,
motion and feed are unknown (the dress program moves the wheel): the next
move writes all of them. A lathe target refuses a move with ``y`` set and a
dress call.

Choices (the manuals leave them open):

* Modal output: G0/G1 is written only when the motion changes; X and Z only
  when their *written text* changes (so no rounding drift and no missing move);
  F only when the written feed text changes, and after a feed-mode code (which
  sets LinuxCNC's F to 0). A move that writes no axis word is
  dropped (it would not move the tool); a feed change it carried is kept as a
  lone ``F`` block.
* Numbers: X, Z, arc words and dwell seconds with 4 decimals in mm and 5 in inch
  for LinuxCNC, 3 and 4 for Fanuc (IS-B least input increment, so a Fanuc
  control never sees more digits than it resolves); F with 6 decimals (feeds per
  revolution in inch need them). Trailing zeros are trimmed but the decimal
  point is always kept (``X80.``): LinuxCNC accepts it and a Fanuc control
  without calculator-type input would read ``X80`` as 0.080 mm. ``-0`` is
  never written. Magnitudes of ``MAX_WORD`` and above, NaN and infinities raise
  ProgramError instead of being written.
* Comments: ``(text)``; parentheses inside the text are dropped, characters
  other than printable ASCII become ``?``, the text is cut to ``MAX_COMMENT``
  characters (and a block to ``MAX_LINE``: LinuxCNC's limit is 252), and a
  text LinuxCNC would execute (``MSG,``, ``DEBUG,``, ``PRINT,``, ``LOG...``,
  ``PROBEOPEN``, ``PY,``, ``ABORT,``, ``AXIS,`` ...) is prefixed with ``- `` so it stays a plain comment.
* Expanded moves never carry line numbers.
* The C axis (GSK G7.1, cylinder interpolation): only the targets with
  ``TargetSpec.c_feed`` write C, in degrees, modal like X and Z, with the
  digits of Z: ``linuxcnc-c`` (a LinuxCNC lathe with a rotary C axis) and
  ``fanuc-c``. The others refuse a move that turns C (``check_axes``). A
  move's F for a move that turns C is in LinuxCNC's reading (along X/Z when
  they move, else degrees per minute): ``linuxcnc-c`` writes it as is;
  ``fanuc-c`` writes the same duration in the reading Fanuc-compatible
  controls document for a linear and rotary move (the path length with
  degrees counted as mm; Mitsubishi M700V manual 7.6), from the position
  written before the move.
"""

import math
import re
from dataclasses import dataclass, replace
from typing import Dict, Iterable, List, Optional

from .errors import ProgramError
from .moves import ARCS, DRESS, DWELL, FEED, RAPID, MachineState, Move
from .numbers import ARC_IJK_TOLERANCE, MAX_DWELL_SECONDS, MAX_WORD, MM_PER_INCH, format_decimal

__all__ = [
    "TARGETS",
    "TargetSpec",
    "Writer",
    "write_moves",
    "write_program",
    "comment",
    "format_number",
    "mill_target",
    "target_spec",
]

TARGETS = ("linuxcnc", "fanuc", "linuxcnc-c", "fanuc-c")
C_FEED_LINEAR = "linear"  # F along X/Z when they move, else degrees per minute (LinuxCNC)
C_FEED_COMPOSITE = "composite"  # F along the path with degrees counted as mm (Fanuc)
MAX_COMMENT = 140
MAX_LINE = 250  # LinuxCNC refuses blocks longer than 252 characters ("Command too long")
FEED_DIGITS = 6
DWELL_DIGITS = 3


@dataclass(frozen=True)
class TargetSpec:
    """What differs between output targets: codes, decimals, units and feed-mode
    codes, the program end, the dwell word, the program frame."""

    name: str
    codes: Dict[str, str]  # move kind -> motion code
    digits_mm: int
    digits_inch: int
    units: Dict[bool, str]  # metric -> code
    feed_modes: Dict[bool, str]  # feed per revolution -> code
    end: str
    dwell_ms: bool  # dwell P in whole milliseconds (else seconds)
    fanuc_style: bool = False  # "%" lines, O number, G18 implied, units and G50 alone in their
    # block, two-digit M codes, whole S words, N up to 99999
    c_feed: Optional[str] = None  # writes the rotary C axis, with F read as C_FEED_*; None: no C axis
    mill: bool = False  # mill style: G17, X a plain coordinate (not a diameter), Y words, dress calls
    dress_call: str = ""  # the subprogram call of a dress program, "%d" its number (mill style)


SPECS = {
    "linuxcnc": TargetSpec(
        "linuxcnc",
        {RAPID: "G0", FEED: "G1", "G2": "G2", "G3": "G3"},
        4,
        5,
        {True: "G21", False: "G20"},
        {False: "G94", True: "G95"},
        "M2",
        False,
    ),
    "fanuc": TargetSpec(
        "fanuc",
        {RAPID: "G00", FEED: "G01", "G2": "G02", "G3": "G03"},
        3,
        4,
        {True: "G21", False: "G20"},
        {False: "G98", True: "G99"},
        "M30",
        True,
        fanuc_style=True,
    ),
}
SPECS["linuxcnc-c"] = replace(SPECS["linuxcnc"], name="linuxcnc-c", c_feed=C_FEED_LINEAR)
SPECS["fanuc-c"] = replace(SPECS["fanuc"], name="fanuc-c", c_feed=C_FEED_COMPOSITE)

# Mill-style twins of the targets (see "Mill style" in the module notes): the
# translator writes them for an input control whose programs are mill-style
# (InputControl.mill), so ``--to linuxcnc`` of a grinder program is a mill program.
MILL_TARGETS = {"linuxcnc": "linuxcnc-mill", "fanuc": "fanuc-mill"}
SPECS["linuxcnc-mill"] = replace(SPECS["linuxcnc"], name="linuxcnc-mill", mill=True, dress_call="o<dress%d> call")
SPECS["fanuc-mill"] = replace(SPECS["fanuc"], name="fanuc-mill", feed_modes={False: "G94", True: "G95"}, mill=True,
                              dress_call="M98 P%d")


def target_spec(target: str) -> TargetSpec:
    """The TargetSpec of ``target`` (a name of TARGETS or its mill twin); ValueError when unknown."""
    try:
        return SPECS[target]
    except KeyError:
        raise ValueError("unknown output target %r (known: %s)" % (target, ", ".join(TARGETS))) from None


def mill_target(target: str) -> str:
    """The mill-style twin of ``target`` ("linuxcnc" -> "linuxcnc-mill"); itself when it is one."""
    target_spec(target)
    return target if SPECS[target].mill else MILL_TARGETS[target]


def format_number(value: float, digits: int = 4) -> str:
    """``value`` with at most ``digits`` decimals, a decimal point always, no ``-0``;
    ProgramError for magnitudes of MAX_WORD and above and NaN."""
    if not -MAX_WORD < value < MAX_WORD:  # also refuses NaN
        raise ProgramError("value %r cannot be written (not a number below %g in magnitude)" % (value, MAX_WORD))
    return format_decimal(value, digits)


_ACTIVE_COMMENT = re.compile(r"(?i)\s*(?:[a-z_]+\s*,|logclose|logopen|logappend|probeopen|probeclose|py\b|abort\b)")
_NOT_PRINTABLE = re.compile(r"[^\x20-\x7e]")


def comment(text: str, limit: int = MAX_COMMENT) -> str:
    """``(text)`` made safe for LinuxCNC and Fanuc (see the module notes); the
    text is cut to ``limit`` characters (ending in ``...``)."""
    text = _NOT_PRINTABLE.sub("?", text.replace("(", "").replace(")", "")).strip()
    if _ACTIVE_COMMENT.match(text):
        text = "- " + text
    if len(text) > limit:
        text = text[: max(0, limit - 3)] + "..."
    return "(" + text + ")"


class Writer:
    """Writes moves for one output target, remembering what is modal in the output.

    State (all of it as *written text*, None = unknown to the output program):
    ``motion`` (RAPID/FEED/"G2"/"G3"), ``x_text`` (diameter), ``z_text``, ``f_text``.
    ``default_feed``: F written on the first feed move when no F is in force in the
    output and the move has none (used by whole-program output).
    """

    def __init__(
        self,
        target: str = "linuxcnc",
        metric: bool = True,
        feed_per_rev: Optional[bool] = None,
        x: Optional[float] = None,
        z: Optional[float] = None,
        feed: Optional[float] = None,
        motion: Optional[str] = None,
        y: Optional[float] = None,
        c: Optional[float] = None,
    ) -> None:
        self.spec = target_spec(target)
        self.target = target
        self.feed_per_rev = feed_per_rev
        self.motion = motion
        self.default_feed: Optional[float] = None
        self.set_units(metric)
        self.sync(x, z, feed, motion, y, c)

    @classmethod
    def from_state(cls, state: MachineState, target: str = "linuxcnc", motion: Optional[str] = None) -> "Writer":
        """A writer whose output is already at ``state`` (position, feed, units)."""
        return cls(target, state.metric, state.feed_per_rev, state.x, state.z, state.feed, motion, state.y, state.c)

    # -- modal state ----------------------------------------------------------

    def set_units(self, metric: bool) -> None:
        """Units of the numbers from now on; the written position is forgotten."""
        self.metric = bool(metric)
        self.digits = self.spec.digits_mm if self.metric else self.spec.digits_inch
        self.x_text = self.y_text = self.z_text = self.f_text = self.c_text = None

    def sync(
        self,
        x: Optional[float] = None,
        z: Optional[float] = None,
        feed: Optional[float] = None,
        motion: Optional[str] = None,
        y: Optional[float] = None,
        c: Optional[float] = None,
    ) -> None:
        """The output is at radius ``x`` (mill style: X ``x``), ``y``, ``z``
        (C at ``c`` degrees) with ``feed`` in force (None = unknown)."""
        self.x_text = None if x is None else self.x_word(x)
        self.y_text = None if y is None else self.z_word(y)
        self.z_text = None if z is None else self.z_word(z)
        self.f_text = None if feed is None else self.f_word(feed)
        self.c_text = None if c is None or not self.spec.c_feed else self.z_word(c)
        self.motion = motion

    # -- words ------------------------------------------------------------------

    def x_word(self, radius: float) -> str:
        """The X word text (a diameter) for a radius; mill style: X as is."""
        return format_number(radius if self.spec.mill else radius * 2.0, self.digits)

    def z_word(self, z: float) -> str:
        """The Z word text."""
        return format_number(z, self.digits)

    def length_word(self, value: float) -> str:
        """A length written as is (arc centre offsets I/K, radius R)."""
        return format_number(value, self.digits)

    def f_word(self, feed: float) -> str:
        """The F word text; ProgramError unless the feed is positive."""
        if not feed > 0:
            raise ProgramError("feed %r cannot be written (must be greater than 0)" % (feed,))
        return format_number(feed, FEED_DIGITS)

    def number(self, value: float, digits: int = 4) -> str:
        """Any other number, with at most ``digits`` decimals."""
        return format_number(value, digits)

    def code(self, kind: str) -> str:
        """The motion code of a move kind."""
        return self.spec.codes[kind]

    def units_code(self, metric: Optional[bool] = None) -> str:
        """G21/G20 for ``metric`` (default: the writer's units)."""
        return self.spec.units[self.metric if metric is None else bool(metric)]

    def feed_mode_code(self, feed_per_rev: bool) -> str:
        """The code of feed per minute or per revolution."""
        return self.spec.feed_modes[bool(feed_per_rev)]

    def set_feed_mode(self, feed_per_rev: bool) -> str:
        """The feed-mode code a block writes; the F in force is forgotten, since
        LinuxCNC sets F to 0 on every G93/G94/G95, even the active one (a block
        that keeps feeding writes F again)."""
        self.feed_per_rev = bool(feed_per_rev)
        self.f_text = None
        return self.feed_mode_code(feed_per_rev)

    def dwell(self, seconds: float) -> str:
        """The dwell block for ``seconds``."""
        if not 0 <= seconds <= MAX_DWELL_SECONDS:
            raise ProgramError("dwell of %r s cannot be written (0 to %g s)" % (seconds, MAX_DWELL_SECONDS))
        if self.spec.dwell_ms:
            return "G04 P%d" % int(round(seconds * 1000.0))
        return "G4 P" + format_number(seconds, DWELL_DIGITS)

    comment = staticmethod(comment)

    # -- blocks -------------------------------------------------------------------

    def header(self, title: Optional[str] = None, program_number: Optional[int] = None) -> List[str]:
        """The lines that open a whole program (modes: G18 and diameter X, mill style
        G17; units, feed mode)."""
        out = []
        s = self.spec
        feed_mode = [] if self.feed_per_rev is None else [s.feed_modes[bool(self.feed_per_rev)]]
        if s.fanuc_style:
            out.append("%")
            if program_number is not None:
                number = "O%04d" % int(program_number)
                out.append(number + (" " + comment(title) if title else ""))
            elif title:
                out.append(comment(title))
            out.append(s.units[self.metric])
            out.append(" ".join((["G17", "G90"] if s.mill else []) + ["G40"] + feed_mode))
        else:
            plane = ["G17"] if s.mill else ["G18", "G7"]
            out.append(" ".join(plane + [s.units[self.metric], "G90", "G91.1", "G40"] + feed_mode))
            if title:
                out.append(comment(title))
        return out

    def footer(self) -> List[str]:
        """The lines that end a whole program."""
        return [self.spec.end, "%"] if self.spec.fanuc_style else [self.spec.end]

    def _feed_text(self, kind: str, f: Optional[float], written: Optional[str]) -> Optional[str]:
        """The F text a move writes (None: none), given the F text in force."""
        if f is not None:
            if not 0 < f < MAX_WORD:
                raise ProgramError("feed %r cannot be written (must be greater than 0)" % (f,))
            text = format_decimal(f, FEED_DIGITS)
            return None if text == written else text
        if kind == FEED and written is None:
            if self.default_feed is None:
                raise ProgramError("feed move with no feed rate (F) in force")
            return self.f_word(self.default_feed)
        return None

    def check_axes(self, move: Move) -> None:
        """ProgramError when ``move`` sets an axis this output has no word for
        (a lathe: Y, C; mill style: C): never drop a motion silently."""
        extra = [name for name, value in zip(("Y", "C"), move[5:]) if value is not None]
        if self.spec.c_feed:
            extra = [name for name in extra if name != "C"]
        if self.spec.mill and "Y" in extra:
            extra.remove("Y")
        if extra:
            with_c = [name for name in TARGETS if SPECS[name].c_feed] if extra == ["C"] else []
            raise ProgramError("a move in %s cannot be written for %s: its output has no %s axis%s"
                               % ("/".join(extra), self.spec.name, "/".join(extra),
                                  " (targets with C: %s)" % ", ".join(with_c) if with_c else ""))

    def _c_feed(self, move: Move) -> Optional[float]:
        """The F of a move that turns C, in the target's reading (the module notes)."""
        f = move.f
        if f is None or self.spec.c_feed != C_FEED_COMPOSITE or move.kind != FEED:
            return f
        if self.x_text is None or self.z_text is None or self.c_text is None:
            raise ProgramError("a feed move in X/Z/C needs its start written before it (the %s feed of a "
                               "rotary move is computed from it)" % self.spec.name)
        linear = math.hypot(move.x - float(self.x_text) / 2.0, move.z - float(self.z_text))
        turn = abs(move.c - float(self.c_text))
        minutes = linear / f if linear > 0 else turn / f
        return math.hypot(linear, turn) / minutes if minutes > 0 else f

    def dress(self, program: int) -> str:
        """The call of the dress subprogram ``program`` (mill style only)."""
        if not self.spec.dress_call:
            raise ProgramError("a dress program call cannot be written for %s: a lathe output" % self.spec.name)
        return self.spec.dress_call % int(program)

    def _dress_here(self, words: List[str], program: int) -> str:
        """The dress call at the position held; afterwards the output's position,
        motion and feed are unknown (the dress program moves the wheel), so the
        next move writes every axis, its motion code and its F."""
        call = self.dress(program)
        if words:
            raise ProgramError("a dress call away from the position held (%s): a move must go there first"
                               % " ".join(words))
        self.x_text = self.y_text = self.z_text = self.f_text = self.motion = None
        return call

    def _written_axes(self, move: Move) -> List[str]:
        """The axis words of ``move`` whose written text changes (X, Z; mill
        style X, Y, Z; with a C axis X, Z, C); the written position is updated.
        check_axes has refused an axis the output has no word for."""
        x, z = move[1], move[2]
        y = move[5] if len(move) > 5 else None
        c = move[6] if len(move) > 6 else None
        scale = 1.0 if self.spec.mill else 2.0
        if not all(-MAX_WORD < value < MAX_WORD for value in (x, z, y, c) if value is not None):
            raise ProgramError("move to X%r Z%r cannot be written (not a number below %g)" % (
                x if x is None else x * scale, z, MAX_WORD))
        words = []
        x_value = None if x is None else x * scale  # None: a Z-only move (Move's x)
        for letter, value, name in (("X", x_value, "x_text"), ("Y", y, "y_text"), ("Z", z, "z_text"),
                                    ("C", c, "c_text")):
            if value is None:
                continue
            text = format_decimal(value, self.digits)
            if text != getattr(self, name):
                words.append(letter + text)
                setattr(self, name, text)
        return words

    def _arc_words(self, move: Move) -> Optional[List[str]]:
        """The end point and centre words of an arc (both axes of its plane, then
        I/K, mill style I/J, or R for an arc given by its radius); None when its
        end is written as its start (an I/K arc would then be a full circle).
        The centre offsets are taken from the start *as written*, so the control
        computes the circle the move means; one the rounding puts off its circle
        by more than ARC_IJK_TOLERANCE is refused."""
        mill = self.spec.mill
        second, second_text, letter = (move.y, self.y_text, "J") if mill else (move.z, self.z_text, "K")
        if self.x_text is None or second_text is None:
            raise ProgramError("an arc needs its start point written before it (%s)" % move.kind)
        if move.x is None or second is None or (move.centre is None and move.radius is None):
            raise ProgramError("an arc needs its end point and its centre or radius (%s)" % move.kind)
        if mill and move.z is not None and format_decimal(move.z, self.digits) != self.z_text:
            raise ProgramError("a helical arc (Z moving in the XY plane) cannot be written")
        scale = 1.0 if mill else 2.0
        ends = (format_number(move.x * scale, self.digits), format_number(second, self.digits))
        if ends == (self.x_text, second_text):
            return None
        x0, s0 = float(self.x_text) / scale, float(second_text)
        words = ["X" + ends[0], ("Y" if mill else "Z") + ends[1]]
        if move.radius is not None:
            words.append("R" + format_number(move.radius, self.digits))
        else:
            offsets = (format_number(move.centre[0] - x0, self.digits), format_number(move.centre[1] - s0, self.digits))
            tolerance = ARC_IJK_TOLERANCE if self.metric else ARC_IJK_TOLERANCE / MM_PER_INCH
            centre = (x0 + float(offsets[0]), s0 + float(offsets[1]))
            start_radius = math.hypot(float(offsets[0]), float(offsets[1]))
            end_radius = math.hypot(float(ends[0]) / scale - centre[0], float(ends[1]) - centre[1])
            if abs(start_radius - end_radius) > tolerance:
                raise ProgramError("%s to X%s %s%s: the end is %.4f off the arc's circle as written"
                                   % (move.kind, ends[0], words[1][0], ends[1], abs(start_radius - end_radius)))
            words += ["I" + offsets[0], letter + offsets[1]]
        self.x_text = ends[0]
        if mill:
            self.y_text = ends[1]
        else:
            self.z_text = ends[1]
        return words

    def write(self, moves: Iterable[Move], prefix: str = "") -> List[str]:
        """Lines for ``moves`` (moves.Move or equal tuples); updates the modal state.

        ``prefix`` is put in front of every line (``"/"`` for block delete).
        """
        out: List[str] = []
        for move in moves:
            kind, x, z, f, p = move[:5]
            self.check_axes(move)
            if kind == DWELL:
                out.append(prefix + self.dwell(p))
                continue
            if move[6:] and move[6] is not None:
                f = self._c_feed(move)  # from the position written before the move
            if kind in ARCS:
                words = self._arc_words(move)
                if words is None:
                    continue  # shorter than the output's resolution: the written position does not change
            else:
                words = self._written_axes(move)
            if kind == DRESS:
                out.append(prefix + self._dress_here(words, p))
                continue
            f_text = self._feed_text(kind, f, self.f_text)
            if f_text is not None:
                self.f_text = f_text
            if words:
                if kind != self.motion:
                    code = self.spec.codes.get(kind)
                    if code is None:
                        raise ProgramError("move kind %r cannot be written" % (kind,))
                    words.insert(0, code)
                    self.motion = kind
                if f_text is not None:
                    words.append("F" + f_text)
                out.append(prefix + " ".join(words))
            elif f_text is not None:
                out.append(prefix + "F" + f_text)
        return out


def write_moves(moves: Iterable[Move], target: str, state: MachineState, motion: Optional[str] = None) -> List[str]:
    """Lines for ``moves`` for output ``target``, dropping the words ``state`` makes redundant.

    ``state`` is a moves.MachineState: the output is at state.x (radius), state.z
    with state.feed in force and state.metric units. ``motion`` is the motion
    (moves.RAPID / moves.FEED) in force, None when unknown.
    """
    return Writer.from_state(state, target, motion).write(moves)


def write_program(
    moves: List[Move],
    target: str,
    state: MachineState,
    title: Optional[str] = None,
    program_number: Optional[int] = None,
    spindle: Optional[float] = None,
) -> str:
    """A whole program: header, a rapid to the start point, ``moves``, end.

    The start point is (state.x, state.z); the tool's position before the
    program is unknown, so the approach writes both axes. state.feed, if set,
    is written on the first feed move that has no F of its own. ``spindle``
    (rpm, optional) starts the spindle clockwise after the header (LinuxCNC
    refuses feed-per-revolution moves with the spindle stopped).
    """
    writer = Writer(target, state.metric, state.feed_per_rev)
    writer.default_feed = state.feed
    lines = writer.header(title, program_number)
    if state.feed_per_rev and spindle is None and any(m.kind == FEED for m in moves):
        raise ProgramError("feed per revolution needs a spindle speed: the spindle would not turn")
    if spindle is not None:
        if not 0 < spindle < MAX_WORD:
            raise ProgramError("spindle speed %r cannot be written" % (spindle,))
        if spindle == int(spindle):
            text = "%d" % spindle
        elif writer.spec.fanuc_style:
            raise ProgramError("spindle speed %r: a Fanuc S word is a whole number" % (spindle,))
        else:
            text = format_number(spindle, 4)
        lines.append(("G97 S%s M03" if writer.spec.fanuc_style else "G97 S%s M3") % text)
    lines.extend(writer.write([Move(RAPID, state.x, state.z, y=state.y)]))
    lines.extend(writer.write(moves))
    lines.extend(writer.footer())
    return "\n".join(lines) + "\n"
