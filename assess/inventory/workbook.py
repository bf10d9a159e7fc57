"""Read the inventory workbook (SPEC §1) into a validated, SI :class:`Inventory`.

:func:`read_workbook` checks the whole file before giving up: every problem of
every sheet and row is collected as a located :class:`~assess.errors.Problem`
and raised together in one :class:`~assess.errors.InputError`. Nothing is
guessed: a unit comes from the header suffix (converted with pint, see
:mod:`assess.inventory.units`), a cell that is not what its column needs is
reported, never turned into NaN, and no row is dropped except a blank one.

The column table that drives the checks is in :mod:`assess.inventory.schema`.

Safety: openpyxl parses the package XML with defusedxml when it is installed,
which refuses entity declarations ("billion laughs") and external references;
this module refuses to load without it. Formula cells are read from the value
Excel or LibreOffice cached when saving; a formula without one is reported.
"""
from __future__ import annotations

import zipfile
from dataclasses import dataclass, field
from pathlib import Path

import defusedxml
import openpyxl
import pandas as pd
from openpyxl.utils import get_column_letter
from openpyxl.worksheet.worksheet import Worksheet

from assess.data import default_settings
from assess.errors import InputError, Problem
from assess.inventory import schema
from assess.inventory.model import Inventory
from assess.inventory.schema import (EQUIPMENT, HAZARD, SETTINGS, UNUSABLE, CellError, Header,
                                     SheetSpec)

if not openpyxl.DEFUSEDXML:  # pragma: no cover - depends on the environment
    raise ImportError("assess needs openpyxl to parse workbooks with defusedxml (XML-bomb "
                      "protection): install defusedxml and unset OPENPYXL_DEFUSEDXML")

_ACCEPTED_SUFFIXES = (".xlsx", ".xlsm")
_OLE_MAGIC = b"\xd0\xcf\x11\xe0\xa1\xb1\x1a\xe1"  # encrypted .xlsx and legacy .xls
_RESAVE = "open it in Excel or LibreOffice and save it as an Excel workbook (.xlsx)."


@dataclass
class SheetReport:
    """Collects the problems of one sheet, located by row and header."""

    file: str
    sheet: str | None
    problems: list[Problem]

    def __call__(self, message: str, fix: str = "", *, row: int | None = None,
                 column: str | None = None, cell: str | None = None) -> None:
        self.problems.append(Problem(self.file, message, fix, sheet=self.sheet, row=row,
                                     column=column, cell=cell))

    def at(self, row: int, header: Header | None, message: str, fix: str = "") -> None:
        """Report a problem in ``row``, at the cell under ``header`` when there is one."""
        if header is None:
            self(message, fix, row=row)
        else:
            self(message, fix, row=row, column=header.text, cell=f"{header.letter}{row}")


@dataclass
class Row:
    """One data row of a sheet: canonical values by column name, and what failed."""

    number: int
    values: dict[str, object] = field(default_factory=dict)
    raw: dict[str, object] = field(default_factory=dict)
    failed: set[str] = field(default_factory=set)

    def ok(self, *names: str) -> bool:
        return not any(name in self.failed for name in names)


@dataclass
class Table:
    """A sheet read against its spec: the recognised headers and the data rows."""

    title: str
    headers: dict[str, Header]
    rows: list[Row]


def read_workbook(path: str | Path) -> Inventory:
    """Read and validate an inventory workbook.

    Parameters
    ----------
    path : str or Path
        The ``.xlsx`` file. Record paths in its ``hazard`` sheet are relative
        to its folder.

    Returns
    -------
    Inventory
        Equipment and hazard tables in SI units with canonical column names
        (see :class:`~assess.inventory.model.Inventory`), and the settings
        merged onto :func:`assess.data.default_settings`.

    Raises
    ------
    InputError
        Holding every problem found in the file, each located by sheet, row,
        column and cell, with a fix.
    """
    given = str(path)
    path = Path(path)
    problems: list[Problem] = []
    report = SheetReport(given, None, problems)
    books = _open(path, report)
    if books is None:
        raise InputError(problems)
    formulas, values = books
    sheets = _find_sheets(formulas, report)
    reports = {name: SheetReport(given, title, problems) for name, title in sheets.items()}
    tables = {name: _read_table(spec, sheets[name], formulas, values, reports[name])
              for name, spec in (("equipment", EQUIPMENT), ("hazard", HAZARD),
                                 ("settings", SETTINGS)) if name in sheets}
    equipment = hazard = []
    if "equipment" in tables:
        equipment = _check_equipment(tables["equipment"], reports["equipment"])
    if "hazard" in tables:
        hazard = _check_hazard(tables["hazard"], path.parent, reports["hazard"])
    settings = default_settings()
    if "settings" in tables:
        settings = _read_settings(tables["settings"], settings, reports["settings"])
    if problems:
        raise InputError(problems)
    return Inventory(path=path, equipment=_frame(equipment, _EQUIPMENT_TYPES),
                     hazard=_frame(hazard, _HAZARD_TYPES), settings=settings)


