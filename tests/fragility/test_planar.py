"""Two horizontal components (record, record_2, azimuth_deg): items that cannot uplift slide in the
plane and their demand is the 2-D peak distance from rest; the others run each direction under its
component. And the workbook's refusals for the new columns (record_2, azimuth_deg, mu_low, mu_high)."""
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from assessed import run_assessment
from assess.inventory.settings import Settings
from assess.errors import InputError
from assess.inventory import Inventory
from assess.mechanics.sliding import sliding_response
from commands import location
from tests.hostile.test_hostile_workbooks import assert_refused, run, workbook
from workbooks import good_sheets

DT_S = 0.01


def component(amplitude_g, period_s, phase, seconds=8.0, dt_s=DT_S):
    """A windowed sine [g]: a smooth, non-trivial floor component."""
    t = np.arange(0.0, seconds, dt_s)
    return amplitude_g * np.sin(2 * np.pi * t / period_s + phase) * np.sin(np.pi * t / seconds) ** 2


def write_record(folder: Path, name: str, accel_g, dt_s=DT_S) -> Path:
    path = folder / name
    pd.DataFrame({"time_s": np.round(np.arange(len(accel_g)) * dt_s, 6), "accel_g": accel_g}).to_csv(path, index=False)
    return path


def items():
    base = {"room": "", "floor": 0, "mass_kg": 100.0, "anchored": False, "quantity": 1,
            "mu_low": np.nan, "mu_high": np.nan}
    return [
        # b/h = 0.5/0.5 = 1 > μs = 0.2: cannot uplift, slides in the plane
        {**base, "id": "SLIDER", "name": "stocky", "height_m": 1.0, "width_m": 1.0, "depth_m": 1.2, "mu": 0.2,
         "mu_static": 0.2, "clearance_m": 0.05, "cg_height_m": 0.5, "row": 2},
        # b/h = 0.3/1 = 0.3 < μs = 0.6: may uplift, each direction under its own component
        {**base, "id": "ROCKER", "name": "slender", "height_m": 2.0, "width_m": 0.6, "depth_m": 0.8, "mu": 0.6,
         "mu_static": 0.6, "clearance_m": 0.05, "cg_height_m": 1.0, "row": 3},
    ]


def pair_inventory(folder: Path, first, second, azimuth_deg=0.0, second_dt_s=DT_S, name="y.csv"):
    hazard = pd.DataFrame([{"level": "test", "level_label": "test", "motion": "pair", "all_floors": False,
                            "floor": 0, "pta_g": np.nan, "tp_s": np.nan, "vp_m_s": np.nan, "pulse": "",
                            "record_path": str(write_record(folder, "x.csv", first)), "scale": 1.0, "row": 2,
                            "record_2_path": str(write_record(folder, name, second, second_dt_s)),
                            "azimuth_deg": azimuth_deg}])
    hazard["floor"] = hazard["floor"].astype("Int64")
    return Inventory(path=folder / "test.xlsx", equipment=pd.DataFrame(items()), hazard=hazard,
                     settings=Settings())


def test_a_pair_along_one_line_gives_the_one_way_answer_under_the_resultant(tmp_path):
    """record_2 = 0.75 record: the floor moves along one line with 1.25 times record's amplitude, so the
    2-D peak equals the one-way exact kernel under 1.25 × record (check (b)), which is more than either
    one-way answer the tool gave before (each component alone)."""
    first = component(0.5, 0.9, 0.3)
    result = run_assessment(pair_inventory(tmp_path, first, 0.75 * first), "test")
    slider = result.summary.set_index("id").loc["SLIDER"]
    resultant_cm = sliding_response(1.25 * first, DT_S, 0.2).sliding_max_m * 100
    assert slider["demand_planar"] and slider["demand_median_cm"] == pytest.approx(resultant_cm, rel=1e-9)
    one_way_cm = [sliding_response(a, DT_S, 0.2).sliding_max_m * 100 for a in (first, 0.75 * first)]
    assert slider["demand_median_cm"] > 1.1 * max(one_way_cm)
    assert "slides in the plane" in slider["demand_note"]
    motions = result.motions.set_index(["id", "direction"])
    # the one-way runs stay in motions.csv: direction 1 under record, direction 2 under record_2
    assert motions.loc[("SLIDER", 1), "sim_sliding_max_cm"] == pytest.approx(one_way_cm[0], rel=1e-9)
    assert motions.loc[("SLIDER", 2), "sim_sliding_max_cm"] == pytest.approx(one_way_cm[1], rel=1e-9)
    assert motions.loc[("SLIDER", 1), "planar_sliding_cm"] == pytest.approx(resultant_cm, rel=1e-9)


