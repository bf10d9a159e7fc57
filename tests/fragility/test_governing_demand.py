"""The governing demand: an item's demand over its floor's suite, from the model that holds there.

Expected values come from outside the pipeline: the exact sliding kernel
under each record (its exactness is tested in test_sliding.py against
Newmark's closed form and pyslammer), the independent Housner ODE of
tests/rocking_reference.py for overturning, numpy's Hazen quantiles, scipy's
exact binomial interval, and the sliding under pyslammer's real records for
the regression's domain.
"""
import dataclasses
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from scipy import stats

from assessed import run_assessment
from assess.inventory.settings import Settings
from assess.fragility.governing import governing_demand
from assess.fragility.suite import (
    PULSE_SHARE_MIN, binomial_interval, effective_count, pulse_acceleration_share, regression_applies,
    weighted_quantile,
)
from assess.inventory import Inventory
from assess.mechanics.sliding import sliding_response
from rocking_reference import reference_rocking

DT_S = 0.005


def _item(item_id, height_cm, width_cm, depth_cm, mu, clearance_cm):
    return {"id": item_id, "name": f"item {item_id}", "room": "R1", "floor": 0, "height_m": height_cm / 100,
            "width_m": width_cm / 100, "depth_m": depth_cm / 100, "mass_kg": 200.0, "mu": mu, "mu_static": mu,
            "clearance_m": clearance_cm / 100, "cg_height_m": height_cm / 200, "anchored": False, "quantity": 1,
            "row": 2}


def _sine_record(folder: Path, name: str, ap_g: float, tp_s: float) -> tuple[Path, np.ndarray]:
    """A one-sine (Type-A) acceleration pulse, at rest before and after, as a CSV record file."""
    time_s = np.arange(0.0, tp_s + DT_S / 2, DT_S)
    accel = np.concatenate([ap_g * np.sin(2 * np.pi * time_s / tp_s), np.zeros(int(3.0 / DT_S))])
    path = folder / f"{name}.csv"
    pd.DataFrame({"time_s": np.arange(accel.size) * DT_S, "accel_g": accel}).to_csv(path, index=False)
    return path, accel


def _record_motion(name, path, row):
    return {"level": "2in50", "level_label": "2in50", "motion": name, "all_floors": False, "floor": 0,
            "pta_g": np.nan, "tp_s": 1.0, "vp_m_s": 0.5, "pulse": "", "record_path": str(path), "scale": 1.0,
            "row": row}


def _inventory(folder, items, motions):
    hazard = pd.DataFrame(motions)
    hazard["floor"] = hazard["floor"].astype("Int64")
    return Inventory(path=folder / "suite.xlsx", equipment=pd.DataFrame(items), hazard=hazard,
                     settings=Settings())


@pytest.fixture(scope="module")
def sliding_suite(tmp_path_factory):
    """Four records on floor 0 and an item that can only slide (μ = 0.13 < b/h)."""
    folder = tmp_path_factory.mktemp("suite")
    specs = [("S1", 0.30, 1.0), ("S2", 0.45, 1.0), ("S3", 0.60, 1.2), ("S4", 0.80, 0.8)]
    records = [_sine_record(folder, *spec) for spec in specs]
    motions = [_record_motion(name, path, k + 2) for k, ((name, _, _), (path, _)) in enumerate(zip(specs, records))]
    item = _item("FORMA", 228.6, 62.2, 80.0, 0.13, clearance_cm=40.0)
    result = run_assessment(_inventory(folder, [item], motions), "2in50")
    peaks_cm = np.array([sliding_response(accel, DT_S, 0.13).sliding_max_m * 100 for _, accel in records])
    return result, peaks_cm


def test_records_suite_gives_the_suite_statistics_of_the_exact_sliding(sliding_suite):
    result, peaks_cm = sliding_suite
    row = result.summary.set_index("id").loc["FORMA"]
    assert row["demand_source"] == ("records",)
    assert row["suite_motions"] == 4 and row["suite_histories"] == 4
    assert row["demand_median_cm"] == pytest.approx(np.quantile(peaks_cm, 0.5, method="hazen"), rel=1e-9)
    assert row["demand_p84_cm"] == pytest.approx(np.quantile(peaks_cm, 0.84, method="hazen"), rel=1e-9)
    beyond = int(np.sum(peaks_cm > 40.0))
    assert 0 < beyond < 4, peaks_cm  # the test means something only if the suite straddles the clearance
    assert row["p_beyond_clearance"] == pytest.approx(beyond / 4)
    interval = stats.binomtest(beyond, 4).proportion_ci(confidence_level=0.90, method="exact")
    assert row["p_beyond_clearance_low"] == pytest.approx(interval.low, rel=1e-9)
    assert row["p_beyond_clearance_high"] == pytest.approx(interval.high, rel=1e-9)
    assert row["p_overturn"] == 0.0


