"""Read the measured table tests (MEASURED.xlsx sheet ``tests``, docs/workbook.md) and the motion of each.

One row per test: ``specimen`` (an ``equipment.id`` of the inventory
workbook), ``motion`` (a ``hazard.motion`` of the workbook: the motion as the
table or floor actually played it) and at least one measure: ``sliding_cm``
(peak |sliding| relative to the floor [cm]), ``theta_max_over_alpha`` (peak
|rotation| over α of the declared dimensions [-]) and ``overturned``
(yes/no). An optional ``direction`` column (1 = along the item's width, 2 =
along its depth) says which base direction the test shook; without it every
test is taken to have shaken direction 1 (the width), which is the direction a
table test of a cabinet usually plays against its slender side.

Every problem of every row is collected and raised together in one
:class:`~assess.errors.InputError` (file, sheet, row, cell and a fix each).
The file is read as the inventory workbook is (:mod:`assess.inventory.xlsx`):
bounded, streamed, only the cells that hold something, a damaged cell or an
Excel error reported at its address; messages quote at most 80 characters
of a cell.
"""
from __future__ import annotations

import difflib
from pathlib import Path

import numpy as np
import pandas as pd

from assess.errors import InputError, Problem, raise_if_any
from assess.hazard.records import Record, pulse_record, read_record

SHEET = "tests"
#: Columns of the ``tests`` sheet; the first two are required, then at least one measure.
REQUIRED = ("specimen", "motion")
MEASURES = ("sliding_cm", "theta_max_over_alpha", "overturned")
OPTIONAL = ("direction",)
#: Pulse simulated for a motion given by PTA and Tp without a pulse type (as the assessment does).
DEFAULT_PULSE = "B"
#: Columns of the table :func:`read_measured` returns (SI).
#: Free-text columns, ignored (the same as the workbook's).
FREE_TEXT = ("notes", "note", "source", "comment")
COLUMNS = ["specimen", "motion", "direction", "sliding_m", "theta_max_over_alpha", "overturned", "row"]

#: Largest plausible measured peak sliding [cm]: no shake table or floor travels 100 m.
SLIDING_MAX_CM = 10_000.0
#: Largest plausible θmax/α: a block that tips past α overturns, and α of any item on a floor
#: exceeds 0.01 rad, so θ/α beyond π/2 / 0.01 ≈ 157 is not a rotation (1000 leaves room).
THETA_MAX_OVER_ALPHA = 1000.0
#: A cell already reported (an Excel error, a damaged cell), skipped by the checks.
_UNUSABLE = object()

_YES = {"yes", "y", "true", "1"}
_NO = {"no", "n", "false", "0"}


def read_measured(path, inventory) -> pd.DataFrame:
    """The tests of MEASURED.xlsx, checked against ``inventory``.

    Returns
    -------
    pandas.DataFrame
        Columns :data:`COLUMNS`: ``sliding_m`` [m] and ``theta_max_over_alpha``
        [-] NaN where not measured, ``overturned`` True/False or None where
        not observed, ``direction`` 1 or 2, ``row`` the Excel row.

    Raises
    ------
    InputError
        With every problem found (unreadable or damaged file, missing sheet or
        column, unknown specimen or motion, a value that is not a measure, a
        row without any measure, no test at all).
    """
    from assess.inventory import xlsx

    path = Path(path)
    name = path.name
    try:
        with xlsx.Book(path) as book:
            if SHEET not in book.sheetnames or not book.is_table(SHEET):
                have = ", ".join(f"'{clip(t, 40)}'" for t in book.sheetnames[:20])
                raise InputError([Problem(name, f"there is no sheet '{SHEET}' (sheets: {have}).",
                                          f"name the sheet of the tests '{SHEET}'.")])
            cells = book.cells(SHEET)
    except xlsx.Unreadable as error:
        message = error.message
        if "does not exist" in message:
            message = f"the measured-tests workbook {clip(str(path), 200)} does not exist."
        raise InputError([Problem(name, message, error.fix, sheet=error.sheet)]) from None
    return measured_from_cells(cells.header, cells.data_rows(), inventory, file=name)


def measured_from_rows(rows, inventory, *, file="MEASURED.xlsx") -> pd.DataFrame:
    """The table of :func:`read_measured` from a ``tests`` sheet given as lists of values (header first)."""
    header = {k + 1: v for k, v in enumerate(rows[0])} if rows else {}
    numbered = [(number, {k + 1: v for k, v in enumerate(values)})
                for number, values in enumerate(rows[1:], start=2)]
    return measured_from_cells(header, numbered, inventory, file=file)


