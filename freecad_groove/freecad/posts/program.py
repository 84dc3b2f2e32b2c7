"""One program's text: its frame (header, setup, end), tool changes, spindle,
coolant, and every object of the post's list handed to the writer it needs
(a Groove op to :class:`~.grooves.GrooveOutput`, any other Path to
:class:`~.path_commands.PathCommands`)."""

from typing import Any, Callable, NamedTuple, Optional

from ... import __version__
from ...engine import CycleError, ProgramError
from ...engine.numbers import MM_PER_INCH
from ...engine.output.program import ProgramBuilder, Spindle
from ...engine.output.writer import Writer
from .grooves import GrooveOutput, groove_cutting
from .lathe_posts import LathePost
from .objects import (
    groove_op_of,
    is_fixture_block,
    is_job,
    is_tool_controller,
    label_of,
    op_property,
    own_groove_op,
)
from .options import Options
from .path_commands import PathCommands
from .post_error import PostError, cycle_post_error
from .slots import SlotOutput, is_slot_op

MAX_RPM = 99999
FT_MIN_PER_M_MIN = 1000.0 / 304.8  # surface speed in inch programs: ft/min
COOLANT_CODES = {"Flood": 8, "Mist": 7}  # CoolantMode -> M code; M9 after the op
COOLANT_OFF = 9


class ToolState(NamedTuple):
    """The tool controller in force: tool number, spindle speed (rpm), SpindleDir."""

    number: int
    speed: float
    direction: str


