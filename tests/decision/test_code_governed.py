"""Equipment a code or FEMA E-74 governs: the table is data, every name in it is one the workbook accepts, and
the action it prescribes is the item's whatever the analysis says, with the analysis's own numbers and action
beside it and the reference printed (issue 30 §2).

Checks against the table's sources as the docs quote them (UPC §507.2: two straps, upper and lower thirds;
NFPA 99: cylinders secured; ASCE 7-22 Table 13.5-1: storage more than 6 ft tall) and against the
component table the workbook reader checks types with (assess/data/components.csv), not against this code's
own output.
"""
import re
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


def test_a_reference_to_asce_7_holds_on_a_site_of_either_edition():
    """The work orders print a rule's reference whatever edition the site sheet names: one that cited
    "ASCE 7-22 §13.5" read so on an ASCE 7-16 site. A reference to ASCE 7 names no edition, or both, and the
    component type its rule takes is a row of both editions' tables."""
    cited = [rule for _, rule in code_rules() if "ASCE 7" in rule.reference]
    assert cited, "the table's tall-shelving row cites ASCE 7 Table 13.5-1"
    for rule in cited:
        editions = set(re.findall(r"7-(\d\d)", rule.reference))
        assert editions in (set(), {"16", "22"}), rule.reference
        for edition in ("ASCE 7-16", "ASCE 7-22"):
            assert component_coefficients(edition, rule.component_type).component_type == rule.component_type


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


def test_a_ups_battery_cabinet_is_anchored_whatever_the_analysis_says():
    """A data centre's 2,800 lb UPS battery cabinet that the analysis gave room to (a new user's, 2026-11-29):
    FEMA E-74's batteries and battery racks are anchored and their batteries held in the rack."""
    for typed in ("battery rack", "UPS", "uninterruptible power supply"):
        ups = actions.decide_action(_item(typed, "UPS-1 battery cabinet", 2.0), _row(p_beyond=0.3, risk="moderate"),
                                    False, None, SETTINGS)
        assert ups.kind == ActionKind.ANCHOR and ups.analysis_kind != ActionKind.ANCHOR
        assert "§6.4.7" in ups.code.reference and "end rails" in ups.code.detail
    # a generator or a transformer shares the battery rack's anchorage force but is left to the analysis
    assert code_rule(_item("generator", "Backup generator")) is None

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
    assert "read from" not in groups[0]["why"]
    rows[0]["type_source"] = "name"  # the water heater's kind read from its name: page 1 asks to confirm it
    assert groups[0]["why"] != action_groups(rows)[0]["why"]
    assert action_groups(rows)[0]["why"].endswith("the kind of 1 of them was read from its name: confirm it, or "
                                                  "write component_type in the workbook")


# ---------------------------------------------------------------- the kind read from the name (no component_type)

from assess.inventory.kinds import default_connections, item_type, kind_from_name  # noqa: E402


@pytest.mark.parametrize("name, kind", [
    ("Gas water heater, 100 gal", "water heater"),
    ("WATER-HEATER (electric), 50 gal", "water heater"),
    ("Water heaters, pair", "water heater"),
    ("Oxygen cylinder rack, 12 cylinders", "gas cylinders"),
    ("Gas-cylinder rack, 4 cylinders, freestanding", "gas cylinders"),
    ("Oxygen cylinder cart, 6 E-cylinders", "gas cylinder cart"),
    ("Server rack, 42U, loaded", "computer rack"),
    ("Network rack, 24U", "computer rack"),
    ("Crash cart, 5 drawers", "medical cart"),
    ("Anesthesia cart", "medical cart"),
    ("Supply shelving, 6 shelves, loaded", "tall shelving"),
    ("Bulk IV-fluid storage rack, 5 shelves", "tall shelving"),
    ("Anesthesia supply cabinet", "tall shelving"),
    ("UPS-1 battery cabinet, 2,800 lb", "battery rack"),
    ("Rackmount UPS", "battery rack"),
    ("Battery rack, two tiers", "battery rack"),
    ("Uninterruptible power supply, 40 kVA", "battery rack"),
    ("Server rack, 42U, UPS batteries in base", "computer rack"),  # the first row with a phrase in the name wins
])
def test_the_name_selects_the_kind_its_phrase_names(name, kind):
    assert kind_from_name(name).equipment == kind


@pytest.mark.parametrize("name", [
    "Heater block, dry bath",          # "heater" without "water heater"
    "Water bath heater",               # a water bath's heater, not a water heater
    "Linen cart, covered",             # a bare cart is not a medical cart
    "Supply cart, stainless, 3 shelves",  # nor are its shelves shelving
    "Cartridge filter housing",        # "cart" inside a word
    "Hydraulic cylinder press",        # a cylinder that holds no gas
    "Rackmount KVM console",           # "rack" inside a word, no rack named
    "Battery charger, bench",          # a battery alone is not a battery rack
    "Groups of shelves",               # "ups" inside a word
    "Serverless kiosk",
    "MRI gradient cabinet",            # a cabinet alone is not storage
    "Biological safety cabinet, class II",
    "Shelf-stable food freezer",       # "shelf" is not shelving
    "Water heaterless sink",
])
def test_near_miss_names_select_nothing(name):
    assert kind_from_name(name) is None


