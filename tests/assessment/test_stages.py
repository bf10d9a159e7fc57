"""The stages' seams: the input rules hold for a library call, the decisions follow the documented rule.

No engine runs here: the input check comes before any record is read, and the
decisions are fed hand-written demand rows, so each expectation is the rule as
docs/outputs.md states it (``risk_pf_high``, ``risk_pf_moderate``), not a
number the pipeline produced.
"""
from pathlib import Path

import dataclasses
import numpy as np
import pandas as pd
import pytest

from assessed import run_assessment
from assess.inventory.settings import Settings
from assess.decision import decisions
from assess.errors import InputError
from assess.report.advice import item_words
from assess.fragility.friction_range import mu_dependence_sentence
from assess.fragility.regression import RegressionConstants
from assess.inventory import Inventory


def _item(item_id, anchored=False):
    return {"id": item_id, "name": f"item {item_id}", "room": "R1", "floor": 0, "height_m": 2.0, "width_m": 0.6,
            "depth_m": 0.8, "mass_kg": 200.0, "mu": 0.3, "mu_static": 0.3, "clearance_m": 0.3, "cg_height_m": 1.0,
            "anchored": anchored, "quantity": 1, "row": 2}


def _motion(record_path="", vp_m_s=-0.75, row=2):
    return {"level": "2in50", "level_label": "2in50", "motion": f"M{row}", "all_floors": False, "floor": 0,
            "pta_g": 0.5, "tp_s": 1.0, "vp_m_s": vp_m_s, "pulse": "B", "record_path": record_path, "scale": 1.0,
            "row": row}


def test_a_library_call_is_held_to_the_hazard_sheets_rules(tmp_path):
    """run_assessment refuses a record outside the workbook's folder and a vp of 0, each at its row and
    column, before reading any record (the record named here is not even a valid file)."""
    (tmp_path / "site").mkdir()
    outside = tmp_path / "elsewhere.csv"
    outside.write_text("not a record\n")
    hazard = pd.DataFrame([_motion(str(outside), row=2), _motion(vp_m_s=0.0, row=3)])
    hazard["floor"] = hazard["floor"].astype("Int64")
    inventory = Inventory(path=tmp_path / "site" / "lab.xlsx", equipment=pd.DataFrame([_item("A")]), hazard=hazard,
                          settings=Settings())
    with pytest.raises(InputError) as refused:
        run_assessment(inventory, "2in50")
    located = [(p.sheet, p.row, p.column) for p in refused.value.problems]
    assert located == [("hazard", 2, "record"), ("hazard", 3, "vp_cm_s")]
    with pytest.raises(InputError) as refused:
        run_assessment(inventory, "2in50", allow_records_outside=True)
    assert [(p.row, p.column) for p in refused.value.problems] == [(3, "vp_cm_s")]


def _demand_row(p_beyond, p_overturn=0.0, p_rocking_harm=0.0):
    return {"p_beyond_clearance": p_beyond, "p_beyond_clearance_low": p_beyond, "p_beyond_clearance_high": p_beyond,
            "p_overturn": p_overturn, "p_overturn_low": p_overturn, "p_overturn_high": p_overturn,
            "p_rocking_harm": p_rocking_harm, "p_rocking_harm_low": p_rocking_harm,
            "p_rocking_harm_high": p_rocking_harm, "demand_room_cm": 42.0, "theta_max_over_alpha": 0.0,
            "suite_motions": 3, "suite_histories": 3, "demand_note": "From 3 motions."}


