"""A Groove op with radii: its Path holds G2/G3 where the engine's passes
write arcs, FreeCAD reads them the way they turn, the posts write them (I/K
from the start, Siemens CR=, radius X words for --x-mode radius), the saved
plans keep them, and the turning check sweeps them. Inside FreeCAD (1.1 and
1.0; run by tests/freecad/run_suite.py); LinuxCNC's rs274 reads the posted
arcs on the host (test_post_artifacts.py)."""

import base64
import json
import math
import re
import zlib

import FreeCAD
import Path
import Path.Main.Stock as PathStock
import pytest
import test_groove_op as tg
import test_posts as tp
from pylib import require_shapely

from freecad_groove import verify_job
from freecad_groove.engine.moves import ARC_CW, ARCS
from freecad_groove.freecad.addon_op import op_error
from freecad_groove.ops.groove import cache as plan_cache

doc, shop = tg.doc, tg.shop

# Base radii 1 and an edge radius 0.8 on the R20 cylinder's groove (4 wide, 2 deep, blade 3 with r 0.2).
RADII = dict(base_corner1=1.0, base_corner1_type="Radius", base_corner2=1.0, base_corner2_type="Radius",
             edge_corner1=0.8, edge_corner1_type="Radius")


def radiused(shop, **extra):
    op = tg.groove(shop, "cylinder", **dict(RADII, **extra))
    assert op_error(op) is None, op_error(op)
    return op


def engine_arcs(op):
    """[(kind, start, end, centre)] of the arcs of the op's plans (x radius, z)."""
    out = []
    for plan in op.Proxy.plan(op):
        here = (plan.start.x, plan.start.z)
        for move in plan.moves:
            if move.kind in ARCS:
                out.append((move.kind, here, (move.x, move.z), move.centre))
            if move.kind != "G4":
                here = (move.x, move.z)
    return out


def path_arcs(op):
    """[(kind, start, end, centre)] of the op's Path's G2/G3, the centre its start plus I, K."""
    out, here = [], (None, None)
    for command in op.Path.Commands:
        words = command.Parameters
        end = (words.get("X", here[0]), words.get("Z", here[1]))
        if command.Name in ("G2", "G3"):
            out.append((command.Name, here, end, (here[0] + words["I"], here[1] + words["K"])))
        if command.Name in ("G0", "G1", "G2", "G3"):
            here = end
    return out


def test_a_groove_with_radii_has_the_engines_arcs_in_its_path(shop):
    op = radiused(shop)
    arcs = engine_arcs(op)
    assert {kind for kind, *_ in arcs} == {"G2", "G3"}
    got = path_arcs(op)
    assert len(got) == len(arcs)
    for (kind, start, end, centre), (want_kind, want_start, want_end, want_centre) in zip(got, arcs):
        assert kind == want_kind
        for a, b in ((start, want_start), (end, want_end), (centre, want_centre)):
            assert a == (pytest.approx(b[0], abs=1e-9), pytest.approx(b[1], abs=1e-9))
    commands = [c for c in op.Path.Commands if c.Name in ("G2", "G3")]
    assert all(c.Parameters["F"] == pytest.approx(tg.FEED_MM_S) for c in commands)
    assert all("Y" not in c.Parameters and "J" not in c.Parameters for c in commands)


def _extremes(start, end, centre, clockwise):
    """(x min, x max) of an arc (Z right, X up: clockwise = the angle about the centre falling)."""
    radius = math.dist(start, centre)
    a0, a1 = (math.atan2(p[0] - centre[0], p[1] - centre[1]) for p in (start, end))
    sweep = (a1 - a0) % (2 * math.pi)
    sweep = sweep - 2 * math.pi if clockwise else sweep
    xs = [start[0], end[0]]
    for k in range(-4, 5):  # the angles where X is extreme: +-90 degrees
        a = (k + 0.5) * math.pi
        if 0 < (a - a0) / sweep < 1:
            xs.append(centre[0] + radius * math.sin(a))
    return min(xs), max(xs)


def test_freecad_reads_the_paths_arcs_the_way_they_turn(shop):
    # FreeCAD's own reading of a G18 arc (its Path's bounding box, which also holds the origin the
    # Path starts from): the X range each G2/G3 sweeps from its start round its centre the way the
    # engine means it, G2 clockwise with Z right and X up. Moved 1000 down in X, its lowest X shows.
    for kind, start, end, centre in path_arcs(radiused(shop)):
        low, high = _extremes(start, end, centre, kind == ARC_CW)
        for shift, seen in ((0.0, "XMax"), (-1000.0, "XMin")):
            one = Path.Path([Path.Command("G18"), Path.Command("G0", {"X": start[0] + shift, "Z": start[1]}),
                             Path.Command(kind, {"X": end[0] + shift, "Z": end[1], "I": centre[0] - start[0],
                                                 "K": centre[1] - start[1], "F": 1.0})])
            want = high if seen == "XMax" else low + shift
            assert getattr(one.BoundBox, seen) == pytest.approx(want, abs=1e-6), (kind, start, end, centre)


_ARC = re.compile(r"^(?:G0?([23]) )?X(-?[\d.]+) Z(-?[\d.]+) (?:I(-?[\d.]+) K(-?[\d.]+)|C?R=?(-?[\d.]+))")