class Program(ProgramBuilder):
    """Builds one program's text in ``lines`` from a Job's objects: the engine's
    program builder (output/program.py) with the lathe post's target and options.

    ``tool_state``: the ToolState in force (None: none yet, or an M6 of a Path
    changed it); ``pending_spindle``: the tool controller of the list whose
    spindle waits for the op that uses it (a Cylinder slot never starts the
    main spindle: its speed is the live tool's); ``missing_switches``: the
    options of live_tool.py the program needed and did not get."""

    def __init__(self, post: LathePost, options: Options) -> None:
        writer = Writer(post.program_target(options), not options.inches, False, digits=options.precision,
                        x_diameter=options.diameter, scale=1.0 / MM_PER_INCH if options.inches else 1.0)
        super().__init__(writer, comments=options.comments)
        self.post = post
        self.options = options
        self.tool_state: Optional[ToolState] = None
        self.pending_spindle: Any = None
        self.missing_switches: list = []

    # -- program frame
    def start(self, title: str) -> None:
        """The header and the target's setup lines."""
        options = self.options
        unit = "in" if options.inches else "mm"
        notes = ["post %s by freecad-groove %s; lengths %s, feeds %s/min or %s/rev"
                 % (self.post.freecad_name, __version__, unit, unit, unit)] if options.header else []
        self.begin(title if options.header else None, options.program_number, notes)

    # -- tools, spindle
    def tool_controller(self, tc: Any, spindle: bool = True) -> None:
        """A tool controller: the tool change and (``spindle``) spindle it asks for, if not in force."""
        if tc is None:
            return
        state = ToolState(int(tc.ToolNumber), float(tc.SpindleSpeed), str(getattr(tc, "SpindleDir", "Forward")))
        if state == self.tool_state:
            return
        if state.number < 0 or state.number > self.target.max_tool:
            raise PostError("ToolNumber %d cannot be written as a tool number of this control" % state.number,
                            op=label_of(tc))
        if self.tool_state is None or self.tool_state.number != state.number:
            self.change_tool(state.number, "tool %d: %s" % (state.number, label_of(tc)), state.number)
        self.tool_state = state
        if spindle:
            self.tool_spindle(tc)

    def tool_spindle(self, tc: Any) -> None:
        """The spindle the tool controller asks for, if not in force (a stop when it gives none)."""
        state = self.tool_state
        if state is not None and state.speed > 0 and state.direction in ("Forward", "Reverse"):
            rpm = int(round(state.speed))
            if rpm < 1 or rpm > MAX_RPM:
                raise PostError("SpindleSpeed %g cannot be written" % state.speed, op=label_of(tc))
            self.start_spindle(Spindle(rpm, state.direction == "Forward"))
        elif self.spindle_on:
            self.stop_spindle()

    def groove_spindle(self, cutting: Any, label: str) -> None:
        """The spindle a Groove op's CuttingData asks for (cutting.py), if not in force."""
        if cutting.direction not in ("Forward", "Reverse"):
            raise PostError("is %s: a groove is cut with the spindle turning (Forward or Reverse)"
                            % cutting.direction, op=label, parameter="ToolController SpindleDir")
        clockwise = cutting.direction == "Forward"
        if cutting.surface_speed is not None:
            speed = cutting.surface_speed * (FT_MIN_PER_M_MIN if self.options.inches else 1.0)
            self.start_spindle(Spindle(max(1, int(round(speed))), clockwise, int(round(cutting.max_rpm))))
        else:
            self.start_spindle(Spindle(max(1, int(round(cutting.rpm))), clockwise))

    # -- objects
    def item(self, obj: Any) -> None:
        """One object of the post's list: a Job, a tool controller or an op (see the package notes)."""
        if own_groove_op(obj):  # what the probes below find of a Groove op, known at once
            if getattr(obj, "Active", True):
                self._op_item(obj, label_of(obj), obj, False, getattr)
            return
        if is_job(obj):
            for op in obj.Operations.Group:
                self.item(op)
            return
        if is_tool_controller(obj):  # the tool change now, its spindle with the op that uses it
            self.tool_controller(obj, spindle=False)
            self.pending_spindle = obj
            return
        if not op_property(obj, "Active", True):
            return
        label = label_of(obj)
        if not hasattr(obj, "Path"):
            raise PostError("is not a Path object (pick operations, tool controllers or a Job)", op=label)
        self._op_item(obj, label, groove_op_of(obj), is_slot_op(obj), op_property)

    def _op_item(self, obj: Any, label: str, groove: Any, slot: bool, read: Callable[..., Any]) -> None:
        """An op of the post's list: its tool, spindle, comments and coolant around its moves; ``groove``: the
        Groove op it is or wraps (None: none), ``slot``: a Cylinder slot, ``read``: how to read a property
        of the op (op_property, or getattr for an op that is no dressup)."""
        # a Cylinder slot's speed is the live tool's (live_tool.py), not the main spindle's
        if self.pending_spindle is not None and not is_fixture_block(obj):
            if not slot:
                self.tool_spindle(self.pending_spindle)
            self.pending_spindle = None
        self.tool_controller(read(obj, "ToolController", None), spindle=not slot)
        if not is_fixture_block(obj):
            self.note(label)
            extra = read(obj, "Comment", "")
            if extra:
                self.note(str(extra))
        coolant = COOLANT_CODES.get(str(read(obj, "CoolantMode", "None") or "None"))
        if coolant is not None:
            self.m_code(coolant)
        self._op(obj, label, groove, slot)
        if coolant is not None:
            self.m_code(COOLANT_OFF)

    def _op(self, obj: Any, label: str, groove: Any, slot: bool) -> None:
        """An op's moves: its grooves (``groove``: the Groove op it is, or a dressup wraps, written with native
        cycles) or its Path; any error becomes a PostError naming the op."""
        try:
            if groove is not None:
                self.groove_spindle(groove_cutting(groove), label)
            elif self.tool_state is not None and op_property(obj, "ToolController") is not None and not slot:
                self.tool_spindle(op_property(obj, "ToolController"))  # after a groove's own spindle
            if groove is not None and (obj is groove or self.options.native):
                if obj is not groove:
                    self.note("%s: native cycles from %s; the dressup's changes are not in them"
                              % (label, label_of(groove)))
                GrooveOutput(self, groove).write()
            elif slot:
                SlotOutput(self, obj).write()
            else:
                PathCommands(self, label).write(obj.Path.Commands)
        except PostError:
            raise
        except CycleError as exc:
            raise cycle_post_error(label_of(groove) if groove is not None else label, exc) from None
        except (ProgramError, ValueError, ArithmeticError) as exc:
            raise PostError(str(exc), op=label) from None
        except Exception as exc:  # a bug or a broken document: still one line naming the op, never a traceback
            raise PostError("%s: %s" % (type(exc).__name__, exc), op=label) from None
