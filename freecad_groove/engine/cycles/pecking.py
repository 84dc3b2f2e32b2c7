"""The pecking machinery every multi-groove pecking cycle shares: Allen-Bradley
G77/G76 (``ab_g77``), Fanuc and Haas G75/G74 (``fanuc_g75``).

:class:`PeckingCycle` is the model (validation, expansion, emit, parse) a
concrete cycle fills in with its words; :func:`peck_grooves` the loop that
expands it; ``cycle_words.py`` reads, checks and writes the words.

Choices the manuals leave open (each a named constant here, each with a test):

* The peck retract e is not clipped: when e > the peck the first retract goes
  beyond the start (away from the part). With e = 0 no zero-length retract is
  written; the pecks stay separate FEED moves.
* Peck depths and groove positions are computed as start + k * step (no
  accumulated drift); a remainder smaller than ``TOLERANCE`` is merged into the
  last peck / last groove rather than cut as a sliver.
* Zero-length moves are not written (the final return when the tool is already
  at the start).
* Without F and without an active feed (``MachineState.feed`` None or 0) the
  cycle is refused (the control would cut at feed 0).
* An expansion longer than ``MAX_MOVES`` moves is refused, naming the peck or
  groove-spacing word that caused it (a typo like I0.0001 must not hang FreeCAD).
* Number format (emit): every word except Fanuc's P/Q is written with a decimal
  point and trailing zeros dropped: ``X20.``, ``X20.5``, ``F0.1``, ``D0.``. At
  most ``DECIMALS`` (4) decimals, F at most ``F_DECIMALS`` (6: a feed per
  revolution in inch, 0.05 mm/rev = F0.001969, where 4 would be 1.6 % off;
  Fanuc reads in/rev to 0.000001), and magnitude below ``MAX_WORD`` (100000):
  validate() refuses other values, so emit() never rounds and
  ``parse(emit(m)) == m`` holds for every valid model.
* parse() refuses a non-zero word written without a decimal point (``X20``):
  the 9/Series reads it per its AMP zero-suppression format (X20 may be 20. or
  0.20), Fanuc in least input increments, Haas per setting 162. ``X0`` is
  accepted. A block holds one G word (the cycle's), an optional leading N number,
  spaces anywhere, an optional ``;``; each word at most once; no comments.
"""

import math
from typing import ClassVar, List, NamedTuple, Optional, Sequence, Tuple

from ..cycle import Cycle
from ..errors import CycleError
from ..moves import FEED, MINUS_X, MINUS_Z, PLUS_X, PLUS_Z, RAPID, MachineState, Move
from ..numbers import MAX_MOVES, format_decimal, format_given
from ..settings import DEFAULT_SETTINGS, Settings
from ..warnings import CycleWarning
from .cycle_words import DECIMALS, TOLERANCE, check_number, read_block, words_text


def _words(value: float) -> str:
    """A length in a warning: at most DECIMALS decimals, no trailing zeros."""
    return format_decimal(value, DECIMALS, point=False)


# ---------------------------------------------------------------- the shared pecking loop


def _count(length, step):
    """How many points start + k*step (k = 0, 1, ...) lie before ``length`` (less TOLERANCE)."""
    return max(1, math.ceil((length - TOLERANCE) / step))


def _points(start, end, step, count):
    """start, start +- step, ... (``count`` points toward end), then end itself."""
    sign = 1.0 if end > start else -1.0
    points = [start + sign * k * step for k in range(count)]
    points.append(end)
    return points


def _plunge_axis_move(axis):
    """A Move maker taking (kind, plunge coordinate, stepping coordinate, feed):
    Move(kind, x, z, f) built directly as its tuple (the loop makes every move
    of a pattern of thousands of grooves)."""
    new, rest = tuple.__new__, tuple(Move._field_defaults[name] for name in Move._fields[4:])
    if axis == "X":
        def move(kind, p, s, f=None):
            return new(Move, (kind, p, s, f) + rest)
    else:
        def move(kind, p, s, f=None):
            return new(Move, (kind, s, p, f) + rest)
    return move


