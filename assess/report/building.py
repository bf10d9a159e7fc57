"""The report's building section: what a yielding building's storeys did, and where the model stops.

Everything here is read from the result's ``floors.csv`` table (:func:`assess.building.yielding.storey_table`
and :func:`assess.building.floors.floors_table`): which model yielded (``yielding_model``: storey springs, or a
wall's base hinge), each storey's peak drift ratio and ductility over the suite, the storeys whose drift passed
the limit the model is trusted to (FEMA 356 Table C1-3's Collapse Prevention drift for the system,
:data:`assess.building.yielding.DRIFT_LIMIT_BY_SYSTEM`), and, as a sanity check beside each floor's PFA/PGA,
ASCE 7-22 §13.3.1's H_f. An elastic building has no section: its floors are described in the report's notes.
"""
from __future__ import annotations

import math

import numpy as np

from assess.building.yielding import BASE_HINGE
from assess.quantity_text import floor_numbering_of, floor_text, runs_text

#: Sentence closing the section, whatever the drifts.
COLLAPSE_NOT_ASSESSED = ("The building's own collapse is not assessed: this report is about its contents, under "
                         "the floor motions of a building that stays standing.")


def _columns_share(table) -> str:
    """The clause saying that the yield shear includes the columns' share, where it differs from the springs' own
    (``storey_spring_yield_ratio``, what ``storey_strength`` gives): a frame whose continuous columns stand apart
    from its storey springs. Empty where the two agree (no columns apart) or the table has no springs' column."""
    if "storey_spring_yield_ratio" not in table:
        return ""
    storeys = table.dropna(subset=["storey_yield_ratio", "storey_spring_yield_ratio"])
    if storeys.empty or np.allclose(storeys["storey_spring_yield_ratio"], storeys["storey_yield_ratio"], rtol=1e-6):
        return ""
    return ("; what its columns carry beside its spring included: the springs' own are floors.csv's "
            "storey_spring_yield_ratio, in the ratios storey_strength gives where it is given")


def _percent(value: float) -> str:
    """A drift ratio in per cent, two significant digits.

    >>> _percent(0.0123), _percent(0.02)
    ('1.2 %', '2 %')
    """
    return f"{100.0 * value:.2g} %"


def _drift_range(low: float, high: float) -> str:
    """``0.00092, 0.0033`` → ``0.092–0.33 %``."""
    return f"{100.0 * low:.2g}–{100.0 * high:.2g} %"


def ductility_text(floors) -> str:
    """How the building page's last two columns are meant: H_f, and H_f/R_μ with the building's R_μ
    (``floors.csv`` of a yielding building).

    >>> import pandas as pd
    >>> ductility_text(pd.DataFrame({"rmu_asce7_22": [1.7127]}))[:62]
    ': H_f for a building that stays elastic, H_f/R_μ with R_μ 1.71'
    """
    return (f": H_f for a building that stays elastic, H_f/R_μ with R_μ {float(floors['rmu_asce7_22'].iloc[0]):.2f} "
            "(eq. 13.3-6, from the system's R and Ω0 and the risk category's I_e) for one that yields as its design "
            "assumes,")


def _number(value: float) -> str:
    """A ductility: one decimal (``1.03`` → ``1.0``), whole numbers from 10; a dash where there is none (a
    wall's storeys above its base hinge do not yield).

    >>> _number(1.03), _number(12.4), _number(float("nan"))
    ('1.0', '12', '–')
    """
    if math.isnan(value):
        return "–"
    return f"{value:.1f}" if value < 10 else f"{value:.0f}"


