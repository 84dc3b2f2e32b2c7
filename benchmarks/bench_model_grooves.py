"""FreeCAD benchmark of reading grooves from the model (ops/groove/model.py):
prints figures, asserts nothing. Runs inside FreeCAD (freecadcmd), headless:

    benchmarks/bench_model_grooves.sh          # FreeCAD 1.1 (scripts/freecad-roots)
    benchmarks/bench_model_grooves.sh 1.0

For shafts R20 carrying 1, 10 and 40 rectangular grooves 4 x 2 mm (a Part
revolve of the section: 7, 43 and 163 faces): the time of one
read_model_groove (each face's section by the half plane, the chained
outline, the recognizer), median of 5; then the recompute of a Groove op
made without dimensions on the last shaft (its groove read from the model),
median of 5 recomputes after touching it. The figures go to
bench_model_grooves.txt in $FREECAD_GROOVE_SHARE (or the current folder), and
as JSON lines (benchmarks/figures.py, which the -c text puts on sys.path) to
figures.jsonl there.
"""


def _bench_model_grooves():
    import os
    import statistics
    import sys
    import time

    import figures
    import FreeCAD

    checkout = os.environ.get("FREECAD_GROOVE_CHECKOUT", os.getcwd())
    for path in (checkout, os.path.join(checkout, "tests", "freecad")):
        if path not in sys.path:
            sys.path.insert(0, path)
    sys.dont_write_bytecode = True  # the checkout may be mounted read-only

    from parts import make_shop

    from freecad_groove import make_groove
    from freecad_groove.ops.groove.model import read_model_groove
    from freecad_groove.ops.groove.op import op_error

    out_path = os.path.join(os.environ.get("FREECAD_GROOVE_SHARE", os.getcwd()), "bench_model_grooves.txt")
    figures.to_file(os.path.join(os.path.dirname(out_path), "figures.jsonl"))
    lines = []

    def emit(text):
        lines.append(text)
        with open(out_path, "w") as f:
            f.write("\n".join(lines) + "\n")

    def median_ms(fn, repeat=5):
        times = []
        for _ in range(repeat):
            t0 = time.perf_counter()
            fn()
            times.append(time.perf_counter() - t0)
        return 1000.0 * statistics.median(times)

    emit("FreeCAD %s: reading a groove from the model" % ".".join(FreeCAD.Version()[:3]))
    for count in (1, 10, 40):
        shape, base = _shaft(count)
        took = median_ms(lambda s=shape, b=base: read_model_groove(s, b, "Shaft"))
        emit("  %2d grooves, %3d faces: read_model_groove %7.1f ms" % (count, len(shape.Faces), took))
        figures.record("read a groove from the model, a %d-groove shaft: median" % count, took, "ms",
                       figures.LOWER)
    doc = FreeCAD.newDocument("BenchModelGrooves")
    _doc, part, job, _tc = make_shop(doc, shape=shape)
    op = make_groove(job, (part, base), infeed=1, tool_width=3, tool_corner_radius=0.2)
    assert op_error(op) is None, op_error(op)

    def recompute():
        op.touch()
        doc.recompute()

    took = median_ms(recompute)
    emit("  the op on the 40-groove shaft, recompute: %7.1f ms" % took)
    figures.record("recompute of a Groove op reading its groove from a 40-groove shaft: median", took, "ms",
                   figures.LOWER)
    FreeCAD.closeDocument(doc.Name)


def _shaft(count):
    """(shape, the name of its first groove's base face): a shaft R20 with
    ``count`` rectangular grooves 4 x 2 mm, 8 mm apart."""
    import FreeCAD
    import Part

    v = FreeCAD.Vector
    profile = [(0, 0), (20, 0)]
    for k in range(count):
        z = 5 + 8 * k
        profile += [(20, z), (18, z), (18, z + 4), (20, z + 4)]
    profile += [(20, 8 * count + 5), (0, 8 * count + 5), (0, 0)]
    shape = Part.Face(Part.makePolygon([v(r, 0, z) for r, z in profile])).revolve(v(0, 0, 0), v(0, 0, 1), 360)
    base = next("Face%d" % (i + 1) for i, f in enumerate(shape.Faces)
                if isinstance(f.Surface, Part.Cylinder) and abs(f.Surface.Radius - 18) < 1e-9)
    return shape, base


try:
    _bench_model_grooves()
except Exception:  # noqa: B902 - shown, then the process ends with status 1
    import sys
    import traceback

    import FreeCAD

    FreeCAD.Console.PrintError(traceback.format_exc())
    sys.exit(1)
