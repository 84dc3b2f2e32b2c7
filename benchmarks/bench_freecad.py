"""FreeCAD benchmark of the Groove op and the linuxcnc_lathe post: prints
figures, asserts nothing. Runs inside FreeCAD (freecadcmd), headless:

    benchmarks/bench_freecad.sh          # FreeCAD 1.1 (scripts/freecad-roots)
    benchmarks/bench_freecad.sh 1.0      # or another label of `scripts/freecad-roots list`

or by hand, with the checkout loaded as a FreeCAD Mod::

    scripts/freecad-roots run 1.1 --share /tmp/bench -- sh -c \\
        'exec freecadcmd -M "$FREECAD_GROOVE_CHECKOUT" -c "$1"' sh \\
        "import os; exec(open(os.environ['FREECAD_GROOVE_CHECKOUT'] + '/benchmarks/bench_freecad.py').read())"

(keep the -c text under 256 characters: FreeCAD 1.1 crashes on longer
ones). The figures go to FreeCAD's console and to bench_freecad.txt in
$FREECAD_GROOVE_SHARE (or $FREECAD_GROOVE_BENCH_OUT), which the wrapper
prints; FREECAD_GROOVE_BENCH_GROOVES changes the 500 of (b).

(a) Recompute of one Groove op: the stepped shaft of the FreeCAD tests
    (tests/freecad/parts.py), a Job, one groove 4 wide and 2 deep with a
    3 mm blade (the test's default groove); Position is changed (5 <-> 6 mm)
    and the document recomputed, 20 times: median, min and max of
    doc.recompute(). The same for a groove on each other kind of face, and the
    op's own planning (op.Proxy.plan) alone.
(b) Posting 500 grooves (also after saving and reopening the document): a plain bar R20, five Groove ops of 100 grooves
    each (GrooveCount 100, Pitch 5, grooves 4 wide on a 3 mm blade: two
    plunges and two pecks each). The list [tool controller, op, ...] is
    posted with our linuxcnc_lathe post and with FreeCAD's own linuxcnc post
    (Path/Post/scripts/linuxcnc_post.py, the script post FreeCAD 1.0 and 1.1
    ship: ``export(objectslist, "-", "--no-show-editor")``), median of 3
    each; then both through FreeCAD's PostProcessorFactory, as the Job's Post
    command runs them (the Job's own post list: fixture, tool controller,
    operations), and FreeCAD's class-based refactored_linuxcnc when it runs.
    Our post derives every groove again from the op (op.Proxy.plan: the
    engine's expansion and the collision checks against the part), to write
    native calls where a control has them; FreeCAD's post only formats the
    op's stored Path. The planning time is shown on its own. Then the
    document is saved and reopened 5 times: the first post after opening and
    the next one against the post before saving, in CPU time of the thread
    (time.thread_time: the machine may be shared), with opening's own time
    and the full garbage collections that fell into the posts.
(c) bench_freecad_fresh.py (run next by bench_freecad.sh): a fresh FreeCAD
    opens the document (b) saved and posts it, one-time imports apart, with
    our post and with FreeCAD's linuxcnc post.

Targets (issue 3): (a) under 50 ms; (b) our post no slower than FreeCAD's own; (issue 10 item 11) the
first post after reopening as fast as before saving (CPU medians within 10 %); (issue 22) a Job of 500
single-groove ops posted at least 5 times faster than FreeCAD's linuxcnc post does.

FREECAD_GROOVE_BENCH_OPS=N makes (b)'s grooves N ops (default 5; 500 with
FREECAD_GROOVE_BENCH_GROOVES=500: 500 ops of one groove each);
FREECAD_GROOVE_BENCH_PARTS picks the parts: a (recompute), b (posting), r
(saving, reopening and posting again; what (c) needs), default "abr". The
figures also go, as JSON lines (benchmarks/figures.py, which the -c text puts
on sys.path), to figures.jsonl in $FREECAD_GROOVE_SHARE; times there are CPU
times (time.process_time, or this thread's where said): the machine may be
shared.
"""


