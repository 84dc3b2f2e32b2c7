"""The Groove op in FreeCAD's GUI (the GUI layer):

    command.py    the Turning Groove command and its place in CAM's toolbar and menu
    view.py       ViewProviderGroove, the op's view provider (GUI documents store its class path), the
                  turned-face selection gate, a new op with its panel open
    panel.py      the task panel: its Groove page (the page class stored in the view provider's state)
                  and its dialog (GrooveTaskPanel: the tool page before the Groove page)
    tool_page.py  the panel's "Tool and coolant" page (grooving tool controller button)
    preview.py    the groove cross-section and toolpath drawn while editing
"""

from ....gui import icon_path
from .. import KIND

ICON = icon_path(KIND.icon)
