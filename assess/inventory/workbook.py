"""Read the inventory workbook (docs/workbook.md) into a validated, SI :class:`Inventory`.

:func:`read_workbook` checks the whole file before giving up: every problem of
every sheet and row is collected as a located :class:`~assess.errors.Problem`
and raised together in one :class:`~assess.errors.InputError`. Nothing is
guessed: a unit comes from the header suffix (converted with pint, see
:mod:`assess.inventory.units`), a cell that is not what its column needs is
reported, never turned into NaN, and no row is dropped except a blank one.

The column table that drives the checks is in :mod:`assess.inventory.schema`.

Safety and bounds: the file is read by :mod:`assess.inventory.xlsx`, which
checks the package's inflated size before parsing, streams each sheet keeping
only its non-empty cells (a stray cell at row 1,048,576 costs nothing), bounds
the cells parsed, and parses XML with defusedxml (no entity declarations, no
external references). Formula cells are read from the value Excel or
LibreOffice cached when saving; a formula without one, an Excel error value
(``#DIV/0!``) and a cell the file cannot decode are reported at their cell.
Messages quote at most 80 characters of a cell and list at most
:data:`assess.errors.MAX_PROBLEMS_SHOWN` problems (the rest are counted).
"""
from __future__ import annotations

import datetime
import errno
from dataclasses import dataclass, field
from pathlib import Path

import pandas as pd

from assess.data import default_settings
from assess.errors import InputError, Problem
from assess.inventory import friction, plausibility, schema, units, xlsx
from assess.inventory.kinds import default_contents, equipment_kind, item_type  # noqa: F401 (re-exported)
from assess.inventory.model import Inventory
from assess.inventory.settings import Settings
from assess.inventory.schema import (BUILDING, EQUIPMENT, HAZARD, SETTINGS, SITE, UNUSABLE, CellError,
                                     Header, SheetSpec)
from assess.inventory.site_building import check_building_strength, check_item_floors, read_building, read_site



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
    with open_book(path, report) as book:
        sheets = _find_sheets(book, report)
        reports = {name: SheetReport(given, title, problems) for name, title in sheets.items()}
        tables = {}
        for name, spec in (("equipment", EQUIPMENT), ("hazard", HAZARD), ("settings", SETTINGS),
                           ("site", SITE), ("building", BUILDING)):
            if name in sheets:
                cells = sheet_cells(book, sheets[name], reports[name])
                if cells is not None:  # a site sheet gives the hazard: a hazard sheet may then hold no rows
                    tables[name] = read_table(spec, cells, reports[name],
                                              rows_required=not (spec is HAZARD and "site" in sheets))
    equipment = hazard = []
    if "equipment" in tables:
        equipment = _check_equipment(tables["equipment"], reports["equipment"])
    if "hazard" in tables:
        hazard = _check_hazard(tables["hazard"], path.parent, reports["hazard"])
    values = default_settings()  # the settings' values, checked at their cells, then typed (Settings)
    if "settings" in tables:
        values = _read_settings(tables["settings"], values, reports["settings"])
    if not str(values.get("units", "")).strip() and "equipment" in tables:
        values["units"] = units.unit_system_of_suffixes(
            header.suffix for header in tables["equipment"].headers.values() if header.column.dimension is units.LENGTH)
    site = read_site(tables["site"], path.parent, reports["site"]) if "site" in tables else None
    building = read_building(tables["building"], reports["building"]) if "building" in tables else None
    if building is not None and (site is not None or "site" not in tables):  # a site sheet in error says so itself
        check_building_strength(tables["building"], building, site, reports["building"])
    if building is not None and "equipment" in tables:  # a floor the building does not have: at its cell
        check_item_floors(tables["equipment"], building, reports["equipment"])
    if problems:
        raise InputError(problems)  # assess.errors lists the first 50 and counts the rest
    warnings = ()
    if "equipment" in tables:  # sizes and densities no equipment has: warned, assessed as written
        warnings = tuple(plausibility.equipment_warnings(tables["equipment"].rows, tables["equipment"].headers,
                                                         given, sheets["equipment"]))
    return Inventory(path=path, equipment=_frame(equipment, _EQUIPMENT_TYPES),
                     hazard=_frame(hazard, _HAZARD_TYPES), settings=Settings.from_mapping(values), site=site,
                     building=building, warnings=warnings)


