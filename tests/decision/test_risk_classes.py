"""The risk class from each failure mode's probability and the item's consequence (docs/outputs.md, `risk`).

The rule is fed hand-made demand rows, each expectation the documented thresholds (docs/workbook.md); the
end-to-end check takes its expected rotations from the independent Housner ODE of
tests/rocking_reference.py, not from the pipeline.
"""

import dataclasses
import numpy as np
import pandas as pd
import pytest

from assessed import run_assessment
from assess.inventory.settings import Settings
from assess.decision import decisions
from assess.decision.risk_classes import CLASS_ORDER, Chances, classify_risk
from assess.fragility.governing import governing_demand, rocking_harm
from assess.fragility.regression import RegressionConstants
from assess.inventory import Inventory
from assess.quantity_text import percent_text
from assess.report.advice import item_words, risk_reason
from assess.report.sentences import format_percent
from rocking_reference import reference_rocking
from tests.fragility.test_governing_demand import DT_S, _sine_record

SETTINGS = Settings()
CONSEQUENCES = ("life-safety", "hazardous", "critical", "valuable", "ordinary")


def test_the_documented_defaults():
    """docs/workbook.md: overturning 2.5 % / 10 % (ASCE 7-16 Table C1.3.1(b)), sliding 10 % / 50 %, rocking
    harm 10 % from half the tipping angle."""
    assert (SETTINGS.risk_overturn_moderate, SETTINGS.risk_overturn_high) == (0.025, 0.10)
    assert (SETTINGS.risk_pf_moderate, SETTINGS.risk_pf_high) == (0.1, 0.5)
    assert (SETTINGS.risk_rocking_moderate, SETTINGS.rocking_harm_theta_over_alpha) == (0.1, 0.5)


def test_the_pharmacy_refrigerator_that_barely_rocks_is_low_not_high():
    """Issue 19: a critical 2-door refrigerator sliding 1-2 cm, 0 % past its room, 0 % overturning, rocking to
    0.05 of its tipping angle was "high, act now". Rocking to 0.05 α is no harm: it is low."""
    assert not rocking_harm(0.05, False)
    chances = Chances(overturn=0.0, beyond_clearance=0.0, rocking_harm=0.0)
    assert classify_risk(chances, "critical", SETTINGS) == "low"
    # through the decisions stage, with the engine saying it uplifts: still low, and the reason says why
    row = {"consequence": "critical", "clearance_cm": 10.0, "p_beyond_clearance": 0.0, "p_beyond_clearance_low": 0.0,
           "p_beyond_clearance_high": 0.0, "p_overturn": 0.0, "p_overturn_low": 0.0, "p_overturn_high": 0.0,
           "p_rocking_harm": 0.0, "p_rocking_harm_low": 0.0, "p_rocking_harm_high": 0.0, "demand_room_cm": 2.0,
           "theta_max_over_alpha": 0.05, "suite_motions": 11, "suite_histories": 11}
    item = pd.DataFrame([{"id": "RX-0-03", "floor": 0, "mass_kg": 150.0, "width_m": 1.2, "depth_m": 0.8,
                          "cg_height_m": 1.0, "consequence": "critical"}]).iloc[0]
    decided = _columns(decisions.decide_item(item, row, True, SETTINGS), SETTINGS)
    assert decided["risk"] == "low" and decided["risk_range"] == ""
    assert decided["risk_reason"].startswith("low: 0% chance of overturning")


def _columns(decision, settings):
    """An item's summary columns: the decision's numbers and kinds and the report's words of them."""
    return {**decisions.item_columns(decision, settings), **item_words(decision, settings)}


def test_shelving_that_overturns_in_most_runs_is_high():
    assert classify_risk(Chances(0.87, 0.0, 0.1), "life-safety", SETTINGS) == "high"
    assert risk_reason(Chances(0.87, 0.0, 0.1), "life-safety", SETTINGS) == \
        "high: 87% chance of overturning (high from 10%)"


