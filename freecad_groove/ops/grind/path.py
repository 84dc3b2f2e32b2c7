"""A Plunge grind op's Path from its plan: G17, a comment with the call, G0
to the safe height (the top of the stock and model + Retract), G0 over the
start, G0 down to it, the engine's expansion (G1 X Y Z at the move's feed in
mm/s; a dress call as the comment "(DRESS P<n>)"), G0 back to the safe
height. The plan's axes map the grinder's words to FreeCAD's (op.py).

FreeCAD layer: Path only.
"""

import Path

from ...engine.moves import DRESS, FEED
from ...freecad.addon_op import comment_body
from ...freecad.units import SECONDS_PER_MINUTE


def path_commands(plan: object) -> list:
    """The op's Path commands for ``plan`` (plan.GrindPlan; see the module notes)."""
    start, (recip, plunge, cross) = plan.start, plan.axes
    commands = [Path.Command("G17"), Path.Command(comment_body("%s: %s" % (plan.face_name, plan.call.emit()))),
                Path.Command("G0", {plunge: plan.safe_z}), Path.Command("G0", {recip: start.x, cross: start.z}),
                Path.Command("G0", {plunge: start.y})]
    for move in plan.moves:
        if move.kind == FEED:
            commands.append(Path.Command("G1", {recip: move.x, cross: move.z, plunge: move.y,
                                                "F": move.f / SECONDS_PER_MINUTE}))
        elif move.kind == DRESS:
            commands.append(Path.Command(comment_body("DRESS P%d" % move.p)))
    commands.append(Path.Command("G0", {"Z": plan.safe_z}))
    return commands
