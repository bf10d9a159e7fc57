"""Stage 7 of the assessment: the result, one row per item (``summary.csv``) and per case (``motions.csv``).

:func:`summarise` lays out, per item, what it is, the regression's numbers
for its governing case and its governing demand (:mod:`assess.assessment.demand`),
and the decisions that follow from it (:mod:`assess.decisions`); it decides
nothing. The columns are described in docs/outputs.md.
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from assess import decisions
from assess.data import default_settings
from assess.fragility.regression import RegressionConstants
from assess.mechanics.geometry import frequency_parameter, slenderness
from assess.result import MOTION_COLUMNS

UPLIFT_MODES = decisions.UPLIFT_MODES


def summarise(equipment: pd.DataFrame, demand, decided) -> pd.DataFrame:
    """One row per item: what it is (id, name, room, floor, quantity, consequence, μ, clearance), its
    demand row (``demand``: :class:`assess.assessment.demand.ItemDemand`; an anchored item: its geometry
    about the more slender direction) and its decisions (``decided``: :class:`assess.decisions.Decisions`)."""
    rows = []
    for item in equipment.itertuples(index=False):
        row = {"id": item.id, "name": item.name, "room": item.room, "floor": item.floor,
               "quantity": item.quantity, "consequence": decisions.item_consequence(item),
               "mu": item.mu, "mu_source": getattr(item, "mu_source", "workbook"),
               "clearance_cm": item.clearance_m * 100.0,
               "overturn_fraction": np.nan, "theta_max_over_alpha": np.nan}
        if item.anchored:
            half_width_m = min(item.width_m, item.depth_m) / 2.0
            row.update({"alpha_rad": float(slenderness(half_width_m, item.cg_height_m)),
                        "p_rad_s": float(frequency_parameter(half_width_m, item.cg_height_m, item.height_m)),
                        "b_over_h": half_width_m / item.cg_height_m,
                        "governing_direction": 1 if item.width_m <= item.depth_m else 2})
        else:
            row.update(demand.rows[item.id])
        row.update(decided.by_item[item.id])
        rows.append(row)
    return pd.DataFrame(rows)


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
