"""docs/op-bounds.md lists every numeric property's range exactly as the ops check it (issue 20, item 12), and
the rules the bounds module applies read as the table says (freecad_groove/freecad/bounds.py; no FreeCAD)."""

import math
import os

import pytest
from conftest import ROOT

from freecad_groove.freecad.bounds import Bound, check_bounds, table_rows
from freecad_groove.ops.grind.bounds import BOUNDS as GRIND
from freecad_groove.ops.groove.bounds import BOUNDS as GROOVE
from freecad_groove.ops.groove.bounds import TOOL_BOUNDS as GROOVE_TOOL
from freecad_groove.ops.slot.properties import BOUNDS as SLOT

DOC = os.path.join(ROOT, "docs", "op-bounds.md")
TABLES = [("Groove", GROOVE), ("Groove (tool bit)", GROOVE_TOOL), ("Cylinder slot", SLOT), ("Plunge grind", GRIND)]


def test_the_document_has_one_row_per_bound_of_every_op():
    lines = open(DOC).read().splitlines()
    for op, bounds in TABLES:
        for row in table_rows(op, bounds):
            assert lines.count(row) == 1, row
    table = [line for line in lines if line.startswith("| ") and line.split("|")[1].strip() in dict(TABLES)]
    assert len(table) == sum(len(bounds) for _op, bounds in TABLES)


class Op:
    def __init__(self, **values):
        self.__dict__.update(values)


class Refused(ValueError):
    def __init__(self, message, properties):
        super().__init__(message)
        self.properties = properties


FEED = Bound("FeedPerRev", 0.0, 10.0, "mm/rev", high_open=False)
DEPTH = Bound("Depth", 0.0, 1e6, "mm")
ANGLE = Bound("FlankAngle1", 0.0, 89.999, "°", checker="the engine (ANG1)")


@pytest.mark.parametrize("bound, value, message", [
    (FEED, math.nan, "FeedPerRev=nan: must be a finite number"),
    (FEED, math.inf, "FeedPerRev=inf: must be a finite number"),
    (FEED, -math.inf, "FeedPerRev=-inf: must be a finite number"),
    (FEED, 1e308, "FeedPerRev=1e+308 mm/rev: must be 0 <= FeedPerRev <= 10 mm/rev"),
    (FEED, 10.000001, "FeedPerRev=10.000001 mm/rev: must be 0 <= FeedPerRev <= 10 mm/rev"),
    (FEED, -0.5, "FeedPerRev=-0.5 mm/rev: must be 0 <= FeedPerRev <= 10 mm/rev"),
    (DEPTH, 1e6, "Depth=1000000 mm: must be 0 <= Depth < 1000000 mm"),
    (ANGLE, 1e15, "FlankAngle1=1e+15 °: must be 0 <= FlankAngle1 < 89.999 °"),
    (ANGLE, math.nan, "FlankAngle1=nan: must be a finite number"),
])
def test_a_value_out_of_range_is_refused_naming_the_property_the_value_and_the_rule(bound, value, message):
    with pytest.raises(Refused) as info:
        check_bounds(Op(**{bound.name: value}), [bound], Refused)
    assert str(info.value) == message and info.value.properties == (bound.name,)


@pytest.mark.parametrize("bound, value", [(FEED, 0.0), (FEED, 10.0), (DEPTH, 999999.9), (ANGLE, 95.0),
                                          (ANGLE, -3.0)])
def test_a_value_in_range_or_left_to_its_checker_passes(bound, value):
    check_bounds(Op(**{bound.name: value}), [bound], Refused)  # 95 degrees: the engine names ANG1 itself
