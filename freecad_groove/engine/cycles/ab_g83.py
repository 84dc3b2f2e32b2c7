"""Allen-Bradley 9/Series grinder G83 / G83.1: plunge surface grinding (the
9/Series grinder manual, chapter 16, pages 16-9, 16-13, 16-16).

``G83 X__ I__ Y__ J__ Z__ K__ R__ Q__ L__ F__ E__ P__ D__;`` with the axes of
the manual's format: X the reciprocating (non-plane) axis, Y the plunge axis
(plane axis 1), Z the crossover axis (plane axis 2). Moves are mill-style:
``Move.x`` a plain X coordinate (not a radius), ``Move.y`` and ``Move.z``.

Words (class 2 = taken from the previous G83/G83.1 of the program when omitted,
class 3 = optional):

* X (2) primary reversal point, I (3) secondary reversal point (G90: a
  coordinate; G91: signed distance from the start; never programmed: the start
  point), Y (2) plunge depth, Z (2) crossover end: absolute or incremental per
  G90/G91 (the block's last mode: the translator applies the block's G90/G91
  first, as the manual says for I, J, K).
* J (2) plunge pick at the start, Q (3, = J) plunge pick at crossover, K (2)
  cross pick at the primary reversal, R (3, = K) at the secondary: incremental
  only, amounts (the direction is toward Y and toward the crossover end).
* L (3, 0) spark-out passes 0..999; D (3, 0, not modal) dress executions 0..999;
  P dress program (3 for G83, 2 for G83.1); F (2, the feed in force) plunge and
  cross pick feed; E (3, the previous cycle's E, else F) reciprocation feed.

The expansion (choices the manual leaves open are marked [choice]; each is a
docs/choices.md row with a test):

1. G83.1: the dress program P first, at the start point.
2. The plunge pick J at F from the start (clipped to Y).
3. Reciprocation: X feeds at E to the secondary reversal point I when the
   start is not on it (the manual's step 3), then to the primary X, to I, and
   so on. At each reversal the crossover axis picks K (at X)
   or R (at I) at F toward the crossover end, the last pick clipped to it.
4. The plunge pick Q at F (clipped to Y) is made at the secondary reversal
   point I only, as the manual's step 4 says ("begins as the X axis
   decelerates to the secondary reversal point"): at the first reversal at I
   that finds the crossover end reached, instead of the cross pick, and the
   crossover turns back toward the start Z [choice]. A reversal at X that
   finds the crossover end reached only turns (no pick) and X strokes back
   to I on that end strip [choice]; so the strip at each end of the crossover
   gets a second stroke (two when the end is reached at X). With no crossover
   (Z = the start Z) every reversal at I plunges, those at X only turn.
5. After the pick that reaches Y: one crossover at the final depth (the pass
   that grinds the face there) [choice], then L spark-out crossovers, each a
   crossover end to end without plunge; with no crossover a pass is one stroke
   [choice]. When J reaches Y at the start and the first stroke (start to I)
   does not span the reversal points, one more crossover at depth [choice].
   A pass ends at the reversal that finds the crossover end reached (it
   only turns). The cycle ends at the reversal where the last pass ends,
   without a return move [choice]; when its last move was at E it ends with a move
   to where the wheel is at F, so that the feed in force after the cycle is
   the plunge feed F (the one the next cycle's F defaults to: a plunge at the
   reciprocation feed E would crash the wheel) [choice].
6. D dresses (P) spread over the Q plunges: dress i (1..D) right after plunge
   ceil(i * n / D) of n, at that reversal (the manual: "immediately after a
   plunge move at reciprocation reversal points") [choice]. D > n calls P
   several times after one plunge.

Remembered from one cycle to the next [choice]: the absolute reversal points,
depth and crossover end (so a G91 cycle after a G90 one grinds the same face),
J, K, E and P; Q and R default to this cycle's J and K, L and D to 0.
"""

