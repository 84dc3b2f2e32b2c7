"""Writers of expanded output: moves.Move lists to G-code text.

Two targets:

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

Choices (the manuals leave them open):

* Modal output: G0/G1 is written only when the motion changes; X and Z only
  when their *written text* changes (so no rounding drift and no missing move);
  F only when the written feed text changes. A move that writes no axis word is
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
  characters (and a block to ``MAX_LINE``: LinuxCNC's limit is 252), and a text LinuxCNC would execute (``MSG,``, ``DEBUG,``,
  ``PRINT,``, ``LOG...``, ``PROBEOPEN``, ``PY,``, ``ABORT,``, ``AXIS,`` ...) is
  prefixed with ``- `` so it stays a plain comment.
* Expanded moves never carry line numbers.
"""

import re

from .errors import ProgramError
from .moves import DWELL, FEED, RAPID

__all__ = [
    "TARGETS",
    "Writer",
    "write_moves",
    "write_program",
    "comment",
    "format_number",
]

TARGETS = ("linuxcnc", "fanuc")
MAX_WORD = 1.0e6
MAX_COMMENT = 140
MAX_LINE = 250  # LinuxCNC refuses blocks longer than 252 characters ("Command too long")
MAX_DWELL = 99999.0  # seconds (Fanuc: P at most 8 digits of ms)


class _Spec:
    def __init__(self, name, codes, digits_mm, digits_inch, units, feed_modes, end, dwell_ms):
        self.name = name
        self.codes = codes
        self.digits_mm = digits_mm
        self.digits_inch = digits_inch
        self.units = units  # {metric: code}
        self.feed_modes = feed_modes  # {feed_per_rev: code}
        self.end = end
        self.dwell_ms = dwell_ms


_SPECS = {
    "linuxcnc": _Spec(
        "linuxcnc",
        {RAPID: "G0", FEED: "G1", "G2": "G2", "G3": "G3"},
        4,
        5,
        {True: "G21", False: "G20"},
        {False: "G94", True: "G95"},
        "M2",
        False,
    ),
    "fanuc": _Spec(
        "fanuc",
        {RAPID: "G00", FEED: "G01", "G2": "G02", "G3": "G03"},
        3,
        4,
        {True: "G21", False: "G20"},
        {False: "G98", True: "G99"},
        "M30",
        True,
    ),
}

FEED_DIGITS = 6


def spec(target):
    try:
        return _SPECS[target]
    except KeyError:
        raise ValueError("unknown output dialect %r (known: %s)" % (target, ", ".join(TARGETS))) from None


def _number(fmt, value):
    if not -MAX_WORD < value < MAX_WORD:  # also refuses NaN
        raise ProgramError("value %r cannot be written (not a number below %g in magnitude)" % (value, MAX_WORD))
    text = (fmt % value).rstrip("0")
    return "0." if text == "-0." else text


def format_number(value, digits=4):
    """``value`` with at most ``digits`` decimals, a decimal point always, no ``-0``."""
    return _number("%%.%df" % digits, value)


_ACTIVE_COMMENT = re.compile(r"(?i)\s*(?:[a-z_]+\s*,|logclose|logopen|logappend|probeopen|probeclose|py\b|abort\b)")
_NOT_PRINTABLE = re.compile(r"[^\x20-\x7e]")


def comment(text, limit=MAX_COMMENT):
    """``(text)`` made safe for LinuxCNC and Fanuc (see the module notes); the
    text is cut to ``limit`` characters (ending in ``...``)."""
    text = _NOT_PRINTABLE.sub("?", text.replace("(", "").replace(")", "")).strip()
    if _ACTIVE_COMMENT.match(text):
        text = "- " + text
    if len(text) > limit:
        text = text[: max(0, limit - 3)] + "..."
    return "(" + text + ")"


