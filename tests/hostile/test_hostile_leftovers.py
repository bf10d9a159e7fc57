"""Still open from the first hostile-input campaign: two sheets with one name, and numbers Python's float() reads
but no record file means (``0.1_0``, full-width digits). Each is refused, exit 2, the file and place named."""
from __future__ import annotations

import zipfile
from pathlib import Path

import pytest

from assess.errors import InputError
from assess.hazard.records import read_record
from assess.inventory import read_workbook
from tests.hostile.test_hostile_records import GOOD_RECORD, assert_refused, run, workbook_naming
from workbooks import good_sheets, write_workbook


def with_second_equipment_sheet(folder: Path, second: str) -> Path:
    """A good workbook plus a one-item sheet titled ``second`` (openpyxl renames a clash: the package is edited)."""
    sheets = good_sheets()
    sheets["other"] = sheets["equipment"][:1]
    written = write_workbook(folder / "written.xlsx", sheets, files={"records/lg.csv": GOOD_RECORD})
    path = folder / "wb.xlsx"
    with zipfile.ZipFile(written) as source, zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as target:
        for member in source.infolist():
            data = source.read(member.filename)
            if member.filename == "xl/workbook.xml":
                data = data.replace(b'name="other"', f'name="{second}"'.encode())
            target.writestr(member, data)
    return path


@pytest.mark.parametrize("second", ["EQUIPMENT", "Equipment ", "equipment "])
def test_two_sheets_named_equipment_are_refused_naming_both(tmp_path, second):
    path = with_second_equipment_sheet(tmp_path, second)  # the second one silently won
    with pytest.raises(InputError) as caught:
        read_workbook(path)
    text = str(caught.value)
    assert "'equipment'" in text and f"'{second}'" in text and "keep one sheet named 'equipment'" in text


def test_two_equipment_sheets_through_the_cli(tmp_path):
    path = with_second_equipment_sheet(tmp_path, "EQUIPMENT")
    done = run(path, "--hazard", "2in50", "--out", tmp_path / "out", cwd=tmp_path)
    assert_refused(done, "wb.xlsx", "the sheets 'equipment' and 'EQUIPMENT' all name the equipment sheet")
    assert not (tmp_path / "out").exists()


#: (what replaces the 0.3 g peak's row value, the name of the case)
ODD_NUMBERS = [("0.1_0", "underscore"), ("\uff10.\uff11", "full-width digits"), ("\u0660.\u0661", "Arabic-Indic digits")]


@pytest.mark.parametrize("value, _", ODD_NUMBERS, ids=[name for _, name in ODD_NUMBERS])
def test_a_number_float_reads_but_no_file_means_is_refused_at_its_line(tmp_path, value, _):
    lines = GOOD_RECORD.splitlines()
    lines[5] = lines[5].split(",")[0] + "," + value  # line 6 of the file
    path = tmp_path / "odd.csv"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    with pytest.raises(InputError) as caught:
        read_record(path)
    (problem,) = caught.value.problems
    assert problem.file.endswith("odd.csv") and problem.row == 6
    assert "not a plain decimal number" in problem.message


def test_an_underscore_number_in_a_workbooks_record_through_the_cli(tmp_path):
    lines = GOOD_RECORD.splitlines()
    lines[5] = lines[5].split(",")[0] + ",0.1_0"
    book = workbook_naming(tmp_path, "odd.csv", files={"odd.csv": "\n".join(lines) + "\n"})
    done = run(book, "--hazard", "2in50", "--out", tmp_path / "out", cwd=tmp_path)
    assert_refused(done, "odd.csv", "line 6", "not a plain decimal number")
    assert not (tmp_path / "out").exists()


def test_an_at2_with_full_width_digits_is_refused_at_its_line(tmp_path):
    path = tmp_path / "odd.AT2"
    path.write_text("PEER NGA\nodd\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS= 4, DT= .0100 SEC\n"
                    "0.1 0.2\n0.3 \uff10.\uff14\n", encoding="utf-8")
    with pytest.raises(InputError) as caught:
        read_record(path)
    assert caught.value.problems[0].row == 6
