"""Milltronics mill autoroutines G33 (facing a rectangle) and G34 (clearing a
rectangular pocket), as section four of the Milltronics mill manual documents them.

Program shape [documented]: the P parameters are set by assignment blocks
before the call (``P151=1``) and stay in force until changed; the call block
holds the autoroutine's G code, G99 (return to the Z clearance at the end; G98,
not on the seed page, the initial level: the Z before the call [choice]),
G41 or G42 (cutter compensation on), R (clearance plane), Z (final depth), V
(first depth; omitted: R - Q), Q (Z increment) and F (Z feed; the X-Y feed is
the F in force before the call). The rectangle is P151 (X size) x P152 (Y size)
centred on the XY position before the call; P155 is the cut width.

A model holds the block's words and the P parameters it runs with; ``emit()``
writes the assignment blocks and then the call, ``parse()`` reads them back.

Expansion (choices the manual leaves open are marked [choice]; each is a docs/choices.md
row with a test), the tool an end mill of diameter ``Settings.mill_tool_diameter``:

- Depths [documented + choice]: V, V - Q, ... down to Z (the last step clipped
  at Z). Between depths the tool rises ``Settings.milltronics_lift_inch`` (0.1",
  2.54 mm in a metric program) above the depth just cut and rapids to the next
  depth's start, then feeds down at the Z feed.
- The tool stays inside the rectangle [choice]: its edge touches the sides, so
  its centre runs inset by the tool radius (G41 and G42 do the same, the
  Milltronics manual says; without either the same path is cut).
- G33 [documented]: starts at the upper right corner, back and forth along the
  long side (X when the sides are equal [choice]), stepping over along the
  short side; the step-overs are equal and at most P155 [choice].
- G34 [choice where not documented]: plunge at the centre; the centre line
  along the long side, then laps each the inward offset of the last lap by an
  equal step at most P155 (and at most 0.85 tool diameters, LAP_STEP_LIMIT,
  so no island is left between the corners of two laps), out to the walls
  less the X-Y finish stock P153,
  their corners those offsets of the corner radius P150 (0: cut at the tool
  radius); G41 (or none) climbs (counter-clockwise with M3), G42 runs
  clockwise. With P154 the depths stop P154 above Z and one more depth is cut
  at Z; with P153 one finishing lap at the walls follows at Z. The laps'
  rounded corners are arcs (G2 clockwise, G3 counter-clockwise, in G17 with
  their centres), a quarter arc shorter than numbers.MIN_ARC_CHORD (its end
  rounded could turn it the other way round) a chord, inside it.
- The tool's moves are made in ``milltronics_paths``.
- Before the first depth the tool goes to the clearance plane R, then over the
  start point, rapids to R and feeds down [choice]; at the end G99 rapids to R,
  G98 to the Z before the call, without either the tool rises the lift above
  the last depth [choice]; X and Y stay where the cut ended.
- The Z before the call may be unknown (the seed's own example: ``G43 H1``
  then ``G0 X1 Y2``, no Z): as the control does, the tool rapids in X and Y
  over the start at the height it is at, then Z to R [choice: nothing is
  assumed of that height]; only G98, which returns to it, is refused.
"""

import re
from dataclasses import dataclass, fields, replace
from typing import ClassVar, Dict, List, Optional, Tuple

from ..cycle import Cycle
from ..errors import CycleError
from ..moves import RAPID, MachineState, Move
from ..numbers import MAX_MOVES, MM_PER_INCH
from ..registry import G_WORD, register
from ..settings import DEFAULT_SETTINGS, Settings
from .cycle_words import check_number, word_value
from .milltronics_paths import TOLERANCE, Cut, facing_moves, pocket_moves

__all__ = ["G31", "G32", "G33", "G34", "MilltronicsCycle"]

PARAMETERS = ("P150", "P151", "P152", "P153", "P154", "P155")
LETTERS = ("R", "Z", "V", "Q", "F")
COMPENSATION = ("G41", "G42")
RETURNS = ("G98", "G99")  # the initial level (the Z before the call), the clearance plane R
Memory = Dict[str, float]  # "P151" -> value, "R" -> the last clearance plane

