"""The lathe posts inside FreeCAD (1.1 and 1.0; run by tests/freecad/run_suite.py).

The stepped shaft, Job and Groove ops of test_groove_op.py are posted with
every post in postprocessors/:

* native calls are read back with the engine's own parsers and compared
  field by field with what the op derives (CYCLE93 with op.Proxy.cycles(op),
  G77/G76/G75/G74 with words worked out here from the op's properties), and
  every native program is read again by the engine's program translator
  (freecad_groove.engine.translator), which must accept it; for CYCLE93 the
  translated moves are the op's own moves;
* ``--expand-cycles`` output, read back, is the engine's moves;
* tool changes, spindle, coolant, other ops' Paths, dressups, options;
* errors name the op and the property, and leave no file (an existing one
  untouched);
* registration puts the posts in FreeCAD's post list and FreeCAD's own
  PostProcessorFactory runs them.

write_post_artifacts.py (run by tests/test_post_artifacts.py) posts more ops
with these helpers for the checks by LinuxCNC's rs274 and the shapely oracle
on the host.
"""

import importlib
import importlib.util
import os
import re
import stat
import sys

import FreeCAD
import Path
import Path.Main.Job as PathJob
import pytest
import test_groove_op as tg

from freecad_groove.engine import GroovingTool, Settings
from freecad_groove.engine.cycles.ab_g77 import G76, G77
from freecad_groove.engine.cycles.cycle93 import Cycle93
from freecad_groove.engine.cycles.fanuc_g75 import FanucG74, FanucG75, HaasG74, HaasG75
from freecad_groove.engine.moves import DWELL, RAPID
from freecad_groove.engine.output.writer import Writer
from freecad_groove.engine.translator import translate_program
from freecad_groove.freecad import posts, registration
from freecad_groove.ops.groove.op import op_error

# The Groove op tests' stepped shaft, Job and helpers (doc and shop are fixtures).
doc, shop, groove, FEED_MM_MIN = tg.doc, tg.shop, tg.groove, tg.FEED_MM_MIN

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
NAMES = ["sinumerik", "ab9", "fanuc", "haas", "linuxcnc"]
PECKING = ["ab9", "fanuc", "haas"]
TOOL_W, TOOL_R = 3.0, 0.2
C = Path.Command

# ----------------------------------------------------------------------------- helpers

_MODULES = {}


def post(name):
    """The post module postprocessors/<name>_lathe_post.py, loaded as FreeCAD loads a script post."""
    if name not in _MODULES:
        path = os.path.join(ROOT, "postprocessors", name + "_lathe_post.py")
        spec = importlib.util.spec_from_file_location(name + "_lathe_post", path)
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        _MODULES[name] = module
    return _MODULES[name]


def export(name, objects, args="", filename="-"):
    return post(name).export(objects, filename, args)


def strip_comment(line, name):
    if name == "sinumerik":
        return line.split(";")[0].strip()
    return re.sub(r"\([^)]*\)", "", line).strip()


_WORD = re.compile(r"([A-Z])(-?\d*\.?\d+)")


def read(text, name, diameter=True):
    """Events of a posted program: ("G0"/"G1"/"G2"/"G3", x radius or None, z or None, f) (an arc's
    centre or CR= left out), ("G4", seconds), ("CALL", native call text), ("LINE", other block)."""
    events = []
    motion, f = None, None
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        line = strip_comment(lines[i], name)
        i += 1
        if not line or line == "%":
            continue
        if line.startswith("CYCLE93("):
            events.append(("CALL", line))
            motion = None
            continue
        if re.match(r"^G7[4-7]\b", line):
            if name == "fanuc" and re.fullmatch(r"G7[45] R-?[\d.]+", line):
                line += "\n" + strip_comment(lines[i], name)
                i += 1
            events.append(("CALL", line))
            motion = None
            continue
        words = _WORD.findall(line)
        letters = [k for k, _v in words]
        gs = [float(v) for k, v in words if k == "G"]
        if 4.0 in gs:
            values = {k: float(v) for k, v in words if k != "G"}
            seconds = values["F"] if name == "sinumerik" else values["P"] / (1000.0 if name == "fanuc" else 1.0)
            events.append(("G4", seconds))
            continue
        if any(k in letters for k in ("T", "M", "S", "O")):
            events.append(("LINE", line))
            continue
        for g in gs:
            if g in (0.0, 1.0, 2.0, 3.0):
                motion = "G%d" % g
        values = {k: float(v) for k, v in words if k in "XZF"}
        if "F" in values:
            f = values["F"]
        if "X" in values or "Z" in values:
            x = values.get("X")
            if x is not None and diameter:
                x /= 2.0
            events.append((motion, x, values.get("Z"), f if motion != "G0" else None))
        elif not values:
            events.append(("LINE", line))
    return events


def positions(events):
    """Moves with full positions, dropping the ones that move nothing; dwells kept."""
    out = []
    x = z = None
    for e in events:
        if e[0] == "G4":
            out.append(("G4", x, z, e[1]))
            continue
        if e[0] not in ("G0", "G1", "G2", "G3"):
            continue
        nx = x if e[1] is None else e[1]
        nz = z if e[2] is None else e[2]
        if (nx, nz) == (x, z):
            continue
        out.append((e[0], nx, nz, e[3]))
        x, z = nx, nz
    return out


