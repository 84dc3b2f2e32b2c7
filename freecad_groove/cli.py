"""Command line: expand the grooving cycles of a lathe program, or write one cycle call.

    python3 -m freecad_groove expand PROGRAM --dialect sinumerik [--tool-table FILE] [-o OUT] [--to linuxcnc]
    python3 -m freecad_groove emit cycle93 --tool-width 3 --axfa 35 --axsa 60 ...
    python3 -m freecad_groove verify PROGRAM --dialect sinumerik --tool-table FILE [--stock D[xL]]
    python3 -m freecad_groove plot PROGRAM --dialect sinumerik --tool-table FILE -o FILE.svg

(verify and plot: cli_verify.py.)

Thin layer: argument parsing and error reporting; the work is done by freecad_groove.engine
(translator.iter_translation, output.program.write_program and the cycle classes).

Errors: an invalid cycle or a line the reader cannot translate prints exactly
one line ``PROGRAM:LINE: message`` on stderr, writes nothing to stdout or OUT
(an existing OUT is left untouched) and exits with status 2. A file that cannot
be read or written is reported the same way with LINE 0 (OUT: what
engine/output/files.py refuses, a full or closed stdout as ``<stdout>:0:``). Bad
option values are reported by argparse (usage and message on stderr, status 2).
A broken pipe on stdout ends quietly with status 1. SIGINT, SIGTERM and SIGHUP
print ``PROGRAM:0: interrupted`` and exit with 128 + the signal's number, the
temporary file of OUT removed. Running out of memory is said in one line too.

Warnings: what a cycle cannot do as programmed but does anyway (the engine's
CycleWarning) prints one line each on stderr, ``PROGRAM:LINE: warning: CYCLE93:
...`` (``emit CYCLE:1: warning: ...`` for emit --expand), after the output is
written; the status stays 0 and stdout and OUT are the same as without them.
A run that fails prints its error alone. Until then they are kept as lines in
a temporary file (cli_io.WarningSpool), not in memory.

Memory: ``expand`` streams. The program is read a line at a time (standard
input or a pipe is first copied to an anonymous temporary file; a first pass
over the file decides its encoding: UTF-8 when the whole file is valid UTF-8,
else Latin-1, as when it was read whole), translated block by block
(translator.iter_translation), and each block's output written as it is made
to a temporary file: with -o, OUT's own temporary file next to it
(output.write_chunks_atomically), renamed over OUT after the last line; for
stdout, an anonymous temporary file (tempfile.TemporaryFile, in TMPDIR, gone
when closed, even on a kill) copied to stdout only when the whole run
succeeded. So memory stays flat with the size of the program and the output,
and a run that fails writes nothing to stdout or OUT. OUT is checked (what
engine/output/files.py refuses) before the translation starts, after the program
and tool table were opened.
"""

import argparse
import os
import re
import signal
import sys
import threading
from typing import Callable, List, Tuple

from . import __version__
from .cli_io import (
    Failure,
    WarningSpool,
    check_not_the_program,
    open_program,
    program_name,
    quiet_stdout,
    read_lines,
    report,
    tool_table,
    unexpected,
    write_chunks,
    write_stdout,
)
from .cli_options import (
    add_settings_options,
    add_start_options,
    add_tool_table_option,
    counted,
    decimal_word,
    finite,
    positive,
    settings_from,
    siemens_value,
    start_state,
)
from .cli_parameters import add_parameter_options, parameter_lines
from .cli_tools import add_tools_parser
from .cli_tools import run as run_tools
from .cli_verify import add_verify_parsers
from .cli_verify import run as run_verify
from .engine import registry
from .engine.dialects import DIALECTS, dialect_named
from .engine.output.targets import TARGETS, program_target
from .engine.registry import CALL, CycleEntry, CycleWord
from .engine.warnings import CycleWarning, cycle_warnings

EXIT_ERROR = 2

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

Blade: CYCLE93 places its plunges with the blade, so it is refused without
one: --tool-width (every tool) or --tool-table FILE (the blade of each T;
--tool-width is then the blade of the tools the table does not list).

Examples:
  python3 -m freecad_groove expand examples/seed_cycle93.mpf --dialect sinumerik --tool-table examples/tools.tbl
  python3 -m freecad_groove expand part.nc --dialect fanuc --to fanuc -o part_expanded.nc
  python3 -m freecad_groove emit g77 -X 40. -Z -30. -I 2. -K 5. -D 0 -F 0.08
