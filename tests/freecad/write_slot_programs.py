"""Write the LinuxCNC programs of Cylinder slot ops for the host's rs274 check
(tests/test_slot_programs.py runs this inside FreeCAD, like write_post_artifacts.py).

Exec'd by freecadcmd from -c. Writes FREECAD_GROOVE_SHARE/slot_programs.json:
{"error": null or a traceback, "cases": {name: {"program": text, "moves":
[[kind, x radius, z, c, f mm/min or null], ...] (the op's Path after its label)}}}.
"""


def _freecad_groove_write_slot_programs():
    import json
    import os
    import sys
    import traceback

    checkout = os.environ.get("FREECAD_GROOVE_CHECKOUT", "/mnt/freecad-groove")
    share = os.environ.get("FREECAD_GROOVE_SHARE", os.getcwd())
    sys.path.insert(0, os.path.join(checkout, "tests", "freecad"))
    result = {"error": None, "cases": {}}
    try:
        import FreeCAD
        import Part
        import test_cylinder_slot as t

        from freecad_groove import make_cylinder_slot

        keyway = Part.makeLine(FreeCAD.Vector(0, 20, 5), FreeCAD.Vector(0, 20, 45))
        cases = {"helix": (t._helix(), dict(depth=2, passes=2, allowance=0.2, retract=1), "--switches-by-hand"),
                 "keyway": (keyway, dict(depth=1.5, passes=1, allowance=0.1, retract=2), "--switches-by-hand"),
                 # the live tool and C axis switches as LinuxCNC digital outputs (posts/live_tool.py)
                 "keyway-switched": (keyway, dict(depth=1.5, passes=1, allowance=0.1, retract=2),
                                     "--c-axis-on 'M64 P0' --c-axis-off 'M65 P0' --live-tool-cw 'M64 P1' "
                                     "--live-tool-stop 'M65 P1'")}
        for name, (edge, values, args) in cases.items():
            doc, shaft, line, job = t._shop(edge)
            op = make_cylinder_slot(job, (shaft, "Face1"), [(line, "Edge1")], **values)
            moves = []
            for c in op.Path.Commands[1:]:
                p = dict(c.Parameters)
                if c.Name in ("G0", "G1"):
                    moves.append([c.Name, p.get("X"), p.get("Z"), p.get("C"), p["F"] * 60 if "F" in p else None])
            result["cases"][name] = {"program": t._post("linuxcnc_lathe", [job], args), "moves": moves}
            FreeCAD.closeDocument(doc.Name)
    except Exception:
        result["error"] = traceback.format_exc()
    with open(os.path.join(share, "slot_programs.json"), "w") as f:
        json.dump(result, f)
    os._exit(0)


_freecad_groove_write_slot_programs()
