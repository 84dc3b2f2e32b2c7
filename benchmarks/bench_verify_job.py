"""Benchmark of verify_job() on the demo Job (freecad_groove/demo/shaft.py: the
stepped shaft with five Groove ops): prints figures, asserts nothing. Runs
inside FreeCAD (freecadcmd), headless, with shapely importable (the wrapper
benchmarks/bench_verify_job.sh provides it from the host, as the tests do):

    benchmarks/bench_verify_job.sh          # FreeCAD 1.1
    benchmarks/bench_verify_job.sh 1.0

Figures: the time of verify_job(job) (median, min, max of 5 runs; each
reads the Job, sweeps every op and sets CycleTime) and its summary. The
figures go to bench_verify_job.txt in $FREECAD_GROOVE_SHARE, and as JSON
lines (benchmarks/figures.py, which the -c text puts on sys.path) to
figures.jsonl there.
"""


def _freecad_groove_bench_verify():
    import os
    import statistics
    import sys
    import time

    share = os.environ.get("FREECAD_GROOVE_SHARE", ".")
    pylib = os.path.join(share, os.environ.get("FREECAD_GROOVE_PYLIB", "pylib"), "cp%d%d" % sys.version_info[:2])
    if os.path.isdir(pylib):
        sys.path.append(pylib)
    import figures
    import FreeCAD

    from freecad_groove import demo, verify_job

    figures.to_file(os.path.join(share, "figures.jsonl"))

    lines = []
    try:
        doc = FreeCAD.newDocument("BenchVerify")
        part = demo.make_part(doc)
        job, tc = demo.make_job(doc, part)
        ops = demo.make_ops(doc, job, part, tc)
        moves = sum(1 for op in ops for c in op.Path.Commands if c.Name in ("G0", "G1", "G4"))
        times, result = [], None
        for _ in range(5):
            start = time.perf_counter()
            result = verify_job(job)
            times.append(time.perf_counter() - start)
        lines.append("FreeCAD %s, Python %s" % (".".join(FreeCAD.Version()[:3]), sys.version.split()[0]))
        lines.append("verify_job(demo Job, %d ops, %d moves): median %.3f s, min %.3f s, max %.3f s"
                     % (len(result.ops), moves, statistics.median(times), min(times), max(times)))
        lines.append(result.summary())
        figures.record("verify the demo Job: median", statistics.median(times), "s", figures.LOWER)
    except Exception:
        import traceback

        lines.append(traceback.format_exc())
    with open(os.path.join(share, "bench_verify_job.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")
    os._exit(0)


_freecad_groove_bench_verify()
