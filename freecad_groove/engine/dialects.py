"""What each dialect's codes mean, as data: one :class:`Dialect` per ``--dialect``.

A *dialect* is the control a program is read as: "sinumerik", "ab9",
"ab9grind", "milltronics", "fanuc", "haas", "gsk" (the keys of ``DIALECTS``);
the output side is the *target* (output/targets.py). What differs between the
dialects is here and nowhere else: the G-code table, the letters a block may
hold, the decimal-point rule, the dwell and tool words, what a cycle leaves
modal. Their grooving cycles come from the cycle registry
(``registry.cycles_of``): Siemens calls (``NAME(...)``, FORM CALL) are read by
the tokenizer (reader.py), G-word cycles (FORM G_WORD) are added to the
dialect's G-code table (``Dialect.code_table``).
"""

from dataclasses import dataclass, field, replace
from typing import Dict, FrozenSet, Mapping, NamedTuple, Optional, Tuple

from .moves import FEED, RAPID
from .registry import CALL, G_WORD, CycleEntry, cycles_of

__all__ = [
    "DIALECTS",
    "Dialect",
    "GCode",
    "Units",
    "dialect_named",
    "g_code_key",
]

# ---------------------------------------------------------------- G codes

# modal groups (and kinds) of the G codes the reader knows
MOTION = "motion"
DWELL = "dwell"
PLANE = "plane"
COMPENSATION = "compensation"
CSS = "constant surface speed"
OFFSET = "work offset"
UNITS = "units"
DISTANCE = "distance mode"
FEED_MODE = "feed mode"
DIAMETER = "diameter mode"
SPEED_LIMIT = "spindle speed limit"
CYCLE = "cycle"
# G codes only a cycle's block may hold (Milltronics G98/G99 and G41/G42 with G33/G34), two modal groups
CYCLE_RETURN = "cycle option: return"
CYCLE_COMPENSATION = "cycle option: compensation"
CYCLE_OPTIONS = (CYCLE_RETURN, CYCLE_COMPENSATION)
REFUSED = "refused"
LENGTH_OFFSET = "tool length offset"  # Milltronics G43 H<n> (True) / G49 (False)
MODE_GROUPS = (UNITS, DISTANCE, FEED_MODE, DIAMETER)  # may share a block with a cycle


class GCode(NamedTuple):
    """What a G code means: its group and a value the group's handler reads
    (the motion kind, True for G91, a Units, the cycle's name, a refusal's reason...)."""

    group: str
    value: object = None


class Units(NamedTuple):
    """A units code: metric or inch, and whether the feed stays in the basic
    system (Siemens G70: inch lengths, metric feed)."""

    metric: bool
    feed_in_basic_system: bool = False


_PLANE_ONLY_XZ = "only the XZ plane (G18) is supported on a lathe"
_NOSE_RADIUS = "tool nose radius compensation (G41/G42) is not translated"

_COMMON = {
    "0": GCode(MOTION, RAPID),
    "1": GCode(MOTION, FEED),
    "2": GCode(MOTION, "G2"),
    "3": GCode(MOTION, "G3"),
    "4": GCode(DWELL),
    "18": GCode(PLANE),
    "17": GCode(REFUSED, _PLANE_ONLY_XZ),
    "19": GCode(REFUSED, _PLANE_ONLY_XZ),
    "40": GCode(COMPENSATION),
    "41": GCode(REFUSED, _NOSE_RADIUS),
    "42": GCode(REFUSED, _NOSE_RADIUS),
    "96": GCode(CSS, True),
    "97": GCode(CSS, False),
    "54": GCode(OFFSET, "G54"),
    "55": GCode(OFFSET, "G55"),
    "56": GCode(OFFSET, "G56"),
    "57": GCode(OFFSET, "G57"),
}
_G58_G59 = {"58": GCode(OFFSET, "G58"), "59": GCode(OFFSET, "G59")}
_G20_G21 = {"20": GCode(UNITS, Units(metric=False)), "21": GCode(UNITS, Units(metric=True))}
_G90_G91 = {"90": GCode(DISTANCE, False), "91": GCode(DISTANCE, True)}
_G94_G95 = {"94": GCode(FEED_MODE, False), "95": GCode(FEED_MODE, True)}

