"""``summary.xlsx``: the summary table for people who open it in a spreadsheet.

The same rows and columns as ``summary.csv`` (one sheet per hazard level),
with a frozen bold header whose names carry their units, number formats that
show what the numbers are (percent for probabilities, one decimal for
lengths), widths that fit, and an autofilter. Text from the workbook is made
inert as in the CSV (:func:`assess.report.tables.neutralise_formulas`): a cell never
becomes a formula. With ``units="us"`` the lengths are also given in inches
and the accelerations stay in g (a US engineer's unit for them), in columns
named with their unit beside the SI ones.
"""
from __future__ import annotations

import datetime
import io
import re
import zipfile

import numpy as np
import pandas as pd

from assess.inventory.units import CM_PER_IN, M_PER_FT, N_PER_LBF
from assess.report.tables import neutralise_formulas

#: The date written into a workbook's document properties and zip entries: no time of day goes into a file,
#: so the same inputs give the same bytes.
FIXED_DATE = datetime.datetime(2024, 1, 1, 0, 0, 0)
_FORBIDDEN_IN_SHEET_NAMES = re.compile(r"[\[\]:*?/\\]")


def sheet_name(label: str) -> str:
    """A sheet name Excel accepts: at most 31 characters, none of []:*?/\\.

    >>> sheet_name("2%/50yr"), sheet_name("")
    ('2%_50yr', 'level')
    """
    name = _FORBIDDEN_IN_SHEET_NAMES.sub("_", str(label)).strip("'")[:31]
    return name or "level"


#: SI column suffix -> (US suffix, factor from the SI unit to the US one): cm -> in, kN -> kip, kN·m -> kip·ft
#: (exact: 1 in = 2.54 cm, 1 lbf = 4.4482216152605 N, 1 ft = 0.3048 m).
US_COLUMNS = {"_cm": ("_in", 1.0 / CM_PER_IN), "_kn": ("_kip", 1.0 / N_PER_LBF),
              "_knm": ("_kip_ft", 1.0 / N_PER_LBF / M_PER_FT)}


def with_us_units(summary: pd.DataFrame) -> pd.DataFrame:
    """``summary`` with every ``*_cm`` column followed by the same length in inches (``*_in``), every
    ``*_kn`` force by kips (``*_kip``) and every ``*_knm`` moment by kip·ft (``*_kip_ft``); the SI columns
    are kept as they are.

    >>> table = pd.DataFrame({"clearance_cm": [2.54], "anchor_force_kn": [4.4482216152605]})
    >>> with_us_units(table).round(6).to_dict("list")
    {'clearance_cm': [2.54], 'clearance_in': [1.0], 'anchor_force_kn': [4.448222], 'anchor_force_kip': [1.0]}
    """
    columns = {}
    for column in summary.columns:
        columns[column] = summary[column]
        for suffix, (us_suffix, factor) in US_COLUMNS.items():
            us_column = column[:-len(suffix)] + us_suffix
            if column.endswith(suffix) and us_column not in summary.columns:
                columns[us_column] = pd.to_numeric(summary[column], errors="coerce") * factor
    return pd.DataFrame(columns, index=summary.index)


#: Name endings of the columns that carry a unit: never a probability, whatever they start with
#: (``p_rad_s`` is the frequency parameter p in rad/s, not a chance).
_UNIT_SUFFIXES = ("_cm", "_in", "_g", "_rad", "_rad_s", "_s", "_kn", "_knm", "_kip", "_kip_ft", "_yr")


