"""What to do about each item: risk class, action, priority, anchorage, what-if and flags.

The decisions stage of the assessment (:func:`decide`, after the demand
stage :mod:`assess.assessment.demand`): every function here is a pure
function of an item's governing demand and the settings. The risk rule is
one function, :func:`classify_risk`, fed by the demand
(``p_beyond_clearance``, ``p_overturn``, ``uplift``): replacing the rule
means replacing that function. What the report says about an item is
built from these fields (:mod:`assess.report.sentences`); the columns are
those of ``summary.csv`` (docs/outputs.md).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from assess.fragility.anchorage import (
    COMPONENT_AMPLIFICATION, COMPONENT_RESPONSE_MODIFICATION, base_overturning, component_design_force,
    importance_factor,
)
from assess.fragility.friction_range import mu_dependence_sentence
from assess.fragility.regression import RegressionConstants
from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2
from assess.mechanics.modes import ROCK, SLIDE_ROCK
from assess.result import Flag

UPLIFT_MODES = (ROCK, SLIDE_ROCK)


def item_consequence(item) -> str:
    """What an item's failure costs (the workbook's ``consequence``; ``ordinary`` where not given)."""
    return str(getattr(item, "consequence", "") or "ordinary")


#: What an anchored item's row says (it is not analysed as freestanding).
ANCHORED = {"mode": "", "risk": "anchored", "action": "None: anchored (not analysed as freestanding)",
            "action_kind": "anchored", "flags": ()}


@dataclass
class Decisions:
    """The decisions stage's output: per item (``by_item``: id -> the summary's decision columns, in
    :data:`assess.result.SUMMARY_COLUMNS`) and the flags of every item, in item order."""

    by_item: dict
    flags: list


def decide(equipment: pd.DataFrame, governing: dict, uplift: dict, cases: pd.DataFrame, at_mu_ends: pd.DataFrame,
           constants: RegressionConstants, settings: dict) -> Decisions:
    """Every item's decisions from its governing demand (``governing``: id -> its demand row,
    :func:`assess.assessment.demand.item_rows`; ``uplift``: id -> whether it uplifts; ``cases``: the
    cases at the workbook's μ; ``at_mu_ends``: the demand at the ends of a μ range).

    An anchored item is not analysed (:data:`ANCHORED`); a freestanding one gets :func:`item_flags`,
    :func:`decide_item` and, with a μ range, :func:`mu_range_decision`; then every item its
    :func:`priorities` rank.
    """
    by_item, flags = {}, []
    for item in equipment.itertuples(index=False):
        decided = dict(NO_MU_RANGE)
        if item.anchored:
            by_item[item.id] = {**ANCHORED, **decided}
            continue
        row = {"consequence": item_consequence(item), "clearance_cm": item.clearance_m * 100.0,
               **governing[item.id]}
        found = item_flags(item, cases[cases["id"] == item.id], constants)
        flags.extend(found)
        decided["flags"] = tuple(flag.code for flag in found)
        decided.update(decide_item(item, row, uplift[item.id], settings))
        if item.id in at_mu_ends.index:
            decided.update(mu_range_decision(at_mu_ends.loc[item.id], decided["risk"], row["demand_note"], settings))
        by_item[item.id] = decided
    table = pd.DataFrame({"id": list(by_item), **{column: [d.get(column, np.nan) for d in by_item.values()]
                                                  for column in ("action_kind", "priority_score")}})
    for item_id, rank in zip(table["id"], priorities(table)):
        by_item[item_id]["priority"] = int(rank)
    return Decisions(by_item, flags)


#: The μ-range columns of an item without a range (or anchored).
NO_MU_RANGE = {"mu_low": np.nan, "mu_high": np.nan, "risk_mu_low": "", "risk_mu_high": "",
               "p_beyond_clearance_mu_low": np.nan, "p_beyond_clearance_mu_high": np.nan, "mu_range_note": ""}


def mu_range_decision(end: pd.Series, risk: str, demand_note: str, settings: dict) -> dict:
    """For an item with a range of friction: its risk class with every run at ``mu_low`` and at
    ``mu_high`` (:func:`classify_risk` of the demand at each end, ``end``: its row of
    :func:`assess.fragility.friction_range.demand_at_ends`), and
    :func:`~assess.fragility.friction_range.mu_dependence_sentence` in ``mu_range_note`` and at the end
    of ``demand_note``."""
    classes = {side: classify_risk(float(end[f"p_beyond_clearance_{side}"]), float(end[f"p_overturn_{side}"]),
                                   bool(end[f"demand_uplift_{side}"]), settings) for side in ("low", "high")}
    chances = {side: float(end[f"p_beyond_clearance_{side}"]) for side in ("low", "high")}
    low, high = float(end["mu_low"]), float(end["mu_high"])
    sentence = mu_dependence_sentence(end.name, low, high, risk, classes["low"], classes["high"],
                                      chances["low"], chances["high"])
    return {"mu_low": low, "mu_high": high, "risk_mu_low": classes["low"], "risk_mu_high": classes["high"],
            "p_beyond_clearance_mu_low": chances["low"], "p_beyond_clearance_mu_high": chances["high"],
            "mu_range_note": sentence, "demand_note": f"{demand_note} {sentence}".strip()}


def classify_risk(p_beyond_clearance: float, p_overturn: float, uplift: bool, settings: dict) -> str:
    """Risk class from the governing demand.

    ``high`` when the item overturns under any motion of its suite
    (``p_overturn`` > 0), uplifts (rocks) under any, or slides past its
    clearance with probability ≥ ``risk_pf_high``; ``moderate`` when that
    probability ≥ ``risk_pf_moderate``; else ``low``.

    >>> settings = {"risk_pf_high": 0.5, "risk_pf_moderate": 0.1}
    >>> classify_risk(0.2, 0.0, False, settings), classify_risk(0.0, 0.1, True, settings)
    ('moderate', 'high')
    """
    if p_overturn > 0.0 or uplift or p_beyond_clearance >= float(settings["risk_pf_high"]):
        return "high"
    if p_beyond_clearance >= float(settings["risk_pf_moderate"]):
        return "moderate"
    return "low"


def risk_range(risk: str, classes: set) -> str:
    """The classes the 90 % interval of P(sliding > clearance) spans, when it spans more than ``risk``."""
    classes = classes | {risk}
    if len(classes) == 1:
        return ""
    order = ["low", "moderate", "high"]
    spanned = sorted(classes, key=order.index)
    return f"{spanned[0]} to {spanned[-1]}"


def decide_item(item, row: dict, uplift: bool, settings: dict) -> dict:
    """The decisions for one freestanding item from its governing demand ``row`` (a dict holding
    ``p_beyond_clearance`` and its interval, ``p_overturn``, ``demand_room_cm``, ``clearance_cm``,
    ``consequence``, ``theta_max_over_alpha``, ``suite_motions``, ``suite_histories``) and whether it
    uplifts under any motion (``uplift``).

    Returns ``risk``, ``risk_range``, ``action``, ``action_kind``, the anchorage columns
    (:func:`anchorage_demand`), ``what_if`` and ``priority_score``.
    """
    decided = {"risk": classify_risk(row["p_beyond_clearance"], row["p_overturn"], uplift, settings)}
    bounds = {classify_risk(p, row["p_overturn"], uplift, settings)
              for p in (row["p_beyond_clearance_low"], row["p_beyond_clearance_high"])}
    decided["risk_range"] = risk_range(decided["risk"], bounds)
    row = {**row, **decided}
    decided["action"] = recommended_action(row, uplift, settings)
    decided["action_kind"] = row["action_kind"] = action_kind(row, uplift)
    decided.update(anchorage_demand(item, row, settings))
    decided["what_if"] = what_if(row, settings)
    decided["priority_score"] = priority_score(row["consequence"], row["p_overturn"], row["p_beyond_clearance"],
                                               uplift)
    return decided


def action_kind(row: dict, uplift: bool) -> str:
    """What the action asks for, in one word the report groups by: ``anchor`` (it overturns or
    rocks), ``restrain`` (high risk of sliding past its room), ``room`` (moderate), ``none``.

    >>> action_kind({"p_overturn": 0.0, "risk": "moderate"}, False)
    'room'
    """
    if row["p_overturn"] > 0.0 or uplift:
        return "anchor"
    return {"high": "restrain", "moderate": "room"}.get(row["risk"], "none")


def recommended_action(row: dict, uplift: bool, settings: dict) -> str:
    """A plain sentence a facility manager can act on, from the item's governing demand.

    The room to give is the sliding that is exceeded with probability
    ``risk_pf_moderate`` (``demand_room_cm``): with that much room the item
    would be low risk on sliding. It is rounded up and the clearance down, so
    the two never read alike.
    """
    if row["p_overturn"] > 0.0:
        return f"Anchor: it overturns under {suite_share_text(row['p_overturn'], row)}"
    if uplift:
        return (f"Anchor or restrain: it uplifts and rocks (peak rotation {row['theta_max_over_alpha']:.2f} of "
                f"its overturning angle alpha) but did not overturn under its {int(row['suite_motions'])} "
                f"motion{'s' if row['suite_motions'] != 1 else ''}")
    if row["risk"] in ("high", "moderate"):
        verb = "Restrain it, or give it room" if row["risk"] == "high" else "Give it room, or restrain it"
        return (f"{verb}: it needs {np.ceil(row['demand_room_cm']):.0f} cm to be low risk and has "
                f"{np.floor(row['clearance_cm']):.0f} cm ({row['p_beyond_clearance']:.0%} chance of sliding past it)")
    return "No action needed"


def suite_share_text(probability: float, row: dict) -> str:
    """"2 of its 3 motions" for records, "12 % of its 30 synthetic histories" otherwise."""
    motions, histories = int(row["suite_motions"]), int(row["suite_histories"])
    if histories == motions:
        count = probability * motions
        if abs(count - round(count)) > 1e-9:  # runs weighted over a range of mu
            return f"a weighted {probability:.0%} of its {motions} motion{'s' if motions != 1 else ''} over its range of mu"
        return f"{int(round(count))} of its {motions} motion{'s' if motions != 1 else ''}"
    return f"{probability:.0%} of its {histories} simulated histories ({motions} motion{'s' if motions != 1 else ''})"


def what_if(row: dict, settings: dict) -> str:
    """The item's risk if the action is taken, in one sentence from its own numbers (its governing demand).

    >>> what_if({"action_kind": "room", "demand_room_cm": 54.2, "clearance_cm": 20.0, "p_overturn": 0.0},
    ...         {"risk_pf_moderate": 0.1})
    'Anchored or restrained, it would neither slide nor overturn. Given 55 cm of room (it has 20 cm), its chance of sliding past it would be 10%: low risk.'
    """
    kind = row.get("action_kind")
    if kind not in ("anchor", "restrain", "room"):
        return ""
    anchored = "Anchored or restrained, it would neither slide nor overturn."
    if kind == "anchor":
        return anchored + (" Giving it room does not help: it overturns or rocks where it stands.")
    room = float(np.ceil(row["demand_room_cm"]))
    return (f"{anchored} Given {room:.0f} cm of room (it has {np.floor(row['clearance_cm']):.0f} cm), its chance of "
            f"sliding past it would be {float(settings['risk_pf_moderate']):.0%}: low risk.")


def anchorage_demand(item, row: dict, settings: dict) -> dict:
    """For an item to anchor or restrain: the ASCE 7-16 §13.3.1 design force and what it does at the base
    (:mod:`assess.fragility.anchorage`), about the base edge of the more slender direction.

    ``anchor_force_kn`` (F_p, per unit), ``anchor_moment_knm``, ``anchor_tension_kn`` and
    ``anchor_basis`` (the factors used, in words); NaN and a sentence saying what is missing where
    ``sds_g`` is not in the settings.
    """
    empty = {"anchor_force_kn": np.nan, "anchor_moment_knm": np.nan, "anchor_tension_kn": np.nan,
             "anchor_basis": ""}
    if row.get("action_kind") not in ("anchor", "restrain"):
        return empty
    sds_g = float(settings.get("sds_g", 0.0))
    if not sds_g > 0.0:
        return {**empty, "anchor_basis": "add sds_g (and roof_floor) to the settings for the ASCE 7-16 design force"}
    roof = float(settings.get("roof_floor", 0.0))
    z_over_h = min(max(float(item.floor) / roof, 0.0), 1.0) if roof > 0.0 else 1.0
    importance = importance_factor(row.get("consequence", "ordinary"))
    weight_n = float(item.mass_kg) * STANDARD_GRAVITY_M_S2
    force_n = float(component_design_force(weight_n, sds_g, z_over_h, importance))
    half_width_m = min(float(item.width_m), float(item.depth_m)) / 2.0
    moment_nm, tension_n = (float(x) for x in base_overturning(force_n, float(item.cg_height_m), weight_n,
                                                               half_width_m, sds_g))
    basis = (f"ASCE 7-16 eqs. 13.3-1 to 13.3-3: a_p {COMPONENT_AMPLIFICATION:g}, R_p "
             f"{COMPONENT_RESPONSE_MODIFICATION:g} (Table 13.5-1), I_p {importance:g} (§13.1.3), S_DS {sds_g:g} g, "
             f"z/h {z_over_h:.2f}{'' if roof > 0.0 else ' (roof_floor not given: z/h = 1)'}; W_p "
             f"{weight_n / 1000:.2f} kN per unit; tension from 0.9D - 1.0E with E_v = 0.2 S_DS D, "
             "without the overstrength factor for anchors in concrete (§13.4.2)")
    return {"anchor_force_kn": force_n / 1000.0, "anchor_moment_knm": moment_nm / 1000.0,
            "anchor_tension_kn": tension_n / 1000.0, "anchor_basis": basis}


#: Weight of what an item's failure costs (the workbook's ``consequence``), for the order of action.
CONSEQUENCE_WEIGHTS = {"life-safety": 5.0, "hazardous": 4.0, "critical": 3.0, "valuable": 2.0, "ordinary": 1.0}
#: Share of an overturning's cost that sliding past the room carries (it hits, pulls its lines, blocks).
SLIDING_SEVERITY = 0.5
#: Stand-in probability of overturning for an item that rocks but did not overturn under its motions.
UPLIFT_SEVERITY = 0.25


def priority_score(consequence: str, p_overturn: float, p_beyond_clearance: float, uplift: bool) -> float:
    """How urgent an item is: its consequence weight times the worst of its chances, overturning
    counting fully, sliding past its room by :data:`SLIDING_SEVERITY`, rocking without overturning by
    :data:`UPLIFT_SEVERITY`.

    >>> priority_score("hazardous", 0.2, 0.0, True), priority_score("ordinary", 0.0, 1.0, False)
    (1.0, 0.5)
    """
    weight = CONSEQUENCE_WEIGHTS.get(str(consequence), 1.0)
    return weight * max(p_overturn, SLIDING_SEVERITY * p_beyond_clearance, UPLIFT_SEVERITY if uplift else 0.0)


def priorities(summary: pd.DataFrame) -> pd.Series:
    """``priority``: 1 = act first, by ``priority_score`` (ties by id); items that need no action and
    anchored items come last, in id order."""
    needs = ~summary["action_kind"].isin(["none", "anchored"])
    score = summary["priority_score"].where(needs, -1.0).fillna(-1.0)
    order = pd.DataFrame({"score": -score, "id": summary["id"].astype(str)}).sort_values(
        ["score", "id"], kind="mergesort").index
    ranks = pd.Series(0, index=summary.index)
    ranks.loc[order] = np.arange(1, len(order) + 1)
    return ranks


def item_flags(item, item_cases: pd.DataFrame, constants: RegressionConstants) -> list[Flag]:
    """The caveats of one freestanding item's result, from its cases (every motion and direction)."""
    flags = []
    uplift = item_cases[item_cases["mode"].isin(UPLIFT_MODES)]
    if len(uplift):
        # the most slender direction, then the strongest motion
        worst = uplift.sort_values(["b_over_h", "pta_g"], ascending=[True, False], kind="stable").iloc[0]
        flags.append(Flag(item.id, "uplift", (
            f"{worst['mode']} under {worst['motion']} in direction {int(worst['direction'])} "
            f"(simulated; peak theta/alpha {worst['sim_theta_max_over_alpha']:.2f}"
            f"{', overturned' if worst['sim_overturned'] else ''}): "
            f"mu_static = {item.mu_static:.2f} >= b/h = {worst['b_over_h']:.2f} and PTA = {worst['pta_g']:.2f} g "
            f"> g b/h. The sliding regression assumes no uplift; the simulation answers for this item.")))
    outside = item_cases[item_cases["im_outside_fit"]]
    if len(outside):
        ims = ", ".join(f"{im:.2f}" for im in sorted(set(outside["im"].round(2))))
        flags.append(Flag(item.id, "im_outside_fit", (
            f"IM = {ims} lies outside the range {constants.im_min:.2f}-{constants.im_max:.2f} the "
            f"regression was fitted on: its numbers shown beside are an extrapolation, and the governing "
            f"demand does not use them for those motions.")))
    if "derived" in item_cases and item_cases["derived"].any():
        flags.append(Flag(item.id, "derived_floor_motion", (
            f"floor {item.floor} has no motion in the workbook: it was assessed under the ground motions "
            f"amplified by ASCE 7-16 eq. 13.3-1 (--derive-floors), an envelope rule, not a floor "
            f"response analysis.")))
    if not np.isclose(item.cg_height_m, item.height_m / 2.0):
        flags.append(Flag(item.id, "cg_not_mid_height", (
            f"centre of mass at {item.cg_height_m * 100:.0f} cm, not mid-height: alpha and b/h use it; "
            "p assumes the mass spread over the whole box.")))
    return flags


def with_input_warnings(decided: Decisions, warnings) -> Decisions:
    """``decided`` with a flag per plausibility warning of the workbook (``warnings``:
    :class:`assess.inventory.plausibility.Implausible`, each naming its item and cell), after the item's own
    flags; the item is assessed as written."""
    if not warnings:
        return decided
    by_item = {item_id: dict(row) for item_id, row in decided.by_item.items()}
    added = []
    for warning in warnings:
        added.append(Flag(warning.item_id, "implausible_input", str(warning.problem)))
        codes = tuple(by_item[warning.item_id].get("flags", ()))
        if "implausible_input" not in codes:
            by_item[warning.item_id]["flags"] = codes + ("implausible_input",)
    order = {item_id: k for k, item_id in enumerate(by_item)}
    flags = sorted(list(decided.flags) + added, key=lambda flag: order.get(flag.item_id, len(order)))
    return Decisions(by_item, flags)
