"""verify_job(), the turning check, inside FreeCAD (1.1 and 1.0; run by tests/freecad/run_suite.py).

The stepped shaft of parts.py (R20 at Z10..30) in a Job whose stock is a bar
of its largest radius, R20 from Z0 to Z60, so that a groove in the R20
cylinder removes exactly the groove: 4 wide and 2 deep (8 mm^2 of the half
section) less what the blade's 0.2 mm corner radius cannot reach in its two
sharp base corners, 0.2^2 (1 - pi/4) each. The check runs on numpy alone (FreeCAD
has no shapely): one test runs it with shapely blocked.
"""

import math
import sys

import FreeCAD
import Path
import Path.Main.Stock as PathStock
import pytest
from parts import face_name, make_shop

from freecad_groove import make_groove, verify_job
from freecad_groove.ops.turning_check.check import TurningCheckError

FILLET = 0.2**2 * (1 - math.pi / 4)
GROOVE = dict(width=4, depth=2, infeed=1, tool_width=3, tool_corner_radius=0.2)


@pytest.fixture
def shop():
    """(doc, shaft, job, tc) with the Job's stock a bar R20 from Z0 to Z60."""
    doc = FreeCAD.newDocument("TurningCheckTest")
    FreeCAD.setActiveDocument(doc.Name)
    doc, shaft, job, tc = make_shop(doc)
    old = job.Stock
    job.Stock = PathStock.CreateCylinder(job, 20.0, 60.0, FreeCAD.Placement())
    doc.removeObject(old.Name)
    doc.recompute()
    yield doc, shaft, job, tc
    FreeCAD.closeDocument(doc.Name)


def cylinder_groove(shop, **values):
    values = {**GROOVE, "position": 5, **values}
    _doc, shaft, job, _tc = shop
    return make_groove(job, (shaft, face_name(shaft.Shape, "cylinder")), **values)


def test_a_groove_removes_its_area_without_gouge(shop):
    op = cylinder_groove(shop)
    result = verify_job(shop[2])
    check = result.ops[0]
    assert check.label == op.Label and check.ok, result.summary()
    assert check.removed == pytest.approx(8.0 - 2 * FILLET, abs=1e-3)
    assert check.unreachable == pytest.approx(2 * FILLET, abs=1e-4)
    assert check.unreachable == pytest.approx(check.reach_warning, abs=1e-4)  # the cycle's own reach warning
    assert check.gouge_depth == 0 and check.leftover == 0 and not check.rapid_hits
    assert "bar R20.000 from Z0.000 to Z60.000" in result.summary()


def test_a_path_plunging_too_deep_shows_the_gouge_and_where(shop):
    """The Path edited so that its plunges at Z21 reach X17, 1 mm below the groove's base R18."""
    op = cylinder_groove(shop)
    commands = []
    for command in op.Path.Commands:
        words = dict(command.Parameters)
        if command.Name == "G1" and abs(words.get("X", 0) - 18.0) < 1e-9 and abs(words.get("Z", 0) - 21.0) < 1e-9:
            words["X"] = 17.0
        commands.append(Path.Command(command.Name, words))
    op.Path = Path.Path(commands)
    check = verify_job(shop[2]).ops[0]
    assert not check.ok
    assert check.gouge_depth == pytest.approx(1.0, abs=1e-3)
    x, z = check.gouge_at
    assert 17.0 <= x <= 18.0 and 21.0 <= z <= 24.0, check.gouge_at
    assert check.summary().startswith(op.Label + ": PROBLEMS") and "GOUGE" in check.summary()


@pytest.mark.parametrize("speeds, expected", [
    # 3 mm at 0.01 mm/rev x 100 rpm = 1 mm/min: 180 s
    (dict(spindle_speed=100), "00:03:00"),
    # V = 10 m/min: rpm(x) = 10000 / (2 pi x) (below the 100 rpm limit from R15.9 out), so
    # t = int_18^21 2 pi x / (0.01 * 10000) dx = pi (21^2 - 18^2) / 100 min = 220.54 s
    (dict(surface_speed="10 m/min", max_spindle_speed=100), "00:03:41"),
])
def test_cycle_time_is_the_hand_computed_time(shop, speeds, expected):
    """A groove as wide as the blade in one plunge: G0 X21 Z22, G1 X18 Z22 (from R20 + the 1 mm retract)."""
    op = cylinder_groove(shop, width=3, infeed=2, feed_per_rev=0.01, **speeds)
    feeds = [(c.Parameters["X"], c.Parameters["Z"]) for c in op.Path.Commands if c.Name == "G1"]
    assert feeds == [(18.0, 22.0)]
    check = verify_job(shop[2]).ops[0]
    assert op.CycleTime == expected, check.summary()
    assert shop[2].CycleTime == expected


