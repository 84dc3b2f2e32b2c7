"""The lathe controls the posts write for: each one's syntax and habits.

Every difference between the controls is a class attribute (data) or a
method of its class here; the rest of the posts asks the control and never
its name. The pecking controls name the engine's input control whose cycles
they write (``cycle_control``) and the codes of those cycles; the classes
themselves come from the engine's cycle registry.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Dict, List, Optional

from ...engine import FEED, RAPID, ProgramError
from ...engine.numbers import format_decimal
from ...engine.registry import cycle_for
from ...engine.targets import C_FEED_COMPOSITE, C_FEED_LINEAR
from ...engine.targets import comment as paren_comment

if TYPE_CHECKING:
    from .options import Options

# What a control writes a groove as, when it writes it natively.
NATIVE_CYCLE93 = "cycle93"  # Siemens CYCLE93, every groove
NATIVE_PECKING = "pecking"  # a pecking cycle (G77/G76, G75/G74), plain grooves only

DWELL_DIGITS = 3  # decimals of a dwell in seconds
ONE_DIGIT_CODES = {RAPID: "G0", FEED: "G1", "G2": "G2", "G3": "G3"}
TWO_DIGIT_CODES = {RAPID: "G00", FEED: "G01", "G2": "G02", "G3": "G03"}


class Control:
    """One lathe control's syntax (the defaults; each control overrides what differs)."""

    name = ""  # the post's CONTROL and the engine's input control of its programs
    post = ""  # post name (without _post)
    title = ""
    codes: Dict[str, str] = ONE_DIGIT_CODES
    digits = 3  # decimals of coordinates (--precision default)
    native: Optional[str] = None  # NATIVE_CYCLE93, NATIVE_PECKING or None (always expanded)
    x_mode_codes: Optional[str] = None  # what --x-mode switches ("DIAMON/DIAMOF"); None: no --x-mode
    x_words = "a diameter"  # how the tooltip says X is written
    expand_help_note = ""  # what --expand-cycles' help adds
    g07_radius_option = False  # --g07-radius: G07 may select radius mode on this control
    o_number_frame = False  # "%" lines around the program, an O number (--program-number)
    max_tool_number = 9999
    m6_stops_spindle = False  # a tool change stops the spindle
    cr_arcs = False  # arcs with their radius CR= (Siemens) instead of I/K
    c_feed: Optional[str] = None  # a C axis: how F of a move that turns C is read (targets.C_FEED_*); None: no C
    native_slot = False  # a Cylinder slot op as a native GSK G7.1 Type II region (--native-cycles)

    @property
    def has_x_mode(self) -> bool:
        """Whether the post takes --x-mode (X words as diameters or radii)."""
        return self.x_mode_codes is not None

    def grooves_summary(self) -> str:
        """How the post writes grooves, for its tooltip."""
        return "grooves expanded into G0/G1 moves and G2/G3 arcs"

    def comment(self, text: str) -> str:
        return paren_comment(text)

    def dwell(self, seconds: float) -> str:
        return "G4 P" + format_decimal(seconds, DWELL_DIGITS)

    def setup(self, options: Options) -> List[str]:
        """The lathe setup lines after the header."""
        raise NotImplementedError

    def tool_change(self, number: int) -> List[str]:
        return ["T%02d%02d" % (number, number)]

    def spindle(self, rpm: int, m_code: str) -> List[str]:
        return ["G97 S%d %s" % (rpm, m_code)]

    feed_mode_codes = ("G94", "G95")  # (per minute, per revolution)
    unit_codes = ("G21", "G20")  # (metric, inch: lengths and feeds)

    def feed_mode(self, per_rev: bool) -> str:
        """The code of feed per minute or (``per_rev``) per revolution."""
        return self.feed_mode_codes[1 if per_rev else 0]

    def units(self, inches: bool) -> str:
        """The code of metric or inch lengths and feeds."""
        return self.unit_codes[1 if inches else 0]

    def surface_speed(self, speed: int, limit: int, m_code: str) -> List[str]:
        """Constant surface speed ``speed`` (m/min, ft/min in inch) with the spindle limited to ``limit`` rpm."""
        raise NotImplementedError

    def m_code(self, number: int) -> str:
        return "M%02d" % number

    def end(self, options: Options) -> List[str]:
        """The lines that end the program."""
        return [self.m_code(30)]

    def work_offset_refusal(self, number: int) -> Optional[str]:
        """Why work offset G``number`` (54..59) cannot be written, or None."""
        return None