def building_context(result) -> dict | None:
    """The section's rows and sentences from ``result.floors`` (None unless the building yields).

    Returns
    -------
    dict or None
        ``lead`` (a sentence), ``rows`` (per storey: ``storey``, ``floors`` (the floors it joins, labelled as
        the report labels floors), ``yield_ratio``, ``drift`` and ``drift_range``, ``ductility`` and
        ``ductility_range``, ``beyond`` (motions beyond the limit), ``pfa_over_pga``, ``hf``), ``warning``
        (a sentence, or "" when no storey passed the limit), ``notice`` (the same in one sentence for the
        report's first page, or "") and ``collapse`` (:data:`COLLAPSE_NOT_ASSESSED`).
    """
    floors = getattr(result, "floors", None)
    if floors is None or "response" not in floors or not (floors["response"] == "yielding").any():
        return None
    numbering = floor_numbering_of(result.settings)
    table = floors.sort_values("floor")
    motions = int(table["motions"].iloc[0])
    yielded = int(table["motions_yielded"].iloc[0])
    limit = float(table["drift_limit"].iloc[0])
    storeys = table[table["floor"] > 0]
    # a wall on its base hinge (the model that ran says so): only storey 1 has a yield strength and a ductility
    hinged = table["yielding_model"].iloc[0] == BASE_HINGE
    rows, beyond = [], {}
    for _, row in storeys.iterrows():
        k = int(row["floor"])
        count = int(row["motions_beyond_drift_limit"])
        if count:
            beyond[k] = count
        rows.append({
            "storey": k,
            "floors": f"{floor_text(k - 1, numbering)}–{floor_text(k, numbering)}",
            "yield_ratio": ("–" if math.isnan(row["storey_yield_ratio"])
                            else f"{row['storey_yield_ratio']:.3f}"),  # one precision down the column
            "drift": _percent(row["drift_ratio_median"]),
            "drift_range": _drift_range(row["drift_ratio_min"], row["drift_ratio_max"]),
            "ductility": _number(row["ductility_median"]),
            "ductility_range": ("" if math.isnan(row["ductility_min"])
                                else f"{_number(row['ductility_min'])}–{_number(row['ductility_max'])}"),
            "beyond": count,
            "pfa_over_pga": f"{row['pfa_over_pga_median']:.2f}",
            "hf": f"{row['hf_asce7_22']:.2f}",
            "hf_over_rmu": f"{row['hf_over_rmu_asce7_22']:.2f}",
        })
    shear = f"a base shear of {float(table['yield_base_shear_g'].iloc[0]):.3f} times its weight (the notes at the " \
            "top say where that comes from)"
    what_yields, yielded_what, measures = (
        (f"a wall that yields in bending at its base only, at {shear}, and stays elastic above", "yielded it",
         "Each storey's peak drift (over its height) is the median over the motions, with their range; the "
         "ductility, in storey 1's row, is the wall's at its base (its peak rotation there over the rotation at "
         "which it yields)") if hinged else
        (f"the first of its storeys to yield does so at {shear}, the others later (the yield shear: each storey's "
         "shear when it yields under the code's lateral forces" + _columns_share(table) + ")",
         "yielded at least one storey",
         "Each storey's peak drift (over its height) and ductility (peak drift over the drift at which it yields) "
         "are the median over the motions, with their range"))
    lead = (f"The upper floors' motions come from a model of the building that yields: {what_yields}. {yielded} of "
            f"the {motions} ground motions {yielded_what}"
            + (" (the others gave the elastic modes' floor motions)." if yielded < motions else ".")
            + f" {measures}; PFA/PGA is the floor's, beside what ASCE 7-22 §13.3.1 takes it to be"
            + ductility_text(table) + " as a check (not a target).")
    warning = notice = ""
    if beyond:
        worst = max(beyond.values())
        warning = (f"Beyond what the model can be trusted for: the drift of {runs_text(beyond, 'storey')} passed "
                   f"{_percent(limit)} under {'a motion' if worst == 1 else f'up to {worst} of the {motions} motions'}"
                   f". {_percent(limit)} is the transient drift of FEMA 356's Collapse Prevention level for this "
                   "system (Table C1-3): there a building is near collapse and its members lose strength with "
                   "every cycle, which the model's storeys do not, so the floor motions under those ground motions, "
                   "and the items' results under them, are outside what the model stands for. Have a structural "
                   "engineer look at the building first.")
        notice = (f"The building's model passed the storey drift it is trusted to ({_percent(limit)}, "
                  f"{runs_text(beyond, 'storey')}) under up to {worst} of the {motions} motions: the floor motions "
                  "under those, and the items' results under them, are outside what it stands for.")
    return {"lead": lead, "rows": rows, "warning": warning, "notice": notice, "collapse": COLLAPSE_NOT_ASSESSED,
            "limit": _percent(limit).replace(" ", "\u00a0") if not math.isnan(limit) else ""}  # "4 %" on one line


__all__ = ["COLLAPSE_NOT_ASSESSED", "building_context"]
