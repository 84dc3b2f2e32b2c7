"""The lathe posts' feeds and speeds, inch output, --help and CAM's Post Process
route (FreeCAD 1.1 and 1.0; run by tests/freecad/run_suite.py).

* a Groove op cuts with its own FeedPerRev / SurfaceSpeed + MaxSpindleSpeed /
  SpindleSpeed, else its tool controller's HorizFeed / SpindleSpeed, else the
  documented defaults (0.05 mm/rev, 500 rpm): a new Job's tool controller
  (feed 0, speed 0) posts; each control writes them its own way;
* ``--inches``: G20 (Siemens G700), every number in inches, the same motion
  as the metric program; FreeCAD's unit schema changes nothing;
* ``--help`` reports the options and writes no program;
* CAM's Post Process command: the class FreeCAD's PostProcessorFactory takes
  from each post returns None and reports one line on any failure;
* no block repeats the position the tool is already at (Fanuc's
  ``G00 X42. Z22.`` twice).
"""

import math
import re

import FreeCAD
import Path
import pytest
import test_groove_op as tg
from test_posts import NAMES, calls, export, positions, post, read, strip_comment

from freecad_groove.engine.cycles.cycle93 import Cycle93
from freecad_groove.freecad import posts
from freecad_groove.ops.groove.op import op_error

doc, shop, groove = tg.doc, tg.shop, tg.groove
MM = 25.4


def code_lines(text, name):
    """The program's blocks without comments."""
    return [line for line in (strip_comment(raw, name) for raw in text.splitlines()) if line]


def f_words(text, name):
    return {float(f) for line in code_lines(text, name) for f in re.findall(r"\bF(-?[\d.]+)", line)}


def new_job_tool_controller(tc):
    """The tool controller as a new Job makes it: no feed, no spindle speed."""
    tc.HorizFeed = tc.VertFeed = 0
    tc.SpindleSpeed = 0


# ----------------------------------------------------------------------------- feeds and speeds

DEFAULT_BLOCKS = {  # the spindle, then the feed mode, before the grooves
    "sinumerik": ["G97 S500 M3", "G95"],
    "ab9": ["G97 S500 M03", "G95"],
    "fanuc": ["G97 S500 M03", "G99"],
    "haas": ["G97 S500 M03", "G99"],
    "linuxcnc": ["G97 S500 M3", "G95"],
}


@pytest.mark.parametrize("name", NAMES)
def test_a_new_jobs_tool_controller_posts_at_the_default_feed_and_speed(shop, name):
    new_job_tool_controller(shop[3])
    op = groove(shop, "cylinder")
    assert op_error(op) is None, op_error(op)
    assert op.FeedsAndSpeeds == (
        "feed 0.05 mm/rev (default: the op's FeedPerRev and the tool controller's HorizFeed are 0); "
        "spindle 500 rpm (default: the op's and the tool controller's SpindleSpeed are 0)")
    assert all(c.Parameters["F"] > 0 for c in op.Path.Commands if c.Name == "G1")  # no G1 F0 in the op's Path
    lines = code_lines(export(name, [op]), name)
    start = lines.index(DEFAULT_BLOCKS[name][0])
    assert lines[start:start + 2] == DEFAULT_BLOCKS[name], lines
    assert f_words(export(name, [op]), name) == {0.05}


CSS_BLOCKS = {
    "sinumerik": ["G96 S120 LIMS=2500 M3", "G95"],
    "fanuc": ["G50 S2500", "G96 S120 M03", "G99"],
    "haas": ["G50 S2500", "G96 S120 M03", "G99"],
    "linuxcnc": ["G96 D2500 S120 M3", "G95"],
}


@pytest.mark.parametrize("name", NAMES)
def test_constant_surface_speed_and_feed_per_revolution_the_controls_way(shop, name):
    op = groove(shop, "cylinder", feed_per_rev=0.08, surface_speed="120 m/min", max_spindle_speed=2500)
    assert op_error(op) is None, op_error(op)
    if name == "ab9":
        with pytest.raises(posts.PostError, match="constant surface speed cannot be written for the Allen-Bradley"):
            export(name, [op])
        return
    text = export(name, [op])
    lines = code_lines(text, name)
    start = lines.index(CSS_BLOCKS[name][0])
    assert lines[start:start + len(CSS_BLOCKS[name])] == CSS_BLOCKS[name], lines
    assert f_words(text, name) == {0.08}
    # inch: surface speed in ft/min (120 m/min = 393.7), feed in in/rev
    inch = code_lines(export(name, [op], "--inches"), name)
    assert any(re.search(r"\bG96\b.*\bS394\b", line) for line in inch), inch