# ---------------------------------------------------------------- the file

def _open(path: Path, report: SheetReport):
    """Both views of the workbook (formulas, cached values), or None after reporting why not."""
    if not path.exists():
        report(f"the file '{path}' does not exist.",
               "check the path and the file name (including its extension .xlsx).")
        return None
    if path.is_dir():
        report(f"'{path}' is a folder, not a workbook.", "give the path of the .xlsx file.")
        return None
    try:
        with path.open("rb") as handle:
            head = handle.read(8)
    except OSError as error:
        report(f"the file cannot be read ({error.strerror or error}).",
               "check that you may read it and that no other program locks it.")
        return None
    if head == _OLE_MAGIC:
        report("the file is password-protected (encrypted) or an old-style .xls workbook, "
               "which cannot be read.",
               "remove the password (in Excel: File > Info > Protect Workbook > Encrypt with "
               "Password, empty it), then save it as an Excel workbook (.xlsx).")
        return None
    if path.suffix.lower() not in _ACCEPTED_SUFFIXES:
        report(f"the file is not an Excel workbook: its extension is '{path.suffix}', "
               f"expected .xlsx.", _RESAVE)
        return None
    if not zipfile.is_zipfile(path):
        report("the file is not a valid .xlsx workbook (it is not a zip package; "
               "it may be damaged or be another kind of file renamed).", _RESAVE)
        return None
    try:
        formulas = openpyxl.load_workbook(path, data_only=False)
        values = openpyxl.load_workbook(path, data_only=True)
    except Exception as error:  # noqa: BLE001 - openpyxl raises many kinds on a damaged package
        unsafe = _unsafe_xml(error)
        if unsafe is not None:
            report(f"the file contains XML that is refused for safety ({type(unsafe).__name__}: "
                   "entity declarations or external references, as in an 'XML bomb'); "
                   "it was not read.",
                   "if the file is yours, " + _RESAVE + " Otherwise do not use it.")
        else:
            reason = str(error).splitlines()[0] if str(error) else type(error).__name__
            report(f"the workbook cannot be read: it looks damaged ({reason}).", _RESAVE)
        return None
    return formulas, values


def _unsafe_xml(error: BaseException | None) -> defusedxml.DefusedXmlException | None:
    """The defusedxml refusal behind ``error`` (openpyxl wraps it in a ValueError), if any."""
    seen = set()
    while error is not None and id(error) not in seen:
        if isinstance(error, defusedxml.DefusedXmlException):
            return error
        seen.add(id(error))
        error = error.__cause__ or error.__context__
    return None


def _find_sheets(book, report: SheetReport) -> dict[str, str]:
    """Sheet titles by spec name (matched case-insensitively); missing required sheets reported."""
    by_lower = {title.strip().lower(): title for title in book.sheetnames}
    found = {}
    for spec in (EQUIPMENT, HAZARD, SETTINGS):
        title = by_lower.get(spec.name)
        if title is not None and not isinstance(book[title], Worksheet):
            report(f"sheet '{title}' is a chart, not a table.",
                   f"put the {spec.name} table on a worksheet named '{spec.name}'.")
            continue
        if title is not None:
            found[spec.name] = title
        elif spec is not SETTINGS:
            have = ", ".join(f"'{t}'" for t in book.sheetnames)
            report(f"the required sheet '{spec.name}' is missing; the workbook has the sheets "
                   f"{have}.",
                   f"add a sheet named '{spec.name}' (or rename the sheet that holds its table).")
    return found


def _grid(formulas: Worksheet, values: Worksheet, report: SheetReport) -> list[list]:
    """The sheet's cell values, row by row; a formula without a computed value is reported."""
    grid = []
    for formula_row, value_row in zip(formulas.iter_rows(), values.iter_rows()):
        cells = []
        for formula_cell, value_cell in zip(formula_row, value_row):
            value = value_cell.value
            if formula_cell.data_type == "f" and value is None:
                text = getattr(formula_cell.value, "text", formula_cell.value)
                header = values.cell(row=1, column=formula_cell.column).value
                report(f"cell {formula_cell.coordinate} holds the formula {text} with no computed "
                       "value (the file was saved by a program that does not calculate formulas).",
                       "open and save the workbook in Excel or LibreOffice, or type the value.",
                       row=formula_cell.row, cell=formula_cell.coordinate,
                       column=None if formula_cell.row == 1 or schema.is_empty(header)
                       else str(header).strip())
                value = UNUSABLE
            cells.append(value)
        grid.append(cells)
    return grid


