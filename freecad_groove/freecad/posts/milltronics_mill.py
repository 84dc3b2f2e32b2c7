"""The ``milltronics_mill`` post: a CAM Job for a Milltronics mill, CAM's Face
and Pocket Shape ops as the autoroutines G33/G34 where they cut what the op
cuts (posts/milltronics_ops.py decides), everything else as moves.

The program: a comment naming the Job, ``G21 G90 G40`` (``G20`` with
``--inches``), then per op in the Job's order:

- a tool change when the op's tool controller is not the one in force:
  ``G32`` (Z to the tool change position), ``T<n> M6``, ``S<rpm> M3`` (M4
  for SpindleDir Reverse), ``D<n> G43 H<n>`` (as the seed's example: the
  diameter register G41/G42 and the autoroutines read, and the length
  offset, both numbered as the tool); the op's CoolantMode: M8 flood, M7
  mist before the op, M9 after it;
- an autoroutine (``--native-cycles``, the default): a comment (the op, the
  G code, a note when the op's Path stops above its FinalDepth), ``G0 Z`` to
  the op's ClearanceHeight, ``G0 X Y`` to the rectangle's centre, ``F`` the
  X-Y feed (the call's F is the Z feed), the P assignment blocks, the
  ``G33``/``G34`` block (with G99: it ends at R, the op's SafeHeight), then
  ``G31``;
- any other op: ``(<op> written as moves: <reason>)`` and the op's own
  Path: G0/G1/G2/G3 with X Y Z I J K (I, J, K from the arc's start, as
  FreeCAD holds them), F in mm/min (in/min); comments dropped; any other
  command is refused naming the op. No G31 after it: its height (the last
  R, else the machine's parameter 140) is not the op's, and the op's Path
  ends at its own clearance already.

``--expand-cycles`` writes every op as its own Path (what FreeCAD shows and
simulates; the engine's expansion of an autoroutine is what
``python3 -m freecad_groove expand --dialect milltronics`` prints). A Job's
fixtures write nothing: the work offset is set on the machine. ``M5``,
``M30`` end the program. Same error contract as the other posts: PostError,
one line, no file written.
"""

from typing import Any, Iterable, List, Optional, Sequence, Union

from ...engine.numbers import MM_PER_INCH, format_decimal
from ..units import SECONDS_PER_MINUTE
from .command_post import each_part, post_class, reported, script_export
from .errors import PostError
from .milltronics_ops import DECIMALS, NativeOp, recognise
from .objects import is_fixture_block, is_job, is_tool_controller, job_of, label_of
from .options import PostParser, split_arguments

POST = "milltronics_mill"
TITLE = "Milltronics mill (Face and Pocket Shape ops as the G33/G34 autoroutines, other ops as moves)"
COOLANT_CODES = {"Flood": "M8", "Mist": "M7"}
MOTION = {"G0": "G0", "G00": "G0", "G1": "G1", "G01": "G1", "G2": "G2", "G02": "G2", "G3": "G3", "G03": "G3"}
WORDS = "XYZIJK"


def make_parser() -> PostParser:
    """The post's options."""
    parser = PostParser(prog=POST + "_post", add_help=False, description=TITLE)
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--native-cycles", dest="native", action="store_true", default=True,
                       help="Face and Pocket Shape ops the autoroutines can cut as G33/G34 (the default)")
    group.add_argument("--expand-cycles", dest="native", action="store_false",
                       help="every op as its own Path's moves")
    parser.add_argument("--inches", action="store_true", help="G20, lengths in inches, feeds in in/min "
                        "(default: G21, mm, mm/min)")
    parser.add_argument("--help", action="store_true", help="show these options, write no program")
    return parser


def _operations(objects: Iterable[Any]) -> List[Any]:
    """The ops to write, in order: a Job's active ops, or the active ops given (tool controllers and
    fixtures dropped: each op's own tool controller decides the tool changes)."""
    ops = []
    for obj in objects:
        if is_job(obj):
            ops += _operations(obj.Operations.Group)
        elif is_tool_controller(obj) or is_fixture_block(obj) or not getattr(obj, "Active", True):
            continue
        elif hasattr(obj, "Path"):
            ops.append(obj)
    return ops