@pytest.mark.parametrize("name", NAMES)
def test_the_tool_controllers_values_where_the_op_leaves_them_unset(shop, name):
    doc_, shaft, job, tc = shop
    tc.SpindleSpeed = 800
    op = groove(shop, "cylinder")  # the tool controller's 120 mm/min and 800 rpm
    text = export(name, [op])
    lines = code_lines(text, name)
    assert not any(line in ("G95", "G99") for line in lines)
    assert f_words(text, name) == {tg.FEED_MM_MIN}
    assert sum(1 for line in lines if re.match(r"G97 S800 M0?3$", line)) == 1
    op.SpindleSpeed = 650  # the op's own fixed speed replaces the tool controller's
    doc_.recompute()
    lines = code_lines(export(name, [op]), name)
    assert [line for line in lines if line.startswith("G97")][-1] in ("G97 S650 M3", "G97 S650 M03")


def test_a_path_after_a_per_revolution_groove_feeds_per_minute_again(doc):
    d, shaft, job, tc = tg.make_shop(doc)
    op = groove((d, shaft, job, tc), "cylinder", feed_per_rev=0.1)
    other = d.addObject("Path::Feature", "Turn")
    other.Path = Path.Path([Path.Command("G18"), Path.Command("G0", {"X": 22.0, "Z": 40.0}),
                            Path.Command("G1", {"X": 21.0, "F": 2.0})])  # 2 mm/s = 120 mm/min
    for name in NAMES:
        lines = code_lines(export(name, [op, other]), name)
        per_min = "G98" if name in ("fanuc", "haas") else "G94"
        back = lines.index(per_min, lines.index("G99" if per_min == "G98" else "G95"))
        assert any(line.endswith("F120.") for line in lines[back:]), (name, lines[back:])


# ----------------------------------------------------------------------------- inches


def in_mm(moves, factor):
    """Moves (kind, x, z, f) times ``factor``, without those that move less than the inch output
    resolves (0.0001 in at 4 decimals: two moves a few microns apart print the same)."""
    out = []
    for kind, x, z, f in moves:
        x, z = (None if v is None else v * factor for v in (x, z))
        f = None if f is None or kind == "G4" else f * factor
        if out and None not in (x, z, out[-1][1], out[-1][2]) and math.dist((x, z), out[-1][1:3]) < 0.003:
            continue
        out.append((kind, x, z, f))
    return out


def same_motion(metric_text, inch_text, name):
    """The inch program moves as the metric one, to the inch output's resolution."""
    metric = in_mm(positions(read(metric_text, name)), 1.0)
    inch = in_mm(positions(read(inch_text, name)), MM)
    assert len(metric) == len(inch), (len(metric), len(inch))
    for m, i in zip(metric, inch):
        assert m[0] == i[0], (m, i)
        for a, b in zip(m[1:3], i[1:3]):
            assert (a is None) == (b is None), (m, i)
            if a is not None:
                assert b == pytest.approx(a, abs=0.0026), (m, i)
        if m[0] == "G1":
            assert i[3] == pytest.approx(m[3], rel=1e-4), (m, i)


@pytest.mark.parametrize("name", NAMES)
def test_inches_writes_inch_values_and_feeds(shop, name):
    ops = [groove(shop, "cylinder", width=3, position=2, groove_count=3, pitch=5),
           groove(shop, "cone_up", flank_angle1=10, base_allowance=0.1)]
    unit = "G700" if name == "sinumerik" else "G20"
    expanded = export(name, ops, "--expand-cycles")
    inch = export(name, ops, "--expand-cycles --inches")
    assert unit in " ".join(code_lines(inch, name)).split()
    assert "G21" not in inch and "G71" not in inch
    same_motion(expanded, inch, name)
    # native calls: every length word in inches
    native, native_inch = export(name, ops), export(name, ops, "--inches")
    if name == "linuxcnc":
        same_motion(native, native_inch, name)
    for got, want in zip(calls(native_inch, name), calls(native, name)):
        if name == "sinumerik":
            a, b = Cycle93.parse(got), Cycle93.parse(want)
            for field in ("axfa", "axsa", "widg", "depg", "fal1", "fal2", "idep"):
                assert getattr(a, field) * MM == pytest.approx(getattr(b, field), abs=1e-9), field
            assert (a.angc, a.ang1, a.typ) == (b.angc, b.ang1, b.typ)
        else:
            words_in = dict(re.findall(r"([A-Z])(-?[\d.]+)", got.replace("\n", " ")))
            words_mm = dict(re.findall(r"([A-Z])(-?[\d.]+)", want.replace("\n", " ")))
            for letter in ("X", "Z", "I", "K"):
                if letter in words_mm:
                    assert float(words_in[letter]) * MM == pytest.approx(float(words_mm[letter]), abs=0.0026)
            for letter in ("P", "Q"):  # counted in 0.0001 in instead of 0.001 mm
                if letter in words_mm:
                    assert int(words_in[letter]) * 0.0001 * MM == pytest.approx(int(words_mm[letter]) * 0.001,
                                                                                 abs=0.0026)


