"""Build inventory workbooks for tests.

A workbook is described as ``{sheet name: rows}``, each sheet's rows either a
list of dicts (the header is the union of the keys, in order of appearance;
``None`` leaves a cell empty, a dict of only ``None`` is a blank row) or a list
of lists whose first row is the header. :func:`good_sheets` returns a fresh,
valid workbook description to alter one cell at a time:
``sheets["equipment"][1]["mu"] = 0`` changes cell ``mu`` of Excel row 3.
"""
from __future__ import annotations

import copy
import re
import zipfile
from pathlib import Path

import openpyxl

RECORD_FILE = "records/lg.csv"

_GOOD = {
    "equipment": [
        # Excel row 2: defaults for mu_static, cg_height, anchored, quantity
        {"id": "INC-1", "name": "FORMA incubator", "room": "B101", "floor": 0,
         "height_in": 90, "width_cm": 70, "depth_mm": 600, "mass_lb": 100, "mu": 0.3,
         "mu_static": None, "clearance_cm": 10, "cg_height_cm": None, "anchored": None,
         "quantity": None, "notes": "on levelling feet"},
        # row 3: every optional column given
        {"id": "FRZ-2", "name": "-80 freezer", "room": None, "floor": 2,
         "height_in": 78, "width_cm": 80, "depth_mm": 850, "mass_lb": 770, "mu": 0.25,
         "mu_static": 0.35, "clearance_cm": 5, "cg_height_cm": 100, "anchored": "Yes",
         "quantity": 2, "notes": None},
        # row 4: blank, skipped
        {},
        # row 5: floor written 3.0, a numeric string, anchored "N"
        {"id": "BSC-3", "name": "biosafety cabinet", "room": "C3", "floor": 3.0,
         "height_in": "62.2", "width_cm": 120, "depth_mm": 800, "mass_lb": 500, "mu": 0.4,
         "clearance_cm": 0, "anchored": "N", "quantity": 1},
    ],
    "hazard": [
        {"level": "2%/50yr", "motion": "Los Gatos PC", "floor": 0, "pta_cm_s2": 490.3325,
         "tp_s": 1.5, "vp_cm_s": -75, "pulse": "b", "record": None, "scale": None,
         "source": "site study"},
        {"level": "2in50", "motion": "Los Gatos PC", "floor": 2, "pta_cm_s2": 686.4655,
         "tp_s": 1.5, "vp_cm_s": None, "pulse": "A"},
        {"level": "10in50", "motion": "Los Gatos record", "floor": "ALL", "record": RECORD_FILE,
         "scale": 1.2},
    ],
    "settings": [
        {"key": "facility", "value": "Bio lab"},
        {"key": "Site", "value": "Berkeley"},
        {"key": "zeta", "value": 0.4},
        {"key": "risk_pf_moderate", "value": "0.2"},
    ],
    "README": [["This workbook lists the lab's equipment."]],
}


def good_sheets() -> dict:
    """A fresh copy of a valid workbook description."""
    return copy.deepcopy(_GOOD)


def job_sheets() -> dict:
    """A valid workbook the main job runs in seconds at level ``2in50``: the good sheets' three
    items (FRZ-2 anchored) under one Type-B pulse on every floor (0.5 g, 1 s), the pulse alone
    simulated (no synthetic motions)."""
    sheets = good_sheets()
    sheets["hazard"] = [{"level": "2in50", "motion": "M1", "floor": "all", "pta_g": 0.5, "tp_s": 1.0,
                         "pulse": "B"}]
    sheets["settings"].append({"key": "simulate_motions", "value": "pulse"})
    return sheets


def rename_column(rows: list[dict], old: str, new: str) -> None:
    """Rename a column of a list-of-dicts sheet in place, keeping its position."""
    for i, row in enumerate(rows):
        rows[i] = {(new if key == old else key): value for key, value in row.items()}


def drop_column(rows: list[dict], name: str) -> None:
    for row in rows:
        row.pop(name, None)


