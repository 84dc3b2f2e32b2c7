"""Write the lathe posts' programs for tests/test_post_artifacts.py (LinuxCNC's
rs274 and the shapely oracle exist only on the host).

Executed *by* freecadcmd inside FreeCAD 1.1 or 1.0, like run_suite.py (from
``-c``: FreeCAD 1.1 swallows print() of a script file, so the result goes to
a file):

    freecadcmd -M CHECKOUT -c "import os; exec(open(os.environ['FREECAD_GROOVE_CHECKOUT']
        + '/tests/freecad/write_post_artifacts.py').read())"      (one line)

tests/test_post_artifacts.py runs it through ``scripts/freecad-roots run
LABEL --share DIR`` once per FreeCAD and session. For every op of
ARTIFACT_CASES (a Groove op on the stepped shaft of test_groove_op.py, put
through every post of postprocessors/ as test_posts.py does) it writes one
JSON file into FREECAD_GROOVE_ARTIFACTS (relative to FREECAD_GROOVE_SHARE):
the programs (or the error) of every post, the engine's moves from the op's
first start point on, per groove the finished region and a stock window
(engine geometry, world (x radius, z)), the tool (with the reference corner
the programs use), the plunge direction and the peck retract.

Environment: FREECAD_GROOVE_CHECKOUT (default /mnt/freecad-groove),
FREECAD_GROOVE_SHARE, FREECAD_GROOVE_ARTIFACTS (default "artifacts"),
FREECAD_GROOVE_RESULT (default "artifacts.json"): {"freecad_version",
"written": [file names], "error": traceback or null}, written to a temporary
name and renamed. The process ends with os._exit (0, or 1 on an error).
"""

ARTIFACT_CASES = {  # name -> (groove key, keywords, post arguments)
    "cylinder_plain": ("cylinder", {}, ""),
    "cylinder_blade_wide_set": ("cylinder", dict(width=3, position=2, groove_count=3, pitch=5), ""),
    "cylinder_wide_set": ("cylinder", dict(width=4.5, position=1, groove_count=2, pitch=8, infeed=0.7), ""),
    "bore_plain": ("bore", {}, ""),
    "shoulder_plain": ("shoulder", {}, ""),
    "left_end_plain": ("left_end", dict(width=5), ""),
    "cone_flanks_allowances": ("cone_up", dict(flank_angle1=10, base_corner2=0.3, base_corner2_type="Radius",
                                               base_allowance=0.1, flank_allowance=0.1), ""),
    # arcs (base and edge radii): radius X words (--x-mode radius; the posts without it write diameters),
    # a face groove's arcs from the other reference corner
    "cylinder_radii_x_radius": ("cylinder", dict(base_corner1=1.0, base_corner1_type="Radius", base_corner2=1.0,
                                                 base_corner2_type="Radius", edge_corner1=0.8,
                                                 edge_corner1_type="Radius", flank_allowance=0.1), "--x-mode radius"),
    "shoulder_radii_reference_override": ("shoulder", dict(base_corner1=0.5, base_corner1_type="Radius",
                                                           edge_corner2=0.5, edge_corner2_type="Radius"),
                                          "--reference-corner plus"),
    "cylinder_chamfer_dwell": ("cylinder", dict(edge_corner1=0.5, edge_corner1_type="Chamfer", dwell=0.3), ""),
    "cylinder_reference_override": ("cylinder", dict(width=5), "--reference-corner plus"),
    "bore_plus_op": ("bore", dict(reference_corner="plus"), ""),
    "shoulder_reference_override": ("shoulder", dict(width=4), "--reference-corner plus --retract 0.3"),
    # lathe feeds and speeds (G95/G99 feed per revolution, G96 constant surface speed) and inch output
    "cylinder_feed_per_rev": ("cylinder", dict(feed_per_rev=0.08, spindle_speed=600), ""),
    "shoulder_surface_speed": ("shoulder", dict(feed_per_rev=0.05, surface_speed="100 m/min",
                                                max_spindle_speed=2000), ""),
    "cylinder_inches": ("cylinder", dict(width=4.5, groove_count=2, pitch=8, feed_per_rev=0.1), "--inches"),
}


def _expected_moves(plans, dx, dz, feed):
    """The engine's moves from the first start point on (links included), shifted by dx, dz: [kind,
    x, z, f, p, centre] (centre: an arc's, shifted, else None)."""
    from freecad_groove.engine.moves import ARCS, DWELL, FEED, RAPID

    first = plans[0]
    expected = [[RAPID, first.start.x + dx, first.start.z + dz, None, 0.0, None]]
    x, z = first.start.x, first.start.z
    for k, plan in enumerate(plans):
        if k:
            for lx, lz in plan.link:
                x = x if lx is None else lx
                z = z if lz is None else lz
                expected.append([RAPID, x + dx, z + dz, None, 0.0, None])
        for mv in plan.moves:
            centre = None if mv.centre is None else [mv.centre[0] + dx, mv.centre[1] + dz]
            cuts = mv.kind == FEED or mv.kind in ARCS
            expected.append([mv.kind, mv.x + dx, mv.z + dz, feed if cuts else None, mv.p, centre])
            if mv.kind != DWELL:
                x, z = mv.x, mv.z
        for lx, lz in plan.retreat:  # the op's last groove: back to its safe start point
            x, z = lx, lz
            expected.append([RAPID, x + dx, z + dz, None, 0.0, None])
    return expected


