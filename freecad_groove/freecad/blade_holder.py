"""What the grooving blade's holder allows: the tool bit's optional holder properties.

A grooving blade tool bit (toolbit.py) carries, beside its shape parameters, four plain properties in its
"Attributes" group (not shape parameters: FreeCAD 1.1 logs "missing parameters" for a shape file, or a shape
installed in its asset store, that lacks a parameter its shape class declares; a plain property is nobody's
parameter). Each is a length; 0, the default, means "not given": nothing is checked, so a tool bit made before
them (saved documents: they have none of them) or without them cuts as before.

==========================  ==========================================================================
FirstCutDiameterMin         a face-grooving blade's smallest first-cut diameter (its curved holder):
                            a face groove whose first plunge cuts below it is refused
FirstCutDiameterMax         its largest: a face groove whose first plunge cuts above it is refused
MinBoreDiameter             an internal grooving bar's smallest bore: an internal groove in a smaller
                            bore is refused
HolderWidth                 the holder's width across the blade, centred on it, beyond the blade's free
                            reach (CuttingEdgeHeight): the turning check draws it and reports it entering
                            standing material
==========================  ==========================================================================

FreeCAD 1.1: the bit's Proxy (toolbit.ToolBitGrooving) adds them whenever CAM sets up its properties (a new
bit, one from the tool library, a restored one; a library's .fctb keeps them with the bit's "Attributes").
FreeCAD 1.0: make_grooving_bit adds them; a bit CAM's 1.0 tool editor makes from the shape file has none
(not given).

FreeCAD layer: FreeCAD only.
"""

from typing import Optional, Tuple

from ..engine.blade_limits import BladeLimits
from .units import length_mm

GROUP = "Attributes"  # where FreeCAD 1.1 keeps a tool bit's non-shape properties (and saves them to .fctb)
PROPERTIES = (
    ("FirstCutDiameterMin", "Face grooving: the smallest first-cut diameter of the blade's curved holder "
                            "(0 = not given: not checked)"),
    ("FirstCutDiameterMax", "Face grooving: the largest first-cut diameter of the blade's curved holder "
                            "(0 = not given: not checked)"),
    ("MinBoreDiameter", "Internal grooving: the smallest bore the bar enters (0 = not given: not checked)"),
    ("HolderWidth", "The holder's width across the blade, centred on it, beyond the free reach "
                    "(CuttingEdgeHeight); the turning check draws it (0 = not given: not drawn)"),
)
NAMES = tuple(name for name, _doc in PROPERTIES)
LIMIT_NAMES = ("FirstCutDiameterMin", "FirstCutDiameterMax", "MinBoreDiameter")


def add_holder_properties(bit: object) -> None:
    """The holder properties on the tool bit ``bit`` (a document object, or CAM 1.1's detached one), those it
    lacks added with 0 (not given)."""
    have = set(getattr(bit, "PropertiesList", ()))
    for name, doc in PROPERTIES:
        if name not in have:
            bit.addProperty("App::PropertyLength", name, GROUP, doc)


def _given(bit: object, name: str) -> Optional[float]:
    """The property in mm, None when the bit has none or it is 0 (not given)."""
    value = getattr(bit, name, None)
    if value is None:
        return None
    mm = length_mm(value)
    return mm if mm > 0 else None


def blade_limits(bit: object) -> Optional[BladeLimits]:
    """The first-cut diameter range and the smallest bore the bit gives (None: it gives none)."""
    values = [_given(bit, name) for name in LIMIT_NAMES]
    if all(value is None for value in values):
        return None
    return BladeLimits(*values, names=LIMIT_NAMES, unit=" mm")


def holder_outline(bit: object) -> Optional[Tuple[float, float]]:
    """(reach, width) in mm of the bit's holder (CuttingEdgeHeight, HolderWidth), None unless both are given."""
    reach, width = _given(bit, "CuttingEdgeHeight"), _given(bit, "HolderWidth")
    if reach is None or width is None:
        return None
    return reach, width
