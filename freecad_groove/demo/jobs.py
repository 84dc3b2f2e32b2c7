"""The demo's other Jobs, beside the Groove Job of shaft.py (in mm):

* ``Slot Job``: the same Shaft and a helix of one turn (pitch 20) on its R18
  neck from Z42 (``SlotLine``): a Cylinder slot op mills it 1.5 deep with
  CAM's end mill as a live tool (1000 rpm, 120 mm/min), the C axis turning
  the part: one GSK G7.1 Type II region (``SLOT``).
* ``Grind Job``: a block 100 x 40 x 20 (X, Y, Z) whose top is plunge ground
  0.1 deep with a 10 mm wide wheel at 3000 rpm: one Allen-Bradley grinder
  G83 (``GRIND``).
* ``Mill Job``: a block 100 x 60 x 20 with a pocket 40 x 20 x 5 (X30..70,
  Y20..40, floor Z15), its stock 1 mm above the block, CAM's 5 mm end mill:
  CAM's own Face op on the top (StepDown 0.5) and Pocket Shape op on the
  pocket's floor (StepDown 2, StepOver 50 %), which the milltronics_mill
  post writes as Milltronics G33 (facing) and G34 (pocket).

The blocks stand beside the shaft (``GRIND_AT``, ``MILL_AT``) so that the
document shows the three parts apart.
"""

SLOT_START_Z = 42.0  # the helix starts here on the R18 neck (Z40..65)
SLOT_RADIUS = 18.0
SLOT = dict(depth=1.5, passes=2, allowance=0.2, retract=1)
SLOT_FEED, LIVE_TOOL_RPM = "120 mm/min", 1000

GRIND_AT = (40.0, 100.0, 0.0)
GRIND_SIZE = (100.0, 40.0, 20.0)
WHEEL_RPM = 3000
GRIND = dict(depth=0.1, start_clearance=0.05, plunge_pick=0.02, cross_pick=5, spark_out_passes=1,
             plunge_feed="60 mm/min", reciprocation_feed="6000 mm/min", wheel_width=10)

MILL_AT = (40.0, 30.0, 0.0)
FACE_STEP_DOWN, POCKET_STEP_DOWN = 0.5, 2.0


def _vector(at):
    import FreeCAD

    return FreeCAD.Vector(*at)


def _fail_on_error(ops, op_error, what):
    bad = ["%s: %s" % (op.Label, op_error(op)) for op in ops if op_error(op)]
    if bad:
        raise RuntimeError("%s failed to recompute: %s" % (what, "; ".join(bad)))


def make_slot_job(doc, shaft, neck_face):
    """The Slot Job: ``shaft`` and the helix on its R18 ``neck_face`` ("FaceN"), one Cylinder slot op:
    (job, op)."""
    import Part
    import Path.Main.Job as PathJob

    from ..ops.slot.api import make_cylinder_slot
    from ..ops.slot.op import op_error

    helix = Part.makeHelix(20.0, 20.0, SLOT_RADIUS)  # pitch, height, radius: one turn from (18, 0, 0)
    helix.translate(_vector((0, 0, SLOT_START_Z)))
    line = doc.addObject("Part::Feature", "SlotLine")
    line.Shape = helix
    doc.recompute()
    job = PathJob.Create("SlotJob", [shaft, line])
    job.Label = "Slot Job"
    tc = job.Tools.Group[0]
    tc.Label = "TC: Live tool end mill"
    tc.HorizFeed = SLOT_FEED
    tc.SpindleSpeed = LIVE_TOOL_RPM
    doc.recompute()
    op = make_cylinder_slot(job, (shaft, neck_face), [(line, "Edge1")], name="CylinderSlot", tool_controller=tc,
                            recompute=False, coolant_mode="Flood", **SLOT)
    op.Label = "Helical slot"
    doc.recompute()
    _fail_on_error([op], op_error, "the Cylinder slot op")
    return job, op


