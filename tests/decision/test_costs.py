"""Costs (assess/decision/costs.py): present value, benefit-cost ratio, expected loss and expected annual loss, checked
against a published worked example and against hand computations; and the report/CSV without costs unchanged.

Expected values are computed here by hand (a different route from the code's where one exists: the
present-value factor as the sum of the discount factors), never from the code's own output.
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np
import pandas as pd
import pytest

from assessed import run_assessment
from assess.inventory.settings import Settings
from assess.decision import costs
from assess.decision.costs import (
    COST_COLUMNS, after_probabilities, benefit_cost_ratio, cost_table, expected_loss_ratio, item_costs,
    present_value_factor,
)
from assess.report import render_html
from assess.report.advice import cost_note_text
from assess.report.costs import costs_context, ranked
from assess.report.render import make_environment, report_context, template_text

from tests.assessment.test_pipeline import inventory, item, motion
from tests.report.test_report import make_result

SETTINGS = Settings(discount_rate=0.07, remaining_life_yr=15.0)


def discount_sum(rate: float, years: int) -> float:
    """Σ_{t=1..n} (1 + r)^-t: the present value of 1 a year, year by year (not the closed form)."""
    return sum((1.0 + rate) ** -t for t in range(1, years + 1))


# ----------------------------------------------------------------- present value and BCR

def test_present_value_of_a_uniform_series_matches_the_published_example():
    # Newnan, Eschenbach & Lavelle, Engineering Economic Analysis, via the R package EngrEcon's
    # annual_to_present(0.08, 30, 30000) example: "Result: pr.value = $337733.5"
    assert 30_000 * present_value_factor(0.08, 30) == pytest.approx(337_733.5, abs=0.05)


@pytest.mark.parametrize("rate, years", [(0.07, 15), (0.031, 30), (0.02, 50), (0.07, 1)])
def test_present_value_factor_is_the_sum_of_the_discount_factors(rate, years):
    assert present_value_factor(rate, years) == pytest.approx(discount_sum(rate, years), rel=1e-12)


def test_present_value_factor_at_no_discount_is_the_years():
    assert present_value_factor(0.0, 15) == 15.0
    assert present_value_factor(1e-9, 15) == pytest.approx(15.0, rel=1e-6)  # continuous at r -> 0


def test_benefit_cost_ratio_by_hand():
    # 30,000 a year avoided for 30 years at 8 %: 337,733.5 of benefits (the example above) for 300,000
    assert benefit_cost_ratio(30_000, 300_000, 0.08, 30) == pytest.approx(337_733.5 / 300_000, rel=1e-6)
    # 250 a year for 15 years at 7 % against 2,000
    assert benefit_cost_ratio(250.0, 2_000.0, 0.07, 15) == pytest.approx(250.0 * discount_sum(0.07, 15) / 2_000.0)


# ----------------------------------------------------------------- loss model

def test_loss_model_by_hand_for_a_made_up_item():
    # 10,000 item: overturns 10 %, slides past its room 40 %, rocking harms it 50 % of the time.
    # Worst state: overturn 0.10 (x1); slide-past but no overturn 0.40 - 0.10 = 0.30 (x0.5);
    # rocking harm only 0.50 - 0.40 = 0.10 (x0.25): 1000 + 1500 + 250 = 2750
    row = {"value": 10_000.0, "p_overturn": 0.1, "p_beyond_clearance": 0.4, "p_rocking_harm": 0.5,
           "action_kind": "anchor", "mitigation_cost": 500.0}
    out = item_costs(row, SETTINGS, has_curve=False)
    assert out["expected_loss"] == pytest.approx(2_750.0)
    assert out["expected_loss_after"] == 0.0  # anchored: held in place (until the actions' own what-if)
    assert out["loss_avoided_per_cost"] == pytest.approx(2_750.0 / 500.0)


def test_overturning_dominates_a_smaller_chance_of_sliding_and_a_missing_mode_counts_zero():
    assert expected_loss_ratio(0.3, 0.1, 0.0) == pytest.approx(0.3)  # every slide-past counted as overturned
    row = {"value": 1_000.0, "p_overturn": 0.0, "p_beyond_clearance": 0.2, "action_kind": "restrain"}
    # no p_rocking_harm column (another branch adds it): 0.5 x 0.2 x 1000
    assert item_costs(row, SETTINGS, False)["expected_loss"] == pytest.approx(100.0)


def test_room_leaves_the_moderate_threshold_and_unknown_actions_leave_no_ratio():
    settings = dataclasses.replace(SETTINGS, risk_pf_moderate=0.1)
    row = {"value": 1_000.0, "p_overturn": 0.0, "p_beyond_clearance": 0.6, "action_kind": "room",
           "mitigation_cost": 100.0}
    out = item_costs(row, settings, False)
    assert out["expected_loss"] == pytest.approx(300.0) and out["expected_loss_after"] == pytest.approx(50.0)
    assert out["loss_avoided_per_cost"] == pytest.approx(2.5)
    relocate = item_costs({**row, "action_kind": "relocate"}, settings, False)
    assert math.isnan(relocate["expected_loss_after"]) and math.isnan(relocate["loss_avoided_per_cost"])
    assert "not known" in cost_note_text(relocate["cost_note"], "relocate")


def test_the_actions_own_probabilities_after_are_used_where_the_summary_has_them():
    row = {"value": 1_000.0, "p_overturn": 0.5, "p_beyond_clearance": 0.5, "action_kind": "lower_contents",
           "p_overturn_after": 0.1, "p_beyond_clearance_after": 0.3, "mitigation_cost": 200.0}
    assert after_probabilities(row, SETTINGS) == (0.1, 0.3, 0.0)
    out = item_costs(row, SETTINGS, False)
    assert out["expected_loss_after"] == pytest.approx(1_000.0 * (0.1 + 0.5 * 0.2))


def test_the_mitigation_cost_comes_from_the_item_else_the_setting_else_none():
    row = {"value": 1_000.0, "p_overturn": 0.2, "p_beyond_clearance": 0.0, "action_kind": "anchor"}
    with_setting = dataclasses.replace(SETTINGS, mitigation_cost_anchor=400.0)
    assert item_costs(row, with_setting, False)["mitigation_cost"] == 400.0
    assert item_costs({**row, "mitigation_cost": 250.0}, with_setting, False)["mitigation_cost"] == 250.0
    none = item_costs(row, SETTINGS, False)
    assert math.isnan(none["mitigation_cost"]) and "mitigation_cost_anchor" in cost_note_text(none["cost_note"], "anchor")


# ----------------------------------------------------------------- annual loss and BCR over a curve

def test_expected_annual_loss_from_the_rates_by_hand():
    # 100,000 item, overturns 1e-3 a year, slides past its room 4e-3 a year:
    # 100,000 x (1e-3 + 0.5 x (4e-3 - 1e-3)) = 250 a year; anchoring (2,000) avoids all of it
    row = {"value": 100_000.0, "p_overturn": 0.3, "p_beyond_clearance": 0.5, "action_kind": "anchor",
           "mitigation_cost": 2_000.0, "annual_rate_overturn": 1e-3, "annual_rate_beyond_clearance": 4e-3}
    out = item_costs(row, SETTINGS, has_curve=True)
    assert out["expected_annual_loss"] == pytest.approx(250.0)
    assert out["expected_annual_loss_after"] == 0.0
    assert out["benefit_cost_ratio"] == pytest.approx(250.0 * discount_sum(0.07, 15) / 2_000.0)


def test_a_rate_given_only_as_a_bound_is_used_and_said():
    row = {"value": 100_000.0, "p_overturn": 0.0, "p_beyond_clearance": 0.5, "action_kind": "restrain",
           "mitigation_cost": 800.0, "annual_rate_overturn": math.nan, "annual_rate_overturn_high": 1e-5,
           "annual_rate_beyond_clearance": 2e-3}
    out = item_costs(row, SETTINGS, has_curve=True)
    # 100,000 x (1e-5 + 0.5 x (2e-3 - 1e-5))
    assert out["expected_annual_loss"] == pytest.approx(100_000 * (1e-5 + 0.5 * (2e-3 - 1e-5)))
    assert "upper bound" in cost_note_text(out["cost_note"])


def test_without_a_curve_there_is_no_benefit_cost_ratio_and_the_note_says_why():
    row = {"value": 1_000.0, "p_overturn": 0.2, "p_beyond_clearance": 0.0, "action_kind": "anchor",
           "mitigation_cost": 100.0}
    out = item_costs(row, SETTINGS, has_curve=False)
    assert math.isnan(out["benefit_cost_ratio"]) and math.isnan(out["expected_annual_loss"])
    assert "no benefit-cost ratio without a hazard curve" in cost_note_text(out["cost_note"])


# ----------------------------------------------------------------- absent costs: nothing changes

def test_no_value_leaves_every_cost_column_empty():
    summary = pd.DataFrame({"id": ["A", "B"], "action_kind": ["anchor", "none"], "p_overturn": [0.5, 0.0],
                            "p_beyond_clearance": [0.0, 0.0]})
    equipment = pd.DataFrame({"id": ["A", "B"], "value": [np.nan, np.nan], "mitigation_cost": [np.nan, np.nan]})
    for table in (cost_table(summary, equipment, SETTINGS, False), cost_table(summary, equipment.drop(
            columns=["value", "mitigation_cost"]), SETTINGS, True)):
        assert list(table.columns) == COST_COLUMNS
        assert table.drop(columns="cost_note").isna().all().all() and (table["cost_note"] == "").all()


def test_the_report_without_costs_is_the_report_without_the_costs_include():
    result = make_result()
    assert costs_context(result) is None
    html = render_html(result)
    without = template_text("report.html.j2").replace('  {% include "_costs.html.j2" %}\n', "")
    assert without != template_text("report.html.j2")  # the include was there to take out
    assert make_environment().from_string(without).render(report_context(result)) == html
    # and the summary without the cost columns renders the same bytes
    bare = dataclasses.replace(result, summary=result.summary.drop(columns=COST_COLUMNS))
    assert render_html(bare) == html


def _job(values: dict | None, **settings):
    items = [dict(item("TALL", height_cm=200, width_cm=40, depth_cm=60, mu=0.5, clearance_cm=30), quantity=2),
             item("SLIDE", height_cm=100, width_cm=80, depth_cm=80, mu=0.1, clearance_cm=2)]
    if values is not None:
        for row in items:
            row["value"], row["mitigation_cost"] = values[row["id"]]
    return run_assessment(inventory(items, [motion("M1", 0.8, 1.0)], simulate_motions="pulse", **settings),
                          "2in50")


def test_an_assessment_without_values_has_empty_cost_columns_and_the_same_other_columns():
    bare, nan_values = _job(None), _job({"TALL": (np.nan, np.nan), "SLIDE": (np.nan, np.nan)})
    assert bare.summary[COST_COLUMNS].drop(columns="cost_note").isna().all().all()
    pd.testing.assert_frame_equal(bare.summary, nan_values.summary)


def test_an_assessment_with_values_gives_the_hand_expected_loss_and_page_one_ranks_the_actions():
    result = _job({"TALL": (20_000.0, np.nan), "SLIDE": (5_000.0, 300.0)}, currency="EUR",
                  mitigation_cost_anchor=1_000.0, mitigation_cost_restrain=400.0)
    summary = result.summary.set_index("id")
    for item_id, value in (("TALL", 20_000.0), ("SLIDE", 5_000.0)):
        row = summary.loc[item_id]
        p_o, p_s = row["p_overturn"], row["p_beyond_clearance"]
        hand = value * (p_o + 0.5 * max(0.0, p_s - p_o))
        assert row["expected_loss"] == pytest.approx(hand)
    assert summary.loc["SLIDE", "mitigation_cost"] == 300.0  # the item's own cost beats the setting
    context = costs_context(result)
    assert context is not None and not context["has_curve"]
    order = [r["id"] for r in context["rows"]]
    acting = ranked(result.summary)
    per_cost = pd.to_numeric(acting["loss_avoided_per_cost"]).fillna(-1.0).tolist()
    assert per_cost == sorted(per_cost, reverse=True) and order == acting["id"].tolist()
    html = render_html(result)
    assert "Where money avoids most loss" in html and "No benefit-cost ratio" in html
    costs_block = html.split("Where money avoids most loss")[1].split("</table>")[0]
    assert costs_block.index('href="#item-TALL"') < costs_block.index('href="#item-SLIDE"')  # 20 before 8.3


# ----------------------------------------------------------------- the workbook's columns and settings

def test_value_and_mitigation_cost_are_read_per_item(make_workbook):
    from assess.inventory import read_workbook
    from workbooks import good_sheets

    sheets = good_sheets()
    sheets["equipment"][0].update({"value": 12_000, "mitigation_cost": None})
    sheets["equipment"][1].update({"value": None, "mitigation_cost": 350.5})
    sheets["settings"] += [{"key": "currency", "value": "EUR"}, {"key": "discount_rate", "value": 0.03},
                           {"key": "mitigation_cost_anchor", "value": 900}]
    inventory = read_workbook(make_workbook(sheets))
    equipment = inventory.equipment.set_index("id")
    assert equipment.loc["INC-1", "value"] == 12_000.0 and math.isnan(equipment.loc["INC-1", "mitigation_cost"])
    assert math.isnan(equipment.loc["FRZ-2", "value"]) and equipment.loc["FRZ-2", "mitigation_cost"] == 350.5
    assert math.isnan(equipment.loc["BSC-3", "value"])
    assert (inventory.settings.currency, inventory.settings.discount_rate,
            inventory.settings.mitigation_cost_anchor) == ("EUR", 0.03, 900.0)


@pytest.mark.parametrize("column, text", [("value", "$12,000"), ("value", -5), ("mitigation_cost", -1)])
def test_a_bad_amount_is_reported_at_its_cell(make_workbook, column, text):
    from tests.inventory.test_inventory import assert_mentions, only_problem
    from workbooks import good_sheets

    sheets = good_sheets()
    sheets["equipment"][0][column] = text
    problem = only_problem(make_workbook(sheets))
    assert problem.row == 2
    assert_mentions(problem, "sheet 'equipment'", f"column '{column}'")
    assert "plain number" in problem.fix or "not a number" in str(problem)


def test_a_discount_rate_in_percent_is_refused(make_workbook):
    from tests.inventory.test_inventory import assert_mentions, only_problem
    from workbooks import good_sheets

    sheets = good_sheets()
    sheets["settings"].append({"key": "discount_rate", "value": 7})
    problem = only_problem(make_workbook(sheets))
    assert_mentions(problem, "setting 'discount_rate' is", "0.07 for 7 %", "use the default 0.07.")
    assert "Konstantinidis" not in str(problem)  # the paper gives regression constants, not discount rates


def test_page_one_ranks_by_the_ratio_then_the_scenario_ratio_then_priority():
    nan = math.nan
    summary = pd.DataFrame({
        "id": ["P1", "B-low", "B-high", "S", "NONE", "P2"],
        "action_kind": ["anchor", "anchor", "restrain", "room", "none", "anchor"],
        "benefit_cost_ratio": [nan, 0.5, 3.0, nan, nan, nan],
        "loss_avoided_per_cost": [nan, 9.0, 1.0, 2.0, nan, nan],
        "priority": [2, 5, 6, 4, 1, 3]})
    # with a ratio (highest first), then with only the scenario's, then by priority; no action: not listed
    assert ranked(summary)["id"].tolist() == ["B-high", "B-low", "S", "P1", "P2"]


def test_page_one_shows_the_ratio_at_other_discount_rates_and_lives():
    """The sensitivity of page 1: at the settings' own rate and life it is the item's benefit_cost_ratio
    (item_costs, another path); elsewhere that ratio times PV(r, n) / PV(r0, n0), PV the sum of the discount
    factors (discount_sum, by hand)."""
    from assess.report.costs import bcr_sensitivity

    row = {"value": 10_000.0, "p_overturn": 0.3, "p_beyond_clearance": 0.5, "action_kind": "anchor",
           "mitigation_cost": 400.0, "annual_rate_overturn": 2e-3, "annual_rate_beyond_clearance": 5e-3}
    settings = dataclasses.replace(SETTINGS, discount_rate=0.07, remaining_life_yr=15.0)
    out = item_costs(row, settings, has_curve=True)
    summary = pd.DataFrame([{**row, **out, "quantity": 3}])
    table = bcr_sensitivity(summary, settings)
    assert table["lives"] == ["10", "15", "30"] and [r["rate"] for r in table["rows"]] == ["3 %", "7 %", "10 %"]
    own = next(r for r in table["rows"] if r["own"])
    assert float(own["ratios"][1]) == pytest.approx(out["benefit_cost_ratio"], rel=0.01)
    for r, rate in zip(table["rows"], (0.03, 0.07, 0.10)):
        for shown, years in zip(r["ratios"], (10, 15, 30)):
            expected = out["benefit_cost_ratio"] * discount_sum(rate, years) / discount_sum(0.07, 15)
            assert float(shown) == pytest.approx(expected, rel=0.05)  # two significant digits shown
