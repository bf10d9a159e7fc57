"""The files of a run, made in memory from its result (:func:`render_outputs`; docs/outputs.md).

They are written by :func:`assess.command.folders.write_atomically` (all of them, or
the folder as it was). Text written to CSV is protected from spreadsheet
formulas (:func:`assess.report.tables.neutralise_formulas`); every column of a CSV is one
``assess/data/columns.csv`` declares, in its order (:func:`assess.report.tables.as_declared`).
"""
from __future__ import annotations

from assess import report
from assess.assessment.result import AssessmentResult
from assess.fragility.stripes import fragility_files
from assess.quantity_text import system_of
from assess.report import advice
from assess.report.anchorage_table import anchorage_rows
from assess.report.spreadsheet import summary_workbook, with_us_units
from assess.report.tables import (  # noqa: F401 (re-exported)
    as_declared, csv_text, declared_csv_text, neutralise_formulas, restore_text, summary_text,
)


def render_outputs(result: AssessmentResult, formats: tuple[str, ...], units: str | None = None,
                   other_levels: tuple[AssessmentResult, ...] = (), pdf_processes: int | None = None
                   ) -> dict[str, bytes]:
    """All files of a run, by name, as bytes (nothing is written here).

    ``formats`` may hold ``html``, ``pdf`` (the report) and ``xlsx``
    (summary.xlsx, :func:`assess.report.spreadsheet.summary_workbook`, with
    inches beside centimetres in US units). ``units`` (``si`` or ``us``) defaults to the result's
    settings' (``--units`` or the workbook's, :func:`assess.quantity_text.system_of`). ``other_levels``, the
    results of the other levels of the same run, add their sheets to summary.xlsx
    after this level's. ``pdf_processes``: as :func:`assess.report.pdf.render_pdf` takes its ``processes``
    (1 on a cluster's worker, which may start no process and has a core per thread; the bytes are the same).
    """
    result = advice.with_words(result)
    other_levels = tuple(advice.with_words(other) for other in other_levels)
    files = _tables(result, formats, units, other_levels)
    files.update(report.report_files(result, html="html" in formats, pdf="pdf" in formats,
                                     pdf_processes=pdf_processes))
    return files


def _tables(result: AssessmentResult, formats: tuple[str, ...], units: str | None,
            other_levels: tuple[AssessmentResult, ...]) -> dict[str, bytes]:
    """The files of a run that are tables (CSV, and summary.xlsx where ``formats`` has ``xlsx``)."""
    units = system_of(result.settings) if units is None else system_of(units)
    summary = with_us_units(result.summary) if units == "us" else result.summary
    files = {
        "summary.csv": declared_csv_text("summary.csv", summary_text(summary)).encode(),
        "motions.csv": declared_csv_text("motions.csv", result.motions).encode(),
        "work_orders.csv": declared_csv_text("work_orders.csv", result.work_orders()).encode(),
    }
    if "xlsx" in formats:
        sheets = {result.level_label: summary_text(result.summary)}
        sheets.update({other.level_label: summary_text(other.summary) for other in other_levels})
        for level in (result, *other_levels):  # the anchorage an engineer checks, a sheet per level
            table = anchorage_rows(level)
            if len(table):
                sheets[f"anchorage {level.level_label}"] = as_declared("summary.xlsx anchorage", table)
        files["summary.xlsx"] = summary_workbook(sheets, units=units)
    if result.curve_risk is not None:
        files.update(fragility_files(result.curve_risk, result.summary))
    if result.comparison is not None:
        files["comparison.csv"] = declared_csv_text("comparison.csv", result.comparison).encode()
    for name, table in (("ground_motions.csv", result.ground_motions), ("spectrum.csv", result.spectrum),
                        ("floors.csv", result.floors)):
        if table is not None:
            files[name] = declared_csv_text(name, table).encode()
    return files