class Writer:
    """Writes moves for one output dialect, remembering what is modal in the output.

    State (all of it as *written text*, None = unknown to the output program):
    ``motion`` (RAPID/FEED/"G2"/"G3"), ``x_text`` (diameter), ``z_text``, ``f_text``.
    ``default_feed``: F written on the first feed move when no F is in force in the
    output and the move has none (used by whole-program output).
    """

    def __init__(self, target="linuxcnc", metric=True, feed_per_rev=None, x=None, z=None, feed=None, motion=None):
        self.spec = spec(target)
        self.target = target
        self.feed_per_rev = feed_per_rev
        self.motion = motion
        self.default_feed = None
        self.set_units(metric)
        self.sync(x, z, feed, motion)

    @classmethod
    def from_state(cls, state, target="linuxcnc", motion=None):
        """A writer whose output is already at ``state`` (position, feed, units)."""
        return cls(target, state.metric, state.feed_per_rev, state.x, state.z, state.feed, motion)

    # -- modal state ----------------------------------------------------------

    def set_units(self, metric):
        """Units of the numbers from now on; the written position is forgotten."""
        self.metric = bool(metric)
        digits = self.spec.digits_mm if self.metric else self.spec.digits_inch
        self.digits = digits
        self._cfmt = "%%.%df" % digits
        self._ffmt = "%%.%df" % FEED_DIGITS
        self.x_text = self.z_text = self.f_text = None

    def sync(self, x=None, z=None, feed=None, motion=None):
        """The output is at radius ``x``, ``z`` with ``feed`` in force (None = unknown)."""
        self.x_text = None if x is None else self.x_word(x)
        self.z_text = None if z is None else self.z_word(z)
        self.f_text = None if feed is None else self.f_word(feed)
        self.motion = motion

    # -- words ------------------------------------------------------------------

    def x_word(self, radius):
        """The X word text (a diameter) for a radius."""
        return _number(self._cfmt, radius * 2.0)

    def z_word(self, z):
        return _number(self._cfmt, z)

    def length_word(self, value):
        """A length written as is (arc centre offsets I/K, radius R)."""
        return _number(self._cfmt, value)

    def f_word(self, feed):
        if not feed > 0:
            raise ProgramError("feed %r cannot be written (must be greater than 0)" % (feed,))
        return _number(self._ffmt, feed)

    def number(self, value, digits=4):
        return format_number(value, digits)

    def code(self, kind):
        return self.spec.codes[kind]

    def units_code(self, metric=None):
        return self.spec.units[self.metric if metric is None else bool(metric)]

    def feed_mode_code(self, feed_per_rev):
        return self.spec.feed_modes[bool(feed_per_rev)]

    def dwell(self, seconds):
        """The dwell block for ``seconds``."""
        if not 0 <= seconds <= MAX_DWELL:
            raise ProgramError("dwell of %r s cannot be written (0 to %g s)" % (seconds, MAX_DWELL))
        if self.spec.dwell_ms:
            return "G04 P%d" % int(round(seconds * 1000.0))
        return "G4 P" + _number("%.3f", seconds)

    comment = staticmethod(comment)

    # -- blocks -------------------------------------------------------------------

    def header(self, title=None, program_number=None):
        """The lines that open a whole program (modes: G18, diameter X, units, feed mode)."""
        out = []
        s = self.spec
        if s.name == "fanuc":
            out.append("%")
            if program_number is not None:
                number = "O%04d" % int(program_number)
                out.append(number + (" " + comment(title) if title else ""))
            elif title:
                out.append(comment(title))
            out.append(s.units[self.metric])
            modes = ["G40"]
            if self.feed_per_rev is not None:
                modes.append(s.feed_modes[bool(self.feed_per_rev)])
            out.append(" ".join(modes))
        else:
            modes = ["G18", "G7", s.units[self.metric], "G90", "G91.1", "G40"]
            if self.feed_per_rev is not None:
                modes.append(s.feed_modes[bool(self.feed_per_rev)])
            out.append(" ".join(modes))
            if title:
                out.append(comment(title))
        return out

    def footer(self):
        """The lines that end a whole program."""
        if self.spec.name == "fanuc":
            return ["M30", "%"]
        return ["M2"]

    def write(self, moves, prefix=""):
        """Lines for ``moves`` (moves.Move or equal tuples); updates the modal state.

        ``prefix`` is put in front of every line (``"/"`` for block delete).
        """
        out = []
        add = out.append
        codes = self.spec.codes
        cfmt = self._cfmt
        ffmt = self._ffmt
        lim = MAX_WORD
        motion = self.motion
        xt = self.x_text
        zt = self.z_text
        ft = self.f_text
        try:
            for kind, x, z, f, p in moves:
                if kind == DWELL:
                    add(prefix + self.dwell(p))
                    continue
                if not (-lim < x < lim and -lim < z < lim):
                    raise ProgramError("move to X%r Z%r cannot be written (not a number below %g)" % (x * 2.0, z, lim))
                words = []
                t = (cfmt % (x * 2.0)).rstrip("0")
                if t == "-0.":
                    t = "0."
                if t != xt:
                    words.append("X" + t)
                    xt = t
                t = (cfmt % z).rstrip("0")
                if t == "-0.":
                    t = "0."
                if t != zt:
                    words.append("Z" + t)
                    zt = t
                if f is not None:
                    if not 0 < f < lim:
                        raise ProgramError("feed %r cannot be written (must be greater than 0)" % (f,))
                    t = (ffmt % f).rstrip("0")
                    if t != ft:
                        fword = "F" + t
                        ft = t
                    else:
                        fword = None
                elif kind == FEED and ft is None:
                    if self.default_feed is None:
                        raise ProgramError("feed move with no feed rate (F) in force")
                    ft = self.f_word(self.default_feed)
                    fword = "F" + ft
                else:
                    fword = None
                if words:
                    if kind != motion:
                        code = codes.get(kind)
                        if code is None:
                            raise ProgramError("move kind %r cannot be written" % (kind,))
                        words.insert(0, code)
                        motion = kind
                    if fword:
                        words.append(fword)
                    add(prefix + " ".join(words))
                elif fword:
                    add(prefix + fword)
        finally:
            self.motion = motion
            self.x_text = xt
            self.z_text = zt
            self.f_text = ft
        return out


