"""The Groove op's Path from its plans: G18, then per groove a comment naming
the face and the call, the link rapids (G0), the engine's expanded moves (G0,
G1 with the op's feed in FreeCAD's mm/s, G4 P<seconds>) and, after the op's
last groove, the rapids back to its safe start point.

FreeCAD layer: Path only.
"""

import Path

from ...engine.moves import DWELL, FEED, RAPID
from ...freecad.addon_op import comment_body
from .plan import GroovePlan


def path_commands(plans: list[GroovePlan], feed_mm_per_s: float) -> list:
    """Path commands (Path.Command) for ``plans``: G18, then per groove a
    comment, the link rapids and the expanded moves, feeds at ``feed_mm_per_s``."""
    commands = [Path.Command("G18")]
    for plan in plans:
        title = "%s groove %d: %s" % (plan.face.name, plan.index + 1, plan.cycle.emit())
        commands.append(Path.Command(comment_body(title)))
        commands.extend(_link_commands(plan.link))
        for move in plan.moves:
            if move.kind == RAPID:
                commands.append(Path.Command("G0", {"X": move.x, "Z": move.z}))
            elif move.kind == FEED:
                commands.append(Path.Command("G1", {"X": move.x, "Z": move.z, "F": feed_mm_per_s}))
            elif move.kind == DWELL:
                commands.append(Path.Command("G4", {"P": move.p}))
        commands.extend(_link_commands(plan.retreat))
    return commands


def _link_commands(steps: list) -> list:
    """A G0 per link step [LinkMove], with the axes it moves."""
    return [Path.Command("G0", {axis: value for axis, value in zip("XZ", step) if value is not None})
            for step in steps]
