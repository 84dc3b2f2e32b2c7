"""Make FreeCAD's CAM workbench find the posts in this add-on's postprocessors/
(:func:`register`) and, in FreeCAD 1.1, the grooving blade among its tool bit
shapes (:func:`register_shapes`, see shape_assets.py; it waits for CAM to
import ``Path.Tool`` the same way as the posts wait for ``Path.Preferences``).

FreeCAD's development version has a route for add-ons: it reads the
``<Postprocessor>`` entry of an installed add-on's package.xml, and
``Path.Preferences.addAddonPostPath(folder)`` adds a folder (for an add-on
loaded from elsewhere, e.g. ``-M``). Where that function exists
:func:`register` calls it (unless the folder is already searched) and wraps
nothing. The rest of this text is about FreeCAD 1.0 and 1.1, which lack it.

FreeCAD 1.0 and 1.1 list and load script posts by globbing ``*_post.py`` in
``Path.Preferences.searchPathsPost()``: the user's DefaultFilePath preference
(one folder, also used for job templates and output files), the Macro folder
and FreeCAD's own post folders. Add-on folders are not searched, and there
is no preference that holds a list of post folders. So :func:`register` wraps
``Path.Preferences.searchPathsPost`` for this FreeCAD session: the wrapper
returns FreeCAD's list with our folder appended when it is not already in it.
Everything FreeCAD does with posts goes through that function at call time
(``allAvailablePostProcessors``/``allEnabledPostProcessors`` for the Job's
post list, the post selection dialog and the preferences page;
``PostProcessorFactory.get_post_processor`` to load a post), so our posts
appear and load like FreeCAD's own. No preference and no file is changed.

* Cheap at start-up: Init.py calls :func:`register` before anything has
  imported ``Path.Preferences`` (importing CAM costs about half a second,
  which a FreeCAD start must not pay when CAM is not used). Then a finder on
  ``sys.meta_path`` waits for that import and wraps the function right after
  the module has run; it removes itself afterwards.
* Idempotent: the wrapper carries the folders it adds; registering again adds
  nothing. Several copies of this module (Init.py loads it by file name, a
  script may import it normally) share that state, because it lives on the
  wrapper and on the finder, not in this module.
* Reversible: :func:`unregister` removes the pending finder, takes our folder
  out of the wrapper and puts FreeCAD's own function back when nobody wrapped
  it after us.

Only the standard library is imported here (FreeCAD's ``Path.Preferences`` is
reached through sys.modules), so importing this file costs nothing.
"""

import importlib.abc
import os
import sys

POSTS_DIR = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
                         "postprocessors")
TARGET = "Path.Preferences"
FUNCTION = "searchPathsPost"
SHAPES_TARGET = "Path.Tool"  # register_shapes: FreeCAD 1.1's tool bit assets are set up by then
ADD_FUNCTION = "addAddonPostPath"  # FreeCAD's development version (after 1.1)
_MARK = "_freecad_groove_post_dirs"  # on the wrapper: the list of folders it appends
_HOOK = "_freecad_groove_post_hook"  # on the finder


def _same(a, b):
    return os.path.normcase(os.path.realpath(a)) == os.path.normcase(os.path.realpath(b))


def _wrapper_of(function):
    """Our wrapper in the chain of wrappers ending at ``function`` (None: not wrapped by us)."""
    seen = set()
    while function is not None and id(function) not in seen:
        seen.add(id(function))
        if isinstance(getattr(function, _MARK, None), list):
            return function
        function = getattr(function, "__wrapped__", None)
    return None


def _wrap(module, folder):
    add = getattr(module, ADD_FUNCTION, None)
    if callable(add):  # FreeCAD's own route for add-on posts
        if not any(p and _same(p, folder) for p in getattr(module, FUNCTION)()):
            add(folder)
        return
    current = getattr(module, FUNCTION)
    wrapper = _wrapper_of(current)
    if wrapper is not None:
        folders = getattr(wrapper, _MARK)
        if not any(_same(f, folder) for f in folders):
            folders.append(folder)
        return
    folders = [folder]

    def searchPathsPost():
        paths = current()
        for f in folders:
            if not any(_same(p, f) for p in paths if p):
                paths.append(f)
        return paths

    searchPathsPost.__wrapped__ = current
    searchPathsPost.__doc__ = current.__doc__
    setattr(searchPathsPost, _MARK, folders)
    setattr(module, FUNCTION, searchPathsPost)