import math
from dataclasses import dataclass, fields, replace
from typing import ClassVar, Dict, List, NamedTuple, Optional

from ..cycle import Cycle
from ..errors import CycleError
from ..moves import DRESS, FEED, MachineState, Move
from ..numbers import MAX_MOVES
from ..registry import G_WORD, register
from ..settings import DEFAULT_SETTINGS, Settings
from .cycle_words import TOLERANCE, check_number, read_block, word_value, words_text

__all__ = ["G83", "G83_1", "GrindPlan", "MAX_PROGRAM_NUMBER", "MAX_COUNT"]

MAX_COUNT = 999  # L and D: "zero to 999"
MAX_PROGRAM_NUMBER = 9999  # P: an O0001..O9999 program (Fanuc's M98 P without a repeat count)

POSITIONS = ("X", "I", "Y", "Z")  # abs or inc per G90/G91
AMOUNTS = ("J", "Q", "K", "R")  # incremental only
REMEMBERED = ("X", "I", "Y", "Z", "J", "K", "E", "P")
CLASS_2 = ("X", "Y", "J", "Z", "K")  # must have been programmed in this or an earlier cycle

Memory = Dict[str, float]  # word -> absolute position (X, I, Y, Z) or value, from the previous cycle


class GrindPlan(NamedTuple):
    """A G83/G83.1 with every word resolved: absolute positions, amounts, feeds."""

    x0: float  # start point
    y0: float
    z0: float
    primary: float  # X
    secondary: float  # I
    depth: float  # Y
    cross_end: float  # Z
    j: float
    q: float
    k: float
    r: float
    spark_out: int  # L
    feed: float  # F
    recip_feed: float  # E
    program: Optional[int]  # P
    dresses: int  # D
    dress_first: bool  # G83.1


def _toward(value: float, target: float, step: float) -> float:
    """``value`` moved by ``step`` toward ``target``, never past it."""
    if abs(target - value) <= step + TOLERANCE:
        return target
    return value + math.copysign(step, target - value)


