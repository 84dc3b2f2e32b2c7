"""The Check turning command in FreeCAD's GUI (1.1 and 1.0, under Xvfb).

What a user does: a Job with a Groove op, press Check turning: the task
panel lists the figures per op and the 3D view shows the stock left (grey);
then the op's Path is changed to plunge 1 mm too deep and Check again shows
the gouge (red) and where; the command pressed once more runs again in the
same panel; Close takes the drawing away. Screenshots of both checks.
"""

import FreeCAD
import FreeCADGui
import Path
import Path.Main.Stock as PathStock
import pytest
from gui_helpers import (  # noqa: E402
    close_shop,
    make_gui_shop,
    process,
    roomy_task_panel,
    screenshot,
    show_part,
    version,
    wait_for,
    zoom_to,
)
from parts import face_name  # noqa: E402
from pylib import require_shapely  # noqa: E402
from PySide import QtGui

from freecad_groove import make_groove  # noqa: E402
from freecad_groove.ops.turning_check.gui import panel as turning_panel  # noqa: E402
from freecad_groove.ops.turning_check.gui.command import CommandCheckTurning  # noqa: E402


@pytest.fixture(scope="module", autouse=True)
def cam_workbench():
    FreeCADGui.getMainWindow().showMaximized()
    FreeCADGui.activateWorkbench("CAMWorkbench")
    process(0.2)


@pytest.fixture
def shop():
    """(doc, job, op): the stepped shaft in a GUI-made Job, stock a bar R20 Z0..60, a groove 4 x 2 at Z21..25."""
    require_shapely()
    doc, job, model = make_gui_shop("TurningGui")
    old = job.Stock
    job.Stock = PathStock.CreateCylinder(job, 20.0, 60.0, FreeCAD.Placement())
    doc.removeObject(old.Name)
    op = make_groove(job, (model, face_name(model.Shape, "cylinder")), position=5, width=4, depth=2, infeed=1,
                     tool_width=3, tool_corner_radius=0.2)
    doc.recompute()
    show_part(doc)
    yield doc, job, op
    close_shop(doc)


def test_command_sits_in_cams_project_setup_after_sanity(shop):
    toolbars = [tb for tb in FreeCADGui.getMainWindow().findChildren(QtGui.QToolBar) if tb.isVisible()]
    setup = next(tb for tb in toolbars if tb.objectName() == CommandCheckTurning.TOOLBAR)
    assert "Check turning" in [a.text() for a in setup.actions()]
    sanity = FreeCADGui.Command.get(CommandCheckTurning.MENU_AFTER).getInfo()["menuText"].replace("&", "")
    for menu in FreeCADGui.getMainWindow().menuBar().findChildren(QtGui.QMenu):
        texts = [a.text().replace("&", "") for a in menu.actions()]
        if sanity in texts:
            assert texts[texts.index(sanity) + 1] == "Check turning", texts
            break
    else:
        raise AssertionError("no menu holds %s" % sanity)
    assert CommandCheckTurning().IsActive()


def plunge_deeper(op):
    """The op's Path with its plunges at Z21 ending at X17 instead of X18 (the groove's base)."""
    commands = []
    for command in op.Path.Commands:
        words = dict(command.Parameters)
        if command.Name == "G1" and abs(words.get("X", 0) - 18.0) < 1e-9 and abs(words.get("Z", 0) - 21.0) < 1e-9:
            words["X"] = 17.0
        commands.append(Path.Command(command.Name, words))
    op.Path = Path.Path(commands)


def test_check_turning_shows_the_section_then_the_gouge(shop):
    doc, job, op = shop
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.runCommand(CommandCheckTurning.NAME)
    panel = wait_for(lambda: turning_panel._open_panel, what="the Turning check panel")
    roomy_task_panel()
    text = panel.figures.toPlainText()
    assert "%s: ok" % op.Label in text and "no gouge" in text and "removed 7.98" in text, text
    assert panel.drawing.in_scene() and panel.drawing.drawn["remaining"] and not panel.drawing.drawn["gouge"]
    # 6.2 mm of feed at 120 mm/min (3.1 s): two plunges from X21 (VRT over the contour) to X18, each 2 mm
    # fed, then 1.1 from the re-entry 0.1 above the chip break; the free-off between them is a rapid
    assert op.CycleTime == "00:00:03"
    job.Stock.ViewObject.Visibility = False  # the drawn section is the stock left
    zoom_to(doc, 17.0, 23.0, 16.0)
    screenshot("%s-turning-check-ok" % version())

    plunge_deeper(op)
    panel.again.click()
    process()
    text = panel.figures.toPlainText()
    assert "%s: PROBLEMS" % op.Label in text and "GOUGE" in text and "1.0000 mm deep at X17." in text, text
    assert panel.drawing.drawn["gouge"] and panel.runs == 2
    screenshot("%s-turning-check-gouge" % version())

    FreeCADGui.runCommand(CommandCheckTurning.NAME)  # pressed again: the same panel, checked anew
    process()
    assert turning_panel._open_panel is panel and panel.runs == 3
    panel.reject()
    process()
    assert not panel.drawing.in_scene() and turning_panel._open_panel is None
    assert not FreeCADGui.Control.activeDialog()


def test_the_panel_offers_the_part_as_turned_as_the_stock_and_says_which_it_used(shop):
    doc, job, op = shop
    old = job.Stock  # a bar R25 around the R20 part: the op's rapids go down through it
    job.Stock = PathStock.CreateCylinder(job, 25.0, 60.0, FreeCAD.Placement())
    doc.removeObject(old.Name)
    doc.recompute()
    FreeCADGui.runCommand(CommandCheckTurning.NAME)
    panel = wait_for(lambda: turning_panel._open_panel, what="the Turning check panel")
    text = panel.figures.toPlainText()
    assert "stock: a bar R25.000" in text and "RAPID THROUGH STOCK" in text, text
    runs = panel.runs
    panel.stock.setCurrentIndex(panel.stock.findData("turned"))  # as the user picks it in the combo box
    wait_for(lambda: panel.runs > runs, what="the check with the part as turned")
    text = panel.figures.toPlainText()
    assert "stock: the part as turned" in text and "RAPID THROUGH STOCK" not in text and "%s: ok" % op.Label in text
    panel.reject()
    process()
