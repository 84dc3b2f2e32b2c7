"""Lathe post-processors for FreeCAD CAM: the logic every freecad-groove post shares.

Headless FreeCAD layer: FreeCAD and Path only (no Qt, no FreeCADGui). The
posts in ``postprocessors/`` (``sinumerik_lathe_post.py``, ``ab9_lathe_post.py``,
``fanuc_lathe_post.py``, ``haas_lathe_post.py``, ``linuxcnc_lathe_post.py``) are
thin FreeCAD script posts: an argument parser from :func:`make_parser` and an
``export`` that calls :func:`export` here.

What a post writes
------------------
A header (program name from the Job, the post's name; ``--no-header`` drops
it), the control's lathe setup line, then for every object in ``objectslist``
in order:

* a Job: its operations (in its order);
* a tool controller (FreeCAD's Job puts them in the list before the ops that
  use them) or an op whose tool controller differs from the current one: the
  tool change in the control's syntax and the spindle from the tool
  controller (``G97 S<rpm> M3``/``M4``; none when SpindleDir is "None" or the
  speed is 0);
* an op (inactive ops are skipped): its label as a comment, the coolant of its
  CoolantMode (M8 flood, M7 mist; M9 after the op), then
  - a Groove op (or a dressup whose ``Base`` chain reaches one): every groove
    of ``op.Proxy.current_plan(op)``: the op's link rapids, then the groove as a
    native cycle call (after a rapid to the cycle's start point, since a
    native cycle starts where the tool stands) or as the engine's expanded
    moves (``--expand-cycles``, the controls without a cycle, grooves the
    control's cycle cannot cut - a comment says why);
  - any other object with a Path (a turning op, a custom Path, a dressup's
    Path, the Job's fixture blocks): its commands as plain moves: G0/G1/G2/G3
    in the XZ plane, X a radius in model coordinates (written as a diameter
    where the control is in diameter mode), arcs with incremental radius
    I/K (Siemens: ``CR=``), G4 dwell, comments, G54..G59, spindle and coolant
    M codes, M6 tool changes. Y moves, arcs outside G18, incremental G91,
    canned drilling cycles, nose radius compensation and other words are
    refused with an error naming the op and the command;
* the end: M9 when coolant was on, M5 when the spindle ran, the program end.

Feeds: FreeCAD's Path F words are mm/s; every post writes mm/min in the
control's feed-per-minute mode (G94, Fanuc/Haas G98); feed per revolution is
not modelled. Lengths are mm (G21, Siemens G71): FreeCAD models are metric.
Numbers: the dialects writer's (a decimal point always, no ``-0``), with the
control's decimals (3; LinuxCNC 4; ``--precision``). Dwell: Siemens
``G4 F<s>``, Fanuc ``G04 P<ms>``, Haas ``G04 P<s>``, LinuxCNC ``G4 P<s>``;
the Allen-Bradley 9/Series dwell word is not documented in the manuals the
engine follows (its program reader refuses G04 for "ab9" too), so a dwell
there is an error naming the op. X words are diameters (DIAMON, G07, G7)
unless ``--x-mode radius``; arc centres I/K are always per-side (radius)
offsets.

The controls
------------
========= ============================ ====================== ===================
post      setup line                   tool change            native grooving
========= ============================ ====================== ===================
sinumerik ``G18 G71 G90 G40 G94 DIAMON`` ``T<n> D1``            CYCLE93 (every groove)
ab9       ``G18 G21 G90 G40 G94 G07``  ``T<nnnn>`` (tool+offs)  G77 / G76 (plain grooves)
fanuc     ``%``, ``G21``, ``G40 G98``  ``T<nn><nn>``            G75 / G74 two-block
haas      ``%``, ``G21``, ``G40 G98``  ``T<nn><nn>``            G75 / G74 one-block
linuxcnc  ``G18 G7 G21 G90 G91.1 G40 G94`` ``T<n> M6 G43``      none: always expanded
========= ============================ ====================== ===================

The pecking cycles (G77/G76, G75/G74) plunge straight, full width of the
blade, to a flat bottom: they replace a CYCLE93 groove only when it is
*plain*: a paraxial contour (cylinder or plane), no flank angles, no edge or
base radii/chamfers, no allowances and no dwell. Then a groove exactly as
wide as the blade, repeated GrooveCount times on a face, is one call (the
pitch as the groove spacing K/Q/I, the last groove as Z/X); a wider groove is
one call per groove stepping across it by 95 % of (blade width - 2 x corner
radius), the engine's own step. The peck depth is the op's Infeed, the
peck retract e the op's Retract (0 = 1 mm) unless ``--retract`` says
otherwise (Fanuc writes it as ``G75 R(e)``; on Allen-Bradley (AMP) and Haas
(setting 22) it is a machine setting, named in a comment). The start point
of the call is the point the engine's CYCLE93 expansion plunges from (VRT
above the contour over the first plunge), reached and left by the same
rapids as the CYCLE93 approach.

Errors: anything that stops a post (an op whose grooves the engine refuses,
a move the control cannot take, a bad option) raises :class:`PostError`,
whose message starts with the op's Label and names the op property (and the
cycle parameter); the message also goes to FreeCAD's report view. A file is
written only when the whole text is built, through a temporary file in the
same folder renamed over the target, so a failed post leaves no file and an
existing one untouched.
"""

import argparse
import math
import re
import shlex
from dataclasses import replace

import FreeCAD

