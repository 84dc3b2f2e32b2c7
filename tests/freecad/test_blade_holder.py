"""What the grooving blade's holder allows (issue 20, item 5): the tool bit's optional FirstCutDiameterMin,
FirstCutDiameterMax (a face-grooving blade's first-cut diameters), MinBoreDiameter (an internal bar's smallest
bore) and HolderWidth (the turning check draws the holder), 0 = not given; documents saved before them open
without an error and cut as before. The stepped shaft of parts.py: its shoulder face (Z30, R14..20, looking +Z)
and its bore (R6, Z25..60). Run inside FreeCAD 1.1 and 1.0.
"""

import os

import FreeCAD
import pytest
from documents import DATA, opened, reopened
from parts import face_name, make_shop
from test_op_errors import LATHE_POSTS, post
from test_saved_documents import DEMO_AT_BFB45FF, OPS_AT_3D18F68
from test_toolbit import _bit_from_the_chooser, _chooser_shapes, needs_assets

from freecad_groove import make_groove
from freecad_groove.freecad import blade_holder, shape_assets, toolbit
from freecad_groove.freecad.addon_op import op_error
from freecad_groove.freecad.posts import PostError
from freecad_groove.ops.groove.properties import error_properties
from freecad_groove.ops.turning_check.check import verify_job

# The shoulder groove: Position 1 from the outer edge (R20), 4 wide: R15..19; its first plunge cuts diameters
# 32..38 (test_the_face_grooves_first_plunge_cuts_the_diameters_worked_out_by_hand).
FACE = dict(position=1, width=4, depth=3, infeed=1)
BORE = dict(position=5, width=4, depth=2, infeed=1)


@pytest.fixture
def shop():
    doc = FreeCAD.newDocument("BladeHolder")
    FreeCAD.setActiveDocument(doc.Name)
    doc, shaft, job, _tc = make_shop(doc)
    tc = toolbit.make_grooving_tool_controller(job, 3, 0.2, name="TC: Grooving blade")
    name = doc.Name
    yield doc, shaft, job, tc
    if name in FreeCAD.listDocuments():  # (a test may have closed it)
        FreeCAD.closeDocument(name)


def groove(shop, face, values):
    doc, shaft, job, tc = shop
    return make_groove(job, (shaft, face_name(shaft.Shape, face)), tool_controller=tc, **values)


def first_plunge_radii(op):
    """The radii the blade spans on the op's first feed (its X and X + the blade's width, minus corner)."""
    plan = op.Proxy.current_plan(op)[0]
    first = next(m for m in plan.moves if m.kind == "G1")
    return float(first.x), float(first.x) + 3.0


def test_a_new_grooving_blade_has_the_holder_properties_not_given():
    doc = FreeCAD.newDocument("NewBlade")
    try:
        bit = toolbit.make_grooving_bit(doc, 3, 0.2)
        for name in blade_holder.NAMES:
            assert bit.getTypeIdOfProperty(name) == "App::PropertyLength"
            assert bit.getGroupOfProperty(name) == "Attributes"
            assert getattr(bit, name).Value == 0.0
        assert blade_holder.blade_limits(bit) is None and blade_holder.holder_outline(bit) is None
        given = toolbit.make_grooving_bit(doc, 3, 0.2, label="Face blade", FirstCutDiameterMin=40,
                                          FirstCutDiameterMax=60, MinBoreDiameter=20, HolderWidth=16)
        assert [getattr(given, name).Value for name in blade_holder.NAMES] == [40.0, 60.0, 20.0, 16.0]
        assert blade_holder.holder_outline(given) == (12.0, 16.0)
    finally:
        FreeCAD.closeDocument(doc.Name)


def test_the_face_grooves_first_plunge_cuts_the_diameters_worked_out_by_hand(shop):
    """CYCLE93 plunges first at the groove's edge Position is measured from (the outer one, R19; FlankAllowance
    0): the 3 mm blade's minus corner at R16, the blade over R16..19, diameters 32..38."""
    op = groove(shop, "shoulder", FACE)
    assert op_error(op) is None, op_error(op)
    assert first_plunge_radii(op) == (16.0, 19.0)


