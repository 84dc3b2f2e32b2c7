"""What the add-on's tool bits (the grooving blade, toolbit.py; the grinding
wheel, wheel_toolbit.py) share: making a bit from the add-on's shape file in
FreeCAD 1.1 (an asset tool bit whose Proxy is the add-on's ToolBit class)
and 1.0 (a plain Bit from the file), its tool controller, and reloading the
shape of a restored 1.1 bit (FreeCAD's asset store does not hold it).

FreeCAD layer: FreeCAD and CAM's Path.Tool only.
"""

import contextlib
import os
from typing import Callable, Iterator

import FreeCAD


@contextlib.contextmanager
def active_document(doc: object) -> Iterator[None]:
    """``doc`` active for the block (CAM creates bits and tool controllers in
    the active document), the one active before put back after it."""
    active = FreeCAD.ActiveDocument
    FreeCAD.setActiveDocument(doc.Name)
    try:
        yield
    finally:
        if active is not None and active.Name in FreeCAD.listDocuments():
            FreeCAD.setActiveDocument(active.Name)


def length(value: object) -> object:
    """A length quantity (mm) from a number or a quantity."""
    return FreeCAD.Units.Quantity("%r mm" % float(getattr(value, "Value", value)))


def make_bit(doc: object, shape_file: str, load_shape: Callable, proxy_class: object, values: dict,
             label: str) -> object:
    """A tool bit in ``doc`` from ``shape_file`` with the shape ``values``
    ({parameter: quantity}): in FreeCAD 1.1 (``proxy_class`` not None) an
    asset bit of ``load_shape()``, else a plain Bit of the file. Hidden in the
    3D view, as CAM hides the end mill of a new Job's tool controller (shown,
    a wheel's disc or a blade's body stands at the origin over the part)."""
    with active_document(doc):
        if proxy_class is not None:
            shape = load_shape()
            shape.set_parameters(**values)
            toolbit = proxy_class(shape)
            toolbit.label = label
            bit = toolbit.attach_to_doc(doc, label=label)
        else:
            import Path.Tool.Bit as PathToolBit

            bit = PathToolBit.Factory.Create("ToolBit", shape_file)
            for name, value in values.items():
                setattr(bit, name, value)
            bit.Proxy._updateBitShape(bit)  # push the values into the body
            bit.Label = label
    if getattr(bit, "ViewObject", None) is not None:
        bit.ViewObject.Visibility = False
    return bit


def make_tool_controller(job: object, bit: object, name: str, tool_number: object = None) -> object:
    """A new tool controller ``name`` in ``job`` holding ``bit``; ``tool_number``
    defaults to the job's next free number."""
    import Path.Tool.Controller as PathToolController

    doc = job.Document
    if tool_number is None:
        tool_number = job.Proxy.nextToolNumber()
    with active_document(doc):
        tc = PathToolController.Create(name, tool=bit, toolNumber=tool_number)
        job.Proxy.addToolController(tc)
    # The new objects (and what they use) only: the whole document's recompute took half a second of the
    # panel's "Create grooving tool controller" (the Job, its model and the open op's plan), which the op's
    # own recompute does again once it is given the tool controller.
    doc.recompute([tc, bit])
    return tc


def reload_shape(proxy: object, obj: object, shape_file: str, load_shape: Callable) -> None:
    """After FreeCAD 1.1 restored the bit ``obj`` (Proxy ``proxy``): its shape's
    file contents (needed to redraw the body when a parameter changes) from
    the add-on, with the bit's parameter values; a shape that cannot be read
    leaves the bit usable as it is, with a warning."""
    shape = proxy._tool_bit_shape
    if getattr(shape, "_data", None) is not None or not os.path.exists(shape_file):
        return
    try:
        loaded = load_shape()
    except Exception as e:  # keep the restored bit usable as it is
        FreeCAD.Console.PrintWarning("freecad_groove: cannot load %s: %s\n" % (shape_file, e))
        return
    for name in loaded.schema():
        if name in obj.PropertiesList:
            loaded.set_parameter(name, obj.getPropertyByName(name))
    proxy._tool_bit_shape = loaded