def _freecad_groove_bench():
    import os
    import sys

    import FreeCAD

    checkout = os.environ.get("FREECAD_GROOVE_CHECKOUT") or os.path.dirname(
        os.path.dirname(os.path.abspath(globals().get("__file__", "benchmarks/x"))))
    for path in (checkout, os.path.join(checkout, "tests", "freecad")):
        if path not in sys.path:
            sys.path.insert(0, path)
    sys.dont_write_bytecode = True  # the checkout may be mounted read-only

    import figures

    share = os.environ.get("FREECAD_GROOVE_SHARE", "")
    if share:
        figures.to_file(os.path.join(share, "figures.jsonl"))
    out_path = os.environ.get("FREECAD_GROOVE_BENCH_OUT") or os.path.join(share or os.getcwd(), "bench_freecad.txt")
    parts_run = os.environ.get("FREECAD_GROOVE_BENCH_PARTS", "abr")
    lines = []

    def emit(text=""):
        lines.append(text)
        FreeCAD.Console.PrintMessage(text + "\n")
        with open(out_path, "w") as f:
            f.write("\n".join(lines) + "\n")

    emit("freecad-groove FreeCAD benchmark: FreeCAD %s, Python %s, %s" % (
        ".".join(FreeCAD.Version()[:3]), sys.version.split()[0], os.uname().machine))
    if "a" in parts_run:
        _bench_recompute(emit, figures)
    if "b" in parts_run:
        _bench_posting(emit, figures, "r" in parts_run)


def _ms(seconds):
    return "%8.1f ms" % (seconds * 1000.0)


def _timed(fn, repeat):
    """([wall seconds], [CPU seconds], the last result) of ``repeat`` calls."""
    import time

    walls, cpus, result = [], [], None
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        result = fn()
        cpus.append(time.process_time() - c0)
        walls.append(time.perf_counter() - t0)
    return walls, cpus, result


def _new_doc(name):
    import FreeCAD

    doc = FreeCAD.newDocument(name)
    FreeCAD.setActiveDocument(doc.Name)
    return doc


def _bench_recompute(emit, figures):
    """(a) the recompute of one Groove op per kind of face."""
    import statistics

    import FreeCAD
    import parts  # tests/freecad/parts.py: the stepped shaft and its Job

    from freecad_groove import make_groove
    op_error = figures.first_of("op_error", "freecad_groove.ops.groove.op", "freecad_groove.freecad.groove_op")

    emit()
    emit("(a) Groove op recompute, one groove (Position 5 <-> 6 mm, doc.recompute()), 20 runs")
    doc = _new_doc("BenchRecompute")
    _doc, shaft, job, tc = parts.make_shop(doc)
    kinds = [("cylinder", {}), ("bore", dict(position=10, depth=1.5)), ("shoulder", dict(position=1, width=3.5)),
             ("cone_up", dict(position=3)), ("left_end", dict(position=2))]
    headline = None
    for key, extra in kinds:
        values = dict(position=5, width=4, depth=2, infeed=1, tool_width=3, tool_corner_radius=0.2)
        values.update(extra)
        op = make_groove(job, (shaft, parts.face_name(shaft.Shape, key)), name="Groove_" + key, **values)
        if op_error(op):
            emit("  %-9s op invalid: %s" % (key, op_error(op)))
            continue
        base = op.Position.Value
        moved = [0]

        def recompute(op=op, base=base, moved=moved):
            op.Position = base + (1.0 if moved[0] % 2 == 0 else 0.0)
            moved[0] += 1
            doc.recompute()

        times, cpus, _result = _timed(recompute, 20)
        op.Position = base
        doc.recompute()
        valid = op_error(op) is None
        plan_times, _cpu, plans = _timed(lambda op=op: [op.Proxy.plan(op)], 20)
        med = statistics.median(times)
        if headline is None:
            headline = med
        emit("  %-9s %-34s median %s (min %.1f, max %.1f ms), CPU %s; plan() alone %s; %d moves%s" % (
            key, op.GrooveKind, _ms(med), min(times) * 1000, max(times) * 1000, _ms(statistics.median(cpus)).strip(),
            _ms(statistics.median(plan_times)).strip(), sum(len(p.moves) for p in plans[0]),
            "" if valid else " (INVALID after the runs)"))
        figures.record("recompute of one plain Groove op, %s face: median CPU" % key.replace("_", " "),
                       1000 * statistics.median(cpus), "ms", figures.LOWER, "< 50")
    FreeCAD.closeDocument(doc.Name)
    if headline is not None:
        emit("  target: under 50 ms for one groove -> cylinder groove %s: %s" % (
            _ms(headline).strip(), "met" if headline < 0.050 else "NOT met"))