def writer(name, precision=None, diameter=True):
    post = posts.LATHE_POSTS[name]
    return Writer(post.target, digits=post.digits if precision is None else precision, x_diameter=diameter)


def expected_events(op, name, precision=None, diameter=True, shift=(0.0, 0.0)):
    """What an expanded groove op must read back as: the op's links and the
    engine's moves for every groove, as the post's writer rounds them."""
    w = writer(name, precision, diameter)
    feed = op.ToolController.HorizFeed.Value * 60.0
    dx, dz = shift

    def xr(x):
        return None if x is None else float(w.x_word(x + dx)) / (2.0 if diameter else 1.0)

    def zr(z):
        return None if z is None else float(w.z_word(z + dz))

    out = []
    for plan in op.Proxy.plan(op):
        for x, z in plan.link:
            out.append(("G0", xr(x), zr(z), None))
        for m in plan.cycle.expand(plan.start, plan.settings):
            if m.kind == DWELL:
                out.append(("G4", m.p))
            else:  # an arc's end (its centre: test_groove_arcs.py)
                out.append((m.kind, xr(m.x), zr(m.z), None if m.kind == RAPID else feed))
        for x, z in plan.retreat:  # the op's last groove: back to its safe start point
            out.append(("G0", xr(x), zr(z), None))
    return out


def calls(text, name):
    return [e[1] for e in read(text, name) if e[0] == "CALL"]


def approx_call(got, want):
    for field in ("axfa", "axsa", "widg", "depg", "angc", "ang1", "ang2", "rco1", "rco2", "rci1", "rci2", "fal1",
                  "fal2", "idep", "dwt", "vrt"):
        assert getattr(got, field) == pytest.approx(getattr(want, field), abs=1e-6), field
    assert got.typ == want.typ and got.dn == want.dn


def translated(text, name, op, reference=None, retract=None):
    """The posted program read by the engine's translator: LinuxCNC text."""
    (_c, settings, _s) = op.Proxy.cycles(op)[0]
    if reference:
        settings = settings.with_tool(reference=reference)
    e = retract if retract is not None else (op.Retract.Value or 1.0)
    from dataclasses import replace

    return translate_program(text, name, replace(settings, peck_retract=e))


def assert_same_path(got, want, tol=1e-9):
    assert len(got) == len(want), "%d moves, expected %d\n%s\n%s" % (len(got), len(want), got[:8], want[:8])
    for i, (a, b) in enumerate(zip(got, want)):
        assert a[0] == b[0], (i, a, b)
        for u, v in zip(a[1:], b[1:]):
            if v is None:
                assert u is None, (i, a, b)
            else:
                assert u == pytest.approx(v, abs=tol), (i, a, b)


# ----------------------------------------------------------------------------- the posts as FreeCAD script posts


@pytest.mark.parametrize("name", NAMES)
def test_every_post_is_a_freecad_script_post(name):
    module = post(name)
    assert isinstance(module.TOOLTIP, str) and module.TOOLTIP
    assert module.UNITS == "G21"
    assert module.TOOLTIP_ARGS == module.parser.format_help()
    for option in ("--expand-cycles", "--reference-corner", "--no-header", "--no-comments", "--precision"):
        assert option in module.TOOLTIP_ARGS
    assert ("--native-cycles" in module.TOOLTIP_ARGS) == (name != "linuxcnc")
    assert ("--retract" in module.TOOLTIP_ARGS) == (name in PECKING)
    assert ("--x-mode" in module.TOOLTIP_ARGS) == (name in ("sinumerik", "ab9", "linuxcnc"))
    text = export(name, [])
    assert text.endswith(("M30\n", "M2\n", "%\n"))

# ----------------------------------------------------------------------------- headers, tools, spindle, coolant


def test_program_frame_per_control(shop):
    doc_, shaft, job, tc = shop
    tc.ToolNumber = 5
    tc.SpindleSpeed = 1200
    tc.SpindleDir = "Reverse"
    op = groove(shop, "cylinder")
    op.CoolantMode = "Flood"
    doc_.recompute()
    frames = {
        "sinumerik": (["; Job", "G18 G71 G90 G40 G94 DIAMON"], ["T5 D1", "G97 S1200 M4", "M8"], ["M9", "M5", "M30"]),
        "ab9": (["(Job)", "G18 G21 G90 G40 G94 G07"], ["T0505", "G97 S1200 M04", "M08"], ["M09", "M05", "M30"]),
        "fanuc": (["%", "O0001 (Job)", "G21", "G40 G98"], ["T0505", "G97 S1200 M04", "M08"],
                  ["M09", "M05", "M30", "%"]),
        "haas": (["%", "O0001 (Job)", "G21", "G40 G98"], ["T0505", "G97 S1200 M04", "M08"], ["M09", "M05", "M30", "%"]),
        "linuxcnc": (["(Job)", "G18 G7 G21 G90 G91.1 G40 G94"], ["T5 M6 G43", "G97 S1200 M4", "M8"],
                     ["M9", "M5", "M2"]),
    }
    for name, (head, tool, tail) in frames.items():
        lines = export(name, [op]).splitlines()
        body = [line for line in lines if not line.startswith(("(post", "; post"))]
        assert body[:len(head)] == head, (name, lines[:6])
        start = body.index(tool[0])
        assert body[start:start + 2] == tool[:2], (name, body[start:start + 4])
        assert tool[2] in body[start:start + 6], name  # coolant after the op's label
        assert lines[-len(tail):] == tail, (name, lines[-5:])
        # --no-header: no title, no post line; the setup stays
        bare = export(name, [op], "--no-header").splitlines()
        assert not any("Job" in line or "post " in line for line in bare[:3]), (name, bare[:4])
        assert head[-1] in bare
        # --no-comments: none at all
        quiet = export(name, [op], "--no-comments")
        assert ";" not in quiet and "(" not in quiet.replace("CYCLE93(", ""), name


