# freecad-groove: runs when the FreeCAD GUI starts.
#
# Adds the Groove command to the CAM workbench's toolbar and menu (through
# FreeCADGui.addWorkbenchManipulator, so CAM itself is not loaded before the
# user opens it). A failure only prints a warning: it must never stop
# FreeCAD from starting.


def _freecad_groove_register_gui():
    import freecad_groove.gui

    freecad_groove.gui.register()


try:
    _freecad_groove_register_gui()
except Exception as e:
    import FreeCAD

    FreeCAD.Console.PrintWarning("freecad-groove: the Groove command is not in the CAM workbench: %s\n" % e)
