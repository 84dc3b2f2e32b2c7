"""Entry point of the GUI test suite, run by FreeCAD's GUI under Xvfb:

    xvfb-run -a -s "-screen 0 1280x800x24" freecad -M CHECKOUT CHECKOUT/tests/freecad_gui/start.py

(tests/test_freecad.py does this in each FreeCAD root.) It runs
tests/freecad/run_suite.py in its GUI mode: pytest over
tests/freecad_gui/test_*.py, the JSON result in FREECAD_GROOVE_RESULT.
"""

import os

os.environ["FREECAD_GROOVE_SUITE"] = "gui"
_checkout = os.environ.get("FREECAD_GROOVE_CHECKOUT", "/mnt/freecad-groove")
with open(os.path.join(_checkout, "tests", "freecad", "run_suite.py")) as _f:
    exec(compile(_f.read(), _f.name, "exec"))
