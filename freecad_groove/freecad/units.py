"""FreeCAD's units as the engine and the posts need them.

FreeCAD keeps lengths in mm and feeds (a tool controller's HorizFeed, a Path's
F words) in mm/s; the engine and every control program feeds in mm/min.
"""

SECONDS_PER_MINUTE = 60.0


def length_mm(value: object) -> float:
    """A length property (a FreeCAD Quantity) or a plain number, in mm."""
    return float(value.Value) if hasattr(value, "Value") else float(value)


def feed_mm_per_min(mm_per_s: float) -> float:
    """A FreeCAD feed (mm/s) in mm/min."""
    return mm_per_s * SECONDS_PER_MINUTE