from .. import __version__
from ..engine import CycleError, MachineState, ProgramError
from ..engine.cycles.ab_g77 import G76, G77
from ..engine.cycles.cycle93 import WIDTH_STEP_FACTOR
from ..engine.targets import TargetSpec, Writer, comment as paren_comment
from ..engine.cycles.fanuc_g75 import FanucG74, FanucG75, HaasG74, HaasG75
from ..engine.moves import DWELL, FEED, RAPID, REFERENCE_MINUS, REFERENCE_PLUS, Move
from ..engine.numbers import ARC_IJK_TOLERANCE, MAX_DWELL_SECONDS
from ..engine.output import write_atomically
from .groove_properties import describe_cycle93_parameter
from .units import feed_mm_per_min

__all__ = ["CONTROLS", "PostError", "export", "make_parser", "tooltip", "groove_op_of"]

MAX_PRECISION = 6
NATIVE_DECIMALS = 4  # the pecking cycles' words hold at most 4 decimals (ab_g77.DECIMALS)
FANUC_INCREMENT = 0.001  # Fanuc P/Q least input increment, mm
TOL = 1e-9


class PostError(ValueError):
    """A post cannot write the program. ``op``: the Label of the object at
    fault (None for option errors); ``parameter``: the op property (and cycle
    parameter) at fault, when known."""

    def __init__(self, message, op=None, parameter=None):
        self.op = op
        self.parameter = parameter
        text = message
        if parameter:
            text = "%s: %s" % (parameter, text)
        if op:
            text = "%s: %s" % (op, text)
        super().__init__(text)


# ----------------------------------------------------------------------------- controls


class Control:
    """One lathe control's syntax."""

    name = ""  # dialect key
    post = ""  # post name (without _post)
    title = ""
    codes = {RAPID: "G0", FEED: "G1", "G2": "G2", "G3": "G3"}
    digits = 3
    has_x_mode = False
    native = None  # "cycle93", "pecking" or None
    fanuc_style = False  # % lines, O number

    def comment(self, text):
        return paren_comment(text)

    def dwell(self, seconds):
        return "G4 P" + _fixed(seconds, 3)

    def setup(self, opts):
        raise NotImplementedError

    def tool_change(self, number):
        return ["T%02d%02d" % (number, number)]

    def spindle(self, rpm, m):
        return ["G97 S%d %s" % (rpm, m)]

    def m(self, number):
        return "M%02d" % number

    def end(self, opts):
        return [self.m(30)]


class Sinumerik(Control):
    name, post, title = "sinumerik", "sinumerik_lathe", "Siemens Sinumerik 840D lathe (CYCLE93)"
    has_x_mode = True
    native = "cycle93"

    def comment(self, text):
        return "; " + paren_comment(text)[1:-1]

    def dwell(self, seconds):
        return "G4 F" + _fixed(seconds, 3)

    def setup(self, opts):
        return ["G18 G71 G90 G40 G94 " + ("DIAMON" if opts.diameter else "DIAMOF")]

    def tool_change(self, number):
        return ["T%d D1" % number]

    def m(self, number):
        return "M%d" % number


class AllenBradley9(Control):
    name, post, title = "ab9", "ab9_lathe", "Allen-Bradley 9/Series lathe (G77/G76)"
    codes = {RAPID: "G00", FEED: "G01", "G2": "G02", "G3": "G03"}
    has_x_mode = True
    native = "pecking"

    def dwell(self, seconds):
        raise ProgramError(
            "a dwell (G4) cannot be written for the Allen-Bradley 9/Series: its dwell word is not documented "
            "in the manuals this post follows (set the groove's Dwell to 0 or use another post)")

    def setup(self, opts):
        diameter_code = "G07" if opts.g07_is_diameter else "G08"
        radius_code = "G08" if opts.g07_is_diameter else "G07"
        return ["G18 G21 G90 G40 G94 " + (diameter_code if opts.diameter else radius_code)]


class Fanuc(Control):
    name, post, title = "fanuc", "fanuc_lathe", "Fanuc lathe, G code system A (two-block G75/G74)"
    codes = {RAPID: "G00", FEED: "G01", "G2": "G02", "G3": "G03"}
    native = "pecking"
    fanuc_style = True

    def dwell(self, seconds):
        return "G04 P%d" % int(round(seconds * 1000.0))

    def setup(self, opts):
        return ["G21", "G40 G98"]

    def end(self, opts):
        return ["M30", "%"]


class Haas(Fanuc):
    name, post, title = "haas", "haas_lathe", "Haas lathe (one-block G75/G74)"

    def dwell(self, seconds):
        return "G04 P" + _fixed(seconds, 3)


class LinuxCNC(Control):
    name, post, title = "linuxcnc", "linuxcnc_lathe", "LinuxCNC lathe (G7, grooves expanded)"
    digits = 4
    has_x_mode = True

    def setup(self, opts):
        return ["G18 %s G21 G90 G91.1 G40 G94" % ("G7" if opts.diameter else "G8")]

    def tool_change(self, number):
        return ["T%d M6 G43" % number]

    def m(self, number):
        return "M%d" % number

    def end(self, opts):
        return ["M2"]


CONTROLS = {c.name: c() for c in (Sinumerik, AllenBradley9, Fanuc, Haas, LinuxCNC)}


def _control(name):
    try:
        return CONTROLS[name]
    except KeyError:
        raise ValueError("unknown control %r (known: %s)" % (name, ", ".join(CONTROLS))) from None


def _fixed(value, digits):
    text = ("%.*f" % (digits, value)).rstrip("0")
    return "0." if text in ("-0.", "0.") else text


# ----------------------------------------------------------------------------- options


class _Parser(argparse.ArgumentParser):
    def error(self, message):
        raise PostError("%s: %s" % (self.prog, message))

    def exit(self, status=0, message=None):
        raise PostError("%s: %s" % (self.prog, (message or "exit %d" % status).strip()))


