"""Bounded reading of an ``.xlsx`` file: only the cells that hold something.

A workbook is a zip of XML parts. A few bytes of it can stand for gigabytes
(a "zip bomb": a 4 MB file whose sheet inflates to 4 GB) or for a sheet whose
used range runs to row 1,048,576 (one whitespace cell there). Reading it cell
by cell over the declared range, as ``openpyxl.load_workbook`` does, builds
every row × column of that range; this reader does not:

* before any XML is parsed, the package is checked from its zip directory:
  the file's size, the number of parts, and the size of every part once
  inflated (``ZipInfo.file_size``; :mod:`zipfile` never inflates a part past
  the size its directory declares, so a part that lies about it stops there
  with a CRC error); then every XML part is inflated once, in chunks, and its
  tags counted (a C-speed byte count): parsing costs some microseconds per
  element, so the tag count bounds the time any parser (openpyxl's at load,
  this module's per sheet) can take, and a part of millions of tiny elements
  (a "shared strings bomb": 190 MB of one-letter strings took 180 s and 1.2 GB)
  is refused in a second;
* a sheet is streamed row by row (``iterparse`` of defusedxml, which refuses
  entity declarations and external references) and only its non-empty cells
  are kept, as ``{row: {column: value}}``; the number of XML elements and of
  cells parsed per sheet is bounded, so a sheet of a million empty or blank
  cells is refused in seconds with the reason;
* a cell that cannot be decoded (a stored number that is not one, a
  shared-string index the file does not have) becomes a :class:`DamagedCell`
  for the caller to report at its address, instead of an exception raised
  half-way through;
* a formula cell carries its cached value (the value Excel or LibreOffice
  computed when saving); a formula without one becomes a
  :class:`NoCachedValue`, an Excel error value (``#DIV/0!``) an
  :class:`ExcelError`.

The bounds are far above any equipment inventory or table-test log (a
10,000-item inventory of 30 columns is some 300,000 cells and 20 MB of XML)
and far below what takes minutes or gigabytes to parse.

Cell decoding (shared strings, numbers, dates, booleans, inline strings) is
openpyxl's ``WorkSheetParser.parse_cell``; only the streaming loop around it
is this module's. ``WorkSheetParser`` (``openpyxl.worksheet._reader``) and the
read-only workbook's archive, shared strings and date formats are openpyxl's
private names: openpyxl's public read-only API (``iter_rows``) has no bound on
the cells it parses, pads every row up to a stray cell at row 1,048,576, turns
a formula without a cached value into an empty cell and raises half-way
through on a damaged cell, so it cannot give what this module promises. The
dependency is pinned to the tested openpyxl 3.1 (``openpyxl>=3.1,<3.2``) and
``tests/inventory/test_xlsx_openpyxl.py`` fails, naming what is missing, when a version
lacks any of these names.
"""
from __future__ import annotations

import errno
import os
import stat
import zipfile
from dataclasses import dataclass, field
from pathlib import Path

import defusedxml
import defusedxml.ElementTree
import openpyxl
from openpyxl.chartsheet import Chartsheet
from openpyxl.utils import coordinate_to_tuple, get_column_letter

try:  # openpyxl's private cell parser (module docstring): the dependency is pinned to openpyxl 3.1
    from openpyxl.worksheet._reader import CELL_TAG, FORMULA_TAG, ROW_TAG, WorkSheetParser
except ImportError as error:  # pragma: no cover - depends on the environment
    raise ImportError(f"assess reads workbooks with openpyxl 3.1's cell parser, which openpyxl "
                      f"{openpyxl.__version__} lacks ({error}): pip install 'openpyxl>=3.1,<3.2'") from error

if not openpyxl.DEFUSEDXML:  # pragma: no cover - depends on the environment
    raise ImportError("assess needs openpyxl to parse workbooks with defusedxml (XML-bomb "
                      "protection): install defusedxml and unset OPENPYXL_DEFUSEDXML")

