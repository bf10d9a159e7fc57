"""The actions: one that fits the item, its sentence never contradicting its numbers, what it would change,
and the work orders by floor and room.

Hand-made demand rows check the rule as docs/outputs.md states it (casters, a room a room can spare,
a chance above 0 never written "0%"). The engine-backed test checks the what-if run of the heavy
contents moved low against the static tipping condition: a block whose centre of mass is at height h
above a base of half-width b does not uplift while the floor's acceleration stays below g b/h (Housner
1963, eq. 2; Makris & Roussos 2000), nor slide while it stays below μ g; the block as loaded is checked
to overturn by the independent Housner ODE of tests/rocking_reference.py.
"""
import dataclasses
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from assessed import run_assessment
from assess.inventory.settings import Settings
from assess.decision import actions
from assess.decision.actions import LoweredDemand
from assess.inventory import Inventory, read_workbook
from assess.report import advice
from rocking_reference import reference_rocking

SETTINGS = Settings(risk_pf_high=0.5, risk_pf_moderate=0.1, room_max_cm=30.0)
DT_S = 0.005


class Item:
    def __init__(self, casters=False, contents="movable"):
        self.casters = casters
        self.contents = contents


def _row(p_beyond=0.0, p_overturn=0.0, room_cm=20.0, risk="high", motions=3, histories=30, p_harm=0.0,
         consequence="ordinary"):
    return {"p_beyond_clearance": p_beyond, "p_overturn": p_overturn, "demand_room_cm": room_cm, "risk": risk,
            "clearance_cm": 10.0, "cg_height_cm": 100.0, "theta_max_over_alpha": 0.4, "suite_motions": motions,
            "suite_histories": histories, "p_rocking_harm": p_harm, "consequence": consequence}


def _decided(item, row, uplift, lowered, settings):
    """The action's columns (numbers and kinds, the decision stage's) and its words (the report's)."""
    action = actions.decide_action(item, row, uplift, lowered, settings)
    assert isinstance(action.kind, actions.ActionKind)
    return {**action.columns(), "action": advice.action_sentence(action.kind, row, uplift, lowered, settings,
                                                                 action.mode),
            "what_if": advice.what_if_sentence(action.kind, row, lowered, settings, action.mode, action.contents)}


def test_an_item_on_casters_is_tethered_or_its_casters_locked_never_bolted_down():
    overturns = _row(p_overturn=0.4)
    assert _decided(Item(casters=True), overturns, True, None, SETTINGS)["action_kind"] == "tether"
    assert _decided(Item(casters=False), overturns, True, None, SETTINGS)["action_kind"] == "anchor"
    rocks = _row(p_overturn=0.0, p_harm=0.3, consequence="critical")  # rocking that harms a critical item
    assert _decided(Item(casters=True), rocks, True, None, SETTINGS)["action_kind"] == "tether"
    # it slides farther than a room can spare: tethered; within what a room can spare: casters locked, room kept
    slides = _row(p_beyond=0.6, room_cm=191.0)
    decided = _decided(Item(casters=True), slides, False, None, SETTINGS)
    assert decided["action_kind"] == "tether" and "181 cm more, beyond the 30 cm a room can spare" in decided["action"]
    assert (decided["p_overturn_after"], decided["p_beyond_clearance_after"]) == (0.0, 0.0)
    rolls = _decided(Item(casters=True), _row(p_beyond=0.6, room_cm=39.1), False, None, SETTINGS)
    assert rolls["action_kind"] == "lock_casters"
    assert rolls["action"].startswith("Lock or chock its casters and keep 40 cm clear around it")
    assert rolls["p_beyond_clearance_after"] == SETTINGS.risk_pf_moderate and "tether it" in rolls["what_if"]
    assert all("Anchor" not in d["action"] for d in (decided, rolls))


