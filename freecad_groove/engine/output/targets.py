"""The targets: one :class:`~.syntax.Target` table per control the output is written for.

Lathes: ``linuxcnc``, ``fanuc``, ``haas``, ``sinumerik``, ``ab9``, ``gsk``;
with a rotary C axis (GSK G7.1 cylinder slots): ``linuxcnc-c``, ``fanuc-c``
(``gsk`` has its C axis). Mills: ``milltronics``; the mill-style twins
``linuxcnc-mill`` and ``fanuc-mill``, on which a mill-style program (a
grinder's or a mill's X/Y/Z) is written when it names ``linuxcnc`` or
``fanuc``; the grinder ``ab9grind`` (Allen-Bradley 9/Series).

Each table says where its control's documentation or habit comes from in a
comment; the choices the manuals leave open are in docs/choices.md.
"""

from dataclasses import replace
from typing import Dict, Tuple

from .syntax import (
    ARC_CR,
    C_FEED_COMPOSITE,
    C_FEED_LINEAR,
    CSS_G50_ALONE,
    CSS_LIMS,
    MILL,
    SEMICOLON,
    TOOL_EDGE,
    TOOL_M6,
    TOOL_OFFSET,
    TWO_DIGIT_CODES,
    NativeCycles,
    Target,
)

__all__ = ["LATHE_TARGETS", "MILL_TARGETS", "TARGETS", "program_target", "target_named", "with_g07_meaning"]

# LinuxCNC in lathe use: G18, X words diameters (G7), absolute, incremental arc centres (G91.1), no nose
# radius compensation; G4 P seconds; M2; its M6 stops the spindle.
LINUXCNC = Target(
    "linuxcnc", "LinuxCNC lathe (G7 diameter mode, G4 P seconds, M2)",
    tool_change_stops_spindle=True, mill_twin="linuxcnc-mill",
)

# Plain Fanuc lathe code, G code system A: G18 implied (plane selection is an option), X words diameters
# (parameter 1006#3), X/Z absolute; G98/G99; G04 P whole milliseconds (parameter 3405#1 DWL off); G21/G20 and
# G50 S in blocks of their own; "%" at both ends and an O number; two-digit codes; whole S words; N of at most
# 5 digits; the least input increment IS-B (3 decimals in mm, 4 in inch).
FANUC = Target(
    "fanuc", "plain Fanuc lathe code (diameter X, G98/G99, G04 P milliseconds, M30, % lines)", maker="Fanuc",
    motion_codes=dict(TWO_DIGIT_CODES), digits_mm=3, digits_inch=4, m_code="M%02d", whole_speed=True,
    max_block_number=99999, units_alone=True, feed_mode_codes=("G98", "G99"), x_mode_codes=("", ""),
    plane_code="", setup=("{units}", "G40 {feed_mode}"), percent_start=True, percent_end=True, program_number="O%04d",
    end_code="M30", tool_form=TOOL_OFFSET, max_tool=99, css_form=CSS_G50_ALONE,
    dwell_code="G04", dwell_milliseconds=True, mill_twin="fanuc-mill",
    native=NativeCycles(grooves="pecking", dialect="fanuc", longitudinal="G75", face="G74", retract_word="e"),
)

# Haas lathe: Fanuc's frame; one-block G75/G74; G04 P in seconds with a decimal point; the peck retract is
# setting 22.
HAAS = replace(
    FANUC, name="haas", title="Haas lathe (Fanuc frame, one-block G75/G74, G04 P seconds)", maker="Haas",
    dwell_milliseconds=False, mill_twin="",
    native=NativeCycles(grooves="pecking", dialect="haas", longitudinal="G75", face="G74",
                        retract_setting="setting 22"),
)

# GSK 980TDi lathe: Fanuc's syntax, two-block G75/G74, G7.1 cylinder interpolation with its roughing cycle;
# the F of a linear and rotary move along their composite path (as Fanuc-compatible controls document it).
GSK = replace(
    FANUC, name="gsk", title="GSK 980TDi lathe (Fanuc syntax, two-block G75/G74, G7.1 cylinder slots)", maker="GSK",
    c_feed=C_FEED_COMPOSITE, mill_twin="",
    native=NativeCycles(grooves="pecking", dialect="gsk", longitudinal="G75", face="G74", retract_word="e",
                        slots=True),
)

# Siemens Sinumerik 840D lathe: ";" comments, G71/G700 (G70 keeps feeds in the basic system), DIAMON/DIAMOF,
# G4 F seconds, T<n> D<edge>, G96 S.. LIMS=.., arcs with CR= (the radius), CYCLE93.
SINUMERIK = Target(
    "sinumerik", "Siemens Sinumerik 840D lathe (DIAMON, ; comments, G4 F seconds, CR= arcs, M30)", maker="Siemens",
    arc_form=ARC_CR, arc_radius_word="CR=", digits_mm=3, digits_inch=4, comments=SEMICOLON, units_codes=("G71", "G700"),
    x_mode_codes=("DIAMON", "DIAMOF"), setup=("G18 {units} G90 G40 {feed_mode} {x_mode}",), end_code="M30",
    tool_form=TOOL_EDGE, max_tool=9999, css_form=CSS_LIMS, dwell_word="F", last_work_offset=57,
    native=NativeCycles(grooves="cycle93", dialect="sinumerik"),
)