# ---------------------------------------------------------------- rows

def _read_table(spec: SheetSpec, title: str, formulas, values, report: SheetReport) -> Table:
    """Headers recognised and every non-blank row parsed cell by cell."""
    grid = _grid(formulas[title], values[title], report)
    if not grid or (len(grid) == 1 and all(schema.is_empty(v) for v in grid[0])):
        report(f"sheet '{title}' is empty.",
               f"write the column headers in row 1: {', '.join(c.header() for c in spec.columns)}.",
               row=1)
        return Table(title, {}, [])
    width = max(len(row) for row in grid)
    letters = [get_column_letter(i + 1) for i in range(width)]
    headers = schema.map_headers(spec, grid, letters, report)
    rows = []
    for number, cells in enumerate(grid[1:], start=2):
        if all(schema.is_empty(v) for v in cells):
            continue
        rows.append(_read_row(spec, headers, number, cells, report))
    if not rows and spec is not SETTINGS:
        report(f"sheet '{title}' has no data rows below its headers.",
               f"add one row per {spec.subject.split(' ', 1)[1]}.", row=2)
    return Table(title, headers, rows)


def _read_row(spec: SheetSpec, headers: dict[str, Header], number: int, cells: list,
              report: SheetReport) -> Row:
    row = Row(number)
    for column in spec.columns:
        header = headers.get(column.name)
        value = cells[header.index] if header is not None and header.index < len(cells) else None
        row.raw[column.name] = value
        if value is UNUSABLE:
            row.failed.add(column.name)
        elif schema.is_empty(value):
            row.values[column.name] = column.default
            if column.required:
                row.failed.add(column.name)
                if header is not None:
                    report.at(number, header, f"{header.text} is empty; every row that "
                              f"describes {spec.subject} needs it.",
                              "fill in the cell, or delete the row if it is not in use.")
        else:
            try:
                parsed = schema.parse_cell(value, column, header.suffix, spec.subject)
                row.values[column.name] = parsed
            except CellError as error:
                row.failed.add(column.name)
                report.at(number, header, error.message, error.fix)
    return row


# ---------------------------------------------------------------- equipment

def _check_equipment(table: Table, report: SheetReport) -> list[dict]:
    """Cross-column checks, defaults that depend on other columns; the output rows."""
    first_row_of: dict[str, int] = {}
    for row in table.rows:
        _check_item(row, table.headers, report)
        item_id = row.values.get("id")
        if row.ok("id") and item_id is not None:
            if item_id in first_row_of:
                report.at(row.number, table.headers.get("id"),
                          f"id '{item_id}' is used twice: by row {first_row_of[item_id]} and by "
                          f"row {row.number}.",
                          "give each item its own id (identical items may share one row "
                          "with a quantity).")
            else:
                first_row_of[item_id] = row.number
    return [{**{c.output: row.values.get(c.name) for c in EQUIPMENT.columns}, "row": row.number}
            for row in table.rows]


def _check_item(row: Row, headers: dict[str, Header], report: SheetReport) -> None:
    values, raw = row.values, row.raw
    mu, mu_static = values.get("mu"), values.get("mu_static")
    if mu_static is None:
        values["mu_static"] = mu
    elif row.ok("mu", "mu_static") and mu is not None and mu_static < mu:
        report.at(row.number, headers["mu_static"],
                  f"mu_static {schema.quote(raw['mu_static'])} is less than mu "
                  f"{schema.quote(raw['mu'])}; static friction is never below kinetic friction.",
                  "check both coefficients; leave mu_static empty if only mu is known.")
    if values.get("cg_height") is None:
        height = values.get("height")
        values["cg_height"] = height / 2 if height is not None and row.ok("height") else None
    elif row.ok("height", "cg_height") and values["height"] is not None \
            and values["cg_height"] > values["height"]:
        cg, height = headers["cg_height"], headers["height"]
        report.at(row.number, cg,
                  f"{cg.text} {schema.quote(raw['cg_height'])} ({values['cg_height']:.3g} m) is "
                  f"above the top of the item, {height.text} {schema.quote(raw['height'])} "
                  f"({values['height']:.3g} m).",
                  "the centre of mass lies between the floor and the top: check both values and "
                  "their units, or leave the cell empty for a uniform block (half the height).")


# ---------------------------------------------------------------- hazard

