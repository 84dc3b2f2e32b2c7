"""Generate resources/tools/grinding_wheel.fcstd, the grinding wheel tool bit shape.

Run inside FreeCAD 1.0 (the oldest supported version, so 1.0 and 1.1 both
open the file), from the checkout, as make_grooving_shape.py is:

    scripts/freecad-roots run 1.0 --share /tmp/share -- sh -c \
      'exec freecadcmd -M "$FREECAD_GROOVE_CHECKOUT" -c "$1"' sh \
      "import os; exec(open(os.environ['FREECAD_GROOVE_CHECKOUT'] + '/resources/tools/make_wheel_shape.py').read())"

and copy /tmp/share/grinding_wheel.fcstd to resources/tools/. It writes to
FREECAD_GROOVE_SHAPE_OUT, else into the share directory, else next to this script.

The layout both tool bit systems read: a PartDesign::Body labelled
"GrindingWheel" (FreeCAD 1.1 picks the ToolBitShape class by it;
freecad_groove.freecad.wheel_toolbit registers it), a PropertyBag
"Attributes" with the parameters Diameter and Width (group "Shape"), and the
wheel: an AdditiveCylinder of radius Diameter / 2 and height Width about the
tool axis Z (the bit's drawing; the op reads the parameters).
"""


def _make_wheel_shape():
    import os

    import FreeCAD
    import Path.Base.PropertyBag as PathPropertyBag

    here = os.path.join(os.environ.get("FREECAD_GROOVE_CHECKOUT", os.getcwd()), "resources", "tools")
    share = os.environ.get("FREECAD_GROOVE_SHARE")
    out = os.environ.get("FREECAD_GROOVE_SHAPE_OUT") or os.path.join(share or here, "grinding_wheel.fcstd")

    doc = FreeCAD.newDocument("grinding_wheel")
    FreeCAD.setActiveDocument(doc.Name)
    body = doc.addObject("PartDesign::Body", "Body")
    body.Label = "GrindingWheel"
    bag = PathPropertyBag.Create("PropertyBag")
    bag.Label = "Attributes"
    for name, value, doc_text in (("Diameter", 200.0, "The wheel's outside diameter"),
                                  ("Width", 20.0, "The wheel's width (its grinding face, across the crossover)")):
        bag.Proxy.addCustomProperty("App::PropertyLength", name, "Shape", doc_text)
        setattr(bag, name, value)
    body.Group = body.Group + [bag]  # addObject refuses non-PartDesign objects
    wheel = doc.addObject("PartDesign::AdditiveCylinder", "Wheel")
    body.addObject(wheel)
    wheel.setExpression("Radius", "Attributes.Diameter / 2")
    wheel.setExpression("Height", "Attributes.Width")
    doc.recompute()
    if wheel.Shape.isNull() or not body.Shape.Solids:
        raise RuntimeError("the grinding wheel body has no solid")
    doc.saveAs(out)
    FreeCAD.closeDocument(doc.Name)
    return out


_make_wheel_shape()