"""


# ---------------------------------------------------------------- emit: one cycle call


def _word_type(entry: CycleEntry, word: CycleWord) -> Callable[[str], str]:
    """How a cycle word is typed on the command line: a Siemens call parameter,
    a counted integer (Fanuc P/Q) or a decimal word."""
    if entry.form == CALL:
        return siemens_value
    return counted if word.counted else decimal_word


def _add_cycle_words(parser: argparse.ArgumentParser, entry: CycleEntry) -> None:
    """One option per cycle word (``--axfa``; ``-X``/``--x``), and Fanuc's first-block R."""
    words = parser.add_argument_group("cycle parameters")
    for word in entry.words:
        flags = ("--" + word.name.lower(),) if entry.form == CALL else ("-" + word.name, "--" + word.name.lower())
        words.add_argument(*flags, dest="w_" + word.name, type=_word_type(entry, word), metavar="V", help=word.help)
    add_parameter_options(words, entry)
    if entry.retract_block:
        words.add_argument(
            "-e", "--first-block-r", dest="retract_e", type=decimal_word, metavar="E",
            help="peck retract e: writes the first block '%s %s(e)' (parameter 5139 otherwise)"
            % (entry.name, entry.retract_block),
        )


def _add_expand_options(parser: argparse.ArgumentParser) -> None:
    """emit --expand: the start point and modes of the whole program."""
    ex = parser.add_argument_group("expanded output (--expand)")
    ex.add_argument("--expand", action="store_true",
                    help="print a whole program with the expanded moves instead of the native call")
    ex.add_argument("--start-x", type=finite, metavar="X",
                    help="start point X as a DIAMETER (the tool position before the call; required with "
                    "--expand)")
    ex.add_argument("--start-z", type=finite, metavar="Z",
                    help="start point Z (required with --expand, except for Milltronics G33/G34: they rapid in X Y "
                    "at the height held, then to R)")
    ex.add_argument("--start-y", type=finite, metavar="Y",
                    help="start point Y of a grinder cycle (G83; required with --expand; its X is then a plain "
                    "coordinate and the output mill-style)")
    ex.add_argument("--feed", type=positive, metavar="F", help="feed in force before the call")
    ex.add_argument("--spindle", type=positive, metavar="RPM",
                    help="spindle speed started (M3) before the moves; needed with feed per revolution")
    ex.add_argument("--incremental", action="store_true", help="G91 in force (AB, Siemens)")
    ex.add_argument("--to", choices=list(TARGETS), default="linuxcnc", metavar="TARGET",
                    help="output control: %s (default linuxcnc)" % ", ".join(TARGETS))
    ex.add_argument("--native-cycles", action="store_true",
                    help="write the call as the --to control's own cycle where one cuts the same (as expand "
                    "--native-cycles does), else the moves after a comment saying why")
    add_start_options(parser, expand=False)


