"""Page 1's account of costs (``templates/_costs.html.j2``): the recommended actions ranked by their
benefit-cost ratio where the result has one, and by priority otherwise, from the cost columns of the
summary (:mod:`assess.decision.costs`).

Every sentence is made here from the result's numbers; the template only places them. Without a
``value`` for any item there is nothing to show (None), and the report is as it was.
"""
from __future__ import annotations

import pandas as pd

from assess.decision.costs import (
    LOSS_RATIO_BEYOND_CLEARANCE, LOSS_RATIO_OVERTURN, LOSS_RATIO_ROCKING_HARM, NO_ACTION, present_value_factor,
)
from assess.report.sentences import DASH, finite, format_significant, text
from assess.inventory.settings import Settings

#: What each kind of action is called in the table.
ACTION_WORDS = {"anchor": "anchor", "tether": "tether", "strap": "strap", "chain": "chain",
                "lock_casters": "lock casters", "restrain": "restrain",
                "room": "give room", "lower_contents": "lower contents", "relocate": "relocate"}


def money_text(amount, currency: str = "") -> str:
    """An amount as a reader budgets it: whole units with thousands separators from 100 up, two
    significant digits below; NaN as "–".

    >>> money_text(12345.6, "USD"), money_text(3.456), money_text(0.0042, "EUR"), money_text(float("nan"))
    ('USD 12,346', '3.5', 'EUR 0.0042', '–')
    """
    number = finite(amount)
    if number is None:
        return DASH
    shown = f"{number:,.0f}" if abs(number) >= 100 else format_significant(number, 2)
    return f"{currency} {shown}" if currency else shown


def ratio_text(ratio) -> str:
    """A benefit-cost ratio (or loss avoided per unit cost) to two significant digits; NaN as "–".

    >>> ratio_text(3.456), ratio_text(0.04949), ratio_text(float("nan"))
    ('3.5', '0.049', '–')
    """
    return format_significant(ratio, 2)


def ranked(summary: pd.DataFrame) -> pd.DataFrame:
    """The items with an action to take: those with a ``benefit_cost_ratio`` first, highest first; then
    those with a ``loss_avoided_per_cost`` (at the level, without a hazard curve), highest first; then the
    rest by ``priority``; ties by id."""
    acting = summary[~summary["action_kind"].astype(str).isin(NO_ACTION)]
    bcr = pd.to_numeric(acting["benefit_cost_ratio"], errors="coerce")
    per_cost = pd.to_numeric(acting["loss_avoided_per_cost"], errors="coerce")
    keys = pd.DataFrame({
        "tier": bcr.isna().astype(int) + (bcr.isna() & per_cost.isna()).astype(int),
        "ratio": -bcr.fillna(per_cost).fillna(0.0),
        "priority": pd.to_numeric(acting["priority"], errors="coerce").fillna(len(summary) + 1),
        "id": acting["id"].astype(str)}, index=acting.index)
    order = keys.sort_values(["tier", "ratio", "priority", "id"], kind="mergesort").index
    return acting.loc[order]


#: The most actions page 1's cost table ranks (the rest are in summary.csv), so that the table, its note and
#: the benefit-cost sensitivity keep to page 1.
MAX_COST_ROWS = 8


def left_out_sentence(more: int, unvalued: list) -> str:
    """What page 1's cost table leaves out: the ranked actions past :data:`MAX_COST_ROWS` and the items
    with an action but no ``value`` (nothing to rank them by), by id; "" where nothing is left out.

    >>> left_out_sentence(0, ["LB-1", "ED-2"])
    'Not ranked, without a value: LB-1, ED-2 (their actions are listed above).'
    >>> left_out_sentence(3, [])
    '3 more actions ranked in summary.csv (benefit_cost_ratio, loss_avoided_per_cost).'
    """
    parts = []
    if more:
        parts.append(f"{more} more action{'s' if more != 1 else ''} ranked in summary.csv "
                     "(benefit_cost_ratio, loss_avoided_per_cost).")
    if unvalued:
        parts.append(f"Not ranked, without a value: {', '.join(unvalued)} (their actions are listed above).")
    return " ".join(parts)


