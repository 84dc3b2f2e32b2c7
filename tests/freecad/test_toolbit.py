"""The grooving blade tool bit shipped with the add-on (freecad_groove.freecad.toolbit),
in FreeCAD 1.1 and 1.0: a tool controller made with it carries a bit whose
Width and CornerRadius the Groove op reads, and it survives save and reopen.
"""

import os

import FreeCAD
import pytest
import test_groove_op as tg
from parts import face_name

from freecad_groove import make_groove
from freecad_groove.freecad import toolbit
from freecad_groove.freecad.groove_op import op_error

# The Groove op tests' document and shop fixtures.
doc, shop = tg.doc, tg.shop


def _groove(shop, tc, **extra):
    doc, shaft, job, _tc = shop
    kw = dict(position=5, width=4, depth=2, infeed=1, tool_width=1, tool_corner_radius=0.5)
    kw.update(extra)
    return make_groove(job, (shaft, face_name(shaft.Shape, "cylinder")), tool_controller=tc, **kw)


def _tool(op):
    (_c, settings, _st), = op.Proxy.cycles(op)
    return settings.tool.width, settings.tool.corner_radius


def _moves(op):
    return [(c.Name, sorted((k, round(v, 6)) for k, v in c.Parameters.items())) for c in op.Path.Commands]


def test_the_shape_file_ships():
    assert os.path.isfile(toolbit.SHAPE_FILE)


def test_tool_controller_with_a_grooving_blade(shop):
    doc, shaft, job, first = shop
    tc = toolbit.make_grooving_tool_controller(job, 3, 0.2)
    assert tc in job.Tools.Group and tc is not first
    assert tc.ToolNumber == first.ToolNumber + 1
    bit = tc.Tool
    assert bit.Width.Value == pytest.approx(3) and bit.CornerRadius.Value == pytest.approx(0.2)
    assert bit.Diameter.Value == pytest.approx(3)
    assert bit.Shape.Solids, "the blade has a solid"
    assert bit.Shape.BoundBox.XLength == pytest.approx(3)
    if toolbit.NEW_TOOLBITS:
        assert bit.ShapeType == "Grooving"
        assert isinstance(bit.Proxy, toolbit.ToolBitGrooving)
    tc2 = toolbit.make_grooving_tool_controller(job, 2, 0.1, tool_number=7, name="TC: narrow", Length=30)
    assert tc2.ToolNumber == 7 and tc2.Label == "TC: narrow"
    assert tc2.Tool.Length.Value == pytest.approx(30) and tc2.Tool.Width.Value == pytest.approx(2)
    with pytest.raises(TypeError):
        toolbit.make_grooving_tool_controller(job, 2, 0.1, Flutes=2)


def test_the_op_reads_the_blades_width_and_corner_radius(shop):
    doc, shaft, job, first = shop
    tc = toolbit.make_grooving_tool_controller(job, 3, 0.2)
    op = _groove(shop, tc)
    assert op_error(op) is None, op_error(op)
    assert _tool(op) == (pytest.approx(3), pytest.approx(0.2))  # not the op's 1 / 0.5
    before = _moves(op)
    tc.Tool.Width = 2.5
    tc.Tool.CornerRadius = 0.4
    doc.recompute()
    assert tc.Tool.Diameter.Value == pytest.approx(2.5)
    if toolbit.NEW_TOOLBITS:  # 1.1 redraws the blade; 1.0 only from its tool bit editor
        assert tc.Tool.Shape.BoundBox.XLength == pytest.approx(2.5)
    assert _tool(op) == (pytest.approx(2.5), pytest.approx(0.4))
    assert op_error(op) is None, op_error(op)
    assert _moves(op) != before
    # a groove narrower than the blade is refused
    op.Width = 2
    doc.recompute()
    assert "(alarm 61602)" in op_error(op) and "tool width 2.5" in op_error(op)
    op.Width = 4
    doc.recompute()
    assert op_error(op) is None, op_error(op)


def test_save_and_reopen_keeps_the_blade(shop, tmp_path):
    doc, shaft, job, first = shop
    tc = toolbit.make_grooving_tool_controller(job, 2.5, 0.3)
    op = _groove(shop, tc)
    assert op_error(op) is None, op_error(op)
    names = op.Name, tc.Name, tc.Tool.Name
    moves = _moves(op)
    path = str(tmp_path / "blade.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    doc2 = FreeCAD.openDocument(path)
    try:
        op2, tc2, bit2 = (doc2.getObject(n) for n in names)
        assert op2.ToolController == tc2 and tc2.Tool == bit2
        assert bit2.Width.Value == pytest.approx(2.5) and bit2.CornerRadius.Value == pytest.approx(0.3)
        assert bit2.Diameter.Value == pytest.approx(2.5)
        if toolbit.NEW_TOOLBITS:
            assert isinstance(bit2.Proxy, toolbit.ToolBitGrooving) and bit2.ShapeType == "Grooving"
        assert _tool(op2) == (pytest.approx(2.5), pytest.approx(0.3))
        doc2.recompute()
        assert op_error(op2) is None, op_error(op2)
        assert _moves(op2) == moves
        # still a working bit: a new width reaches the op and the blade's body
        bit2.Width = 3
        doc2.recompute()
        assert _tool(op2)[0] == pytest.approx(3) and bit2.Diameter.Value == pytest.approx(3)
        if toolbit.NEW_TOOLBITS:  # the shape was reloaded from the add-on: the body follows
            assert bit2.Shape.BoundBox.XLength == pytest.approx(3)
        assert op_error(op2) is None, op_error(op2)
        assert all(o.isValid() for o in doc2.Objects), [o.Name for o in doc2.Objects if not o.isValid()]
    finally:
        FreeCAD.closeDocument(doc2.Name)


def test_no_blade_width_is_an_error_not_a_default(shop):
    doc, shaft, job, first = shop  # the Job's tool controller: FreeCAD's end mill, no Width
    op = make_groove(job, (shaft, face_name(shaft.Shape, "cylinder")), position=5, width=4, depth=2)
    assert op.ToolWidth.Value == 0  # unknown, not a made-up 3 mm
    status = op_error(op)
    assert status is not None
    assert "ToolWidth: the blade's width is unknown" in status and first.Label in status
    assert not [c for c in op.Path.Commands if c.Name in ("G0", "G1")]
    # A grooving tool controller gives the width...
    op.ToolController = toolbit.make_grooving_tool_controller(job, 3, 0.2)
    doc.recompute()
    assert op_error(op) is None, op_error(op)
    assert _tool(op) == (pytest.approx(3), pytest.approx(0.2))
    # ... and so does a width typed into the op, with the end mill.
    op.ToolController = first
    op.ToolWidth = 2.5
    doc.recompute()
    assert op_error(op) is None, op_error(op)
    assert _tool(op)[0] == pytest.approx(2.5)
