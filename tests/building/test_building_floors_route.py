"""The floors of a ``building`` sheet: items on floors it does not have are refused at their cell, a
hazard sheet that gives every floor its own motions leaves the building nothing to do, and under
``floor_numbering`` ``ground_1`` every floor label a user reads counts the ground floor 1 (docs/workbook.md).

Expected labels are the workbook's numbers plus one (the US count), written out here, never read back
from the tool; the refusals are checked for what the rules of the project ask of a message: the file,
sheet, row, column, what the building has and a fix.
"""
from __future__ import annotations

import html
import re

import pandas as pd
import pytest

from assess import cli
from assessed import run_assessment
from assess.errors import InputError
from assess.inventory import read_workbook

#: Items on the ground floor, floor 1 and the roof (floor 2) of a 2-storey building.
EQUIPMENT = [
    {"id": "G-1", "name": "incubator", "floor": 0, "height_cm": 180, "width_cm": 70, "depth_cm": 80,
     "mass_kg": 200, "mu": 0.3, "clearance_cm": 10},
    {"id": "M-1", "name": "freezer", "floor": 1, "height_cm": 190, "width_cm": 80, "depth_cm": 85,
     "mass_kg": 300, "mu": 0.25, "clearance_cm": 8},
    {"id": "R-2", "name": "rack", "floor": 2, "height_cm": 200, "width_cm": 60, "depth_cm": 100,
     "mass_kg": 400, "mu": 0.35, "clearance_cm": 5},
]
SITE = [["key", "value"], ["sds_g", 1.0], ["sd1_g", 0.6], ["suite_size", 3], ["risk_category", "IV"]]
BUILDING = [["key", "value"], ["storeys", 2], ["storey_height_m", 4.0], ["period_s", 0.3]]
GROUND_1 = [["key", "value"], ["floor_numbering", "ground_1"]]


def _sheets(floors=None, **extra):
    equipment = [dict(item) for item in EQUIPMENT]
    for item, floor in zip(equipment, floors or []):
        item["floor"] = floor
    sheets = {"equipment": equipment, "site": SITE, "building": BUILDING}
    sheets.update(extra)
    return sheets


# ---------------------------------------------------------------- floors the building does not have

@pytest.mark.parametrize("floor, words", [(3, "above the roof"), (7, "above the roof"), (-1, "below the ground")])
def test_an_item_on_a_floor_the_building_does_not_have_is_refused_at_its_cell(make_workbook, floor, words):
    path = make_workbook(_sheets(floors=[0, 1, floor]), record=False)
    with pytest.raises(InputError) as error:
        read_workbook(path)
    (problem,) = error.value.problems
    # R-2 is the third item: Excel row 4; floor is the 3rd column (C)
    assert (problem.sheet, problem.row, problem.column, problem.cell) == ("equipment", 4, "floor", "C4")
    assert words in problem.message and f"floor {floor}" in problem.message and "R-2" in problem.message
    assert "floors 0 (the ground floor) to 2 (the roof" in problem.message and problem.fix