# ---------------------------------------------------------------- the file

def open_book(path: Path, report: SheetReport) -> xlsx.Book:
    """The workbook at ``path``, open; one that cannot be read is reported and raised as an InputError."""
    try:
        return xlsx.Book(path)
    except xlsx.Unreadable as error:
        report(error.message, error.fix)
        raise InputError(report.problems) from None


def _find_sheets(book: xlsx.Book, report: SheetReport) -> dict[str, str]:
    """Sheet titles by spec name (matched case-insensitively); missing required sheets reported."""
    by_lower = {title.strip().lower(): title for title in book.sheetnames}
    found = {}
    optional = (SETTINGS, SITE, BUILDING)  # hazard too, where a site sheet gives the hazard
    for spec in (EQUIPMENT, HAZARD, SETTINGS, SITE, BUILDING):
        same = same_name_sheets(book.sheetnames, spec.name)
        if len(same) > 1:
            shown = " and ".join("'" + title[:40] + "'" for title in same[:4])  # trailing spaces shown
            report(f"the sheets {shown} all name the "
                   f"{spec.name} sheet (sheet names are matched ignoring case and spaces around them), so "
                   "which one holds the table is not clear.",
                   f"keep one sheet named '{spec.name}': delete or rename the others.")
            continue
        title = by_lower.get(spec.name)
        if title is not None and not book.is_table(title):
            report(f"sheet '{title}' is a chart, not a table.",
                   f"put the {spec.name} table on a worksheet named '{spec.name}'.")
            continue
        if title is not None:
            found[spec.name] = title
        elif spec not in optional and not (spec is HAZARD and SITE.name in by_lower):
            have = ", ".join(f"'{schema.clip(t, 40)}'" for t in book.sheetnames[:20])
            more = f" and {len(book.sheetnames) - 20} more" if len(book.sheetnames) > 20 else ""
            report(f"the required sheet '{spec.name}' is missing; the workbook has the sheets "
                   f"{have}{more}.",
                   f"add a sheet named '{spec.name}' (or rename the sheet that holds its table)"
                   + (", or a 'site' sheet with the site's hazard." if spec is HAZARD else "."))
    return found


def same_name_sheets(titles, name: str) -> list[str]:
    """The sheet titles that name sheet ``name`` (ignoring case and surrounding spaces), in order.

    >>> same_name_sheets(["equipment", "hazard", "EQUIPMENT "], "equipment")
    ['equipment', 'EQUIPMENT ']
    """
    return [title for title in titles if title.strip().lower() == name]


def sheet_cells(book: xlsx.Book, title: str, report: SheetReport) -> xlsx.SheetCells | None:
    """The sheet's non-empty cells, each cell that is a problem reported and made UNUSABLE;
    None after reporting a sheet that cannot be read."""
    try:
        cells = book.cells(title)
    except xlsx.Unreadable as error:
        report(error.message, error.fix, row=error.row)
        return None
    header = cells.header
    for number, row in cells.rows.items():
        for column, value in row.items():
            if not isinstance(value, xlsx.MARKERS):
                continue
            message, fix = _marker_problem(value)
            name = header.get(column)
            report(f"cell {xlsx.address(number, column)} {message}", fix, row=number,
                   cell=xlsx.address(number, column),
                   column=None if number == 1 or schema.is_empty(name) or name is UNUSABLE
                   or isinstance(name, xlsx.MARKERS) else schema.clip(name, 40))
            row[column] = UNUSABLE
    return cells


def _marker_problem(marker) -> tuple[str, str]:
    """What is wrong with a cell the reader marked, and the fix."""
    if isinstance(marker, xlsx.NoCachedValue):
        return (f"holds the formula {schema.clip(marker.formula, 60)} with no computed value (the "
                "file was saved by a program that does not calculate formulas).",
                "open and save the workbook in Excel or LibreOffice, or type the value.")
    if isinstance(marker, xlsx.ExcelError):
        return (f"shows the Excel error {marker.code} (a formula that failed).",
                "correct the formula so that it gives a value, or type the value.")
    return (f"cannot be read: {marker.reason}; the file is damaged there.",
            "retype the cell in Excel or LibreOffice and save the workbook.")


# ---------------------------------------------------------------- rows

