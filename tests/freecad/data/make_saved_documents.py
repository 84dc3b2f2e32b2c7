"""Makes ops_saved_at_3d18f68.FCStd: a document saved from FreeCAD 1.1's GUI
by commit 3d18f68, the last commit before the ops moved into
freecad_groove/ops/ (one folder per op). The tests open it with the current
code (tests/freecad/test_saved_documents.py headless,
tests/freecad_gui/test_saved_documents.py in the GUI).

It holds one Job per op kind, made as CAM's GUI makes a Job, each op with the
view provider the GUI gives it, so the document stores every class path the
ops had at 3d18f68:

- GrooveJob: the stepped shaft of tests/freecad/parts.py, a grooving tool
  controller (its tool bit: freecad_groove.freecad.toolbit.ToolBitGrooving)
  and two Grooves 8 mm apart on the R20 cylinder
  (freecad_groove.freecad.groove_op.ObjectGroove; view provider
  freecad_groove.gui.task_panel.ViewProvider, page
  freecad_groove.gui.task_panel.GroovePage);
- SlotJob: an R20 cylinder and a helix of one turn on it (a separate model
  object), CAM's default end mill, and a Cylinder slot along the helix
  (freecad_groove.freecad.cylinder_slot_op.ObjectCylinderSlot; view provider
  freecad_groove.gui.slot_view.ViewProviderCylinderSlot);
- GrindJob: a 100 x 40 x 20 block, a grinding wheel tool controller (its bit:
  freecad_groove.freecad.wheel_toolbit.ToolBitGrindingWheel) and a Plunge
  grind of its top face (freecad_groove.freecad.plunge_grind_op.ObjectPlungeGrind;
  view provider freecad_groove.gui.grind_view.ViewProviderPlungeGrind, page
  freecad_groove.gui.grind_panel.PlungeGrindPage).

Only the public scripting calls and the tool bit modules are used, so the
script runs on 3d18f68 and on the current code alike. The file in the tree
was made from an export of 3d18f68 with that export's own
scripts/freecad-roots, which mounts it as the add-on in FreeCAD 1.1's root:

    mkdir -p /tmp/base /tmp/saved && git archive 3d18f68 | tar -x -C /tmp/base
    cp tests/freecad/data/make_saved_documents.py /tmp/saved/
    /tmp/base/scripts/freecad-roots run 1.1 --share /tmp/saved -- sh -c \\
        'exec xvfb-run -a -s "-screen 0 1280x800x24" freecad -M "$FREECAD_GROOVE_CHECKOUT" \\
         "$FREECAD_GROOVE_SHARE/make_saved_documents.py"'
    cp /tmp/saved/ops_saved_at_3d18f68.FCStd tests/freecad/data/

then the programs 3d18f68 posts from it: post_saved_documents.py. It writes
the document and make_saved_documents.log (what it made, or the traceback)
into $FREECAD_GROOVE_SHARE, then ends FreeCAD.

(groove_gui_saved_at_bfb45ff.FCStd, the Groove alone, was made the same way
from bfb45ff by this script as it stood at commit 29b236f.)
"""

import os
import sys
import traceback

DOCUMENT = "ops_saved_at_3d18f68"
# The values the tests expect back (tests/freecad/test_saved_documents.py repeats them).
BLADE_WIDTH, BLADE_CORNER_RADIUS = 2.5, 0.1
GROOVE = dict(position=5, width=4, depth=2, infeed=1, groove_count=2, pitch=8)
SLOT = dict(depth=2, passes=2, allowance=0.2, retract=1)
WHEEL_WIDTH, WHEEL_DIAMETER = 10.0, 150.0
GRIND = dict(depth=0.1, start_clearance=0.05, plunge_pick=0.02, cross_pick=5, spark_out_passes=1,
             plunge_feed="60 mm/min", reciprocation_feed="6000 mm/min")


def _job(doc, label, models):
    import Path.Main.Gui.Job as PathJobGui

    job = PathJobGui.Create(models, openTaskPanel=False)
    job.Label = label
    return job


