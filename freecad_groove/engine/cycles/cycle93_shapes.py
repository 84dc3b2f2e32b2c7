"""CYCLE93: a groove's shape worked out once for every place a program cuts it.

A groove's geometry (``GrooveGeometry``) is built in its own frame (u across
from its start point AXFA/AXSA, v out of the material) from the other
parameters, the settings and the units alone: only its ``Frame`` puts it in
the world. So the grooves of one shape at other places share the shape's
geometry (``placed``: the same profiles, envelopes and corners, read only; the
call's parameters read and checked again, the frame moved to its AXFA/AXSA).
Their moves are planned afresh from the placed geometry (a plan depends on the
start point), their warnings are the shape's (``cycle93_reach`` keeps them).
tests/test_cycle93_shapes.py compares both with a groove worked out afresh.

A few shapes are kept (SHAPES), so memory stays flat however long the program.
"""

import copy
from collections import OrderedDict
from typing import TYPE_CHECKING, Any, Callable

from ..settings import Settings
from .cycle93_geometry import GrooveGeometry

if TYPE_CHECKING:
    from .cycle93 import Cycle93

__all__ = ["SHAPES", "forget_shapes", "geometry", "placed", "shape_key"]

SHAPES = 16  # shapes kept
_PLACE = ("axfa", "axsa")  # the call's parameters that only place the groove


class _Recent:
    """The last ``size`` values used, by key."""

    def __init__(self, size: int) -> None:
        self.size = size
        self.items: "OrderedDict[Any, Any]" = OrderedDict()

    def get(self, key: Any) -> Any:
        found = self.items.get(key)
        if found is not None:
            self.items.move_to_end(key)
        return found

    def put(self, key: Any, value: Any) -> None:
        self.items[key] = value
        if len(self.items) > self.size:
            self.items.popitem(last=False)


_GEOMETRIES = _Recent(SHAPES)


def shape_key(call: "Cycle93", settings: Settings, metric: bool) -> tuple:
    """What a groove's geometry in its own frame depends on: every parameter but AXFA and AXSA (as their repr:
    -0.0 is not 0.0), the settings and the units."""
    return repr(tuple(value for name, value in vars(call).items() if name not in _PLACE)), settings, metric


def geometry(call: "Cycle93", settings: Settings, metric: bool,
             build: Callable[..., GrooveGeometry] = GrooveGeometry) -> GrooveGeometry:
    """The GrooveGeometry of ``call``: built (``build``), or the one of its shape placed at its start point."""
    key = shape_key(call, settings, metric)
    shape = _GEOMETRIES.get(key)
    if shape is None:
        geo = build(call, settings, metric)
        _GEOMETRIES.put(key, geo)
        return geo
    return placed(shape, call)


def placed(shape: GrooveGeometry, call: "Cycle93") -> GrooveGeometry:
    """``shape`` at the start point of ``call``, a call of the same shape: the
    parameters read and checked as GrooveGeometry reads them (only AXFA and
    AXSA can fail where the shape did not), the frame moved there."""
    params = GrooveGeometry._read_parameters(call, shape.settings, shape.metric)
    geo = copy.copy(shape)
    geo.call, geo.params = call, params
    geo.frame = copy.copy(shape.frame)
    geo.frame.x0, geo.frame.z0 = params["AXFA"], params["AXSA"]
    return geo


def forget_shapes() -> None:
    """Keep no shape (the geometry cache's cache_clear: what is built next is built afresh)."""
    _GEOMETRIES.items.clear()
