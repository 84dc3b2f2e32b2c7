"""What the ops' make_* calls for scripts share (freecad_groove.make_groove,
make_cylinder_slot, make_plunge_grind; each in its op's api.py): keywords
from property names, the faces and parts given checked against the Job's
model before anything is made, nothing left behind when a call fails, and
the op's properties set from the keywords.

Each message starts with the call it is about ("make_groove(): ...").

FreeCAD layer: duck-typed FreeCAD objects, no import of FreeCAD.
"""

import contextlib
import math
import re
import sys
from typing import Iterator


def snake_case(name: str) -> str:
    """Property name -> keyword: "EdgeCorner1Type" -> "edge_corner1_type"."""
    return re.sub(r"(?<!^)(?=[A-Z])", "_", name).lower()


def _pairs(call: str, faces: object) -> list:
    """The (part, subs) pairs of the ``faces`` argument of ``call``."""
    if isinstance(faces, tuple) and len(faces) == 2 and not isinstance(faces[0], (tuple, list)):
        return [faces]
    if not isinstance(faces, (list, tuple)) or not faces:
        raise ValueError("%s(): faces=%r: give (part, \"Face3\"), (part, [\"Face3\", ...]) "
                         "or a list of those" % (call, faces))
    return list(faces)


def model_of(call: str, job: object, part: object) -> object:
    """The Job's model clone of ``part`` (``part`` itself when it is one);
    ValueError when ``part`` is no object of the Job's model."""
    if not (hasattr(part, "Shape") and hasattr(part, "Document") and hasattr(part, "Name")):
        raise ValueError("%s(): faces: %r is not a FreeCAD object with a shape" % (call, part))
    model = job.Proxy.resourceClone(job, part)
    if model is None and part in job.Model.Group:
        model = part
    if model is None:
        raise ValueError("%s(): %s is not in the model of the Job %s" % (call, part.Label, job.Label))
    return model


def picked_faces(call: str, job: object, faces: object) -> list:
    """[(model clone, [sub, ...])] from (obj, "Face3"), (obj, ["Face3", ...]) or a
    list of those, every face checked: ValueError before anything is made."""
    out = []
    for pair in _pairs(call, faces):
        if not isinstance(pair, (tuple, list)) or len(pair) != 2:
            raise ValueError("%s(): faces: %r is not a (part, \"FaceN\") pair" % (call, pair))
        part, subs = pair
        model = model_of(call, job, part)
        subs = [subs] if isinstance(subs, str) else list(subs or [])
        if not subs:
            raise ValueError("%s(): faces: no face named for %s" % (call, part.Label))
        for sub in subs:
            if not isinstance(sub, str) or not sub.startswith("Face"):
                raise ValueError("%s(): faces: %s.%s is not a face name (\"FaceN\")" % (call, part.Label, sub))
            try:
                model.Shape.getElement(sub)
            except Exception:
                raise ValueError("%s(): %s has no %s" % (call, part.Label, sub)) from None
        out.append((model, subs))
    return out


@contextlib.contextmanager
def nothing_left_behind(doc: object) -> Iterator[None]:
    """The objects made in ``doc`` inside the block are removed again (newest
    first) when it raises: a make_* call makes a complete op or nothing."""
    before = {o.Name for o in doc.Objects}
    try:
        yield
    except BaseException:
        new = [o.Name for o in doc.Objects if o.Name not in before]
        for name in reversed(new):  # removing a tool controller removes its tool bit too
            if doc.getObject(name) is not None:
                doc.removeObject(name)
        raise


def set_keyword_values(call: str, obj: object, keywords: dict, values: dict) -> None:
    """The op's properties from the keywords of the make_* ``call`` ({keyword: property} ``keywords``);
    ValueError naming the keyword whose value FreeCAD refuses."""
    for key, value in values.items():
        try:
            setattr(obj, keywords[key], value)
        except Exception as e:
            raise ValueError("%s(): %s=%r: not a value for %s (%s: %s)"
                             % (call, key, value, keywords[key], type(e).__name__, e)) from None
        if not finite(value) or not finite(getattr(obj, keywords[key])):
            raise ValueError("%s(): %s=%r: %s must be a finite number" % (call, key, value, keywords[key]))


def finite(value: object) -> bool:
    """False for a number (a Quantity's Value) that is NaN or infinite, or the largest double FreeCAD keeps in
    place of an infinite length; True for anything else (text, a link, a list)."""
    number = getattr(value, "Value", value)
    if isinstance(number, bool) or not isinstance(number, (int, float)):
        return True
    return math.isfinite(number) and abs(number) < sys.float_info.max
