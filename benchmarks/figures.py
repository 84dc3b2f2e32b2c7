"""The figures of the benchmarks, machine-readable beside their human output.

Every benchmark prints its table for a reader as before and, for each figure
it measures, calls ``record(name, value, unit, direction, goal)``. That does
nothing unless the figures were asked for:

- ``--json`` (``add_json_option`` and ``start``): one JSON object per figure
  on standard output, a line each; the human table then goes to standard
  error, so nothing of it is lost;
- ``to_file(path)``: the FreeCAD benchmarks, which run inside FreeCAD and
  cannot print to the caller, append the same lines to a file in the shared
  folder.

``benchmarks/run`` (the benchmark guard) reads these lines and sets each
figure of the working tree beside the same figure of an earlier tree.

``use_package`` puts the checkout to measure on sys.path: this script's own,
or the one FREECAD_GROOVE_BENCH_PACKAGE names (the guard measures an earlier
tree's package with the working tree's benchmark code that way).
"""

import importlib
import json
import os
import sys

LOWER = "lower"  # a smaller value is better (time, memory)
HIGHER = "higher"  # a larger value is better (moves a second, a speed-up)
PACKAGE_ENV = "FREECAD_GROOVE_BENCH_PACKAGE"

_sink = None  # None: figures not asked for; a stream (--json) or a file path (to_file)


def add_json_option(parser) -> None:
    """Add ``--json`` to an argparse parser."""
    parser.add_argument("--json", action="store_true",
                        help="print one JSON object per figure on standard output (name, value, unit, direction, "
                             "goal); the human output goes to standard error")


def start(args) -> None:
    """After parsing: with ``--json``, figures go to standard output and what
    the script prints for a reader to standard error."""
    global _sink
    if getattr(args, "json", False):
        _sink = sys.stdout
        sys.stdout = sys.stderr


def to_file(path: str) -> None:
    """Append every figure recorded from now on to ``path`` (JSON lines)."""
    global _sink
    _sink = path


def record(name: str, value: float, unit: str, direction: str, goal: str | None = None) -> dict:
    """One figure: ``name`` says what was measured (the workload included),
    ``direction`` whether lower or higher is better, ``goal`` the target where
    one is set (e.g. "< 3", ">= 1,000,000", "flat"). Returns the figure."""
    if direction not in (LOWER, HIGHER):
        raise ValueError("direction %r: must be %r or %r" % (direction, LOWER, HIGHER))
    figure = {"name": name, "value": float(value), "unit": unit, "direction": direction}
    if goal:
        figure["goal"] = goal
    if _sink is not None:
        line = json.dumps(figure) + "\n"
        if isinstance(_sink, str):
            with open(_sink, "a") as f:
                f.write(line)
        else:
            _sink.write(line)
            _sink.flush()
    return figure


def package_root(script: str) -> str:
    """The checkout whose freecad_groove is measured: FREECAD_GROOVE_BENCH_PACKAGE,
    or the one holding ``script`` (a benchmark's __file__)."""
    return os.environ.get(PACKAGE_ENV) or os.path.dirname(os.path.dirname(os.path.abspath(script)))


def use_package(script: str) -> str:
    """Put the checkout to measure first on sys.path; returns it."""
    root = package_root(script)
    sys.path.insert(0, root)
    return root


def first_of(name: str, *modules: str):
    """``name`` from the first of ``modules`` that has it: a function that
    moved between releases (an earlier tree is measured with today's code)."""
    for module in modules:
        try:
            return getattr(importlib.import_module(module), name)
        except (ImportError, AttributeError):
            continue
    raise ImportError("%s is in none of %s" % (name, ", ".join(modules)))


def thousands(count: int) -> str:
    """1000 -> "1k", 2500 -> "2.5k", 100 -> "100": sizes in figure names."""
    if count >= 1000:
        return "%gk" % (count / 1000.0)
    return "%d" % count


# The code of a command-line child: runs freecad_groove's command line on its arguments, then writes its own peak
# resident memory as "maxrss KIB" on stderr. Linux's VmHWM (/proc/self/status): getrusage's ru_maxrss is not the
# child's own peak there, since the child is started with vfork and exec, and exec keeps the larger of the old
# and new peaks: ru_maxrss gave the benchmark's own peak (a 100k-call program and a 30k-call run's warnings held:
# 50 MiB) for a command line that peaked at 24 MiB. Elsewhere ru_maxrss (KiB on Linux, bytes on macOS).
CLI_CHILD = ("import resource, sys; sys.argv[0] = 'freecad_groove'; "
             "from freecad_groove import cli; code = cli.main(sys.argv[1:]); "
             "peak = [int(l.split()[1]) for l in open('/proc/self/status') if l.startswith('VmHWM:')] "
             "if sys.platform.startswith('linux') else []; "
             "sys.stderr.write('maxrss %d\\n' % (peak[0] if peak else "
             "resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)); sys.exit(code)")


def child_env(folder: str) -> dict:
    """The environment of a benchmark's command-line child: Python's bytecode cached in ``folder`` (outside
    the checkouts; the guard and this machine's shell set PYTHONDONTWRITEBYTECODE), so that after one warm-up
    run a child starts from bytecode as an installed package does, and compiling the package's sources (about
    0.17 s of CPU a start here) is not counted as the command's time."""
    env = dict(os.environ, PYTHONPYCACHEPREFIX=os.path.join(folder, "pycache"))
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    return env