#: Largest workbook file read [bytes]: an inventory with photos stays well below.
MAX_FILE_BYTES = 100 * 2**20
#: Most parts (zip members) a workbook may have; Excel writes some 10 plus 2 per sheet.
MAX_PARTS = 2_000
#: Largest size of all parts once inflated [bytes]: the XML of 10,000 items is some 20 MB.
MAX_INFLATED_BYTES = 200 * 2**20
#: Largest XML part once inflated [bytes]: a worksheet, and any other part (shared strings,
#: styles: Excel's 64,000 cell formats take some 10 MB).
MAX_SHEET_PART_BYTES, MAX_OTHER_PART_BYTES = 64 * 2**20, 16 * 2**20
#: Most tags (``<``) in one XML part: a worksheet of 500,000 cells has some 2 million (a cell
#: and its value, opened and closed), shared strings of 100,000 texts some 400,000.
MAX_SHEET_PART_TAGS, MAX_OTHER_PART_TAGS = 4_000_000, 1_000_000
#: Most XML elements (rows, cells, values, formatting...) parsed in one sheet.
MAX_ELEMENTS_PER_SHEET = MAX_SHEET_PART_TAGS // 2
#: Most cells (empty or not) parsed in one sheet: 10,000 rows of 50 columns.
MAX_CELLS_PER_SHEET = 500_000
_XML_SUFFIXES = (".xml", ".rels", ".vml")
#: Excel's own limits of a sheet.
MAX_ROW, MAX_COLUMN = 1_048_576, 16_384

_OLE_MAGIC = b"\xd0\xcf\x11\xe0\xa1\xb1\x1a\xe1"  # encrypted .xlsx and legacy .xls
_ACCEPTED_SUFFIXES = (".xlsx", ".xlsm")
RESAVE = "open it in Excel or LibreOffice and save it as an Excel workbook (.xlsx)."
#: Texts Excel shows for a formula that failed.
EXCEL_ERRORS = frozenset({"#NULL!", "#DIV/0!", "#VALUE!", "#REF!", "#NAME?", "#NUM!", "#N/A",
                          "#GETTING_DATA", "#SPILL!", "#CALC!", "#FIELD!", "#BLOCKED!",
                          "#CONNECT!", "#BUSY!", "#UNKNOWN!"})


class Unreadable(Exception):
    """The file (or one sheet of it) cannot be read: what is wrong and how to fix it."""

    def __init__(self, message: str, fix: str = RESAVE, *, sheet: str | None = None,
                 row: int | None = None) -> None:
        super().__init__(message)
        self.message = message
        self.fix = fix
        self.sheet = sheet
        self.row = row


@dataclass(frozen=True)
class ExcelError:
    """A cell showing an Excel error value such as ``#DIV/0!``."""

    code: str

    def __str__(self) -> str:
        return self.code


@dataclass(frozen=True)
class NoCachedValue:
    """A formula cell saved without its computed value (by a program that does not calculate)."""

    formula: str

    def __str__(self) -> str:
        return self.formula


@dataclass(frozen=True)
class DamagedCell:
    """A cell whose stored value cannot be decoded; ``reason`` says why (never its content)."""

    reason: str

    def __str__(self) -> str:
        return "<damaged cell>"


#: Cell values that are not data but a problem of the cell.
MARKERS = (ExcelError, NoCachedValue, DamagedCell)


@dataclass
class SheetCells:
    """The non-empty cells of one sheet: ``rows[row][column]`` (both 1-based, as in Excel)."""

    title: str
    rows: dict[int, dict[int, object]] = field(default_factory=dict)

    @property
    def header(self) -> dict[int, object]:
        """The cells of row 1 by column."""
        return self.rows.get(1, {})

    def data_rows(self) -> list[tuple[int, dict[int, object]]]:
        """``(row number, cells by column)`` of every row below the header that holds a cell."""
        return [(number, self.rows[number]) for number in sorted(self.rows) if number > 1]

    @property
    def max_column(self) -> int:
        return max((max(cells) for cells in self.rows.values() if cells), default=0)


def address(row: int, column: int) -> str:
    """Excel reference of a cell, e.g. ``C7``."""
    return f"{get_column_letter(column)}{row}"


def is_blank(value: object) -> bool:
    return value is None or (isinstance(value, str) and not value.strip())


# ---------------------------------------------------------------- the package

