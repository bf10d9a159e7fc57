"""The exported fragility at the level's own accelerations, beside the level's answer.

The level's answer (``p_beyond_clearance``, ``p_overturn``: :mod:`assess.fragility.governing`) takes each
motion of the item's floor from the model that holds for it: the paper's regression where a pulse carries
the motion, IM lies in the range it was fitted on and the item does not uplift; the engine under the
motion's records or histories otherwise. The fragility (:mod:`assess.fragility.stripes`) runs the engine
under the same histories scaled to stripes from 0.05 to 2 g of ground acceleration: the regression cannot
give a stripe (its IM range is narrow, and it knows pulses only), so the engine answers for every motion
there. Where the regression answers at the level, the two may differ; this module puts the fragility's
probability at the level's accelerations beside the level's answer, so that the report can say so and
which governs (:func:`assess.report.curve.governs_sentences`).

For one item and failure mode, with every motion of its floor's suite weighing the same (as in the level's
answer), the fragility's probability at the level is

.. math:: \\bar P = \\frac{1}{M} \\sum_{m=1}^{M} \\Phi\\left(\\frac{\\ln(a_m/\\theta)}{\\beta}\\right)

with :math:`a_m` the motion's peak acceleration at the level: the floor's (PTA) for a fragility in PFA,
the ground motion's behind it for one in PGA (stripes through the building).
"""
from __future__ import annotations

import math

import numpy as np
import pandas as pd

#: Per failure mode (:data:`assess.fragility.stripes.MODES`), the summary column of its fragility's
#: probability at the level's accelerations.
AT_LEVEL = {"beyond_clearance": "p_beyond_clearance_fragility", "overturn": "p_overturn_fragility"}
AT_LEVEL_COLUMNS = list(AT_LEVEL.values())


def level_intensities(cases: pd.DataFrame, level_table: pd.DataFrame, intensity: str) -> pd.DataFrame:
    """One row per item and motion of the level: ``id``, ``motion_key``, ``a_g``, the acceleration the
    fragility is in at the level (the motion's PTA; for ``PGA``, that of the ground motion behind it)."""
    per_motion = cases.drop_duplicates(["id", "motion_key"])[["id", "motion_key", "pta_g"]]
    if intensity == "PFA":
        return per_motion.rename(columns={"pta_g": "a_g"}).reset_index(drop=True)
    table = level_table.set_index("motion_key")
    from_ground = table["from_ground"] if "from_ground" in table else pd.Series(-1, index=table.index)

    def ground_pta(key) -> float:
        source = int(from_ground.get(key, -1))
        return float(table.at[source if source >= 0 else key, "pta_g"])

    return per_motion.assign(a_g=[ground_pta(k) for k in per_motion["motion_key"]]) \
        .drop(columns="pta_g").reset_index(drop=True)


def fragility_at_level(cases: pd.DataFrame, level_table: pd.DataFrame, curve) -> pd.DataFrame:
    """``id`` and :data:`AT_LEVEL_COLUMNS`: each fitted fragility's mean
    probability over the item's motions at the level (module docstring); NaN without a fit."""
    accelerations = level_intensities(cases, level_table, curve.intensity)
    rows = []
    for item_id, group in accelerations.groupby("id", sort=False):
        row = {"id": item_id}
        for mode, column in AT_LEVEL.items():
            fit = curve.fits.get((item_id, mode))
            row[column] = (float(np.mean(fit.probability(group["a_g"].to_numpy(dtype=float))))
                           if fit is not None and fit.fitted else math.nan)
        rows.append(row)
    return pd.DataFrame(rows, columns=["id"] + list(AT_LEVEL_COLUMNS))


#: A level answer and its fragility's at the same accelerations this far apart (or further) are said apart.
APART = 0.10
_MODE_WORDS = {"beyond_clearance": "sliding past its room", "overturn": "overturning"}


def _percent(p: float) -> str:
    return "<1%" if 0.0 < p < 0.005 else (">99%" if 0.995 <= p < 1.0 else f"{p:.0%}")


def _sources(value) -> tuple:
    if isinstance(value, str):
        return tuple(part.strip() for part in value.split("+") if part.strip())
    return tuple(value) if value is not None else ()


def level_comparison_sentence(row, why: bool = True) -> str:
    """Where the level's answer and the fragility's at the level's accelerations are :data:`APART` or more,
    one sentence saying both, which governs and why (``why`` False: both, and in brackets where the level's
    answer comes from, for a list under a paragraph that gives the reasons); "" where they agree (or there is
    no fragility).

    ``row``: a summary row (``id``, ``demand_source``, ``p_beyond_clearance``, ``p_overturn`` and
    :data:`AT_LEVEL_COLUMNS`).

    >>> text = level_comparison_sentence({"id": "REF-6-01", "demand_source": ("regression",),
    ...     "p_beyond_clearance": 0.84, "p_overturn": 0.0, "p_beyond_clearance_fragility": 0.64,
    ...     "p_overturn_fragility": float("nan")})
    >>> print(text.split(". ")[0])  # doctest: +NORMALIZE_WHITESPACE
    REF-6-01, sliding past its room at this level: 84% from the level's answer, 64% from its fragility at the same
    accelerations
    >>> print(text.split(": ", 2)[2][:60])
    it takes the paper's regression, fitted on experiments, wher
    """
    parts = []
    for mode, column in AT_LEVEL.items():
        level, fragility = float(row[f"p_{mode}"]), float(row[column])
        if math.isfinite(level) and math.isfinite(fragility) and abs(level - fragility) >= APART:
            parts.append(f"{_MODE_WORDS[mode]} at this level: {_percent(level)} from the level's answer, "
                         f"{_percent(fragility)} from its fragility at the same accelerations")
    if not parts:
        return ""
    regression = "regression" in _sources(row["demand_source"])
    if not why:
        return (f"{row['id']}, " + "; ".join(parts) + (
            " (the level takes the paper's regression where it holds)." if regression else
            " (both from the simulations: the lognormal smooths the level's outcomes)."))
    if regression:
        why = ("it takes the paper's regression, fitted on experiments, where it holds for a motion (a pulse, IM "
               "in its fitted range, no uplift); the fragility runs the engine under those motions' histories, at "
               "this level as at every stripe, and serves the rates over the hazard curve and pelicun.")
    else:
        why = ("it counts the simulated outcomes at the level's own accelerations; the fragility is one lognormal "
               "fitted over every stripe, which smooths them, and serves the rates over the hazard curve and "
               "pelicun.")
    return f"{row['id']}, " + "; ".join(parts) + ". The level's answer governs the class and the advice: " + why