def test_a_named_item_takes_the_kind_s_type_contents_and_lines_and_the_advice_asks_to_confirm_it():
    """The lead's new-user check: without component_type the Seattle hospital's gas water heater got
    "restrain", its oxygen rack "anchor", its server rack and crash cart nothing; now each gets its code's
    action, with the type read from its name (and the water heater's gas line from its name) said in the advice."""
    heater = item_type({"name": "Gas water heater, 100 gal", "component_type": "", "contents": ""}, {})
    assert heater == {"component_type": "mechanical equipment", "equipment_kind": "water heater", "type_source": "name",
                      "contents": "none", "connections": "gas, fluid", "connections_assumed": True}
    rack = item_type({"name": "Server rack, 42U, loaded", "component_type": ""}, {})
    assert (rack["component_type"], rack["contents"], rack["connections"]) == ("computer rack", "fixed", "none")
    shelving = item_type({"name": "Spare-parts shelving", "component_type": ""}, {})
    assert (shelving["component_type"], shelving["contents"]) == ("storage shelving", "movable")
    # typed: the name is not read, whatever it says
    typed = item_type({"name": "Gas water heater", "component_type": "laboratory equipment"},
                      {"component_type": "lab"})
    assert (typed["type_source"], typed["equipment_kind"], typed["connections"]) == ("typed", "lab", "none")
    assert item_type({"name": "Chemistry analyser", "component_type": ""}, {})["type_source"] == "default"

    item = SimpleNamespace(**heater, height_m=72 * 0.0254, casters=False, name="Gas water heater, 100 gal")
    decided = actions.decide_action(item, _row(p_beyond=0.8, risk="high"), False, None, SETTINGS)
    assert decided.kind == ActionKind.STRAP and decided.type_source == "name"
    assert decided.connections == ("gas", "fluid") and decided.connections_assumed
    action, _ = advice.code_sentences(decided, _row(p_beyond=0.8, risk="high"), SETTINGS)
    assert "was read from its name: confirm it" in action
    lines = advice.connection_sentence(decided)
    assert lines.startswith("Its gas line: a flexible connector") and "FEMA E-74 (2012) §6.4" in lines
    assert "Its water or fluid lines: flexible hoses" in lines
    assert "assumed from its kind (read from its name)" in lines
    columns = decided.columns()
    assert columns["connection_detail"].startswith("gas: a flexible connector")
    assert "§6.4.1.3" in columns["connection_reference"]


@pytest.mark.parametrize("name, expected", [
    ("Electric water heater", ("fluid",)),          # a water heater always has water lines
    ("Gas water heater", ("gas", "fluid")),          # and a gas line where its name says gas
    ("Gas-cylinder rack", ()),                       # "gas" in a cylinder rack's name is no line
    ("Crash cart", ()),
])
def test_the_lines_of_a_kind_where_the_workbook_gives_none(name, expected):
    assert default_connections(kind_from_name(name), name) == expected


def test_a_bare_cart_type_is_no_code_rule():
    """component_type `cart` is medical equipment for the force (components.csv) but selects no code rule:
    a linen or supply cart is left to the analysis (tether or lock its casters); `crash cart` selects it."""
    assert code_rule(_item("medical equipment", "cart", 1.1, casters=True)) is None
    assert code_rule(_item("medical equipment", "crash cart", 1.1, casters=True)).equipment == "medical cart"


def test_the_tables_of_many_items_give_a_code_action_s_head_and_send_its_detail_to_the_work_orders():
    """A code-prescribed action's detail and reference filled the narrow 'What to do' column of the tables that
    list many items 40 lines deep (the lab's report grew from 56 to 62 pages): those tables give the
    sentence's head, the rest of the sentence stands whole in summary.csv, the work orders and Appendix A."""
    heater = item_type({"name": "Gas water heater, 100 gal", "component_type": "", "contents": ""}, {})
    item = SimpleNamespace(**heater, height_m=72 * 0.0254, casters=False, name="Gas water heater, 100 gal")
    decided = actions.decide_action(item, _row(p_beyond=0.8, risk="high"), False, None, SETTINGS)
    action, _ = advice.code_sentences(decided, _row(p_beyond=0.8, risk="high"), SETTINGS)
    brief = advice.brief_action(action, "name")
    head = action.split(advice.CODE_REQUIRED)[0] + advice.CODE_REQUIRED
    assert brief.startswith(head) and head.startswith("Strap it (water heater")
    assert decided.code.detail in action and decided.code.detail not in brief
    assert decided.code.reference not in brief and "in the work orders and Appendix A" in brief
    assert brief.endswith("its kind was read from its name: confirm it.")
    assert advice.brief_action("Give it room: it needs 18 cm.", "name") == "Give it room: it needs 18 cm."
