"""The FreeCAD layer of freecad-groove, headless part: what the ops share.

Imports FreeCAD, Part and Path (never Qt or FreeCADGui), so it works in
``freecadcmd`` scripts. The ops themselves, each in a folder of its own, are
in freecad_groove/ops/ (the same layer; their gui/ packages are the GUI
layer); what several of them use stays here:

    addon_op.py       what the ops share on CAM's op framework: their base class, creation, the SetupSheet,
                      the report of an op that cannot cut, an op seen with a panel's values
    scripting.py      what the make_* calls share (faces and parts checked, nothing left behind)
    faces.py          what a picked face of a turned part means for a groove; element names
    units.py          FreeCAD's units as the engine and the posts need them (mm, mm/s -> mm/min)
    toolbit.py, wheel_toolbit.py, addon_bits.py, shape_assets.py
                      the grooving blade and grinding wheel tool bits (classes saved documents store)
    registration.py   the posts in CAM's post list, the tool bit shapes, at FreeCAD's start
    posts/            the lathe, grinder and mill posts
    groove_op.py, cylinder_slot_op.py, plunge_grind_op.py
                      shims: the op classes' paths in documents saved before the ops moved to ops/
"""

__all__ = ["make_groove"]


def __getattr__(name):
    # Loaded on first use: toolbit.py (imported when CAM's tool bits load, and
    # by saved documents) must not pull in the op and its imports of CAM.
    if name == "make_groove":
        from ..ops.groove.api import make_groove

        return make_groove
    raise AttributeError("module %r has no attribute %r" % (__name__, name))
