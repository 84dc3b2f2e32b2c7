"""The FreeCAD-level tests (tests/freecad/) and the GUI tests
(tests/freecad_gui/), run inside each FreeCAD.

For every FreeCAD that `scripts/freecad-roots` provides (1.1 and 1.0: Debian
sid and trixie roots, or the host's own freecadcmd) this runs
tests/freecad/run_suite.py under `freecadcmd`, with a directory shared with
the run: the host writes the seed CYCLE93 moves there (the FreeCAD side
compares its own expansion with them) and the run writes its JSON result
there. The GUI tests run in FreeCAD's GUI on a virtual X screen
(`xvfb-run freecad -M <checkout> tests/freecad_gui/start.py`, the same
runner in its GUI mode); their screenshots go to out/gui-screenshots/.
A FreeCAD that is not available skips, with how to get it; under CI=true it
fails. (A host FreeCAD used instead of a root needs `freecad` and
`xvfb-run` too for the GUI tests.)
"""

import ast
import json
import os
import re
import shutil
import sys

import freecad_shapely
import pytest
import rs274
from conftest import ROOT
from freecad_roots import FREECADCMD, LABELS, available, describe, exec_code, run

sys.path.insert(0, os.path.join(ROOT, "tests", "freecad"))
import seed_case  # noqa: E402  (no FreeCAD in it)

SUITE = os.path.join(ROOT, "tests", "freecad", "run_suite.py")
TIMEOUT = 1800  # seconds for one FreeCAD's suite (about 30 s on a 2-core machine)
RUN_SUITE_CODE = exec_code("tests/freecad/run_suite.py")
# The GUI suite: FreeCAD's GUI on a virtual X screen, running a script file.
GUI_COMMAND = ('exec xvfb-run -a -s "-screen 0 1600x1000x24" freecad -M "$FREECAD_GROOVE_CHECKOUT" '
               '"$FREECAD_GROOVE_CHECKOUT/tests/freecad_gui/start.py"')
GUI_TIMEOUT = 2400  # a hang guard, not a speed check: a busy 2-core machine runs the GUI suites several times slower
CROSS_CHECK = "tests/freecad/test_environment.py::test_seed_cycle93_expands_to_the_hosts_moves"


def engine_test_files():
    """ENGINE_TESTS of run_suite.py (read, not imported: it runs on import)."""
    with open(SUITE) as f:
        tree = ast.parse(f.read())
    for node in tree.body:
        if isinstance(node, ast.Assign) and [t.id for t in node.targets] == ["ENGINE_TESTS"]:
            return list(ast.literal_eval(node.value))
    raise AssertionError("ENGINE_TESTS not found in " + SUITE)


def describe_failures(result):
    parts = []
    if result.get("internal_error"):
        parts.append("run_suite.py itself failed:\n" + result["internal_error"])
    for entry in result.get("collection_errors", []):
        parts.append("COLLECTION ERROR %s\n%s" % (entry["nodeid"], entry["longrepr"]))
    for key in ("failed", "errors"):
        for entry in result.get(key, []):
            text = "%s %s (%s)\n%s" % (key.upper()[:-1] if key == "errors" else "FAILED",
                                       entry["nodeid"], entry["when"], entry["longrepr"])
            for stream in ("stdout", "stderr"):
                if entry.get(stream):
                    text += "\n--- captured %s ---\n%s" % (stream, entry[stream])
            parts.append(text)
    return "\n\n".join(parts)


def publish_screenshots(src, label):
    """The GUI run's screenshots to out/gui-screenshots/<label>/ (scripts/screenshots
    copies FreeCAD 1.1's into docs/ for the guide)."""
    dest = os.path.join(ROOT, "out", "gui-screenshots", label)
    shutil.rmtree(dest, ignore_errors=True)
    if src.is_dir():
        shutil.copytree(src, dest)