def read_table(spec: SheetSpec, cells: xlsx.SheetCells, report: SheetReport, *, rows_required: bool = True) -> Table:
    """Headers recognised and every non-blank row parsed cell by cell; a sheet without rows (or even headers)
    is refused unless ``rows_required`` is false (the settings sheet, a hazard sheet beside a site sheet)."""
    title = cells.title
    rows = [(number, row) for number, row in cells.data_rows()
            if not all(schema.is_empty(v) for v in row.values())]
    header_row = cells.header
    if all(schema.is_empty(v) for v in header_row.values()) and not rows:
        if not rows_required:
            return Table(title, {}, [])
        report(f"sheet '{schema.clip(title, 40)}' is empty.",
               f"write the column headers in row 1: {', '.join(c.header() for c in spec.columns)}.",
               row=1)
        return Table(title, {}, [])
    headers = schema.map_headers(spec, header_row, rows, report)
    parsed = [_read_row(spec, headers, number, row, report) for number, row in rows]
    if not parsed and spec is not SETTINGS and rows_required:
        report(f"sheet '{schema.clip(title, 40)}' has no data rows below its headers.",
               f"add one row per {spec.subject.split(' ', 1)[1]}.", row=2)
    return Table(title, headers, parsed)


def _read_row(spec: SheetSpec, headers: dict[str, Header], number: int, cells: dict[int, object],
              report: SheetReport) -> Row:
    row = Row(number)
    for column in spec.columns:
        header = headers.get(column.name)
        value = cells.get(header.index) if header is not None else None
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
    return [{**{c.output: row.values.get(c.name) for c in EQUIPMENT.columns}, **item_type(row.values, row.raw),
             "mu_source": row.values.get("mu_source", ""), "row": row.number} for row in table.rows]


def _check_item(row: Row, headers: dict[str, Header], report: SheetReport) -> None:
    values, raw = row.values, row.raw
    defaulted = _default_mu(row, headers, report)
    mu, mu_static = values.get("mu"), values.get("mu_static")
    if defaulted and mu_static is not None:
        report.at(row.number, headers["mu_static"],
                  f"mu_static {schema.quote(raw['mu_static'])} is given without mu, so the kinetic coefficient "
                  "it must not fall below is not known.",
                  "give mu too (at most mu_static), or leave both empty for the default range of mu.")
    elif mu_static is None:
        values["mu_static"] = mu
    elif row.ok("mu", "mu_static") and mu is not None and mu_static < mu:
        report.at(row.number, headers["mu_static"],
                  f"mu_static {schema.quote(raw['mu_static'])} is less than mu "
                  f"{schema.quote(raw['mu'])}; static friction is never below kinetic friction.",
                  "check both coefficients; leave mu_static empty if only mu is known.")
    _check_mu_range(row, headers, report)
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


def _default_mu(row: Row, headers: dict[str, Header], report: SheetReport) -> bool:
    """``mu`` for a row that leaves it empty, and ``mu_source``; True when ``mu`` was filled in here.

    A freestanding item without ``mu`` takes the middle of its ``mu_low``-``mu_high`` where the row gives
    both, else the default range of its ``base`` on its ``floor_finish``
    (:func:`assess.inventory.friction.default_range`) as ``mu_low``, ``mu_high`` and ``mu`` at its middle;
    an anchored item needs none. A ``base`` or ``floor_finish`` the table does not know is reported at its cell.
    """
    values = row.values
    values["mu_source"] = "workbook" if values.get("mu") is not None else ""
    base, finish = str(values.get("base") or ""), str(values.get("floor_finish") or "")
    known = True
    for name, text, kind, accepted in (("base", base, friction.base_kind, friction.BASES),
                                       ("floor_finish", finish, friction.finish_kind, friction.FINISHES)):
        if text and kind(text) is None:
            close = schema.suggest(text.strip().lower(), list(accepted))
            report.at(row.number, headers.get(name), f"{name} {schema.quote(text)} is not one the default "
                      "friction table knows" + (f"; did you mean '{close}'?" if close else "."),
                      f"write one of {', '.join(sorted(accepted))}, or leave it empty (docs/workbook.md).")
            known = False
    if values.get("mu") is not None or values.get("anchored") or not known \
            or not row.ok("mu", "mu_low", "mu_high", "base", "floor_finish", "casters"):
        return False
    low, high = values.get("mu_low"), values.get("mu_high")
    if low is not None and high is not None:
        if low > high:
            report.at(row.number, headers["mu_low"], f"mu_low {schema.quote(row.raw['mu_low'])} is above mu_high "
                      f"{schema.quote(row.raw['mu_high'])}.", "give the range's lower end in mu_low.")
            return False
        values["mu"] = round(0.5 * (low + high), 6)
        values["mu_source"] = f"the workbook's mu_low-mu_high {low:g}-{high:g}, mu at its middle"
        return True
    if low is not None or high is not None:
        return False  # one end alone: reported by _check_mu_range
    chosen = friction.default_range(base, finish, bool(values.get("casters")))
    values.update(mu=chosen.mu, mu_low=chosen.mu_low, mu_high=chosen.mu_high, mu_source=chosen.why)
    return True