@register
@dataclass(frozen=True)
class G83(Cycle):
    """Allen-Bradley 9/Series ``G83`` plunge surface grinding (see the module notes)."""

    NAME: ClassVar[str] = "G83"
    KEY: ClassVar[str] = "ab-g83"
    ALIASES: ClassVar[tuple] = ("g83",)
    DIALECTS: ClassVar[tuple] = ("ab9grind",)
    TITLE: ClassVar[str] = "Allen-Bradley 9/Series grinder G83 plunge surface grinding"
    FORM: ClassVar[str] = G_WORD
    MEMORY: ClassVar[str] = "ab-g83"  # the translator keeps remembered() under this key for the next cycle
    MILL: ClassVar[bool] = True  # mill-style moves (X, Y, Z)
    DRESS_FIRST: ClassVar[bool] = False
    WORDS: ClassVar[tuple] = ("X", "I", "Y", "J", "Z", "K", "R", "Q", "L", "F", "E", "P", "D")
    COUNTED: ClassVar[tuple] = ("L", "P", "D")
    WORD_HELP: ClassVar[tuple] = (
        ("X", "reciprocation primary reversal point (abs/inc; from the last cycle when omitted)"),
        ("I", "reciprocation secondary reversal point (G90 coordinate, G91 distance from the start; "
              "default the last cycle's, else the start point)"),
        ("Y", "plunge depth (abs/inc; from the last cycle when omitted)"),
        ("J", "plunge pick at start (incremental amount; from the last cycle when omitted)"),
        ("Z", "crossover end (abs/inc; from the last cycle when omitted)"),
        ("K", "cross pick at the primary reversal (incremental amount; from the last cycle when omitted)"),
        ("R", "cross pick at the secondary reversal (incremental amount; default K)"),
        ("Q", "plunge pick at crossover (incremental amount; default J)"),
        ("L", "spark-out passes, 0..999 (default 0)"),
        ("F", "plunge and cross pick feed (default the feed in force)"),
        ("E", "reciprocation feed (default the last cycle's E, else F)"),
        ("P", "dress program number, 1..9999 (from the last cycle when omitted)"),
        ("D", "dress executions over the cycle, 0..999 (not modal; default 0)"),
    )

    X: Optional[float] = None
    I: Optional[float] = None  # noqa: E741 - the control's word
    Y: Optional[float] = None
    J: Optional[float] = None
    Z: Optional[float] = None
    K: Optional[float] = None
    R: Optional[float] = None
    Q: Optional[float] = None
    L: Optional[int] = None
    F: Optional[float] = None
    E: Optional[float] = None
    P: Optional[int] = None
    D: Optional[int] = None

    # -- words -------------------------------------------------------------------

    @classmethod
    def parse(cls, text: str) -> "G83":
        """The model of a block as written; raises CycleError naming the word."""
        return cls(**read_block(text, cls.NAME, cls.WORDS, cls.COUNTED)).validate()

    def emit(self) -> str:
        """The block as the control reads it (no N number, no end of block)."""
        return words_text(self, self.NAME, self.WORDS, self.COUNTED)

    def _error(self, letter: str, rule: str) -> CycleError:
        return CycleError(letter, getattr(self, letter), rule, cycle=self.NAME)

    def validate(self, settings: Settings = DEFAULT_SETTINGS) -> "G83":
        """The rules on the words as written (those that need the program's
        memory or the start point are checked by plan()); returns self."""
        for item in fields(self):
            value = getattr(self, item.name)
            if value is not None:
                check_number(self.NAME, item.name, value, item.name in self.COUNTED)
        for letter in ("L", "D"):
            value = getattr(self, letter)
            if value is not None and not 0 <= value <= MAX_COUNT:
                raise self._error(letter, "must be a whole number from 0 to %d" % MAX_COUNT)
        if self.P is not None and not 1 <= self.P <= MAX_PROGRAM_NUMBER:
            raise self._error("P", "must be a program number from 1 to %d" % MAX_PROGRAM_NUMBER)
        for letter in AMOUNTS:
            value = getattr(self, letter)
            if value is not None and value < 0:
                raise self._error(letter, "is incremental only: an amount, not negative (the direction comes "
                                          "from %s)" % ("Y" if letter in ("J", "Q") else "Z"))
        if self.Q is not None and self.Q == 0:
            raise self._error("Q", "must be greater than 0: the plunge would never reach Y")
        for letter in ("K", "R"):
            if getattr(self, letter) == 0:
                raise self._error(letter, "must be greater than 0: the crossover would never end")
        for letter in ("F", "E"):
            value = getattr(self, letter)
            if value is not None and not value > 0:
                raise self._error(letter, "must be greater than 0")
        return self

    # -- the program's memory -------------------------------------------------------

    def with_earlier(self, memory: Memory, state: MachineState) -> "G83":
        """This call with the words it omits taken from the previous cycle's
        ``memory`` (remembered()), written in the distance mode of ``state``."""
        filled = {}
        for letter in REMEMBERED:
            if getattr(self, letter) is not None or letter not in memory:
                continue
            value = memory[letter]
            if letter in POSITIONS and state.incremental:
                start = state.x if letter in ("X", "I") else state.y if letter == "Y" else state.z
                if start is None:
                    continue  # plan() names the unknown start point
                value -= start
            filled[letter] = int(value) if letter in self.COUNTED else value
        return replace(self, **filled)

    def remembered(self, state: MachineState) -> Memory:
        """What the next G83/G83.1 takes from this one (absolute positions)."""
        plan = self.plan(state)
        memory = {"X": plan.primary, "Y": plan.depth, "Z": plan.cross_end, "J": plan.j, "K": plan.k,
                  "E": plan.recip_feed}
        if self.I is not None:
            memory["I"] = plan.secondary
        if plan.program is not None:
            memory["P"] = plan.program
        return memory

    # -- the plan ---------------------------------------------------------------------

    def _position(self, letter: str, start: float, incremental: bool) -> float:
        value = getattr(self, letter)
        return start + value if incremental else value

    def _check_complete(self, state: MachineState) -> None:
        for axis, value in (("X", state.x), ("Y", state.y), ("Z", state.z)):
            if value is None:
                raise CycleError(axis, None, "the start position is not known: program an absolute %s before the "
                                             "cycle" % axis, cycle=self.NAME)
        for letter in CLASS_2:
            if getattr(self, letter) is None:
                raise CycleError(letter, None, "must be programmed (no earlier G83/G83.1 of the program gave it)",
                                 cycle=self.NAME)
        if self.F is None and state.feed is None:
            raise CycleError("F", None, "must be programmed (no feed in force)", cycle=self.NAME)
        if self.P is None and (self.DRESS_FIRST or self.D):
            why = "G83.1 dresses first" if self.DRESS_FIRST else "D=%d dresses" % self.D
            raise CycleError("P", None, "must be programmed (%s; no earlier cycle gave P)" % why, cycle=self.NAME)

    def plan(self, state: MachineState) -> GrindPlan:
        """Every word resolved against the start ``state``; CycleError on a rule broken."""
        self.validate()
        self._check_complete(state)
        inc = state.incremental
        primary = self._position("X", state.x, inc)
        secondary = state.x if self.I is None else self._position("I", state.x, inc)
        if abs(primary - secondary) <= TOLERANCE:
            raise CycleError("I" if self.I is not None else "X", self.I if self.I is not None else self.X,
                             "the secondary reversal point equals the primary one (X%s): no reciprocation"
                             % word_value(primary), cycle=self.NAME)
        feed = self.F if self.F is not None else state.feed
        plan = GrindPlan(
            state.x, state.y, state.z, primary, secondary, self._position("Y", state.y, inc),
            self._position("Z", state.z, inc), self.J, self.J if self.Q is None else self.Q, self.K,
            self.K if self.R is None else self.R, self.L or 0, feed, self.E if self.E is not None else feed,
            self.P, self.D or 0, self.DRESS_FIRST,
        )
        if plan.q == 0 and abs(plan.depth - plan.y0) > plan.j + TOLERANCE:
            raise CycleError("Q", plan.q, "must be greater than 0: the plunge would never reach Y (J=0 is taken "
                                          "for Q when Q is omitted)", cycle=self.NAME)
        if plan.dresses and not _plunges(plan):
            raise CycleError("D", self.D, "the cycle has no plunge at a reversal to dress after (J reaches Y at "
                                          "the start)", cycle=self.NAME)
        return plan

    def expand(self, state: MachineState, settings: Settings = DEFAULT_SETTINGS) -> List[Move]:
        """The moves of the cycle from ``state`` (see the module notes)."""
        return grind_moves(self.plan(state), self.NAME)


