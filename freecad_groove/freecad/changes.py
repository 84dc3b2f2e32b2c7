"""Values read from document objects, read again only after the object changed.

A Groove op checks at every recompute, and at every post for each of its
ops, what it read of other objects: its tool controller's and tool bit's
properties (AddonOp.mustExecute: FreeCAD does not recompute an op whose tool
bit changed), the fingerprint of its plans' inputs (ops/groove/cache.py: the
tool controller, the tool bit, the model, the stock). Reading them costs
about 1-3 ms an op, for objects that rarely change. A document observer
counts every change FreeCAD signals for an object (any property set, the
object created or deleted; a document opened or closed starts its objects
over), and ``read_once(obj, what, read)`` gives what ``read(obj)`` gave
while that count has not moved: the check runs once per change of what it
reads, not once per recompute.

Every property change of a document object goes through FreeCAD's
signalChangedObject (set from Python, by an expression, a recompute, undo and
redo), which the observer hears; an object's Shape is one of its properties.

Hearing a change costs one dict store: the object is only noted (by its
wrapper, which FreeCAD keeps for the object's life) and counted at the next
read (read_once, last_change, unchanged_memo), once however many of its
properties changed. Opening a document signals every restored property (about
a thousand for a saved 5-op Job, 27 objects), and FreeCAD 1.0 and 1.1 tell a
Python observer neither where a restore starts nor where it ends: finding the
object's document and name at each of them cost 9-13 ms of CPU an opening.

FreeCAD layer: FreeCAD only.
"""

import itertools
from typing import Callable, TypeVar

import FreeCAD

Value = TypeVar("Value")

_COUNTER = itertools.count(1)
_last = [0]  # the counter at the last change of any object (counted)
_unchanged: dict = {"at": None, "memo": {}}  # unchanged_memo()'s
_changed: dict = {}  # (document name, object name) -> the counter at its last change
_opened: dict = {}  # document name -> the counter when it was opened or created
_read: dict = {}  # (document name, object name, what) -> (its change count then, the value)
_heard: dict = {}  # id(object) -> the object: changed since the last count (its wrapper kept: the id stays its own)
work = {"heard": 0, "keyed": 0}  # changes heard, objects' names found (to count them, to read): the tests read these


def _key(obj: object) -> tuple:
    key = (obj.Document.Name, obj.Name)
    work["keyed"] += 1
    return key


class _Observer:
    """Notes the changes of every document object (FreeCAD calls these slots; one that raised would print a
    traceback in the report view at every change: none does)."""

    def slotChangedObject(self, obj, prop):  # noqa: N802 - FreeCAD's names
        _heard[id(obj)] = obj
        work["heard"] += 1

    def slotCreatedObject(self, obj):  # noqa: N802
        _heard[id(obj)] = obj
        work["heard"] += 1

    def slotDeletedObject(self, obj):  # noqa: N802 - counted now: its name is gone after
        _heard[id(obj)] = obj
        work["heard"] += 1
        _count_heard()

    def slotAppendDynamicProperty(self, obj, prop):  # noqa: N802 - a property added: PropertiesList changed
        _heard[id(obj)] = obj
        work["heard"] += 1

    slotRemoveDynamicProperty = slotAppendDynamicProperty  # noqa: N815

    def slotCreatedDocument(self, doc):  # noqa: N802
        _start_over(getattr(doc, "Name", None))

    # undo and redo set properties (signalled too): all read again all the same
    slotDeletedDocument = slotUndoDocument = slotRedoDocument = slotCreatedDocument  # noqa: N815


def _count_heard() -> None:
    """Count the changes heard since the last count: one new counter value for all of them."""
    if not _heard:
        return
    heard = list(_heard.values())
    _heard.clear()
    count = _next()
    for obj in heard:
        try:
            _changed[_key(obj)] = count
        except Exception:  # a view provider's property, an object of a closed document (_start_over counted it)
            pass


def _next() -> int:
    _last[0] = next(_COUNTER)
    return _last[0]


def _start_over(document: str) -> None:
    _opened[document] = _next()
    for key in [key for key in _read if key[0] == document]:
        del _read[key]


def _count(key: tuple) -> tuple:
    """The change count of the object of ``key`` (_key), the changes heard counted first."""
    _count_heard()
    return (_opened.get(key[0], 0), _changed.get(key, 0))


_OBSERVER = _Observer()
FreeCAD.addDocumentObserver(_OBSERVER)


def read_once(obj: object, what: str, read: Callable[[object], Value]) -> Value:
    """``read(obj)``, read again only when ``obj`` changed since (the module's notes); ``what`` names the
    reading (one object has several)."""
    key = _key(obj)
    count = _count(key)
    key += (what,)
    kept = _read.get(key)
    if kept is not None and kept[0] == count:
        return kept[1]
    value = read(obj)
    _read[key] = (count, value)
    return value


def last_change() -> int:
    """A number that moves at every change of any document object (the module's notes)."""
    _count_heard()
    return _last[0]


def unchanged_memo() -> dict:
    """A dict of values read from documents, kept while no document object changed (emptied at the first
    change after): a post reads the same tool controller, model and stock for each of its ops."""
    _count_heard()
    if _unchanged["at"] != _last[0]:
        _unchanged["at"], _unchanged["memo"] = _last[0], {}
    return _unchanged["memo"]
