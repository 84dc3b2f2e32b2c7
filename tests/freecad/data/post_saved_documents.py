"""Records ops_saved_at_3d18f68.programs.json: the programs commit 3d18f68
posts from ops_saved_at_3d18f68.FCStd (make_saved_documents.py) in each
FreeCAD, opened headless and recomputed, every Job through the posts of
tests/freecad/saved_programs.py, and its ops' Paths then.
tests/freecad/test_saved_documents.py does the same with the current code
and compares. (A recompute after reopening is what counts: the Cylinder
slot's safe radius comes from the bounding boxes of the model and stock,
which are not those of the GUI session that saved them.)

Run from the same export of 3d18f68 as the document, in each FreeCAD (the
share holds this script, saved_programs.py and the document; the JSON there
gathers one entry per FreeCAD):

    cp tests/freecad/data/post_saved_documents.py tests/freecad/saved_programs.py \\
       tests/freecad/data/ops_saved_at_3d18f68.FCStd /tmp/saved/
    for v in 1.1 1.0; do
        /tmp/base/scripts/freecad-roots run $v --share /tmp/saved -- sh -c \\
            'exec freecadcmd -M "$FREECAD_GROOVE_CHECKOUT" -c \\
             "exec(open(\\"$FREECAD_GROOVE_SHARE/post_saved_documents.py\\").read())"'
    done
    cp /tmp/saved/ops_saved_at_3d18f68.programs.json tests/freecad/data/

It writes post_saved_documents.log (what it posted, or the traceback).
"""

import json
import os
import sys
import traceback

DOCUMENT = "ops_saved_at_3d18f68"
OPS = ("Groove", "CylinderSlot", "PlungeGrind")


def _record(share, log):
    import FreeCAD

    sys.path.insert(0, share)
    from saved_programs import op_paths, programs

    version = ".".join(FreeCAD.Version()[:2])
    doc = FreeCAD.openDocument(os.path.join(share, DOCUMENT + ".FCStd"))
    for obj in doc.Objects:
        if hasattr(obj, "Proxy") and hasattr(obj, "Path") and type(obj.Proxy).__module__.startswith("freecad_groove"):
            obj.touch()
    doc.recompute()
    posted = programs(os.environ["FREECAD_GROOVE_CHECKOUT"], doc)
    path = os.path.join(share, DOCUMENT + ".programs.json")
    recorded = json.load(open(path)) if os.path.exists(path) else {}
    recorded[version] = {"programs": posted, "paths": op_paths(doc, OPS)}
    with open(path, "w") as f:
        json.dump(recorded, f, indent=1, sort_keys=True)
    log.write("FreeCAD %s: %s\n" % (version, ", ".join("%s %d lines" % (k, len(v.splitlines()))
                                                     for k, v in posted.items())))


def _main():
    share = os.environ["FREECAD_GROOVE_SHARE"]
    with open(os.path.join(share, "post_saved_documents.log"), "a") as log:
        try:
            _record(share, log)
        except BaseException:  # noqa: B902 - everything goes into the log
            log.write(traceback.format_exc())


_main()