def _add_emit_parsers(sub: argparse._SubParsersAction) -> None:
    entries = registry.cycles()
    aliases = ", ".join("%s = %s" % (alias, entry.key) for entry in entries for alias in entry.aliases)
    emit = sub.add_parser(
        "emit",
        help="check one cycle call and print it in the control's own syntax (or expanded)",
        description="Check one cycle call with its parameters and print it as the control reads it. "
        "With --expand, print instead a whole program that goes to the start point and runs the "
        "expanded moves. Cycles: "
        + ", ".join(sorted(entry.key for entry in entries))
        + " (aliases: %s)." % aliases,
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    cycles = emit.add_subparsers(dest="cycle", metavar="CYCLE", required=True)
    for entry in entries:
        parser = cycles.add_parser(
            entry.key,
            aliases=list(entry.aliases),
            help=entry.title,
            description=entry.title + ". Lengths in the program's units; X as a diameter unless stated.",
            epilog=EPILOG,
            formatter_class=argparse.RawDescriptionHelpFormatter,
        )
        parser.set_defaults(cycle_name=entry.key)
        _add_cycle_words(parser, entry)
        add_settings_options(parser)
        _add_expand_options(parser)


def _native_text(args: argparse.Namespace, entry: CycleEntry) -> str:
    """The call as the control writes it, from the options given."""
    values = [(word.name, getattr(args, "w_" + word.name)) for word in entry.words]
    if entry.form == CALL:
        while values and values[-1][1] is None:
            values.pop()
        return "%s(%s)" % (entry.name, ", ".join("" if value is None else value for _, value in values))
    text = " ".join([entry.name] + [name + value for name, value in values if value is not None])
    retract_e = getattr(args, "retract_e", None)
    if entry.retract_block and retract_e is not None:
        text = "%s %s%s\n%s" % (entry.name, entry.retract_block, retract_e, text)
    return "\n".join(parameter_lines(args, entry) + [text])


def _emit(args: argparse.Namespace, warnings: List[Tuple[int, CycleWarning]]) -> str:
    """The native call, or with --expand the whole program; the cycle's warnings
    are appended to ``warnings`` (on line 1)."""
    from .engine.errors import CycleError, ProgramError
    from .engine.output.program import write_program
    from .engine.tool_table import BLADE_UNKNOWN

    entry = registry.entry(args.cycle_name)
    settings = settings_from(args)
    text = _native_text(args, entry)
    try:
        model = entry.cycle_class.parse(text)
        if entry.needs_blade and settings.tool is None:
            raise ProgramError("%s: %s: give --tool-width" % (entry.name, BLADE_UNKNOWN))
        model.validate(settings)
        if not args.expand:
            return model.emit() + "\n"
        unknown_z = entry.cycle_class.FROM_UNKNOWN_Z  # G33/G34: X Y at the height held, then Z to R
        if args.start_x is None or (args.start_z is None and not unknown_z):
            raise ProgramError("--expand needs the start point: --start-x (diameter) and --start-z")
        state = start_state(args, feed_default="rev")
        mill = entry.cycle_class.MILL  # a grinder cycle: X/Y/Z, a mill-style program
        state.x = args.start_x if mill else args.start_x / 2.0
        state.z = args.start_z
        state.y = args.start_y if mill else None
        state.feed = args.feed
        state.incremental = args.incremental
        moves = model.expand(state, settings)
        warnings.extend((1, warning) for warning in cycle_warnings(model, state, settings))
        try:
            target = program_target(args.to, mill)
        except ValueError as exc:
            raise ProgramError("--to %s: %s" % (args.to, exc)) from None
        call, note = _native_call(args, model, state, settings, moves, target)
        return write_program(
            moves, target, state, title="%s: %s" % (entry.title, " / ".join(text.split("\n"))), spindle=args.spindle,
            call=call, note=note,
        )
    except CycleError as exc:
        raise Failure("emit %s" % args.cycle_name, 1, exc.message) from None
    except ProgramError as exc:
        raise Failure("emit %s" % args.cycle_name, 1, str(exc)) from None


def _native_call(args, model, state, settings, moves, target):
    """emit --expand --native-cycles: (the target's call, None) or (None, the comment saying why not)."""
    if not args.native_cycles:
        return None, None
    from dataclasses import replace

    from .engine.native import NativeOutput, NotNative
    from .engine.output.writer import Writer

    decider = NativeOutput(target, Writer(target, state.metric, state.feed_per_rev))
    try:
        return decider.call(model, replace(state), settings, moves, settings.tool), None
    except NotNative as why:
        return None, "expanded: %s" % why


# ---------------------------------------------------------------- expand: a program


def _expand(args, warnings):
    """Translate the program to OUT (or stdout), streaming: the program is read
    a line at a time (open_program), each line's translation written as it is
    made (write_chunks). Everything the translation needs (modules, codecs) is
    loaded before OUT's temporary file is made, so that a signal there is never
    taken inside an import. The cycles' warnings are appended to ``warnings``."""
    from .engine.errors import ProgramError
    from .engine.translator import iter_translation

    tools = tool_table(args)
    name = program_name(args.program)
    check_not_the_program(args.output, args.program)
    try:  # a mill-style program for a lathe target, or the reverse: refused before anything is read
        program_target(args.to, dialect_named(args.dialect).mill)
    except ValueError as exc:
        raise Failure(name, 0, "--to %s: %s" % (args.to, exc)) from None
    with open_program(args.program, name) as text:
        chunks = iter_translation(
            read_lines(text, name),
            args.dialect,
            settings_from(args),
            target=args.to,
            source_name=os.path.basename(name) if name != "<stdin>" else "stdin",
            start=start_state(args),
            tools=tools,
            warnings=warnings,
            native_cycles=args.native_cycles,
        )
        try:
            write_chunks(chunks, args.output)
        except ProgramError as exc:
            raise Failure.of_program_error(name, exc) from None


# ---------------------------------------------------------------- signals


class _Interrupted(BaseException):
    """SIGINT, SIGTERM or SIGHUP arrived (a BaseException, so no ``except
    Exception`` takes it for an error; write_chunks_atomically removes its temporary
    file on the way out)."""

    def __init__(self, signum):
        super().__init__(signum)
        self.signum = signum


_SIGNALS = tuple(getattr(signal, name) for name in ("SIGINT", "SIGTERM", "SIGHUP") if hasattr(signal, name))


def _on_signal(signum, frame):
    for sig in _SIGNALS:  # the first signal ends the run: the cleanup is not interrupted by another
        if signal.getsignal(sig) is _on_signal:
            signal.signal(sig, signal.SIG_IGN)
    raise _Interrupted(signum)


def _catch_signals():
    """Make SIGINT, SIGTERM and SIGHUP raise _Interrupted; a signal ignored
    when we start (nohup, a background job) stays ignored. Returns the
    handlers to restore."""
    if threading.current_thread() is not threading.main_thread():
        return {}
    previous = {}
    for sig in _SIGNALS:
        handler = signal.getsignal(sig)
        if handler is not signal.SIG_IGN:
            previous[sig] = handler
            signal.signal(sig, _on_signal)
    return previous


def _restore_signals(previous):
    for sig, handler in previous.items():
        signal.signal(sig, signal.SIG_DFL if handler is None else handler)


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
        choices=list(DIALECTS),
        help="the control the program is written for: "
        + "; ".join("%s = %s" % (dialect.name, dialect.help) for dialect in DIALECTS.values()),
    )
    ex.add_argument(
        "--to",
        choices=list(TARGETS),
        default="linuxcnc",
        metavar="TARGET",
        help="the control the output is for (default linuxcnc): "
        + "; ".join("%s = %s" % (name, target.title.replace("%", "%%")) for name, target in TARGETS.items())
        + ". A mill-style program (--dialect ab9grind, milltronics) naming linuxcnc or fanuc is written on its "
        "mill twin (linuxcnc-mill, fanuc-mill)",
    )
    ex.add_argument("--native-cycles", action="store_true", help=_native_help())
    ex.add_argument(
        "-o",
        "--output",
        metavar="OUT",
        help="write the translated program to OUT (replaced only when the whole run succeeds) instead of "
        "standard output",
    )
    add_start_options(ex, expand=True)
    add_settings_options(ex)
    add_tool_table_option(ex)
    _add_emit_parsers(sub)
    add_verify_parsers(sub)
    add_tools_parser(sub)
    return parser


