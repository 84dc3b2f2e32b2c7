"""scripts/demo end to end: the command-line examples and the FreeCAD 1.1 demo
(freecad_groove/demo.py: a turned part, a Job with five Groove ops, every post).

Runs ``scripts/demo DIR`` once into a temporary directory and checks:

* every file it should write exists and is not empty (the expanded examples,
  the FreeCAD document, one program per post and mode, the summaries);
* LinuxCNC's rs274 accepts the linuxcnc_lathe program (with a tool table
  holding its tools), and its blade reaches the axis (the cut-off);
* the native programs hold the native calls (CYCLE93, G77/G76, G75/G74), as
  many as the summary says, and the expanded ones none;
* every Sinumerik, Allen-Bradley, Fanuc and Haas program, native and
  expanded, is read back by the engine's program translator for its dialect
  (freecad_groove.engine.translator.translate_program), and rs274 accepts the
  LinuxCNC program that makes.

FreeCAD 1.1 comes from scripts/freecad-roots. When it is not built (or the
demo cannot run it: not root and no sudo) this skips, except under CI=true,
where it fails. scripts/test does not build the roots for this file alone:
`scripts/freecad-roots ensure` (or a run of tests/test_freecad.py) does.
"""

import json
import os
import re
import subprocess
import zipfile

import pytest
from conftest import IN_CI, ROOT
from freecad_roots import HOW_TO_GET, available
from rs274 import RS274Error, require_rs274, run_rs274

from freecad_groove import demo
from freecad_groove.engine import GroovingTool, Settings
from freecad_groove.engine.translator import translate_program

SCRIPT = os.path.join(ROOT, "scripts", "demo")
LABEL = "1.1"
TIMEOUT = 1800  # seconds (the FreeCAD part takes a few seconds once FreeCAD is built)
EXAMPLES = ["seed_cycle93", "ab9_g77", "fanuc_g75", "haas_g75", "ab9_g83", "milltronics_g33_g34", "gsk_g7_1"]
PLOTTED = ["seed_cycle93", "ab9_g77", "fanuc_g75", "haas_g75"]  # the turning programs (a lathe's XZ section)
NATIVE = {"sinumerik": {"CYCLE93"}, "ab9": {"G77", "G76"}, "fanuc": {"G75", "G74"}, "haas": {"G75", "G74"}}
SKIPPED = "FreeCAD part SKIPPED"


def unavailable(why):
    message = "FreeCAD %s is not available for the demo: %s. %s" % (LABEL, why.strip(), HOW_TO_GET)
    if IN_CI:
        pytest.fail(message + " (CI: a missing FreeCAD is a failure)", pytrace=False)
    pytest.skip(message)


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    """(output dir, scripts/demo's stdout): the demo run once for this module."""
    if LABEL not in available():
        unavailable("`scripts/freecad-roots list` does not list it")
    out = tmp_path_factory.mktemp("demo")
    env = dict(os.environ)
    env.pop("FREECAD_GROOVE_DEMO_FREECAD", None)
    proc = subprocess.run([SCRIPT, str(out)], capture_output=True, text=True, timeout=TIMEOUT, env=env, cwd=ROOT)
    text = "exit status %d\n--- stdout ---\n%s\n--- stderr ---\n%s" % (proc.returncode, proc.stdout, proc.stderr)
    assert proc.returncode == 0, text
    if SKIPPED in proc.stdout:
        unavailable(proc.stdout[proc.stdout.index(SKIPPED):].splitlines()[0])
    return out, proc.stdout


@pytest.fixture(scope="module")
def summary(run):
    out, _stdout = run
    with open(out / "freecad" / "summary.json") as f:
        return json.load(f)


def program(run, entry):
    return (run[0] / "freecad" / entry["file"]).read_text()


def settings_of(summary):
    tool = summary["tool"]
    return Settings(tool=GroovingTool(tool["width"], tool["corner_radius"], reference=tool["reference"]),
                    peck_retract=summary["peck_retract"])


def tools_in(text):
    """Tool numbers of the LinuxCNC tool changes (T<n> M6) in ``text``."""
    return {int(t) for t in re.findall(r"^T(\d+) M6\b", text, re.M)}


def test_every_file_is_written_and_not_empty(run, summary):
    out, stdout = run
    expected = []
    for name in EXAMPLES:
        expected += [out / (name + ".ngc"), out / (name + ".fanuc.nc")]
    fc = out / "freecad"
    expected += [fc / (demo.DOCUMENT + ".FCStd")]
    expected += [fc / filename for _post, _mode, _args, filename in demo.OUTPUTS]
    expected += [fc / "summary.txt", fc / "summary.json"]
    for path in expected:
        assert path.is_file(), "%s is missing; scripts/demo said:\n%s" % (path, stdout)
        assert path.stat().st_size > 0, "%s is empty" % path
        if path.parent == fc and path.name != "summary.json":
            assert str(path) in stdout, "scripts/demo does not say where %s went" % path.name
    # the summary lists every program, with the post and mode it came from
    listed = [(e["dialect"], e["mode"], e["args"], e["file"]) for e in summary["outputs"]]
    assert listed == [tuple(o) for o in demo.OUTPUTS]
    assert [op["label"] for op in summary["ops"]] == [label for label, _face, _values in demo.OPS]
    # the document is a FreeCAD file holding the Job and its five Groove ops
    with zipfile.ZipFile(fc / (demo.DOCUMENT + ".FCStd")) as z:
        document = z.read("Document.xml").decode()
    assert document.count("freecad_groove.ops.groove.op") >= 1
    assert len(re.findall(r'<Object type="Path::FeaturePython" name="Groove\d*"', document)) == len(demo.OPS)