def test_room_is_asked_only_where_a_room_can_spare_it():
    """It has 10 cm: 191 cm means gaining 181 cm, far beyond the 30 cm a room can spare; 40 cm means 30 more."""
    far = _decided(Item(), _row(p_beyond=0.6, room_cm=190.3), False, None, SETTINGS)
    assert far["action_kind"] == "restrain"
    assert not far["action"].startswith("Give it room") and "181 cm more, beyond the 30 cm a room can spare" in \
        far["action"]
    assert "it needs 191 cm to be low risk and has 10 cm" in far["action"]  # the need is still said, rounded up
    near = _decided(Item(), _row(p_beyond=0.3, room_cm=39.2, risk="moderate"), False, None, SETTINGS)
    assert near["action_kind"] == "room" and near["action"].startswith("Give it room: it needs 40 cm")
    assert _decided(Item(), _row(p_beyond=0.3, room_cm=40.2, risk="moderate"), False, None,
                                 SETTINGS)["action_kind"] == "restrain"
    # the setting moves the line: with 200 cm to spare the far item gets room
    assert _decided(Item(), _row(p_beyond=0.6, room_cm=190.3), False, None,
                                 dataclasses.replace(SETTINGS, room_max_cm=200.0))["action_kind"] == "room"
    # in US units the room is in inches (191 cm = 75.2 in, rounded up)
    us = _decided(Item(), _row(p_beyond=0.6, room_cm=190.3), False, None, dataclasses.replace(SETTINGS, units="us"))
    assert "it needs 75 in" in us["action"] and "12 in a room can spare" in us["action"]
    assert "has 3 in" in us["action"]  # 10 cm = 3.9 in, rounded down


@pytest.mark.parametrize("p_overturn", [0.001, 0.004, 1 / 300])
def test_a_chance_of_overturning_above_0_never_reads_0_percent(p_overturn):
    decided = _decided(Item(), _row(p_overturn=p_overturn, p_harm=0.3, consequence="critical"), True, None,
                       SETTINGS)
    assert decided["action_kind"] == "anchor" and decided["action_mode"] == "rocking_harm"
    assert "0%" not in decided["action"].replace("<1%", "") and "under <1% of its 30 simulated histories" in \
        decided["action"]


def test_the_residual_chances_follow_the_action():
    anchored = _decided(Item(), _row(p_beyond=0.7, p_overturn=0.9), True, None, SETTINGS)
    assert (anchored["p_overturn_after"], anchored["p_beyond_clearance_after"]) == (0.0, 0.0)
    assert "assumed to hold" in anchored["what_if"]
    room = _decided(Item(), _row(p_beyond=0.3, room_cm=35.0, risk="moderate"), False, None, SETTINGS)
    assert (room["p_overturn_after"], room["p_beyond_clearance_after"]) == (0.0, 0.1)
    none = _decided(Item(), _row(p_beyond=0.02, risk="low"), False, None, SETTINGS)
    assert none["action_kind"] == "none" and none["p_beyond_clearance_after"] == 0.02


def test_lowering_the_contents_is_the_action_only_where_the_engine_finds_the_item_still():
    row = _row(p_overturn=0.4)
    still = LoweredDemand(p_overturn=0.0, p_beyond_clearance=0.0, uplift=False, theta_max_over_alpha=0.0,
                          cg_fraction=0.4, cg_height_cm=80.0)
    decided = _decided(Item(), row, True, still, SETTINGS)
    assert decided["action_kind"] == "lower_contents"
    assert (decided["p_overturn_after"], decided["p_beyond_clearance_after"]) == (0.0, 0.0)
    assert decided["action"].startswith("Move its heavy contents to the lowest shelves or drawers: as loaded it overturns under 40% of its 30")
    assert "centre of mass at 40% of its height, 80 cm instead of 100 cm" in decided["what_if"]
    rocking = dataclasses.replace(still, p_overturn=0.1, uplift=True)
    decided = _decided(Item(), row, True, rocking, SETTINGS)
    assert decided["action_kind"] == "anchor" and "Lowering its contents alone is not enough" in decided["what_if"]
    assert "overturning 10% (as loaded 40%)" in decided["what_if"]


