"""Every op kind of the add-on in CAM's SetupSheet (1.1 and 1.0; run by tests/freecad/run_suite.py).

CAM's Job panel builds an editor of every registered op kind's defaults and,
on every OK, asks each kind's prototype (SetupSheet._RegisteredOp.prototype)
for each property the kind's SetupProperties() name
(Path/Base/Gui/SetupSheet.py OpTaskPanel.accept): a prototype without them
failed every Job panel OK of the session with KeyError 'Allowance' once the
Cylinder slot had registered. Here, with CAM's own SetupSheet code: each
prototype answers for each of its properties, with the value a new op really
gets; a default set in a Job's SetupSheet reaches a new op of that kind.
"""

import FreeCAD
import Part
import Path.Base.SetupSheet as PathSetupSheet
import Path.Main.Job as PathJob
import pytest

from freecad_groove.ops import KINDS


@pytest.fixture
def job(closing):
    doc = FreeCAD.newDocument("SetupSheetKinds")
    closing.append(doc)
    shaft = doc.addObject("Part::Feature", "Shaft")
    shaft.Shape = Part.makeCylinder(20, 50)
    doc.recompute()
    return PathJob.Create("Job", [shaft])


def _registered(kind):
    kind.load(kind.proxy)  # its module loaded: the kind registered itself (addon_op.AddonOp)
    return PathSetupSheet._RegisteredOps[kind.name]


def _same(a, b):
    if hasattr(a, "Value") and hasattr(b, "Value"):
        return str(a.Unit) == str(b.Unit) and a.Value == pytest.approx(b.Value)
    return a == b


def test_every_op_kind_is_registered_with_the_setup_sheet():
    assert {k.name for k in KINDS} <= set(PathSetupSheet._RegisteredOps)
    for kind in KINDS:
        assert _registered(kind).properties() == kind.load(kind.setup_properties)()


def test_the_cylinder_slot_offers_its_region_values_as_setup_sheet_defaults():
    slot = next(k for k in KINDS if k.name == "CylinderSlot")
    assert sorted(_registered(slot).properties()) == ["Allowance", "Depth", "Passes", "Retract"]


@pytest.mark.parametrize("kind", KINDS, ids=[k.name for k in KINDS])
def test_each_prototype_gives_every_setup_property_with_the_value_a_new_op_gets(job, kind):
    registered = _registered(kind)
    prototype = registered.prototype(kind.name)
    op = kind.load("op.Create")(kind.name, parentJob=job)
    for name in registered.properties():
        prop = prototype.getProperty(name)  # what the Job panel's OK asks (the KeyError of issue 21)
        assert prop.propType == op.getTypeIdOfProperty(name), name
        assert _same(prop.getValue(), getattr(op, name)), (name, prop.getValue(), getattr(op, name))
        assert not str(prop.displayString()).startswith(("a ", "an "))  # the table shows the value, not "a Length"


def test_a_default_in_the_jobs_setup_sheet_reaches_a_new_cylinder_slot(job):
    # as the Job panel's "Operations" defaults write it (OpTaskPanel.accept): the prototype's property set up
    # on the SetupSheet with the value typed in the editor
    slot = next(k for k in KINDS if k.name == "CylinderSlot")
    prototype = _registered(slot).prototype(slot.name)
    sheet = job.SetupSheet
    for name, value in (("Depth", FreeCAD.Units.Quantity("2.5 mm")), ("Passes", 4)):
        prop = prototype.getProperty(name)
        prop.setValue(value)
        prop.setupProperty(sheet, PathSetupSheet.OpPropertyName(slot.name, name),
                           PathSetupSheet.OpPropertyGroup(slot.name), prop.getValue())
    assert sheet.Proxy.operationsWithSettings() == [slot.name]
    op = slot.load("op.Create")("CylinderSlot", parentJob=job)
    assert op.Depth.Value == pytest.approx(2.5) and op.Passes == 4
    assert op.Allowance.Value == pytest.approx(0.1)  # not set in the sheet: the op's own default
    # a Job template saved from this sheet gives another Job's sheet the same defaults (CAM's template code,
    # which reads each value back through the prototype)
    attrs = sheet.Proxy.templateAttributes(includeOps=[slot.name])
    other = PathJob.Create("Job2", [job.Model.Group[0]])
    other.SetupSheet.Proxy.setFromTemplate(attrs)
    assert other.SetupSheet.CylinderSlotDepth.Value == pytest.approx(2.5)
    assert other.SetupSheet.CylinderSlotPasses == 4
