"""The command line's shared options: value types, the tool and machine
settings, the modes at the start of a program (``expand`` and ``emit`` both
take them). ``cli.py`` builds the parsers and runs the commands."""

import argparse
import math
import re
from dataclasses import replace
from typing import Optional

from .engine.moves import MachineState
from .engine.settings import DEFAULT_SETTINGS, Settings

# ---------------------------------------------------------------- value types


def finite(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError("%r is not a number" % text) from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError("%r is not a finite number" % text)
    return value


def positive(text: str) -> float:
    value = finite(text)
    if not value > 0:
        raise argparse.ArgumentTypeError("%r must be greater than 0" % text)
    return value


def not_negative(text: str) -> float:
    value = finite(text)
    if value < 0:
        raise argparse.ArgumentTypeError("%r must not be negative" % text)
    return value


_DECIMAL = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)\Z")
_INTEGER = re.compile(r"[+-]?[0-9]+\Z")


def decimal_word(text: str) -> str:
    """A word value as typed; a decimal point is added to whole numbers (``20`` -> ``20.``)."""
    text = text.strip()
    if not _DECIMAL.match(text):
        raise argparse.ArgumentTypeError("%r is not a plain decimal number" % text)
    return text if "." in text else text + "."


def siemens_value(text: str) -> str:
    text = text.strip()
    if not _DECIMAL.match(text):
        raise argparse.ArgumentTypeError("%r is not a plain decimal number" % text)
    return text


def counted(text: str) -> str:
    text = text.strip()
    if not _INTEGER.match(text):
        raise argparse.ArgumentTypeError("%r must be a whole number (least input increments: P2000 = 2 mm)" % text)
    return text


# ---------------------------------------------------------------- settings options


def add_settings_options(parser: argparse.ArgumentParser) -> None:
    g = parser.add_argument_group(
        "tool and machine settings (accepted with every dialect, ignored where a cycle does not use them)"
    )
    g.add_argument(
        "--tool-width",
        type=positive,
        metavar="W",
        help="width of the grooving blade, in the program's units when the cycle runs. No default: CYCLE93 "
        "places its plunges with it, so it is refused without the blade (this option or expand's --tool-table; "
        "with a table, this blade is the one of tools the table does not list and of cycles before any T).",
    )
    g.add_argument(
        "--tool-radius",
        type=not_negative,
        metavar="R",
        help="corner radius of both front corners of the --tool-width blade (default 0.2); must be less than "
        "half the width.",
    )
    g.add_argument(
        "--reference-corner",
        choices=("minus", "plus"),
        help="CYCLE93: which front corner of the --tool-width blade the moves drive: minus = the -Z corner (-X "
        "for face grooves, the default), plus = the other. Must match the corner your tool offset was measured "
        "on. (The pecking cycles G77/G76/G75/G74 drive the programmed point, as the control does.)",
    )
    g.add_argument(
        "--retract",
        type=not_negative,
        metavar="E",
        help="peck retract e per side after each infeed of Allen-Bradley G77/G76 (AMP parameter) and Haas "
        "G75/G74 (setting 22); also Fanuc G75/G74 when the program has no 'G75 R(e)' block "
        "(parameter 5139). Default 0.5 mm / 0.02 in.",
    )
    g.add_argument(
        "--diameter-input",
        action="store_true",
        help="CYCLE93: read AXFA, DEPG, FAL1 and FAL2 as diameters (840D with DIAMON). Default: radius values, "
        "as the Siemens manual says.",
    )
    g.add_argument(
        "--g07-radius",
        action="store_true",
        help="Allen-Bradley: G07 selects RADIUS mode and G08 diameter mode. Default: G07 = diameter, G08 = radius "
        "(the 9/Series manual uses both readings; check your control).",
    )
    _add_clearance_and_limit_options(g)
    _add_milltronics_options(g)


def _add_clearance_and_limit_options(g: argparse._ArgumentGroup) -> None:
    """The clearance of cycles without a retract parameter, CYCLE93's shop limit."""
    g.add_argument(
        "--clearance",
        type=not_negative,
        metavar="C",
        help="clearance per side kept above the material before a plunge, for cycles without a retract "
        "parameter (default 1).",
    )
    g.add_argument(
        "--max-contour-tilt",
        type=finite,
        metavar="DEG",
        help="CYCLE93: refuse contours tilted more than DEG degrees from the groove's own axis (a shop "
        "limit; default: none, the whole ANGC range 0..180 is machined).",
    )


