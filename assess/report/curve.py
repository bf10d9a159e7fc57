"""The report's account of the whole hazard curve: each item's chance over 50 years, from its
fragilities over stripes (:mod:`assess.fragility.stripes`).

Every sentence is made here from the result's numbers; the template only places them.
"""
from __future__ import annotations

import math

import pandas as pd

from assess.quantity_text import floor_text, floors_text

#: A chance in 50 years at or above this is named on page 1.
NOTABLE_P50YR = 0.10
MODE_WORDS = {"beyond_clearance": "sliding past its room", "overturn": "overturning"}


def chance_text(central, low, high) -> str:
    """A probability in 50 years with its 90 % interval, or the one-sided bound the outcomes allow.

    >>> chance_text(0.031, 0.025, 0.04), chance_text(float("nan"), float("nan"), 0.005)
    ('3.1% (2.5–4.0%)', 'below 0.5%')
    >>> chance_text(float("nan"), float("nan"), 0.0002)
    '<0.1%'

    >>> chance_text(float("nan"), 0.99999, float("nan"))
    'at least 100.0%'
    """
    def pct(p):
        return f"{100 * p:.1f}%" if p >= 0.001 else "<0.1%"

    values = [float(v) if v is not None else math.nan for v in (central, low, high)]
    central, low, high = values
    if math.isfinite(central):
        if math.isfinite(low) and math.isfinite(high) and not (low == central == high):
            return f"{pct(central)} ({pct(low).rstrip('%')}–{pct(high)})"
        return pct(central)
    if math.isfinite(high):
        return pct(high) if high < 0.001 else f"below {pct(high)}"
    if math.isfinite(low):
        return f"at least {pct(low)}"
    return "–"


def curve_context(result, numbering: str = "ground_0") -> dict | None:
    """What the report shows of the hazard curve; None without one. Floors as ``numbering`` labels them
    (:func:`assess.report.sentences.floor_text`)."""
    curve = getattr(result, "curve_risk", None)
    if curve is None:
        return None
    summary = result.summary
    free = summary[summary["risk"] != "anchored"]
    rows = []
    for _, row in free.iterrows():
        entry = {"id": str(row["id"]), "name": str(row["name"]), "floor": floor_text(row["floor"], numbering),
                 "ratio": f"{row['pfa_per_pga']:.2f}", "note": str(row.get("curve_note") or "")}
        for mode in MODE_WORDS:
            entry[mode] = chance_text(row[f"p50yr_{mode}"], row[f"p50yr_{mode}_low"], row[f"p50yr_{mode}_high"])
            median = row[f"fragility_{mode}_median_g"]
            entry[f"{mode}_fragility"] = (f"{median:.2f} g, β {row[f'fragility_{mode}_beta']:.2f}"
                                          if pd.notna(median) else "–")
        rows.append(entry)
    notable = {mode: [str(i) for i in free.loc[_at_least(free, mode), "id"]] for mode in MODE_WORDS}
    return {"curve": curve.curve, "rows": rows, "lead": lead_sentence(notable, len(free)),
            "floors": floors_sentence(curve.floors, numbering), "runs": curve.runs,
            "stripes": _stripes_sentence(curve), "intensity": getattr(curve, "intensity", "PFA"),
            "notes": list(curve.notes), **governs_sentences(free)}


def floors_sentence(floors: dict, numbering: str = "ground_0") -> str:
    """The floors' bases (``floors``: floor -> ``{"basis": "floor LABEL: what", ...}``, as the curve gives them)
    joined, the floors whose ``what`` reads the same named together (:func:`~assess.quantity_text.floors_text`),
    in the order of the floors.

    >>> floors_sentence({k: {"basis": f"floor {k}: " + ("the ground" if k == 0 else "through it")} for k in range(5)})
    'floor 0: the ground; floors 1 to 4: through it'
    """
    groups: dict[str, list[int]] = {}
    for floor, entry in sorted(floors.items()):
        groups.setdefault(entry["basis"].partition(": ")[2], []).append(int(floor))
    return "; ".join(f"{floors_text(numbers, numbering)}: {what}"
                     for what, numbers in groups.items())