def test_the_class_and_the_action_follow_the_governing_demand_and_say_its_interval(sliding_suite):
    result, peaks_cm = sliding_suite
    row = result.summary.set_index("id").loc["FORMA"]
    p = row["p_beyond_clearance"]
    expected = "high" if p >= 0.5 else "moderate" if p >= 0.1 else "low"
    assert row["risk"] == expected
    assert row["risk_range"] == "low to high"  # 4 motions cannot tell the classes apart
    room_cm = np.quantile(peaks_cm, 0.9, method="hazen")
    assert f"needs {np.ceil(room_cm):.0f} cm" in row["action"] and "has 40 cm" in row["action"]


def test_overturn_share_over_a_suite_matches_an_independent_rocking_solution(tmp_path):
    """A slender rack (b/h = 0.2, μ = 0.9: it rocks) under four pulses; the share that overturn it."""
    specs = [("R1", 0.15, 1.0), ("R2", 0.30, 0.5), ("R3", 0.30, 1.0), ("R4", 0.50, 0.5)]
    records = [_sine_record(tmp_path, *spec) for spec in specs]
    motions = [_record_motion(name, path, k + 2) for k, ((name, _, _), (path, _)) in enumerate(zip(specs, records))]
    rack = _item("RACK", 200.0, 40.0, 200.0, 0.9, clearance_cm=20.0)
    result = run_assessment(_inventory(tmp_path, [rack], motions), "2in50")
    alpha = np.arctan(0.2)
    p = np.sqrt(3 * 9.80665 / (4 * np.hypot(0.2, 1.0)))
    e = 1 - 1.5 * np.sin(alpha) ** 2
    overturned = [reference_rocking(np.concatenate([accel, np.zeros(int(10 / DT_S))]), DT_S, alpha, p, e)["overturned"]
                  for _, accel in records]
    assert 0 < sum(overturned) < 4, overturned
    row = result.summary.set_index("id").loc["RACK"]
    assert row["p_overturn"] == pytest.approx(np.mean(overturned))
    assert row["overturn_fraction"] == row["p_overturn"]
    assert row["risk"] == "high" and row["action"].startswith(
        f"Anchor it to the floor or wall: it overturns under {sum(overturned)} of its 4")
    interval = stats.binomtest(sum(overturned), 4).proportion_ci(confidence_level=0.90, method="exact")
    assert (row["p_overturn_low"], row["p_overturn_high"]) == pytest.approx((interval.low, interval.high))


@pytest.mark.parametrize("successes, count", [(0, 3), (1, 3), (3, 3), (7, 20), (0, 50)])
def test_binomial_interval_is_scipys_exact_interval(successes, count):
    expected = stats.binomtest(successes, count).proportion_ci(confidence_level=0.90, method="exact")
    assert binomial_interval(successes / count, count) == pytest.approx((expected.low, expected.high), abs=1e-12)


def test_weighted_quantile_with_equal_weights_is_hazens_and_weights_count():
    values = np.array([3.0, 1.0, 7.0, 2.0, 5.0])
    for q in (0.1, 0.5, 0.84, 0.95):
        assert weighted_quantile(values, np.ones(5), q) == pytest.approx(np.quantile(values, q, method="hazen"))
    # one motion of two with three histories: each history weighs 1/6, the record 1/2
    assert weighted_quantile([1.0, 1.0, 1.0, 10.0], [1 / 6, 1 / 6, 1 / 6, 1 / 2], 0.8) == pytest.approx(10.0)
    assert effective_count([1 / 6, 1 / 6, 1 / 6, 1 / 2]) == pytest.approx(1 / (3 / 36 + 1 / 4))


