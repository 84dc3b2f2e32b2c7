"""The verification layer: material-removal simulation of expanded grooving
moves and the verdict on the groove they cut. Today it is the tests' oracle.

Two models of the material. The column model (``columns``, ``shapes``,
``column_sweep``, ``column_reach``, ``column_figures``; ``turning``,
``turned_section``, ``program_check``) needs numpy only: verify_job (FreeCAD
ships numpy, not shapely) and the command line's verify and plot run it. The
shapely model (everything else; ``turning_shapely``, ``section``,
``program_check_shapely``) is the tests' oracle and second opinion. Both
import the engine (``freecad_groove.engine.moves``), never FreeCAD or Qt; the
engine never imports this package. plot.py imports matplotlib (``plot``
only).

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

# The shapely oracle's names, imported when first asked for: the column model
# (turning, program_check, plot) needs numpy only, and FreeCAD has no shapely.
_LAZY = {
    "ARC_EXCESS": "outline", "swept_area": "blade", "tool_outline": "blade", "DEPTH_PRECISION": "depth",
    "NOISE_AREA": "overlay", "QUAD_SEGS": "overlay", "FIT_SLACK": "reach", "reachable_region": "reach",
    "unreachable_region": "reach", "bar": "stock", "region": "stock", "RAPID_AREA_TOL": "sweep",
    "RAPID_SKIN": "sweep", "DwellMismatch": "sweep", "RapidCollision": "sweep", "SimulationResult": "sweep",
    "simulate": "sweep", "Verdict": "verdict", "assert_clean": "verdict", "check_groove": "verdict",
}


def __getattr__(name: str):
    if name in _LAZY:
        import importlib

        return getattr(importlib.import_module("." + _LAZY[name], __name__), name)
    raise AttributeError("module %r has no attribute %r" % (__name__, name))


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