def test_the_failure_that_makes_the_class_decides_the_action():
    """Issue 30's reagent refrigerator: it overturns under a weighted <1% of its motions (low on its own:
    moderate from 2.5%) and slides past its 15 cm (6 in) in 78%: the sliding decides. It is restrained
    against sliding (not anchored), its overturning left as it is, and its what-if says why not room
    and why not anchoring; its neighbour that slides as far and does not overturn gets the same action."""
    fridge = _row(p_beyond=0.78, p_overturn=0.004, room_cm=95.0, risk="high", motions=11, histories=11)
    fridge["clearance_cm"] = 15.24
    neighbour = {**fridge, "p_overturn": 0.0}
    decided = _decided(Item(contents="fixed"), fridge, True, None, SETTINGS)
    assert (decided["action_kind"], decided["action_mode"]) == ("restrain", "beyond_clearance")
    assert decided["action"].startswith("Restrain it against sliding")
    assert (decided["p_overturn_after"], decided["p_beyond_clearance_after"]) == (0.004, 0.0)
    assert "its chance of overturning stays <1%, low on its own, so anchoring is not needed" in decided["what_if"]
    assert "Room would not do: it needs 80 cm more, beyond the 30 cm a room can spare" in decided["what_if"]
    assert _decided(Item(contents="fixed"), neighbour, False, None, SETTINGS)["action_kind"] == "restrain"
    # where its overturning is not low on its own (5% >= 2.5%), room or a restraint would leave it: anchored
    tips = _decided(Item(), {**fridge, "p_overturn": 0.05}, True, None, SETTINGS)
    assert (tips["action_kind"], tips["action_mode"]) == ("anchor", "overturn")
    assert "Room or a restraint against sliding would not do" in tips["what_if"]


def test_lowering_is_offered_only_for_movable_contents_and_never_where_it_raises_a_chance():
    row = _row(p_overturn=0.4, p_beyond=0.05)
    still = LoweredDemand(p_overturn=0.0, p_beyond_clearance=0.0, uplift=False, theta_max_over_alpha=0.0,
                          cg_fraction=0.4, cg_height_cm=80.0)
    assert _decided(Item(contents="movable"), row, True, still, SETTINGS)["action_kind"] == "lower_contents"
    for contents, why in (("fixed", "its contents are fixed"), ("none", "it has no contents to move")):
        decided = _decided(Item(contents=contents), row, True, still, SETTINGS)
        assert decided["action_kind"] == "anchor" and f"Moving its contents low is not offered: {why}" in \
            decided["what_if"]
    # still with the contents low, but sliding past its room more often (8% > 5%): not offered
    slides_more = dataclasses.replace(still, p_beyond_clearance=0.08)
    assert _decided(Item(), row, True, slides_more, SETTINGS)["action_kind"] == "anchor"


def test_work_orders_group_the_actions_by_floor_and_room():
    summary = pd.DataFrame({
        "id": ["B", "A", "C", "D", "E", "F"], "floor": [1, 1, 0, 1, 1, 2],
        "room": ["1-10", "1-10", "0-01", "1-10", "1-20", "2-01"], "quantity": [2, 1, 3, 1, 1, 1],
        "action_kind": ["anchor", "anchor", "tether", "room", "anchor", "none"]})
    orders = actions.work_orders(summary)
    assert list(orders.columns) == ["floor", "floor_label", "room", "action", "items", "names", "count", "detail",
                                    "reference", "connection_detail", "connection_reference", "force_kn", "unit_cost",
                                    "total_cost"]
    assert orders[["floor", "floor_label", "room", "action", "items", "count"]].values.tolist() == [
        [0, "0", "0-01", "tether", "C", 3], [1, "1", "1-10", "anchor", "A, B", 3],
        [1, "1", "1-10", "room", "D", 1], [1, "1", "1-20", "anchor", "E", 1]]
    # under ground_1 (the US) the label counts the ground floor 1; the workbook's number stays
    us = actions.work_orders(summary, "ground_1")
    assert list(zip(us["floor"], us["floor_label"])) == [(0, "1"), (1, "2"), (1, "2"), (1, "2")]
    # every unit that needs an action is in exactly one order
    needs = summary[~summary["action_kind"].isin(["none", "anchored"])]
    assert orders["count"].sum() == needs["quantity"].sum()
    floors = advice.work_order_sentences(orders)
    assert [f["floor"] for f in floors] == [0, 1] and floors[1]["units"] == 3 + 1 + 1
    assert floors[1]["rooms"][0]["orders"] == ["anchor to the floor or wall: A, B (3 units)",
                                               "give room (each item's in its details): D (1 unit)"]


