"""GSK 980TDi ``G7.1``: cylindrical interpolation (Type I) and its roughing cycle (Type II).

A *region*, not one block (the GSK 980TDi manual, chapter 3; notes/other-cycles.md)::

    G7.1 C(c) [J(di) R(dd) K(du) L(d)]   start: c = the cylinder's radius
    G1 Z.. C.. F..                        the path on the developed surface:
    G2 Z.. C.. R..                        Z along the axis, C in degrees,
    ...                                   arcs by their radius R (developed mm)
    G7.1 C0                               cancel

``G07.1`` and ``G107`` are the same code (GSK 988TA); the model keeps the
spelling it was read with and writes it back. Type I (no J, R, K, L) runs the
path once at the X where the tool stands. Type II (J, R, K and L all given) is
the roughing cycle of the manual's steps 1-5: X rapids from the start F to the
cycle start G, feeds in to pass n, follows the path, rapids back out in X,
returns Z and C to G, and repeats down to the finish pass.

Choices the manual leaves open (docs/choices.md, "GSK G7.1" table, each with a test):

* Depths are measured from the cylinder (diameter 2c): the finish pass runs at
  diameter 2c + J; the cycle start G is at diameter 2c - sign(J)*R, i.e. R is
  the clearance the tool retracts to above the cylinder (the manual's infeed
  "dd + n*du" read as R plus n pass depths). The start X must be at G or
  farther out; the F->G rapid is written only when X differs.
* Passes: d = max(L, 2) rough passes (L1 runs as 2, as documented) of equal
  depth down to the allowance K, then the finish pass: rough pass n at
  2c + sign(J)*(|J| - K)*n/d, the finish at 2c + J.
* After each pass: X rapids straight out to G's X (E), then Z and C rapid back
  to G (never a Z/C move at depth, where the straight line back may cross
  uncut stock). The cycle ends at G. Type I ends where its path ends.
* Arcs: G2 is clockwise seen with +Z to the right and the developed C (c times
  C in radians) upward (the G18 sense with C in place of X); R > 0 (over 180
  degrees is refused); arcs become straight segments within
  numbers.ARC_CHORD_TOLERANCE (0.001 mm; 0.001/25.4 in in inch programs) of the arc.
  They stay segments (not moves.ARC_CW/ARC_CCW as CYCLE93's passes and G34's
  corners write): these arcs lie on the developed surface of the rotary axis,
  in Z and C; in the target's plane (X and Z, G18) they are helices around the
  cylinder, which no G2/G3 of that plane describes.
* Feeds: F is the feed along the developed path (mm/min, G98; G99 is
  refused). A move that turns C carries the feed as LinuxCNC reads it: along
  Z when Z moves, else in degrees per minute, so the tool runs the developed
  path at F. The X infeed feeds at the feed in force (on the first pass: the
  one before the call, else the path's first F).
* In the region: G1/G2/G3 blocks of Z, C, R, F only, absolute (W and H, X/U,
  I/K, G0, M/S/T are refused, each with its reason); a block without a G code
  keeps the last motion. Numbers need a decimal point (L: a whole number). C must be known at the call.
"""

import math
import re
from dataclasses import dataclass
from typing import ClassVar, Dict, List, NamedTuple, Optional, Tuple

from ..cycle import Cycle
from ..errors import CycleError
from ..moves import FEED, RAPID, MachineState, Move
from ..numbers import ARC_CHORD_TOLERANCE, ARC_R_TOLERANCE, MAX_MOVES, MM_PER_INCH, format_decimal
from ..region_blocks import RegionBlocks
from ..registry import G_WORD, register
from ..settings import DEFAULT_SETTINGS, Settings

__all__ = ["GskG7_1", "PathBlock", "SPELLINGS"]

NAME = "G7.1"
SPELLINGS = ("G7.1", "G07.1", "G107")
MOTIONS = ("G1", "G2", "G3")
MAX_WORD = 100000.0  # 99999999 least input increments of 0.001 mm
MAX_PASSES = 9999
DECIMALS = 4
F_DECIMALS = 6

