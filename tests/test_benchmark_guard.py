"""The benchmark guard's own logic (benchmarks/guard.py, benchmarks/figures.py)
on fake figures: the order of the runs, the medians, the ratio's direction, a
figure missing on one side, a side that failed. Nothing is timed: the
benchmarks themselves are not run here (benchmarks/run runs them; it is not
a test and CI does not run it)."""

import io
import json
import os
import sys
from dataclasses import dataclass

import pytest
from conftest import ROOT

sys.path.insert(0, os.path.join(ROOT, "benchmarks"))
import figures  # noqa: E402
import guard  # noqa: E402
import guard_run  # noqa: E402
import guard_suite  # noqa: E402


@dataclass(frozen=True)
class FakeBench:
    name: str
    script: str = "bench_fake.py"
    max_rounds: int | None = None


def fig(name, value, direction="lower", unit="ms", goal=None):
    return {"name": name, "value": value, "unit": unit, "direction": direction, **({"goal": goal} if goal else {})}


class Scripted:
    """A fake run: the values each side gives, run after run; records the order it was called in."""

    def __init__(self, values):
        self.values = {side: list(v) for side, v in values.items()}
        self.calls = []

    def __call__(self, bench, side):
        self.calls.append((bench.name, side))
        given = self.values[side].pop(0)
        if isinstance(given, str):
            return [], given
        return [fig(name, value) for name, value in given.items()], None


def test_the_sides_alternate_which_runs_first_round_by_round():
    assert guard.round_order(4) == [("ref", "tree"), ("tree", "ref"), ("ref", "tree"), ("tree", "ref")]
    run = Scripted({"ref": [{"t": 1}] * 3, "tree": [{"t": 1}] * 3})
    guard.measure([FakeBench("a")], 3, run)
    assert [side for _name, side in run.calls] == ["ref", "tree", "tree", "ref", "ref", "tree"]


def test_a_benchmark_runs_all_its_rounds_before_the_next_one_and_max_rounds_caps_them():
    run = Scripted({"ref": [{"t": 1}] * 3, "tree": [{"t": 1}] * 3})
    guard.measure([FakeBench("a", max_rounds=1), FakeBench("b")], 2, run)
    assert run.calls == [("a", "ref"), ("a", "tree"), ("b", "ref"), ("b", "tree"), ("b", "tree"), ("b", "ref")]


def test_each_side_s_value_is_the_median_of_its_rounds_not_the_mean_or_the_best():
    run = Scripted({"ref": [{"t": 10.0}, {"t": 30.0}, {"t": 11.0}], "tree": [{"t": 5.0}, {"t": 100.0}, {"t": 6.0}]})
    (_bench, taken), = guard.measure([FakeBench("a")], 3, run)
    # the runs in order: ref 10, tree 5, tree 100, ref 30, ref 11, tree 6
    assert taken.median("ref", "t") == 11.0
    assert taken.median("tree", "t") == 6.0
    (row,) = guard.rows(taken)
    assert (row.ref, row.tree, row.ratio, row.verdict) == ("11.00", "6.00", "0.55", "better")


@pytest.mark.parametrize("direction, tree, ref, said", [
    ("lower", 8.0, 10.0, "better"),  # less time
    ("lower", 12.0, 10.0, "worse"),
    ("higher", 8.0, 10.0, "worse"),  # fewer moves a second
    ("higher", 12.0, 10.0, "better"),
    ("lower", 10.2, 10.0, "same"),  # within the noise
    ("higher", 9.8, 10.0, "same"),
])
def test_better_or_worse_follows_the_figure_s_direction(direction, tree, ref, said):
    assert guard.verdict(guard.ratio(tree, ref), direction) == said


def test_the_ratio_is_tree_over_ref_and_none_without_both():
    assert guard.ratio(3.0, 12.0) == 0.25
    assert guard.ratio(None, 12.0) is None
    assert guard.ratio(3.0, None) is None
    assert guard.ratio(3.0, 0.0) is None
    assert guard.verdict(None, "lower") == ""


