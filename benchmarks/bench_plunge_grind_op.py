"""FreeCAD benchmark of the Plunge grind op and the grinder posts: prints
figures, asserts nothing. Runs inside FreeCAD (freecadcmd), headless:

    benchmarks/bench_plunge_grind_op.sh          # FreeCAD 1.1
    benchmarks/bench_plunge_grind_op.sh 1.0      # or another label of `scripts/freecad-roots list`

The figures go to bench_plunge_grind_op.txt in $FREECAD_GROOVE_SHARE, which
the wrapper prints.

The part: the 100 x 40 x 20 box of tests/freecad/test_plunge_grind.py, its
top face ground with a 10 mm wide wheel (0.1 mm allowance, 0.02 mm picks,
K 5: the test's values), and the stepped part of the same tests (a wall
12 mm beyond the face's end, one along its side).

(a) doc.recompute() of the op, Overtravel toggled 5 <-> 6 mm, 20 times:
    median, min, max; the Path's commands and the G83's moves. Three cases:
    the wheel's diameter unknown (no body check: a warning), a 200 mm wheel
    on the box (the body checked: five solids against the part), a 10 mm
    wheel on the stepped part (the body checked, walls near).
(b) op.Proxy.plan(op) alone (the face, the call, the expansion, the checks),
    20 times, for the same cases.
(c) Posting the Job (ab9_grind native and --expand-cycles, linuxcnc_grind),
    median of 10: time and lines.
(d) A fine grind: PlungePick 0.001 over 0.1 mm (100 plunges), to show how
    the op scales with its moves.

The medians also go, as CPU times (time.process_time: the machine may be
shared), to figures.jsonl in $FREECAD_GROOVE_SHARE as JSON lines
(benchmarks/figures.py, which the -c text puts on sys.path).
"""


def _freecad_groove_bench_grind():
    import os
    import sys

    import figures
    import FreeCAD
    import Part

    share = os.environ.get("FREECAD_GROOVE_SHARE", ".")
    figures.to_file(os.path.join(share, "figures.jsonl"))
    lines = ["FreeCAD %s, Python %s" % (".".join(FreeCAD.Version()[:3]), sys.version.split()[0])]
    box = Part.makeBox(100, 40, 20)
    stepped = box.fuse([Part.makeBox(22, 40, 10, FreeCAD.Vector(100, 0, 0)),
                        Part.makeBox(10, 40, 30, FreeCAD.Vector(112, 0, 0)),
                        Part.makeBox(100, 10, 30, FreeCAD.Vector(0, 40, 0))])
    cases = (("box, diameter unknown", box, {}), ("box, 200 mm wheel", box, {"wheel_diameter": 200}),
             ("stepped part, 10 mm wheel", stepped, {"wheel_diameter": 10}),
             ("box, 200 mm wheel, fine picks (J0.001)", box, {"wheel_diameter": 200, "plunge_pick": 0.001}))
    ops = [_grind_case(index, case, lines, figures) for index, case in enumerate(cases)]
    _grind_posts(ops, lines, figures)
    with open(os.path.join(share, "bench_plunge_grind_op.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")


def _grind_timed(action, count=20):
    """([wall seconds], [CPU seconds]) of ``count`` calls action(k)."""
    import time

    times, cpus = [], []
    for k in range(count):
        start, cpu = time.perf_counter(), time.process_time()
        action(k)
        cpus.append(time.process_time() - cpu)
        times.append(time.perf_counter() - start)
    return times, cpus


def _grind_figures(times):
    import statistics

    return "median %.2f ms, min %.2f ms, max %.2f ms" % (statistics.median(times) * 1e3, min(times) * 1e3,
                                                         max(times) * 1e3)


def _grind_job(name, shape):
    """(doc, part, job, the top face's name) for ``shape``."""
    import FreeCAD
    import Path.Main.Job as PathJob

    doc = FreeCAD.newDocument(name)
    part = doc.addObject("Part::Feature", "Part")
    part.Shape = shape
    doc.recompute()
    job = PathJob.Create("Job", [part])
    job.Tools.Group[0].SpindleSpeed = 3000
    doc.recompute()
    top = next("Face%d" % (i + 1) for i, f in enumerate(part.Shape.Faces)
               if abs(f.BoundBox.ZMin - 20) < 1e-9 and abs(f.BoundBox.ZMax - 20) < 1e-9)
    return doc, part, job, top


def _grind_case(index, case, lines, figures):
    """(a) and (b) of one case; returns (title, doc, job)."""
    import statistics

    from freecad_groove import make_plunge_grind

    title, shape, extra = case
    values = dict(depth=0.1, start_clearance=0.05, plunge_pick=0.02, cross_pick=5, spark_out_passes=1,
                  plunge_feed="60 mm/min", reciprocation_feed="6000 mm/min", wheel_width=10)
    doc, part, job, top = _grind_job("BenchGrind%d" % index, shape)
    op = make_plunge_grind(job, (part, top), **dict(values, **extra))

    def recompute(k):
        op.Overtravel = 6 if k % 2 == 0 else 5
        doc.recompute()

    recomputes, recompute_cpus = _grind_timed(recompute)
    plans, plan_cpus = _grind_timed(lambda k: op.Proxy.plan(op))
    plan = op.Proxy.plan(op)
    lines.append("%s: %d Path commands, %d G83 moves, warnings %d" % (title, len(op.Path.Commands),
                                                                     len(plan.moves), len(plan.warnings)))
    lines.append("  (a) recompute: %s" % _grind_figures(recomputes))
    lines.append("  (b) plan alone: %s" % _grind_figures(plans))
    figures.record("Plunge grind op, %s: recompute, median CPU" % title, 1e3 * statistics.median(recompute_cpus),
                   "ms", figures.LOWER)
    figures.record("Plunge grind op, %s: plan alone, median CPU" % title, 1e3 * statistics.median(plan_cpus), "ms",
                   figures.LOWER)
    return title, doc, job


def _grind_posts(ops, lines, figures):
    """(c) the grinder posts on the 200 mm wheel's Jobs."""
    import importlib.util
    import os
    import statistics

    root = os.environ.get("FREECAD_GROOVE_CHECKOUT", ".")
    for name, args in (("ab9_grind", ""), ("ab9_grind", "--expand-cycles"), ("linuxcnc_grind", "")):
        spec = importlib.util.spec_from_file_location(name + "_post", os.path.join(root, "postprocessors",
                                                                                   name + "_post.py"))
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        for title, _doc, job in (ops[1], ops[3]):
            text = module.export([job], "-", args)
            times, cpus = _grind_timed(lambda k, module=module, job=job, args=args: module.export([job], "-", args), 10)
            lines.append("(c) %s %s, %s: %d lines, %s" % (name, args or "(default options)", title,
                                                         len(text.splitlines()), _grind_figures(times)))
            figures.record("grinder post %s%s, %s: median CPU" % (name, " " + args if args else "", title),
                           1e3 * statistics.median(cpus), "ms", figures.LOWER)


import os  # noqa: E402

try:
    _freecad_groove_bench_grind()
except Exception:
    import traceback

    with open(os.path.join(os.environ.get("FREECAD_GROOVE_SHARE", "."), "bench_plunge_grind_op.txt"), "w") as out:
        out.write(traceback.format_exc())
os._exit(0)
