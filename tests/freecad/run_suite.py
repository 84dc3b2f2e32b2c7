"""Run the FreeCAD-level tests inside FreeCAD and write the result as JSON.

Executed *by* freecadcmd (FreeCAD 1.1 swallows print() of a script file given
as `freecadcmd file.py`, so this file is exec'd from `-c`, and the result goes
to a file rather than to stdout):

    freecadcmd -M CHECKOUT -c "$CODE"
    CODE="import os; exec(open(os.environ['FREECAD_GROOVE_CHECKOUT'] + '/tests/freecad/run_suite.py').read())"

(`-M CHECKOUT` loads the checkout as a FreeCAD Mod, as an installed add-on
would be. Keep the -c text short: FreeCAD 1.1 crashes on 256 characters or
more.) `scripts/freecad-roots run LABEL --share DIR -- ...` sets the
variables below; tests/test_freecad.py does all of this for every FreeCAD.

Runs with pytest (the root's python3-pytest), in this FreeCAD process, one
session: every tests/freecad/test_*.py and the pure-Python engine test files
in ENGINE_TESTS. Environment:

    FREECAD_GROOVE_CHECKOUT  the checkout (default /mnt/freecad-groove)
    FREECAD_GROOVE_RESULT    where the JSON goes: absolute, or relative to
                             FREECAD_GROOVE_SHARE (default result.json there,
                             else in the current directory)
    FREECAD_GROOVE_PYTEST_ARGS  extra pytest arguments (split like a shell)
    FREECAD_GROOVE_SUITE_EXIT   0 = return instead of ending the process with
                             pytest's exit status (default: os._exit(status),
                             which also skips FreeCAD's own shutdown)
    FREECAD_GROOVE_SUITE     "gui": run tests/freecad_gui/test_*.py instead
                             (no engine tests), started from the Qt event
                             loop of FreeCAD's GUI; tests/freecad_gui/start.py
                             sets it (the GUI runs a script file, not -c)

The JSON: {"exitstatus", "freecad_version", "python", "counts": {passed,
failed, errors, skipped, xfailed, xpassed}, "passed": [nodeid, ...],
"failed"/"errors": [{"nodeid", "when", "longrepr", "stdout", "stderr"}],
"skipped": [{"nodeid", "reason"}], "collection_errors": [{"nodeid",
"longrepr"}], "internal_error": traceback or null}. It is written to a
temporary name and renamed, so a file that exists is complete.
"""

ENGINE_TESTS = ("tests/test_cycle93.py", "tests/test_ab_g77.py", "tests/test_fanuc_g75.py")


def _freecad_groove_run_suite():
    import glob
    import json
    import os
    import shlex
    import shutil
    import sys
    import tempfile
    import traceback

    checkout = os.environ.get("FREECAD_GROOVE_CHECKOUT", "/mnt/freecad-groove")
    gui = os.environ.get("FREECAD_GROOVE_SUITE", "") == "gui"
    share = os.environ.get("FREECAD_GROOVE_SHARE", "")
    result_path = os.environ.get("FREECAD_GROOVE_RESULT", "result.json")
    if not os.path.isabs(result_path):
        result_path = os.path.join(share or os.getcwd(), result_path)

    result = {
        "exitstatus": None,
        "freecad_version": None,
        "python": sys.version,
        "counts": {},
        "passed": [],
        "failed": [],
        "errors": [],
        "skipped": [],
        "xfailed": [],
        "xpassed": [],
        "collection_errors": [],
        "internal_error": None,
    }

    def text(longrepr):
        if longrepr is None:
            return ""
        if isinstance(longrepr, tuple) and len(longrepr) == 3:  # skip: (file, line, reason)
            return "%s:%s: %s" % longrepr
        return str(longrepr)

    class Collector:
        def pytest_runtest_teardown(self, item, nextitem):
            # pytest keeps the last failure for a post-mortem (sys.last_traceback and its frames' locals): in
            # the GUI suite those locals hold PySide wrappers of widgets FreeCAD deletes with the panel, and a
            # wrapper outliving its widget is handed out for the next panel's widget built at that address
            # (gui/qt_wrappers.py): one failed test then crashed a later one. Nothing here needs them.
            for name in ("last_type", "last_value", "last_traceback", "last_exc"):
                if hasattr(sys, name):
                    setattr(sys, name, None)

        def pytest_runtest_logreport(self, report):
            entry = {
                "nodeid": report.nodeid,
                "when": report.when,
                "longrepr": text(report.longrepr),
                "stdout": report.capstdout[-20000:],
                "stderr": report.capstderr[-20000:],
            }
            wasxfail = hasattr(report, "wasxfail")
            if report.when == "call":
                if report.passed:
                    result["xpassed" if wasxfail else "passed"].append(report.nodeid)
                elif report.failed:
                    result["failed"].append(entry)
                elif wasxfail:
                    result["xfailed"].append(report.nodeid)
                else:
                    result["skipped"].append({"nodeid": report.nodeid, "reason": text(report.longrepr)})
            elif report.failed:  # setup or teardown
                result["errors"].append(entry)
            elif report.skipped and report.when == "setup":
                if wasxfail:
                    result["xfailed"].append(report.nodeid)
                else:
                    result["skipped"].append({"nodeid": report.nodeid, "reason": text(report.longrepr)})

        def pytest_collectreport(self, report):
            if report.failed:
                result["collection_errors"].append(
                    {"nodeid": report.nodeid, "longrepr": text(report.longrepr)}
                )

    status = 3
    basetemp = None
    try:
        import FreeCAD

        result["freecad_version"] = list(FreeCAD.Version())
        sys.dont_write_bytecode = True  # the checkout is mounted read-only
        if checkout not in sys.path:
            sys.path.insert(0, checkout)
        import pytest

        result["pytest"] = pytest.__version__
        if gui:
            files = sorted(glob.glob(os.path.join(checkout, "tests", "freecad_gui", "test_*.py")))
        else:
            files = sorted(glob.glob(os.path.join(checkout, "tests", "freecad", "test_*.py")))
            files += [os.path.join(checkout, name) for name in ENGINE_TESTS]
        basetemp = tempfile.mkdtemp(prefix="freecad-groove-pytest-")  # tmp_path, removed below
        args = ["-p", "no:cacheprovider", "--rootdir", checkout, "--basetemp", basetemp, "-rfEs"]
        args += shlex.split(os.environ.get("FREECAD_GROOVE_PYTEST_ARGS", ""))
        status = int(pytest.main(args + files, plugins=[Collector()]))
    except BaseException:  # noqa: B902 - everything goes into the JSON
        result["internal_error"] = traceback.format_exc()
        status = 3
    if basetemp:
        shutil.rmtree(basetemp, ignore_errors=True)
    result["exitstatus"] = status
    result["counts"] = {
        key: len(result[key])
        for key in ("passed", "failed", "errors", "skipped", "xfailed", "xpassed", "collection_errors")
    }
    tmp = result_path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(result, f, indent=1)
    os.replace(tmp, result_path)
    sys.stdout.flush()
    sys.stderr.flush()
    if os.environ.get("FREECAD_GROOVE_SUITE_EXIT", "1") != "0":
        os._exit(status)
    return status


import os as _os  # noqa: E402

if _os.environ.get("FREECAD_GROOVE_SUITE", "") == "gui":
    # After the main window is up, from inside the event loop the tests drive.
    from PySide import QtCore as _QtCore

    _QtCore.QTimer.singleShot(0, _freecad_groove_run_suite)
else:
    _freecad_groove_run_suite()
