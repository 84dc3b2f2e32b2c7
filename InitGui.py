# freecad-groove: runs when the FreeCAD GUI starts.
#
# The Groove command and task panel are added to the CAM workbench from here
# once they exist (see README, "Status"); the engine and command-line tool
# need no GUI.
