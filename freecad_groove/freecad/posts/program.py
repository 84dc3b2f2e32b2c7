"""One program's text: its frame (header, setup, end), tool changes, spindle,
coolant, and every object of the post's list handed to the writer it needs
(a Groove op to :class:`~.grooves.GrooveOutput`, any other Path to
:class:`~.path_commands.PathCommands`)."""

from typing import Any, Iterable, List, NamedTuple, Optional, Tuple

from ... import __version__
from ...engine import RAPID, CycleError, ProgramError
from .controls import Control
from .errors import PostError, cycle_post_error
from .grooves import GrooveOutput, groove_cutting
from .objects import groove_op_of, is_fixture_block, is_job, is_tool_controller, label_of, op_property
from .options import Options
from .path_commands import PathCommands
from .slots import SlotOutput, is_slot_op
from .writer import LatheWriter

MAX_RPM = 99999
FT_MIN_PER_M_MIN = 1000.0 / 304.8  # surface speed in inch programs: ft/min
COOLANT_CODES = {"Flood": 8, "Mist": 7}  # CoolantMode -> M code; M9 after the op
COOLANT_OFF = 9


class ToolState(NamedTuple):
    """The tool controller in force: tool number, spindle speed (rpm), SpindleDir."""

    number: int
    speed: float
    direction: str