def governs_sentences(free: pd.DataFrame) -> dict:
    """Which answer to use: ``governs`` (one sentence, always) and ``apart`` (one per item whose level answer
    and fragility at the level's accelerations differ by :data:`~assess.fragility.agreement.APART` or more)."""
    from assess.fragility.agreement import APART, level_comparison_sentence

    apart = [text for text in (level_comparison_sentence(row, why=False) for _, row in free.iterrows()) if text]
    governs = (
        "Which to use: at the design level, the level's answer governs (the risk classes, the advice, "
        "p_beyond_clearance and p_overturn in summary.csv): it takes each motion from the model that holds for "
        "it, the paper's regression where a pulse, IM in its fitted range and no uplift make it hold, the "
        "engine otherwise. The fragilities (these rates, fragility/ and pelicun with it) run the engine under "
        "the same motions' histories for every motion and every stripe: the regression holds over too narrow "
        "a range of intensity to give a stripe from 0.05 to 2 g; where the engine answers at the level too, "
        "the fragility is one lognormal over every stripe, which smooths the level's outcomes. summary.csv "
        "gives each fragility at this level's accelerations (p_beyond_clearance_fragility, "
        "p_overturn_fragility); ")
    if apart:
        governs += (f"for {len(apart)} of the {len(free)} items it differs from the level's answer by "
                    f"{APART:.0%} or more:")
    else:
        governs += f"for every item it lies within {APART:.0%} of the level's answer."
    return {"governs": governs, "apart": apart}


def _at_least(free: pd.DataFrame, mode: str) -> pd.Series:
    """Items whose chance in 50 years is at least :data:`NOTABLE_P50YR`, or bounded below by it."""
    central = free[f"p50yr_{mode}"].fillna(free[f"p50yr_{mode}_low"])
    return central >= NOTABLE_P50YR


def lead_sentence(notable: dict, n_items: int) -> str:
    """Page 1's sentence on the whole curve, from the items named in ``notable`` (mode -> ids).

    >>> lead_sentence({"beyond_clearance": ["A", "B"], "overturn": []}, 9)  # doctest: +NORMALIZE_WHITESPACE
    'Over 50 years (the whole hazard curve, not only this level): 2 of the 9 freestanding items have a 10% chance or
    more of sliding past their room (A, B); none has one of overturning.'
    >>> lead_sentence({"beyond_clearance": [], "overturn": ["C"]}, 9)  # doctest: +NORMALIZE_WHITESPACE
    'Over 50 years (the whole hazard curve, not only this level): none of the 9 freestanding items has a 10% chance or
    more of sliding past its room; 1 has one of overturning (C).'
    """
    chance = f"a {NOTABLE_P50YR:.0%} chance or more"
    parts = []
    for mode, words in (("beyond_clearance", "sliding past {} room"), ("overturn", "overturning")):
        ids = notable.get(mode, [])
        has = "has" if len(ids) <= 1 else "have"
        subject = (f"{len(ids) if ids else 'none'} of the {n_items} freestanding items {has} {chance}" if not parts
                   else f"{len(ids) if ids else 'none'} {has} one")
        parts.append(f"{subject} of {words.format('their' if len(ids) > 1 else 'its')}"
                     + (f" ({', '.join(ids[:8])}{f' and {len(ids) - 8} more' if len(ids) > 8 else ''})" if ids else ""))
    return "Over 50 years (the whole hazard curve, not only this level): " + "; ".join(parts) + "."


def _stripes_sentence(curve) -> str:
    """What the fragilities were fitted from: "its floor's motions scaled to 10 stripes per floor (31 more where
    an item's failures rise steeply), from 0.05 g to 3.25 g of floor acceleration; 22620 simulations", or, through
    a building, "the level's ground motions scaled to 10 stripes (…) of ground acceleration, and, above the ground
    floor, passed through the building to the item's floor; …"."""
    from assess.fragility.stripes import N_STRIPES

    if curve.stripes.empty:
        return ""
    per_item = curve.stripes.drop_duplicates(["id", "pfa_g"]).groupby("id").size()
    extra = int((per_item - N_STRIPES).clip(lower=0).sum())
    more = f" ({extra} more where an item's failures rise steeply)" if extra else ""
    span = f"from {curve.stripes['pfa_g'].min():.2f} g to {curve.stripes['pfa_g'].max():.2f} g"
    if getattr(curve, "intensity", "PFA") == "PFA":
        return (f"its floor's motions scaled to {N_STRIPES} stripes per floor{more}, {span} of floor acceleration; "
                f"{curve.runs} simulations")
    return (f"the level's ground motions scaled to {N_STRIPES} stripes{more}, {span} of ground acceleration, and, "
            f"above the ground floor, passed through the building to the item's floor; {curve.runs} simulations")
