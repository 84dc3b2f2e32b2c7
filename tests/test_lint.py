"""The lint of the whole tree: ruff with the project's one configuration
(ruff.toml: line length 120; pycodestyle, pyflakes, import order, bugbear).
Pinned in requirements-test.txt, so every machine runs the same rules."""

import os
import shutil
import subprocess
import sys

from conftest import ROOT


def _ruff():
    local = os.path.join(os.path.dirname(sys.executable), "ruff")
    return local if os.path.exists(local) else shutil.which("ruff")


def test_ruff_finds_nothing_to_fix():
    ruff = _ruff()
    assert ruff, "ruff is missing: scripts/test installs it from requirements-test.txt"
    proc = subprocess.run([ruff, "check", "--no-cache", "--output-format", "concise", "."], cwd=ROOT,
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_ruff_reads_the_project_configuration(tmp_path):
    """A line of 121 characters fails: the configuration is the one in force."""
    ruff = _ruff()
    assert ruff
    long_line = "X = " + repr("a" * 115) + "\n"
    assert len(long_line.rstrip("\n")) == 121
    sample = tmp_path / "sample.py"
    sample.write_text(long_line)
    proc = subprocess.run([ruff, "check", "--no-cache", "--config", os.path.join(ROOT, "ruff.toml"), str(sample)],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 1 and "E501" in proc.stdout