@register
@dataclass(frozen=True)
class G83_1(G83):
    """``G83.1``: G83 with the dress program P run before the cycle starts."""

    NAME: ClassVar[str] = "G83.1"
    KEY: ClassVar[str] = "ab-g83.1"
    ALIASES: ClassVar[tuple] = ("g83.1",)
    TITLE: ClassVar[str] = "Allen-Bradley 9/Series grinder G83.1 plunge surface grinding, dressing first"
    DRESS_FIRST: ClassVar[bool] = True


# ---------------------------------------------------------------- the moves


def _plunges(plan: GrindPlan) -> int:
    """How many Q plunges at the reversals the cycle makes."""
    left = abs(plan.depth - _toward(plan.y0, plan.depth, plan.j))
    if left <= TOLERANCE:
        return 0
    return max(1, math.ceil((left - TOLERANCE) / plan.q))


def _dress_after(plan: GrindPlan) -> Dict[int, int]:
    """Plunge number (1..n) -> how many dresses follow it."""
    count = _plunges(plan)
    after: Dict[int, int] = {}
    for index in range(1, plan.dresses + 1):
        plunge = math.ceil(index * count / plan.dresses)
        after[plunge] = after.get(plunge, 0) + 1
    return after


class _Wheel:
    """The wheel's position as the moves are made."""

    def __init__(self, plan: GrindPlan, cycle: str) -> None:
        self.x, self.y, self.z = plan.x0, plan.y0, plan.z0
        self.q = plan.q
        self.cycle = cycle
        self.moves: List[Move] = []

    def feed(self, f: float, x: Optional[float] = None, y: Optional[float] = None, z: Optional[float] = None) -> None:
        self.x = self.x if x is None else x
        self.y = self.y if y is None else y
        self.z = self.z if z is None else z
        self.moves.append(Move(FEED, self.x, self.z, f, 0.0, self.y))
        if len(self.moves) > MAX_MOVES:
            raise CycleError("Q", self.q, "the cycle would make more than %d moves: picks too small for the depth "
                                          "and crossover" % MAX_MOVES, cycle=self.cycle)

    def dress(self, program: int) -> None:
        self.moves.append(Move(DRESS, self.x, self.z, None, program, self.y))