_WORD = re.compile(r"([A-Z])([+-]?(?:\d+\.?\d*|\.\d+))")
_REFUSED_IN_PATH = {
    "X": "the depth of a G7.1 region is its start X (Type I) or the cycle's (Type II): no X in the path",
    "U": "the depth of a G7.1 region is its start X (Type I) or the cycle's (Type II): no U in the path",
    "W": "write absolute Z in a G7.1 region (W is not supported there)",
    "H": "write absolute C in a G7.1 region (H is not supported there)",
    "I": "arcs in the developed plane are given by their radius R, not I/K",
    "K": "arcs in the developed plane are given by their radius R, not I/K",
    "M": "program M codes outside the G7.1 region",
    "S": "program the spindle outside the G7.1 region",
    "T": "program the tool outside the G7.1 region",
}


class PathBlock(NamedTuple):
    """One block of the path in the developed plane, words as written (None: not written)."""

    motion: str  # "G1", "G2", "G3"
    z: Optional[float] = None
    c: Optional[float] = None  # degrees
    r: Optional[float] = None  # arc radius on the developed surface
    f: Optional[float] = None


def _fail(parameter: str, value: object, rule: str) -> CycleError:
    return CycleError(parameter, value, rule, cycle=NAME)


def _check_number(letter: str, value: object, positive: bool = False) -> None:
    """A word the control reads back exactly: finite, below MAX_WORD, few decimals."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise _fail(letter, value, "must be a finite number")
    if not abs(value) < MAX_WORD:
        raise _fail(letter, value, "must be less than %d in magnitude" % MAX_WORD)
    digits = F_DECIMALS if letter == "F" else DECIMALS
    if round(value, digits) != value:
        raise _fail(letter, value, "must have at most %d decimal places" % digits)
    if positive and not value > 0:
        raise _fail(letter, value, "must be greater than 0")


def _word_text(letter: str, value: float) -> str:
    return "%s%s" % (letter, format_decimal(value, F_DECIMALS if letter == "F" else DECIMALS))


# ---------------------------------------------------------------- reading blocks


def split_words(block: str) -> Tuple[Optional[str], List[Tuple[str, str]]]:
    """``G7.1 C20. J-4.`` -> ("G7.1", [("C", "20."), ("J", "-4.")]); the G word as
    written (None when the block has none); N numbers, spaces and ``;`` dropped."""
    text = "".join(block.split()).upper().rstrip(";")
    text = re.sub(r"^N\d+", "", text)
    code, words, pos = None, [], 0
    while pos < len(text):
        match = _WORD.match(text, pos)
        if not match:
            raise _fail(text[pos], None, "cannot read %r as a word of a G7.1 region" % text[pos:])
        letter, number = match.groups()
        pos = match.end()
        if letter == "G":
            if code is not None:
                raise _fail("G", "%s G%s" % (code, number), "one G code per block in a G7.1 region")
            code = "G" + number
        else:
            if any(letter == seen for seen, _ in words):
                raise _fail(letter, float(number), "is programmed twice")
            words.append((letter, number))
    return code, words


def _decimal(letter: str, number: str) -> float:
    value = float(number)
    if "." not in number and value != 0:
        raise _fail(letter, value, "needs a decimal point: without one the control reads it in least input "
                    "increments; write %s%s." % (letter, number))
    return value


def spelling(code: Optional[str]) -> Optional[str]:
    """The G7.1 spelling of a G word as written ("G07.1"), None for another code."""
    if code is None:
        return None
    upper = code.upper()
    return upper if upper in SPELLINGS else None


def motion_of(code: str) -> str:
    """"G01" -> "G1"; CycleError for a code that may not move in the region."""
    try:
        number = float(code[1:])
    except ValueError:
        raise _fail("G", code, "is not a G code") from None
    name = "G%g" % number
    if name == "G0":
        raise _fail("G", code, "rapid moves are not allowed in a G7.1 region (cylindrical interpolation)")
    if name not in MOTIONS:
        raise _fail("G", code, "only G1, G2 and G3 may be programmed in a G7.1 region")
    return name


def read_path_block(text: str, motion: Optional[str]) -> PathBlock:
    """One path block; ``motion`` is the motion in force (None before the first)."""
    code, words = split_words(text)
    if code is not None:
        if spelling(code):
            raise _fail("G", code, "a second G7.1 start inside the region: cancel with %s C0 first" % code)
        motion = motion_of(code)
    if motion is None:
        raise _fail("G", None, "the first path block of a G7.1 region needs G1, G2 or G3")
    values: Dict[str, float] = {}
    for letter, number in words:
        if letter in _REFUSED_IN_PATH:
            raise _fail(letter, float(number), _REFUSED_IN_PATH[letter])
        if letter not in ("Z", "C", "R", "F"):
            raise _fail(letter, float(number), "is not a word of a G7.1 path block (words: Z C R F)")
        values[letter.lower()] = _decimal(letter, number)
    return PathBlock(motion, **values)


def read_start_block(text: str) -> Tuple[str, Dict[str, float]]:
    """The start (or cancel) block: its spelling and its words {C, J, R, K, L}."""
    code, words = split_words(text)
    if spelling(code) is None:
        raise _fail("G", code, "a G7.1 region starts with G7.1 (G07.1, G107) C(radius)")
    values: Dict[str, float] = {}
    for letter, number in words:
        if letter not in GskG7_1.WORDS:
            raise _fail(letter, float(number), "only C, J, R, K, L may share the %s block" % code)
        if letter == "L":
            if "." in number or number.startswith("-"):
                raise _fail("L", float(number), "must be a whole number of passes, without a decimal point")
            values[letter] = int(number)
        else:
            values[letter] = _decimal(letter, number)
    return spelling(code), values


# ---------------------------------------------------------------- the developed plane

Point = Tuple[float, float]  # (z, s): s = the developed length of C, radius * C in radians


def arc_points(start: Point, end: Point, radius: float, clockwise: bool, scale: float = 1.0) -> List[Point]:
    """The points after ``start`` of straight segments within ARC_CHORD_TOLERANCE of
    the arc (R form, under 180 degrees); the last is ``end`` exactly. ``scale``:
    the program's length unit per mm (1 / 25.4 in inch programs)."""
    (z0, s0), (z1, s1) = start, end
    chord = math.hypot(z1 - z0, s1 - s0)
    if chord == 0.0:
        raise _fail("R", radius, "an arc by R needs an end point other than its start (a full circle cannot be "
                    "written with R)")
    half = chord / 2.0
    if half > radius + ARC_R_TOLERANCE * scale:
        raise _fail("R", radius, "the arc's end is out of reach: the chord is %s on the developed surface"
                    % format_decimal(chord, DECIMALS, point=False))
    height = math.sqrt(max(0.0, radius * radius - half * half))
    side = 1.0 if clockwise else -1.0  # clockwise: the centre is right of the chord
    dz, ds = (z1 - z0) / chord, (s1 - s0) / chord
    cz, cs = (z0 + z1) / 2.0 + side * height * ds, (s0 + s1) / 2.0 - side * height * dz
    a0, a1 = math.atan2(s0 - cs, z0 - cz), math.atan2(s1 - cs, z1 - cz)
    sweep = (a1 - a0) % (2.0 * math.pi) if not clockwise else -((a0 - a1) % (2.0 * math.pi))
    radius = max(radius, half)
    step = 2.0 * math.acos(max(-1.0, 1.0 - ARC_CHORD_TOLERANCE * scale / radius))
    count = max(1, math.ceil(abs(sweep) / step - 1e-9))
    points = [(cz + radius * math.cos(a0 + sweep * k / count), cs + radius * math.sin(a0 + sweep * k / count))
              for k in range(1, count)]
    return points + [end]