def tooltip(name):
    c = _control(name)
    how = {
        "cycle93": "grooves as native CYCLE93 calls",
        "pecking": "plain grooves as native %s calls, others expanded" % ("G77/G76" if c.name == "ab9" else "G75/G74"),
        None: "grooves expanded into G0/G1 moves",
    }[c.native]
    return "%s post by freecad-groove: %s; other operations as X/Z moves (X as %s)." % (
        c.title, how, "a diameter" if c.name != "linuxcnc" else "a diameter, G7")


def make_parser(name):
    """The argparse parser of post ``name`` (a key of CONTROLS)."""
    c = _control(name)
    p = _Parser(prog=c.post + "_post", add_help=False, description=tooltip(name))
    cycles = p.add_mutually_exclusive_group()
    if c.native:
        cycles.add_argument("--native-cycles", dest="cycles", action="store_const", const="native",
                            help="write grooves as the control's own cycle calls where it has one (default)")
    cycles.add_argument("--expand-cycles", dest="cycles", action="store_const", const="expand",
                        help="write every groove as G0/G1 moves (the op's own path)"
                        + ("" if c.native else "; the default: LinuxCNC has no grooving cycle"))
    if c.native == "pecking":
        p.add_argument("--retract", type=float, metavar="E",
                       help="peck retract e of the %s cycles, mm (default: the op's Retract, 0 = 1 mm)%s"
                       % ("G77/G76" if c.name == "ab9" else "G75/G74",
                          "; written as G75 R(e)" if c.name == "fanuc" else "; a machine setting on this control, "
                          "stated in a comment"))
    if c.has_x_mode:
        p.add_argument("--x-mode", choices=("diameter", "radius"), default="diameter",
                       help="X words as diameters (default) or radii (%s)"
                       % {"sinumerik": "DIAMON/DIAMOF", "ab9": "G07/G08", "linuxcnc": "G7/G8"}[c.name])
    if c.name == "ab9":
        p.add_argument("--g07-radius", action="store_true",
                       help="on this control G07 selects radius mode and G08 diameter mode (default: G07 diameter)")
    if c.name == "sinumerik":
        p.add_argument("--diameter-input", action="store_true",
                       help="write CYCLE93 AXFA, DEPG, FAL1 (longitudinal) and FAL2 (face) as diameters "
                       "(default: radius values, as the engine reads them)")
    p.add_argument("--reference-corner", choices=(REFERENCE_MINUS, REFERENCE_PLUS),
                   help="the blade corner the control's tool offset measures (default: each op's ReferenceCorner)")
    if c.fanuc_style:
        p.add_argument("--program-number", type=int, default=1, metavar="N",
                       help="O number of the program (default 1)")
    p.add_argument("--no-header", action="store_true", help="no program name / post comment at the top")
    p.add_argument("--no-comments", action="store_true", help="no comments at all")
    p.add_argument("--precision", type=int, default=c.digits, metavar="N",
                   help="decimals of coordinates (default %d%s)"
                   % (c.digits, "; cycle words keep at most 4" if c.native == "pecking" else ""))
    p.add_argument("--help", action="store_true", help="return this help instead of a program")
    return p


class Options:
    """The parsed options, completed."""

    def __init__(self, control, ns):
        self.cycles = ns.cycles or ("native" if control.native else "expand")
        self.native = self.cycles == "native" and control.native is not None
        self.retract = getattr(ns, "retract", None)
        if self.retract is not None and not (math.isfinite(self.retract) and self.retract >= 0):
            raise PostError("--retract %s: must be a number not less than 0" % self.retract)
        self.diameter = getattr(ns, "x_mode", "diameter") == "diameter"
        self.g07_is_diameter = not getattr(ns, "g07_radius", False)
        self.diameter_input = getattr(ns, "diameter_input", False)
        self.reference = ns.reference_corner
        self.program_number = getattr(ns, "program_number", None)
        if self.program_number is not None and not 0 <= self.program_number <= 9999:
            raise PostError("--program-number %d: must be 0 to 9999" % self.program_number)
        self.header = not ns.no_header
        self.comments = not ns.no_comments
        if not 0 <= ns.precision <= MAX_PRECISION:
            raise PostError("--precision %d: must be 0 to %d" % (ns.precision, MAX_PRECISION))
        self.precision = ns.precision
        self.native_decimals = min(self.precision, NATIVE_DECIMALS)
        self.help = ns.help


def parse_options(name, argstring):
    c = _control(name)
    parser = make_parser(name)
    if argstring is None:
        args = []
    elif isinstance(argstring, (list, tuple)):
        args = list(argstring)
    else:
        try:
            args = shlex.split(argstring)
        except ValueError as e:
            raise PostError("%s_post: cannot read the arguments %r: %s" % (c.post, argstring, e)) from None
    return Options(c, parser.parse_args(args)), parser


# ----------------------------------------------------------------------------- writer


