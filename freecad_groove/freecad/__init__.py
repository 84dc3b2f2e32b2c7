"""The FreeCAD layer of freecad-groove, headless part: the Groove operation.

Imports FreeCAD, Part and Path (never Qt or FreeCADGui), so it works in
``freecadcmd`` scripts. The GUI layer (task panel, commands, view provider)
builds on it.

    faces.py              what a picked face of a turned part means for a groove
    groove_properties.py  the op's properties, declared once, and the errors that name them
    groove_op.py          ObjectGroove (the op's proxy, a class path saved documents store) and Create()
    groove_plan.py        one groove's plan: its start point, the engine's moves, the link to it
    links.py              the safe envelope around the model and the link rapids along it
    api.py                make_groove(): a groove op in a job from a script
    plunge_grind_op.py    ObjectPlungeGrind (a saved class path): a 9/Series G83/G83.1 grind of a flat face
    plunge_grind_properties.py  its properties and the G83 word -> property map for errors
    plunge_grind_api.py   make_plunge_grind(): a plunge grind op from a script
"""

__all__ = ["make_groove"]


def __getattr__(name):
    # Loaded on first use: toolbit.py (imported when CAM's tool bits load, and
    # by saved documents) must not pull in the op and its imports of CAM.
    if name == "make_groove":
        from .api import make_groove

        return make_groove
    raise AttributeError("module %r has no attribute %r" % (__name__, name))
