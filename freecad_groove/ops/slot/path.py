"""A Cylinder slot op's Path from its plan: a comment naming the face and the
region (its start block), G18, G0 X to the safe radius, G0 Z C to the path's
start (G0 X down to the region's clearance radius when that is below the safe
radius), the region's moves (G0/G1 with X, Z, C; F in FreeCAD's mm/s: for a
move that turns C only it is the engine's degrees per minute over 60), then
G0 X back to the safe radius.

FreeCAD layer: Path only.
"""

import Path

from ...engine.moves import FEED, RAPID
from ...freecad.addon_op import comment_body
from ...freecad.units import SECONDS_PER_MINUTE


def path_commands(plan: object) -> list:
    """The op's Path commands after its label for ``plan`` (plan.SlotPlan; see the module notes)."""
    start = plan.start
    commands = [Path.Command(comment_body("%s: %s" % (plan.cylinder.name, plan.region.emit().split("\n")[0]))),
                Path.Command("G18"),
                Path.Command("G0", {"X": plan.safe_radius}),
                Path.Command("G0", {"Z": start.z, "C": start.c})]
    if plan.safe_radius != start.x:
        commands.append(Path.Command("G0", {"X": start.x}))
    for move in plan.moves:
        words = {"X": move.x, "Z": move.z, "C": move.c}
        if move.kind == FEED:
            words["F"] = move.f / SECONDS_PER_MINUTE
            commands.append(Path.Command("G1", words))
        elif move.kind == RAPID:
            commands.append(Path.Command("G0", words))
    commands.append(Path.Command("G0", {"X": plan.safe_radius}))
    return commands

