"""The grooving blade and the grinding wheel among FreeCAD 1.1's built-in tool bit shapes.

FreeCAD 1.1's tool bits are assets (Path.Tool.camassets): the tool library's
shape chooser (Path.Tool.shape.ui.shapeselector, behind "Add tool bit" in the
tool library editor) lists ``cam_assets.fetch(asset_type="toolbitshape",
store="builtin")`` plus the user's shapes (store "local"), and draws each
with the icon asset ``toolbitshapesvg://<shape id>.svg``. The "builtin" store
is a FileStore on FreeCAD's own Mod/CAM/Tools folder, which an add-on must not
write to, and FreeCAD has no list of extra shape folders.

So :func:`install` puts :class:`AddonShapeStore` in the asset manager under
the name "builtin", for this session: it answers from FreeCAD's own store
first and adds the add-on's files (:data:`ASSETS`: the shapes
resources/tools/grooving.fcstd and grinding_wheel.fcstd and their drawings
grooving.svg and grinding_wheel.svg). Everything
that reads built-in assets goes through the manager's store table at call
time (the chooser, ToolBit.from_dict, a bit restored from a document), so
the grooving shape is listed, loads and is drawn like FreeCAD's own shapes;
writes still go to FreeCAD's store. No file and no preference is changed.

registration.register_shapes calls :func:`install` once CAM has imported
Path.Tool (never at FreeCAD's start). FreeCAD 1.0 has no asset store: there
:data:`AVAILABLE` is False and :func:`install` does nothing.
"""

import os
import pathlib

try:  # FreeCAD 1.1
    from Path.Tool.assets import AssetUri
    from Path.Tool.assets.store.base import AssetStore
except ImportError:  # FreeCAD 1.0: tool bits are not assets
    AssetStore = AssetUri = None

AVAILABLE = AssetStore is not None
STORE_NAME = "builtin"  # the store the shape chooser lists built-in shapes from
SHAPE_ID = "grooving"
TOOLS_DIR = pathlib.Path(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))) / \
    "resources" / "tools"
WHEEL_SHAPE_ID = "grindingwheel"  # the Plunge grind op's grinding wheel (wheel_toolbit.py)
# (asset type, asset id) -> the add-on's file
ASSETS = {
    ("toolbitshape", SHAPE_ID): TOOLS_DIR / "grooving.fcstd",
    ("toolbitshapesvg", SHAPE_ID + ".svg"): TOOLS_DIR / "grooving.svg",
    ("toolbitshape", WHEEL_SHAPE_ID): TOOLS_DIR / "grinding_wheel.fcstd",
    ("toolbitshapesvg", WHEEL_SHAPE_ID + ".svg"): TOOLS_DIR / "grinding_wheel.svg",
}


if AVAILABLE:

    class AddonShapeStore(AssetStore):
        """FreeCAD's built-in store ``base`` plus the read-only ``files``
        ({(asset type, asset id): path}); FreeCAD's own assets win."""

        def __init__(self, base: AssetStore, files: dict):
            super().__init__(base.name)
            self.base = base
            self.files = dict(files)

        def _own(self, uri):
            return self.files.get((uri.asset_type, uri.asset_id))

        def _own_uris(self, asset_type=None):
            return [AssetUri.build(asset_type=t, asset_id=i) for (t, i) in sorted(self.files)
                    if asset_type is None or t == asset_type]

        async def get(self, uri):
            try:
                return await self.base.get(uri)
            except FileNotFoundError:
                path = self._own(uri)
                if path is None or not path.is_file():
                    raise
                return path.read_bytes()

        async def exists(self, uri):
            return await self.base.exists(uri) or bool(self._own(uri) and self._own(uri).is_file())

        async def delete(self, uri):
            return await self.base.delete(uri)

        async def create(self, asset_type, asset_id, data):
            return await self.base.create(asset_type, asset_id, data)

        async def update(self, uri, data):
            return await self.base.update(uri, data)

        async def list_assets(self, asset_type=None, limit=None, offset=None):
            uris = list(await self.base.list_assets(asset_type))
            known = {(u.asset_type, u.asset_id) for u in uris}
            uris += [u for u in self._own_uris(asset_type) if (u.asset_type, u.asset_id) not in known]
            uris = uris[offset or 0:]
            return uris if limit is None else uris[:limit]

        async def count_assets(self, asset_type=None):
            return len(await self.list_assets(asset_type))

        async def list_versions(self, uri):
            versions = await self.base.list_versions(uri)
            if not versions and self._own(uri):
                return [AssetUri.build(asset_type=uri.asset_type, asset_id=uri.asset_id)]
            return versions

        async def is_empty(self, asset_type=None):
            return await self.base.is_empty(asset_type) and not self._own_uris(asset_type)

        def __getattr__(self, name):  # set_dir, _base_dir, ... of FreeCAD's store
            if name == "base":
                raise AttributeError(name)
            return getattr(self.base, name)


def installed(manager=None) -> bool:
    """True when ``manager`` (default: CAM's cam_assets) serves the add-on's shape."""
    if not AVAILABLE:
        return False
    if manager is None:
        from Path.Tool.camassets import cam_assets as manager
    store = manager.stores.get(STORE_NAME)
    return isinstance(getattr(store, "files", None), dict) and all(key in store.files for key in ASSETS)


def install(manager=None) -> bool:
    """Serve the add-on's shape and icon from ``manager``'s "builtin" store
    (default: CAM's cam_assets). Idempotent; False where FreeCAD has no asset
    store (1.0)."""
    if not AVAILABLE:
        return False
    if manager is None:
        from Path.Tool.camassets import cam_assets as manager
    from . import toolbit, wheel_toolbit  # noqa: F401  (register the Grooving and GrindingWheel shape and bit classes)

    if installed(manager):
        return True
    base = manager.stores.get(STORE_NAME)
    if base is None:
        raise RuntimeError("CAM's asset manager has no %r store" % STORE_NAME)
    manager.register_store(AddonShapeStore(base, ASSETS), cacheable=STORE_NAME in manager._cacheable_stores)
    return True


def uninstall(manager=None) -> None:
    """Put FreeCAD's own "builtin" store back."""
    if not AVAILABLE:
        return
    if manager is None:
        from Path.Tool.camassets import cam_assets as manager
    store = manager.stores.get(STORE_NAME)
    if installed(manager):
        manager.register_store(store.base, cacheable=STORE_NAME in manager._cacheable_stores)