def test_a_regression_governed_suite_has_the_regressions_median_and_p84():
    """One motion in the regression's domain: the suite's quantiles are the lognormal's."""
    cases = pd.DataFrame({"id": ["A", "A"], "motion_key": [0, 0], "motion": ["LG"] * 2, "direction": [1, 2],
                          "demand_source": ["regression"] * 2, "pta_g": [0.54] * 2, "tp_s": [2.1] * 2,
                          "im": [0.54 / 0.13 - 1] * 2, "mode": ["slide"] * 2, "clearance_m": [0.5] * 2,
                          "pulse_share": [0.42] * 2, "sim_uplift": [False] * 2, "mu_static": [0.13] * 2,
                          "b_over_h": [0.39, 0.5]})
    runs = pd.DataFrame({"case": [0, 1], "realization": [0, 0], "sliding_max_cm": [50.0, 50.0],
                         "overturned": [False, False], "theta_max_over_alpha": [0.0, 0.0]})
    from assess.fragility import RegressionConstants

    constants = RegressionConstants.from_settings(Settings())
    row = governing_demand(cases, runs, constants).loc["A"]
    omega = 2 * np.pi / 2.1
    median_cm = 0.370 * (0.54 / 0.13 - 1) ** 0.953 * 0.54 * 9.80665 / omega ** 2 * 100  # eq. 21
    assert row["demand_median_cm"] == pytest.approx(median_cm, rel=1e-9)
    assert row["demand_p84_cm"] == pytest.approx(median_cm * np.exp(0.445 * stats.norm.ppf(0.84)), rel=2e-3)
    expected_pf = stats.lognorm.sf(50.0, 0.445, scale=median_cm)
    assert row["p_beyond_clearance"] == pytest.approx(expected_pf, rel=1e-6)
    assert row["p_beyond_clearance_low"] == row["p_beyond_clearance_high"] == row["p_beyond_clearance"]


def test_regression_domain_holds_for_pulse_like_records_and_not_for_records_without_a_pulse():
    """pyslammer's records at PGA 0.7 g, μ = 0.1 (IM 6, inside the fit): where the identified pulse
    carries ≥ PULSE_SHARE_MIN of PTA the sliding under the record itself lies inside the regression's own
    95 % band (median × e^(±1.96σ), a factor 2.39); where it does not, the regression overshoots by more
    than a factor 4 (measured: predicted/actual 0.59-2.02 and 61-209)."""
    pyslammer = pytest.importorskip("pyslammer")
    from assess.inventory.settings import Settings as defaults
    from assess.fragility import RegressionConstants, intensity_measure, sliding_quantile
    from assess.hazard.pulse_identification import identify_pulse

    constants = RegressionConstants.from_settings(defaults())
    records = pyslammer.sample_ground_motions()
    pulse_like = ["Kobe_1995_TAK-090", "Loma_Prieta_1989_HSP-000", "Northridge_1994_PAC-175"]
    no_pulse = ["Duzce_1999_375-090", "Landers_1992_LCN-345", "Nahanni_1985_NS1-280"]
    for name in pulse_like + no_pulse:
        accel = np.asarray(records[name].accel, dtype=float)
        accel = accel * 0.7 / np.max(np.abs(accel))
        dt_s = float(records[name].dt)
        fit = identify_pulse(accel, dt_s, models=("B",))
        share = float(pulse_acceleration_share(0.7, fit.tp_s, fit.vp_m_s))
        im = float(intensity_measure(0.7, 0.1))
        predicted = float(sliding_quantile(im, 0.7, fit.tp_s, constants))
        actual = sliding_response(accel, dt_s, 0.1).sliding_max_m
        inside = bool(regression_applies(share, im, constants.im_min, constants.im_max, False))
        if name in pulse_like:
            band = np.exp(1.96 * constants.sigma)
            assert inside and 1 / band < predicted / actual < band, (name, share, predicted / actual)
        else:
            assert not inside and predicted / actual > 4.0, (name, share, predicted / actual)


def test_the_domain_is_the_pulse_share_of_the_papers_own_motions():
    """PULSE_SHARE_MIN is read off Table 3 (not off the records it is checked on): its smallest share."""
    from assess.data import km2010_table3

    table = km2010_table3()
    shares = pulse_acceleration_share(table["pta_g"], table["tp_s"], table["vp_cm_s"] / 100)
    assert round(float(shares.min()), 2) == PULSE_SHARE_MIN  # Los Gatos at 0.60 g; Corralitos 0.78 at most
    assert float(shares.max()) == pytest.approx(0.785, abs=0.001)


