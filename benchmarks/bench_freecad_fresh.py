"""Part (c) of the FreeCAD benchmark (bench_freecad.sh runs it after
bench_freecad.py): the first post in a FreeCAD that has just started, as a
user opens a saved document and posts it. Each run is a fresh freecadcmd:
FREECAD_GROOVE_BENCH_FRESH=ours posts with our linuxcnc_lathe post,
=freecad with FreeCAD's own linuxcnc post, the document bench_post.FCStd
that bench_freecad.py saved in $FREECAD_GROOVE_SHARE (500 grooves). The
figures are appended to bench_freecad.txt there: the one-time imports (the
add-on's op module, the post's modules) apart from the posts themselves, CPU
time of this thread (time.thread_time) and wall time; the CPU times also
as JSON lines (benchmarks/figures.py) in figures.jsonl there.
"""


def _freecad_groove_bench_fresh():
    import os
    import sys
    import time

    import FreeCAD

    checkout = os.environ["FREECAD_GROOVE_CHECKOUT"]
    if checkout not in sys.path:
        sys.path.insert(0, checkout)
    sys.dont_write_bytecode = True  # the checkout may be mounted read-only
    share = os.environ["FREECAD_GROOVE_SHARE"]
    which = os.environ.get("FREECAD_GROOVE_BENCH_FRESH", "ours")
    rows = []
    import figures

    figures.to_file(os.path.join(share, "figures.jsonl"))
    title = {"ours": "ours (linuxcnc_lathe)", "freecad": "FreeCAD's linuxcnc post"}[which]
    who = {"ours": "ours", "freecad": "FreeCAD's linuxcnc post"}[which]

    def step(label, fn, figure=None):
        cpu, wall = time.thread_time(), time.perf_counter()
        result = fn()
        cpu = time.thread_time() - cpu
        rows.append("    %-56s %8.1f ms CPU (%.1f ms wall)" % (label, cpu * 1e3, (time.perf_counter() - wall) * 1e3))
        if figure:
            figures.record("fresh FreeCAD, the saved 500-groove Job, %s: %s, thread CPU" % (who, figure), cpu * 1e3,
                           "ms", figures.LOWER)
        return result

    if which == "ours":  # what opening a document with Groove ops imports: FreeCAD's CAM op modules, then ours
        step("import FreeCAD's Path.Op.Base (once)", lambda: __import__("Path.Op.Base"))
        step("import the Groove op's module (once)", lambda: figures.first_of(
            "ObjectGroove", "freecad_groove.ops.groove.op", "freecad_groove.freecad.groove_op"),
             "importing our op module")
    doc = step("open the document (FreeCAD.openDocument)",
               lambda: FreeCAD.openDocument(os.path.join(share, "bench_post.FCStd")), "opening the document")
    ops = [obj for obj in doc.Objects if hasattr(obj, "GrooveCount")]
    objects = [ops[0].ToolController] + ops
    if which == "ours":
        from freecad_groove import demo

        post = step("load our linuxcnc_lathe post (imports, once)", lambda: demo.load_post("linuxcnc"),
                    "loading the post")
        args = ""
    else:
        post = step("import FreeCAD's linuxcnc_post (once)",
                    lambda: __import__("Path.Post.scripts.linuxcnc_post", fromlist=["export"]))
        args = "--no-show-editor"
    step("the first post", lambda: post.export(objects, "-", args), "the first post")
    step("the second post", lambda: post.export(objects, "-", args), "the second post")
    FreeCAD.closeDocument(doc.Name)
    with open(os.path.join(share, "bench_freecad.txt"), "a") as f:
        if which == "ours":
            f.write("\n(c) the first post in a FreeCAD just started (bench_freecad_fresh.py), 500 grooves:\n")
        f.write("  %s in a fresh FreeCAD, opening the saved document and posting it:\n" % title)
        f.write("\n".join(rows) + "\n")


try:
    _freecad_groove_bench_fresh()
except Exception:  # noqa: B902 - shown, then the process ends with status 1
    import sys
    import traceback

    import FreeCAD

    FreeCAD.Console.PrintError(traceback.format_exc())
    sys.exit(1)