def test_tool_controllers_in_the_list_and_changes_between_ops(shop):
    doc_, shaft, job, tc = shop
    import Path.Tool.Controller as PathToolController

    tc2 = PathToolController.Create("TC: second", toolNumber=7, assignViewProvider=False)
    job.Proxy.addToolController(tc2)
    tc2.HorizFeed = "60 mm/min"
    tc2.SpindleSpeed = 500
    doc_.recompute()
    a = groove(shop, "cylinder")
    b = groove(shop, "shoulder", tool_controller=tc2)
    text = export("linuxcnc", [tc, a, tc2, b])
    lines = text.splitlines()
    assert [line for line in lines if " M6 " in line] == ["T1 M6 G43", "T7 M6 G43"]
    # the same without the tool controllers in the list: the ops' own
    assert export("linuxcnc", [a, b]) == text
    # a tool controller equal to the one in force changes nothing
    assert export("linuxcnc", [tc, a, tc, a]).count("M6") == 1
    # the second op's feed is its own tool controller's
    feeds = {e[3] for e in read(text, "linuxcnc") if e[0] == "G1"}
    assert feeds == {FEED_MM_MIN, 60.0}


# ----------------------------------------------------------------------------- Siemens CYCLE93


KEYS = ["cylinder", "cone_up", "cone_down", "shoulder", "left_end", "bore"]


@pytest.mark.parametrize("key", KEYS)
def test_cycle93_calls_are_the_ops_calls(shop, key):
    op = groove(shop, key, flank_angle2=5, base_corner1=0.3, base_corner1_type="Radius", base_allowance=0.1,
                dwell=0.2)
    assert op_error(op) is None, op_error(op)
    cycles = op.Proxy.cycles(op)
    text = export("sinumerik", [op])
    events = read(text, "sinumerik")
    got = [e for e in events if e[0] == "CALL"]
    assert len(got) == len(cycles)
    for (call, _settings, start), (_kind, line) in zip(cycles, got):
        approx_call(Cycle93.parse(line), call)
        index = events.index(("CALL", line))
        # the start point is programmed, whole, right before the call, then the feed
        before = [e for e in events[:index] if e[0] in ("G0", "G1")][-1]
        assert before[0] == "G0" and before[1] == pytest.approx(start.x, abs=5e-4)
        assert before[2] == pytest.approx(start.z, abs=5e-4)
        lines = text.splitlines()
        at = lines.index(line)
        assert lines[at - 1] == "F120." and lines[at - 2].startswith("G0 X") and " Z" in lines[at - 2]
    # the engine's translator reads the program; its moves are the op's moves
    lc = translated(text, "sinumerik", op)
    assert_same_path(positions(read(lc, "linuxcnc")), positions(expected_events(op, "linuxcnc")), tol=2e-3)


def test_cycle93_several_grooves_and_faces(shop):
    doc_, shaft, job, tc = shop
    op = groove(shop, "cylinder", position=2, width=3.5, groove_count=3, pitch=5)
    text = export("sinumerik", [op])
    assert [Cycle93.parse(c).axsa for c in calls(text, "sinumerik")] == [28.0, 23.0, 18.0]
    lc = translated(text, "sinumerik", op)
    assert_same_path(positions(read(lc, "linuxcnc")), positions(expected_events(op, "linuxcnc")), tol=2e-3)


def test_cycle93_diameter_input_doubles_the_diameter_words(shop):
    op = groove(shop, "cylinder", base_allowance=0.1, flank_allowance=0.2)
    face = groove(shop, "shoulder", flank_allowance=0.2)
    text = export("sinumerik", [op, face], "--diameter-input")
    lon, fac = [Cycle93.parse(c) for c in calls(text, "sinumerik")]
    (c1, _s, _st), = op.Proxy.cycles(op)
    (c2, _s, _st), = face.Proxy.cycles(face)
    assert (lon.axfa, lon.depg, lon.fal1, lon.fal2) == (2 * c1.axfa, 2 * c1.depg, 2 * c1.fal1, c1.fal2)
    assert (fac.axfa, fac.depg, fac.fal1, fac.fal2) == (2 * c2.axfa, c2.depg, c2.fal1, 2 * c2.fal2)
    # read as diameters they are the same grooves
    diam = Settings(tool=GroovingTool(TOOL_W, TOOL_R), cycle93_diameter_input=True)
    assert lon.geometry(diam).region_world() == pytest.approx(c1.geometry(Settings(tool=diam.tool)).region_world())


# ----------------------------------------------------------------------------- pecking cycles


