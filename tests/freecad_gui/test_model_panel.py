"""The Groove task panel on a groove read from the model (FreeCAD 1.1 and 1.0, under Xvfb)."""

import FreeCAD
import FreeCADGui
import pytest
from gui_helpers import (
    buttons_shown,
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


def base_face(shape):
    """The modelled groove's base face: its cylinder of the smallest radius among the groove's faces."""
    faces = []
    for i, face in enumerate(shape.Faces):
        sub = "Face%d" % (i + 1)
        try:
            read_model_groove(shape, sub, "Part")
        except ValueError:
            continue
        if type(face.Surface).__name__ == "Cylinder":
            faces.append((face.Surface.Radius, sub))
    return min(faces)[1]


def test_picking_the_base_face_of_a_modelled_groove_takes_the_models_groove(modelled):
    # issue 21: the box stayed unticked and the panel offered a valid default 4 x 2 groove in the base face,
    # 2 mm below the finished groove
    from freecad_groove.ops.groove.gui.command import CommandGroove

    doc, job, model = modelled
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(doc.Name, model.Name, base_face(model.Shape))
    process()
    FreeCADGui.runCommand(CommandGroove.NAME)
    panel = wait_for(lambda: open_panel(doc), what="the Groove task panel")
    page = panel.groove_page
    wait_for(lambda: page.replans > 0 and not page._timer.isActive(), what="the first preview")
    assert page.model_box().isChecked()  # ticked by the pick: the model's groove
    assert page.field("Width").property("rawValue") == pytest.approx(5.0)
    assert page.error.startswith("ToolWidth:"), page.error  # the Job's end mill: no blade, none made up
    type_into(page.field("ToolWidth"), "2")
    wait_for(lambda: page.error is None and not page._timer.isActive(), what="the groove with a 2 mm blade")
    wait_for(lambda: buttons_shown(panel), what="the buttons")
    task_button(panel, Ok).click()
    wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    process(0.1)
    (op,) = [o for o in job.Operations.Group if hasattr(o, "ModelGroove")]
    want = read_model_groove(model.Shape, base_face(model.Shape), model.Label).values
    assert op.ModelGroove and list(op.ModelOverrides) == [] and list(op.FromModel) == list(MODEL_VALUES)
    assert op.Width.Value == want["Width"] and op.Depth.Value == want["Depth"], (op.Width, op.Depth, want)


def us_customary():
    """The index of FreeCAD's "US customary" unit schema (the one CAM's first-start dialog preselects)."""
    count = len(FreeCAD.Units.listSchemas())
    return next(i for i in range(count) if "US" in FreeCAD.Units.listSchemas(i))


def test_in_us_customary_units_the_models_values_are_never_written_back_rounded(modelled):
    # issue 21: the fields showed 0.20" for 5 mm and OK wrote 5.08 mm back as an override
    doc, job, model = modelled
    op = make_groove(job, (model, base_face(model.Shape)), model_groove=False, position=2, width=3, depth=1,
                     infeed=1, tool_width=2, tool_corner_radius=0.1)
    was = FreeCAD.Units.getSchema()
    FreeCAD.Units.setSchema(us_customary())
    try:
        FreeCADGui.getDocument(doc.Name).setEdit(op.Name)
        panel = wait_for(lambda: open_panel(doc), what="the panel")
        page = panel.groove_page
        wait_for(lambda: page.replans > 0 and buttons_shown(panel), what="the preview")
        assert not page.model_box().isChecked()  # the op's own choice is kept when its panel opens
        page.model_box().click()
        wait_for(lambda: page.error is None and not page._timer.isActive(), what="the model's groove")
        assert '"' in page.field("Width").text() or "in" in page.field("Width").text()  # shown in inches
        task_button(panel, Ok).click()
        wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
        process(0.1)
    finally:
        FreeCAD.Units.setSchema(was)
    doc.recompute()
    want = read_model_groove(model.Shape, base_face(model.Shape), model.Label).values
    assert op.ModelGroove and list(op.ModelOverrides) == [], list(op.ModelOverrides)
    for name in ("Position", "Width", "Depth"):
        assert getattr(op, name).Value == pytest.approx(want[name], abs=1e-9), (name, getattr(op, name))