def test_a_face_groove_outside_the_blades_first_cut_range_is_refused_naming_the_property(shop):
    doc, shaft, job, tc = shop
    op = groove(shop, "shoulder", FACE)
    low, high = 32.0, 38.0
    tc.Tool.FirstCutDiameterMin = low + 1.0
    doc.recompute()
    message = op_error(op)
    assert message.startswith("FirstCutDiameterMin=%g mm: the face groove's first plunge cuts diameters %g..%g mm, "
                              "below the first-cut diameter range of Grooving blade, FirstCutDiameterMin=%g mm, no "
                              "FirstCutDiameterMax: its curved holder would hit "
                              "the face" % (low + 1.0, low, high, low + 1.0)), message
    assert message.endswith("(use a blade for these diameters); the groove at Position=1 mm of Shaft.%s"
                            % face_name(shaft.Shape, "shoulder")), message
    assert [c for c in op.Path.Commands if c.Parameters] == []
    for name in LATHE_POSTS:
        with pytest.raises(PostError) as info:
            post(name, [op])
        assert str(info.value) == "%s: %s" % (op.Label, message)
    tc.Tool.FirstCutDiameterMin = low
    tc.Tool.FirstCutDiameterMax = high - 0.5
    doc.recompute()
    assert op_error(op).startswith("FirstCutDiameterMax=%g mm: the face groove's first plunge cuts diameters "
                                   "%g..%g mm, above the first-cut diameter range of Grooving blade, "
                                   "FirstCutDiameterMin=%g mm to FirstCutDiameterMax=%g mm: its curved holder"
                                   % (high - 0.5, low, high, low, high - 0.5)), op_error(op)
    tc.Tool.FirstCutDiameterMax = high  # the range holds the first plunge exactly
    doc.recompute()
    assert op_error(op) is None, op_error(op)


def test_the_panels_plan_refuses_a_position_outside_the_range_marking_position(shop):
    doc, shaft, job, tc = shop
    op = groove(shop, "shoulder", FACE)
    tc.Tool.FirstCutDiameterMin = 31
    tc.Tool.FirstCutDiameterMax = 40
    doc.recompute()
    assert op_error(op) is None, op_error(op)
    with pytest.raises(ValueError) as info:
        op.Proxy.plan_with(op, {"Position": 2})  # the groove at R14..18: its first plunge at diameters 30..36
    assert str(info.value).startswith("FirstCutDiameterMin=31 mm: the face groove's first plunge cuts diameters "
                                      "30..36 mm, below")
    assert error_properties(info.value) == ("Position",)
    assert op.Position.Value == 1.0 and op_error(op) is None  # the document is not touched


def test_the_diameter_range_says_nothing_about_a_longitudinal_groove(shop):
    doc, shaft, job, tc = shop
    tc.Tool.FirstCutDiameterMin = 100
    op = groove(shop, "cylinder", dict(position=5, width=4, depth=2, infeed=1))
    assert op_error(op) is None, op_error(op)


def test_an_internal_groove_in_a_bore_smaller_than_the_bars_is_refused_naming_base(shop):
    doc, shaft, job, tc = shop
    op = groove(shop, "bore", BORE)
    assert op_error(op) is None, op_error(op)
    tc.Tool.MinBoreDiameter = 12.5  # the bore is 12 (R6)
    doc.recompute()
    message = op_error(op)
    assert message.startswith("MinBoreDiameter=12.5 mm: the internal groove's bore is 12 mm, smaller than the "
                              "smallest bore Grooving blade enters: its bar would hit the bore"), message
    with pytest.raises(ValueError) as info:
        op.Proxy.plan_with(op, {"Depth": 1.0})
    assert error_properties(info.value) == ("Base",)
    tc.Tool.MinBoreDiameter = 12
    doc.recompute()
    assert op_error(op) is None, op_error(op)


# The R14 cylinder (Z30..50) beside the R20 step: a groove at its -Z end (Position 15, 4 wide: Z31..35), 2 deep.
STEP_FACES = {"small": lambda f: f.surface == "cylinder" and f.external and abs(f.r_max - 14) < 1e-9}
BESIDE_STEP = dict(position=15, width=4, depth=2, infeed=1)


def test_the_turning_check_reports_a_holder_entering_the_step_beside_the_groove(shop):
    """The blade reaches 4 mm: at the groove's bottom (R12) its holder begins at R16; 20 mm wide, centred on the
    blade (Z about 22..44), it reaches over the R20 step (Z < 30): reported naming the op and the move. A holder
    4 mm wide (Z30.5..34.5 at most), or one beginning at R20 (a reach of 8), stays out."""
    doc, shaft, job, tc = shop
    tc.Tool.CuttingEdgeHeight = 4
    op = make_groove(job, (shaft, face_name(shaft.Shape, "small", STEP_FACES)), tool_controller=tc, **BESIDE_STEP)
    assert op_error(op) is None, op_error(op)
    assert verify_job(job, stock="turned").ok  # no HolderWidth: no holder drawn
    tc.Tool.HolderWidth = 20
    doc.recompute()
    result = verify_job(job, stock="turned")
    assert not result.ok, result.summary()
    hits = result.ops[0].holder_hits
    assert hits and (hits[0].holder.reach, hits[0].holder.width) == (4.0, 20.0)
    assert hits[0].at[0] > 16.0 - 1e-6 and hits[0].at[1] < 30.0  # in the step, beyond the reach
    text = result.summary()
    assert "%s: PROBLEMS" % op.Label in text
    assert "HOLDER IN STOCK: " + hits[0].describe() in text, text
    assert hits[0].describe().startswith("G0 (Path command %d) X21.000 Z" % hits[0].command)  # the approach
    tc.Tool.HolderWidth = 4
    doc.recompute()
    assert verify_job(job, stock="turned").ok
    tc.Tool.HolderWidth = 20
    tc.Tool.CuttingEdgeHeight = 8
    doc.recompute()
    assert verify_job(job, stock="turned").ok


