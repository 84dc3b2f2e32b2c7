"""The ``milltronics_mill`` post: a CAM Job for a Milltronics mill, CAM's Face
and Pocket Shape ops as the autoroutines G33/G34 where they cut what the op
cuts (posts/milltronics_ops.py decides), everything else as moves.

The program: a comment naming the Job, ``G21 G90 G40`` (``G20`` with
``--inches``), then per op in the Job's order:

- a tool change when the op's tool controller is not the one in force:
  ``G32`` (Z to the tool change position), ``T<n> M6``, ``S<rpm> M3`` (M4
  for SpindleDir Reverse), ``D<n> G43 H<n>`` (as the Milltronics manual's example: the
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

from ...engine.errors import ProgramError
from ...engine.mill_program import MillMoves, MillNative, MillToolChange, milltronics_program
from ...engine.moves import ARC_CCW, ARC_CW, FEED, RAPID, Move
from ..units import SECONDS_PER_MINUTE
from .command_post import each_part, post_class, reported, script_export
from .milltronics_ops import NativeOp, recognise
from .objects import is_fixture_block, is_job, is_tool_controller, job_of, label_of
from .options import PostParser, split_arguments
from .post_error import PostError

POST = "milltronics_mill"
TITLE = "Milltronics mill (Face and Pocket Shape ops as the G33/G34 autoroutines, other ops as moves)"
COOLANT_CODES = {"Flood": 8, "Mist": 7}
MOTION = {"G0": RAPID, "G00": RAPID, "G1": FEED, "G01": FEED, "G2": ARC_CW, "G02": ARC_CW, "G3": ARC_CCW,
          "G03": ARC_CCW}


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


def path_moves(op: Any) -> List[Move]:
    """The op's own G0-G3 moves (mm, feeds per minute; an axis a command does not name is None; an arc's
    centre from the position before it); PostError naming any other command."""
    moves: List[Move] = []
    where = {"X": None, "Y": None}
    for index, command in enumerate(op.Path.Commands):
        name = command.Name
        if not name or name.startswith("("):
            continue
        if name not in MOTION:
            raise PostError("%s (command %d) cannot be written by %s_post: G0 to G3 moves only"
                            % (name, index + 1, POST), label_of(op))
        params, kind = command.Parameters, MOTION[name]
        centre = None
        if kind in (ARC_CW, ARC_CCW):
            if where["X"] is None or where["Y"] is None:
                raise PostError("%s (command %d): an arc from an unknown X-Y position" % (name, index + 1),
                                label_of(op))
            centre = (where["X"] + params.get("I", 0.0), where["Y"] + params.get("J", 0.0))
        f = params["F"] * SECONDS_PER_MINUTE if kind != RAPID and "F" in params else None
        moves.append(Move(kind, params.get("X"), params.get("Z"), f, y=params.get("Y"), centre=centre))
        where.update({axis: params[axis] for axis in "XY" if axis in params})
    return moves


def _items(objects: Iterable[Any], native: bool, inches: bool) -> list:
    """The program's items for ``objects`` (engine/mill_program.py)."""
    items: list = []
    tool = None
    for op in _operations(objects):
        controller = getattr(op, "ToolController", None)
        if controller is not None and controller is not tool:
            tool = controller
            items.append(MillToolChange(label_of(controller), int(controller.ToolNumber),
                                        float(controller.SpindleSpeed),
                                        str(getattr(controller, "SpindleDir", "Forward")) != "Reverse"))
        coolant = COOLANT_CODES.get(str(getattr(op, "CoolantMode", "None") or "None"))
        found = recognise(op, inches) if native else "--expand-cycles"
        if isinstance(found, NativeOp):
            items.append(MillNative(_bracketed(found.label), found.call, found.note, found.x, found.y,
                                    found.clearance, found.xy_feed, coolant))
        else:
            items.append(MillMoves(_bracketed(label_of(op)), _bracketed(found), path_moves(op), coolant))
    return items


def _bracketed(text: str) -> str:
    """A text for a comment, its parentheses as brackets (a comment cannot hold parentheses)."""
    return text.replace("(", "[").replace(")", "]")


def milltronics_program_of(objects: Iterable[Any], native: bool, inches: bool) -> str:
    """The program for ``objects`` (see the module notes); PostError on what cannot be written."""
    objects = list(objects or [])
    job = job_of(objects)
    title = "%s: %s_post of freecad-groove" % (_bracketed(label_of(job)) if job else "FreeCAD", POST)
    try:
        return milltronics_program(_items(objects, native, inches), inches, title)
    except PostError:
        raise
    except (ProgramError, ValueError) as exc:
        raise PostError(str(exc)) from None


def _program(objects: Iterable[Any], argstring: Union[None, str, Sequence[str]]) -> Optional[str]:
    """The program, or None for --help (the options go to the report view)."""
    import FreeCAD

    parser = make_parser()
    options = parser.parse_args(split_arguments(POST, argstring))
    if options.help:
        FreeCAD.Console.PrintMessage("%s_post --help: no program written; the options:\n%s\n"
                                     % (POST, parser.format_help().rstrip("\n")))
        return None
    return milltronics_program_of(objects, options.native, options.inches)


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
