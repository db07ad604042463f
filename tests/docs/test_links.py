"""README.md and docs/*.md: every relative link names a file of the repository, every
#anchor a heading of the file it points into (GitHub's heading ids), and the README stays
a doorway (at most 400 lines) whose documentation table lists every file of docs/."""
from __future__ import annotations

import re
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
PAGES = [REPO / "README.md", *sorted((REPO / "docs").glob("*.md"))]
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")


def heading_ids(page: Path) -> set[str]:
    """GitHub's ids of a page's headings: lower case, punctuation but - and _ dropped,
    spaces to -, a repeated id suffixed -1, -2, ..."""
    ids: set[str] = set()
    fenced = False
    for line in page.read_text().splitlines():
        if line.startswith("```"):
            fenced = not fenced
        if fenced or not re.match(r"^#{1,6} ", line):
            continue
        base = re.sub(r"[^\w\- ]", "", line.lstrip("#").strip().lower()).replace(" ", "-")
        slug, k = base, 0
        while slug in ids:
            k += 1
            slug = f"{base}-{k}"
        ids.add(slug)
    return ids


def links(page: Path) -> list[str]:
    text = re.sub(r"```.*?```", "", page.read_text(), flags=re.S)  # code is not a link
    return LINK.findall(text)


def test_every_relative_link_and_anchor_resolves():
    broken = []
    for page in PAGES:
        for target in links(page):
            if re.match(r"^[a-z]+:", target):
                continue
            path, _, anchor = target.partition("#")
            dest = (page.parent / path).resolve() if path else page
            if not dest.exists():
                broken.append(f"{page.relative_to(REPO)}: {target} (no such file)")
            elif anchor and dest.suffix == ".md" and anchor not in heading_ids(dest):
                broken.append(f"{page.relative_to(REPO)}: {target} (no heading #{anchor} in {dest.name})")
    assert not broken, "\n".join(broken)


def test_the_checker_finds_a_broken_link_and_anchor(tmp_path):
    page = tmp_path / "page.md"
    page.write_text("# Title\n\n## A `code` heading: here\n\n[ok](#a-code-heading-here) [bad](#nowhere)\n")
    assert heading_ids(page) == {"title", "a-code-heading-here"}
    assert links(page) == ["#a-code-heading-here", "#nowhere"]


def test_the_readme_is_a_doorway_to_every_doc():
    readme = (REPO / "README.md").read_text()
    assert readme.count("\n") <= 400, f"README.md has {readme.count(chr(10))} lines; move detail to docs/"
    listed = set(re.findall(r"\]\(docs/([\w-]+\.md)\)", readme))
    assert listed == {p.name for p in (REPO / "docs").glob("*.md")}