class _Loader(importlib.abc.Loader):
    """Runs the real loader, then the hook's action on the module."""

    def __init__(self, loader, hook):
        self._loader = loader
        self._hook = hook

    def create_module(self, spec):
        return self._loader.create_module(spec)

    def exec_module(self, module):
        self._loader.exec_module(module)
        _remove_hooks(self._hook.target)
        try:
            self._hook.action(module)
        except Exception as e:  # never break FreeCAD's own import
            _warn("freecad-groove: %s: %s" % (self._hook.failure, e))

    def __getattr__(self, name):  # get_source, get_filename, ... of the real loader
        return getattr(self._loader, name)


class _Hook(importlib.abc.MetaPathFinder):
    """Waits for module ``target`` to be imported, then runs ``action(module)``."""

    def __init__(self, target, action, failure):
        self.target = target
        self.action = action
        self.failure = failure  # what did not happen, for the warning
        setattr(self, _HOOK, True)

    def find_spec(self, name, path=None, target=None):
        if name != self.target:
            return None
        for finder in list(sys.meta_path):
            if getattr(finder, _HOOK, False):
                continue
            find = getattr(finder, "find_spec", None)
            if find is None:
                continue
            spec = find(name, path, target)
            if spec is not None:
                break
        else:
            return None
        if spec.loader is None or not hasattr(spec.loader, "exec_module"):
            return spec
        spec.loader = _Loader(spec.loader, self)
        return spec


def _hooks(target=TARGET):
    return [f for f in sys.meta_path if getattr(f, _HOOK, False) and getattr(f, "target", TARGET) == target]


def _remove_hooks(target=TARGET):
    for hook in _hooks(target):
        try:
            sys.meta_path.remove(hook)
        except ValueError:
            pass


def _after_import(target, action, failure):
    """Run ``action(module)`` once ``target`` is imported (a pending action
    for ``target`` is replaced)."""
    hooks = _hooks(target)
    if hooks:
        hooks[0].action, hooks[0].failure = action, failure
        return
    sys.meta_path.insert(0, _Hook(target, action, failure))


def _warn(text):
    try:
        import FreeCAD

        FreeCAD.Console.PrintWarning(text + "\n")
    except Exception:
        sys.stderr.write(text + "\n")


def register(folder=POSTS_DIR):
    """Add ``folder`` (default: this add-on's postprocessors/) to FreeCAD's
    post search path for this session. Safe to call any number of times."""
    module = sys.modules.get(TARGET)
    if module is not None and hasattr(module, FUNCTION):
        _remove_hooks(TARGET)
        _wrap(module, folder)
        return
    _after_import(TARGET, lambda module: _wrap(module, folder),
                  "could not add the lathe posts to the CAM post list")


def unregister(folder=POSTS_DIR):
    """Undo :func:`register`: FreeCAD's post search path is its own again.
    (Where FreeCAD has addAddonPostPath it has no way to take a folder out:
    only a pending registration is dropped.)"""
    _remove_hooks()
    module = sys.modules.get(TARGET)
    if module is None:
        return
    current = getattr(module, FUNCTION, None)
    wrapper = _wrapper_of(current)
    if wrapper is None:
        return
    folders = getattr(wrapper, _MARK)
    folders[:] = [f for f in folders if not _same(f, folder)]
    if not folders and current is wrapper:
        setattr(module, FUNCTION, wrapper.__wrapped__)


def is_registered(folder=POSTS_DIR):
    """True when FreeCAD's post search path holds ``folder`` (imports Path.Preferences)."""
    import Path.Preferences

    return any(p and _same(p, folder) for p in Path.Preferences.searchPathsPost())


def _install_shapes(module):
    if not hasattr(module, "cam_assets"):  # FreeCAD 1.0: no asset based tool bits
        return
    from freecad_groove.freecad import shape_assets

    shape_assets.install(module.cam_assets)


def register_shapes():
    """Put the grooving blade among FreeCAD 1.1's built-in tool bit shapes
    (freecad_groove.freecad.shape_assets) once CAM imports ``Path.Tool``, or
    now if it has. Nothing in FreeCAD 1.0. Safe to call any number of times."""
    module = sys.modules.get(SHAPES_TARGET)
    if module is not None:
        _remove_hooks(SHAPES_TARGET)
        _install_shapes(module)
        return
    _after_import(SHAPES_TARGET, _install_shapes, "could not add the grooving shape to CAM's tool bit shapes")


def unregister_shapes():
    """Undo :func:`register_shapes`."""
    _remove_hooks(SHAPES_TARGET)
    if SHAPES_TARGET in sys.modules:
        from freecad_groove.freecad import shape_assets

        shape_assets.uninstall()