def write_workbook(path: Path, sheets: dict, cells: dict | None = None,
                   files: dict | None = None) -> Path:
    """Write ``sheets`` to the .xlsx ``path``.

    ``cells`` overrides single cells after the tables are written:
    ``{"equipment": {"F3": "=A1*2"}}``. ``files`` writes extra text files
    relative to the workbook's folder (``{"records/lg.csv": "..."}``).
    """
    book = openpyxl.Workbook()
    book.remove(book.active)
    for name, rows in sheets.items():
        sheet = book.create_sheet(name)
        for values in _as_lists(rows):
            sheet.append(values)
    for name, overrides in (cells or {}).items():
        for ref, value in overrides.items():
            book[name][ref] = value
    path = Path(path)
    book.save(path)
    for relative, text in (files or {}).items():
        target = path.parent / relative
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(text)
    return path


def _as_lists(rows: list) -> list[list]:
    if not rows or not isinstance(rows[0], dict):
        return [list(row) for row in rows]
    header = list(dict.fromkeys(key for row in rows for key in row))
    return [header] + [[row.get(key) for key in header] for row in rows]


def sheet_xml_name(path: Path, sheet: str) -> str:
    """The zip member holding ``sheet`` of a workbook written by :func:`write_workbook`."""
    index = openpyxl.load_workbook(path).sheetnames.index(sheet) + 1
    return f"xl/worksheets/sheet{index}.xml"


def rewrite_member(path: Path, member: str, change) -> None:
    """Replace zip member ``member`` of ``path`` by ``change(old_text)``."""
    with zipfile.ZipFile(path) as source:
        contents = {info.filename: source.read(info.filename) for info in source.infolist()}
    contents[member] = change(contents[member].decode("utf-8")).encode("utf-8")
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as target:
        for name, data in contents.items():
            target.writestr(name, data)


def add_cached_value(path: Path, sheet: str, ref: str, value: float) -> None:
    """Give the formula in ``sheet!ref`` a cached value, as Excel does on saving."""
    def change(xml: str) -> str:
        pattern = re.compile(rf'(<c r="{ref}"[^>]*>\s*<f>[^<]*</f>)\s*(<v\s*/>|<v>\s*</v>)?')
        new, count = pattern.subn(rf"\g<1><v>{value}</v>", xml)
        assert count == 1, f"no formula cell {ref} in {sheet}"
        return new
    rewrite_member(path, sheet_xml_name(path, sheet), change)


BILLION_LAUGHS = """<?xml version="1.0" encoding="UTF-8" standalone="yes"?>
<!DOCTYPE worksheet [
 <!ENTITY lol "lol">
 <!ENTITY lol1 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">
 <!ENTITY lol2 "&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;">
 <!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;">
 <!ENTITY lol4 "&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;">
 <!ENTITY lol5 "&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;">
 <!ENTITY lol6 "&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;">
 <!ENTITY lol7 "&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;">
 <!ENTITY lol8 "&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;">
 <!ENTITY lol9 "&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;">
]>
<worksheet xmlns="http://schemas.openxmlformats.org/spreadsheetml/2006/main">
<sheetData><row r="1"><c r="A1" t="inlineStr"><is><t>&lol9;</t></is></c></row></sheetData>
</worksheet>
"""


def replace_member_streamed(path: Path, member: str, pieces) -> None:
    """Replace zip member ``member`` of ``path`` by the bytes ``pieces`` yields, written piece by
    piece (a member of hundreds of MB never sits in memory; it deflates to a few hundred kB)."""
    path = Path(path)
    with zipfile.ZipFile(path) as source:
        others = {info.filename: source.read(info.filename) for info in source.infolist()
                  if info.filename != member}
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as target:
        for name, data in others.items():
            target.writestr(name, data)
        with target.open(member, "w", force_zip64=True) as handle:
            for piece in pieces:
                handle.write(piece)


def sheet_xml(rows_xml):
    """A worksheet part around ``rows_xml`` (an iterable of ``<row>`` texts, as bytes)."""
    yield (b'<?xml version="1.0" encoding="UTF-8" standalone="yes"?>\n'
           b'<worksheet xmlns="http://schemas.openxmlformats.org/spreadsheetml/2006/main">'
           b'<sheetData>')
    yield from rows_xml
    yield b"</sheetData></worksheet>"


def write_tests_workbook(path: Path, rows: list[list], sheet: str = "tests") -> Path:
    """A measured-tests workbook (docs/workbook.md): ``rows`` of the sheet ``tests``, header first."""
    book = openpyxl.Workbook()
    book.active.title = sheet
    for row in rows:
        book.active.append(row)
    book.save(path)
    return Path(path)
