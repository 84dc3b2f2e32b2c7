"""The benchmark guard's bookkeeping (benchmarks/run): the order of the runs,
the figures they gave, the medians, the ratios and the table. Nothing here
runs or times anything; guard_run.py does, through the ``run`` function
``measure`` is given (tests/test_benchmark_guard.py gives a fake one).

Each benchmark runs ``rounds`` times on each side, interleaved: round 1 the
ref then the tree, round 2 the tree then the ref, and so on, so neither side
always runs first (on a machine warming up, or growing busier, the order
alone would favour one). A figure's value on a side is the median of what
that side's runs gave.
"""

import statistics
import textwrap
from dataclasses import dataclass, field

REF, TREE = "ref", "tree"
NOISE = 0.03  # a ratio within 3 % of 1 is "same": closer than this machine's noise


def round_order(rounds: int) -> list:
    """The sides in the order they run, round by round: [(ref, tree), (tree, ref), ...]."""
    return [(REF, TREE) if r % 2 == 0 else (TREE, REF) for r in range(rounds)]


@dataclass
class Taken:
    """What one benchmark gave over its rounds, on both sides."""

    values: dict = field(default_factory=dict)  # (side, figure name) -> [values]
    figures: dict = field(default_factory=dict)  # figure name -> its record (unit, direction, goal), the tree's first
    names: dict = field(default_factory=lambda: {REF: [], TREE: []})  # each side's names, in the order printed
    runs: dict = field(default_factory=lambda: {REF: 0, TREE: 0})
    failed: dict = field(default_factory=lambda: {REF: [], TREE: []})  # side -> [why a run failed]
    notes: list = field(default_factory=list)

    def add(self, side: str, figures: list, failure: str | None = None) -> None:
        """One run's figures (dicts: name, value, unit, direction, goal) and why it failed, if it did."""
        self.runs[side] += 1
        if failure:
            self.failed[side].append(failure)
        for figure in figures:
            name = figure["name"]
            self.values.setdefault((side, name), []).append(float(figure["value"]))
            if name not in self.names[side]:
                self.names[side].append(name)
            if side == TREE or name not in self.figures:  # the tree's unit, direction and goal win
                self.figures[name] = figure

    def median(self, side: str, name: str) -> float | None:
        values = self.values.get((side, name))
        return statistics.median(values) if values else None

    def taken(self, side: str) -> bool:
        """Whether any run of ``side`` gave a figure."""
        return any(key[0] == side for key in self.values)

    def order(self) -> list:
        """Figure names: the tree's in its order, then those only the ref gave."""
        return self.names[TREE] + [name for name in self.names[REF] if name not in self.names[TREE]]


def measure(benches: list, rounds: int, run, progress=None) -> list:
    """Run each benchmark ``rounds`` times a side (fewer where its
    ``max_rounds`` says so), interleaved by ``round_order``. ``run(bench,
    side)`` returns (figures, failure or None). Returns [(bench, Taken)]."""
    results = []
    for bench in benches:
        taken = Taken()
        count = min(rounds, getattr(bench, "max_rounds", None) or rounds)
        for number, sides in enumerate(round_order(count), 1):
            for side in sides:
                if progress:
                    progress(bench, number, count, side)
                figures, failure = run(bench, side)
                taken.add(side, figures, failure)
        results.append((bench, taken))
    return results


def ratio(tree: float | None, ref: float | None) -> float | None:
    """tree / ref, or None when either is missing or the ref is 0."""
    if tree is None or ref is None or ref == 0:
        return None
    return tree / ref


def verdict(value: float | None, direction: str, noise: float = NOISE) -> str:
    """"better", "worse" or "same" (within ``noise``) for a tree/ref ratio, by
    the figure's direction ("lower" or "higher" is better)."""
    if value is None:
        return ""
    if abs(value - 1.0) <= noise:
        return "same"
    improved = value < 1.0 if direction == "lower" else value > 1.0
    return "better" if improved else "worse"


