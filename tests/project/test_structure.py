"""The package's shape: no import cycle (imports inside functions included), no module too long to read.

The import graph is read from the source with :mod:`ast`, not by importing it,
so an import inside a function counts as much as one at the top.
"""
import ast
from pathlib import Path


PACKAGE = Path(__file__).resolve().parents[2] / "assess"
#: Longest module [lines] (STYLE: split a module before it passes ~800 lines); the command line parses and prints.
MAX_LINES, MAX_CLI_LINES = 800, 450
#: Modules over the limit whose split is under way elsewhere; an entry fails once the module is short enough.
KNOWN_LONG: dict[str, str] = {}  # a module knowingly over the limit while it is being split, with why


def module_name(path: Path) -> str:
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


MODULES = {module_name(path): path for path in sorted(PACKAGE.rglob("*.py"))}


def imported_modules(name: str, path: Path) -> set[str]:
    """The ``assess`` modules that ``path`` imports anywhere in it (a ``from P import n`` of a submodule
    ``P.n`` counts as importing ``P.n``; of a name, as importing ``P``)."""
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = package.split(".")[:len(package.split(".")) - (node.level - 1)]
                base = ".".join(anchor + ([base] if base else []))
            for alias in node.names:
                found.add(f"{base}.{alias.name}" if f"{base}.{alias.name}" in MODULES else base)
    return {module for module in found if module in MODULES and module != name}


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan), each sorted."""
    index, low, stack, on_stack, found, counter = {}, {}, [], set(), [], [0]

    def visit(node):
        index[node] = low[node] = counter[0]
        counter[0] += 1
        stack.append(node)
        on_stack.add(node)
        for target in sorted(graph[node]):
            if target not in index:
                visit(target)
                low[node] = min(low[node], low[target])
            elif target in on_stack:
                low[node] = min(low[node], index[target])
        if low[node] == index[node]:
            component = []
            while True:
                member = stack.pop()
                on_stack.discard(member)
                component.append(member)
                if member == node:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for node in sorted(graph):
        if node not in index:
            visit(node)
    return found


def test_the_cycle_finder_finds_a_cycle():
    graph = {"assess.a": {"assess.b"}, "assess.b": {"assess.a"}, "assess.c": set()}
    assert cycles(graph) == [["assess.a", "assess.b"]]
    assert cycles({"assess.a": {"assess.b"}, "assess.b": set()}) == []


def test_no_package_imports_one_that_imports_it_back():
    """The packages as layers: each module of a package collapsed to the package (the few modules at the top,
    cli.py, startup.py, errors.py ..., left out), the import graph still has no cycle."""
    layer = {name: ".".join(name.split(".")[:2]) for name, path in MODULES.items()
             if path.parent != PACKAGE and name != "assess"}
    graph = {package: set() for package in layer.values()}
    for name, path in MODULES.items():
        if name in layer:
            graph[layer[name]].update(layer[t] for t in imported_modules(name, path)
                                      if t in layer and layer[t] != layer[name])
    assert len(graph) == len([p for p in PACKAGE.iterdir() if (p / "__init__.py").is_file()])
    assert cycles(graph) == []


def test_the_graph_reads_imports_inside_functions_and_relative_ones():
    assert "assess.building.modes" in imported_modules("assess.building.response", MODULES["assess.building.response"])  # relative
    assert "assess.assessment.pipeline" in imported_modules("assess.command.job", MODULES["assess.command.job"])
    assert "assess.command.job" in imported_modules("assess.cli", MODULES["assess.cli"])  # inside a function


def test_no_import_cycle():
    graph = {name: imported_modules(name, path) for name, path in MODULES.items()}
    assert cycles(graph) == []


def module_lines() -> dict[str, int]:
    """Every module of the package and its line count, by path relative to the repository."""
    return {path.relative_to(PACKAGE.parent).as_posix(): len(path.read_text(encoding="utf-8").splitlines())
            for path in sorted(PACKAGE.rglob("*.py"))}


def too_long(lines: dict[str, int]) -> list[str]:
    """The modules over their limit (the command line's own), and those of KNOWN_LONG now short enough."""
    found = []
    for relative, count in lines.items():
        limit = MAX_CLI_LINES if relative == "assess/cli.py" else MAX_LINES
        if relative in KNOWN_LONG and count <= limit:
            found.append(f"{relative} is {count} lines now: remove it from KNOWN_LONG")
        elif relative not in KNOWN_LONG and count > limit:
            found.append(f"{relative} has {count} lines (at most {limit}): split it")
    return found


def test_the_size_rule_names_every_long_module():
    lines = {"assess/a.py": MAX_LINES + 1, "assess/b.py": MAX_LINES, "assess/cli.py": MAX_CLI_LINES + 1}
    assert too_long(lines) == [f"assess/a.py has {MAX_LINES + 1} lines (at most {MAX_LINES}): split it",
                               f"assess/cli.py has {MAX_CLI_LINES + 1} lines (at most {MAX_CLI_LINES}): split it"]


def test_no_module_is_too_long():
    lines = module_lines()
    assert len(lines) == len(MODULES)  # every module counted
    offending = too_long(lines)
    assert not offending, "\n".join(offending)
