"""The programs the posts write for the Jobs of a saved document, and its
ops' Paths: what tests/freecad/data/post_saved_documents.py recorded with the
code that saved the document, and what tests/freecad/test_saved_documents.py
gets with this code. Needs FreeCAD (a document), not pytest; imports nothing of the add-on
(the posts are loaded from their files, as FreeCAD loads a script post), so
the same file serves an older checkout.
"""

import importlib.util
import os

# Job label -> [(post, its arguments)]: each op kind through a native and an expanded post.
JOB_POSTS = {
    "GrooveJob": [("linuxcnc_lathe_post", ""), ("sinumerik_lathe_post", "--native-cycles"),
                  ("fanuc_lathe_post", "")],
    "SlotJob": [("gsk_lathe_post", "--native-cycles --switches-by-hand"),
                ("linuxcnc_lathe_post", "--switches-by-hand")],
    "GrindJob": [("ab9_grind_post", ""), ("linuxcnc_grind_post", "")],
}


def post_module(checkout, name):
    """postprocessors/<name>.py of ``checkout``, loaded from its file."""
    spec = importlib.util.spec_from_file_location(name, os.path.join(checkout, "postprocessors", name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def job_named(doc, label):
    """The Job of ``doc`` labelled ``label``."""
    jobs = [o for o in doc.Objects if o.Label == label and hasattr(o, "Operations")]
    assert len(jobs) == 1, (label, [o.Label for o in doc.Objects])
    return jobs[0]


def programs(checkout, doc):
    """{"Job label/post args": the program} of every Job and post of JOB_POSTS."""
    out = {}
    for label, posts in JOB_POSTS.items():
        job = job_named(doc, label)
        for name, args in posts:
            out["%s/%s %s" % (label, name, args)] = post_module(checkout, name).export([job], "-", args)
    return out


def op_paths(doc, names):
    """{op name: [[command name, {word: value rounded to 6 places}]]} of the ops ``names`` of ``doc``
    (as JSON reads them back)."""
    return {name: [[c.Name, {k: round(v, 6) for k, v in c.Parameters.items()}]
                   for c in doc.getObject(name).Path.Commands] for name in names}
