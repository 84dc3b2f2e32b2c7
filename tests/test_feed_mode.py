"""The feed rate across feed-mode codes (G94/G95, Fanuc/Haas G98/G99).

The source controls keep the feed when the active feed-mode code is
programmed again and forget it on a real change. LinuxCNC sets F to 0 on
every G93/G94/G95, even the active one ("Cannot do g1 with zero feed rate"),
so a repeated code is written with the feed again. Each program goes through
LinuxCNC's own interpreter (tests/rs274.py), which must accept it with the
feed the source control would cut at.
"""

import pytest
from rs274 import canonical_matches, require_rs274, run_rs274, written_moves

from freecad_groove.engine import GroovingTool, ProgramError, Settings
from freecad_groove.engine.registry import cycle_for
from freecad_groove.engine.translator import Translator, translate_program

BLADE = Settings(tool=GroovingTool(3.0, 0.2))
SEED_CALL = "CYCLE93(35, 60, 30, 25, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0)"

# (dialect, per minute, per revolution, a whole number as the dialect writes it)
CODES = [
    ("sinumerik", "G94", "G95", "{}"),
    ("ab9", "G94", "G95", "{}."),
    ("fanuc", "G98", "G99", "{}."),
    ("haas", "G98", "G99", "{}."),
]


def repeated_codes_program(per_min, per_rev, number):
    """The feed set in each mode, the active code repeated alone and with a move, then feed moves without F."""
    n = number.format
    return "\n".join([
        "N20 %s F%s S500 M3" % (per_rev, "0.2"),
        "N30 G00 X%s Z%s" % (n(80), n(65)),
        "N35 %s" % per_rev,
        "N40 G1 X%s" % n(70),
        "N45 %s G1 X%s" % (per_rev, n(68)),
        "N50 %s F%s" % (per_min, n(100)),
        "N55 %s" % per_min,
        "N60 G1 X%s" % n(60),
        "N70 M30",
    ])


def g1_feeds(canon):
    return [c[3] for c in canon if c[0] == "G1"]


@pytest.mark.parametrize("dialect, per_min, per_rev, number", CODES, ids=[c[0] for c in CODES])
def test_a_repeated_feed_mode_code_keeps_the_feed_in_linuxcnc(dialect, per_min, per_rev, number):
    text = repeated_codes_program(per_min, per_rev, number)
    out = translate_program(text, dialect).splitlines()
    assert "N35 G95 F0.2" in out and "N55 G94 F100." in out
    assert "N40 G1 X70." in out  # the feed is in force again: the move needs no F of its own
    require_rs274()
    assert g1_feeds(run_rs274("\n".join(out) + "\n")) == [0.2, 0.2, 100.0]


@pytest.mark.parametrize("dialect, per_min, per_rev, number", CODES, ids=[c[0] for c in CODES])
def test_fanuc_output_writes_the_feed_again_too(dialect, per_min, per_rev, number):
    # A Fanuc control keeps F on a repeated G99; writing it again is harmless and keeps one rule.
    out = translate_program(repeated_codes_program(per_min, per_rev, number), dialect, target="fanuc").splitlines()
    assert "N35 G99 F0.2" in out and "N40 G01 X70." in out and "N55 G98 F100." in out


def test_a_real_change_still_forgets_the_feed():
    e = pytest.raises(ProgramError, translate_program, "G95 F0.2 S500 M3\nG0 X80 Z65\nG94\nG1 X70", "sinumerik")
    assert e.value.line == 4 and "no feed rate" in str(e.value)
    lines = translate_program("G95 F0.2 S500 M3\nG0 X80 Z65\nG94\nG1 X70 F100", "sinumerik").splitlines()
    assert "G94" in lines and "G1 X70. F100." in lines


def test_the_block_own_feed_is_written_once():
    lines = translate_program("G95 F0.2 S500 M3\nG0 X80 Z65\nG95 F0.3\nG1 X70\nM30", "sinumerik").splitlines()
    assert "G95 F0.3" in lines
    require_rs274()
    assert g1_feeds(run_rs274("\n".join(lines) + "\n")) == [0.3]


def test_block_delete_and_the_repeated_code():
    # a '/' repeated code: rewritten with the feed, so both switch positions cut at F0.2
    lines = translate_program("G95 F0.2 S500 M3\nG0 X80 Z65\n/G95\nG1 X70\nM30", "sinumerik").splitlines()
    assert "/G95 F0.2" in lines and "G1 X70." in lines
    require_rs274()
    assert g1_feeds(run_rs274("\n".join(lines) + "\n")) == [0.2]
    # a feed that depends on the switch is not written again: the next move must give F
    text = "G95 F0.2 S500 M3\nG0 X80 Z65\n/F0.3\nG95\nG1 X70"
    e = pytest.raises(ProgramError, translate_program, text, "sinumerik")
    assert e.value.line == 5 and "feed" in str(e.value)
    lines = translate_program(text + " F0.1\nM30", "sinumerik").splitlines()
    assert "G95" in lines and "G1 X70. F0.1" in lines


# A cycle in the block of the repeated code: the cycle feeds at the feed in force (CYCLE93,
# G77 without F) or at its own F, the same as the one in force (G75).
CYCLE_CASES = [
    ("sinumerik", "G95 F0.2 S400 M3\nG0 X80 Z65\n", "G95 ", SEED_CALL, "G95 F0.2"),
    ("sinumerik", "G94 F100 S400 M3\nG0 X80 Z65\n", "G94 ", SEED_CALL, "G94 F100."),
    ("ab9", "G21 G90 G95 F0.1 S500 M3\nG0 X52. Z-10.\n", "G95 ", "G77 X44. Z-30. I1.5 K10. D0.", "G95 F0.1"),
    ("fanuc", "G21\nG99 F0.05\nS500 M3\nG00 X62. Z-15.\n", "G99 ", "G75 X50. Z-35. P2000 Q2500 R0.1 F0.05",
     "G95 F0.05"),
    ("haas", "G21\nG99 F0.05\nS500 M3\nG00 X62. Z-15.\n", "G99 ", "G75 X50. Z-30. I2. K2.5 D0.1 F0.05",
     "G95 F0.05"),
]


@pytest.mark.parametrize("dialect, before, code, call, written", CYCLE_CASES,
                         ids=["%s-%s" % (c[0], c[2].strip()) for c in CYCLE_CASES])
def test_a_cycle_in_the_block_of_a_repeated_code(dialect, before, code, call, written):
    t = Translator(dialect, BLADE)
    for number, line in enumerate((before + code + call + "\nM30").split("\n"), 1):
        if line.startswith(code):
            state = t.state.machine_state()
        t.line(line, number)
    out = t.result()
    assert written in out.splitlines()
    name = "CYCLE93" if dialect == "sinumerik" else call.split()[0]
    moves = cycle_for(dialect, name).parse(call).expand(state, BLADE)
    require_rs274()
    canon = run_rs274(out)
    first = [i for i, c in enumerate(canon) if c[0] == "G0"][0]  # the approach to the start point
    problems = canonical_matches(written_moves(moves, state.metric), canon, start=first + 1, trailing=True)
    assert not problems, "\n".join(problems[:5])
    assert set(g1_feeds(canon)) == {state.feed}  # every cut at the feed the source control cuts at
