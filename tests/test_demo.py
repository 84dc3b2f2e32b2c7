"""scripts/demo end to end: the command-line examples and the FreeCAD 1.1 demo
(freecad_groove/demo/: one document with a Groove Job on a turned shaft, a
Cylinder slot, a Plunge grind and a Mill Job with CAM's Face and Pocket Shape
ops; every system's posts).

Runs ``scripts/demo DIR`` once into a temporary directory and checks:

* every file it should write exists and is not empty (the expanded examples,
  the FreeCAD document, one program per post and mode, the turning check,
  the summaries), and summary.txt and scripts/demo's output name each;
* the document holds the four Jobs and their ops (Groove, Cylinder slot,
  Plunge grind, CAM's Face and Pocket Shape);
* the Groove Job's own turning check ran clean: every Groove op checked,
  material removed, no gouge, no leftover, no rapid through standing stock;
* each native program holds its system's cycle words as blocks (CYCLE93,
  G77/G76, G75/G74, G7.1, G83, G33 and G34), as many as the summary says,
  and the expanded ones none;
* LinuxCNC's rs274 accepts the LinuxCNC programs of the Groove ops (its
  blade reaches the axis: the cut-off), of the slot (C turns a full turn
  while Z moves 20) and of the grind (the wheel stays above the face);
* every Sinumerik, Allen-Bradley (lathe and grinder), Fanuc, Haas and GSK program is read back
  by the engine's program translator for its dialect (freecad_groove.engine.translator.translate_program), and rs274
  accepts the LinuxCNC program that makes.

The demo's own cycle-word check (demo.check_cycle_words) is tested here on
hand-written programs, without FreeCAD.

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
# each native program's cycle words, as blocks: written out here, not taken from the demo
NATIVE = {"sinumerik": {"CYCLE93"}, "ab9": {"G77", "G76"}, "fanuc": {"G75", "G74"}, "haas": {"G75", "G74"},
          "gsk": {"G7.1"}, "ab9grind": {"G83"}, "milltronics": {"G33", "G34"}}
CALL = re.compile(r"^(CYCLE93|G7[4-7]|G7\.1|G83|G3[34])(?![\d.])", re.M)
# the systems the demo shows, and the posts each goes through
SYSTEMS = {"groove": {"sinumerik_lathe", "ab9_lathe", "fanuc_lathe", "haas_lathe", "linuxcnc_lathe"},
           "slot": {"gsk_lathe", "linuxcnc_lathe"}, "grind": {"ab9_grind", "linuxcnc_grind"},
           "mill": {"milltronics_mill"}}
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
    expected += [fc / (demo.DOCUMENT + ".FCStd"), fc / (demo.DOCUMENT + "_turning_check.txt")]
    expected += [fc / program[4] for program in demo.PROGRAMS]
    expected += [fc / "summary.txt", fc / "summary.json"]
    listing = (fc / "summary.txt").read_text()
    for path in expected:
        assert path.is_file(), "%s is missing; scripts/demo said:\n%s" % (path, stdout)
        assert path.stat().st_size > 0, "%s is empty" % path
        if path.parent == fc:
            assert str(path) in stdout, "scripts/demo does not say where %s went" % path.name
            assert len(re.findall(r"^  %s " % re.escape(path.name), listing, re.M)) == 1, (path.name, listing)
    assert sorted(p.name for p in fc.iterdir()) == sorted(p.name for p in expected if p.parent == fc)
    # the summary lists every program, with the post and mode it came from
    listed = [(e["system"], e["post"], e["mode"], e["args"], e["file"]) for e in summary["outputs"]]
    assert listed == [tuple(p) for p in demo.PROGRAMS]
    assert [op["label"] for op in summary["ops"]] == [label for label, _face, _values in demo.OPS]


def test_each_system_is_posted_with_its_posts(summary):
    posts = {}
    for entry in summary["outputs"]:
        posts.setdefault(entry["system"], set()).add(entry["post"])
    assert posts == SYSTEMS
    assert [job["system"] for job in summary["jobs"]] == ["groove", "slot", "grind", "mill"]


def test_the_document_holds_the_four_jobs_and_their_ops(run):
    with zipfile.ZipFile(run[0] / "freecad" / (demo.DOCUMENT + ".FCStd")) as z:
        document = z.read("Document.xml").decode()
    jobs = re.findall(r'<Property name="Label" type="App::PropertyString" status="\d+">\s*<String value="(\w+ Job)"',
                      document)
    assert sorted(set(jobs)) == ["Grind Job", "Groove Job", "Mill Job", "Slot Job"], jobs
    proxies = re.findall(r'module="([\w.]+)" class="(\w+)"', document)
    assert ("freecad_groove.ops.groove.op", "ObjectGroove") in proxies
    assert len(re.findall(r'<Object type="Path::FeaturePython" name="Groove\d*"', document)) == len(demo.OPS)
    for name in ("CylinderSlot", "PlungeGrind", "Face", "Pocket"):
        assert re.search(r'<Object type="Path::FeaturePython" name="%s"' % name, document), name


def test_the_groove_jobs_turning_check_is_clean(run, summary):
    check = summary["turning_check"]
    assert check["clean"] is True, check
    assert [op["label"] for op in check["ops"]] == [label for label, _face, _values in demo.OPS]
    for op in check["ops"]:
        assert op["ok"] and op["error"] is None, op
        assert op["removed"] > 0 and op["gouge_depth"] == 0 and op["leftover"] == 0 and op["rapid_hits"] == 0, op
    text = (run[0] / "freecad" / check["file"]).read_text()
    assert text.startswith("Turning check: ") and text.splitlines()[0].endswith("5 op(s): ok"), text
    assert "stock: the Job's stock" in text and "PROBLEMS" not in text and "RAPID THROUGH STOCK" not in text
    assert "turning check of the Groove Job: clean" in run[1]


def test_native_programs_hold_their_cycle_words_and_expanded_ones_none(run, summary):
    grooves = sum(op["grooves"] for op in summary["ops"])
    natives = set()
    for entry in summary["outputs"]:
        text = program(run, entry)
        found = set(CALL.findall(text))
        if entry["mode"] == "expanded":
            assert not found, "%s: native calls %s in an expanded program" % (entry["file"], found)
            continue
        natives.add(entry["dialect"])
        assert found == NATIVE[entry["dialect"]], (entry["file"], found)
        assert set(entry["native_calls"]) == found, entry
        counted = sum(entry["native_calls"].values())
        if entry["dialect"] == "sinumerik":
            assert counted == grooves  # every groove is one CYCLE93 call
        elif entry["system"] == "groove":
            assert 0 < counted < grooves  # plain grooves share a call; the cone groove is expanded
            assert "cannot cut" in text  # ... with the reason in a comment
    assert natives == set(NATIVE)
    slot, = [e for e in summary["outputs"] if e["post"] == "gsk_lathe"]
    lines = program(run, slot).splitlines()
    region = summary["jobs"][1]["ops"][0]["call"]
    assert region.startswith("G7.1 C18. ") and lines[lines.index(region) + 1:lines.index(region) + 3] == [
        "G1 Z62. C360. F120.", "G7.1 C0"]
    assert lines.index("M14") < lines.index("M13 S1000") < lines.index(region) < lines.index("M25") < lines.index(
        "M15")  # C axis on, live tool on, the region, live tool off, C axis off
    mill, = [e for e in summary["outputs"] if e["post"] == "milltronics_mill"]
    assert re.search(r"^G33 G99 G41 R24\. Z20\. V20\.5 Q0\.5 F300\.$", program(run, mill), re.M)
    assert re.search(r"^G34 G99 G41 R24\. Z15\. V19\. Q2\. F300\.$", program(run, mill), re.M)


def test_the_linuxcnc_groove_program_runs_in_rs274(run, summary):
    require_rs274()
    entry, = [e for e in summary["outputs"] if e["post"] == "linuxcnc_lathe" and e["system"] == "groove"]
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


def test_the_linuxcnc_slot_program_turns_c_once_along_the_helix_in_rs274(run, summary):
    require_rs274()
    entry, = [e for e in summary["outputs"] if e["post"] == "linuxcnc_lathe" and e["system"] == "slot"]
    text = program(run, entry)
    canon = run_rs274(text, tool_table=tools_in(text), rotary=True)
    along = [c for c in canon if c[0] == "G1" and abs(c[2] - 62.0) < 1e-9]
    # 2 rough passes and the finish, each from Z42 C0 to Z62 C360 (the helix: pitch 20, one turn)
    assert len(along) == 3 and all(c[5] == pytest.approx(360.0) for c in along), canon
    # the finish 1.5 deep in the R18 neck (the program's X is a diameter, G7; rs274's canonical X a radius)
    assert min(c[1] for c in canon) == pytest.approx(18 - 1.5, abs=1e-6)
    assert re.search(r"^G1 X33\. F120\.$", text, re.M), text


def test_the_linuxcnc_grind_program_stays_above_the_face_in_rs274(run, summary):
    require_rs274()
    entry, = [e for e in summary["outputs"] if e["post"] == "linuxcnc_grind"]
    text = program(run, entry)
    canon = run_rs274(text, tool_table=tools_in(text), xyz=True)
    feeds = [c for c in canon if c[0] == "G1"]
    assert len(feeds) > 20
    # the block's top at height 20 (the grinder's Y) is the finished face: the op grinds the 0.1 above it
    # (Allowance), starting 0.05 higher (StartClearance), and never goes below it
    assert min(c[2] for c in feeds) == pytest.approx(20.0, abs=1e-9)
    assert max(c[2] for c in feeds) == pytest.approx(20.15 - 0.02, abs=1e-9)  # the first plunge pick J0.02


# The machine's C axis and live tool codes the demo gives the gsk post, which the engine's reader does not
# translate (they are the machine's own): left out of the program read back.
GSK_SWITCHES = {"M14", "M15", "M13 S1000", "M25"}


@pytest.mark.parametrize("dialect", ["sinumerik", "ab9", "fanuc", "haas", "gsk", "ab9grind"])
def test_programs_parse_back_with_the_engine(run, summary, dialect):
    settings = settings_of(summary)
    translated = {}
    for entry in summary["outputs"]:
        if entry["dialect"] == dialect:
            text = "".join(line for line in program(run, entry).splitlines(True) if line.strip() not in GSK_SWITCHES)
            target = "linuxcnc-c" if dialect == "gsk" else "linuxcnc"
            translated[entry["file"]] = translate_program(text, dialect, settings, target=target,
                                                          source_name=entry["file"])
            assert re.search(r"^G1 ", translated[entry["file"]], re.M), entry["file"]
    assert len(translated) == (2 if NATIVE[dialect] & {"CYCLE93", "G77", "G75"} else 1)  # native and expanded
    require_rs274()
    for name, linuxcnc in translated.items():
        try:
            run_rs274(linuxcnc, tool_table=tools_in(linuxcnc), rotary=dialect == "gsk")
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
    assert re.search(r"^C90\.? F286\.4788", fanuc, re.M), fanuc


# ------------------------------------------------------------- the demo's own check, without FreeCAD

def test_a_native_program_without_its_cycle_word_fails_the_demo_naming_file_post_and_word():
    calls = demo.native_calls("G00 X38.\nG1 Z62. C360. F120.\n", demo.CYCLE_WORDS["gsk"])
    assert calls == {}
    with pytest.raises(demo.CycleWordMissing, match=r"^slot\.nc: the gsk_lathe post wrote no G7\.1 block in its "
                                                    r"native program$"):
        demo.check_cycle_words("slot.nc", "gsk_lathe", "native", calls)
    with pytest.raises(demo.CycleWordMissing, match=r"^mill\.nc: .* wrote no G34 block"):
        demo.check_cycle_words("mill.nc", "milltronics_mill", "native",
                               demo.native_calls("G33 G99 R24. Z20.\nG31\n", demo.CYCLE_WORDS["milltronics"]))


def test_an_expanded_program_holding_a_native_cycle_fails_the_demo():
    calls = demo.native_calls("G0 Y26.\nG83 X145. I35. Y20. J0.02\n", ("G83",))
    assert calls == {"G83": 1}
    with pytest.raises(demo.CycleWordMissing, match=r"^g\.ngc: the linuxcnc_grind post wrote native G83 in an "
                                                    r"expanded program$"):
        demo.check_cycle_words("g.ngc", "linuxcnc_grind", "expanded", calls)


def test_blocks_that_are_not_calls_are_not_counted():
    # Fanuc's first G75 block (the peck retract), GSK's G7.1 C0 (the end of the region), longer words (G75.1, G330)
    text = "G75 R1.\nG75 X40. Z-10. P1000 Q2000 F0.05\nG7.1 C18. J-3.\nG7.1 C0\nG75.1 X0\nG330\nN10 G75 X1\n"
    assert demo.native_calls(text, ("G75", "G7.1", "G33")) == {"G75": 1, "G7.1": 1}
