"""The command line's ``tools``: the project's tool table written as a
control's lathe tool table.

    python3 -m freecad_groove tools tools.tbl --to linuxcnc --units mm [-o tool.tbl]
"""

import argparse

from .cli_io import Failure, check_not_the_program, read_text, write_chunks
from .engine.errors import ProgramError
from .engine.output.lathe_tools import UNITS, linuxcnc_tool_table
from .engine.tool_table import SIDES, read_tool_table

__all__ = ["add_tools_parser", "run"]

WRITERS = {"linuxcnc": linuxcnc_tool_table}


def add_tools_parser(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser(
        "tools", help="write the tool table (--tool-table's format) as a control's lathe tool table",
        description="Write the project's tool table (one blade a line: T width corner-radius reference, and "
        "side=%s for where it cuts) as a control's lathe tool table: LinuxCNC's, with each blade's "
        "orientation Q, tip diameter D and front and back angles I/J (docs/tool-tables.md)." % "|".join(SIDES))
    parser.add_argument("table", metavar="TABLE", help="the tool table to read; - reads standard input")
    parser.add_argument("--to", required=True, choices=list(WRITERS), help="the control whose table to write")
    parser.add_argument("--units", required=True, choices=UNITS,
                        help="the unit of the table's lengths, written as they are: the control reads its tool "
                        "table in the machine's units")
    parser.add_argument("-o", "--output", metavar="OUT", help="write to OUT (replaced only when the whole table is "
                        "written) instead of standard output")


def run(args: argparse.Namespace) -> None:
    """Read, convert and write; a Failure (TABLE:LINE: message) on bad input."""
    check_not_the_program(args.output, args.table)
    name, text = read_text(args.table, "the tool table")
    try:
        written = WRITERS[args.to](read_tool_table(text, name), args.units)
    except ProgramError as exc:
        raise Failure.of_program_error(name, exc) from None
    write_chunks([written], args.output)
