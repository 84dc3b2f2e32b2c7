"""freecad_groove/freecad/registration.py's import hooks, on the host (the
module needs only the standard library; Init.py loads it by file name, as
here): an action waits for its module's import, runs once after it, and a
failing action warns without breaking the import. The FreeCAD side (the
posts in CAM's list, the grooving shape in 1.1's shape chooser) is tested in
tests/freecad/test_posts.py and test_toolbit.py.
"""

import importlib.util
import os
import sys

import pytest
from conftest import ROOT


@pytest.fixture
def registration():
    path = os.path.join(ROOT, "freecad_groove", "freecad", "registration.py")
    spec = importlib.util.spec_from_file_location("_test_registration", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    before = list(sys.meta_path)
    yield module
    sys.meta_path[:] = before


@pytest.fixture
def fake_module(tmp_path, monkeypatch):
    """The name of a module that is importable and not yet imported."""
    name = "_freecad_groove_fake_%d" % os.getpid()
    (tmp_path / (name + ".py")).write_text("VALUE = 42\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    yield name
    sys.modules.pop(name, None)


def test_an_action_runs_once_after_its_module_is_imported(registration, fake_module):
    seen = []
    registration._after_import(fake_module, lambda m: seen.append(m.VALUE), "no fake")
    registration._after_import(fake_module, lambda m: seen.append(-m.VALUE), "no fake")  # replaces
    assert len(registration._hooks(fake_module)) == 1 and seen == []
    module = importlib.import_module(fake_module)
    assert module.VALUE == 42 and seen == [-42]
    assert registration._hooks(fake_module) == []


def test_a_failing_action_warns_and_the_import_still_works(registration, fake_module, capsys):
    def fail(module):
        raise RuntimeError("boom")

    registration._after_import(fake_module, fail, "could not do the fake thing")
    assert importlib.import_module(fake_module).VALUE == 42
    assert "freecad-groove: could not do the fake thing: boom" in capsys.readouterr().err


def test_the_shapes_wait_for_cams_tool_bits_without_touching_the_posts_hook(registration):
    if registration.SHAPES_TARGET in sys.modules:  # pragma: no cover - no FreeCAD on the host
        pytest.skip("Path.Tool is imported")
    registration.register()  # Path.Preferences is not imported on the host: a pending hook
    registration.register_shapes()
    registration.register_shapes()
    assert len(registration._hooks(registration.SHAPES_TARGET)) == 1
    assert len(registration._hooks(registration.TARGET)) == 1
    registration.unregister_shapes()
    assert registration._hooks(registration.SHAPES_TARGET) == []
    assert len(registration._hooks(registration.TARGET)) == 1
