"""A shim, kept because documents saved before the ops moved into
freecad_groove/ops/ (up to commit 3d18f68) store the Cylinder slot op's proxy
as ``freecad_groove.freecad.cylinder_slot_op.ObjectCylinderSlot``: FreeCAD
imports this module to open them. The class lives in
freecad_groove/ops/slot/op.py (documents saved since store that path);
nothing else belongs here.
"""

from ..ops.slot.op import ObjectCylinderSlot

__all__ = ["ObjectCylinderSlot"]
