"""The syntax of one control's programs, declared as data: :class:`Target`.

A target is a control the output is written for (the command line's ``--to``,
a lathe post's ``LathePost.target``). Everything that differs between the controls' programs
is an attribute here, declared once with its default and read by the one
writer (``writer.py``) and the one program builder (``program.py``): nothing
else asks which control it is. The tables themselves are in ``targets.py``.

The forms an attribute may take are the constants below; a writer method
implements each form once.
"""

from dataclasses import dataclass, field
from typing import Dict, Optional, Tuple

from ..moves import ARC_CCW, ARC_CW, FEED, RAPID

__all__ = [
    "ARC_CENTRE", "ARC_CR", "CSS_D_WORD", "CSS_G50_ALONE", "CSS_LIMS", "C_FEED_COMPOSITE", "C_FEED_LINEAR",
    "LATHE", "MILL", "NativeCycles", "ONE_DIGIT_CODES", "PARENS", "SEMICOLON", "TOOL_EDGE", "TOOL_M6",
    "TOOL_OFFSET", "TWO_DIGIT_CODES", "Target",
]

# What the machine is: the plane of its arcs and what X means.
LATHE = "lathe"  # X across the spindle axis (a diameter or a radius word), Z along it; arcs in XZ (G18)
MILL = "mill"  # X, Y, Z plain coordinates; arcs in XY (G17): mills, and the grinder's X/Y/Z

# How an arc's circle is written.
ARC_CENTRE = "centre"  # I and K (mill: I and J): the centre from the start, radius values
ARC_CR = "cr"  # Siemens CR=: the radius, negative for more than 180 degrees

# Comments.
PARENS = "parens"  # (text)
SEMICOLON = "semicolon"  # ; text (Siemens)

# Tool changes.
TOOL_M6 = "m6"  # T<n> M6, then the length offset: G43 (the tool's own entry), G43 H<n>, G49 (LinuxCNC)
TOOL_OFFSET = "offset"  # T<tool, 2 digits><offset, 2 digits>: the turret indexes, the offset applies (Fanuc)
TOOL_EDGE = "edge"  # T<n> D<edge> (Siemens: D the cutting edge)

# Constant surface speed with its spindle limit.
CSS_D_WORD = "d-word"  # G96 D<limit> S<speed> (LinuxCNC)
CSS_G50_ALONE = "g50"  # G50 S<limit> in a block of its own, then G96 S<speed> (Fanuc, Haas, GSK)
CSS_LIMS = "lims"  # G96 S<speed> LIMS=<limit> (Siemens)

# How the F of a move that turns the C axis (a rotary axis, degrees) is read.
C_FEED_LINEAR = "linear"  # along X/Z when they move, else degrees per minute (LinuxCNC)
C_FEED_COMPOSITE = "composite"  # along the path with degrees counted as mm (Fanuc-compatible controls)

ONE_DIGIT_CODES = {RAPID: "G0", FEED: "G1", ARC_CW: "G2", ARC_CCW: "G3"}
TWO_DIGIT_CODES = {RAPID: "G00", FEED: "G01", ARC_CW: "G02", ARC_CCW: "G03"}


@dataclass(frozen=True)
class NativeCycles:
    """The cycles a target writes as its own calls (``--native-cycles``, the posts' default).

    ``grooves``: "cycle93" (Siemens CYCLE93, every groove), "pecking" (plain
    rectangular grooves as the pecking cycles of ``dialect``: its
    ``longitudinal`` and ``face`` codes), "" none. ``retract_word``: the
    cycle word holding the peck retract e (Fanuc's first-block R), else
    ``retract_setting``: where the control keeps it (named in a comment).
    ``slots``: a Cylinder slot as a G7.1 Type II region. ``grinds``: plunge
    grinds as G83/G83.1. ``mill``: faces and pockets as Milltronics G33/G34."""

    grooves: str = ""
    dialect: str = ""
    longitudinal: str = ""
    face: str = ""
    retract_word: str = ""
    retract_setting: str = ""
    slots: bool = False
    grinds: bool = False
    mill: bool = False


