"""The posts' line writer: the engine's target writer with a control's codes, dwell, precision, X mode and units.

Everything handed to it is in mm (lengths, radii) and mm/min or mm/rev (feeds);
with ``inches`` every number it writes is divided by 25.4 (feeds too: in/min,
in/rev)."""

import math
from typing import Iterable, List, Optional

from ...engine import FEED, ProgramError
from ...engine.moves import ARC_CCW, ARCS, Move
from ...engine.numbers import MAX_DWELL_SECONDS, MM_PER_INCH, format_decimal
from ...engine.targets import TargetSpec, Writer
from .controls import Control


class LatheWriter(Writer):
    """targets.Writer with a control's codes, dwell, precision and X mode.

    ``move`` writes single-axis and partial moves (the op's link rapids, other
    ops' Paths), ``arc`` arcs; ``write`` (the engine's move lists) is the
    target writer's own."""

    def __init__(self, control: Control, precision: int, diameter: bool, inches: bool = False) -> None:
        self.control = control
        self.diameter = diameter
        self.inches = inches
        super().__init__("linuxcnc", True, False)  # a target to start from: the control's own spec replaces it
        self.spec = TargetSpec(control.name, dict(control.codes), precision, precision,
                               {True: control.units(False), False: control.units(True)},
                               {False: control.feed_mode(False), True: control.feed_mode(True)}, "M2", False,
                               c_feed=control.c_feed)
        self.set_units(not inches)

    def out(self, mm: float) -> float:
        """A length (or feed) in mm in the output's units."""
        return mm / MM_PER_INCH if self.inches else mm

    def x_word(self, radius: float) -> str:
        return super().x_word(self.out(radius if self.diameter else radius / 2.0))

    def z_word(self, z: float) -> str:
        return super().z_word(self.out(z))

    def length_word(self, value: float) -> str:
        return super().length_word(self.out(value))

    def f_word(self, feed: float) -> str:
        return super().f_word(self.out(feed))

    def write(self, moves: Iterable[Move], prefix: str = "") -> List[str]:
        moves = list(moves)
        for move in moves:
            self.check_axes(move)
        return super().write([self._handed(Move(*move)) for move in moves], prefix)

    def _handed(self, move: Move) -> Move:
        """``move`` as the target writer takes it: in the output's units, X halved for radius X words
        (the target writer doubles X; exact in binary), C (degrees) kept where the control has it. An
        arc keeps its X and its centre whole (``_arc_words`` writes its radius words), its radius in
        the output's units."""
        half = 1.0 if self.diameter or move.kind in ARCS else 0.5
        x, z, f = move.x, move.z, move.f
        centre = None if move.centre is None else (self.out(move.centre[0]), self.out(move.centre[1]))
        return Move(move.kind, None if x is None else self.out(x * half), None if z is None else self.out(z),
                    None if f is None else self.out(f), move.p, None, move.c, centre,
                    None if move.radius is None else self.out(move.radius))

    def _arc_words(self, move: Move) -> Optional[List[str]]:
        """An arc's words: X Z I K from the start as written (the target writer's), Siemens X Z CR=.
        With radius X words (not ``diameter``) the target writer, which works an arc's I/K out on
        diameter X words, is handed the start's radius text doubled (exact in decimal) and the arc
        whole, and its X word is written back as the radius. An arc whose end is written as its start
        writes nothing (I/K would make it a full circle)."""
        if self.x_text is None or self.z_text is None:
            return super()._arc_words(move)  # its refusal: the start must be written first
        start = (float(self.x_text) / (2.0 if self.diameter else 1.0), float(self.z_text))
        if self.diameter:
            words = super()._arc_words(move)
        else:
            radius_text, z_text = self.x_text, self.z_text
            self.x_text = format_decimal(2.0 * float(radius_text), self.digits)
            words = super()._arc_words(move)
            x_text = format_decimal(move.x, self.digits)
            if words is None or (x_text == radius_text and self.z_text == z_text):
                self.x_text, self.z_text = radius_text, z_text
                return None
            words[0] = "X" + x_text
            self.x_text = x_text
        if words is not None and self.control.cr_arcs and len(words) == 4:
            offset = (float(words[2][1:]), float(words[3][1:]))
            words[2:] = ["CR=" + format_decimal(_signed_radius(move.kind, start, offset, move), self.digits)]
        return words

    def dwell(self, seconds: float) -> str:
        if not 0 <= seconds <= MAX_DWELL_SECONDS:
            raise ProgramError("dwell of %r s cannot be written (0 to %g s)" % (seconds, MAX_DWELL_SECONDS))
        return self.control.dwell(seconds)

    def forget(self, position: bool = True, motion: bool = True, feed: bool = True) -> None:
        """The output no longer knows the position / the motion mode / the feed in force."""
        if position:
            self.x_text = self.z_text = self.c_text = None
        if motion:
            self.motion = None
        if feed:
            self.f_text = None

    def _axis_words(self, x: Optional[float], z: Optional[float], force: bool) -> List[str]:
        """The X and Z words of a move: the ones whose text changes (all given ones with ``force``)."""
        words = []
        if x is not None:
            text = self.x_word(x)
            if force or text != self.x_text:
                words.append("X" + text)
                self.x_text = text
        if z is not None:
            text = self.z_word(z)
            if force or text != self.z_text:
                words.append("Z" + text)
                self.z_text = text
        return words

    def _feed_word(self, f: Optional[float], what: str) -> Optional[str]:
        """The F word of a cutting move (None: the feed in force stays); ProgramError
        when there is no feed at all. ``what``: the move, for the message."""
        if f is not None:
            text = self.f_word(f)
            if text != self.f_text:
                self.f_text = text
                return "F" + text
        elif self.f_text is None:
            raise ProgramError("%s with no feed rate (F) in force" % what)
        return None

    def move(self, kind: str, x: Optional[float] = None, z: Optional[float] = None, f: Optional[float] = None,
             force: bool = False) -> List[str]:
        """Lines for one RAPID/FEED move to the given axes (None: not written)."""
        words = self._axis_words(x, z, force)
        fword = self._feed_word(f, "feed move") if kind == FEED else None
        if not words:
            return [fword] if fword else []
        if kind != self.motion or force:
            words.insert(0, self.code(kind))
            self.motion = kind
        if fword:
            words.append(fword)
        return [" ".join(words)]

    def arc(self, kind: str, x: float, z: float, i: float, k: float, f: Optional[float],
            radius: Optional[float] = None) -> List[str]:
        """An arc G2/G3 to radius x, z with incremental radius centre offsets
        i (X), k (Z); ``radius`` (signed, Siemens CR=) instead of I/K."""
        x_text, z_text = self.x_word(x), self.z_word(z)
        words = [self.code(kind), "X" + x_text, "Z" + z_text]
        if radius is None:
            words += ["I" + self.length_word(i), "K" + self.length_word(k)]
        else:
            words.append("CR=" + self.length_word(radius))
        fword = self._feed_word(f, "arc")
        if fword:
            words.append(fword)
        self.motion = kind
        self.x_text, self.z_text = x_text, z_text
        return [" ".join(words)]


def _signed_radius(kind: str, start: tuple, offset: tuple, move: Move) -> float:
    """Siemens CR= of an arc ``kind`` from ``start`` (x radius, z) with its centre ``offset`` (i, k)
    from it to ``move``'s end: the radius, negative above 180 degrees (G2 clockwise, Z right and X up)."""
    cx, cz = start[0] + offset[0], start[1] + offset[1]
    a0 = math.atan2(start[0] - cx, start[1] - cz)
    a1 = math.atan2(move.x - cx, move.z - cz)
    ccw = (a1 - a0) % (2 * math.pi)
    sweep = ccw if kind == ARC_CCW else 2 * math.pi - ccw
    radius = math.hypot(*offset)
    return radius if sweep <= math.pi + 1e-12 else -radius
