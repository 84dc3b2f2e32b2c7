"""The Cylinder slot op in FreeCAD's GUI (the GUI layer):

    command.py  the Cylinder slot command (a face and the slot's edges selected -> the op)
    view.py     ViewProviderCylinderSlot, the op's view provider (GUI documents store its class path): the
                op's X/Z/C moves drawn wrapped on the cylinder; editing opens the panel
    panel.py    the task panel (Base Geometry, then the tool, the path, Depth, Passes, ...)
    preview.py  the slot's developed path drawn in the panel while it is open
"""

from ....gui import icon_path
from .. import KIND

ICON = icon_path(KIND.icon)