def expected_pecking(name, op, e=None):
    """The native call for a plain Groove op, worked out from its properties:
    longitudinal grooves plunge from VRT above the contour over the groove's
    start edge (the blade's minus corner at AXSA - tool width: TYP "right"),
    step toward -Z to AXSA - Width of the last groove; face grooves the same
    along X toward the axis."""
    cycles = [c for c, _s, _st in op.Proxy.cycles(op)]
    first, last = cycles[0], cycles[-1]
    vrt = op.Retract.Value or 1.0
    e = vrt if e is None else e
    longitudinal = first.typ % 10 in (5, 7)
    external = first.typ % 10 in (5, 6)
    s = 1.0 if external else -1.0
    width, depth, idep = op.Width.Value, op.Depth.Value, op.Infeed.Value
    single = abs(width - TOOL_W) < 1e-9
    # one call for a set of blade-wide grooves (spacing = the pitch, ending at
    # the last groove), else one per groove stepping 95 % of (3 - 2 x 0.2) = 2.47
    far_groove = last if single else first
    several = len(cycles) > 1 and single
    if longitudinal:
        start = (first.axfa + s * vrt, first.axsa - TOOL_W)
        bottom = first.axfa - s * depth
        far = far_groove.axsa - width if (several or not single) else None
        pitch = abs(cycles[1].axsa - first.axsa) if several else 2.47
    else:
        start = (first.axfa - TOOL_W, first.axsa + s * vrt)
        bottom = first.axsa - s * depth
        far = far_groove.axfa - width if (several or not single) else None
        pitch = abs(cycles[1].axfa - first.axfa) if several else 2.47
    w = {}
    if name == "ab9":
        cls = G77 if longitudinal else G76
        peck_word, pitch_word = ("I", "K") if longitudinal else ("K", "I")
        w = {peck_word: idep, "F": FEED_MM_MIN, "D": 0.0}
    elif name == "fanuc":
        cls = FanucG75 if longitudinal else FanucG74
        peck_word, pitch_word = ("P", "Q") if longitudinal else ("Q", "P")
        w = {peck_word: int(round(idep * 1000)), "F": FEED_MM_MIN, "e": e}
    else:
        cls = HaasG75 if longitudinal else HaasG74
        peck_word, pitch_word = ("I", "K") if longitudinal else ("K", "I")
        w = {peck_word: idep, "F": FEED_MM_MIN}
    if longitudinal:
        w["X"] = round(2 * bottom, 3)
        if far is not None:
            w["Z"] = round(far, 3)
    else:
        w["Z"] = round(bottom, 3)
        if far is not None:
            w["X"] = round(2 * far, 3)
    if far is not None:
        w[pitch_word] = int(round(pitch * 1000)) if name == "fanuc" else round(pitch, 3)
    return cls(**w), start


PLAIN = {  # name -> (groove key, extra keywords)
    "cylinder": ("cylinder", {}),
    "cylinder_blade_wide": ("cylinder", dict(width=3)),
    "cylinder_set": ("cylinder", dict(width=3, position=2, groove_count=3, pitch=5)),
    "cylinder_wide_set": ("cylinder", dict(width=4, position=1, groove_count=2, pitch=8)),
    "bore": ("bore", {}),
    "shoulder": ("shoulder", {}),
    "left_end": ("left_end", {}),
    "left_end_set": ("left_end", dict(width=3, position=1, groove_count=2, pitch=4)),
}


@pytest.mark.parametrize("name", PECKING)
@pytest.mark.parametrize("case", sorted(PLAIN))
def test_plain_grooves_are_native_pecking_calls(shop, name, case):
    key, extra = PLAIN[case]
    op = groove(shop, key, **extra)
    assert op_error(op) is None, op_error(op)
    text = export(name, [op])
    events = read(text, name)
    got = [e[1] for e in events if e[0] == "CALL"]
    count = len(op.Proxy.cycles(op))
    single = abs(op.Width.Value - TOOL_W) < 1e-9
    assert len(got) == (1 if single else count), text
    want, start = expected_pecking(name, op)
    cls = type(want)
    model = cls.parse(got[0])
    assert model == want, (got[0], want.emit())
    index = events.index(("CALL", got[0]))
    before = [e for e in events[:index] if e[0] == "G0"][-1]
    assert (before[1], before[2]) == (pytest.approx(start[0], abs=5e-4), pytest.approx(start[1], abs=5e-4))
    lines = text.splitlines()
    call_line = lines.index(got[0].split("\n")[0])
    assert re.match(r"^G0?0 X-?[\d.]+ Z-?[\d.]+$", lines[call_line - 1]), lines[call_line - 1]
    if name == "fanuc":
        assert lines[call_line] == "G%s R1." % model.NAME[1:]
    else:
        assert "retract e = 1. mm" in text
    # our own program reader accepts the program; its feed moves cut the groove's span
    lc = translated(text, name, op)
    feeds = [m for m in positions(read(lc, "linuxcnc")) if m[0] == "G1"]
    cycles = [c for c, _s, _st in op.Proxy.cycles(op)]
    longitudinal = cycles[0].typ % 10 in (5, 7)
    along = [m[2] if longitudinal else m[1] for m in feeds]
    plunge = [m[1] if longitudinal else m[2] for m in feeds]
    edge = [c.axsa if longitudinal else c.axfa for c in cycles]
    assert max(along) == pytest.approx(edge[0] - TOOL_W, abs=1e-3)
    assert min(along) == pytest.approx(edge[-1] - op.Width.Value, abs=1e-3)
    external = cycles[0].typ % 10 in (5, 6)
    top = cycles[0].axfa if longitudinal else cycles[0].axsa
    deepest = min(plunge) if external else max(plunge)
    assert deepest == pytest.approx(top - (1 if external else -1) * op.Depth.Value, abs=1e-3)