def posted_arcs(text, diameter=True):
    """[(kind, start, end, centre or radius)] of a program's arc lines (x radius): I/K, CR= or R."""
    out, here, motion = [], (None, None), None
    for line in text.splitlines():
        words = dict(re.findall(r"\b([XZ])(-?[\d.]+)", line))
        codes = [code for code in re.findall(r"\bG0?(\d)\b", line) if code in "0123"]  # not G4
        motion = codes[0] if codes else motion
        x = float(words["X"]) / (2.0 if diameter else 1.0) if "X" in words else here[0]
        end = (x, float(words["Z"]) if "Z" in words else here[1])
        m = _ARC.match(line)
        if m and motion in ("2", "3"):
            centre = (here[0] + float(m.group(4)), here[1] + float(m.group(5))) if m.group(4) else float(m.group(6))
            out.append(("G" + motion, here, end, centre))
        if words:
            here = end
    return out


@pytest.mark.parametrize("name, args, diameter", [("linuxcnc", "", True), ("linuxcnc", "--x-mode radius", False),
                                                  ("linuxcnc", "--inches", True), ("fanuc", "", True),
                                                  ("sinumerik", "--x-mode radius", False)])
def test_the_posts_write_the_engines_arcs(shop, name, args, diameter):
    op = radiused(shop)
    text = tp.export(name, [op], args + " --expand-cycles")
    unit = 25.4 if "--inches" in args else 1.0  # the posted words' unit, in mm
    got, arcs = posted_arcs(text, diameter), engine_arcs(op)
    assert len(got) == len(arcs) and arcs
    step = 10.0 ** -posts_digits(name)  # the output's resolution
    for (kind, _start, end, centre), (want_kind, _s, want_end, want_centre) in zip(got, arcs):
        assert kind == want_kind
        want_end, want_centre = [(p[0] / unit, p[1] / unit) for p in (want_end, want_centre)]
        assert end == (pytest.approx(want_end[0], abs=step), pytest.approx(want_end[1], abs=step))
        if name == "sinumerik":  # CR=: the radius, positive (no arc of the passes turns more than 180 degrees)
            assert centre == pytest.approx(math.dist(want_end, want_centre), abs=2 * step)
        else:
            assert centre == (pytest.approx(want_centre[0], abs=2 * step), pytest.approx(want_centre[1], abs=2 * step))
    if unit == 1.0:  # the whole path read back as the posts' tests read it (arcs by their ends)
        tp.assert_same_path(tp.positions(tp.read(text, name, diameter)),
                            tp.positions(tp.expected_events(op, name, diameter=diameter)))


def posts_digits(name):
    return tp.posts.LATHE_POSTS[name].digits


def test_a_siemens_program_with_cr_arcs_translates_to_the_engines_arcs(shop):
    op = radiused(shop)
    linuxcnc = tp.translated(tp.export("sinumerik", [op], "--expand-cycles"), "sinumerik", op)
    ends = [end for _k, _s, end, _c in posted_arcs(linuxcnc)]
    assert ends == [(pytest.approx(e[0], abs=2e-3), pytest.approx(e[1], abs=2e-3)) for _k, _s, e, _c in engine_arcs(op)]


def test_the_reference_corner_option_shifts_the_arcs_centres(shop):
    op = radiused(shop)
    minus, plus = (posted_arcs(tp.export("linuxcnc", [op], args)) for args in ("", "--reference-corner plus"))
    assert len(minus) == len(plus) and minus
    for (kind, _s, end, centre), (kind_plus, _sp, end_plus, centre_plus) in zip(minus, plus):
        assert kind == kind_plus  # a longitudinal groove: every word moves by the blade's width along Z
        assert end_plus == (pytest.approx(end[0], abs=1e-4), pytest.approx(end[1] + tg.BLADE, abs=1e-4))
        assert centre_plus == (pytest.approx(centre[0], abs=2e-4), pytest.approx(centre[1] + tg.BLADE, abs=2e-4))


def test_saved_plans_keep_their_arcs(shop):
    op = radiused(shop)
    plans = op.Proxy.current_plan(op)
    restored = plan_cache.unpack(plan_cache.pack(plans, "stamp"))
    assert [p.moves for p in restored] == [p.moves for p in plans]
    arcs = [m for p in restored for m in p.moves if m.kind in ARCS]
    assert arcs and all(isinstance(m.centre, tuple) and m.radius is None for m in arcs)


def test_plans_saved_by_a_release_without_arcs_are_planned_again(shop):
    # An older release saved format 3 (no arc column): never read as plans, so the op plans again;
    # this release's format is not read by that one either (it reads format 3 only).
    op = radiused(shop)
    text = plan_cache.pack(op.Proxy.current_plan(op), "stamp")
    data = json.loads(zlib.decompress(base64.b64decode(text)))
    assert data["format"] == plan_cache.FORMAT == 4
    data["format"] = 3
    del data["moves"]["c"], data["moves"]["r"]
    old = base64.b64encode(zlib.compress(json.dumps(data).encode())).decode("ascii")
    assert plan_cache.read(old) is None and plan_cache.unpack(old) is None
    assert plan_cache.saved_fingerprint(old) is None


def test_the_turning_check_sweeps_the_arcs_without_a_gouge(shop):
    # In a bar stock of the cylinder's own radius (R20, Z0..60: the cycle takes the contour as turned).
    require_shapely()
    doc_, _shaft, job, _tc = shop
    old = job.Stock
    job.Stock = PathStock.CreateCylinder(job, 20.0, 60.0, FreeCAD.Placement())
    doc_.removeObject(old.Name)
    doc_.recompute()
    op = radiused(shop)
    assert any(c.Name in ("G2", "G3") for c in op.Path.Commands)
    result = verify_job(shop[2])
    check = result.ops[0]
    assert check.label == op.Label and check.ok, result.summary()
    assert check.gouge_depth == 0 and check.leftover == 0 and not check.rapid_hits
