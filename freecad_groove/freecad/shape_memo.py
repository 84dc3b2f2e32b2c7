"""Values computed from a Part shape, kept while that shape is the same one.

A recompute of a Groove op reads the model's and the stock's largest radius
(ops/groove/links.py) and, for the plans kept in the saved document, a digest
of their BREP text (ops/groove/cache.py): about 1 ms each, on every recompute
and every preview, for shapes that rarely change. ShapeMemo keeps each value
with the shape it was computed from and gives it again for a shape that is the
same one: ``isEqual`` (the same OpenCASCADE TShape, the same Location and
orientation). FreeCAD never edits a document object's shape in place: a
changed model, a new Placement or a recompute makes a new TShape or Location,
so a changed shape is never taken for the old one. The shape is kept (a
wrapper of its own, which a caller moving its wrapper does not move), so its
TShape stays alive and no new shape can be made at its address.

FreeCAD layer: Part only.
"""

from typing import Callable, Generic, TypeVar

import Part

Value = TypeVar("Value")


class ShapeMemo(Generic[Value]):
    """``compute(shape)`` memoized per shape (the newest ``size`` shapes)."""

    def __init__(self, compute: Callable[[object], Value], size: int = 16):
        self._compute = compute
        self._size = size
        self._entries: dict = {}  # shape.hashCode() -> [(kept shape, value)], in insertion order
        self.computed = 0  # how many times compute ran (the tests count it)

    def __call__(self, shape: object) -> Value:
        key = shape.hashCode()
        for kept, value in self._entries.get(key, ()):
            if kept.isEqual(shape):
                return value
        value = self._compute(shape)
        self.computed += 1
        if sum(len(entries) for entries in self._entries.values()) >= self._size:
            del self._entries[next(iter(self._entries))]  # the oldest hash
        kept = Part.Shape(shape)  # a wrapper of its own: same TShape and Location
        if kept.isEqual(shape):
            self._entries.setdefault(key, []).append((kept, value))
        return value

    def clear(self) -> None:
        self._entries.clear()
