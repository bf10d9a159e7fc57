"""A calibration's ``input_scale`` s with a building sheet: every item's floor shakes s times what it would.

``input_scale`` says the floor shook s times what the record says. On a building's floors the record is the
floor's history, which a yielding building gives from the ground motion; a yielding storey keeps the floors from
scaling with the ground, so the ground motion times s through the building is not the floor times s (on the
5-storey wall clinic of a new user, s 1.4 raised the roof's PTA 1.22 times before this was put right). Here the
calibrated run's floor motions are checked against the declared run's times s, and the building's own response
(``floors.csv``) against the declared run's: the building takes the earthquake as the workbook gives it.
"""
from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest

from assess.assessment.pipeline import run_assessment
from assess.calibration.apply import read_calibration
from assess.inventory import read_workbook

from workbooks import write_workbook

S = 1.4
ITEMS = [("GROUND", 0), ("ROOF", 3)]


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    folder = tmp_path_factory.mktemp("clinic")
    equipment = [{"id": i, "name": "incubator", "floor": f, "height_m": 1.8, "width_m": 0.7, "depth_m": 0.8,
                  "mass_kg": 250, "mu": 0.3, "clearance_m": 0.1} for i, f in ITEMS]
    site = [["key", "value"], ["sds_g", 1.0], ["sd1_g", 0.6], ["risk_category", "II"], ["suite_size", 3]]
    building = [["key", "value"], ["storeys", 3], ["storey_height_m", 4.0], ["system", "steel moment frame"],
                ["response", "yielding"], ["yield_base_shear_g", 0.15]]
    path = write_workbook(folder / "clinic.xlsx", {"equipment": equipment, "site": site, "building": building})
    calibration = folder / "calibration.json"
    calibration.write_text(json.dumps({"selected": {"effect": "input_scale", "parameters": {"s": S}},
                                       "applies_to": "all"}))
    declared = run_assessment(read_workbook(path), "DE", seed=0)
    calibrated = run_assessment(read_workbook(path), "DE", seed=0, calibration=read_calibration(calibration))
    return declared, calibrated


def _pta(result):
    motions = result.motions.drop_duplicates("motion").set_index("motion")
    return motions["pta_g"].astype(float), motions["floor"]


def test_every_floor_shakes_s_times_what_it_would(runs):
    (declared, floor), (calibrated, _) = (_pta(result) for result in runs)
    assert set(floor) == {0, 3} and len(declared) == 6
    np.testing.assert_allclose(calibrated.loc[declared.index] / declared, S, rtol=1e-9)


def test_the_building_takes_the_earthquake_as_the_workbook_gives_it(runs):
    declared, calibrated = runs
    assert declared.floors["ductility_max"].max() > 1.5  # it yields: the ground times s would not scale its floors
    pd.testing.assert_frame_equal(declared.floors, calibrated.floors, rtol=1e-9)  # to the round-off of 1/s × s
    assert any("floors' motions are multiplied by 1.4" in note for note in calibrated.hazard_notes)
