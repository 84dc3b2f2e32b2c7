"""Documents in FreeCAD (1.1 and 1.0; run by tests/freecad/run_suite.py):
an op saved and opened again, one whose document lacks newer properties, and
the demo document saved by the previous release (commit bfb45ff), whose ops
name the class ``freecad_groove.freecad.groove_op.ObjectGroove``.
"""

import os

import pytest
import test_groove_op as tg
from documents import DATA, opened, path_commands, reopened

from freecad_groove import make_groove
from freecad_groove.freecad import groove_op
from freecad_groove.freecad.api import snake_case
from freecad_groove.freecad.groove_op import op_error

# The Groove op tests' document and shop fixtures, and their groove maker.
doc, shop, groove = tg.doc, tg.shop, tg.groove

# scripts/demo's document (freecad_groove/demo.py) as commit bfb45ff saved it from FreeCAD 1.1.
DEMO_AT_BFB45FF = os.path.join(DATA, "demo_part_saved_at_bfb45ff.FCStd")
DEMO_OPS = ["External grooves", "Face groove", "Bore groove", "Cone groove", "Cut-off"]
SETTABLE = [name for name in groove_op.PROPERTY_NAMES if name not in groove_op.DERIVED] + ["Comment"]


def _values(op):
    values = {}
    for name in groove_op.PROPERTY_NAMES:
        value = getattr(op, name)
        values[name] = round(value.Value, 9) if hasattr(value, "Value") else value
    return values


def test_save_and_reopen(shop, tmp_path):
    doc, shaft, job, tc = shop
    op = groove(shop, "cone_up", flank_angle1=10, edge_corner2=0.5, edge_corner2_type="Radius", base_allowance=0.2,
                flank_allowance=0.1, dwell=0.3, retract=0.5)
    assert op_error(op) is None, op_error(op)
    values, commands, name = _values(op), path_commands(op), op.Name
    with reopened(doc, tmp_path / "groove.FCStd") as doc2:
        op2 = doc2.getObject(name)
        assert op2 is not None
        assert isinstance(op2.Proxy, groove_op.ObjectGroove)
        assert _values(op2) == values
        assert path_commands(op2) == commands
        assert op2.getEditorMode("AXFA") == ["ReadOnly"]
        doc2.recompute()
        assert op_error(op2) is None, op_error(op2)
        assert path_commands(op2) == commands


def test_missing_properties_come_back_with_defaults(shop, tmp_path):
    doc, shaft, job, tc = shop
    op = groove(shop, "cylinder", pitch=5)
    name = op.Name
    for prop in ("Pitch", "ChamferMeasure", "GrooveCount", "AXFA"):
        op.removeProperty(prop)
    assert not hasattr(op, "Pitch")
    op.Proxy.onDocumentRestored(op)
    assert op.Pitch.Value == 0.0
    assert op.ChamferMeasure == "Chamfer length (CHF)"
    assert op.GrooveCount == 1
    assert op.getEditorMode("AXFA") == ["ReadOnly"]
    doc.recompute()
    assert op_error(op) is None and op.AXFA.Value == 20.0
    # the same through a saved document that lacks the properties
    op.removeProperty("Dwell")
    op.removeProperty("ReferenceCorner")
    with reopened(doc, tmp_path / "old.FCStd") as doc2:
        op2 = doc2.getObject(name)
        assert op2.Dwell == 0.0
        assert op2.ReferenceCorner == "minus"
        doc2.recompute()
        assert op_error(op2) is None, op_error(op2)


def _groove_ops(doc):
    return [obj for obj in doc.Objects if type(getattr(obj, "Proxy", None)).__name__ == "ObjectGroove"]


def _same_op_made_now(op):
    """A new op in ``op``'s Job on the same faces, with the same tool
    controller and the same values, made by this code."""
    job = op.Proxy.getJob(op)
    values = {snake_case(name): getattr(op, name) for name in SETTABLE}
    return make_groove(job, [(base, list(subs)) for base, subs in op.Base], name="Again",
                       tool_controller=op.ToolController, **values)


@pytest.fixture
def demo_at_bfb45ff():
    with opened(DEMO_AT_BFB45FF) as demo:
        yield demo


def test_the_previous_releases_demo_opens_with_its_ops(demo_at_bfb45ff):
    ops = _groove_ops(demo_at_bfb45ff)
    assert [op.Label for op in ops] == DEMO_OPS
    for op in ops:
        assert isinstance(op.Proxy, groove_op.ObjectGroove)
        assert op.Path.Commands, op.Label
        assert op.getEditorMode("AXFA") == ["ReadOnly"]  # opOnDocumentRestored ran


def test_the_previous_releases_demo_recomputes_to_what_a_new_op_makes(demo_at_bfb45ff):
    """Its ops, recomputed by this code, are the ops this code makes from the
    same values: every property came back. (Their saved Paths are bfb45ff's
    moves; issue 9 changed the CYCLE93 moves on purpose, so a recompute no
    longer gives those.)"""
    ops = _groove_ops(demo_at_bfb45ff)
    for op in ops:
        op.touch()
    demo_at_bfb45ff.recompute()
    for op in ops:
        assert op_error(op) is None, "%s: %s" % (op.Label, op_error(op))
        assert any(name == "G1" for name, _words in path_commands(op)), op.Label
        again = _same_op_made_now(op)
        assert op_error(again) is None, "%s: %s" % (op.Label, op_error(again))
        # the same after each op's own label comment
        assert path_commands(again)[1:] == path_commands(op)[1:], op.Label
        assert len(again.Proxy.plan(again)) == len(op.Proxy.plan(op)), op.Label
