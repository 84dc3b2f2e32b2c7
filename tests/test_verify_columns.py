"""The column model (verify.turning, program_check: numpy only) against the
shapely oracle (turning_shapely, program_check_shapely) on generated
programs: G75 grooves and CYCLE93 calls at drawn places and sizes, each also
with hand-written G1 plunges into the part (a gouge 0.002 mm to 1.5 mm deep)
and G0 moves through the bar. Both models must give the same verdict and the
same findings (gouges and collisions, each on its line), the gouges' depths
and areas within 1 % (areas to 2e-4 mm^2 where a gouge is thinner than
that), every rapid through stock in both."""

import random

import pytest

from freecad_groove.engine.settings import DEFAULT_SETTINGS
from freecad_groove.verify import program_check, program_check_shapely
from freecad_groove.verify.program_record import record_program

G75 = "G00 X{d0:.3f} Z{z:.3f}\nG75 R0.5\nG75 X{d1:.3f} Z{z1:.3f} P1500 Q{q:.0f} R0. F0.05\n"
CYCLE93 = ("G00 X{d0:.3f} Z{z0:.3f}\n"
           "CYCLE93({spd:.3f}, {z:.3f}, {w:.3f}, {depth:.3f}, 0, {a1:g}, {a2:g}, {r}, 1, 0.2, 5, 0)\n")


def plunge_into_part(rng, radius, z):
    """A G1 plunge beside the grooves, from the bar's surface ``radius`` down by 0.002 to 1.5 mm (a gouge)."""
    depth = rng.choice([0.002, 0.05, 0.4, 1.5])
    return "G00 X{a:.3f} Z{z:.3f}\nG01 X{b:.4f} F0.05\nG00 X{a:.3f}\n".format(
        a=2 * radius + 2, b=2 * (radius - depth), z=z)


def rapid_through_bar(radius, z):
    return "G00 X{a:.3f} Z{z:.3f}\nG00 X{b:.3f} Z{z2:.3f}\nG00 X{a:.3f}\n".format(
        a=2 * radius + 2, b=2 * radius - 4, z=z, z2=z - 3)


def fanuc_program(seed: int) -> str:
    rng = random.Random(seed)
    radius, lines, z = 30.0, ["O1", "G21", "G99", "T0303", "G97 S500 M03"], -5.0
    for _k in range(3):
        width, depth = rng.choice([3.0, 4.5, 7.0]), rng.uniform(1.0, 6.0)
        lines.append(G75.format(d0=2 * radius + 2, z=z, d1=2 * (radius - depth), z1=z - (width - 3.0),
                                q=1000 * min(2.5, max(width - 3.0, 0.5))))
        z -= width + 6.0
        if rng.random() < 0.5:
            lines.append(plunge_into_part(rng, radius, z + 3.0))
        if rng.random() < 0.3:
            lines.append(rapid_through_bar(radius, z + 2.0))
    lines += ["G00 X100. Z50.", "M30"]
    return "\n".join(lines) + "\n", "fanuc", DEFAULT_SETTINGS.with_tool(3.0, rng.choice([0.0, 0.2, 0.4]), None)


def siemens_program(seed: int) -> str:
    rng = random.Random(seed)
    radius, lines, z = 17.5, ["T5 D1 S400 M03", "G95 G90 F0.2", "G00 X80 Z5"], 0.0
    for _k in range(2):
        width, depth = rng.uniform(6.0, 12.0), rng.uniform(2.0, 5.0)
        a1, a2 = rng.choice([0, 5, 15]), rng.choice([0, 10])
        radii = rng.choice(["0, 0, 0, 0, 0, 0", "0.5, 0.5, -1, -1, 0.3, 0.2"])
        lines.append(CYCLE93.format(d0=80.0, z0=z + 5, spd=2 * radius, z=z, w=width, depth=depth,
                                    a1=a1, a2=a2, r=radii))
        z -= width + 8.0
        if rng.random() < 0.5:
            lines.append(plunge_into_part(rng, radius, z + 4.0))
        if rng.random() < 0.3:
            lines.append(rapid_through_bar(radius, z + 3.0))
    lines.append("M02")
    return "\n".join(lines) + "\n", "sinumerik", DEFAULT_SETTINGS.with_tool(3.0, rng.choice([0.0, 0.4]), None)


def findings(result):
    """(line, kind) of each finding."""
    return sorted((line, text.split(":")[0]) for line, text in result.findings)


@pytest.mark.parametrize("program", [fanuc_program(seed) for seed in range(4)] +
                         [siemens_program(seed) for seed in range(3)])
def test_the_column_model_agrees_with_the_shapely_oracle(program):
    text, dialect, settings = program
    record = record_program(text, dialect, settings)
    columns = program_check.check_program("p", record)
    oracle = program_check_shapely.check_program("p", record)
    assert columns.ok == oracle.ok and findings(columns) == findings(oracle), (columns.findings, oracle.findings)
    for mine, theirs in zip(columns.job.ops, oracle.job.ops):
        assert mine.removed == pytest.approx(theirs.removed, rel=0.01, abs=1e-3)
        assert bool(mine.gouge_depth) == bool(theirs.gouge_depth), (mine.label, mine.gouge_depth, theirs.gouge_depth)
        assert mine.gouge_depth == pytest.approx(theirs.gouge_depth, rel=0.01, abs=1e-5)
        assert mine.gouge_area == pytest.approx(theirs.gouge_area, rel=0.01, abs=2e-4)
        assert [h.command for h in mine.rapid_hits] == [h.command for h in theirs.rapid_hits]
        assert bool(mine.leftover) == bool(theirs.leftover), (mine.label, mine.leftover, theirs.leftover)


def test_a_gouge_of_two_thousandths_is_found_with_its_depth():
    text = ("O1\nG21\nG99\nT0303\nG97 S500 M03\nG00 X62. Z-15.\nG75 R0.5\nG75 X50. Z-15. P1500 F0.05\n"
            "G00 X64. Z-30.\nG01 X61.996 F0.05\nG00 X64.\nG00 X100. Z50.\nM30\n")
    record = record_program(text, "fanuc", DEFAULT_SETTINGS.with_tool(3.0, 0.0, None))
    result = program_check.check_program("p", record)
    gouge = [check for check in result.job.ops if check.gouge_depth]
    assert len(gouge) == 1 and gouge[0].gouge_depth == pytest.approx(0.002, rel=0.01)
    assert gouge[0].gouge_area == pytest.approx(3 * 0.001, rel=0.01)  # 3 wide, the 0.001 beyond the tolerance
    assert [line for line, _text in result.findings] == [10]
