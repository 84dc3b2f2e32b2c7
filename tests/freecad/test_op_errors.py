"""What the ops did not see (issue 20, items 6 and 12), each case by hand:
non-finite values given to make_groove/make_cylinder_slot/make_plunge_grind,
a feed per revolution the Path would write as "F inf", Plunge grind lengths
that overflowed, a tool bit changed under a Cylinder slot, the modelled part
or the Job's clone deleted under the lathe and grinder posts.

Run inside FreeCAD 1.1 and 1.0 (tests/freecad/run_suite.py).
"""

import importlib.util
import math
import os

import FreeCAD
import pytest
from parts import face_name, make_shop
from test_op_bounds import GROOVE, grind_job, grind_shop, slot_shop

from freecad_groove import make_cylinder_slot, make_groove, make_plunge_grind
from freecad_groove.freecad.addon_op import op_error
from freecad_groove.freecad.posts import PostError

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
LATHE_POSTS = ("sinumerik_lathe", "ab9_lathe", "fanuc_lathe", "haas_lathe", "gsk_lathe", "linuxcnc_lathe")
GRIND_POSTS = ("ab9_grind", "linuxcnc_grind")


def post(name, objects, args=""):
    """postprocessors/<name>_post.py's export, loaded from its file as FreeCAD loads a script post."""
    spec = importlib.util.spec_from_file_location(name + "_post", os.path.join(ROOT, "postprocessors",
                                                                               name + "_post.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.export(objects, "-", args)


@pytest.fixture
def doc():
    d = FreeCAD.newDocument("OpErrors")
    FreeCAD.setActiveDocument(d.Name)
    yield d
    if d.Name in FreeCAD.listDocuments():
        FreeCAD.closeDocument(d.Name)


def names(document):
    return sorted(o.Name for o in document.Objects)


# -- item 6: the make_* calls -------------------------------------------------------------------------------


@pytest.mark.parametrize("keyword, value", [("dwell", float("nan")), ("dwell", float("inf")),
                                            ("depth", float("nan")), ("feed_per_rev", float("inf")),
                                            ("surface_speed", float("-inf")), ("width", "nan mm")])
def test_make_groove_refuses_a_non_finite_value_leaving_nothing_behind(doc, keyword, value):
    doc, shaft, job, tc = make_shop(doc)
    before = names(doc)
    values = dict(GROOVE)
    values[keyword] = value
    with pytest.raises(ValueError, match=r"^make_groove\(\): %s=" % keyword) as info:
        make_groove(job, (shaft, face_name(shaft.Shape, "cylinder")), **values)
    assert "\n" not in str(info.value)
    assert names(doc) == before and job.Operations.Group == []


@pytest.mark.parametrize("keyword", ["depth", "allowance", "retract"])
def test_make_cylinder_slot_refuses_a_non_finite_value_leaving_nothing_behind(keyword):
    doc, op, (shaft, line, job, tc) = slot_shop()
    try:
        before = names(doc)
        with pytest.raises(ValueError, match=r"^make_cylinder_slot\(\): %s=nan" % keyword):
            make_cylinder_slot(job, (shaft, "Face1"), [(line, "Edge1")], **{keyword: float("nan")})
        assert names(doc) == before and job.Operations.Group == [op]
    finally:
        FreeCAD.closeDocument(doc.Name)


@pytest.mark.parametrize("keyword", ["depth", "start_clearance", "overtravel", "wheel_diameter", "plunge_feed"])
def test_make_plunge_grind_refuses_a_non_finite_value_leaving_nothing_behind(keyword):
    doc, block, job = grind_job()
    try:
        before = names(doc)
        with pytest.raises(ValueError, match=r"^make_plunge_grind\(\): %s=inf" % keyword):
            make_plunge_grind(job, (block, "Face6"), wheel_width=10, **{keyword: float("inf")})
        assert names(doc) == before and job.Operations.Group == []
    finally:
        FreeCAD.closeDocument(doc.Name)


def test_a_nan_dwell_set_later_leaves_no_moves_and_every_post_refuses_it(doc):
    doc, shaft, job, tc = make_shop(doc)
    op = make_groove(job, (shaft, face_name(shaft.Shape, "cylinder")), **GROOVE)
    op.Dwell = float("nan")
    doc.recompute()
    assert op_error(op) == "Dwell=nan: must be a finite number"
    assert [c for c in op.Path.Commands if c.Parameters] == []
    for name in LATHE_POSTS:
        with pytest.raises(PostError, match=r"^%s: Dwell=nan: must be a finite number$" % op.Label):
            post(name, [op])


# -- item 12: values the ops did not see -----------------------------------------------------------------------


@pytest.mark.parametrize("value", [1e308, float("inf")])
def test_a_huge_feed_per_rev_is_refused_naming_it_and_never_written_as_f_inf(doc, value):
    doc, shaft, job, tc = make_shop(doc)
    op = make_groove(job, (shaft, face_name(shaft.Shape, "cylinder")), **GROOVE)
    op.FeedPerRev = value
    doc.recompute()
    error = op_error(op)
    assert error is not None and error.startswith("FeedPerRev=1.79769313486e+308 mm/rev" if math.isinf(value)
                                                  else "FeedPerRev=1e+308 mm/rev"), error
    assert "must be 0 <= FeedPerRev <= 10 mm/rev" in error
    assert all(math.isfinite(v) for c in op.Path.Commands for v in c.Parameters.values())
    with pytest.raises(PostError, match=r"^%s: FeedPerRev=" % op.Label):
        post("fanuc_lathe", [op])
    op.FeedPerRev = 0.1  # a real feed: cut again
    doc.recompute()
    assert op_error(op) is None


@pytest.mark.parametrize("name", ["Allowance", "StartClearance", "WheelWidth", "WheelDiameter", "Retract"])
def test_plunge_grind_lengths_beyond_a_g83_word_are_refused_naming_them(name):
    doc, op, _others = grind_shop()
    try:
        setattr(op, name, 1e308)
        doc.recompute()
        assert op_error(op) == "%s=1e+308 mm: must be 0 <= %s < 100000 mm" % (name, name)
        with pytest.raises(PostError, match=r"^%s: %s=1e\+308 mm" % (op.Label, name)):
            post("ab9_grind", [op])
    finally:
        FreeCAD.closeDocument(doc.Name)


def _slot_post(op):
    return post("linuxcnc_lathe", [op], "--switches-by-hand")


@pytest.mark.parametrize("change", ["diameter 0", "no tool"])
def test_a_cylinder_slot_recomputes_when_its_tool_changes_and_is_not_posted_without_one(change):
    doc, op, (shaft, line, job, tc) = slot_shop()
    try:
        assert op_error(op) is None and "G1" in _slot_post(op)
        if change == "diameter 0":
            tc.Tool.Diameter = 0
        else:
            tc.Tool = None
        doc.recompute()
        error = op_error(op)
        assert error is not None and error.startswith("ToolController: "), error
        if "Invalid" not in tc.State:  # recomputed: no stale toolpath
            assert [c for c in op.Path.Commands if c.Parameters] == []
        else:  # FreeCAD 1.1: a tool controller without a tool is itself Invalid, and its ops wait for it
            assert change == "no tool"
        with pytest.raises(PostError, match=r"^%s: ToolController: " % op.Label):
            _slot_post(op)
    finally:
        FreeCAD.closeDocument(doc.Name)


def test_a_changed_tool_is_seen_by_the_post_even_before_a_recompute():
    doc, op, (shaft, line, job, tc) = slot_shop()
    try:
        _slot_post(op)
        tc.Tool.Diameter = 0  # no recompute: the post plans again
        with pytest.raises(PostError, match=r"^%s: ToolController: " % op.Label):
            _slot_post(op)
    finally:
        FreeCAD.closeDocument(doc.Name)


def test_deleting_the_modelled_part_gives_the_lathe_posts_one_line_naming_the_op(doc):
    doc, shaft, job, tc = make_shop(doc)
    op = make_groove(job, (shaft, face_name(shaft.Shape, "cylinder")), **GROOVE)
    doc.removeObject(shaft.Name)
    doc.recompute()
    error = op_error(op)
    assert error is not None and error.startswith("Base: ") and "deleted" in error, error
    for name in LATHE_POSTS:
        with pytest.raises(PostError) as info:
            post(name, [op])
        assert str(info.value).startswith(op.Label + ": Base: ") and "\n" not in str(info.value), str(info.value)


def test_with_the_jobs_clone_deleted_no_groove_op_is_posted(doc):
    doc, shaft, job, tc = make_shop(doc)
    op = make_groove(job, (shaft, face_name(shaft.Shape, "cylinder")), **GROOVE)
    doc.removeObject(job.Model.Group[0].Name)
    doc.recompute()
    assert (op_error(op) or "").startswith("Base: "), op_error(op)
    assert [c for c in op.Path.Commands if c.Parameters] == []
    for name in LATHE_POSTS:
        with pytest.raises(PostError, match=r"^%s: Base: " % op.Label):
            post(name, [op])


def test_with_the_jobs_clone_deleted_no_plunge_grind_is_posted():
    doc, op, (block, job, tc) = grind_shop()
    try:
        doc.removeObject(job.Model.Group[0].Name)
        doc.recompute()
        assert (op_error(op) or "").startswith("Base: "), op_error(op)
        assert [c for c in op.Path.Commands if c.Parameters] == []
        for name in GRIND_POSTS:
            with pytest.raises(PostError, match=r"^%s: Base: " % op.Label):
                post(name, [op])
    finally:
        FreeCAD.closeDocument(doc.Name)