def test_an_item_that_can_uplift_keeps_the_one_way_answers(tmp_path):
    first, second = component(0.7, 0.9, 0.3), component(0.6, 1.3, 1.1)
    result = run_assessment(pair_inventory(tmp_path, first, second), "test")
    rocker = result.summary.set_index("id").loc["ROCKER"]
    assert not rocker["demand_planar"] and "slides in the plane" not in rocker["demand_note"]
    assert np.isnan(result.motions.set_index("id").loc["ROCKER", "planar_sliding_cm"]).all()


def test_azimuth_turns_the_one_way_answers_but_not_the_distance_in_the_plane(tmp_path):
    """Isotropic friction: the 2-D peak does not depend on the pair's azimuth (to the substep's
    round-off); direction 1 runs under record cos θ − record_2 sin θ (θ = 30°)."""
    first, second = component(0.5, 0.9, 0.3), component(0.45, 1.3, 1.1)
    straight = run_assessment(pair_inventory(tmp_path, first, second), "test")
    turned = run_assessment(pair_inventory(tmp_path, first, second, azimuth_deg=30.0), "test")
    planar = [r.summary.set_index("id").loc["SLIDER", "demand_median_cm"] for r in (straight, turned)]
    assert planar[1] == pytest.approx(planar[0], rel=1e-6)
    theta = np.deg2rad(30.0)
    expected_cm = sliding_response(first * np.cos(theta) - second * np.sin(theta), DT_S, 0.2).sliding_max_m * 100
    motions = turned.motions.set_index(["id", "direction"])
    assert motions.loc[("SLIDER", 1), "sim_sliding_max_cm"] == pytest.approx(expected_cm, rel=1e-9)


def test_components_with_different_steps_are_refused_and_different_lengths_explained(tmp_path):
    first = component(0.5, 0.9, 0.3)
    with pytest.raises(InputError) as refused:
        run_assessment(pair_inventory(tmp_path, first, component(0.4, 1.3, 1.1, dt_s=0.02), second_dt_s=0.02,
                                      name="coarse.csv"), "test")
    problem = refused.value.problems[0]
    assert (problem.sheet, problem.row, problem.column) == ("hazard", 2, "record_2")
    assert "different time steps" in problem.message
    shorter = component(0.4, 1.3, 1.1, seconds=6.0)
    result = run_assessment(pair_inventory(tmp_path, first, shorter, name="short.csv"), "test")
    said = [note for note in result.hazard_notes if "short.csv ends 2.00 s before x.csv" in note]
    assert len(said) == 1 and said[0].startswith("Motion 'pair' (") and "taken as zero" in said[0]
    # several uneven pairs (a site's suite of recorded pairs may hold many): one note names each
    two = pair_inventory(tmp_path, first, shorter, name="short.csv")
    two.hazard.loc[1] = {**two.hazard.iloc[0].to_dict(), "motion": "other", "row": 3}
    two.hazard["floor"] = two.hazard["floor"].astype("Int64")
    notes = [n for n in run_assessment(two, "test").hazard_notes if "taken as zero" in n]
    assert len(notes) == 1 and notes[0].startswith("2 motions 'pair' (") and "'other' (short.csv" in notes[0]


# ----------------------------------------------------------------------------- the workbook's refusals
def equipment_with(**columns):
    sheets = good_sheets()
    for key, value in columns.items():
        sheets["equipment"][0][key] = value
    return sheets


@pytest.mark.parametrize("columns, cell, fragments", [
    # the new columns follow the good sheet's 15 (A-O): the first given is P, the second Q
    ({"mu_low": 0.2}, "P2", ["cell ", "column 'mu_low'", "without mu_high"]),
    ({"mu_high": 0.4}, "P2", ["column 'mu_high'", "without mu_low"]),
    ({"mu_low": 0.35, "mu_high": 0.5}, "P2", ["column 'mu_low'", "is above mu '0.3'"]),
    ({"mu_low": 0.2, "mu_high": 0.25}, "Q2", ["column 'mu_high'", "is below mu '0.3'"]),
    ({"mu_low": 0.2, "mu_high": 3.0}, "Q2", ["column 'mu_high'", "not plausible"]),
    ({"mu_low": "best fit", "mu_high": 0.4}, "P2", ["column 'mu_low'", "is not a number"]),
])
def test_bad_mu_range_is_refused_at_its_cell(tmp_path, columns, cell, fragments):
    path = workbook(tmp_path, equipment_with(**columns))
    assert_refused(run(path, "--hazard", "2in50", "--out", tmp_path / "out", cwd=tmp_path), path.name,
                   "sheet 'equipment'", *fragments, places=[location("inventory.xlsx", "equipment", cell)])
    assert not (tmp_path / "out").exists()