def costs_context(result, anchors: dict | None = None) -> dict | None:
    """What page 1 shows of costs; None where no item has a ``value`` (nothing changes in the report).
    ``anchors``: each item's HTML anchor (id -> anchor), to link the rows to the items' blocks. Its rows are
    the actions of the items with a value, ranked (:func:`ranked`), at most :data:`MAX_COST_ROWS`;
    ``left_out`` says what the table leaves out (:func:`left_out_sentence`)."""
    summary = result.summary
    if "value" not in summary or not pd.to_numeric(summary["value"], errors="coerce").notna().any():
        return None
    settings = result.settings
    currency = settings.currency
    has_curve = getattr(result, "curve_risk", None) is not None
    rows = []
    acting = ranked(summary)
    valued = pd.to_numeric(acting["value"], errors="coerce").notna()
    unvalued = acting.loc[~valued, "id"].astype(str).tolist()
    shown, more = acting[valued].iloc[:MAX_COST_ROWS], max(int(valued.sum()) - MAX_COST_ROWS, 0)
    for rank, (_, row) in enumerate(shown.iterrows(), start=1):
        quantity = finite(row.get("quantity"))
        rows.append({
            "rank": rank, "id": text(row.get("id")), "name": text(row.get("name")),
            "anchor": (anchors or {}).get(text(row.get("id")), ""),
            "quantity": int(quantity) if quantity is not None and quantity > 1 else None,
            "action": ACTION_WORDS.get(str(row.get("action_kind")), text(row.get("action_kind"))),
            "value": money_text(row.get("value")), "cost": money_text(row.get("mitigation_cost")),
            "loss": money_text(row.get("expected_loss")), "loss_after": money_text(row.get("expected_loss_after")),
            "annual_loss": money_text(row.get("expected_annual_loss")),
            "annual_loss_after": money_text(row.get("expected_annual_loss_after")),
            "ratio": ratio_text(row.get("benefit_cost_ratio") if has_curve else row.get("loss_avoided_per_cost")),
            "note": text(row.get("cost_note")),
        })
    return {"currency": currency or "the workbook's currency", "has_curve": has_curve, "rows": rows,
            "left_out": left_out_sentence(more, unvalued),
            "sensitivity": bcr_sensitivity(summary, settings) if has_curve else None,
            "lead": lead_sentence(summary, settings, has_curve),
            "basis": basis_sentence(settings, has_curve, "p_overturn_after" in summary),
            "ratio_heading": "Benefit / cost" if has_curve else "Loss avoided per 1 spent"}


#: The discount rates [1/yr] and remaining lives [yr] page 1's sensitivity shows beside the settings' own:
#: 3 % and 7 % (OMB Circular A-94's two rates, the lower for cost-effectiveness; FEMA BCA uses 7 %), 10 %;
#: 10 and 30 years either side of the default 15.
SENSITIVITY_RATES = (0.03, 0.07, 0.10)
SENSITIVITY_LIVES_YR = (10.0, 15.0, 30.0)


def bcr_sensitivity(summary: pd.DataFrame, settings: Settings) -> dict | None:
    """The benefit-cost ratio of all the recommended actions together (Σ avoided annual loss × PV / Σ cost,
    every unit counted, over the items that have a ratio) at each discount rate and remaining life of
    :data:`SENSITIVITY_RATES` and :data:`SENSITIVITY_LIVES_YR` (with the settings' own), for page 1: the
    ratio scales with the present-value factor, :func:`~assess.decision.costs.present_value_factor`. None
    where no item has a ratio.

    >>> table = pd.DataFrame({"quantity": [2], "expected_annual_loss": [100.0], "expected_annual_loss_after": [0.0],
    ...                       "mitigation_cost": [500.0], "benefit_cost_ratio": [1.8]})
    >>> out = bcr_sensitivity(table, Settings(discount_rate=0.07, remaining_life_yr=15.0))
    >>> out["lives"], out["rows"][1]  # 2 x 100 x 9.108 / (2 x 500) = 1.8 at 7 %, 15 years; 7.024 and 12.41
    (['10', '15', '30'], {'rate': '7 %', 'own': True, 'ratios': ['1.4', '1.8', '2.5']})
    """
    bcr = pd.to_numeric(summary.get("benefit_cost_ratio"), errors="coerce") if "benefit_cost_ratio" in summary \
        else pd.Series(dtype=float)
    has = bcr.notna()
    if not has.any():
        return None
    cost = _total(summary, "mitigation_cost", has)
    avoided = _total(summary, "expected_annual_loss", has) - _total(summary, "expected_annual_loss_after", has)
    own_rate, own_years = settings.discount_rate, settings.remaining_life_yr
    rates = sorted(set(SENSITIVITY_RATES) | {own_rate})
    lives = sorted(set(SENSITIVITY_LIVES_YR) | {own_years})
    rows = [{"rate": f"{100 * rate:g} %", "own": rate == own_rate,
             "ratios": [ratio_text(avoided * present_value_factor(rate, years) / cost) for years in lives]}
            for rate in rates]
    return {"lives": [f"{years:g}" for years in lives], "rows": rows, "own_life": f"{own_years:g}",
            "own_rate": f"{100 * own_rate:g} %", "own_index": lives.index(own_years)}


def _total(summary: pd.DataFrame, column: str, where=None) -> float:
    """Sum of ``column`` times ``quantity`` over the rows (``where``: a mask), counting every unit."""
    values = pd.to_numeric(summary[column], errors="coerce") * pd.to_numeric(summary["quantity"], errors="coerce")
    return float(values[where].sum() if where is not None else values.sum())


