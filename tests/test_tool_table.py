"""The blade a cycle cuts with: no silent default, the tool table
(freecad_groove.engine.tool_table) and its rules, in the engine and on the
command line (expand --tool-table, --tool-width, emit)."""

import os
import subprocess
import sys
from dataclasses import dataclass
from typing import ClassVar

import pytest
from conftest import ROOT
from test_registry import ToyPlunge

from freecad_groove.engine import (
    DEFAULT_SETTINGS,
    FEED,
    RAPID,
    CycleError,
    GroovingTool,
    MachineState,
    Move,
    ProgramError,
    Settings,
    registry,
)
from freecad_groove.engine.cycles.cycle93 import Cycle93
from freecad_groove.engine.tool_table import ToolTable, blade_for, read_tool_table
from freecad_groove.engine.translator import translate_program

SEED = os.path.join(ROOT, "examples", "seed_cycle93.mpf")
TOOLS = os.path.join(ROOT, "examples", "tools.tbl")
SEED_CALL = "CYCLE93(35, 60, 30, 25, 12, 15, 16, 0, 0, -2, -2, 1, 1, 10, 1, 5, 0)"
NO_BLADE = "CYCLE93: the blade width is unknown: give --tool-width or a tool table"
BLADE_3 = GroovingTool(3.0, 0.2)
BLADE_25 = GroovingTool(2.5, 0.1, "plus")
TABLE_TEXT = """\
# T  width  corner-radius  reference
5    3.0    0.2            minus

7\t2.5\t0.1\tplus   # a comment after the fields
"""


def run(*args, stdin=None):
    return subprocess.run([sys.executable, "-m", "freecad_groove", *args], cwd=ROOT, input=stdin,
                          capture_output=True, timeout=120)


def one_error_line(proc):
    """The one stderr line of a refusal (exit 2, nothing on stdout)."""
    assert proc.returncode == 2 and proc.stdout == b"", proc.stderr
    lines = proc.stderr.decode().splitlines()
    assert len(lines) == 1, lines
    return lines[0]


# ---------------------------------------------------------------- reading a table


def test_read_a_table():
    table = read_tool_table(TABLE_TEXT, "tools.tbl")
    assert table == {5: BLADE_3, 7: BLADE_25}
    assert table.source == "tools.tbl"
    assert read_tool_table("") == {} and read_tool_table("# only a comment\n\n   \n") == {}
    assert read_tool_table("0 1 0 minus\n") == {0: GroovingTool(1.0, 0.0)}  # tool 0, a sharp blade
    assert read_tool_table(open(TOOLS).read()) == {5: BLADE_3}  # the examples' table: the seed's blade


@pytest.mark.parametrize(
    "line, message",
    [
        ("5 3.0 0.2 minus 1 2", "6 fields: a tool line has 4: T, width, corner radius, reference (and "
         "optionally reach)"),
        ("5 3.0 0.2", "3 fields: a tool line has 4: T, width, corner radius, reference (and optionally reach)"),
        ("5 3.0 0.2 minus 0", "reach=0: must be greater than 0 (leave the field out when it is not known)"),
        ("5 3.0 0.2 minus -12", "reach=-12: must be greater than 0 (leave the field out when it is not known)"),
        ("5 3.0 0.2 minus nan", "reach=nan: must be a number"),
        ("5 3.0 0.2 minus 1e999", "reach=1e999: must be a number"),
        ("5.0 3.0 0.2 minus", "T=5.0: must be a whole number, 0 or more"),
        ("-1 3.0 0.2 minus", "T=-1: must be a whole number, 0 or more"),
        ("T5 3.0 0.2 minus", "T=T5: must be a whole number, 0 or more"),
        ("5 0 0 minus", "width=0: must be greater than 0"),
        ("5 -3 0 minus", "width=-3: must be greater than 0"),
        ("5 three 0.2 minus", "width=three: must be a number"),
        ("5 nan 0.2 minus", "width=nan: must be a number"),
        ("5 inf 0.2 minus", "width=inf: must be a number"),
        ("5 3.0 -0.1 minus", "corner radius=-0.1: must be 0 or more and less than half the width 3"),
        ("5 3.0 1.5 minus", "corner radius=1.5: must be 0 or more and less than half the width 3"),
        ("5 3.0 r minus", "corner radius=r: must be a number"),
        ("5 3.0 0.2 left", "reference=left: must be minus or plus"),
        ("5 3.0 0.2 Minus", "reference=Minus: must be minus or plus"),
        ("7 2.5 0.1 plus", "T=7: must be unique; line 4 gives it already"),
    ],
)
def test_every_bad_line_is_refused_with_its_line_the_field_the_value_and_the_rule(line, message):
    with pytest.raises(ProgramError) as info:
        read_tool_table(TABLE_TEXT + line + "\n", "tools.tbl")
    assert info.value.line == 5 and str(info.value) == message


