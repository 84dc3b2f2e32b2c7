"""The live tool and C axis mode switches around a Cylinder slot in the posts (posts/live_tool.py), on the
posted text; inside FreeCAD 1.1 and 1.0. The op: the helix of test_cylinder_slot.py (tool controller
SpindleSpeed 1000). LinuxCNC programs with the switches go through rs274 in tests/test_slot_programs.py."""

import re

import pytest
from test_cylinder_slot import _helix_op, _post

from freecad_groove.freecad.posts import PostError
from freecad_groove.ops.slot.op import op_error

SWITCHES = "--c-axis-on M14 --c-axis-off M15 --live-tool-cw M13 --live-tool-ccw M23 --live-tool-stop M25"


def _lines(text):
    return [line.strip() for line in text.splitlines() if line.strip()]


def _index(lines, start):
    return next(i for i, line in enumerate(lines) if line.startswith(start))


def test_given_codes_are_written_around_the_slot_and_the_main_spindle_stays_off(closing):
    job, op = _helix_op(closing)
    lines = _lines(_post("gsk_lathe", [job], "--native-cycles " + SWITCHES))
    region, cancel = _index(lines, "G7.1 C20. J"), _index(lines, "G7.1 C0")
    on = [line for line in lines[:region] if line in ("M14", "M13 S1000")]
    off = [line for line in lines[cancel:] if line in ("M25", "M15")]
    assert on == ["M14", "M13 S1000"] and off == ["M25", "M15"], lines
    assert lines.index("M14") < lines.index("M13 S1000") < _index(lines, "G0")  # before the first move
    assert not [line for line in lines if line.startswith(("M03", "M04", "M3 ", "M4 ")) or " M03" in line], lines
    assert not [line for line in lines if "given, the post cannot write it" in line]


def test_without_the_options_the_slot_is_refused_naming_the_op_and_the_option(closing):
    job, op = _helix_op(closing)
    with pytest.raises(PostError, match=r"^%s: C axis mode on: no --c-axis-on given: the post does not know the "
                       r"machine's code .* give --c-axis-on WORDS, or --switches-by-hand" % op.Label):
        _post("gsk_lathe", [job], "--native-cycles")
    with pytest.raises(PostError, match=r"^%s: live tool on at S1000: no --live-tool-cw given" % op.Label):
        _post("linuxcnc_lathe", [job], "--c-axis-on M14")


def test_switches_by_hand_writes_a_comment_in_place_of_each_missing_switch(closing):
    job, op = _helix_op(closing)
    text = _post("gsk_lathe", [job], "--native-cycles --switches-by-hand")
    lines = _lines(text)
    region, cancel = _index(lines, "G7.1 C20. J"), _index(lines, "G7.1 C0")
    before = [line for line in lines[:region] if "cannot write it" in line]
    after = [line for line in lines[cancel:] if "cannot write it" in line]
    assert before == ["(C AXIS MODE ON: NO --C-AXIS-ON GIVEN, THE POST CANNOT WRITE IT)",
                      "(LIVE TOOL ON AT S1000: NO --LIVE-TOOL-CW GIVEN, THE POST CANNOT WRITE IT)"] or before == [
        "(C axis mode on: no --c-axis-on given, the post cannot write it)",
        "(live tool on at S1000: no --live-tool-cw given, the post cannot write it)"], before
    assert len(after) == 2 and "--live-tool-stop" in after[0].lower() and "--c-axis-off" in after[1].lower()
    assert "G97 S1000 M03" not in text  # the main spindle is not started for a slot
    bare = _post("gsk_lathe", [job], "--native-cycles --no-comments --switches-by-hand")
    # the placeholders stay: they mark where the machinist writes the codes
    assert [line for line in _lines(bare) if "cannot write it" in line] == before + after and "M03" not in bare


def test_a_reversed_tool_uses_the_ccw_code(closing):
    job, op = _helix_op(closing)
    op.ToolController.SpindleDir = "Reverse"
    lines = _lines(_post("linuxcnc_lathe", [job], SWITCHES))
    assert "M23 S1000" in lines and "M13 S1000" not in lines


@pytest.mark.parametrize("args, message", [
    ("--c-axis-on 'M1 4x'", "--c-axis-on 'M1 4x': must be program words"),
    ("--live-tool-cw ''", "--live-tool-cw '': must be program words"),
])
def test_words_that_are_not_program_words_are_refused(closing, args, message):
    job, op = _helix_op(closing)
    with pytest.raises(PostError, match="^" + message):
        _post("gsk_lathe", [job], args)


def test_a_live_tool_without_speed_turns_at_the_slots_default(closing):
    job, op = _helix_op(closing)
    op.ToolController.SpindleSpeed = 0
    job.Document.recompute()
    assert "M13 S1000" in _lines(_post("gsk_lathe", [job], SWITCHES))  # ops/slot/cutting.DEFAULT_LIVE_RPM
    op.ToolController.SpindleSpeed = 2400
    job.Document.recompute()
    assert "M13 S2400" in _lines(_post("gsk_lathe", [job], SWITCHES))


def test_posts_without_c_have_no_switch_options(closing):
    job, op = _helix_op(closing)
    with pytest.raises(PostError, match="unrecognized arguments: --c-axis-on M14"):
        _post("fanuc_lathe", [job], "--c-axis-on M14")


def _cam_post(job, name, args):
    """The program CAM's Post Process command writes: its post list (fixture, tool controller, op: the
    PostProcessorFactory's class, as CAM_Post runs it), one section."""
    from Path.Post.Processor import PostProcessorFactory

    job.PostProcessorArgs = args
    sections = PostProcessorFactory.get_post_processor(job, name).export()
    assert sections is not None and len(sections) == 1, sections
    return sections[0][1]


@pytest.mark.parametrize("name", ["gsk_lathe", "linuxcnc_lathe"])
def test_the_main_spindle_is_never_started_for_a_slot_posted_as_cams_post_command_lists_it(closing, name):
    # CAM's list puts the tool controller before the op: its main spindle start (S1000 M03) and, at once, the
    # stop the slot needs (M05) were written before the C axis switch
    job, op = _helix_op(closing)
    lines = _lines(_cam_post(job, name, SWITCHES))
    tool = next(i for i, line in enumerate(lines) if line.startswith("T"))
    assert lines[tool].startswith(("T0101", "T1 M6")), lines
    spindle = [line for line in lines if re.search(r"\b(M0?[345]|S\d+ M|G97|G96)\b", line)]
    assert spindle == [], lines
    assert lines[tool + 1:].index("M14") < lines[tool + 1:].index("M13 S1000")


def test_after_a_groove_the_main_spindle_is_stopped_before_the_slot(closing):
    from freecad_groove import make_groove

    job, op = _helix_op(closing)
    shaft = job.Model.Group[0]
    groove = make_groove(job, (shaft, "Face1"), width=4, depth=1, position=3, tool_width=3,
                         tool_controller=op.ToolController)
    assert op_error(groove) is None, op_error(groove)
    job.Operations.Group = [groove, op]
    job.Document.recompute()
    lines = _lines(_cam_post(job, "linuxcnc_lathe", SWITCHES))
    start, stop, c_on = _index(lines, "G97 S"), lines.index("M5"), lines.index("M14")
    assert lines[start].endswith("M3") and start < stop < c_on, lines