def _post_job(emit, ops_count, per_op):
    """(doc, job, [tool controller, op, ...]) of (b): ``ops_count`` Groove ops of
    ``per_op`` grooves each on a bar R20; None when an op is invalid."""
    import time

    import figures
    import parts

    from freecad_groove import make_groove
    op_error = figures.first_of("op_error", "freecad_groove.ops.groove.op", "freecad_groove.freecad.groove_op")

    pitch = 5.0
    span = per_op * pitch
    length = ops_count * span + 10.0
    emit("(b) posting %d grooves: %d ops x GrooveCount %d on a bar R20 x %g mm, median of 3" % (
        ops_count * per_op, ops_count, per_op, length))
    doc = _new_doc("BenchPost")
    shape = parts.shaft_shape([(0, 0), (20, 0), (20, length), (0, length), (0, 0)])
    _doc, bar, job, tc = parts.make_shop(doc, shape=shape)
    face = parts.face_name(bar.Shape, "cylinder", {"cylinder": lambda f: f.surface == "cylinder"})
    t0 = time.perf_counter()
    ops = []
    for k in range(ops_count):
        ops.append(make_groove(job, (bar, face), name="Grooves%d" % (k + 1), recompute=False,
                               position=5 + k * span, width=4, depth=2, infeed=1, groove_count=per_op,
                               pitch=pitch, tool_width=3, tool_corner_radius=0.2))
    doc.recompute()
    build = time.perf_counter() - t0
    bad = ["%s: %s" % (op.Label, op_error(op)) for op in ops if op_error(op)]
    if bad:
        emit("  ops invalid: %s" % ", ".join(bad[:5]))
        return None
    emit("  job: %d grooves, %d Path commands; creating and recomputing the ops took %.2f s" % (
        sum(len(op.Proxy.plan(op)) for op in ops), sum(len(op.Path.Commands) for op in ops), build))
    return doc, job, [tc] + ops


def _post_row(emit, label, fn):
    """Time a post 3 times: (wall median, CPU median), or None when it does not run here."""
    import statistics

    try:
        times, cpus, text = _timed(fn, 3)
    except Exception as e:  # a post that does not run here: say so, go on
        emit("  %-58s does not run: %s: %s" % (label, type(e).__name__, e))
        return None
    if isinstance(text, list):  # PostProcessorFactory: [(section, gcode)]
        text = "".join(g or "" for _s, g in text)
    med, cpu = statistics.median(times), statistics.median(cpus)
    emit("  %-58s %s  (%d lines; CPU %s)" % (label, _ms(med), (text or "").count("\n"), _ms(cpu).strip()))
    return med, cpu


def _via_factories(emit, job):
    """Both posts through FreeCAD's PostProcessorFactory, as the Job's Post command runs them."""
    try:
        from Path.Post.Processor import PostProcessorFactory
    except ImportError as e:
        emit("  PostProcessorFactory: not in this FreeCAD (%s)" % e)
        return
    for name, args in (("linuxcnc_lathe", ""), ("linuxcnc", "--no-show-editor"), ("refactored_linuxcnc", "")):
        def via_factory(name=name, args=args):
            job.PostProcessorArgs = args
            post = PostProcessorFactory.get_post_processor(job, name)
            if post is None:
                raise LookupError("PostProcessorFactory found no post %r" % name)
            return post.export()

        _post_row(emit, "PostProcessorFactory(job, %r).export()" % name, via_factory)