def _check_mu_range(row: Row, headers: dict[str, Header], report: SheetReport) -> None:
    """``mu_low`` and ``mu_high``: both or neither, and ``mu_low <= mu <= mu_high``; reported at the cell."""
    values, raw = row.values, row.raw
    given = {name: values.get(name) for name in ("mu_low", "mu_high") if values.get(name) is not None}
    if not row.ok("mu", "mu_low", "mu_high") or not given:
        return
    if len(given) == 1:
        (name, _), = given.items()
        other = "mu_high" if name == "mu_low" else "mu_low"
        report.at(row.number, headers[name],
                  f"{name} {schema.quote(raw[name])} is given without {other}; the range of the friction "
                  "coefficient needs both ends.",
                  f"give {other} too (e.g. the best-fit and the slow-pull values), or leave both empty.")
        return
    mu, low, high = values.get("mu"), given["mu_low"], given["mu_high"]
    if mu is None or values.get("mu_source") != "workbook":  # mu at the range's middle (_default_mu)
        return
    if low > mu:
        report.at(row.number, headers["mu_low"],
                  f"mu_low {schema.quote(raw['mu_low'])} is above mu {schema.quote(raw['mu'])}; the range "
                  "mu_low to mu_high holds mu.",
                  "check the three coefficients: mu_low <= mu <= mu_high.")
    if high < mu:
        report.at(row.number, headers["mu_high"],
                  f"mu_high {schema.quote(raw['mu_high'])} is below mu {schema.quote(raw['mu'])}; the range "
                  "mu_low to mu_high holds mu.",
                  "check the three coefficients: mu_low <= mu <= mu_high.")


# ---------------------------------------------------------------- hazard

def _check_hazard(table: Table, folder: Path, report: SheetReport) -> list[dict]:
    """Records, pta/tp where no record, duplicated motions; the output rows."""
    headers = table.headers
    first_row_of: dict[tuple, int] = {}
    lacking: dict[str, list[int]] = {"pta": [], "tp": []}  # rows needing an absent column
    names: dict[str, str] = {}  # a level's name by its key: 'DE' for DE and de
    records = []
    for row in table.rows:
        record_path = _record_path(row, folder, headers, report)
        record_2_path = _record_path(row, folder, headers, report, "record_2")
        _check_second_component(row, headers, report)
        if not record_path and row.ok("record"):
            for name in _require_pulse_measures(row, headers, report):
                lacking[name].append(row.number)
        _check_duplicate_motion(row, headers, first_row_of, report)
        records.append(_hazard_record(row, record_path, names, record_2_path))
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


#: Longest file name (one path component) most file systems take [bytes].
_NAME_MAX_BYTES = 255


