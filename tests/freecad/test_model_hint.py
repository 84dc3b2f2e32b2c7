"""A face that only a modelled groove explains (a corner radius: a torus)
picked for a groove typed in by its values: the op's one-line face error
says to tick "Groove from the model" (FreeCAD 1.1 and 1.0). A torus that is
no part of a groove (a rounded shoulder) keeps the plain face error."""

import FreeCAD
import pytest
from model_parts import CASES, part_shape
from parts import make_shop, shaft_shape

from freecad_groove import make_groove
from freecad_groove.ops.groove.model import MODEL_HINT
from freecad_groove.ops.groove.op import op_error

TYPED = dict(width=2, depth=1, infeed=1, tool_width=2, tool_corner_radius=0.1)


@pytest.fixture
def doc():
    d = FreeCAD.newDocument("ModelHintTest")
    FreeCAD.setActiveDocument(d.Name)
    yield d
    FreeCAD.closeDocument(d.Name)


def torus_faces(shape):
    return ["Face%d" % (i + 1) for i, f in enumerate(shape.Faces) if type(f.Surface).__name__ == "Toroid"]


def rounded_shoulder():
    """The stepped shaft of parts.py with its R20 / Z30 shoulder edge rounded R1: a torus in no groove."""
    shape = shaft_shape()
    edge = next(e for e in shape.Edges if type(e.Curve).__name__ == "Circle"
                and abs(e.Curve.Radius - 20) < 1e-9 and abs(e.Curve.Center.z - 30) < 1e-9)
    return shape.makeFillet(1.0, [edge])


def test_a_corner_radius_of_a_modelled_groove_says_tick_groove_from_the_model(doc):
    _doc, part, job, _tc = make_shop(doc, shape=part_shape(CASES["angled_radii"]))
    corners = torus_faces(part.Shape)
    assert len(corners) == 3  # the edge corner R0.3, the base corners R0.5
    for sub in corners:
        op = make_groove(job, (part, sub), name="Typed_" + sub, **TYPED)
        error = op_error(op)
        assert error.startswith("Shaft.%s: a toroid face;" % sub) and "\n" not in error, error
        assert error.endswith(MODEL_HINT) and 'tick "Groove from the model"' in error, error
        op.ModelGroove = True  # what the hint says: the op cuts the modelled groove
        doc.recompute()
        assert op_error(op) is None, op_error(op)
        assert op.Width.Value == pytest.approx(CASES["angled_radii"].widg, abs=1e-3)


def test_a_torus_in_no_groove_keeps_the_plain_face_error(doc):
    _doc, part, job, _tc = make_shop(doc, shape=rounded_shoulder())
    (sub,) = torus_faces(part.Shape)
    op = make_groove(job, (part, sub), **TYPED)
    error = op_error(op)
    assert error.startswith("Shaft.%s: a toroid face;" % sub) and MODEL_HINT not in error, error