_ASSIGNMENT = re.compile(r"^P(\d+)=([+-]?(?:\d+\.?\d*|\.\d+))$")
_WORD = re.compile(r"([A-Z])([+-]?(?:\d+\.?\d*|\.\d+))")


def _read_assignment(line: str, name: str, values: Dict[str, object]) -> None:
    match = _ASSIGNMENT.match(line)
    key = "P" + str(int(match.group(1)))
    if key not in PARAMETERS:
        raise CycleError(key, None, "is not a parameter of the autoroutines (%s)" % ", ".join(PARAMETERS), cycle=name)
    values[key] = float(match.group(2))


def _read_call(line: str, cls: type, values: Dict[str, object]) -> None:
    name = cls.NAME
    pos, seen = 0, False
    while pos < len(line):
        match = _WORD.match(line, pos)
        if match is None:
            raise CycleError("block", line, "is not a %s block (letter-number words)" % name, cycle=name)
        letter, number = match.groups()
        pos = match.end()
        if letter == "G":
            code = "G%d" % int(float(number)) if float(number).is_integer() else "G" + number
            if code == name and not seen:
                seen = True
            elif code in RETURNS and code in cls.OPTIONS:
                if values.get("G98" if code == "G99" else "G99"):
                    raise CycleError(code, None, "G98 and G99 in one block: program one", cycle=name)
                values[code] = True
            elif code in COMPENSATION and code in cls.OPTIONS:
                if values.get("compensation") not in (None, code):
                    raise CycleError(code, None, "G41 and G42 in one block: program one", cycle=name)
                values["compensation"] = code
            else:
                raise CycleError(code, None, "may not share the %s block" % name, cycle=name)
        elif letter in cls.WORDS and letter not in values:
            values[letter] = float(number)
        else:
            raise CycleError(letter, float(number), "is not a word of %s (or is given twice)" % name, cycle=name)
    if not seen:
        raise CycleError("block", line, "does not call %s" % name, cycle=name)