def _record_path(row: Row, folder: Path, headers: dict[str, Header], report: SheetReport,
                 name: str = "record") -> str:
    """The absolute path of the row's record (column ``name``; "" when none); a path that cannot
    name a file, or a file that is not there, is reported at the row's cell of that column."""
    text = row.values.get(name) or ""
    if not text:
        return ""
    header = headers.get(name)
    too_long = [part for part in Path(text).parts if len(part.encode("utf-8", "replace")) > _NAME_MAX_BYTES]
    if too_long:
        row.failed.add(name)
        report.at(row.number, header, f"the record path {schema.quote(text)} has a name of "
                  f"{len(too_long[0]):,} characters; a file name has at most {_NAME_MAX_BYTES}.",
                  "give the record file's real name, relative to the workbook's folder.")
        return ""
    try:
        path = (folder / text).resolve()
        found = path.is_file()
    except (OSError, RuntimeError, ValueError) as error:  # a symlink loop, a NUL, a bad name
        row.failed.add(name)
        loop = isinstance(error, RuntimeError) or getattr(error, "errno", None) == errno.ELOOP
        why = ("it is a link that leads back to itself" if loop
               else getattr(error, "strerror", None) or type(error).__name__)
        report.at(row.number, header, f"the record path {schema.quote(text)} cannot be followed "
                  f"({why}).", "give the path of the record file itself, relative to the "
                  "workbook's folder.")
        return ""
    if not found:
        report.at(row.number, header,
                  f"the record file {schema.quote(text)} was not found (looked for "
                  f"{schema.clip(str(path), 200)}).",
                  "put the record file there, or correct its path (relative to the "
                  "workbook's folder).")
    return str(path)


def _check_second_component(row: Row, headers: dict[str, Header], report: SheetReport) -> None:
    """``record_2`` is the second component of the row's ``record``; ``azimuth_deg`` turns that pair."""
    values = row.values
    if values.get("record_2") and not values.get("record") and row.ok("record", "record_2"):
        row.failed.add("record_2")
        report.at(row.number, headers.get("record_2"),
                  "record_2 is given but record is empty; record_2 is the second horizontal component "
                  "(along the items' depth) of the motion whose first component (along their width) is record.",
                  "give the first component in the record column, or move the file there if it is the only one.")
    azimuth = values.get("azimuth_deg")
    if row.ok("azimuth_deg", "record_2") and azimuth not in (None, 0.0) and not values.get("record_2"):
        row.failed.add("azimuth_deg")
        report.at(row.number, headers.get("azimuth_deg"),
                  f"azimuth_deg {schema.quote(row.raw['azimuth_deg'])} is given but the row has no record_2; "
                  "the azimuth turns a pair of records (record and record_2) onto the items' axes.",
                  "give the second component in record_2, or leave azimuth_deg empty.")


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
    key = (level.key, str(motion).casefold(), floor)
    if key not in first_row_of:
        first_row_of[key] = row.number
        return
    report.at(row.number, headers.get("motion"),
              f"motion '{motion}' at level {row.raw['level']}, floor {floor} is given twice: in row "
              f"{first_row_of[key]} and in row {row.number}.",
              "delete one of the two rows, or correct its level, motion or floor.")


def _hazard_record(row: Row, record_path: str, names: dict[str, str], record_2_path: str = "") -> dict:
    """One output row of the hazard frame (canonical names, SI); ``names`` gives every spelling
    of a level the name of its first (a label's case as first written)."""
    values = row.values
    level, floor = values.get("level"), values.get("floor")
    label = row.raw["level"]
    return {
        "level": names.setdefault(level.key, level.name) if level is not None else None,
        "level_label": schema.parse_text(label, HAZARD.column("level")) if level else None,
        "motion": values.get("motion"),
        "all_floors": floor == "all",
        "floor": pd.NA if floor in ("all", None) else floor,
        "pta_g": values.get("pta"), "tp_s": values.get("tp"), "vp_m_s": values.get("vp"),
        "pulse": values.get("pulse"), "record_path": record_path,
        "scale": values.get("scale"), "row": row.number,
        "record_2_path": record_2_path,
        "azimuth_deg": values.get("azimuth_deg") if values.get("azimuth_deg") is not None else 0.0,
    }


# ---------------------------------------------------------------- settings

_IM_WHY = ("IM = PTA/(mu g) - 1 lies between 0 (the onset of sliding) and 499 (PTA 5 g on "
           "mu 0.01, the equipment and hazard sheets' bounds)")
