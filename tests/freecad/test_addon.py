"""What the add-on declares and registers in FreeCAD 1.1 and 1.0: package.xml
read by FreeCAD's own metadata reader (what the Addon Manager and the
development version's post discovery read), the post folder through
Path.Preferences.addAddonPostPath where FreeCAD has it, and the op's entry in
CAM's SetupSheet registry.
"""

import glob
import os
import types

import FreeCAD
import Path.Base.SetupSheet as PathSetupSheet
import Path.Log
import test_groove_op as tg
from parts import face_name

from freecad_groove import make_groove
from freecad_groove.freecad import registration
from freecad_groove.ops.groove import KIND as GROOVE

doc, shop = tg.doc, tg.shop
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def metadata():
    return FreeCAD.Metadata(os.path.join(ROOT, "package.xml"))


def test_package_xml_declares_what_the_add_on_contains():
    md = metadata()
    assert md.Name == "freecad-groove"
    assert md.supportsCurrentFreeCAD()
    assert os.path.isfile(os.path.join(ROOT, md.Icon))
    assert [d["package"] for d in md.Depend] == ["cam", "matplotlib"]
    # matplotlib (plot): optional, offered by the Addon Manager; the turning check needs numpy only (FreeCAD's)
    assert [bool(d.get("optional")) for d in md.Depend] == [False, True]
    # FreeCAD runs Init.py and InitGui.py from the folder of a workbench entry;
    # the add-on has no workbench class (it adds to CAM's), so no classname.
    (entry,) = md.Content["workbench"]
    for name in ("Init.py", "InitGui.py"):
        assert os.path.isfile(os.path.join(ROOT, entry.Subdirectory, name))
    assert entry.Classname == ""
    assert set(md.Content) == {"workbench", "Postprocessor"}
    # The post folder, as FreeCAD's development version looks for it.
    (posts,) = md.Content["Postprocessor"]
    folder = os.path.join(ROOT, posts.Subdirectory)
    names = sorted(os.path.basename(p) for p in glob.glob(os.path.join(folder, "*_post.py")))
    assert names == ["ab9_grind_post.py", "ab9_lathe_post.py", "fanuc_lathe_post.py", "gsk_lathe_post.py",
                     "haas_lathe_post.py", "linuxcnc_grind_post.py", "linuxcnc_lathe_post.py",
                     "milltronics_mill_post.py", "sinumerik_lathe_post.py"]


def fake_preferences(with_add):
    """A Path.Preferences stand-in: FreeCAD's development version (with_add) or 1.0/1.1."""
    module = types.ModuleType("Path.Preferences")
    module.extra = []
    module.searchPathsPost = lambda: ["/usr/share/freecad/Mod/CAM/Path/Post/scripts/"] + module.extra
    if with_add:
        module.addAddonPostPath = lambda path: module.extra.append(path) if path not in module.extra else None
    return module


def test_posts_registered_through_add_addon_post_path_where_freecad_has_it():
    module = fake_preferences(with_add=True)
    original = module.searchPathsPost
    registration._wrap(module, registration.POSTS_DIR)
    registration._wrap(module, registration.POSTS_DIR)
    assert module.extra == [registration.POSTS_DIR]  # FreeCAD's route, once
    assert module.searchPathsPost is original  # nothing wrapped
    # Already found by FreeCAD's package.xml scan (a symlinked Mod folder, say): not added again.
    module = fake_preferences(with_add=True)
    module.extra.append(os.path.join(ROOT, ".", "postprocessors"))
    registration._wrap(module, registration.POSTS_DIR)
    assert len(module.extra) == 1


def test_posts_registered_by_wrapping_where_freecad_has_no_add_addon_post_path():
    module = fake_preferences(with_add=False)
    registration._wrap(module, registration.POSTS_DIR)
    assert registration.POSTS_DIR in module.searchPathsPost()
    import Path.Preferences as Prefs

    if not hasattr(Prefs, registration.ADD_FUNCTION):  # FreeCAD 1.0 and 1.1
        assert registration._wrapper_of(Prefs.searchPathsPost) is not None


def test_a_new_op_finds_its_setup_sheet_entry(shop, monkeypatch):
    doc, shaft, job, tc = shop
    logged = []
    monkeypatch.setattr(Path.Log, "info", lambda text, *a, **k: logged.append(str(text)))
    op = make_groove(job, (shaft, face_name(shaft.Shape, "cylinder")), name="Cutoff", width=4, depth=1,
                     tool_width=3)
    assert op.Proxy is not None
    assert not [t for t in logged if "SetupSheet" in t], logged
    assert GROOVE.name in PathSetupSheet._RegisteredOps
    # The Job's SetupSheet editor builds a prototype of every registered op.
    prototype = PathSetupSheet._RegisteredOps[GROOVE.name].prototype(GROOVE.name)
    assert prototype is not None
    job.SetupSheet.Proxy.setOperationProperties(op, GROOVE.name)
