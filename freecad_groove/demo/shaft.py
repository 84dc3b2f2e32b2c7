"""The demo's lathe part: a turned shaft, its Groove Job (tool controller, five Groove ops).

The part ("Shaft", a ``Part::Revolution`` of the half section ``PROFILE``
about the Z axis, in mm)::

    Z  0..12   cylinder R15   the bar the part is cut off from
    Z 12       face looking -Z, R15..25
    Z 12..40   cylinder R25
    Z 40       shoulder looking +Z, R18..25
    Z 40..65   cylinder R18
    Z 65..75   cone R18 -> R14 (shrinking toward +Z, ANGC 158.2 degrees)
    Z 50..75   bore R8, open at the +Z end

The Job's stock is the part itself (CAM's stock from an existing solid: a
clone of the Shaft): the demo only grooves, on a part already turned to its
contour, so its own turning check (``verify_job``) runs clean on it.

The Job holds one tool controller, "TC: Grooving blade 3 mm" (tool 3,
800 rpm forward, 40 mm/min; its tool bit carries the blade's Width 3 mm and
CornerRadius 0.2 mm, which the Groove ops read, and its free reach
CuttingEdgeHeight 16 mm: a parting blade deep enough for the cut-off, which
the ops check every groove's Depth against), and five Groove ops, all
with flood coolant, in machining order (``OPS``):

* ``External grooves``: three plain grooves 3 wide, 2.5 deep on the R25
  cylinder, 7 apart (GrooveCount 3, Pitch 7);
* ``Face groove``: a plain groove 3 wide, 2 deep in the shoulder at Z40;
* ``Bore groove``: an internal groove 4 wide, 1.5 deep in the bore,
  entered from its open end;
* ``Cone groove``: an oblique groove on the cone with 15 degree flanks,
  0.3 mm edge radii and 0.1 mm finishing allowances;
* ``Cut-off``: a groove as wide as the blade, 15 deep on the R15 cylinder, so
  the blade's front edge ends on the axis (X0) and parts the part off the
  bar. This is the closest the Groove op comes to a cut-off: it refuses a
  groove whose finished profile passes the axis (a real parting tool is fed
  a little past centre), and it has no parting-specific moves (no slower
  feed near the centre, no spindle speed clamp, no bar catcher M code).
"""

# (radius, z) of the part's half section, revolved about Z.
PROFILE = [(0, 0), (15, 0), (15, 12), (25, 12), (25, 40), (18, 40), (18, 65), (14, 75), (8, 75), (8, 50), (0, 50),
           (0, 0)]

DOCUMENT = "demo_part"
TOOL_NUMBER = 3
TOOL_WIDTH = 3.0
TOOL_CORNER_RADIUS = 0.2
TOOL_REACH = 16.0  # the blade's free reach (CuttingEdgeHeight): deeper than the 15 mm cut-off
SPINDLE_RPM = 800
FEED_MM_MIN = 40.0

# The faces, told apart by what faces.analyse_face makes of them.
FACES = {
    "bar": lambda f: f.surface == "cylinder" and f.external and abs(f.r_max - 15) < 1e-6,
    "cylinder": lambda f: f.surface == "cylinder" and f.external and abs(f.r_max - 25) < 1e-6,
    "shoulder": lambda f: f.surface == "plane" and f.external and abs(f.z_min - 40) < 1e-6,
    "cone": lambda f: f.surface == "cone",
    "bore": lambda f: f.surface == "cylinder" and not f.external,
    "neck": lambda f: f.surface == "cylinder" and f.external and abs(f.r_max - 18) < 1e-6,  # the Cylinder slot's
}

# (op label, face key, make_groove keywords), in machining order.
OPS = [
    ("External grooves", "cylinder", dict(position=6, width=3, depth=2.5, infeed=1, groove_count=3, pitch=7)),
    ("Face groove", "shoulder", dict(position=2, width=3, depth=2, infeed=0.8)),
    ("Bore groove", "bore", dict(position=8, width=4, depth=1.5, infeed=0.75)),
    ("Cone groove", "cone", dict(position=3, width=4, depth=1.5, infeed=0.75, flank_angle1=15, flank_angle2=15,
                                 edge_corner1=0.3, edge_corner1_type="Radius", edge_corner2=0.3,
                                 edge_corner2_type="Radius", base_allowance=0.1, flank_allowance=0.1)),
    ("Cut-off", "bar", dict(position=4, width=3, depth=15, infeed=2)),
]

# -- the part and the Job -----------------------------------------------------------------


def make_part(doc):
    """The part: a Part::Revolution of the PROFILE wire about Z (returns it, recomputed)."""
    import FreeCAD
    import Part

    section = doc.addObject("Part::Feature", "HalfSection")
    section.Shape = Part.makePolygon([FreeCAD.Vector(r, 0, z) for r, z in PROFILE])
    shaft = doc.addObject("Part::Revolution", "Shaft")
    shaft.Source = section
    shaft.Base = FreeCAD.Vector(0, 0, 0)
    shaft.Axis = FreeCAD.Vector(0, 0, 1)
    shaft.Angle = 360.0
    shaft.Solid = True
    doc.recompute()
    if not shaft.isValid() or not shaft.Shape.Solids:
        raise RuntimeError("the revolved part is not a solid: %s" % shaft.getStatusString())
    return shaft


