"""The demo of every system (freecad_groove/demo/) inside FreeCAD (1.1 and 1.0; run by tests/freecad/run_suite.py;
tests/test_demo.py runs it through scripts/demo in 1.1 only).

demo.run() builds one document with a Groove Job (the shaft, its stock the
part as turned), a Slot Job (Cylinder slot), a Grind Job (Plunge grind) and a
Mill Job (CAM's Face and Pocket Shape ops), runs the Groove Job's turning
check, saves the document and posts every program. Checked here: the
document reopens with those Jobs and ops, the check is clean, every native
program holds its cycle words as blocks (written out here, not taken from
the demo), and the demo fails loudly on a turning check that is not clean
and on a native program without its cycle word.
"""

import os
import re

import FreeCAD
import Path.Main.Stock as PathStock
import pytest
from pylib import require_shapely

from freecad_groove import demo
from freecad_groove.demo import runner

# program file (after "demo_part_") -> the cycle words its blocks must start with
NATIVE = {"sinumerik_native.mpf": {"CYCLE93"}, "ab9_native.nc": {"G77", "G76"}, "fanuc_native.nc": {"G75", "G74"},
          "haas_native.nc": {"G75", "G74"}, "slot_gsk_native.nc": {"G7.1"}, "grind_ab9_native.nc": {"G83"},
          "mill_milltronics_native.nc": {"G33", "G34"}}
EXPANDED = ["sinumerik_expanded.mpf", "ab9_expanded.nc", "fanuc_expanded.nc", "haas_expanded.nc", "linuxcnc.ngc",
            "slot_linuxcnc.ngc", "grind_linuxcnc.ngc"]
CALL = re.compile(r"^(CYCLE93|G7[4-7]|G7\.1|G83|G3[34])(?![\d.])", re.M)
# (Job label, the class of each op's proxy, in order)
JOBS = [
    ("Groove Job", ["ObjectGroove"] * 5),
    ("Slot Job", ["ObjectCylinderSlot"]),
    ("Grind Job", ["ObjectPlungeGrind"]),
    ("Mill Job", ["ObjectFace", "ObjectPocket"]),
]


@pytest.fixture(scope="module")
def ran(tmp_path_factory):
    require_shapely()
    out = tmp_path_factory.mktemp("demo")
    return out, demo.run(str(out))


def test_the_demo_document_reopens_with_every_systems_job_and_ops(ran):
    out, _summary = ran
    doc = FreeCAD.openDocument(str(out / "demo_part.FCStd"))
    try:
        jobs = [o for o in doc.Objects if hasattr(o, "Operations") and hasattr(o, "Model")]
        got = [(job.Label, [type(op.Proxy).__name__ for op in job.Operations.Group]) for job in jobs]
        assert got == JOBS
        groove_job = jobs[0]
        assert groove_job.Stock.Shape.Volume == pytest.approx(groove_job.Model.Group[0].Shape.Volume, rel=1e-9)
    finally:
        FreeCAD.closeDocument(doc.Name)


def test_the_groove_jobs_turning_check_is_clean_and_written(ran):
    out, summary = ran
    check = summary["turning_check"]
    assert check["clean"] and len(check["ops"]) == 5
    assert all(op["ok"] and op["removed"] > 0 and not op["rapid_hits"] for op in check["ops"]), check
    text = (out / "demo_part_turning_check.txt").read_text()
    assert text.splitlines()[0].endswith("5 op(s): ok") and "stock: the Job's stock" in text, text


def test_every_native_program_holds_its_cycle_words_and_no_expanded_one_any(ran):
    out, summary = ran
    for name, words in NATIVE.items():
        text = (out / ("demo_part_" + name)).read_text()
        assert set(CALL.findall(text)) == words, (name, text)
    for name in EXPANDED:
        text = (out / ("demo_part_" + name)).read_text()
        assert not CALL.findall(text), (name, text)
    written = sorted(os.listdir(out))
    assert written == sorted(name for name, _what in summary["files"])
    listing = (out / "summary.txt").read_text()
    assert all(re.search(r"^  %s " % re.escape(name), listing, re.M) for name in written), listing


def test_the_mill_programs_face_and_pocket_are_g33_and_g34_in_either_freecad(ran):
    out, _summary = ran
    lines = (out / "demo_part_mill_milltronics_native.nc").read_text().splitlines()
    # FreeCAD 1.0's Face op never cuts its last depth (its Path stops at 20.5): the G33 says so
    floor = "20.5" if FreeCAD.Version()[:2] == ["1", "0"] else "20."
    assert "G33 G99 G41 R24. Z%s V20.5 Q0.5 F300." % floor in lines
    assert "G34 G99 G41 R24. Z15. V19. Q2. F300." in lines
    assert lines[lines.index("(Pocket: G34)") + 2] == "G0 X90. Y60."  # the pocket's centre on the moved block


def test_a_turning_check_that_is_not_clean_fails_the_demo(closing, tmp_path):
    # issue 21: on a bar stock R25 the grooves below the bar's surface rapid through standing stock
    require_shapely()
    doc = FreeCAD.newDocument("DemoNotClean")
    closing.append(doc)
    FreeCAD.setActiveDocument(doc.Name)
    part = demo.make_part(doc)
    job, tc = demo.make_job(doc, part)
    ops = demo.make_ops(doc, job, part, tc)
    old = job.Stock
    job.Stock = PathStock.CreateCylinder(job, 25.0, 75.0, FreeCAD.Placement())
    doc.removeObject(old.Name)
    doc.recompute()
    with pytest.raises(demo.TurningCheckNotClean, match=r"^the Groove Job's turning check is not clean "
                                                        r"\(demo_part_turning_check.txt\):\nTurning check: .*PROBLEMS"):
        runner.turning_check(job, ops, str(tmp_path))
    assert "RAPID THROUGH STOCK" in (tmp_path / "demo_part_turning_check.txt").read_text()


def test_a_native_post_that_writes_no_cycle_fails_the_demo(closing, tmp_path):
    doc = FreeCAD.newDocument("DemoNoCycle")
    closing.append(doc)
    FreeCAD.setActiveDocument(doc.Name)
    part = demo.make_part(doc)
    job, tc = demo.make_job(doc, part)
    ops = demo.make_ops(doc, job, part, tc)
    program = ("groove", "sinumerik_lathe", "native", "--expand-cycles", "x.mpf")  # "native", posted expanded
    with pytest.raises(demo.CycleWordMissing, match=r"^x\.mpf: the sinumerik_lathe post wrote no CYCLE93 block"):
        demo.posting.post_program([tc] + ops, str(tmp_path), program)