def measured_from_cells(header_cells: dict, rows: list, inventory, *, file="MEASURED.xlsx") -> pd.DataFrame:
    """Check a ``tests`` sheet and return the table of :func:`read_measured`.

    ``header_cells`` holds row 1 by 1-based column; ``rows`` the rows below as
    ``(row number, {column: value})`` (blank cells may be absent).
    """
    from openpyxl.utils import get_column_letter

    from assess.inventory import xlsx

    problems: list[Problem] = []

    def report(message, fix, row=None, column=None, cell=None):
        problems.append(Problem(file, message, fix, sheet=SHEET, row=row, column=column, cell=cell))

    for number, values in [(1, header_cells), *rows]:  # cells the file could not give a value
        for k, value in list(values.items()):
            if isinstance(value, xlsx.MARKERS):
                report(f"cell {get_column_letter(k)}{number} {_marker_text(value)}",
                       "retype the cell in Excel or LibreOffice and save the workbook.",
                       row=number, cell=f"{get_column_letter(k)}{number}")
                values[k] = _UNUSABLE
    if all(_blank(v) for v in header_cells.values()):
        report("the sheet is empty.", "put the headers specimen, motion and at least one of "
               "sliding_cm, theta_max_over_alpha, overturned in row 1, and one test per row below.", row=1)
        raise InputError(problems)
    header = {}
    for k in sorted(header_cells):
        value = header_cells[k]
        if _blank(value) or value is _UNUSABLE:
            continue
        text = str(value).strip().lower()
        if text in FREE_TEXT:  # as in the workbook: free text, ignored
            continue
        if text in header:
            report(f"the column '{clip(text, 40)}' appears twice.", "keep one of them.", row=1,
                   cell=f"{get_column_letter(k)}1")
        elif text not in REQUIRED + MEASURES + OPTIONAL:
            close = difflib.get_close_matches(text, REQUIRED + MEASURES + OPTIONAL, n=1)
            report(f"unknown column '{clip(value, 40)}'.", f"rename it to '{close[0]}'." if close else
                   f"use only {', '.join(REQUIRED + MEASURES + OPTIONAL)} (and free-text "
                   f"{', '.join(FREE_TEXT)}).", row=1,
                   cell=f"{get_column_letter(k)}1")
        else:
            header[text] = k
    for column in REQUIRED:
        if column not in header:
            report(f"the required column '{column}' is missing.", f"add a column headed '{column}'.", row=1)
    if not any(m in header for m in MEASURES):
        report("no measure column.", "add at least one of sliding_cm, theta_max_over_alpha, overturned.",
               row=1)
    raise_if_any(problems)  # assess.errors lists the first 50 and counts the rest

    equipment = inventory.equipment.set_index("id", drop=False)
    known_ids = [str(i) for i in equipment["id"]]
    known_motions = list(dict.fromkeys(str(m) for m in inventory.hazard["motion"]))
    workbook = Path(inventory.path).name
    records = []
    for number, values in rows:
        if all(_blank(v) for v in values.values()):
            continue

        def cell(column):
            k = header.get(column)
            return None if k is None else values.get(k)

        def where(column):
            return dict(row=number, column=column, cell=f"{get_column_letter(header[column])}{number}")

        specimen = cell("specimen")
        if specimen is _UNUSABLE:
            pass
        elif _blank(specimen):
            report("no specimen.", f"give the id of an item of {workbook}.", **where("specimen"))
        elif str(specimen).strip() not in known_ids:
            report(f"specimen '{clip(specimen)}' is not an equipment id of {workbook}.",
                   _closest(specimen, known_ids,
                            f"use one of the ids of {workbook}'s equipment sheet, or add the item there."),
                   **where("specimen"))
        elif bool(equipment.loc[str(specimen).strip(), "anchored"]):
            report(f"specimen '{clip(specimen)}' is anchored in {workbook}: an anchored item neither slides "
                   f"nor rocks in the model, so its tests cannot calibrate it.",
                   f"set anchored to no in {workbook} for the tested item, or remove the test.",
                   **where("specimen"))
        motion = cell("motion")
        if motion is _UNUSABLE:
            pass
        elif _blank(motion):
            report("no motion.", f"give the name of a motion of {workbook}'s hazard sheet.", **where("motion"))
        elif str(motion).strip() not in known_motions:
            report(f"motion '{clip(motion)}' is not a motion of {workbook}'s hazard sheet.",
                   _closest(motion, known_motions, f"add the motion the table played to {workbook}'s "
                            "hazard sheet (record or PTA and Tp)."),
                   **where("motion"))

        direction = 1
        if _given(cell("direction")):
            value = _number(cell("direction"))
            if value not in (1.0, 2.0):
                report(f"direction '{clip(cell('direction'))}' is neither 1 nor 2.",
                       "write 1 for shaking along the width, 2 along the depth.", **where("direction"))
            else:
                direction = int(value)

        sliding_m = np.nan
        if _given(cell("sliding_cm")):
            value = _number(cell("sliding_cm"))
            if value is None or not 0.0 <= value <= SLIDING_MAX_CM:
                report(f"sliding_cm '{clip(cell('sliding_cm'))}' is not a peak sliding (a number from 0 "
                       f"to {SLIDING_MAX_CM:,.0f}, in cm).",
                       "write the measured peak sliding in cm, or leave the cell empty.", **where("sliding_cm"))
            else:
                sliding_m = value / 100.0
        theta = np.nan
        if _given(cell("theta_max_over_alpha")):
            value = _number(cell("theta_max_over_alpha"))
            if value is None or not 0.0 <= value <= THETA_MAX_OVER_ALPHA:
                report(f"theta_max_over_alpha '{clip(cell('theta_max_over_alpha'))}' is not a number "
                       f"from 0 to {THETA_MAX_OVER_ALPHA:g}.",
                       "write the peak rotation divided by the item's slenderness α, or leave it empty.",
                       **where("theta_max_over_alpha"))
            else:
                theta = value
        overturned = None
        if _given(cell("overturned")):
            value = cell("overturned")
            text = str(value).strip().lower() if not isinstance(value, bool) else str(value).lower()
            if text in _YES:
                overturned = True
            elif text in _NO:
                overturned = False
            else:
                report(f"overturned '{clip(value)}' is neither yes nor no.", "write yes or no, or leave it empty.",
                       **where("overturned"))
        if all(_blank(cell(m)) for m in MEASURES if m in header):
            report("the test has no measure.", "give at least one of sliding_cm, theta_max_over_alpha, "
                   "overturned, or delete the row.", row=number)
        records.append(dict(specimen=None if _blank(specimen) else str(specimen).strip(),
                            motion=None if _blank(motion) else str(motion).strip(), direction=direction,
                            sliding_m=sliding_m, theta_max_over_alpha=theta, overturned=overturned,
                            row=number))
    if not records and not problems:
        report("the sheet has headers but no test.", "add one row per test below the headers.", row=2)
    raise_if_any(problems)  # assess.errors lists the first 50 and counts the rest
    return pd.DataFrame(records, columns=COLUMNS)