def test_blade_for():
    table = ToolTable({5: BLADE_3}.items(), "tools.tbl")
    assert blade_for(5, table, None) is BLADE_3
    assert blade_for(5, table, BLADE_25) is BLADE_3  # the table's own entry first
    assert blade_for(7, table, BLADE_25) is BLADE_25  # a tool the table does not list: the default
    assert blade_for(None, table, BLADE_25) is BLADE_25  # no T yet: the default
    assert blade_for(7, None, BLADE_25) is BLADE_25  # no table: the default for every tool
    for tool, tools, message in [
        (5, None, "the blade width is unknown: give --tool-width or a tool table"),
        (7, table, "the blade width is unknown: T7 is not in the tool table tools.tbl; add it there, or give "
                   "--tool-width for the tools the table does not list"),
        (None, table, "the blade width is unknown: no tool (T) is selected before it, so the tool table tools.tbl "
                      "cannot give the blade; program T first or give --tool-width for it"),
    ]:
        with pytest.raises(ProgramError) as info:
            blade_for(tool, tools, None)
        assert str(info.value) == message and info.value.line is None


def test_cycle93_itself_refuses_to_run_without_a_blade():
    call = Cycle93.parse(SEED_CALL)
    for run_it in (lambda: call.validate(Settings()), lambda: call.expand(MachineState(x=40.0, z=65.0), Settings())):
        with pytest.raises(CycleError) as info:
            run_it()
        assert info.value.message == "CYCLE93 tool width: the blade is unknown: give it as Settings.tool"


def test_settings_without_a_blade_and_with_tool():
    assert DEFAULT_SETTINGS.tool is None  # no silent default blade
    assert DEFAULT_SETTINGS.with_tool(None, 0.4, "plus").tool is None  # a radius alone is no blade
    assert DEFAULT_SETTINGS.with_tool(3.0).tool == BLADE_3  # the width alone: radius 0.2, minus
    assert DEFAULT_SETTINGS.with_tool(2.5, 0.1, "plus").tool == BLADE_25
    assert Settings(tool=BLADE_3).with_tool(reference="plus").tool == GroovingTool(3.0, 0.2, "plus")


# ---------------------------------------------------------------- the translator


def program(*blocks):
    return "\n".join(("G95 F0.2 S400 M3",) + blocks + ("M30",))


def cycle_lines(text, **kw):
    """The translated lines of each cycle (its comment and moves), in order."""
    lines = translate_program(text, "sinumerik", **kw).splitlines()
    starts = [i for i, line in enumerate(lines) if line.startswith("(CYCLE93")] + [len(lines)]
    return [[line for line in lines[a:b] if not line.startswith(("T", "G0 X80.", "M"))]
            for a, b in zip(starts, starts[1:])]


def test_cycle93_is_refused_without_a_blade_the_pecking_cycles_are_not():
    with pytest.raises(ProgramError) as info:
        translate_program(open(SEED).read(), "sinumerik")
    assert info.value.line == 4 and str(info.value) == NO_BLADE
    for name, dialect in [("ab9_g77.nc", "ab9"), ("fanuc_g75.nc", "fanuc"), ("haas_g75.nc", "haas")]:
        assert translate_program(open(os.path.join(ROOT, "examples", name)).read(), dialect)


