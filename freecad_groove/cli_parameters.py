"""emit's options for the P parameters a cycle reads from assignment blocks
(Milltronics G33/G34: ``--p151 1 --p152 3 --p155 .1``): each given value
becomes a ``P151=1.`` block before the call, as a program sets them. A
parameter not given is not written (the cycle's own rules say whether it is
needed)."""

import argparse
from typing import List

from .cli_options import decimal_word
from .engine.registry import CycleEntry

PARAMETER_HELP = {
    "P150": "corner radius (G34; 0: the corners at the tool radius)",
    "P151": "X size of the rectangle",
    "P152": "Y size of the rectangle",
    "P153": "X-Y finish stock (G34)",
    "P154": "Z finish stock (G34)",
    "P155": "cut width (at most the tool's diameter)",
}


def parameters_of(entry: CycleEntry) -> tuple:
    """The P parameters ``entry``'s cycle reads (none for most cycles)."""
    return tuple(entry.cycle_class.PARAMETERS)


def add_parameter_options(group: argparse._ArgumentGroup, entry: CycleEntry) -> None:
    """One ``--p1nn`` option per P parameter of the cycle."""
    for name in parameters_of(entry):
        group.add_argument("--" + name.lower(), dest="p_" + name, type=decimal_word, metavar="V",
                           help="%s, written as a %s=V block before the call" % (PARAMETER_HELP.get(name, name), name))


def parameter_lines(args: argparse.Namespace, entry: CycleEntry) -> List[str]:
    """The assignment blocks of the P parameters given, in the cycle's order."""
    lines = []
    for name in parameters_of(entry):
        value = getattr(args, "p_" + name, None)
        if value is not None:
            lines.append("%s=%s" % (name, value))
    return lines