def _check_hazard(table: Table, folder: Path, report: SheetReport) -> list[dict]:
    """Records, pta/tp where no record, duplicated motions; the output rows."""
    headers = table.headers
    first_row_of: dict[tuple, int] = {}
    lacking: dict[str, list[int]] = {"pta": [], "tp": []}  # rows needing an absent column
    records = []
    for row in table.rows:
        record_path = _record_path(row, folder, headers, report)
        if not record_path and row.ok("record"):
            for name in _require_pulse_measures(row, headers, report):
                lacking[name].append(row.number)
        _check_duplicate_motion(row, headers, first_row_of, report)
        records.append(_hazard_record(row, record_path))
    for name, rows in lacking.items():
        if rows and "record" in headers:  # else the missing column is already reported
            column = HAZARD.column(name)
            listed = ", ".join(str(n) for n in rows)
            plural = len(rows) > 1
            report(f"the column '{column.header()}' is missing, and row{'s' if plural else ''} "
                   f"{listed} name{'' if plural else 's'} no record.",
                   f"add a column headed {schema.or_list(column.accepted_headers())} in row 1, "
                   "or give those rows an acceleration record file.",
                   row=1, column=column.header())
    return records


def _record_path(row: Row, folder: Path, headers: dict[str, Header], report: SheetReport) -> str:
    """The absolute path of the row's record ("" when none); a missing file is reported."""
    text = row.values.get("record") or ""
    if not text:
        return ""
    path = (folder / text).absolute()  # never .resolve(): it raises on a symlink loop
    if not path.is_file():
        report.at(row.number, headers.get("record"),
                  f"the record file '{text}' was not found (looked for {path}).",
                  "put the record file there, or correct its path (relative to the "
                  "workbook's folder).")
    return str(path)


def _require_pulse_measures(row: Row, headers: dict[str, Header], report: SheetReport) -> list[str]:
    """pta and tp are required on a row without a record; returns those whose column is absent."""
    absent = []
    for name in ("pta", "tp"):
        header = headers.get(name)
        if not row.ok(name) or not pd.isna(row.values.get(name)):
            continue
        row.failed.add(name)
        if header is None:
            absent.append(name)
            continue
        report.at(row.number, header,
                  f"{header.text} is empty and the row names no record; a motion is described "
                  "either by its peak acceleration and pulse period (pta and tp) or by a record.",
                  f"fill in {header.text}, or give an acceleration record file in the 'record' "
                  "column.")
    return absent


def _check_duplicate_motion(row: Row, headers: dict[str, Header], first_row_of: dict,
                            report: SheetReport) -> None:
    """The same (level, motion, floor) on two rows is reported at the second."""
    level = row.values.get("level")
    if not row.ok("level", "motion", "floor") or level is None:
        return
    motion, floor = row.values["motion"], row.values["floor"]
    key = (level.name, str(motion).casefold(), floor)
    if key not in first_row_of:
        first_row_of[key] = row.number
        return
    report.at(row.number, headers.get("motion"),
              f"motion '{motion}' at level {level.name}, floor {floor} is given twice: in row "
              f"{first_row_of[key]} and in row {row.number}.",
              "delete one of the two rows, or correct its level, motion or floor.")


def _hazard_record(row: Row, record_path: str) -> dict:
    """One output row of the hazard frame (canonical names, SI)."""
    values = row.values
    level, floor = values.get("level"), values.get("floor")
    label = row.raw["level"]
    return {
        "level": level.name if level is not None else None,
        "level_label": schema.parse_text(label, HAZARD.column("level")) if level else None,
        "motion": values.get("motion"),
        "all_floors": floor == "all",
        "floor": pd.NA if floor in ("all", None) else floor,
        "pta_g": values.get("pta"), "tp_s": values.get("tp"), "vp_m_s": values.get("vp"),
        "pulse": values.get("pulse"), "record_path": record_path,
        "scale": values.get("scale"), "row": row.number,
    }


# ---------------------------------------------------------------- settings

_POSITIVE_SETTINGS = ("zeta", "eta", "sigma")
_ORDERED_SETTINGS = (("risk_pf_moderate", "risk_pf_high"), ("im_min", "im_max"))