@dataclass(frozen=True)
class MilltronicsCycle(Cycle):
    """The words and P parameters shared by G33 and G34 (see the module notes)."""

    NAME: ClassVar[str] = ""
    DIALECTS: ClassVar[tuple] = ("milltronics",)
    FORM: ClassVar[str] = G_WORD
    MEMORY: ClassVar[str] = "milltronics"  # the P parameters and the last R, for the next call
    MILL: ClassVar[bool] = True
    COUNTED: ClassVar[tuple] = ()
    WORDS: ClassVar[tuple] = LETTERS  # the call's letter words; the P parameters come from assignment blocks
    OPTIONS: ClassVar[tuple] = RETURNS + COMPENSATION  # the G codes the call block may hold
    FROM_UNKNOWN_Z: ClassVar[bool] = True  # X Y at the height held, then Z to R: needs no Z before the call
    PARAMETERS: ClassVar[tuple] = PARAMETERS  # set by assignment blocks (the translator keeps them under MEMORY)
    MEMORY_WHAT: ClassVar[str] = "the P parameters and the clearance plane R %s runs with"

    R: Optional[float] = None
    Z: Optional[float] = None
    V: Optional[float] = None
    Q: Optional[float] = None
    F: Optional[float] = None
    G99: bool = False
    G98: bool = False
    compensation: Optional[str] = None  # "G41", "G42" or None
    P150: Optional[float] = None
    P151: Optional[float] = None
    P152: Optional[float] = None
    P153: Optional[float] = None
    P154: Optional[float] = None
    P155: Optional[float] = None

    @classmethod
    def parse(cls, text: str) -> "MilltronicsCycle":
        """The model of ``P1nn=value`` assignment lines and the call block; CycleError naming the word."""
        values: Dict[str, object] = {}
        lines = ["".join(line.split()).upper().rstrip(";") for line in text.split("\n")]
        lines = [line for line in lines if line]
        if not lines:
            raise CycleError("block", text, "is empty", cycle=cls.NAME)
        for line in lines[:-1]:
            if not _ASSIGNMENT.match(line):
                raise CycleError("block", line, "only P assignments (P151=1) may come before the call", cycle=cls.NAME)
            _read_assignment(line, cls.NAME, values)
        _read_call(lines[-1], cls, values)
        return cls(**values).validate()

    def emit(self) -> str:
        """The assignment blocks and the call as the control reads them."""
        lines = ["%s=%s" % (key, word_value(getattr(self, key))) for key in PARAMETERS
                 if getattr(self, key) is not None]
        parts = [self.NAME] + [code for code in RETURNS if getattr(self, code)]
        parts += [self.compensation] if self.compensation else []
        parts += [letter + word_value(getattr(self, letter), letter) for letter in LETTERS
                  if getattr(self, letter) is not None]
        return "\n".join(lines + [" ".join(parts)])

    def _error(self, name: str, rule: str) -> CycleError:
        return CycleError(name, getattr(self, name, None), rule, cycle=self.NAME)

    def validate(self, settings: Settings = DEFAULT_SETTINGS) -> "MilltronicsCycle":
        """The rules on the words and parameters as held; returns self."""
        for item in fields(self):
            value = getattr(self, item.name)
            if item.name in LETTERS + PARAMETERS and value is not None:
                check_number(self.NAME, item.name, value)
        if self.compensation not in (None,) + COMPENSATION:
            raise self._error("compensation", "must be G41, G42 or none")
        if self.G98 and self.G99:
            raise CycleError("G98", None, "G98 and G99 in one block: program one", cycle=self.NAME)
        if self.Q is not None and not self.Q > 0:
            raise self._error("Q", "must be greater than 0: the depths would never reach Z")
        if self.F is not None and not self.F > 0:
            raise self._error("F", "must be greater than 0")
        if self.V is not None and self.Z is not None and self.V < self.Z - TOLERANCE:
            raise self._error("V", "the first depth is below the final depth Z%s" % word_value(self.Z))
        for key in ("P151", "P152", "P155"):
            value = getattr(self, key)
            if value is not None and not value > 0:
                raise self._error(key, "must be greater than 0")
        for key in ("P150", "P153", "P154"):
            value = getattr(self, key)
            if value is not None and value < 0:
                raise self._error(key, "must not be negative")
        if settings.mill_tool_diameter is not None:
            self._check_tool(settings.mill_tool_diameter)
        return self

    def _check_tool(self, diameter: float) -> None:
        if not diameter > 0:
            raise CycleError("tool diameter", diameter, "must be greater than 0", cycle=self.NAME)
        if self.P155 is not None and self.P155 > diameter + TOLERANCE:
            raise self._error("P155", "the cut width is larger than the tool (diameter %s): ridges would be left"
                              % word_value(diameter))

    # -- the program's memory -------------------------------------------------------

    def with_earlier(self, memory: Memory, state: MachineState) -> "MilltronicsCycle":
        """This call with the P parameters in force and the last clearance plane R."""
        filled = {key: memory[key] for key in PARAMETERS + ("R",) if getattr(self, key) is None and key in memory}
        return replace(self, **filled)

    def remembered(self, state: MachineState) -> Memory:
        """The P parameters in force and the clearance plane, for what follows."""
        return {key: getattr(self, key) for key in PARAMETERS + ("R",) if getattr(self, key) is not None}

    # -- the plan ---------------------------------------------------------------------

    def _require(self, name: str, why: str) -> float:
        value = getattr(self, name)
        if value is None:
            raise CycleError(name, None, "must be given (%s)" % why, cycle=self.NAME)
        return value

    def _depths(self, clearance: float, final: float) -> Tuple[float, ...]:
        """V, V - Q, ... down to ``final`` (Z, or Z + P154)."""
        if not final < clearance - TOLERANCE:
            raise self._error("Z", "the final depth must be below the clearance plane R%s" % word_value(clearance))
        first = self.V
        if first is None:
            first = clearance - self._require("Q", "the first depth without V is R - Q")
        if first > clearance + TOLERANCE:
            raise self._error("V", "the first depth is above the clearance plane R%s" % word_value(clearance))
        if first < final - TOLERANCE:
            name = "V" if self.V is not None else "Q"
            raise CycleError(name, getattr(self, name), "the first depth %s is below the final depth %s"
                             % (word_value(first), word_value(final)), cycle=self.NAME)
        depths = [max(first, final)]
        while depths[-1] > final + TOLERANCE:
            step = self._require("Q", "more than one depth from V to Z")
            depths.append(max(depths[-1] - step, final))
            if len(depths) > MAX_MOVES:
                raise self._error("Q", "too small for the depth: more than %d depths" % MAX_MOVES)
        return tuple(depths)

    def plan(self, state: MachineState, settings: Settings, final: Optional[float] = None) -> Cut:
        """Every value resolved against the start ``state``; CycleError on a rule broken."""
        self.validate(settings)
        diameter = settings.mill_tool_diameter
        if diameter is None:
            raise CycleError("tool diameter", None, "is not known: give the end mill's diameter with "
                             "--tool-diameter, or program D<n> and give a tool table of diameters by D",
                             cycle=self.NAME)
        for axis, value in (("X", state.x), ("Y", state.y)):
            if value is None:
                raise CycleError(axis, None, "the start position is not known: program it before the call",
                                 cycle=self.NAME)
        if state.z is None and self.G98:
            raise CycleError("G98", None, "returns to the Z before the call, which is not known: program Z before "
                             "the call, or G99 (return to R)", cycle=self.NAME)
        if state.incremental:
            raise CycleError("G91", None, "R, Z and V are read as absolute Z: program the autoroutine in G90",
                             cycle=self.NAME)
        size_x = self._require("P151", "the X size of the rectangle, P151=...")
        size_y = self._require("P152", "the Y size of the rectangle, P152=...")
        width = self._require("P155", "the cut width, P155=...")
        clearance = self._require("R", "the clearance plane; no earlier call gave it")
        z = self._require("Z", "the final depth")
        if state.feed is None:
            raise CycleError("F", None, "no X-Y feed in force: program F before the call", cycle=self.NAME)
        for key, size in (("P151", size_x), ("P152", size_y)):
            if size < diameter - TOLERANCE:
                raise self._error(key, "the rectangle is smaller than the tool (diameter %s)" % word_value(diameter))
        lift = settings.milltronics_lift_inch * (MM_PER_INCH if state.metric else 1.0)
        depths = self._depths(clearance, z if final is None else final)
        return Cut(state.x, state.y, state.z, size_x, size_y, width, diameter / 2.0, clearance, depths, lift,
                   state.feed, state.feed if self.F is None else self.F, self._back_to(state, clearance),
                   self.compensation == "G42")

    def _back_to(self, state: MachineState, clearance: float) -> Optional[float]:
        """The Z the cycle ends at: G99 R, G98 the Z before the call; None: the lift above the last depth."""
        if self.G99:
            return clearance
        return state.z if self.G98 else None


