"""The Export tool table command in CAM's GUI: in CAM's menu right after
Check turning, and no toolbar button; it writes the Job's LinuxCNC tool table
to the file chosen, and says in a message box what it cannot write."""

import FreeCAD
import FreeCADGui
import pytest
from gui_helpers import close_shop, make_gui_shop, no_traceback, process, report_view
from parts import face_name
from PySide import QtGui

from freecad_groove import make_groove
from freecad_groove.freecad import toolbit
from freecad_groove.gui import tool_table_command
from freecad_groove.gui.tool_table_command import CommandExportToolTable

TEXT = "Export tool table (LinuxCNC)..."


@pytest.fixture
def shop():
    FreeCADGui.getMainWindow().showMaximized()
    FreeCADGui.activateWorkbench("CAMWorkbench")
    process(0.2)
    doc, job, model = make_gui_shop("ToolTable")
    report_view().clear()
    yield doc, job, model
    close_shop(doc)


def test_the_command_follows_check_turning_in_cams_menu_and_has_no_button(shop):
    window = FreeCADGui.getMainWindow()
    for menu in window.menuBar().findChildren(QtGui.QMenu):
        texts = [a.text().replace("&", "") for a in menu.actions()]
        if "Check turning" in texts:
            assert texts[texts.index("Check turning") + 1] == TEXT, texts
            break
    else:
        raise AssertionError("no menu holds Check turning")
    for toolbar in window.findChildren(QtGui.QToolBar):
        assert TEXT not in [a.text() for a in toolbar.actions()], toolbar.objectName()
    assert CommandExportToolTable().IsActive()


def test_the_jobs_table_is_written_to_the_file_chosen(shop, tmp_path, monkeypatch):
    doc, job, model = shop
    tc = toolbit.make_grooving_tool_controller(job, 3, 0.2)
    make_groove(job, (model, face_name(model.Shape, "cylinder")), tool_controller=tc, position=5, width=4, depth=2,
                infeed=1)
    doc.recompute()
    out = tmp_path / "lathe.tbl"
    monkeypatch.setattr(QtGui.QFileDialog, "getSaveFileName", staticmethod(lambda *a, **k: (str(out), "")))
    FreeCADGui.runCommand(CommandExportToolTable.NAME)
    process()
    lines = out.read_text().splitlines()
    number = int(tc.ToolNumber)
    assert "T%d P%d D0.4 I90 J0 Q2 ;" % (number, number) in "\n".join(lines)
    assert no_traceback("export") is not None


def test_what_cannot_be_written_is_said_in_a_message_box_and_no_file_is_made(shop, tmp_path, monkeypatch):
    doc, job, _model = shop
    tc = toolbit.make_grooving_tool_controller(job, 3, 0.2)  # a blade no op uses: its side is unknown
    said = []
    monkeypatch.setattr(QtGui.QMessageBox, "warning", staticmethod(lambda parent, title, text: said.append(text)))
    out = tmp_path / "lathe.tbl"
    assert not tool_table_command.export(job, str(out))
    assert said and said[0].startswith("%s: no Groove op cuts with its grooving blade" % tc.Label)
    assert not out.exists()
    assert FreeCAD.ActiveDocument is doc
