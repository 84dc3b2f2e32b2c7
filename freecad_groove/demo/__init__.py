"""Headless FreeCAD demo of every system: one document, four CAM Jobs, their programs from every post.

Runs inside FreeCAD (``freecadcmd``; FreeCAD, Part and Path only, no Qt and
no FreeCADGui)::

    import freecad_groove.demo as demo
    summary = demo.run("/tmp/groove-demo")     # a dict, also summary.json

``scripts/demo`` runs it in FreeCAD 1.1 after the command-line examples and
copies the files to ``out/freecad/`` (see that script); :func:`main` is its
entry point. The document (``demo_part.FCStd``) holds:

* the ``Groove Job`` (shaft.py): a turned shaft, its stock the part as
  turned, five Groove ops; its own turning check (``verify_job``) must run
  clean, its summary goes to ``demo_part_turning_check.txt``;
* the ``Slot Job`` (jobs.py): a Cylinder slot op, a helix on the shaft's
  neck milled with the C axis and a live tool;
* the ``Grind Job``: a Plunge grind op on a block's top;
* the ``Mill Job``: CAM's own Face and Pocket Shape ops on a block.

posting.py posts them (``PROGRAMS``): the Groove ops with the Sinumerik
(CYCLE93), Allen-Bradley (G77/G76), Fanuc and Haas (G75/G74) posts native
and expanded and LinuxCNC; the slot with gsk_lathe (native G7.1) and
linuxcnc_lathe; the grind with ab9_grind (native G83) and linuxcnc_grind; the
mill ops with milltronics_mill (G33/G34). Every native program must hold its
cycle words, every expanded one none, else the demo fails. summary.txt lists
every file written, one line each; summary.json holds the same and more for
tests/test_demo.py.
"""

from .jobs import make_grind_job, make_mill_job, make_slot_job
from .posting import (
    CYCLE_WORDS,
    OUTPUTS,
    PROGRAMS,
    SYSTEMS,
    CycleWordMissing,
    check_cycle_words,
    load_post,
    load_post_file,
    native_calls,
)
from .runner import TURNING_CHECK_FILE, TurningCheckNotClean, main, run
from .shaft import DOCUMENT, FACES, OPS, PROFILE, face_names, make_job, make_ops, make_part, turned_stock

__all__ = [
    "CYCLE_WORDS", "DOCUMENT", "FACES", "OPS", "OUTPUTS", "PROFILE", "PROGRAMS", "SYSTEMS", "TURNING_CHECK_FILE",
    "CycleWordMissing", "TurningCheckNotClean", "check_cycle_words", "face_names", "load_post", "load_post_file",
    "main", "make_grind_job", "make_job", "make_mill_job", "make_ops", "make_part", "make_slot_job",
    "native_calls", "run", "turned_stock",
]
