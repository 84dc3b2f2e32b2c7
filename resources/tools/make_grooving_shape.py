"""Generate resources/tools/grooving.fcstd, the grooving blade tool bit shape.

Run inside FreeCAD 1.0 (the oldest supported version, so 1.0 and 1.1 both
open the file), from the checkout:

    scripts/freecad-roots run 1.0 --share /tmp/share -- sh -c \
      'exec freecadcmd -M "$FREECAD_GROOVE_CHECKOUT" -c "$1"' sh \
      "import os; exec(open(os.environ['FREECAD_GROOVE_CHECKOUT'] + '/resources/tools/make_grooving_shape.py').read())"

and copy /tmp/share/grooving.fcstd to resources/tools/ (the checkout is
read-only inside the root). It writes grooving.fcstd to FREECAD_GROOVE_SHAPE_OUT,
else into the share directory, else next to this script (e.g. when exec'd
from a FreeCAD Python console).

The layout is what both tool bit systems read from a shape file:
- a PartDesign::Body, the first root object, labelled "Grooving" (FreeCAD
  1.1 picks the ToolBitShape class by this label; freecad_groove registers
  a "Grooving" class),
- inside it a PropertyBag (Path.Base.PropertyBag) labelled "Attributes"
  whose custom properties (group "Shape") are the bit's parameters: Width,
  CornerRadius, CuttingEdgeHeight, Length, Diameter (FreeCAD's ops need a
  non-zero Diameter; the tool bit drives it from Width),
- the blade's solid, an AdditiveBox whose size follows the parameters by
  expressions: Width across the cut (X), CuttingEdgeHeight (the reach of
  the blade, Y) and Length along the tool axis (Z); a fillet "Corners" rounds
  the two front corners with CornerRadius (see _round_front_corners).
"""


def _make_grooving_shape():
    import os

    import FreeCAD
    import Path.Base.PropertyBag as PathPropertyBag

    here = os.path.join(os.environ.get("FREECAD_GROOVE_CHECKOUT", os.getcwd()), "resources", "tools")
    share = os.environ.get("FREECAD_GROOVE_SHARE")  # set by scripts/freecad-roots run --share
    out = os.environ.get("FREECAD_GROOVE_SHAPE_OUT") or os.path.join(share or here, "grooving.fcstd")

    doc = FreeCAD.newDocument("grooving")
    FreeCAD.setActiveDocument(doc.Name)
    body = doc.addObject("PartDesign::Body", "Body")
    body.Label = "Grooving"

    bag = PathPropertyBag.Create("PropertyBag")
    bag.Label = "Attributes"
    params = [
        ("Width", 3.0, "Width of the blade's cutting edge (across the cut)"),
        ("CornerRadius", 0.2, "Radius of the blade's two front corners"),
        ("CuttingEdgeHeight", 12.0, "How deep the blade can plunge (its free reach)"),
        ("Length", 25.0, "Overall length of the blade"),
        ("Diameter", 3.0, "Equal to Width: FreeCAD's operations need a tool diameter"),
    ]
    for name, value, doc_text in params:
        bag.Proxy.addCustomProperty("App::PropertyLength", name, "Shape", doc_text)
        setattr(bag, name, value)
    body.Group = body.Group + [bag]  # addObject refuses non-PartDesign objects

    box = doc.addObject("PartDesign::AdditiveBox", "Blade")
    body.addObject(box)
    box.setExpression("Length", "Attributes.Width")
    box.setExpression("Width", "Attributes.CuttingEdgeHeight")
    box.setExpression("Height", "Attributes.Length")
    # centred across the cut, the cutting edge at Z = 0, the blade reaching -Y
    box.setExpression(".AttachmentOffset.Base.x", "-Attributes.Width / 2")
    box.setExpression(".AttachmentOffset.Base.y", "-Attributes.CuttingEdgeHeight")
    doc.recompute()
    if box.Shape.isNull() or not body.Shape.Solids:
        raise RuntimeError("the grooving blade body has no solid")
    _round_front_corners(doc, body, box)
    doc.saveAs(out)
    FreeCAD.closeDocument(doc.Name)
    return out


def _round_front_corners(doc, body, box):
    """A fillet of CornerRadius on the two edges at the ends of the cutting
    edge (parallel to Y at Z = 0, X = +-Width/2). A fillet needs a radius
    above 0 and below half the width: a sharp blade is drawn with 1 um, a
    full-radius one with 99.9 % of Width / 2 (the op reads the parameter,
    not this solid)."""
    names = ["Edge%d" % (i + 1) for i, e in enumerate(box.Shape.Edges)
             if abs(e.BoundBox.ZMax) < 1e-9 and e.BoundBox.YLength > 1e-6]
    if len(names) != 2:
        raise RuntimeError("expected the blade's two front edges, found %s" % names)
    fillet = doc.addObject("PartDesign::Fillet", "Corners")
    body.addObject(fillet)
    fillet.Base = (box, names)
    fillet.setExpression("Radius", "min(max(Attributes.CornerRadius; 0.001 mm); Attributes.Width * 0.4995)")
    doc.recompute()
    if not fillet.isValid() or not body.Shape.Solids:
        raise RuntimeError("the blade's corner fillet failed: %s" % fillet.getStatusString())


_make_grooving_shape()
