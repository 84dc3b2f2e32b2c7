"""What verify's work grows with (issue 22: 2000 calls within 10x the time
of 200): the shapes' edges are held in pieces short along Z only (the test
fails with the code before: 2006 pieces of a CYCLE93's air, not 8), a
gouge's hint takes capsules on the lines of the columns it cuts only and
leaves a rounding residue alone (fails before: the residue hinted), a union
clipped to an op's lines finds its parts by their sorted low ends, and a
plain step finds the cycle nearest it without scanning the program. The
hint's columns, the union's parts and the plain step keep what the code
before did (their tests pass on it) and fail when the new code slips:
capsules put on the wrong columns, a long part starting far below the lines
missed or the parts out of order, the cycle after a plain step taken where
one stands before it."""

import numpy as np
import pytest
from shapely.geometry import Point, Polygon

from freecad_groove.engine.moves import MINUS_X, MINUS_Z
from freecad_groove.engine.settings import DEFAULT_SETTINGS
from freecad_groove.verify import program_check
from freecad_groove.verify.column_figures import hinted
from freecad_groove.verify.columns import Grid
from freecad_groove.verify.program_record import record_program
from freecad_groove.verify.shapes import Edges, Union, box, distances, rings

AIR = [(0.0, 35.0), (3.0, 35.0), (3.0, 1035.0), (0.0, 1035.0)]  # (z, x): a CYCLE93's air, 1000 mm up


def test_an_edge_across_z_is_one_piece_and_the_nearest_edge_is_found_as_on_the_whole_ring():
    edges = Edges(rings([AIR]))
    # the two edges along Z in pieces of at most 1 mm (3 each), the two across Z whole (2000 pieces before)
    assert len(edges.segments) == 8
    assert np.all(np.abs(edges.segments[:, 2] - edges.segments[:, 0]) <= 1.0)
    wall = edges.near(-0.1, 0.1)  # the edge at z 0 whole, and the first pieces of those along Z
    assert sorted(tuple(sorted((s[1], s[3]))) for s in wall if s[0] == s[2] == 0.0) == [(35.0, 1035.0)]
    ring = Polygon([(z, x) for z, x in AIR]).exterior
    rng = np.random.default_rng(22)
    points = np.column_stack([rng.uniform(-1.0, 4.0, 200), rng.uniform(30.0, 1040.0, 200)])
    for z, x in points:
        found = distances(np.array([[z, x]]), edges.near(z - 5.0, z + 5.0))[0]
        assert found == pytest.approx(ring.distance(Point(z, x)), abs=1e-9)


def test_a_gouge_is_hinted_in_the_columns_whose_cut_lies_farther_than_the_tolerance_from_the_part():
    # ten columns 0.1 wide on z 0..1 and one 0.004 wide after them (narrow: its sides count too); the part a
    # box up to x = 10; what was cut inside it: within 0.001 of its top edge (columns 2 and 7), deeper (5)
    grid = Grid(np.concatenate([np.linspace(0.0, 1.0, 11), [1.004]]))
    part = rings([[(0.0, 0.0), (2.0, 0.0), (2.0, 10.0), (0.0, 10.0)]])
    cut = (np.array([2, 5, 7, 10]), np.array([9.9995, 9.99, 9.9999, 9.9995]), np.array([10.0, 10.0, 10.0, 10.0]))
    kept = hinted(cut, grid, Edges(part), 0.001)
    assert list(kept[0]) == [5]
    assert kept[1][0] == 9.99 and kept[2][0] == 10.0


def test_a_narrow_column_s_cut_is_hinted_where_its_side_lies_farther_than_the_tolerance_from_the_part():
    # the part's wall slants (x = 10 - 5 z near z = 1): at the narrow column's centre (z 1.002) the cut
    # touches it, at its side (z 1.004) it lies 0.01 beyond it in X, 0.002 square to it
    grid = Grid(np.concatenate([np.linspace(0.0, 1.0, 11), [1.004]]))
    part = rings([[(0.0, 0.0), (1.2, 0.0), (1.2, 4.0), (1.0, 5.0), (0.0, 5.0)]])
    x = 5.0 - 5.0 * 0.002
    cut = (np.array([3, 10]), np.array([4.9995, x - 1e-4]), np.array([5.0, x]))
    kept = hinted(cut, grid, Edges(part), 0.001)
    assert list(kept[0]) == [10]


def test_a_rounding_residue_on_the_part_s_wall_in_a_narrow_column_is_not_hinted():
    # as above, the row 1e-11 thick on the wall (where a blade finishing the wall leaves one by rounding):
    # it was hinted, and each such op measured exactly (a fourth of the ops of 2000 CYCLE93 calls)
    grid = Grid(np.concatenate([np.linspace(0.0, 1.0, 11), [1.004]]))
    part = rings([[(0.0, 0.0), (1.2, 0.0), (1.2, 4.0), (1.0, 5.0), (0.0, 5.0)]])
    x = 5.0 - 5.0 * 0.002
    kept = hinted((np.array([10]), np.array([x]), np.array([x + 1e-11])), grid, Edges(part), 0.001)
    assert not len(kept[0])


def test_a_union_clipped_keeps_the_parts_that_reach_the_lines_in_their_order():
    # many short parts and a few long ones (a long one starting far below the lines still reaches them)
    rng = np.random.default_rng(7)
    lows = rng.uniform(0.0, 1000.0, 400)
    lengths = np.where(rng.random(400) < 0.02, rng.uniform(100.0, 600.0, 400), rng.uniform(0.5, 5.0, 400))
    parts = tuple(box(z, 0.0, z + length, 1.0 + k) for k, (z, length) in enumerate(zip(lows, lengths)))
    union = Union(parts)
    for zlo in rng.uniform(-10.0, 1010.0, 50):
        zhi = zlo + rng.choice([0.0, 0.3, 20.0])
        expected = [k for k, (z, length) in enumerate(zip(lows, lengths)) if z <= zhi and z + length >= zlo]
        # each part is a box of its own height 1 + k: the clipped union's parts say which they are
        assert [int(p.rings[0][:, 1].max()) - 1 for p in union.clipped(zlo, zhi).parts] == expected


PROGRAM = """O1
G21
G99
T0303
G97 S500 M03
G00 X62. Z2.
G01 X61. F0.1
G00 X50. Z2.
G74 R0.5
G74 X46. Z-3. P1000 Q1500 F0.05
G00 X62. Z2.
G01 X61.5 F0.1
G00 X62. Z-20.
G75 R0.5
G75 X50. Z-20. P1500 F0.05
G01 X63. F0.1
M30
"""


def test_a_plain_step_cuts_as_the_cycle_before_it_holds_its_blade_else_as_the_one_after():
    record = record_program(PROGRAM, "fanuc", DEFAULT_SETTINGS.with_tool(3.0, 0.0, None))
    steps = program_check.checked_steps(record)
    kinds = [(step.cycle, step.plunge) for step in steps]
    assert kinds == [(False, MINUS_Z),  # before any cycle: the face groove's G74 after it
                     (True, MINUS_Z),
                     (False, MINUS_Z),  # between the two: the G74 before it, not the G75 after it
                     (True, MINUS_X),
                     (False, MINUS_X)]