@pytest.mark.parametrize("consequence", CONSEQUENCES)
@pytest.mark.parametrize("p_harm", [0.0, 0.09, 0.1, 0.5, 1.0])
def test_rocking_alone_is_never_high(consequence, p_harm):
    risk = classify_risk(Chances(0.0, 0.0, p_harm), consequence, SETTINGS)
    counts = consequence != "ordinary"
    assert risk == ("moderate" if counts and p_harm >= 0.1 else "low"), (consequence, p_harm, risk)


@pytest.mark.parametrize("p_overturn, expected", [(0.0, "low"), (0.02, "low"), (0.025, "moderate"),
                                                  (0.099, "moderate"), (0.10, "high"), (1 / 3, "high")])
def test_overturning_follows_its_thresholds_for_every_consequence(p_overturn, expected):
    assert {classify_risk(Chances(p_overturn, 0.0, 0.0), c, SETTINGS) for c in CONSEQUENCES} == {expected}


@pytest.mark.parametrize("p_beyond, expected", [(0.05, "low"), (0.1, "moderate"), (0.49, "moderate"),
                                                (0.5, "high")])
def test_sliding_past_the_room_keeps_its_thresholds(p_beyond, expected):
    assert classify_risk(Chances(0.0, p_beyond, 0.0), "valuable", SETTINGS) == expected


def test_the_worst_mode_wins_and_the_thresholds_are_settings():
    assert classify_risk(Chances(0.03, 0.6, 0.5), "hazardous", SETTINGS) == "high"  # sliding
    strict = dataclasses.replace(SETTINGS, risk_overturn_high=0.02, risk_overturn_moderate=0.01)
    assert classify_risk(Chances(0.03, 0.0, 0.0), "ordinary", strict) == "high"


def _decided(row_chances, consequence="critical"):
    p_over, p_beyond, p_harm = row_chances
    row = {"consequence": consequence, "clearance_cm": 30.0, "demand_room_cm": 10.0, "theta_max_over_alpha": 0.6,
           "suite_motions": 3, "suite_histories": 30}
    for name, (value, low, high) in (("p_overturn", p_over), ("p_beyond_clearance", p_beyond),
                                     ("p_rocking_harm", p_harm)):
        row.update({name: value, f"{name}_low": low, f"{name}_high": high})
    item = pd.DataFrame([{"id": "X", "floor": 0, "mass_kg": 100.0, "width_m": 0.6, "depth_m": 0.6,
                          "cg_height_m": 0.9, "consequence": consequence}]).iloc[0]
    return _columns(decisions.decide_item(item, row, True, dataclasses.replace(SETTINGS, sds_g=0.0)), SETTINGS)


def test_the_risk_range_spans_the_classes_of_every_chances_interval():
    # overturning 1 of 30 (3 %, moderate) with its interval 0.2 %-15 %: low to high
    decided = _decided(((1 / 30, 0.0017, 0.150), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)))
    assert decided["risk"] == "moderate" and decided["risk_range"] == "low to high"
    # rocking harm alone, however wide its interval, never reaches high
    decided = _decided(((0.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.2, 0.05, 0.9)))
    assert decided["risk"] == "moderate" and decided["risk_range"] == "low to moderate"


def test_priority_weighs_rocking_harm_by_its_probability_and_the_consequence():
    """No flat stand-in: an item that rocks harmlessly scores 0, one that harms itself in 80 % of runs
    scores 0.25 × 0.8 × its consequence weight."""
    assert _decided(((0.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)))["priority_score"] == 0.0
    assert _decided(((0.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.8, 0.8, 0.8)))["priority_score"] == pytest.approx(
        decisions.CONSEQUENCE_WEIGHTS["critical"] * 0.25 * 0.8)
    assert _decided(((0.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.8, 0.8, 0.8)), "ordinary")["priority_score"] == 0.0


