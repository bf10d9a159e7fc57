"""The assessment pipeline on hand-built inventories (no workbook reader involved)."""
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from assessed import run_assessment
from assess.assessment.result import MOTION_COLUMNS, SUMMARY_COLUMNS
from assess.command.output import csv_text
from assess.data import km2010_table3
from assess.inventory.settings import Settings
from assess.errors import InputError
from assess.inventory import Inventory


def item(item_id, floor=0, height_cm=228.6, width_cm=62.2, depth_cm=80.0, mu=0.13, mu_static=None,
         clearance_cm=30.0, cg_height_cm=None, anchored=False, row=2):
    return {"id": item_id, "name": f"item {item_id}", "room": "R1", "floor": floor,
            "height_m": height_cm / 100, "width_m": width_cm / 100, "depth_m": depth_cm / 100,
            "mass_kg": 200.0, "mu": mu, "mu_static": mu if mu_static is None else mu_static,
            "clearance_m": clearance_cm / 100,
            "cg_height_m": (height_cm / 2 if cg_height_cm is None else cg_height_cm) / 100,
            "anchored": anchored, "quantity": 1, "row": row}


def motion(name, pta_g, tp_s, floor=0, vp_cm_s=-75.0, level="2in50", row=2):
    return {"level": level, "level_label": level, "motion": name, "all_floors": floor is None,
            "floor": floor, "pta_g": pta_g, "tp_s": tp_s, "vp_m_s": vp_cm_s / 100, "pulse": "B",
            "record_path": "", "scale": 1.0, "row": row}


def inventory(items, motions, **settings):
    hazard = pd.DataFrame(motions)
    hazard["floor"] = hazard["floor"].astype("Int64")
    return Inventory(path=Path("test.xlsx"), equipment=pd.DataFrame(items), hazard=hazard,
                     settings=Settings(**settings))


TABLE3_GROUND = [motion("Los Gatos 0.54", 0.54, 2.10), motion("Corralitos 0.84", 0.84, 0.60, vp_cm_s=-61),
                 motion("Gilroy 0.59", 0.59, 1.50, vp_cm_s=-84)]


def test_paper_prototypes_reproduce_table3_im_and_slide():
    items = [item("FORMA", mu=0.13), item("KELVINATOR", height_cm=213.4, width_cm=66.0, mu=0.17),
             item("ASP", height_cm=180.3, width_cm=58.4, mu=0.20)]
    result = run_assessment(inventory(items, TABLE3_GROUND, simulate_motions="pulse"), "2in50")
    motions = result.motions.set_index(["id", "motion", "direction"])
    table3 = km2010_table3()
    for equipment, pta, tp in [("FORMA", 0.54, 2.10), ("KELVINATOR", 0.84, 0.60), ("ASP", 0.59, 1.50)]:
        printed = table3[(table3.equipment == equipment) & (table3.pta_g == pta)].iloc[0]
        name = {0.54: "Los Gatos 0.54", 0.84: "Corralitos 0.84", 0.59: "Gilroy 0.59"}[pta]
        row = motions.loc[(equipment, name, 1)]
        assert abs(row["im"] - printed.im) <= 0.005 / printed.mu_best_fit + 0.005
        assert row["mode"] == "slide"
        # median of the regression at that IM, converted with the motion's PTA and Tp
        expected_cm = 0.370 * row["im"] ** 0.953 * pta * 9.80665 / (2 * np.pi / tp) ** 2 * 100
        assert row["sliding_median_cm"] == pytest.approx(expected_cm, rel=1e-9)
    assert set(result.summary["mode"]) == {"slide"}
    assert result.simulated and (result.summary["overturn_fraction"] == 0.0).all()
    assert (result.summary["theta_max_over_alpha"] == 0.0).all()
    # the simulation of each case is the exact sliding kernel under the motion's Type-B pulse
    from assess.hazard.records import pulse_record
    from assess.mechanics.sliding import sliding_response
    los_gatos = pulse_record("B", 0.54, 2.10)
    direct = sliding_response(los_gatos.accel_g, los_gatos.dt_s, 0.13)
    row = motions.loc[("FORMA", "Los Gatos 0.54", 1)]
    assert row["sim_sliding_max_cm"] == pytest.approx(direct.sliding_max_m * 100, rel=1e-12)
    assert row["sim_solver"] == "sliding kernel" and not row["sim_overturned"]


