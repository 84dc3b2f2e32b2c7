"""The benchmark guard: every benchmark of the project on the working tree
and on an earlier tree (a git ref), interleaved, in one table.

    benchmarks/run [--against REF] [--only NAME,...] [--rounds N] [--quick]

The ref (default: the newest tag, else main) is written out with
``git archive REF`` into a temporary folder. A benchmark runs there with the
ref's own script when that script prints figures (--json, benchmarks/figures.py);
otherwise, or when the ref's own script fails, the working tree's script runs
against the ref's package (FREECAD_GROOVE_BENCH_PACKAGE; inside FreeCAD the
ref's tree is the mounted checkout). The table says when a figure could not
be taken. See docs/benchmarks.md.
"""

import argparse
import json
import os
import platform
import shutil
import subprocess
import sys
import tempfile
import time

import guard
import guard_suite

BENCH_DIR = os.path.dirname(os.path.abspath(__file__))
TREE = os.path.dirname(BENCH_DIR)
LABEL = "1.1"  # the FreeCAD the FreeCAD benchmarks run in
XVFB = '%s xvfb-run -a -s "-screen 0 1600x1000x24" freecad -M "$FREECAD_GROOVE_CHECKOUT" "$FREECAD_GROOVE_SHARE/%s"'
FREECADCMD = '%s freecadcmd -M "$FREECAD_GROOVE_CHECKOUT" -c "$%d"'
# Short: FreeCAD 1.1 crashes on a -c text of 256 characters or more.
CODE = ("import os, sys; B = os.environ['FREECAD_GROOVE_SHARE'] + '/bench'; sys.path.insert(0, B); "
        "exec(open(B + '/%s').read())")


def git(*args: str, cwd: str = TREE) -> str:
    return subprocess.run(["git", *args], cwd=cwd, capture_output=True, text=True, check=True).stdout.strip()


def default_ref() -> str:
    """The newest tag, or main when there is none."""
    tags = git("tag", "--sort=-creatordate").split()
    return tags[0] if tags else "main"


def check_out(ref: str, into: str) -> str:
    """``git archive REF`` unpacked in ``into``; the tree's scripts/freecad-roots
    beside it (the one that knows this machine's FreeCAD roots; it mounts the
    folder it sits in). Returns the commit."""
    commit = git("rev-parse", "--verify", ref + "^{commit}")
    archive = subprocess.run(["git", "archive", "--format=tar", commit], cwd=TREE, capture_output=True, check=True)
    subprocess.run(["tar", "-x", "-C", into], input=archive.stdout, check=True)
    os.makedirs(os.path.join(into, "scripts"), exist_ok=True)
    shutil.copy2(os.path.join(TREE, "scripts", "freecad-roots"), os.path.join(into, "scripts", "freecad-roots"))
    os.chmod(into, 0o755)
    return commit


def speaks_json(root: str, script: str) -> bool:
    """Whether ``root``'s own ``script`` prints figures (it uses benchmarks/figures.py)."""
    path = os.path.join(root, "benchmarks", script)
    if not (os.path.isfile(path) and os.path.isfile(os.path.join(root, "benchmarks", "figures.py"))):
        return False
    with open(path) as f:
        return "figures.record(" in f.read()


def last_words(text: str, lines: int = 1) -> str:
    """The last non-empty lines of ``text``, shortened: why a run failed."""
    kept = [line.strip() for line in (text or "").splitlines() if line.strip()][-lines:]
    said = " | ".join(kept)
    return said if len(said) <= 240 else said[:237] + "..."


def parse_figures(text: str) -> list:
    """The figures among a run's output lines (JSON objects with a name and a value)."""
    found = []
    for line in (text or "").splitlines():
        line = line.strip()
        if not line.startswith("{"):
            continue
        try:
            figure = json.loads(line)
        except ValueError:
            continue
        if isinstance(figure, dict) and "name" in figure and "value" in figure:
            found.append(figure)
    return found


