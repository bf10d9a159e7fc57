"""The code's layout as the README and docs/internals.md draw it, and imports that go one way.

The README's *Layout* block must name every package and every top-level module of ``assess/`` (and
nothing that is not there); docs/internals.md must name every module. The import graph is read from
the source with :mod:`ast` (every ``import``, also inside functions), and must have no cycle, between
modules or between packages.
"""
from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
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


def _modules() -> dict[str, Path]:
    """Every module of assess, by its dotted name (a package by its own name)."""
    found = {}
    for path in PACKAGE.rglob("*.py"):
        parts = path.relative_to(ROOT).with_suffix("").parts
        found[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    return found


def import_graph(modules: dict[str, Path]) -> dict[str, set[str]]:
    """Which module imports which, from the source: ``from pkg import sub`` counts as importing the
    submodule ``sub`` (the package's ``__init__`` need not have finished), ``from pkg import name`` as
    importing ``pkg``."""

    def known(name):
        while name and name not in modules:
            name = name.rpartition(".")[0]
        return name or None

    graph = {name: set() for name in modules}
    for name, path in modules.items():
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                targets = [alias.name for alias in node.names]
            elif isinstance(node, ast.ImportFrom):
                if node.level:
                    base = name.split(".") if path.name == "__init__.py" else name.split(".")[:-1]
                    base = base[:len(base) - (node.level - 1)]
                    source = ".".join(base + ([node.module] if node.module else []))
                else:
                    source = node.module or ""
                targets = [f"{source}.{a.name}" if f"{source}.{a.name}" in modules else source for a in node.names]
            else:
                continue
            for target in targets:
                target = known(target)
                if target is not None and target != name:
                    graph[name].add(target)
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan)."""
    index, low, stack, on_stack, found = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in graph.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


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


def test_no_module_of_assess_imports_one_that_imports_it_back():
    modules = _modules()
    graph = import_graph(modules)
    assert sum(map(len, graph.values())) > 300  # the graph was read (about 370 imports between modules)
    assert cycles(graph) == []


def test_no_package_of_assess_imports_one_that_imports_it_back():
    """The packages of assess as layers: every module of a package collapsed to the package, the import graph
    still has no cycle (the few modules at the top, cli.py, startup.py, errors.py ..., are left out)."""
    modules = _modules()
    layer = {name: ".".join(name.split(".")[:2]) for name, path in modules.items()
             if path.parent != PACKAGE and name != "assess"}
    graph = {}
    for name, targets in import_graph(modules).items():
        if name in layer:
            graph.setdefault(layer[name], set()).update(
                layer[t] for t in targets if t in layer and layer[t] != layer[name])
    assert len(graph) == len([p for p in PACKAGE.iterdir() if (p / "__init__.py").is_file()])
    assert cycles(graph) == []


def test_the_cycle_check_finds_a_cycle(tmp_path):
    """The check above can fail: a package whose two modules import each other, one inside a function."""
    package = tmp_path / "assess"
    (package / "inner").mkdir(parents=True)
    (package / "__init__.py").write_text("")
    (package / "inner" / "__init__.py").write_text("")
    (package / "inner" / "a.py").write_text("from assess.inner import b\n")
    (package / "c.py").write_text("import assess.inner.a\n")
    (package / "inner" / "b.py").write_text("def f():\n    from assess import c\n")
    modules = {}
    for path in package.rglob("*.py"):
        parts = path.relative_to(tmp_path).with_suffix("").parts
        modules[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    assert cycles(import_graph(modules)) == [["assess.c", "assess.inner.a", "assess.inner.b"]]


def test_the_tree_reader_follows_the_indentation():
    block = "assess/  the package\n  cli.py  x\n  report/  y\n    pdf.py  z\ntemplates/  t\n"
    assert _tree_paths(block) == {"assess/cli.py", "assess/report/", "assess/report/pdf.py"}