_SIEMENS_CODES = {
    **_COMMON,
    "70": GCode(UNITS, Units(metric=False, feed_in_basic_system=True)),
    "71": GCode(UNITS, Units(metric=True)),
    "700": GCode(UNITS, Units(metric=False)),
    "710": GCode(UNITS, Units(metric=True)),
    **_G90_G91,
    **_G94_G95,
}

_AB9_CODES = {
    **_COMMON,
    **_G58_G59,
    "7": GCode(DIAMETER, "G07"),
    "8": GCode(DIAMETER, "G08"),
    **_G20_G21,
    **_G90_G91,
    **_G94_G95,
}

# Fanuc and Haas lathes, G code system A
_SYSTEM_A_CODES = {
    **_COMMON,
    **_G58_G59,
    **_G20_G21,
    "98": GCode(FEED_MODE, False),
    "99": GCode(FEED_MODE, True),
    "50": GCode(SPEED_LIMIT),
    "28": GCode(REFUSED, "reference return G28 is not translated (LinuxCNC's G28 goes to a stored position)"),
    "90": GCode(REFUSED, "G90 is the turning cycle on this lathe control (G code system A): not supported"),
    "92": GCode(REFUSED, "G92 is the threading cycle on this lathe control: not supported"),
    "94": GCode(REFUSED, "G94 is the facing cycle on this lathe control (feed per minute is G98): not supported"),
    "70": GCode(REFUSED, "G70 (finishing cycle) is not supported"),
    "71": GCode(REFUSED, "G71 (turning stock removal cycle) is not supported"),
    "72": GCode(REFUSED, "G72 (facing stock removal cycle) is not supported"),
    "73": GCode(REFUSED, "G73 (pattern repeating cycle) is not supported"),
    "76": GCode(REFUSED, "G76 (threading cycle) is not supported"),
}


def g_code_key(text: str) -> Optional[str]:
    """The table key of a G number as written: "00" -> "0", "+1" -> "1", "91.1"
    stays; None for what is not a G number (a sign other than +, no digits)."""
    key = text.lstrip("+")
    whole, _point, fraction = key.partition(".")
    if not (whole.isdigit() or (whole == "" and fraction)) or (fraction and not fraction.isdigit()):
        return None
    if fraction:  # "07.1" -> "7.1" (GSK G07.1); "91.1" stays
        return "%d.%s" % (int(whole) if whole else 0, fraction)
    return str(int(whole))


# M codes every dialect shares: code -> modal group
M_GROUPS = {0: "stop", 1: "stop", 2: "end", 30: "end", 3: "spindle", 4: "spindle", 5: "spindle", 7: "coolant",
            8: "coolant", 9: "coolant"}

# ---------------------------------------------------------------- dialects

# how a dwell word is read (Dialect.dwell_words)
DWELL_SECONDS = "seconds"
DWELL_LENGTH_SECONDS = "seconds, written as a length word (decimal point rule)"
DWELL_MILLISECONDS = "milliseconds, a whole number"
DWELL_POINT_SECONDS = "seconds with a decimal point, milliseconds without"

# how the tool is selected (Dialect.tool_words)
TOOL_AND_EDGE = "T<tool> D<cutting edge>"
TOOL_AND_OFFSET = "T<tool><2-digit offset>"
# the 9/Series grinder: its lathe-style T<tool><offset>, or the mill form T<tool> M06 its posts write
TOOL_AND_OFFSET_OR_M6 = "T<tool><2-digit offset>, or T<tool> M6"
# Milltronics: T<n> M6 changes the tool, G43 H<n> / G49 the length offset, D selects the end mill's diameter
# (mill_tool_table)
DIAMETER_REGISTER = "T<tool> M6, D<diameter register>, G43 H<length offset>"


