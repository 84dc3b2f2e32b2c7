"""The lathe posts' programs, checked on the host by LinuxCNC's rs274 and the
simulation oracle (neither exists inside the FreeCAD roots).

The programs come from tests/freecad/write_post_artifacts.py, which the
``posted`` fixture runs itself, once per session, inside FreeCAD 1.1 and 1.0
(``scripts/freecad-roots run LABEL --share <pytest tmp dir>``): one JSON per
case, a Groove op's programs from every post, the engine's moves from the
op's first start point on, and per groove the finished region and a stock
window (engine geometry, world (x radius, z)), the tool (with the reference
corner the programs use), the plunge direction and the peck retract. Here,
for every case and post:

* linuxcnc_lathe: rs274 must accept the program; its canonical moves from
  the moment the tool reaches the start point must be the engine's moves;
* sinumerik/ab9/fanuc/haas: the engine's program translator reads the native
  program (CYCLE93, G77/G76, G75/G74 or expanded moves) and writes it for
  LinuxCNC, which rs274 must accept;
* for every post, the canonical moves (rs274's own reading) from the start
  point on are swept through the stock by the oracle: no gouge, the groove
  complete within the blade's reach, no rapid into stock.

A FreeCAD that is not available skips its tests (CI=true: fails); a FreeCAD
run that writes no programs fails them.
"""

import json
import math
import re

import pytest
import rs274
from freecad_roots import FREECADCMD, LABELS, describe, exec_code, once_per_label, run
from rs274 import RS274Error, canonical_matches, require_rs274, written_moves
from shapely.geometry import Polygon
from shapely.ops import unary_union

from freecad_groove import verify as sim
from freecad_groove.engine import GroovingTool, Settings
from freecad_groove.engine.moves import ARC_CCW, ARC_CW, DWELL, FEED, RAPID, Move
from freecad_groove.engine.translator import translate_program

POSTS = ["linuxcnc", "sinumerik", "ab9", "fanuc", "haas"]
START_TOL = 1e-3  # how close a canonical move must end to the start point (3-decimal output)
KINDS = {"G0": RAPID, "G1": FEED, "G4": DWELL, "G2": ARC_CW, "G3": ARC_CCW}
WRITER_CODE = exec_code("tests/freecad/write_post_artifacts.py")
WRITE_TIMEOUT = 600  # seconds for one FreeCAD's run (about 20 s on a 2-core machine)


def write_artifacts(label, share):
    """Run write_post_artifacts.py in FreeCAD ``label``; the cases it wrote into ``share``."""
    env = {"FREECAD_GROOVE_RESULT": "artifacts.json", "FREECAD_GROOVE_ARTIFACTS": "artifacts"}
    proc, where = run(label, share, FREECADCMD, [WRITER_CODE], env, WRITE_TIMEOUT)
    result_file = share / "artifacts.json"
    assert result_file.exists(), "FreeCAD %s (%s) wrote no result:\n%s" % (label, where, describe(proc))
    result = json.loads(result_file.read_text())
    assert not result["error"] and proc.returncode == 0, "FreeCAD %s (%s) could not write the programs:\n%s\n%s" % (
        label, where, result["error"], describe(proc))
    out = []
    for name in sorted(result["written"]):
        with open(share / "artifacts" / name) as f:
            out.append(json.load(f))
    assert out, "FreeCAD %s (%s) wrote no post programs" % (label, where)
    return out


@pytest.fixture(scope="session")
def posted(tmp_path_factory):
    """cases(label): the programs of FreeCAD ``label``, written once per session
    (an outcome that skipped or failed is repeated for every test that asks)."""
    return once_per_label(write_artifacts, tmp_path_factory, "post-artifacts-")


def run_rs274(text, tools):
    """rs274.run_rs274 with a tool table holding ``tools`` (rs274 refuses a T
    word for a tool it does not know)."""
    require_rs274()
    return rs274.run_rs274(text, timeout=120, tool_table=tools)


def linuxcnc_text(case, post):
    """The program as LinuxCNC text: the linuxcnc_lathe output as is, the
    others through the engine's translator."""
    program = case["programs"][post]
    text = program["text"]
    if post == "linuxcnc":
        return text
    tool = case["tool"]
    unit = 25.4 if case.get("inches") else 1.0  # the translator takes the blade in the program's units
    settings = Settings(tool=GroovingTool(tool["width"] / unit, tool["corner_radius"] / unit,
                                          reference=tool["reference"]), peck_retract=case["retract"] / unit)
    return translate_program(text, post, settings, source_name="%s %s" % (case["case"], post))


