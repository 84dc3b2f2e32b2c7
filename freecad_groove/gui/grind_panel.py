"""A shim, kept because GUI documents saved before the ops moved into
freecad_groove/ops/ (up to commit 3d18f68) store the Plunge grind op's page
class ``freecad_groove.gui.grind_panel.PlungeGrindPage`` in its view
provider's state: FreeCAD imports this module to edit their ops. The class
lives in freecad_groove/ops/grind/gui/panel.py (documents saved since store
that path); nothing else belongs here.
"""

from ..ops.grind.gui.panel import PlungeGrindPage

__all__ = ["PlungeGrindPage"]
