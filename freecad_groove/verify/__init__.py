"""The verification layer: material-removal simulation of expanded grooving
moves and the verdict on the groove they cut. Today it is the tests' oracle.

It imports the engine (``freecad_groove.engine.moves``) and shapely (>= 2.0)
with numpy, never FreeCAD or Qt; the engine never imports it. FreeCAD does not
bundle shapely: the tests, verify_job and the command line's verify and plot
import this package (plot.py also matplotlib, imported by ``plot`` only).

Geometry lives in the lathe's half plane. A shapely point is ``(z, x)`` with
``x`` the *radius*, so a plot reads like a lathe drawing: Z horizontal, X up.
Functions that take a tool position take ``(x, z)`` like ``moves.Move`` does;
only the shapely geometry is ``(z, x)``.

What the oracle checks (see ``check_groove``):

* gouge: material removed that had to stay (stock minus target) deeper than
  ``tol`` below its surface (the target or the air); reported as the deepest
  such point (mm).
* incomplete: target material still standing farther than ``tol`` from every
  cut surface and the air, not counting what the blade cannot reach
  (``unreachable_region``, grown by ``tol``): the corner-radius fillets.
* infeasible: the target holds material farther than corner radius + ``tol``
  from every place the blade can reach (narrower than the blade, undercut,
  acute corner): no program can make it, the verdict is not ok.
* rapid collision: a RAPID whose swept tool area (less a RAPID_SKIN of
  3e-5 mm) overlaps the stock still standing at that moment by more than
  ``RAPID_AREA_TOL`` mm^2.

Modules: ``overlay`` (robust shapely overlays), ``blade`` (tool outline,
swept area), ``sweep`` (``simulate``), ``reach`` (reachable and unreachable
regions, Minkowski sums), ``depth`` (the distances the verdict reports),
``verdict`` (``check_groove``), ``stock`` (``region``, ``bar``); the command
line's ``program_record`` (a program's moves by line), ``program_check``
(``verify``) and ``plot``.
"""

from .blade import ARC_EXCESS, swept_area, tool_outline
from .depth import DEPTH_PRECISION
from .overlay import NOISE_AREA, QUAD_SEGS
from .reach import FIT_SLACK, reachable_region, unreachable_region
from .stock import bar, region
from .sweep import RAPID_AREA_TOL, RAPID_SKIN, DwellMismatch, RapidCollision, SimulationResult, simulate
from .verdict import Verdict, assert_clean, check_groove

__all__ = [
    "tool_outline",
    "swept_area",
    "simulate",
    "check_groove",
    "assert_clean",
    "unreachable_region",
    "reachable_region",
    "region",
    "bar",
    "SimulationResult",
    "Verdict",
    "RapidCollision",
    "DwellMismatch",
    "ARC_EXCESS",
    "RAPID_SKIN",
    "RAPID_AREA_TOL",
    "NOISE_AREA",
    "QUAD_SEGS",
    "FIT_SLACK",
    "DEPTH_PRECISION",
]
