"""A shim, kept because GUI documents saved before the ops moved into
freecad_groove/ops/ (up to commit 3d18f68) store the Cylinder slot op's view
provider as ``freecad_groove.gui.slot_view.ViewProviderCylinderSlot``:
FreeCAD imports this module to open them. The class lives in
freecad_groove/ops/slot/gui/view.py (documents saved since store that path);
nothing else belongs here.
"""

from ..ops.slot.gui.view import ViewProviderCylinderSlot

__all__ = ["ViewProviderCylinderSlot"]
