"""freecad-groove: lathe grooving and canned cycles for FreeCAD's CAM workbench.

``freecad_groove.engine`` is the pure-Python cycle engine (no FreeCAD import);
the FreeCAD operation and GUI layers import FreeCAD only when they are used:
``freecad_groove.make_groove`` loads the FreeCAD layer on its first call.
"""

__version__ = "0.2.0"


def make_groove(*args, **kwargs):
    """Create a Groove operation in a CAM Job (needs FreeCAD); see
    freecad_groove.ops.groove.api.make_groove for the arguments."""
    from .ops.groove.api import make_groove as _make_groove

    return _make_groove(*args, **kwargs)


def make_plunge_grind(*args, **kwargs):
    """Create a Plunge grind operation (9/Series G83) in a CAM Job (needs
    FreeCAD); see freecad_groove.ops.grind.api.make_plunge_grind."""
    from .ops.grind.api import make_plunge_grind as _make_plunge_grind

    return _make_plunge_grind(*args, **kwargs)


def verify_job(*args, **kwargs):
    """The turning check of a CAM Job's Groove ops (needs FreeCAD, whose
    numpy it runs on); see freecad_groove.ops.turning_check.check.verify_job."""
    from .ops.turning_check.check import verify_job as _verify_job

    return _verify_job(*args, **kwargs)


def make_cylinder_slot(*args, **kwargs):
    """Create a Cylinder slot operation in a CAM Job (needs FreeCAD); see
    freecad_groove.ops.slot.api.make_cylinder_slot for the arguments."""
    from .ops.slot.api import make_cylinder_slot as _make_cylinder_slot

    return _make_cylinder_slot(*args, **kwargs)
