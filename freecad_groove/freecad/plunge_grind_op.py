"""A shim, kept because documents saved before the ops moved into
freecad_groove/ops/ (up to commit 3d18f68) store the Plunge grind op's proxy
as ``freecad_groove.freecad.plunge_grind_op.ObjectPlungeGrind``: FreeCAD
imports this module to open them. The class lives in
freecad_groove/ops/grind/op.py (documents saved since store that path);
nothing else belongs here.
"""

from ..ops.grind.op import ObjectPlungeGrind

__all__ = ["ObjectPlungeGrind"]
