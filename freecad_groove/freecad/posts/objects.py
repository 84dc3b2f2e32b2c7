"""What a post recognises among the FreeCAD objects it is given: Jobs, tool
controllers, Groove ops (also inside dressups), the ops' properties and labels.

The objects are recognised by what they hold (duck typing), as FreeCAD's own
posts do: a post runs on whatever list the Job or a script hands it.
"""

from typing import Any, Iterable, Iterator, Optional


def op_chain(obj: Any) -> Iterator[Any]:
    """``obj``, then the op it wraps, and so on (dressups hold their op in ``Base``)."""
    seen = set()
    while obj is not None and id(obj) not in seen:
        seen.add(id(obj))
        yield obj
        base = getattr(obj, "Base", None)
        obj = base if hasattr(base, "Path") else None


def is_groove_op(obj: Any) -> bool:
    """Whether ``obj`` is a Groove op (its proxy plans grooves)."""
    proxy = getattr(obj, "Proxy", None)
    return proxy is not None and hasattr(proxy, "plan") and hasattr(proxy, "cycles") and hasattr(obj, "GrooveCount")


def own_groove_op(obj: Any) -> bool:
    """Whether ``obj`` is a Groove op itself (not a dressup of one), known in one lookup: its proxy's class
    says so (ObjectGroove.POSTED_AS). A post asks this of every object first, because each of the duck-typing
    probes below costs a FreeCAD property lookup (1-4 us; hasattr(op, "Path") copies the Path): 500 ops."""
    try:
        return getattr(type(getattr(obj, "Proxy", None)), "POSTED_AS", None) == "groove"
    except ReferenceError:  # a deleted object (see has())
        return False


def groove_op_of(obj: Any) -> Optional[Any]:
    """The Groove op ``obj`` is or wraps (dressups hold their op in ``Base``), else None."""
    return next((link for link in op_chain(obj) if is_groove_op(link)), None)


def op_property(obj: Any, name: str, default: Any = None) -> Any:
    """A property of the op or of the op a dressup wraps (FreeCAD's opProperty)."""
    for link in op_chain(obj):
        if hasattr(link, name):
            return getattr(link, name)
    return default


def has(obj: Any, name: str) -> bool:
    """hasattr() that takes a deleted FreeCAD object for one without the attribute (FreeCAD 1.0/1.1's
    fixture objects in a Job's post list share one InList, which keeps the Jobs of closed documents)."""
    try:
        return hasattr(obj, name)
    except ReferenceError:
        return False


def is_tool_controller(obj: Any) -> bool:
    return has(obj, "ToolNumber") and has(obj, "SpindleSpeed") and has(obj, "HorizFeed")


def is_job(obj: Any) -> bool:
    return has(obj, "Operations") and has(getattr(obj, "Operations", None), "Group")


def is_fixture_block(obj: Any) -> bool:
    """FreeCAD's fixture blocks (G54 ...) in a Job's post list: they carry no label of their own."""
    return type(obj).__name__ == "_TempObject"


def label_of(obj: Any) -> str:
    """The object's Label (its Name when it has none) for comments and messages."""
    return str(getattr(obj, "Label", None) or getattr(obj, "Name", None) or "object")


def job_of(objects: Iterable[Any]) -> Optional[Any]:
    """The Job the objects belong to: the first Job among them, their parent's or their grandparent's
    (not a fixture block's: its InList is shared, see has())."""
    for obj in objects:
        if is_job(obj):
            return obj
        if is_fixture_block(obj):
            continue
        for parent in getattr(obj, "InList", None) or []:
            if is_job(parent):
                return parent
            for grand in (getattr(parent, "InList", None) if has(parent, "InList") else None) or []:
                if is_job(grand):
                    return grand
    return None