def test_columns_and_row_counts():
    items = [item("A"), item("B", anchored=True)]
    result = run_assessment(inventory(items, TABLE3_GROUND), "2in50")
    assert list(result.summary.columns) == SUMMARY_COLUMNS
    assert list(result.motions.columns) == MOTION_COLUMNS
    assert len(result.summary) == 2
    assert len(result.motions) == 1 * 3 * 2  # freestanding items x motions x directions
    anchored = result.summary.set_index("id").loc["B"]
    assert anchored["risk"] == "anchored" and np.isnan(anchored["pf_sliding"])


def test_rocking_item_is_high_risk_with_uplift_flag_and_no_regression_demand():
    # tall narrow rack, rubber feet: mu = 0.6 > b/h = 0.2, PTA 0.84 g > 0.2 g
    rack = item("RACK", height_cm=200, width_cm=40, depth_cm=60, mu=0.6)
    result = run_assessment(inventory([rack], TABLE3_GROUND), "2in50")
    row = result.summary.iloc[0]
    assert row["mode"] in ("rock", "slide-rock") and row["risk"] == "high"
    assert "uplift" in row["flags"]
    assert any(flag.code == "uplift" and flag.item_id == "RACK" for flag in result.flags)
    assert row["action"].startswith("Anchor")


def test_stocky_high_friction_item_stays_at_rest():
    safe = item("BOX", height_cm=60, width_cm=80, depth_cm=80, mu=0.9)  # b/h = 1.33, A < mu
    row = run_assessment(inventory([safe], TABLE3_GROUND), "2in50").summary.iloc[0]
    assert row["mode"] == "rest" and row["pf_sliding"] == 0 and row["sliding_median_cm"] == 0
    assert row["risk"] == "low"


def test_risk_classes_follow_pf_thresholds():
    items = [item("TIGHT", clearance_cm=1.0), item("ROOMY", clearance_cm=2000.0)]
    summary = run_assessment(inventory(items, TABLE3_GROUND), "2in50").summary.set_index("id")
    assert summary.loc["TIGHT", "pf_sliding"] > 0.99 and summary.loc["TIGHT", "risk"] == "high"
    assert summary.loc["ROOMY", "pf_sliding"] < 0.01 and summary.loc["ROOMY", "risk"] == "low"
    # the governing motion is the one with the largest median sliding
    motions = run_assessment(inventory(items, TABLE3_GROUND), "2in50").motions
    tight = motions[(motions.id == "TIGHT") & (motions.direction == 1)]
    assert summary.loc["TIGHT", "governing_motion"] == tight.loc[tight.sliding_median_cm.idxmax(), "motion"]


def test_im_outside_fitted_range_is_flagged():
    items = [item("LOWIM", mu=0.45, width_cm=150, depth_cm=150, height_cm=100)]  # IM = 0.54/0.45-1 = 0.2
    result = run_assessment(inventory(items, [motion("LG", 0.54, 2.1)]), "2in50")
    assert "im_outside_fit" in result.summary.iloc[0]["flags"]
    assert "outside the range 1.71-6.40" in result.flags[0].message


def test_level_spellings_and_missing_level_lists_the_levels():
    inv = inventory([item("A")], TABLE3_GROUND + [motion("x", 0.3, 1.0, level="10in50")])
    assert run_assessment(inv, "2475yr").level_label == "2in50"
    assert run_assessment(inv, "2%/50yr").level.name == "2in50"
    with pytest.raises(InputError) as caught:
        run_assessment(inv, "50in50")
    message = str(caught.value)
    assert "'2in50'" in message and "'10in50'" in message and "sheet 'hazard'" in message


