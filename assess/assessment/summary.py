"""Stage 7 of the assessment: the result, one row per item (``summary.csv``) and per case (``motions.csv``).

:func:`summarise` lays out, per item, its geometry, the regression's numbers
for its governing case, its governing demand (:mod:`assess.assessment.demand`)
and the decisions that follow from it (:mod:`assess.decisions`); the columns
are described in docs/outputs.md.
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from assess import decisions
from assess.assessment.demand import governing_case
from assess.data import default_settings
from assess.fragility.regression import RegressionConstants
from assess.mechanics.geometry import frequency_parameter, slenderness
from assess.result import MOTION_COLUMNS, Flag

UPLIFT_MODES = decisions.UPLIFT_MODES
#: Columns of the governing case an item's row shows.
GOVERNING_CASE_COLUMNS = ("alpha_rad", "p_rad_s", "b_over_h", "mode", "pta_g", "tp_s", "im", "edp_median",
                          "sliding_median_cm", "sliding_p84_cm", "pf_sliding", "sim_sliding_max_cm")


def summarise(equipment: pd.DataFrame, cases: pd.DataFrame, demand, constants: RegressionConstants,
              settings: dict) -> tuple[pd.DataFrame, list[Flag]]:
    """One row per item and the flags: its geometry, the regression's numbers for its governing case
    (``cases``: those at the workbook's μ), the governing demand over its suite (``demand``:
    :class:`assess.assessment.demand.Demand`), and the decisions (:func:`assess.decisions.decide_item`,
    :func:`assess.decisions.priorities`, :func:`assess.decisions.mu_range_decisions`)."""
    governing = governing_case(cases).set_index("id") if len(cases) else pd.DataFrame()
    rows, flags = [], []
    for item in equipment.itertuples(index=False):
        row = {"id": item.id, "name": item.name, "room": item.room, "floor": item.floor,
               "quantity": item.quantity, "consequence": str(getattr(item, "consequence", "") or "ordinary"),
               "mu": item.mu, "clearance_cm": item.clearance_m * 100.0,
               "overturn_fraction": np.nan, "theta_max_over_alpha": np.nan}
        if item.anchored:
            half_width_m = min(item.width_m, item.depth_m) / 2.0
            row.update({"alpha_rad": float(slenderness(half_width_m, item.cg_height_m)),
                        "p_rad_s": float(frequency_parameter(half_width_m, item.cg_height_m, item.height_m)),
                        "b_over_h": half_width_m / item.cg_height_m,
                        "governing_direction": 1 if item.width_m <= item.depth_m else 2,
                        **decisions.ANCHORED})
            rows.append(row)
            continue
        case = governing.loc[item.id]
        item_cases = cases[cases["id"] == item.id]
        row.update({column: case[column] for column in GOVERNING_CASE_COLUMNS})
        row["governing_direction"] = int(case["direction"])
        row["governing_motion"] = case["motion"]
        row.update(demand.governing.loc[item.id].to_dict())
        row["overturn_fraction"] = row["p_overturn"]
        uplift = bool(item_cases["sim_uplift"].any()) or bool(row.get("demand_uplift", False))
        item_flags = decisions.item_flags(item, item_cases, constants)
        flags.extend(item_flags)
        row["flags"] = tuple(flag.code for flag in item_flags)
        row.update(decisions.decide_item(item, row, uplift, settings))
        rows.append(row)
    summary = pd.DataFrame(rows)
    summary["priority"] = decisions.priorities(summary)
    return decisions.mu_range_decisions(summary, demand.at_mu_ends, settings), flags


def motion_table(cases: pd.DataFrame) -> pd.DataFrame:
    """``motions.csv``: one row per case at the workbook's μ, in workbook order (:data:`MOTION_COLUMNS`)."""
    table = cases.assign(
        vp_cm_s=cases["vp_m_s"] * 100.0,
        flags=np.where(cases["im_outside_fit"], "im_outside_fit", ""),
    )
    table["flags"] = np.where(table["mode"].isin(UPLIFT_MODES),
                              np.where(table["flags"] == "", "uplift", table["flags"] + ";uplift"), table["flags"])
    table = table.sort_values(["pair_index", "direction"], kind="stable")  # workbook order
    return table[MOTION_COLUMNS].reset_index(drop=True)


def regression_record(constants: RegressionConstants, settings: dict) -> dict:
    """The regression's constants as used, and where they come from (:attr:`AssessmentResult.regression`)."""
    return {"zeta": constants.zeta, "eta": constants.eta, "sigma": constants.sigma,
            "im_min": constants.im_min, "im_max": constants.im_max, "source": regression_source(settings)}


def regression_source(settings: dict) -> str:
    """Where the regression's constants come from, for the report."""
    defaults = default_settings()
    if all(float(settings[key]) == float(defaults[key]) for key in ("zeta", "eta", "sigma")):
        return "Konstantinidis & Makris (2010), eq. 21 (Table 3 simulations)"
    return "the workbook's settings sheet"