def test_p_rocking_harm_counts_the_runs_that_rock_past_the_threshold_without_overturning():
    """One motion, four histories, by hand: θ/α 0.05, 0.6, 0.4 and an overturn (θ/α 2.0) -> P(overturn)
    1/4, P(rocking harm) 1/4 at 0.5 and 2/4 at 0.3; the mode over the suite is rock."""
    cases = pd.DataFrame({"id": ["A", "A"], "motion_key": [0, 0], "motion": ["M"] * 2, "direction": [1, 2],
                          "demand_source": ["synthetic"] * 2, "pta_g": [0.5] * 2, "tp_s": [1.0] * 2,
                          "im": [0.5 / 0.6 - 1] * 2, "mode": ["rock", "rest"], "clearance_m": [0.5] * 2,
                          "pulse_share": [0.5] * 2, "sim_uplift": [True, False], "mu_static": [0.6] * 2,
                          "b_over_h": [0.2, 1.0]})
    theta = [0.05, 0.6, 0.4, 2.0]
    runs = pd.DataFrame({"case": [0] * 4 + [1] * 4, "realization": list(range(4)) * 2,
                         "sliding_max_cm": [0.0] * 8, "overturned": [False, False, False, True] + [False] * 4,
                         "theta_max_over_alpha": theta + [0.0] * 4, "uplift": [True] * 4 + [False] * 4,
                         "mode": ["rock"] * 4 + ["rest"] * 4})
    constants = RegressionConstants.from_settings(SETTINGS)
    row = governing_demand(cases, runs, constants).loc["A"]
    assert row["p_overturn"] == pytest.approx(0.25) and row["p_rocking_harm"] == pytest.approx(0.25)
    assert row["p_rocking_harm_low"] < 0.25 < row["p_rocking_harm_high"] and row["demand_mode"] == "rock"
    assert governing_demand(cases, runs, constants, harm_theta_over_alpha=0.3).loc["A", "p_rocking_harm"] == \
        pytest.approx(0.5)


def test_an_item_that_cannot_uplift_has_no_chance_of_overturning_not_a_sampled_zero():
    cases = pd.DataFrame({"id": ["S"], "motion_key": [0], "motion": ["M"], "direction": [1],
                          "demand_source": ["synthetic"], "pta_g": [0.5], "tp_s": [1.0], "im": [2.0],
                          "mode": ["slide"], "clearance_m": [0.5], "pulse_share": [0.5], "sim_uplift": [False],
                          "mu_static": [0.13], "b_over_h": [0.39]})
    runs = pd.DataFrame({"case": [0] * 10, "realization": range(10), "sliding_max_cm": [10.0] * 10,
                         "overturned": [False] * 10, "theta_max_over_alpha": [0.0] * 10, "mode": ["slide"] * 10})
    row = governing_demand(cases, runs, RegressionConstants.from_settings(SETTINGS)).loc["S"]
    assert row["p_overturn_high"] == 0.0 and row["p_rocking_harm_high"] == 0.0 and row["demand_mode"] == "slide"
    assert row["p_beyond_clearance_high"] > 0.2  # 0 of 10 beyond: the sliding interval stays a sample's


def test_one_formatting_of_a_chance():
    """A table and a sentence write the same chance alike: never ">99%" beside "100%"."""
    for p in (0.0, 0.003, 0.39, 0.996, 1.0):
        assert format_percent(p) == percent_text(p)
    assert percent_text(0.996) == ">99%" and percent_text(1.0) == "100%"
    assert "39% chance of overturning" in risk_reason(Chances(0.39, 0.0, 0.0), "ordinary", SETTINGS)


# ------------------------------------------------------------------ end to end

def _rack(item_id, floor, consequence):
    # b/h = 0.2 across its width, 1.0 across its depth (it rocks one way only); mu = 0.9 >= b/h
    return {"id": item_id, "name": f"rack {item_id}", "room": "R1", "floor": floor, "height_m": 2.0, "width_m": 0.4,
            "depth_m": 2.0, "mass_kg": 200.0, "mu": 0.9, "mu_static": 0.9, "clearance_m": 0.2, "cg_height_m": 1.0,
            "anchored": False, "quantity": 1, "row": 2, "consequence": consequence}