#: Bounds of the numeric settings, (low, high, why), Konstantinidis & Makris (2010) eqs. 8-11:
#: a value outside makes the regression Pi = zeta IM^eta Z say nothing about a real block.
SETTING_BOUNDS = {
    # the median of Pi = Umax wp^2/PTA at IM = 1: Newmark's rectangular pulse of duration Tp,
    # the most damaging pulse of its period, gives Pi = 2 pi^2 IM, about 20 at IM = 1
    "zeta": (1e-3, 100.0, "zeta is the median of Pi = Umax wp^2/PTA at IM = 1, which is 0.5 to "
             "2.8 in the paper's simulations (Table 3) and about 20 for Newmark's rectangular "
             "pulse, the most damaging pulse of its period"),
    # the power of IM: exactly 1 for Newmark's rectangular pulse, 0.953 in the paper
    "eta": (0.1, 3.0, "eta is the power of IM in the median sliding: 1 for Newmark's "
            "rectangular pulse, 0.953 in the paper; beyond 3 the median sliding at IM = 10 would "
            "be a thousand times the pulse's own displacement"),
    # the log-standard deviation of Pi given IM: at 2 the 84th percentile is 7.4 medians
    "sigma": (0.01, 2.0, "sigma is the log-standard deviation of the sliding given IM: 0.445 in "
              "the paper, 0.3 to 1 for record-to-record scatter; at 2 the 84th percentile is "
              "already 7.4 times the median"),
    "im_min": (0.0, 500.0, _IM_WHY),
    "im_max": (0.0, 500.0, _IM_WHY),
    "sds_g": (0.01, 5.0, "sds_g is S_DS of ASCE 7-16 §11.4.5, the design spectral acceleration at short "
              "periods, 0.01 to about 2.5 g on any mapped site"),
    "room_max_cm": (0.0, 500.0, "room_max_cm is the most room in cm an action may ask an item to gain beyond "
                    "its clearance, 0 (never give room) to 500 (5 m)"),
    "lower_contents_cg_fraction": (0.05, 0.5, "lower_contents_cg_fraction is the height of the centre of mass, "
                                   "as a fraction of the item's height, with its heavy contents low: above 0 and "
                                   "at most 0.5 (mid-height, a uniformly loaded item)"),
    "roof_floor": (1.0, 200.0, "roof_floor is the roof's floor number, for z/h in ASCE 7-16 eq. 13.3-1"),
    # costs (assess/decision/costs.py)
    "discount_rate": (0.0, 0.3, "discount_rate is a real rate per year as a fraction: 0.07 for 7 % "
                      "(OMB Circular A-94), 0.02 to 0.1 in practice"),
    "remaining_life_yr": (1.0, 100.0, "remaining_life_yr is the years the action protects the item"),
    **{f"mitigation_cost_{kind}": (0.0, 1e12, f"mitigation_cost_{kind} is what '{kind}' costs per unit, "
                                   "0 or more (0: not given)")
       for kind in ("anchor", "tether", "strap", "chain", "lock_casters", "restrain", "room", "lower_contents",
                    "relocate")},
    "rocking_harm_theta_over_alpha": (0.01, 0.99, "rocking_harm_theta_over_alpha is the peak rotation, as a "
                                      "share of the tipping angle alpha, from which rocking that does not "
                                      "overturn harms the item or its contents; at 1 the item overturns"),
}
#: The settings whose defaults are the paper's (the others cite their own source in defaults.toml).
_REGRESSION_SETTINGS = ("zeta", "eta", "sigma", "im_min", "im_max")
#: Longest text of a text setting (facility, site): it heads the report.
SETTING_TEXT_MAX_CHARS = 200
_ORDERED_SETTINGS = (("risk_pf_moderate", "risk_pf_high"), ("im_min", "im_max"),
                     ("risk_overturn_moderate", "risk_overturn_high"))
#: Settings that are probability thresholds (strictly between 0 and 1).
_PROBABILITY_SETTINGS = ("risk_pf_moderate", "risk_pf_high", "risk_overturn_moderate", "risk_overturn_high",
                         "risk_rocking_moderate")


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
        if isinstance(raw, datetime.time) or (isinstance(raw, datetime.datetime) and raw.date() <= EXCEL_DAY_ZERO):
            # a time of day, or Excel's day 0 (1899-12-30/31): a date cell holding 0, not a date anyone meant
            report.at(row.number, header, f"setting '{key}' is a date cell holding no date (Excel's day 0 or a "
                      "time of day).", "type the date (e.g. 2026-11-28), or text.")
            return None
        text = "" if schema.is_empty(raw) else schema.parse_text(_date_text(raw), SETTINGS.column("value"))
        if len(text) > SETTING_TEXT_MAX_CHARS:
            report.at(row.number, header, f"setting '{key}' is {len(text):,} characters long "
                      f"({schema.quote(text)}); it takes at most {SETTING_TEXT_MAX_CHARS}.",
                      "shorten it.")
            return None
        return text
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