def file_problem(path) -> str | None:
    """What keeps ``path`` from being opened as a workbook file, in words; None for a regular file.

    Never raises and never opens the file: a loop of symbolic links, a name
    too long, a missing file, a folder, or something that is not a regular
    file (a FIFO named ``bad.xlsx`` would make any open wait forever).

    >>> file_problem("/nowhere/at/all.xlsx")
    'the file does not exist.'
    """
    try:
        mode = os.stat(path).st_mode
    except OSError as error:
        if error.errno == errno.ELOOP:
            return "the path is a loop of symbolic links (a link that points back at itself)."
        if error.errno == errno.ENAMETOOLONG:
            return "the file name is too long for the file system."
        if error.errno in (errno.ENOENT, errno.ENOTDIR):
            return "the file does not exist."
        return f"the file cannot be read ({error.strerror or type(error).__name__})."
    except ValueError:
        return "the path holds a NUL character."
    if stat.S_ISDIR(mode):
        return "this is a folder, not a workbook."
    if not stat.S_ISREG(mode):
        return "this is not a regular file (a pipe, a device or a socket), so not a workbook."
    return None


def _head(path: Path, size: int) -> bytes:
    """The first ``size`` bytes of ``path``, opened without blocking and checked to be a regular file."""
    descriptor = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_BINARY", 0))
    with os.fdopen(descriptor, "rb") as handle:
        if not stat.S_ISREG(os.fstat(descriptor).st_mode):
            raise Unreadable("this is not a regular file (a pipe, a device or a socket), so not a workbook.",
                             "give the path of the .xlsx file.")
        return handle.read(size)


def check_file(path: Path) -> None:
    """Raise :class:`Unreadable` unless ``path`` is a readable .xlsx package within the bounds."""
    why = file_problem(path)
    if why is not None and why != "the file does not exist." and not path.is_dir():
        raise Unreadable(why, "give the path of the .xlsx file itself.")
    if not path.exists():
        raise Unreadable(f"the file '{path}' does not exist.",
                         "check the path and the file name (including its extension .xlsx).")
    if path.is_dir():
        raise Unreadable(f"'{path}' is a folder, not a workbook.", "give the path of the .xlsx file.")
    try:
        head = _head(path, 8)
        size = path.stat().st_size
    except OSError as error:
        raise Unreadable(f"the file cannot be read ({error.strerror or type(error).__name__}).",
                         "check that you may read it and that no other program locks it.") from None
    if head == _OLE_MAGIC:
        raise Unreadable("the file is password-protected (encrypted) or an old-style .xls workbook, "
                         "which cannot be read.",
                         "remove the password (in Excel: File > Info > Protect Workbook > Encrypt with "
                         "Password, empty it), then save it as an Excel workbook (.xlsx).")
    if path.suffix.lower() not in _ACCEPTED_SUFFIXES:
        raise Unreadable(f"the file is not an Excel workbook: its extension is '{path.suffix[:20]}', "
                         "expected .xlsx.")
    if size > MAX_FILE_BYTES:
        raise Unreadable(f"the file is {size / 2**20:.0f} MB; a workbook of equipment or tests is "
                         f"read up to {MAX_FILE_BYTES // 2**20} MB.",
                         "remove what the file does not need (pictures, other sheets), or split it.")
    if not zipfile.is_zipfile(path):
        raise Unreadable("the file is not a valid .xlsx workbook (it is not a zip package; "
                         "it may be damaged or be another kind of file renamed).")
    try:
        with zipfile.ZipFile(path) as package:
            parts = package.infolist()
            if len(parts) > MAX_PARTS:
                raise Unreadable(f"the workbook package holds {len(parts):,} parts; a workbook has "
                                 f"at most {MAX_PARTS:,} (Excel writes some 10 plus 2 per sheet).",
                                 "if the file is yours, " + RESAVE + " Otherwise do not use it.")
            inflated = sum(part.file_size for part in parts)
            if inflated > MAX_INFLATED_BYTES:
                raise _bomb(f"the workbook's {size / 2**20:.1f} MB inflate to "
                            f"{inflated / 2**20:,.0f} MB of content; a workbook is read up to "
                            f"{MAX_INFLATED_BYTES // 2**20} MB inflated")
            for part in parts:
                if part.filename.lower().endswith(_XML_SUFFIXES):
                    _check_part(package, part)
    except zipfile.BadZipFile as error:
        raise Unreadable(f"the workbook cannot be read: it looks damaged ({_short(error)}).") from None
    except (OSError, EOFError, zipfile.LargeZipFile, NotImplementedError) as error:
        raise Unreadable(f"the workbook cannot be read: it looks damaged or uses a zip feature "
                         f"Excel does not write ({_short(error)}).") from None