@dataclass(frozen=True)
class Dialect:
    """What the reader and the translator need to know of one dialect (the control a program is read as)."""

    name: str  # as --dialect names it: "sinumerik"
    maker: str  # for messages: "Siemens"
    help: str  # one line for the command line's --dialect help
    g_codes: Mapping[str, GCode]  # without the cycles: code_table() adds them from the registry
    plain_letters: FrozenSet[str]  # the letters a block other than a cycle or dwell may hold
    letter_refusals: Mapping[str, str] = field(default_factory=dict)  # letter -> why it is refused
    decimal_point: bool = True  # a non-zero length or feed word needs a decimal point
    long_names: bool = False  # Siemens names: keywords, NAME= assignments, NAME(...) calls, X=20
    keywords: Tuple[str, ...] = ()  # words without a value (DIAMON)
    assignments: Tuple[str, ...] = ()  # NAME=value words (CR=5)
    arc_radius_word: str = "R"  # as messages write it: "R", "CR="
    tool_words: str = TOOL_AND_OFFSET
    dwell_words: Mapping[str, str] = field(default_factory=dict)  # letter -> DWELL_* reading
    dwell_refusals: Mapping[str, str] = field(default_factory=dict)  # letter -> message
    dwell_unsupported: str = ""  # when set, G4 is refused with this message
    cycle_keeps_motion: bool = False  # after a cycle the motion mode is the one before it (group 00)
    program_numbers: bool = True  # an O number may name the program
    mill: bool = False  # mill-style programs (a grinder's X/Y/Z): X plain, Y words, output on the targets' mill twins
    parameter_assignments: bool = False  # "P151=1" blocks set the cycles' P parameters (Milltronics)
    feed_per_minute: bool = False  # feed per minute from the start (a mill), without G94

    def cycles(self) -> Tuple[CycleEntry, ...]:
        """The registered cycles this dialect's programs call."""
        return cycles_of(self.name)

    def cycle(self, name: str) -> CycleEntry:
        """The registry entry of this dialect's cycle ``name`` ("G75", "CYCLE93")."""
        return next(entry for entry in self.cycles() if entry.name == name)

    def call_names(self) -> Tuple[str, ...]:
        """The names of the cycles called as ``NAME(...)``."""
        return tuple(entry.name for entry in self.cycles() if entry.form == CALL)

    def code_table(self) -> Dict[str, GCode]:
        """G number (``g_code_key``) -> meaning, the dialect's G-word cycles included."""
        table = dict(self.g_codes)
        for entry in self.cycles():
            if entry.form == G_WORD:
                table[g_code_key(entry.name[1:])] = GCode(CYCLE, entry.name)
        return table

    @property
    def feed_mode_codes(self) -> str:
        """The feed-mode codes as messages name them: "G94/G95", "G98/G99"."""
        codes = sorted((code.value, key) for key, code in self.g_codes.items() if code.group == FEED_MODE)
        return "/".join("G" + key for _, key in codes)


_PLAIN = frozenset("XZFSTMGIK")

_GRINDER_AXES = "the grinder cycles' axes are fixed (X reciprocation, Y plunge, Z crossover): not translated"
_AB9_GRINDER_CODES = {
    **{key: code for key, code in _AB9_CODES.items() if key not in ("7", "8", "96", "97")},
    "2": GCode(REFUSED, "arcs (G02/G03) in a grinder program are not translated"),
    "3": GCode(REFUSED, "arcs (G02/G03) in a grinder program are not translated"),
    "17": GCode(REFUSED, "plane selection: " + _GRINDER_AXES),
    "18": GCode(REFUSED, "plane selection: " + _GRINDER_AXES),
    "19": GCode(REFUSED, "plane selection: " + _GRINDER_AXES),
}

_MILLTRONICS_CODES = {
    **{key: code for key, code in _COMMON.items() if key not in ("17", "18", "19", "96", "97")},
    **_G58_G59,
    **_G20_G21,
    **_G90_G91,
    "2": GCode(REFUSED, "arcs (G02/G03) in a Milltronics program are not translated"),
    "3": GCode(REFUSED, "arcs (G02/G03) in a Milltronics program are not translated"),
    "17": GCode(REFUSED, "plane selection is not translated: the output is in the XY plane (G17) already"),
    "18": GCode(REFUSED, "plane selection: only the XY plane (G17) is translated"),
    "19": GCode(REFUSED, "plane selection: only the XY plane (G17) is translated"),
    "43": GCode(LENGTH_OFFSET, True),
    "49": GCode(LENGTH_OFFSET, False),
    "98": GCode(CYCLE_RETURN, "G98"),
    "99": GCode(CYCLE_RETURN, "G99"),
    "41": GCode(CYCLE_COMPENSATION, "G41"),
    "42": GCode(CYCLE_COMPENSATION, "G42"),
}

_FANUC = Dialect(
    name="fanuc",
    maker="Fanuc",
    help="Fanuc lathe, G code system A (two-block G75/G74: G75 R(e) then G75 X(U) Z(W) P Q R F; "
    "G20/G21, G98/G99, U/W incremental)",
    g_codes=_SYSTEM_A_CODES,
    plain_letters=_PLAIN | {"U", "W", "R"},
    dwell_words={"X": DWELL_LENGTH_SECONDS, "U": DWELL_LENGTH_SECONDS, "P": DWELL_MILLISECONDS},
    cycle_keeps_motion=True,
)

