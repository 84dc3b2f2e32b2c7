"""Grooves read from the modelled part: the turned section and its notches.

The part turns about Z. Its section by a half plane through the Z axis is
the same at every angle; it is taken at HALF_PLANE_ANGLE off the XZ plane,
where a revolved solid has its seams. Each face's section gives the
outline's elements (lines and arcs in the (z, radius) half plane), so each
element knows the face it comes from; the elements chained from the picked
face's make the closed outline (closed along the axis where a solid bar's
section meets it). The engine's recognizer
(``engine/cycles/cycle93_recognize``) reads the notch of the picked face as
a CYCLE93 call; here it becomes the op's values and the face it is cut into:
the contour line itself, from the end of its piece before the notch to the
end of its piece after it (the model has no face spanning the groove any
more).

Only Part is needed (no Path, no GUI).
"""

import math
from dataclasses import dataclass
from typing import Dict, List, Tuple

import FreeCAD
import Part

from ...engine.cycles.cycle93_outline import ArcSegment, Element, NotchError, Segment
from ...engine.cycles.cycle93_recognize import RecognisedGroove, recognize
from ...freecad.faces import FACE, LONGITUDINAL, GrooveFace

HALF_PLANE_ANGLE = 0.5  # radians off the XZ plane: off the seams of revolved faces
CHAIN_TOLERANCE = 1e-5  # mm: section ends closer than this are one point
# The op properties a modelled groove sets, each corner with its type.
MODEL_VALUES = ("Position", "Width", "Depth", "FlankAngle1", "FlankAngle2", "EdgeCorner1", "EdgeCorner1Type",
                "EdgeCorner2", "EdgeCorner2Type", "BaseCorner1", "BaseCorner1Type", "BaseCorner2", "BaseCorner2Type")
CORNER_WORDS = {"EdgeCorner1": "rco1", "EdgeCorner2": "rco2", "BaseCorner1": "rci1", "BaseCorner2": "rci2"}


@dataclass(frozen=True)
class ModelGroove:
    """A groove read from the model.

    face        the GrooveFace it is cut into: the notch's contour line
    values      {op property: value} (mm, degrees, corner types) for MODEL_VALUES
    recognised  the recognizer's result (the call, the contour line, the notch)
    """

    face: GrooveFace
    values: Dict[str, object]
    recognised: RecognisedGroove


def _half_plane(shape: object) -> object:
    box = shape.BoundBox
    reach = math.hypot(max(abs(box.XMin), abs(box.XMax)), max(abs(box.YMin), abs(box.YMax))) + 1.0
    c, s = math.cos(HALF_PLANE_ANGLE), math.sin(HALF_PLANE_ANGLE)
    v = FreeCAD.Vector
    pts = [v(0, 0, box.ZMin - 1), v(reach * c, reach * s, box.ZMin - 1), v(reach * c, reach * s, box.ZMax + 1),
           v(0, 0, box.ZMax + 1)]
    return Part.Face(Part.makePolygon(pts + [pts[0]]))


def _zr(p: object) -> Tuple[float, float]:
    return p.z, p.x * math.cos(HALF_PLANE_ANGLE) + p.y * math.sin(HALF_PLANE_ANGLE)


def _element(edge: object, name: str) -> Element:
    """The section edge as a Segment or an ArcSegment in (z, radius)."""
    first, last = edge.FirstParameter, edge.LastParameter
    start, end = _zr(edge.valueAt(first)), _zr(edge.valueAt(last))
    curve = edge.Curve
    if isinstance(curve, (Part.Line, Part.LineSegment)):
        return Segment(start, end)
    if isinstance(curve, Part.Circle):
        center, mid = _zr(curve.Center), _zr(edge.valueAt(0.5 * (first + last)))
        ccw = (start[0] - center[0]) * (mid[1] - center[1]) - (start[1] - center[1]) * (mid[0] - center[0]) > 0
        return ArcSegment(start, end, center, ccw)
    raise NotchError("%s: its section is a %s, not a line or a circular arc" % (name, type(curve).__name__))


def section_elements(shape: object, label: str) -> List[Tuple[Element, str]]:
    """[(element, "FaceN")] of every face's section by the half plane."""
    plane = _half_plane(shape)
    out = []
    for i, face in enumerate(shape.Faces):
        sub = "Face%d" % (i + 1)
        for edge in face.section(plane).Edges:
            if edge.Length > CHAIN_TOLERANCE:
                out.append((_element(edge, "%s.%s" % (label, sub)), sub))
    return out


def _extend(loop: list, left: list) -> None:
    """Add to ``loop`` the pieces of ``left`` that continue from its end, while there are any."""
    while math.dist(loop[-1][0].end, loop[0][0].start) > CHAIN_TOLERANCE:
        end = loop[-1][0].end
        for k, (element, _sub) in enumerate(left):
            if math.dist(element.start, end) <= CHAIN_TOLERANCE:
                loop.append(left.pop(k))
                break
            if math.dist(element.end, end) <= CHAIN_TOLERANCE:
                loop.append((element.reversed(), left.pop(k)[1]))
                break
        else:
            return