def developed_feed(start: Point, end: Point, feed: float, radius: float) -> float:
    """The F that runs the developed segment at ``feed`` on LinuxCNC's rule: F is
    along Z when Z moves, else degrees per minute of C."""
    dz, ds = abs(end[0] - start[0]), abs(end[1] - start[1])
    length = math.hypot(dz, ds)
    if dz > 0.0:
        return feed * dz / length
    return feed * 180.0 / (math.pi * radius)


class Segment(NamedTuple):
    """A straight piece of the path: its end (z, C degrees) and the F to write."""

    z: float
    c: float
    f: float


def path_segments(radius: float, start: Tuple[float, float], blocks: Tuple[PathBlock, ...],
                  feed: Optional[float], scale: float = 1.0) -> List[Segment]:
    """The path from ``start`` (z, C degrees) as straight segments; ``feed`` the feed
    in force before the first block; ``scale`` the length unit per mm (arc_points)."""
    to_s = radius * math.pi / 180.0
    z, c = start
    out: List[Segment] = []
    for block in blocks:
        feed = block.f if block.f is not None else feed
        if feed is None:
            raise _fail("F", None, "no feed in force for the G7.1 path: program F in its first block or before")
        end_z = block.z if block.z is not None else z
        end_c = block.c if block.c is not None else c
        here, there = (z, c * to_s), (end_z, end_c * to_s)
        if block.motion == "G1":
            points = [there] if there != here else []
        else:
            points = arc_points(here, there, block.r, block.motion == "G2", scale)
        for point in points:
            out.append(Segment(point[0], point[1] / to_s, developed_feed(here, point, feed, radius)))
            here = point
        z, c = end_z, end_c
        if out and block.motion != "G1":
            out[-1] = out[-1]._replace(z=end_z, c=end_c)  # the block's end exactly, not through s and back
    return out