class Runner:
    """Runs one benchmark on one side and returns (figures, failure or None)."""

    def __init__(self, ref_root: str, python: str, label: str = LABEL, tree_scripts: bool = False):
        self.roots = {guard.REF: ref_root, guard.TREE: TREE}
        self.tree_scripts = tree_scripts  # both sides measured by the tree's benchmark code
        self.python = python
        self.label = label
        self.code = {}  # (bench name, side) -> the checkout whose benchmark code measures it
        self.pylib = None  # shapely for FreeCAD's Python, made once

    def code_roots(self, bench, side: str) -> list:
        """The checkouts whose benchmark code may measure ``side``: its own if it
        prints figures, then the tree's."""
        if (bench.name, side) in self.code:
            return [self.code[bench.name, side]]
        root = self.roots[side]
        if self.tree_scripts:
            return [TREE]
        return [root, TREE] if root != TREE and speaks_json(root, bench.script) else [TREE]

    def __call__(self, bench, side: str) -> tuple:
        failure = None
        for code in self.code_roots(bench, side):
            if not os.path.isfile(os.path.join(code, "benchmarks", bench.script)):
                failure = "no %s in %s" % (bench.script, "the tree" if code == TREE else "the ref")
                continue
            run = self.freecad if bench.freecad else self.host
            figures, failure = run(bench, code, self.roots[side])
            if figures:
                self.code[bench.name, side] = code
                return figures, failure
        return [], failure or "printed no figures"

    def host(self, bench, code: str, package: str) -> tuple:
        """The benchmark ``code``/benchmarks/SCRIPT --json on the host's Python, measuring ``package``."""
        env = dict(os.environ, PYTHONDONTWRITEBYTECODE="1", **dict(bench.env))
        env["FREECAD_GROOVE_BENCH_PACKAGE"] = package
        argv = [self.python, os.path.join(code, "benchmarks", bench.script), "--json", *bench.args]
        try:
            proc = subprocess.run(argv, cwd=package, env=env, capture_output=True, text=True, timeout=bench.timeout)
        except subprocess.TimeoutExpired:
            return [], "took longer than %d s" % bench.timeout
        figures = parse_figures(proc.stdout)
        if proc.returncode != 0:
            return figures, "exit status %d: %s" % (proc.returncode, last_words(proc.stderr))
        return figures, None if figures else "printed no figures: %s" % last_words(proc.stderr)

    def freecad(self, bench, code: str, checkout: str) -> tuple:
        """The benchmark inside FreeCAD, ``checkout`` mounted as the add-on, the
        benchmark files of ``code`` copied into the shared folder."""
        share = tempfile.mkdtemp(prefix="freecad-groove-guard.")
        try:
            os.chmod(share, 0o755)
            shutil.copytree(os.path.join(code, "benchmarks"), os.path.join(share, "bench"),
                            ignore=shutil.ignore_patterns("__pycache__"))
            env = dict(os.environ, **dict(bench.env))
            if bench.shapely:
                if not self.provide_shapely(share):
                    return [], "shapely for FreeCAD's Python could not be provided (tests/freecad_shapely.py)"
                env["FREECAD_GROOVE_PYLIB"] = "pylib"
            proc, failure = self.in_freecad(bench, checkout, share, env)
            figures = []
            path = os.path.join(share, "figures.jsonl")
            if os.path.exists(path):
                with open(path) as f:
                    figures = parse_figures(f.read())
            if failure is None and proc.returncode != 0:
                failure = "FreeCAD %s exited with status %d: %s" % (self.label, proc.returncode,
                                                                   self.why(bench, share, proc))
            if not figures and failure is None:
                failure = "printed no figures: %s" % self.why(bench, share, proc)
            return figures, failure
        finally:
            shutil.rmtree(share, ignore_errors=True)

    def in_freecad(self, bench, checkout: str, share: str, env: dict) -> tuple:
        """(the finished process, or None; a failure, or None) of the FreeCAD run."""
        if bench.freecad == "gui":  # each step a FreeCAD GUI of its own
            script, codes = " && ".join(XVFB % (prefix, "bench/" + name) for prefix, name in bench.files()), []
        else:
            files = bench.files()
            script = " && ".join(FREECADCMD % (prefix, k + 1) for k, (prefix, _f) in enumerate(files))
            codes = [CODE % name for _prefix, name in files]
        argv = [os.path.join(checkout, "scripts", "freecad-roots"), "run", self.label, "--share", share, "--",
                "sh", "-c", script, "sh", *codes]
        try:
            proc = subprocess.run(argv, env=env, capture_output=True, text=True, timeout=bench.timeout)
        except subprocess.TimeoutExpired:
            return None, "took longer than %d s" % bench.timeout
        if proc.returncode == 77:
            return proc, "FreeCAD %s is not available here: %s" % (self.label, last_words(proc.stderr))
        return proc, None

    @staticmethod
    def why(bench, share: str, proc) -> str:
        """What the run said last: its own text file (a traceback there), else FreeCAD's output."""
        text = os.path.join(share, bench.script[:-3] + ".txt")
        if os.path.exists(text):
            with open(text) as f:
                said = last_words(f.read())
            if said:
                return said
        return last_words((proc.stderr or "") + "\n" + (proc.stdout or "")) if proc is not None else ""

    def provide_shapely(self, share: str) -> bool:
        """shapely for FreeCAD's Python in ``share``/pylib (tests/freecad_shapely.py, made once per guard run)."""
        if self.pylib is None:
            self.pylib = tempfile.mkdtemp(prefix="freecad-groove-guard-pylib.")
            code = "import sys; sys.path[:0] = ['tests']; import freecad_shapely; freecad_shapely.provide(sys.argv[1])"
            subprocess.run([self.python, "-c", code, self.pylib], cwd=TREE, capture_output=True, timeout=900)
        source = os.path.join(self.pylib, "pylib")
        if not os.path.isdir(source):
            return False
        shutil.copytree(source, os.path.join(share, "pylib"))
        return True


