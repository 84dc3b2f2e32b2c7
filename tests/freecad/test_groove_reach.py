"""The grooving blade's free reach (issue 20, item 5): a Groove deeper than
its grooving blade tool bit's CuttingEdgeHeight ("Cutting depth (free
reach)") is refused naming Depth and CuttingEdgeHeight; the op, its task
panel's plan and every lathe post refuse it. The stepped shaft of parts.py,
its R20 cylinder (Z10..30). Run inside FreeCAD 1.1 and 1.0.
"""

import FreeCAD
import pytest
from parts import face_name, make_shop
from test_op_errors import LATHE_POSTS, post

from freecad_groove import make_groove
from freecad_groove.freecad import toolbit
from freecad_groove.freecad.addon_op import op_error
from freecad_groove.freecad.posts import PostError
from freecad_groove.ops.groove.properties import error_properties

BLADE = dict(position=5, width=4, infeed=1)
REFUSED = ("Depth=12 mm: deeper than the blade's free reach, CuttingEdgeHeight=8 mm of Grooving blade: its holder "
           "would hit the part (use a blade that reaches 12 mm, or groove less deep)")


@pytest.fixture
def shop():
    doc = FreeCAD.newDocument("GrooveReach")
    FreeCAD.setActiveDocument(doc.Name)
    doc, shaft, job, _tc = make_shop(doc)
    tc = toolbit.make_grooving_tool_controller(job, 3, 0.2, name="TC: Grooving blade", CuttingEdgeHeight=8)
    yield doc, shaft, job, tc
    FreeCAD.closeDocument(doc.Name)


def groove(shop, depth):
    doc, shaft, job, tc = shop
    return make_groove(job, (shaft, face_name(shaft.Shape, "cylinder")), tool_controller=tc, depth=depth, **BLADE)


def test_a_groove_deeper_than_the_blades_reach_is_refused_naming_depth_and_cutting_edge_height(shop):
    op = groove(shop, 12)
    assert op_error(op) == REFUSED
    assert [c for c in op.Path.Commands if c.Parameters] == []
    for name in LATHE_POSTS:
        with pytest.raises(PostError) as info:
            post(name, [op])
        assert str(info.value) == "%s: %s" % (op.Label, REFUSED)


def test_the_panels_plan_refuses_it_marking_depth(shop):
    """The task panel's OK and Apply are refused while its plan fails (gui/task_dialog.py): the plan_with
    of the values it shows."""
    op = groove(shop, 4)
    assert op_error(op) is None
    with pytest.raises(ValueError) as info:
        op.Proxy.plan_with(op, {"Depth": 12.0})
    assert str(info.value) == REFUSED and error_properties(info.value) == ("Depth",)
    assert op.Depth.Value == 4.0 and op_error(op) is None  # the document is not touched


def test_a_groove_as_deep_as_the_reach_is_cut_and_a_longer_blade_takes_the_deeper_one(shop):
    doc, shaft, job, tc = shop
    op = groove(shop, 8)
    assert op_error(op) is None and "G75 X24. Z21." in post("fanuc_lathe", [op])  # down to R12: 8 deep
    op.Depth = 12
    doc.recompute()
    assert op_error(op) == REFUSED
    tc.Tool.CuttingEdgeHeight = 12  # the op recomputes when its tool changes
    doc.recompute()
    assert op_error(op) is None
    tc.Tool.CuttingEdgeHeight = 0  # unknown: not checked
    doc.recompute()
    assert op_error(op) is None


def test_the_default_grooving_blade_reaches_12_mm(shop):
    doc, shaft, job, _tc = shop
    tc = toolbit.make_grooving_tool_controller(job, 3, 0.2, name="TC: default blade")
    assert tc.Tool.CuttingEdgeHeight.Value == 12.0
    op = make_groove(job, (shaft, face_name(shaft.Shape, "cylinder")), tool_controller=tc, depth=12.5, **BLADE)
    assert op_error(op).startswith("Depth=12.5 mm: deeper than the blade's free reach, CuttingEdgeHeight=12 mm")


def test_an_end_mills_cutting_edge_height_is_not_a_blades_reach(shop):
    """A new Job's tool controller holds CAM's end mill (no Width): the op takes ToolWidth, and the end mill's
    CuttingEdgeHeight says nothing about a blade."""
    doc, shaft, job, _tc = shop
    end_mill = job.Tools.Group[0]
    end_mill.Tool.CuttingEdgeHeight = 5
    op = make_groove(job, (shaft, face_name(shaft.Shape, "cylinder")), tool_controller=end_mill, depth=12,
                     tool_width=3, tool_corner_radius=0.2, **BLADE)
    assert op_error(op) is None
