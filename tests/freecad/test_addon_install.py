"""The add-on installed by FreeCAD's own Addon Manager code, headless: its
AddonInstaller copies a local clone of this checkout into a fresh user data
folder's Mod, and a new freecadcmd started on that folder alone finds the
add-on: its ops, its posts in CAM's post list, the package's version.

(FreeCAD's Addon Manager installs a local folder by copying it, a zip by
extracting it, a remote repository with git, which the test roots lack: the
copy is the one it can do here. The GUI commands need the GUI: the GUI suite
finds them in CAM's toolbar and menu.)"""

import json
import os
import shutil
import subprocess
import sys

import FreeCAD
import pytest

CHECKOUT = os.environ.get("FREECAD_GROOVE_CHECKOUT") or os.path.dirname(
    os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
NAME = "freecad-groove"
POSTS = sorted(name[:-len("_post.py")] for name in os.listdir(os.path.join(CHECKOUT, "postprocessors"))
               if name.endswith("_post.py"))
CHILD = r"""
import json, os, sys
import FreeCAD
import Path.Preferences as preferences
import freecad_groove
from freecad_groove.ops import registry
import freecad_groove.ops
posts = preferences.allAvailablePostProcessors()
print("RESULT " + json.dumps({"package": os.path.dirname(os.path.dirname(freecad_groove.__file__)),
                              "version": freecad_groove.__version__, "posts": sorted(posts),
                              "ops": [k.name for k in registry.kinds()],
                              "mod": os.path.join(FreeCAD.getUserAppDataDir(), "Mod")}))
"""


def local_clone(dest):
    """This checkout's files as a clone has them (no virtualenv, build output or caches)."""
    ignore = shutil.ignore_patterns(".git", ".venv", "out", "__pycache__", "*.pyc", ".pytest_cache", ".hypothesis")
    shutil.copytree(CHECKOUT, dest, ignore=ignore)
    return dest


def test_the_addon_managers_installer_installs_it_and_freecad_finds_ops_and_posts(tmp_path):
    try:
        sys.path.insert(0, os.path.join(FreeCAD.getHomePath(), "Mod", "AddonManager"))
        from Addon import Addon
        from addonmanager_installer import AddonInstaller, InstallationMethod
    except ImportError as exc:
        pytest.skip("FreeCAD %s has no Addon Manager to drive headless (%s)" % (FreeCAD.Version()[1], exc))
    clone = local_clone(str(tmp_path / "clone"))
    data = tmp_path / "userdata"
    addon = Addon(NAME, url=clone, branch="main")
    addon.icon_data = None  # no QtGui icon headless
    installer = AddonInstaller(addon, allow_list=[])  # a list given: no download of the allowed packages
    installer.installation_path = str(data / "Mod")
    assert installer.run(InstallationMethod.COPY)
    installed = data / "Mod" / NAME
    assert (installed / "package.xml").is_file() and (installed / "postprocessors").is_dir()
    # a clean environment: the running FreeCAD's own variables (its Python's paths) would crash the child
    env = {key: os.environ[key] for key in ("PATH", "HOME", "LANG", "TMPDIR") if key in os.environ}
    env["FREECAD_USER_DATA"] = str(data)
    child = tmp_path / "child.py"  # through a file: freecadcmd -c with a text of many lines crashed at start
    child.write_text(CHILD)
    proc = subprocess.run(["freecadcmd", "-c", "exec(open(%r).read())" % str(child)], capture_output=True, text=True,
                          env=env, timeout=600, cwd=str(tmp_path))
    lines = [line for line in proc.stdout.splitlines() if line.startswith("RESULT ")]
    assert lines, "status %d\n%s\n%s" % (proc.returncode, proc.stdout[-3000:], proc.stderr[-3000:])
    found = json.loads(lines[-1][len("RESULT "):])
    assert os.path.realpath(found["package"]) == os.path.realpath(str(installed)), found
    assert found["version"] == __import__("freecad_groove").__version__
    assert set(POSTS) <= set(found["posts"]), found["posts"]
    assert found["ops"] == ["Groove", "CylinderSlot", "PlungeGrind"]