def face_names(shape):
    """{face key: "FaceN"} for every key of FACES (exactly one face each)."""
    from ..freecad.faces import analyse_face

    found = {key: [] for key in FACES}
    for i, face in enumerate(shape.Faces):
        name = "Face%d" % (i + 1)
        try:
            gf = analyse_face(face, name)
        except ValueError:
            continue
        for key, test in FACES.items():
            if test(gf):
                found[key].append(name)
    for key, names in found.items():
        if len(names) != 1:
            raise RuntimeError("the part should have one %s face, found %s" % (key, names or "none"))
    return {key: names[0] for key, names in found.items()}


def _remove_tree(doc, obj):
    """Remove ``obj`` and what it alone uses (a tool bit and its shape body)."""
    tree = [obj] + list(obj.OutListRecursive)
    names = {o.Name for o in tree}
    doomed = [o.Name for o in tree if all(i.Name in names for i in o.InList)]
    if obj.Name not in doomed:
        return
    for name in doomed:
        if doc.getObject(name) is not None:
            doc.removeObject(name)


def turned_stock(doc, job, part):
    """The Job's stock made the part itself, as CAM's "existing solid" stock makes it (a clone of ``part``):
    what the demo's grooving ops start from."""
    import Path.Main.Job as PathJob
    import Path.Main.Stock as PathStock

    old = job.Stock
    stock = PathJob.createResourceClone(job, part, "Stock", "Stock")
    PathStock.SetupStockObject(stock, PathStock.StockType.Unknown)
    stock.Proxy.execute(stock)
    job.Stock = stock
    if old is not None:
        doc.removeObject(old.Name)


def make_job(doc, part):
    """A CAM Job for ``part`` with the part as its stock (turned_stock) and one tool controller for a 3 mm
    grooving blade (replacing the default one the Job makes): (job, tool controller)."""
    import Path.Main.Job as PathJob
    import Path.Tool.Controller as PathToolController

    job = PathJob.Create("Job", [part])
    job.Label = "Groove Job"
    turned_stock(doc, job, part)
    default = list(job.Tools.Group)
    tc = PathToolController.Create("TC: Grooving blade 3 mm", toolNumber=TOOL_NUMBER, assignViewProvider=False)
    job.Proxy.addToolController(tc)
    for old in default:
        bit = getattr(old, "Tool", None)
        job.Tools.removeObject(old)
        doc.removeObject(old.Name)
        if bit is not None and not bit.InList:
            _remove_tree(doc, bit)
    bit = tc.Tool
    bit.Label = "Grooving blade 3 mm"
    # The Groove op reads the blade's size from these tool bit properties.
    bit.addProperty("App::PropertyLength", "Width", "Grooving blade", "Width of the blade's cutting edge")
    bit.addProperty("App::PropertyLength", "CornerRadius", "Grooving blade", "Radius of the blade's front corners")
    bit.Width = TOOL_WIDTH
    bit.CornerRadius = TOOL_CORNER_RADIUS
    if "CuttingEdgeHeight" not in bit.PropertiesList:
        bit.addProperty("App::PropertyLength", "CuttingEdgeHeight", "Grooving blade", "Cutting depth (free reach)")
    bit.CuttingEdgeHeight = TOOL_REACH
    tc.SpindleSpeed = SPINDLE_RPM
    tc.SpindleDir = "Forward"
    tc.HorizFeed = "%g mm/min" % FEED_MM_MIN
    tc.VertFeed = "%g mm/min" % FEED_MM_MIN
    tc.HorizRapid = "5000 mm/min"
    tc.VertRapid = "5000 mm/min"
    # The Job's own Post button then offers our lathe post (when it is registered).
    try:
        choices = job.getEnumerationsOfProperty("PostProcessor") or []
    except Exception:
        choices = []
    if "sinumerik_lathe" in choices:
        job.PostProcessor = "sinumerik_lathe"
    doc.recompute()
    return job, tc


def make_ops(doc, job, part, tc):
    """The Groove ops of OPS in ``job``; each must recompute without error."""
    from ..freecad.addon_op import op_error
    from ..ops.groove.api import make_groove

    names = face_names(part.Shape)
    ops = []
    for label, key, values in OPS:
        op = make_groove(job, (part, names[key]), name="Groove", tool_controller=tc, recompute=False,
                         coolant_mode="Flood", **values)
        op.Label = label
        ops.append(op)
    doc.recompute()
    bad = ["%s: %s" % (op.Label, op_error(op)) for op in ops if op_error(op)]
    if bad:
        raise RuntimeError("Groove op(s) failed to recompute: " + "; ".join(bad))
    return ops