def test_each_cycle_cuts_with_the_blade_of_its_tool():
    text = program("T5 D1", "G0 X80 Z65", SEED_CALL, "T7 D1", "G0 X80 Z65", SEED_CALL, "T5", "G0 X80 Z65",
                   SEED_CALL)
    table = read_tool_table(TABLE_TEXT, "tools.tbl")
    with_3 = cycle_lines(text, settings=Settings(tool=BLADE_3))
    with_25 = cycle_lines(text, settings=Settings(tool=BLADE_25))
    assert with_3[0] != with_25[0]
    assert cycle_lines(text, tools=table) == [with_3[0], with_25[1], with_3[2]]
    # a default blade does not override the table's entries
    assert cycle_lines(text, tools=table, settings=Settings(tool=GroovingTool(4.0, 0.3))) == \
        [with_3[0], with_25[1], with_3[2]]


def test_without_a_table_the_blade_is_every_tools():
    text = program("T5 D1", "G0 X80 Z65", SEED_CALL, "T7 D1", "G0 X80 Z65", SEED_CALL)
    assert cycle_lines(text, settings=Settings(tool=BLADE_3)) == [cycle_lines(program("G0 X80 Z65", SEED_CALL),
                                                                              settings=Settings(tool=BLADE_3))[0]] * 2


def test_a_tool_the_table_does_not_list():
    table = read_tool_table(TABLE_TEXT, "tools.tbl")
    text = program("T9 D1", "G0 X80 Z65", SEED_CALL)
    with pytest.raises(ProgramError) as info:
        translate_program(text, "sinumerik", tools=table)
    assert info.value.line == 4 and str(info.value) == (
        "CYCLE93: the blade width is unknown: T9 is not in the tool table tools.tbl; add it there, or give "
        "--tool-width for the tools the table does not list")
    # --tool-width is the blade of the tools the table does not list
    assert cycle_lines(text, tools=table, settings=Settings(tool=BLADE_25)) == \
        cycle_lines(text, settings=Settings(tool=BLADE_25))


def test_a_cycle_before_any_tool_with_a_table():
    table = read_tool_table(TABLE_TEXT, "tools.tbl")
    text = program("G0 X80 Z65", SEED_CALL)
    with pytest.raises(ProgramError) as info:
        translate_program(text, "sinumerik", tools=table)
    assert info.value.line == 3 and "no tool (T) is selected before it" in str(info.value)
    assert cycle_lines(text, tools=table, settings=Settings(tool=BLADE_3)) == \
        cycle_lines(text, settings=Settings(tool=BLADE_3))


def test_a_tool_change_on_a_block_delete_line_is_ambiguous_with_a_table():
    table = read_tool_table(TABLE_TEXT, "tools.tbl")
    text = program("T5 D1", "/T7 D1", "G0 X80 Z65", SEED_CALL)
    with pytest.raises(ProgramError) as info:
        translate_program(text, "sinumerik", tools=table)
    assert info.value.line == 5 and "block-delete" in str(info.value) and "tool" in str(info.value)
    assert translate_program(text, "sinumerik", settings=Settings(tool=BLADE_3))  # one blade for all: no matter


# A cycle whose moves depend on the blade is a declared property of its class (NEEDS_BLADE), not
# its name: test_registry's toy plunge made to step one blade width toward +Z after the plunge,
# registered for Allen-Bradley programs, whose T0512 selects tool 5 (offset 12).


@dataclass(frozen=True)
class ToyBladePlunge(ToyPlunge):
    NAME: ClassVar[str] = "G78"
    KEY: ClassVar[str] = "toy-blade-g78"
    ALIASES: ClassVar[tuple] = ()
    NEEDS_BLADE: ClassVar[bool] = True

    def expand(self, state: object, settings: Settings) -> list:
        width = settings.tool.width
        return [Move(FEED, self.X / 2.0, state.z, self.F), Move(FEED, self.X / 2.0, state.z + width),
                Move(RAPID, state.x, state.z + width)]


def test_the_registry_carries_needs_blade():
    assert {entry.name: entry.needs_blade for entry in registry.cycles()} == {
        "CYCLE93": True, "G77": False, "G76": False, "G75": False, "G74": False, "G7.1": False,
        "G83": False, "G83.1": False, "G33": False, "G34": False, "G31": False, "G32": False}


