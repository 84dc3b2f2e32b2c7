"""Every numeric property of every op, swept through the values FreeCAD lets a
script or an expression set (issue 20, items 6 and 12): NaN, infinities, the
largest numbers, 0 and a negative number. The op ends either valid or with one
line naming the property (op_error); it never lets an exception escape its
execute (FreeCAD would mark it Invalid after a Python traceback), never writes
a non-finite number into its Path, and the document stays valid: set back, the
op recomputes clean.

The properties are read from each op's own declaration (PROPERTIES), so a new
numeric property is swept without a change here. Run inside FreeCAD 1.1 and
1.0 (tests/freecad/run_suite.py).
"""

import math

import FreeCAD
import Part
import Path.Main.Job as PathJob
import pytest
from parts import face_name, make_shop

from freecad_groove import make_cylinder_slot, make_groove, make_plunge_grind
from freecad_groove.freecad.addon_op import op_error
from freecad_groove.ops.grind import properties as grind_properties
from freecad_groove.ops.groove import properties as groove_properties
from freecad_groove.ops.slot import properties as slot_properties

V = FreeCAD.Vector
NUMERIC = ("App::PropertyLength", "App::PropertyDistance", "App::PropertyAngle", "App::PropertyFloat",
           "App::PropertySpeed", "App::PropertyInteger", "App::PropertyIntegerConstraint")
SWEEP = (float("nan"), float("inf"), float("-inf"), 1e308, 0.0, -1.0)
GROOVE = dict(position=5, width=4, depth=2, infeed=1, tool_width=3, tool_corner_radius=0.2)


def _numeric(declared, derived):
    return [row[1] for row in declared if row[0] in NUMERIC and row[1] not in derived]


GROOVE_PROPERTIES = _numeric(groove_properties.PROPERTIES, groove_properties.DERIVED)
SLOT_PROPERTIES = _numeric([(t, n) for t, n, _tip, _d in slot_properties.PROPERTIES], slot_properties.DERIVED)
GRIND_PROPERTIES = _numeric(grind_properties.PROPERTIES, grind_properties.DERIVED)


def groove_shop():
    doc = FreeCAD.newDocument("SweepGroove")
    doc, shaft, job, tc = make_shop(doc)
    op = make_groove(job, (shaft, face_name(shaft.Shape, "cylinder")), **GROOVE)
    return doc, op, [shaft, job, tc]


def slot_shop():
    doc = FreeCAD.newDocument("SweepSlot")
    shaft = doc.addObject("Part::Feature", "Shaft")
    shaft.Shape = Part.makeCylinder(20, 50)
    line = doc.addObject("Part::Feature", "SlotLine")
    line.Shape = Part.makeLine(V(20, 0, 5), V(20, 0, 45))
    doc.recompute()
    job = PathJob.Create("Job", [shaft, line])
    tc = job.Tools.Group[0]
    tc.HorizFeed = "120 mm/min"
    tc.SpindleSpeed = 1000
    doc.recompute()
    op = make_cylinder_slot(job, (shaft, "Face1"), [(line, "Edge1")], depth=1, passes=2, allowance=0.1, retract=1)
    return doc, op, [shaft, line, job, tc]


def grind_job():
    doc = FreeCAD.newDocument("SweepGrind")
    block = doc.addObject("Part::Feature", "Block")
    block.Shape = Part.makeBox(100, 40, 20)
    doc.recompute()
    job = PathJob.Create("Job", [block])
    job.Tools.Group[0].SpindleSpeed = 3000
    doc.recompute()
    return doc, block, job


def grind_shop():
    doc, block, job = grind_job()
    op = make_plunge_grind(job, (block, "Face6"), depth=0.1, plunge_pick=0.02, cross_pick=5, wheel_width=10,
                           plunge_feed="60 mm/min", reciprocation_feed="6000 mm/min")
    return doc, op, [block, job, job.Tools.Group[0]]


SHOPS = {"groove": groove_shop, "slot": slot_shop, "grind": grind_shop}


@pytest.fixture(scope="module")
def shops():
    """One document per op kind for the whole sweep (each case sets its property back)."""
    made = {}

    def get(kind):
        if kind not in made:
            made[kind] = SHOPS[kind]()
        return made[kind]

    yield get
    for doc, _op, _others in made.values():
        FreeCAD.closeDocument(doc.Name)


def path_numbers(op):
    return [value for command in op.Path.Commands for value in command.Parameters.values()]


def moves(op):
    return [c.Name for c in op.Path.Commands if not c.Name.startswith("(") and c.Name != "G18"]


@pytest.mark.parametrize("kind, name", [("groove", n) for n in GROOVE_PROPERTIES]
                         + [("slot", n) for n in SLOT_PROPERTIES] + [("grind", n) for n in GRIND_PROPERTIES])
def test_every_numeric_property_ends_valid_or_named_never_a_traceback_nor_a_non_finite_path(shops, kind, name):
    doc, op, others = shops(kind)
    assert op_error(op) is None, op_error(op)
    old = getattr(op, name)
    seen = []
    try:
        for value in SWEEP:
            try:
                setattr(op, name, value)
            except Exception:  # FreeCAD refuses it (an integer property and NaN): it never reaches the op
                seen.append((value, "refused by FreeCAD"))
                continue
            doc.recompute()
            error = op_error(op)
            assert op.isValid(), (name, value, op.getStatusString())  # nothing escaped execute
            assert all(math.isfinite(v) for v in path_numbers(op)), (name, value, op.Path.toGCode())
            if error is not None:
                assert name in error and "\n" not in error, (name, value, error)
                assert not error.split(":")[0].endswith("Error"), (name, value, error)  # no bare exception
                assert moves(op) == [], (name, value)
            seen.append((value, error))
            for other in others:
                assert other.isValid(), (name, value, other.Name)
    finally:
        setattr(op, name, old)
        doc.recompute()
    assert op_error(op) is None, (name, op_error(op))  # the document stays valid: set back, the op cuts again
    assert moves(op)
    assert seen[0][1] is not None, seen  # NaN never passes: FreeCAD refuses it, or the op names the property
