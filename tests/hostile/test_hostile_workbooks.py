"""Hostile and odd workbooks (issue 9): labels as hazard levels, numbers out of any physical
range, damaged cells, bombs. Each reproducer is run as a user runs it, the command in a scratch
folder (in this process: tests/commands.py): it ends in exit 2 with a located message (file, sheet, cell, a fix) and writes nothing,
or in exit 0; never a traceback, never a message that echoes a file.
"""
from __future__ import annotations

import json
import math
import os
import tracemalloc
from pathlib import Path

import pandas as pd
import pytest

from assess.errors import InputError
from assess.hazard.levels import parse_level
from assess.hazard.motions import select_level
from assess.inventory import read_workbook
from commands import location, run
from conftest import RECORD_TEXT
from workbooks import (RECORD_FILE, good_sheets, replace_member_streamed, rewrite_member,
                       sheet_xml, sheet_xml_name, write_tests_workbook, write_workbook)

ROOT = Path(__file__).resolve().parents[2]
KM2010 = ROOT / "inventories" / "km2010-prototypes.xlsx"
HAZARD_MAP = ROOT / "tests" / "data" / "openquake" / "case_18-hazard_map-mean.csv"
#: Longest stderr a refusal may print: a few located problems, never a file's content.
MESSAGE_MAX_CHARS = 6000


def assert_refused(completed, *fragments, places=(), max_chars=MESSAGE_MAX_CHARS):
    """Exit 2, no traceback, a short message holding every fragment and naming every place (file, sheet,
    cell or row, as ``assess.errors.Problem.location`` writes it), nothing written."""
    err = completed.stderr
    for place in places:
        assert place in err, f"{place!r} not in {err!r}"
    assert completed.returncode == 2, err[-3000:]
    assert "Traceback" not in err and "internal error" not in err, err[-3000:]
    assert len(err) < max_chars, f"{len(err)} characters of message"
    for fragment in fragments:
        assert fragment in err, f"{fragment!r} not in {err!r}"
    assert "Nothing was written." in err


def workbook(folder: Path, sheets=None, cells=None, name="inventory.xlsx") -> Path:
    return write_workbook(folder / name, good_sheets() if sheets is None else sheets, cells,
                          {RECORD_FILE: RECORD_TEXT})


def assess_refuses(folder: Path, path: Path, *fragments, places=()):
    completed = run(path, "--hazard", "2in50", "--out", folder / "out", cwd=folder)
    assert_refused(completed, path.name, *fragments, places=places)
    assert not (folder / "out").exists()


# ---------------------------------------------------------------- hazard levels as labels

def label_sheets() -> dict:
    """One ground motion per level, named by label; pulses only (a quick run)."""
    sheets = good_sheets()
    sheets["hazard"] = [
        {"level": "DE", "motion": "P1", "floor": "all", "pta_g": 0.5, "tp_s": 1.0, "pulse": "B"},
        {"level": "MCE_R", "motion": "P1", "floor": "all", "pta_g": 0.8, "tp_s": 1.0, "pulse": "B"}]
    sheets["settings"].append({"key": "simulate_motions", "value": "pulse"})
    return sheets


