"""FreeCAD benchmark: our linuxcnc_lathe post against FreeCAD's own linuxcnc post on a Job of 500 single-groove
ops, in one FreeCAD process, the two posts alternating (prints figures, asserts nothing):

    benchmarks/bench_post_ab.sh          # FreeCAD 1.1 (scripts/freecad-roots)
    benchmarks/bench_post_ab.sh 1.0

Each post is run 3 times to warm up, then 7 times each, alternating; the line printed gives the median CPU time
(time.process_time) of each and FreeCAD's over ours. Alternating in one process makes the ratio hold on a shared
machine better than bench_freecad.py's rounds do; to compare two trees, run this script in each, alternating
the trees, a few times (docs/benchmarks.md). The Job is bench_freecad.py's (b) with 500 ops of one groove.
"""


def _freecad_groove_post_ab():
    import os
    import sys
    import time

    checkout = os.environ["FREECAD_GROOVE_CHECKOUT"]
    sys.path[:0] = [checkout, checkout + "/benchmarks", checkout + "/tests/freecad", checkout + "/tests"]
    source = open(checkout + "/benchmarks/bench_freecad.py").read()
    source = source[:source.rindex("\ntry:\n    _freecad_groove_bench()")]  # its functions, not its run
    bench = {"__name__": "bench_freecad"}
    exec(compile(source, "bench_freecad.py", "exec"), bench)
    _doc, _job, objects = bench["_post_job"](lambda *args: None, 500, 1)
    import Path.Post.scripts.linuxcnc_post as freecad_post

    from freecad_groove import demo

    ours = demo.load_post("linuxcnc")
    for _ in range(3):
        ours.export(objects, "-", "")
        freecad_post.export(objects, "-", "--no-show-editor")
    times = {"ours": [], "freecad": []}
    for _ in range(7):
        start = time.process_time()
        ours.export(objects, "-", "")
        times["ours"].append(time.process_time() - start)
        start = time.process_time()
        freecad_post.export(objects, "-", "--no-show-editor")
        times["freecad"].append(time.process_time() - start)
    ours_ms, freecad_ms = (sorted(times[key])[3] * 1e3 for key in ("ours", "freecad"))
    line = ("post 500 single-groove ops, CPU ms, median of 7: ours %.1f, FreeCAD's linuxcnc %.1f, "
            "FreeCAD's / ours %.2f\n")
    with open(os.path.join(os.environ["FREECAD_GROOVE_SHARE"], "bench_post_ab.txt"), "w") as out:
        out.write(line % (ours_ms, freecad_ms, freecad_ms / ours_ms))


_freecad_groove_post_ab()