def _passes_at_depth(plan: GrindPlan) -> int:
    """The crossovers at the final depth when J reaches it at the start: one
    more when the first stroke (start -> I) does not span the reversal points,
    so the face is ground at depth between them over the whole crossover."""
    on_i = abs(plan.x0 - plan.secondary) <= TOLERANCE
    beyond_x = (plan.x0 - plan.primary) * (plan.primary - plan.secondary) >= 0  # at X or past it, seen from I
    return (1 if on_i or beyond_x else 2) + plan.spark_out


def _ending_at_feed(moves: List[Move], plan: GrindPlan) -> List[Move]:
    """The moves, with F in force again at the end when the last was at E."""
    last = moves[-1]
    if last.f == plan.feed:
        return moves
    return moves + [last._replace(f=plan.feed)]


def grind_moves(plan: GrindPlan, cycle: str = "G83") -> List[Move]:
    """The moves of a resolved G83/G83.1 (see the module notes); ``cycle`` names it in errors."""
    wheel = _Wheel(plan, cycle)
    if plan.dress_first:
        wheel.dress(plan.program)
    depth_at_start = _toward(plan.y0, plan.depth, plan.j)
    if depth_at_start != plan.y0:
        wheel.feed(plan.feed, y=depth_at_start)
    dresses = _dress_after(plan)
    passes_left = _passes_at_depth(plan) if wheel.y == plan.depth else None
    # the manual's step 3: X moves to the secondary reversal point I first (when the start is not on it)
    reversal = plan.secondary if abs(plan.x0 - plan.secondary) > TOLERANCE else plan.primary
    cross_to, plunge = plan.cross_end, 0
    while True:
        if wheel.x != reversal:  # the start may be on a reversal point already
            wheel.feed(plan.recip_feed, x=reversal)
        pick = plan.k if reversal == plan.primary else plan.r
        if abs(wheel.z - cross_to) > TOLERANCE:
            wheel.feed(plan.feed, z=_toward(wheel.z, cross_to, pick))
        elif passes_left is None:
            if reversal == plan.secondary:  # step 4: the plunge pick Q as X decelerates to I
                wheel.feed(plan.feed, y=_toward(wheel.y, plan.depth, plan.q))
                plunge += 1
                for _ in range(dresses.get(plunge, 0)):
                    wheel.dress(plan.program)
                if wheel.y == plan.depth:
                    passes_left = 1 + plan.spark_out
                cross_to = plan.z0 if cross_to == plan.cross_end else plan.cross_end
            # at the primary X the crossover end waits for I: no pick, one more stroke on the end strip
        else:
            passes_left -= 1
            if passes_left == 0:
                return _ending_at_feed(wheel.moves, plan)
            cross_to = plan.z0 if cross_to == plan.cross_end else plan.cross_end
        reversal = plan.secondary if reversal == plan.primary else plan.primary