# ---------------------------------------------------------------- the region


@register
@dataclass(frozen=True)
class GskG7_1(Cycle):
    """GSK ``G7.1 C(c) [J R K L]`` ... path ... ``G7.1 C0``: cylindrical interpolation
    (Type I) and its roughing cycle (Type II); see the module notes."""

    NAME: ClassVar[str] = NAME
    KEY: ClassVar[str] = "gsk-g7.1"
    ALIASES: ClassVar[tuple] = ("g7.1", "g107")
    DIALECTS: ClassVar[tuple] = ("gsk",)
    TITLE: ClassVar[str] = "GSK G7.1 cylindrical interpolation and its roughing cycle (a region up to G7.1 C0)"
    FORM: ClassVar[str] = G_WORD
    BLOCKS: ClassVar[type] = RegionBlocks  # the blocks up to the cancel block belong to the call
    C_AXIS: ClassVar[bool] = True  # an end mill on the developed surface
    WORDS: ClassVar[tuple] = ("C", "J", "R", "K", "L")
    TYPE_II: ClassVar[tuple] = ("J", "R", "K", "L")
    WORD_HELP: ClassVar[tuple] = (
        ("C", "radius of the cylinder (C0 is the cancel block)"),
        ("J", "Type II: total cut along X (diameter, signed: - infeeds toward -X)"),
        ("R", "Type II: retraction along X above the cylinder (diameter, no sign)"),
        ("K", "Type II: finishing allowance along X (diameter, no sign)"),
        ("L", "Type II: rough passes, the finish not counted (1..9999; L1 runs as 2)"),
    )

    C: float
    path: Tuple[PathBlock, ...] = ()
    J: Optional[float] = None
    R: Optional[float] = None
    K: Optional[float] = None
    L: Optional[int] = None
    code: str = NAME  # the spelling read: G7.1, G07.1, G107

    @property
    def type_ii(self) -> bool:
        return self.J is not None

    # -- validation -------------------------------------------------------------------

    def validate(self, settings: Settings = DEFAULT_SETTINGS) -> "GskG7_1":
        """CycleError on the first rule the region breaks; returns self."""
        if self.code not in SPELLINGS:
            raise _fail("G", self.code, "must be one of %s" % ", ".join(SPELLINGS))
        _check_number("C", self.C, positive=True)
        given = [word for word in self.TYPE_II if getattr(self, word) is not None]
        if given and len(given) < len(self.TYPE_II):
            missing = next(word for word in self.TYPE_II if getattr(self, word) is None)
            raise _fail(missing, None, "must be programmed: Type II needs J, R, K and L (Type I has none of them)")
        if given:
            self._validate_type_ii()
        if not self.path:
            raise _fail("path", None, "a G7.1 region needs at least one G1/G2/G3 block before its cancel block")
        for block in self.path:
            self._validate_block(block)
        return self

    def _validate_type_ii(self) -> None:
        _check_number("J", self.J)
        if self.J == 0:
            raise _fail("J", self.J, "the total cut must not be 0")
        if not 2.0 * self.C + self.J > 0:
            raise _fail("J", self.J, "the finish diameter 2C+J = %s must be greater than 0: the cut would leave "
                        "the cylinder through its axis" % format_decimal(2.0 * self.C + self.J, DECIMALS, False))
        for letter in ("R", "K"):
            _check_number(letter, getattr(self, letter))
            if getattr(self, letter) < 0:
                raise _fail(letter, getattr(self, letter), "is written without a sign: must not be negative")
        if not self.K < abs(self.J):
            raise _fail("K", self.K, "the finishing allowance must be less than the total cut |J| = %s"
                        % format_decimal(abs(self.J), DECIMALS, False))
        if isinstance(self.L, bool) or not isinstance(self.L, int) or not 1 <= self.L <= MAX_PASSES:
            raise _fail("L", self.L, "must be a whole number of passes from 1 to %d" % MAX_PASSES)

    @staticmethod
    def _validate_block(block: PathBlock) -> None:
        if block.motion not in MOTIONS:
            raise _fail("G", block.motion, "only G1, G2 and G3 may be programmed in a G7.1 region")
        if block.z is None and block.c is None:
            raise _fail(block.motion, None, "a path block needs Z or C")
        for letter, value in (("Z", block.z), ("C", block.c)):
            if value is not None:
                _check_number(letter, value)
        if block.f is not None:
            _check_number("F", block.f, positive=True)
        if block.motion == "G1" and block.r is not None:
            raise _fail("R", block.r, "a G1 block has no arc radius")
        if block.motion != "G1":
            if block.r is None:
                raise _fail("R", None, "%s needs its radius R on the developed surface" % block.motion)
            _check_number("R", block.r)
            if not block.r > 0:
                raise _fail("R", block.r, "must be greater than 0 (arcs over 180 degrees are not supported)")

    # -- expansion -----------------------------------------------------------------------

    def expand(self, state: MachineState, settings: Settings = DEFAULT_SETTINGS) -> List[Move]:
        """The moves of the region from ``state`` (x radius, z, c degrees, feed)."""
        self.validate(settings)
        if state.c is None:
            raise _fail("C", None, "the C position before %s is not known: program C before the region" % self.code)
        if state.feed_per_rev:
            raise _fail("G99", None, "cylindrical interpolation feeds per minute: program G98 before %s" % self.code)
        scale = 1.0 if state.metric else 1.0 / MM_PER_INCH
        segments = path_segments(self.C, (state.z, state.c), self.path, state.feed, scale)
        if not segments:  # every block ends where the tool is: no slot (Type II would retract from nowhere)
            raise _fail("path", None, "no block of the region moves Z or C from where the tool is (Z%s C%s): "
                        "nothing to cut" % (format_decimal(state.z, DECIMALS), format_decimal(state.c, DECIMALS)))
        passes = self.pass_radii(state)
        if len(passes) * (len(segments) + 3) > MAX_MOVES:
            raise _fail("L", self.L, "the region would expand into more than %d moves" % MAX_MOVES)
        if not self.type_ii:
            return [Move(FEED, state.x, seg.z, seg.f, c=seg.c) for seg in segments]
        return self._rough_and_finish(state, segments, passes)

    def pass_radii(self, state: MachineState) -> List[float]:
        """The X (radius) of each pass: Type I the start X; Type II the rough passes then the finish."""
        if not self.type_ii:
            return [state.x]
        sign = 1.0 if self.J > 0 else -1.0
        count = max(self.L, 2)
        rough = [self.C + sign * (abs(self.J) - self.K) / 2.0 * n / count for n in range(1, count + 1)]
        return rough + [self.C + self.J / 2.0]

    def clearance_radius(self) -> float:
        """The X (radius) of the cycle start G: R above the cylinder, away from the cut."""
        sign = 1.0 if self.J > 0 else -1.0
        return self.C - sign * self.R / 2.0

    def _rough_and_finish(self, state: MachineState, segments: List[Segment], passes: List[float]) -> List[Move]:
        sign = 1.0 if self.J > 0 else -1.0
        clear = self.clearance_radius()
        if sign * (state.x - clear) > 1e-9:
            raise _fail("X", state.x * 2.0, "the start must be at the cycle start X%s (2C - sign(J)*R) or farther "
                        "from the cut" % format_decimal(clear * 2.0, DECIMALS))
        infeed = state.feed if state.feed is not None else next(b.f for b in self.path if b.f is not None)
        moves = []
        if state.x != clear:
            moves.append(Move(RAPID, clear, state.z, c=state.c))  # F -> G
        for radius in passes:
            moves.append(Move(FEED, radius, state.z, infeed, c=state.c))  # G -> An
            moves.extend(Move(FEED, radius, seg.z, seg.f, c=seg.c) for seg in segments)  # An -> Dn
            end = segments[-1]
            moves.append(Move(RAPID, clear, end.z, c=end.c))  # Dn -> E
            if (end.z, end.c) != (state.z, state.c):  # a path back to its start: E is G already
                moves.append(Move(RAPID, clear, state.z, c=state.c))  # E -> G
            infeed = next((b.f for b in reversed(self.path) if b.f is not None), infeed)
        return moves

    # -- text ------------------------------------------------------------------------------

    def emit(self) -> str:
        """The region as GSK blocks, one per line: start, path, cancel."""
        start = [self.code, _word_text("C", self.C)]
        for letter in self.TYPE_II:
            value = getattr(self, letter)
            if value is not None:
                start.append("L%d" % value if letter == "L" else _word_text(letter, value))
        lines = [" ".join(start)]
        for block in self.path:
            words = [block.motion]
            for letter, value in (("Z", block.z), ("C", block.c), ("R", block.r), ("F", block.f)):
                if value is not None:
                    words.append(_word_text(letter, value))
            lines.append(" ".join(words))
        lines.append("%s C0" % self.code)
        return "\n".join(lines)

    # -- the region block by block (the program reader) ----------------------------------

    @classmethod
    def region_ends(cls, text: str) -> bool:
        """Whether the block ``text`` is the cancel block that closes the region."""
        return is_cancel_block(text)

    @classmethod
    def check_region_block(cls, text: str, context: Optional[str]) -> Optional[str]:
        """CycleError when the path block ``text`` may not be in the region, checked
        as it is read; ``context`` is what the block before returned (None first)."""
        return read_path_block(text, context).motion

    @classmethod
    def parse(cls, text: str) -> "GskG7_1":
        """A whole region: blocks on lines or separated by ``;``."""
        blocks = [block for block in text.replace(";", "\n").split("\n") if block.strip()]
        if not blocks:
            raise _fail("G", None, "a G7.1 region starts with G7.1 C(radius)")
        code, words = read_start_block(blocks[0])
        if "C" not in words or words["C"] == 0:
            raise _fail("C", words.get("C"), "the start block needs the cylinder's radius C (C0 cancels)")
        if len(blocks) < 2 or not is_cancel_block(blocks[-1]):
            raise _fail("G", None, "a G7.1 region ends with its cancel block %s C0" % code)
        path, motion = [], None
        for block in blocks[1:-1]:
            path.append(read_path_block(block, motion))
            motion = path[-1].motion
        return cls(C=words["C"], path=tuple(path), J=words.get("J"), R=words.get("R"), K=words.get("K"),
                   L=words.get("L"), code=code).validate()


def is_cancel_block(text: str) -> bool:
    """Whether ``text`` is the cancel block ``G7.1 C0`` (any spelling); CycleError
    when it is a G7.1 block with other words than C0."""
    code, words = split_words(text)
    if spelling(code) is None:
        return False
    values = dict(words)
    if "C" in values and float(values["C"]) == 0:
        if len(values) > 1:
            raise _fail(next(letter for letter in values if letter != "C"), None,
                        "the cancel block %s C0 holds nothing else" % code)
        return True
    return False
