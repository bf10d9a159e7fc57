"""--compare-with and the summary.csv found in --out: a previous summary is read only when it is a bounded
regular CSV table of known classes (a third hostile-input campaign: a FIFO hung the run, /dev/zero grew to
gigabytes, 20,000 rows took 1.5 GB laying every removed item out in the report, raw pandas errors were
passed through, an unknown class counted as "same")."""
from __future__ import annotations

import os
import threading

import pandas as pd
import pytest

from assess.assessment import comparison
from assess.errors import InputError
from assess.report.sentences import MAX_CHANGE_ROWS, changes


def _summary(path, rows):
    pd.DataFrame(rows).to_csv(path, index=False)
    return path


def test_a_fifo_is_refused_without_blocking(tmp_path):
    fifo = tmp_path / "summary.csv"
    os.mkfifo(fifo)
    outcome = {}

    def read():
        try:
            comparison.read_previous_summary(fifo)
        except InputError as error:
            outcome["message"] = error.problems[0].message

    reader = threading.Thread(target=read, daemon=True)
    reader.start()
    reader.join(timeout=10)
    assert not reader.is_alive(), "reading a FIFO blocked"
    assert "not a regular file" in outcome["message"]


def test_a_device_is_refused():
    with pytest.raises(InputError, match="not a regular file"):
        comparison.read_previous_summary("/dev/zero")


def test_a_file_too_large_is_refused(tmp_path, monkeypatch):
    path = _summary(tmp_path / "summary.csv", [{"id": "A", "risk": "low"}] * 50)
    monkeypatch.setattr(comparison, "MAX_PREVIOUS_BYTES", 100)
    with pytest.raises(InputError, match="larger than"):
        comparison.read_previous_summary(path)
    monkeypatch.setattr(comparison, "MAX_PREVIOUS_BYTES", 10**6)
    monkeypatch.setattr(comparison, "MAX_PREVIOUS_ROWS", 20)
    with pytest.raises(InputError, match="more than 20 rows"):
        comparison.read_previous_summary(path)


def test_a_broken_table_is_named_by_line_without_its_contents(tmp_path):
    path = tmp_path / "summary.csv"
    path.write_text('id,risk\nA,low\nB,"secret\\n text,high,x,y\n')
    with pytest.raises(InputError) as error:
        comparison.read_previous_summary(path)
    message = error.value.problems[0].message
    assert "not a CSV table" in message and "secret" not in message and "\\n" not in message


def test_an_unknown_previous_class_is_refused_at_its_line(tmp_path):
    path = _summary(tmp_path / "summary.csv", [{"id": "A", "risk": "low"}, {"id": "B", "risk": "extreme"}])
    with pytest.raises(InputError) as error:
        comparison.read_previous_summary(path)
    problem = error.value.problems[0]
    assert problem.row == 3 and "not one of" in problem.message


def test_the_report_lays_out_at_most_its_share_of_changes():
    previous = pd.DataFrame({"id": [f"X{k}" for k in range(20_000)], "name": "gone", "risk": "low"})
    current = pd.DataFrame({"id": ["A"], "name": ["here"], "risk": ["high"]})
    table = comparison.compare_summaries(previous, current)
    shown = changes(table)
    assert shown["changed"] == 20_001 and len(shown["rows"]) == MAX_CHANGE_ROWS