class LatheWriter(Writer):
    """targets.Writer with a control's codes, dwell, precision and X mode.

    ``move`` writes single-axis and partial moves (the op's link rapids, other
    ops' Paths), ``arc`` arcs; ``write`` (the engine's move lists) is the
    dialects writer's own."""

    def __init__(self, control, precision, diameter):
        self.control = control
        self.diameter = diameter
        super().__init__("linuxcnc", True, False)
        self.spec = TargetSpec(control.name, dict(control.codes), precision, precision, {True: "G21", False: "G20"},
                               {False: "G94", True: "G95"}, "M2", False)
        self.set_units(True)

    def x_word(self, radius):
        return super().x_word(radius if self.diameter else radius / 2.0)

    def write(self, moves, prefix=""):
        if not self.diameter:  # the dialects writer doubles X: hand it half (exact in binary)
            moves = [(k, x / 2.0, z, f, p) for k, x, z, f, p in moves]
        return super().write(moves, prefix)

    def dwell(self, seconds):
        if not 0 <= seconds <= MAX_DWELL_SECONDS:
            raise ProgramError("dwell of %r s cannot be written (0 to %g s)" % (seconds, MAX_DWELL_SECONDS))
        return self.control.dwell(seconds)

    def forget(self, position=True, motion=True, feed=True):
        if position:
            self.x_text = self.z_text = None
        if motion:
            self.motion = None
        if feed:
            self.f_text = None

    def move(self, kind, x=None, z=None, f=None, force=False):
        """Lines for one RAPID/FEED move to the given axes (None: not written)."""
        words = []
        if x is not None:
            t = self.x_word(x)
            if force or t != self.x_text:
                words.append("X" + t)
                self.x_text = t
        if z is not None:
            t = self.z_word(z)
            if force or t != self.z_text:
                words.append("Z" + t)
                self.z_text = t
        fword = None
        if kind == FEED:
            if f is not None:
                t = self.f_word(f)
                if t != self.f_text:
                    fword = "F" + t
                    self.f_text = t
            elif self.f_text is None:
                raise ProgramError("feed move with no feed rate (F) in force")
        if not words:
            return ["F" + self.f_text] if fword else []
        if kind != self.motion or force:
            words.insert(0, self.code(kind))
            self.motion = kind
        if fword:
            words.append(fword)
        return [" ".join(words)]

    def arc(self, kind, x, z, i, k, f, radius=None):
        """An arc G2/G3 to radius x, z with incremental radius centre offsets
        i (X), k (Z); ``radius`` (signed, Siemens CR=) instead of I/K."""
        words = [self.code(kind), "X" + self.x_word(x), "Z" + self.z_word(z)]
        if radius is None:
            words += ["I" + self.length_word(i), "K" + self.length_word(k)]
        else:
            words.append("CR=" + self.length_word(radius))
        if f is not None:
            t = self.f_word(f)
            if t != self.f_text:
                words.append("F" + t)
                self.f_text = t
        elif self.f_text is None:
            raise ProgramError("arc with no feed rate (F) in force")
        self.motion = kind
        self.x_text, self.z_text = words[1][1:], words[2][1:]
        return [" ".join(words)]


# ----------------------------------------------------------------------------- FreeCAD objects


def _is_groove_op(obj):
    proxy = getattr(obj, "Proxy", None)
    return proxy is not None and hasattr(proxy, "plan") and hasattr(proxy, "cycles") and hasattr(obj, "GrooveCount")


def groove_op_of(obj):
    """The Groove op ``obj`` is or wraps (dressups hold their op in ``Base``), else None."""
    seen = set()
    while obj is not None and id(obj) not in seen:
        seen.add(id(obj))
        if _is_groove_op(obj):
            return obj
        base = getattr(obj, "Base", None)
        obj = base if hasattr(base, "Path") else None
    return None


def _op_property(obj, name, default=None):
    """A property of the op or of the op a dressup wraps (FreeCAD's opProperty)."""
    seen = set()
    while obj is not None and id(obj) not in seen:
        seen.add(id(obj))
        if hasattr(obj, name):
            return getattr(obj, name)
        base = getattr(obj, "Base", None)
        obj = base if hasattr(base, "Path") else None
    return default


def _is_tool_controller(obj):
    return hasattr(obj, "ToolNumber") and hasattr(obj, "SpindleSpeed") and hasattr(obj, "HorizFeed")


def _is_job(obj):
    return hasattr(obj, "Operations") and hasattr(getattr(obj, "Operations", None), "Group")


def _label(obj):
    return str(getattr(obj, "Label", None) or getattr(obj, "Name", None) or "object")


def _job_of(objects):
    for obj in objects:
        if _is_job(obj):
            return obj
        for parent in getattr(obj, "InList", None) or []:
            if _is_job(parent):
                return parent
            for grand in getattr(parent, "InList", None) or []:
                if _is_job(grand):
                    return grand
    return None


# pecking word -> what the op sets it from
PECKING_PROPERTIES = {"I": "Infeed", "K": "Infeed", "P": "Infeed", "Q": "Infeed", "X": "Depth", "Z": "Depth",
                      "F": "ToolController HorizFeed", "e": "Retract", "R(e)": "Retract"}


def _cycle_error(label, exc, table=None):
    """A PostError for a CycleError, naming the op property (pecking words:
    ``table``; else the CYCLE93 parameter's property)."""
    if table is None:
        parameter = describe_cycle93_parameter(exc.parameter)
    else:
        parameter = table.get(exc.parameter)
    return PostError(exc.message, op=label, parameter=parameter or None)


# ----------------------------------------------------------------------------- the program