class _Output:
    """The lines written so far, the tool in force and the number format."""

    def __init__(self, inches: bool) -> None:
        self.inches = inches
        self.digits = DECIMALS[inches]
        self.lines: List[str] = []
        self.tool: Optional[Any] = None
        self.feed: Optional[str] = None

    def number(self, mm: float) -> str:
        return format_decimal(mm / MM_PER_INCH if self.inches else mm, self.digits)

    def tool_change(self, op: Any) -> None:
        controller = getattr(op, "ToolController", None)
        if controller is None or controller is self.tool:
            return
        self.tool = controller
        spin = "M4" if str(getattr(controller, "SpindleDir", "Forward")) == "Reverse" else "M3"
        number = int(controller.ToolNumber)
        # the seed's D1 G43 H1: the autoroutines' G41/G42 read the diameter register, every Z the length offset
        self.lines += ["G32", "T%d M6" % number, "S%s %s" % (format_decimal(float(controller.SpindleSpeed), 3, False),
                                                             spin), "D%d G43 H%d" % (number, number)]
        self.feed = None

    def path(self, op: Any) -> None:
        """The op's own G0-G3 moves; PostError naming any other command."""
        for index, command in enumerate(op.Path.Commands):
            name = command.Name
            if not name or name.startswith("("):
                continue
            if name not in MOTION:
                raise PostError("%s (command %d) cannot be written by %s_post: G0 to G3 moves only"
                                % (name, index + 1, POST), label_of(op))
            params = command.Parameters
            words = [MOTION[name]] + [axis + self.number(params[axis]) for axis in WORDS if axis in params]
            if name not in ("G0", "G00") and "F" in params:
                feed = self.number(params["F"] * SECONDS_PER_MINUTE)
                if feed != self.feed:
                    words.append("F" + feed)
                    self.feed = feed
            if len(words) > 1:
                self.lines.append(" ".join(words))

    def native(self, item: NativeOp) -> None:
        digits = self.digits
        title = item.call.NAME + ("; " + item.note if item.note else "")
        self.lines += ["(%s: %s)" % (_comment_text(item.label), title), "G0 Z" + format_decimal(item.clearance, digits),
                       "G0 X%s Y%s" % (format_decimal(item.x, digits), format_decimal(item.y, digits)),
                       "F" + format_decimal(item.xy_feed, digits)]
        self.lines += item.call.emit().split("\n") + ["G31"]
        self.feed = None  # the call's F is the Z feed: the next feed move writes its own


def _comment_text(text: str) -> str:
    return text.replace("(", "[").replace(")", "]")


def milltronics_program(objects: Iterable[Any], native: bool, inches: bool) -> str:
    """The program for ``objects`` (see the module notes); PostError on what cannot be written."""
    objects = list(objects or [])
    job = job_of(objects)
    out = _Output(inches)
    out.lines += ["(%s: %s_post of freecad-groove)" % (_comment_text(label_of(job) if job else "FreeCAD"), POST),
                  "%s G90 G40" % ("G20" if inches else "G21")]
    for op in _operations(objects):
        out.tool_change(op)
        coolant = COOLANT_CODES.get(str(getattr(op, "CoolantMode", "None") or "None"))
        if coolant:
            out.lines.append(coolant)
        item = recognise(op, inches) if native else "--expand-cycles"
        if isinstance(item, NativeOp):
            out.native(item)
        else:
            out.lines.append("(%s written as moves: %s)" % (_comment_text(label_of(op)), _comment_text(item)))
            out.path(op)
        if coolant:
            out.lines.append("M9")
    out.lines += ["M5", "M30"]
    return "\n".join(out.lines) + "\n"


def _program(objects: Iterable[Any], argstring: Union[None, str, Sequence[str]]) -> Optional[str]:
    """The program, or None for --help (the options go to the report view)."""
    import FreeCAD

    parser = make_parser()
    options = parser.parse_args(split_arguments(POST, argstring))
    if options.help:
        FreeCAD.Console.PrintMessage("%s_post --help: no program written; the options:\n%s\n"
                                     % (POST, parser.format_help().rstrip("\n")))
        return None
    return milltronics_program(objects, options.native, options.inches)


def export(objectslist: Optional[Iterable[Any]], filename: Optional[str],
           argstring: Union[None, str, Sequence[str]]) -> Optional[str]:
    """A script post's export(): the program, written to ``filename`` unless "-"; PostError on any problem."""
    return script_export(POST + "_post", lambda: _program(objectslist or [], argstring), filename)


def command_post_class() -> type:
    """The class FreeCAD's PostProcessorFactory takes from the post's module (see command_post.py):
    its export() reports a failed post in one line and returns None."""
    def sections(processor: Any, argstring: str) -> Optional[list]:
        return reported(POST + "_post", lambda: each_part(processor, lambda objects: _program(objects, argstring)))

    return post_class(POST.title(), TITLE, make_parser().format_help(), sections)