def _chain(pieces: List[Tuple[Element, str]], first: int) -> List[Tuple[Element, str]]:
    """The loop of pieces through ``pieces[first]`` (first in it), each
    ending where the next starts; closed along the axis when a solid's
    section meets it."""
    left = list(pieces)
    loop = [left.pop(first)]
    _extend(loop, left)
    end, start = loop[-1][0].end, loop[0][0].start
    if math.dist(end, start) <= CHAIN_TOLERANCE:
        return loop
    back = [(loop[0][0].reversed(), loop[0][1])]  # the other way from the picked piece
    _extend(back, left)
    loop = [(e.reversed(), sub) for e, sub in reversed(back[1:])] + loop
    end, start = loop[-1][0].end, loop[0][0].start
    if abs(end[1]) <= CHAIN_TOLERANCE and abs(start[1]) <= CHAIN_TOLERANCE:
        loop.append((Segment(end, start), ""))  # along the axis: no face of the part
    else:
        raise NotchError("the part's section is not closed: it stops at Z%.4f X%.4f and Z%.4f X%.4f"
                         % (end + start))
    picked = len(back) - 1
    return loop[picked:] + loop[:picked]


def read_model_groove(shape: object, sub: str, label: str, chr_chamfers: bool = False) -> ModelGroove:
    """The groove the face ``sub`` of ``shape`` belongs to; NotchError
    ("Label.FaceN: ...") saying what does not fit."""
    name = "%s.%s" % (label, sub)
    try:
        pieces = section_elements(shape, label)
        first = next((k for k, (_e, s) in enumerate(pieces) if s == sub), None)
        if first is None:
            raise NotchError("not cut by a half plane through the Z axis: no face of a part turned about Z")
        loop = _chain(pieces, first)
        recognised = recognize([e for e, _s in loop], 0, right=True, chr_chamfers=chr_chamfers)
    except NotchError as e:
        raise NotchError("%s: %s" % (name, e)) from None
    face = contour_face("%s (modelled groove)" % name, recognised)
    return ModelGroove(face, model_values(face, recognised), recognised)


def contour_face(name: str, recognised: RecognisedGroove) -> GrooveFace:
    """The GrooveFace of the notch's contour line (its start: the +Z end for
    longitudinal grooves, the outer end for face grooves, as faces.py)."""
    call = recognised.call
    longitudinal, external, _left, _chr = call.kind()
    ends = [(r, z) for z, r in (recognised.contour_start, recognised.contour_end)]
    (ra, za), (rb, zb) = ends
    if longitudinal:
        start, end = sorted(ends, key=lambda p: -p[1])
    else:
        start, end = sorted(ends, key=lambda p: -p[0])
    surface = "cylinder" if call.angc == 0 else "plane" if call.angc == 90 else "cone"
    return GrooveFace(name, surface, LONGITUDINAL if longitudinal else FACE, external, call.angc,
                      min(ra, rb), max(ra, rb), min(za, zb), max(za, zb), start, end)


def model_values(face: GrooveFace, recognised: RecognisedGroove) -> Dict[str, object]:
    """{op property: value} of the recognised call on ``face``."""
    call = recognised.call
    position = face.start[1] - call.axsa if face.longitudinal else face.start[0] - call.axfa
    values: Dict[str, object] = {"Position": round(position, 6) + 0.0, "Width": call.widg, "Depth": call.depg,
                                 "FlankAngle1": call.ang1, "FlankAngle2": call.ang2}
    for name, word in CORNER_WORDS.items():
        size = getattr(call, word)
        values[name] = abs(size)
        values[name + "Type"] = "Radius" if size > 0 else "Chamfer" if size < 0 else "None"
    return values


def read_picked_groove(picked: List[Tuple[object, str, str]], chr_chamfers: bool = False) -> ModelGroove:
    """The one modelled groove the picked faces [(shape, "FaceN", label)]
    belong to; ValueError when there is none or they belong to several."""
    found = [read_model_groove(shape, sub, label, chr_chamfers) for shape, sub, label in picked]
    if not found:
        raise ValueError("ModelGroove: pick a face of the modelled groove")
    if any(m.recognised.call != found[0].recognised.call for m in found[1:]):
        raise ValueError("ModelGroove: the picked faces belong to different grooves; an op with ModelGroove "
                         "cuts one (make an op for each)")
    return found[0]


def not_overridden(values: Dict[str, object], overrides: List[str]) -> Dict[str, object]:
    """The model ``values`` less the ``overrides`` (a corner's size and type go together)."""
    out = {}
    for name, value in values.items():
        corner = name[:-4] if name.endswith("Type") else name
        if not {name, corner, corner + "Type"} & set(overrides):
            out[name] = value
    return out


MODEL_HINT = 'It is a face of a modelled groove: tick "Groove from the model" (ModelGroove) to cut that groove'


def with_model_hint(message: str, shape: object, sub: str) -> str:
    """A face error ``message`` for face ``sub`` of ``shape``, with MODEL_HINT
    when the face belongs to a groove in the model (a corner radius is a torus,
    which no groove typed in by its values goes on)."""
    try:
        read_model_groove(shape, sub, sub)
    except ValueError:
        return message
    return "%s. %s" % (message, MODEL_HINT)