def test_linuxcnc_program_runs_in_rs274(run, summary):
    require_rs274()
    entry, = [e for e in summary["outputs"] if e["dialect"] == "linuxcnc"]
    text = program(run, entry)
    tools = tools_in(text)
    assert tools == {summary["tool"]["number"]}
    try:
        canon = run_rs274(text, tool_table=tools)
    except RS274Error as e:
        raise AssertionError("rs274 refused %s: %s\n%s" % (entry["file"], e, text)) from None
    feeds = [c for c in canon if c[0] == "G1"]
    assert len(feeds) > 20
    assert all(c[0] in ("G0", "G1", "G2", "G3") for c in canon)  # no dwells in this job
    assert any(c[0] in ("G2", "G3") for c in canon)  # the finishing passes over the 0.3 mm edge radii
    # the cut-off: the blade's reference corner reaches the axis, never past it
    assert min(c[1] for c in feeds) == pytest.approx(0.0, abs=1e-9)
    assert min(c[1] for c in canon) >= -1e-9


@pytest.mark.parametrize("dialect", sorted(NATIVE))
def test_native_programs_hold_the_native_calls(run, summary, dialect):
    grooves = sum(op["grooves"] for op in summary["ops"])
    for entry in summary["outputs"]:
        if entry["dialect"] != dialect:
            continue
        text = program(run, entry)
        found = set(re.findall(r"^(CYCLE93|G7[4-7])\b", text, re.M))
        if entry["mode"] == "expanded":
            assert not found, "%s: native calls %s in an expanded program" % (entry["file"], found)
            continue
        assert found == NATIVE[dialect], (entry["file"], found)
        counted = sum(entry["native_calls"].values())
        if dialect == "sinumerik":
            assert counted == grooves  # every groove is one CYCLE93 call
        else:
            assert 0 < counted < grooves  # plain grooves share a call; the cone groove is expanded
            assert "cannot cut" in text  # ... with the reason in a comment


@pytest.mark.parametrize("dialect", sorted(NATIVE))
def test_programs_parse_back_with_the_engine(run, summary, dialect):
    settings = settings_of(summary)
    translated = {}
    for entry in summary["outputs"]:
        if entry["dialect"] == dialect:
            text = program(run, entry)
            translated[entry["file"]] = translate_program(text, dialect, settings, source_name=entry["file"])
            assert re.search(r"^G1 ", translated[entry["file"]], re.M), entry["file"]
    assert len(translated) == 2  # native and expanded
    require_rs274()
    for name, linuxcnc in translated.items():
        try:
            run_rs274(linuxcnc, tool_table=tools_in(linuxcnc))
        except RS274Error as e:
            raise AssertionError("rs274 refused %s translated for LinuxCNC: %s\n%s" % (name, e, linuxcnc)) from None


def test_every_example_program_is_in_the_demo():
    programs = sorted(os.path.splitext(name)[0] for name in os.listdir(os.path.join(ROOT, "examples"))
                      if not name.endswith(".tbl"))
    assert programs == sorted(EXAMPLES)


def test_each_turning_example_is_plotted_and_the_summary_lists_every_file(run):
    out, _stdout = run
    for name in PLOTTED:
        assert (out / (name + ".png")).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", name
    listed = (out / "summary.txt").read_text()
    for name in EXAMPLES:
        for path in (out / (name + ".ngc"), out / (name + ".fanuc.nc")):
            assert str(path) in listed, path
    for name in set(EXAMPLES) - set(PLOTTED):
        assert "examples/%s" % name in listed and "not plotted: milled" in listed


def test_the_gsk_slot_is_written_for_the_c_axis_lathes(run):
    out, _stdout = run
    linuxcnc = (out / "gsk_g7_1.ngc").read_text()
    fanuc = (out / "gsk_g7_1.fanuc.nc").read_text()
    # the example's path at the finishing pass's diameter 36 (J-4 from 40): along Z, then around C at
    # 100 mm/min on R18 ... the developed surface's feed in degrees a minute at R20 (the G7.1 radius C20.)
    assert "C90. F286.478898" in linuxcnc and "G1 X36." in linuxcnc
    assert re.search(r"^C90\.? F286\.4789", fanuc, re.M), fanuc
