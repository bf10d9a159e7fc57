"""The workbook reader: a good workbook to SI, and every kind of wrong workbook reported."""
from __future__ import annotations

import math
import zipfile

import pytest

from assess.data import default_settings
from assess.inventory.settings import Settings
from assess.errors import InputError, Problem
from assess.inventory import read_workbook
from workbooks import (BILLION_LAUGHS, RECORD_FILE, add_cached_value, drop_column, good_sheets,
                       rename_column, rewrite_member, sheet_xml_name)


def problems_of(path) -> list[Problem]:
    with pytest.raises(InputError) as caught:
        read_workbook(path)
    assert caught.value.problems, "InputError without problems"
    return caught.value.problems


def only_problem(path) -> Problem:
    problems = problems_of(path)
    assert len(problems) == 1, "\n".join(str(p) for p in problems)
    return problems[0]


def assert_mentions(problem: Problem, *fragments: str) -> None:
    text = str(problem)
    for fragment in fragments:
        assert fragment in text, f"{fragment!r} not in {text!r}"


# ---------------------------------------------------------------- a good workbook

def test_good_workbook_reads_to_documented_si_columns(make_workbook):
    path = make_workbook()
    inventory = read_workbook(path)

    equipment = inventory.equipment
    assert list(equipment.columns) == [
        "id", "name", "room", "floor", "height_m", "width_m", "depth_m", "mass_kg", "mu",
        "mu_static", "clearance_m", "cg_height_m", "anchored", "casters", "quantity", "consequence", "component_type", "contents", "equipment_kind",
            "type_source", "connections", "connections_assumed", "ip",
        "mu_low", "mu_high", "value", "mitigation_cost", "base", "floor_finish", "mu_source", "row"]
    assert list(equipment["id"]) == ["INC-1", "FRZ-2", "BSC-3"]
    assert list(equipment["row"]) == [2, 3, 5]  # blank row 4 skipped
    first = equipment.iloc[0]
    assert first["height_m"] == pytest.approx(2.286, rel=1e-12)  # 90 in
    assert first["width_m"] == pytest.approx(0.70, rel=1e-12)  # 70 cm
    assert first["depth_m"] == pytest.approx(0.60, rel=1e-12)  # 600 mm
    assert first["mass_kg"] == pytest.approx(45.359237, rel=1e-12)  # 100 lb
    assert first["clearance_m"] == pytest.approx(0.10, rel=1e-12)
    # defaults
    assert first["mu_static"] == first["mu"] == 0.3
    assert first["cg_height_m"] == pytest.approx(2.286 / 2, rel=1e-12)
    assert first["quantity"] == 1 and not first["anchored"] and not first["casters"]  # casters: not given, no
    second = equipment.iloc[1]
    assert second["room"] == ""
    assert second["mu_static"] == 0.35
    assert second["cg_height_m"] == pytest.approx(1.0, rel=1e-12)
    assert bool(second["anchored"]) is True and second["quantity"] == 2
    third = equipment.iloc[2]
    assert third["floor"] == 3 and third["height_m"] == pytest.approx(62.2 * 0.0254, rel=1e-12)
    assert bool(third["anchored"]) is False and third["clearance_m"] == 0.0
    assert str(equipment["floor"].dtype) == "int64"
    assert str(equipment["anchored"].dtype) == "bool"
    assert "notes" not in equipment.columns

    hazard = inventory.hazard
    assert list(hazard.columns) == [
        "level", "level_label", "motion", "all_floors", "floor", "pta_g", "tp_s", "vp_m_s",
        "pulse", "record_path", "scale", "record_2_path", "azimuth_deg", "row"]
    assert list(hazard["level"]) == ["2in50", "2in50", "10in50"]
    assert list(hazard["level_label"]) == ["2%/50yr", "2in50", "10in50"]
    assert inventory.levels == ["2in50", "10in50"]
    assert hazard["pta_g"].iloc[0] == pytest.approx(0.5, rel=1e-12)  # 490.3325 cm/s² / g
    assert hazard["pta_g"].iloc[1] == pytest.approx(0.7, rel=1e-12)
    assert hazard["vp_m_s"].iloc[0] == pytest.approx(-0.75, rel=1e-12)  # sign kept
    assert math.isnan(hazard["vp_m_s"].iloc[1])
    assert list(hazard["pulse"]) == ["B", "A", ""]
    assert list(hazard["scale"]) == [1.0, 1.0, 1.2]
    assert list(hazard["all_floors"]) == [False, False, True]
    assert hazard["floor"].iloc[1] == 2 and hazard["floor"].isna().iloc[2]
    assert hazard["record_path"].iloc[0] == ""
    assert hazard["record_path"].iloc[2] == str((path.parent / RECORD_FILE).resolve())
    assert math.isnan(hazard["pta_g"].iloc[2]) and math.isnan(hazard["tp_s"].iloc[2])

    settings = inventory.settings
    assert settings.facility == "Bio lab" and settings.site == "Berkeley"
    assert settings.zeta == 0.4 and settings.risk_pf_moderate == 0.2
    assert settings.eta == 0.953 and settings.sigma == 0.445
    assert default_settings()["zeta"] == 0.370  # the packaged defaults are untouched


