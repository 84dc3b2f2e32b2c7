"""Command line: expand the grooving cycles of a lathe program, or write one cycle call.

    python3 -m freecad_groove expand PROGRAM --dialect sinumerik [-o OUT] [--to linuxcnc]
    python3 -m freecad_groove emit cycle93 --axfa 35 --axsa 60 ...

Thin layer: argument parsing and error reporting; the work is done by
freecad_groove.engine (program.translate_program, targets.write_program and
the cycle classes).

Errors: an invalid cycle or a line the reader cannot translate prints exactly
one line ``PROGRAM:LINE: message`` on stderr, writes nothing to stdout or OUT
(an existing OUT is left untouched) and exits with status 2. A file that cannot
be read or written is reported the same way with LINE 0. Bad option values are
reported by argparse (usage and message on stderr, status 2).
"""

import argparse
import math
import os
import re
import sys
from dataclasses import replace

from . import __version__
from .engine.output import write_atomically

EXIT_ERROR = 2

DIALECT_HELP = {
    "sinumerik": "Siemens (CYCLE93 calls; DIAMON/DIAMOF, G70/G71, G700/G710, G90/G91, G94/G95)",
    "ab9": "Allen-Bradley 9/Series lathe (G77 grooving/cut-off, G76 face grooving; G07/G08, G20/G21, "
    "G90/G91, G94/G95)",
    "fanuc": "Fanuc lathe, G code system A (two-block G75/G74: G75 R(e) then G75 X(U) Z(W) P Q R F; "
    "G20/G21, G98/G99, U/W incremental)",
    "haas": "Haas lathe (one-block G75/G74 X(U) Z(W) I K D F; G20/G21, G98/G99, U/W incremental)",
}

DESCRIPTION = """\
Expand the grooving cycles of a lathe program into plain G0/G1/G4 moves.

Every cycle call (Siemens CYCLE93, Allen-Bradley G77/G76, Fanuc G75/G74,
Haas G75/G74) is replaced by the moves the control would make, preceded by a
comment naming the call. The other blocks are carried over and rewritten for
the target control: X words are always DIAMETERS and all coordinates ABSOLUTE
in the output (LinuxCNC: G7 G90), whatever the input used (radius mode,
G91, U/W). A line that cannot be translated faithfully stops the run: nothing
is written, and one line PROGRAM:LINE: message tells you where and why.
"""

EPILOG = """\
Diameter and radius: X is the cross axis of the lathe. The moves inside the
engine are radii (distance from the spindle axis); programs write X as a
diameter unless the control is in radius mode (Siemens DIAMOF, AB radius
G code, --x-mode radius). CYCLE93 is different: its manual gives AXFA, DEPG,
FAL1 and FAL2 as radius values; use --diameter-input if your control reads them
as diameters (840D with DIAMON).

Reference corner: a grooving blade has two front corners. The expanded moves
drive one of them, the one whose tool offset you measured: --reference-corner
minus = the corner toward -Z (the blade extends from it toward +Z; for face
grooves, the corner toward -X), plus = the other one.

Examples:
  python3 -m freecad_groove expand examples/seed_cycle93.mpf --dialect sinumerik
  python3 -m freecad_groove expand part.nc --dialect fanuc --to fanuc -o part_expanded.nc
  python3 -m freecad_groove emit g77 -X 40. -Z -30. -I 2. -K 5. -D 0 -F 0.08
"""


# ---------------------------------------------------------------- argument types


def _finite(text):
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError("%r is not a number" % text) from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError("%r is not a finite number" % text)
    return value


def _positive(text):
    value = _finite(text)
    if not value > 0:
        raise argparse.ArgumentTypeError("%r must be greater than 0" % text)
    return value


def _not_negative(text):
    value = _finite(text)
    if value < 0:
        raise argparse.ArgumentTypeError("%r must not be negative" % text)
    return value


_DECIMAL = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)\Z")
_INTEGER = re.compile(r"[+-]?[0-9]+\Z")


def _decimal_word(text):
    """A word value as typed; a decimal point is added to whole numbers (``20`` -> ``20.``)."""
    text = text.strip()
    if not _DECIMAL.match(text):
        raise argparse.ArgumentTypeError("%r is not a plain decimal number" % text)
    return text if "." in text else text + "."


def _siemens_value(text):
    text = text.strip()
    if not _DECIMAL.match(text):
        raise argparse.ArgumentTypeError("%r is not a plain decimal number" % text)
    return text


