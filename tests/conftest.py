"""Shared fixtures: workbooks built in a scratch folder (see ``tests/workbooks.py``), the sample lab's
run (see ``tests/commands.py``)."""
from __future__ import annotations

import json
import os
import subprocess

import pytest

try:
    import fcntl
except ImportError:  # not on Windows
    fcntl = None

from commands import LAB, run
from workbooks import RECORD_FILE, good_sheets, write_workbook

#: A small acceleration record (2.5 s, the reader's minimum is 2 s), written next to every
#: built workbook unless asked not to.
RECORD_TEXT = "time_s,accel_g\n" + "".join(f"{k * 0.01:.2f},{0.1 if k == 1 else 0.0}\n" for k in range(251))


@pytest.fixture
def make_workbook(tmp_path):
    """``make_workbook(sheets=None, cells=None, name=..., record=True) -> Path``.

    Writes ``sheets`` (default: :func:`workbooks.good_sheets`) to ``tmp_path/name``
    with ``cells`` overridden, and the record file the good hazard sheet names.
    """
    def make(sheets=None, cells=None, name="inventory.xlsx", record=True):
        files = {RECORD_FILE: RECORD_TEXT} if record else None
        chosen = good_sheets() if sheets is None else sheets
        return write_workbook(tmp_path / name, chosen, cells, files)

    return make


@pytest.fixture(scope="session")
def lab_run(tmp_path_factory):
    """The sample lab (``inventories/lab.xlsx``) at 2in50 in every format, run once for the session
    as a user runs it in a scratch folder: ``(scratch, what the command returned)``, the outputs in
    ``scratch/reports/lab-2in50``. Tests read them or copy them; none changes them.

    Under pytest-xdist the run is made once for all the workers: the first to ask runs it, in the
    session's shared temporary folder, and the others wait for it and read what it left (the pattern of
    pytest-xdist's documentation, "Making session-scoped fixtures execute only once", with the standard
    library's ``fcntl.flock`` for the lock; where there is none, each worker runs the lab itself)."""
    if "PYTEST_XDIST_WORKER" not in os.environ or fcntl is None:  # one process (no xdist), or no flock
        scratch = tmp_path_factory.mktemp("lab")
        return scratch, run(LAB, "--hazard", "2in50", cwd=scratch)
    shared = tmp_path_factory.getbasetemp().parent
    scratch, answer = shared / "lab", shared / "lab.json"
    with open(shared / "lab.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not answer.exists():
            scratch.mkdir(exist_ok=True)  # a worker that died mid-run left it: the run writes it anew
            done = run(LAB, "--hazard", "2in50", cwd=scratch)
            answer.write_text(json.dumps([done.args, done.returncode, done.stdout, done.stderr]))
    return scratch, subprocess.CompletedProcess(*json.loads(answer.read_text()))