def _number_format(column: str) -> str | None:
    """The Excel number format of a summary column: a percentage for a probability (``p_…``, ``p50yr_…``,
    but not a name that ends in a unit), one decimal for lengths, three for the other quantities and ratios.

    >>> _number_format("p_overturn"), _number_format("p_rad_s"), _number_format("clearance_cm")
    ('0.0%', '0.000', '0.0')
    """
    if (column.startswith(("p_", "p50yr_")) and not column.endswith(_UNIT_SUFFIXES)) \
            or column in ("pf_sliding", "overturn_fraction"):
        return "0.0%"
    if column.startswith("annual_rate_"):
        return "0.00E+00"
    if column in ("value", "mitigation_cost", "expected_loss", "expected_loss_after", "expected_annual_loss",
                  "expected_annual_loss_after"):
        return "#,##0.00"
    if column in ("benefit_cost_ratio", "loss_avoided_per_cost"):
        return "0.00"
    if column.endswith(("_cm", "_in")):
        return "0.0"
    if column.endswith(("_kn", "_knm", "_kip", "_kip_ft")):  # the anchorage forces and moments
        return "0.00"
    if column.endswith(("_g", "_rad", "_rad_s", "_s")) or column in ("b_over_h", "mu", "im", "edp_median",
                                                                      "theta_max_over_alpha"):
        return "0.000"
    return None


def summary_workbook(tables: dict[str, pd.DataFrame], units: str = "si") -> bytes:
    """The ``.xlsx`` bytes of one sheet per level: ``tables`` maps a level's label to its summary.

    ``units``: ``"si"`` (the CSV's SI columns) or ``"us"`` (inches beside every length in cm, kips beside
    every force in kN, :func:`with_us_units`).
    """
    from openpyxl import Workbook
    from openpyxl.styles import Alignment, Font, PatternFill
    from openpyxl.utils import get_column_letter

    workbook = Workbook()
    workbook.remove(workbook.active)
    for label, summary in tables.items():
        table = neutralise_formulas(with_us_units(summary) if units == "us" else summary)
        sheet = workbook.create_sheet(sheet_name(label))
        sheet.append(list(table.columns))
        for values in table.itertuples(index=False):
            sheet.append([_cell(v) for v in values])
        for k, column in enumerate(table.columns, start=1):
            letter = get_column_letter(k)
            header = sheet.cell(row=1, column=k)
            header.font = Font(bold=True)
            header.fill = PatternFill("solid", fgColor="E5E8E8")
            header.alignment = Alignment(wrap_text=True, vertical="top")
            number_format = _number_format(column)
            if number_format:
                for cell in sheet[letter][1:]:
                    cell.number_format = number_format
            longest = max([len(str(column))] + [len(str(v)) for v in table[column].head(200) if isinstance(v, str)])
            sheet.column_dimensions[letter].width = min(max(9, longest * 0.9 + 2), 60)
        sheet.freeze_panes = "C2"  # the header, and the id and name columns
        sheet.auto_filter.ref = sheet.dimensions
    return deterministic_bytes(workbook, "assess")


def deterministic_bytes(workbook, creator: str, date: datetime.datetime = FIXED_DATE) -> bytes:
    """The .xlsx bytes of an openpyxl ``workbook`` with ``date`` as its document dates and zip timestamps.

    openpyxl stamps the document's ``modified`` property and every zip entry with the time of saving;
    both are rewritten here, so a workbook saved twice is the same bytes.
    """
    from openpyxl.xml.functions import tostring  # openpyxl is imported with the workbook it serialises

    workbook.properties.creator = creator
    workbook.properties.created = workbook.properties.modified = date
    raw = io.BytesIO()
    workbook.save(raw)
    workbook.properties.modified = date
    out = io.BytesIO()
    with zipfile.ZipFile(raw) as zin, zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as zout:
        for info in zin.infolist():
            data = zin.read(info.filename)
            if info.filename == "docProps/core.xml":
                data = tostring(workbook.properties.to_tree())
            zout.writestr(zipfile.ZipInfo(info.filename, date.timetuple()[:6]), data,
                          compress_type=zipfile.ZIP_DEFLATED)
    return out.getvalue()


def _cell(value):
    """A value openpyxl writes as it is: NaN as an empty cell, infinity (an interval the suite cannot bound)
    as "unbounded", numpy scalars as Python numbers."""
    if value is None or (isinstance(value, float) and np.isnan(value)) or value is pd.NA:
        return None
    if isinstance(value, np.generic):
        value = value.item()
        if isinstance(value, float) and np.isnan(value):
            return None
    if isinstance(value, float) and np.isinf(value):  # a spreadsheet has no infinity: say it in words
        return "unbounded" if value > 0 else "-unbounded"
    return value