def test_an_op_with_an_error_is_named_not_checked(shop):
    op = cylinder_groove(shop, position=50)  # past the face (Z10..30)
    check = verify_job(shop[2]).ops[0]
    assert check.error and "past the face" in check.error
    assert check.summary().startswith("%s: not checked:" % op.Label)


def test_the_check_needs_no_shapely(shop, monkeypatch):
    """With shapely not importable (and the check's modules imported afresh under that), verify_job gives the
    groove's figures: FreeCAD ships numpy, not shapely."""
    cylinder_groove(shop)
    for name in ["shapely"] + [n for n in sys.modules if n.startswith("shapely.")]:
        monkeypatch.setitem(sys.modules, name, None)  # import shapely (or any of its modules) raises ImportError
    for name in [n for n in sys.modules if n.startswith(("freecad_groove.verify", "freecad_groove.ops.turning_check"))]:
        monkeypatch.delitem(sys.modules, name)
    check = verify_job(shop[2]).ops[0]
    assert check.ok and check.removed == pytest.approx(8.0 - 2 * FILLET, abs=1e-3)
    assert check.unreachable == pytest.approx(2 * FILLET, abs=1e-4)


def test_not_a_job_is_one_clear_message(shop):
    with pytest.raises(TurningCheckError, match="is not a CAM Job"):
        verify_job(shop[1])


def test_the_part_as_turned_is_the_stock_a_grooving_op_assumes(shop):
    # the shaft's R20 cylinder from Z10 to Z30 is its largest radius: a bar R25 around the part stands where
    # the op's rapids go down to the groove (the op assumes the part turned to its contour first)
    doc, shaft, job, _tc = shop
    old = job.Stock
    job.Stock = PathStock.CreateCylinder(job, 25.0, 60.0, FreeCAD.Placement())
    doc.removeObject(old.Name)
    doc.recompute()
    op = cylinder_groove(shop)
    on_bar = verify_job(job)
    assert on_bar.ops[0].rapid_hits and on_bar.notes[0].startswith("stock: a bar R25.000"), on_bar.summary()
    turned = verify_job(job, stock="turned")
    check = turned.ops[0]
    assert turned.ok and not check.rapid_hits, turned.summary()
    assert turned.notes[0] == "stock: the part as turned (the model's contour plus the material of the ops' " \
                              "planned grooves)"
    assert check.removed == pytest.approx(4 * 2 - 2 * FILLET, abs=1e-3)  # the groove, as on the R20 bar
    assert check.label == op.Label


def test_a_stock_made_from_an_existing_solid_is_its_own_section(shop):
    from freecad_groove.demo import turned_stock

    doc, shaft, job, _tc = shop
    turned_stock(doc, job, shaft)  # CAM's stock from an existing solid: the part itself
    doc.recompute()
    cylinder_groove(shop)
    result = verify_job(job)
    assert result.ok and result.notes[0].startswith("stock: the Job's stock"), result.summary()
    assert result.notes[0].endswith("its own section")


def test_an_unknown_stock_choice_is_one_clear_message(shop):
    with pytest.raises(TurningCheckError, match=r"^verify_job\(\): stock='bar': must be 'job' \(the Job's stock\) "
                                                r"or 'turned' \(the part as turned\)$"):
        verify_job(shop[2], stock="bar")


def test_the_demo_job_runs_its_own_turning_check_clean(closing):
    # issue 21: on a bar stock, 4 of its 5 ops rapid through standing stock (no op turns it to the contour)
    from freecad_groove import demo

    doc = FreeCAD.newDocument("DemoCheck")
    closing.append(doc)
    FreeCAD.setActiveDocument(doc.Name)
    part = demo.make_part(doc)
    job, tc = demo.make_job(doc, part)
    demo.make_ops(doc, job, part, tc)
    result = verify_job(job)
    assert result.ok, result.summary()
    assert result.notes[0].startswith("stock: the Job's stock") and len(result.ops) == len(demo.OPS)
    assert all(check.removed > 0 and not check.rapid_hits for check in result.ops), result.summary()
