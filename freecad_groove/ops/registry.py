"""The registry of the add-on's ops, as FreeCAD CAM's ``SetupOperation``
(Path/Op/Gui/Base.py) is for its own: each op folder declares itself once
(an OpKind in its ``__init__.py``: name, op class, SetupSheet properties,
view provider, command, icon) and one call, ``register(kind)``, registers it
(freecad_groove/ops/__init__.py, in the order of the commands in CAM's
toolbar and menu).

A declaration names the op's parts by where they are in its folder
("op.ObjectGroove": the class ObjectGroove of the folder's op.py), so that
declaring an op imports nothing of FreeCAD: FreeCAD's GUI reads the
declarations when it starts, before CAM is loaded. Each part is loaded where
it is used, by its own layer:

- the proxy class when its module loads (a document naming it, a make_*
  call, a post): its base, addon_op.AddonOp, looks its kind up here
  (kind_of) and registers it with CAM's SetupSheet;
- the command and the view provider by the GUI when it starts
  (freecad_groove.gui.register -> gui/commands.register_op): the command
  into CAM's toolbar and menu, the view provider bound here
  (bind_view_provider), so that an op made by a script gets it too
  (addon_op.create_op -> assign_view_provider).

Plain Python: imports neither FreeCAD nor another layer (tests/test_layers.py).
"""

import importlib
from dataclasses import dataclass
from typing import Callable, Dict, List, Optional, Tuple

GUI_PACKAGE = "gui."  # an op's layer 3 part: its view provider and command live in its gui/ package


@dataclass(frozen=True)
class OpKind:
    """One op of the add-on, as its folder declares it. Parts are "module.Name" in the folder's package."""

    name: str  # its kind in CAM's SetupSheet registry, and a new op's object name ("Groove")
    package: str  # its folder as a package ("freecad_groove.ops.groove")
    proxy: str  # its proxy class, whose path every document stores ("op.ObjectGroove")
    setup_properties: str  # what a Job's SetupSheet may hold defaults for ("op.SetupProperties")
    view_provider: str  # its view provider class, whose path GUI documents store ("gui.view.ViewProviderGroove")
    command: str  # the class of the FreeCAD command that makes one ("gui.command.CommandGroove")
    icon: str  # its icon, a file in resources/icons ("groove.svg")

    def path(self, part: str) -> str:
        """The dotted path of one of its parts ("op.ObjectGroove" -> "freecad_groove.ops.groove.op.ObjectGroove")."""
        return "%s.%s" % (self.package, part)

    def load(self, part: str) -> object:
        """One of its parts, its module imported."""
        module, _dot, name = self.path(part).rpartition(".")
        return getattr(importlib.import_module(module), name)


_KINDS: List[OpKind] = []
_VIEW_PROVIDERS: Dict[str, Callable[[object], None]] = {}


def register(kind: OpKind) -> OpKind:
    """Register ``kind``; ValueError when its name or proxy is taken, or a part is in the wrong layer (the view
    provider and the command in its gui/ package, the proxy and its SetupSheet properties outside it)."""
    for part, in_gui in ((kind.proxy, False), (kind.setup_properties, False), (kind.view_provider, True),
                         (kind.command, True)):
        if part.startswith(GUI_PACKAGE) != in_gui:
            raise ValueError("op %s: %s must %sbe in its gui/ package" % (kind.name, part, "" if in_gui else "not "))
    for other in _KINDS:
        if kind.name == other.name or kind.path(kind.proxy) == other.path(other.proxy):
            raise ValueError("op %s: registered already (%s)" % (kind.name, other.path(other.proxy)))
    _KINDS.append(kind)
    return kind


def kinds() -> Tuple[OpKind, ...]:
    """Every registered op, in the order registered."""
    return tuple(_KINDS)


def kind_of(proxy_class: type) -> Optional[OpKind]:
    """The kind whose proxy is ``proxy_class`` (by its class path), or None."""
    path = "%s.%s" % (proxy_class.__module__, proxy_class.__qualname__)
    return next((kind for kind in _KINDS if kind.path(kind.proxy) == path), None)


def bind_view_provider(kind: OpKind, assign: Callable[[object], None]) -> None:
    """The GUI's: ``assign(obj)`` gives a new op of ``kind`` its view provider."""
    _VIEW_PROVIDERS[kind.name] = assign


def assign_view_provider(kind: OpKind, obj: object) -> None:
    """Give the new op ``obj`` of ``kind`` its view provider, when the GUI bound one (it is up) and ``obj``
    has a view object."""
    assign = _VIEW_PROVIDERS.get(kind.name)
    if assign is not None and getattr(obj, "ViewObject", None) is not None:
        assign(obj)
