"""A shim, kept because GUI documents saved before the ops moved into
freecad_groove/ops/ (up to commit 3d18f68) store the Groove op's view
provider as ``freecad_groove.gui.task_panel.ViewProvider`` and, in its state,
the page class ``freecad_groove.gui.task_panel.GroovePage``: FreeCAD imports
this module to open them and to edit their ops. The classes live in
freecad_groove/ops/groove/gui/ (view.py: ViewProviderGroove, panel.py:
GroovePage; documents saved since store those paths); nothing else belongs
here.
"""

from ..ops.groove.gui.panel import GroovePage
from ..ops.groove.gui.view import ViewProviderGroove as ViewProvider

__all__ = ["GroovePage", "ViewProvider"]