def test_a_cycle_that_needs_a_blade_by_its_declaration(monkeypatch):
    monkeypatch.setattr(registry, "_ENTRIES", list(registry.cycles()))  # copies: no other test sees the toy
    monkeypatch.setattr(registry, "_BY_KEY", dict(registry._BY_KEY))
    registry.register(ToyBladePlunge)
    text = "G21 G90 G95 F0.1\nS500 M3\nT0512\nG0 X50. Z-4.\nG78 X40.\nM30\n"
    with pytest.raises(ProgramError) as info:
        translate_program(text, "ab9")
    assert info.value.line == 5 and str(info.value).startswith("G78: the blade width is unknown")
    lines = translate_program(text, "ab9", tools=ToolTable({5: GroovingTool(2.0, 0.1)}.items())).splitlines()
    assert lines[-4:-1] == ["G1 X40.", "Z-2.", "G0 X50."]  # tool 5's 2 mm blade (T0512: tool 5, offset 12)
    with pytest.raises(ProgramError, match="T5 is not in the tool table"):
        translate_program(text, "ab9", tools=ToolTable({12: GroovingTool(2.0, 0.1)}.items()))


# ---------------------------------------------------------------- the command line


def test_expand_without_a_blade_is_refused(tmp_path):
    out = tmp_path / "seed.ngc"
    out.write_text("old\n")
    for extra in ([], ["--tool-radius", "0.2"], ["--reference-corner", "minus"]):
        proc = run("expand", "examples/seed_cycle93.mpf", "--dialect", "sinumerik", "-o", str(out), *extra)
        assert one_error_line(proc) == "examples/seed_cycle93.mpf:4: " + NO_BLADE
    assert out.read_text() == "old\n"
    for name, dialect in [("ab9_g77.nc", "ab9"), ("fanuc_g75.nc", "fanuc"), ("haas_g75.nc", "haas")]:
        assert run("expand", "examples/" + name, "--dialect", dialect).returncode == 0


def test_expand_with_the_tool_table(tmp_path):
    proc = run("expand", "examples/seed_cycle93.mpf", "--dialect", "sinumerik", "--tool-table", "examples/tools.tbl")
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout == run("expand", "examples/seed_cycle93.mpf", "--dialect", "sinumerik", "--tool-width", "3",
                              "--tool-radius", "0.2", "--reference-corner", "minus").stdout
    table = tmp_path / "t.tbl"
    table.write_text("7 2.5 0.1 plus\n")
    proc = run("expand", "examples/seed_cycle93.mpf", "--dialect", "sinumerik", "--tool-table", str(table))
    assert one_error_line(proc) == "examples/seed_cycle93.mpf:4: CYCLE93: the blade width is unknown: T5 is not in " \
        "the tool table %s; add it there, or give --tool-width for the tools the table does not list" % table
    proc = run("expand", "examples/seed_cycle93.mpf", "--dialect", "sinumerik", "--tool-table", str(table),
               "--tool-width", "3")
    assert proc.returncode == 0 and proc.stdout == run("expand", "examples/seed_cycle93.mpf", "--dialect",
                                                       "sinumerik", "--tool-width", "3").stdout


def test_expand_refuses_a_bad_table(tmp_path):
    table = tmp_path / "t.tbl"
    table.write_text("# T width radius reference\n5 3.0 0.2 minus\n7 2.5 1.5 plus\n")
    proc = run("expand", "examples/seed_cycle93.mpf", "--dialect", "sinumerik", "--tool-table", str(table))
    assert one_error_line(proc) == "%s:3: corner radius=1.5: must be 0 or more and less than half the width 2.5" % table
    missing = str(tmp_path / "none.tbl")
    proc = run("expand", "examples/ab9_g77.nc", "--dialect", "ab9", "--tool-table", missing)
    assert one_error_line(proc).startswith(missing + ":0: cannot read the tool table")


def test_the_table_from_standard_input():
    table = open(TOOLS, "rb").read()
    proc = run("expand", "examples/seed_cycle93.mpf", "--dialect", "sinumerik", "--tool-table", "-", stdin=table)
    assert proc.returncode == 0 and proc.stdout == run("expand", "examples/seed_cycle93.mpf", "--dialect",
                                                       "sinumerik", "--tool-table", TOOLS).stdout
    proc = run("expand", "-", "--dialect", "sinumerik", "--tool-table", "-", stdin=table)
    assert one_error_line(proc) == "<stdin>:0: the program and the tool table cannot both be read from standard input"
    proc = run("expand", "examples/seed_cycle93.mpf", "--dialect", "sinumerik", "--tool-table", "-", stdin=b"5 3 2 x")
    assert one_error_line(proc) == "<stdin>:1: corner radius=2: must be 0 or more and less than half the width 3"


