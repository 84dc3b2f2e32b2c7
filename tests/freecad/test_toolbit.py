"""The grooving blade tool bit shipped with the add-on (freecad_groove.freecad.toolbit),
in FreeCAD 1.1 and 1.0: a tool controller made with it carries a bit whose
Width and CornerRadius the Groove op reads, and it survives save and reopen.
In FreeCAD 1.1 the shape is among the built-in shapes CAM's shape chooser
lists (shape_assets), and a bit made the way the tool library makes one
grooves, posts and survives save and reopen; 1.0 has no such chooser.
"""

import json
import math
import os
import subprocess
import sys

import FreeCAD
import pytest
import test_groove_op as tg
import test_posts as tp
from parts import face_name

from freecad_groove import make_groove
from freecad_groove.freecad import registration, shape_assets, toolbit
from freecad_groove.ops.groove.op import op_error

# The Groove op tests' document and shop fixtures.
doc, shop = tg.doc, tg.shop


def _groove(shop, tc, **extra):
    doc, shaft, job, _tc = shop
    kw = dict(position=5, width=4, depth=2, infeed=1, tool_width=1, tool_corner_radius=0.5)
    kw.update(extra)
    return make_groove(job, (shaft, face_name(shaft.Shape, "cylinder")), tool_controller=tc, **kw)


def _tool(op):
    (_c, settings, _st), = op.Proxy.cycles(op)
    return settings.tool.width, settings.tool.corner_radius


def _moves(op):
    return [(c.Name, sorted((k, round(v, 6)) for k, v in c.Parameters.items())) for c in op.Path.Commands]


def test_the_shape_file_ships():
    assert os.path.isfile(toolbit.SHAPE_FILE)


def test_tool_controller_with_a_grooving_blade(shop):
    doc, shaft, job, first = shop
    tc = toolbit.make_grooving_tool_controller(job, 3, 0.2)
    assert tc in job.Tools.Group and tc is not first
    assert tc.ToolNumber == first.ToolNumber + 1
    bit = tc.Tool
    assert bit.Width.Value == pytest.approx(3) and bit.CornerRadius.Value == pytest.approx(0.2)
    assert bit.Diameter.Value == pytest.approx(3)
    assert bit.Shape.Solids, "the blade has a solid"
    assert bit.Shape.BoundBox.XLength == pytest.approx(3)
    if toolbit.NEW_TOOLBITS:
        assert bit.ShapeType == "Grooving"
        assert isinstance(bit.Proxy, toolbit.ToolBitGrooving)
    tc2 = toolbit.make_grooving_tool_controller(job, 2, 0.1, tool_number=7, name="TC: narrow", Length=30)
    assert tc2.ToolNumber == 7 and tc2.Label == "TC: narrow"
    assert tc2.Tool.Length.Value == pytest.approx(30) and tc2.Tool.Width.Value == pytest.approx(2)
    with pytest.raises(TypeError):
        toolbit.make_grooving_tool_controller(job, 2, 0.1, Flutes=2)


def _width_at(bit, z):
    """The blade solid's width across the cut (X) at height ``z`` above its cutting edge."""
    return max(e.BoundBox.XLength for e in bit.Shape.slice(FreeCAD.Vector(0, 0, 1), z))


@pytest.mark.parametrize("radius", [0.5, 0, 1.5])
def test_the_blade_is_drawn_with_its_corner_radius(doc, radius):
    bit = toolbit.make_grooving_bit(doc, 3, radius)
    doc.recompute()
    assert bit.Shape.isValid() and len(bit.Shape.Solids) == 1
    # A sharp blade is drawn with 1 um, a full radius with 99.9 % of the half width (a fillet needs both).
    r = min(max(radius, 0.001), 3 * 0.4995)
    # 0.1 above the cutting edge each corner is r - sqrt(r^2 - (r - 0.1)^2) in from its side (0 if r <= 0.1).
    inset = r - math.sqrt(r * r - (r - 0.1) ** 2) if r > 0.1 else 0
    assert _width_at(bit, 0.1) == pytest.approx(3 - 2 * inset, abs=1e-3)
    assert _width_at(bit, 2) == pytest.approx(3)


def test_the_op_reads_the_blades_width_and_corner_radius(shop):
    doc, shaft, job, first = shop
    tc = toolbit.make_grooving_tool_controller(job, 3, 0.2)
    op = _groove(shop, tc)
    assert op_error(op) is None, op_error(op)
    assert _tool(op) == (pytest.approx(3), pytest.approx(0.2))  # not the op's 1 / 0.5
    before = _moves(op)
    tc.Tool.Width = 2.5
    tc.Tool.CornerRadius = 0.4
    doc.recompute()
    assert tc.Tool.Diameter.Value == pytest.approx(2.5)
    if toolbit.NEW_TOOLBITS:  # 1.1 redraws the blade; 1.0 only from its tool bit editor
        assert tc.Tool.Shape.BoundBox.XLength == pytest.approx(2.5)
    assert _tool(op) == (pytest.approx(2.5), pytest.approx(0.4))
    assert op_error(op) is None, op_error(op)
    assert _moves(op) != before
    # a groove narrower than the blade is refused
    op.Width = 2
    doc.recompute()
    assert "(alarm 61602)" in op_error(op) and "tool width 2.5" in op_error(op)
    op.Width = 4
    doc.recompute()
    assert op_error(op) is None, op_error(op)