def test_settings_sheet_is_optional_and_sheet_names_ignore_case(make_workbook):
    sheets = good_sheets()
    del sheets["settings"]
    sheets["EQUIPMENT"] = sheets.pop("equipment")
    inventory = read_workbook(make_workbook(sheets))
    assert len(inventory.equipment) == 3
    # the defaults, with the units resolved from the headers (lengths in in, cm and mm: SI)
    assert inventory.settings == Settings(units="si")


def test_formula_with_cached_value_is_read(make_workbook):
    path = make_workbook(cells={"equipment": {"I2": "=0.1*3"}})
    add_cached_value(path, "equipment", "I2", 0.3)
    assert read_workbook(path).equipment["mu"].iloc[0] == 0.3


# ---------------------------------------------------------------- the file itself

def test_missing_file(tmp_path):
    problem = only_problem(tmp_path / "nowhere.xlsx")
    assert_mentions(problem, "nowhere.xlsx", "does not exist")
    assert "path" in problem.fix


def test_text_file_named_xlsx_is_not_a_workbook(tmp_path):
    path = tmp_path / "inventory.xlsx"
    path.write_text("id,name\nINC-1,incubator\n")
    problem = only_problem(path)
    assert_mentions(problem, "inventory.xlsx", "not a valid .xlsx workbook", "not a zip")
    assert "save it as an Excel workbook (.xlsx)" in problem.fix


def test_csv_file_is_not_accepted(tmp_path):
    path = tmp_path / "inventory.csv"
    path.write_text("id,name\n")
    assert_mentions(only_problem(path), "its extension is '.csv'", "expected .xlsx")


def test_encrypted_workbook(tmp_path):
    path = tmp_path / "locked.xlsx"
    path.write_bytes(b"\xd0\xcf\x11\xe0\xa1\xb1\x1a\xe1" + b"\0" * 504)  # an OLE container
    problem = only_problem(path)
    assert_mentions(problem, "locked.xlsx", "password-protected")
    assert "remove the password" in problem.fix