def _add_milltronics_options(g: argparse._ArgumentGroup) -> None:
    """The Milltronics autoroutines' end mill and Z heights."""
    g.add_argument(
        "--tool-diameter",
        type=positive,
        metavar="D",
        help="Milltronics G33/G34: the end mill's diameter, in the program's units. No default: the "
        "autoroutines are refused without it.",
    )
    g.add_argument(
        "--g31-clearance",
        type=finite,
        metavar="INCH",
        help="Milltronics G31 before any R: the clearance Z (parameter 140), in inches (x 25.4 in a metric "
        "program; default 0.1).",
    )
    g.add_argument(
        "--g32-tool-change",
        type=finite,
        metavar="INCH",
        help="Milltronics G32: the tool change Z (a machine builder's setting), in inches (x 25.4 in a metric "
        "program; default 4).",
    )


def add_tool_table_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--tool-table",
        metavar="FILE",
        help="the blade of each tool number, one tool a line: T width corner-radius reference (minus/plus), "
        "e.g. '5 3.0 0.2 minus'; '#' starts a comment; lengths in the program's units when the cycle runs; "
        "- reads standard input. "
        "A CYCLE93 cuts with the blade of the tool in force (Siemens T5 D1, Fanuc-style T0512: tool 5); a tool "
        "the table does not list, or a cycle before any T, is refused unless --tool-width gives a default blade. "
        "With --dialect milltronics: the end mill's diameter of each D register, one 'D diameter' a line, e.g. "
        "'2 0.125'; G33/G34 cut with the D in force, else with --tool-diameter.",
    )


def settings_from(args: argparse.Namespace) -> Settings:
    """The engine Settings the options ask for."""
    s = DEFAULT_SETTINGS.with_tool(args.tool_width, args.tool_radius, args.reference_corner)
    changes = {}
    if args.retract is not None:
        changes["peck_retract"] = args.retract
    if args.diameter_input:
        changes["cycle93_diameter_input"] = True
    if args.g07_radius:
        changes["ab_g07_is_diameter"] = False
    if args.clearance is not None:
        changes["clearance"] = args.clearance
    if args.max_contour_tilt is not None:
        changes["cycle93_max_contour_tilt"] = args.max_contour_tilt
    for option, setting in (("tool_diameter", "mill_tool_diameter"), ("g31_clearance", "milltronics_clearance_inch"),
                            ("g32_tool_change", "milltronics_tool_change_inch")):
        if getattr(args, option, None) is not None:
            changes[setting] = getattr(args, option)
    return replace(s, **changes) if changes else s


def add_start_options(parser: argparse.ArgumentParser, expand: bool) -> None:
    g = parser.add_argument_group("modes at the start of the program" if expand else "start point and modes")
    g.add_argument(
        "--units",
        choices=("mm", "inch"),
        default="mm",
        help="length unit until the program selects one (G20/G21, Siemens G70/G71/G700/G710). Default mm.",
    )
    g.add_argument(
        "--feed-mode",
        choices=("min", "rev"),
        default=None,
        help="feed per minute or per revolution until the program selects one (G94/G95, Fanuc/Haas G98/G99). "
        "Default: none, and a feed move or cycle before the program selects one is refused."
        if expand
        else "feed per minute or per revolution (default rev).",
    )
    g.add_argument(
        "--x-mode",
        choices=("diameter", "radius"),
        default="diameter",
        help="how X words are read until the program says otherwise (Siemens DIAMON/DIAMOF, AB G07/G08). "
        "Default diameter; use radius for a Fanuc/Haas lathe set to radius programming (Fanuc parameter "
        "1006#3 off). The output always writes diameters.",
    )


def start_state(args: argparse.Namespace, feed_default: Optional[str] = None) -> MachineState:
    """The modes at the start of the program, as the options give them."""
    mode = args.feed_mode or feed_default
    return MachineState(
        diameter_mode=args.x_mode == "diameter",
        metric=args.units == "mm",
        feed_per_rev=None if mode is None else mode == "rev",
    )
