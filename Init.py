# freecad-groove: runs when FreeCAD starts, with or without the GUI.
#
# FreeCAD puts this folder on sys.path, so `import freecad_groove` works in
# scripts and in freecadcmd. Here the lathe posts in postprocessors/ are added
# to CAM's post list, and (FreeCAD 1.1) the grooving blade to CAM's tool bit
# shapes once CAM loads them (freecad_groove/freecad/registration.py). That
# module is loaded by its file name, so a start imports nothing but it (the
# standard library); CAM's modules and ours load when CAM is used. A failure
# only prints a warning: it must never stop FreeCAD from starting.


def _freecad_groove_register_posts():
    import importlib.util
    import os

    import freecad_groove

    path = os.path.join(os.path.dirname(freecad_groove.__file__), "freecad", "registration.py")
    spec = importlib.util.spec_from_file_location("_freecad_groove_registration", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    module.register()
    module.register_shapes()


try:
    _freecad_groove_register_posts()
except Exception as e:
    import FreeCAD

    FreeCAD.Console.PrintWarning("freecad-groove: the lathe posts are not in CAM's post list: %s\n" % e)
