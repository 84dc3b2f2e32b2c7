"""The live tool and the C axis mode around a Cylinder slot op in a program.

A slot is milled with the main spindle held as the C axis and a driven
(live) tool turning in the turret. The codes that switch the spindle into and
out of C axis mode and that start and stop the live tool are the machine
builder's: the GSK 980TDi manual's pages on G7.1 name none, nor does
LinuxCNC (a lathe's C axis and a second spindle are configured per machine).
So they are post options without defaults, on the posts that write C:

    --c-axis-on WORDS    --c-axis-off WORDS
    --live-tool-cw WORDS --live-tool-ccw WORDS   (written with S<rpm> of the tool controller)
    --live-tool-stop WORDS
    --switches-by-hand   (a comment in place of each switch not given)

WORDS: program words, space separated (``M14``, ``"M64 P0"``, ``"M3 $1"``).
The main spindle is never started for a slot (program.py: a tool
controller's spindle waits for the op that uses it). Around a slot the post
stops the main spindle (the control's spindle stop) if an earlier op left it
turning, switches C axis mode on, starts the live tool in the tool
controller's SpindleDir at its SpindleSpeed (0: the slot's default,
ops/slot/cutting.py), writes the slot, then stops the live tool and switches
C axis mode off. A switch whose option is not given is not guessed: the
slot is refused (PostError naming the option), since a program without it
feeds an end mill that does not turn. With
--switches-by-hand the machinist takes them on: a comment in its place says
what is missing and which option writes it (even with --no-comments: it
marks where the code goes), and ``Program.missing_switches`` lists it for
the report view.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, Any, NamedTuple, Optional

from .post_error import PostError

if TYPE_CHECKING:
    from .program import Program

WORDS = re.compile(r"^[A-Z$][-+]?[0-9]+(\.[0-9]+)?( +[A-Z$][-+]?[0-9]+(\.[0-9]+)?)*$")

# (option, attribute, help)
OPTIONS = (
    ("--c-axis-on", "c_axis_on", "the words that switch the spindle into C axis mode before a Cylinder slot "
                                 "(machine-specific; no default: a Cylinder slot without it is refused, "
                                 "or with --switches-by-hand a comment marks the missing switch)"),
    ("--c-axis-off", "c_axis_off", "the words that switch C axis mode off after a Cylinder slot (no default)"),
    ("--live-tool-cw", "live_tool_cw", "the words that start the live tool clockwise (SpindleDir Forward), "
                                       "written with S<rpm> of the tool controller (no default)"),
    ("--live-tool-ccw", "live_tool_ccw", "as --live-tool-cw, counter-clockwise (SpindleDir Reverse)"),
    ("--live-tool-stop", "live_tool_stop", "the words that stop the live tool after a Cylinder slot (no default)"),
)
BY_HAND = "--switches-by-hand"


class LiveToolCodes(NamedTuple):
    """The words of each switch (None: not given)."""

    c_axis_on: Optional[str] = None
    c_axis_off: Optional[str] = None
    live_tool_cw: Optional[str] = None
    live_tool_ccw: Optional[str] = None
    live_tool_stop: Optional[str] = None
    by_hand: bool = False  # BY_HAND: a comment in place of each switch not given, instead of a refusal


def add_options(parser: Any) -> None:
    """The options of OPTIONS on a post's parser (a post whose control writes C)."""
    for option, attribute, text in OPTIONS:
        parser.add_argument(option, dest=attribute, metavar="WORDS", default=None, help=text)
    parser.add_argument(BY_HAND, dest="switches_by_hand", action="store_true",
                        help="write a comment in place of each live tool / C axis switch not given (you add the "
                             "machine's codes by hand); without it a Cylinder slot missing a switch is refused")


def read_options(namespace: Any) -> LiveToolCodes:
    """The codes given, each checked: PostError naming the option for words that are not program words."""
    values = {}
    for option, attribute, _text in OPTIONS:
        value = getattr(namespace, attribute, None)
        if value is not None:
            value = " ".join(value.split())
            if not WORDS.match(value):
                raise PostError("%s %r: must be program words, a letter and a number each, space separated "
                                "(e.g. M14, \"M64 P0\")" % (option, value))
        values[attribute] = value
    return LiveToolCodes(by_hand=bool(getattr(namespace, "switches_by_hand", False)), **values)


def _switch(program: Program, words: Optional[str], option: str, what: str, label: str) -> None:
    if words:
        program.add([words])
        return
    if not program.options.live_tool.by_hand:
        raise PostError("%s: no %s given: the post does not know the machine's code (without it the end mill "
                        "would not turn or C would not be an axis); give %s WORDS, or %s to write a comment in "
                        "its place and add the code by hand" % (what, option, option, BY_HAND), op=label)
    program.missing_switches.append(option)
    program.add([program.writer.comment("%s: no %s given, the post cannot write it" % (what, option))])


def switch_on(program: Program, cutting: Any, label: str) -> None:
    """Before the slot op ``label``: the main spindle stopped, C axis mode on, the live tool started at the
    speed and in the direction ``cutting`` gives (ops/slot/cutting.SlotCutting: the tool controller's, or
    the default)."""
    codes = program.options.live_tool
    if program.spindle_on:
        program.stop_spindle()
    _switch(program, codes.c_axis_on, "--c-axis-on", "C axis mode on", label)
    words, option = (codes.live_tool_ccw, "--live-tool-ccw") if cutting.reverse else (codes.live_tool_cw,
                                                                                      "--live-tool-cw")
    _switch(program, "%s S%d" % (words, cutting.rpm) if words else None, option, "live tool on at S%d" % cutting.rpm,
            label)


def switch_off(program: Program, label: str) -> None:
    """After the slot op ``label``: the live tool stopped, C axis mode off."""
    codes = program.options.live_tool
    _switch(program, codes.live_tool_stop, "--live-tool-stop", "live tool stop", label)
    _switch(program, codes.c_axis_off, "--c-axis-off", "C axis mode off", label)
