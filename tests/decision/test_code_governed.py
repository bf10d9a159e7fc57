"""Equipment a code or FEMA E-74 governs: the table is data, every name in it is one the workbook accepts, and
the action it prescribes is the item's whatever the analysis says, with the analysis's own numbers and action
beside it and the reference printed (issue 30 §2).

Checks against the table's sources as the docs quote them (UPC §507.2: two straps, upper and lower thirds;
NFPA 99: cylinders secured; ASCE 7-22 Table 13.5-1: storage more than 6 ft tall) and against the
component table the workbook reader checks types with (assess/data/components.csv), not against this code's
own output.
"""
from types import SimpleNamespace

import pytest

from assess.anchorage.coefficients import component_coefficients
from assess.inventory.settings import Settings
from assess.decision import actions
from assess.decision.actions import ActionKind
from assess.decision.code_governed import code_rule, code_rules
from assess.inventory.schema import parse_component_type
from assess.report import advice

SETTINGS = Settings(risk_pf_high=0.5, risk_pf_moderate=0.1, room_max_cm=30.0)


def _item(component_type, kind, height_m=1.8, casters=False, contents="none"):
    return SimpleNamespace(component_type=component_type, equipment_kind=kind, height_m=height_m, casters=casters,
                           contents=contents)


def _row(p_beyond=0.0, p_overturn=0.0, risk="low"):
    return {"p_beyond_clearance": p_beyond, "p_overturn": p_overturn, "p_rocking_harm": 0.0, "risk": risk,
            "consequence": "hazardous", "demand_room_cm": 8.0, "clearance_cm": 15.24, "cg_height_cm": 91.0,
            "theta_max_over_alpha": 0.1, "suite_motions": 11, "suite_histories": 11}


def test_every_name_of_the_table_is_a_component_type_the_workbook_accepts():
    for matches, rule in code_rules():
        assert ActionKind(rule.action) in ActionKind
        assert rule.reference and rule.detail
        for name in matches:
            assert parse_component_type(name, None) == component_coefficients("ASCE 7-22", name).component_type


def test_a_water_heater_is_strapped_whatever_the_analysis_says():
    """A 100-gallon gas water heater that the analysis finds low (no action): the plumbing code's two straps."""
    heater = _item("mechanical equipment", "gas water heater")
    decided = actions.decide_action(heater, _row(p_beyond=0.02), False, None, SETTINGS)
    assert decided.kind == ActionKind.STRAP and decided.analysis_kind == ActionKind.NONE
    assert (decided.p_overturn_after, decided.p_beyond_clearance_after) == (0.0, 0.0)
    columns = decided.columns()
    assert "upper third" in columns["action_detail"] and "lower third" in columns["action_detail"]
    assert columns["action_reference"].startswith("UPC §507.2")
    action, what_if = advice.code_sentences(decided, _row(p_beyond=0.02), SETTINGS)
    assert action.startswith("Strap it (water heater: required whatever the analysis says)")
    assert "Reference: UPC §507.2" in action and "FEMA E-74 (2012)" in action
    assert "the analysis alone asks for no action" in what_if
    # where the analysis finds it moving, it says what the analysis alone would do
    moving = actions.decide_action(heater, _row(p_beyond=0.8, risk="high"), False, None, SETTINGS)
    assert moving.kind == ActionKind.STRAP and moving.analysis_kind in (ActionKind.ROOM, ActionKind.RESTRAIN)
    assert "the analysis alone would" in advice.code_sentences(moving, _row(p_beyond=0.8, risk="high"), SETTINGS)[1]


def test_gas_cylinders_are_chained_and_tall_shelving_anchored_with_its_contents_restrained():
    rack = actions.decide_action(_item("storage shelving", "cylinder rack", 1.5), _row(), False, None, SETTINGS)
    assert rack.kind == ActionKind.CHAIN and "NFPA 99" in rack.code.reference
    tall = actions.decide_action(_item("storage shelving", "shelving", 84 * 0.0254), _row(), False, None, SETTINGS)
    assert tall.kind == ActionKind.ANCHOR and "shelf lips" in tall.code.detail
    assert "Table 13.5-1" in tall.code.reference
    # 6 ft (183 cm) is the line: 60 in shelving is left to the analysis
    low = actions.decide_action(_item("storage shelving", "shelving", 60 * 0.0254), _row(), False, None, SETTINGS)
    assert low.code is None and low.kind == ActionKind.NONE


@pytest.mark.parametrize("kind", ["", "laboratory equipment", "refrigerator"])
def test_equipment_the_table_does_not_name_is_left_to_the_analysis(kind):
    assert code_rule(_item(component_coefficients("ASCE 7-22", kind or None).component_type, kind)) is None


def test_a_strap_has_its_work_order_words():
    assert advice.WORK_ORDER_TEXT["strap"].startswith("strap to the wall")
    assert "chain" in advice.WORK_ORDER_TEXT["chain"]


def test_page_one_gathers_the_code_governed_items_first():
    from assess.report.sentences import action_groups

    rows = [{"id": "WH", "action_kind": "strap", "action_reference": "UPC §507.2"},
            {"id": "SH", "action_kind": "anchor", "action_reference": "ASCE 7-22 Table 13.5-1"},
            {"id": "FR", "action_kind": "anchor", "action_reference": ""},
            {"id": "OK", "action_kind": "none", "action_reference": ""}]
    groups = action_groups(rows)
    assert [(g["kind"], [r["id"] for r in g["rows"]]) for g in groups] == [
        ("code", ["WH", "SH"]), ("anchor", ["FR"]), ("none", ["OK"])]
