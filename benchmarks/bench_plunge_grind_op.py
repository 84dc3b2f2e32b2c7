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
"""


def _freecad_groove_bench_grind():
    import importlib.util
    import os
    import statistics
    import sys
    import time

    import FreeCAD
    import Part
    import Path.Main.Job as PathJob

    from freecad_groove import make_plunge_grind

    root = os.environ.get("FREECAD_GROOVE_CHECKOUT", ".")
    share = os.environ.get("FREECAD_GROOVE_SHARE", ".")
    values = dict(depth=0.1, start_clearance=0.05, plunge_pick=0.02, cross_pick=5, spark_out_passes=1,
                  plunge_feed="60 mm/min", reciprocation_feed="6000 mm/min", wheel_width=10)
    lines = ["FreeCAD %s, Python %s" % (".".join(FreeCAD.Version()[:3]), sys.version.split()[0])]

    def figures(times):
        return "median %.2f ms, min %.2f ms, max %.2f ms" % (statistics.median(times) * 1e3, min(times) * 1e3,
                                                             max(times) * 1e3)

    def job_with(name, shape):
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

    def timed(action, count=20):
        times = []
        for k in range(count):
            start = time.perf_counter()
            action(k)
            times.append(time.perf_counter() - start)
        return times

    box = Part.makeBox(100, 40, 20)
    stepped = box.fuse([Part.makeBox(22, 40, 10, FreeCAD.Vector(100, 0, 0)),
                        Part.makeBox(10, 40, 30, FreeCAD.Vector(112, 0, 0)),
                        Part.makeBox(100, 10, 30, FreeCAD.Vector(0, 40, 0))])
    cases = (("diameter unknown, box", box, {}), ("200 mm wheel, box", box, {"wheel_diameter": 200}),
             ("10 mm wheel, stepped part", stepped, {"wheel_diameter": 10}),
             ("fine picks (J0.001), 200 mm wheel, box", box, {"wheel_diameter": 200, "plunge_pick": 0.001}))
    ops = []
    for index, (title, shape, extra) in enumerate(cases):
        doc, part, job, top = job_with("BenchGrind%d" % index, shape)
        op = make_plunge_grind(job, (part, top), **dict(values, **extra))

        def recompute(k, doc=doc, op=op):
            op.Overtravel = 6 if k % 2 == 0 else 5
            doc.recompute()

        recomputes = timed(recompute)
        plans = timed(lambda k, op=op: op.Proxy.plan(op))
        plan = op.Proxy.plan(op)
        lines.append("%s: %d Path commands, %d G83 moves, warnings %d" % (title, len(op.Path.Commands),
                                                                         len(plan.moves), len(plan.warnings)))
        lines.append("  (a) recompute: %s" % figures(recomputes))
        lines.append("  (b) plan alone: %s" % figures(plans))
        ops.append((title, doc, job))

    for name, args in (("ab9_grind", ""), ("ab9_grind", "--expand-cycles"), ("linuxcnc_grind", "")):
        spec = importlib.util.spec_from_file_location(name + "_post", os.path.join(root, "postprocessors",
                                                                                   name + "_post.py"))
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        for title, _doc, job in (ops[1], ops[3]):
            text = module.export([job], "-", args)
            times = timed(lambda k, module=module, job=job, args=args: module.export([job], "-", args), 10)
            lines.append("(c) %s %s, %s: %d lines, %s" % (name, args or "(default options)", title,
                                                         len(text.splitlines()), figures(times)))
    with open(os.path.join(share, "bench_plunge_grind_op.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")


import os  # noqa: E402

try:
    _freecad_groove_bench_grind()
except Exception:
    import traceback

    with open(os.path.join(os.environ.get("FREECAD_GROOVE_SHARE", "."), "bench_plunge_grind_op.txt"), "w") as out:
        out.write(traceback.format_exc())
os._exit(0)
