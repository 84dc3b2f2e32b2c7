"""Documents in FreeCAD (1.1 and 1.0; run by tests/freecad/run_suite.py):
an op saved and opened again, and one whose document lacks newer properties.
"""

import test_groove_op as tg
from documents import path_commands, reopened

from freecad_groove.freecad import groove_op

# The Groove op tests' document and shop fixtures, and their groove maker.
doc, shop, groove = tg.doc, tg.shop, tg.groove


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
