"""package.xml, read as FreeCAD's add-on catalog and CAM read it: every op
and every post named, the icon small, no FreeCAD version compared in a way
that breaks on calendar versions (26.3, 27.1.0-dev)."""

import ast
import glob
import os
import xml.etree.ElementTree as ET

from conftest import ROOT

NS = {"p": "https://wiki.freecad.org/Package_Metadata"}
PACKAGE = ET.parse(os.path.join(ROOT, "package.xml")).getroot()
OPS = ("Turning Groove", "Cylinder slot", "Plunge grind", "Check turning")  # the menu texts of the commands


def text(path):
    return " ".join(e.text or "" for e in PACKAGE.findall(path, NS))


def test_the_package_names_every_op():
    for op in OPS:
        assert op in text("p:description"), op
        assert op in text("p:content/p:workbench/p:description"), op


def test_the_ops_named_are_the_commands_the_add_on_registers():
    # the menu texts above are those of the commands (a renamed command must be renamed here too)
    sources = "".join(open(p, encoding="utf-8").read()
                      for p in glob.glob(os.path.join(ROOT, "freecad_groove", "ops", "*", "gui", "command.py")))
    sources += open(os.path.join(ROOT, "freecad_groove", "gui", "commands.py"), encoding="utf-8").read()
    for op in OPS:
        assert '"%s"' % op in sources, op


def test_every_post_stub_is_named_and_its_folder_is_the_postprocessor_content():
    stubs = sorted(os.path.basename(p)[:-len("_post.py")]
                   for p in glob.glob(os.path.join(ROOT, "postprocessors", "*_post.py")))
    assert len(stubs) == 9
    named = text("p:content/p:Postprocessor/p:description").replace(",", " ").split()
    assert sorted(named) == stubs
    # FreeCAD's development version (Path/Preferences.py _scan_addon_post_dirs) reads <Postprocessor>'s
    # <subdirectory>, the tag spelled with its capital P (FreeCAD.Metadata keeps tags as written)
    assert text("p:content/p:Postprocessor/p:subdirectory") == "postprocessors"


def test_the_icon_is_an_svg_under_10_kb_and_the_catalogs_required_fields_are_there():
    icon = os.path.join(ROOT, text("p:icon"))
    assert icon.endswith(".svg") and os.path.getsize(icon) < 10 * 1024
    for field in ("name", "description", "version", "maintainer", "author", "license", "freecadmin", "url"):
        assert text("p:" + field).strip(), field
    major, minor, patch = text("p:version").split(".")
    assert (major + minor + patch).isdigit()


def test_the_add_on_version_is_the_packages():
    import freecad_groove

    assert freecad_groove.__version__ == text("p:version")


def _version_uses(path):
    """(line, source) of each FreeCAD.Version() call in ``path`` used other than joined for display."""
    with open(path, encoding="utf-8") as f:
        source = f.read()
    tree = ast.parse(source)
    parents = {child: node for node in ast.walk(tree) for child in ast.iter_child_nodes(node)}
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and getattr(node.func, "attr", "") == "Version":
            up = parents.get(parents.get(node))  # Version()[:3] -> its subscript's parent
            shown = isinstance(up, ast.Call) and getattr(up.func, "attr", "") == "join"
            if not shown:
                found.append((node.lineno, ast.get_source_segment(source, node)))
    return found


def test_no_product_code_compares_freecad_versions():
    # A comparison like Version()[1] >= "1" breaks on 26.3 or 27.1.0-dev; the add-on asks for what it needs
    # (hasattr, try/except ImportError) instead. Tests may look at the version (they know the roots).
    sources = glob.glob(os.path.join(ROOT, "freecad_groove", "**", "*.py"), recursive=True)
    sources += [os.path.join(ROOT, name) for name in ("Init.py", "InitGui.py")]
    sources += glob.glob(os.path.join(ROOT, "postprocessors", "*.py"))
    uses = {os.path.relpath(p, ROOT): _version_uses(p) for p in sources}
    assert {p: u for p, u in uses.items() if u} == {}


def test_the_version_check_finds_a_comparison():
    import tempfile

    with tempfile.NamedTemporaryFile("w", suffix=".py", delete=False) as f:
        f.write("import FreeCAD\nOLD = FreeCAD.Version()[1] < '1'\nSHOWN = '.'.join(FreeCAD.Version()[:3])\n")
    try:
        assert [line for line, _ in _version_uses(f.name)] == [2]
    finally:
        os.unlink(f.name)
