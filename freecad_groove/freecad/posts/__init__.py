"""Lathe post-processors for FreeCAD CAM: the logic every freecad-groove post shares.

Headless FreeCAD layer: FreeCAD and Path only (no Qt, no FreeCADGui). The
posts in ``postprocessors/`` (``sinumerik_lathe_post.py``, ``ab9_lathe_post.py``,
``fanuc_lathe_post.py``, ``haas_lathe_post.py``, ``gsk_lathe_post.py``, ``linuxcnc_lathe_post.py``) are
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
  tool change in the control's syntax and, with the op that uses it, the
  spindle from the tool controller (``G97 S<rpm> M3``/``M4``; none when
  SpindleDir is "None" or the speed is 0; never for a Cylinder slot, whose
  speed is the live tool's);
* an op (inactive ops are skipped): its label as a comment, the coolant of its
  CoolantMode (M8 flood, M7 mist; M9 after the op), then
  - a Groove op (or a dressup whose ``Base`` chain reaches one): every groove
    of ``op.Proxy.current_plan(op)``: the op's link rapids, then the groove as a
    native cycle call (after a rapid to the cycle's start point, since a
    native cycle starts where the tool stands) or as the engine's expanded
    moves (``--expand-cycles``, the controls without a cycle, grooves the
    control's cycle cannot cut - a comment says why);
  - a Cylinder slot op: its X/Z/C moves, on GSK its G7.1 region (slots.py);
    a control without a C axis refuses it;
  - any other object with a Path (a turning op, a custom Path, a dressup's
    Path, the Job's fixture blocks): its commands as plain moves: G0/G1/G2/G3
    in the XZ plane, X a radius in model coordinates (written as a diameter
    where the control is in diameter mode), arcs with incremental radius
    I/K (Siemens: ``CR=``), G4 dwell, comments, G54..G59, spindle and coolant
    M codes, M6 tool changes. Y moves, arcs outside G18, incremental G91,
    canned drilling cycles, nose radius compensation and other words are
    refused with an error naming the op and the command;
* the end: M9 when coolant was on, M5 when the spindle ran, the program end.

Feeds and speeds: a Groove op's own (``freecad/cutting.py``: FeedPerRev,
SurfaceSpeed with MaxSpindleSpeed, SpindleSpeed; else the tool controller's;
else 0.05 mm/rev and 500 rpm), written the control's way (the post's
target, ``LathePost.target``; docs/posts.md, "Feeds and speeds");
other objects' Path F words are mm/s, written per minute (G94, Fanuc/Haas
G98), the mode switched back where a groove fed per revolution. Lengths are
mm (G21, Siemens G71), or inches with ``--inches`` (G20, Siemens G700: the
writer divides every length and feed by 25.4; native calls get their words
in inches). ``--help`` reports the options and returns None.
Numbers: the target writer's (a decimal point always, no ``-0``), with the
control's decimals (3; LinuxCNC 4; ``--precision``). Dwell: Siemens
``G4 F<s>``, Fanuc ``G04 P<ms>``, Haas ``G04 P<s>``, LinuxCNC ``G4 P<s>``;
the Allen-Bradley 9/Series dwell word is not documented in the manuals the
engine follows (its program reader refuses G04 for "ab9" too), so a dwell
there is an error naming the op. X words are diameters (DIAMON, G07, G7)
unless ``--x-mode radius``; arc centres I/K are always per-side (radius)
offsets.

The lathe posts
---------------
========= ============================ ====================== ===================
post      setup line                   tool change            native grooving
========= ============================ ====================== ===================
sinumerik ``G18 G71 G90 G40 G94 DIAMON`` ``T<n> D1``            CYCLE93 (every groove)
ab9       ``G18 G21 G90 G40 G94 G07``  ``T<nnnn>`` (tool+offs)  G77 / G76 (plain grooves)
fanuc     ``%``, ``G21``, ``G40 G98``  ``T<nn><nn>``            G75 / G74 two-block
haas      ``%``, ``G21``, ``G40 G98``  ``T<nn><nn>``            G75 / G74 one-block
gsk       ``%``, ``G21``, ``G40 G98``  ``T<nn><nn>``            G75 / G74 two-block
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
written only when the whole text is built, by the engine's
``write_atomically`` (engine/output/files.py): through a temporary file in the
target's folder renamed over it, so a failed post leaves no file and an
existing one untouched; a symbolic link is followed to the file it names; a
directory, pipe, device or write-protected file is refused with a PostError
``cannot write FILE: <why>``.

The package
-----------
One concern a module: ``lathe_posts`` (each lathe post, :class:`LathePost`:
its target and what the post says of it), ``options`` (the argument parsers
and the parsed options), ``objects`` (what a post recognises among FreeCAD
objects), ``program`` (one program's text: frame, tools, spindle, coolant,
objects, on the engine's program builder and writer), ``path_commands``
(other objects' Paths as plain moves), ``grooves`` (a Groove op's grooves:
native or expanded; the pecking-cycle calls for plain grooves, which the
engine decides in engine/native/cycle93_pecking.py as ``expand
--native-cycles`` does, with the output's blade corner), ``slots`` and
``live_tool`` (Cylinder slots, the live tool's switches), ``post_error``
(:class:`PostError`), ``program_file`` (the program written to its file,
atomically), ``command_post`` (the classes CAM's Post Process command takes).
The grinder and Milltronics posts: ``grind``, ``milltronics_mill`` and
``milltronics_ops``. This module: :func:`build` and :func:`export`.
"""

from typing import Any, Iterable, Optional, Sequence, Union

import FreeCAD

from .command_post import command_post_class, report_help, script_export
from .grooves import PECKING_PROPERTIES
from .lathe_posts import LATHE_POSTS, LathePost, lathe_post_named
from .objects import groove_op_of, job_of, label_of
from .options import Options, make_parser, parse_options, tooltip
from .post_error import PostError
from .program import Program

__all__ = ["LATHE_POSTS", "PostError", "export", "build", "parse_options", "make_parser", "tooltip", "groove_op_of",
           "LathePost", "Options", "PECKING_PROPERTIES", "command_post_class"]


def build(name: str, objectslist: Optional[Iterable[Any]], options: Options) -> str:
    """The program text for ``objectslist`` (PostError on any problem)."""
    program = Program(lathe_post_named(name), options)
    objects = list(objectslist or [])
    job = job_of(objects)
    program.start(label_of(job) if job is not None else "FreeCAD")
    for obj in objects:
        program.item(obj)
    program.finish()
    if program.missing_switches:  # machine codes the post could not write (posts/live_tool.py)
        missing = ", ".join(dict.fromkeys(program.missing_switches))
        FreeCAD.Console.PrintWarning("%s_post: no %s given: the program has a comment in place of each such switch"
                                     "\n" % (program.post.freecad_name, missing))
    return program.text()


def export(name: str, objectslist: Optional[Iterable[Any]], filename: Optional[str],
           argstring: Union[None, str, Sequence[str]]) -> Optional[str]:
    """A FreeCAD script post's export(): the program for ``objectslist``;
    ``filename`` "-" returns the text only, else it is also written (atomically).
    Raises PostError (also printed on FreeCAD's report view) on any problem.
    ``--help`` shows the options in the report view and returns None (no
    program, no file), as FreeCAD's own script posts return None when they
    write nothing."""
    def text_of():
        options, parser = parse_options(name, argstring)
        if options.help:
            report_help(name, parser.format_help())
            return None
        return build(name, objectslist, options)

    return script_export(lathe_post_named(name).freecad_name + "_post", text_of, filename)
