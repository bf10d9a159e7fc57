"""The files of a run, made in memory from its result (:func:`render_outputs`; docs/outputs.md).

They are written by :func:`assess.command.folders.write_atomically` (all of them, or
the folder as it was). Text written to CSV is protected from spreadsheet
formulas (:func:`assess.report.tables.neutralise_formulas`).
"""
from __future__ import annotations

from assess import report
from assess.assessment.result import AssessmentResult
from assess.fragility.stripes import fragility_files
from assess.quantity_text import system_of
from assess.report import advice
from assess.report.anchorage_table import anchorage_rows
from assess.report.spreadsheet import summary_workbook, with_us_units
from assess.report.tables import csv_text, neutralise_formulas, restore_text, summary_text  # noqa: F401 (re-exported)


def render_outputs(result: AssessmentResult, formats: tuple[str, ...], units: str | None = None,
                   other_levels: tuple[AssessmentResult, ...] = ()) -> dict[str, bytes]:
    """All files of a run, by name, as bytes (nothing is written here).

    ``formats`` may hold ``html``, ``pdf`` (the report) and ``xlsx``
    (summary.xlsx, :func:`assess.report.spreadsheet.summary_workbook`, with
    inches beside centimetres in US units). ``units`` (``si`` or ``us``) defaults to the result's
    settings' (``--units`` or the workbook's, :func:`assess.quantity_text.system_of`). ``other_levels``, the
    results of the other levels of the same run, add their sheets to summary.xlsx
    after this level's.
    """
    result = advice.with_words(result)
    other_levels = tuple(advice.with_words(other) for other in other_levels)
    files = _tables(result, formats, units, other_levels)
    if "html" in formats or "pdf" in formats:
        html = report.render_html(result)
        if "html" in formats:
            files["report.html"] = html.encode()
        if "pdf" in formats:
            files["report.pdf"] = report.render_pdf(html)
    return files


def _tables(result: AssessmentResult, formats: tuple[str, ...], units: str | None,
            other_levels: tuple[AssessmentResult, ...]) -> dict[str, bytes]:
    """The files of a run that are tables (CSV, and summary.xlsx where ``formats`` has ``xlsx``)."""
    units = system_of(result.settings or {}) if units is None else system_of(units)
    summary = with_us_units(result.summary) if units == "us" else result.summary
    files = {
        "summary.csv": csv_text(summary_text(summary)).encode(),
        "motions.csv": csv_text(result.motions).encode(),
        "work_orders.csv": csv_text(result.work_orders()).encode(),
    }
    if "xlsx" in formats:
        sheets = {result.level_label: summary_text(result.summary)}
        sheets.update({other.level_label: summary_text(other.summary) for other in other_levels})
        for level in (result, *other_levels):  # the anchorage an engineer checks, a sheet per level
            table = anchorage_rows(level)
            if len(table):
                sheets[f"anchorage {level.level_label}"] = table
        files["summary.xlsx"] = summary_workbook(sheets, units=units)
    if result.curve_risk is not None:
        files.update(fragility_files(result.curve_risk, result.summary))
    if result.comparison is not None:
        files["comparison.csv"] = csv_text(result.comparison).encode()
    for name, table in (("ground_motions.csv", result.ground_motions), ("spectrum.csv", result.spectrum),
                        ("floors.csv", result.floors)):
        if table is not None:
            files[name] = csv_text(table).encode()
    return files