def peck_grooves(
    axis: str,
    start: Tuple[float, float],
    bottom: float,
    positions: Sequence[float],
    peck: float,
    retract: float,
    relief: float = 0.0,
    relief_on_first: bool = True,
    feed: Optional[float] = None,
    return_to_start: bool = True,
) -> List[Move]:
    """Expand pecked grooves: the loop every pecking cycle shares.

    axis       plunge axis, "X" (grooves along Z) or "Z" (face grooves along X).
    start      (x radius, z) of the tool before the cycle.
    bottom     groove bottom on the plunge axis (radius for "X").
    positions  groove positions on the other axis, in cutting order; the first
               is the start's own coordinate.
    peck       infeed per peck (> 0); the last infeed is shortened to the bottom.
    retract    peck retract e (>= 0): FEED peck, RAPID back e, FEED peck + e ...
    relief     signed rapid move along the stepping axis at the bottom, before
               the rapid retract (Allen-Bradley D, Fanuc R(dd), Haas D).
    relief_on_first  False: not at the first groove (Fanuc/Haas).
    feed       F for the infeed FEED moves (None = the active feed).
    return_to_start  end with a rapid to the start position.

    Between grooves the tool rapids along the stepping axis at the start plunge
    coordinate. Returns a list of moves.Move.
    """
    if axis == "X":
        p0, s0 = float(start[0]), float(start[1])
    else:
        s0, p0 = float(start[0]), float(start[1])
    sign = 1.0 if bottom > p0 else -1.0
    depth = abs(bottom - p0)
    targets = _points(p0, bottom, peck, _count(depth, peck))[1:]
    pecks = [(t, t - sign * retract) for t in targets[:-1]]

    move = _plunge_axis_move(axis)
    out = []
    add = out.append
    s = s0
    for index, s in enumerate(positions):
        if index:
            add(move(RAPID, p0, s))
        for target, back in pecks:
            add(move(FEED, target, s, feed))
            if retract:
                add(move(RAPID, back, s))
        add(move(FEED, bottom, s, feed))
        if relief and (index or relief_on_first):
            s += relief
            add(move(RAPID, bottom, s))
        add(move(RAPID, p0, s))
    if return_to_start and s != s0:
        add(move(RAPID, p0, s0))
    return out


# ---------------------------------------------------------------- the shared cycle model


class PeckingLayout(NamedTuple):
    """What a pecking call cuts, resolved against its start (lengths in the
    program's units, X radii): ``longitudinal`` it plunges in X; ``bottom``
    and ``plunge_start`` on the plunge axis; ``positions`` the grooves on the
    other; ``pitch`` the spacing as programmed (None: one groove); ``peck``;
    ``relief`` as the cycle moves it (signed; 0: none); ``relief_first`` it
    is made at the first groove too (Allen-Bradley D); ``retract`` e; ``feed``
    the call's F (None: the feed in force). engine/native rebuilds the call
    for another control from it."""

    longitudinal: bool
    bottom: float
    plunge_start: float
    positions: List[float]
    pitch: Optional[float]
    peck: float
    relief: float
    relief_first: bool
    retract: float
    feed: Optional[float]

    @property
    def pecks(self) -> int:
        """Infeeds per groove."""
        return _count(abs(self.bottom - self.plunge_start), self.peck)

    @property
    def relief_made(self) -> bool:
        """Whether the relief moves the blade at all."""
        return bool(self.relief) and (self.relief_first or len(self.positions) > 1)