def test_save_and_reopen_keeps_the_blade(shop, tmp_path):
    doc, shaft, job, first = shop
    tc = toolbit.make_grooving_tool_controller(job, 2.5, 0.3)
    op = _groove(shop, tc)
    assert op_error(op) is None, op_error(op)
    names = op.Name, tc.Name, tc.Tool.Name
    moves = _moves(op)
    path = str(tmp_path / "blade.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    doc2 = FreeCAD.openDocument(path)
    try:
        op2, tc2, bit2 = (doc2.getObject(n) for n in names)
        assert op2.ToolController == tc2 and tc2.Tool == bit2
        assert bit2.Width.Value == pytest.approx(2.5) and bit2.CornerRadius.Value == pytest.approx(0.3)
        assert bit2.Diameter.Value == pytest.approx(2.5)
        if toolbit.NEW_TOOLBITS:
            assert isinstance(bit2.Proxy, toolbit.ToolBitGrooving) and bit2.ShapeType == "Grooving"
        assert _tool(op2) == (pytest.approx(2.5), pytest.approx(0.3))
        doc2.recompute()
        assert op_error(op2) is None, op_error(op2)
        assert _moves(op2) == moves
        # still a working bit: a new width reaches the op and the blade's body
        bit2.Width = 3
        doc2.recompute()
        assert _tool(op2)[0] == pytest.approx(3) and bit2.Diameter.Value == pytest.approx(3)
        if toolbit.NEW_TOOLBITS:  # the shape was reloaded from the add-on: the body follows
            assert bit2.Shape.BoundBox.XLength == pytest.approx(3)
        assert op_error(op2) is None, op_error(op2)
        assert all(o.isValid() for o in doc2.Objects), [o.Name for o in doc2.Objects if not o.isValid()]
    finally:
        FreeCAD.closeDocument(doc2.Name)


def test_no_blade_width_is_an_error_not_a_default(shop):
    doc, shaft, job, first = shop  # the Job's tool controller: FreeCAD's end mill, no Width
    op = make_groove(job, (shaft, face_name(shaft.Shape, "cylinder")), position=5, width=4, depth=2)
    assert op.ToolWidth.Value == 0  # unknown, not a made-up 3 mm
    status = op_error(op)
    assert status is not None
    assert "ToolWidth: the blade's width is unknown" in status and first.Label in status
    assert not [c for c in op.Path.Commands if c.Name in ("G0", "G1")]
    # A grooving tool controller gives the width...
    op.ToolController = toolbit.make_grooving_tool_controller(job, 3, 0.2)
    doc.recompute()
    assert op_error(op) is None, op_error(op)
    assert _tool(op) == (pytest.approx(3), pytest.approx(0.2))
    # ... and so does a width typed into the op, with the end mill.
    op.ToolController = first
    op.ToolWidth = 2.5
    doc.recompute()
    assert op_error(op) is None, op_error(op)
    assert _tool(op)[0] == pytest.approx(2.5)


# ----------------------------------------------------------------------------- FreeCAD 1.1's shape chooser

needs_assets = pytest.mark.skipif(not shape_assets.AVAILABLE, reason="FreeCAD 1.0 has no tool bit asset store and "
                                  "no shape chooser: the grooving blade comes from the Groove panel's tool page")


def _chooser_shapes():
    """The shapes CAM's shape chooser lists, the way it fetches them
    (Path.Tool.shape.ui.shapeselector.ShapeSelector.update_shapes)."""
    from Path.Tool.camassets import cam_assets

    builtin = {c.id: c for c in cam_assets.fetch(asset_type="toolbitshape", store="builtin")}
    for shape in cam_assets.fetch(asset_type="toolbitshape", store="local"):
        builtin.pop(shape.id, None)
    return builtin


def _bit_from_the_chooser(shape):
    """A tool bit made the way the tool library editor makes one from the
    chosen shape (library/ui/editor.py _on_add_toolbit_requested), saved as
    an asset and read back as the library does."""
    from Path.Tool.camassets import cam_assets
    from Path.Tool.toolbit import ToolBit

    tool_bit_class = {b.SHAPE_CLASS.name: b for b in ToolBit.__subclasses__()}[shape.name]
    new_toolbit = tool_bit_class(shape)
    new_toolbit.label = "New Toolbit"
    uri = cam_assets.add(new_toolbit)
    return cam_assets.get(uri, store=["local", "builtin"])


@needs_assets
def test_the_shape_chooser_lists_the_grooving_blade():
    assert shape_assets.installed(), "Init.py registered the shape when CAM imported Path.Tool"
    shapes = _chooser_shapes()
    assert "endmill" in shapes  # FreeCAD's own shapes are still there
    shape = shapes[shape_assets.SHAPE_ID]
    assert isinstance(shape, toolbit.ToolBitShapeGrooving) and shape.label == "Grooving blade"
    assert shape.is_builtin
    params = shape.get_parameters()
    assert params["Width"].Value == pytest.approx(3) and params["CornerRadius"].Value == pytest.approx(0.2)
    icon = shape.get_icon()  # what the chooser's button draws
    from Path.Tool.shape import ToolBitShapeSvgIcon

    assert isinstance(icon, ToolBitShapeSvgIcon)
    assert icon.abbreviations == {"Width": "W", "CornerRadius": "R", "CuttingEdgeHeight": "h", "Length": "L"}


@needs_assets
def test_register_shapes_is_idempotent_and_reversible():
    from Path.Tool.camassets import cam_assets

    freecads = cam_assets.stores["builtin"].base
    try:
        registration.register_shapes()
        registration.register_shapes()
        assert cam_assets.stores["builtin"].base is freecads  # not wrapped twice
        registration.unregister_shapes()
        assert cam_assets.stores["builtin"] is freecads
        assert shape_assets.SHAPE_ID not in _chooser_shapes()
    finally:
        registration.register_shapes()
    assert shape_assets.SHAPE_ID in _chooser_shapes()


@needs_assets
def test_a_bit_from_the_chooser_grooves_posts_and_survives_reopen(shop, tmp_path):
    doc, shaft, job, first = shop
    toolbit_asset = _bit_from_the_chooser(_chooser_shapes()[shape_assets.SHAPE_ID])
    assert isinstance(toolbit_asset, toolbit.ToolBitGrooving)
    # The tool library's "Add to Job" (library/ui/dock.py), then the user's values.
    import Path.Tool.Controller as PathToolController

    bit = toolbit_asset.attach_to_doc(doc)
    bit.Width, bit.CornerRadius = 2.5, 0.3
    tc = PathToolController.Create("TC: " + toolbit_asset.label, bit, 4)
    job.Proxy.addToolController(tc)
    op = _groove(shop, tc)
    doc.recompute()
    assert op_error(op) is None, op_error(op)
    assert _tool(op) == (pytest.approx(2.5), pytest.approx(0.3))
    assert bit.Diameter.Value == pytest.approx(2.5)  # follows the width
    program = tp.export("linuxcnc", [tc, op])
    assert "T4 M6" in program and [e for e in tp.read(program, "linuxcnc") if e[0] == "G1"]
    moves = _moves(op)
    path = str(tmp_path / "chooser.FCStd")
    doc.saveAs(path)
    names = op.Name, bit.Name
    FreeCAD.closeDocument(doc.Name)
    doc2 = FreeCAD.openDocument(path)
    try:
        op2, bit2 = (doc2.getObject(n) for n in names)
        assert isinstance(bit2.Proxy, toolbit.ToolBitGrooving) and bit2.ShapeType == "Grooving"
        assert bit2.Width.Value == pytest.approx(2.5) and bit2.CornerRadius.Value == pytest.approx(0.3)
        doc2.recompute()
        assert op_error(op2) is None, op_error(op2)
        assert _moves(op2) == moves
        assert tp.export("linuxcnc", [op2.ToolController, op2]) == program
    finally:
        FreeCAD.closeDocument(doc2.Name)
    # A new FreeCAD session (only Init.py has run) opening it first thing.
    assert _reopened_in_a_new_session(path, names, tmp_path) == {
        "cam_tool_bits_loaded_at_start": False, "proxy": "ToolBitGrooving", "width": 2.5, "corner_radius": 0.3,
        "error": None, "moves": len(moves), "chooser_lists_it": True}


REOPEN_SCRIPT = """
import json, sys
out = {"cam_tool_bits_loaded_at_start": "Path.Tool" in sys.modules}
import FreeCAD
doc = FreeCAD.openDocument(%(path)r)
op, bit = doc.getObject(%(op)r), doc.getObject(%(bit)r)
doc.recompute()
from freecad_groove.freecad import shape_assets
from freecad_groove.ops.groove.op import op_error
out.update(proxy=type(bit.Proxy).__name__, width=bit.Width.Value, corner_radius=bit.CornerRadius.Value,
           error=op_error(op), moves=len(op.Path.Commands), chooser_lists_it=shape_assets.installed())
open(%(result)r, "w").write(json.dumps(out))
"""


def _reopened_in_a_new_session(path, names, tmp_path):
    """What a fresh freecadcmd with the add-on (-M) sees opening ``path``."""
    script, result = tmp_path / "reopen.py", tmp_path / "reopen.json"
    script.write_text(REOPEN_SCRIPT % dict(path=path, op=names[0], bit=names[1], result=str(result)))
    checkout = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    freecadcmd = os.path.join(os.path.dirname(sys.executable), "freecadcmd")
    if not os.path.exists(freecadcmd):
        freecadcmd = "freecadcmd"
    proc = subprocess.run([freecadcmd, "-M", checkout, "-c", "exec(open(%r).read())" % str(script)],
                          capture_output=True, text=True, timeout=300)
    assert result.exists(), proc.stdout[-3000:] + proc.stderr[-3000:]
    return json.loads(result.read_text())
