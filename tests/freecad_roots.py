"""Running a command inside FreeCAD 1.1 or 1.0 from a host test.

`scripts/freecad-roots` provides each FreeCAD (a Debian root, or the host's
own freecadcmd); ``run`` runs an ``sh -c`` command in one of them with a
folder shared with the run (FREECAD_GROOVE_SHARE inside). A FreeCAD that is
not available skips the test, with how to get it; under CI=true it fails.
Used by tests/test_freecad.py (the FreeCAD-level and GUI suites) and
tests/test_post_artifacts.py (the posts' programs it checks).
"""

import functools
import os
import subprocess

import pytest
from conftest import IN_CI, ROOT

SCRIPT = os.path.join(ROOT, "scripts", "freecad-roots")
LABELS = ["1.1", "1.0"]  # 1.1 first: the primary target
HOW_TO_GET = "`scripts/freecad-roots ensure` (as root) builds FreeCAD 1.1 and 1.0 (about 5 GB, a few minutes)"
# freecadcmd running the Python text $1; -M: the checkout is loaded as a FreeCAD Mod, like an installed add-on.
# (Keep that text short: FreeCAD 1.1 crashes on a -c text of 256 characters or more.)
FREECADCMD = 'exec freecadcmd -M "$FREECAD_GROOVE_CHECKOUT" -c "$1"'


def exec_code(path):
    """The -c text that runs checkout file ``path`` (relative) inside freecadcmd."""
    return "import os; exec(open(os.environ['FREECAD_GROOVE_CHECKOUT'] + '/%s').read())" % path


@functools.lru_cache(maxsize=None)
def available():
    """{label: where} from `scripts/freecad-roots list`; {} if it fails."""
    try:
        out = subprocess.run([SCRIPT, "list"], capture_output=True, text=True, timeout=120).stdout
    except (OSError, subprocess.SubprocessError):
        return {}
    found = {}
    for line in out.splitlines():
        fields = line.split("\t")
        if len(fields) >= 2:
            found[fields[0]] = fields[1]
    return found


def not_available(label, why):
    message = "FreeCAD %s is not available: %s. %s" % (label, why.strip(), HOW_TO_GET)
    if IN_CI:
        pytest.fail(message + " (CI: a missing FreeCAD is a failure)", pytrace=False)
    pytest.skip(message)


def tail(text, lines=40):
    return "\n".join(text.splitlines()[-lines:])


def describe(proc):
    """A finished run's exit status and the ends of its output, for a failure
    message; after a crash also the start of Python's fault report (its
    innermost frames come first, the tail would cut them off)."""
    text = "exit status %d\n--- stdout ---\n%s\n--- stderr ---\n%s" % (
        proc.returncode, tail(proc.stdout), tail(proc.stderr))
    at = proc.stderr.find("Fatal Python error") if proc.stderr else -1
    if at >= 0:
        text += "\n--- fault report ---\n%s" % "\n".join(proc.stderr[at:].splitlines()[:30])
    return text


def run(label, share, command, args=(), env_extra=None, timeout=1800, drop=()):
    """Run ``command`` (an sh -c text; ``args`` are its $1...) in FreeCAD ``label``
    with folder ``share`` shared, the caller's environment without ``drop`` and
    with ``env_extra``; returns (CompletedProcess, where FreeCAD is). Skips (CI:
    fails) when that FreeCAD is missing."""
    where = available().get(label)
    if where is None:
        not_available(label, "`scripts/freecad-roots list` does not list it")
    env = dict(os.environ)
    for name in drop:
        env.pop(name, None)
    env.update(env_extra or {})
    proc = subprocess.run([SCRIPT, "run", label, "--share", str(share), "--", "sh", "-c", command, "sh", *args],
                          capture_output=True, text=True, timeout=timeout, env=env)
    if proc.returncode == 77:
        not_available(label, proc.stderr)
    return proc, where


def once_per_label(write, tmp_path_factory, prefix):
    """cases(label): what ``write(label, a new temporary folder named prefix...)``
    returns, computed once per session and FreeCAD label; an outcome that
    skipped or failed is raised again for every test that asks."""
    outcomes = {}

    def cases(label):
        if label not in outcomes:
            try:
                outcomes[label] = write(label, tmp_path_factory.mktemp("%s%s-" % (prefix, label)))
            except (Exception, pytest.skip.Exception, pytest.fail.Exception) as exc:
                outcomes[label] = exc
        if isinstance(outcomes[label], BaseException):
            raise outcomes[label]
        return outcomes[label]

    return cases