# Allen-Bradley 9/Series lathe: two-digit codes, G07/G08 (which one is diameter mode is a post option), T<tool>
# <offset>; its dwell word and its spindle limit word are not documented in the manual this follows.
AB9 = Target(
    "ab9", "Allen-Bradley 9/Series lathe (G07 diameter mode, two-digit codes, M30)", maker="Allen-Bradley",
    motion_codes=dict(TWO_DIGIT_CODES), arc_radius_word="", digits_mm=3, digits_inch=4, m_code="M%02d",
    whole_speed=True, x_mode_codes=("G07", "G08"), setup=("G18 {units} G90 G40 {feed_mode} {x_mode}",), end_code="M30",
    tool_form=TOOL_OFFSET, max_tool=99,
    css_refusal="constant surface speed cannot be written for the Allen-Bradley 9/Series: its spindle limit word "
    "is not documented in the manual this follows",
    dwell_refusal="a dwell (G4) cannot be written for the Allen-Bradley 9/Series: its dwell word is not documented "
    "in the manual this follows",
    native=NativeCycles(grooves="pecking", dialect="ab9", longitudinal="G77", face="G76",
                        retract_setting="AMP parameter"),
)

# Mill-style twins (a grinder's or a mill's X/Y/Z program written for LinuxCNC or Fanuc): G17, X plain, Y words;
# a dress program's call (LinuxCNC: a named subroutine file dressN.ngc; Fanuc M98).
LINUXCNC_MILL = replace(
    LINUXCNC, name="linuxcnc-mill", title="LinuxCNC mill (G17, X/Y/Z, o<dressN> call)", machine=MILL,
    x_mode_codes=("", ""), plane_code="G17", setup=("G17 {units} G90 G91.1 G40 {feed_mode}",),
    dress_call="o<dress%d> call", mill_twin="",
)
FANUC_MILL = replace(
    FANUC, name="fanuc-mill", title="plain Fanuc mill code (G17, X/Y/Z, G94/G95, M98 P)", machine=MILL,
    feed_mode_codes=("G94", "G95"), plane_code="G17", setup=("{units}", "G17 G90 G40 {feed_mode}"),
    dress_call="M98 P%d", mill_twin="", tool_form=TOOL_M6, tool_number="T%02d", native=NativeCycles(),
)

# Allen-Bradley 9/Series grinder: G83/G83.1 plunge grinding; "%", the O number, the title on a line of its own,
# G90 G94 and the units; T<nn> M06; its dress program call is not documented in the manual this follows.
AB9GRIND = replace(
    FANUC_MILL, name="ab9grind", title="Allen-Bradley 9/Series grinder (G83/G83.1, two-digit codes, M30)",
    maker="Allen-Bradley",
    title_on_number_line=False, units_alone=False, setup=("G90 G94 {units}",), dress_call="", percent_end=False,
    tool_length_offset=False, max_block_number=None, native=NativeCycles(grinds=True),
)

# Milltronics mill: G33/G34 autoroutines, 3 decimals in mm and 4 in inch (words and parameters), feeds too.
MILLTRONICS = replace(
    LINUXCNC_MILL, name="milltronics", title="Milltronics mill (G33/G34 autoroutines, G31/G32, T<n> M6, M30)",
    maker="Milltronics",
    digits_mm=3, digits_inch=4, feed_digits=3, setup=("{units} G90 G40",), end_code="M30", dress_call="",
    tool_length_offset=False,
    native=NativeCycles(mill=True),
)

_LATHES = (LINUXCNC, FANUC, HAAS, SINUMERIK, AB9, GSK,
           replace(LINUXCNC, name="linuxcnc-c", title=LINUXCNC.title + " with a rotary C axis", c_feed=C_FEED_LINEAR,
                   mill_twin=""),
           replace(FANUC, name="fanuc-c", title=FANUC.title + " with a rotary C axis",
                   c_feed=C_FEED_COMPOSITE, mill_twin=""))
_MILLS = (MILLTRONICS, AB9GRIND, LINUXCNC_MILL, FANUC_MILL)

TARGETS: Dict[str, Target] = {target.name: target for target in _LATHES + _MILLS}
LATHE_TARGETS: Tuple[str, ...] = tuple(target.name for target in _LATHES)
MILL_TARGETS: Tuple[str, ...] = tuple(target.name for target in _MILLS)


def target_named(name: str) -> Target:
    """The table of target ``name``; ValueError naming the known ones when there is none."""
    try:
        return TARGETS[name]
    except KeyError:
        raise ValueError("unknown output target %r (known: %s)" % (name, ", ".join(TARGETS))) from None


def program_target(name: str, mill: bool) -> Target:
    """The target a program is written on when it names ``name``: a mill-style
    program (X/Y/Z, ``mill``) on the target's mill twin, a lathe program on a
    lathe target; ValueError naming the targets that take it otherwise."""
    target = target_named(name)
    if target.mill == mill:
        return target
    if mill and target.mill_twin:
        return TARGETS[target.mill_twin]
    takes = [n for n, t in TARGETS.items() if (t.mill or t.mill_twin) and n not in _TWINS] if mill else \
        list(LATHE_TARGETS)
    raise ValueError("%s is a %s target: a %s program (%s) cannot be written for it (targets for it: %s)" % (
        name, "mill" if target.mill else "lathe", "mill-style" if mill else "lathe",
        "X/Y/Z" if mill else "X/Z", ", ".join(takes)))


def with_g07_meaning(target: Target, g07_is_diameter: bool) -> Target:
    """The target with the machine's G07/G08 meaning: on an Allen-Bradley 9/Series
    G07 may select radius mode and G08 diameter mode (a setting of the machine,
    Settings.ab_g07_is_diameter, the posts' --g07-radius)."""
    if target.x_mode_codes != ("G07", "G08") or g07_is_diameter:
        return target
    return replace(target, x_mode_codes=("G08", "G07"))


_TWINS = frozenset(t.mill_twin for t in TARGETS.values() if t.mill_twin)