class PeckingCycle(Cycle):
    """Validation, expansion, emit and parse shared by the pecking cycles.

    A concrete cycle is a frozen dataclass whose fields are named after its
    words, and which sets the declaration of every cycle (cycle.Cycle: NAME,
    COUNTED, ...) and these class attributes of the pecking cycles:

    AXIS      plunge axis, "X" or "Z".
    WORDS     letters in the order emit() writes them.
    BOTTOM    the words that may give the groove bottom (("X",) or ("X", "U")).
    LAST      the words that may give the last groove position.
    PECK, PITCH, RELIEF   the letters of the peck depth, the groove spacing and
              the shift/relief at the bottom.
    SHIFT_D   True: RELIEF is Allen-Bradley's D: required, signed, done at every
              groove. False: Fanuc/Haas relief: optional, unsigned, toward the
              grooves already cut, not at the first.
    """

    AXIS: ClassVar[str]
    WORDS: ClassVar[tuple]
    BOTTOM: ClassVar[tuple]
    LAST: ClassVar[tuple]
    PECK: ClassVar[str]
    PITCH: ClassVar[str]
    RELIEF: ClassVar[str]
    SHIFT_D: ClassVar[bool] = False

    # -- hooks a dialect may override

    def _returns_to_start(self):
        return True

    def _retract(self, settings, metric):
        """(peck retract e, the name to blame when it is wrong)."""
        return settings.retract_e(metric), "e"

    # -- reading words

    def _programmed(self, letters):
        """The one programmed letter among ``letters`` (None when none is)."""
        found = [letter for letter in letters if getattr(self, letter) is not None]
        if len(found) > 1:
            raise CycleError(
                found[1], getattr(self, found[1]), "must not be programmed together with %s" % found[0], cycle=self.NAME
            )
        return found[0] if found else None

    def _length(self, letter, metric):
        value = getattr(self, letter)
        if letter in self.COUNTED:
            return value * (0.001 if metric else 0.0001)
        return float(value)

    def _position(self, letter, state):
        """Absolute coordinate (X as a radius) a position word programs."""
        axis = "X" if letter in ("X", "U") else "Z"
        value = getattr(self, letter)
        if axis == "X" and state.diameter_mode:
            value = value / 2.0
        if letter in ("U", "W") or state.incremental:
            return (state.x if axis == "X" else state.z) + value
        return float(value)

    def _bottom_letter(self):
        letter = self._programmed(self.BOTTOM)
        if letter is None:
            rule = "must be programmed (%s: the groove bottom)" % " or ".join(self.BOTTOM)
            raise CycleError(self.BOTTOM[0], None, rule, cycle=self.NAME)
        return letter

    def _bottom(self, state):
        letter = self._bottom_letter()
        bottom = self._position(letter, state)
        start = state.x if self.AXIS == "X" else state.z
        if abs(bottom - start) <= TOLERANCE:
            raise CycleError(
                letter,
                getattr(self, letter),
                "puts the groove bottom at the start %s: nothing to cut" % self.AXIS,
                cycle=self.NAME,
            )
        return bottom, start

    # -- the common API

    def validate(self, settings: Settings = DEFAULT_SETTINGS) -> "PeckingCycle":
        """Check every rule that does not depend on the machine state; returns self."""
        name = self.NAME
        for letter in self.WORDS:
            value = getattr(self, letter)
            if value is not None:
                check_number(name, letter, value, letter in self.COUNTED)
        self._bottom_letter()
        self._programmed(self.LAST)
        peck = getattr(self, self.PECK)
        if peck is None:
            raise CycleError(self.PECK, None, "must be programmed (the infeed per peck)", cycle=name)
        if not peck > 0:
            raise CycleError(self.PECK, peck, "peck depth must be greater than 0", cycle=name)
        pitch = getattr(self, self.PITCH)
        if pitch is not None and pitch < 0:
            raise CycleError(
                self.PITCH,
                pitch,
                "groove spacing must not be negative (it is unsigned: the grooves step from the start toward %s)"
                % "/".join(self.LAST),
                cycle=name,
            )
        relief = getattr(self, self.RELIEF)
        if self.SHIFT_D:
            if relief is None:
                raise CycleError(self.RELIEF, None, "must be programmed (0 when not cutting off)", cycle=name)
        elif relief is not None and relief < 0:
            raise CycleError(
                self.RELIEF, relief, "relief at the groove bottom must not be negative (it is unsigned)", cycle=name
            )
        if self.F is not None and not self.F > 0:
            raise CycleError("F", self.F, "feed must be greater than 0", cycle=name)
        for metric in (True, False):
            retract, word = self._retract(settings, metric)
            if isinstance(retract, bool) or not isinstance(retract, (int, float)) or not retract >= 0:
                raise CycleError(word, retract, "peck retract must be a number not less than 0", cycle=name)
        return self

    def plunge_direction(self, state: MachineState) -> str:
        """MINUS_X / PLUS_X (AXIS "X") or MINUS_Z / PLUS_Z: bottom below or above the start."""
        bottom, start = self._bottom(state)
        if self.AXIS == "X":
            return MINUS_X if bottom < start else PLUS_X
        return MINUS_Z if bottom < start else PLUS_Z

    def _grooves(self, state):
        """(bottom, start on the plunge axis, groove positions, peck length):
        the layout expand() cuts, checked (a feed too)."""
        name = self.NAME
        bottom, p0 = self._bottom(state)
        s0 = state.z if self.AXIS == "X" else state.x
        last_letter = self._programmed(self.LAST)
        last = s0 if last_letter is None else self._position(last_letter, state)
        span = abs(last - s0)
        pitch = getattr(self, self.PITCH)
        if span > TOLERANCE:
            if pitch is None or pitch == 0:
                raise CycleError(
                    self.PITCH,
                    pitch,
                    "groove spacing must be programmed and greater than 0 when %s puts the last groove away from "
                    "the start" % last_letter,
                    cycle=name,
                )
            pitch = self._length(self.PITCH, state.metric)
            grooves = _count(span, pitch) + 1
        else:
            grooves = 1
        if self.F is None and not state.feed:
            raise CycleError("F", None, "must be programmed: no feed is active before the cycle", cycle=name)
        peck = self._length(self.PECK, state.metric)
        pecks = _count(abs(bottom - p0), peck)
        if grooves * (2 * pecks + 3) + 1 > MAX_MOVES:
            letter = self.PITCH if grooves > pecks else self.PECK
            raise CycleError(
                letter,
                getattr(self, letter),
                "gives %d grooves of %d pecks: more than the %d moves an expansion may hold"
                % (grooves, pecks, MAX_MOVES),
                cycle=name,
            )
        positions = [s0] if grooves == 1 else _points(s0, last, pitch, grooves - 1)
        return bottom, p0, positions, peck

    def layout(self, state: MachineState, settings: Settings = DEFAULT_SETTINGS) -> PeckingLayout:
        """What the call cuts from ``state`` (validated), as expand() cuts it."""
        self.validate(settings)
        bottom, p0, positions, peck = self._grooves(state)
        relief = float(getattr(self, self.RELIEF) or 0.0)
        if not self.SHIFT_D:
            relief = relief if positions[-1] < positions[0] else -relief  # back toward the grooves already cut
        pitch = self._length(self.PITCH, state.metric) if len(positions) > 1 else None
        return PeckingLayout(self.AXIS == "X", bottom, p0, positions, pitch, peck, relief, self.SHIFT_D,
                             self._retract(settings, state.metric)[0], self.F)

    def expand(self, state: MachineState, settings: Settings = DEFAULT_SETTINGS) -> List[Move]:
        """The moves the control makes, from ``state`` (x radius, z)."""
        self.validate(settings)
        bottom, _p0, positions, peck = self._grooves(state)
        s0, last = positions[0], positions[-1]
        relief = float(getattr(self, self.RELIEF) or 0.0)
        if not self.SHIFT_D:
            relief = relief if last < s0 else -relief  # back toward the grooves already cut
        return peck_grooves(
            self.AXIS,
            (state.x, state.z),
            bottom,
            positions,
            peck,
            self._retract(settings, state.metric)[0],
            relief,
            self.SHIFT_D,
            self.F,
            self._returns_to_start(),
        )

    def warnings(self, state: MachineState, settings: Settings = DEFAULT_SETTINGS) -> List[CycleWarning]:
        """A Fanuc/Haas relief that rapids the blade's side into material: the
        relief moves the blade at the bottom back toward the grooves already cut,
        so it needs that much bottom already cut behind the blade. Grooves further
        apart than the blade's width leave a wall between them (any relief hits
        it); overlapping plunges leave their spacing behind the second groove.
        Needs the blade (``settings.tool``): without one, no warning. None for
        Allen-Bradley's D, which is signed and meant to move away from the part."""
        relief = getattr(self, self.RELIEF)
        if self.SHIFT_D or settings.tool is None or not relief:
            return []
        positions = self._grooves(state)[2]
        steps = [abs(b - a) for a, b in zip(positions, positions[1:])]
        if not steps:
            return []
        width = settings.tool.width
        units = "mm" if state.metric else "in"
        given = "%s=%s" % (self.RELIEF, format_given(relief))
        pitch = "%s=%s" % (self.PITCH, format_given(getattr(self, self.PITCH)))
        wall = max(steps)
        if wall > width + TOLERANCE:
            message = ("the relief %s at the groove bottom rapids the blade's side into the wall between grooves: "
                       "grooves %s %s apart (%s) leave a %s %s wall beside the %s %s blade"
                       % (given, _words(wall), units, pitch, _words(wall - width), units, _words(width), units))
        elif relief > steps[0] + TOLERANCE:
            message = ("the relief %s at the groove bottom rapids the blade's side past the cut bottom into the "
                       "wall: grooves %s %s apart (%s) cut only %s %s behind the %s %s blade at the second groove"
                       % (given, _words(steps[0]), units, pitch, _words(steps[0]), units, _words(width), units))
        else:
            return []
        return [CycleWarning(self.NAME, self.RELIEF, message)]

    def _words_text(self):
        return words_text(self, self.NAME, self.WORDS, self.COUNTED)

    def emit(self) -> str:
        """The block as the control reads it (no N number, no end of block)."""
        return self._words_text()

    @classmethod
    def parse(cls, text: str) -> "PeckingCycle":
        """The model of a block as written; raises CycleError naming the word."""
        return cls(**read_block(text, cls.NAME, cls.WORDS, cls.COUNTED)).validate()
