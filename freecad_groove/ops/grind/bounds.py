"""The Plunge grind op's numeric properties and their ranges (freecad/bounds.py;
the table in docs/op-bounds.md is made from these rows).

FreeCAD layer: plain data.
"""

from ...freecad.bounds import Bound

# The ranges of the numeric properties (freecad/bounds.py; docs/op-bounds.md). Lengths and feeds: below the
# 100000 every G83 word must stay below (engine cycle_words MAX_WORD); the counts: the 9/Series manual's.
MAX_WORD = 100000.0
_WORD = "G83's words are below 100000 (engine cycle_words MAX_WORD)"


def _length(name: str, more: str = "") -> Bound:
    return Bound(name, 0.0, MAX_WORD, "mm", more, _WORD)


BOUNDS = (
    _length("Allowance", "greater than 0 (the op)"),
    _length("StartClearance"),
    _length("PlungePick", "greater than 0 (the op)"),
    _length("CrossoverPlungePick", "0 = PlungePick"),
    _length("CrossPick", "at most the wheel's width; 0 = half the wheel's width (the op)"),
    _length("SecondaryCrossPick", "at most the wheel's width; 0 = CrossPick (the op)"),
    _length("Overtravel"),
    Bound("SparkOutPasses", 0, 999, "", "", "9/Series G83 L: zero to 999", high_open=False,
          checker="the engine (G83 L)"),
    Bound("PlungeFeed", 0.0, MAX_WORD, "mm/min", "0 = the tool controller's VertFeed", _WORD, scale=60.0),
    Bound("ReciprocationFeed", 0.0, MAX_WORD, "mm/min", "0 = the tool controller's HorizFeed", _WORD, scale=60.0),
    Bound("DressProgram", 0, 9999, "", "0 = none", "9/Series G83 P: a program O0001..O9999", high_open=False,
          checker="the engine (G83 P)"),
    Bound("DressCount", 0, 999, "", "", "9/Series G83 D: zero to 999", high_open=False,
          checker="the engine (G83 D)"),
    _length("WheelWidth", "greater than 0 unless the tool bit has a Width (the op)"),
    _length("WheelDiameter", "0 = unknown: the wheel's body is not checked (a warning)"),
    _length("Retract"),
)