def _read_settings(table: Table, defaults: dict, report: SheetReport) -> dict:
    """``defaults`` updated with the sheet's key/value rows (a new dict), each checked."""
    key_header, value_header = table.headers.get("key"), table.headers.get("value")
    user: dict[str, tuple[object, int]] = {}
    for row in table.rows:
        if not row.ok("key", "value") or value_header is None or row.values["key"] is None:
            continue
        key = row.values["key"].lower()
        if key not in defaults:
            close = schema.suggest(key, list(defaults))
            report.at(row.number, key_header, f"unknown setting '{row.values['key']}'"
                      + (f"; did you mean '{close}'?" if close else "."),
                      f"use one of the settings {', '.join(defaults)}.")
        elif key in user:
            report.at(row.number, key_header, f"setting '{key}' is given twice: in row "
                      f"{user[key][1]} and in row {row.number}.", "delete one of the two rows.")
        else:
            value = _setting_value(key, row, defaults[key], value_header, report)
            if value is not None:
                user[key] = (value, row.number)
    merged = {**defaults, **{key: value for key, (value, _) in user.items()}}
    _check_settings(merged, user, value_header, report)
    return merged


def _setting_value(key: str, row: Row, default: object, header: Header, report: SheetReport):
    """The value of one settings row (float for numeric keys), or None after reporting."""
    raw = row.values["value"]
    if not isinstance(default, (int, float)) or isinstance(default, bool):
        return "" if schema.is_empty(raw) else schema.parse_text(raw, SETTINGS.column("value"))
    if schema.is_empty(raw):
        report.at(row.number, header, f"setting '{key}' has no value.",
                  f"type a number, or delete the row to use the default {default}.")
        return None
    try:
        return schema.parse_number(raw, SETTINGS.column("value"))
    except CellError as error:
        report.at(row.number, header, f"setting '{key}': {error.message}",
                  f"type a plain number, or delete the row to use the default {default}.")
        return None


def _check_settings(merged: dict, user: dict, header: Header | None, report: SheetReport) -> None:
    bad = set()
    for key in _POSITIVE_SETTINGS:
        if key in user and merged[key] <= 0:
            bad.add(key)
            report.at(user[key][1], header, f"setting '{key}' is "
                      f"{schema.quote(merged[key])}; it must be greater than 0.",
                      "correct it, or delete the row to use the paper's value.")
    for key in _ORDERED_SETTINGS[0]:
        if key in user and not 0 < merged[key] < 1:
            bad.add(key)
            report.at(user[key][1], header, f"setting '{key}' is {schema.quote(merged[key])}; "
                      "a probability threshold lies strictly between 0 and 1.",
                      "write it as a fraction, e.g. 0.1 for 10 %.")
    if "simulate_motions" in user and str(merged["simulate_motions"]).strip().lower() not in ("synthetic", "pulse"):
        report.at(user["simulate_motions"][1], header, f"setting 'simulate_motions' is "
                  f"{schema.quote(merged['simulate_motions'])}; it is 'synthetic' or 'pulse'.",
                  "write synthetic (near-fault histories) or pulse (the motion's pulse).")
    if "synthetic_realizations" in user:
        count = merged["synthetic_realizations"]
        if not (float(count).is_integer() and 1 <= count <= 100):
            report.at(user["synthetic_realizations"][1], header, f"setting 'synthetic_realizations' is "
                      f"{schema.quote(count)}; it is a whole number from 1 to 100.",
                      "write how many synthetic histories to simulate per motion, e.g. 5.")
    for low, high in _ORDERED_SETTINGS:
        set_by_user = [k for k in (low, high) if k in user]
        if not set_by_user or bad & {low, high} or merged[low] < merged[high]:
            continue
        where = max(set_by_user, key=lambda k: user[k][1])
        report.at(user[where][1], header,
                  f"{low} {schema.quote(merged[low])} must be less than "
                  f"{high} {schema.quote(merged[high])}.",
                  f"correct {' or '.join(set_by_user)} (values not in the sheet are the defaults).")


# ---------------------------------------------------------------- output

#: Output columns in order (``Inventory`` docstring) and their types.
_EQUIPMENT_TYPES = {"id": "str", "name": "str", "room": "str", "floor": "int64",
                    "height_m": "float64", "width_m": "float64", "depth_m": "float64",
                    "mass_kg": "float64", "mu": "float64", "mu_static": "float64",
                    "clearance_m": "float64", "cg_height_m": "float64", "anchored": "bool",
                    "quantity": "int64", "row": "int64"}
_HAZARD_TYPES = {"level": "str", "level_label": "str", "motion": "str", "all_floors": "bool",
                 "floor": "Int64", "pta_g": "float64", "tp_s": "float64", "vp_m_s": "float64",
                 "pulse": "str", "record_path": "str", "scale": "float64", "row": "int64"}


def _frame(records: list[dict], types: dict[str, str]) -> pd.DataFrame:
    """The output table of validated ``records`` (built only when no problem was found)."""
    return pd.DataFrame.from_records(records, columns=list(types)).astype(types)
