"""Dask is an extra (``pip install "assess[cluster]"``): the main job never needs it, and ``--scheduler``
without it exits 2 saying how to install it.
"""
from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

from assess import cli

ROOT = Path(__file__).resolve().parents[2]
LAB = ROOT / "inventories" / "lab.xlsx"


def test_scheduler_without_dask_exits_2_naming_the_extra(monkeypatch, tmp_path, capsys):
    # None in sys.modules makes ``import distributed`` raise ImportError, as on an installation without Dask
    monkeypatch.setitem(sys.modules, "distributed", None)
    out = tmp_path / "out"
    code = cli.main([str(LAB), "--hazard", "2in50", "--out", str(out), "--format", "xlsx", "--quiet",
                     "--scheduler", "tcp://127.0.0.1:8786"])
    err = capsys.readouterr().err
    assert code == 2
    problems = [line for line in err.splitlines() if line.startswith("  - ")]
    assert len(problems) == 1, err
    assert problems[0].startswith("  - --scheduler: ")
    assert 'pip install "assess[cluster]"' in problems[0]
    assert "Traceback" not in err
    assert not out.exists()


def test_every_module_imports_without_dask():
    """On an installation without the cluster extra (Dask hidden: None in sys.modules), every module of
    the package imports, so the main job on this machine's cores runs without it."""
    script = (
        "import importlib, pkgutil, sys\n"
        "sys.modules['dask'] = sys.modules['distributed'] = None\n"
        "import assess\n"
        "names = [m.name for m in pkgutil.walk_packages(assess.__path__, 'assess.') if m.name != 'assess.__main__']\n"
        "for name in names:\n"
        "    importlib.import_module(name)\n"
        "print(len(names))\n"
    )
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, cwd=ROOT, timeout=300)
    assert done.returncode == 0, done.stderr
    assert int(done.stdout) > 50  # every module was imported, not none


def test_dask_is_imported_only_inside_the_functions_that_use_it():
    """No module of the package imports Dask when it is imported: only the functions that run on a
    cluster do (with Dask installed, pint still imports dask.base on its own, to support dask arrays)."""
    top_level = []
    for path in sorted((ROOT / "assess").rglob("*.py")):
        tree = ast.parse(path.read_text(), str(path))
        for node in tree.body:  # module level, including under if/try at module level
            for inner in ast.walk(node) if not isinstance(node, (ast.FunctionDef, ast.ClassDef)) else ():
                names = ([a.name for a in inner.names] if isinstance(inner, ast.Import)
                         else [inner.module or ""] if isinstance(inner, ast.ImportFrom) else [])
                if any(name.split(".")[0] in ("dask", "distributed") for name in names):
                    top_level.append(f"{path.relative_to(ROOT)}:{inner.lineno}")
    assert top_level == []
    # and the check sees imports where they are: the cluster runner imports distributed in its methods
    source = (ROOT / "assess" / "mechanics" / "distributed.py").read_text()
    assert "from distributed import Client" in source
