"""openpyxl's private names that the bounded workbook reader (assess/inventory/xlsx.py) stands on.

The reader streams a sheet through openpyxl's ``WorkSheetParser.parse_cell`` (private:
``openpyxl.worksheet._reader``) and reaches the read-only workbook's archive, shared strings and
date formats; the dependency is pinned to the tested openpyxl 3.1 (pyproject.toml). These tests fail,
naming what is missing, when an installed openpyxl lacks any of them, before any hostile-workbook test
fails for a less obvious reason.
"""
from __future__ import annotations

import inspect
import re
from importlib import import_module, metadata

import openpyxl
import pytest

from assess.inventory import xlsx
from workbooks import good_sheets, write_workbook

#: (module, names) the reader imports from openpyxl's private modules.
PRIVATE_IMPORTS = [("openpyxl.worksheet._reader", ("WorkSheetParser", "CELL_TAG", "FORMULA_TAG", "ROW_TAG"))]
#: Keyword arguments the reader gives WorkSheetParser, and the attributes it reads and sets on it.
PARSER_ARGUMENTS = ("src", "shared_strings", "data_only", "epoch", "date_formats", "timedelta_formats")
PARSER_ATTRIBUTES = ("parse_cell", "row_counter", "col_counter")
#: Attributes of the read-only workbook and worksheet the reader uses.
BOOK_ATTRIBUTES = ("_archive", "epoch", "_date_formats", "_timedelta_formats")
SHEET_ATTRIBUTES = ("parent", "_worksheet_path", "_shared_strings", "title")


def _pinned_range() -> tuple[tuple[int, ...], tuple[int, ...]]:
    """The openpyxl range assess declares (``openpyxl>=3.1,<3.2``), as version tuples."""
    requirement = next(r for r in metadata.requires("assess") if re.match(r"openpyxl\b", r))
    low = re.search(r">=\s*([\d.]+)", requirement)
    high = re.search(r"<\s*([\d.]+)", requirement)
    assert low and high, f"openpyxl is not pinned to a tested range in pyproject.toml: {requirement!r}"
    return tuple(map(int, low.group(1).split("."))), tuple(map(int, high.group(1).split(".")))


def _version(text: str) -> tuple[int, ...]:
    return tuple(int(part) for part in re.findall(r"\d+", text)[:3])


def test_openpyxl_is_pinned_and_the_installed_version_is_in_the_range():
    low, high = _pinned_range()
    assert (low, high) == ((3, 1), (3, 2))
    assert low <= _version(openpyxl.__version__) < high, (
        f"openpyxl {openpyxl.__version__} is installed, outside the tested range; the workbook reader uses "
        "its private cell parser")


@pytest.mark.parametrize("module, names", PRIVATE_IMPORTS)
def test_the_private_names_the_reader_imports_exist(module, names):
    found = import_module(module)
    missing = [name for name in names if not hasattr(found, name)]
    assert not missing, f"openpyxl {openpyxl.__version__}: {module} lacks {missing} (assess/inventory/xlsx.py)"


def test_the_cell_parser_takes_what_the_reader_gives_it():
    from openpyxl.worksheet._reader import WorkSheetParser
    parameters = inspect.signature(WorkSheetParser.__init__).parameters
    missing = [name for name in PARSER_ARGUMENTS if name not in parameters]
    assert not missing, f"openpyxl {openpyxl.__version__}: WorkSheetParser() no longer takes {missing}"
    parser = WorkSheetParser(None, [], data_only=True)
    missing = [name for name in PARSER_ATTRIBUTES if not hasattr(parser, name)]
    assert not missing, f"openpyxl {openpyxl.__version__}: WorkSheetParser lacks {missing}"


def test_the_read_only_workbook_has_the_attributes_the_reader_uses(tmp_path):
    path = write_workbook(tmp_path / "book.xlsx", good_sheets())
    book = openpyxl.load_workbook(path, read_only=True, data_only=True)
    try:
        sheet = book["equipment"]
        missing = ([f"workbook.{name}" for name in BOOK_ATTRIBUTES if not hasattr(book, name)]
                   + [f"worksheet.{name}" for name in SHEET_ATTRIBUTES if not hasattr(sheet, name)])
        assert not missing, f"openpyxl {openpyxl.__version__}: the read-only workbook lacks {missing}"
    finally:
        book.close()


def test_the_reader_reads_a_sheet_through_them(tmp_path):
    """End to end, the names above give the cells (row 1 the header, a value typed in row 2)."""
    path = write_workbook(tmp_path / "book.xlsx", good_sheets())
    with xlsx.Book(path) as book:
        assert book.is_table("equipment")
        cells = book.cells("equipment")
    assert cells.header[1] == "id"
    assert cells.rows[2][1] == "INC-1"


def test_a_chart_sheet_is_told_from_a_worksheet(tmp_path):
    """``Book.is_table`` (openpyxl's public Chartsheet): a chart sheet named like a table is reported as one."""
    from openpyxl.chart import BarChart, Reference

    path = write_workbook(tmp_path / "book.xlsx", good_sheets())
    book = openpyxl.load_workbook(path)
    del book["hazard"]
    chart = BarChart()
    chart.add_data(Reference(book["equipment"], min_col=5, min_row=1, max_row=3), titles_from_data=True)
    book.create_chartsheet("hazard").add_chart(chart)
    book.save(path)
    with xlsx.Book(path) as opened:
        assert opened.is_table("equipment") and not opened.is_table("hazard")
    from assess.errors import InputError
    from assess.inventory import read_workbook
    with pytest.raises(InputError) as raised:
        read_workbook(path)
    assert any("sheet 'hazard' is a chart, not a table" in p.message for p in raised.value.problems)