class Program:
    """Builds one program's text in ``lines``.

    ``tool``: the ToolState in force (None: none yet, or an M6 of a Path
    changed it); ``spindle_on``: the program started the spindle; ``spindle``:
    the spindle command in force as written (("rpm", S, M) or ("css", S, limit,
    M); None: off or unknown); ``per_rev``: feed per revolution in force (the
    setup lines select feed per minute); ``x``, ``z``: the tool's model radius
    and z when known (None after a tool change, a work offset)."""

    def __init__(self, control: Control, options: Options) -> None:
        self.control = control
        self.options = options
        self.writer = LatheWriter(control, options.precision, options.diameter, options.inches)
        self.lines: List[str] = []
        self.tool: Optional[ToolState] = None
        self.spindle_on = False
        self.spindle: Optional[Tuple[Any, ...]] = None
        self.per_rev = False
        self.x: Optional[float] = None
        self.z: Optional[float] = None
        self.missing_switches: List[str] = []  # options of live_tool.py the program needed and did not get

    # -- output helpers
    def add(self, lines: Iterable[str]) -> None:
        self.lines.extend(lines)

    def note(self, text: str) -> None:
        """A comment, unless --no-comments."""
        if self.options.comments:
            self.lines.append(self.control.comment(text))

    def m_code(self, number: int) -> None:
        self.lines.append(self.control.m_code(number))

    def moved(self, x: Optional[float] = None, z: Optional[float] = None) -> None:
        """The tool is now at radius ``x`` / ``z`` (None: that axis did not move)."""
        if x is not None:
            self.x = x
        if z is not None:
            self.z = z

    def rapid(self, x: Optional[float] = None, z: Optional[float] = None, force: bool = False) -> None:
        self.add(self.writer.move(RAPID, x, z, force=force))
        self.moved(x, z)

    def unknown_position(self) -> None:
        self.x = self.z = None
        self.writer.forget(position=True, motion=True, feed=False)

    def change_tool(self, number: int, note: str) -> None:
        """The tool change to tool ``number`` with a comment ``note``."""
        self.note(note)
        self.add(self.control.tool_change(number))
        self.unknown_position()
        if self.control.m6_stops_spindle:
            self.spindle_on = False
            self.spindle = None

    def set_feed_mode(self, per_rev: bool) -> None:
        """Feed per revolution or per minute from here on (the code only when it changes; F is written again)."""
        if per_rev != self.per_rev:
            self.add([self.control.feed_mode(per_rev)])
            self.writer.forget(position=False, motion=False, feed=True)
            self.per_rev = per_rev

    def start_spindle(self, spindle: Tuple[Any, ...]) -> None:
        """The spindle command ``spindle`` (see the class notes), unless it is in force."""
        if spindle == self.spindle:
            return
        if spindle[0] == "css":
            self.add(self.control.surface_speed(spindle[1], spindle[2], spindle[3]))
        else:
            self.add(self.control.spindle(spindle[1], spindle[2]))
        self.spindle = spindle
        self.spindle_on = True

    def stop_spindle(self) -> None:
        self.m_code(5)
        self.spindle_on = False
        self.spindle = None

    # -- program frame
    def begin(self, title: str) -> None:
        """The header and the control's setup lines."""
        control, options = self.control, self.options
        if control.o_number_frame:
            self.lines.append("%")
            if options.program_number is not None:
                name = " " + control.comment(title) if (options.header and options.comments and title) else ""
                self.lines.append("O%04d%s" % (options.program_number, name))
        elif options.header and title:
            self.note(title)
        if options.header:
            unit = "in" if options.inches else "mm"
            self.note("post %s by freecad-groove %s; lengths %s, feeds %s/min or %s/rev"
                      % (control.post, __version__, unit, unit, unit))
        self.add(control.setup(options))

    def finish(self) -> None:
        """The spindle stop and the program end."""
        if self.spindle_on:
            self.stop_spindle()
        self.add(self.control.end(self.options))

    # -- tools, spindle
    def tool_controller(self, tc: Any, spindle: bool = True) -> None:
        """A tool controller: the tool change and (``spindle``) spindle it asks for, if not in force."""
        if tc is None:
            return
        state = ToolState(int(tc.ToolNumber), float(tc.SpindleSpeed), str(getattr(tc, "SpindleDir", "Forward")))
        if state == self.tool:
            return
        if state.number < 0 or state.number > self.control.max_tool_number:
            raise PostError("ToolNumber %d cannot be written as a tool number of this control" % state.number,
                            op=label_of(tc))
        if self.tool is None or self.tool.number != state.number:
            self.change_tool(state.number, "tool %d: %s" % (state.number, label_of(tc)))
        self.tool = state
        if spindle:
            self.tool_spindle(tc)

    def tool_spindle(self, tc: Any) -> None:
        """The spindle the tool controller asks for, if not in force (a stop when it gives none)."""
        state = self.tool
        if state is not None and state.speed > 0 and state.direction in ("Forward", "Reverse"):
            rpm = int(round(state.speed))
            if rpm < 1 or rpm > MAX_RPM:
                raise PostError("SpindleSpeed %g cannot be written" % state.speed, op=label_of(tc))
            self.start_spindle(("rpm", rpm, self.control.m_code(3 if state.direction == "Forward" else 4)))
        elif self.spindle_on:
            self.stop_spindle()

    def groove_spindle(self, cutting: Any, label: str) -> None:
        """The spindle a Groove op's CuttingData asks for (cutting.py), if not in force."""
        if cutting.direction not in ("Forward", "Reverse"):
            raise PostError("is %s: a groove is cut with the spindle turning (Forward or Reverse)"
                            % cutting.direction, op=label, parameter="ToolController SpindleDir")
        m_code = self.control.m_code(3 if cutting.direction == "Forward" else 4)
        if cutting.surface_speed is not None:
            speed = cutting.surface_speed * (FT_MIN_PER_M_MIN if self.options.inches else 1.0)
            self.start_spindle(("css", max(1, int(round(speed))), int(round(cutting.max_rpm)), m_code))
        else:
            self.start_spindle(("rpm", max(1, int(round(cutting.rpm))), m_code))

    # -- objects
    def item(self, obj: Any) -> None:
        """One object of the post's list: a Job, a tool controller or an op (see the package notes)."""
        if is_job(obj):
            for op in obj.Operations.Group:
                self.item(op)
            return
        if is_tool_controller(obj):
            self.tool_controller(obj)
            return
        if not op_property(obj, "Active", True):
            return
        label = label_of(obj)
        if not hasattr(obj, "Path"):
            raise PostError("is not a Path object (pick operations, tool controllers or a Job)", op=label)
        # a Cylinder slot's speed is the live tool's (live_tool.py), not the main spindle's
        self.tool_controller(op_property(obj, "ToolController"), spindle=not is_slot_op(obj))
        if not is_fixture_block(obj):
            self.note(label)
            extra = op_property(obj, "Comment", "")
            if extra:
                self.note(str(extra))
        coolant = COOLANT_CODES.get(str(op_property(obj, "CoolantMode", "None") or "None"))
        if coolant is not None:
            self.m_code(coolant)
        self._op(obj, label)
        if coolant is not None:
            self.m_code(COOLANT_OFF)

    def _op(self, obj: Any, label: str) -> None:
        """An op's moves: its grooves (a Groove op, or a dressup of one with native
        cycles) or its Path; any error becomes a PostError naming the op."""
        groove = groove_op_of(obj)
        try:
            if groove is not None:
                self.groove_spindle(groove_cutting(groove), label)
            elif self.tool is not None and op_property(obj, "ToolController") is not None and not is_slot_op(obj):
                self.tool_spindle(op_property(obj, "ToolController"))  # after a groove's own spindle
            if groove is not None and (obj is groove or self.options.native):
                if obj is not groove:
                    self.note("%s: native cycles from %s; the dressup's changes are not in them"
                              % (label, label_of(groove)))
                GrooveOutput(self, groove).write()
            elif is_slot_op(obj):
                SlotOutput(self, obj).write()
            else:
                PathCommands(self, label).write(obj.Path.Commands)
        except PostError:
            raise
        except CycleError as exc:
            raise cycle_post_error(label_of(groove) if groove is not None else label, exc) from None
        except (ProgramError, ValueError, ArithmeticError) as exc:
            raise PostError(str(exc), op=label) from None
