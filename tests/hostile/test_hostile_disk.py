"""A full disk (or a quota, a read-only file system) while writing the output: exit 2, the folder named.

It is the machine, not a bug: no "internal error", no traceback, and the
previous output folder left byte for byte as it was. The write is made to fail
by monkeypatching it to raise ``OSError(ENOSPC)``, and, where this process may
mount one (root), on a real 1 MB tmpfs filled up.
"""
from __future__ import annotations

import errno
import os
import pathlib
import shutil
import subprocess
import sys
import uuid
from pathlib import Path

import pytest

from assess import cli
from tests.portfolio.test_batch import ITEMS, _write_building
from workbooks import write_workbook

ROOT = Path(__file__).resolve().parents[2]


def _snapshot(folder: Path) -> dict:
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


def _failing_writes(monkeypatch, code):
    def write_bytes(self, data):
        raise OSError(code, os.strerror(code), str(self))
    monkeypatch.setattr(pathlib.Path, "write_bytes", write_bytes)


@pytest.fixture
def building(tmp_path):
    folder = tmp_path / "site"
    folder.mkdir()
    return _write_building(folder, "alpha", ITEMS["alpha"])


@pytest.mark.parametrize("code, words", [(errno.ENOSPC, "the disk is full"), (errno.EDQUOT, "your disk quota is used up"),
                                         (errno.EROFS, "the file system is read-only"),
                                         (errno.EACCES, "you may not write there (permission denied)")])
def test_the_main_job_on_a_full_disk_exits_2_and_keeps_the_previous_output(tmp_path, building, monkeypatch,
                                                                            capsys, code, words):
    out = tmp_path / "out"
    assert cli.main([str(building), "--hazard", "2in50", "--out", str(out), "--format", "xlsx", "--quiet"]) == 0
    before = _snapshot(out)
    capsys.readouterr()
    _failing_writes(monkeypatch, code)
    assert cli.main([str(building), "--hazard", "2in50", "--out", str(out), "--format", "xlsx", "--quiet",
                     "--seed", "1"]) == 2
    err = capsys.readouterr().err
    assert f"{out}: the output could not be written: {words}" in err, err
    assert "internal error" not in err and "Traceback" not in err
    assert _snapshot(out) == before
    assert [p.name for p in tmp_path.iterdir() if p.name.startswith(".out-")] == []  # no staging left behind


def test_batch_on_a_full_disk_exits_2_and_keeps_the_previous_output(tmp_path, monkeypatch, capsys):
    folder = tmp_path / "portfolio"
    folder.mkdir()
    _write_building(folder, "alpha", ITEMS["alpha"])
    portfolio = write_workbook(folder / "portfolio.xlsx", {"buildings": [
        {"building": "alpha", "workbook": "alpha.xlsx", "level": "2in50"}]})
    out = tmp_path / "out"
    assert cli.main(["batch", str(portfolio), "--out", str(out), "--format", "xlsx", "--quiet"]) == 0
    before = _snapshot(out)
    capsys.readouterr()
    _failing_writes(monkeypatch, errno.ENOSPC)
    assert cli.main(["batch", str(portfolio), "--out", str(out), "--format", "xlsx", "--quiet",
                     "--seed", "1"]) == 2
    err = capsys.readouterr().err
    assert f"{out}: the output could not be written: the disk is full" in err, err
    assert "internal error" not in err and "Traceback" not in err
    assert _snapshot(out) == before


@pytest.fixture
def tiny_disk(tmp_path):
    """A 1 MB tmpfs mounted for the test (needs root); skipped where it cannot be mounted."""
    if not hasattr(os, "geteuid") or os.geteuid() != 0 or shutil.which("mount") is None:
        pytest.skip("mounting a tmpfs needs root and mount(8)")
    mount_point = tmp_path / f"disk-{uuid.uuid4().hex[:8]}"
    mount_point.mkdir()
    done = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=1m", "tmpfs", str(mount_point)],
                          capture_output=True, text=True)
    if done.returncode != 0:
        pytest.skip(f"a tmpfs cannot be mounted here ({done.stderr.strip()[:100]})")
    try:
        yield mount_point
    finally:
        subprocess.run(["umount", str(mount_point)], capture_output=True)


def test_a_real_full_disk(tmp_path, building, tiny_disk):
    out = tiny_disk / "out"
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")])}
    command = [sys.executable, "-m", "assess", str(building), "--hazard", "2in50", "--out", str(out),
               "--format", "xlsx", "--quiet"]
    first = subprocess.run(command, capture_output=True, text=True, timeout=300, env=env)
    assert first.returncode == 0, first.stderr
    before = _snapshot(out)
    free = os.statvfs(tiny_disk)
    with open(tiny_disk / "filler", "wb") as filler:  # leave about 8 kB: less than one output file
        filler.write(b"\0" * max(free.f_bavail * free.f_frsize - 8192, 0))
    second = subprocess.run(command + ["--seed", "1"], capture_output=True, text=True, timeout=300, env=env)
    assert second.returncode == 2, second.stderr
    assert f"{out}: the output could not be written: the disk is full" in second.stderr
    assert "internal error" not in second.stderr and "Traceback" not in second.stderr
    assert _snapshot(out) == before
    assert sorted(p.name for p in tiny_disk.iterdir()) == ["filler", "out"]