def goal_met(value: float | None, goal: str | None) -> bool | None:
    """Whether ``value`` meets a goal "< 3", "<= 1.15", "> 2", ">= 1,000,000";
    None for a goal without a bound ("flat") or without a value."""
    if value is None or not goal:
        return None
    for op in ("<=", ">=", "<", ">"):
        if goal.startswith(op):
            try:
                bound = float(goal[len(op):].replace(",", "").strip())
            except ValueError:
                return None
            return {"<=": value <= bound, ">=": value >= bound, "<": value < bound, ">": value > bound}[op]
    return None


@dataclass
class Row:
    name: str
    unit: str
    ref: str
    tree: str
    ratio: str
    verdict: str
    goal: str


def show(value: float | None) -> str:
    """A figure's value: 4 significant digits, thousands separated."""
    if value is None:
        return "-"
    size = abs(value)
    if size >= 10000:
        return "{:,.0f}".format(value)
    if size >= 100:
        return "%.1f" % value
    if size >= 1:
        return "%.2f" % value
    return "%.3g" % value


def rows(taken: Taken, noise: float = NOISE) -> list:
    """The table's rows of one benchmark. A side that gave no figure at all
    shows "failed"; one that ran but did not give this figure, "-"."""
    out = []
    for name in taken.order():
        figure = taken.figures[name]
        ref, tree = taken.median(REF, name), taken.median(TREE, name)
        r = ratio(tree, ref)
        goal = figure.get("goal") or ""
        met = goal_met(tree, goal)
        if met is not None:
            goal += " met" if met else " NOT met"
        out.append(Row(name, figure.get("unit", ""),
                       show(ref) if ref is not None or taken.taken(REF) else "failed",
                       show(tree) if tree is not None or taken.taken(TREE) else "failed",
                       "-" if r is None else "%.2f" % r, verdict(r, figure.get("direction", "lower"), noise), goal))
    return out


def notes(taken: Taken, ref_label: str) -> list:
    """What the reader must know about a benchmark's figures: failed runs, how the ref was measured."""
    out = list(taken.notes)
    for side, label in ((REF, ref_label), (TREE, "the tree")):
        failed = taken.failed[side]
        if not failed:
            continue
        if not taken.taken(side):
            out.append("%s: could not be taken (%d run%s): %s" % (label, len(failed), "s" if len(failed) > 1 else "",
                                                                   failed[-1]))
        else:
            out.append("%s: %d of %d runs failed, the figures are the others': %s" % (
                label, len(failed), taken.runs[side], failed[-1]))
    return out


HEADINGS = ("figure", "unit", "ref", "tree", "tree/ref", "", "goal")


def table(results: list, ref_label: str, noise: float = NOISE, name_width: int = 76) -> str:
    """The table of every benchmark's figures: [(bench, Taken)] -> text."""
    all_rows = [(bench, rows(taken, noise), notes(taken, ref_label)) for bench, taken in results]
    cells = [r for _bench, these, _notes in all_rows for r in these]
    width = min(name_width, max([len(r.name) for r in cells] + [20]))
    widths = [max([len(getattr(r, key)) for r in cells] + [len(head)])
              for key, head in zip(("unit", "ref", "tree", "ratio", "verdict"), ("unit", ref_label, "tree",
                                                                                 "tree/ref", ""))]
    fmt = "  %-*s  %-*s  %*s  %*s  %*s  %-*s  %s"

    def line(name, unit, ref, tree, r, verdict_, goal):
        return (fmt % (width, name, widths[0], unit, widths[1], ref, widths[2], tree, widths[3], r,
                       widths[4], verdict_, goal)).rstrip()

    out = [line("figure", "unit", ref_label, "tree", "tree/ref", "", "goal")]
    for bench, these, said in all_rows:
        out.append("%s (%s)" % (bench.name, bench.script))
        for r in these:
            wrapped = textwrap.wrap(r.name, width) or [""]
            out.append(line(wrapped[0], r.unit, r.ref, r.tree, r.ratio, r.verdict, r.goal))
            out.extend("    " + more for more in wrapped[1:])  # the rest of a long name, under its start
        if not these and not said:
            out.append("  (no figures)")
        out.extend("  note: " + note for note in said)
    return "\n".join(out)
