"""run() and main(): the demo document built, checked, saved and posted; its summary."""

import json
import os
import sys
import time

from . import jobs, posting, shaft
from .shaft import DOCUMENT

TURNING_CHECK_FILE = DOCUMENT + "_turning_check.txt"


def say(text):
    import FreeCAD

    FreeCAD.Console.PrintMessage("freecad-groove demo: %s\n" % text)


class TurningCheckNotClean(RuntimeError):
    """The Groove Job's own turning check found a problem (or could not check an op)."""


def turning_check(job, groove_ops, out_dir):
    """verify_job() on the Groove Job (its own stock: the part as turned), written to TURNING_CHECK_FILE:
    its summary dict. TurningCheckNotClean unless every Groove op is checked and clean."""
    from ..ops.turning_check.check import verify_job

    result = verify_job(job)
    text = result.summary()
    with open(os.path.join(out_dir, TURNING_CHECK_FILE), "w") as f:
        f.write(text + "\n")
    checked = [check.label for check in result.ops]
    clean = result.ok and checked == [op.Label for op in groove_ops]
    summary = {
        "clean": clean, "verdict": text.splitlines()[0], "stock": result.notes[0] if result.notes else "",
        "file": TURNING_CHECK_FILE,
        "ops": [{"label": c.label, "ok": c.ok, "error": c.error, "removed": round(c.removed, 4),
                 "gouge_depth": c.gouge_depth, "leftover": round(c.leftover, 4), "rapid_hits": len(c.rapid_hits)}
                for c in result.ops],
    }
    if not clean:
        raise TurningCheckNotClean("the Groove Job's turning check is not clean (%s):\n%s" % (
            TURNING_CHECK_FILE, text))
    return summary


def build(doc, out_dir):
    """Every Job and op of the demo in ``doc``, the Groove Job checked: (jobs summary, {system: objects to post},
    turning check summary, groove ops)."""
    part = shaft.make_part(doc)
    groove_job, tc = shaft.make_job(doc, part)
    groove_ops = shaft.make_ops(doc, groove_job, part, tc)
    slot_job, slot = jobs.make_slot_job(doc, part, shaft.face_names(part.Shape)["neck"])
    grind_job, grind = jobs.make_grind_job(doc)
    mill_job, mill_ops = jobs.make_mill_job(doc)
    check = turning_check(groove_job, groove_ops, out_dir)
    listed = [
        {"system": "groove", "job": groove_job.Label, "ops": [
            {"label": op.Label, "kind": op.GrooveKind, "typ": op.TYP, "grooves": len(op.Proxy.plan(op)),
             "faces": ["%s.%s" % (part.Label, s) for _b, subs in op.Base for s in subs]} for op in groove_ops]},
        {"system": "slot", "job": slot_job.Label, "ops": [{"label": slot.Label, "call": slot.Region}]},
        {"system": "grind", "job": grind_job.Label, "ops": [{"label": grind.Label, "call": grind.GrindCall}]},
        {"system": "mill", "job": mill_job.Label, "ops": [{"label": op.Label, "call": "CAM's %s op" % (
            "Face" if "Face" in op.Name else "Pocket Shape")} for op in mill_ops]},
    ]
    objects = {"groove": [tc] + groove_ops, "slot": [slot_job], "grind": [grind_job], "mill": [mill_job]}
    return listed, objects, check, groove_ops


