"""In the session, a post reuses the plans the op's last recompute made
(freecad_groove/ops/groove/kept_plans.py) only while nothing they were
planned from changed: after a post, each input is changed (the op's
properties, the model's shape, placement and label, the Job's stock, the tool
controller, the tool bit), with and without a recompute of the document, and
the next post must write what a fresh plan writes, and differ from the post
before the change. What the recompute reads of other objects is read again
only after they changed (freecad_groove/freecad/changes.py,
freecad_groove/freecad/shape_memo.py). Run by tests/freecad/run_suite.py in
FreeCAD 1.1 and 1.0.
"""

import FreeCAD
import Part
import pytest
import test_groove_op as tg
import test_plan_cache as tc
from documents import reopened
from parts import PROFILE, shaft_shape

from freecad_groove.freecad import addon_bits, changes, toolbit
from freecad_groove.ops.groove import links
from freecad_groove.ops.groove.op import op_error

doc, shop, plan_calls = tg.doc, tg.shop, tc.plan_calls


def _feed_from_the_tool_controller(op, shop):
    op.ToolController.HorizFeed = "50 mm/min"  # the op's FeedPerRev is 0: the tool controller's HorizFeed counts


def _op_spindle_speed(op, shop):
    op.SpindleSpeed = 1234


def _tool_controller_spindle_speed(op, shop):
    op.ToolController.SpindleSpeed = 777  # the op's SpindleSpeed is 0: the tool controller's counts


def _grooving_tool_controller(op, shop):
    op.ToolController = toolbit.make_grooving_tool_controller(shop[2], 2.5, 0.1)


def _tool_bit_width(op, shop):
    op.ToolController.Tool.Width = 2.0


def _tool_bit_corner_radius(op, shop):
    op.ToolController.Tool.CornerRadius = 0.4


def _part_shape(op, shop):
    # the part the Job's model is a clone of: the cylinder 0.5 mm larger (20 -> 20.5), the same faces
    shop[1].Shape = shaft_shape([(r + 0.5 if r == 20 else r, z) for r, z in PROFILE])


def _model_shape(op, shop):
    tc._change_model_shape(op, shop[2].Model.Group[0])


def _op_width(op, shop):
    op.Width = 3.5


def _stock_shape(op, shop):
    tc._change_stock(op, None)


def _stock_placement(op, shop):
    shop[2].Stock.Placement = FreeCAD.Placement(FreeCAD.Vector(0, 0, 3), FreeCAD.Rotation())


# (change, whether it is posted with the document recomputed first): a clone follows its part at a recompute
CHANGES = [(_op_width, True), (_op_width, False), (_part_shape, True), (_model_shape, False),
           (_stock_shape, True), (_stock_shape, False), (_stock_placement, True), (_stock_placement, False),
           (_feed_from_the_tool_controller, True), (_feed_from_the_tool_controller, False),
           (_op_spindle_speed, True), (_op_spindle_speed, False), (_tool_controller_spindle_speed, True),
           (_tool_controller_spindle_speed, False),
           (_grooving_tool_controller, True), (_grooving_tool_controller, False),
           (_tool_bit_width, True), (_tool_bit_width, False), (_tool_bit_corner_radius, True),
           (_tool_bit_corner_radius, False)]


@pytest.mark.parametrize("change, recompute", CHANGES,
                         ids=["%s-%s" % (f.__name__.lstrip("_"), "recomputed" if r else "not recomputed")
                              for f, r in CHANGES])
def test_a_post_after_an_input_changed_in_the_session_writes_the_change(shop, change, recompute):
    doc = shop[0]
    op = tc._grooves(shop)
    if change in (_tool_bit_width, _tool_bit_corner_radius):
        _grooving_tool_controller(op, shop)
        doc.recompute()
    before = tc._post(op)
    assert tc._post(op) == before
    change(op, shop)
    if recompute:
        doc.recompute()
    assert op_error(op) is None, op_error(op)
    text = tc._post(op)
    assert text != before
    assert text == tc._fresh_post(op)


def test_posts_of_an_unchanged_op_plan_once(shop, plan_calls):
    op = tc._grooves(shop)
    calls = plan_calls[0]
    first = tc._post(op)
    for _ in range(3):
        assert tc._post(op) == first
    assert plan_calls[0] == calls
    shop[0].recompute()  # nothing touched: nothing recomputed, the plans kept
    assert tc._post(op) == first
    assert plan_calls[0] == calls


