"""The Groove op's Dwell goes through the engine's one bound on CYCLE93 DWT (issue 20, item 9): 0 to 99999 s,
the longest dwell every target writes. A Dwell beyond it makes the op Invalid with the engine's one-line
message naming Dwell, leaves no toolpath, and every lathe post refuses the op (the Siemens post wrote it as
DWT before); the bound itself is cut and posted."""

import pytest
import test_groove_op as tg
import test_posts as tp

from freecad_groove.freecad import posts
from freecad_groove.ops.groove.op import op_error

# The Groove op tests' stepped shaft, Job and helpers (doc and shop are fixtures).
doc, shop, groove = tg.doc, tg.shop, tg.groove
RULE = "the dwell must be 0 to 99999 s, the longest every target writes"


@pytest.mark.parametrize("dwell, message", [
    (99999.5, "Dwell: CYCLE93 DWT=99999.5: " + RULE),  # the engine's bound, the property named first
    (1e6, "Dwell: CYCLE93 DWT=1000000: " + RULE),
    (1e308, "Dwell=1e+308 s: must be 0 <= Dwell <= 99999 s"),  # the op's own bound (docs/op-bounds.md) first
])
def test_a_dwell_beyond_the_bound_makes_the_op_invalid_naming_dwell(shop, dwell, message):
    doc_, shaft, job, tc = shop
    op = groove(shop, "cylinder")
    assert tg.path_moves(op)
    op.Dwell = dwell
    doc_.recompute()
    assert op_error(op) == message
    assert tg.path_moves(op) == []  # no stale toolpath
    for name in tp.NAMES:
        with pytest.raises(posts.PostError) as info:
            tp.export(name, [op])
        assert str(info.value) == "%s: %s" % (op.Label, message), name


def test_the_bound_itself_is_cut_and_written_as_the_sinumerik_call(shop):
    doc_, shaft, job, tc = shop
    op = groove(shop, "cylinder", dwell=99999.0)
    assert op_error(op) is None
    dwells = [params for name, params in tg.path_moves(op) if name == "G4"]
    assert dwells and all(params == {"P": 99999.0} for params in dwells)
    program = tp.export("sinumerik", [op], "--native-cycles")
    calls = [line for line in program.splitlines() if line.startswith("CYCLE93(")]
    assert len(calls) == 1 and calls[0].split(",")[14].strip() == "99999", calls
