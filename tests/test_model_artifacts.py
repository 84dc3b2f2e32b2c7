"""Grooves read from modelled parts cut exactly the modelled groove: checked
on the host by the simulation oracle (it does not exist inside the FreeCAD
roots).

tests/freecad/write_model_artifacts.py runs inside FreeCAD 1.1 and 1.0 (once
per session, ``scripts/freecad-roots run LABEL --share <pytest tmp dir>``):
for every part of tests/freecad/model_parts.py a Groove op made by
make_groove with no dimensions, its expanded moves, and the part's section
as FreeCAD's own boolean makes it. Here the moves are swept through the bar
before grooving: the material they remove must be the modelled groove (no
gouge into the part, nothing left that the blade can reach, no rapid into
material).
"""

import json

import pytest
from freecad_roots import FREECADCMD, LABELS, describe, exec_code, once_per_label, run
from shapely.geometry import Polygon

from freecad_groove import verify as sim
from freecad_groove.engine import GroovingTool
from freecad_groove.engine.moves import Move

WRITER_CODE = exec_code("tests/freecad/write_model_artifacts.py")
WRITE_TIMEOUT = 600
CASES = 10  # the parts of model_parts.CASES


@pytest.fixture(scope="session")
def modelled(tmp_path_factory):
    """cases(label): the artifacts FreeCAD ``label`` wrote, once per session."""
    return once_per_label(_write, tmp_path_factory, "model-artifacts-")


def _write(label, share):
    env = {"FREECAD_GROOVE_RESULT": "model-artifacts.json", "FREECAD_GROOVE_ARTIFACTS": "model-artifacts"}
    proc, where = run(label, share, FREECADCMD, [WRITER_CODE], env, WRITE_TIMEOUT)
    result_file = share / "model-artifacts.json"
    assert result_file.exists(), "FreeCAD %s (%s) wrote no result:\n%s" % (label, where, describe(proc))
    result = json.loads(result_file.read_text())
    assert not result["error"] and proc.returncode == 0, "FreeCAD %s (%s):\n%s\n%s" % (
        label, where, result["error"], describe(proc))
    return [json.loads((share / "model-artifacts" / name).read_text()) for name in sorted(result["written"])]


@pytest.mark.parametrize("label", LABELS)
def test_ops_read_from_modelled_grooves_cut_exactly_the_modelled_groove(modelled, label):
    cases = modelled(label)
    assert len(cases) == CASES
    for case in cases:
        name = "FreeCAD %s %s (%s)" % (case["freecad"], case["case"], case["derived"])
        assert case["error"] is None, "%s: %s" % (name, case["error"])
        tool = case["tool"]
        blade = GroovingTool(tool["width"], tool["corner_radius"], reference=tool["reference"])
        bar = Polygon(case["bar"]).buffer(0)
        part = Polygon(case["part"]).buffer(0)
        target = bar.difference(part)
        assert target.area > 1.0, name  # the modelled groove is there
        moves = [Move(kind, x, z, None, p, centre=centre and tuple(centre)) for kind, x, z, p, centre in case["moves"]]
        result = sim.simulate(moves, blade, case["plunge"], tuple(case["start"]), bar)
        verdict = sim.check_groove(result, target, blade, tol=0.001, plunge=case["plunge"], label=name)
        sim.assert_clean(verdict, allow_infeasible=True)
