"""The README and the guide under docs/: every relative link leads to a file
that exists (and an anchor to a heading of it), the front page stays short
and renders without HTML, and every guide page is linked from it."""

import glob
import os
import re

import pytest
from conftest import ROOT

PAGES = [os.path.join(ROOT, "README.md"), os.path.join(ROOT, "CHANGELOG.md")] + sorted(
    glob.glob(os.path.join(ROOT, "docs", "*.md")))
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")
FENCE = re.compile(r"^```.*?^```", re.M | re.S)


def links(path):
    with open(path, encoding="utf-8") as f:
        text = FENCE.sub("", f.read())
    return [target for target in LINK.findall(text) if not re.match(r"[a-z]+:", target)]


def anchors(path):
    """GitHub's anchors of the headings of ``path``: lower case, punctuation dropped, spaces to hyphens."""
    with open(path, encoding="utf-8") as f:
        text = FENCE.sub("", f.read())
    out = set()
    for heading in re.findall(r"^#+ (.+)$", text, re.M):
        out.add(re.sub(r"[^\w\- ]", "", heading.strip().lower()).replace(" ", "-"))
    return out


def broken(path):
    found = []
    for target in links(path):
        file, _hash, anchor = target.partition("#")
        where = os.path.normpath(os.path.join(os.path.dirname(path), file)) if file else path
        if not os.path.exists(where):
            found.append(target)
        elif anchor and where.endswith(".md") and anchor not in anchors(where):
            found.append(target)
    return found


@pytest.mark.parametrize("path", PAGES, ids=lambda p: os.path.relpath(p, ROOT))
def test_every_relative_link_leads_somewhere(path):
    assert broken(path) == []


def test_the_check_finds_a_broken_link_and_a_broken_anchor(tmp_path):
    (tmp_path / "a.md").write_text("# Title\n\n[ok](a.md#title) [gone](b.md) [lost](a.md#nowhere)\n")
    assert broken(str(tmp_path / "a.md")) == ["b.md", "a.md#nowhere"]


def test_the_front_page_is_short_and_has_no_html():
    with open(os.path.join(ROOT, "README.md"), encoding="utf-8") as f:
        text = f.read()
    assert text.count("\n") <= 300
    prose = re.sub(r"`[^`]*`", "", FENCE.sub("", text))  # code may hold <tags>
    assert not re.search(r"<[a-zA-Z/][^>]*>", prose)


def test_every_guide_page_is_linked_from_the_front_page():
    linked = {os.path.normpath(os.path.join(ROOT, t.partition("#")[0])) for t in links(os.path.join(ROOT, "README.md"))}
    for page in glob.glob(os.path.join(ROOT, "docs", "*.md")):
        assert page in linked or os.path.basename(page) == "index.md", os.path.relpath(page, ROOT)


def placeholders(text):
    """Lines that are only a token of capitals and underscores (RUN_TABLE): a generated table never filled in."""
    return [line for line in text.splitlines() if re.fullmatch(r"[A-Z][A-Z0-9]*_[A-Z0-9_]+", line.strip())]


def test_no_page_holds_a_placeholder_for_a_table_never_filled_in():
    assert placeholders("Figures:\n\nRUN_TABLE\n\nmore") == ["RUN_TABLE"]  # the check finds one
    assert {os.path.basename(path): placeholders(open(path, encoding="utf-8").read()) for path in PAGES
            if placeholders(open(path, encoding="utf-8").read())} == {}