def test_retract_option_and_fanuc_first_block(shop):
    op = groove(shop, "cylinder", retract=0.5)
    assert "G75 R0.5\nG75 X36." in export("fanuc", [op])
    assert "G75 R0.2\nG75 X36." in export("fanuc", [op], "--retract 0.2")
    assert "retract e = 0.2 mm: setting 22" in export("haas", [op], "--retract 0.2")
    assert "retract e = 0.5 mm: AMP parameter" in export("ab9", [op])


@pytest.mark.parametrize("extra, why", [
    (dict(flank_angle1=5), "flank angles"),
    (dict(base_corner1=0.3, base_corner1_type="Radius"), "edge or base radii/chamfers"),
    (dict(edge_corner2=0.3, edge_corner2_type="Chamfer"), "edge or base radii/chamfers"),
    (dict(base_allowance=0.1), "finishing allowances"),
    (dict(dwell=0.5), "a dwell at the bottom"),
])
@pytest.mark.parametrize("name", ["fanuc", "haas", "ab9"])
def test_grooves_a_pecking_cycle_cannot_cut_are_expanded_with_the_reason(shop, name, extra, why):
    op = groove(shop, "cylinder", **extra)
    if name == "ab9" and "dwell" in extra:
        with pytest.raises(posts.PostError, match="^Groove_cylinder: Dwell: a dwell .*Allen-Bradley 9/Series"):
            export(name, [op])
        return
    text = export(name, [op])
    assert not calls(text, name)
    cycle = "G77" if name == "ab9" else "G75"
    assert "(expanded: %s cannot cut %s)" % (cycle, why) in text
    assert_same_path(positions(read(text, name)), positions(expected_events(op, name)))


def test_oblique_contours_are_expanded(shop):
    op = groove(shop, "cone_up")
    text = export("haas", [op])
    assert "(expanded: G75 cannot cut an oblique contour ANGC 21.801)" in text
    assert_same_path(positions(read(text, "haas")), positions(expected_events(op, "haas")))


# ----------------------------------------------------------------------------- expanded output


@pytest.mark.parametrize("name", NAMES)
def test_expand_cycles_writes_the_engines_moves(shop, name):
    doc_, shaft, job, tc = shop
    ops = [groove(shop, "cone_down", flank_angle1=8, edge_corner2=0.4, edge_corner2_type="Radius",
                  flank_allowance=0.1, dwell=0.0 if name == "ab9" else 0.4),
           groove(shop, "cylinder", position=2, groove_count=3, pitch=5),
           groove(shop, "bore", reference_corner="plus")]
    for op in ops:
        assert op_error(op) is None, op_error(op)
    for args, precision in (("--expand-cycles", None), ("--expand-cycles --precision 6", 6)):
        text = export(name, ops, args)
        assert not calls(text, name)
        want = []
        for op in ops:
            want += expected_events(op, name, precision)
        assert_same_path(positions(read(text, name)), positions(want))
        # every feed at the tool controller's HorizFeed in mm/min
        assert {e[3] for e in read(text, name) if e[0] == "G1"} == {FEED_MM_MIN}
    if name == "linuxcnc":
        assert export(name, ops) == export(name, ops, "--expand-cycles")


@pytest.mark.parametrize("name", ["sinumerik", "ab9", "linuxcnc"])
def test_x_mode_radius(shop, name):
    op = groove(shop, "cylinder", flank_angle1=5)
    text = export(name, [op], "--x-mode radius --expand-cycles")
    setup = {"sinumerik": "G18 G71 G90 G40 G94 DIAMOF", "ab9": "G18 G21 G90 G40 G94 G08",
             "linuxcnc": "G18 G8 G21 G90 G91.1 G40 G94"}[name]
    assert setup in text.splitlines()
    assert_same_path(positions(read(text, name, diameter=False)),
                     positions(expected_events(op, name, diameter=False)))
    if name == "ab9":
        assert "G18 G21 G90 G40 G94 G07" in export(name, [op], "--x-mode radius --g07-radius").splitlines()
        assert "G18 G21 G90 G40 G94 G08" in export(name, [op], "--g07-radius").splitlines()
        native = export(name, [groove(shop, "shoulder")], "--x-mode radius")
        assert "G76 X15.5 Z28. I2.47 K1. F120. D0." in native
    if name == "sinumerik":
        lc = translated(export(name, [op], "--x-mode radius"), "sinumerik", op)
        assert_same_path(positions(read(lc, "linuxcnc")), positions(expected_events(op, "linuxcnc")), tol=2e-3)


@pytest.mark.parametrize("name", NAMES)
def test_reference_corner_option_moves_the_words_not_the_blade(shop, name):
    minus = groove(shop, "cylinder", width=5, flank_angle1=3)
    plus = groove(shop, "cylinder", width=5, flank_angle1=3, reference_corner="plus")
    face_minus = groove(shop, "shoulder")
    face_plus = groove(shop, "shoulder", reference_corner="plus")
    quiet = "--no-comments --no-header"
    for a, b in ((minus, plus), (face_minus, face_plus)):
        assert export(name, [a], quiet + " --reference-corner plus") == export(name, [b], quiet)
        assert export(name, [b], quiet + " --reference-corner minus") == export(name, [a], quiet)
    if name == "linuxcnc":  # the words move by the tool width along the groove's axis
        shifted = positions(read(export(name, [minus], "--reference-corner plus"), name))
        assert_same_path(shifted, positions(expected_events(minus, name, shift=(0.0, TOOL_W))))