DIALECTS: Dict[str, Dialect] = {
    dialect.name: dialect
    for dialect in (
        Dialect(
            name="sinumerik",
            maker="Siemens",
            help="Siemens (CYCLE93 calls; DIAMON/DIAMOF, G70/G71, G700/G710, G90/G91, G94/G95)",
            g_codes=_SIEMENS_CODES,
            plain_letters=_PLAIN | {"D", "CR", "LIMS"},
            letter_refusals={"R": "Siemens R parameters are not evaluated"},
            decimal_point=False,  # Siemens reads X80 as 80.
            long_names=True,
            keywords=("DIAMON", "DIAMOF", "DIAM90"),
            assignments=("CR", "LIMS"),
            arc_radius_word="CR=",
            tool_words=TOOL_AND_EDGE,
            dwell_words={"F": DWELL_SECONDS},
            dwell_refusals={"S": "G4 S (dwell in spindle revolutions) is not translated: use G4 F<seconds>"},
            program_numbers=False,
        ),
        Dialect(
            name="ab9",
            maker="Allen-Bradley",
            help="Allen-Bradley 9/Series lathe (G77 grooving/cut-off, G76 face grooving; G07/G08, G20/G21, "
            "G90/G91, G94/G95)",
            g_codes=_AB9_CODES,
            plain_letters=_PLAIN | {"R"},
            dwell_unsupported="G04: the 9/Series dwell word is not documented here; not translated",
        ),
        Dialect(
            name="ab9grind",
            maker="Allen-Bradley",
            help="Allen-Bradley 9/Series grinder (G83/G83.1 plunge surface grinding; X/Y/Z, output mill-style "
            "with G17; G20/G21, G90/G91, G94/G95)",
            g_codes=_AB9_GRINDER_CODES,
            plain_letters=frozenset("XYZFSTMG"),
            tool_words=TOOL_AND_OFFSET_OR_M6,
            dwell_unsupported="G04: the 9/Series dwell word is not documented here; not translated",
            mill=True,
        ),
        Dialect(
            name="milltronics",
            maker="Milltronics",
            help="Milltronics mill (G33 facing and G34 rectangular pocket autoroutines with P151=.. assignment "
            "blocks, G31/G32 Z to clearance / tool change; T<n> M6, G43 H<n>/G49, D<n>; X/Y/Z, feed per minute; "
            "G20/G21, G90/G91)",
            g_codes=_MILLTRONICS_CODES,
            plain_letters=frozenset("XYZFSMGDTH"),
            tool_words=DIAMETER_REGISTER,
            decimal_point=False,  # the Milltronics manual writes X1 Y2 F20 for 1", 2", 20 in/min
            dwell_unsupported="G04: the Milltronics dwell word is not documented here; not translated",
            mill=True,
            parameter_assignments=True,
            feed_per_minute=True,
        ),
        _FANUC,
        replace(  # a Fanuc-like lathe that reads the dwell P with or without a decimal point
            _FANUC,
            name="haas",
            maker="Haas",
            help="Haas lathe (one-block G75/G74 X(U) Z(W) I K D F; G20/G21, G98/G99, U/W incremental)",
            dwell_words={"P": DWELL_POINT_SECONDS},
        ),
        replace(  # GSK 980TDi: Fanuc system A codes, Fanuc-style G75/G74, the G7.1 region, a C axis
            _FANUC,
            name="gsk",
            maker="GSK",
            help="GSK 980TDi lathe (G7.1/G07.1/G107 C.. [J R K L] region up to G7.1 C0: cylindrical interpolation "
            "and its roughing cycle; Fanuc-style G75/G74; G0 C.. positions C; G20/G21, G98/G99, U/W incremental)",
            g_codes={**_SYSTEM_A_CODES, "107": GCode(CYCLE, "G7.1")},
            plain_letters=_FANUC.plain_letters | {"C"},
        ),
    )
}


def dialect_named(name: str) -> Dialect:
    """The Dialect ``name`` (a key of DIALECTS); ValueError when unknown."""
    try:
        return DIALECTS[name]
    except KeyError:
        raise ValueError("unknown dialect %r (known: %s)" % (name, ", ".join(DIALECTS))) from None
