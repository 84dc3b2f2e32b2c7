"""A shim, kept because GUI documents saved before the ops moved into
freecad_groove/ops/ (up to commit 3d18f68) store the Plunge grind op's view
provider as ``freecad_groove.gui.grind_view.ViewProviderPlungeGrind``: FreeCAD
imports this module to open them. The class lives in
freecad_groove/ops/grind/gui/view.py (documents saved since store that path);
nothing else belongs here.
"""

from ..ops.grind.gui.view import ViewProviderPlungeGrind

__all__ = ["ViewProviderPlungeGrind"]