def test_a_new_tool_controller_recomputes_itself_and_its_bit_not_the_ops(shop, plan_calls):
    # Issue 21 item 10: the panel's "Create grooving tool controller" recomputed the whole document (the Job, its
    # model, the open op's plan: half a second); the op is planned when it is recomputed with its new tool.
    # (FreeCAD 1.0's own ToolBit recomputes the document when it is made: the tool controller is timed apart.)
    doc, _shaft, job, _tc = shop
    op = tc._grooves(shop)
    bit = toolbit.make_grooving_bit(doc, 2.5, 0.2)
    op.touch()  # an op being edited in its panel
    calls = plan_calls[0]
    new = addon_bits.make_tool_controller(job, bit, "TC: Grooving blade")
    assert plan_calls[0] == calls and "Touched" in op.State
    assert "Touched" not in new.State and "Touched" not in new.Tool.State and new in job.Tools.Group
    op.ToolController = new
    doc.recompute()
    assert plan_calls[0] > calls and op_error(op) is None


def test_the_model_s_largest_radius_is_found_once_per_shape(shop):
    op = tc._grooves(shop)
    model = shop[2].Model.Group[0]
    found = links._LARGEST_RADIUS.computed
    for width in (3.5, 4.0, 3.5):
        op.Width = width
        shop[0].recompute()
    assert links._LARGEST_RADIUS.computed == found
    assert links.largest_radius(model.Shape) == pytest.approx(20.0)
    model.Shape = shaft_shape([(r + 0.5 if r == 20 else r, z) for r, z in PROFILE])
    assert links.largest_radius(model.Shape) == pytest.approx(20.5)
    assert links._LARGEST_RADIUS.computed == found + 1
    moved = Part.Shape(model.Shape)  # the same TShape
    moved.Placement = FreeCAD.Placement(FreeCAD.Vector(1.5, 0, 0), FreeCAD.Rotation())
    assert links.largest_radius(moved) == pytest.approx(22.0, abs=0.011)  # the same TShape moved off the axis
    assert links.largest_radius(model.Shape) == pytest.approx(20.5)


def test_a_value_read_once_is_read_again_after_any_change_of_its_object(doc):
    box = doc.addObject("Part::Box", "Box")
    reads = []

    def read(obj):
        reads.append(obj.Length.Value)
        return obj.Length.Value

    assert changes.read_once(box, "test", read) == 10.0
    assert changes.read_once(box, "test", read) == 10.0
    assert len(reads) == 1
    box.Length = 12
    assert changes.read_once(box, "test", read) == 12.0
    box.Label = "Other"  # any property
    changes.read_once(box, "test", read)
    box.addProperty("App::PropertyFloat", "Extra")
    changes.read_once(box, "test", read)
    assert len(reads) == 4
    box.Length = 12
    assert changes.read_once(box, "test", read) == 12.0  # set again, unchanged: read again all the same
    assert len(reads) == 5
    doc.removeObject("Box")
    again = doc.addObject("Part::Box", "Box")  # the same name, a new object
    again.Length = 3
    assert changes.read_once(again, "test", read) == 3.0


def test_a_recompute_reads_the_tool_bit_once_per_change(shop, monkeypatch):
    from freecad_groove.freecad import addon_op

    op = tc._grooves(shop)
    _grooving_tool_controller(op, shop)
    shop[0].recompute()
    reads = [0]
    lengths = addon_op._tool_lengths

    def counted(tool):
        reads[0] += 1
        return lengths(tool)

    monkeypatch.setattr(addon_op, "_tool_lengths", counted)
    for width in (3.5, 4.0):
        op.Width = width
        shop[0].recompute()
    assert reads[0] <= 1
    read = reads[0]
    op.ToolController.Tool.Width = 2.0
    assert op.Proxy.mustExecute(op)  # FreeCAD recomputes the op: its blade changed
    shop[0].recompute()
    assert op_error(op) is None
    assert [c for c in op.Path.Commands if c.Name == "G1"]
    assert reads[0] > read  # read again: it changed
    assert not op.Proxy.mustExecute(op)
    op.Width = 3.0
    shop[0].recompute()  # FreeCAD 1.1 sets the bit's properties again once after it changed
    read = reads[0]
    for width in (3.5, 4.0):
        op.Width = width
        shop[0].recompute()
    assert reads[0] == read


