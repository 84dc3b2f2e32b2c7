"""The Cylinder slot op's reach check (ops/slot/reach.py) inside FreeCAD (1.1 and 1.0).

The Job's default end mill: Diameter 5, CuttingEdgeHeight 30, Length 50 (both
versions). The shaft: R20, Z 0..50; a keyway line along Z at C90 or a sketch of
the developed surface is the path.
"""

import math

import FreeCAD
import Part
import Path.Main.Job as PathJob
import pytest

from freecad_groove import make_cylinder_slot
from freecad_groove.ops.slot.op import op_error

V = FreeCAD.Vector


def _shop(closing, shaft_shape=None, line=None):
    doc = FreeCAD.newDocument("reach")
    closing.append(doc)
    shaft = doc.addObject("Part::Feature", "Shaft")
    shaft.Shape = shaft_shape if shaft_shape is not None else Part.makeCylinder(20, 50)
    keyway = doc.addObject("Part::Feature", "SlotLine")
    keyway.Shape = line if line is not None else Part.makeLine(V(0, 20, 5), V(0, 20, 45))
    doc.recompute()
    job = PathJob.Create("Job", [shaft, keyway])
    job.Tools.Group[0].HorizFeed = "120 mm/min"
    doc.recompute()
    return doc, job, shaft, keyway


def _bit(job, **values):
    tool = job.Tools.Group[0].Tool
    for name, value in values.items():
        setattr(tool, name, value)
    return tool


def _keyway(job, shaft, keyway, depth):
    return make_cylinder_slot(job, (shaft, "Face1"), [(keyway, "Edge1")], depth=depth, passes=2, allowance=0.1,
                              retract=1)


def test_a_slot_deeper_than_the_flutes_is_an_error_naming_depth(closing):
    doc, job, shaft, keyway = _shop(closing)
    _bit(job, CuttingEdgeHeight=3.0)
    op = _keyway(job, shaft, keyway, depth=4)
    assert op_error(op) == ("Depth=4 mm: deeper than the cutting edge of Endmill (CuttingEdgeHeight=3 mm): the "
                            "shank would rub the slot's walls")
    op.Depth = 3.0  # as deep as the flutes: fine
    doc.recompute()
    assert op_error(op) is None and op.Proxy.plan(op).warnings == ()


def test_an_end_mill_without_diameter_is_an_error(closing):
    doc, job, shaft, keyway = _shop(closing)
    _bit(job, Diameter=0.0)
    op = _keyway(job, shaft, keyway, depth=1)
    # CAM's own execute stops before the op at a tool of diameter 0 (a log line); the panel's plan says why
    with pytest.raises(ValueError, match="^ToolController: Endmill has no Diameter: the end mill's diameter is the "
                       "slot's width$"):
        op.Proxy.plan(op)


def test_a_holder_inside_the_parts_largest_radius_is_a_warning(closing):
    """A shoulder of R35 beyond the R20 face: a 10 mm long end mill at the slot's bottom (R18) holds at R28."""
    shoulder = Part.makeCylinder(20, 50).fuse(Part.makeCylinder(35, 10, V(0, 0, 50))).removeSplitter()
    doc, job, shaft, keyway = _shop(closing, shoulder)
    face = next("Face%d" % (i + 1) for i, f in enumerate(shaft.Shape.Faces)
                if isinstance(f.Surface, Part.Cylinder) and abs(f.Surface.Radius - 20) < 1e-9)
    _bit(job, Length=10.0, CuttingEdgeHeight=8.0)
    op = make_cylinder_slot(job, (shaft, face), [(keyway, "Edge1")], depth=2, passes=2, allowance=0.1, retract=1)
    assert op_error(op) is None
    largest = max(35.0, math.hypot(job.Stock.Shape.BoundBox.XMax, job.Stock.Shape.BoundBox.YMax))
    assert op.Proxy.plan(op).warnings == (
        "Endmill (Length=10 mm) at the slot's bottom (radius 18 mm) has its holder at radius 28 mm, inside the "
        "part's largest radius %g mm (model and stock): check that the holder clears the part" % round(largest, 4),)
    _bit(job, Length=40.0)
    doc.recompute()
    assert op.Proxy.plan(op).warnings == ()


def test_a_bit_without_lengths_warns_that_the_reach_is_not_checked(closing):
    doc, job, shaft, keyway = _shop(closing)
    _bit(job, Length=0.0, CuttingEdgeHeight=0.0)
    op = _keyway(job, shaft, keyway, depth=1)
    assert op_error(op) is None
    assert op.Proxy.plan(op).warnings == (
        "Endmill has neither CuttingEdgeHeight nor Length: the end mill's reach is not checked",)


def test_a_sketch_path_may_leave_the_face_by_the_tool_radius_with_a_warning(closing):
    """A keyway run out of the shaft's Z0 end: its centre 2 mm past the end (less than the 2.5 mm radius) is a
    warning naming the overrun (4.5 mm of the slot's side); 3 mm past is an error."""
    import Sketcher

    doc, job, shaft, keyway = _shop(closing)
    assert Sketcher
    sketch = doc.addObject("Sketcher::SketchObject", "Developed")
    sketch.addGeometry(Part.LineSegment(V(-2, 10, 0), V(30, 10, 0)))
    doc.recompute()
    op = make_cylinder_slot(job, (shaft, "Face1"), sketch, depth=1, passes=2, allowance=0.1, retract=1)
    assert op_error(op) is None, op_error(op)
    assert op.Proxy.plan(op).warnings == (
        "the slot runs 4.5 mm past the Z0 end of Shaft.Face1 (the end mill cuts beyond the face)",)
    moves = [c for c in op.Path.Commands if c.Name == "G1"]
    assert min(c.Parameters["Z"] for c in moves) == pytest.approx(-2.0)
    sketch.delGeometry(0)
    sketch.addGeometry(Part.LineSegment(V(-3, 10, 0), V(30, 10, 0)))
    doc.recompute()
    assert op_error(op).startswith("DevelopedSketch: Developed.Edge1 leaves Shaft.Face1 by more than the end "
                                   "mill's radius 2.5 (a point at sketch x = Z -3.0000"), op_error(op)


def test_a_keyway_from_end_to_end_warns_at_both_ends(closing):
    doc, job, shaft, keyway = _shop(closing, line=Part.makeLine(V(0, 20, 0), V(0, 20, 50)))
    op = _keyway(job, shaft, keyway, depth=1)
    assert op_error(op) is None
    # the centre line on the face from end to end: the slot's sides run 2.5 mm past both ends
    assert op.Proxy.plan(op).warnings == (
        "the slot runs 2.5 mm past the Z0 end of Shaft.Face1 (the end mill cuts beyond the face)",
        "the slot runs 2.5 mm past the Z50 end of Shaft.Face1 (the end mill cuts beyond the face)")