def _check_part(package: zipfile.ZipFile, part: zipfile.ZipInfo) -> None:
    """Refuse an XML part whose inflated size or tag count passes its bound (see module doc)."""
    is_sheet = part.filename.lower().startswith("xl/worksheets/")
    max_bytes = MAX_SHEET_PART_BYTES if is_sheet else MAX_OTHER_PART_BYTES
    max_tags = MAX_SHEET_PART_TAGS if is_sheet else MAX_OTHER_PART_TAGS
    name = _short(part.filename)
    if part.file_size > max_bytes:
        raise _bomb(f"the part {name} of the workbook inflates to {part.file_size / 2**20:,.0f} MB; "
                    f"a part is read up to {max_bytes // 2**20} MB")
    tags = 0
    with package.open(part) as handle:
        while chunk := handle.read(2**20):
            tags += chunk.count(b"<")
            if tags > max_tags:
                raise _bomb(f"the part {name} of the workbook holds more than {max_tags:,} XML "
                            "tags")


def _bomb(what: str) -> Unreadable:
    return Unreadable(f"{what} (a workbook of tens of thousands of items stays far below; a file "
                      "this big inside is damaged or built to exhaust memory, and was not parsed).",
                      "if the file is yours, delete the unused rows, columns, sheets and cell "
                      "formats and save it again. Otherwise do not use it.")


def _short(error: object, limit: int = 100) -> str:
    """An exception (or a name) as a short phrase: its first line, at most ``limit`` characters."""
    text = str(error).splitlines()[0] if str(error).strip() else type(error).__name__
    return text if len(text) <= limit else text[:limit - 1] + "…"


def unsafe_xml(error: BaseException | None) -> BaseException | None:
    """The defusedxml refusal behind ``error`` (openpyxl wraps it in a ValueError), if any."""
    seen = set()
    while error is not None and id(error) not in seen:
        if isinstance(error, defusedxml.DefusedXmlException):
            return error
        seen.add(id(error))
        error = error.__cause__ or error.__context__
    return None


def _refuse_unsafe(unsafe: BaseException) -> Unreadable:
    return Unreadable(f"the file contains XML that is refused for safety ({type(unsafe).__name__}: "
                      "entity declarations or external references, as in an 'XML bomb'); "
                      "it was not read.", "if the file is yours, " + RESAVE + " Otherwise do not use it.")


class Book:
    """An open workbook: its sheet names, and the cells of any of its sheets on demand.

    Use as a context manager (the package stays open until :meth:`close`).
    """

    def __init__(self, path: str | Path) -> None:
        path = Path(path)
        check_file(path)
        try:
            self._book = openpyxl.load_workbook(path, read_only=True, data_only=True)
        except Exception as error:  # noqa: BLE001 - openpyxl raises many kinds on a damaged package
            unsafe = unsafe_xml(error)
            if unsafe is not None:
                raise _refuse_unsafe(unsafe) from None
            raise Unreadable(f"the workbook cannot be read: it looks damaged ({_short(error)}).") from None

    def __enter__(self) -> "Book":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def close(self) -> None:
        self._book.close()

    @property
    def sheetnames(self) -> list[str]:
        return list(self._book.sheetnames)

    def is_table(self, title: str) -> bool:
        """True for a worksheet, False for a chart sheet."""
        return not isinstance(self._book[title], Chartsheet)

    def cells(self, title: str) -> SheetCells:
        """The non-empty cells of sheet ``title``; raises :class:`Unreadable` (located) when it
        cannot be read or passes the bounds."""
        sheet = self._book[title]
        parser = _CellParser(sheet, self._book)
        try:
            with sheet.parent._archive.open(sheet._worksheet_path) as source:
                return parser.read(source)
        except Unreadable:
            raise
        except Exception as error:  # noqa: BLE001 - XML errors, bad row numbers, zip CRC errors
            unsafe = unsafe_xml(error)
            if unsafe is not None:
                raise _refuse_unsafe(unsafe) from None
            near = f" near row {parser.row_counter}" if parser.row_counter else ""
            raise Unreadable(f"sheet '{_short(title, 40)}' cannot be read: its XML is damaged{near} "
                             f"({_short(error)}).", sheet=title) from None