def run_in_freecad(label, tmp_path, env_extra, command, args=(), timeout=TIMEOUT):
    """Run ``command`` (an sh -c text; ``args`` are its $1...) in FreeCAD
    ``label`` with tmp_path shared; returns (result JSON, summary, output,
    exit status); skips when that FreeCAD is missing."""
    env = dict(env_extra, FREECAD_GROOVE_SUITE_EXIT="1")
    proc, where = run(label, tmp_path, command, args, env, timeout, drop=("FREECAD_GROOVE_PYTEST_ARGS",))
    output = describe(proc)
    result_file = tmp_path / env_extra["FREECAD_GROOVE_RESULT"]
    assert result_file.exists(), "FreeCAD %s (%s) wrote no result:\n%s" % (label, where, output)
    result = json.loads(result_file.read_text())
    counts = result["counts"]
    summary = "FreeCAD %s (%s, %s): %s" % (
        ".".join(result["freecad_version"][:3]) if result["freecad_version"] else "?",
        where, result["python"].split()[0], ", ".join("%s %d" % kv for kv in counts.items() if kv[1]))
    print(summary)
    return result, summary, output, proc.returncode


def check_result(result, summary, returncode, output):
    failures = describe_failures(result)
    assert not failures, "%s\n\n%s\n\nexit status %d" % (summary, failures, returncode)
    assert result["exitstatus"] == 0 and returncode == 0, "%s\n%s" % (summary, output)
    assert result["counts"]["passed"] > 0, summary


LABELS_FOUND = LABELS + sorted(set(available()) - set(LABELS))


@pytest.mark.parametrize("label", LABELS_FOUND)
def test_freecad_level_suite(label, tmp_path):
    with open(tmp_path / seed_case.HOST_MOVES_FILE, "w") as f:
        json.dump(seed_case.as_json(), f)
    env = {"FREECAD_GROOVE_RESULT": "result.json"}
    env.update(freecad_shapely.provide(tmp_path))  # for the turning check (tests/freecad/test_turning_check.py)
    result, summary, output, returncode = run_in_freecad(label, tmp_path, env, FREECADCMD, [RUN_SUITE_CODE])
    check_result(result, summary, returncode, output)
    assert CROSS_CHECK in result["passed"], "%s: %s did not pass (skipped: %s)" % (
        summary, CROSS_CHECK, result["skipped"])
    for name in engine_test_files():
        ran = [n for n in result["passed"] if n.startswith(name + "::")]
        assert ran, "%s: no test of %s passed under FreeCAD's Python" % (summary, name)


@pytest.mark.parametrize("label", LABELS_FOUND)
def test_freecad_gui_suite(label, tmp_path):
    """tests/freecad_gui/ in FreeCAD's GUI under Xvfb; screenshots to out/gui-screenshots/<label>/."""
    env = {"FREECAD_GROOVE_RESULT": "gui-result.json", "FREECAD_GROOVE_SCREENSHOTS": "screenshots"}
    env.update(freecad_shapely.provide(tmp_path))  # for the Check turning command (test_turning_view.py)
    # Once, no retry: a crash of FreeCAD fails like any test (the 1.0 crash of docs/testing.md is mended).
    result, summary, output, returncode = run_in_freecad(label, tmp_path, env, GUI_COMMAND, timeout=GUI_TIMEOUT)
    publish_screenshots(tmp_path / "screenshots", label)
    check_result(result, summary, returncode, output)
    # Only what this FreeCAD lacks may skip (a reason saying "FreeCAD 1.0 has no ...").
    skipped = [s for s in result["skipped"] if "FreeCAD %s has no " % label not in s["reason"]]
    assert not skipped, "%s: skipped %s" % (summary, skipped)
    # the LinuxCNC programs CAM's Post Process command wrote for a new Job (test_new_user_post.py), and for each
    # op's first hour (test_first_hour.py: the groove, the slot with its C axis, the grind)
    names = ["new_job_linuxcnc.ngc"] + ["first_hour_%s.ngc" % what for what in
                                        ("groove_linuxcnc_lathe", "slot_linuxcnc_lathe", "grind_linuxcnc_grind")]
    rs274.require_rs274()
    for name in names:
        posted = tmp_path / "posted" / name
        assert posted.exists(), "%s: CAM_Post wrote no %s" % (summary, name)
        text = posted.read_text()
        tools = {int(t) for t in re.findall(r"^T(\d+) M6", text, re.M)}
        canon = rs274.run_rs274(text, timeout=120, tool_table=tools)  # RS274Error when rs274 refuses it
        assert any(move[0] == "G1" for move in canon), (name, text)