#: The last day a date cell holding 0 (or a fraction of a day) shows: Excel's 1900 date system counts from
#: 1899-12-30 (openpyxl reads 0 as that day, or as a time of day).
EXCEL_DAY_ZERO = datetime.date(1899, 12, 31)


def _date_text(value):
    """A date cell (a ``report_date`` typed as a date) as its ISO date, 2026-11-26, with the time of day only
    where it has one; any other value as it is.

    >>> _date_text(datetime.datetime(2026, 11, 26)), _date_text(datetime.datetime(2026, 11, 26, 9, 30)), _date_text("B")
    ('2026-11-26', '2026-11-26 09:30', 'B')
    """
    if isinstance(value, datetime.datetime):
        return value.date().isoformat() if value.time() == datetime.time() else value.isoformat(" ", "minutes")
    if isinstance(value, datetime.date):
        return value.isoformat()
    return value


def _check_settings(merged: dict, user: dict, header: Header | None, report: SheetReport) -> None:
    bad = set()
    defaults = default_settings()
    for key, (low, high, why) in SETTING_BOUNDS.items():
        if key in user and not low <= merged[key] <= high:
            bad.add(key)
            report.at(user[key][1], header, f"setting '{key}' is {merged[key]:g}, outside {low:g} to {high:g}; "
                      f"it lies between them: {why}.",
                      f"correct it, or delete the row to use the default {defaults[key]:g}"
                      + (" (Konstantinidis & Makris 2010)." if key in _REGRESSION_SETTINGS else "."))
    for key in _PROBABILITY_SETTINGS:
        if key in user and not 0 < merged[key] < 1:
            bad.add(key)
            report.at(user[key][1], header, f"setting '{key}' is {schema.quote(merged[key])}; "
                      "a probability threshold lies strictly between 0 and 1.",
                      "write it as a fraction, e.g. 0.1 for 10 %.")
    if "simulate_motions" in user and str(merged["simulate_motions"]).strip().lower() not in ("synthetic", "pulse"):
        report.at(user["simulate_motions"][1], header, f"setting 'simulate_motions' is "
                  f"{schema.quote(merged['simulate_motions'])}; it is 'synthetic' or 'pulse'.",
                  "write synthetic (near-fault histories) or pulse (the motion's pulse).")
    for key, allowed, fix in (("units", ("si", "us"), "write si (cm, kN) or us (in, lb, kip), or delete the row "
                               "(then us when the equipment sheet's lengths are in inches or feet)."),
                              ("floor_numbering", ("ground_0", "ground_1"), "write ground_0 (the ground floor is 0) "
                               "or ground_1 (the ground floor is 1, as in the US).")):
        if key in user:
            value = str(merged[key]).strip().lower()
            if value and value not in allowed:
                report.at(user[key][1], header, f"setting '{key}' is {schema.quote(merged[key])}; it is "
                          f"{' or '.join(allowed)}.", fix)
            merged[key] = value or ("ground_0" if key == "floor_numbering" else "")
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
                    "casters": "bool", "quantity": "int64", "consequence": "str", "component_type": "str",
                    "contents": "str", "equipment_kind": "str",
                    "type_source": "str", "connections": "str", "connections_assumed": "bool",
                    "ip": "float64",
                    "mu_low": "float64", "mu_high": "float64", "value": "float64", "mitigation_cost": "float64",
                    "base": "str", "floor_finish": "str", "mu_source": "str", "row": "int64"}
_HAZARD_TYPES = {"level": "str", "level_label": "str", "motion": "str", "all_floors": "bool",
                 "floor": "Int64", "pta_g": "float64", "tp_s": "float64", "vp_m_s": "float64",
                 "pulse": "str", "record_path": "str", "scale": "float64", "record_2_path": "str",
                 "azimuth_deg": "float64", "row": "int64"}


def _frame(records: list[dict], types: dict[str, str]) -> pd.DataFrame:
    """The output table of validated ``records`` (built only when no problem was found)."""
    return pd.DataFrame.from_records(records, columns=list(types)).astype(types)
