"""The package's lines are at most 120 characters, as the project's code is written; the exceptions are text
quoted as it is, which a line break would misstate (each named here with why)."""
from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
LIMIT = 120
#: (file, the long line's start): a doctest's output with no space to break at, or a file format's one-line header.
QUOTED = {
    ("assess/command/cache.py", "    assess.mechanics.block.Block("): "a doctest's output, one token",
    ("assess/fragility/pelicun_export.py", "    ID,Incomplete,Demand-Type,"): "pelicun's CSV header, one line",
    ("assess/hazard/openquake.py", "    #,,,,,\"generated_by="): "OpenQuake's CSV comment line, one line",
    ("assess/site/uhs.py", "    #,,,,\"generated_by="): "OpenQuake's CSV comment line, one line",
}


def _package_files() -> list[str]:
    try:
        listed = subprocess.run(["git", "ls-files", "assess/*.py"], cwd=REPO, capture_output=True, text=True,
                                check=True).stdout.split()
    except (OSError, subprocess.CalledProcessError):
        pytest.skip("not a git checkout: the package's files are listed by git")
    return listed


def test_no_line_of_the_package_is_longer_than_120_characters():
    long = [f"{name}:{number} ({len(line)})" for name in _package_files()
            for number, line in enumerate((REPO / name).read_text(encoding="utf-8").splitlines(), 1)
            if len(line) > LIMIT and not any(name == file and line.startswith(start) for file, start in QUOTED)]
    assert not long, "lines over 120 characters: " + ", ".join(long)


def test_each_quoted_exception_is_still_there():
    """An exception whose line was shortened or moved is taken off the list rather than left to excuse another."""
    for file, start in QUOTED:
        lines = (REPO / file).read_text(encoding="utf-8").splitlines()
        assert any(line.startswith(start) and len(line) > LIMIT for line in lines), (file, start)