def _native_help():
    """--native-cycles' help: what it does and the pairs written natively (engine/native/pairs.py)."""
    from .engine.native import native_pairs

    pairs = "; ".join("%s: %s" % item for item in native_pairs().items())
    return ("write each cycle call as the target's own cycle where one cuts the same grooves, else its moves "
            "after a comment saying why (the same reasons as the lathe posts give). A call converted to another "
            "control's cycle is written only when the engine's expansion of the call as written cuts the same "
            "moves (within the output's resolution); CYCLE93 becomes a pecking cycle as the lathe posts decide "
            "(plain grooves only). A call relying on a machine setting (the peck retract e of Allen-Bradley and "
            "Haas, from --retract) says so in a comment. Default: every call expanded. Native per --to target: "
            + pairs + ".").replace("%", "%%")


_TRAILING_POINT = re.compile(r"^-\d+\.$")


def _negative_words(argv):
    """argparse takes "-30." (a G-code style number) for an option; "-30.0" it
    reads as the negative number it is."""
    return [a + "0" if _TRAILING_POINT.match(a) else a for a in argv]


def main(argv=None):
    """Run the command line; returns the exit status: 0, 1 for a broken pipe
    (and for verify/plot, a gouge or collision found), 2 for an error (one
    line PROGRAM:LINE: message on stderr), 128 + the signal's number for
    SIGINT (130), SIGTERM (143) and SIGHUP (129)."""
    previous = _catch_signals()
    name = "freecad_groove"
    try:
        parser = build_parser()
        args = parser.parse_args(_negative_words(sys.argv[1:] if argv is None else list(argv)))
        name = _run_name(args)
        return _run(args, name)
    except _Interrupted as exc:
        report(name, 0, "interrupted")
        return 128 + exc.signum
    finally:
        _restore_signals(previous)


def _run_name(args):
    """The name an error of this run starts with."""
    if args.command in ("expand", "verify", "plot"):
        return program_name(args.program)
    if args.command == "tools":
        return program_name(args.table)
    return "emit %s" % args.cycle_name


def _run(args, name):
    warnings = WarningSpool()  # kept out of memory until the run has succeeded
    try:
        status = 0
        if args.command == "expand":
            _expand(args, warnings)
        elif args.command in ("verify", "plot"):
            status = run_verify(args, warnings, report)
        elif args.command == "tools":
            run_tools(args)
        else:
            write_stdout((_emit(args, warnings),))
        warnings.report(name)  # after the output: a failed run reports its error alone
        return status
    except Failure as exc:
        report(exc.name, exc.line, exc.message)
    except BrokenPipeError:
        quiet_stdout()
        return 1
    except Exception as exc:  # never a traceback: one line, status 2
        report(name, 0, unexpected(exc, args.command))
    finally:
        warnings.close()
    return EXIT_ERROR




if __name__ == "__main__":
    sys.exit(main())