@register
@dataclass(frozen=True)
class G33(MilltronicsCycle):
    """Milltronics ``G33`` facing autoroutine."""

    NAME: ClassVar[str] = "G33"
    KEY: ClassVar[str] = "milltronics-g33"
    ALIASES: ClassVar[tuple] = ("g33",)
    TITLE: ClassVar[str] = "Milltronics G33 facing a rectangle P151 x P152 (cut width P155) centred on the start"
    WORD_HELP: ClassVar[tuple] = (
        ("R", "clearance plane (default the last R of the program)"),
        ("Z", "final depth"),
        ("V", "first depth (default R - Q)"),
        ("Q", "Z increment, greater than 0"),
        ("F", "Z feed (default the X-Y feed in force)"),
    )

    def expand(self, state: MachineState, settings: Settings = DEFAULT_SETTINGS) -> List[Move]:
        """The moves of the facing from ``state`` (see the module notes)."""
        return facing_moves(self.plan(state, settings), self.NAME)


@register
@dataclass(frozen=True)
class G34(MilltronicsCycle):
    """Milltronics ``G34`` rectangular pocket autoroutine."""

    NAME: ClassVar[str] = "G34"
    KEY: ClassVar[str] = "milltronics-g34"
    ALIASES: ClassVar[tuple] = ("g34",)
    TITLE: ClassVar[str] = ("Milltronics G34 rectangular pocket P151 x P152 centred on the start, corner radius P150, "
                            "finish stock P153 (X-Y) and P154 (Z), cut width P155")
    WORD_HELP: ClassVar[tuple] = G33.WORD_HELP

    def expand(self, state: MachineState, settings: Settings = DEFAULT_SETTINGS) -> List[Move]:
        """The moves of the pocket from ``state`` (see the module notes)."""
        floor = self.P154 or 0.0
        z = self._require("Z", "the final depth")
        cut = self.plan(state, settings, z + floor)
        self._check_pocket(cut)
        return pocket_moves(cut, self.P153 or 0.0, self.P150 or 0.0, z if floor > 0 else None, self.NAME)

    def _check_pocket(self, cut: Cut) -> None:
        corner, stock = self.P150 or 0.0, self.P153 or 0.0
        if 0 < corner < cut.radius - TOLERANCE:
            raise self._error("P150", "the corner radius is smaller than the tool radius %s (0 cuts the corners at "
                                      "the tool radius)" % word_value(cut.radius))
        if corner > min(cut.size_x, cut.size_y) / 2.0 + TOLERANCE:
            raise self._error("P150", "the corner radius is more than half the pocket's short side")
        for key, size in (("P151", cut.size_x), ("P152", cut.size_y)):
            if size - 2 * stock < 2 * cut.radius - TOLERANCE:
                raise CycleError("P153", stock, "the pocket less the finish stock on both walls (%s = %s) is "
                                 "smaller than the tool" % (key, word_value(size)), cycle=self.NAME)