def test_radius_or_reference_without_a_width_beside_a_table_is_refused():
    proc = run("expand", "examples/seed_cycle93.mpf", "--dialect", "sinumerik", "--tool-table", "examples/tools.tbl",
               "--reference-corner", "plus")
    assert one_error_line(proc).startswith("examples/tools.tbl:0: --tool-radius and --reference-corner shape the "
                                           "--tool-width blade, which is not given")


CYCLE93_WORDS = ["--axfa", "35", "--axsa", "60", "--widg", "30", "--depg", "25", "--idep", "10", "--typ", "5"]


def test_emit_cycle93_needs_the_blade():
    message = "emit cycle93:1: CYCLE93: the blade width is unknown: give --tool-width"
    assert one_error_line(run("emit", "cycle93", *CYCLE93_WORDS)) == message
    assert one_error_line(run("emit", "cycle93", *CYCLE93_WORDS, "--expand", "--start-x", "80", "--start-z", "65",
                              "--feed", "0.2", "--spindle", "400")) == message
    proc = run("emit", "cycle93", *CYCLE93_WORDS, "--expand", "--start-x", "80", "--start-z", "65", "--feed", "0.2",
               "--spindle", "400", "--tool-width", "3")
    assert proc.returncode == 0 and b"G1 " in proc.stdout
    proc = run("emit", "g77", "-X", "40", "-I", "2", "-D", "0")  # the pecking cycles need none
    assert proc.returncode == 0 and proc.stdout == b"G77 X40. I2. D0.\n"


# ---------------------------------------------------------------- the blade's reach (issue 20, item 5)


def test_a_table_may_give_each_blades_free_reach():
    table = read_tool_table(TABLE_TEXT + "9 3.0 0.2 minus 12   # reach 12\n", "tools.tbl")
    assert table[9] == BLADE_3 and table.reach == {9: 12.0}  # tools 5 and 7 give none: not checked


def test_a_cycle93_deeper_than_the_tables_reach_is_refused_naming_depg_and_the_reach():
    """The seed's groove is 25 deep (DEPG, a radius): a blade reaching 24 cannot cut it, one reaching 25 can
    and cuts it exactly as a table without a reach does."""
    short = read_tool_table("5 3.0 0.2 minus 24\n", "tools.tbl")
    with pytest.raises(ProgramError) as info:
        translate_program(open(SEED).read(), "sinumerik", tools=short)
    assert info.value.line == 4
    assert str(info.value) == ("CYCLE93 DEPG=25: deeper than the free reach 24 of T5's blade (tools.tbl): its "
                               "holder would hit the part; use a blade that reaches 25 or groove less deep")
    enough = read_tool_table("5 3.0 0.2 minus 25\n", "tools.tbl")
    plain = read_tool_table("5 3.0 0.2 minus\n", "tools.tbl")
    assert translate_program(open(SEED).read(), "sinumerik", tools=enough) == \
        translate_program(open(SEED).read(), "sinumerik", tools=plain)


def test_expand_refuses_a_groove_deeper_than_the_reach_in_the_tool_table(tmp_path):
    table = tmp_path / "t.tbl"
    table.write_text("# T width radius reference reach\n5 3.0 0.2 minus 12\n")
    proc = run("expand", "examples/seed_cycle93.mpf", "--dialect", "sinumerik", "--tool-table", str(table))
    assert one_error_line(proc) == ("examples/seed_cycle93.mpf:4: CYCLE93 DEPG=25: deeper than the free reach 12 of "
                                    "T5's blade (%s): its holder would hit the part; use a blade that reaches 25 "
                                    "or groove less deep" % table)
    table.write_text("5 3.0 0.2 minus 30\n")
    proc = run("expand", "examples/seed_cycle93.mpf", "--dialect", "sinumerik", "--tool-table", str(table))
    assert proc.returncode == 0, proc.stderr
