"""shapely for the FreeCAD runs of the tests (the turning check needs it;
the Debian roots of scripts/freecad-roots do not have it).

``provide(share)`` unpacks shapely (the version requirements-test.txt pins)
for each Python the FreeCAD roots run (PYTHONS) into ``share``/pylib/cpXY
and returns the environment that tells the run where: FREECAD_GROOVE_PYLIB
(relative to FREECAD_GROOVE_SHARE). tests/freecad/test_turning_check.py puts
the folder of its own Python on sys.path. The wheels are downloaded once,
with pip, into out/wheels/ (PyPI's manylinux wheels bundle GEOS and use the
root's numpy). When pip cannot get them the environment is empty and the
FreeCAD turning-check tests skip (under CI=true they fail).
"""

import os
import re
import subprocess
import sys
import zipfile

from conftest import ROOT

PYTHONS = ("3.13", "3.14")  # FreeCAD 1.0 (trixie) and 1.1 (sid)
WHEELS = os.path.join(ROOT, "out", "wheels")
PLATFORMS = ("manylinux_2_17_x86_64", "manylinux2014_x86_64")


def pinned_version(name="shapely"):
    with open(os.path.join(ROOT, "requirements-test.txt")) as f:
        match = re.search(r"^%s==(\S+)" % name, f.read(), re.M | re.I)
    return match.group(1)


def wheel(python, version):
    """The shapely wheel for ``python`` ("3.13"), downloaded when missing; None when pip cannot get it."""
    tag = "cp" + python.replace(".", "")
    folder = os.path.join(WHEELS, tag)
    os.makedirs(folder, exist_ok=True)
    found = [f for f in os.listdir(folder) if f.startswith("shapely-%s-%s" % (version, tag)) and f.endswith(".whl")]
    if not found:
        platforms = [arg for p in PLATFORMS for arg in ("--platform", p)]
        subprocess.run([sys.executable, "-m", "pip", "download", "-q", "--retries", "1", "--timeout", "20", "--no-deps",
                        "--only-binary=:all:",
                        "--python-version", python, *platforms, "-d", folder, "shapely==%s" % version],
                       capture_output=True, text=True, timeout=300)
        found = [f for f in os.listdir(folder) if f.startswith("shapely-%s-%s" % (version, tag))]
    return os.path.join(folder, found[0]) if found else None


def provide(share):
    """{FREECAD_GROOVE_PYLIB: "pylib"} with shapely unpacked in ``share``/pylib/cpXY; {} when none could be had."""
    version = pinned_version()
    provided = False
    for python in PYTHONS:
        path = wheel(python, version)
        if path is None:
            continue
        with zipfile.ZipFile(path) as archive:
            archive.extractall(os.path.join(str(share), "pylib", "cp" + python.replace(".", "")))
        provided = True
    return {"FREECAD_GROOVE_PYLIB": "pylib"} if provided else {}
