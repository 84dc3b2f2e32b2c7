"""The grinder posts: ``ab9_grind`` (Allen-Bradley 9/Series grinder: Plunge
grind ops as native G83/G83.1 blocks, or expanded) and ``linuxcnc_grind``
(the cycles expanded, dress calls ``o<dressN> call``). The program itself is
written by the engine (engine/grind_program.py); here the objects become its
items.

Axes: ``--axes`` (default XZY) names the FreeCAD axes of the grinder's X
(reciprocation), Y (plunge) and Z (crossover) words: every other op's Path is
written through it; a Plunge grind op grinds along its own (its
ReciprocationAxis: XZY or YZX) and is refused when they differ.

What a post writes for the objects: a Job: its operations in order; a tool
controller, and the tool controller of each op: the wheel (engine
grind_program.WheelChange: the tool change when its ToolNumber differs from
the one in force, then its SpindleSpeed with M3 for SpindleDir Forward, M4
for Reverse, M5 for 0 or None); a Plunge grind op is refused unless its tool
controller turns the wheel (SpindleSpeed above 0, SpindleDir Forward or
Reverse); a fixture block: nothing (the work offset is the machine's); an
inactive op: nothing; a Plunge grind op: its
plan (op.Proxy.current_plan; an op that cannot grind is refused with its
message); any other object with a Path: its G0/G1 moves as they are (feeds
in mm/min), comments dropped, any other command refused naming the op. An
op's CoolantMode: M8 (flood) or M7 (mist) before it, M9 after it.
"""

import argparse
import shlex
from typing import Any, Iterable, List, Optional, Sequence, Union

from ...engine.errors import ProgramError
from ...engine.grind_program import GrindItem, PlainMoves, WheelChange, grind_program
from ...engine.moves import FEED, RAPID, Move
from ...ops.grind.op import ObjectPlungeGrind, op_error
from ..units import SECONDS_PER_MINUTE
from .command_post import each_part, post_class, reported, script_export
from .objects import is_fixture_block, is_job, is_tool_controller, job_of, label_of
from .post_error import PostError

AXES = ("XZY", "YZX", "XYZ", "YXZ", "ZXY", "ZYX")
DEFAULT_AXES = "XZY"
COOLANT_CODES = {"Flood": 8, "Mist": 7}  # CoolantMode -> M code; M9 after the op
# post name -> (engine target, native G83 by default, title)
GRIND_POSTS = {
    "ab9_grind": ("ab9grind", True, "Allen-Bradley 9/Series grinder (G83/G83.1 plunge grinding)"),
    "linuxcnc_grind": ("linuxcnc", False, "LinuxCNC grinder (G83 plunge grinds expanded, dress o<dressN> call)"),
}


def make_grind_parser(name: str) -> argparse.ArgumentParser:
    """The options of grinder post ``name``."""
    target, native, title = GRIND_POSTS[name]
    parser = argparse.ArgumentParser(prog=name + "_post", add_help=False, description=title)
    if native:
        group = parser.add_mutually_exclusive_group()
        group.add_argument("--native-cycles", dest="native", action="store_true", default=True,
                           help="Plunge grind ops as G83/G83.1 blocks (the default)")
        group.add_argument("--expand-cycles", dest="native", action="store_false",
                           help="Plunge grind ops as their G1 moves (a dress cannot be written expanded)")
    parser.add_argument("--axes", choices=AXES, default=DEFAULT_AXES,
                        help="the FreeCAD axes of the grinder's X (reciprocation), Y (plunge), Z (crossover) words "
                             "(default %s); a Plunge grind op's ReciprocationAxis must agree" % DEFAULT_AXES)
    parser.add_argument("--program-number", type=int, default=1, help="the O number (default 1)")
    parser.add_argument("--help", action="store_true", help="show these options, write no program")
    return parser


def _moves_of_path(obj: Any, axes: str) -> List[Move]:
    """The G0/G1 moves of ``obj``'s Path in grinder axes; PostError naming any other command."""
    where = {"X": None, "Y": None, "Z": None}
    moves = []
    for index, command in enumerate(obj.Path.Commands):
        name = command.Name
        if name.startswith("(") or not name:
            continue
        if name not in ("G0", "G00", "G1", "G01"):
            raise PostError("%s (command %d) cannot be written by a grinder post: G0/G1 moves only"
                            % (name, index + 1), label_of(obj))
        params = command.Parameters
        where.update({axis: params[axis] for axis in "XYZ" if axis in params})
        unknown = [axis for axis, value in where.items() if value is None]
        if unknown:
            raise PostError("%s (command %d): the position of %s is not known" % (name, index + 1,
                                                                                  "/".join(unknown)), label_of(obj))
        rapid = name in ("G0", "G00")
        feed = None if rapid or "F" not in params else params["F"] * SECONDS_PER_MINUTE
        moves.append(Move(RAPID if rapid else FEED, where[axes[0]], where[axes[2]], feed, 0.0, where[axes[1]]))
    return moves