@dataclass(frozen=True)
class Target:
    """One control's program syntax (see the module notes); every attribute
    has the default most controls share (LinuxCNC's, where they differ)."""

    name: str  # the --to name
    title: str  # one line for help texts
    maker: str = "LinuxCNC"  # for messages: "a Fanuc S word is a whole number"
    machine: str = LATHE  # LATHE or MILL
    # -- words ---------------------------------------------------------------------
    motion_codes: Dict[str, str] = field(default_factory=lambda: dict(ONE_DIGIT_CODES))
    arc_form: str = ARC_CENTRE
    arc_radius_word: str = "R"  # an arc programmed by its radius keeps it as this word; "": by its centre
    digits_mm: int = 4  # decimals of lengths in mm
    digits_inch: int = 5  # and in inch
    feed_digits: int = 6  # decimals of F (inch feeds per revolution need them)
    m_code: str = "M%d"  # "M%02d": two-digit M codes
    whole_speed: bool = False  # S is a whole number of rpm (m/min, ft/min)
    comments: str = PARENS
    max_block_number: Optional[int] = None  # the largest N; None: no limit of its own
    # -- modes ---------------------------------------------------------------------
    units_codes: Tuple[str, str] = ("G21", "G20")  # (metric, inch: lengths and feeds)
    units_alone: bool = False  # the units code stands in a block of its own
    feed_mode_codes: Tuple[str, str] = ("G94", "G95")  # (per minute, per revolution)
    x_mode_codes: Tuple[str, str] = ("G7", "G8")  # (X a diameter, X a radius); ("", ""): a machine parameter
    compensation_off: str = "G40"  # cancels tool nose radius compensation
    plane_code: str = "G18"  # the plane a program selects; "": implied (an option on the control)
    last_work_offset: int = 59  # the work offsets are G54..G<this>
    setup: Tuple[str, ...] = ("G18 {x_mode} {units} G90 G91.1 G40 {feed_mode}",)  # the lines opening a program
    # -- frame -----------------------------------------------------------------------
    percent_start: bool = False  # a "%" line before the program
    percent_end: bool = False  # and after it
    program_number: str = ""  # the O line's format ("O%04d"); "": the control has none
    title_on_number_line: bool = True  # the title's comment on the O line (else a line of its own)
    end_code: str = "M2"  # the program's end
    # -- tools and spindle -------------------------------------------------------------
    tool_form: str = TOOL_M6
    tool_number: str = "T%d"  # the T word of a TOOL_M6 change ("T%02d": two digits)
    tool_length_offset: bool = True  # a TOOL_M6 change is followed by its length offset (G43, G43 H, G49)
    max_tool: int = 99999
    tool_change_stops_spindle: bool = False  # LinuxCNC's M6 stops the spindle: the program starts it again
    css_form: str = CSS_D_WORD
    css_refusal: str = ""  # why constant surface speed cannot be written ("": it can)
    # -- dwell --------------------------------------------------------------------------
    dwell_code: str = "G4"
    dwell_word: str = "P"
    dwell_milliseconds: bool = False  # the dwell word counts whole milliseconds (else seconds)
    dwell_refusal: str = ""  # why a dwell cannot be written ("": it can)
    # -- axes ------------------------------------------------------------------------------
    c_feed: Optional[str] = None  # writes the rotary C axis, F read as C_FEED_*; None: no C axis
    dress_call: str = ""  # the subprogram call of a dress program, "%d" its number (grinders)
    mill_twin: str = ""  # the target a mill-style program is written on when it names this one
    # -- native cycles ----------------------------------------------------------------------
    native: NativeCycles = NativeCycles()

    @property
    def mill(self) -> bool:
        """Whether programs are mill-style: X plain, Y words, G17 arcs."""
        return self.machine == MILL

    def digits(self, metric: bool) -> int:
        """Decimals of lengths in the program's units."""
        return self.digits_mm if metric else self.digits_inch