def make_grind_job(doc):
    """The Grind Job: a block and one Plunge grind op on its top: (job, op)."""
    import Part
    import Path.Main.Job as PathJob

    from ..ops.grind.api import make_plunge_grind
    from ..ops.grind.op import op_error

    block = doc.addObject("Part::Feature", "GrindBlock")
    block.Shape = Part.makeBox(*GRIND_SIZE, _vector(GRIND_AT))
    doc.recompute()
    job = PathJob.Create("GrindJob", [block])
    job.Label = "Grind Job"
    tc = job.Tools.Group[0]
    tc.Label = "TC: Grinding wheel"
    tc.SpindleSpeed = WHEEL_RPM  # the grinder posts refuse a wheel that does not turn
    doc.recompute()
    top = _face_at(block.Shape, GRIND_AT[2] + GRIND_SIZE[2], (GRIND_AT[0], GRIND_AT[0] + GRIND_SIZE[0]))
    op = make_plunge_grind(job, (block, top), name="PlungeGrind", tool_controller=tc, recompute=False, **GRIND)
    op.Label = "Plunge grind top"
    doc.recompute()
    _fail_on_error([op], op_error, "the Plunge grind op")
    return job, op


def _face_at(shape, z, x_range):
    """"FaceN" of the flat face of ``shape`` at height ``z`` whose centre's X is in ``x_range``."""
    for index, face in enumerate(shape.Faces):
        box = face.BoundBox
        if abs(box.ZMin - z) < 1e-6 and abs(box.ZMax - z) < 1e-6 and x_range[0] <= box.Center.x <= x_range[1]:
            return "Face%d" % (index + 1)
    raise RuntimeError("the demo's block has no flat face at Z%g" % z)


def _mill_block():
    import Part

    pocket = Part.makeBox(40, 20, 5, _vector((30, 20, 15)))
    shape = Part.makeBox(100, 60, 20).cut(pocket)
    shape.translate(_vector(MILL_AT))
    return shape


def make_mill_job(doc):
    """The Mill Job: a block with a pocket, CAM's Face op on its top and Pocket Shape op on the pocket's floor:
    (job, [face op, pocket op])."""
    import FreeCAD
    import Path.Main.Job as PathJob
    import Path.Op.MillFace as MillFace
    import Path.Op.PocketShape as PocketShape

    block = doc.addObject("Part::Feature", "MillBlock")
    block.Shape = _mill_block()
    doc.recompute()
    job = PathJob.Create("MillJob", [block])
    job.Label = "Mill Job"
    doc.recompute()
    model = job.Model.Group[0]
    tc = job.Tools.Group[0]
    tc.HorizFeed, tc.VertFeed, tc.SpindleSpeed = 10.0, 5.0, 3000.0  # mm/s, mm/s, rpm
    x_range = (MILL_AT[0], MILL_AT[0] + 100)
    face = MillFace.Create("Face", parentJob=job)
    face.Base = [(model, [_face_at(model.Shape, 20.0, x_range)])]
    face.ZigZagAngle = 0.0
    pocket = PocketShape.Create("Pocket", parentJob=job)
    pocket.Base = [(model, [_face_at(model.Shape, 15.0, (x_range[0] + 25, x_range[0] + 75))])]
    # FreeCAD 1.1 renamed OffsetPattern to ClearingPattern; "Offset" and StepOver 50 % are 1.1's defaults
    pattern = "ClearingPattern" if hasattr(pocket, "ClearingPattern") else "OffsetPattern"
    setattr(pocket, pattern, "Offset")
    pocket.StepOver = 50
    for op, step in ((face, FACE_STEP_DOWN), (pocket, POCKET_STEP_DOWN)):
        op.setExpression("StepDown", None)  # CAM's default: the tool's diameter
        op.StepDown = step
    doc.recompute()
    bad = [op.Label for op in (face, pocket) if not op.isValid() or not op.Path.Commands]
    if bad:
        raise RuntimeError("CAM's %s op(s) made no Path in FreeCAD %s" % (", ".join(bad), ".".join(
            FreeCAD.Version()[:3])))
    return job, [face, pocket]