GUI_AT_BFB45FF = os.path.join(DATA, "groove_gui_saved_at_bfb45ff.FCStd")


@pytest.mark.parametrize("path", [DEMO_AT_BFB45FF, OPS_AT_3D18F68, GUI_AT_BFB45FF])
def test_documents_saved_before_the_properties_open_without_an_error_and_check_nothing_new(path, console):
    with opened(path) as doc:
        assert console["PrintError"] == []
        bits = [o for o in doc.Objects if "CuttingEdgeHeight" in getattr(o, "PropertiesList", ())
                and "Width" in o.PropertiesList]
        assert bits
        for bit in bits:
            assert blade_holder.blade_limits(bit) is None and blade_holder.holder_outline(bit) is None
        doc.recompute()
        assert console["PrintError"] == []


def test_a_blade_saved_with_the_properties_opens_with_them(shop, tmp_path):
    doc, shaft, job, tc = shop
    tc.Tool.FirstCutDiameterMin = 28
    tc.Tool.HolderWidth = 16
    name = tc.Tool.Name
    with reopened(doc, tmp_path / "holder.FCStd") as again:
        bit = again.getObject(name)
        assert bit.FirstCutDiameterMin.Value == 28.0 and bit.HolderWidth.Value == 16.0
        assert bit.MinBoreDiameter.Value == 0.0


@needs_assets
def test_a_blade_from_the_shape_chooser_has_them_and_the_tool_library_keeps_them(shop):
    """FreeCAD 1.1: a bit the tool library editor makes from the chosen shape carries the properties (0); a value
    given is saved with the bit's attributes in the library (.fctb) and read back."""
    from Path.Tool.toolbit import ToolBit

    doc, shaft, job, tc = shop
    asset = _bit_from_the_chooser(_chooser_shapes()[shape_assets.SHAPE_ID])
    assert [getattr(asset.obj, name).Value for name in blade_holder.NAMES] == [0.0] * 4
    asset.obj.MinBoreDiameter = FreeCAD.Units.Quantity("20 mm")
    asset.obj.HolderWidth = FreeCAD.Units.Quantity("16 mm")
    saved = asset.to_dict()  # what the library's .fctb holds (toolbit/serializers/fctb.py)
    assert saved["parameter"]["MinBoreDiameter"] == "20.00 mm"
    again = ToolBit.from_dict(saved)
    assert again.obj.MinBoreDiameter.Value == 20.0 and again.obj.HolderWidth.Value == 16.0
    bit = again.attach_to_doc(doc)
    assert bit.MinBoreDiameter.Value == 20.0 and bit.FirstCutDiameterMin.Value == 0.0
    assert blade_holder.blade_limits(bit).min_bore == 20.0


SWEEP = (float("nan"), float("inf"), float("-inf"), 1e308, 0.0, -1.0)


@pytest.mark.parametrize("name", blade_holder.NAMES)
def test_each_property_swept_through_bad_values_ends_valid_or_named(shop, name):
    """As tests/freecad/test_op_bounds.py sweeps the ops' own properties: NaN, infinities, 1e308 and -1 refused
    naming the property (its bound: docs/op-bounds.md), 0 (not given; FreeCAD keeps a negative length as 0) cuts as
    before; never a traceback, never a
    non-finite number in the Path; set back, the op cuts again."""
    doc, shaft, job, tc = shop
    op = groove(shop, "shoulder", FACE)
    commands = op.Path.toGCode()
    for value in SWEEP:
        setattr(tc.Tool, name, value)
        doc.recompute()
        error = op_error(op)
        assert op.isValid(), (name, value, op.getStatusString())
        assert all(v == v and abs(v) != float("inf") for c in op.Path.Commands for v in c.Parameters.values())
        if getattr(tc.Tool, name).Value == 0.0:  # 0, or a negative length FreeCAD's PropertyLength kept as 0
            assert error is None and op.Path.toGCode() == commands, (name, value, error)
        else:
            assert error is not None and name in error and "\n" not in error, (name, value, error)
            assert [c for c in op.Path.Commands if c.Parameters] == []
    setattr(tc.Tool, name, 0.0)
    doc.recompute()
    assert op_error(op) is None and op.Path.toGCode() == commands