def hazard_with(**columns):
    sheets = good_sheets()
    for key, value in columns.items():
        sheets["hazard"][2][key] = value  # Excel row 4: the motion with a record
    return sheets


@pytest.mark.parametrize("columns, where, fragments", [
    ({"record": None, "pta_g": 0.5, "tp_s": 1.0, "record_2": "records/lg.csv"}, "L4",
     ["column 'record_2'", "record is empty"]),
    ({"azimuth_deg": 30}, "K4", ["column 'azimuth_deg'", "has no record_2"]),
    ({"record_2": "records/missing.csv"}, "K4", ["column 'record_2'", "was not found"]),
    ({"record_2": "records/lg.csv", "azimuth_deg": 400}, "L4", ["column 'azimuth_deg'", "not plausible"]),
    ({"record_2": "../outside.csv"}, 4, ["column 'record_2'", "outside the workbook's folder"]),
])
def test_bad_second_component_is_refused_at_its_cell(tmp_path, columns, where, fragments):
    folder = tmp_path / "site"
    folder.mkdir()
    (tmp_path / "outside.csv").write_text("time_s,accel_g\n0,0\n0.01,0.1\n")
    path = workbook(folder, hazard_with(**columns))
    completed = run(path, "--hazard", "10in50", "--out", folder / "out", cwd=folder)
    assert_refused(completed, path.name, "sheet 'hazard'", "row 4" if "outside" in fragments[-1] else "4",
                   *fragments, places=[location("inventory.xlsx", "hazard", where)])
    assert not (folder / "out").exists()


def test_a_pair_in_a_workbook_runs_end_to_end(tmp_path):
    """record and record_2 (the same file: a motion along the diagonal) with scale 1.2 on both: exit 0,
    and summary.csv says which items' demand is the 2-D one."""
    path = workbook(tmp_path, hazard_with(record_2="records/lg.csv"))
    completed = run(path, "--hazard", "10in50", "--format", "xlsx", "--out", tmp_path / "out", cwd=tmp_path)
    assert completed.returncode == 0, completed.stderr[-2000:]
    summary = pd.read_csv(tmp_path / "out" / "summary.csv")
    assert "demand_planar" in summary and "planar_sliding_cm" in pd.read_csv(tmp_path / "out" / "motions.csv")


def test_an_item_with_a_mu_range_slides_in_the_plane_at_each_mu_value(tmp_path):
    """The 2-D peaks at each μ value of SLIDER's range (0.15-0.25), pair along one line: the one-way
    exact kernel under the resultant at that μ."""
    first = component(0.5, 0.9, 0.3)
    inventory = pair_inventory(tmp_path, first, 0.75 * first)
    equipment = inventory.equipment.copy()
    equipment.loc[equipment["id"] == "SLIDER", ["mu_low", "mu_high"]] = [0.15, 0.25]
    result = run_assessment(Inventory(path=inventory.path, equipment=equipment, hazard=inventory.hazard,
                                      settings=inventory.settings), "test")
    runs = result.suite_runs[result.suite_runs["id"] == "SLIDER"]
    assert runs["planar"].all() and runs["mu"].nunique() == 9
    for history in runs.itertuples():
        expected_cm = sliding_response(1.25 * first, DT_S, history.mu).sliding_max_m * 100
        assert history.sliding_cm == pytest.approx(expected_cm, rel=1e-9), history.mu


def test_a_second_component_that_is_not_a_record_is_refused_naming_record_2(tmp_path):
    path = workbook(tmp_path, hazard_with(record_2="records/bad.csv"))
    (tmp_path / "records" / "bad.csv").write_text("time_s,accel_g\n0,0\n0.01,nan\n0.02,0\n")
    completed = run(path, "--hazard", "10in50", "--out", tmp_path / "out", cwd=tmp_path)
    assert_refused(completed, "bad.csv", "record_2:", "row 4",
                   places=["bad.csv, row 3: record_2: the record of motion 'Los Gatos record' "
                           "(inventory.xlsx, sheet 'hazard', row 4)"])
    assert not (tmp_path / "out").exists()
