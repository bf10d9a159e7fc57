"""What to do about each item: risk class, action, priority, anchorage, what-if and flags.

The decisions stage of the assessment (:func:`decide`, after the demand
stage :mod:`assess.assessment.demand`): every function here is a pure
function of an item's governing demand and the settings. The risk rule is
:func:`assess.decision.risk_classes.classify_risk`, fed by the demand's probabilities
of each failure mode (``p_overturn``, ``p_beyond_clearance``, ``p_rocking_harm``)
and the item's consequence: replacing the rule means replacing that module.

The stage gives numbers (SI) and kinds only, one frozen :class:`ItemDecision` per item, and knows nothing of
the units the report is written in: what the report and the files say about an item (its action, what-if,
why it is in its class, the anchorage's basis and its forces in kip) is made from it by
:mod:`assess.report.advice`. The columns are those of ``summary.csv`` (docs/outputs.md).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from types import MappingProxyType

import numpy as np
import pandas as pd

from assess.anchorage import AnchorageSite, ItemAnchorage, anchorage_site, item_anchorage
from assess.decision import actions
from assess.decision.actions import ActionDecision, ActionKind
from assess.decision.flags import Flag
from assess.decision.risk_classes import (
    ROCKING_HARM_SEVERITY, SLIDING_SEVERITY, Chances, classify_risk, deciding_chance, performance_objective,
    risk_range, rocking_harm_counts,
)
from assess.fragility.friction_range import mu_dependence_sentence
from assess.fragility.regression import RegressionConstants
from assess.inventory.settings import Settings
from assess.mechanics.modes import ROCK, SLIDE_ROCK
from assess.quantity_text import floor_numbering_of, floor_text

UPLIFT_MODES = (ROCK, SLIDE_ROCK)


def item_consequence(item) -> str:
    """What an item's failure costs (the workbook's ``consequence``; ``ordinary`` where not given)."""
    return str(getattr(item, "consequence", "") or "ordinary")


#: What an anchored item's row holds (it is not analysed as freestanding).
ANCHORED = {"mode": "", "risk": "anchored", "action_kind": ActionKind.ANCHORED.value, "action_mode": "",
            "action_analysis": ActionKind.ANCHORED.value, "action_detail": "", "action_reference": "", "flags": (),
            "performance_objective": "", "p_overturn_after": np.nan, "p_beyond_clearance_after": np.nan}
#: The action of an anchored item.
ANCHORED_ACTION = ActionDecision(ActionKind.ANCHORED, np.nan, np.nan)


def anchored_action(item) -> ActionDecision:
    """The action of an anchored item (:data:`ANCHORED_ACTION`) with its type's source and its lines, whose
    flexible connections it takes all the same."""
    return ActionDecision(ActionKind.ANCHORED, np.nan, np.nan,
                          type_source=str(getattr(item, "type_source", "") or "default"),
                          connections=actions.item_connections(item),
                          connections_assumed=bool(getattr(item, "connections_assumed", False)))


@dataclass(frozen=True)
class ItemDecision:
    """What was decided for one item, in numbers and kinds (SI): the words a reader sees are made from it
    by :mod:`assess.report.advice`.

    ``risk``: its class (``anchored`` for an anchored item); ``chances``: its chances (None where anchored);
    ``action``: :class:`~assess.decision.actions.ActionDecision`; ``anchorage``:
    :class:`~assess.anchorage.ItemAnchorage`; ``demand``: the governing demand the decision read (lengths in
    cm; empty where anchored).
    """

    item_id: str
    risk: str
    consequence: str
    chances: Chances | None
    action: ActionDecision
    anchorage: ItemAnchorage
    demand: MappingProxyType = field(default_factory=lambda: MappingProxyType({}))


@dataclass
class Decisions:
    """The decisions stage's output: per item (``by_item``: id -> the summary's decision columns that are
    numbers and kinds, in :data:`assess.assessment.result.SUMMARY_COLUMNS`; ``items``: id ->
    :class:`ItemDecision`) and the flags of every item, in item order."""

    by_item: dict
    flags: list
    items: dict = field(default_factory=dict)


def decide(equipment: pd.DataFrame, governing: dict, uplift: dict, cases: pd.DataFrame, at_mu_ends: pd.DataFrame,
           constants: RegressionConstants, settings: Settings, site: AnchorageSite | None = None,
           lowered: dict | None = None) -> Decisions:
    """Every item's decisions from its governing demand (``governing``: id -> its demand row,
    :func:`assess.assessment.demand.item_rows`; ``uplift``: id -> whether it uplifts; ``cases``: the
    cases at the workbook's μ; ``at_mu_ends``: the demand at the ends of a μ range).

    An anchored item is not analysed (:data:`ANCHORED`); a freestanding one gets :func:`item_flags`,
    :func:`decide_item` and, with a μ range, :func:`mu_range_decision`; then every item its
    :func:`priorities` rank. ``site``: what the anchorage force takes from the site and building sheets
    (:func:`assess.anchorage.anchorage_site`; None: from the settings alone).
    """
    site = site if site is not None else anchorage_site(None, None, settings)
    by_item, flags, items = {}, [], {}
    for item in equipment.itertuples(index=False):
        decided = dict(NO_MU_RANGE)
        if item.anchored:
            consequence = item_consequence(item)
            anchorage = item_anchorage(item, consequence, ANCHORED["action_kind"], site)
            action = anchored_action(item)
            items[item.id] = ItemDecision(item.id, "anchored", consequence, None, action, anchorage)
            lines = {key: value for key, value in action.columns().items() if key.startswith("connection_")}
            by_item[item.id] = {**ANCHORED, **decided, **lines, **anchorage.columns()}
            continue
        row = {"consequence": item_consequence(item), "clearance_cm": item.clearance_m * actions.CM_PER_M,
               "cg_height_cm": item.cg_height_m * actions.CM_PER_M, **governing[item.id]}
        found = item_flags(item, cases[cases["id"] == item.id], constants, floor_numbering_of(settings))
        flags.extend(found)
        decided["flags"] = tuple(flag.code for flag in found)
        items[item.id] = decide_item(item, row, uplift[item.id], settings, site, (lowered or {}).get(item.id))
        decided.update(item_columns(items[item.id], settings))
        if item.id in at_mu_ends.index:
            decided.update(mu_range_decision(at_mu_ends.loc[item.id], decided["risk"], row["demand_note"],
                                             row["consequence"], settings))
        by_item[item.id] = decided
    table = pd.DataFrame({"id": list(by_item), **{column: [d.get(column, np.nan) for d in by_item.values()]
                                                  for column in ("action_kind", "priority_score")}})
    for item_id, rank in zip(table["id"], priorities(table)):
        by_item[item_id]["priority"] = int(rank)
    return Decisions(by_item, flags, items)


#: The μ-range columns of an item without a range (or anchored).
NO_MU_RANGE = {"mu_low": np.nan, "mu_high": np.nan, "risk_mu_low": "", "risk_mu_high": "",
               "p_beyond_clearance_mu_low": np.nan, "p_beyond_clearance_mu_high": np.nan, "mu_range_note": ""}


def mu_range_decision(end: pd.Series, risk: str, demand_note: str, consequence: str, settings: Settings) -> dict:
    """For an item with a range of friction: its risk class with every run at ``mu_low`` and at
    ``mu_high`` (:func:`~assess.decision.risk_classes.classify_risk` of the demand at each end, ``end``: its row of
    :func:`assess.fragility.friction_range.demand_at_ends`), and
    :func:`~assess.fragility.friction_range.mu_dependence_sentence` in ``mu_range_note`` and at the end
    of ``demand_note``."""
    chances = {side: Chances(float(end[f"p_overturn_{side}"]), float(end[f"p_beyond_clearance_{side}"]),
                             float(end[f"p_rocking_harm_{side}"])) for side in ("low", "high")}
    classes = {side: classify_risk(chances[side], consequence, settings) for side in ("low", "high")}
    why = {side: deciding_chance(chances[side], consequence, settings) for side in ("low", "high")}
    low, high = float(end["mu_low"]), float(end["mu_high"])
    sentence = mu_dependence_sentence(end.name, low, high, risk, classes["low"], classes["high"],
                                      why["low"], why["high"])
    return {"mu_low": low, "mu_high": high, "risk_mu_low": classes["low"], "risk_mu_high": classes["high"],
            "p_beyond_clearance_mu_low": chances["low"].beyond_clearance,
            "p_beyond_clearance_mu_high": chances["high"].beyond_clearance,
            "mu_range_note": sentence, "demand_note": f"{demand_note} {sentence}".strip()}


def decide_item(item, row: dict, uplift: bool, settings: Settings, site: AnchorageSite | None = None,
                lowered: actions.LoweredDemand | None = None) -> ItemDecision:
    """The decision for one freestanding item (:class:`ItemDecision`) from its governing demand ``row`` (a
    dict holding ``p_beyond_clearance``, ``p_overturn``, ``p_rocking_harm`` and their intervals,
    ``demand_room_cm``, ``clearance_cm``, ``cg_height_cm``, ``consequence``, ``theta_max_over_alpha``,
    ``suite_motions``, ``suite_histories``) and whether it uplifts under any motion (``uplift``).

    Its class (:func:`~assess.decision.risk_classes.classify_risk`), its action
    (:func:`assess.decision.actions.decide_action`; ``lowered``: the engine's demand with the heavy contents
    low, where it was simulated) and its anchorage (:func:`assess.anchorage.item_anchorage` in ``site``).
    """
    consequence = row["consequence"]
    chances = Chances.of(row)
    risk = classify_risk(chances, consequence, settings)
    action = actions.decide_action(item, {**row, "risk": risk}, uplift, lowered, settings)
    site = site if site is not None else anchorage_site(None, None, settings)
    anchorage = item_anchorage(item, consequence, action.kind.value, site)
    return ItemDecision(str(item.id), risk, consequence, chances, action, anchorage,
                        MappingProxyType({**row, "risk": risk}))


def item_columns(decision: ItemDecision, settings: Settings) -> dict:
    """The summary's decision columns of one freestanding item that are numbers and kinds: ``risk``,
    ``performance_objective``, ``risk_range`` (the classes at the lower and at the upper ends of every
    chance's 90 % interval), the action's (:meth:`~assess.decision.actions.ActionDecision.columns`), the
    anchorage's in SI (:meth:`~assess.anchorage.ItemAnchorage.columns`) and ``priority_score``."""
    row, consequence = decision.demand, decision.consequence
    bounds = {classify_risk(Chances.of(row, suffix), consequence, settings) for suffix in ("_low", "_high")}
    return {"risk": decision.risk, "performance_objective": performance_objective(consequence),
            "risk_range": risk_range(decision.risk, bounds), **decision.action.columns(),
            **decision.anchorage.columns(), "priority_score": priority_score(consequence, decision.chances)}


#: Weight of what an item's failure costs (the workbook's ``consequence``), for the order of action.
CONSEQUENCE_WEIGHTS = {"life-safety": 5.0, "hazardous": 4.0, "critical": 3.0, "valuable": 2.0, "ordinary": 1.0}


def priority_score(consequence: str, chances: Chances) -> float:
    """How urgent an item is: its consequence weight times the worst of its severity-weighted chances,
    overturning counting fully, sliding past its room by :data:`SLIDING_SEVERITY`, rocking that harms it
    by :data:`ROCKING_HARM_SEVERITY` (where it counts for the item's consequence,
    :func:`~assess.decision.risk_classes.rocking_harm_counts`).

    >>> priority_score("hazardous", Chances(0.2, 0.0, 0.4)), priority_score("ordinary", Chances(0.0, 1.0, 1.0))
    (0.8, 0.5)
    """
    weight = CONSEQUENCE_WEIGHTS.get(str(consequence), 1.0)
    harm = ROCKING_HARM_SEVERITY * chances.rocking_harm if rocking_harm_counts(consequence) else 0.0
    return weight * max(chances.overturn, SLIDING_SEVERITY * chances.beyond_clearance, harm)


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


def ims_range(ims) -> str:
    """The IMs of an item's motions as their range, "0.06–0.16" (one value alone as it is).

    >>> ims_range([0.16, 0.06, 0.09]), ims_range([1.63, 1.634]), ims_range([-0.02, 0.53])
    ('0.06–0.16', '1.63', '−0.02–0.53')
    """
    low, high = (f"{value:.2f}".replace("-", "−") for value in (min(ims), max(ims)))
    return low if low == high else f"{low}–{high}"


def item_flags(item, item_cases: pd.DataFrame, constants: RegressionConstants,
               numbering: str = "ground_0") -> list[Flag]:
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
            f"> g b/h. The sliding regression assumes no uplift; the simulation answers for this item."),
            f"{worst['mode']}{', overturns' if worst['sim_overturned'] else ''}"))
    outside = item_cases[item_cases["im_outside_fit"]]
    if len(outside):
        ims = ", ".join(f"{im:.2f}" for im in sorted(set(outside["im"].round(2))))
        flags.append(Flag(item.id, "im_outside_fit", (
            f"IM = {ims} lies outside the range {constants.im_min:.2f}-{constants.im_max:.2f} the "
            f"regression was fitted on: its numbers shown beside are an extrapolation, and the governing "
            f"demand does not use them for those motions."),
            f"IM {ims_range(outside['im'])}"))
    if "derived" in item_cases and item_cases["derived"].any():
        flags.append(Flag(item.id, "derived_floor_motion", (
            f"floor {floor_text(item.floor, numbering)} has no motion in the workbook: it was assessed under the "
            f"ground motions amplified by ASCE 7-16 eq. 13.3-1 (--derive-floors), an envelope rule, not a floor "
            f"response analysis.")))
    if "beyond_drift" in item_cases and item_cases["beyond_drift"].astype(bool).any():
        beyond = item_cases.loc[item_cases["beyond_drift"].astype(bool), "motion_key"].nunique()
        motions = item_cases["motion_key"].nunique()
        flags.append(Flag(item.id, "building_beyond_drift", (
            f"under {beyond} of its {motions} motions the building's model passed the storey drift it is trusted "
            "to: the floor motions under those, and its results under them, are outside what the model stands "
            "for (the report's building page says which storeys)."), f"{beyond} of {motions} motions"))
    if not np.isclose(item.cg_height_m, item.height_m / 2.0):
        flags.append(Flag(item.id, "cg_not_mid_height", (
            "centre of mass at {length}, not mid-height: alpha and b/h use it; "
            "p assumes the mass spread over the whole box."), "{length}", item.cg_height_m * actions.CM_PER_M))
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
    return Decisions(by_item, flags, decided.items)