def test_label_level_runs_the_main_job_matched_without_case(tmp_path):
    path = workbook(tmp_path, label_sheets())
    done = run(path, "--hazard", "de", "--out", tmp_path / "de", "--format", "html", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    motions = pd.read_csv(tmp_path / "de" / "motions.csv")
    assert set(motions["pta_g"]) == {0.5}  # the DE row of the sheet, not MCE_R's 0.8 g
    assert "DE" in (tmp_path / "de" / "report.html").read_text()


def test_an_oq_hazard_map_at_a_label_level_is_refused_naming_the_level(tmp_path):
    """A map only scales motions, at a probability a label lacks. (A curve at a label keeps the level's
    motions and gives the annual rates: tests/verification/test_usgs_hazard.py.)"""
    path = workbook(tmp_path, label_sheets())
    done = run(path, "--hazard", "MCE_R", "--oq-hazard", HAZARD_MAP, "--oq-site", "0",
               "--out", tmp_path / "out", cwd=tmp_path)
    assert_refused(done, "'MCE_R' is a label", "--oq-hazard", "sheet 'hazard'", "2in50",
                   places=["inventory.xlsx, sheet 'hazard', column 'level'"])
    assert not (tmp_path / "out").exists()


def test_calibrate_a_shake_table_workbook_whose_level_is_test(tmp_path):
    import openpyxl

    book = openpyxl.load_workbook(KM2010)
    for row in book["hazard"].iter_rows(min_row=2):
        row[0].value = "test"
    book.save(tmp_path / "table.xlsx")
    measured = write_tests_workbook(tmp_path / "measured.xlsx", [
        ["specimen", "motion", "sliding_cm"],
        ["FORMA", "Los Gatos PC, ground, run 1 (0.54 g)", 45.6],
        ["FORMA", "Corralitos, ground, run 1 (0.84 g)", 19.9],
        ["KELVINATOR", "Los Gatos PC, ground, run 1 (0.54 g)", 31.7]])
    done = run("calibrate", tmp_path / "table.xlsx", "--measured", measured, "--out",
               tmp_path / "cal", "--format", "html", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    result = json.loads((tmp_path / "cal" / "calibration.json").read_text())
    assert result["error_before"]["tests_sliding"] == 3


def poisson_return_period_yr(percent, years):
    """T_R = -t / ln(1 - P), written out here (not the package's)."""
    return -years / math.log(1.0 - percent / 100.0)


@pytest.mark.parametrize("first, second", [
    ("2in50", "2%/50yr"), ("2in50", "2475yr"), ("2% in 50 years", "2_50"),
    ("10in50", "475yr"), ("10%/50yr", "475 years"), ("50in30", "43yr"),
])
def test_probability_spellings_alias(first, second):
    assert parse_level(first).same_as(parse_level(second))
    assert parse_level(first).return_period_yr == pytest.approx(
        parse_level(second).return_period_yr, rel=0.01)
    if "30" not in first:  # in the same exposure time, one name (an output folder's)
        assert parse_level(first).name == parse_level(second).name


def test_labels_match_as_text_ignoring_case_and_never_a_probability():
    assert parse_level("MCE_R").same_as(parse_level(" mce_r "))
    assert parse_level("Design Earthquake").same_as(parse_level("design  earthquake"))
    assert not parse_level("DE").same_as(parse_level("MCE_R"))
    assert not parse_level("DE").same_as(parse_level("2in50"))
    assert parse_level("test").name == "test" and not parse_level("test").has_probability
    assert parse_level("MCE R / site").name == "MCE_R_site"  # a name safe in a folder name


@pytest.mark.parametrize("text, percent, years", [
    ("0.04in50", 0.04, 50), ("0.5in50", 0.5, 50), ("2in50", 2, 50), ("63.2in50", 63.2, 50),
    ("99.9in50", 99.9, 50), ("5%/30yr", 5, 30), ("0.0001in50", 0.0001, 50), ("1in1", 1, 1),
])
def test_level_name_keeps_its_digits_and_parses_back(text, percent, years):
    """The canonical name parses back to the same level, at the rate of the spelling."""
    level = parse_level(text)
    again = parse_level(level.name)
    expected = 1.0 / poisson_return_period_yr(percent, years)
    assert again.annual_rate == pytest.approx(expected, rel=1e-3)
    assert again.same_as(level) and again.name == level.name


def test_level_0_04in50_is_stored_and_selected_as_itself(tmp_path):
    sheets = good_sheets()
    for row in sheets["hazard"][:2]:
        row["level"] = "0.04in50"
    inventory = read_workbook(workbook(tmp_path, sheets))
    assert list(inventory.hazard["level"]) == ["0.04in50", "0.04in50", "10in50"]
    level, rows = select_level(inventory.hazard, "0.04%/50yr", "inventory.xlsx")
    assert len(rows) == 2 and level.return_period_yr == pytest.approx(
        poisson_return_period_yr(0.04, 50), rel=1e-9)


@pytest.mark.parametrize("text, phrase", [
    ("0in50", "between 0 and 100 %"), ("100%/50yr", "between 0 and 100 %"),
    ("2in0", "between 0 and 100 %"), ("5yr", "between 10 and"),
    ("0.0000000001in50", "return period"), ("L" * 41, "at most 40 characters"), ("", "empty"),
])
def test_impossible_levels_are_refused(text, phrase):
    with pytest.raises(ValueError, match=phrase):
        parse_level(text)


# ---------------------------------------------------------------- numbers and cells

def with_cell(sheet, index, column, value):
    sheets = good_sheets()
    sheets[sheet][index][column] = value
    return sheets


@pytest.mark.parametrize("sheet, index, column, value, fragments", [
    ("equipment", 0, "quantity", 1e19, ("sheet 'equipment'", "cell N2", "1 to 1000000")),
    ("equipment", 0, "quantity", 1e300, ("cell N2", "quantity 1e+300", "1 to 1000000")),
    ("equipment", 0, "cg_height_cm", 1e-308, ("cell L2", "cg_height 1e-308 cm", "0.01 to 6 m")),
    ("equipment", 0, "id", "#DIV/0!", ("cell A2", "Excel error #DIV/0!")),
    ("equipment", 1, "name", "#DIV/0!", ("cell B3", "Excel error #DIV/0!")),
    ("hazard", 0, "motion", "#DIV/0!", ("sheet 'hazard'", "cell B2", "Excel error #DIV/0!")),
    ("hazard", 2, "record", 1e308, ("cell H4", "is a number, not the path of a record file")),
    ("hazard", 2, "record", "records/" + "a" * 300, ("cell H4", "308 characters", "aaaa…")),
    ("hazard", 2, "record", "records/" + "é" * 130 + ".csv", ("cell H4", "a file name has at most 255")),
    ("hazard", 2, "scale", 1e300, ("cell I4", "0.0001 to 100")),
    ("hazard", 0, "vp_cm_s", 0, ("cell F2", "vp 0 cm/s", "magnitude of 0.001 to 5 m/s",
                                 "leave vp empty")),
])
def test_numbers_and_cells_out_of_range_are_refused_at_their_cell(tmp_path, sheet, index, column,
                                                                    value, fragments):
    cell = next(fragment for fragment in fragments if fragment.startswith("cell "))[len("cell "):]
    assess_refuses(tmp_path, workbook(tmp_path, with_cell(sheet, index, column, value)), *fragments,
                   places=[location("inventory.xlsx", sheet, cell)])


def test_quantity_1e19_is_not_read_as_a_negative_count(tmp_path):
    with pytest.raises(InputError):
        read_workbook(workbook(tmp_path, with_cell("equipment", 0, "quantity", 1e19)))


def test_400_digit_integer_in_a_numeric_cell(tmp_path):
    path = workbook(tmp_path, with_cell("equipment", 0, "mass_lb", 123456789))
    rewrite_member(path, sheet_xml_name(path, "equipment"),
                   lambda xml: xml.replace("<v>123456789</v>", "<v>" + "9" * 400 + "</v>"))
    assess_refuses(tmp_path, path, "cell H2", "column 'mass_lb'", "(a 400-digit number)",
                   "not a finite number", places=[location("inventory.xlsx", "equipment", "H2")])


@pytest.mark.parametrize("key, value", [
    ("eta", 1e308), ("zeta", 1e308), ("sigma", 1e308), ("eta", 50), ("sigma", 0),
])
def test_regression_settings_out_of_their_physical_range(tmp_path, key, value):
    sheets = good_sheets()
    sheets["settings"].append({"key": key, "value": value})  # Excel row 6
    if key == "zeta":
        del sheets["settings"][2]  # the good sheet already sets zeta (row 4): the new row is row 5
    assess_refuses(tmp_path, workbook(tmp_path, sheets), "sheet 'settings'", "column 'value'",
                   f"setting '{key}'", "it lies between", "delete the row to use the default",
                   places=[location("inventory.xlsx", "settings", "B5" if key == "zeta" else "B6")])


def test_long_cell_text_is_quoted_80_characters_at_most(tmp_path):
    sheets = good_sheets()
    sheets["equipment"][0]["name"] = "x" * 40_000
    sheets["equipment"][0]["mu"] = "y" * 40_000
    path = workbook(tmp_path, sheets)
    completed = run(path, "--hazard", "2in50", "--out", tmp_path / "out", cwd=tmp_path)
    assert_refused(completed, "cell B2", "cell I2", "x" * 79 + "…", "y" * 79 + "…",
                   places=[location("inventory.xlsx", "equipment", cell) for cell in ("B2", "I2")])
    assert "x" * 81 not in completed.stderr and "y" * 81 not in completed.stderr
    assert len(completed.stderr) < 1500


def test_problems_listed_are_capped(tmp_path):
    sheets = good_sheets()
    row = dict(sheets["equipment"][0], mu="low")
    sheets["equipment"] = [dict(row, id=f"I{k}") for k in range(300)]
    completed = run(workbook(tmp_path, sheets), "--hazard", "2in50", cwd=tmp_path)
    assert_refused(completed, "300 problems in the input", "and 250 more; fix these first", max_chars=50 * 400,
                   places=[location("inventory.xlsx", "equipment", f"I{row}") for row in range(2, 52)])
    assert completed.stderr.count("is not a number") == 50


def test_damaged_shared_string_index_is_located(tmp_path):
    path = workbook(tmp_path)
    member = sheet_xml_name(path, "equipment")

    def break_b2(xml):
        start = xml.index('<c r="B2"')
        end = xml.index("</c>", start)
        return xml[:start] + '<c r="B2" t="s"><v>99999</v>' + xml[end:]
    rewrite_member(path, member, break_b2)
    assess_refuses(tmp_path, path, "cell B2", "shared-text index is not in the file",
                   places=[location("inventory.xlsx", "equipment", "B2")])


# ---------------------------------------------------------------- the measured tests

def km2010_tests_with(tmp_path, cell_xml):
    """A tests sheet of one FORMA test whose C2 (sliding_cm) is written as ``cell_xml``."""
    path = write_tests_workbook(tmp_path / "measured.xlsx", [
        ["specimen", "motion", "sliding_cm"],
        ["FORMA", "Los Gatos PC, ground, run 1 (0.54 g)", 123456789]])
    rewrite_member(path, sheet_xml_name(path, "tests"),
                   lambda xml: xml.replace('<c r="C2" t="n"><v>123456789</v></c>', cell_xml))
    return path


@pytest.mark.parametrize("cell_xml, fragments", [
    ('<c r="C2"><v>' + "9" * 400 + "</v></c>", ("cell C2", "not a peak sliding", "999…")),
    ('<c r="C2"><v>NaN</v></c>', ("cell C2", "cannot be read", "stored value cannot be decoded")),
    ('<c r="C2" t="s"><v>4242</v></c>', ("cell C2", "shared-text index is not in the file")),
    ('<c r="C2" t="e"><v>#DIV/0!</v></c>', ("cell C2", "Excel error #DIV/0!")),
])
def test_calibrate_refuses_a_damaged_tests_sheet_at_its_cell(tmp_path, cell_xml, fragments):
    measured = km2010_tests_with(tmp_path, cell_xml)
    assert cell_xml in _member_text(measured, "xl/worksheets/sheet1.xml")
    done = run("calibrate", KM2010, "--measured", measured, "--out", tmp_path / "cal", cwd=tmp_path)
    assert_refused(done, "measured.xlsx", "sheet 'tests'", *fragments, places=[location("measured.xlsx", "tests", "C2")])
    assert not (tmp_path / "cal").exists()


def _member_text(path, member):
    import zipfile
    with zipfile.ZipFile(path) as package:
        return package.read(member).decode()


# ---------------------------------------------------------------- size: the used range, bombs

def test_a_blank_cell_at_the_last_row_costs_nothing(tmp_path):
    """One whitespace cell at row 1,048,576 (the file is 7 kB): the same inventory as without it,
    read keeping well under a megabyte of Python objects (it once built every row x column)."""
    plain = read_workbook(workbook(tmp_path, name="plain.xlsx"))
    path = workbook(tmp_path, cells={"equipment": {"A1048576": " ", "R1048576": "\t"}},
                    name="far.xlsx")
    tracemalloc.start()
    try:
        far = read_workbook(path)
        peak_bytes = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    pd.testing.assert_frame_equal(far.equipment, plain.equipment)
    pd.testing.assert_frame_equal(far.hazard, plain.hazard)
    assert peak_bytes < 5 * 2**20, f"{peak_bytes / 2**20:.1f} MB"


def test_workbook_that_inflates_past_the_bound_is_refused_unread(tmp_path):
    """The equipment sheet padded to 210 MB (deflated: about 200 kB): refused from the zip
    directory before any XML is parsed, with the reason."""
    path = workbook(tmp_path)
    chunk = b" " * 2**20
    replace_member_streamed(path, sheet_xml_name(path, "equipment"),
                            sheet_xml(chunk for _ in range(210)))
    assert path.stat().st_size < 5 * 2**20
    assess_refuses(tmp_path, path, "inflate to", "MB of content", "200 MB", "Fix:",
                   places=["inventory.xlsx: the workbook's"])


def test_cell_bomb_is_refused_with_the_reason(tmp_path):
    """600,000 empty cells (about 8 MB of XML, a few kB deflated) in the equipment sheet."""
    path = workbook(tmp_path)
    header = (b'<row r="1"><c r="A1" t="inlineStr"><is><t>id</t></is></c></row>')
    rows = (f'<row r="{r}">'.encode() + b"<c/>" * 100 + b"</row>" for r in range(2, 6002))
    replace_member_streamed(path, sheet_xml_name(path, "equipment"),
                            sheet_xml([header, *rows]))
    assess_refuses(tmp_path, path, "sheet 'equipment'", "more than 500,000 cells",
                   "delete the rows below", places=["inventory.xlsx, sheet 'equipment': "])


def test_shared_strings_bomb_is_refused_before_openpyxl_parses_it(tmp_path):
    """17 MB of one-letter shared strings (a million of them; 190 MB of them once took 180 s
    and 1.2 GB to load): refused from the part's inflated size."""
    path = workbook(tmp_path)
    strings = (b'<sst xmlns="http://schemas.openxmlformats.org/spreadsheetml/2006/main">',
               *(b"<si><t>a</t></si>" * 2**16 for _ in range(16)), b"</sst>")
    replace_member_streamed(path, "xl/sharedStrings.xml", strings)
    rewrite_member(path, "[Content_Types].xml", lambda xml: xml.replace("</Types>", (
        '<Override PartName="/xl/sharedStrings.xml" ContentType="application/vnd.openxmlformats-'
        'officedocument.spreadsheetml.sharedStrings+xml"/></Types>')))
    assess_refuses(tmp_path, path, "xl/sharedStrings.xml", "inflates to 17 MB",
                   "a part is read up to 16 MB", places=["inventory.xlsx: the part xl/sharedStrings.xml"])


def test_element_bomb_is_refused_from_its_tag_count(tmp_path):
    """4.2 million empty elements (17 MB of XML, 20 kB deflated) beside the sheet's rows."""
    path = workbook(tmp_path)
    replace_member_streamed(path, sheet_xml_name(path, "equipment"), sheet_xml(
        [b"</sheetData><cols>", *(b"<x/>" * 2**16 for _ in range(64)), b"</cols><sheetData>"]))
    assess_refuses(tmp_path, path, "xl/worksheets/sheet1.xml", "more than 4,000,000 XML tags",
                   places=["inventory.xlsx: the part xl/worksheets/sheet1.xml"])


@pytest.mark.parametrize("bad_cell", ['<c r="ZZZZ2"><v>1</v></c>', '<c r="B9"><v>1</v></c>'])
def test_a_cell_address_that_does_not_fit_makes_the_sheet_unreadable(tmp_path, bad_cell):
    """Never a value put in a cell it does not come from: the sheet is refused, located."""
    path = workbook(tmp_path)

    def break_b2(xml):
        start = xml.index('<c r="B2"')
        end = xml.index("</c>", start) + len("</c>")
        return xml[:start] + bad_cell + xml[end:]
    rewrite_member(path, sheet_xml_name(path, "equipment"), break_b2)
    assess_refuses(tmp_path, path, "sheet 'equipment' cannot be read", "damaged near row 2",
                   places=["inventory.xlsx, sheet 'equipment': "])
    completed = run(path, "--hazard", "2in50", cwd=tmp_path)
    assert "ZZZZ" not in completed.stderr and "B9" not in completed.stderr


def test_a_record_path_that_is_a_symlink_loop(tmp_path):
    sheets = with_cell("hazard", 2, "record", "records/loop.csv")
    path = workbook(tmp_path, sheets)
    os.symlink("loop.csv", tmp_path / "records" / "loop.csv")
    assess_refuses(tmp_path, path, "cell H4", "'records/loop.csv' cannot be followed",
                   "a link that leads back to itself", places=[location("inventory.xlsx", "hazard", "H4")])


def test_calibrate_lists_at_most_50_problems(tmp_path):
    rows = [["specimen", "motion", "sliding_cm"]] + [["NOPE", "Nowhere", -1]] * 100
    measured = write_tests_workbook(tmp_path / "measured.xlsx", rows)
    done = run("calibrate", KM2010, "--measured", measured, "--out", tmp_path / "cal", cwd=tmp_path)
    assert_refused(done, "and 250 more; fix these first", max_chars=50 * 400,
                   places=[location("measured.xlsx", "tests", "A2"), location("measured.xlsx", "tests", "B2")])
    assert done.stderr.count("  - ") == 50


def test_consequence_column_is_read_and_a_wrong_value_is_located(tmp_path):
    """consequence (docs/workbook.md): any case, space or underscore for the hyphen, ordinary when empty; anything else
    exit 2 at its cell."""
    sheets = good_sheets()
    for row in sheets["equipment"]:
        row["consequence"] = ""
    sheets["equipment"][0]["consequence"] = "Life Safety"
    path = workbook(tmp_path, sheets)
    consequences = read_workbook(path).equipment["consequence"]
    assert consequences.iloc[0] == "life-safety" and consequences.iloc[-1] == "ordinary"
    sheets["equipment"][0]["consequence"] = "catastrophic"
    bad = workbook(tmp_path, sheets, name="bad.xlsx")
    assess_refuses(tmp_path, bad, "'catastrophic' is not a consequence", "consequence",
                   places=[location("bad.xlsx", "equipment", "P2")])
