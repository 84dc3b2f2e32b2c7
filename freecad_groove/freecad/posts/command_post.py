"""The posts as CAM's Post Process command (CAM_Post) runs them, without a traceback.

FreeCAD 1.0's and 1.1's ``PostProcessorFactory`` loads ``<name>_post.py`` and
takes the class ``<name>.title()`` from it (``Fanuc_Lathe``) before it would
wrap the module's ``export()`` in its ``WrapperPost``; CAM_Post then calls
the instance's ``export()`` and takes a falsy result as a failed post: it
aborts its transaction and writes no file (1.0 and 1.1 alike), while an
exception reaches the user as a Python traceback. So each post module names
a class made here whose ``export()`` never raises: a failed post is one
error line in the report view (``fanuc_lathe_post: Groove: ...``, FreeCAD's
own way of reporting, Console.PrintError) and None; ``--help`` shows the
options in the report view and is None too. The module's ``export()`` stays
the script API (it raises PostError, for scripts and tests).

The class derives from FreeCAD's ``Path.Post.Processor.PostProcessor`` for its
``_buildPostList`` (the Job's output order, split output, fixtures), but not
for its argument handling: FreeCAD 1.1's constructor builds its own shared
argument parsers, which these posts do not take.

Every post family builds its class with ``post_class`` (the lathe posts
through ``command_post_class``, the grinder posts in grind.py, the Milltronics
post in milltronics_mill.py), reports a failed post with ``reported``, and
writes a script post's file with ``script_export``.
"""

import traceback
from typing import Any, Callable, List, Optional, Tuple

import FreeCAD

from .lathe_posts import lathe_post_named
from .options import make_parser, parse_options, tooltip
from .post_error import PostError
from .program_file import write_program_file

Sections = List[Tuple[str, str]]


def report_help(name: str, text: str) -> None:
    """The post's help in the report view (no program is written)."""
    FreeCAD.Console.PrintMessage("%s_post --help: no program written; the options:\n%s\n"
                                 % (lathe_post_named(name).freecad_name, text.rstrip("\n")))


def reported(post: str, attempt: Callable[[], Optional[Sections]]) -> Optional[Sections]:
    """attempt(), or None after reporting why not in one line of the report view (``post``: "fanuc_lathe_post")."""
    try:
        return attempt()
    except PostError as exc:
        text = str(exc)  # an option error already names the post
        FreeCAD.Console.PrintError("%s (no file written)\n" % (text if text.startswith(post) else post + ": " + text))
    except Exception as exc:  # noqa: BLE001 - a user action must never end in a traceback
        FreeCAD.Console.PrintError("%s: could not post the Job: %s: %s (no file written; please report it)\n"
                                   % (post, type(exc).__name__, exc))
        FreeCAD.Console.PrintLog(traceback.format_exc())
    return None


def each_part(processor: Any, program: Callable[[list], Optional[str]]) -> Optional[Sections]:
    """[(part name, program(objects))] of the Job's post list; None when a program is None (--help)."""
    sections = [(part, program(objects)) for part, objects in processor._buildPostList()]
    return None if any(text is None for _part, text in sections) else sections


def post_sections(name: str, processor: Any, argstring: Any) -> Optional[Sections]:
    """[(part name, program)] of the Job's post list, or None after reporting
    why not (a PostError, --help, anything unexpected) in the report view."""
    from . import build  # the package's build(); imported here, the package imports this module

    def attempt():
        options, parser = parse_options(name, argstring)
        if options.help:
            report_help(name, parser.format_help())
            return None
        return [(part, build(name, objects, options)) for part, objects in processor._buildPostList()]

    return reported(lathe_post_named(name).freecad_name + "_post", attempt)


def post_class(class_name: str, tip: str, tip_args: str, sections: Callable[[Any, str], Optional[Sections]]) -> type:
    """A class for FreeCAD's PostProcessorFactory named ``class_name``: its export() is
    ``sections(self, the Job's PostProcessorArgs)`` (which must not raise: see ``reported``)."""
    from Path.Post.Processor import PostProcessor

    class CommandPost(PostProcessor):
        """A post of the add-on for CAM's Post Process command (see the module notes)."""

        def __init__(self, job: Any, *args: Any, **kwargs: Any) -> None:  # noqa: D107 - no base constructor
            self._job = job
            self._args = args
            self._kwargs = kwargs

        tooltip = property(lambda self: tip)
        tooltipArgs = property(lambda self: tip_args)  # noqa: N815 - FreeCAD's name
        units = property(lambda self: "Metric")

        def export(self) -> Optional[Sections]:
            return sections(self, getattr(self._job, "PostProcessorArgs", ""))

    CommandPost.__name__ = CommandPost.__qualname__ = class_name
    return CommandPost


def command_post_class(name: str) -> type:
    """The class FreeCAD's PostProcessorFactory takes from lathe post ``name``'s module."""
    return post_class(lathe_post_named(name).freecad_name.title(), tooltip(name), make_parser(name).format_help(),
                      lambda processor, argstring: post_sections(name, processor, argstring))


def script_export(post: str, text_of: Callable[[], Optional[str]], filename: Optional[str]) -> Optional[str]:
    """A script post's export(): text_of() (None: --help, nothing written), written to ``filename`` unless it is
    "-" or None; a PostError is printed on the report view (``post``: "ab9_grind_post") and raised."""
    try:
        text = text_of()
        if text is not None and filename and filename != "-":
            write_program_file(filename, text)
        return text
    except PostError as e:
        FreeCAD.Console.PrintError("%s: %s\n" % (post, e))
        raise
