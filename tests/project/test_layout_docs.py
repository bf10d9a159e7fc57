"""The code's layout as the README and docs/internals.md draw it (the imports that go one way are
tests/test_structure.py's).

The README's *Layout* block must name every package and every top-level module of ``assess/`` (and
nothing that is not there); docs/internals.md must name every module.
"""
from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "assess"


def _block_after(text: str, heading: str) -> str:
    """The first fenced block after ``heading``."""
    rest = text[text.index(heading):]
    return rest.split("```")[1]


def _tree_paths(block: str, top: str = "assess/") -> set[str]:
    """The paths a tree drawn with two spaces a level names, below ``top`` (``assess/cli.py``,
    ``assess/report/``, ``assess/report/pdf.py``)."""
    paths, stack = set(), []
    for line in block.splitlines():
        if not line.strip():
            continue
        depth = (len(line) - len(line.lstrip(" "))) // 2
        name = line.split()[0]
        stack[depth:] = [name]
        if stack[0] == top and depth > 0:
            paths.add("".join(stack))
    return paths


def test_the_readme_layout_names_every_package_and_top_level_module():
    drawn = {p for p in _tree_paths(_block_after((ROOT / "README.md").read_text(encoding="utf-8"), "## Layout"))
             if p.count("/") == 1 or (p.count("/") == 2 and p.endswith("/"))}
    there = {f"assess/{p.name}/" for p in PACKAGE.iterdir() if (p / "__init__.py").is_file()}
    there |= {f"assess/{p.name}" for p in PACKAGE.glob("*.py") if p.name != "__init__.py"}
    assert drawn == there, f"missing from the README: {sorted(there - drawn)}; not there: {sorted(drawn - there)}"


def test_docs_internals_names_every_module():
    drawn = _tree_paths(_block_after((ROOT / "docs" / "internals.md").read_text(encoding="utf-8"), "## Layout"))
    there = {str(p.relative_to(ROOT)) for p in PACKAGE.rglob("*.py") if p.name != "__init__.py"}
    there |= {str(p.parent.relative_to(ROOT)) + "/" for p in PACKAGE.rglob("__init__.py") if p.parent != PACKAGE}
    assert drawn == there, f"missing from docs/internals.md: {sorted(there - drawn)}; not there: {sorted(drawn - there)}"


def test_the_tree_reader_follows_the_indentation():
    block = "assess/  the package\n  cli.py  x\n  report/  y\n    pdf.py  z\ntemplates/  t\n"
    assert _tree_paths(block) == {"assess/cli.py", "assess/report/", "assess/report/pdf.py"}
