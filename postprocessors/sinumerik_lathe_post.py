# SPDX-License-Identifier: LGPL-2.1-or-later
"""Siemens Sinumerik 840D lathe: grooves as native CYCLE93 calls.

A FreeCAD CAM script post of freecad-groove: this file is the argument parser
and a call into the shared post logic, freecad_groove/freecad/posts/ (which
documents the output, the options and every choice). `--help` in the Job's
post-processor arguments shows the options in the report view and writes no program.
"""

import os
import sys

try:
    from freecad_groove.freecad import posts as _posts
except ModuleNotFoundError as _e:  # this folder added to the post path without the add-on on sys.path
    if not (_e.name or "").startswith("freecad_groove"):
        raise
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    from freecad_groove.freecad import posts as _posts

LATHE_POST = "sinumerik"
UNITS = "G21"  # metric (FreeCAD's WrapperPost reads this)
parser = _posts.make_parser(LATHE_POST)
TOOLTIP = _posts.tooltip(LATHE_POST)
TOOLTIP_ARGS = parser.format_help()


# CAM's Post Process command takes this class (named after the post) and reports a failed post in one line
Sinumerik_Lathe = _posts.command_post_class(LATHE_POST)


def export(objectslist, filename, argstring):
    """The program for ``objectslist``; ``filename`` "-" only returns it."""
    return _posts.export(LATHE_POST, objectslist, filename, argstring)