def test_decisions_follow_the_thresholds_and_rank_the_items():
    equipment = pd.DataFrame([_item("LOW"), _item("MID"), _item("HIGH"), _item("FIXED", anchored=True),
                              _item("TIPS")])
    governing = {"LOW": _demand_row(0.05), "MID": _demand_row(0.2), "HIGH": _demand_row(0.6),
                 "TIPS": _demand_row(0.0, p_overturn=1 / 3)}
    uplift = {"LOW": False, "MID": False, "HIGH": False, "TIPS": True}
    cases = pd.DataFrame({"id": ["LOW"], "mode": ["slide"], "im_outside_fit": [False]})
    settings = Settings(risk_pf_high=0.5, risk_pf_moderate=0.1)
    constants = RegressionConstants.from_settings(settings)
    decided = decisions.decide(equipment, governing, uplift, cases, pd.DataFrame(), constants, settings)
    by_item = {i: {**row, **item_words(decided.items[i], settings)} for i, row in decided.by_item.items()}
    assert [by_item[i]["risk"] for i in ("LOW", "MID", "HIGH", "TIPS", "FIXED")] == [
        "low", "moderate", "high", "high", "anchored"]
    # each has 30 cm: the 12 cm more it needs is within room_max_cm (30 cm): room for both
    assert [by_item[i]["action_kind"] for i in ("LOW", "MID", "HIGH", "TIPS")] == ["none", "room", "room", "anchor"]
    assert by_item["MID"]["action"].startswith("Give it room: it needs 42 cm to be low risk and has 30 cm")
    # with no room to spare: restrain
    assert by_item["TIPS"]["action"] == "Anchor it to the floor or wall: it overturns under 1 of its 3 motions"
    tight_settings = dataclasses.replace(settings, room_max_cm=11.0)
    tight = decisions.decide(equipment, governing, uplift, cases, pd.DataFrame(), constants, tight_settings)
    tight = {i: {**row, **item_words(tight.items[i], tight_settings)} for i, row in tight.by_item.items()}
    assert [tight[i]["action_kind"] for i in ("MID", "HIGH")] == ["restrain", "restrain"]
    assert tight["MID"]["action"].startswith(
        "Restrain it against sliding (edge stops, bumpers or cable restraints): it needs 42 cm to be low risk and "
        "has 30 cm (20% chance of "
        "sliding past it): 12 cm more, beyond the 11 cm a room can spare")
    # ordinary items: overturning 1/3 outranks 0.5 x 0.6 sliding, then 0.5 x 0.2; no action and anchored last, by id
    assert sorted(by_item, key=lambda i: by_item[i]["priority"]) == ["TIPS", "HIGH", "MID", "FIXED", "LOW"]
    assert decided.flags == [] and all(by_item[i]["flags"] == () for i in governing)


def test_an_item_whose_class_changes_over_its_mu_range_says_so():
    end = pd.Series({"mu_low": 0.13, "mu_high": 0.23, "p_beyond_clearance_low": 0.6, "p_overturn_low": 0.0,
                     "p_rocking_harm_low": 0.0, "demand_uplift_low": False, "p_beyond_clearance_high": 0.0,
                     "p_overturn_high": 0.0, "p_rocking_harm_high": 0.0, "demand_uplift_high": False},
                    name="INC-G-01")
    settings = Settings()
    decided = decisions.mu_range_decision(end, "high", "From 3 motions.", "critical", settings)
    assert (decided["risk_mu_low"], decided["risk_mu_high"]) == ("high", "low")
    sentence = mu_dependence_sentence("INC-G-01", 0.13, 0.23, "high", "high", "low",
                                      "60% chance of sliding past its room", "0% chance of overturning")
    assert decided["mu_range_note"] == sentence and decided["demand_note"] == f"From 3 motions. {sentence}"
    assert np.isnan(decisions.NO_MU_RANGE["mu_low"]) and decisions.NO_MU_RANGE["risk_mu_low"] == ""


def test_a_cases_mode_is_its_most_frequent_and_a_tie_goes_to_the_more_severe():
    import numpy as np

    from assess.assessment.run import majority_modes
    from assess.mechanics.modes import REST, ROCK, SLIDE, SLIDE_ROCK

    case = np.array([2, 0, 0, 0, 1, 1, 2, 2, 1, 1])
    mode = [SLIDE, REST, SLIDE, REST, ROCK, SLIDE, SLIDE_ROCK, SLIDE_ROCK, SLIDE, ROCK]
    assert majority_modes(case, mode).to_dict() == {0: REST, 1: ROCK, 2: SLIDE_ROCK}
