"""The Groove panel on every face of the modelled grooves of model_parts.py
(FreeCAD 1.1 and 1.0, under Xvfb): issue 11's "Done when", in the panel.

What a user does, for each face of each modelled groove (base, flanks,
corner radii and chamfers): select the face in the Job's model, press the
Groove button: "Groove from the model" is ticked by the pick (issue 21: a
groove typed into a modelled groove's face cuts below its finished shape).
The fields must then show the
modelled groove's values, to 0.001 mm and 0.01 degrees: Width, Depth and the
flank angles as the part was modelled (the CYCLE93 call it was built from,
not what the reader says), the corner sizes and kinds; Position as the model
reader gives it; every value marked as from the model. Cancel leaves no op.

The fields show as many decimals as a value has (the model's Position on a
bore with chamfered edges is 6.212132 mm): a field rounded to the user's 2
decimals would show 6.21, no longer count as the model's and, on OK, write
6.21 into the op as an override.
"""

import FreeCADGui
import pytest
from gui_helpers import close_shop, make_gui_shop, open_panel, process, task_button, wait_for
from model_parts import CASES, part_shape
from PySide import QtGui

from freecad_groove import make_groove
from freecad_groove.gui.widgets import ERROR_LABEL
from freecad_groove.ops.groove.gui import panel as task_panel
from freecad_groove.ops.groove.gui.command import CommandGroove
from freecad_groove.ops.groove.model import MODEL_HINT, MODEL_VALUES, read_model_groove
from freecad_groove.ops.groove.properties import CHAMFER_MEASURES

LENGTH_TOL = 0.001  # mm
ANGLE_TOL = 0.01  # degrees
CORNERS = {"EdgeCorner1": "rco1", "EdgeCorner2": "rco2", "BaseCorner1": "rci1", "BaseCorner2": "rci2"}
# rectangular, angled flanks with corner radii, chamfers (CHF and CHR), oblique on a cone, face grooves
# (external, internal, on a steep cone), a bore groove, a cut-off: every case of model_parts.py
PANEL_CASES = sorted(CASES)


def groove_faces(shape, chr_chamfers):
    """{"FaceN": ModelGroove} of the faces of ``shape`` that read as a groove."""
    found = {}
    for i in range(len(shape.Faces)):
        sub = "Face%d" % (i + 1)
        try:
            found[sub] = read_model_groove(shape, sub, "Part", chr_chamfers=chr_chamfers)
        except ValueError:
            continue
    return found


def expected_fields(call):
    """{op property: value} the panel must show for the modelled ``call`` (lengths mm, angles degrees)."""
    values = {"Width": call.widg, "Depth": call.depg, "FlankAngle1": call.ang1, "FlankAngle2": call.ang2}
    for prop, word in CORNERS.items():
        size = getattr(call, word)
        values[prop] = abs(size)
        values[prop + "Type"] = "Radius" if size > 0 else "Chamfer" if size < 0 else "None"
    return values


def open_on_face(doc, model, sub):
    """Select ``sub`` of the Job's model, press the Groove button: the panel's Groove page."""
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(doc.Name, model.Name, sub)
    process()
    FreeCADGui.runCommand(CommandGroove.NAME)
    return wait_for(lambda: open_panel(doc), what="the Groove panel on %s" % sub)


def cancel_shown(panel):
    """Cancel is in the panel's button box and shown (the first panel of a session takes a moment)."""
    button = panel.buttonBox.button(QtGui.QDialogButtonBox.Cancel)
    return button is not None and button.isVisible()


def assert_fields(page, expected, where):
    for prop, value in expected.items():
        widget = page.field(prop)
        if prop.endswith("Type"):
            assert widget.currentData() == value, (where, prop)
        else:
            tol = ANGLE_TOL if prop.startswith("Flank") else LENGTH_TOL
            assert widget.property("rawValue") == pytest.approx(value, abs=tol), (where, prop)
        assert widget.property(task_panel.FROM_MODEL_PROPERTY) is True, (where, prop)


