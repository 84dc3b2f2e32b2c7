"""The Check turning task panel: verify_job() on a Job (check.py), the
figures per op, and the resulting half section drawn in the 3D view over the
part (preview.py). "Stock" chooses what the ops start from (the Job's stock,
or the part as turned: check.STOCKS; the figures' first note says which);
"Check again" (or the command once more) runs the check anew after a change;
Close takes the drawing away.
"""

import FreeCAD
import FreeCADGui
from PySide import QtGui

from .preview import SectionDrawing

translate = FreeCAD.Qt.translate
_open_panel = None  # the TurningPanel shown in the task view, if any


class TurningPanel:
    """The task panel: the figures per op (the check's summary), Check again, Close."""

    def __init__(self, job):
        self.job = job
        self.form = QtGui.QWidget()
        self.form.setWindowTitle(translate("FreeCADGroove_CheckTurning", "Turning check"))
        layout = QtGui.QVBoxLayout(self.form)
        from ..check import STOCKS

        self.stock = QtGui.QComboBox()
        self.stock.setObjectName("stock")
        self.stock.setToolTip(translate("FreeCADGroove_CheckTurning", "What the ops start from: the Job's stock, "
                                        "or the part as turned (the model's contour plus the grooves' material), "
                                        "which a grooving op assumes"))
        for key, text in STOCKS.items():
            self.stock.addItem(translate("FreeCADGroove_CheckTurning", "Stock: %s" % text), key)
        self.stock.currentIndexChanged.connect(lambda *_a: self.check())
        layout.addWidget(self.stock)
        self.figures = QtGui.QPlainTextEdit()
        self.figures.setObjectName("figures")
        self.figures.setReadOnly(True)
        self.again = QtGui.QPushButton(translate("FreeCADGroove_CheckTurning", "Check again"))
        self.again.setObjectName("check_again")
        self.again.clicked.connect(self.check)
        layout.addWidget(self.figures)
        layout.addWidget(self.again)
        gui_doc = FreeCADGui.getDocument(job.Document.Name)
        self.drawing = SectionDrawing(gui_doc.ActiveView if gui_doc is not None else None)
        self.result = None
        self.runs = 0
        self.check()

    def check(self):
        """Run verify_job and show its result; its message when the Job cannot be checked."""
        from ..check import TurningCheckError, verify_job

        try:
            self.result = verify_job(self.job, stock=self.stock.currentData())
            text = self.result.summary()
        except TurningCheckError as e:
            self.result, text = None, str(e)
        self.runs += 1
        self.figures.setPlainText(text)
        self.drawing.show(self.result)
        FreeCAD.Console.PrintMessage(text + "\n")

    def getStandardButtons(self):
        return QtGui.QDialogButtonBox.Close

    def _close(self):
        global _open_panel
        self.drawing.remove()
        if _open_panel is self:
            _open_panel = None
        FreeCADGui.Control.closeDialog()
        return True

    def reject(self):
        return self._close()

    def accept(self):
        return self._close()


def open_panel(job: object) -> object:
    """The panel checking ``job``: the one open, checking again, or a new one in the task view."""
    global _open_panel
    if _open_panel is not None and FreeCADGui.Control.activeDialog():  # a second run: the new result
        _open_panel.job = job
        _open_panel.check()
        return _open_panel
    if FreeCADGui.Control.activeDialog():
        FreeCADGui.Control.closeDialog()
    _open_panel = TurningPanel(job)
    FreeCADGui.Control.showDialog(_open_panel)
    return _open_panel