# ----------------------------------------------------------------------------- other ops, dressups


def turning_path(doc_, label="Turning", commands=None):
    obj = doc_.addObject("Path::Feature", label)
    obj.Path = Path.Path(commands or [
        C("(rough the end)"), C("G18"), C("G0", {"X": 22.0, "Z": 65.0}), C("G1", {"X": 10.0, "Z": 61.0, "F": 2.0}),
        C("G1", {"Z": 60.0}), C("G2", {"X": 12.0, "Z": 58.0, "I": 2.0, "K": 0.0}), C("G4", {"P": 0.5}),
        C("G0", {"X": 25.0, "Y": 0.0})])
    return obj


def test_other_paths_are_written_as_plain_moves(doc):
    obj = turning_path(doc)
    expect = {
        "linuxcnc": ["(Turning)", "(rough the end)", "G0 X44. Z65.", "G1 X20. Z61. F120.", "Z60.",
                     "G2 X24. Z58. I2. K0.", "G4 P0.5", "G0 X50."],
        "sinumerik": ["; Turning", "; rough the end", "G0 X44. Z65.", "G1 X20. Z61. F120.", "Z60.",
                      "G2 X24. Z58. CR=2.", "G4 F0.5", "G0 X50."],
        "fanuc": ["(Turning)", "(rough the end)", "G00 X44. Z65.", "G01 X20. Z61. F120.", "Z60.",
                  "G02 X24. Z58. I2. K0.", "G04 P500", "G00 X50."],
        "haas": ["(Turning)", "(rough the end)", "G00 X44. Z65.", "G01 X20. Z61. F120.", "Z60.",
                 "G02 X24. Z58. I2. K0.", "G04 P0.5", "G00 X50."],
    }
    for name, lines in expect.items():
        text = export(name, [obj], "--no-header")
        body = text.splitlines()
        start = body.index(lines[0])
        assert body[start:start + len(lines)] == lines, (name, body)
    # the 9/Series dwell word is not documented: refused, naming the object
    with pytest.raises(posts.PostError, match=r"^Turning: .*dwell"):
        export("ab9", [obj])
    # an arc over 180 degrees: negative CR
    big = turning_path(doc, "Big", [C("G18"), C("G0", {"X": 10.0, "Z": 10.0}),
                                     C("G3", {"X": 10.0, "Z": 6.0, "I": 0.5, "K": -2.0, "F": 1.0})])
    assert "G3 X20. Z6. CR=-2.062" in export("sinumerik", [big])
    assert "G3 X20. Z6. CR=2.062" in export("sinumerik", [turning_path(doc, "Small", [
        C("G18"), C("G0", {"X": 10.0, "Z": 10.0}), C("G3", {"X": 10.0, "Z": 6.0, "I": -0.5, "K": -2.0, "F": 1.0})])])


@pytest.mark.parametrize("commands, match", [
    ([C("G0", {"X": 5.0, "Y": 3.0, "Z": 10.0})], r"^Mill: G0 .*Y3\..*: a Y move"),
    ([C("G0", {"X": 5.0, "Z": 10.0}), C("G2", {"X": 7.0, "Z": 8.0, "I": 2.0, "K": 0.0, "F": 1.0})],
     r"^Mill: G2 .*an arc in the XY plane"),
    ([C("G18"), C("G0", {"X": 5.0, "Z": 10.0}), C("G2", {"X": 7.0, "Z": 8.0, "I": 2.0, "J": 1.0, "F": 1.0})],
     r"^Mill: G2 .*J1\.: an arc centre off the XZ plane"),
    ([C("G91"), C("G0", {"X": 5.0})], r"^Mill: G91.*incremental"),
    ([C("G81", {"X": 0.0, "Z": -5.0, "R": 2.0, "F": 1.0})], r"^Mill: G81 .*canned drilling cycle"),
    ([C("G41")], r"^Mill: G41.*nose radius compensation"),
    ([C("G1", {"X": 5.0, "Z": 1.0})], r"^Mill: feed move with no feed rate"),
    ([C("G0", {"X": 5.0, "A": 90.0})], r"^Mill: G0 .*axis A"),
])
def test_moves_a_lathe_cannot_make_are_refused_naming_the_op(doc, commands, match):
    obj = turning_path(doc, "Mill", commands)
    for name in NAMES:
        with pytest.raises(posts.PostError, match=match):
            export(name, [obj])


def make_dressup(doc_, op, extra):
    """A dressup as FreeCAD's look to a post: its own Path, the op in Base."""
    dressup = doc_.addObject("Path::FeaturePython", "Dressup")
    dressup.addProperty("App::PropertyLink", "Base", "Path")
    dressup.Base = op
    dressup.Path = Path.Path(list(op.Path.Commands) + extra)
    return dressup


