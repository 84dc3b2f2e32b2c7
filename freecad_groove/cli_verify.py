"""The command line's ``verify`` and ``plot`` (the work is in freecad_groove.verify):

    python3 -m freecad_groove verify PROGRAM --dialect D [--tool-width W | --tool-table FILE] [--stock D[xL]]
    python3 -m freecad_groove plot PROGRAM --dialect D ... -o FILE.svg|.png

Exit status: 0 when the program cuts only its declared grooves and no rapid
enters standing stock; 1 when it gouges or collides (each finding one line
``PROGRAM:LINE: gouge: ...`` / ``collision: ...`` on stderr; plot still
writes its picture); 2 for bad input, as expand (one line ``PROGRAM:LINE:
message``, nothing written), a missing numpy or matplotlib included.
"""

from __future__ import annotations

import argparse
import re
from typing import List, Tuple

from .cli_options import add_settings_options, add_start_options, add_tool_table_option, not_negative, settings_from
from .engine.dialects import DIALECTS
from .engine.warnings import CycleWarning

NUMPY_MISSING = ("verify and plot need the Python package numpy: Debian/Ubuntu: apt install python3-numpy; "
                 "elsewhere: python3 -m pip install numpy")
MATPLOTLIB_MISSING = ("plot needs the Python package matplotlib: Debian/Ubuntu: apt install python3-matplotlib; "
                      "elsewhere: python3 -m pip install matplotlib")
DESCRIPTION = """\
verify: run every move of a program (cycle calls expanded, plain G0/G1/G2/G3
blocks, arcs as chords) through the turned section of the stock with the
blade's outline, and compare with the part the program declares: the stock
less the grooves its cycle calls describe. A feed cutting anything else is a
gouge, a rapid entering standing stock a collision. Prints per cycle call and
in total: removed, gouge, leftover the blade could reach, unreachable,
machining time. plot: draw that XZ section (-o FILE.svg or FILE.png).

Exit status: 0 no gouge and no collision; 1 a gouge or collision (one line
PROGRAM:LINE: gouge|collision: ... on stderr each; plot still draws); 2 bad
input (one line PROGRAM:LINE: message), numpy or matplotlib missing too.
The stock by default: a bar through the program's first approach point (see
docs/command-line.md, "verify and plot"); --stock D[xL] gives it.
"""
_STOCK = re.compile(r"^\s*(\d+(?:\.\d*)?|\.\d+)\s*(?:[xX]\s*(\d+(?:\.\d*)?|\.\d+))?\s*$")


def stock_option(text: str) -> Tuple[float, object]:
    """--stock DIAMETER[xLENGTH] (mm, both positive)."""
    match = _STOCK.match(text)
    if not match or float(match.group(1)) <= 0 or (match.group(2) is not None and float(match.group(2)) <= 0):
        raise argparse.ArgumentTypeError("%r must be DIAMETER or DIAMETERxLENGTH, both positive mm (60 or 60x120)"
                                         % text)
    return float(match.group(1)), None if match.group(2) is None else float(match.group(2))


def add_verify_parsers(sub: argparse._SubParsersAction) -> None:
    for command, helptext in (("verify", "simulate a program's moves over the stock: gouges, collisions, figures"),
                              ("plot", "draw a program's XZ section: stock, part, moves, gouges (SVG or PNG)")):
        parser = sub.add_parser(command, help=helptext, description=DESCRIPTION,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
        parser.add_argument("program", metavar="PROGRAM", help="the program to read; - reads standard input")
        parser.add_argument("--dialect", required=True, choices=list(DIALECTS), help="the control the program is for: "
                            + "; ".join("%s = %s" % (d.name, d.help) for d in DIALECTS.values()))
        parser.add_argument("--stock", type=stock_option, metavar="D[xL]",
                            help="the bar: diameter D mm and optionally length L mm back from its face end "
                            "(default: a bar through the program's first approach point, see docs/command-line.md)")
        parser.add_argument("--rapid-rate", type=not_negative, default=0.0, metavar="MM_PER_MIN",
                            help="rapid rate of both axes for the machining time (default: rapids not timed)")
        if command == "plot":
            parser.add_argument("-o", "--output", required=True, metavar="FILE",
                                help="the picture to write: FILE.svg or FILE.png (replaced only when drawn whole)")
        add_start_options(parser, expand=True)
        add_settings_options(parser)
        add_tool_table_option(parser)


def _missing(exc: ImportError, packages: Tuple[str, ...]) -> None:
    """Re-raise an ImportError that is not one of ``packages`` missing (a bug, not the user's setup)."""
    if (exc.name or "").split(".")[0] not in packages:
        raise exc


def _check(args: argparse.Namespace, warnings: List[Tuple[int, CycleWarning]]):
    """The ProgramCheck of the program the options name; Failure on bad input."""
    from .cli_io import MAX_PROGRAM_BYTES, Failure, check_line_lengths, program_name, read_text, tool_table
    from .cli_options import start_state
    from .engine.errors import ProgramError

    name = program_name(args.program)
    if DIALECTS[args.dialect].mill:  # a grinder's X/Y/Z: no turned section to check it on
        raise Failure(name, 0, "verify and plot check turning programs (the lathe's XZ section); %s programs "
                                "are mill-style (X/Y/Z)" % args.dialect)
    try:
        from .verify.program_check import StockSpec, check_program
        from .verify.program_record import record_program
    except ImportError as exc:
        _missing(exc, ("numpy",))
        raise Failure(name, 0, NUMPY_MISSING) from None
    tools = tool_table(args)
    name, text = read_text(args.program, "the program", MAX_PROGRAM_BYTES)
    check_line_lengths(text, name)
    try:
        record = record_program(text, args.dialect, settings_from(args), start_state(args), tools)
        warnings.extend(record.warnings)
        spec = None if args.stock is None else StockSpec(*args.stock)
        return check_program(name, record, spec, args.rapid_rate, regions=args.command == "plot")
    except ProgramError as exc:
        raise Failure.of_program_error(name, exc) from None


def _drawer(args: argparse.Namespace):
    """plot's draw function, checked before the simulation: the picture's format and matplotlib."""
    from .cli_io import Failure, check_not_the_program

    if not args.output.lower().endswith((".svg", ".png")):
        raise Failure(args.output, 0, "the picture's name must end in .svg or .png")
    check_not_the_program(args.output, args.program)
    try:
        from .verify.plot import draw
    except ImportError as exc:
        _missing(exc, ("matplotlib",))
        raise Failure(args.output, 0, MATPLOTLIB_MISSING) from None
    return draw


def _plot(args: argparse.Namespace, draw, result) -> None:
    from .cli_io import Failure
    from .engine.output.files import write_chunks_atomically

    data = draw(result, args.output.lower().rsplit(".", 1)[1])
    try:  # bytes through the text writer: Latin-1 maps each byte to one character and back
        write_chunks_atomically(args.output, [data.decode("latin-1")], encoding="latin-1")
    except OSError as exc:
        raise Failure(args.output, 0, "cannot write the picture: %s" % (exc.strerror or exc)) from None


def run(args: argparse.Namespace, warnings: List[Tuple[int, CycleWarning]], report_line) -> int:
    """verify or plot; returns 0 or 1 (findings); bad input raises cli.Failure."""
    draw = _drawer(args) if args.command == "plot" else None
    result = _check(args, warnings)
    if draw is not None:
        _plot(args, draw, result)
    else:
        from .cli_io import write_stdout
        from .verify.program_check import report

        write_stdout((report(result),))
    for line, text in result.findings:
        report_line(result.name, line, text)
    return 1 if result.findings else 0
