"""The stepped shaft and its Job, built by script: shared by the FreeCAD-level
tests (test_groove_op.py, test_posts.py) and benchmarks/bench_freecad.py.

Needs FreeCAD (Part, Path) but not pytest. The shaft turns about Z (a revolved
half section) and carries a face of every kind: a cylinder, a cone growing
toward +Z, a cone shrinking toward +Z, a shoulder face looking +Z, the left
end face looking -Z and a blind bore open toward +Z.
"""

import FreeCAD
import Part

from freecad_groove.freecad import faces as faces_mod

V = FreeCAD.Vector

# (radius, z) of the shaft's half section, revolved about Z.
PROFILE = [(0, 0), (16, 0), (20, 10), (20, 30), (14, 30), (14, 50), (10, 60), (6, 60), (6, 25), (0, 25), (0, 0)]
FEED_MM_MIN = 120.0


def shaft_shape(profile=PROFILE):
    """The solid of revolution of ``profile`` [(radius, z), ...] (closed) about Z."""
    wire = Part.makePolygon([V(r, 0, z) for r, z in profile])
    return Part.Face(wire).revolve(V(0, 0, 0), V(0, 0, 1), 360)


# name -> predicate on the analysed face (of PROFILE's shaft)
FACES = {
    "cylinder": lambda f: f.surface == "cylinder" and f.external and abs(f.r_max - 20) < 1e-9,
    "cone_up": lambda f: f.surface == "cone" and abs(f.z_min) < 1e-9,
    "cone_down": lambda f: f.surface == "cone" and abs(f.z_max - 60) < 1e-9,
    "shoulder": lambda f: f.surface == "plane" and abs(f.z_min - 30) < 1e-9,
    "left_end": lambda f: f.surface == "plane" and abs(f.z_min) < 1e-9,
    "bore": lambda f: f.surface == "cylinder" and not f.external,
}


def face_name(shape, key, faces=FACES):
    """The name ("FaceN") of the one face of ``shape`` that ``faces[key]`` accepts."""
    hits = []
    for i, face in enumerate(shape.Faces):
        try:
            gf = faces_mod.analyse_face(face, "Face%d" % (i + 1))
        except ValueError:
            continue
        if faces[key](gf):
            hits.append("Face%d" % (i + 1))
    assert len(hits) == 1, (key, hits)
    return hits[0]


def make_shop(doc, shape=None, feed_mm_min=FEED_MM_MIN):
    """(doc, shaft, job, tc): a Part::Feature "Shaft" (``shape``, default the
    stepped shaft) in a new Job, whose first tool controller feeds at
    ``feed_mm_min``."""
    import Path.Main.Job as PathJob

    shaft = doc.addObject("Part::Feature", "Shaft")
    shaft.Shape = shaft_shape() if shape is None else shape
    doc.recompute()
    job = PathJob.Create("Job", [shaft])
    tc = job.Tools.Group[0]
    tc.HorizFeed = "%g mm/min" % feed_mm_min
    tc.VertFeed = "%g mm/min" % feed_mm_min
    doc.recompute()
    return doc, shaft, job, tc