@pytest.mark.parametrize("name", NAMES)
def test_inch_feeds_per_revolution_keep_six_decimals(shop, name):
    """0.05 mm/rev is 0.0019685 in/rev: every F word of the inch programs, native (the pecking cycles' F
    included) and expanded, is that to the output's 6 decimals (0.001969), not 4 (0.002, 1.6 % faster)."""
    op = groove(shop, "cylinder", width=3, position=2, groove_count=3, pitch=5, feed_per_rev=0.05, spindle_speed=600)
    for options in ("--inches", "--expand-cycles --inches"):
        feeds = f_words(export(name, [op], options), name)
        assert feeds, (name, options)
        for feed in feeds:
            assert feed == pytest.approx(0.05 / MM, abs=5e-7), (name, options, feed)


def test_the_unit_schema_does_not_change_the_numbers(shop):
    op = groove(shop, "cylinder", feed_per_rev=0.08, spindle_speed=700)
    before = {name: (export(name, [op]), export(name, [op], "--inches")) for name in NAMES}
    schema = FreeCAD.Units.getSchema()
    try:
        for index in range(len(FreeCAD.Units.listSchemas())):
            FreeCAD.Units.setSchema(index)
            for name in NAMES:
                assert (export(name, [op]), export(name, [op], "--inches")) == before[name], (name, index)
    finally:
        FreeCAD.Units.setSchema(schema)


# ----------------------------------------------------------------------------- --help, CAM's Post Process


@pytest.mark.parametrize("name", NAMES)
def test_help_reports_the_options_and_writes_no_program(shop, name, tmp_path, console):
    target = tmp_path / "out.nc"
    assert export(name, [], "--help", str(target)) is None
    assert not target.exists()
    assert "--inches" in post(name).TOOLTIP_ARGS
    assert post(name).TOOLTIP_ARGS.strip() in "".join(console["PrintMessage"])
    # through CAM's Post Process: no sections, so the command writes no file
    doc_, shaft, job, tc = shop
    groove(shop, "cylinder")
    job.PostProcessorArgs = "--help"
    assert processor(job, name).export() is None
    assert not console["PrintError"]


def processor(job, name):
    """What CAM's Post Process command gets for post ``name`` (FreeCAD's own factory)."""
    from Path.Post.Processor import PostProcessorFactory

    job.PostProcessor = name + "_lathe"
    found = PostProcessorFactory.get_post_processor(job, name + "_lathe")
    assert type(found).__name__ == (name + "_lathe").title()
    return found


@pytest.mark.parametrize("name", NAMES)
def test_cam_post_reports_a_failed_post_in_one_line_and_returns_nothing(shop, name, console):
    doc_, shaft, job, tc = shop
    op = groove(shop, "cylinder", infeed=0)  # the engine refuses IDEP 0
    del console["PrintError"][:]
    job.PostProcessorArgs = ""
    found = processor(job, name)
    assert found.export() is None  # CAM_Post: abort the transaction, no file, no traceback
    assert len(console["PrintError"]) == 1, console["PrintError"]
    line = console["PrintError"][0]
    assert line.startswith("%s_lathe_post: %s: Infeed: " % (name, op.Label)) and line.endswith("(no file written)\n")
    assert line.count("\n") == 1
    del console["PrintError"][:]
    job.PostProcessorArgs = "--bogus"
    assert found.export() is None
    assert console["PrintError"] == ["%s_lathe_post: unrecognized arguments: --bogus (no file written)\n" % name]
    # the tooltips FreeCAD's Job panel and preferences show
    assert found.tooltip == post(name).TOOLTIP and found.tooltipArgs == post(name).TOOLTIP_ARGS


@pytest.mark.parametrize("name", NAMES)
def test_cam_post_of_a_new_job_writes_the_program(shop, name):
    doc_, shaft, job, tc = shop
    new_job_tool_controller(tc)
    op = groove(shop, "cylinder")
    job.PostProcessorArgs = ""
    sections = processor(job, name).export()
    assert len(sections) == 1 and sections[0][1].replace("G54\n", "", 1) == export(name, [tc, op])


# ----------------------------------------------------------------------------- no repeated positions


@pytest.mark.parametrize("name", NAMES)
def test_no_block_repeats_the_position_the_tool_stands_at(shop, name):
    ops = [groove(shop, "cylinder", width=3, position=2, groove_count=3, pitch=5),
           groove(shop, "shoulder"), groove(shop, "bore"), groove(shop, "cylinder", width=5, position=12)]
    for args in ("", "--expand-cycles"):
        text = export(name, ops, args)
        x = z = None
        for event in read(text, name):
            if event[0] == "LINE" and event[1].startswith("T"):  # a tool change: the position is unknown
                x = z = None
            if event[0] not in ("G0", "G1"):
                continue
            nx = x if event[1] is None else event[1]
            nz = z if event[2] is None else event[2]
            assert (nx, nz) != (x, z), "%s %s: a block to X%s Z%s where the tool stands\n%s" % (
                name, args, nx, nz, text)
            x, z = nx, nz