def _change_ids(changes):
    """The test ids of (change, recompute) pairs: "stock_shape-recomputed"."""
    return ["%s-%s" % (f.__name__.lstrip("_"), "recomputed" if r else "not recomputed") for f, r in changes]


SAVED_CHANGES = [(_op_width, False), (_stock_shape, True), (_stock_shape, False), (_tool_bit_width, False),
                 (_feed_from_the_tool_controller, False)]


@pytest.mark.parametrize("change, recompute", SAVED_CHANGES, ids=_change_ids(SAVED_CHANGES))
def test_a_document_saved_after_an_input_changed_reopens_with_the_change(shop, tmp_path, plan_calls, change,
                                                                          recompute):
    # the plans' fingerprint is taken when the document is saved: never of inputs changed since they were planned
    doc = shop[0]
    op = tc._grooves(shop)
    if change is _tool_bit_width:
        _grooving_tool_controller(op, shop)
        doc.recompute()
    name, before = op.Name, tc._post(op)
    change(op, shop)
    if recompute:
        doc.recompute()
    with reopened(doc, tmp_path / "a.FCStd") as doc2:
        op2 = doc2.getObject(name)
        text = tc._post(op2)
        assert text != before
        assert text == tc._fresh_post(op2)


def test_a_document_saved_unchanged_reopens_without_planning(shop, tmp_path, plan_calls):
    doc = shop[0]
    op = tc._grooves(shop)
    op.Width = 3.5
    doc.recompute()  # planned at this recompute, not posted: the fingerprint is taken at the save
    name, before = op.Name, tc._post(op)
    with reopened(doc, tmp_path / "a.FCStd") as doc2:
        calls = plan_calls[0]
        assert tc._post(doc2.getObject(name)) == before
        assert plan_calls[0] == calls


# (change, whether it is posted with the document recomputed first), made in the session that reopened the document
REOPENED_CHANGES = [(_model_shape, False), (_part_shape, True), (_stock_shape, False), (_stock_placement, False),
                    (_tool_bit_width, False)]


@pytest.mark.parametrize("change, recompute", REOPENED_CHANGES, ids=_change_ids(REOPENED_CHANGES))
def test_a_change_after_reopening_and_posting_is_written_by_the_next_post(shop, tmp_path, plan_calls, change,
                                                                          recompute):
    # what the observer heard while the document was restored is counted at the first post; a change after that
    # must still be heard: the saved plans, checked once at that post, are not taken again for the next one
    doc, part, job, _tc = shop
    op = tc._grooves(shop)
    if change is _tool_bit_width:
        _grooving_tool_controller(op, shop)
        doc.recompute()
    names, before = (part.Name, job.Name, op.Name), tc._post(op)
    with reopened(doc, tmp_path / "a.FCStd") as doc2:
        part2, job2, op2 = (doc2.getObject(name) for name in names)
        calls = plan_calls[0]
        assert tc._post(op2) == before
        assert plan_calls[0] == calls  # the saved plans
        change(op2, (doc2, part2, job2, op2.ToolController))
        if recompute:
            doc2.recompute()
        assert op_error(op2) is None, op_error(op2)
        text = tc._post(op2)
        assert plan_calls[0] > calls
        assert text != before
        assert text == tc._fresh_post(op2)


def test_opening_a_document_looks_up_each_restored_object_once_not_each_property(shop, tmp_path):
    # opening signals every restored property (hundreds for one op); the observer only notes the object at
    # each and finds its name once, when the changes are next counted (changes.py)
    op = tc._grooves(shop)
    name, before = op.Name, tc._post(op)
    path = tmp_path / "a.FCStd"
    shop[0].saveAs(str(path))
    FreeCAD.closeDocument(shop[0].Name)
    heard, keyed = changes.work["heard"], changes.work["keyed"]
    doc2 = FreeCAD.openDocument(str(path))
    try:
        changes.last_change()  # counts what was heard
        objects = len(doc2.Objects)
        assert changes.work["heard"] - heard > 5 * objects
        assert changes.work["keyed"] - keyed <= objects
        assert tc._post(doc2.getObject(name)) == before
    finally:
        FreeCAD.closeDocument(doc2.Name)