def test_a_motion_named_on_two_floors_is_two_motions(tmp_path):
    """M1 at 0.3 g on floor 0 and M1 at 1.5 g on floor 1: each floor's item is simulated under its own row
    (found by an independent check: the floor-0 item used to be simulated under the 1.5 g motion)."""
    from assess.hazard.records import pulse_record

    items = [_item("LOW", 228.6, 62.2, 80.0, 0.13, 30.0), {**_item("HIGH", 228.6, 62.2, 80.0, 0.13, 30.0), "floor": 1}]
    rows = [{"level": "2in50", "level_label": "2in50", "motion": "M1", "all_floors": False, "floor": floor,
             "pta_g": pta, "tp_s": 1.0, "vp_m_s": np.nan, "pulse": "B", "record_path": "", "scale": 1.0, "row": row}
            for floor, pta, row in ((0, 0.3, 2), (1, 1.5, 3))]
    result = run_assessment(_inventory(tmp_path, items, rows), "2in50")
    for item_id, pta in (("LOW", 0.3), ("HIGH", 1.5)):
        case = result.motions[(result.motions["id"] == item_id) & (result.motions["direction"] == 1)].iloc[0]
        pulse = pulse_record("B", pta, 1.0)
        assert case["pta_g"] == pta
        assert case["sim_sliding_max_cm"] == pytest.approx(
            sliding_response(pulse.accel_g, pulse.dt_s, 0.13).sliding_max_m * 100, rel=1e-12)


def test_the_report_shows_the_governing_numbers_of_the_summary(sliding_suite):
    """Page 1 and the all-items table show the summary's governing demand, its interval and its source."""
    from assess.report import render_html
    from assess.report.render import format_cm, format_percent

    result, _ = sliding_suite
    row = result.summary.set_index("id").loc["FORMA"]
    html = render_html(result)
    page1 = html.split('<section id="all-items"')[0]
    assert f"{format_cm(row['demand_median_cm'])} · {format_cm(row['demand_p84_cm'])}" in page1
    assert format_percent(row["p_beyond_clearance"]) in page1
    interval = f"{format_percent(row['p_beyond_clearance_low'])}–{format_percent(row['p_beyond_clearance_high'])}"
    assert interval in page1 and "from records" in page1
    all_items = html.split('<section id="all-items"')[1].split("</section>")[0]
    assert f"{format_cm(row['demand_median_cm'])} / {format_cm(row['demand_p84_cm'])}" in all_items
    assert "4 motions" in all_items and row["action"] in html.replace("&#39;", "'")


def test_quantile_interval_covers_the_true_quantile_as_often_as_it_says():
    """Draws from a known lognormal (400 seeded suites each of 5 and of 30 motions): the 90 % interval of the
    median and of the 84th percentile contains the true value in at least 88 % of the suites, and is not
    needlessly wide (at most 99 %) where the draws can bound it."""
    from assess.fragility.suite import quantile_interval

    rng = np.random.default_rng(2024)
    for n in (5, 30):
        for q in (0.5, 0.84):
            truth = np.exp(0.6 * stats.norm.ppf(q))
            hits = 0
            for _ in range(400):
                draws = np.exp(0.6 * rng.standard_normal(n))
                low, high = quantile_interval(draws, np.ones(n), q, n)
                hits += low <= truth <= high
            assert hits / 400 >= 0.88, (n, q, hits / 400)
            if n == 30:
                assert hits / 400 <= 0.99, (n, q, hits / 400)


def test_the_suite_median_carries_its_interval(sliding_suite):
    result, peaks_cm = sliding_suite
    row = result.summary.set_index("id").loc["FORMA"]
    assert row["demand_median_low_cm"] <= row["demand_median_cm"] <= row["demand_median_high_cm"]
    # 4 motions cannot bound a median at 90 %: all four fall on one side of it with probability 2/16
    assert row["demand_median_low_cm"] == 0.0 and row["demand_median_high_cm"] == np.inf