def machine() -> str:
    """This machine: CPUs, their model, the load when the run starts."""
    model = platform.processor() or "?"
    try:
        with open("/proc/cpuinfo") as f:
            model = next((line.split(":", 1)[1].strip() for line in f if line.startswith("model name")), model)
    except OSError:
        pass
    load = ", load average %.1f at the start" % os.getloadavg()[0] if hasattr(os, "getloadavg") else ""
    return "%d CPUs (nproc), %s%s" % (os.cpu_count() or 0, model, load)


def describe_tree() -> str:
    """The working tree: its branch, commit and whether it has uncommitted changes."""
    try:
        head = git("rev-parse", "--short", "HEAD")
        branch = git("rev-parse", "--abbrev-ref", "HEAD")
        dirty = bool(git("status", "--porcelain", "--untracked-files=no"))
    except (OSError, subprocess.CalledProcessError):
        return TREE
    return "%s (%s at %s%s)" % (TREE, branch, head, ", with uncommitted changes" if dirty else "")


def header(args, ref: str, commit: str, benches: list, python_version: str) -> list:
    shown = ["benchmarks/run " + " ".join(args.argv)]
    shown.append("tree: %s; ref: %s (%s, written out by git archive)" % (describe_tree(), ref, commit[:10]))
    shown.append("machine: %s; Python %s%s" % (machine(), python_version,
                                                  "; FreeCAD %s (scripts/freecad-roots)" % LABEL
                                                  if any(b.freecad for b in benches) else ""))
    shown.append("each figure: the median of %d rounds a side, interleaved (round 1 the ref then the tree, round 2 "
                 "the tree then the ref, ...);" % args.rounds)
    shown.append("tree/ref: the tree's value over the ref's; better/worse by the figure's direction, \"same\" within "
                 "%d %%; \"-\": that side printed no such figure" % round(100 * args.noise))
    return shown


