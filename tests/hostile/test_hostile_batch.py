"""Hostile portfolios given to ``assess batch``: refused (exit 2, the file named) before any simulation.

A building name that fits 80 characters but not 255 bytes, a workbook that is
a link to itself, and a FIFO named like a workbook. Each runs the CLI in a
child process with a timeout (the FIFO hung the run).
"""
from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

from assess.inventory.xlsx import file_problem
from assess.portfolio.batch import MAX_NAME_BYTES, building_name_problem
from tests.portfolio.test_batch import ITEMS, _write_building
from workbooks import write_workbook

ROOT = Path(__file__).resolve().parents[2]
BOLD_A = "\U0001D400"  # MATHEMATICAL BOLD CAPITAL A: one character, a letter (\w), four bytes in UTF-8


def run(*args, cwd, timeout=120):
    started = time.monotonic()
    done = subprocess.run([sys.executable, "-m", "assess", *map(str, args)], cwd=cwd, capture_output=True,
                          text=True, timeout=timeout,
                          env={**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")])})
    done.seconds = time.monotonic() - started
    return done


def assert_refused(done, *expected):
    assert done.returncode == 2, done.stderr
    assert "Traceback" not in done.stderr and "internal error" not in done.stderr, done.stderr
    assert "cases simulated" not in done.stderr + done.stdout
    for text in expected:
        assert text in done.stderr, done.stderr


def test_a_name_of_80_characters_and_320_bytes_is_refused():
    name = BOLD_A * 80
    assert len(name) == 80 and len(name.encode("utf-8")) == 320
    why = building_name_problem(name)
    assert why is not None and "320 bytes" in why and f"at most {MAX_NAME_BYTES}" in why
    assert building_name_problem("A" * 80) is None
    assert building_name_problem(BOLD_A * 50) is None  # 200 bytes


def test_a_320_byte_building_name_exits_2_before_any_simulation(tmp_path):
    folder = tmp_path / "portfolio"
    folder.mkdir()
    _write_building(folder, "alpha", ITEMS["alpha"])
    portfolio = write_workbook(folder / "portfolio.xlsx", {"buildings": [
        {"building": BOLD_A * 80, "workbook": "alpha.xlsx", "level": "2in50"}]})
    done = run("batch", portfolio, "--out", tmp_path / "out", "--format", "xlsx", cwd=tmp_path)
    assert_refused(done, "portfolio.xlsx, sheet 'buildings', cell A2", "320 bytes in UTF-8")
    assert not (tmp_path / "out").exists()


def test_a_workbook_that_is_a_link_to_itself_is_named(tmp_path):
    folder = tmp_path / "portfolio"
    folder.mkdir()
    _write_building(folder, "alpha", ITEMS["alpha"])
    (folder / "bad.xlsx").symlink_to(folder / "bad.xlsx")
    assert "loop of symbolic links" in file_problem(folder / "bad.xlsx")
    done = run("batch", folder, "--out", tmp_path / "out", "--format", "xlsx", cwd=tmp_path)
    assert_refused(done, "bad.xlsx", "loop of symbolic links")
    assert "RuntimeError" not in done.stderr


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs on this system")
def test_a_fifo_named_like_a_workbook_does_not_hang(tmp_path):
    folder = tmp_path / "portfolio"
    folder.mkdir()
    _write_building(folder, "alpha", ITEMS["alpha"])
    os.mkfifo(folder / "bad.xlsx")
    done = run("batch", folder, "--out", tmp_path / "out", "--format", "xlsx", cwd=tmp_path, timeout=60)
    assert_refused(done, "bad.xlsx", "not a regular file")
    # the main command and a sheet portfolio that names it: refused too, not waiting for a writer
    assert_refused(run(folder / "bad.xlsx", "--hazard", "2in50", cwd=tmp_path, timeout=60), "bad.xlsx",
                   "not a regular file")


def test_a_portfolio_with_two_buildings_sheets_is_refused(tmp_path):
    """Second hostile-input campaign: sheets 'buildings' and 'BUILDINGS' ran (exit 0) on one of them; which
    one holds the portfolio is not clear, as for a workbook's sheets. (openpyxl itself renames a second
    'BUILDINGS' to 'BUILDINGS1', so the file is written with it and renamed in its workbook part.)"""
    import zipfile
    from openpyxl import Workbook
    from assess.portfolio.batch import read_portfolio
    from assess.errors import InputError
    book = Workbook()
    book.active.title = "buildings"
    book.create_sheet("XUILDINGS")
    for sheet in book.worksheets:
        sheet.append(["building", "workbook"])
        sheet.append(["lab", "lab.xlsx"])
    book.save(tmp_path / "written.xlsx")
    with zipfile.ZipFile(tmp_path / "written.xlsx") as source, \
            zipfile.ZipFile(tmp_path / "portfolio.xlsx", "w", zipfile.ZIP_DEFLATED) as target:
        for part in source.infolist():
            data = source.read(part.filename)
            if part.filename == "xl/workbook.xml":
                data = data.replace(b'name="XUILDINGS"', b'name="BUILDINGS"')
            target.writestr(part, data)
    with pytest.raises(InputError) as error:
        read_portfolio(tmp_path / "portfolio.xlsx")
    assert "'buildings' and 'BUILDINGS'" in error.value.problems[0].message