class PeckingControl(Control):
    """A control whose pecking cycles cut plain grooves natively."""

    native = NATIVE_PECKING
    codes = TWO_DIGIT_CODES
    max_tool_number = 99
    cycle_control = ""  # the engine's input control whose cycles the post writes
    longitudinal_cycle = ""  # the code of its grooves along Z ("G77")
    face_cycle = ""  # the code of its face grooves ("G76")
    retract_word: Optional[str] = None  # the cycle word holding the peck retract e (Fanuc's first-block R)
    retract_setting: Optional[str] = None  # where the control keeps e otherwise (named in a comment)
    least_input_increment = 0.001  # mm: counted words (Fanuc P/Q) are whole multiples of it
    least_input_increment_inch = 0.0001  # in: the same in inch programs

    @property
    def pecking_codes(self) -> str:
        """Both cycle codes, for help texts ("G77/G76")."""
        return "%s/%s" % (self.longitudinal_cycle, self.face_cycle)

    def pecking_cycle(self, longitudinal: bool) -> type:
        """The engine's cycle class the post writes for a longitudinal or a face groove."""
        return cycle_for(self.cycle_control, self.longitudinal_cycle if longitudinal else self.face_cycle)

    def grooves_summary(self) -> str:
        return "plain grooves as native %s calls, others expanded" % self.pecking_codes

    def retract_help(self) -> str:
        """How --retract reaches the control, for its help."""
        if self.retract_word:
            return "written as %s R(%s)" % (self.longitudinal_cycle, self.retract_word)
        return "a machine setting on this control, stated in a comment"


class Sinumerik(Control):
    name, post, title = "sinumerik", "sinumerik_lathe", "Siemens Sinumerik 840D lathe (CYCLE93)"
    native = NATIVE_CYCLE93
    x_mode_codes = "DIAMON/DIAMOF"
    cr_arcs = True
    last_work_offset = 57

    def grooves_summary(self) -> str:
        return "grooves as native CYCLE93 calls"

    def comment(self, text: str) -> str:
        return "; " + paren_comment(text)[1:-1]

    def dwell(self, seconds: float) -> str:
        return "G4 F" + format_decimal(seconds, DWELL_DIGITS)

    unit_codes = ("G71", "G700")  # G700: inch lengths and feeds (G70 keeps feeds in the basic system)

    def setup(self, options: Options) -> List[str]:
        return ["G18 %s G90 G40 G94 %s" % (self.units(options.inches), "DIAMON" if options.diameter else "DIAMOF")]

    def surface_speed(self, speed: int, limit: int, m_code: str) -> List[str]:
        return ["G96 S%d LIMS=%d %s" % (speed, limit, m_code)]

    def tool_change(self, number: int) -> List[str]:
        return ["T%d D1" % number]

    def m_code(self, number: int) -> str:
        return "M%d" % number

    def work_offset_refusal(self, number: int) -> Optional[str]:
        if number > self.last_work_offset:
            return "Siemens' settable offsets are G54..G%d here" % self.last_work_offset
        return None


