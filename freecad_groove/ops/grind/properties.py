"""The Plunge grind op's properties, declared once (type, name, group,
tooltip, default), and which property each G83 word comes from, so that an
error of the engine names the property to fix.

FreeCAD layer: imports FreeCAD (for the tooltips' translation marker), never Qt.
"""

import FreeCAD

from .bounds import BOUNDS, MAX_WORD  # noqa: F401 - this module's API too

QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP

GROUP = "Plunge grind"
DEFAULT_OVERTRAVEL_MM = 5.0  # past each end of the face: picks happen while the table decelerates, off the face


def _tip(text: str) -> str:
    return QT_TRANSLATE_NOOP("App::Property", text)


PROPERTIES = (
    ("App::PropertyLength", "Allowance", GROUP,
     _tip("Stock left on the face: the wheel grinds from the face + Allowance down to the face (G83 Y = the face)."),
     0.1),
    ("App::PropertyLength", "StartClearance", GROUP,
     _tip("The start point's height above the stock (face + Allowance): the first picks grind air."), 0.05),
    ("App::PropertyLength", "PlungePick", GROUP, _tip("G83 J: the plunge pick at the start (more than 0)."), 0.01),
    ("App::PropertyLength", "CrossoverPlungePick", GROUP,
     _tip("G83 Q: the plunge pick at each crossover; 0 = PlungePick."), 0.0),
    ("App::PropertyLength", "CrossPick", GROUP,
     _tip("G83 K: the cross pick at the primary reversal, at most the wheel's width; 0 = half the wheel's width."),
     0.0),
    ("App::PropertyLength", "SecondaryCrossPick", GROUP,
     _tip("G83 R: the cross pick at the secondary reversal, at most the wheel's width; 0 = CrossPick."), 0.0),
    ("App::PropertyEnumeration", "ReciprocationAxis", GROUP,
     _tip("The FreeCAD axis the wheel reciprocates along (the face's length; the crossover is along the other of "
          "X and Y). The grinder posts' --axes must agree: XZY for X, YZX for Y."), ["X", "Y"]),
    ("App::PropertyLength", "Overtravel", GROUP,
     _tip("How far the wheel runs past each end of the face (the reversal points X and I): picks start while "
          "the reciprocating axis decelerates, so they must happen off the face."), DEFAULT_OVERTRAVEL_MM),
    ("App::PropertyInteger", "SparkOutPasses", GROUP, _tip("G83 L: spark-out passes at the final depth, 0..999."), 1),
    ("App::PropertySpeed", "PlungeFeed", GROUP,
     _tip("G83 F: the plunge and cross pick feed; 0 = the tool controller's VertFeed."), 0.0),
    ("App::PropertySpeed", "ReciprocationFeed", GROUP,
     _tip("G83 E: the reciprocation feed; 0 = the tool controller's HorizFeed."), 0.0),
    ("App::PropertyInteger", "DressProgram", GROUP, _tip("G83 P: the dress program number, 1..9999; 0 = none."), 0),
    ("App::PropertyInteger", "DressCount", GROUP,
     _tip("G83 D: how many times the dress program runs over the cycle (after plunges), 0..999."), 0),
    ("App::PropertyBool", "DressFirst", GROUP, _tip("G83.1: run the dress program before the cycle."), False),
    ("App::PropertyLength", "WheelWidth", GROUP,
     _tip("The wheel's width when the tool bit has no Width (a grinding wheel tool bit gives it)."), 0.0),
    ("App::PropertyLength", "WheelDiameter", GROUP,
     _tip("The wheel's diameter when the tool bit has no Width (a grinding wheel tool bit gives it): the wheel's "
          "body is checked against the part with it; 0 = unknown: not checked (a warning)."), 0.0),
    ("App::PropertyLength", "Retract", GROUP,
     _tip("Rapids above the stock and model by this much (the wheel's lowest point)."), 5.0),
    ("App::PropertyString", "GrindCall", GROUP, _tip("The G83/G83.1 block the op programs (read-only)."), ""),
)
DERIVED = ("GrindCall",)
PROPERTY_NAMES = tuple(p[1] for p in PROPERTIES)

# G83 word -> the op property it comes from (engine errors name both)
WORD_PROPERTIES = {
    "X": "Overtravel", "I": "Overtravel", "Y": "Allowance", "Z": "WheelWidth", "J": "PlungePick",
    "Q": "CrossoverPlungePick", "K": "CrossPick", "R": "SecondaryCrossPick", "L": "SparkOutPasses",
    "F": "PlungeFeed", "E": "ReciprocationFeed", "P": "DressProgram", "D": "DressCount",
}


class GrindInputError(ValueError):
    """A value of the op that cannot make a grind; ``properties`` names the op properties to fix."""

    def __init__(self, message: str, properties: tuple = ()):
        super().__init__(message)
        self.properties = tuple(properties)