def test_floor_without_motion_names_the_item_row():
    inv = inventory([item("A", floor=3, row=7)], TABLE3_GROUND)
    with pytest.raises(InputError) as caught:
        run_assessment(inv, "2in50")
    problem = caught.value.problems[0]
    assert (problem.sheet, problem.row, problem.column) == ("equipment", 7, "floor")
    assert "floor 3" in problem.message and "has floors [0]" in problem.message


def test_all_floors_motion_reaches_every_floor():
    inv = inventory([item("A", floor=3), item("B", floor=0)], [motion("everywhere", 0.5, 1.0, floor=None)])
    result = run_assessment(inv, "2in50")
    assert len(result.motions) == 4


def test_custom_regression_constants_are_used_and_reported():
    inv = inventory([item("A")], TABLE3_GROUND, zeta=0.5, eta=1.0, sigma=0.3)
    result = run_assessment(inv, "2in50")
    row = result.motions.iloc[0]
    assert row["edp_median"] == pytest.approx(0.5 * row["im"])
    assert result.regression.source == "the workbook's settings sheet"


def test_same_input_gives_identical_csv():
    inv = inventory([item("A"), item("RACK", height_cm=200, width_cm=40, mu=0.6)], TABLE3_GROUND)
    first, second = run_assessment(inv, "2in50", seed=1), run_assessment(inv, "2in50", seed=1)
    assert csv_text(first.summary) == csv_text(second.summary)
    assert csv_text(first.motions) == csv_text(second.motions)


def test_simulation_fills_overturning_and_the_report_shows_histories():
    """A slender rack on rubber feet overturns under the 0.84 g Corralitos pulse; the report says so."""
    from assess.report import render_html

    rack = item("RACK", height_cm=200, width_cm=40, depth_cm=60, mu=0.6)
    fridge = item("FRIDGE", row=3)
    result = run_assessment(inventory([rack, fridge], TABLE3_GROUND), "2in50")
    summary = result.summary.set_index("id")
    motions = result.motions.set_index(["id", "motion", "direction"]).sort_index()
    per_motion = motions.loc["RACK"].groupby(level="motion")["sim_overturned"].any()
    assert summary.loc["RACK", "overturn_fraction"] == pytest.approx(per_motion.mean())
    assert summary.loc["RACK", "overturn_fraction"] > 0 and summary.loc["RACK", "action"].startswith("Anchor")
    assert summary.loc["RACK", "theta_max_over_alpha"] == motions.loc["RACK", "sim_theta_max_over_alpha"].max()
    assert summary.loc["FRIDGE", "overturn_fraction"] == 0.0
    assert [h["id"] for h in result.histories] == ["RACK", "FRIDGE"]  # overturned first
    rack_history = result.histories[0]
    assert np.nanmax(np.abs(rack_history["theta_over_alpha"])) >= 1.0
    html = render_html(result)
    assert 'id="simulation"' in html and html.count("as Fig. 7 of the paper") == 2
    assert "Regression and simulation side by side" in html


