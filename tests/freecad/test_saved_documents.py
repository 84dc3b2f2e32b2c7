"""Documents in FreeCAD (1.1 and 1.0; run by tests/freecad/run_suite.py):
an op saved and opened again, one whose document lacks newer properties, and
the demo document saved by the previous release (commit bfb45ff), whose ops
name the class ``freecad_groove.freecad.groove_op.ObjectGroove``.
"""

import os
import re

import pytest
import test_groove_op as tg
from documents import DATA, opened, path_commands, reopened, without_chip_break_reentries

from freecad_groove import make_groove
from freecad_groove.engine.numbers import format_value
from freecad_groove.freecad import groove_op
from freecad_groove.freecad.api import snake_case

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
    assert op.isValid(), op.getStatusString()
    values, commands, name = _values(op), path_commands(op), op.Name
    with reopened(doc, tmp_path / "groove.FCStd") as doc2:
        op2 = doc2.getObject(name)
        assert op2 is not None
        assert isinstance(op2.Proxy, groove_op.ObjectGroove)
        assert _values(op2) == values
        assert path_commands(op2) == commands
        assert op2.getEditorMode("AXFA") == ["ReadOnly"]
        doc2.recompute()
        assert op2.isValid(), op2.getStatusString()
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
    assert op.isValid() and op.AXFA.Value == 20.0
    # the same through a saved document that lacks the properties
    op.removeProperty("Dwell")
    op.removeProperty("ReferenceCorner")
    with reopened(doc, tmp_path / "old.FCStd") as doc2:
        op2 = doc2.getObject(name)
        assert op2.Dwell == 0.0
        assert op2.ReferenceCorner == "minus"
        doc2.recompute()
        assert op2.isValid(), op2.getStatusString()


def _calls_at_6_decimals(commands):
    """Path commands with the values of the CYCLE93 calls in their groove
    comments at 6 decimals, as the previous release wrote them (calls now
    carry every decimal the op computed, e.g. the cone's ANGC 158.198590514;
    the moves are the same)."""
    def call_at_6(match):
        return re.sub(r"-?\d+\.\d+", lambda number: format_value(float(number.group())), match.group())

    return [(re.sub(r"CYCLE93\[[^]]*\]", call_at_6, name), words) for name, words in commands]


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


def test_the_previous_releases_demo_recomputes_to_the_paths_it_saved(demo_at_bfb45ff):
    ops = _groove_ops(demo_at_bfb45ff)
    saved = {op.Name: path_commands(op) for op in ops}
    for op in ops:
        op.touch()
    demo_at_bfb45ff.recompute()
    for op in ops:
        assert op.isValid(), "%s: %s" % (op.Label, op.getStatusString())
        assert any(name == "G1" for name, _words in path_commands(op)), op.Label
        # The same moves, but for the rapid back down the slot after each
        # chip-breaking retract (issue 9), which the ops with several infeeds gain.
        now = _calls_at_6_decimals(path_commands(op))
        assert without_chip_break_reentries(now) == saved[op.Name], op.Label
        assert without_chip_break_reentries(saved[op.Name]) == saved[op.Name], op.Label


def test_the_previous_releases_demo_ops_cut_what_a_new_op_cuts(demo_at_bfb45ff):
    for op in _groove_ops(demo_at_bfb45ff):
        again = _same_op_made_now(op)
        assert again.isValid(), "%s: %s" % (op.Label, again.getStatusString())
        # the same after each op's own label comment
        # (op's Path is the one saved, before the chip-break re-entries of issue 9)
        assert without_chip_break_reentries(_calls_at_6_decimals(path_commands(again)))[1:] == \
            path_commands(op)[1:], op.Label
        assert len(again.Proxy.plan(again)) == len(op.Proxy.plan(op)), op.Label