def _coolant(obj: Any) -> Optional[int]:
    """The M code of the op's CoolantMode (8 flood, 7 mist), None for none."""
    return COOLANT_CODES.get(str(getattr(obj, "CoolantMode", "None") or "None"))


def _wheel(tc: Any) -> WheelChange:
    """The wheel of tool controller ``tc``."""
    direction = str(getattr(tc, "SpindleDir", "Forward"))
    rpm = float(tc.SpindleSpeed) if direction in ("Forward", "Reverse") else 0.0
    return WheelChange(label_of(tc), int(tc.ToolNumber), rpm, direction != "Reverse")


def _grinding_wheel(obj: Any) -> WheelChange:
    """The wheel of a Plunge grind op's tool controller; PostError unless it turns."""
    tc = getattr(obj, "ToolController", None)
    if tc is None:
        raise PostError("no tool controller: the post starts the wheel from it (ToolNumber, SpindleSpeed, "
                        "SpindleDir)", label_of(obj))
    wheel = _wheel(tc)
    if not wheel.rpm > 0:
        raise PostError("the wheel does not turn: %s has SpindleSpeed %g, SpindleDir %s (set a speed above 0, "
                        "Forward or Reverse)" % (label_of(tc), float(tc.SpindleSpeed),
                                                 getattr(tc, "SpindleDir", "Forward")), label_of(obj))
    return wheel


def _items(objects: Iterable[Any], axes: str) -> list:
    items = []
    for obj in objects:
        if is_job(obj):
            items += _items(obj.Operations.Group, axes)
        elif is_tool_controller(obj):
            items.append(_wheel(obj))
        elif is_fixture_block(obj) or not getattr(obj, "Active", True):
            continue
        elif isinstance(getattr(obj, "Proxy", None), ObjectPlungeGrind):
            error = op_error(obj)
            if error:
                raise PostError(error, label_of(obj))
            items.append(_grinding_wheel(obj))
            try:
                plan = obj.Proxy.current_plan(obj)
            except ValueError as e:
                raise PostError(str(e), label_of(obj)) from None
            except Exception as e:  # a bug or a broken document: one line naming the op, never a traceback
                raise PostError("%s: %s" % (type(e).__name__, e), label_of(obj)) from None
            if plan.axes != axes:
                raise PostError("ReciprocationAxis=%s grinds with the grinder's X, Y, Z along FreeCAD %s, the post's "
                                "--axes is %s: give --axes %s or change ReciprocationAxis"
                                % (obj.ReciprocationAxis, plan.axes, axes, plan.axes), label_of(obj))
            items.append(GrindItem("%s: %s" % (label_of(obj), plan.face_name), plan.call, plan.start, plan.safe_z,
                                   plan.moves, _coolant(obj)))
        elif hasattr(obj, "Path"):
            if getattr(obj, "ToolController", None) is not None:
                items.append(_wheel(obj.ToolController))
            items.append(PlainMoves(label_of(obj), _moves_of_path(obj, axes), _coolant(obj)))
    return items


def _program(name: str, objects: Iterable[Any], argstring: Union[None, str, Sequence[str]]) -> Optional[str]:
    """The program of post ``name`` for ``objects``, None for --help (the options go to the report view)."""
    import FreeCAD

    parser = make_grind_parser(name)
    args = shlex.split(argstring) if isinstance(argstring, str) else list(argstring or [])
    options, unknown = parser.parse_known_args(args)
    if unknown:
        raise PostError("unrecognized arguments: %s" % " ".join(unknown))
    if options.help:
        FreeCAD.Console.PrintMessage("%s_post --help: no program written; the options:\n%s\n"
                                     % (name, parser.format_help().rstrip("\n")))
        return None
    objects = list(objects or [])
    job = job_of(objects)
    target, native, _title = GRIND_POSTS[name]
    try:
        return grind_program(_items(objects, options.axes), target, getattr(options, "native", native),
                             label_of(job) if job is not None else "FreeCAD", options.program_number)
    except ProgramError as e:
        raise PostError(str(e)) from None


def grind_export(name: str, objectslist: Optional[Iterable[Any]], filename: Optional[str],
                 argstring: Union[None, str, Sequence[str]]) -> Optional[str]:
    """A script post's export() for grinder post ``name`` (see the module notes); PostError on any problem."""
    return script_export(name + "_post", lambda: _program(name, objectslist or [], argstring), filename)


def grind_command_post_class(name: str) -> type:
    """The class FreeCAD's PostProcessorFactory takes from grinder post ``name``'s module (command_post.py):
    its export() reports a failed post in one line and returns None."""
    def sections(processor: Any, argstring: str) -> Optional[list]:
        return reported(name + "_post", lambda: each_part(processor, lambda objects: _program(name, objects,
                                                                                              argstring)))

    return post_class(name.title(), GRIND_POSTS[name][2], make_grind_parser(name).format_help(), sections)
