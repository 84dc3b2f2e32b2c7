"""A post after reopening a document reuses the plans the op saved
(freecad_groove/ops/groove/cache.py) while their fingerprint matches, and
plans again when any input changed while the document was closed (here: the
saved document's values changed without a recompute, as an edit of the file
or an older add-on leaves them) or the add-on's planning code changed. Run by
tests/freecad/run_suite.py in FreeCAD 1.1 and 1.0.
"""

import dataclasses
import re
import zipfile

import FreeCAD
import Part
import pytest
import test_groove_op as tg
from documents import DATA, opened, reopened
from parts import PROFILE, shaft_shape

from freecad_groove import demo
from freecad_groove.ops.groove import cache as plan_cache
from freecad_groove.ops.groove import op as groove_op
from freecad_groove.ops.groove.op import op_error

doc, shop = tg.doc, tg.shop


@pytest.fixture
def plan_calls(monkeypatch):
    """The ops' plan() calls, counted: [count]."""
    calls = [0]
    plan = groove_op.ObjectGroove.plan

    def counted(self, obj, faces=None):
        calls[0] += 1
        return plan(self, obj, faces)

    monkeypatch.setattr(groove_op.ObjectGroove, "plan", counted)
    return calls


def _grooves(shop):
    """Two grooves on the cylinder, one with radii (it has more moves)."""
    op = tg.groove(shop, "cylinder", groove_count=2, pitch=6, base_corner1=0.5, base_corner1_type="Radius")
    assert op_error(op) is None, op_error(op)
    return op


def _post(op):
    return demo.load_post("linuxcnc").export([op.ToolController, op], "-", "")


def _fresh_post(op):
    """What the post writes from a fresh plan of ``op``."""
    op.Proxy._plans, op.Proxy._saved_plans = None, None
    return _post(op)


def test_a_post_after_reopening_does_not_plan_again(shop, tmp_path, plan_calls):
    doc = shop[0]
    op = _grooves(shop)
    name, before = op.Name, _post(op)
    with reopened(doc, tmp_path / "a.FCStd") as doc2:
        calls = plan_calls[0]
        assert _post(doc2.getObject(name)) == before
        assert plan_calls[0] == calls
        doc2.saveAs(str(tmp_path / "b.FCStd"))  # saved with the plans it reused
    with opened(str(tmp_path / "a.FCStd")) as doc3:
        doc3.saveAs(str(tmp_path / "c.FCStd"))  # saved before any post
    for again in ("b.FCStd", "c.FCStd"):
        with opened(str(tmp_path / again)) as doc4:
            assert _post(doc4.getObject(name)) == before, again
            assert plan_calls[0] == calls, again


def _change_width(op, model):
    op.Width = 3.5


def _change_model_shape(op, model):
    # the same faces, the cylinder 0.5 mm larger (20 -> 20.5); Base names the same face again
    # (FreeCAD's element map marks it "?Face3" when the shape is replaced)
    base = [(obj, [sub.lstrip("?") for sub in subs]) for obj, subs in op.Base]
    model.Shape = shaft_shape([(r + 0.5 if r == 20 else r, z) for r, z in PROFILE])
    op.Base = base


def _change_model_placement(op, model):
    model.Placement = FreeCAD.Placement(FreeCAD.Vector(0, 0, 1), FreeCAD.Rotation())


def _change_tool_controller(op, model):
    op.ToolController.HorizFeed = "50 mm/min"


def _change_tool_bit(op, model):
    bit = op.ToolController.Tool
    name = next(n for n in bit.PropertiesList if hasattr(getattr(bit, n), "Value"))
    setattr(bit, name, getattr(bit, name).Value + 1.0)


def _change_model_label(op, model):
    model.Label = "Bar"  # the posts name each groove's face by it


def _change_stock(op, model):
    # a larger stock moves the safe start point the first groove is linked from
    op.Proxy._parent_job(op).Stock.Shape = Part.makeCylinder(30, 80, FreeCAD.Vector(0, 0, -5))


def _change_engine(op, model, monkeypatch):
    monkeypatch.setattr(plan_cache, "engine_stamp", lambda: "another version")


CHANGES = [_change_width, _change_model_shape, _change_model_placement, _change_model_label, _change_stock,
           _change_tool_controller, _change_tool_bit]