def run(out_dir):
    """Build the demo document (the Groove, Slot, Grind and Mill Jobs), run the Groove Job's turning check,
    save ``out_dir``/demo_part.FCStd, write every program of posting.PROGRAMS into ``out_dir`` (each native one
    checked for its cycle words) and the summary (summary.txt, summary.json, FreeCAD's console). Returns the
    summary dict. Raises on any failure (an op that does not recompute, a turning check that is not clean, a
    post error, a native program without its cycle word)."""
    import FreeCAD

    t0 = time.perf_counter()
    out_dir = os.path.abspath(out_dir)
    os.makedirs(out_dir, exist_ok=True)
    doc = FreeCAD.newDocument(DOCUMENT)
    name = doc.Name
    try:
        FreeCAD.setActiveDocument(name)
        listed, objects, check, groove_ops = build(doc, out_dir)
        document = os.path.join(out_dir, DOCUMENT + ".FCStd")
        doc.saveAs(document)
        entries = posting.post_all(objects, out_dir)
        summary = {
            "freecad": ".".join(FreeCAD.Version()[:3]),
            "python": sys.version.split()[0],
            "document": os.path.basename(document),
            "tool": {"number": shaft.TOOL_NUMBER, "width": shaft.TOOL_WIDTH,
                     "corner_radius": shaft.TOOL_CORNER_RADIUS,
                     "reach": shaft.TOOL_REACH, "reference": "minus"},
            # every Groove op keeps Retract 0 (= 1 mm): the peck retract e of the pecking cycles
            "peck_retract": 1.0,
            "jobs": listed,
            "ops": listed[0]["ops"],
            "turning_check": check,
            "outputs": entries,
            "seconds": None,
        }
    finally:
        FreeCAD.closeDocument(name)
    summary["seconds"] = round(time.perf_counter() - t0, 3)
    summary["files"] = written_files(summary)
    lines = summary_lines(summary)
    with open(os.path.join(out_dir, "summary.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(os.path.join(out_dir, "summary.json"), "w") as f:
        json.dump(summary, f, indent=1)
    for line in lines:
        say(line)
    say("files in %s (%.1f s)" % (out_dir, summary["seconds"]))
    return summary


def _describe(entry):
    calls = ", ".join("%d %s" % (n, c) for c, n in sorted(entry["native_calls"].items()))
    return "%-6s %-16s %-8s %5d lines%s" % (entry["system"], entry["post"], entry["mode"], entry["lines"],
                                             ", native: " + calls if calls else "")


def written_files(summary):
    """[(file name, what it is)] of every file the demo writes, in the order summary.txt lists them."""
    names = ", ".join(job["job"] for job in summary["jobs"])
    files = [(summary["document"], "the document: %s" % names)]
    files += [(e["file"], _describe(e)) for e in summary["outputs"]]
    files.append((TURNING_CHECK_FILE, "the Groove Job's turning check: " + summary["turning_check"]["verdict"]))
    files += [("summary.txt", "this list"), ("summary.json", "the same, for tests/test_demo.py")]
    return files


def summary_lines(summary):
    jobs_ = summary["jobs"]
    lines = ["FreeCAD %s demo: one document, %d Jobs, %d ops, %d programs (%.1f s)" % (
        summary["freecad"], len(jobs_), sum(len(j["ops"]) for j in jobs_), len(summary["outputs"]),
        summary["seconds"])]
    for job in jobs_:
        lines.append("%s (%s):" % (job["job"], job["system"]))
        for op in job["ops"]:
            if job["system"] == "groove":
                lines.append("  op %-18s %-40s TYP %2d, %d groove(s) on %s" % (
                    op["label"], op["kind"], op["typ"], op["grooves"], ", ".join(op["faces"])))
            else:
                lines.append("  op %-18s %s" % (op["label"], op["call"]))
    check = summary["turning_check"]
    lines.append("turning check of the Groove Job: %s; %s" % ("clean" if check["clean"] else "NOT CLEAN",
                                                            check["verdict"]))
    lines.append("files (%d):" % len(summary["files"]))
    lines += ["  %-40s %s" % item for item in summary["files"]]
    return lines


def main():
    """Entry point for ``freecadcmd -c``: run() into $FREECAD_GROOVE_DEMO_OUT
    (relative to $FREECAD_GROOVE_SHARE when that is set; default: the share,
    else ./groove-demo), then end FreeCAD through sys.exit: status 0, or 1
    after writing the traceback to demo_error.txt there and to the console."""
    import traceback

    share = os.environ.get("FREECAD_GROOVE_SHARE", "")
    out_dir = os.environ.get("FREECAD_GROOVE_DEMO_OUT", "") or (share or "groove-demo")
    if not os.path.isabs(out_dir):
        out_dir = os.path.join(share or os.getcwd(), out_dir)
    status = 0
    try:
        sys.dont_write_bytecode = True  # the checkout may be mounted read-only
        run(out_dir)
    except BaseException:  # noqa: B902 - reported in the file and on the console
        status = 1
        text = traceback.format_exc()
        try:
            os.makedirs(out_dir, exist_ok=True)
            with open(os.path.join(out_dir, "demo_error.txt"), "w") as f:
                f.write(text)
        except OSError:
            pass
        import FreeCAD

        FreeCAD.Console.PrintError("freecad-groove demo failed:\n%s" % text)
    sys.stdout.flush()
    sys.stderr.flush()
    sys.exit(status)  # freecadcmd ends with this status (os._exit would lose console output)
