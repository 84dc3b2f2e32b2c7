"""The Groove task panel on a groove read from the model (FreeCAD 1.1 and 1.0, under Xvfb)."""

import FreeCAD
import FreeCADGui
import pytest
from gui_helpers import (
    close_shop,
    make_gui_shop,
    open_panel,
    process,
    screenshot,
    show_part,
    task_button,
    type_into,
    version,
    wait_for,
)
from model_parts import CASES, part_shape
from PySide import QtGui

from freecad_groove import make_groove
from freecad_groove.freecad import faces as faces_mod
from freecad_groove.ops.groove.gui import panel as task_panel
from freecad_groove.ops.groove.gui.view import TurnedFaceGate
from freecad_groove.ops.groove.model import MODEL_VALUES, read_model_groove

Ok = QtGui.QDialogButtonBox.Ok


@pytest.fixture
def modelled():
    """(doc, job, model): a shaft R20 with the angled, radiused groove of model_parts in a GUI Job."""
    doc, job, model = make_gui_shop("ModelGrooveGui")
    doc.getObject("Shaft").Shape = part_shape(CASES["angled_radii"])
    doc.recompute()
    show_part(doc)
    yield doc, job, job.Model.Group[0]
    close_shop(doc)


def groove_face(shape):
    for i in range(len(shape.Faces)):
        try:
            read_model_groove(shape, "Face%d" % (i + 1), "Part")
            return "Face%d" % (i + 1)
        except ValueError:
            continue
    raise AssertionError("no face of a groove")


def test_the_panel_shows_the_values_from_the_model_and_an_edit_overrides_one(modelled):
    doc, job, model = modelled
    op = make_groove(job, (model, groove_face(model.Shape)), infeed=1, tool_width=2, tool_corner_radius=0.1)
    assert list(op.FromModel) == list(MODEL_VALUES)
    FreeCADGui.getDocument(doc.Name).setEdit(op.Name)
    panel = wait_for(lambda: open_panel(doc), what="the panel")
    page = panel.groove_page
    wait_for(lambda: page.replans > 0, what="the preview")
    assert page.model_box().isChecked()
    label = page.form.findChild(QtGui.QLabel, task_panel.FROM_MODEL_LABEL)
    assert label.isVisible() and label.text() == "From the model: " + ", ".join(MODEL_VALUES)
    assert page.field("Width").property(task_panel.FROM_MODEL_PROPERTY) is True
    assert page.field("Width").property("rawValue") == pytest.approx(5.0)
    assert page.field("BaseCorner1Type").currentData() == "Radius"
    assert page.error is None, page.error
    type_into(page.field("Depth"), "3 mm")
    wait_for(lambda: "Depth" not in label.text(), what="Depth to leave the model's list")
    assert page.field("Depth").property(task_panel.FROM_MODEL_PROPERTY) is False
    screenshot("%s-model-groove" % version())
    task_button(panel, Ok).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    process(0.1)
    FreeCAD.ActiveDocument.recompute()
    assert list(op.ModelOverrides) == ["Depth"]
    assert op.Depth.Value == pytest.approx(3.0) and op.Width.Value == pytest.approx(5.0)
    assert "Depth" not in op.FromModel and "Width" in op.FromModel


def test_a_corner_radius_of_a_modelled_groove_can_be_picked(modelled):
    doc, job, model = modelled
    gate = TurnedFaceGate()
    torus = next("Face%d" % (i + 1) for i, f in enumerate(model.Shape.Faces) if type(f.Surface).__name__ == "Toroid")
    with pytest.raises(ValueError, match="toroid face"):  # no face a groove is cut into ...
        faces_mod.analyse_face(model.Shape.getElement(torus), torus)
    assert gate.allow(doc, model, torus)  # ... but a face of a modelled groove