def test_the_command_exits_2_naming_the_cell_and_writes_nothing(make_workbook, tmp_path, capsys):
    path = make_workbook(_sheets(floors=[0, -1, 7]), record=False)
    out = tmp_path / "out"
    assert cli.main([str(path), "--hazard", "DE", "--out", str(out), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert "sheet 'equipment'" in err and "cell C3" in err and "cell C4" in err
    assert "below the ground floor" in err and "above the roof" in err
    assert "Traceback" not in err and "--derive-floors" not in err and not out.exists()


def test_every_floor_with_its_own_pulse_rows_needs_nothing_from_the_building(make_workbook):
    """A hazard sheet of pulses for floors 0, 1 and 2 beside a building sheet: the floors keep their rows
    (no floors.csv, since no floor's motion comes from the building), and the notes say so."""
    hazard = [{"level": "DE", "motion": f"pulse {floor}", "floor": floor, "pta_g": 0.4 + 0.2 * floor,
               "tp_s": 0.5, "vp_cm_s": 30, "pulse": "B"} for floor in (0, 1, 2)]
    sheets = _sheets(hazard=hazard)
    del sheets["site"]
    result = run_assessment(read_workbook(make_workbook(sheets, record=False)), "DE", seed=1)
    motions = result.motions.drop_duplicates("id").set_index("id")["motion"]
    assert dict(motions) == {"G-1": "pulse 0", "M-1": "pulse 1", "R-2": "pulse 2"}
    assert result.floors is None
    assert any("gives no floor its motion" in note for note in result.hazard_notes)


# ---------------------------------------------------------------- one floor numbering

@pytest.fixture(scope="module")
def us_hospital(tmp_path_factory):
    from workbooks import write_workbook
    path = write_workbook(tmp_path_factory.mktemp("us") / "h.xlsx", _sheets(settings=GROUND_1))
    return run_assessment(read_workbook(path), "DE", seed=3)


def test_under_ground_1_motion_names_count_the_ground_floor_1(us_hospital):
    result = us_hospital
    motions = result.motions
    ground = set(result.ground_motions["motion"])
    named = {item: set(motions.loc[motions["id"] == item, "motion"]) for item in ("G-1", "M-1", "R-2")}
    assert named["G-1"] == ground
    assert named["M-1"] == {f"{name} @ floor 2" for name in ground}  # the workbook's floor 1
    assert named["R-2"] == {f"{name} @ floor 3" for name in ground}  # the workbook's floor 2, the roof
    # the histories the engine ran say the same floor
    assert all(label.endswith("@ floor 3, through the building")
               for label in motions.loc[motions["id"] == "R-2", "sim_motion"].dropna().astype(str)
               if "through the building" in label)


def test_under_ground_1_the_notes_label_floors_as_the_tables_and_say_which_is_the_roof(us_hospital):
    notes = us_hospital.hazard_notes
    assert any(note.startswith("Floors 2 and 3: each ground motion through the building") for note in notes), notes
    roof = [note for note in notes if "roof" in note and note.startswith("Floor 3 is the building's roof")]
    assert roof and "R-2" in roof[0] and "the workbook's floor 2" in roof[0]
    # no note labels a floor with the workbook's number 1 or 2 as if it were the label
    assert not any(re.search(r"@ floor 1\b", note) for note in notes)


def test_under_ground_1_the_report_and_work_orders_use_the_same_labels(us_hospital):
    from assess.report import render_html
    result = us_hospital
    text = html.unescape(render_html(result))
    # item table, motion names, notes, work orders: only labels 1 (ground) to 3 (roof) appear, besides the
    # sentences that quote "the workbook's floor N"
    shown = {int(n) for n in re.findall(r"(?<!workbook's )[Ff]loors? (\d+)\b", text)}
    assert shown <= {1, 2, 3}, shown
    orders = result.work_orders()
    expected = {str(f + 1) for f in orders["floor"]}
    assert set(orders["floor_label"]) == expected


def test_under_ground_1_derived_floor_motions_are_named_by_the_label():
    """--derive-floors without a building: the workbook's floor 3 of roof 6 is labelled 4, its factor 1 + 2·3/6 = 2."""
    from assess.hazard.motions import derive_floor_motions
    ground = pd.DataFrame({"motion": ["LG"], "floor": pd.array([0], dtype="Int64"), "all_floors": [False],
                           "pta_g": [0.5], "vp_m_s": [0.4], "tp_s": [1.0], "scale": [1.0], "record_path": [""]})
    derived = derive_floor_motions(ground, [0, 3], 6, "w.xlsx", "ground_1")
    row = derived[derived["derived"]].iloc[0]
    assert int(row["floor"]) == 3 and row["motion"] == "LG -> floor 4 (derived, x2.00)"
    assert row["pta_g"] == pytest.approx(1.0)