def _artifact(op, case, args):
    """One case's JSON data: the op's programs from every post and the engine's view of its grooves."""
    import re

    import FreeCAD
    from test_posts import NAMES, PECKING, export

    from freecad_groove.freecad import posts

    plans = op.Proxy.plan(op)
    first = plans[0]
    reference = None
    m = re.search(r"--reference-corner (\w+)", args)
    if m:
        reference = m.group(1)
    out_ref = reference or first.settings.tool.reference
    tool = first.settings.tool
    d = (tool.width if out_ref == "plus" else 0.0) - tool.reference_offset
    longitudinal = first.cycle.kind()[0]
    dx, dz = (0.0, d) if longitudinal else (d, 0.0)
    retract = op.Retract.Value or 1.0
    m = re.search(r"--retract ([\d.]+)", args)
    if m:
        retract = float(m.group(1))
    from freecad_groove.ops.groove.cutting import cutting_data

    expected = _expected_moves(plans, dx, dz, cutting_data(op).feed)
    programs = {}
    for name in NAMES:
        own = args if name in PECKING else re.sub(r"\s*--retract [\d.]+", "", args)  # only they have it
        if not posts.LATHE_POSTS[name].has_x_mode:
            own = re.sub(r"\s*--x-mode \w+", "", own)
        try:
            programs[name] = {"args": own, "text": export(name, [op], own), "error": None}
        except posts.PostError as e:
            programs[name] = {"args": own, "text": None, "error": str(e)}
    return {
        "case": case,
        "inches": "--inches" in args,
        "freecad": ".".join(FreeCAD.Version()[:3]),
        "op": op.Label,
        "tool": {"width": tool.width, "corner_radius": tool.corner_radius, "reference": out_ref},
        "retract": retract,
        "plunge": first.cycle.plunge_direction(),
        "start": [first.start.x + dx, first.start.z + dz],
        "expected": expected,
        "grooves": [{
            "call": p.cycle.emit(),
            "region": [list(pt) for pt in p.cycle.geometry(p.settings).region_world()],
            "stock": [list(pt) for pt in p.cycle.geometry(p.settings).stock_world()],
        } for p in plans],
        "programs": programs,
    }


def _write_artifacts(folder):
    """One JSON file per ARTIFACT_CASES op into ``folder``; the file names."""
    import json
    import os

    import FreeCAD
    from parts import make_shop
    from test_groove_op import groove
    from test_posts import read

    from freecad_groove.ops.groove.op import op_error

    os.makedirs(folder, exist_ok=True)
    doc = FreeCAD.newDocument("PostArtifacts")
    shop = make_shop(doc)
    shop[3].SpindleSpeed = 800  # the tool controller
    doc.recompute()
    written = []
    for case, (key, values, args) in sorted(ARTIFACT_CASES.items()):
        op = groove(shop, key, **values)
        assert op_error(op) is None, (case, op_error(op))
        data = _artifact(op, case, args)
        assert data["programs"]["linuxcnc"]["text"], case
        # the expected moves are what the LinuxCNC program holds
        events = read(data["programs"]["linuxcnc"]["text"], "linuxcnc")
        assert any(e[0] == "G1" for e in events), case
        path = os.path.join(folder, case + ".json")
        with open(path + ".tmp", "w") as f:
            json.dump(data, f)
        os.replace(path + ".tmp", path)
        written.append(case + ".json")
    return written


def _main():
    import json
    import os
    import sys
    import traceback

    checkout = os.environ.get("FREECAD_GROOVE_CHECKOUT", "/mnt/freecad-groove")
    share = os.environ.get("FREECAD_GROOVE_SHARE") or os.getcwd()
    folder = os.path.join(share, os.environ.get("FREECAD_GROOVE_ARTIFACTS", "artifacts"))
    result_path = os.path.join(share, os.environ.get("FREECAD_GROOVE_RESULT", "artifacts.json"))
    result = {"freecad_version": None, "written": [], "error": None}
    try:
        import FreeCAD

        result["freecad_version"] = list(FreeCAD.Version())
        sys.dont_write_bytecode = True  # the checkout is mounted read-only
        for path in (checkout, os.path.join(checkout, "tests"), os.path.join(checkout, "tests", "freecad")):
            if path not in sys.path:
                sys.path.insert(0, path)
        result["written"] = _write_artifacts(folder)
    except BaseException:  # noqa: B902 - everything goes into the JSON
        result["error"] = traceback.format_exc()
    with open(result_path + ".tmp", "w") as f:
        json.dump(result, f, indent=1)
    os.replace(result_path + ".tmp", result_path)
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(1 if result["error"] else 0)


_main()
