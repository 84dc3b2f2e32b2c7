"""The holder check (verify/holder.py) against a second model on shapely polygons, generated: random plunges
(external and face, with side steps) into a bar, random blades, reaches and holder widths (a fixed seed). The
oracle draws the holder by hand from the blade's geometry (not from holder.py): beyond the reach behind the cutting
edge, the holder's width centred on the blade; the material a move's holder may not enter is the bar less what the
blade swept in the feeds up to that move. Every move whose holder enters more than the column model's sampling
error is a hit with the same area; none whose holder enters nothing is."""

import random

import pytest
import shapely
from shapely.geometry import box as sbox

from freecad_groove.engine.moves import FEED, MINUS_X, MINUS_Z, RAPID, GroovingTool, Move
from freecad_groove.verify.blade import swept_area
from freecad_groove.verify.holder import HOLDER_LENGTH, Holder
from freecad_groove.verify.shapes import box
from freecad_groove.verify.turning import GrooveRun, OpInput, check_ops

BAR_R, BAR_Z0, BAR_Z1 = 30.0, -80.0, 0.0
CASES = 24


def holder_rect(plunge, tool, holder, x, z):
    """The holder (z, x) with the blade's minus reference corner at (x, z), drawn from the blade's geometry."""
    w, h, v0, v1 = tool.width, holder.width, holder.reach, holder.reach + HOLDER_LENGTH
    if plunge == MINUS_X:  # blade over z..z+w, its body toward +X
        return sbox(z + w / 2 - h / 2, x + v0, z + w / 2 + h / 2, x + v1)
    return sbox(z + v0, x + w / 2 - h / 2, z + v1, x + w / 2 + h / 2)  # MINUS_Z: over x..x+w, body toward +Z


def holder_sweep(plunge, tool, holder, a, b):
    return shapely.union(holder_rect(plunge, tool, holder, *a), holder_rect(plunge, tool, holder, *b)).convex_hull


def case(rng):
    plunge = rng.choice([MINUS_X, MINUS_Z])
    tool = GroovingTool(rng.choice([2.0, 3.0, 4.0]), rng.choice([0.0, 0.2, 0.4]))
    holder = Holder(rng.uniform(3.0, 14.0), tool.width + rng.uniform(0.0, 20.0))
    moves, position = [], (BAR_R + 5.0, 5.0) if plunge == MINUS_X else (rng.uniform(5.0, 20.0), 5.0)
    for _ in range(rng.randint(1, 3)):
        depth = rng.uniform(2.0, 14.0)
        if plunge == MINUS_X:
            z = rng.uniform(-60.0, -10.0)
            moves += [Move(RAPID, BAR_R + 2.0, z), Move(FEED, BAR_R - depth, z, f=0.1)]
            if rng.random() < 0.5:
                moves.append(Move(FEED, BAR_R - depth, z + rng.uniform(-3.0, 3.0), f=0.1))
            moves.append(Move(RAPID, BAR_R + 2.0, moves[-1].z))
        else:
            x = rng.uniform(4.0, BAR_R - tool.width - 2.0)
            moves += [Move(RAPID, x, 2.0), Move(FEED, x, -depth, f=0.1)]
            if rng.random() < 0.5:
                moves.append(Move(FEED, x + rng.uniform(-2.0, 2.0), -depth, f=0.1))
            moves.append(Move(RAPID, moves[-1].x, 2.0))
    return plunge, tool, holder, position, moves


def oracle(plunge, tool, holder, start, moves):
    """{move number (1-based): area the holder enters}, the bar less the blade's feeds up to that move."""
    material = sbox(BAR_Z0, 0.0, BAR_Z1, BAR_R)
    areas, position = {}, start
    for k, move in enumerate(moves, 1):
        end = (move.x, move.z)
        if move.kind == FEED:
            material = material.difference(swept_area(tool, plunge, position, end))
        areas[k] = holder_sweep(plunge, tool, holder, position, end).intersection(material).area
        position = end
    return areas


@pytest.mark.parametrize("seed", range(CASES))
def test_the_holder_hits_are_the_oracles(seed):
    rng = random.Random(20_000 + seed)
    plunge, tool, holder, start, moves = case(rng)
    bar = box(BAR_Z0, 0.0, BAR_Z1, BAR_R)
    run = GrooveRun(moves, list(range(1, len(moves) + 1)), tool, plunge, [], holder=holder)
    check = check_ops([OpInput("Op", start, [run])], bar, bar).ops[0]
    found = {hit.command: hit.area for hit in check.holder_hits}
    expected = oracle(plunge, tool, holder, start, moves)
    sampling = 2 * 0.05 * (holder.reach + BAR_R)  # a holder side inside a column: at most a column's width across
    for k, area in expected.items():
        if area > sampling:
            assert k in found and found[k] == pytest.approx(area, abs=sampling), (seed, k, area, found)
        elif area == 0.0:
            assert k not in found, (seed, k, found)