class Program:
    """Builds one program's text."""

    def __init__(self, control, opts):
        self.c = control
        self.o = opts
        self.w = LatheWriter(control, opts.precision, opts.diameter)
        self.lines = []
        self.tool = None  # (number, speed, direction) in force
        self.spindle_on = False
        self.x = self.z = None  # model radius / z of the tool when known

    # -- output helpers
    def add(self, lines):
        self.lines.extend(lines)

    def note(self, text):
        if self.o.comments:
            self.lines.append(self.c.comment(text))

    def m(self, number):
        self.lines.append(self.c.m(number))

    def moved(self, x=None, z=None):
        if x is not None:
            self.x = x
        if z is not None:
            self.z = z

    def rapid(self, x=None, z=None, force=False):
        self.add(self.w.move(RAPID, x, z, force=force))
        self.moved(x, z)

    def unknown_position(self):
        self.x = self.z = None
        self.w.forget(position=True, motion=True, feed=False)

    # -- program frame
    def begin(self, title):
        c, o = self.c, self.o
        if c.fanuc_style:
            self.lines.append("%")
            if o.program_number is not None:
                name = " " + c.comment(title) if (o.header and o.comments and title) else ""
                self.lines.append("O%04d%s" % (o.program_number, name))
        elif o.header and title:
            self.note(title)
        if o.header:
            self.note("post %s by freecad-groove %s; lengths mm, feeds mm/min" % (c.post, __version__))
        self.add(c.setup(o))

    def finish(self):
        if self.spindle_on:
            self.m(5)
        self.add(self.c.end(self.o))

    # -- tools, spindle, coolant
    def tool_controller(self, tc):
        if tc is None:
            return
        number = int(tc.ToolNumber)
        speed = float(tc.SpindleSpeed)
        direction = str(getattr(tc, "SpindleDir", "Forward"))
        state = (number, speed, direction)
        if state == self.tool:
            return
        if number < 0 or number > 9999 or (self.c.name in ("ab9", "fanuc", "haas") and number > 99):
            raise PostError("ToolNumber %d cannot be written as a tool number of this control" % number,
                            op=_label(tc))
        if self.tool is None or self.tool[0] != number:
            self.note("tool %d: %s" % (number, _label(tc)))
            self.add(self.c.tool_change(number))
            self.unknown_position()
            if self.c.name == "linuxcnc":
                self.spindle_on = False  # LinuxCNC's M6 stops the spindle
        if speed > 0 and direction in ("Forward", "Reverse"):
            rpm = int(round(speed))
            if rpm < 1 or rpm > 99999:
                raise PostError("SpindleSpeed %g cannot be written" % speed, op=_label(tc))
            self.add(self.c.spindle(rpm, self.c.m(3 if direction == "Forward" else 4)))
            self.spindle_on = True
        elif self.spindle_on:
            self.m(5)
            self.spindle_on = False
        self.tool = state

    # -- objects
    def item(self, obj):
        if _is_job(obj):
            for op in obj.Operations.Group:
                self.item(op)
            return
        if _is_tool_controller(obj):
            self.tool_controller(obj)
            return
        if not _op_property(obj, "Active", True):
            return
        label = _label(obj)
        if not hasattr(obj, "Path"):
            raise PostError("is not a Path object (pick operations, tool controllers or a Job)", op=label)
        self.tool_controller(_op_property(obj, "ToolController"))
        groove = groove_op_of(obj)
        if type(obj).__name__ != "_TempObject":  # FreeCAD's fixture blocks (G54 ...) carry no label
            self.note(label)
            extra = _op_property(obj, "Comment", "")
            if extra:
                self.note(str(extra))
        coolant = str(_op_property(obj, "CoolantMode", "None") or "None")
        if coolant == "Flood":
            self.m(8)
        elif coolant == "Mist":
            self.m(7)
        try:
            if groove is not None and (obj is groove or self.o.native):
                if obj is not groove:
                    self.note("%s: native cycles from %s; the dressup's changes are not in them"
                              % (label, _label(groove)))
                GrooveOutput(self, groove).write()
            else:
                self.path(obj, label)
        except PostError:
            raise
        except CycleError as exc:
            raise _cycle_error(_label(groove) if groove is not None else label, exc) from None
        except (ProgramError, ValueError, ArithmeticError) as exc:
            raise PostError(str(exc), op=label) from None
        if coolant in ("Flood", "Mist"):
            self.m(9)

    # -- plain Paths
    _CODE = re.compile(r"^([GMT])0*(\d+)(\.\d+)?$")

    def path(self, obj, label):
        w = self.w
        plane = "G17"  # FreeCAD's default plane
        for cmd in obj.Path.Commands:
            name = cmd.Name.strip()
            if name.startswith("("):
                self.note(name[1:-1] if name.endswith(")") else name[1:])
                continue
            name = name.upper()
            params = {k.upper(): float(v) for k, v in cmd.Parameters.items()}
            m = self._CODE.match(name)
            if not m:
                raise PostError("command %s cannot be written by a lathe post" % cmd.toGCode(), op=label)
            letter, number, frac = m.group(1), int(m.group(2)), m.group(3)
            code = "%s%d%s" % (letter, number, frac or "")

            def refuse(why):
                raise PostError("%s: %s" % (cmd.toGCode().strip(), why), op=label)

            for axis in ("A", "B", "C", "U", "V", "W"):
                if axis in params:
                    refuse("axis %s: a lathe post writes X and Z only" % axis)
            if abs(params.get("Y", 0.0)) > TOL:
                refuse("Y%s: a Y move; a lathe post writes moves in the XZ plane (X radius, Z) only"
                       % _fixed(params["Y"], 4))
            if letter == "G" and code in ("G0", "G1"):
                kind = RAPID if code == "G0" else FEED
                f = feed_mm_per_min(params["F"]) if (kind == FEED and "F" in params) else None
                if kind == FEED and f is not None and not f > 0:
                    refuse("feed F%s: must be greater than 0" % _fixed(params["F"], 6))
                x, z = params.get("X"), params.get("Z")
                self.add(w.move(kind, x, z, f))
                self.moved(x, z)
            elif letter == "G" and code in ("G2", "G3"):
                if plane != "G18":
                    refuse("an arc in the %s plane; a lathe post writes arcs in the XZ plane (G18) only"
                           % {"G17": "XY", "G19": "YZ"}[plane])
                if abs(params.get("J", 0.0)) > TOL:
                    refuse("J%s: an arc centre off the XZ plane" % _fixed(params["J"], 4))
                if "R" in params:
                    refuse("R-form arcs are not written; give the centre with I and K")
                if self.x is None or self.z is None:
                    refuse("an arc from an unknown position: program X and Z before it")
                x = params.get("X", self.x)
                z = params.get("Z", self.z)
                i, k = params.get("I", 0.0), params.get("K", 0.0)
                f = feed_mm_per_min(params["F"]) if "F" in params else None
                radius = None
                if self.c.name == "sinumerik":
                    radius = self._cr(code, self.x, self.z, x, z, i, k, refuse)
                self.add(w.arc(code, x, z, i, k, f, radius))
                self.moved(x, z)
            elif letter == "G" and code == "G4":
                seconds = params.get("P", params.get("S", params.get("X", 0.0)))
                self.lines.append(w.dwell(seconds))
            elif letter == "G" and code in ("G17", "G18", "G19"):
                plane = code
            elif letter == "G" and number in (54, 55, 56, 57, 58, 59) and (frac is None or code.startswith("G59")):
                if self.c.name == "sinumerik" and number > 57:
                    refuse("work offset %s: Siemens' settable offsets are G54..G57 here" % code)
                self.lines.append(code)
                self.unknown_position()
            elif letter == "G" and code in ("G90", "G40", "G49", "G80", "G94", "G21", "G98", "G99", "G43"):
                continue  # the post's own modes (absolute, no compensation, per minute, mm)
            elif letter == "G" and code == "G91":
                refuse("incremental distances (G91) are not written; FreeCAD ops program absolute positions")
            elif letter == "G" and code in ("G41", "G42"):
                refuse("tool nose radius compensation is not written by these posts")
            elif letter == "G" and 73 <= number <= 89:
                refuse("a canned drilling cycle; lathe posts do not translate FreeCAD's XY drilling cycles")
            elif letter == "M" and number in (3, 4):
                if "S" in params:
                    rpm = int(round(params["S"]))
                    self.add(self.c.spindle(rpm, self.c.m(number)))
                else:
                    self.m(number)
                self.spindle_on = True
            elif letter == "M" and number == 5:
                self.m(5)
                self.spindle_on = False
            elif letter == "M" and number in (0, 1, 7, 8, 9):
                self.m(number)
            elif letter == "M" and number == 6:
                if "T" not in params:
                    refuse("M6 without T")
                self.note("tool %d" % int(params["T"]))
                self.add(self.c.tool_change(int(params["T"])))
                self.unknown_position()
                self.tool = None
                if self.c.name == "linuxcnc":
                    self.spindle_on = False
            elif letter == "M" and number in (2, 30):
                continue  # the post ends the program
            else:
                refuse("not a command these lathe posts write")

    def _cr(self, code, x0, z0, x1, z1, i, k, refuse):
        """Siemens CR= for an I/K arc: the radius, negative above 180 degrees."""
        cx, cz = x0 + i, z0 + k
        r = math.hypot(i, k)
        r1 = math.hypot(x1 - cx, z1 - cz)
        if r < TOL or abs(r - r1) > ARC_IJK_TOLERANCE:
            refuse("the arc's end is not on its circle (radius %.4f at the start, %.4f at the end)" % (r, r1))
        if math.hypot(x1 - x0, z1 - z0) < TOL:
            refuse("a full circle cannot be written with CR=")
        # sweep angle in the (z, x) plane seen from +Y: G2 clockwise
        a0 = math.atan2(x0 - cx, z0 - cz)
        a1 = math.atan2(x1 - cx, z1 - cz)
        ccw = (a1 - a0) % (2 * math.pi)
        sweep = ccw if code == "G3" else 2 * math.pi - ccw
        return r if sweep <= math.pi + 1e-12 else -r


