"""The ops' registry (freecad_groove/ops/registry.py) and their declarations,
on the host (no FreeCAD: the declarations import none, which is what lets
FreeCAD's GUI read them at its start). Each declared part is read from the
source (ast), not imported: the proxy, view provider and command classes
exist where the declaration says, so the class paths documents store are the
declared ones; and each shim of a path stored before the ops moved hands on
the declared class.
"""

import ast
import os
import re

import pytest
from conftest import ROOT

from freecad_groove import ops
from freecad_groove.ops import registry

# op folder -> (kind name, proxy, view provider, command, icon)
DECLARED = {
    "groove": ("Groove", "op.ObjectGroove", "gui.view.ViewProviderGroove", "gui.command.CommandGroove",
               "groove.svg"),
    "slot": ("CylinderSlot", "op.ObjectCylinderSlot", "gui.view.ViewProviderCylinderSlot",
             "gui.command.CommandCylinderSlot", "cylinder_slot.svg"),
    "grind": ("PlungeGrind", "op.ObjectPlungeGrind", "gui.view.ViewProviderPlungeGrind",
              "gui.command.CommandPlungeGrind", "plunge_grind.svg"),
}
# a class path documents saved before the move store -> (its shim module's file, the declared part it names)
SHIMS = {
    "freecad_groove.freecad.groove_op.ObjectGroove": ("groove", "op.ObjectGroove"),
    "freecad_groove.freecad.cylinder_slot_op.ObjectCylinderSlot": ("slot", "op.ObjectCylinderSlot"),
    "freecad_groove.freecad.plunge_grind_op.ObjectPlungeGrind": ("grind", "op.ObjectPlungeGrind"),
    "freecad_groove.gui.task_panel.ViewProvider": ("groove", "gui.view.ViewProviderGroove"),
    "freecad_groove.gui.task_panel.GroovePage": ("groove", "gui.panel.GroovePage"),
    "freecad_groove.gui.slot_view.ViewProviderCylinderSlot": ("slot", "gui.view.ViewProviderCylinderSlot"),
    "freecad_groove.gui.grind_view.ViewProviderPlungeGrind": ("grind", "gui.view.ViewProviderPlungeGrind"),
    "freecad_groove.gui.grind_panel.PlungeGrindPage": ("grind", "gui.panel.PlungeGrindPage"),
}


def source_of(module):
    """The parsed source of ``module`` ("freecad_groove.ops.groove.op")."""
    path = os.path.join(ROOT, *module.split(".")) + ".py"
    assert os.path.isfile(path), path
    with open(path, encoding="utf-8") as f:
        return ast.parse(f.read(), path)


def defines(module, name):
    """Whether ``module``'s source defines ``name`` at its top (a class or a function)."""
    return any(isinstance(node, (ast.ClassDef, ast.FunctionDef)) and node.name == name
               for node in source_of(module).body)


def test_every_op_is_registered_once_in_the_order_of_its_command():
    """(Imported above without FreeCAD, which the host has not.) The Plunge grind's command follows the
    Groove's in CAM's menu: the Groove's registers first."""
    assert [kind.name for kind in ops.KINDS] == ["Groove", "CylinderSlot", "PlungeGrind"]
    assert registry.kinds() == ops.KINDS


@pytest.mark.parametrize("folder", sorted(DECLARED))
def test_each_op_declares_its_parts_where_they_are(folder):
    name, proxy, view_provider, command, icon = DECLARED[folder]
    kind = next(k for k in ops.KINDS if k.package == "freecad_groove.ops." + folder)
    assert (kind.name, kind.proxy, kind.view_provider, kind.command, kind.icon) == DECLARED[folder]
    for part in (kind.proxy, kind.setup_properties, kind.view_provider, kind.command):
        module, _dot, defined = kind.path(part).rpartition(".")
        assert defines(module, defined), kind.path(part)
    assert kind.path(kind.proxy) == "freecad_groove.ops.%s.op.%s" % (folder, proxy.split(".")[-1])
    assert os.path.isfile(os.path.join(ROOT, "resources", "icons", kind.icon))


def test_every_command_of_the_add_on_has_its_own_icon():
    """Each op's command and the Check turning command show their own picture (the Cylinder slot and Check
    turning borrowed the Groove's), each an SVG file of resources/icons."""
    check = re.search(r'icon_path\("([^"]+)"\)', open(os.path.join(ROOT, "freecad_groove", "ops", "turning_check",
                                                                   "gui", "__init__.py")).read()).group(1)
    icons = [kind.icon for kind in ops.KINDS] + [check]
    assert len(set(icons)) == len(icons), icons
    for icon in icons:
        with open(os.path.join(ROOT, "resources", "icons", icon)) as f:
            assert f.read().lstrip().startswith("<svg"), icon


