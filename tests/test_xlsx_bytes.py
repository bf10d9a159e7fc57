"""summary.xlsx carries no time of writing: the same inputs give the same bytes (docs/outputs.md)."""
from __future__ import annotations

import io
import zipfile

import pandas as pd

from assess.report.spreadsheet import FIXED_DATE, summary_workbook


def test_no_time_of_writing_in_the_workbook():
    data = summary_workbook({"2in50": pd.DataFrame({"id": ["a"], "clearance_cm": [1.0]})})
    with zipfile.ZipFile(io.BytesIO(data)) as archive:
        assert {info.date_time for info in archive.infolist()} == {FIXED_DATE.timetuple()[:6]}
        core = archive.read("docProps/core.xml").decode()
    stamp = FIXED_DATE.strftime("%Y-%m-%dT%H:%M:%SZ")
    assert core.count(stamp) == 2, core  # created and modified
    assert data == summary_workbook({"2in50": pd.DataFrame({"id": ["a"], "clearance_cm": [1.0]})})