def _groove_job(doc):
    from parts import face_name, shaft_shape

    from freecad_groove import make_groove
    from freecad_groove.freecad import toolbit

    shaft = doc.addObject("Part::Feature", "Shaft")
    shaft.Shape = shaft_shape()
    doc.recompute()
    job = _job(doc, "GrooveJob", [shaft])
    tc = toolbit.make_grooving_tool_controller(job, BLADE_WIDTH, BLADE_CORNER_RADIUS)
    tc.HorizFeed = tc.VertFeed = "120 mm/min"
    return make_groove(job, (shaft, face_name(shaft.Shape, "cylinder")), tool_controller=tc, **GROOVE)


def _slot_job(doc):
    import FreeCAD
    import Part

    from freecad_groove import make_cylinder_slot

    cylinder = doc.addObject("Part::Feature", "Cylinder")
    cylinder.Shape = Part.makeCylinder(20, 50)
    helix = Part.makeHelix(20.0, 20.0, 20.0)  # pitch, height, radius: one turn from (20, 0, 0)
    helix.translate(FreeCAD.Vector(0, 0, 10))
    line = doc.addObject("Part::Feature", "SlotLine")
    line.Shape = helix
    doc.recompute()
    job = _job(doc, "SlotJob", [cylinder, line])
    tc = job.Tools.Group[0]  # CAM's default end mill: its diameter is the slot's width
    tc.HorizFeed = "120 mm/min"
    tc.SpindleSpeed = 1000
    return make_cylinder_slot(job, (cylinder, "Face1"), [(line, "Edge1")], tool_controller=tc, **SLOT)


def _grind_job(doc):
    import Part

    from freecad_groove import make_plunge_grind
    from freecad_groove.freecad import wheel_toolbit

    block = doc.addObject("Part::Feature", "Block")
    block.Shape = Part.makeBox(100, 40, 20)
    doc.recompute()
    job = _job(doc, "GrindJob", [block])
    tc = wheel_toolbit.make_wheel_tool_controller(job, WHEEL_WIDTH, WHEEL_DIAMETER)
    tc.SpindleSpeed = 3000
    return make_plunge_grind(job, (block, "Face6"), tool_controller=tc, **GRIND)


def make(share, log):
    import FreeCAD
    import FreeCADGui

    sys.path.insert(0, os.path.join(os.environ["FREECAD_GROOVE_CHECKOUT"], "tests", "freecad"))
    FreeCADGui.activateWorkbench("CAMWorkbench")
    doc = FreeCAD.newDocument(DOCUMENT)
    ops = [_groove_job(doc), _slot_job(doc), _grind_job(doc)]
    doc.recompute()
    log.write("FreeCAD %s\n" % ".".join(FreeCAD.Version()[:3]))
    for op in ops:
        error = getattr(op.Proxy, "error", None)
        log.write("op %s (%s) valid %s, error %s, %d commands, view provider %s\n" % (
            op.Name, type(op.Proxy), op.isValid(), error, len(op.Path.Commands), type(op.ViewObject.Proxy)))
        tc = op.ToolController
        bit = tc.Tool
        log.write("  tool controller %s, bit %s (%s)\n" % (tc.Name, bit.Name, type(getattr(bit, "Proxy", None))))
        if error or not op.isValid():
            raise RuntimeError("%s cannot be cut: %s" % (op.Label, error))
    doc.saveAs(os.path.join(share, DOCUMENT + ".FCStd"))
    log.write("saved\n")


def main():
    share = os.environ["FREECAD_GROOVE_SHARE"]
    status = 1
    with open(os.path.join(share, "make_saved_documents.log"), "w") as log:
        try:
            make(share, log)
            status = 0
        except BaseException:  # noqa: B902 - everything goes into the log
            log.write(traceback.format_exc())
    os._exit(status)  # closing the GUI would wait on the unsaved-document dialog


main()
