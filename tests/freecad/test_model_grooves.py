"""Grooves read from the modelled part (freecad/model_grooves.py, the op's
ModelGroove): parts whose section carries the profile of a known CYCLE93
call (model_parts.py), every face of the groove picked in turn."""

import dataclasses

import FreeCAD
import pytest
from model_parts import CASES, part_shape, undercut_shape
from parts import make_shop

from freecad_groove import make_groove
from freecad_groove.engine.cycles.cycle93_recognize import profile_elements
from freecad_groove.freecad.groove_op import op_error
from freecad_groove.freecad.model_grooves import MODEL_VALUES, read_model_groove

FIELDS = ("axfa", "axsa", "widg", "depg", "angc", "ang1", "ang2", "rco1", "rco2", "rci1", "rci2", "typ")
LENGTH_TOL = 0.001  # mm: the "to 0.001 mm / 0.01 degrees"
ANGLE_TOL = 0.01
CORNERS = {"EdgeCorner1": "rco1", "EdgeCorner2": "rco2", "BaseCorner1": "rci1", "BaseCorner2": "rci2"}


@pytest.fixture
def doc():
    d = FreeCAD.newDocument("ModelGrooveTest")
    name = d.Name
    FreeCAD.setActiveDocument(name)
    yield d
    if name in FreeCAD.listDocuments():
        FreeCAD.closeDocument(name)


def assert_call(found, call):
    for name in FIELDS:
        tol = ANGLE_TOL if name.startswith("ang") else LENGTH_TOL
        assert getattr(found, name) == pytest.approx(getattr(call, name), abs=tol), name


def groove_faces(shape, label="Part"):
    """{"FaceN": ModelGroove} of the faces that read as a groove; the others' errors."""
    found, refused = {}, {}
    for i in range(len(shape.Faces)):
        sub = "Face%d" % (i + 1)
        try:
            found[sub] = read_model_groove(shape, sub, label, chr_chamfers=False)
        except ValueError as e:
            refused[sub] = str(e)
    return found, refused


@pytest.mark.parametrize("case", sorted(CASES))
def test_every_face_of_a_modelled_groove_reads_as_its_call(case):
    call = CASES[case]
    shape = part_shape(call)
    found = {}
    for i in range(len(shape.Faces)):
        sub = "Face%d" % (i + 1)
        try:
            found[sub] = read_model_groove(shape, sub, "Part", chr_chamfers=call.typ > 10)
        except ValueError as e:
            assert "is in no notch" in str(e), (sub, str(e))
    # one face per element of the profile: base, flanks, corners; the contour and the rest are in no notch
    assert len(found) == len(profile_elements(call)), sorted(found)
    for groove in found.values():
        assert_call(groove.recognised.call, call)


@pytest.mark.parametrize("case", ["rectangular", "angled_radii", "oblique_cone", "face_external", "bore"])
def test_make_groove_without_dimensions_takes_the_models_values(doc, case):
    call = CASES[case]
    _doc, part, job, tc = make_shop(doc, shape=part_shape(call))
    subs = sorted(groove_faces(part.Shape)[0])
    for sub in subs:
        op = make_groove(job, (part, sub), name="Groove_" + sub, infeed=1, tool_width=2, tool_corner_radius=0.1)
        assert op_error(op) is None, (sub, op_error(op))
        assert op.ModelGroove and list(op.FromModel) == list(MODEL_VALUES) and list(op.ModelOverrides) == []
        assert (op.TYP, op.AXFA.Value, op.AXSA.Value, op.ANGC.Value) == (
            call.typ, pytest.approx(call.axfa, abs=LENGTH_TOL), pytest.approx(call.axsa, abs=LENGTH_TOL),
            pytest.approx(call.angc, abs=ANGLE_TOL))
        assert op.Width.Value == pytest.approx(call.widg, abs=LENGTH_TOL)
        assert op.Depth.Value == pytest.approx(call.depg, abs=LENGTH_TOL)
        assert op.FlankAngle1.Value == pytest.approx(call.ang1, abs=ANGLE_TOL)
        assert op.FlankAngle2.Value == pytest.approx(call.ang2, abs=ANGLE_TOL)
        for prop, word in CORNERS.items():
            value = getattr(call, word)
            assert getattr(op, prop).Value == pytest.approx(abs(value), abs=LENGTH_TOL), prop
            assert getattr(op, prop + "Type") == ("Radius" if value > 0 else "Chamfer" if value < 0 else "None")
        plan = op.Proxy.current_plan(op)[0]
        assert_call(plan.cycle, call)


def test_a_value_given_explicitly_overrides_the_models(doc):
    call = CASES["rectangular"]
    _doc, part, job, tc = make_shop(doc, shape=part_shape(call))
    sub = sorted(groove_faces(part.Shape)[0])[0]
    op = make_groove(job, (part, sub), model_groove=True, depth=3, infeed=1, tool_width=2)
    assert op_error(op) is None, op_error(op)
    assert list(op.ModelOverrides) == ["Depth"] and "Depth" not in op.FromModel and "Width" in op.FromModel
    assert op.Depth.Value == 3 and op.Proxy.current_plan(op)[0].cycle.depg == 3
    # set by hand later: an override too; taken off the list: the model's value again
    op.Width = 5
    assert list(op.ModelOverrides) == ["Depth", "Width"]
    doc.recompute()
    assert op.Proxy.current_plan(op)[0].cycle.widg == 5
    op.ModelOverrides = []
    doc.recompute()
    assert op_error(op) is None and op.Depth.Value == pytest.approx(2) and op.Width.Value == pytest.approx(4)


def test_the_values_follow_the_model_when_it_changes(doc):
    _doc, part, job, tc = make_shop(doc, shape=part_shape(CASES["rectangular"]))
    sub = sorted(groove_faces(part.Shape)[0])[0]
    op = make_groove(job, (part, sub), infeed=1, tool_width=2)
    assert op.Width.Value == pytest.approx(4)
    wider = dataclasses.replace(CASES["rectangular"], widg=6.0)
    part.Shape = part_shape(wider)
    doc.recompute()
    model = job.Model.Group[0]
    assert sorted(groove_faces(model.Shape)[0]) == sorted(groove_faces(part.Shape)[0])
    assert op_error(op) is None, op_error(op)
    assert op.Width.Value == pytest.approx(6)


def test_an_undercut_gives_the_ops_one_line_error(doc):
    _doc, part, job, tc = make_shop(doc, shape=undercut_shape())
    found, refused = groove_faces(part.Shape)
    assert not found
    base = next(sub for sub, message in refused.items() if "leans" in message)
    op = make_groove(job, (part, base), infeed=1, tool_width=2)
    error = op_error(op)
    assert "\n" not in error
    assert "leans 26.565051 degrees back over the base (an undercut" in error and error.startswith("Shaft.")