class AllenBradley9(PeckingControl):
    name, post, title = "ab9", "ab9_lathe", "Allen-Bradley 9/Series lathe (G77/G76)"
    x_mode_codes = "G07/G08"
    g07_radius_option = True
    cycle_control, longitudinal_cycle, face_cycle = "ab9", "G77", "G76"
    retract_setting = "AMP parameter"

    def dwell(self, seconds: float) -> str:
        raise ProgramError(
            "a dwell (G4) cannot be written for the Allen-Bradley 9/Series: its dwell word is not documented "
            "in the manuals this post follows (set the groove's Dwell to 0 or use another post)")

    def setup(self, options: Options) -> List[str]:
        diameter_code = "G07" if options.g07_is_diameter else "G08"
        radius_code = "G08" if options.g07_is_diameter else "G07"
        return ["G18 %s G90 G40 G94 %s" % (self.units(options.inches),
                                          diameter_code if options.diameter else radius_code)]

    def surface_speed(self, speed: int, limit: int, m_code: str) -> List[str]:
        raise ProgramError(
            "constant surface speed cannot be written for the Allen-Bradley 9/Series: its spindle limit word is "
            "not documented in the manuals this post follows (set SurfaceSpeed to 0 and give SpindleSpeed)")


class FanucFrame(PeckingControl):
    """The program frame Fanuc and Haas share: "%" lines, an O number, G21 alone, G98."""

    o_number_frame = True

    feed_mode_codes = ("G98", "G99")

    def setup(self, options: Options) -> List[str]:
        return [self.units(options.inches), "G40 G98"]

    def surface_speed(self, speed: int, limit: int, m_code: str) -> List[str]:
        return ["G50 S%d" % limit, "G96 S%d %s" % (speed, m_code)]

    def end(self, options: Options) -> List[str]:
        return ["M30", "%"]


class Fanuc(FanucFrame):
    name, post, title = "fanuc", "fanuc_lathe", "Fanuc lathe, G code system A (two-block G75/G74)"
    cycle_control, longitudinal_cycle, face_cycle = "fanuc", "G75", "G74"
    retract_word = "e"

    def dwell(self, seconds: float) -> str:
        return "G04 P%d" % int(round(seconds * 1000.0))


class Haas(FanucFrame):
    name, post, title = "haas", "haas_lathe", "Haas lathe (one-block G75/G74)"
    cycle_control, longitudinal_cycle, face_cycle = "haas", "G75", "G74"
    retract_setting = "setting 22"

    def dwell(self, seconds: float) -> str:
        return "G04 P" + format_decimal(seconds, DWELL_DIGITS)


class Gsk(Fanuc):
    name, post, title = "gsk", "gsk_lathe", "GSK 980TDi lathe (G75/G74 two-block, G7.1 cylinder slots)"
    cycle_control = "gsk"
    c_feed = C_FEED_COMPOSITE  # Fanuc-like: F of a linear and rotary move along their composite path
    native_slot = True


class LinuxCNC(Control):
    name, post, title = "linuxcnc", "linuxcnc_lathe", "LinuxCNC lathe (G7, grooves expanded)"
    digits = 4
    x_mode_codes = "G7/G8"
    x_words = "a diameter, G7"
    expand_help_note = "; the default: LinuxCNC has no grooving cycle"
    m6_stops_spindle = True  # LinuxCNC's M6 stops the spindle
    c_feed = C_FEED_LINEAR  # a lathe with a rotary C axis: F along X/Z when they move, else degrees/min

    def setup(self, options: Options) -> List[str]:
        return ["G18 %s %s G90 G91.1 G40 G94" % ("G7" if options.diameter else "G8", self.units(options.inches))]

    def surface_speed(self, speed: int, limit: int, m_code: str) -> List[str]:
        return ["G96 D%d S%d %s" % (limit, speed, m_code)]

    def tool_change(self, number: int) -> List[str]:
        return ["T%d M6 G43" % number]

    def m_code(self, number: int) -> str:
        return "M%d" % number

    def end(self, options: Options) -> List[str]:
        return ["M2"]


CONTROLS: Dict[str, Control] = {c.name: c() for c in (Sinumerik, AllenBradley9, Fanuc, Haas, Gsk, LinuxCNC)}


def control_named(name: str) -> Control:
    """The control of post ``name`` (a key of CONTROLS); ValueError when unknown."""
    try:
        return CONTROLS[name]
    except KeyError:
        raise ValueError("unknown control %r (known: %s)" % (name, ", ".join(CONTROLS))) from None