@register
@dataclass(frozen=True)
class G31(MilltronicsCycle):
    """Milltronics ``G31``: Z rapids to the clearance plane, the last R of the program,
    else ``Settings.milltronics_clearance_inch`` (parameter 140)."""

    NAME: ClassVar[str] = "G31"
    KEY: ClassVar[str] = "milltronics-g31"
    ALIASES: ClassVar[tuple] = ("g31",)
    TITLE: ClassVar[str] = "Milltronics G31 Z to the clearance position (the last R, else parameter 140)"
    WORDS: ClassVar[tuple] = ()
    OPTIONS: ClassVar[tuple] = ()
    PARAMETERS: ClassVar[tuple] = ()  # reads none (the P parameters pass through its memory unchanged)
    WORD_HELP: ClassVar[tuple] = ()
    Z_ONLY: ClassVar[bool] = True  # moves Z alone: the translator needs no X Y before it
    FROM_UNKNOWN_Z: ClassVar[bool] = False  # Z_ONLY needs no start point at all

    def height(self, state: MachineState, settings: Settings) -> float:
        """The Z the block goes to, in the program's units."""
        if self.R is not None:
            return self.R
        return settings.milltronics_clearance_inch * (MM_PER_INCH if state.metric else 1.0)

    def note(self, state: MachineState, settings: Settings) -> str:
        """The Z used and where it comes from, for the translated program's comment."""
        source = "the last R" if self.R is not None else "setting milltronics_clearance_inch"
        return "Z%s, %s" % (word_value(self.height(state, settings)), source)

    def expand(self, state: MachineState, settings: Settings = DEFAULT_SETTINGS) -> List[Move]:
        """One rapid of Z alone (X and Y None: held, and not needed, so the call may come before any X Y, as
        the G32 at the start of a program does)."""
        return [Move(RAPID, None, self.height(state, settings), None, 0.0, None)]


@register
@dataclass(frozen=True)
class G32(G31):
    """Milltronics ``G32``: Z rapids to the tool change position, ``Settings.milltronics_tool_change_inch``."""

    NAME: ClassVar[str] = "G32"
    KEY: ClassVar[str] = "milltronics-g32"
    ALIASES: ClassVar[tuple] = ("g32",)
    TITLE: ClassVar[str] = "Milltronics G32 Z to the tool change position (a machine setting)"

    def height(self, state: MachineState, settings: Settings) -> float:
        return settings.milltronics_tool_change_inch * (MM_PER_INCH if state.metric else 1.0)

    def note(self, state: MachineState, settings: Settings) -> str:
        return "Z%s, setting milltronics_tool_change_inch" % word_value(self.height(state, settings))