def parse(argv: list) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog="benchmarks/run", description=__doc__.split("\n\n")[0])
    parser.add_argument("--against", metavar="REF", help="the git ref to compare with (default: the newest tag, "
                                                         "else main)")
    parser.add_argument("--only", metavar="NAME,...", help="only these benchmarks (names: %s)"
                        % ", ".join(b.name for b in guard_suite.BENCHES))
    parser.add_argument("--rounds", type=int, default=3, help="runs a side of each benchmark (default 3)")
    parser.add_argument("--quick", action="store_true", help="without the FreeCAD benchmarks and the long runs "
                                                            "(cli_memory_large, cli_verify_large)")
    venv = os.path.join(TREE, ".venv", "bin", "python")
    parser.add_argument("--python", default=venv if os.path.exists(venv) else sys.executable,
                        help="the Python that runs the host benchmarks (default: the tree's .venv, which "
                             "scripts/test makes, else this one; verify needs shapely)")
    parser.add_argument("--tree-scripts", action="store_true",
                        help="measure the ref with the tree's benchmark scripts too, not its own (when the way a "
                             "benchmark measures has changed since the ref)")
    parser.add_argument("--noise", type=float, default=guard.NOISE, help="a ratio this close to 1 is \"same\" "
                                                                         "(default 0.03)")
    args = parser.parse_args(argv)
    if args.rounds < 1:
        parser.error("--rounds %d: must be 1 or more" % args.rounds)
    args.argv = argv
    return args


def progress_runner(runner: Runner, ref: str):
    """``runner`` saying on standard error what runs and how it went."""
    at = {}

    def progress(bench, number, count, side):
        at["start"] = time.perf_counter()
        sys.stderr.write("%s: round %d of %d, %s ... " % (bench.name, number, count, ref if side == guard.REF
                                                          else "tree"))
        sys.stderr.flush()

    def run(bench, side):
        figures, failure = runner(bench, side)
        sys.stderr.write("%d figures in %.0f s%s\n" % (len(figures), time.perf_counter() - at["start"],
                                                      "; " + failure if failure else ""))
        return figures, failure

    return progress, run


def main(argv: list | None = None) -> int:
    args = parse(sys.argv[1:] if argv is None else argv)
    try:
        benches = guard_suite.select(args.only.split(",") if args.only else None, args.quick)
    except ValueError as e:
        sys.stderr.write("benchmarks/run: %s\n" % e)
        return 2
    ref = args.against or default_ref()
    version = subprocess.run([args.python, "-c", "import sys; print(sys.version.split()[0])"], capture_output=True,
                             text=True).stdout.strip()
    with tempfile.TemporaryDirectory(prefix="freecad-groove-ref.") as ref_root:
        try:
            commit = check_out(ref, ref_root)
        except subprocess.CalledProcessError as e:
            sys.stderr.write("benchmarks/run: --against %s: not a commit here (%s)\n" % (ref, last_words(e.stderr)))
            return 2
        said = header(args, ref, commit, benches, version)  # the tree and the load as the run starts
        runner = Runner(ref_root, args.python, tree_scripts=args.tree_scripts)
        progress, run = progress_runner(runner, ref)
        results = guard.measure(benches, args.rounds, run, progress)
        for bench, taken in results:
            if runner.code.get((bench.name, guard.REF)) == TREE:
                taken.notes.append("%s measured with the tree's %s on %s's package (%s)"
                                   % (ref, bench.script, ref, "--tree-scripts" if args.tree_scripts
                                      else "its own prints no figures"))
    print("\n".join(said))
    print()
    print(guard.table(results, ref, args.noise))
    return 0


if __name__ == "__main__":
    sys.exit(main())
