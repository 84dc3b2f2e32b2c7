"""The Groove op's Path from its plans: G18, then per groove a comment naming
the face and the call, the link rapids (G0), the engine's expanded moves (G0,
G1 and the arcs G2/G3 with the op's feed in FreeCAD's mm/s, G4 P<seconds>)
and, after the op's last groove, the rapids back to its safe start point.

X is a radius, as everywhere in the op's Path; an arc's I and K are its
centre's offsets from its start (incremental, as FreeCAD CAM holds them), in
mm, I along X as a radius. In G18, G2 turns clockwise seen with Z to the right
and X up, as FreeCAD's own Path geometry reads it.

FreeCAD layer: Path only.
"""

import Path

from ...engine.moves import ARCS, DWELL, FEED, RAPID
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
        commands.extend(move_commands(plan.moves, (plan.start.x, plan.start.z), feed_mm_per_s))
        commands.extend(_link_commands(plan.retreat))
    return commands


def move_commands(moves: list, start: tuple, feed_mm_per_s: float) -> list:
    """Path commands of the engine's ``moves`` from ``start`` (x radius, z)."""
    commands, here = [], start
    for move in moves:
        if move.kind == RAPID:
            commands.append(Path.Command("G0", {"X": move.x, "Z": move.z}))
        elif move.kind == FEED:
            commands.append(Path.Command("G1", {"X": move.x, "Z": move.z, "F": feed_mm_per_s}))
        elif move.kind in ARCS:
            centre = move.centre
            commands.append(Path.Command(move.kind, {"X": move.x, "Z": move.z, "I": centre[0] - here[0],
                                                     "K": centre[1] - here[1], "F": feed_mm_per_s}))
        elif move.kind == DWELL:
            commands.append(Path.Command("G4", {"P": move.p}))
            continue
        here = (move.x, move.z)
    return commands


def _link_commands(steps: list) -> list:
    """A G0 per link step [LinkMove], with the axes it moves."""
    return [Path.Command("G0", {axis: value for axis, value in zip("XZ", step) if value is not None})
            for step in steps]
