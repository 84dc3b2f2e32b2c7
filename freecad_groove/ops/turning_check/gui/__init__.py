"""The Check turning command in FreeCAD's GUI (the GUI layer):

    command.py  the Check turning command and its place in CAM's "Project Setup" toolbar and menu
    panel.py    the task panel: the figures per op, Check again, Close
    preview.py  the check's half section drawn in the 3D view while the panel is open
"""

from ....gui import icon_path

ICON = icon_path("check_turning.svg")