# ----------------------------------------------------------------------------- grooves


def _call_text(call):
    """A CYCLE93 call for a comment (comments cannot hold parentheses)."""
    return call.emit().replace("(", "[").replace(")", "]")


def _plain_reason(call, geo):
    """None when a pecking cycle can cut this CYCLE93 groove, else why not."""
    reasons = []
    if geo.slope != 0.0:
        reasons.append("an oblique contour (ANGC %s)" % _fixed(call.value("ANGC"), 3))
    if call.value("ANG1") or call.value("ANG2"):
        reasons.append("flank angles")
    if any(call.value(n) for n in ("RCO1", "RCO2", "RCI1", "RCI2")):
        reasons.append("edge or base radii/chamfers")
    if call.value("FAL1") or call.value("FAL2"):
        reasons.append("finishing allowances")
    if call.value("DWT"):
        reasons.append("a dwell at the bottom")
    return ", ".join(reasons) or None


class GrooveOutput:
    """Writes one Groove op's grooves, native or expanded."""

    def __init__(self, program, op):
        self.p = program
        self.op = op
        self.label = _label(op)

    def write(self):
        p = self.p
        try:
            plans = self.op.Proxy.current_plan(self.op)
        except CycleError:
            raise
        except ValueError as exc:
            raise PostError(str(exc), op=self.label) from None
        if not plans:
            p.note("%s: no groove (no face in Base)" % self.label)
            return
        tc = getattr(self.op, "ToolController", None)
        if tc is None:
            raise PostError("is not set: the grooves' feed comes from it", op=self.label, parameter="ToolController")
        feed = feed_mm_per_min(tc.HorizFeed.Value)
        if not feed > 0:
            raise PostError("is 0: the grooves need a feed", op=self.label, parameter="ToolController HorizFeed")
        self.feed = feed
        groups = []
        for plan in plans:
            if plan.index == 0 or not groups:
                groups.append([plan])
            else:
                groups[-1].append(plan)
        for group in groups:
            if p.o.native and p.c.native == "cycle93":
                for plan in group:
                    self.cycle93(plan)
            elif p.o.native and p.c.native == "pecking":
                self.pecking(group)
            else:
                for plan in group:
                    self.expanded(plan, None)

    # -- coordinates for the output's reference corner
    def shift(self, plan):
        """(dx radius, dz) from the op's reference corner to the output's."""
        ref = self.p.o.reference
        tool = plan.settings.tool
        if ref is None or ref == tool.reference:
            return 0.0, 0.0
        d = (tool.width if ref == REFERENCE_PLUS else 0.0) - tool.reference_offset
        return (0.0, d) if plan.cycle.kind()[0] else (d, 0.0)

    def settings(self, plan):
        ref = self.p.o.reference
        return plan.settings if ref is None else plan.settings.with_tool(reference=ref)

    def link(self, plan, to_start=True):
        """The op's link rapids to the plan's start point (``to_start`` False:
        without the last one when it is the start point, which the caller writes)."""
        dx, dz = self.shift(plan)
        link = list(plan.link)
        if not to_start and link and link[-1] == (plan.start.x, plan.start.z):
            link = link[:-1]
        for x, z in link:
            self.p.rapid(None if x is None else x + dx, None if z is None else z + dz)

    def rapid_to(self, plan, point, force=False):
        dx, dz = self.shift(plan)
        self.p.rapid(point[0] + dx, point[1] + dz, force=force)

    # -- expanded
    def expanded(self, plan, why):
        p = self.p
        p.note("%s groove %d: %s" % (plan.face.name, plan.index + 1, _call_text(plan.cycle)))
        if why:
            p.note("expanded: " + why)
        self.link(plan)
        dx, dz = self.shift(plan)
        feed = self.feed
        moves = [Move(m.kind, m.x + dx, m.z + dz, feed if m.kind == FEED else None, m.p) for m in plan.moves]
        if p.x is None or p.z is None:  # the link always ends at the start point; this is a guard
            self.rapid_to(plan, (plan.start.x, plan.start.z), force=True)
        try:
            p.add(p.w.write(moves))
        except ProgramError as exc:
            dwell = any(m.kind == DWELL for m in moves) and "dwell" in str(exc)
            raise PostError(str(exc), op=self.label, parameter="Dwell" if dwell else None) from None
        if moves:
            p.moved(moves[-1].x, moves[-1].z)

    # -- Siemens CYCLE93
    def cycle93(self, plan):
        p = self.p
        call = plan.cycle
        if p.o.diameter_input:
            longitudinal = call.kind()[0]
            call = replace(
                call, axfa=2 * call.axfa,
                depg=2 * call.depg if longitudinal else call.depg,
                fal1=2 * call.value("FAL1") if longitudinal else call.fal1,
                fal2=call.fal2 if longitudinal else 2 * call.value("FAL2"),
            )
        p.note("%s groove %d" % (plan.face.name, plan.index + 1))
        self.link(plan, to_start=False)
        self.rapid_to(plan, (plan.start.x, plan.start.z), force=True)
        p.lines.append("F" + p.w.f_word(self.feed))  # CYCLE93 cuts at the feed in force
        p.lines.append(call.emit())
        # CYCLE93 ends at its start point; the motion mode it leaves is not documented
        p.w.forget(position=False, motion=True, feed=True)

    # -- pecking cycles (Allen-Bradley G77/G76, Fanuc and Haas G75/G74)
    def pecking(self, group):
        first = group[0]
        call = first.cycle
        geo = call.geometry(first.settings)
        why = _plain_reason(call, geo)
        if why is None:
            try:
                calls = self._pecking_calls(group, geo)
            except _NotNative as e:
                why = str(e)
        if why is not None:
            cycle = self._pecking_name(call)
            for plan in group:
                self.expanded(plan, "%s cannot cut %s" % (cycle, why))
            return
        for plans, approach, model, state in calls:
            self._write_pecking(plans, approach, model, state)

    def _pecking_name(self, call):
        longitudinal = call.kind()[0]
        if self.p.c.name == "ab9":
            return "G77" if longitudinal else "G76"
        return "G75" if longitudinal else "G74"

    def _pecking_calls(self, group, geo0):
        """[(plans, approach points, model, start MachineState)]: one call per
        groove, or one for the whole group when each groove is one plunge."""
        o = self.p.o
        tool = group[0].settings.tool
        single = abs(geo0.params["WIDG"] - tool.width) <= 1e-9
        per = []
        for plan in group:
            geo = plan.cycle.geometry(plan.settings)
            frame = geo.frame
            positions = geo.plunge_positions()
            u0, u1 = positions[0], positions[-1]
            start = frame.blade(u0, geo.clearance(u0))
            approach = [(plan.start.x, plan.start.z)]
            for m in plan.moves:
                if m.kind != RAPID:
                    break
                approach.append((m.x, m.z))
            if math.dist(approach[-1], start) > 1e-9:
                raise _NotNative("its start point (the approach of the expansion ends elsewhere)")
            bottom = frame.blade(u0, -geo.params["DEPG"])
            far = frame.blade(u1, geo.clearance(u1))
            per.append((plan, geo, approach, start, bottom, far))
        longitudinal = geo0.longitudinal
        axis = 1 if longitudinal else 0  # the stepping coordinate of (x, z): Z for G77/G75, X for G76/G74
        calls = []
        if single and len(group) > 1:
            steps = [per[k][3][axis] - per[0][3][axis] for k in range(len(per))]
            pitch = abs(steps[1])
            for k, s in enumerate(steps):
                if abs(abs(s) - k * pitch) > 1e-6:
                    raise _NotNative("grooves that are not equally spaced")
            plan, geo, approach, start, bottom, _far = per[0]
            last = per[-1][3]
            calls.append(([p[0] for p in per], approach,
                          *self._model(group[0], start, bottom, last, pitch, geo)))
        else:
            for plan, geo, approach, start, bottom, far in per:
                if single:
                    calls.append(([plan], approach, *self._model(plan, start, bottom, None, None, geo)))
                    continue
                step = WIDTH_STEP_FACTOR * (tool.width - 2 * tool.corner_radius)
                scale = 10 ** o.native_decimals
                pitch = math.floor(step * scale + 1e-9) / scale
                if not pitch > 0:
                    raise _NotNative("a groove wider than the blade with a step below the cycle's resolution")
                calls.append(([plan], approach, *self._model(plan, start, bottom, far, pitch, geo)))
        return calls

    def _model(self, plan, start, bottom, last, pitch, geo):
        """(the cycle model, its start MachineState) in output coordinates."""
        c, o = self.p.c, self.p.o
        dx, dz = self.shift(plan)
        nd = o.native_decimals
        start = (start[0] + dx, start[1] + dz)
        bottom = (bottom[0] + dx, bottom[1] + dz)
        last = None if last is None else (last[0] + dx, last[1] + dz)
        longitudinal = geo.longitudinal
        diameter = o.diameter if c.name == "ab9" else True

        def xw(radius):
            return round(radius * (2.0 if diameter else 1.0), nd) + 0.0

        def lw(value):
            return round(value, nd) + 0.0

        def written(value, x_axis):
            """The value the control reads back from the written start word."""
            return float(self.p.w.x_word(value) if x_axis else self.p.w.z_word(value)) / (
                2.0 if (x_axis and self.p.w.diameter) else 1.0)

        sx, sz = written(start[0], True), written(start[1], False)
        peck = lw(geo.params["IDEP"])
        if not peck > 0:
            raise _NotNative("an Infeed below the cycle's resolution")
        feed = round(self.feed, 4)
        e = o.retract if o.retract is not None else geo.params["VRT"]
        e = lw(e)
        words = {}
        if longitudinal:
            words["X"] = xw(bottom[0])
            if last is not None:
                words["Z"] = lw(last[1])
        else:
            words["Z"] = lw(bottom[1])
            if last is not None:
                words["X"] = xw(last[0])
        if c.name == "ab9":
            cls = G77 if longitudinal else G76
            words.update({("I" if longitudinal else "K"): peck, "F": feed, "D": 0.0})
            if last is not None:
                words["K" if longitudinal else "I"] = lw(pitch)
            model = cls(**words)
        elif c.name == "fanuc":
            cls = FanucG75 if longitudinal else FanucG74
            inc = lambda v: int(round(v / FANUC_INCREMENT))  # noqa: E731
            words.update({("P" if longitudinal else "Q"): inc(peck), "F": feed, "e": e})
            if last is not None:
                words["Q" if longitudinal else "P"] = inc(pitch)
            model = cls(**words)
        else:
            cls = HaasG75 if longitudinal else HaasG74
            words.update({("I" if longitudinal else "K"): peck, "F": feed})
            if last is not None:
                words["K" if longitudinal else "I"] = lw(pitch)
            model = cls(**words)
        state = MachineState(x=sx, z=sz, feed=feed, diameter_mode=diameter, metric=True, feed_per_rev=False)
        settings = replace(self.settings(plan), peck_retract=e)
        try:
            model.validate(settings)
            model.expand(state, settings)
        except CycleError as exc:
            raise _cycle_error(self.label, exc, PECKING_PROPERTIES) from None
        return model, (state, e)

    def _write_pecking(self, plans, approach, model, state_e):
        p = self.p
        state, e = state_e
        first = plans[0]
        if len(plans) > 1:
            what = "%s grooves %d-%d" % (first.face.name, plans[0].index + 1, plans[-1].index + 1)
        else:
            what = "%s groove %d" % (first.face.name, first.index + 1)
        p.note("%s: %s as %s" % (what, _call_text(first.cycle), model.NAME))
        if p.c.name in ("ab9", "haas"):
            p.note("peck retract e = %s mm: %s" % (_fixed(e, 4), "AMP parameter" if p.c.name == "ab9"
                                                   else "setting 22"))
        self.link(first)
        for point in approach[1:-1]:
            self.rapid_to(first, point)
        self.rapid_to(first, approach[-1], force=True)
        p.lines.extend(model.emit().split("\n"))
        # the cycle ends at its start point; motion and feed after it: not relied on
        p.w.forget(position=False, motion=True, feed=True)
        for point in reversed(approach[:-1]):
            self.rapid_to(first, point)
        for plan in plans[1:]:
            self.link(plan)


class _NotNative(Exception):
    pass


# ----------------------------------------------------------------------------- export


def build(name, objectslist, opts):
    """The program text for ``objectslist`` (PostError on any problem)."""
    c = _control(name)
    prog = Program(c, opts)
    objects = list(objectslist or [])
    job = _job_of(objects)
    title = _label(job) if job is not None else "FreeCAD"
    prog.begin(title)
    for obj in objects:
        prog.item(obj)
    prog.finish()
    return "\n".join(prog.lines) + "\n"


def export(name, objectslist, filename, argstring):
    """A FreeCAD script post's export(): the program for ``objectslist``;
    ``filename`` "-" returns the text only, else it is also written (atomically).
    Raises PostError (also printed on FreeCAD's report view) on any problem."""
    try:
        opts, parser = parse_options(name, argstring)
        if opts.help:
            return parser.format_help()
        text = build(name, objectslist, opts)
        if filename and filename != "-":
            try:
                write_atomically(filename, text)
            except OSError as e:
                raise PostError("cannot write %s: %s" % (filename, e.strerror or e)) from None
        return text
    except PostError as e:
        FreeCAD.Console.PrintError("%s_post: %s\n" % (_control(name).post, e))
        raise