@pytest.mark.parametrize("change", CHANGES + [_change_engine], ids=lambda f: f.__name__)
def test_a_changed_input_makes_the_post_plan_again(shop, tmp_path, plan_calls, monkeypatch, change):
    doc = shop[0]
    op = _grooves(shop)
    name, job_name = op.Name, shop[2].Name
    with reopened(doc, tmp_path / "a.FCStd") as doc2:
        op2 = doc2.getObject(name)
        model = doc2.getObject(job_name).Model.Group[0]
        if change is _change_engine:
            change(op2, model, monkeypatch)
        else:
            change(op2, model)
        for obj in doc2.Objects:  # as a document saved with the new value and not recomputed opens
            obj.purgeTouched()
        calls = plan_calls[0]
        text = _post(op2)
        assert plan_calls[0] > calls
        assert text == _fresh_post(op2)


def test_restored_plans_are_the_saved_ones(shop):
    op = _grooves(shop)
    plans = op.Proxy.current_plan(op)
    stamp = plan_cache.fingerprint(op, shop[2])
    restored = plan_cache.unpack(plan_cache.pack(plans, stamp))
    assert restored == [dataclasses.replace(plan, geometry=None) for plan in plans]

    def types(plans):  # 1 and 1.0 are equal but are not written alike: the saved data keeps each value's type
        return [([type(v) for v in dataclasses.astuple(p.cycle)], [[type(v) for v in move] for move in p.moves],
                 [[type(v) for v in step] for step in p.link + p.retreat]) for p in plans]

    assert types(restored) == types(plans)
    assert plan_cache.saved_fingerprint(plan_cache.pack(plans, stamp)) == stamp
    assert plan_cache.saved_fingerprint("not saved plans") is None


@pytest.mark.parametrize("path", ["demo_part_saved_at_bfb45ff.FCStd", "groove_gui_saved_at_bfb45ff.FCStd"])
def test_documents_saved_before_open_and_post(path, plan_calls):
    with opened(DATA + "/" + path) as saved:
        ops = [obj for obj in saved.Objects if isinstance(getattr(obj, "Proxy", None), groove_op.ObjectGroove)]
        assert ops
        for op in ops:
            text = _post(op)
            assert "G1" in text, op.Label
        assert plan_calls[0] >= len(ops)  # they saved no plans


def _three_ops(shop):
    """Three Groove ops on the cylinder of the shaft, in one Job."""
    ops = [_grooves(shop)]
    for position in (12, 14):
        ops.append(tg.groove(shop, "cylinder", position=position))
        assert op_error(ops[-1]) is None, op_error(ops[-1])
    return ops


@pytest.fixture
def shape_digests(monkeypatch):
    """The Shape digests plan_cache takes, counted: [count]."""
    calls = [0]
    digest = plan_cache._shape_digest

    def counted(shape):
        calls[0] += 1
        return digest(shape)

    monkeypatch.setattr(plan_cache, "_shape_digest", counted)
    return calls


def test_the_first_post_after_reopening_reads_each_shared_input_once(shop, tmp_path, plan_calls, shape_digests):
    # the ops' Base and the Job's model are one object: its Shape, and the stock's, are digested once for all
    names = [op.Name for op in _three_ops(shop)]
    with reopened(shop[0], tmp_path / "a.FCStd") as doc2:
        ops = [doc2.getObject(name) for name in names]
        calls, digests = plan_calls[0], shape_digests[0]
        demo.load_post("linuxcnc").export([ops[0].ToolController] + ops, "-", "")
        assert plan_calls[0] == calls
        assert shape_digests[0] - digests == 2  # the shaft and the stock


def test_saved_plans_are_read_as_the_document_opens(shop, tmp_path, plan_calls, monkeypatch):
    # the first post only checks their fingerprint
    op = _grooves(shop)
    name, before = op.Name, _post(op)
    with reopened(shop[0], tmp_path / "a.FCStd") as doc2:
        reads = []
        monkeypatch.setattr(plan_cache, "read", lambda text: reads.append(text))
        calls = plan_calls[0]
        assert _post(doc2.getObject(name)) == before
        assert (reads, plan_calls[0]) == ([], calls)


def test_an_op_changed_while_closed_plans_again_its_siblings_do_not(shop, tmp_path, plan_calls):
    # the first post checks every Groove op of the Job at once: the changed one plans again, alone
    names = [op.Name for op in _three_ops(shop)]
    with reopened(shop[0], tmp_path / "a.FCStd") as doc2:
        ops = [doc2.getObject(name) for name in names]
        ops[1].Width = 3.5
        for obj in doc2.Objects:
            obj.purgeTouched()
        calls = plan_calls[0]
        texts = [_post(op) for op in ops]
        assert plan_calls[0] == calls + 1
        assert texts[1] == _fresh_post(ops[1])
        assert [_post(op) for op in ops] == texts


