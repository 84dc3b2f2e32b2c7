"""The benchmarks the guard (benchmarks/run) runs: every benchmark of the
project, each with the options that give issue 22's figures.

``freecad``: "" runs on the host's Python; "cmd" inside freecadcmd, "gui" in
FreeCAD's GUI under Xvfb (FreeCAD 1.1 of scripts/freecad-roots; skipped by
--quick). ``steps``: the files run one after the other, each in a FreeCAD of
its own with its environment (bench_freecad.py, then bench_freecad_fresh.py in
two fresh FreeCADs; bench_first_hour.py in a session, then fresh).
``max_rounds``: long runs measured once a side whatever --rounds says (their
figures are memory or minutes-long, not noise-bound).
"""

from dataclasses import dataclass


@dataclass(frozen=True)
class Bench:
    name: str
    script: str
    about: str
    args: tuple = ()
    freecad: str = ""
    steps: tuple = ()  # ((environment assignments for sh, file), ...): runs of more than one file
    env: tuple = ()  # ((name, value), ...) for the run
    max_rounds: int | None = None
    quick: bool = True  # run by --quick
    shapely: bool = False  # FreeCAD's Python needs shapely (from the host's wheels)
    timeout: int = 1800  # seconds a run may take

    def files(self) -> tuple:
        """The files a FreeCAD run executes, with their sh environment prefixes."""
        return self.steps or (("", self.script),)


FRESH = (("", "bench_freecad.py"), ("FREECAD_GROOVE_BENCH_FRESH=ours", "bench_freecad_fresh.py"),
         ("FREECAD_GROOVE_BENCH_FRESH=freecad", "bench_freecad_fresh.py"))

FIRST_HOUR = tuple(("FREECAD_GROOVE_BENCH_PHASE=%s" % phase, "bench_first_hour.py") for phase in ("session", "fresh",
                                                                                                   "cam"))

BENCHES = (
    Bench("engine", "bench_engine.py", "G77 pattern and CYCLE93 program: expand and write"),
    Bench("cycle93_radii", "bench_cycle93_radii.py", "CYCLE93 time a call against its corner radii"),
    Bench("cycle93_air", "bench_cycle93_air.py", "CYCLE93 material tracking's cost a call"),
    Bench("cycle93_reach", "bench_cycle93_reach.py", "CYCLE93 unreachable-material warning's cost a call"),
    Bench("machining_time", "bench_machining_time.py", "CYCLE93 machining time of six reference grooves"),
    Bench("motion_blocks", "bench_motion_blocks.py", "CYCLE93 with corner radii: blocks written and time"),
    Bench("gsk_g7_1", "bench_gsk_g7_1.py", "GSK G7.1 regions: expand and write"),
    Bench("ab_g83", "bench_ab_g83.py", "Allen-Bradley G83 plunge grinding: expand and write"),
    Bench("milltronics", "bench_milltronics.py", "Milltronics G33/G34: expand and write"),
    Bench("cli_memory", "bench_cli_memory.py", "command line expand: peak memory and time a plain call",
          args=("--plain", "--calls", "1000", "10000")),
    Bench("cli_memory_large", "bench_cli_memory.py", "the same on 30k and 100k plain calls (once a side)",
          args=("--plain", "--calls", "30000", "100000"), max_rounds=1, quick=False, timeout=5400),
    Bench("cli_verify", "bench_cli_verify.py", "command line verify of 20 and 200 featured calls",
          args=("--calls", "20", "200")),
    Bench("cli_verify_large", "bench_cli_verify.py", "command line verify of 2000 featured calls (once a side)",
          args=("--calls", "2000"), max_rounds=1, quick=False, timeout=5400),
    Bench("freecad", "bench_freecad.py", "Groove op recompute; posting 500 grooves in 5 ops, reopened, fresh",
          freecad="cmd", steps=FRESH, quick=False),
    Bench("freecad_500_ops", "bench_freecad.py", "posting a Job of 500 single-groove ops, also after reopening",
          freecad="cmd",
          env=(("FREECAD_GROOVE_BENCH_OPS", "500"), ("FREECAD_GROOVE_BENCH_PARTS", "br")), quick=False),
    Bench("plunge_grind_op", "bench_plunge_grind_op.py", "Plunge grind op recompute and the grinder posts",
          freecad="cmd", quick=False),
    Bench("model_grooves", "bench_model_grooves.py", "reading a groove from the model", freecad="cmd",
          quick=False),
    Bench("verify_job", "bench_verify_job.py", "verify_job on the demo Job", freecad="cmd", shapely=True,
          quick=False),
    Bench("preview", "bench_preview.py", "the Groove panel's live preview (GUI, Xvfb)", freecad="gui",
          quick=False),
    Bench("first_hour", "bench_first_hour.py", "a new user's slow steps: the grooving tool controller, the first "
          "Job panel OK after reopening, recomputing in a fresh FreeCAD (GUI, Xvfb)", freecad="gui",
          steps=FIRST_HOUR, quick=False),
)


def select(only: list | None, quick: bool) -> list:
    """The benchmarks to run: those ``only`` names (or whose script it names),
    else all, without the long and the FreeCAD ones under ``quick`` (unless
    named). ValueError naming what is unknown."""
    if not only:
        return [b for b in BENCHES if b.quick or not quick]
    known = {b.name: b for b in BENCHES}
    chosen = []
    for name in only:
        found = [b for b in BENCHES if name in (b.name, b.script, b.script[:-3])]
        if not found:
            raise ValueError("--only %s: no such benchmark (known: %s)" % (name, ", ".join(known)))
        chosen.extend(b for b in found if b not in chosen)
    return chosen