@pytest.mark.parametrize("stored", sorted(SHIMS))
def test_each_path_stored_before_the_move_is_a_shim_of_the_declared_class(stored):
    """The shim imports the declared class from its module, under the stored name."""
    module, _dot, name = stored.rpartition(".")
    folder, part = SHIMS[stored]
    target, _dot, declared = ("freecad_groove.ops.%s.%s" % (folder, part)).rpartition(".")
    tree = source_of(module)
    imports = [node for node in tree.body if isinstance(node, ast.ImportFrom)]
    handed_on = {(alias.asname or alias.name): (node.level, node.module, alias.name)
                 for node in imports for alias in node.names}
    level, relative, imported = handed_on[name]
    base = module.split(".")[: -level]
    assert ".".join(base + [relative]) == target and imported == declared
    assert ast.get_docstring(tree).startswith("A shim, kept because")
    # nothing but the stored classes: imports and __all__
    assert all(isinstance(node, (ast.ImportFrom, ast.Assign, ast.Expr)) for node in tree.body)


def _kind(**changes):
    values = dict(name="Test", package="freecad_groove.ops.test", proxy="op.ObjectTest",
                  setup_properties="op.SetupProperties", view_provider="gui.view.ViewProviderTest",
                  command="gui.command.CommandTest", icon="groove.svg")
    values.update(changes)
    return registry.OpKind(**values)


@pytest.mark.parametrize("changes, message", [
    (dict(view_provider="view.ViewProviderTest"), "must be in its gui/ package"),
    (dict(command="command.CommandTest"), "must be in its gui/ package"),
    (dict(proxy="gui.op.ObjectTest"), "must not be in its gui/ package"),
    (dict(name="Groove"), "registered already"),
    (dict(package="freecad_groove.ops.groove", proxy="op.ObjectGroove"), "registered already"),
])
def test_a_declaration_in_the_wrong_layer_or_twice_is_refused(changes, message):
    with pytest.raises(ValueError, match=message):
        registry.register(_kind(**changes))
    assert registry.kinds() == ops.KINDS


def test_a_proxy_class_is_found_by_its_class_path():
    groove = ops.KINDS[0]
    proxy = type("ObjectGroove", (), {"__module__": "freecad_groove.ops.groove.op"})
    assert registry.kind_of(proxy) is groove
    elsewhere = type("ObjectGroove", (), {"__module__": "freecad_groove.freecad.groove_op"})
    assert registry.kind_of(elsewhere) is None


def test_a_view_provider_is_given_only_once_the_gui_bound_one(monkeypatch):
    monkeypatch.setattr(registry, "_VIEW_PROVIDERS", {})
    given = []

    class Op:
        ViewObject = object()

    registry.assign_view_provider(ops.KINDS[0], Op())  # no GUI: nothing bound, nothing given
    registry.bind_view_provider(ops.KINDS[0], given.append)
    registry.assign_view_provider(ops.KINDS[1], Op())  # another kind
    op = Op()
    registry.assign_view_provider(ops.KINDS[0], op)
    headless = type("Headless", (), {"ViewObject": None})()
    registry.assign_view_provider(ops.KINDS[0], headless)
    assert given == [op]


def _top_level_imports(module):
    """The absolute names ``module`` (a module or a package) imports when it loads (its functions' imports
    left out)."""
    is_package = os.path.isdir(os.path.join(ROOT, *module.split(".")))
    package = module.split(".") if is_package else module.split(".")[:-1]
    for node in source_of(module + ".__init__" if is_package else module).body:
        if isinstance(node, ast.Import):
            yield from (alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                base = ".".join(package[: len(package) - node.level + 1] + ([node.module] if node.module else []))
            yield base
            yield from (base + "." + alias.name for alias in node.names)


def test_what_freecads_gui_start_loads_imports_no_cam_module():
    """InitGui.py runs freecad_groove.gui.register(): it loads the declarations, gui/commands.py, each op's
    command module and the Check turning command, and whatever those import when they load; none may
    import CAM (Path, PathScripts) or Part: a FreeCAD start must not pay for CAM before it is used."""
    start = ["freecad_groove.gui", "freecad_groove.gui.commands", "freecad_groove.ops",
             "freecad_groove.ops.turning_check.gui.command"]
    start += [kind.path(kind.command).rpartition(".")[0] for kind in ops.KINDS]
    seen, todo = set(), list(start)
    while todo:
        module = todo.pop()
        if module in seen:
            continue
        seen.add(module)
        for name in _top_level_imports(module):
            assert name.split(".")[0] not in {"Path", "PathScripts", "Part"}, "%s imports %s" % (module, name)
            path = os.path.join(ROOT, *name.split("."))
            if name.startswith("freecad_groove") and (os.path.isfile(path + ".py") or os.path.isdir(path)):
                todo.append(name)
    assert "freecad_groove.ops.groove.gui.command" in seen and "freecad_groove.ops.groove.op" not in seen
