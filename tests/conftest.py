"""Shared fixtures: workbooks built in a scratch folder (see ``tests/workbooks.py``)."""
from __future__ import annotations

import pytest

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