def test_a_work_order_gives_the_crew_names_detail_force_and_cost():
    """Two gas cylinder racks a code governs and an item the analysis anchors, in one room: the racks' order
    carries NFPA 99's detail and reference, the largest F_p of the two (2.0 kN, not 1.5) and 2 x 300 + 1 x 300 in
    all; the anchored item its own order; an item without a cost leaves its order's cost empty."""
    summary = pd.DataFrame({
        "id": ["G2", "G1", "S1", "S2"], "name": ["rack B", "rack A", "shelving", "cart"], "floor": [0, 0, 0, 0],
        "room": ["gases"] * 4, "quantity": [2, 1, 1, 1], "action_kind": ["chain", "chain", "anchor", "tether"],
        "action_detail": ["each cylinder chained", "each cylinder chained", "", ""],
        "action_reference": ["NFPA 99 (2021) ch. 11", "NFPA 99 (2021) ch. 11", "", ""],
        "anchor_force_kn": [2.0, 1.5, 3.0, np.nan], "mitigation_cost": [300.0, 300.0, 500.0, np.nan]})
    orders = actions.work_orders(summary).set_index("action")
    chain = orders.loc["chain"]
    assert (chain["items"], chain["names"], chain["count"]) == ("G1, G2", "rack A; rack B", 3)
    assert (chain["detail"], chain["reference"], chain["force_kn"]) == ("each cylinder chained", "NFPA 99 (2021) ch. 11", 2.0)
    assert (chain["total_cost"], chain["unit_cost"]) == (900.0, 300.0)
    assert orders.loc["anchor", "detail"] == "" and orders.loc["anchor", "force_kn"] == 3.0
    assert np.isnan(orders.loc["tether", "total_cost"])
    sentence = advice.work_order_sentences(actions.work_orders(summary), "us", "USD")[0]["rooms"][0]["orders"][0]
    assert sentence.startswith("anchor to the floor or wall: S1 (1 unit: shelving)")
    sentences = advice.work_order_sentences(actions.work_orders(summary), "us", "USD")[0]["rooms"][0]["orders"]
    chained = next(sentence for sentence in sentences if sentence.startswith("chain"))
    assert "each cylinder chained (NFPA 99 (2021) ch. 11)" in chained
    assert "force to resist up to 450 lb per unit" in chained  # 2.0 kN = 449.6 lbf
    assert "cost USD 300 per unit, USD 900 in all" in chained


def test_lines_that_need_flexible_connections_get_a_work_order_even_where_the_item_needs_no_restraint():
    """A CO2 incubator that needs no restraint and an anchored analyser, both with lines, each get an order for
    the connections alone (action none or anchored); an item with neither an action nor lines gets none."""
    summary = pd.DataFrame({
        "id": ["INC", "MS", "FR", "SH"], "name": ["incubator", "analyser", "freezer", "shelving"],
        "floor": [1, 1, 1, 1], "room": ["lab"] * 4, "quantity": [2, 1, 1, 1],
        "action_kind": ["none", "anchored", "none", "anchor"],
        "connection_detail": ["gas: a flexible connector", "fluid: braided hoses", "", ""],
        "connection_reference": ["FEMA E-74 (2012) §6.4"] * 2 + ["", ""]})
    orders = actions.work_orders(summary)
    assert orders[["action", "items", "count", "connection_detail"]].values.tolist() == [
        ["anchor", "SH", 1, ""], ["none", "INC", 2, "gas: a flexible connector"],
        ["anchored", "MS", 1, "fluid: braided hoses"]]
    sentences = advice.work_order_sentences(orders)[0]["rooms"][0]["orders"]
    assert sentences[1] == ("no restraint needed, only the lines: INC (2 units: incubator); flexible connections"
                            " — gas: a flexible connector (FEMA E-74 (2012) §6.4)")
    assert sentences[2].startswith("already anchored, only the lines: MS (1 unit: analyser)")