def _counted(text):
    text = text.strip()
    if not _INTEGER.match(text):
        raise argparse.ArgumentTypeError("%r must be a whole number (least input increments: P2000 = 2 mm)" % text)
    return text


# ---------------------------------------------------------------- settings options


def _add_settings_options(parser):
    g = parser.add_argument_group(
        "tool and machine settings (accepted with every dialect, ignored where a cycle does not use them)"
    )
    g.add_argument(
        "--tool-width",
        type=_positive,
        metavar="W",
        help="width of the grooving blade, in the program's units (default 3: set it for inch programs). "
        "CYCLE93 places its plunges with it and refuses a groove narrower than the blade.",
    )
    g.add_argument(
        "--tool-radius",
        type=_not_negative,
        metavar="R",
        help="corner radius of both front corners of the blade (default 0.2); must be less than half the width.",
    )
    g.add_argument(
        "--reference-corner",
        choices=("minus", "plus"),
        help="CYCLE93: which front corner the moves drive: minus = the -Z corner (-X for face grooves, the "
        "default), plus = the other. Must match the corner your tool offset was measured on. (The pecking "
        "cycles G77/G76/G75/G74 drive the programmed point, as the control does.)",
    )
    g.add_argument(
        "--retract",
        type=_not_negative,
        metavar="E",
        help="peck retract e per side after each infeed of Allen-Bradley G77/G76 (AMP parameter) and Haas "
        "G75/G74 (setting 22); also Fanuc G75/G74 when the program has no 'G75 R(e)' block "
        "(parameter 5139). Default 0.5 mm / 0.02 in.",
    )
    g.add_argument(
        "--diameter-input",
        action="store_true",
        help="CYCLE93: read AXFA, DEPG, FAL1 and FAL2 as diameters (840D with DIAMON). Default: radius values, "
        "as the seed manual says.",
    )
    g.add_argument(
        "--g07-radius",
        action="store_true",
        help="Allen-Bradley: G07 selects RADIUS mode and G08 diameter mode. Default: G07 = diameter, G08 = radius "
        "(the 9/Series manual uses both readings; check your control).",
    )
    g.add_argument(
        "--clearance",
        type=_not_negative,
        metavar="C",
        help="clearance per side kept above the material before a plunge, for cycles without a retract "
        "parameter (default 1).",
    )
    g.add_argument(
        "--max-contour-tilt",
        type=_finite,
        metavar="DEG",
        help="CYCLE93: steepest contour (degrees from the groove's own axis) the paraxial roughing accepts "
        "(default 45).",
    )


def _settings(args):
    from .engine.settings import DEFAULT_SETTINGS

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
    return replace(s, **changes) if changes else s


def _add_start_options(parser, expand):
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


def _start_state(args, feed_default=None):
    from .engine.moves import MachineState

    mode = args.feed_mode or feed_default
    return MachineState(
        diameter_mode=args.x_mode == "diameter",
        metric=args.units == "mm",
        feed_per_rev=None if mode is None else mode == "rev",
    )


# ---------------------------------------------------------------- emit: one cycle call