def test_a_small_workbook_where_rocking_alone_is_never_high(tmp_path):
    """Floor 0: four one-sine records under which a slender rack (b/h 0.2) rocks and never overturns, one of
    them to ~0.68 α; floor 1: one record under which it barely uplifts (θ/α ~0.02, the refrigerator's case).
    Expected rotations from the independent Housner ODE; the classes from the documented rule."""
    specs = {0: [("A", 0.22, 1.0), ("B", 0.25, 1.0), ("C", 0.30, 0.5), ("D", 0.40, 0.3)], 1: [("E", 0.22, 1.0)]}
    alpha = np.arctan(0.2)
    p = np.sqrt(3 * 9.80665 / (4 * np.hypot(0.2, 1.0)))
    restitution = 1 - 1.5 * np.sin(alpha) ** 2
    motions, reference = [], {}
    for floor, floor_specs in specs.items():
        for name, ap_g, tp_s in floor_specs:
            path, accel = _sine_record(tmp_path, name, ap_g, tp_s)
            motions.append({"level": "2in50", "level_label": "2in50", "motion": name, "all_floors": False,
                            "floor": floor, "pta_g": np.nan, "tp_s": tp_s, "vp_m_s": 0.5, "pulse": "",
                            "record_path": str(path), "scale": 1.0, "row": len(motions) + 2})
            reference.setdefault(floor, []).append(reference_rocking(
                np.concatenate([accel, np.zeros(int(10 / DT_S))]), DT_S, alpha, p, restitution))
    assert not any(r["overturned"] for runs in reference.values() for r in runs)
    harm = {floor: np.mean([r["theta_max_over_alpha"] >= 0.5 for r in runs]) for floor, runs in reference.items()}
    assert harm == {0: 0.25, 1: 0.0}  # the test means something only if one record harms and none overturns
    items = [_rack("CRIT", 0, "critical"), _rack("ORD", 0, "ordinary"), _rack("FRIDGE", 1, "critical")]
    hazard = pd.DataFrame(motions)
    hazard["floor"] = hazard["floor"].astype("Int64")
    inventory = Inventory(path=tmp_path / "rocking.xlsx", equipment=pd.DataFrame(items), hazard=hazard,
                          settings=Settings())
    summary = run_assessment(inventory, "2in50").summary.set_index("id")
    for item_id, floor in (("CRIT", 0), ("ORD", 0), ("FRIDGE", 1)):
        row = summary.loc[item_id]
        assert row["p_overturn"] == 0.0 and row["mode"] in ("rock", "slide-rock"), (item_id, row["mode"])
        assert row["p_rocking_harm"] == pytest.approx(harm[floor]), item_id
        assert CLASS_ORDER.index(row["risk"]) < CLASS_ORDER.index("high"), (item_id, row["risk"])
        # it uplifts: the regression (pure sliding) does not apply and says why
        assert not row["regression_applies"] and "the item uplifts" in row["regression_note"], item_id
    assert summary.loc["CRIT", "risk"] == "moderate"  # critical: 25 % >= risk_rocking_moderate
    assert summary.loc["ORD", "risk"] == "low"  # ordinary: rocking that stays upright endangers nobody
    assert summary.loc["FRIDGE", "risk"] == "low"  # rocks to ~0.02 alpha: the old rule made it high
    assert summary.loc["FRIDGE", "theta_max_over_alpha"] == pytest.approx(
        reference[1][0]["theta_max_over_alpha"], abs=0.01)


def test_a_class_changed_by_the_rule_alone_says_so_in_the_comparison():
    """A previous summary (old rule: high because it rocked) against this run's, with the same numbers."""
    from assess.assessment.comparison import compare_summaries

    before = pd.DataFrame({"id": ["RX-0-03"], "name": ["Pharmacy refrigerator"], "risk": ["high"], "pta_g": [0.45],
                           "mode": ["slide-rock"], "p_beyond_clearance": [0.0], "p_overturn": [0.0]})
    reason = risk_reason(Chances(0.0, 0.0, 0.0), "critical", SETTINGS)
    after = before.assign(risk="low", p_rocking_harm=0.0, risk_reason=reason)
    row = compare_summaries(before, after).iloc[0]
    assert row["change"] == "down" and row["why"] == f"the same chances under another class rule or thresholds (now {reason})"