class _CellParser(WorkSheetParser):
    """openpyxl's cell decoding in a streaming loop that keeps only non-empty cells, within bounds."""

    def __init__(self, sheet, book) -> None:
        super().__init__(None, sheet._shared_strings, data_only=True, epoch=book.epoch,
                         date_formats=book._date_formats, timedelta_formats=book._timedelta_formats)
        self.title = sheet.title
        self.cells_parsed = 0

    def read(self, source) -> SheetCells:
        found = SheetCells(self.title)
        parents = []  # open elements, outermost first
        in_row = False
        elements = 0
        for event, element in defusedxml.ElementTree.iterparse(
                source, events=("start", "end"), forbid_dtd=False):
            if event == "start":
                parents.append(element)
                if element.tag == ROW_TAG:
                    in_row = True
                continue
            parents.pop()
            elements += 1
            if elements > MAX_ELEMENTS_PER_SHEET:
                raise self._too_big(f"more than {MAX_ELEMENTS_PER_SHEET:,} XML elements")
            if element.tag == ROW_TAG:
                in_row = False
                number, cells = self._row(element)
                if cells:
                    found.rows.setdefault(number, {}).update(cells)
            elif in_row:
                continue  # a cell or its value: the row reads it when it ends
            element.clear()
            if parents:  # keep the tree from growing: every finished element is dropped
                parents[-1].remove(element)
        return found

    def _row(self, element) -> tuple[int, dict[int, object]]:
        r = element.get("r")
        self.row_counter = int(r) if r is not None else self.row_counter + 1
        if not 1 <= self.row_counter <= MAX_ROW:
            raise ValueError(f"row number {self.row_counter} is outside 1 to {MAX_ROW:,}")
        self.col_counter = 0
        kept = {}
        for child in element:
            if child.tag != CELL_TAG:
                continue
            self.cells_parsed += 1
            if self.cells_parsed > MAX_CELLS_PER_SHEET:
                raise self._too_big(f"more than {MAX_CELLS_PER_SHEET:,} cells")
            column, value = self._cell(child)
            if not is_blank(value):
                kept[column] = value
        return self.row_counter, kept

    def _cell(self, element) -> tuple[int, object]:
        """``(column, value)`` of a cell element; the value may be a marker (see :data:`MARKERS`).

        A cell whose address cannot be read, or lies outside its row or the sheet, makes the
        sheet unreadable (ValueError): no value is ever put in a cell it does not come from.
        """
        reference = element.get("r")
        if reference is None:
            row, column = self.row_counter, self.col_counter + 1
        else:
            try:
                row, column = coordinate_to_tuple(reference)
            except (ValueError, TypeError):
                raise ValueError("a cell address is not one") from None
        if row != self.row_counter or not 1 <= column <= MAX_COLUMN:
            raise ValueError("a cell address lies outside its row or the sheet")
        try:
            cell = self.parse_cell(element)
        except Exception as error:  # noqa: BLE001 - a stored value openpyxl cannot decode
            self.col_counter = column
            reason = ("its shared-text index is not in the file" if element.get("t") == "s"
                      else f"its stored value cannot be decoded ({type(error).__name__})")
            return column, DamagedCell(reason)
        value = cell["value"]
        if cell["data_type"] == "e":
            return column, ExcelError(str(value)[:20]) if value is not None else DamagedCell(
                "it is marked as an error without one")
        formula = element.find(FORMULA_TAG)
        if formula is not None and value is None:
            return column, NoCachedValue("=" + (formula.text or ""))
        if isinstance(value, str) and value.strip() in EXCEL_ERRORS:
            return column, ExcelError(value.strip())
        return column, value

    def _too_big(self, what: str) -> Unreadable:
        last = f" (up to row {self.row_counter:,})" if self.row_counter else ""
        return Unreadable(
            f"sheet '{_short(self.title, 40)}' holds {what}{last}; a sheet is read up to "
            f"{MAX_CELLS_PER_SHEET:,} cells, far more than any inventory or test log needs "
            "(formatting or a stray value far down or to the right can make a sheet this big).",
            "delete the rows below and the columns right of the table (select them, "
            "right-click, Delete), then save the workbook.", sheet=self.title)
