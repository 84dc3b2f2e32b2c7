"""What the translator (freecad_groove.engine.translator) accepts, and LinuxCNC's
rs274 with it: random text and G-code soup end in a ProgramError naming a line
or in a program, never in another error; rs274 reads every example's
translation, a cycle call's translation as the cycle's own moves, and any
generated lathe program the translator accepts."""

import os

import pytest
from conftest import EXAMPLES, ROOT
from hypothesis import given
from hypothesis import strategies as st

from freecad_groove.engine.dialects import DIALECTS
from freecad_groove.engine.errors import ProgramError
from freecad_groove.engine.moves import GroovingTool
from freecad_groove.engine.settings import Settings
from freecad_groove.engine.translator import Translator, translate_program

BLADE = Settings(tool=GroovingTool(3.0, 0.2))  # the seed's blade (examples/tools.tbl, T5), as in test_translator.py
LATHE_DIALECTS = tuple(name for name, dialect in DIALECTS.items() if not dialect.mill)  # the lathe program generator's


# ---------------------------------------------------------------- fuzzing: only ProgramError, never a bug


def _check_garbage(text, dialect):
    try:
        out = translate_program(text, dialect, BLADE)
    except ProgramError as e:
        assert not str(e).startswith("internal error"), str(e)
        assert isinstance(e.line, int) and 1 <= e.line <= text.count("\n") + text.count("\r") + 1
        return None
    assert isinstance(out, str)
    return out


@given(st.text(max_size=200), st.sampled_from(tuple(DIALECTS)))
def test_random_text(text, dialect):
    _check_garbage(text, dialect)


WORDS = st.sampled_from(
    ["G0", "G00", "G1", "G2", "G3", "G4", "G7", "G8", "G20", "G21", "G70", "G71", "G74", "G75", "G76", "G77",
     "G90", "G91", "G94", "G95", "G96", "G97", "G98", "G99", "G50", "G54", "G18", "G40", "X", "Z", "U", "W",
     "I", "K", "R", "P", "Q", "D", "F", "S", "T", "M", "N", "DIAMON", "DIAMOF", "DIAM90", "CR=", "LIMS=",
     "(c)", ";c", "/", "%", "O", "CYCLE93(35, 60, 30, 25, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0)",
     "CYCLE93(", ")", ",", "-", "."]
)
NUMBERS = st.sampled_from(["0", "1", "2.", "-3.", "0.5", "10", "44.", "50.", "-20.", "2000", "0101", "1.5", ".1"])


@st.composite
def gcode_soup(draw):
    lines = []
    for _ in range(draw(st.integers(1, 12))):
        parts = []
        for _ in range(draw(st.integers(0, 6))):
            parts.append(draw(WORDS))
            if draw(st.booleans()):
                parts.append(draw(NUMBERS))
        lines.append(draw(st.sampled_from([" ", ""])).join(parts))
    return "\n".join(lines)


@given(gcode_soup(), st.sampled_from(tuple(DIALECTS)))
def test_random_gcode_soup(text, dialect):
    _check_garbage(text, dialect)


# ---------------------------------------------------------------- rs274 reads every translation

TOOL_TABLE = "".join("T%d P%d X0 Z0 D0.4 ;\n" % (n, n) for n in range(1, 13))


def run_rs274_with_tools(text):
    """rs274 with a tool table holding tools 1..12 (the translations change tools)."""
    from rs274 import require_rs274, run_rs274

    require_rs274()
    return run_rs274(text, tool_table=TOOL_TABLE)


@pytest.mark.parametrize("name", sorted(EXAMPLES))
def test_rs274_accepts_every_example(name):
    text = open(os.path.join(ROOT, "examples", name)).read()
    out = translate_program(text, EXAMPLES[name], BLADE, source_name=name)
    canon = run_rs274_with_tools(out)
    assert len(canon) > 10
    last = canon[-1]
    assert last[0] == "G0"


CASES = [
    ("sinumerik", "G95 F0.2 S400 M3\nG0 X80 Z65\n",
     "CYCLE93(35, 60, 30, 25, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0)", "G0 X50 Z65\nM2"),
    ("ab9", "G21 G90 G95 F0.1 S500 M3\nG0 X52. Z-10.\n", "G77 X44. Z-30. I1.5 K10. F0.06 D0.", "M30"),
    ("ab9", "G21 G90 G95 F0.1 S500 M3\nG0 X52. Z-63.\n", "G77 X-1. I2. F0.04 D0.5", "M30"),
    ("ab9", "G21 G90 G95 F0.1 S500 M3\nG0 X40. Z2.\n", "G76 X60. Z-4. I2. K1. D0.", "M30"),
    ("fanuc", "G21\nG99 F0.1\nS500 M3\nG00 X62. Z-15.\n", "G75 X50. Z-35. P2000 Q2500 R0.1 F0.05", "M30"),
    ("fanuc", "G21\nG99 F0.1\nS500 M3\nG00 X40. Z2.\n", "G74 X60. Z-5. P2500 Q1500 F0.05", "M30"),
    ("haas", "G21\nG99 F0.1\nS500 M3\nG00 X62. Z-15.\n", "G75 X50. Z-30. I2. K2.5 D0.1 F0.05", "M30"),
    ("haas", "G20\nG99 F0.004\nS500 M3\nG00 X2.4 Z-0.5\n", "G75 X2. Z-1.2 I0.08 K0.1 F0.002", "M30"),
]