def test_the_sample_workbooks_mark_their_mobile_items():
    folder = Path(__file__).resolve().parents[2] / "inventories"
    hospital = read_workbook(folder / "hospital.xlsx").equipment.set_index("id")["casters"]
    assert set(hospital[hospital].index) == {"ED-0-01", "ED-0-04", "PT-3-03"}
    assert not hospital["ED-0-02"]


def _sine_record(folder: Path, ap_g: float, tp_s: float) -> tuple[Path, np.ndarray]:
    time_s = np.arange(0.0, tp_s + DT_S / 2, DT_S)
    accel = np.concatenate([ap_g * np.sin(2 * np.pi * time_s / tp_s), np.zeros(int(4.0 / DT_S))])
    path = folder / "pulse.csv"
    pd.DataFrame({"time_s": np.arange(accel.size) * DT_S, "accel_g": accel}).to_csv(path, index=False)
    return path, accel


def test_lowering_the_centre_of_mass_stops_a_slender_block_overturning_under_a_pulse(tmp_path):
    """A 2 m tall, 40 cm wide block (μ 0.9: it rocks, never slides) under a one-sine pulse of 0.45 g, 4 s.

    As loaded (centre of mass at 1.0 m, tan α = 0.2) the pulse is 2.25 g tan α for longer than the
    block takes to fall: the independent Housner ODE overturns it. With its contents low (centre of mass
    at 0.2 of its height, 0.4 m) the static tipping condition needs a ≥ g b/h = 0.5 g, and sliding
    a ≥ μ g = 0.9 g: below both, the block cannot move at all, so the engine must give no uplift and no
    overturning. Along its 2 m depth it cannot move either way (b/h ≥ 1 > 0.45)."""
    ap_g, tp_s = 0.45, 4.0
    path, accel = _sine_record(tmp_path, ap_g, tp_s)
    half_width_m, height_m, fraction = 0.2, 2.0, 0.2
    assert ap_g < half_width_m / (fraction * height_m) < 0.9  # the closed form's premise, lowered
    alpha = np.arctan(half_width_m / (height_m / 2))
    p = np.sqrt(3 * 9.80665 / (4 * np.hypot(half_width_m, height_m / 2)))
    as_loaded = reference_rocking(np.concatenate([accel, np.zeros(int(6 / DT_S))]), DT_S, alpha, p,
                                  1 - 1.5 * np.sin(alpha) ** 2)
    assert as_loaded["overturned"]
    item = {"id": "TALL", "name": "tall shelving", "room": "R1", "floor": 0, "height_m": height_m,
            "width_m": 2 * half_width_m, "depth_m": 2.0, "mass_kg": 200.0, "mu": 0.9, "mu_static": 0.9,
            "clearance_m": 0.2, "cg_height_m": height_m / 2, "anchored": False, "casters": False, "quantity": 1,
            "contents": "movable", "row": 2}
    hazard = pd.DataFrame([{"level": "2in50", "level_label": "2in50", "motion": "P", "all_floors": False,
                            "floor": 0, "pta_g": np.nan, "tp_s": tp_s, "vp_m_s": 0.5, "pulse": "",
                            "record_path": str(path), "scale": 1.0, "row": 2}])
    hazard["floor"] = hazard["floor"].astype("Int64")
    settings = Settings(lower_contents_cg_fraction=fraction)
    inventory = Inventory(path=tmp_path / "one.xlsx", equipment=pd.DataFrame([item]), hazard=hazard,
                          settings=settings)
    row = run_assessment(inventory, "2in50").summary.set_index("id").loc["TALL"]
    assert row["p_overturn"] == 1.0  # the engine agrees with the reference as loaded
    assert row["action_kind"] == "lower_contents"
    assert row["p_overturn_after"] == 0.0 and row["p_beyond_clearance_after"] == 0.0
    assert "the engine finds it still" in row["action"]
    assert "it no longer rocks" in row["what_if"] and "40 cm instead of 100 cm" in row["what_if"]
