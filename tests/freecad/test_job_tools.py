"""A Job's tool controllers as a LinuxCNC tool table (freecad/job_tools.py):
each grooving blade's orientation from the Groove ops that cut with it, the
Job's end mill by its diameter; ops that disagree are refused by name."""

import pytest
import test_groove_op as tg
from parts import face_name

from freecad_groove import make_groove
from freecad_groove.freecad import toolbit
from freecad_groove.freecad.job_tools import ToolTableError, linuxcnc_tool_table_of

doc, shop = tg.doc, tg.shop


def _groove(shop, tc, face, **extra):
    _doc, shaft, job, _first = shop
    kw = dict(position=5, width=4, depth=2, infeed=1)
    kw.update(extra)
    return make_groove(job, (shaft, face_name(shaft.Shape, face)), tool_controller=tc, **kw)


def test_a_jobs_blades_and_end_mill_by_hand(shop):
    _doc, _shaft, job, first = shop
    outside = toolbit.make_grooving_tool_controller(job, 3, 0.2)
    inside = toolbit.make_grooving_tool_controller(job, 2, 0.1)
    _groove(shop, outside, "cylinder")  # external, ReferenceCorner minus by default
    bore = _groove(shop, inside, "bore", width=3, depth=1)
    bore.ReferenceCorner = "plus"
    job.Document.recompute()
    lines = linuxcnc_tool_table_of(job).splitlines()
    assert lines[0].startswith(";LinuxCNC lathe tool table from the Job %s, lengths in mm" % job.Label)
    # the blade cutting the outside from its -Z corner: control point at low X, low Z: LinuxCNC's Q2; the bore's
    # from its +Z corner: high X, high Z: Q4. D is twice the corner radius; the end mill its 5 mm diameter.
    by_number = {int(line.split()[0][1:]): line for line in lines[1:]}
    assert by_number[int(outside.ToolNumber)].startswith(
        "T%d P%d D0.4 I90 J0 Q2 ;T%d: grooving blade 3 mm, corner radius 0.2, reference minus, external"
        % ((int(outside.ToolNumber),) * 3))
    assert by_number[int(inside.ToolNumber)].startswith(
        "T%d P%d D0.2 I270 J180 Q4 ;" % ((int(inside.ToolNumber),) * 2))
    diameter = first.Tool.Diameter.Value
    assert by_number[int(first.ToolNumber)].startswith("T%d P%d D%g ;" % (int(first.ToolNumber),
                                                                           int(first.ToolNumber), diameter))


def test_one_blade_cut_two_ways_is_refused_naming_the_ops(shop):
    _doc, _shaft, job, _first = shop
    tc = toolbit.make_grooving_tool_controller(job, 3, 0.2)
    one = _groove(shop, tc, "cylinder")
    two = _groove(shop, tc, "cylinder", position=15)
    two.ReferenceCorner = "plus"
    job.Document.recompute()
    with pytest.raises(ToolTableError) as info:
        linuxcnc_tool_table_of(job)
    message = str(info.value)
    assert message.startswith(tc.Label + ": its ops cut with it in 2 ways")
    assert one.Label in message and two.Label in message


def test_a_blade_no_op_uses_is_refused_its_side_unknown(shop):
    _doc, _shaft, job, _first = shop
    tc = toolbit.make_grooving_tool_controller(job, 3, 0.2)
    with pytest.raises(ToolTableError, match="^%s: no Groove op cuts with its grooving blade" % tc.Label):
        linuxcnc_tool_table_of(job)
