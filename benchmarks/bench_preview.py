"""GUI benchmark of the Groove task panel's live preview: prints figures,
asserts nothing. Runs in FreeCAD's GUI under Xvfb (benchmarks/bench_preview.sh).

For the stepped shaft of the tests (tests/freecad/parts.py) in a Job, the
Groove command is run on a face and the Width field is typed into, key by key
as a user would (tests/freecad_gui/gui_helpers.py), alternating between two
values, 30 times per case. Measured: the time from the key press that
completes the value to the preview showing the new grooves (drawn in the 3D
view: the event loop runs until the preview's redraw count moves, then once
more so Coin renders it). It includes the panel's 20 ms coalescing delay.
Cases: one groove on the cylinder, one on the cone, 10 grooves on the
cylinder (GrooveCount 10). Target (issue 4): within 100 ms.

The figures go to FreeCAD's console and to bench_preview.txt in
$FREECAD_GROOVE_SHARE.
"""

import os
import statistics
import sys
import time
import traceback

REPEATS = 30


def _bench():
    import FreeCAD
    import FreeCADGui

    checkout = os.environ.get("FREECAD_GROOVE_CHECKOUT", os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    sys.path.insert(0, os.path.join(checkout, "tests", "freecad_gui"))
    from gui_helpers import key_of, make_gui_shop, press, process, start_groove_command, wait_for

    FreeCADGui.getMainWindow().showMaximized()
    FreeCADGui.activateWorkbench("CAMWorkbench")
    process(0.2)
    version = ".".join(FreeCAD.Version()[:3])
    lines = ["freecad-groove preview benchmark, FreeCAD %s, %s" % (version, sys.version.split()[0]),
             "time from the last key press of a new Width to the redrawn preview (median / min / max of %d):" % REPEATS]
    for label, face, count in (("cylinder, 1 groove", "cylinder", 1), ("cone, 1 groove", "cone_up", 1),
                               ("cylinder, 10 grooves", "cylinder", 10)):
        doc, job, model = make_gui_shop("Bench")
        panel = start_groove_command(doc, model, face)
        page = panel.groove_page
        if count > 1:
            page.field("Pitch").setProperty("rawValue", 1.5)
            page.field("Width").setProperty("rawValue", 3.5)
            page.field("Position").setProperty("rawValue", 0.0)
            page.field("GrooveCount").setValue(count)
            wait_for(lambda page=page, count=count: page.error is None and len(page.preview.sections) == count,
                     what="the grooves")
        field = page.field("Width")
        times = []
        for i in range(REPEATS):
            text = "3.5" if i % 2 else "3.25"
            field.setFocus()
            field.selectAll()
            for char in text[:-1]:
                press(field, key_of(char), char)
            process()
            before = page.preview.updates
            t0 = time.perf_counter()
            press(field, key_of(text[-1]), text[-1])
            wait_for(lambda page=page, before=before: page.preview.updates > before, what="the redraw")
            process()  # and let Coin draw the changed scene
            times.append((time.perf_counter() - t0) * 1000.0)
            assert page.error is None, page.error
        lines.append("  %-22s %6.1f ms / %6.1f / %6.1f  (%d grooves, %d preview segments)" % (
            label, statistics.median(times), min(times), max(times), len(page.preview.sections),
            len(page.preview.feeds) + len(page.preview.rapids)))
        panel.reject()
        process()
        FreeCAD.closeDocument(doc.Name)
    return lines


def _main():
    share = os.environ.get("FREECAD_GROOVE_SHARE", ".")
    try:
        lines = _bench()
        status = 0
    except Exception:
        lines = ["bench_preview failed:", traceback.format_exc()]
        status = 1
    text = "\n".join(lines) + "\n"
    import FreeCAD

    FreeCAD.Console.PrintMessage(text)
    with open(os.path.join(share, "bench_preview.txt"), "w") as f:
        f.write(text)
    os._exit(status)


from PySide import QtCore  # noqa: E402

QtCore.QTimer.singleShot(0, _main)