def lead_sentence(summary: pd.DataFrame, settings: Settings, has_curve: bool) -> str:
    """Page 1's sentence on costs, counting every unit.

    >>> table = pd.DataFrame({"quantity": [1, 2], "expected_loss": [100.0, 50.0], "expected_loss_after": [0.0, 50.0],
    ...                       "mitigation_cost": [40.0, float("nan")], "benefit_cost_ratio": [float("nan")] * 2,
    ...                       "expected_annual_loss": [float("nan")] * 2,
    ...                       "expected_annual_loss_after": [float("nan")] * 2,
    ...                       "value": [1000.0, 500.0], "action_kind": ["anchor", "none"]})
    >>> lead_sentence(table, Settings(currency="USD"), False)  # doctest: +NORMALIZE_WHITESPACE
    'If this earthquake happens, the 3 freestanding units with a value are expected to lose USD 200 (USD 100 after the
    recommended actions, which cost USD 40 where a cost is given). No benefit-cost ratio: this level is one
    earthquake, not how often it happens; give a hazard curve (--oq-hazard: an OpenQuake or USGS curve) for one.'
    >>> lead_sentence(table.assign(mitigation_cost=float("nan")), Settings(currency="USD"),
    ...               False)[:201]  # doctest: +NORMALIZE_WHITESPACE
    'If this earthquake happens, the 3 freestanding units with a value are expected to lose USD 200 (USD 100 after the
    recommended actions, whose costs the workbook does not give: the column mitigation_cost'
    """
    currency = settings.currency
    valued = pd.to_numeric(summary["expected_loss"], errors="coerce").notna()  # a value, and analysed
    units = int(pd.to_numeric(summary.loc[valued, "quantity"], errors="coerce").sum())
    loss, after = _total(summary, "expected_loss", valued), _total(summary, "expected_loss_after", valued)
    acting = valued & ~summary["action_kind"].astype(str).isin(NO_ACTION)
    cost = _total(summary, "mitigation_cost", acting)
    costed = bool(pd.to_numeric(summary.loc[acting, "mitigation_cost"], errors="coerce").notna().any())
    cost_words = (f"which cost {money_text(cost, currency)} where a cost is given" if costed or not acting.any()
                  else "whose costs the workbook does not give: the column mitigation_cost, or the settings' "
                       "mitigation_cost_<action>")
    sentence = (f"If this earthquake happens, the {units} freestanding unit{'s' if units != 1 else ''} with a value "
                f"{'are' if units != 1 else 'is'} expected to lose {money_text(loss, currency)} "
                f"({money_text(after, currency)} after the recommended actions, {cost_words}).")
    if not has_curve:
        return (sentence + " No benefit-cost ratio: this level is one earthquake, not how often it happens; "
                "give a hazard curve (--oq-hazard: an OpenQuake or USGS curve) for one.")
    bcr = pd.to_numeric(summary["benefit_cost_ratio"], errors="coerce")
    worth = bcr >= 1.0
    n_worth = int(worth.sum())
    if not n_worth:
        return sentence + " Over the hazard curve, no action has a benefit-cost ratio of 1 or more."
    avoided = _total(summary, "expected_annual_loss", worth) - _total(summary, "expected_annual_loss_after", worth)
    return (sentence + f" Over the hazard curve, the {n_worth} action{'s' if n_worth != 1 else ''} with a "
            f"benefit-cost ratio of 1 or more cost {money_text(_total(summary, 'mitigation_cost', worth), currency)} "
            f"and avoid {money_text(avoided, currency)} of expected loss a year.")


def basis_sentence(settings: Settings, has_curve: bool, own_after: bool = False) -> str:
    """How the amounts are computed, in one paragraph (the loss model, and the discounting with a curve);
    ``own_after``: the summary gives each action's probabilities after it (``p_overturn_after``).

    >>> basis_sentence(Settings(discount_rate=0.07, remaining_life_yr=15.0), True).split("avoided, ")[-1]
    'over 15 years at 7 % a year (present value factor 9.11, as in FEMA benefit-cost analysis), divided by its cost.'
    """
    text_ = (f"Amounts per unit. Expected loss: the item's value times the share its worst outcome costs "
             f"(overturning {LOSS_RATIO_OVERTURN:.0%}, sliding past its room {LOSS_RATIO_BEYOND_CLEARANCE:.0%}, "
             f"rocking that harms it {LOSS_RATIO_ROCKING_HARM:.0%}), weighed by its chances under this "
             "earthquake; after: with the chances the action leaves"
             + (" (its what-if)." if own_after else
                " (none for anchoring, tethering, restraining or locking casters; for giving room, the chance "
                "of sliding past the room given)."))
    if not has_curve:
        return text_ + (" Loss avoided per 1 spent: the expected loss the action avoids if this earthquake "
                        "happens once, over its cost.")
    rate, years = settings.discount_rate, settings.remaining_life_yr
    return text_ + (f" Annual loss: the same shares weighed by the yearly rates of overturning and of sliding "
                    f"past the room over the hazard curve. Benefit / cost: the annual loss avoided, over "
                    f"{years:g} years at {100 * rate:g} % a year (present value factor "
                    f"{present_value_factor(rate, years):.2f}, as in FEMA benefit-cost analysis), divided by its "
                    "cost.")