def test_a_figure_only_one_side_printed_shows_a_dash_on_the_other():
    run = Scripted({"ref": [{"old": 2.0, "both": 4.0}], "tree": [{"both": 2.0, "new": 1.0}]})
    (_bench, taken), = guard.measure([FakeBench("a")], 1, run)
    shown = {r.name: (r.ref, r.tree, r.ratio, r.verdict) for r in guard.rows(taken)}
    assert shown == {"both": ("4.00", "2.00", "0.50", "better"), "new": ("-", "1.00", "-", ""),
                     "old": ("2.00", "-", "-", "")}
    assert taken.order() == ["both", "new", "old"]  # the tree's figures first, in its order


def test_a_side_whose_runs_all_failed_shows_failed_and_why():
    run = Scripted({"ref": ["exit status 1: ImportError: no module x"], "tree": [{"t": 3.0}]})
    results = guard.measure([FakeBench("a")], 1, run)
    (row,) = guard.rows(results[0][1])
    assert (row.ref, row.tree, row.ratio) == ("failed", "3.00", "-")
    text = guard.table(results, "v1")
    assert "v1: could not be taken (1 run): exit status 1: ImportError: no module x" in text


def test_a_run_that_failed_among_good_ones_is_noted_and_left_out_of_the_median():
    run = Scripted({"ref": [{"t": 4.0}, "took longer than 10 s", {"t": 6.0}], "tree": [{"t": 5.0}] * 3})
    (_bench, taken), = guard.measure([FakeBench("a")], 3, run)
    assert taken.median("ref", "t") == 5.0
    assert guard.notes(taken, "v1") == ["v1: 1 of 3 runs failed, the figures are the others': took longer than 10 s"]


@pytest.mark.parametrize("value, goal, met", [
    (2.9, "< 3", True), (3.0, "< 3", False), (1.15, "<= 1.15", True), (1.2, "<= 1.15", False),
    (999999.0, ">= 1,000,000", False), (1e6, ">= 1,000,000", True), (5.0, "> 5", False),
    (23.0, "flat", None), (None, "< 3", None),
])
def test_a_goal_is_met_or_not_by_its_bound(value, goal, met):
    assert guard.goal_met(value, goal) is met


def test_the_goal_column_judges_the_tree_s_value():
    taken = guard.Taken()
    taken.add("ref", [fig("t", 2.0, goal="< 3")])
    taken.add("tree", [fig("t", 4.0, goal="< 3")])
    (row,) = guard.rows(taken)
    assert row.goal == "< 3 NOT met"


def test_figures_prints_json_lines_on_stdout_and_the_human_text_on_stderr(monkeypatch):
    out, err = io.StringIO(), io.StringIO()
    monkeypatch.setattr(sys, "stdout", out)
    monkeypatch.setattr(sys, "stderr", err)
    monkeypatch.setattr(figures, "_sink", None)
    figures.start(type("Args", (), {"json": True})())
    print("a table for a reader")
    figures.record("G77 expand + write, 10k grooves", 123456.0, "moves/s", figures.HIGHER, ">= 1,000,000")
    assert err.getvalue() == "a table for a reader\n"
    assert [json.loads(line) for line in out.getvalue().splitlines()] == [
        {"name": "G77 expand + write, 10k grooves", "value": 123456.0, "unit": "moves/s", "direction": "higher",
         "goal": ">= 1,000,000"}]
    assert guard_run.parse_figures("noise\n" + out.getvalue() + "{not json\n") == [json.loads(out.getvalue())]


def test_a_figure_without_a_direction_is_refused():
    with pytest.raises(ValueError, match="direction 'faster'"):
        figures.record("t", 1.0, "ms", "faster")


def test_only_names_benchmarks_and_quick_leaves_out_freecad_and_the_long_runs():
    quick = guard_suite.select(None, quick=True)
    assert quick and not any(b.freecad or b.max_rounds for b in quick)
    assert {b.name for b in guard_suite.select(None, quick=False)} == {b.name for b in guard_suite.BENCHES}
    assert [b.name for b in guard_suite.select(["preview", "engine"], quick=True)] == ["preview", "engine"]
    with pytest.raises(ValueError, match="--only nothing: no such benchmark"):
        guard_suite.select(["nothing"], quick=False)


def test_every_benchmark_script_the_guard_names_exists_and_records_figures():
    for bench in guard_suite.BENCHES:
        for _prefix, name in bench.files():
            with open(os.path.join(ROOT, "benchmarks", name)) as f:
                assert "figures.record(" in f.read(), name