def _bench_posting(emit, figures, reopen):
    """(b) posting the Job with our post and FreeCAD's; with ``reopen``, then after saving and reopening."""
    import os
    import statistics

    from freecad_groove import demo

    total = int(os.environ.get("FREECAD_GROOVE_BENCH_GROOVES", "500"))
    ops_count = int(os.environ.get("FREECAD_GROOVE_BENCH_OPS", "5"))
    per_op = max(1, total // ops_count)
    emit()
    made = _post_job(emit, ops_count, per_op)
    if made is None:
        return
    doc, job, objects = made
    ops = objects[1:]
    what = ("post a Job of %d single-groove ops" % ops_count if per_op == 1
            else "post a Job of %d grooves in %d ops" % (ops_count * per_op, ops_count))
    ours = demo.load_post("linuxcnc")
    import Path.Post.scripts.linuxcnc_post as fc_linuxcnc

    mine = _post_row(emit, "ours: linuxcnc_lathe_post.export(objects, '-', '')", lambda: ours.export(objects, "-", ""))
    plan_med = statistics.median(_timed(lambda: [op.Proxy.plan(op) for op in ops], 3)[0])
    emit("  %-58s %s" % ("  (op.Proxy.plan() of every op, which a post of up-to-date ops skips)", _ms(plan_med)))
    theirs = _post_row(emit, "FreeCAD: linuxcnc_post.export(objects, '-', '--no-show-editor')",
                       lambda: fc_linuxcnc.export(objects, "-", "--no-show-editor"))
    _via_factories(emit, job)
    if mine is not None:
        figures.record(what + ": ours (linuxcnc_lathe), median CPU", 1000 * mine[1], "ms", figures.LOWER)
    if theirs is not None:
        figures.record(what + ": FreeCAD's linuxcnc post, median CPU", 1000 * theirs[1], "ms", figures.LOWER)
    if mine is not None and theirs is not None:
        emit("  target: ours no slower than FreeCAD's linuxcnc post -> %.2f x its time: %s" % (
            mine[0] / theirs[0], "met" if mine[0] <= theirs[0] else "NOT met"))
        emit("  a post of touched (not recomputed) ops plans them again: about %s" % _ms(mine[0] + plan_med).strip())
        figures.record(what + ": FreeCAD's linuxcnc post / ours, CPU time", theirs[1] / mine[1], "x",
                       figures.HIGHER, ">= 5" if per_op == 1 else ">= 1")
    reopened = _post_after_reopening(doc, ours, fc_linuxcnc, emit, _ms) if reopen else None
    if reopened is not None:
        first, before, opening, freecad_after = reopened
        emit("  target: the first post after saving and reopening as fast as before saving (CPU medians, within 10 %%)"
             " -> %.2f x: %s" % (first / before, "met" if first <= 1.10 * before else "NOT met"))
        figures.record(what + ", reopened: opening it, median thread CPU", 1000 * opening, "ms", figures.LOWER)
        figures.record(what + ", reopened: the first post, median thread CPU", 1000 * first, "ms", figures.LOWER)
        figures.record(what + ": first post after reopening / before saving, thread CPU", first / before, "x",
                       figures.LOWER, "<= 1.10")
        figures.record(what + ", reopened: FreeCAD's linuxcnc post / our first post, thread CPU",
                       freecad_after / first, "x", figures.HIGHER, ">= 5" if per_op == 1 else ">= 1")


def _cpu(fn):
    """This thread's CPU seconds of fn()."""
    import time

    t0 = time.thread_time()
    fn()
    return time.thread_time() - t0


class _FullCollections:
    """The full collections (gen2) of Python's cyclic garbage collector, as
    [(start, seconds)] in this thread's CPU time, while installed."""

    def __init__(self):
        self.full = []
        self.started = 0.0

    def __call__(self, phase, info):
        import time

        if info["generation"] == 2:
            if phase == "start":
                self.started = time.thread_time()
            else:
                self.full.append((self.started, time.thread_time() - self.started))

    def since(self, t0):
        """(count, seconds) of the full collections that started after ``t0``."""
        return sum(1 for at, _s in self.full if at >= t0), sum(seconds for at, seconds in self.full if at >= t0)


def _post_after_reopening(doc, post, theirs, emit, ms, rounds=5):
    """Save ``doc`` (as bench_post.FCStd in the shared folder, which
    bench_freecad_fresh.py opens next, or a temporary one), close it, then
    ``rounds`` times: open it (FreeCAD does not recompute), post its tool
    controller and Groove ops with ``post`` (the first post), post again (the
    next one), then once with ``theirs`` (FreeCAD's linuxcnc post module), close it.
    Times are this thread's CPU time (time.thread_time:
    other processes on a shared machine do not count), the post before saving
    timed the same way for the comparison, with the full collections of
    Python's cyclic garbage collector (gen2) that fell into the posts. Returns
    (first post, post before saving, opening, FreeCAD's post after opening) CPU medians, or None when it
    does not run."""
    import gc
    import os
    import statistics
    import tempfile

    objects = [obj for obj in doc.Objects if hasattr(obj, "GrooveCount")]
    objects.insert(0, objects[0].ToolController)
    share = os.environ.get("FREECAD_GROOVE_SHARE")
    path = os.path.join(share or tempfile.mkdtemp(), "bench_post.FCStd")
    times = {"before": [], "first": [], "after": [], "opening": [], "theirs": []}
    collections = _FullCollections()
    gc.callbacks.append(collections)
    try:
        for _ in range(rounds):
            times["before"].append(_cpu(lambda: post.export(objects, "-", "")))
        doc.saveAs(path)
        size = os.path.getsize(path)
        collected = _reopen_and_post(doc, path, (post, theirs), rounds, times, collections)
    except Exception as e:  # shown, not fatal
        emit("  %-58s does not run: %s: %s" % ("ours after reopening", type(e).__name__, e))
        return None
    finally:
        gc.callbacks.remove(collections)
        if not share and os.path.exists(path):
            os.remove(path)

    def spread(values):
        return "median %s (min %.1f, max %.1f ms)" % (ms(statistics.median(values)), min(values) * 1e3,
                                                      max(values) * 1e3)

    emit("  saved and reopened %d times (%.0f kB saved); CPU time of this thread (time.thread_time):" % (
        rounds, size / 1000.0))
    emit("    %-56s %s" % ("ours before saving, for comparison", spread(times["before"])))
    emit("    %-56s %s" % ("opening the document (FreeCAD.openDocument)", spread(times["opening"])))
    emit("    %-56s %s" % ("ours after opening: the first post", spread(times["first"])))
    emit("    %-56s %s" % ("ours after opening: the next one", spread(times["after"])))
    emit("    %-56s %s" % ("FreeCAD's linuxcnc post after ours", spread(times["theirs"])))
    emit("    full garbage collections (gen2) in the first posts: %d, %.0f ms in all; in the next ones: %d, %.0f ms" % (
        collected[0][0], collected[0][1] * 1e3, collected[1][0], collected[1][1] * 1e3))
    return tuple(statistics.median(times[key]) for key in ("first", "before", "opening", "theirs"))


def _reopen_and_post(doc, path, posts, rounds, times, collections):
    """Close ``doc``, then ``rounds`` times open ``path``, post twice with
    ours and once with FreeCAD's (``posts``); returns [[count, seconds],
    [count, seconds]]: the full collections in our first posts and in the next ones."""
    import time

    import FreeCAD

    post, theirs = posts
    collected = [[0, 0.0], [0, 0.0]]
    FreeCAD.closeDocument(doc.Name)
    for _ in range(rounds):
        again = []
        times["opening"].append(_cpu(lambda again=again: again.append(FreeCAD.openDocument(path))))
        try:
            ops = [o for o in again[0].Objects if hasattr(o, "GrooveCount")]
            listed = [ops[0].ToolController] + ops
            for k, key in enumerate(("first", "after")):
                t0 = time.thread_time()
                times[key].append(_cpu(lambda listed=listed: post.export(listed, "-", "")))
                count, seconds = collections.since(t0)
                collected[k][0] += count
                collected[k][1] += seconds
            times["theirs"].append(_cpu(lambda listed=listed: theirs.export(listed, "-", "--no-show-editor")))
        finally:
            FreeCAD.closeDocument(again[0].Name)
    return collected


try:
    _freecad_groove_bench()
except Exception:  # noqa: B902 - shown, then the process ends with status 1
    import sys
    import traceback

    import FreeCAD

    FreeCAD.Console.PrintError(traceback.format_exc())
    sys.exit(1)
