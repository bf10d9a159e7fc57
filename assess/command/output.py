"""The files of a run, made in memory from its result (:func:`render_outputs`; docs/outputs.md).

They are written by :func:`assess.command.folders.write_atomically` (all of them, or
the folder as it was). Text written to CSV is protected from spreadsheet
formulas (:func:`assess.report.tables.neutralise_formulas`).
"""
from __future__ import annotations

import contextlib

from assess import report
from assess.assessment.result import AssessmentResult
from assess.fragility.stripes import fragility_files
from assess.quantity_text import system_of
from assess.report.spreadsheet import summary_workbook, with_us_units
from assess.report.tables import csv_text, neutralise_formulas, restore_text, summary_text  # noqa: F401 (re-exported)


def render_outputs(result: AssessmentResult, formats: tuple[str, ...], units: str | None = None,
                   other_levels: tuple[AssessmentResult, ...] = (), pdf_process=None) -> dict[str, bytes]:
    """All files of a run, by name, as bytes (nothing is written here).

    ``formats`` may hold ``html``, ``pdf`` (the report) and ``xlsx``
    (summary.xlsx, :func:`assess.report.spreadsheet.summary_workbook`, with
    inches beside centimetres in US units). ``units`` (``si`` or ``us``) defaults to the result's
    settings' (``--units`` or the workbook's, :func:`assess.quantity_text.system_of`). ``other_levels``, the
    results of the other levels of the same run, add their sheets to summary.xlsx
    after this level's. ``pdf_process``, the second process that draws the PDF's appendix
    (:func:`assess.report.pdf_process`), is started here where not given: a caller that renders several
    reports (``assess batch``) starts one for all of them. The ``assess`` command gives the two processes
    it starts before making the result (:func:`assess.report.body_and_appendix_processes`): one draws some
    of the figures then lays out the body, the other the appendix, and this one makes the tables meanwhile.
    """
    # the PDF's second process starts first, so that it has imported WeasyPrint by the time the HTML is made,
    # and is sent the appendix before this one draws the figures (render_html), so that it lays it out meanwhile
    started = report.pdf_process() if "pdf" in formats and pdf_process is None else contextlib.nullcontext(pdf_process)
    with started as pdf_process:
        html = None
        if "html" in formats or "pdf" in formats:
            html = report.render_html(result, pdf_process if "pdf" in formats else None)
        files: dict[str, bytes] = {}

        def tables() -> None:
            files.update(_tables(result, formats, units, other_levels))

        pdf = None
        if "pdf" in formats:  # the tables are made while the PDF's parts are laid out, where other processes do
            pdf = report.render_pdf(html, process=pdf_process, meanwhile=tables)
        else:
            tables()
        if "html" in formats:
            files["report.html"] = html.encode()
        if pdf is not None:
            files["report.pdf"] = pdf
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
