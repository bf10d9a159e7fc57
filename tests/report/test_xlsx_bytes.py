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


def test_probabilities_are_percentages_and_a_frequency_in_rad_s_is_not():
    """p_rad_s (the frequency parameter p [rad/s]) begins like a probability (p_overturn) but carries a unit:
    it is shown as a number, the chances as percentages."""
    from openpyxl import load_workbook

    data = summary_workbook({"DE": pd.DataFrame({"id": ["a"], "p_rad_s": [2.31], "p_overturn": [0.25],
                                                 "p50yr_overturn": [0.01], "pta_g": [0.5]})})
    sheet = load_workbook(io.BytesIO(data))["DE"]
    formats = {sheet.cell(1, k).value: sheet.cell(2, k).number_format for k in range(1, sheet.max_column + 1)}
    assert "%" not in formats["p_rad_s"] and "%" not in formats["pta_g"]
    assert formats["p_overturn"].endswith("%") and formats["p50yr_overturn"].endswith("%")