def test_damaged_package(make_workbook):
    path = make_workbook()
    rewrite_member(path, "xl/workbook.xml", lambda xml: xml[: len(xml) // 2])
    assert_mentions(only_problem(path), "cannot be read", "damaged")


def test_billion_laughs_payload_is_refused(make_workbook):
    path = make_workbook()
    rewrite_member(path, sheet_xml_name(path, "equipment"), lambda _: BILLION_LAUGHS)
    problem = only_problem(path)
    assert_mentions(problem, "inventory.xlsx", "refused for safety", "EntitiesForbidden")


# ---------------------------------------------------------------- sheets and headers

def test_missing_sheet_lists_the_sheets_the_file_has(make_workbook):
    sheets = good_sheets()
    del sheets["hazard"]
    problem = only_problem(make_workbook(sheets))
    assert_mentions(problem, "required sheet 'hazard' is missing",
                    "'equipment', 'settings', 'README'")


def test_every_missing_required_column_is_reported(make_workbook):
    sheets = good_sheets()
    drop_column(sheets["equipment"], "mu")  # optional: a default range (test_default_mu.py)
    drop_column(sheets["equipment"], "mass_lb")
    problems = problems_of(make_workbook(sheets))
    assert sorted(p.column for p in problems) == ["mass_kg"]
    for problem in problems:
        assert_mentions(problem, "sheet 'equipment'", "row 1", "required column")
    mass = next(p for p in problems if p.column == "mass_kg")
    assert "mass_kg or mass_lb" in mass.fix


def test_unknown_column_suggests_the_closest(make_workbook):
    sheets = good_sheets()
    rename_column(sheets["equipment"], "clearance_cm", "clearence_cm")
    problem = only_problem(make_workbook(sheets))  # not also "clearance missing"
    assert_mentions(problem, "sheet 'equipment'", "cell K1", "column 'clearence_cm'",
                    "unknown column 'clearence_cm'", "did you mean 'clearance_cm'?")


def test_a_weight_column_is_taken_for_the_mass_it_means(make_workbook):
    """``weight_lb``, as a facilities list heads it: one problem, pointing at ``mass_lb`` (difflib alone
    offered ``height_m``), and no second one for the missing mass."""
    sheets = good_sheets()
    rename_column(sheets["equipment"], "mass_lb", "weight_lb")
    problem = only_problem(make_workbook(sheets))
    assert_mentions(problem, "sheet 'equipment'", "column 'weight_lb'", "unknown column 'weight_lb'",
                    "did you mean 'mass_lb'?")
    assert "rename it to 'mass_lb'" in problem.fix


def test_header_without_unit_lists_the_suffixes(make_workbook):
    sheets = good_sheets()
    rename_column(sheets["equipment"], "height_in", "Height ")
    problem = only_problem(make_workbook(sheets))
    assert_mentions(problem, "sheet 'equipment'", "cell E1", "column 'Height'",
                    "the column 'Height' does not say its unit")
    assert "height_cm, height_m, height_mm, height_in or height_ft" in problem.fix


def test_unit_suffix_not_accepted(make_workbook):
    sheets = good_sheets()
    rename_column(sheets["equipment"], "mass_lb", "mass_g")
    problem = only_problem(make_workbook(sheets))
    assert_mentions(problem, "column 'mass_g'", "'g' is not an accepted unit for mass")
    assert "mass_kg or mass_lb" in problem.fix


def test_two_columns_for_one_quantity(make_workbook):
    sheets = good_sheets()
    for row in sheets["equipment"]:
        if row:
            row["height_m"] = 2.0
    problem = only_problem(make_workbook(sheets))
    assert_mentions(problem, "sheet 'equipment'", "columns 'height_in' (E1) and 'height_m'",
                    "both give height")


def test_values_under_an_empty_header(make_workbook):
    path = make_workbook(cells={"equipment": {"Z3": 42}})
    assert_mentions(only_problem(path), "sheet 'equipment'", "cell Z1",
                    "column Z holds values (e.g. Z3) but has no header")


# ---------------------------------------------------------------- equipment cells

def test_non_numeric_cell_is_quoted(make_workbook):
    sheets = good_sheets()
    sheets["equipment"][1]["width_cm"] = "62 cm"
    problem = only_problem(make_workbook(sheets))
    assert (problem.sheet, problem.row, problem.column, problem.cell) == (
        "equipment", 3, "width_cm", "F3")
    assert_mentions(problem, "sheet 'equipment'", "cell F3", "column 'width_cm'",
                    "'62 cm' is not a number")
    assert "unit is given by the column header" in problem.fix


@pytest.mark.parametrize("mu", [0, -0.2])
def test_zero_or_negative_friction(make_workbook, mu):
    sheets = good_sheets()
    sheets["equipment"][0]["mu"] = mu
    problem = only_problem(make_workbook(sheets))
    assert problem.row == 2
    assert_mentions(problem, "cell I2", "column 'mu'", f"mu {mu} must be greater than 0")


def test_friction_in_percent_is_implausible(make_workbook):
    sheets = good_sheets()
    sheets["equipment"][0]["mu"] = 30
    problem = only_problem(make_workbook(sheets))
    assert_mentions(problem, "cell I2", "mu 30 is not plausible", "expected 0.01 to 1.5")
    assert "not 30 %" in problem.fix


def test_height_in_mm_written_as_cm_suggests_the_unit(make_workbook):
    sheets = good_sheets()
    rename_column(sheets["equipment"], "height_in", "height_cm")
    for row, height in zip(sheets["equipment"], [180, 2286, None, 150]):
        row["height_cm"] = height
    problem = only_problem(make_workbook(sheets))
    assert_mentions(problem, "sheet 'equipment'", "cell E3", "column 'height_cm'",
                    "height 2286 cm = 22.9 m is not plausible for a piece of equipment",
                    "expected 0.05 to 6 m")
    assert "if the values are in mm, name the column height_mm" in problem.fix


def test_duplicate_id_names_both_rows(make_workbook):
    sheets = good_sheets()
    sheets["equipment"][3]["id"] = "INC-1"
    problem = only_problem(make_workbook(sheets))
    assert_mentions(problem, "sheet 'equipment'", "cell A5", "id 'INC-1' is used twice",
                    "row 2", "row 5")


def test_non_integer_floor(make_workbook):
    sheets = good_sheets()
    sheets["equipment"][1]["floor"] = 3.5
    problem = only_problem(make_workbook(sheets))
    assert_mentions(problem, "cell D3", "column 'floor'", "'3.5' is not a whole number")


def test_bad_anchored_value(make_workbook):
    sheets = good_sheets()
    sheets["equipment"][0]["anchored"] = "bolted"
    problem = only_problem(make_workbook(sheets))
    assert_mentions(problem, "cell M2", "column 'anchored'", "'bolted' is not yes or no")


def test_component_type_and_ip_are_read_and_checked(make_workbook):
    sheets = good_sheets()
    sheets["equipment"][0]["component_type"] = " UPS "
    sheets["equipment"][0]["ip"] = 1.5
    equipment = read_workbook(make_workbook(sheets)).equipment
    assert list(equipment["component_type"]) == ["battery rack", "", ""]  # as the table names it; empty: default
    assert equipment["ip"].iloc[0] == 1.5 and equipment["ip"].iloc[1:].isna().all()
    sheets["equipment"][0]["component_type"] = "toaster"
    assert_mentions(only_problem(make_workbook(sheets)), "column 'component_type'", "'toaster' is not a component type",
                    "laboratory equipment")
    sheets["equipment"][0]["component_type"] = "freezer"
    sheets["equipment"][1]["ip"] = 1.25
    assert_mentions(only_problem(make_workbook(sheets)), "cell", "column 'ip'",
                    "'1.25' is not a component importance factor", "13.1.3")


def test_contents_are_read_with_their_default_and_checked(make_workbook):
    """contents: as written in any case; empty: movable for shelving and cabinets, none otherwise
    (docs/workbook.md); the component type as written is kept beside the table's name (equipment_kind)."""
    sheets = good_sheets()
    sheets["equipment"][0]["component_type"] = "Storage_Cabinet"
    sheets["equipment"][1]["contents"] = " FIXED "
    equipment = read_workbook(make_workbook(sheets)).equipment
    assert list(equipment["contents"]) == ["movable", "fixed", "none"]
    assert list(equipment["equipment_kind"]) == ["storage cabinet", "", ""]
    assert equipment["component_type"].iloc[0] == "storage shelving"
    sheets["equipment"][1]["contents"] = "loose"
    assert_mentions(only_problem(make_workbook(sheets)), "column 'contents'", "'loose' is not a kind of contents",
                    "movable", "fixed", "none")


def test_static_friction_below_kinetic(make_workbook):
    sheets = good_sheets()
    sheets["equipment"][1]["mu_static"] = 0.2
    problem = only_problem(make_workbook(sheets))
    assert_mentions(problem, "cell J3", "column 'mu_static'",
                    "mu_static '0.2' is less than mu '0.25'")


def test_centre_of_mass_above_the_top(make_workbook):
    sheets = good_sheets()
    sheets["equipment"][1]["cg_height_cm"] = 250  # the freezer is 78 in = 1.98 m high
    problem = only_problem(make_workbook(sheets))
    assert_mentions(problem, "cell L3", "column 'cg_height_cm'", "cg_height_cm '250' (2.5 m)",
                    "above the top of the item", "height_in '78' (1.98 m)")


def test_partly_filled_row_reports_each_missing_required_cell(make_workbook):
    sheets = good_sheets()
    sheets["equipment"][2] = {"name": "a trolley"}  # row 4 no longer blank
    problems = problems_of(make_workbook(sheets))
    assert {p.cell for p in problems} == {"A4", "D4", "E4", "F4", "G4", "H4", "K4"}  # I4, mu: optional
    assert_mentions(problems[0], "sheet 'equipment'", "cell A4", "id is empty")


# ---------------------------------------------------------------- hazard cells

def test_impossible_probability_level(make_workbook):
    """A probability spelling out of range is refused (any other text is a label)."""
    sheets = good_sheets()
    sheets["hazard"][1]["level"] = "150in50"
    problem = only_problem(make_workbook(sheets))
    assert_mentions(problem, "sheet 'hazard'", "cell A3", "column 'level'",
                    "'150in50'", "between 0 and 100 %")


def test_motion_without_pta_and_without_record(make_workbook):
    sheets = good_sheets()
    sheets["hazard"][1]["pta_cm_s2"] = None
    problem = only_problem(make_workbook(sheets))
    assert_mentions(problem, "sheet 'hazard'", "cell D3", "column 'pta_cm_s2'",
                    "pta_cm_s2 is empty and the row names no record")


def test_no_pta_column_reported_once_with_the_rows_that_need_it(make_workbook):
    sheets = good_sheets()
    drop_column(sheets["hazard"], "pta_cm_s2")  # rows 2 and 3 have no record; row 4 has one
    problem = only_problem(make_workbook(sheets))
    assert (problem.sheet, problem.row, problem.column) == ("hazard", 1, "pta_g")
    assert_mentions(problem, "the column 'pta_g' is missing, and rows 2, 3 name no record")


def test_missing_record_file(make_workbook):
    path = make_workbook(record=False)
    problem = only_problem(path)
    assert_mentions(problem, "sheet 'hazard'", "cell H4", "column 'record'",
                    f"the record file '{RECORD_FILE}' was not found",
                    f"looked for {(path.parent / RECORD_FILE).resolve()}")
    assert "relative to the workbook's folder" in problem.fix


def test_same_motion_twice(make_workbook):
    sheets = good_sheets()
    sheets["hazard"][1]["floor"] = 0  # row 2 is the same level (2%/50yr = 2in50) and motion
    problem = only_problem(make_workbook(sheets))
    assert_mentions(problem, "sheet 'hazard'", "cell B3",
                    "motion 'Los Gatos PC' at level 2in50, floor 0 is given twice",
                    "row 2", "row 3")


def test_pta_in_cm_s2_named_g_suggests_the_unit(make_workbook):
    sheets = good_sheets()
    rename_column(sheets["hazard"], "pta_cm_s2", "pta_g")
    problems = problems_of(make_workbook(sheets))  # 490 and 686 "g"
    assert [p.cell for p in problems] == ["D2", "D3"]
    assert_mentions(problems[0], "sheet 'hazard'", "column 'pta_g'",
                    "pta 490.3325 g is not plausible for a floor motion")
    assert problems[0].fix.startswith("if the values are in cm/s², name the column pta_cm_s2;")


def test_bad_pulse_type(make_workbook):
    sheets = good_sheets()
    sheets["hazard"][0]["pulse"] = "D"
    assert_mentions(only_problem(make_workbook(sheets)), "cell G2", "'D' is not a pulse type")


# ---------------------------------------------------------------- settings

def test_unknown_settings_key_suggests_the_closest(make_workbook):
    sheets = good_sheets()
    sheets["settings"][2]["key"] = "zeeta"
    problem = only_problem(make_workbook(sheets))
    assert_mentions(problem, "sheet 'settings'", "cell A4", "unknown setting 'zeeta'",
                    "did you mean 'zeta'?")


@pytest.mark.parametrize("key, value, expected", [
    ("zeta", "abc", "setting 'zeta': 'abc' is not a number"),
    ("sigma", -0.4, "setting 'sigma' is -0.4, outside 0.01 to 2; it lies between them"),
    ("risk_pf_high", 1.5, "setting 'risk_pf_high' is '1.5'; a probability threshold lies"),
    ("risk_pf_high", 0.15, "risk_pf_moderate '0.2' must be less than risk_pf_high '0.15'"),
    ("im_max", 1.0, "im_min '1.71' must be less than im_max '1'"),
    ("simulate_motions", "records", "setting 'simulate_motions' is 'records'; it is 'synthetic' or 'pulse'"),
    ("synthetic_realizations", 2.5, "setting 'synthetic_realizations' is '2.5'; it is a whole number"),
])
def test_bad_settings_value(make_workbook, key, value, expected):
    sheets = good_sheets()
    sheets["settings"].append({"key": key, "value": value})  # Excel row 6
    if key == "zeta":
        del sheets["settings"][2]
    problem = only_problem(make_workbook(sheets))
    assert problem.column == "value"
    assert_mentions(problem, "sheet 'settings'", expected)
    assert problem.row in (5, 6)


# ---------------------------------------------------------------- formulas

def test_formula_without_computed_value(make_workbook):
    path = make_workbook(cells={"equipment": {"H3": "=G3*2"}})
    problem = only_problem(path)
    assert_mentions(problem, "sheet 'equipment'", "cell H3", "column 'mass_lb'",
                    "holds the formula =G3*2 with no computed value")
    assert "open and save the workbook in Excel or LibreOffice" in problem.fix


# ---------------------------------------------------------------- all at once

def test_all_problems_of_the_workbook_are_reported_together(make_workbook):
    sheets = good_sheets()
    sheets["equipment"][0]["mu"] = "low"  # I2
    sheets["equipment"][3]["floor"] = 2.5  # D5
    sheets["hazard"][0]["level"] = "0%/50yr"  # A2
    with pytest.raises(InputError) as caught:
        read_workbook(make_workbook(sheets))
    problems = caught.value.problems
    assert [(p.sheet, p.cell) for p in problems] == [
        ("equipment", "I2"), ("equipment", "D5"), ("hazard", "A2")]
    text = str(caught.value)
    assert text.startswith("3 problems in the input:")
    assert "'low' is not a number" in text and "'2.5' is not a whole number" in text
    assert "hazard level '0%/50yr': the probability must lie between 0 and 100 %" in text


def test_zip_that_is_not_a_workbook(tmp_path):
    path = tmp_path / "photos.xlsx"
    with zipfile.ZipFile(path, "w") as archive:
        archive.writestr("holiday.txt", "not a spreadsheet")
    problem = only_problem(path)
    assert problem.file == str(path) and problem.sheet is None
    assert_mentions(problem, "photos.xlsx: the workbook cannot be read", "damaged")


def test_connections_are_read_in_any_order_and_a_bad_one_names_its_cell(make_workbook):
    """connections: gas, fluid, both (comma or semicolon, any case) or none; empty: from the item's kind
    (docs/workbook.md); a word not in the list is a problem naming the cell, the column and the words to write."""
    sheets = good_sheets()
    sheets["equipment"][0]["connections"] = "Fluid; GAS"
    sheets["equipment"][1]["connections"] = "none"
    equipment = read_workbook(make_workbook(sheets)).equipment
    assert list(equipment["connections"]) == ["gas, fluid", "none", "none"]
    assert list(equipment["connections_assumed"]) == [False, False, False]
    sheets["equipment"][1]["connections"] = "steam"
    assert_mentions(only_problem(make_workbook(sheets)), "column 'connections'",
                    "'steam' is not a list of connections", "gas", "fluid", "none")