def test_every_item_is_in_one_action_group_and_no_advice_contradicts_its_numbers(tmp_path):
    """A small inventory under three Table-3 pulses: page 1's groups add up to the freestanding items, and
    each item's sentence agrees with its own numbers (walks every item)."""
    from assess.report import render_html
    from assess.report.render import report_context
    from assess.report.sentences import action_groups as _action_groups

    motions = [{"level": "2in50", "level_label": "2in50", "motion": name, "all_floors": False, "floor": 0,
                "pta_g": pta, "tp_s": tp, "vp_m_s": vp, "pulse": "B", "record_path": "", "scale": 1.0, "row": k + 2}
               for k, (name, pta, tp, vp) in enumerate([("LG", 0.54, 2.1, -0.75), ("CO", 0.84, 0.6, -0.61),
                                                        ("GI", 0.59, 1.5, -0.84)])]
    items = [_item("TIGHT", 228.6, 62.2, 80.0, 0.13, 2.0), _item("ROOMY", 228.6, 62.2, 80.0, 0.13, 2000.0),
             _item("RACK", 200.0, 40.0, 60.0, 0.6, 20.0), _item("BOX", 60.0, 80.0, 80.0, 0.9, 10.0),
             {**_item("ANCH", 200.0, 40.0, 60.0, 0.6, 20.0), "anchored": True}]
    inventory = _inventory(tmp_path, items, motions)
    inventory = dataclasses.replace(inventory, settings=dataclasses.replace(inventory.settings, simulate_motions="pulse",
                                                                           sds_g=1.0, roof_floor=4.0))
    result = run_assessment(inventory, "2in50")
    summary = result.summary.set_index("id")
    groups = _action_groups(report_context(result)["rows"])
    grouped = [r["id"] for g in groups for r in g["rows"]]
    freestanding = summary[summary["risk"] != "anchored"]
    assert sorted(grouped) == sorted(freestanding.index) and len(grouped) == len(set(grouped))
    for item_id, row in freestanding.iterrows():
        kind, action = row["action_kind"], row["action"]
        if kind == "anchor":
            assert action.startswith("Anchor") and row["risk"] == "high"
            assert (row["p_overturn_after"], row["p_beyond_clearance_after"]) == (0.0, 0.0)
        elif kind == "lower_contents":  # the engine's what-if: still with its contents low
            assert action.startswith("Move its heavy contents") and row["p_overturn_after"] == 0.0, (item_id, action)
            assert row["p_beyond_clearance_after"] < 0.1 and "under 0%" not in action
        elif kind in ("restrain", "room", "lock_casters"):
            needs = float(action.split("needs ")[1].split(" cm")[0])
            has = float(action.split("has ")[1].split(" cm")[0])
            assert needs > has and row["p_beyond_clearance"] >= 0.1, (item_id, action)
        else:
            assert action == "No action needed" and row["risk"] == "low", (item_id, action)
    assert {"TIGHT": "restrain", "ROOMY": "none", "RACK": "anchor", "BOX": "none"} == \
        {i: summary.loc[i, "action_kind"] for i in ("TIGHT", "ROOMY", "RACK", "BOX")}
    assert sum(result.risk_counts().values()) == len(summary)
    # ASCE 7-22 (no site sheet) by hand for the rack on the ground floor (z/h = 0, I_p = 1, laboratory equipment
    # C_AR 1.0, R_po 1.5, H_f 1, R_mu 1.0 at grade): 0.4·1.0·W·1·(1/1.5) = 0.267 W is below the floor of
    # eq. 13.3-2, 0.3·S_DS·W; W = 200 kg · g. Tension: (F·h_cg − 0.7·W·b) / 2b, b = 0.2, h_cg = 1.0.
    weight_kn = 200 * 9.80665 / 1000
    rack = summary.loc["RACK"]
    assert rack["anchor_force_kn"] == pytest.approx(0.3 * weight_kn, rel=1e-12)
    assert rack["anchor_tension_kn"] == pytest.approx((0.3 * weight_kn * 1.0 - 0.7 * weight_kn * 0.2) / 0.4, rel=1e-12)
    assert np.isnan(summary.loc["ROOMY", "anchor_force_kn"])  # no action, no force
    assert rack["anchor_force_kip"] == pytest.approx(0.3 * weight_kn / 4.4482216152605, rel=1e-12)
    assert rack["anchor_shear_omega_kn"] == pytest.approx(2.0 * 0.3 * weight_kn, rel=1e-12)  # Omega_0p 2.0
    assert summary.loc["ANCH", "anchor_force_kn"] == pytest.approx(0.3 * weight_kn, rel=1e-12)  # to check it
    assert summary.loc["TIGHT", "what_if"].startswith("Restrained") and "beyond the 30 cm a room can spare" in \
        summary.loc["TIGHT", "what_if"] and summary.loc["RACK", "what_if"].startswith("Anchored")
    assert "What to do first" in render_html(result)


def test_the_simulation_counts_add_up(sliding_suite):
    from assess.report.render import report_context

    result, _ = sliding_suite
    counts = report_context(result)["simulation"]
    assert counts["overturned"] + counts["uplift"] + counts["slid"] + counts["rest"] == counts["cases"]
    assert sum(n for _, n in counts["solvers"]) == counts["runs"] == len(result.motions)