def test_motion(inventory, motion: str) -> Record:
    """The floor acceleration a test under ``motion`` played, from the workbook's hazard sheet.

    The first hazard row named ``motion`` gives it: its record times its
    ``scale`` when it has a record, else its pulse (the ``pulse`` column,
    Type-B when empty) of amplitude ``pta_g`` and period ``tp_s``. This is
    deterministic on purpose: a table test plays one known motion, so the
    calibration compares each measurement with one simulation, never with the
    synthetic realisations the assessment draws for a design motion.

    Raises
    ------
    InputError
        When the row has neither a readable record nor PTA and Tp.
    """
    rows = inventory.hazard[inventory.hazard["motion"].astype(str) == str(motion)]
    workbook = Path(inventory.path).name
    if rows.empty:
        raise InputError([Problem(workbook, f"there is no motion '{motion}'.",
                                  "add the motion to the hazard sheet.", sheet="hazard")])
    row = rows.iloc[0]
    record_path = str(row.get("record_path", "") or "")
    if record_path:
        try:
            record = read_record(record_path)
        except InputError as error:
            raise InputError([Problem(p.file, f"the record of motion '{motion}' ({workbook}, sheet 'hazard', "
                                      f"row {int(row['row'])}): {p.message}", p.fix, row=p.row)
                              for p in error.problems]) from None
        return record.scaled(float(row.get("scale", 1.0) or 1.0))
    pta, tp = float(row["pta_g"]), float(row["tp_s"])
    if not (np.isfinite(pta) and pta > 0 and np.isfinite(tp) and tp > 0):
        raise InputError([Problem(workbook, f"motion '{motion}' has neither a record nor PTA and Tp, so the "
                                  f"motion the table played is unknown.", "give its record_path, or pta and tp.",
                                  sheet="hazard", row=int(row["row"]))])
    return pulse_record(str(row.get("pulse", "") or "") or DEFAULT_PULSE, pta, tp)


test_motion.__test__ = False  # not a pytest test despite its name





def _closest(value, known, otherwise: str) -> str:
    """'did you mean …?' with the closest of ``known``, or ``otherwise``."""
    close = difflib.get_close_matches(str(value).strip(), list(known), n=1)
    return f"did you mean '{close[0]}'?" if close else otherwise


def _blank(value) -> bool:
    return value is None or (isinstance(value, str) and not value.strip())


def _given(value) -> bool:
    """A cell that holds a value to check (not blank, not already reported)."""
    return not _blank(value) and value is not _UNUSABLE


def _number(value):
    """The finite number in a cell, or None (text, a date, NaN, infinity, hundreds of digits)."""
    if isinstance(value, bool):
        return None
    try:
        number = float(value) if isinstance(value, (int, float)) else float(str(value).strip())
    except (ValueError, OverflowError):
        return None
    return number if np.isfinite(number) else None


def _marker_text(marker) -> str:
    """What is wrong with a cell the reader could not give a value (see assess.inventory.xlsx)."""
    from assess.inventory import xlsx

    if isinstance(marker, xlsx.ExcelError):
        return f"shows the Excel error {marker.code} (a formula that failed)."
    if isinstance(marker, xlsx.NoCachedValue):
        return "holds a formula with no computed value (saved by a program that does not calculate)."
    return f"cannot be read: {marker.reason}; the file is damaged there."


def clip(value, limit: int = 80) -> str:
    """A cell's text on one line, at most ``limit`` characters (never a whole cell of the file)."""
    text = " ".join(str(value).split())
    return text if len(text) <= limit else text[:limit - 1] + "…"