@pytest.mark.parametrize("case", PANEL_CASES)
def test_ticking_groove_from_the_model_shows_the_modelled_values_on_every_face(case):
    call = CASES[case]
    chr_chamfers = call.typ > 10
    doc, job, model = make_gui_shop("ModelPanel_" + case, shape=part_shape(call))
    try:
        faces = groove_faces(model.Shape, chr_chamfers)
        assert len(faces) >= 3, sorted(faces)  # at least the base and the two flanks
        expected = expected_fields(call)
        for sub, groove in sorted(faces.items()):
            panel = open_on_face(doc, model, sub)
            page = panel.groove_page
            assert page.model_box().isChecked()  # the pick of a face of a modelled groove ticked it
            if chr_chamfers:  # the chamfers read again as the measure changes
                page.form.chamferMeasure.setCurrentIndex(page.form.chamferMeasure.findData(CHAMFER_MEASURES[1]))
                process()
            label = page.form.findChild(QtGui.QLabel, task_panel.FROM_MODEL_LABEL)
            assert label.text() == "From the model: " + ", ".join(MODEL_VALUES), (sub, label.text())
            position = {"Position": groove.values["Position"]}
            assert_fields(page, {**expected, **position}, (case, sub))
            before = list(job.Operations.Group)
            wait_for(lambda p=panel: cancel_shown(p), what="Cancel on %s %s" % (case, sub))
            task_button(panel, QtGui.QDialogButtonBox.Cancel).click()
            wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
            process(0.05)
            assert len(job.Operations.Group) == len(before) - 1  # the new op goes with Cancel
            # Not held while the next panel opens: the closed panel's pages hold wrappers of widgets and list
            # items FreeCAD deleted, which the next panel's widgets at those addresses were handed (FreeCAD 1.0
            # segfaulted in fill_combo; qt_wrappers.collect_closed_panels frees only what nothing holds).
            del panel, page, label
    finally:
        close_shop(doc)


def test_ok_on_an_untouched_panel_keeps_the_models_unrounded_values():
    call = CASES["bore"]
    doc, job, model = make_gui_shop("ModelPanelOk", shape=part_shape(call))
    try:
        sub, groove = sorted(groove_faces(model.Shape, False).items())[0]
        position = groove.values["Position"]
        assert round(position, 2) != position  # a value the user's 2 decimals would round
        op = make_groove(job, (model, sub), infeed=1, tool_width=2, tool_corner_radius=0.1)
        FreeCADGui.getDocument(doc.Name).setEdit(op.Name)
        panel = wait_for(lambda: open_panel(doc), what="the panel")
        page = panel.groove_page
        wait_for(lambda: page.replans > 0, what="the preview")
        assert page.field("Position").property("rawValue") == pytest.approx(position, abs=1e-9)
        assert page.field("Position").text().startswith("%.6f" % position)
        task_button(panel, QtGui.QDialogButtonBox.Ok).click()
        wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
        process(0.1)
        doc.recompute()
        assert list(op.ModelOverrides) == [] and list(op.FromModel) == list(MODEL_VALUES)
        assert op.Position.Value == pytest.approx(position, abs=1e-9)
    finally:
        close_shop(doc)


def test_a_corner_radius_unticked_says_tick_groove_from_the_model_and_ticking_it_cuts_the_groove():
    call = CASES["angled_radii"]
    doc, job, model = make_gui_shop("ModelPanelHint", shape=part_shape(call))
    try:
        torus = next("Face%d" % (i + 1) for i, f in enumerate(model.Shape.Faces)
                     if type(f.Surface).__name__ == "Toroid")
        panel = open_on_face(doc, model, torus)
        page = panel.groove_page
        wait_for(lambda: page.replans > 0, what="the first preview")
        assert page.model_box().isChecked()  # ticked by the pick
        replans = page.replans
        page.model_box().click()  # the user unticks it: no groove can be typed into a torus
        wait_for(lambda: page.replans > replans and not page._timer.isActive(), what="the preview after unticking")
        assert page.error is not None and "toroid face" in str(page.error), page.error
        assert str(page.error).endswith(MODEL_HINT), page.error
        error_label = page.form.findChild(QtGui.QLabel, ERROR_LABEL)
        assert 'tick "Groove from the model"' in error_label.text(), error_label.text()
        replans = page.replans
        page.model_box().click()
        wait_for(lambda: page.replans > replans, what="the preview after ticking")
        # the face is fine now; what is left is the Job's default end mill (no grooving blade yet)
        assert page.error is None or str(page.error).startswith("ToolWidth: the blade's width is unknown"), page.error
        assert_fields(page, expected_fields(call), ("angled_radii", torus))
        wait_for(lambda p=panel: cancel_shown(p), what="Cancel")
        task_button(panel, QtGui.QDialogButtonBox.Cancel).click()
        wait_for(lambda: not FreeCADGui.Control.activeDialog(), what="the panel to close")
    finally:
        close_shop(doc)
