"""Makes groove_gui_saved_at_bfb45ff.FCStd: a document saved by the previous
release (commit bfb45ff) from FreeCAD 1.1's GUI, for the tests that open old
documents with the current code (tests/freecad_gui/test_saved_documents.py).

It holds what only the GUI and the tool bit store: the stepped shaft of
tests/freecad/parts.py in a Job made as CAM's GUI makes it, a grooving tool
controller (freecad_groove.freecad.toolbit.make_grooving_tool_controller: its
tool bit's class path is stored), and a Groove op on the shaft's R20 cylinder
whose view provider (freecad_groove.gui.task_panel.ViewProvider, with the page
class freecad_groove.gui.task_panel.GroovePage) is stored in GuiDocument.xml.

The file in the tree was made from a checkout of bfb45ff (/tmp/baseline) with
that checkout's own scripts/freecad-roots, which mounts it as the add-on in
FreeCAD 1.1's root; this script was copied into the shared directory first:

    mkdir -p /tmp/saved && cp tests/freecad/data/make_saved_documents.py /tmp/saved/
    /tmp/baseline/scripts/freecad-roots run 1.1 --share /tmp/saved -- sh -c \\
        'exec xvfb-run -a -s "-screen 0 1280x800x24" freecad -M "$FREECAD_GROOVE_CHECKOUT" \\
         "$FREECAD_GROOVE_SHARE/make_saved_documents.py"'
    cp /tmp/saved/groove_gui_saved_at_bfb45ff.FCStd tests/freecad/data/

It writes the document and make_saved_documents.log (what it made, or the
traceback) into $FREECAD_GROOVE_SHARE, then ends FreeCAD.
"""

import os
import sys
import traceback

DOCUMENT = "groove_gui_saved_at_bfb45ff"
# The values the tests expect back (test_saved_documents.py repeats them).
BLADE_WIDTH, BLADE_CORNER_RADIUS = 2.5, 0.1
GROOVE = dict(position=5, width=4, depth=2, infeed=1)


def make(share, log):
    import FreeCAD
    import FreeCADGui
    import Path.Main.Gui.Job as PathJobGui

    sys.path.insert(0, os.path.join(os.environ["FREECAD_GROOVE_CHECKOUT"], "tests", "freecad"))
    from parts import face_name, shaft_shape

    from freecad_groove import make_groove
    from freecad_groove.freecad import toolbit

    FreeCADGui.activateWorkbench("CAMWorkbench")
    doc = FreeCAD.newDocument(DOCUMENT)
    shaft = doc.addObject("Part::Feature", "Shaft")
    shaft.Shape = shaft_shape()
    doc.recompute()
    job = PathJobGui.Create([shaft], openTaskPanel=False)
    tc = toolbit.make_grooving_tool_controller(job, BLADE_WIDTH, BLADE_CORNER_RADIUS)
    tc.HorizFeed = tc.VertFeed = "120 mm/min"
    op = make_groove(job, (shaft, face_name(shaft.Shape, "cylinder")), tool_controller=tc, **GROOVE)
    doc.recompute()
    log.write("FreeCAD %s\n" % ".".join(FreeCAD.Version()[:3]))
    log.write("op %s valid %s, %d commands, view provider %s\n" % (
        op.Name, op.isValid(), len(op.Path.Commands), type(op.ViewObject.Proxy)))
    log.write("tool controller %s, bit %s (%s), Width %s, CornerRadius %s\n" % (
        tc.Name, tc.Tool.Name, type(tc.Tool.Proxy), tc.Tool.Width, tc.Tool.CornerRadius))
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