# name -> (engine module, class, dialect label, [(option letters, word, kind, help)])
# kind: "d" decimal word, "c" counted integer (Fanuc P/Q), "s" Siemens value
_AB_HELP = {
    "X": "groove bottom X (absolute or incremental per G90/G91; diameter in diameter mode)",
    "Z": "Z of the LAST groove (omit for one groove)",
    "I": "infeed per peck along X, per side",
    "K": "distance between grooves along Z (always incremental)",
    "F": "feed for the infeeds (optional: the active feed otherwise)",
    "D": "rapid shift along Z at full depth (signed, away from the part; 0 when not cutting off; required)",
}
_AB76_HELP = {
    "X": "X of the LAST face groove (omit for one; diameter in diameter mode)",
    "Z": "groove bottom Z (absolute or incremental)",
    "I": "distance between grooves along X, per side",
    "K": "infeed per peck along Z",
    "F": "feed for the infeeds (optional)",
    "D": "rapid shift along X at full depth (signed, per side; required, 0 = none)",
}
_FANUC75_HELP = {
    "X": "groove bottom X (diameter, absolute)",
    "U": "groove bottom as an increment from the start X (diameter)",
    "Z": "Z of the last groove (absolute; omit for one groove)",
    "W": "last groove as an increment from the start Z",
    "P": "peck depth along X in least input increments, no decimal point (P2000 = 2 mm)",
    "Q": "groove spacing along Z in least input increments (Q5000 = 5 mm)",
    "R": "relief along Z at the groove bottom (not on the first groove)",
    "F": "feed (optional)",
}
_FANUC74_HELP = {
    "X": "X of the last face groove (diameter; omit for one groove / peck drilling)",
    "U": "last groove as an increment from the start X (diameter)",
    "Z": "groove bottom Z (absolute)",
    "W": "groove bottom as an increment from the start Z",
    "P": "groove spacing along X in least input increments (P5000 = 5 mm)",
    "Q": "peck depth along Z in least input increments, no decimal point (Q2000 = 2 mm)",
    "R": "relief along X at the groove bottom (not on the first groove)",
    "F": "feed (optional)",
}
_HAAS75_HELP = {
    "X": "groove bottom X (diameter, absolute)",
    "U": "groove bottom as an increment from the start X (diameter)",
    "Z": "Z of the last groove (omit for one groove)",
    "W": "last groove as an increment from the start Z",
    "I": "peck depth along X, per side",
    "K": "groove spacing along Z",
    "D": "relief along Z at the groove bottom (not on the first groove)",
    "F": "feed (optional)",
}
_HAAS74_HELP = {
    "X": "X of the last face groove (diameter; omit for one)",
    "U": "last groove as an increment from the start X (diameter)",
    "Z": "groove bottom Z (absolute)",
    "W": "groove bottom as an increment from the start Z",
    "I": "groove spacing along X, per side",
    "K": "peck depth along Z",
    "D": "relief along X at the groove bottom (not on the first groove)",
    "F": "feed (optional)",
}
_CYCLE93_HELP = (
    ("AXFA", "start point in the transverse axis X (radius value unless --diameter-input)"),
    ("AXSA", "start point in the longitudinal axis Z (absolute)"),
    ("WIDG", "groove width (without sign)"),
    ("DEPG", "groove depth (without sign; radius value unless --diameter-input)"),
    ("ANGC", "angle between the contour and the longitudinal axis, 0..180 degrees"),
    ("ANG1", "flank angle on the start point side, 0..<89.999 degrees"),
    ("ANG2", "flank angle on the other side, 0..<89.999 degrees"),
    ("RCO1", "outer edge on the start side: radius (positive) or chamfer (negative)"),
    ("RCO2", "outer edge on the other side: radius (positive) or chamfer (negative)"),
    ("RCI1", "groove base corner on the start side: radius (positive) or chamfer (negative)"),
    ("RCI2", "groove base corner on the other side: radius (positive) or chamfer (negative)"),
    ("FAL1", "finishing allowance on the groove base"),
    ("FAL2", "finishing allowance on the flanks"),
    ("IDEP", "infeed depth per plunge (required, without sign)"),
    ("DWT", "dwell at the groove base, seconds"),
    ("TYP", "machining type 1..8 / 11..18: 1 long. ext. left, 2 face ext. left, 3 long. int. left, "
     "4 face int. left, 5..8 the same on the right; +10 = chamfers as CHR"),
    ("VRT", "retraction distance from the contour (0 = 1 mm), also the chip-breaking retract"),
    ("DN", "D number of the second cutting edge (840D, optional)"),
)

_CYCLES = {
    "cycle93": ("Siemens CYCLE93 groove", "sinumerik", None, None),
    "ab-g77": ("Allen-Bradley 9/Series G77 grooving / cut-off", "ab9", "G77", _AB_HELP),
    "ab-g76": ("Allen-Bradley 9/Series G76 face grooving", "ab9", "G76", _AB76_HELP),
    "fanuc-g75": ("Fanuc two-block G75 grooving", "fanuc", "G75", _FANUC75_HELP),
    "fanuc-g74": ("Fanuc two-block G74 face grooving / peck drilling", "fanuc", "G74", _FANUC74_HELP),
    "haas-g75": ("Haas one-block G75 grooving", "haas", "G75", _HAAS75_HELP),
    "haas-g74": ("Haas one-block G74 face grooving", "haas", "G74", _HAAS74_HELP),
}
_ALIASES = {"g77": "ab-g77", "g76": "ab-g76", "g75": "fanuc-g75", "g74": "fanuc-g74"}


