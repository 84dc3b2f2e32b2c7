"""The Export tool table command: the Job's tool controllers written as a
LinuxCNC lathe tool table (freecad/job_tools.py), in CAM's menu after Check
turning (no toolbar button: an export, used once a setup). The Job is chosen
as for the ops (gui/commands.chosen_job); the file is replaced only when the
whole table is written; what cannot be written is said in one message box.

Not stored in documents: free to move.
"""

import FreeCAD

from .commands import chosen_job, has_job

QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP


def _tr(text: str) -> str:
    return FreeCAD.Qt.translate("FreeCADGroove_ExportToolTable", text)


class CommandExportToolTable:
    NAME = "FreeCADGroove_ExportToolTable"
    TOOLBAR = None  # the menu only
    MENU_AFTER = "FreeCADGroove_CheckTurning"

    def GetResources(self):
        return {
            "MenuText": QT_TRANSLATE_NOOP("FreeCADGroove_ExportToolTable", "Export tool table (LinuxCNC)..."),
            "ToolTip": QT_TRANSLATE_NOOP(
                "FreeCADGroove_ExportToolTable",
                "Write the Job's tool controllers as a LinuxCNC lathe tool table: each grooving blade's "
                "orientation Q from the Groove ops cutting with it, tip diameter D, front and back angles; end "
                "mills and wheels by their diameter. X and Z offsets are touched off on the machine."),
        }

    def IsActive(self):
        return has_job()

    def Activated(self):
        job = chosen_job()
        if job is None:
            return
        export(job)


def export(job: object, path: str = None) -> bool:
    """Write ``job``'s tool table to ``path`` (None: asked in a file dialog); a
    message box says why when it cannot be written. True when written."""
    import FreeCADGui
    from PySide import QtGui

    from ..engine.output.files import write_chunks_atomically
    from ..freecad.job_tools import ToolTableError, linuxcnc_tool_table_of

    window = FreeCADGui.getMainWindow()
    try:
        text = linuxcnc_tool_table_of(job)
    except ToolTableError as exc:
        QtGui.QMessageBox.warning(window, _tr("Export tool table"), str(exc))
        return False
    if path is None:
        path, _filter = QtGui.QFileDialog.getSaveFileName(window, _tr("Export tool table"), job.Label + ".tbl",
                                                          _tr("LinuxCNC tool table (*.tbl)"))
        if not path:
            return False
    try:
        write_chunks_atomically(path, [text], encoding="utf-8")
    except OSError as exc:
        QtGui.QMessageBox.warning(window, _tr("Export tool table"), "%s: %s" % (path, exc.strerror or exc))
        return False
    FreeCAD.Console.PrintMessage("freecad-groove: the tool table of %s written to %s\n" % (job.Label, path))
    return True
