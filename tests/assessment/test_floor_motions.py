"""Floor motions from the site and the building (docs/workbook.md, sheets ``site`` and ``building``).

The pieces are verified on their own against independent references (the building's floor histories
against OpenSeesPy and closed forms: tests/verification/test_building_*.py; the spectra and the suites:
tests/verification/test_site_*.py, tests/site/test_site_suite.py). Here: that the assessment takes its
motions from them as documented — the site's suite at the ground, each floor's motion that suite through the building, a floor with its own
hazard rows keeping them, --derive-floors giving way, and refusals located on the site sheet.
"""
from __future__ import annotations

import numpy as np
import pytest

from assessed import run_assessment
from assess.building import building_modes
from assess.building.response import floor_records
from assess.errors import InputError
from assess.inventory import read_workbook

EQUIPMENT = [
    {"id": "G-1", "name": "incubator", "floor": 0, "height_cm": 180, "width_cm": 70, "depth_cm": 80,
     "mass_kg": 200, "mu": 0.3, "clearance_cm": 10},
    {"id": "R-2", "name": "rack", "floor": 2, "height_cm": 200, "width_cm": 60, "depth_cm": 100,
     "mass_kg": 400, "mu": 0.35, "clearance_cm": 5},
    {"id": "M-1", "name": "freezer", "floor": 1, "height_cm": 190, "width_cm": 80, "depth_cm": 85,
     "mass_kg": 300, "mu": 0.25, "clearance_cm": 8},
]
SITE = [["key", "value"], ["sds_g", 1.0], ["sd1_g", 0.6], ["suite_size", 3], ["risk_category", "IV"]]
BUILDING = [["key", "value"], ["storeys", 2], ["storey_height_m", 4.0], ["period_s", 0.3]]


def _sheets(**extra):
    sheets = {"equipment": [dict(item) for item in EQUIPMENT], "site": SITE, "building": BUILDING}
    sheets.update(extra)
    return sheets


@pytest.fixture(scope="module")
def hospital(tmp_path_factory):
    from workbooks import write_workbook
    path = write_workbook(tmp_path_factory.mktemp("hospital") / "h.xlsx", _sheets())
    return read_workbook(path), run_assessment(read_workbook(path), "DE", seed=3)


def test_the_site_gives_the_ground_suite_and_the_building_every_floor(hospital):
    inventory, result = hospital
    ground = result.ground_motions
    assert len(ground) == 3 and set(ground["record"]) == {"synthetic"}
    motions = result.motions
    on_floor = {floor: set(motions.loc[motions["id"] == item, "motion"])
                for item, floor in (("G-1", 0), ("M-1", 1), ("R-2", 2))}
    assert on_floor[0] == set(ground["motion"])
    assert on_floor[1] == {f"{name} @ floor 1" for name in ground["motion"]}
    assert on_floor[2] == {f"{name} @ floor 2" for name in ground["motion"]}
    assert list(result.floors["floor"]) == [0, 1, 2]
    assert any(note.startswith("Ground floor: 3 spectrum-compatible synthetic") for note in result.hazard_notes)
    assert any(note.startswith("Floors 1 and 2: each ground motion through the building") for note in result.hazard_notes)


def test_a_floor_motion_is_the_ground_motion_through_the_building(hospital):
    """The PTA the assessment measured on floor 2 equals the peak of the building's response to the
    same ground motion, computed here from the building's modes directly."""
    inventory, result = hospital
    from assess.site.suite import synthetic_suite  # noqa: F401  (the suite itself is tested elsewhere)
    modes = building_modes(2, 4.0, system="other", period_s=0.3, damping=0.05)
    motions = result.motions.drop_duplicates("motion").set_index("motion")
    ground_pga = result.ground_motions.set_index("motion")["pga_g"]
    for name, pga in ground_pga.items():
        assert motions.loc[name, "pta_g"] == pytest.approx(pga, rel=1e-6)
    # floor/ground PTA ratios as the modes give them, for a unit impulse-free check: rebuild one history
    from assess.assessment.motions import level_motions
    level = level_motions(inventory, "DE", lambda m: None, seed=3)
    first_key = level.table.loc[level.table["floor"] == 0, "record_path"].iloc[0]
    ground = level.records[first_key]
    roof = floor_records(modes, [ground], floors=[2])[2][0]
    name = level.table.loc[level.table["floor"] == 0, "motion"].iloc[0]
    assert motions.loc[f"{name} @ floor 2", "pta_g"] == pytest.approx(float(np.max(np.abs(roof.accel_g))), rel=1e-9)


@pytest.mark.parametrize("response, floors", [("elastic", [0, 2]), ("yielding", [0, 1, 2])])
def test_a_floor_with_its_own_rows_keeps_them(make_workbook, response, floors):
    """floors.csv: the ground and the building's floors with items (elastic), every floor with the storey
    below it (yielding, docs/outputs.md)."""
    hazard = [{"level": "DE", "motion": "engineer's floor 1", "floor": 1, "pta_g": 0.8, "tp_s": 0.5,
               "vp_cm_s": 30, "pulse": "B"}]
    path = make_workbook(_sheets(hazard=hazard, building=BUILDING + [["response", response]]), record=False)
    result = run_assessment(read_workbook(path), "DE", seed=3)
    floor_1 = set(result.motions.loc[result.motions["id"] == "M-1", "motion"])
    floor_2 = set(result.motions.loc[result.motions["id"] == "R-2", "motion"])
    assert floor_1 == {"engineer's floor 1"}
    assert all(name.endswith("@ floor 2") for name in floor_2) and len(floor_2) == 3
    assert list(result.floors["floor"]) == floors


def test_derive_floors_gives_way_to_the_building(make_workbook):
    path = make_workbook(_sheets(), record=False)
    result = run_assessment(read_workbook(path), "DE", seed=3, derive_floors_roof=2)
    assert not any("1 + 2z/h" in note for note in result.hazard_notes)
    assert any("--derive-floors gives way to the building sheet" in note for note in result.hazard_notes)


@pytest.mark.parametrize("level, words", [("2in50", "only an OpenQuake"), ("SLE", "SLE")])
def test_a_level_the_site_cannot_give_is_refused_on_the_site_sheet(make_workbook, level, words):
    path = make_workbook(_sheets(), record=False)
    with pytest.raises(InputError) as error:
        run_assessment(read_workbook(path), level)
    problem = error.value.problems[0]
    assert problem.sheet == "site" and words in problem.message, str(problem)


def test_without_a_building_an_upper_floor_still_needs_its_motions(make_workbook):
    sheets = _sheets()
    del sheets["building"]
    path = make_workbook(sheets, record=False)
    with pytest.raises(InputError) as error:
        run_assessment(read_workbook(path), "DE", seed=3)
    assert any(p.sheet == "equipment" and "has no motion for that floor" in p.message for p in error.value.problems)
