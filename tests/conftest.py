"""Shared fixtures: workbooks built in a scratch folder (see ``tests/workbooks.py``)."""
from __future__ import annotations

import pytest

from workbooks import RECORD_FILE, good_sheets, write_workbook

#: A tiny acceleration record, written next to every built workbook unless asked not to.
RECORD_TEXT = "time_s,accel_g\n0.00,0.0\n0.01,0.1\n0.02,0.0\n"


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
