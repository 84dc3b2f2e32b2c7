"""freecad-groove: lathe grooving and canned cycles for FreeCAD's CAM workbench.

``freecad_groove.engine`` is the pure-Python cycle engine (no FreeCAD import);
the FreeCAD operation and GUI layers import FreeCAD only when they are used.
"""

__version__ = "0.1.0"
