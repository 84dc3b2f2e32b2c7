"""The one writer: moves and machine functions in one target's words and lines.

Everything a program says is written here, in the syntax its
:class:`~.syntax.Target` table declares; the translator, the program
builder and the posts hand over what to say, never how.

Choices (the manuals leave them open):

* Modal output: the motion code is written only when the motion changes;
  X, Y, Z and C only when their *written text* changes (so no rounding drift
  and no missing move); F only when the written feed text changes, and after
  a feed-mode code (which sets LinuxCNC's F to 0). A move that writes no axis
  word is dropped (it would not move the tool); a feed change it carried is
  kept as a lone ``F`` block. ``programmed`` writes a block's words as the
  program gave them instead (every axis it names).
* Numbers: lengths with the target's decimals (``Target.digits``, or the
  posts' ``--precision``), F with ``Target.feed_digits``; trailing zeros
  trimmed but the decimal point kept (``X80.``: a Fanuc control without
  calculator-type input reads ``X80`` as 0.080 mm); ``-0`` never written;
  magnitudes of ``MAX_WORD`` and above, NaN and infinities refused
  (ProgramError), never written.
* Arcs: G2/G3 with both end words of their plane and the centre from the
  start *as written* (I/K, mill I/J: the control then computes the circle the
  move means; one the rounding puts off its circle by more than
  ARC_IJK_TOLERANCE is refused), or Siemens ``CR=`` (negative above 180
  degrees); an arc programmed with its radius keeps it (``R``, ``CR=``) where
  the target has that word. An arc whose end is written as its start is not
  written (an I/K arc would be a full circle).
* Comments: the target's form, ``(text)`` or ``; text``; parentheses inside
  the text dropped, characters other than printable ASCII made ``?``, cut to
  ``MAX_COMMENT`` characters (a block to ``MAX_LINE``: LinuxCNC's limit is
  252); a text LinuxCNC would execute (``MSG,``, ``DEBUG,``, ``PRINT,``,
  ``LOG...``, ``PROBEOPEN``, ``PY,``, ``ABORT,`` ...) is prefixed with
  ``- `` so it stays a plain comment.
* The C axis (GSK G7.1): only a target with ``c_feed`` writes C, in degrees,
  modal like X and Z, with the digits of Z. A move's F for a move that turns C
  is in LinuxCNC's reading (along X/Z when they move, else degrees per
  minute): C_FEED_LINEAR writes it as is; C_FEED_COMPOSITE the same duration
  in the reading Fanuc-compatible controls document (the path length with
  degrees counted as mm; Mitsubishi M700V manual 7.6), from the position
  written before the move.
"""

import math
from typing import Iterable, List, Optional, Tuple, Union

from ..errors import ProgramError
from ..moves import ARCS, DRESS, DWELL, FEED, RAPID, MachineState, Move
from ..numbers import ARC_IJK_TOLERANCE, MAX_WORD, MM_PER_INCH, format_decimal
from .arcs import centre_of, signed_radius
from .machine_words import MachineWords
from .syntax import ARC_CR, C_FEED_COMPOSITE, Target
from .targets import TARGETS, target_named
from .words import MAX_COMMENT, MAX_LINE, comment_text, format_number

__all__ = ["MAX_COMMENT", "MAX_LINE", "Writer", "comment_text", "format_number"]


