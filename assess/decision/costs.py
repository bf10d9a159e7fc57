"""What an item's failure is expected to cost, and what its recommended action buys: expected loss at the
level, expected annual loss over a hazard curve, and the benefit-cost ratio of the action.

A pure function of the summary (each item's per-mode probabilities at the level, its annual rates where
a hazard curve was given, its ``action_kind``), the equipment's ``value`` and ``mitigation_cost`` and
the settings (``currency``, ``discount_rate``, ``remaining_life_yr``, ``mitigation_cost_<action_kind>``);
docs/workbook.md and docs/outputs.md describe the inputs and the columns. Every amount is per unit of a
row (like the mass and the annual rates), in the settings' currency.

Loss model (FEMA P-58 style: damage states, each with the share of the item's value it costs):

* overturning costs the whole ``value`` (:data:`LOSS_RATIO_OVERTURN`; ``value`` is what the item's
  failure costs, replacement, contents and downtime);
* sliding past its room (hitting a wall or a neighbour, pulling its lines) :data:`LOSS_RATIO_BEYOND_CLEARANCE`;
* rocking that harms it or its contents, where the summary gives ``p_rocking_harm``,
  :data:`LOSS_RATIO_ROCKING_HARM`.

An earthquake costs the loss of the worst state it causes. The summary gives each mode's probability,
not their joint one; the states are taken as sequential (FEMA P-58-1: P(DS_i) = P(D ≥ ds_i) −
P(D ≥ ds_i+1)), each cumulative probability the largest of the modes at or above it
(:func:`expected_loss_ratio`). That is the smallest expected loss the per-mode probabilities allow (exact
where the modes nest, e.g. every run that overturns also slid past its room), so the loss avoided by an
action that holds the item in place is never overstated by the way the modes are combined.

References
----------
FEMA P-58-1 (2018), Seismic Performance Assessment of Buildings, Vol. 1 - Methodology, 2nd ed.
    (fragility and consequence functions; sequential damage states).
OMB Circular A-94 (1992), Guidelines and Discount Rates for Benefit-Cost Analysis of Federal Programs,
    §8 and Appendix A (present value of a uniform series; 7 % real discount rate).
FEMA Benefit-Cost Analysis: benefits are the present value of the avoided annual losses over the
    project's useful life, BCR = benefits / cost; FEMA uses the OMB rate (7 % since April 2025).
Newnan, Eschenbach & Lavelle, Engineering Economic Analysis (uniform-series present worth factor).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd

from assess.decision.risk_classes import ROCKING_HARM_SEVERITY, SLIDING_SEVERITY
from assess.inventory.settings import Settings

#: Share of ``value`` lost when the item overturns: all of it (``value`` is what its failure costs).
LOSS_RATIO_OVERTURN = 1.0
#: Share of ``value`` lost when it slides past its room: it hits a wall or a neighbour, pulls its utility
#: lines or blocks a door, and is mostly repaired, not replaced. Our judgement: the share of an
#: overturning's cost the order of action gives sliding past the room, one number for both.
LOSS_RATIO_BEYOND_CLEARANCE = SLIDING_SEVERITY
#: Share of ``value`` lost when rocking harms it or its contents without overturning it (contents thrown
#: off shelves, impacts on the base). Our judgement: half of sliding past the room, the share the order of
#: action gives it too.
LOSS_RATIO_ROCKING_HARM = ROCKING_HARM_SEVERITY

#: Actions after which the item is taken to neither slide, rock nor overturn (held in place; a restraint against
#: sliding leaves its overturning and rocking, ``p_overturn_after``), until the
#: summary gives the probabilities after the action (``p_overturn_after``, ``p_beyond_clearance_after``).
HOLDING_ACTIONS = ("anchor", "tether", "strap", "chain", "lock_casters")
#: Actions that are no action (nothing to buy).
NO_ACTION = ("none", "anchored", "")

@dataclass(frozen=True)
class CostNote:
    """What an item's cost numbers rest on, or why one is missing, as a kind (``code``): ``no_value``,
    ``anchored``, ``curve_rates`` (with ``bounds``: "upper bound", "lower bound" where a rate is a bound),
    ``no_action``, ``unknown_after``, ``no_cost``, ``free``, ``scaled_after``, ``no_curve``; the
    ``cost_note`` column is their words (:func:`assess.report.advice.cost_note_text`)."""

    code: str
    bounds: tuple = ()


#: Columns this module adds to ``summary.csv`` (docs/outputs.md), in order (``cost_note``: a tuple of
#: :class:`CostNote`, words in the files).
COST_COLUMNS = [
    "value", "mitigation_cost", "expected_loss", "expected_loss_after", "loss_avoided_per_cost",
    "expected_annual_loss", "expected_annual_loss_after", "benefit_cost_ratio", "cost_note",
]


def present_value_factor(discount_rate: float, years: float) -> float:
    """Present value of 1 a year for ``years`` years at ``discount_rate`` (uniform-series present worth factor).

    .. math:: PV = \\frac{1 - (1 + r)^{-n}}{r}, \\qquad PV = n \\text{ at } r = 0

    Parameters
    ----------
    discount_rate : float
        Real discount rate r [1/yr] (0.07 for 7 %).
    years : float
        Years n over which the annual amount is received [yr].

    References: OMB Circular A-94 (1992), Appendix A; Newnan et al., Engineering Economic Analysis (P/A, i, n).

    >>> round(present_value_factor(0.08, 30), 4)  # Newnan et al.: 30,000 a year, 8 %, 30 years = 337,733.5
    11.2578
    >>> present_value_factor(0.0, 15)
    15.0
    """
    rate, years = float(discount_rate), float(years)
    if rate == 0.0:
        return years
    return (1.0 - (1.0 + rate) ** -years) / rate


def expected_loss_ratio(p_overturn: float, p_beyond_clearance: float, p_rocking_harm: float = 0.0) -> float:
    """Expected share of the value lost, from the probabilities of each mode (or their annual rates).

    Sequential damage states, worst first (FEMA P-58-1), each cumulative probability the largest of
    the modes at or above it:

    .. math::
        P_o = p_o,\\quad P_s = \\max(p_o, p_s),\\quad P_r = \\max(P_s, p_r)

        E[L]/V = 1 \\cdot P_o + LR_s (P_s - P_o) + LR_r (P_r - P_s)

    with LR_s = :data:`LOSS_RATIO_BEYOND_CLEARANCE`, LR_r = :data:`LOSS_RATIO_ROCKING_HARM`. A missing
    (NaN) probability counts as 0. Applied to annual rates instead of probabilities it gives the expected
    annual loss ratio (the rate of the worst state reached is combined the same way).

    >>> expected_loss_ratio(0.2, 0.6, 0.0)  # 0.2 x 1 + 0.5 x (0.6 - 0.2)
    0.4
    >>> expected_loss_ratio(0.0, 0.1, 0.3)  # 0.5 x 0.1 + 0.25 x (0.3 - 0.1)
    0.1
    """
    p_o, p_s, p_r = (_zero_if_missing(p) for p in (p_overturn, p_beyond_clearance, p_rocking_harm))
    at_least_sliding = max(p_o, p_s)
    at_least_rocking = max(at_least_sliding, p_r)
    return (LOSS_RATIO_OVERTURN * p_o + LOSS_RATIO_BEYOND_CLEARANCE * (at_least_sliding - p_o)
            + LOSS_RATIO_ROCKING_HARM * (at_least_rocking - at_least_sliding))


def benefit_cost_ratio(annual_loss_avoided: float, mitigation_cost: float, discount_rate: float,
                       years: float) -> float:
    """Present value of the expected annual loss avoided over ``years`` at ``discount_rate``, over the cost.

    .. math:: BCR = \\frac{\\Delta EAL \\cdot PV(r, n)}{C}

    (FEMA BCA: benefits are the avoided losses' present value over the project's useful life.)

    >>> round(benefit_cost_ratio(30_000.0, 300_000.0, 0.08, 30), 4)  # 337,733.5 / 300,000
    1.1258
    """
    return float(annual_loss_avoided) * present_value_factor(discount_rate, years) / float(mitigation_cost)


def _zero_if_missing(value) -> float:
    value = float(value) if value is not None else math.nan
    return 0.0 if math.isnan(value) else value


def _number(row, column: str) -> float:
    """``row[column]`` as a float, NaN where the column is absent or empty."""
    value = row.get(column, math.nan) if hasattr(row, "get") else math.nan
    try:
        return float(value)
    except (TypeError, ValueError):
        return math.nan


def after_probabilities(row, settings: Settings) -> tuple[float, float, float] | None:
    """The item's (p_overturn, p_beyond_clearance, p_rocking_harm) if its recommended action is taken, or
    None where nothing says what the action leaves.

    From the summary's ``p_overturn_after`` and ``p_beyond_clearance_after`` where it has them (the
    action's own what-if); otherwise: an action that holds the item in place (:data:`HOLDING_ACTIONS`)
    leaves nothing; ``room`` (given ``demand_room_cm`` of room) leaves sliding past it at
    ``risk_pf_moderate`` (the room is the sliding exceeded with that probability), overturning and
    rocking as they were. Rocking harm after the action is ``p_rocking_harm_after`` where given, else 0
    for a holding action and unchanged otherwise.
    """
    kind = str(row.get("action_kind") or "")
    p_rock = _zero_if_missing(_number(row, "p_rocking_harm"))
    p_rock_after = _number(row, "p_rocking_harm_after")
    given = (_number(row, "p_overturn_after"), _number(row, "p_beyond_clearance_after"))
    if not any(math.isnan(p) for p in given):
        if math.isnan(p_rock_after):
            p_rock_after = 0.0 if kind in HOLDING_ACTIONS else p_rock
        return given[0], given[1], p_rock_after
    if kind in HOLDING_ACTIONS:
        return 0.0, 0.0, 0.0
    if kind == "room":
        return (_number(row, "p_overturn"), settings.risk_pf_moderate,
                p_rock if math.isnan(p_rock_after) else p_rock_after)
    return None


def mitigation_cost_of(row, settings: Settings) -> float:
    """What the item's recommended action costs per unit: its ``mitigation_cost``, else the setting
    ``mitigation_cost_<action_kind>`` where that is given (> 0); NaN otherwise."""
    given = _number(row, "mitigation_cost")
    if not math.isnan(given):
        return given
    default = settings.mitigation_cost(str(row.get('action_kind')))
    return default if default > 0.0 else math.nan


def _annual_rate(row, mode: str) -> tuple[float, str]:
    """The annual rate of ``mode`` [1/yr]: the central value, else the bound the stripes give (the upper one
    where no stripe failed, the lower one where every stripe failed), and which it is."""
    central = _number(row, f"annual_rate_{mode}")
    if not math.isnan(central):
        return central, ""
    high, low = _number(row, f"annual_rate_{mode}_high"), _number(row, f"annual_rate_{mode}_low")
    if not math.isnan(high):
        return high, "upper bound"
    if not math.isnan(low):
        return low, "lower bound"
    return math.nan, ""


def item_costs(row, settings: Settings, has_curve: bool) -> dict:
    """The cost columns (:data:`COST_COLUMNS`) of one item's summary ``row`` (a dict or Series).

    * ``expected_loss``: value x :func:`expected_loss_ratio` of the level's probabilities;
      ``expected_loss_after`` the same with :func:`after_probabilities`;
    * ``loss_avoided_per_cost``: (expected_loss − expected_loss_after) / mitigation_cost — what one unit of
      money buys if the level's earthquake happens once (a scenario, not a benefit-cost ratio);
    * with a hazard curve: ``expected_annual_loss`` = value x :func:`expected_loss_ratio` of the annual
      rates of overturning and of sliding past the room (the curve gives no rate of rocking harm);
      ``expected_annual_loss_after`` is 0 for an action that holds the item in place and, for another,
      the expected annual loss scaled by the share the action leaves of the loss at the level (a stated
      approximation); ``benefit_cost_ratio`` (:func:`benefit_cost_ratio`) of the avoided annual loss over
      ``remaining_life_yr`` at ``discount_rate``;
    * ``cost_note``: what the numbers rest on, or why one is missing (a tuple of :class:`CostNote`).
    """
    empty = {column: math.nan for column in COST_COLUMNS}
    empty["cost_note"] = ()
    value = _number(row, "value")
    kind = str(row.get("action_kind") or "")
    if math.isnan(value):
        return {**empty, "cost_note": () if kind == "anchored" else (CostNote("no_value"),)}
    out = {**empty, "value": value}
    if kind == "anchored":
        return {**out, "cost_note": (CostNote("anchored"),)}
    p_now = (_number(row, "p_overturn"), _number(row, "p_beyond_clearance"), _number(row, "p_rocking_harm"))
    out["expected_loss"] = value * expected_loss_ratio(*p_now)
    notes = []
    if has_curve:
        rate_overturn, bound_o = _annual_rate(row, "overturn")
        rate_beyond, bound_s = _annual_rate(row, "beyond_clearance")
        out["expected_annual_loss"] = value * expected_loss_ratio(rate_overturn, rate_beyond, 0.0)
        notes.append(CostNote("curve_rates", tuple(sorted({b for b in (bound_o, bound_s) if b}))))
    if kind in NO_ACTION:
        out["expected_loss_after"] = out["expected_loss"]
        out["expected_annual_loss_after"] = out["expected_annual_loss"]
        return {**out, "cost_note": (CostNote("no_action"), *notes)}
    p_after = after_probabilities(row, settings)
    cost = mitigation_cost_of(row, settings)
    out["mitigation_cost"] = cost
    if p_after is None:
        return {**out, "cost_note": (CostNote("unknown_after"), *notes)}
    out["expected_loss_after"] = value * expected_loss_ratio(*p_after)
    avoided = out["expected_loss"] - out["expected_loss_after"]
    if math.isnan(cost):
        notes.insert(0, CostNote("no_cost"))
    elif cost > 0.0:
        out["loss_avoided_per_cost"] = avoided / cost
    else:
        notes.insert(0, CostNote("free"))
    if has_curve:
        eal = out["expected_annual_loss"]
        if kind in HOLDING_ACTIONS:
            out["expected_annual_loss_after"] = 0.0
        elif out["expected_loss"] > 0.0:
            out["expected_annual_loss_after"] = eal * out["expected_loss_after"] / out["expected_loss"]
            notes.append(CostNote("scaled_after"))
        if not math.isnan(out["expected_annual_loss_after"]) and not math.isnan(cost) and cost > 0.0:
            out["benefit_cost_ratio"] = benefit_cost_ratio(eal - out["expected_annual_loss_after"], cost,
                                                           settings.discount_rate,
                                                           settings.remaining_life_yr)
    else:
        notes.append(CostNote("no_curve"))
    return {**out, "cost_note": tuple(notes)}


def cost_table(summary: pd.DataFrame, equipment: pd.DataFrame, settings: Settings, has_curve: bool) -> pd.DataFrame:
    """:data:`COST_COLUMNS` for every item of ``summary`` (by ``id``, in its order), from the equipment's
    ``value`` and ``mitigation_cost``. Where no item has a value, every column is empty (NaN, "")."""
    given = equipment.set_index("id")[["value", "mitigation_cost"]] if "value" in equipment else None
    if given is None or not given["value"].notna().any():
        table = pd.DataFrame({column: np.full(len(summary), np.nan) for column in COST_COLUMNS},
                             index=summary.index)
        table["cost_note"] = ""
        return table
    rows = []
    for _, row in summary.iterrows():
        item = {**row.to_dict(), **given.loc[row["id"]].to_dict()}
        rows.append(item_costs(item, settings, has_curve))
    return pd.DataFrame(rows, columns=COST_COLUMNS, index=summary.index)