def _add_emit_parsers(sub):
    emit = sub.add_parser(
        "emit",
        help="check one cycle call and print it in the control's own syntax (or expanded)",
        description="Check one cycle call with its parameters and print it as the control reads it. "
        "With --expand, print instead a whole program that goes to the start point and runs the "
        "expanded moves. Cycles: "
        + ", ".join(sorted(_CYCLES))
        + " (aliases: g77 = ab-g77, g76 = ab-g76, g75 = fanuc-g75, g74 = fanuc-g74).",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    cycles = emit.add_subparsers(dest="cycle", metavar="CYCLE", required=True)
    for name, (title, dialect, code, helps) in _CYCLES.items():
        aliases = [a for a, target in _ALIASES.items() if target == name]
        p = cycles.add_parser(
            name,
            aliases=aliases,
            help=title,
            description=title + ". Lengths in the program's units; X as a diameter unless stated.",
            epilog=EPILOG,
            formatter_class=argparse.RawDescriptionHelpFormatter,
        )
        p.set_defaults(cycle_name=name)
        words = p.add_argument_group("cycle parameters")
        if helps is None:
            for param, text in _CYCLE93_HELP:
                words.add_argument("--" + param.lower(), dest="w_" + param, type=_siemens_value, metavar="V",
                                   help=text)
        else:
            for letter, text in helps.items():
                kind = _counted if (dialect == "fanuc" and letter in "PQ") else _decimal_word
                words.add_argument("-" + letter, "--" + letter.lower(), dest="w_" + letter, type=kind, metavar="V",
                                   help=text)
            if dialect == "fanuc":
                words.add_argument(
                    "-e", "--first-block-r", dest="fanuc_e", type=_decimal_word, metavar="E",
                    help="peck retract e: writes the first block '%s R(e)' (parameter 5139 otherwise)" % code,
                )
        _add_settings_options(p)
        ex = p.add_argument_group("expanded output (--expand)")
        ex.add_argument("--expand", action="store_true",
                        help="print a whole program with the expanded moves instead of the native call")
        ex.add_argument("--start-x", type=_finite, metavar="X",
                        help="start point X as a DIAMETER (the tool position before the call; required with "
                        "--expand)")
        ex.add_argument("--start-z", type=_finite, metavar="Z", help="start point Z (required with --expand)")
        ex.add_argument("--feed", type=_positive, metavar="F", help="feed in force before the call")
        ex.add_argument("--spindle", type=_positive, metavar="RPM",
                        help="spindle speed started (M3) before the moves; needed with feed per revolution")
        ex.add_argument("--incremental", action="store_true", help="G91 in force (AB, Siemens)")
        ex.add_argument("--to", choices=("linuxcnc", "fanuc"), default="linuxcnc", help="output control")
        _add_start_options(p, expand=False)


def _native_text(args):
    title, dialect, code, helps = _CYCLES[args.cycle_name]
    if helps is None:
        values = [getattr(args, "w_" + param) for param, _ in _CYCLE93_HELP]
        while values and values[-1] is None:
            values.pop()
        return "CYCLE93(%s)" % ", ".join("" if v is None else v for v in values)
    parts = [code]
    for letter in helps:
        value = getattr(args, "w_" + letter)
        if value is not None:
            parts.append(letter + value)
    text = " ".join(parts)
    if dialect == "fanuc" and args.fanuc_e is not None:
        text = "%s R%s\n%s" % (code, args.fanuc_e, text)
    return text


def _emit(args):
    from .engine import targets
    from .engine.errors import CycleError, ProgramError
    from .engine.registry import cycle_for

    title, dialect, code, helps = _CYCLES[args.cycle_name]
    settings = _settings(args)
    text = _native_text(args)
    try:
        cls = cycle_for(dialect, code or "CYCLE93")
        model = cls.parse(text)
        model.validate(settings)
        if not args.expand:
            return model.emit() + "\n"
        if args.start_x is None or args.start_z is None:
            raise ProgramError("--expand needs the start point: --start-x (diameter) and --start-z")
        state = _start_state(args, feed_default="rev")
        state.x = args.start_x / 2.0
        state.z = args.start_z
        state.feed = args.feed
        state.incremental = args.incremental
        moves = model.expand(state, settings)
        return targets.write_program(
            moves, args.to, state, title="%s: %s" % (title, " / ".join(text.split("\n"))), spindle=args.spindle
        )
    except CycleError as exc:
        raise _Failure("emit %s" % args.cycle_name, 1, exc.message) from None
    except ProgramError as exc:
        raise _Failure("emit %s" % args.cycle_name, 1, str(exc)) from None


# ---------------------------------------------------------------- expand: a program


class _Failure(Exception):
    def __init__(self, name, line, message):
        super().__init__(message)
        self.name = name
        self.line = line
        self.message = message


def _one_line(text):
    return " ".join(str(text).split())


def _read_program(path):
    name = "<stdin>" if path == "-" else path
    try:
        if path == "-":
            data = sys.stdin.buffer.read()
        else:
            with open(path, "rb") as f:
                data = f.read()
    except OSError as exc:
        raise _Failure(name, 0, "cannot read the program: %s" % (exc.strerror or exc)) from None
    try:
        return name, data.decode("utf-8")
    except UnicodeDecodeError:
        return name, data.decode("latin-1")


def _expand(args):
    from .engine.errors import ProgramError
    from .engine.program import translate_program

    name, text = _read_program(args.program)
    settings = _settings(args)
    try:
        return translate_program(
            text,
            args.dialect,
            settings,
            target=args.to,
            source_name=os.path.basename(name) if name != "<stdin>" else "stdin",
            start=_start_state(args),
        )
    except ProgramError as exc:
        raise _Failure(name, exc.line if exc.line is not None else 0, str(exc)) from None


def _write_output(text, out):
    """Write ``text`` to ``out`` atomically ("-" or None: stdout)."""
    if out in (None, "-"):
        sys.stdout.write(text)
        sys.stdout.flush()
        return
    try:
        write_atomically(out, text, encoding="ascii", errors="replace")
    except OSError as exc:
        raise _Failure(out, 0, "cannot write the output: %s" % (exc.strerror or exc)) from None


# ---------------------------------------------------------------- parser and main


def build_parser():
    parser = argparse.ArgumentParser(
        prog="python3 -m freecad_groove",
        description=DESCRIPTION,
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("--version", action="version", version="freecad-groove " + __version__)
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)

    ex = sub.add_parser(
        "expand",
        help="expand every grooving cycle of a program (writes the translated program)",
        description=DESCRIPTION,
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    ex.add_argument("program", metavar="PROGRAM", help="the program to read; - reads standard input")
    ex.add_argument(
        "--dialect",
        required=True,
        choices=tuple(DIALECT_HELP),
        help="the control the program is written for: "
        + "; ".join("%s = %s" % item for item in DIALECT_HELP.items()),
    )
    ex.add_argument(
        "--to",
        choices=("linuxcnc", "fanuc"),
        default="linuxcnc",
        help="the control the output is for: linuxcnc (G7 diameter mode, G4 P seconds, M2; the default) or "
        "fanuc (plain Fanuc lathe code: diameter X, G98/G99, G04 P milliseconds, M30, %% lines)",
    )
    ex.add_argument(
        "-o",
        "--output",
        metavar="OUT",
        help="write the translated program to OUT (replaced only when the whole run succeeds) instead of "
        "standard output",
    )
    _add_start_options(ex, expand=True)
    _add_settings_options(ex)
    _add_emit_parsers(sub)
    return parser


_TRAILING_POINT = re.compile(r"^-\d+\.$")


def _negative_words(argv):
    """argparse takes "-30." (a G-code style number) for an option; "-30.0" it
    reads as the negative number it is."""
    return [a + "0" if _TRAILING_POINT.match(a) else a for a in argv]


def main(argv=None):
    parser = build_parser()
    args = parser.parse_args(_negative_words(sys.argv[1:] if argv is None else list(argv)))
    try:
        if args.command == "expand":
            text = _expand(args)
            _write_output(text, args.output)
        else:
            text = _emit(args)
            _write_output(text, None)
        return 0
    except _Failure as exc:
        _report(exc.name, exc.line, exc.message)
    except BrokenPipeError:
        try:
            sys.stdout = open(os.devnull, "w")
        except OSError:
            pass
        return 1
    except Exception as exc:  # never a traceback: one line, status 2
        name = getattr(args, "program", None) or "freecad_groove"
        _report("<stdin>" if name == "-" else name, 0, "internal error (%s: %s)" % (type(exc).__name__, exc))
    return EXIT_ERROR


def _report(name, line, message):
    sys.stderr.write("%s:%s: %s\n" % (_one_line(name), line, _one_line(message)))
    sys.stderr.flush()


if __name__ == "__main__":
    sys.exit(main())