def test_a_gui_benchmark_s_steps_each_run_in_a_freecad_gui_of_their_own_with_their_environment(monkeypatch):
    ran = []

    class Done:
        returncode = 0

    monkeypatch.setattr(guard_run.subprocess, "run", lambda argv, **kw: ran.append(argv) or Done())
    (first_hour,) = guard_suite.select(["first_hour"], quick=False)
    guard_run.Runner("/ref", "python3").in_freecad(first_hour, "/checkout", "/share", {})
    (argv,) = ran
    script = argv[argv.index("-c") + 1]
    steps = script.split(" && ")
    assert [s.split()[0] for s in steps] == ["FREECAD_GROOVE_BENCH_PHASE=%s" % p for p in ("session", "fresh", "cam")]
    assert all("xvfb-run" in s and s.endswith('"$FREECAD_GROOVE_SHARE/bench/bench_first_hour.py"') for s in steps)
    ran.clear()
    (preview,) = guard_suite.select(["preview"], quick=False)
    guard_run.Runner("/ref", "python3").in_freecad(preview, "/checkout", "/share", {})
    assert " && " not in ran[0][ran[0].index("-c") + 1] and "bench/bench_preview.py" in ran[0][ran[0].index("-c") + 1]


def test_the_material_tracking_benchmark_runs_with_its_stub_standing_in_for_material_top():
    # bench_cycle93_air.py swaps MaterialTop for a stub that cuts every stretch; when MaterialTop gained
    # stand_blade the stub did not, and the benchmark failed on every tree, unnoticed, until the guard said so.
    import subprocess

    proc = subprocess.run([sys.executable, os.path.join(ROOT, "benchmarks", "bench_cycle93_air.py"), "--calls", "1"],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr[-2000:]
    rows = [line.split() for line in proc.stdout.splitlines()[2:]]
    assert [row[0] for row in rows] == ["rect", "R1", "flanks", "ANGC", "narrow", "deep", "all"], proc.stdout


def test_tree_scripts_measure_the_ref_with_the_tree_s_benchmark_code(tmp_path):
    # A ref whose own script prints figures is measured with it, unless the way the benchmark measures changed
    # since (the command-line children's warm-up): --tree-scripts measures both sides with the tree's.
    ref = tmp_path / "ref"
    (ref / "benchmarks").mkdir(parents=True)
    (ref / "benchmarks" / "figures.py").write_text("")
    (ref / "benchmarks" / "bench_fake.py").write_text("figures.record('x', 1, 'ms', 'lower')\n")
    bench = FakeBench("fake")
    assert guard_run.Runner(str(ref), "python3").code_roots(bench, guard.REF) == [str(ref), guard_run.TREE]
    assert guard_run.Runner(str(ref), "python3", tree_scripts=True).code_roots(bench, guard.REF) == [guard_run.TREE]
    assert guard_run.Runner(str(ref), "python3", tree_scripts=True).code_roots(bench, guard.TREE) == [guard_run.TREE]
    assert guard_run.parse(["--tree-scripts"]).tree_scripts and not guard_run.parse([]).tree_scripts


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="VmHWM is Linux's")
def test_a_command_line_child_reports_its_own_peak_memory_not_its_parents(tmp_path):
    # A child started with vfork and exec inherits the parent's peak in ru_maxrss: the 100k-call figure was the
    # benchmark's own 50 MiB (the program text and the last run's warnings it held), the command line's 24 MiB.
    import subprocess

    held = bytearray(160 * 2**20)
    held[::4096] = b"x" * len(held[::4096])  # resident, then freed: the parent's peak stays
    del held
    program = tmp_path / "part.nc"
    program.write_text("G21 G98\nG0 X40. Z2.\nM30\n")
    proc = subprocess.run([sys.executable, "-c", figures.CLI_CHILD, "expand", str(program), "--dialect", "fanuc"],
                          cwd=ROOT, capture_output=True, text=True, check=False)
    assert proc.returncode == 0, proc.stderr
    peak_mib = int(proc.stderr.split("maxrss")[-1]) / 1024
    assert 5 < peak_mib < 100, peak_mib
