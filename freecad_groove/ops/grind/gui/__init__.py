"""The Plunge grind op in FreeCAD's GUI (the GUI layer):

    command.py  the Plunge grind command and its place in CAM's toolbar and menu
    view.py     ViewProviderPlungeGrind, the op's view provider (GUI documents store its class path), a new
                op with its panel open
    panel.py    the task panel's Plunge grind page (its class path is stored in the view provider's state)
                and the flat-face selection gate
    preview.py  the strokes drawn in the 3D view while the panel is open
"""

from ....gui import icon_path
from .. import KIND

ICON = icon_path(KIND.icon)
