"""The lathe posts and the command line's ``expand --native-cycles`` decide alike
(inside FreeCAD 1.1 and 1.0; run by tests/freecad/run_suite.py): a Groove op
posted for a pecking control, and the same groove as a Siemens program's
CYCLE93 translated for that control, give the same pecking call, word for
word, with the same peck retract note, or the same reason for the moves."""

import re
from dataclasses import replace

import pytest
import test_posts as tp

from freecad_groove.engine.translator import translate_program
from freecad_groove.ops.groove.op import op_error

shop, groove, FEED_MM_MIN = tp.shop, tp.groove, tp.FEED_MM_MIN
doc = tp.doc

CASES = {  # name -> (face key, op properties)
    "cylinder_wider_than_the_blade": ("cylinder", {}),
    "cylinder_blade_wide": ("cylinder", dict(width=3)),
    "bore": ("bore", {}),
    "shoulder_face": ("shoulder", {}),
    "left_end_face": ("left_end", dict(width=3)),
    "flank_angle": ("cylinder", dict(flank_angle1=5)),
    "base_allowance": ("cylinder", dict(base_allowance=0.1)),
    "edge_chamfer": ("cylinder", dict(edge_corner2=0.3, edge_corner2_type="Chamfer")),
    "oblique_contour": ("cone_up", {}),
}


def siemens_program(op):
    """The op's one groove as a Siemens program: the feed per minute the op cuts at, a rapid to
    the op's start point, its CYCLE93 call."""
    (cycle, _settings, start), = op.Proxy.cycles(op)
    return "G18 G71 G90 G94 F%r\nG0 X%r Z%r\n%s\nM2\n" % (FEED_MM_MIN, 2.0 * start.x, start.z, cycle.emit())


def decision(text, name):
    """What a program says of its groove: the native calls, the peck retract notes, the reasons for moves."""
    return (tp.calls(text, name), re.findall(r"\((peck retract e = [^)]*)\)", text),
            re.findall(r"\(expanded: ([^)]*)\)", text))


@pytest.mark.parametrize("name", tp.PECKING)
@pytest.mark.parametrize("case", sorted(CASES))
def test_the_posts_and_the_command_line_decide_alike(shop, name, case):
    key, extra = CASES[case]
    op = groove(shop, key, **extra)
    assert op_error(op) is None, op_error(op)
    (_cycle, settings, _start), = op.Proxy.cycles(op)
    retract = op.Retract.Value or 1.0  # the posts' peck retract: the op's Retract (0 = 1 mm), as --retract
    posted = tp.export(name, [op])
    command_line = translate_program(siemens_program(op), "sinumerik", replace(settings, peck_retract=retract),
                                     target=name, native_cycles=True)
    ours, theirs = decision(posted, name), decision(command_line, name)
    assert ours == theirs, "%s\n----\n%s" % (posted, command_line)
    assert ours[0] or ours[2]  # a call or a reason


