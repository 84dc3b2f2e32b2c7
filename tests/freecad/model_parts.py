"""Modelled grooves: turned parts whose section carries the finished profile
of a known CYCLE93 call, built by script (Part revolve of the section), for
test_model_grooves.py and write_model_artifacts.py.

Needs FreeCAD (Part) but not pytest. The section is the call's profile
(engine: cycle93_recognize.profile_elements) between two pieces of its
contour line EXTENSION mm long, closed through the material: along the axis
for external longitudinal grooves, outside the bore for internal ones,
behind the face for face grooves.
"""

import math

import FreeCAD
import Part

from freecad_groove.engine.cycles.cycle93 import Cycle93
from freecad_groove.engine.cycles.cycle93_outline import Segment
from freecad_groove.engine.cycles.cycle93_recognize import profile_elements

V = FreeCAD.Vector
EXTENSION = 6.0  # mm of contour line on either side of the notch
BEHIND = 10.0  # mm of material behind the deepest point (bores, faces)

# name -> the modelled call (TYP 5..8 "right", as the op reads grooves; 15..18: chamfers measured as CHR)
CASES = {
    "rectangular": Cycle93(axfa=20, axsa=30, widg=4, depg=2, angc=0, ang1=0, ang2=0, rco1=0, rco2=0, rci1=0, rci2=0,
                           typ=5),
    "angled_radii": Cycle93(axfa=20, axsa=30, widg=5, depg=2.5, angc=0, ang1=10, ang2=15, rco1=0.3, rco2=0,
                            rci1=0.5, rci2=0.5, typ=5),
    "chamfers": Cycle93(axfa=20, axsa=30, widg=4, depg=2, angc=0, ang1=0, ang2=0, rco1=-0.5, rco2=-0.5, rci1=-0.3,
                        rci2=0, typ=5),
    "chamfers_chr": Cycle93(axfa=20, axsa=30, widg=4, depg=2, angc=0, ang1=5, ang2=0, rco1=-0.4, rco2=-0.4, rci1=0,
                            rci2=-0.2, typ=15),
    "oblique_cone": Cycle93(axfa=20, axsa=30, widg=4, depg=2, angc=12, ang1=5, ang2=0, rco1=0, rco2=0.3, rci1=0,
                            rci2=0.4, typ=5),
    "face_external": Cycle93(axfa=30, axsa=0, widg=5, depg=3, angc=90, ang1=0, ang2=8, rco1=0, rco2=0, rci1=0.5,
                             rci2=0, typ=6),
    "face_internal": Cycle93(axfa=30, axsa=0, widg=4, depg=2, angc=90, ang1=0, ang2=0, rco1=-0.3, rco2=0, rci1=0,
                             rci2=0, typ=8),
    "face_on_steep_cone": Cycle93(axfa=30, axsa=0, widg=4, depg=2, angc=70, ang1=5, ang2=0, rco1=0, rco2=0,
                                  rci1=0.3, rci2=0, typ=6),
    "bore": Cycle93(axfa=15, axsa=30, widg=4, depg=2, angc=0, ang1=0, ang2=0, rco1=-0.3, rco2=-0.3, rci1=0,
                    rci2=0.2, typ=7),
    "cut_off": Cycle93(axfa=20, axsa=30, widg=3, depg=8, angc=0, ang1=0, ang2=0, rco1=0, rco2=0, rci1=0, rci2=0,
                       typ=5),
}


def _edge(element):
    r0, z0 = element.start[1], element.start[0]
    r1, z1 = element.end[1], element.end[0]
    if isinstance(element, Segment):
        return Part.LineSegment(V(r0, 0, z0), V(r1, 0, z1)).toShape()
    a0 = math.atan2(element.start[1] - element.center[1], element.start[0] - element.center[0])
    mid = a0 + element.sweep() / 2
    zm, rm = element.center[0] + element.radius * math.cos(mid), element.center[1] + element.radius * math.sin(mid)
    return Part.Arc(V(r0, 0, z0), V(rm, 0, zm), V(r1, 0, z1)).toShape()


def section(call):
    """The closed section [(z, radius) elements] of a part carrying ``call``'s groove."""
    notch = profile_elements(call)
    first, last = notch[0].start, notch[-1].end
    d = (last[0] - first[0], last[1] - first[1])
    n = math.hypot(*d)
    d = (d[0] / n, d[1] / n)
    a = (first[0] - EXTENSION * d[0], first[1] - EXTENSION * d[1])
    b = (last[0] + EXTENSION * d[0], last[1] + EXTENSION * d[1])
    longitudinal, external, _left, _chr = call.kind()
    if longitudinal:
        far = 0.0 if external else max(p[1] for e in notch for p in (e.start, e.end)) + BEHIND
        c, dd = (b[0], far), (a[0], far)
    else:
        zs = [p[0] for e in notch for p in (e.start, e.end)]
        far = min(zs) - BEHIND if external else max(zs) + BEHIND
        c, dd = (far, b[1]), (far, a[1])
    return [Segment(a, first), *notch, Segment(last, b), Segment(b, c), Segment(c, dd), Segment(dd, a)]


def part_shape(call):
    """The solid of revolution about Z of ``section(call)``."""
    wire = Part.Wire([_edge(e) for e in section(call) if math.dist(e.start, e.end) > 1e-9])
    return Part.Face(wire).revolve(V(0, 0, 0), V(0, 0, 1), 360)


def undercut_shape():
    """A shaft R20 with a dovetail groove: 4 mm at the top, 6 mm at its 2 mm deep base."""
    pts = [(0, 0), (20, 0), (20, 20), (18, 19), (18, 25), (20, 24), (20, 40), (0, 40), (0, 0)]
    return Part.Face(Part.makePolygon([V(r, 0, z) for r, z in pts])).revolve(V(0, 0, 0), V(0, 0, 1), 360)
