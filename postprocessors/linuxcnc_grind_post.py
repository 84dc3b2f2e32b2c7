# SPDX-License-Identifier: LGPL-2.1-or-later
"""LinuxCNC grinder: Plunge grind ops expanded into G1 moves, dress calls o<dressN> call.

A FreeCAD CAM script post of freecad-groove: a thin stub over
freecad_groove/freecad/posts/grind.py (which documents the output and the
options). `--help` in the Job's post-processor arguments shows the options.
"""

import os
import sys

try:
    from freecad_groove.freecad.posts import grind as _grind
except ModuleNotFoundError as _e:  # this folder added to the post path without the add-on on sys.path
    if not (_e.name or "").startswith("freecad_groove"):
        raise
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    from freecad_groove.freecad.posts import grind as _grind

POST = "linuxcnc_grind"
UNITS = "G21"  # metric (FreeCAD's WrapperPost reads this)
parser = _grind.make_grind_parser(POST)
TOOLTIP = _grind.GRIND_POSTS[POST][2]
TOOLTIP_ARGS = parser.format_help()

# CAM's Post Process command takes this class (named after the post) and reports a failed post in one line
Linuxcnc_Grind = _grind.grind_command_post_class(POST)


def export(objectslist, filename, argstring):
    """The program for ``objectslist``; ``filename`` "-" only returns it."""
    return _grind.grind_export(POST, objectslist, filename, argstring)
