# SPDX-License-Identifier: LGPL-2.1-or-later
"""Milltronics mill: CAM's Face and Pocket Shape ops as the G33/G34 autoroutines, other ops as moves.

A FreeCAD CAM script post of freecad-groove: a thin stub over
freecad_groove/freecad/posts/milltronics_mill.py (which documents the output
and the options). `--help` in the Job's post-processor arguments shows them.
"""

import os
import sys

try:
    from freecad_groove.freecad.posts import milltronics_mill as _mill
except ModuleNotFoundError as _e:  # this folder added to the post path without the add-on on sys.path
    if not (_e.name or "").startswith("freecad_groove"):
        raise
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    from freecad_groove.freecad.posts import milltronics_mill as _mill

POST = _mill.POST
UNITS = "G21"  # metric (FreeCAD's WrapperPost reads this)
parser = _mill.make_parser()
TOOLTIP = _mill.TITLE
TOOLTIP_ARGS = parser.format_help()

# CAM's Post Process command takes this class (named after the post) and reports a failed post in one line
Milltronics_Mill = _mill.command_post_class()


def export(objectslist, filename, argstring):
    """The program for ``objectslist``; ``filename`` "-" only returns it."""
    return _mill.export(objectslist, filename, argstring)
