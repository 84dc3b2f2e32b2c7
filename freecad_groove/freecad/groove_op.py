"""A shim, kept because documents saved before the ops moved into
freecad_groove/ops/ (up to commit 3d18f68) store the Groove op's proxy as
``freecad_groove.freecad.groove_op.ObjectGroove``: FreeCAD imports this
module to open them. The class lives in freecad_groove/ops/groove/op.py
(documents saved since store that path); nothing else belongs here.
"""

from ..ops.groove.op import ObjectGroove

__all__ = ["ObjectGroove"]