def test_derived_floor_motions_are_amplified_and_flagged():
    """--derive-floors: floor 3 of 6 takes the ground motions x (1 + 2*3/6) = 2 (ASCE 7-16 eq. 13.3-1)."""
    inv = inventory([item("UP", floor=3, row=7), item("DOWN", row=8)], TABLE3_GROUND)
    result = run_assessment(inv, "2in50", derive_floors_roof=6)
    up = result.motions[result.motions["id"] == "UP"].drop_duplicates("motion")
    ground = {m["name"]: m["pta_g"] for m in [{"name": r["motion"], "pta_g": r["pta_g"]} for r in TABLE3_GROUND]}
    for row in up.itertuples():
        source = row.motion.split(" -> ")[0]
        assert row.pta_g == pytest.approx(2.0 * ground[source], rel=1e-12)
        assert "derived" in row.motion
    assert len(up) == len(TABLE3_GROUND)
    assert any(f.code == "derived_floor_motion" and f.item_id == "UP" for f in result.flags)
    assert not any(f.code == "derived_floor_motion" and f.item_id == "DOWN" for f in result.flags)
    assert any("ASCE 7-16" in note for note in result.hazard_notes)
    with pytest.raises(InputError) as caught:  # without the option it stays an error
        run_assessment(inv, "2in50")
    assert "--derive-floors" in caught.value.problems[0].fix


def test_synthetic_motions_are_simulated_by_default_and_summarised_over_realisations():
    """PTA, Tp and vp only: each case runs under the level's synthetic histories (seeded);
    the case reports the median over them, and the same seed gives the same numbers."""
    from assess.hazard.synthesis import synthesize_motion
    from assess.mechanics.block import Block
    from assess.mechanics.engine import simulate

    items = [item("FORMA", mu=0.13)]
    result = run_assessment(inventory(items, TABLE3_GROUND[:1], synthetic_realizations=3), "2in50", seed=7)
    row = result.motions[result.motions["direction"] == 1].iloc[0]
    assert row["sim_realizations"] == 3 and "3 synthetic histories" in row["sim_motion"]
    records = synthesize_motion(0.54, 2.10, -0.75, n_realizations=3, seed=np.random.default_rng([7, 0]))
    block = Block(half_width_m=0.311, cg_height_m=1.143, height_m=2.286, mu=0.13)
    peaks = [simulate(block, r.accel_g, r.dt_s).sliding_max_m * 100 for r in records]
    assert row["sim_sliding_max_cm"] == pytest.approx(np.median(peaks), rel=1e-12)
    again = run_assessment(inventory(items, TABLE3_GROUND[:1], synthetic_realizations=3), "2in50", seed=7)
    assert again.motions["sim_sliding_max_cm"].equals(result.motions["sim_sliding_max_cm"])
    other = run_assessment(inventory(items, TABLE3_GROUND[:1], synthetic_realizations=3), "2in50", seed=8)
    assert not other.motions["sim_sliding_max_cm"].equals(result.motions["sim_sliding_max_cm"])


def test_record_without_pulse_numbers_is_measured_and_simulated(tmp_path):
    """A hazard row with only a record: PTA from its peak, Tp and vp from a Type-B pulse fitted
    to its velocity (here a 1.5 s Type-B pulse of 0.4 g inside 12 s of record), then simulated under it."""
    from assess.hazard.pulses import pulse_acceleration

    time_s = np.arange(0.0, 12.0, 0.005)
    accel = pulse_acceleration("B", 0.4, 1.5, time_s - 3.0)
    path = tmp_path / "floor.csv"
    pd.DataFrame({"time_s": time_s, "accel_g": accel}).to_csv(path, index=False)
    row = {**motion("recorded", np.nan, np.nan, vp_cm_s=np.nan), "record_path": str(path), "pulse": ""}
    result = run_assessment(inventory([item("FORMA", mu=0.13)], [row]), "2in50", allow_records_outside=True)
    case = result.motions.iloc[0]
    assert case["pta_g"] == pytest.approx(0.4, rel=1e-9)
    assert case["tp_s"] == pytest.approx(1.5, rel=0.05)
    assert case["vp_cm_s"] == pytest.approx(0.4 * 9.80665 / (2 * np.pi / 1.5) * 100, rel=0.10)  # vp = ap/wp
    assert "measured from the record" in case["pulse_source"] and "a clear pulse" in case["pulse_source"]
    assert case["sim_motion"].startswith("record floor.csv") and case["sim_realizations"] == 1
    assert any("recorded" in note for note in result.hazard_notes)
