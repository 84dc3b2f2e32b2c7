"""Grooves read from the modelled part (ops/groove/model.py, the op's
ModelGroove): parts whose section carries the profile of a known CYCLE93
call (model_parts.py), every face of the groove picked in turn."""

import dataclasses

import FreeCAD
import Part
import Path.Main.Job as PathJob
import pytest
from documents import reopened
from model_parts import CASES, part_shape, undercut_shape
from parts import make_shop

from freecad_groove import make_groove
from freecad_groove.engine.cycles.cycle93_recognize import profile_elements
from freecad_groove.ops.groove.model import MODEL_VALUES, read_model_groove
from freecad_groove.ops.groove.op import op_error

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


def partdesign_grooved_shaft(doc):
    """A PartDesign Body: a R20 x 50 cylinder with a PartDesign Groove of a 3 x 4 mm rectangle
    sketched on the XZ plane (X 18..21, Z 20..24) revolved about the sketch's V axis (Z)."""
    V = FreeCAD.Vector
    body = doc.addObject("PartDesign::Body", "Body")
    cylinder = doc.addObject("PartDesign::AdditiveCylinder", "Cylinder")
    body.addObject(cylinder)
    cylinder.Radius, cylinder.Height = 20, 50
    sketch = doc.addObject("Sketcher::SketchObject", "GrooveSketch")
    body.addObject(sketch)
    xz = next(f for f in body.Origin.OriginFeatures if f.Role == "XZ_Plane")
    setattr(sketch, "AttachmentSupport" if hasattr(sketch, "AttachmentSupport") else "Support", [(xz, "")])
    sketch.MapMode = "FlatFace"
    pts = [(18, 20), (21, 20), (21, 24), (18, 24)]
    for a, b in zip(pts, pts[1:] + pts[:1]):
        sketch.addGeometry(Part.LineSegment(V(a[0], a[1], 0), V(b[0], b[1], 0)))
    groove = doc.addObject("PartDesign::Groove", "Groove")
    body.addObject(groove)
    groove.Profile = sketch
    groove.ReferenceAxis = (sketch, ["V_Axis"])
    groove.Angle = 360
    doc.recompute()
    assert groove.isValid()
    return body


def test_a_partdesign_groove_is_read_from_its_body(doc):
    body = partdesign_grooved_shaft(doc)
    job = PathJob.Create("Job", [body])
    doc.recompute()
    model = job.Model.Group[0]
    subs = sorted(groove_faces(model.Shape)[0])
    assert len(subs) == 3  # the base and the two flanks
    for sub in subs:
        op = make_groove(job, (body, sub), infeed=1, tool_width=3, tool_corner_radius=0.2)
        assert op_error(op) is None, op_error(op)
        call = op.Proxy.current_plan(op)[0].cycle
        assert (call.axfa, call.axsa, call.widg, call.depg, call.angc, call.typ) == (
            pytest.approx(20), pytest.approx(24), pytest.approx(4), pytest.approx(2), 0, 5)


def test_a_modelled_base_radius_smaller_than_the_blades_corner_is_reported(doc):
    # base corners R0.1 in the model, the blade's corners r0.4: the op cuts the groove as modelled and says
    # what stays at each base corner (never a silent approximation)
    call = dataclasses.replace(CASES["rectangular"], rci1=0.1, rci2=0.1)
    _doc, part, job, tc = make_shop(doc, shape=part_shape(call))
    sub = sorted(groove_faces(part.Shape)[0])[0]
    op = make_groove(job, (part, sub), infeed=1, tool_width=3, tool_corner_radius=0.4)
    assert op_error(op) is None, op_error(op)
    plan = op.Proxy.current_plan(op)[0]
    assert plan.cycle.rci1 == pytest.approx(0.1) and plan.cycle.rci2 == pytest.approx(0.1)
    texts = plan.warning_texts
    assert any("base corner 1 cannot be reached by a 3 mm flat blade (r0.4)" in t for t in texts), texts
    assert any("base corner 2 cannot be reached" in t for t in texts), texts


def test_a_model_groove_op_saved_and_reopened_keeps_its_overrides_and_reads_the_model_again(doc, tmp_path):
    _doc, part, job, tc = make_shop(doc, shape=part_shape(CASES["angled_radii"]))
    sub = sorted(groove_faces(part.Shape)[0])[0]
    op = make_groove(job, (part, sub), model_groove=True, depth=3, infeed=1, tool_width=2)
    assert op_error(op) is None, op_error(op)
    name, from_model = op.Name, list(op.FromModel)
    with reopened(doc, tmp_path / "model_groove.FCStd") as doc2:
        op2 = doc2.getObject(name)
        assert op2.ModelGroove and list(op2.ModelOverrides) == ["Depth"]  # restoring the values overrides nothing
        assert list(op2.FromModel) == from_model
        op2.touch()
        doc2.recompute()
        assert op_error(op2) is None and op2.Depth.Value == pytest.approx(3) and op2.Width.Value == pytest.approx(5)
        assert list(op2.ModelOverrides) == ["Depth"]