class Writer(MachineWords):
    """Writes moves and machine functions for one target, remembering what is
    modal in the output.

    State (as *written text*, None = unknown to the output program):
    ``motion`` (the move kind in force), ``x_text``, ``y_text``, ``z_text``,
    ``c_text``, ``f_text``. ``default_feed``: F written on the first feed
    move when no F is in force and the move has none (whole programs).

    Lengths handed over are radii (X of a lathe; mill style: plain X) in the
    caller's unit, times ``scale`` in the output's (the posts: mm, written in
    inches with ``scale`` 1/25.4); X is written as a diameter unless
    ``x_diameter`` is False (or the target is a mill). ``digits`` overrides the
    target's decimals of lengths (the posts' ``--precision``).
    """

    def __init__(self, target: Union[str, Target] = "linuxcnc", metric: bool = True,
                 feed_per_rev: Optional[bool] = None, x: Optional[float] = None, z: Optional[float] = None,
                 feed: Optional[float] = None, motion: Optional[str] = None, y: Optional[float] = None,
                 c: Optional[float] = None, *, digits: Optional[int] = None, x_diameter: bool = True,
                 scale: float = 1.0) -> None:
        self.target = target if isinstance(target, Target) else target_named(target)
        self.x_diameter = x_diameter and not self.target.mill
        self.scale = scale
        self.x_factor = scale * (2.0 if self.x_diameter else 1.0)
        self.fixed_digits = digits
        self.feed_per_rev = feed_per_rev
        self.default_feed: Optional[float] = None
        self.set_units(metric)
        self.sync(x, z, feed, motion, y, c)

    @classmethod
    def from_state(cls, state: MachineState, target: Union[str, Target] = "linuxcnc",
                   motion: Optional[str] = None) -> "Writer":
        """A writer whose output is already at ``state`` (position, feed, units)."""
        return cls(target, state.metric, state.feed_per_rev, state.x, state.z, state.feed, motion, state.y, state.c)

    # -- modal state ----------------------------------------------------------

    def set_units(self, metric: bool) -> None:
        """Units of the numbers from now on; the written position and feed are forgotten."""
        self.metric = bool(metric)
        self.digits = self.target.digits(self.metric) if self.fixed_digits is None else self.fixed_digits
        self.x_text = self.y_text = self.z_text = self.f_text = self.c_text = None
        # write()'s texts of the X, Y, Z, C and F values met (value -> text), kept from call to call (a post
        # writes each groove with a call of its own): valid for these digits only
        self.texts: Tuple[dict, dict, dict, dict, dict] = ({}, {}, {}, {}, {})

    def sync(self, x: Optional[float] = None, z: Optional[float] = None, feed: Optional[float] = None,
             motion: Optional[str] = None, y: Optional[float] = None, c: Optional[float] = None) -> None:
        """The output is at ``x`` (a radius; mill style: X), ``y``, ``z`` (C at ``c``
        degrees) with ``feed`` in force and ``motion`` (None = unknown)."""
        self.x_text = None if x is None else self.x_word(x)
        self.y_text = None if y is None else self.z_word(y)
        self.z_text = None if z is None else self.z_word(z)
        self.f_text = None if feed is None else self.f_word(feed)
        self.c_text = None if c is None or not self.target.c_feed else self.number(c, self.digits)
        self.motion = motion

    def forget(self, position: bool = True, motion: bool = True, feed: bool = True) -> None:
        """The output no longer knows the position / the motion in force / the feed."""
        if position:
            self.x_text = self.y_text = self.z_text = self.c_text = None
        if motion:
            self.motion = None
        if feed:
            self.f_text = None

    # -- words ------------------------------------------------------------------

    def x_word(self, x: float) -> str:
        """The X word's text for a radius (a diameter unless radius mode; mill style: X as is)."""
        return format_number(x * self.x_factor, self.digits)

    def z_word(self, z: float) -> str:
        """The text of a Z (or Y) word."""
        return format_number(z * self.scale, self.digits)

    y_word = z_word

    def length_word(self, value: float) -> str:
        """A length written as is (arc centre offsets, radii, cycle words in the output's units)."""
        return format_number(value * self.scale, self.digits)

    def written_x(self, x: float) -> float:
        """The radius (mill style: X) the control reads from the X word of ``x``, in the output's units."""
        return float(self.x_word(x)) * self.scale / self.x_factor

    def f_word(self, feed: float) -> str:
        """The F word's text; ProgramError unless the feed is positive."""
        if not 0 < feed < MAX_WORD:
            raise ProgramError("feed %r cannot be written (must be greater than 0)" % (feed,))
        return format_number(feed * self.scale, self.target.feed_digits)

    def feed_word(self, feed: float) -> str:
        """``F..``: the feed word."""
        return "F" + self.f_word(feed)

    def number(self, value: float, digits: int = 4) -> str:
        """Any other number, with at most ``digits`` decimals."""
        return format_number(value, digits)

    def code(self, kind: str) -> str:
        """The motion code of a move kind."""
        code = self.target.motion_codes.get(kind)
        if code is None:
            raise ProgramError("move kind %r cannot be written" % (kind,))
        return code

    # -- moves --------------------------------------------------------------------

    def check_axes(self, move: Move) -> None:
        """ProgramError when ``move`` sets an axis this output has no word for
        (a lathe: Y, C; mill style: C): never drop a motion silently."""
        extra = []
        if move.y is not None and not self.target.mill:
            extra.append("Y")
        if move.c is not None and not self.target.c_feed:
            extra.append("C")
        if extra:
            with_c = [name for name, target in TARGETS.items() if target.c_feed] if extra == ["C"] else []
            raise ProgramError("a move in %s cannot be written for %s: its output has no %s axis%s"
                               % ("/".join(extra), self.target.name, "/".join(extra),
                                  " (targets with C: %s)" % ", ".join(with_c) if with_c else ""))

    def _scaled(self, move: Move) -> Move:
        """The move in the output's units (``scale``: mm handed over, inches written)."""
        s = self.scale
        return move._replace(
            x=None if move.x is None else move.x * s, z=None if move.z is None else move.z * s,
            f=None if move.f is None else move.f * s, y=None if move.y is None else move.y * s,
            centre=None if move.centre is None else (move.centre[0] * s, move.centre[1] * s),
            radius=None if move.radius is None else move.radius * s)

    def _feed_text(self, kind: str, f: Optional[float]) -> Optional[str]:
        """The F text a move writes (None: none), given the F text in force."""
        if f is not None:
            if not 0 < f < MAX_WORD:
                raise ProgramError("feed %r cannot be written (must be greater than 0)" % (f,))
            text = format_decimal(f, self.target.feed_digits)
            return None if text == self.f_text else text
        if kind != RAPID and self.f_text is None:
            if self.default_feed is None:
                raise ProgramError("feed move with no feed rate (F) in force")
            return format_number(self.default_feed, self.target.feed_digits)
        return None

    def _c_feed(self, move: Move) -> Optional[float]:
        """The F of a move that turns C, in the target's reading (the module notes)."""
        f = move.f
        if f is None or self.target.c_feed != C_FEED_COMPOSITE or move.kind != FEED:
            return f
        start = self._c_start((self.x_text, self.z_text, self.c_text))
        x_factor = self.x_factor / self.scale
        end = tuple(text if value is None else format_decimal(value, self.digits)
                    for value, text in ((None if move.x is None else move.x * x_factor, start[0]),
                                        (move.z, start[1]), (move.c, start[2])))
        return _composite_feed(f, start, end, x_factor)

    def _c_start(self, start: tuple) -> tuple:
        """``start``, the X, Z and C texts written before a feed move in X/Z/C; ProgramError when one is not known."""
        if None in start:
            raise ProgramError("a feed move in X/Z/C needs its start written before it (the %s feed of a "
                               "rotary move is computed from it)" % self.target.name)
        return start

    def _axis_words(self, move: Move, force: bool = False) -> List[str]:
        """The axis words of ``move`` whose written text changes (all it sets
        with ``force``); the written position is updated."""
        words = []
        x_factor = self.x_factor / self.scale  # the move is in the output's units already
        for letter, value, name, factor in (("X", move.x, "x_text", x_factor), ("Y", move.y, "y_text", 1.0),
                                            ("Z", move.z, "z_text", 1.0), ("C", move.c, "c_text", 1.0)):
            if value is None:
                continue
            if not -MAX_WORD < value * factor < MAX_WORD:
                raise ProgramError("move to %s%r cannot be written (not a number below %g)"
                                   % (letter, value * factor, MAX_WORD))
            text = format_decimal(value * factor, self.digits)
            if force or text != getattr(self, name):
                words.append(letter + text)
                setattr(self, name, text)
        return words

    def _arc_words(self, move: Move, programmed: bool = False) -> Optional[List[str]]:
        """The words of an arc after its code (see the module notes); None when
        its end is written as its start. ``programmed``: a program's arc block,
        its axis words as programmed (None: not programmed, at the start), and
        written even when it ends where it starts (a full circle)."""
        mill = self.target.mill
        second, second_text, letter = (move.y, self.y_text, "J") if mill else (move.z, self.z_text, "K")
        if self.x_text is None or second_text is None:
            raise ProgramError("an arc needs its start point written before it (%s)" % move.kind)
        if (move.centre is None and move.radius is None) or (not programmed and (move.x is None or second is None)):
            raise ProgramError("an arc needs its end point and its centre or radius (%s)" % move.kind)
        if mill and move.z is not None and format_decimal(move.z, self.digits) != self.z_text:
            raise ProgramError("a helical arc (Z moving in the XY plane) cannot be written")
        x_factor = self.x_factor / self.scale
        ends = (self.x_text if move.x is None else format_number(move.x * x_factor, self.digits),
                second_text if second is None else format_number(second, self.digits))
        if ends == (self.x_text, second_text) and not programmed:
            return None
        start = (float(self.x_text) / x_factor, float(second_text))
        end = (float(ends[0]) / x_factor, float(ends[1]))
        words = ([] if move.x is None else ["X" + ends[0]]) + ([] if second is None else
                                                               [("Y" if mill else "Z") + ends[1]])
        words += self._circle_words(move, start, end, letter)
        self.x_text = ends[0]
        if mill:
            self.y_text = ends[1]
        else:
            self.z_text = ends[1]
        return words

    def _circle_words(self, move: Move, start: tuple, end: tuple, letter: str) -> List[str]:
        """The words that give an arc's circle from its start and end as written."""
        target = self.target
        if move.radius is not None and target.arc_radius_word:
            return [target.arc_radius_word + format_number(move.radius, self.digits)]
        mill = target.mill
        centre = move.centre if move.centre is not None else centre_of(move, start, end, mill)
        if target.arc_form == ARC_CR:
            return [target.arc_radius_word + format_number(signed_radius(move, start, end, centre, mill),
                                                           self.digits)]
        offsets = (format_number(centre[0] - start[0], self.digits), format_number(centre[1] - start[1], self.digits))
        written = (start[0] + float(offsets[0]), start[1] + float(offsets[1]))
        off = abs(math.hypot(float(offsets[0]), float(offsets[1])) - math.dist(end, written))
        if off > (ARC_IJK_TOLERANCE if self.metric else ARC_IJK_TOLERANCE / MM_PER_INCH):
            raise ProgramError("%s: the arc's end is %.4f off its circle as written" % (move.kind, off))
        return ["I" + offsets[0], letter + offsets[1]]

    def write(self, moves: Iterable[Move], prefix: str = "") -> List[str]:
        """Lines for ``moves`` (moves.Move); updates the modal state; ``prefix`` before every line (``"/"``:
        block delete). Straight moves are written inline, the words ``_move_lines`` writes, each axis's text
        formatted once per value (``texts``: value -> text, kept while the units are); the rest goes the
        general way (``_general``)."""
        if self.scale != 1.0:
            return [prefix + line for move in moves for line in self._move_lines(move, False)]
        out: List[str] = []
        append, codes, target = out.append, self.target.motion_codes, self.target
        fmt, f_fmt, x_factor = "%%.%df" % self.digits, "%%.%df" % target.feed_digits, self.x_factor
        y_ok, c_ok, c_composite = target.mill, target.c_feed is not None, target.c_feed == C_FEED_COMPOSITE
        (xs, ys, zs, cs, fs), (x_text, y_text, z_text, c_text, f_text, motion) = self.texts, self._modal()
        fast = True
        try:
            for move in moves:
                kind, x, z, f, _p, y, c, _centre, _radius = move
                if not (kind == FEED or kind == RAPID) or (y is not None and not y_ok) or (c is not None
                                                                                and not c_ok):
                    fast = False  # the state is the general way's, also after an error
                    x_text, y_text, z_text, c_text, f_text, motion = self._general(
                        move, prefix, out, (x_text, y_text, z_text, c_text, f_text, motion))
                    fast = True
                    continue
                composite = c_composite and c is not None and kind == FEED and f is not None
                start = composite and self._c_start((x_text, z_text, c_text))  # the feed: from start to end written
                line = ""
                if x is not None:
                    text = xs.get(x) or _axis_text(xs, x, "X", x * x_factor, fmt)
                    if text != x_text:
                        x_text, line = text, " X" + text
                if y is not None:
                    text = ys.get(y) or _axis_text(ys, y, "Y", y, fmt)
                    if text != y_text:
                        y_text, line = text, line + " Y" + text
                if z is not None:
                    text = zs.get(z) or _axis_text(zs, z, "Z", z, fmt)
                    if text != z_text:
                        z_text, line = text, line + " Z" + text
                if c is not None:
                    text = cs.get(c) or _axis_text(cs, c, "C", c, fmt)
                    if text != c_text:
                        c_text, line = text, line + " C" + text
                if composite:
                    f = _composite_feed(f, start, (x_text, z_text, c_text), x_factor)
                if line and kind != motion:
                    line = " " + codes[kind] + line
                    motion = kind
                if f is not None:
                    text = fs.get(f) or _feed_text(fs, f, f_fmt)
                    if text != f_text:
                        f_text, line = text, line + " F" + text
                elif kind == FEED and f_text is None:
                    f_text = self._default_feed_text()
                    line += " F" + f_text
                if line:
                    append(prefix + line[1:])
        finally:
            if fast:
                self._set_modal(x_text, y_text, z_text, c_text, f_text, motion)
        return out

    def _general(self, move: Move, prefix: str, out: List[str], modal: tuple) -> tuple:
        """``move`` written the general way (arcs, dwells, dress calls, an axis the
        target lacks: refused there) after the modal state ``modal``; the state after it."""
        self._set_modal(*modal)
        try:
            out.extend(prefix + line for line in self._move_lines(move, False))
        finally:  # also what it wrote before an error
            modal = self._modal()
        return modal

    def _default_feed_text(self) -> str:
        """The F text of a feed move with no F in force: the default feed's."""
        if self.default_feed is None:
            raise ProgramError("feed move with no feed rate (F) in force")
        return format_number(self.default_feed, self.target.feed_digits)

    def _modal(self) -> tuple:
        """The modal state as written: x, y, z, c, f texts and the motion."""
        return self.x_text, self.y_text, self.z_text, self.c_text, self.f_text, self.motion

    def _set_modal(self, x_text, y_text, z_text, c_text, f_text, motion) -> None:
        self.x_text, self.y_text, self.z_text, self.c_text, self.f_text, self.motion = (
            x_text, y_text, z_text, c_text, f_text, motion)

    def programmed(self, move: Move, explicit: bool = False) -> List[str]:
        """The words of a program's motion block as programmed: every axis the
        move sets (None: not programmed), the code when ``explicit`` or when the
        motion changes, the arc's words; F is the caller's."""
        return self._move_words(move, True, explicit)

    def programmed_line(self, move: Move, what: str = "feed move") -> List[str]:
        """The line of one programmed move (a FreeCAD Path command): its code,
        every axis it sets, its arc words and F when that changes; ProgramError
        naming ``what`` when it feeds with no F in force."""
        self.check_axes(move)
        if self.scale != 1.0:
            move = self._scaled(move)
        words = self._move_words(move, True, True) or []
        try:
            f_text = self._feed_text(move.kind, move.f)
        except ProgramError:
            raise ProgramError("%s with no feed rate (F) in force" % what) from None
        if f_text is not None:
            self.f_text = f_text
            words.append("F" + f_text)
        return [" ".join(words)] if words else []

    def move(self, kind: str, x: Optional[float] = None, z: Optional[float] = None, f: Optional[float] = None,
             force: bool = False) -> List[str]:
        """Lines for one RAPID/FEED move to the given axes (None: not written);
        ``force``: every given axis and the code written."""
        return self._move_lines(Move(kind, x, z, f), force)

    def _move_lines(self, move: Move, force: bool) -> List[str]:
        self.check_axes(move)
        if self.scale != 1.0:
            move = self._scaled(move)
        kind = move.kind
        if kind == DWELL:
            return [self.dwell(move.p)]
        if kind == DRESS:
            return [self._dress_here(self._axis_words(move), int(move.p))]
        f = self._c_feed(move) if move.c is not None else move.f
        words = self._move_words(move, force, force)
        if words is None:
            return []
        f_text = self._feed_text(kind, f)
        if f_text is not None:
            self.f_text = f_text
            words.append("F" + f_text)
        return [" ".join(words)] if words else []

    def _move_words(self, move: Move, force: bool, explicit: bool) -> Optional[List[str]]:
        """The motion code and axis (and arc) words; [] when no axis changes
        (an F alone may follow), None for an arc too short to write."""
        kind = move.kind
        if kind in ARCS:
            words = self._arc_words(move, force)
            if words is None:
                return None
        else:
            words = self._axis_words(move, force)
        if words and (explicit or kind != self.motion):
            words.insert(0, self.code(kind))
            self.motion = kind
        return words

    def dress(self, program: int) -> str:
        """The call of the dress subprogram ``program`` (mill style only)."""
        if not self.target.dress_call:
            raise ProgramError("a dress program call cannot be written for %s: its call is not known"
                               % self.target.name)
        return self.target.dress_call % int(program)

    def _dress_here(self, words: List[str], program: int) -> str:
        """The dress call at the position held; afterwards the output's position,
        motion and feed are unknown (the dress program moves the wheel), so the
        next move writes every axis, its motion code and its F."""
        call = self.dress(program)
        if words:
            raise ProgramError("a dress call away from the position held (%s): a move must go there first"
                               % " ".join(words))
        self.forget()
        return call