@pytest.mark.parametrize("dialect, before, call, after", CASES)
def test_rs274_moves_equal_the_cycle_moves(dialect, before, call, after):
    """The canonical moves rs274 reads from the translation, from the cycle on,
    are the cycle's own expand() moves (rounded to the written resolution)."""
    from rs274 import canonical_matches, written_moves

    from freecad_groove.engine.registry import cycle_for

    t = Translator(dialect, BLADE)
    lines = (before + call + "\n" + after).split("\n")
    for number, line in enumerate(lines, 1):
        if line.strip() == call:
            state = t.state.machine_state()
        t.line(line, number)
    out = t.result()
    name = "CYCLE93" if dialect == "sinumerik" else call.split()[0]
    model = cycle_for(dialect, name).parse(call)
    moves = model.expand(state, BLADE)
    canon = run_rs274_with_tools(out)
    first = [i for i, c in enumerate(canon) if c[0] == "G0"][0]  # the approach to the start point
    problems = canonical_matches(written_moves(moves, state.metric), canon, start=first + 1, trailing=True)
    assert not problems, "\n".join(problems[:5])


# ---------------------------------------------------------------- property: what we accept, LinuxCNC accepts

_NUM = st.decimals(min_value=-100, max_value=100, places=3).map(lambda d: format(d, "f"))
_POS = st.decimals(min_value="0.01", max_value=5, places=2).map(lambda d: format(d, "f"))
_MODES = {  # feed modes with and without F (repeated without F: the feed carries over)
    "sinumerik": ["DIAMOF", "DIAMON", "DIAM90", "G700", "G710", "G94 F100", "G95 F0.1", "G94", "G95", "G91", "G90"],
    "ab9": ["G07", "G08", "G20", "G21", "G94 F100.", "G95 F0.1", "G94", "G95", "G91", "G90"],
    "fanuc": ["G20", "G21", "G98 F100.", "G99 F0.1", "G98", "G99"],
    "haas": ["G20", "G21", "G98 F100.", "G99 F0.1", "G98", "G99"],
    "gsk": ["G20", "G21", "G98 F100.", "G99 F0.1", "G98", "G99"],
}


@st.composite
def lathe_program(draw, dialect):
    """A plausible program: valid-looking blocks in random order with random numbers."""
    fanuc_like = dialect in ("fanuc", "haas", "gsk")
    num = lambda: draw(_NUM)  # noqa: E731
    pos = lambda: draw(_POS)  # noqa: E731
    lines = [
        "G71" if dialect == "sinumerik" else "G21",
        "G99" if fanuc_like else "G95",
        "T1 D1" if dialect == "sinumerik" else "T0101",
        draw(st.sampled_from(["S500 M3", "G96 S150 M3", "S500 M4"])),
        "G0 X%s Z%s" % (num(), num()),
        "F" + pos(),
    ]
    for _ in range(draw(st.integers(1, 8))):
        kind = draw(st.sampled_from(["g0", "g1", "inc", "arc", "arc_ik", "cycle", "dwell", "mode", "m", "t"]))
        if kind == "g0":
            lines.append("G0 X%s Z%s" % (num(), num()))
        elif kind == "g1":
            lines.append("G1 X%s F%s" % (num(), pos()))
        elif kind == "inc":
            lines.append(("G1 U%s W%s" if fanuc_like else "G91 G1 X%s Z%s\nG90") % (num(), num()))
        elif kind == "arc":
            radius = draw(st.sampled_from(["50.", "200.", "1000."]))
            lines.append("G2 X%s Z%s %s%s" % (num(), num(), "CR=" if dialect == "sinumerik" else "R", radius))
        elif kind == "arc_ik":
            lines.append("G0 X20. Z0.\nG3 X40. Z-10. I0 K-10.")
        elif kind == "dwell":
            lines.append({"sinumerik": "G4 F1.5", "fanuc": "G04 P1500", "haas": "G04 P1.5", "ab9": "M8",
                          "gsk": "G04 P1500"}[dialect])
        elif kind == "mode":
            lines.append(draw(st.sampled_from(_MODES[dialect])))
        elif kind == "m":
            lines.append(draw(st.sampled_from(["M5", "M3", "M4", "M8", "M9", "S800", "G97 S700", "G96 S120"])))
        elif kind == "t":
            lines.append("T2 D1" if dialect == "sinumerik" else "T0202")
        elif dialect == "sinumerik":
            lines.append(
                "CYCLE93(%s, %s, %s, %s, 0, %s, %s, 0, 0, 0, 0, %s, %s, %s, 0, %d, 0)"
                % (pos(), num(), draw(st.sampled_from(["3.", "4.", "6.5"])), pos(),
                   draw(st.sampled_from(["0", "10"])), draw(st.sampled_from(["0", "5"])),
                   draw(st.sampled_from(["0", "0.2"])), draw(st.sampled_from(["0", "0.2"])), pos(),
                   draw(st.integers(1, 8)))
            )
        elif dialect == "ab9":
            lines.append("G77 X%s Z%s I%s K%s D0." % (num(), num(), pos(), pos()))
        elif dialect in ("fanuc", "gsk"):
            lines.append("G75 R%s\nG75 X%s Z%s P%d Q%d F%s"
                         % (pos(), num(), num(), draw(st.integers(100, 5000)), draw(st.integers(100, 5000)), pos()))
        else:
            lines.append("G75 X%s Z%s I%s K%s F%s" % (num(), num(), pos(), pos(), pos()))
    lines.append("M30")
    return "\n".join(lines)


@given(st.sampled_from(LATHE_DIALECTS).flatmap(lambda d: st.tuples(st.just(d), lathe_program(d))))
def test_rs274_accepts_whatever_is_translated(case):
    dialect, text = case
    try:
        out = translate_program(text, dialect, BLADE)
    except ProgramError as e:
        assert not str(e).startswith("internal error"), str(e)
        return
    run_rs274_with_tools(out)
