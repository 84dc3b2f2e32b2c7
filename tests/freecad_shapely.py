"""shapely for the FreeCAD runs of the tests (the turning check needs it;
the Debian roots of scripts/freecad-roots do not have it): scripts/shapely_wheels.py,
which scripts/demo uses too.

``provide(share)`` unpacks shapely (the version requirements-test.txt pins)
for each Python the FreeCAD roots run into ``share``/pylib/cpXY and returns
the environment that tells the run where: FREECAD_GROOVE_PYLIB (relative to
FREECAD_GROOVE_SHARE). tests/freecad/test_turning_check.py puts the folder
of its own Python on sys.path. The wheels are downloaded once, with pip, into
out/wheels/. When pip cannot get them the environment is empty and the
FreeCAD turning-check tests skip (under CI=true they fail).
"""

import importlib.util
import os

from conftest import ROOT

_spec = importlib.util.spec_from_file_location("shapely_wheels", os.path.join(ROOT, "scripts", "shapely_wheels.py"))
shapely_wheels = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(shapely_wheels)

PYTHONS = shapely_wheels.PYTHONS
WHEELS = shapely_wheels.WHEELS
pinned_version = shapely_wheels.pinned_version
wheel = shapely_wheels.wheel
provide = shapely_wheels.provide
