"""shapely for the FreeCAD roots' test runs (the tests' second oracle of the
turning check; the Debian roots of scripts/freecad-roots do not have it). Python 3 standard library only.

``provide(share)`` unpacks shapely (the version requirements-test.txt pins)
for each Python the FreeCAD roots run (PYTHONS) into ``share``/pylib/cpXY
and returns the environment that tells the run where: FREECAD_GROOVE_PYLIB
(relative to FREECAD_GROOVE_SHARE); inside FreeCAD the tests
(tests/freecad/pylib.py) put the folder of their own Python on
sys.path. The wheels are downloaded once, with pip, into out/wheels/ (PyPI's
manylinux wheels bundle GEOS and use the root's numpy). When no pip can get
them the environment is empty.

    python3 scripts/shapely_wheels.py SHARE   prints FREECAD_GROOVE_PYLIB=pylib, or nothing
                                              (and why on stderr) when shapely could not be had

The tests use it through tests/freecad_shapely.py; scripts/demo runs it.
"""

import os
import re
import subprocess
import sys
import zipfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PYTHONS = ("3.13", "3.14")  # FreeCAD 1.0 (trixie) and 1.1 (sid)
WHEELS = os.path.join(ROOT, "out", "wheels")
PLATFORMS = ("manylinux_2_17_x86_64", "manylinux2014_x86_64")
VENV_PYTHON = os.path.join(ROOT, ".venv", "bin", "python")  # scripts/test's venv, which has pip


def pinned_version(name="shapely"):
    with open(os.path.join(ROOT, "requirements-test.txt")) as f:
        match = re.search(r"^%s==(\S+)" % name, f.read(), re.M | re.I)
    return match.group(1)


def _pips():
    """The interpreters to run pip with: this one, then scripts/test's venv."""
    found = [sys.executable]
    if os.path.exists(VENV_PYTHON):
        found.append(VENV_PYTHON)
    return found


def wheel(python, version):
    """The shapely wheel for ``python`` ("3.13"), downloaded when missing; None when pip cannot get it."""
    tag = "cp" + python.replace(".", "")
    folder = os.path.join(WHEELS, tag)
    os.makedirs(folder, exist_ok=True)

    def found():
        return [f for f in os.listdir(folder) if f.startswith("shapely-%s-%s" % (version, tag)) and f.endswith(".whl")]

    for interpreter in _pips():
        if found():
            break
        platforms = [arg for p in PLATFORMS for arg in ("--platform", p)]
        try:
            subprocess.run([interpreter, "-m", "pip", "download", "-q", "--retries", "1", "--timeout", "20",
                            "--no-deps", "--only-binary=:all:", "--python-version", python, *platforms, "-d", folder,
                            "shapely==%s" % version], capture_output=True, text=True, timeout=300)
        except (OSError, subprocess.TimeoutExpired):
            continue
    return os.path.join(folder, found()[0]) if found() else None


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


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: python3 scripts/shapely_wheels.py SHARE")
    env = provide(sys.argv[1])
    if not env:
        print("shapely %s could not be had for FreeCAD's Pythons %s: no wheel in %s and pip could not download one"
              % (pinned_version(), ", ".join(PYTHONS), WHEELS), file=sys.stderr)
    for key, value in env.items():
        print("%s=%s" % (key, value))
