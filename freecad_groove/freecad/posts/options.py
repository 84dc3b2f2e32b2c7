"""The posts' arguments: each post's argparse parser, its tooltip, and :class:`Options`, the parsed options completed.

A post takes only the options its target has a use for (the target's data,
through its LathePost, says which); a bad argument raises PostError instead of ending FreeCAD.
"""

import argparse
import math
import shlex
from typing import List, Optional, Sequence, Tuple, Union

from ...engine.cycles.cycle_words import DECIMALS as CYCLE_WORD_DECIMALS
from ...engine.moves import REFERENCE_MINUS, REFERENCE_PLUS
from .lathe_posts import NATIVE_CYCLE93, NATIVE_PECKING, LathePost, lathe_post_named
from .live_tool import add_options as add_live_tool_options
from .live_tool import read_options as read_live_tool_options
from .post_error import PostError

MAX_PRECISION = 6
MAX_PROGRAM_NUMBER = 9999


class PostParser(argparse.ArgumentParser):
    """An ArgumentParser that raises PostError where argparse would exit."""

    def error(self, message: str) -> None:
        raise PostError("%s: %s" % (self.prog, message))

    def exit(self, status: int = 0, message: Optional[str] = None) -> None:
        raise PostError("%s: %s" % (self.prog, (message or "exit %d" % status).strip()))


def tooltip(name: str) -> str:
    """The one-line description of post ``name`` FreeCAD shows."""
    post = lathe_post_named(name)
    return "%s post by freecad-groove: %s; other operations as X/Z moves (X as %s)." % (
        post.title, post.grooves_summary(), post.x_words)


def _add_groove_options(parser: PostParser, post: LathePost) -> None:
    """--native-cycles/--expand-cycles, --retract and the X word options."""
    cycles = parser.add_mutually_exclusive_group()
    if post.native:
        cycles.add_argument("--native-cycles", dest="cycles", action="store_const", const="native",
                            help="write grooves as the control's own cycle calls where it has one (default)")
    cycles.add_argument("--expand-cycles", dest="cycles", action="store_const", const="expand",
                        help="write every groove as G0/G1 moves and G2/G3 arcs (the op's own path)"
                        + post.expand_help_note)
    if post.native == NATIVE_PECKING:
        parser.add_argument("--retract", type=float, metavar="E",
                            help="peck retract e of the %s cycles, mm (default: the op's Retract, 0 = 1 mm); %s"
                            % (post.pecking_codes, post.retract_help()))
    if post.has_x_mode:
        parser.add_argument("--x-mode", choices=("diameter", "radius"), default="diameter",
                            help="X words as diameters (default) or radii (%s)" % post.x_mode_codes)
    if post.g07_radius_option:
        parser.add_argument("--g07-radius", action="store_true",
                            help="on this control G07 selects radius mode and G08 diameter mode "
                            "(default: G07 diameter)")
    if post.native == NATIVE_CYCLE93:
        parser.add_argument("--diameter-input", action="store_true",
                            help="write CYCLE93 AXFA, DEPG, FAL1 (longitudinal) and FAL2 (face) as diameters "
                            "(default: radius values, as the engine reads them)")


def _add_program_options(parser: PostParser, post: LathePost) -> None:
    """The reference corner, the program frame, comments, precision and --help."""
    parser.add_argument("--reference-corner", choices=(REFERENCE_MINUS, REFERENCE_PLUS),
                        help="the blade corner the control's tool offset measures "
                        "(default: each op's ReferenceCorner)")
    if post.o_number_frame:
        parser.add_argument("--program-number", type=int, default=1, metavar="N",
                            help="O number of the program (default 1)")
    parser.add_argument("--no-header", action="store_true", help="no program name / post comment at the top")
    parser.add_argument("--no-comments", action="store_true", help="no comments at all")
    cycle_words = "; cycle words keep at most %d" % CYCLE_WORD_DECIMALS if post.native == NATIVE_PECKING else ""
    parser.add_argument("--inches", action="store_true",
                        help="inch output: %s, lengths in inches, feeds in in/min or in/rev, surface speed in "
                        "ft/min (default: metric, %s)" % (post.units(True), post.units(False)))
    parser.add_argument("--precision", type=int, default=None, metavar="N",
                        help="decimals of coordinates (default %d, %d with --inches%s)"
                        % (post.digits, post.digits + 1, cycle_words))
    parser.add_argument("--help", action="store_true",
                        help="show this help in the report view and write no program")


def make_parser(name: str) -> PostParser:
    """The argparse parser of lathe post ``name`` (a key of LATHE_POSTS)."""
    post = lathe_post_named(name)
    parser = PostParser(prog=post.freecad_name + "_post", add_help=False, description=tooltip(name))
    _add_groove_options(parser, post)
    if post.c_feed is not None:  # Cylinder slots: the live tool and C axis mode switches
        add_live_tool_options(parser)
    _add_program_options(parser, post)
    return parser


class Options:
    """The parsed options, completed with the post's defaults and checked.

    ``diameter``: X words as diameters (always, for a control without
    --x-mode); ``native``: grooves as the control's own cycles;
    ``native_decimals``: decimals of the pecking cycles' words."""

    def __init__(self, post: LathePost, namespace: argparse.Namespace) -> None:
        self.cycles: str = namespace.cycles or ("native" if post.native else "expand")
        self.native: bool = self.cycles == "native" and post.native is not None
        self.retract: Optional[float] = getattr(namespace, "retract", None)
        if self.retract is not None and not (math.isfinite(self.retract) and self.retract >= 0):
            raise PostError("--retract %s: must be a number not less than 0" % self.retract)
        self.diameter: bool = getattr(namespace, "x_mode", "diameter") == "diameter"
        self.g07_is_diameter: bool = not getattr(namespace, "g07_radius", False)
        self.diameter_input: bool = getattr(namespace, "diameter_input", False)
        self.reference: Optional[str] = namespace.reference_corner
        self.program_number: Optional[int] = getattr(namespace, "program_number", None)
        if self.program_number is not None and not 0 <= self.program_number <= MAX_PROGRAM_NUMBER:
            raise PostError("--program-number %d: must be 0 to %d" % (self.program_number, MAX_PROGRAM_NUMBER))
        self.header: bool = not namespace.no_header
        self.comments: bool = not namespace.no_comments
        self.inches: bool = namespace.inches
        precision = namespace.precision
        if precision is None:
            precision = post.digits + (1 if self.inches else 0)
        if not 0 <= precision <= MAX_PRECISION:
            raise PostError("--precision %d: must be 0 to %d" % (precision, MAX_PRECISION))
        self.precision: int = precision
        self.native_decimals: int = min(self.precision, CYCLE_WORD_DECIMALS)
        self.help: bool = namespace.help
        self.live_tool = read_live_tool_options(namespace)


def split_arguments(post: str, argstring: Union[None, str, Sequence[str]]) -> List[str]:
    """The post's argument string (or list) as a list of arguments."""
    if argstring is None:
        return []
    if isinstance(argstring, (list, tuple)):
        return list(argstring)
    try:
        return shlex.split(argstring)
    except ValueError as e:
        raise PostError("%s_post: cannot read the arguments %r: %s" % (post, argstring, e)) from None


def parse_options(name: str, argstring: Union[None, str, Sequence[str]]) -> Tuple[Options, PostParser]:
    """The options of post ``name`` from FreeCAD's argument string, and the parser (for --help)."""
    post = lathe_post_named(name)
    parser = make_parser(name)
    return Options(post, parser.parse_args(split_arguments(post.freecad_name, argstring))), parser