def _saved_with_width(path, op_name, width):
    """The saved document at ``path`` with the op's Width replaced in its Document.xml (an edit of the file)."""
    with zipfile.ZipFile(str(path)) as saved:
        members = [(info, saved.read(info.filename)) for info in saved.infolist()]
    pattern = re.compile(r'(<Object name="%s"[^>]*>.*?<Property name="Width" type="App::PropertyLength"[^>]*>\s*'
                         r'<Float value=")[^"]+(")' % op_name, re.S)
    edited = path.with_name("edited.FCStd")
    with zipfile.ZipFile(str(edited), "w", zipfile.ZIP_DEFLATED) as out:
        for info, data in members:
            if info.filename == "Document.xml":
                text, count = pattern.subn(r"\g<1>%r\g<2>" % width, data.decode())
                assert count == 1, "the op's Width not found once in Document.xml"
                data = text.encode()
            out.writestr(info, data)
    return edited


def test_an_op_edited_in_the_saved_file_plans_again(shop, tmp_path, plan_calls):
    # the Width changed in the file's Document.xml, its saved plans not: the first post's fingerprint finds it
    # (the other tests change a value after opening, as such an edit leaves it)
    ops = _three_ops(shop)
    names, before = [op.Name for op in ops], _post(ops[1])
    shop[0].saveAs(str(tmp_path / "a.FCStd"))
    FreeCAD.closeDocument(shop[0].Name)
    edited = _saved_with_width(tmp_path / "a.FCStd", names[1], 3.5)
    with opened(str(edited)) as doc2:
        ops = [doc2.getObject(name) for name in names]
        assert ops[1].Width.Value == 3.5
        calls = plan_calls[0]
        texts = [_post(op) for op in ops]
        assert plan_calls[0] == calls + 1  # the edited op alone
        assert texts[1] != before  # the 3.5 mm groove, not the saved plans' 4 mm one
        assert texts[1] == _fresh_post(ops[1])


def test_no_post_after_reopening_plans_again(shop, tmp_path, plan_calls):
    # issue 21: posts after save, close and reopen planned every op again, at every post
    names = [op.Name for op in _three_ops(shop)]
    with reopened(shop[0], tmp_path / "a.FCStd") as doc2:
        ops = [doc2.getObject(name) for name in names]
        calls = plan_calls[0]
        for _post_again in range(3):
            demo.load_post("linuxcnc").export([ops[0].ToolController] + ops, "-", "")
        assert plan_calls[0] == calls


@pytest.mark.parametrize("change", [_change_width, _change_tool_controller], ids=lambda f: f.__name__)
def test_plans_made_after_reopening_are_kept_for_the_next_posts(shop, tmp_path, plan_calls, change):
    # an input changed while the document was closed: the first post plans each op it touches once, the
    # next posts reuse those plans (they planned every op again at every post)
    ops = _three_ops(shop)
    names, job_name = [op.Name for op in ops], shop[2].Name
    with reopened(shop[0], tmp_path / "a.FCStd") as doc2:
        ops = [doc2.getObject(name) for name in names]
        change(ops[0], doc2.getObject(job_name).Model.Group[0])
        for obj in doc2.Objects:  # as a document saved with the new value and not recomputed opens
            obj.purgeTouched()
        post = demo.load_post("linuxcnc")
        calls = plan_calls[0]
        first = post.export([ops[0].ToolController] + ops, "-", "")
        planned = plan_calls[0] - calls
        assert 1 <= planned <= len(ops)
        assert post.export([ops[0].ToolController] + ops, "-", "") == first
        assert post.export([ops[0].ToolController] + ops, "-", "") == first
        assert plan_calls[0] - calls == planned
        doc2.saveAs(str(tmp_path / "b.FCStd"))  # saved with the plans made after reopening
    with opened(str(tmp_path / "b.FCStd")) as doc3:
        ops = [doc3.getObject(name) for name in names]
        calls = plan_calls[0]
        assert demo.load_post("linuxcnc").export([ops[0].ToolController] + ops, "-", "") == first
        assert plan_calls[0] == calls


@pytest.mark.parametrize("path", ["demo_part_saved_at_bfb45ff.FCStd"])
def test_a_document_saved_before_plans_once_then_reuses_them(path, plan_calls):
    with opened(DATA + "/" + path) as saved:
        ops = [obj for obj in saved.Objects if isinstance(getattr(obj, "Proxy", None), groove_op.ObjectGroove)]
        post = demo.load_post("linuxcnc")
        calls = plan_calls[0]
        first = post.export([ops[0].ToolController] + ops, "-", "")
        assert plan_calls[0] - calls == len(ops)  # it saved no plans
        assert post.export([ops[0].ToolController] + ops, "-", "") == first
        assert plan_calls[0] - calls == len(ops)