def test_dressup_around_a_groove_op(shop):
    doc_, shaft, job, tc = shop
    op = groove(shop, "cylinder")
    op.CoolantMode = "Mist"
    dressup = make_dressup(doc_, op, [C("G0", {"X": 30.0, "Z": 70.0})])
    assert posts.groove_op_of(dressup) is op
    # native: the op's call, from its own properties; the tool and coolant are the op's
    text = export("sinumerik", [dressup])
    approx_call(Cycle93.parse(calls(text, "sinumerik")[0]), op.Proxy.cycles(op)[0][0])
    assert "T1 D1" in text and "M7" in text
    assert "the dressup's changes are not in them" in text
    # expanded: the dressup's Path (its extra move is there)
    expanded = export("sinumerik", [dressup], "--expand-cycles")
    assert not calls(expanded, "sinumerik")
    assert positions(read(expanded, "sinumerik"))[-1] == ("G0", 30.0, 70.0, None)
    assert positions(read(export("linuxcnc", [dressup]), "linuxcnc"))[-1] == ("G0", 30.0, 70.0, None)
    # an inactive op is skipped, also through its dressup
    op.Active = False
    assert "CYCLE93" not in export("sinumerik", [dressup])
    assert "CYCLE93" not in export("sinumerik", [op])


def test_a_job_in_the_list_posts_its_operations(shop):
    doc_, shaft, job, tc = shop
    op = groove(shop, "cylinder")
    assert export("linuxcnc", [job]) == export("linuxcnc", [op])


# ----------------------------------------------------------------------------- errors, files


def snapshot(folder):
    return sorted(os.listdir(folder))


@pytest.mark.parametrize("name", NAMES)
def test_an_invalid_groove_op_fails_naming_the_op_and_leaves_files_alone(shop, name, tmp_path):
    doc_, shaft, job, tc = shop
    good = groove(shop, "shoulder")
    op = groove(shop, "cylinder")
    op.Width = 2  # narrower than the 3 mm blade
    doc_.recompute()
    new = tmp_path / "new.nc"
    old = tmp_path / "old.nc"
    old.write_text("(an older program)\n")
    os.utime(old, (1_000_000_000, 1_000_000_000))
    before = snapshot(tmp_path)
    for target in (new, old):
        with pytest.raises(posts.PostError) as info:
            export(name, [good, op], filename=str(target))
        message = str(info.value)
        assert message.startswith("Groove_cylinder: Width: CYCLE93 WIDG=2: groove is narrower than the tool "
                                  "width 3 (alarm 61602)"), message
        assert info.value.op == "Groove_cylinder" and info.value.parameter == "Width"
    assert not new.exists()
    assert old.read_text() == "(an older program)\n" and old.stat().st_mtime == 1_000_000_000
    assert snapshot(tmp_path) == before  # no temporary file left behind
    # a Y move in another Path object: the same
    mill = turning_path(doc_, "Mill", [C("G0", {"X": 5.0, "Y": 3.0, "Z": 10.0})])
    with pytest.raises(posts.PostError, match=r"^Mill: .*Y3"):
        export(name, [good, mill], filename=str(old))
    assert old.read_text() == "(an older program)\n" and snapshot(tmp_path) == before


def test_other_invalid_op_properties_are_named(shop):
    doc_, shaft, job, tc = shop
    cases = [
        (dict(infeed=0), "Infeed: CYCLE93 IDEP"),
        (dict(flank_angle1=95), "FlankAngle1: CYCLE93 ANG1"),
        (dict(base_allowance=5), "BaseAllowance: CYCLE93 FAL1"),
        (dict(groove_count=2), "Pitch=0: must be greater than 0"),
        (dict(position=18), "past the face"),
    ]
    for values, text in cases:
        op = groove(shop, "cylinder", **values)
        for name in NAMES:
            with pytest.raises(posts.PostError) as info:
                export(name, [op])
            assert str(info.value).startswith(op.Label + ": ") and text in str(info.value), (name, str(info.value))
        doc_.removeObject(op.Name)
    op = groove(shop, "cylinder", surface_speed="100 m/min")  # constant surface speed without its limit
    assert "MaxSpindleSpeed=0" in (op_error(op) or "")
    with pytest.raises(posts.PostError, match="^%s: MaxSpindleSpeed=0: constant surface speed" % op.Label):
        export("fanuc", [op])


@pytest.mark.parametrize("name", NAMES)
def test_files_are_written_whole_and_replace_the_old_one(shop, name, tmp_path):
    op = groove(shop, "cylinder")
    target = tmp_path / "prog.nc"
    text = export(name, [op], filename=str(target))
    assert target.read_text() == text == export(name, [op])
    target.write_text("old")
    os.chmod(target, 0o640)
    assert export(name, [op], "--no-comments", filename=str(target)) == target.read_text()
    assert stat.S_IMODE(target.stat().st_mode) == 0o640
    assert snapshot(tmp_path) == ["prog.nc"]
    with pytest.raises(posts.PostError, match="cannot write"):
        export(name, [op], filename=str(tmp_path / "missing" / "prog.nc"))


@pytest.mark.parametrize("name", ["sinumerik", "fanuc"])
def test_files_the_posts_write_and_refuse(shop, name, tmp_path):
    # The engine's writer (tests/test_output.py): the file a link leads to, never
    # a pipe, a device or a write-protected file; one PostError for each refusal.
    op = groove(shop, "cylinder")
    (tmp_path / "jobs").mkdir()
    real = tmp_path / "jobs" / "prog.nc"
    real.write_text("old\n")
    link = tmp_path / "prog.nc"
    link.symlink_to(real)
    assert export(name, [op], filename=str(link)) == real.read_text() and link.is_symlink()
    fifo = tmp_path / "pipe.nc"
    os.mkfifo(fifo)
    with pytest.raises(posts.PostError) as info:
        export(name, [op], filename=str(fifo))
    assert str(info.value) == "cannot write %s: it is a named pipe (FIFO), not a regular file" % fifo
    device = tmp_path / "full.nc"
    device.symlink_to("/dev/full")
    with pytest.raises(posts.PostError, match="its link target /dev/full is a character device"):
        export(name, [op], filename=str(device))
    protected = tmp_path / "protected.nc"
    protected.write_text("keep me\n")
    os.chmod(protected, 0o444)
    with pytest.raises(posts.PostError, match=r"it is write-protected \(mode 0444\)"):
        export(name, [op], filename=str(protected))
    assert protected.read_text() == "keep me\n" and stat.S_ISFIFO(os.lstat(fifo).st_mode)
    assert snapshot(tmp_path) == ["full.nc", "jobs", "pipe.nc", "prog.nc", "protected.nc"]
    assert snapshot(tmp_path / "jobs") == ["prog.nc"]


