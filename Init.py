# freecad-groove: runs when FreeCAD starts, with or without the GUI.
#
# FreeCAD puts this folder on sys.path, so `import freecad_groove` works in
# scripts and in freecadcmd. The cycle engine (freecad_groove.engine) needs
# nothing from FreeCAD; the Groove operation and the lathe posts register
# themselves here once they exist (see README, "Status").
