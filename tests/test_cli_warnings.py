"""The command line's warnings are kept out of memory until the run has
succeeded (cli_io.WarningSpool, issue 22): printed after the output, in the
order they arose, exactly as they were given; a run that fails prints its
error alone."""

import subprocess
import sys

from freecad_groove.cli_io import WarningSpool
from freecad_groove.engine.warnings import CycleWarning

PLAIN = "CYCLE93(35, %g, 10, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 5, 0)"


def program(calls, last=""):
    lines = ["N10 T5 D1 S400 M03", "N20 G95 G90 F0.2", "N30 G00 X80 Z65"]
    for k in range(calls):
        lines += ["G00 X80 Z%g" % (5 - 40 * k), PLAIN % (-40 * k)]
    return "\n".join(lines + [last, "N60 M02"]) + "\n"


def expand(tmp_path, text):
    path = tmp_path / "p.mpf"
    path.write_text(text)
    return subprocess.run([sys.executable, "-m", "freecad_groove", "expand", str(path), "--dialect", "sinumerik",
                           "--tool-width", "3", "--tool-radius", "0.4"], capture_output=True, text=True)


def test_the_spool_gives_back_each_warning_on_its_line_in_order_with_its_text_on_one_line(capsys):
    spool = WarningSpool()
    spool.append((7, CycleWarning("CYCLE93", "RCI1", "0.03 mm² up to 0.40 mm deep\tat base corner 1")))
    spool.extend([(3, CycleWarning("G75", None, "relief  R\nlarger than the blade")), (12, CycleWarning(
        "CYCLE93", "FAL2", "ü é"))])
    spool.report("prog.mpf")
    spool.close()
    assert capsys.readouterr().err == (
        "prog.mpf:7: warning: CYCLE93: 0.03 mm² up to 0.40 mm deep at base corner 1\n"
        "prog.mpf:3: warning: G75: relief R larger than the blade\n"
        "prog.mpf:12: warning: CYCLE93: ü é\n")


def test_every_call_of_a_long_program_warns_on_its_own_line_after_the_output(tmp_path):
    proc = expand(tmp_path, program(300))
    lines = proc.stderr.splitlines()
    assert proc.returncode == 0 and proc.stdout.endswith("M2\n") and len(lines) == 600
    # the calls are on lines 5, 7, 9, ...: both base corners of each, in the program's order
    assert [int(line.split(":")[1]) for line in lines] == [5 + 2 * (k // 2) for k in range(600)]
    assert lines[0].endswith("warning: CYCLE93: 0.03 mm² up to 0.40 mm deep at base corner 1 cannot be reached "
                             "by a 3 mm flat blade (r0.4)")


def test_a_program_that_fails_after_warnings_prints_its_error_alone(tmp_path):
    proc = expand(tmp_path, program(20, "CYCLE93(35, -900, 10, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0, -2, 0, 5, 0)"))
    assert proc.returncode == 2 and proc.stdout == ""
    assert len(proc.stderr.splitlines()) == 1 and "IDEP" in proc.stderr and "warning" not in proc.stderr