@pytest.mark.parametrize("args, match", [
    ("--precision 9", "--precision 9: must be 0 to 6"),
    ("--bogus", "unrecognized arguments: --bogus"),
    ("--reference-corner middle", "invalid choice"),
    ("--precision", "expected one argument"),
    ("'--no-header", "cannot read the arguments"),
])
def test_bad_options_are_errors(shop, args, match):
    op = groove(shop, "cylinder")
    for name in NAMES:
        with pytest.raises(posts.PostError, match=match):
            export(name, [op], args)
    with pytest.raises(posts.PostError, match="--retract -1"):
        export("fanuc", [op], "--retract -1")
    with pytest.raises(posts.PostError, match="unrecognized arguments: --native-cycles"):
        export("linuxcnc", [op], "--native-cycles")


# ----------------------------------------------------------------------------- registration


def test_init_registered_the_posts_at_start_up():
    import Path.Preferences as Prefs

    # run_suite.py starts FreeCAD with the checkout as a Mod: its Init.py ran
    assert registration._wrapper_of(Prefs.searchPathsPost) is not None
    assert registration.is_registered()
    available = Prefs.allAvailablePostProcessors()
    for name in NAMES:
        assert name + "_lathe" in available
        assert name + "_lathe" in Prefs.allEnabledPostProcessors()


def test_registration_is_idempotent_and_reversible():
    import Path.Preferences as Prefs

    try:
        registration.register()
        registration.register()
        folders = [p for p in Prefs.searchPathsPost() if p and os.path.realpath(p) ==
                   os.path.realpath(registration.POSTS_DIR)]
        assert len(folders) == 1
        assert Prefs.allAvailablePostProcessors().count("fanuc_lathe") == 1
        registration.unregister()
        assert not registration.is_registered()
        assert "fanuc_lathe" not in Prefs.allAvailablePostProcessors()
        assert registration._wrapper_of(Prefs.searchPathsPost) is None  # FreeCAD's own function again
        registration.unregister()  # twice: nothing more to undo
    finally:
        registration.register()
    assert registration.is_registered()
    # FreeCAD's preferences are not touched
    assert registration.POSTS_DIR not in Prefs.preferences().GetString(Prefs.DefaultFilePath, "")
    macro = FreeCAD.ParamGet("User parameter:BaseApp/Preferences/Macro")
    assert registration.POSTS_DIR not in macro.GetString("MacroPath", "")


def test_registration_waits_for_the_cam_import():
    """Before Path.Preferences is imported, register() installs a finder that
    wraps the function as soon as the module is loaded (what Init.py does)."""
    import Path.Preferences as Prefs

    saved = sys.modules.pop("Path.Preferences")
    try:
        registration.register()
        assert registration._hooks()
        fresh = importlib.import_module("Path.Preferences")
        assert fresh is not Prefs
        assert not registration._hooks()  # the finder removed itself
        assert registration._wrapper_of(fresh.searchPathsPost) is not None
        assert registration.POSTS_DIR in fresh.searchPathsPost()
    finally:
        registration._remove_hooks()
        sys.modules["Path.Preferences"] = saved
        import Path as PathPackage

        PathPackage.Preferences = saved


def test_init_py_never_breaks_start_up(monkeypatch):
    source = open(os.path.join(ROOT, "Init.py"), encoding="utf-8").read()
    warnings = []
    monkeypatch.setattr(FreeCAD.Console, "PrintWarning", warnings.append, raising=False)
    broken = type(sys)("freecad_groove")  # no __file__: the registration cannot be found
    monkeypatch.setitem(sys.modules, "freecad_groove", broken)
    exec(compile(source, "Init.py", "exec"), {"__name__": "Init"})
    assert warnings and warnings[0].startswith("freecad-groove: the lathe posts are not in CAM's post list")


def test_the_jobs_post_list_and_freecads_post_runner(shop):
    doc_, shaft, job, tc = shop
    op = groove(shop, "cylinder")
    new_job = PathJob.Create("Job2", [shaft])
    for name in NAMES:
        assert name + "_lathe" in new_job.getEnumerationsOfProperty("PostProcessor")
    from Path.Post.Processor import PostProcessorFactory

    job.PostProcessorArgs = ""
    for name in NAMES:
        job.PostProcessor = name + "_lathe"
        processor = PostProcessorFactory.get_post_processor(job, name + "_lathe")
        sections = processor.export()
        assert len(sections) == 1
        _part, text = sections[0]
        # FreeCAD's list: the fixture (G54), the tool controller, the op
        assert "G54" in text and text.replace("G54\n", "", 1) == export(name, [tc, op])
        assert processor.tooltip == post(name).TOOLTIP
