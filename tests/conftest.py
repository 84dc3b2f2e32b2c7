"""Test configuration shared by every test module.

* Puts the repository root (for ``freecad_groove``) and this folder (for the
  helper modules such as ``rs274``) on sys.path.
* Hypothesis profiles: "ci" (derandomized, 200 examples) when the CI
  environment variable is set (and not 0/false/no), else "dev" (60
  examples). Override with ``--hypothesis-profile ci``. Neither has a
  deadline: a simulated groove takes 10-50 ms.
* tests/freecad/ holds FreeCAD-level tests: they run inside FreeCAD
  (tests/freecad/run_suite.py, driven by tests/test_freecad.py), so the host's
  pytest, which has no FreeCAD, does not collect them.
"""

import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
# The example programs in examples/ (one per control) and their dialects.
EXAMPLES = {
    "seed_cycle93.mpf": "sinumerik",
    "ab9_g77.nc": "ab9",
    "fanuc_g75.nc": "fanuc",
    "haas_g75.nc": "haas",
}
for path in (ROOT, HERE):
    if path not in sys.path:
        sys.path.insert(0, path)

# Inside FreeCAD (run_suite.py) FreeCAD is already imported; on the host it is not.
collect_ignore = [] if "FreeCAD" in sys.modules else ["freecad", "freecad_gui"]

from hypothesis import settings  # noqa: E402

settings.register_profile("ci", deadline=None, derandomize=True, max_examples=200)
settings.register_profile("dev", deadline=None, max_examples=60)
IN_CI = os.environ.get("CI", "").strip().lower() not in ("", "0", "false", "no")
settings.load_profile("ci" if IN_CI else "dev")