CACHED_TEXTS = 1024  # the texts of this many values of an axis are kept (Writer.texts), then dropped


def _axis_text(cache: dict, value: float, letter: str, scaled: float, fmt: str) -> str:
    """The text of an axis word's number ``scaled`` (``fmt``: "%.4f") as
    format_number writes it, kept in ``cache`` under ``value``; ProgramError
    for magnitudes of MAX_WORD and above and NaN."""
    if not -MAX_WORD < scaled < MAX_WORD:
        raise ProgramError("move to %s%r cannot be written (not a number below %g)" % (letter, scaled, MAX_WORD))
    text = (fmt % scaled).rstrip("0")
    if len(cache) >= CACHED_TEXTS:
        cache.clear()
    cache[value] = text = "0." if text == "-0." else text
    return text


def _feed_text(cache: dict, feed: float, fmt: str) -> str:
    """The text of an F word's number, kept in ``cache``; ProgramError unless the feed is positive."""
    if not 0 < feed < MAX_WORD:
        raise ProgramError("feed %r cannot be written (must be greater than 0)" % (feed,))
    if len(cache) >= CACHED_TEXTS:
        cache.clear()
    cache[feed] = text = (fmt % feed).rstrip("0")
    return text


def _composite_feed(f: float, start: tuple, end: tuple, x_factor: float) -> float:
    """The F of a feed in X/Z/C along its composite path (degrees counted as mm)
    lasting as long as F ``f`` in LinuxCNC's reading, from the texts written at
    its ``start`` to those at its ``end`` (X, Z, C), as the control reads the
    move: a radius 0.71000000000000001 written X1.42 again does not move X (its
    float residue would make the linear length 1e-16 and the feed 1e+20)."""
    dx = (float(end[0]) - float(start[0])) / x_factor
    dz = float(end[1]) - float(start[1])
    linear = math.hypot(dx, dz)
    turn = abs(float(end[2]) - float(start[2]))
    minutes = linear / f if linear > 0 else turn / f
    return math.hypot(linear, turn) / minutes if minutes > 0 else f
