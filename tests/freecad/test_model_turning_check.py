"""verify_job() on a groove read from the model (issue 11's "Done when": the
turning check joined with the model's grooves), in FreeCAD 1.1 and 1.0.

The part is model_parts.py's "rectangular" case: a bar R20 from Z20 to Z36
with a 4 wide, 2 deep groove at Z26..30 (base R18); the Job's default stock
(the part's bounds and 1 mm) is a bar R21 from Z19 to Z37. Two ops on the
same face of the groove: one derived from the model (no value typed), and
one whose Depth is overridden 1 mm deeper than the model (ModelOverrides
["Depth"]). The check must pass the first and find,
for the second only, a gouge about 1 mm deep at the model's groove base,
naming that op.
"""

import FreeCAD
import pytest
from model_parts import CASES, part_shape
from parts import make_shop
from test_model_grooves import groove_faces

from freecad_groove import make_groove, verify_job
from freecad_groove.ops.groove.op import op_error

BLADE = dict(infeed=1, tool_width=2, tool_corner_radius=0.1)
CALL = CASES["rectangular"]
BASE_RADIUS = CALL.axfa - CALL.depg  # 18
GROOVE_Z = (CALL.axsa - CALL.widg, CALL.axsa)  # 26..30


@pytest.fixture
def shop():
    doc = FreeCAD.newDocument("ModelTurningCheck")
    FreeCAD.setActiveDocument(doc.Name)
    yield make_shop(doc, shape=part_shape(CALL))
    FreeCAD.closeDocument(doc.Name)


def model_groove_op(shop, name, **values):
    _doc, part, job, _tc = shop
    sub = sorted(groove_faces(part.Shape)[0])[0]
    op = make_groove(job, (part, sub), name=name, **BLADE, **values)
    assert op_error(op) is None, op_error(op)
    return op


def test_the_op_derived_from_the_model_cuts_it_exactly(shop):
    op = model_groove_op(shop, "FromModel")
    assert list(op.ModelOverrides) == [] and op.Depth.Value == pytest.approx(CALL.depg)
    result = verify_job(shop[2])
    check = result.ops[0]
    assert check.label == op.Label and check.ok and result.ok, result.summary()
    assert check.gouge_depth == 0 and check.gouge_area == 0 and check.leftover == pytest.approx(0, abs=1e-4)
    # the stock (a bar R21: the model's bounds and the Job's 1 mm) over the groove down to its base, less
    # the blade's r0.1 corners in the two sharp base corners (the cycle's own reach warnings)
    assert "bar R21.000 from Z19.000 to Z37.000" in result.summary()
    assert check.unreachable == pytest.approx(check.reach_warning, abs=1e-4) and 0 < check.unreachable < 0.01
    assert check.removed == pytest.approx(CALL.widg * (CALL.depg + 1) - check.unreachable, abs=1e-3)


def test_a_depth_overridden_1mm_deeper_than_the_model_is_a_gouge_naming_the_op(shop):
    good = model_groove_op(shop, "FromModel")
    deep = model_groove_op(shop, "TooDeep", model_groove=True, depth=CALL.depg + 1)
    assert list(deep.ModelOverrides) == ["Depth"] and deep.Depth.Value == pytest.approx(CALL.depg + 1)
    result = verify_job(shop[2])
    by_label = {check.label: check for check in result.ops}
    assert by_label[good.Label].ok, result.summary()
    check = by_label[deep.Label]
    assert not check.ok and not result.ok
    assert check.gouge_depth == pytest.approx(1.0, abs=1e-3), result.summary()
    x, z = check.gouge_at
    assert x == pytest.approx(BASE_RADIUS - 1, abs=0.01) and GROOVE_Z[0] <= z <= GROOVE_Z[1], check.gouge_at
    assert check.gouge_area == pytest.approx(CALL.widg * 1.0, abs=0.01), result.summary()
    assert check.summary().startswith(deep.Label + ": PROBLEMS") and "GOUGE" in check.summary()
    assert "TooDeep: PROBLEMS" in result.summary() and "FromModel: ok" in result.summary()



def _base_face(part):
    """The modelled groove's base face (the R18 cylinder)."""
    return next("Face%d" % (i + 1) for i, face in enumerate(part.Shape.Faces)
                if hasattr(face.Surface, "Radius") and face.Surface.Radius == pytest.approx(BASE_RADIUS))


def test_a_groove_typed_into_the_modelled_grooves_base_is_a_gouge_and_excuses_no_other(shop):
    # issue 21: the base face picked without "Groove from the model": a 2 x 1 groove typed in cuts below the
    # finished base. The check took that op's planned groove as part of the design: "ok, no gouge", and another
    # op's gouge there shrank by it.
    _doc, part, job, _tc = shop
    typed = make_groove(job, (part, _base_face(part)), name="Typed", model_groove=False, position=1, width=2,
                        depth=1, **BLADE)
    assert op_error(typed) is None and not typed.ModelGroove, op_error(typed)
    result = verify_job(job)
    check = result.ops[0]
    assert not check.ok and check.gouge_depth == pytest.approx(1.0, abs=1e-3), result.summary()
    assert check.gouge_area == pytest.approx(2.0, abs=0.01) and check.gouge_at[0] == pytest.approx(BASE_RADIUS - 1,
                                                                                                   abs=0.01)
    # an op 1 mm too deep over the whole base, run before it: its whole 4 x 1 below the base is its gouge
    deep = model_groove_op(shop, "TooDeep", model_groove=True, depth=CALL.depg + 1)
    job.Operations.Group = [deep, typed]
    result = verify_job(job)
    by_label = {check.label: check for check in result.ops}
    assert by_label[deep.Label].gouge_area == pytest.approx(CALL.widg * 1.0, abs=0.01), result.summary()