def arrival(canon, start):
    """Index of the first canonical move that ends at ``start``."""
    for i, c in enumerate(canon):
        if c[0] in ("G0", "G1") and abs(c[1] - start[0]) <= START_TOL and abs(c[2] - start[1]) <= START_TOL:
            return i
    raise AssertionError("the program never reaches the start point X%.4f Z%.4f (radius)" % tuple(start))


def judge(case, canon, index, label):
    """Sweep the canonical moves after ``index`` through the stock: the oracle's verdict."""
    tool = case["tool"]
    blade = GroovingTool(tool["width"], tool["corner_radius"], reference=tool["reference"])
    moves = [Move(KINDS[c[0]], c[1], c[2], None, c[4] if c[0] == "G4" else 0.0, centre=c.centre)
             for c in canon[index + 1:]]
    stock = unary_union([Polygon([(z, x) for x, z in g["stock"]]) for g in case["grooves"]])
    target = unary_union([Polygon([(z, x) for x, z in g["region"]]).buffer(0) for g in case["grooves"]])
    start = tuple(canon[index][1:3])
    result = sim.simulate(moves, blade, case["plunge"], start, stock)
    verdict = sim.check_groove(result, target, blade, tol=0.001, plunge=case["plunge"], label=label)
    sim.assert_clean(verdict, allow_infeasible=True)
    return verdict


def expected_move(row, feed=True):
    """An engine move of a case's "expected" list: [kind, x, z, f, p, centre]."""
    kind, x, z, f, p, centre = row
    return Move(kind, x, z, f if feed else None, p, centre=None if centre is None else tuple(centre))


def check_inch_moves(case, canon, post, name):
    """An --inches program: rs274 reports inches to 4 decimals (0.00254 mm), coarser than the oracle's
    0.001 mm; the LinuxCNC program's moves, in mm, must still be the engine's to that resolution."""
    if post != "linuxcnc":
        return
    canon = [rs274.Canonical((c[0], c[1] * 25.4, c[2] * 25.4, None, c[4]),
                             None if c.centre is None else (c.centre[0] * 25.4, c.centre[1] * 25.4)) for c in canon]
    index = next(i for i, c in enumerate(canon) if c[0] in ("G0", "G1") and
                 math.dist(c[1:3], case["start"]) <= 0.003)
    expected = [expected_move(m, feed=False) for m in case["expected"]]
    problems = canonical_matches(written_moves(expected), canon, start=index, tol=0.003, centre_tol=0.006)
    assert not problems, "%s:\n%s" % (name, "\n".join(problems[:8]))


@pytest.mark.parametrize("post", POSTS)
@pytest.mark.parametrize("label", LABELS)
def test_posted_grooves_run_in_rs274_and_cut_cleanly(posted, label, post):
    require_rs274()
    checked = 0
    for case in posted(label):
        name = "FreeCAD %s %s %s_lathe %s" % (case["freecad"], case["case"], post, case["programs"][post]["args"])
        program = case["programs"][post]
        if program["text"] is None:
            # the refusals the FreeCAD tests expect on the Allen-Bradley 9/Series: a dwell, constant surface speed
            assert post == "ab9" and ("Dwell" in program["error"] or "constant surface speed" in program["error"]), \
                "%s: %s" % (name, program["error"])
            continue
        text = linuxcnc_text(case, post)
        tools = {int(t) for t in re.findall(r"^T(\d+) M6", text, re.M)}
        try:
            canon = run_rs274(text, tools)
        except RS274Error as e:
            raise AssertionError("%s: rs274 refused the program: %s\n%s" % (name, e, text)) from None
        if case.get("inches"):
            check_inch_moves(case, canon, post, name)
            checked += 1
            continue
        index = arrival(canon, case["start"])
        if post == "linuxcnc":
            expected = [expected_move(m) for m in case["expected"]]
            problems = canonical_matches(written_moves(expected), canon, start=index)
            assert not problems, "%s:\n%s" % (name, "\n".join(problems[:8]))
        judge(case, canon, index, name)
        checked += 1
    assert checked, "no %s program of FreeCAD %s was checked" % (post, label)


def test_every_case_has_native_calls_where_the_control_has_them(posted):
    """The cases cover native CYCLE93, G77/G76 and G75/G74 calls, not only expanded moves."""
    seen = {post: set() for post in POSTS}
    for label in LABELS:
        for case in posted(label):
            for post in POSTS:
                text = case["programs"][post]["text"] or ""
                seen[post] |= set(re.findall(r"^(CYCLE93|G7[4-7])\b", text, re.M))
    assert seen["sinumerik"] == {"CYCLE93"}
    assert seen["ab9"] == {"G77", "G76"}
    assert seen["fanuc"] == {"G75", "G74"} and seen["haas"] == {"G75", "G74"}
    assert seen["linuxcnc"] == set()