def write_moves(moves, dialect, state, motion=None):
    """Lines for ``moves`` in output ``dialect``, dropping the words ``state`` makes redundant.

    ``state`` is a moves.MachineState: the output is at state.x (radius), state.z
    with state.feed in force and state.metric units. ``motion`` is the motion
    (moves.RAPID / moves.FEED) in force, None when unknown.
    """
    return Writer.from_state(state, dialect, motion).write(moves)


def write_program(moves, dialect, state, title=None, program_number=None, spindle=None):
    """A whole program: header, a rapid to the start point, ``moves``, end.

    The start point is (state.x, state.z); the tool's position before the
    program is unknown, so the approach writes both axes. state.feed, if set,
    is written on the first feed move that has no F of its own. ``spindle``
    (rpm, optional) starts the spindle clockwise after the header (LinuxCNC
    refuses feed-per-revolution moves with the spindle stopped).
    """
    writer = Writer(dialect, state.metric, state.feed_per_rev)
    writer.default_feed = state.feed
    lines = writer.header(title, program_number)
    if state.feed_per_rev and spindle is None and any(m[0] == FEED for m in moves):
        raise ProgramError("feed per revolution needs a spindle speed: the spindle would not turn")
    if spindle is not None:
        if not 0 < spindle < MAX_WORD:
            raise ProgramError("spindle speed %r cannot be written" % (spindle,))
        if spindle == int(spindle):
            text = "%d" % spindle
        elif dialect == "fanuc":
            raise ProgramError("spindle speed %r: a Fanuc S word is a whole number" % (spindle,))
        else:
            text = _number("%.4f", spindle)
        lines.append(("G97 S%s M03" if dialect == "fanuc" else "G97 S%s M3") % text)
    lines.extend(writer.write([(RAPID, state.x, state.z, None, 0.0)]))
    lines.extend(writer.write(moves))
    lines.extend(writer.footer())
    return "\n".join(lines) + "\n"
