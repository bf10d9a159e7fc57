"""Stage 5 of the assessment: the demand on each item, from its cases and the engine's runs.

Per case: the mode, IM and the paper's regression (Konstantinidis & Makris
2010, eq. 21) for its sliding (:func:`regression_demand`). Per item: the case
that its summary row shows (:func:`governing_case`) and the governing demand
over its suite of motions (:func:`assess.fragility.governing.governing_demand`),
at the workbook's μ and, for an item with a range of friction, at each end of
it (:func:`assess.fragility.friction_range.demand_at_ends`).
"""
from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np
import pandas as pd

from assess.fragility import (
    RegressionConstants, capacity_edp, intensity_measure, median_edp, probability_of_exceedance, sliding_quantile,
)
from assess.fragility.friction_range import demand_at_ends
from assess.inventory.settings import Settings
from assess.fragility.governing import add_pulse_share, governing_demand, motion_sources, regression_note
from assess.inventory.units import CM_PER_M
from assess.mechanics.modes import MODE_SEVERITY, ROCK, SLIDE, SLIDE_ROCK, initial_mode

SLIDING_MODES = (SLIDE, SLIDE_ROCK)
#: Columns of the governing case an item's row shows.
GOVERNING_CASE_COLUMNS = ("alpha_rad", "p_rad_s", "b_over_h", "mode", "pta_g", "tp_s", "im", "edp_median",
                          "sliding_median_cm", "sliding_p84_cm", "pf_sliding", "sim_sliding_max_cm")


@dataclass
class Demand:
    """The demand stage's output.

    ``cases``: every case with its regression columns, ``pulse_share`` and ``demand_source``;
    ``governing``: per item (index ``id``), the governing demand over its suite
    (:data:`assess.fragility.governing` columns); ``at_mu_ends``: per item with a μ range, the
    demand at each end (:func:`~assess.fragility.friction_range.demand_at_ends`).
    """

    cases: pd.DataFrame
    governing: pd.DataFrame
    at_mu_ends: pd.DataFrame


def item_demand(cases: pd.DataFrame, runs: pd.DataFrame, planar, simulated_as: dict,
                constants: RegressionConstants, settings: Settings) -> Demand:
    """The regression per case and the governing demand per item (module docstring)."""
    cases = add_pulse_share(regression_demand(cases, constants))
    cases["demand_source"] = motion_sources(cases, simulated_as, constants)
    room_quantile = 1.0 - settings.risk_pf_moderate
    harm = settings.rocking_harm_theta_over_alpha
    governing = governing_demand(cases, runs, constants, room_quantile=room_quantile, planar=planar,
                                 harm_theta_over_alpha=harm)
    return Demand(cases, governing, demand_at_ends(cases, runs, planar, constants, room_quantile, harm))


@dataclass(frozen=True)
class GoverningDemand:
    """One freestanding item's demand row: the regression's numbers for its governing case
    (:data:`GOVERNING_CASE_COLUMNS`, eqs. 7, 11, 20 and 21 of Konstantinidis & Makris 2010), which case that is
    and whether the regression applies to it, and the governing demand over its suite
    (:data:`assess.fragility.governing.DEMAND_COLUMNS`, ``demand_mode`` as ``mode``). Values are as the stages
    computed them (numpy scalars where pandas gave them); the summary's columns of the same names
    (``docs/outputs.md``) say what each is. Lengths in cm, accelerations in g, angles in rad."""

    # the governing case: its geometry and the regression's numbers (GOVERNING_CASE_COLUMNS)
    alpha_rad: float
    p_rad_s: float
    b_over_h: float
    mode: str  #: the most severe mode any run of the suite reaches (the governing demand's), else the case's
    pta_g: float
    tp_s: float
    im: float
    edp_median: float
    sliding_median_cm: float
    sliding_p84_cm: float
    pf_sliding: float
    sim_sliding_max_cm: float
    governing_direction: int
    governing_motion: str
    regression_note: str  #: why the regression does not apply to the governing case ("" where it does)
    regression_applies: bool
    pulse_share: float  #: the share of PTA the governing motion's pulse carries (whether ``tp_s`` is a pulse's)
    # the governing demand over the suite (assess.fragility.governing.DEMAND_COLUMNS)
    demand_source: tuple
    demand_median_cm: float
    demand_p84_cm: float
    demand_median_low_cm: float
    demand_median_high_cm: float
    demand_p84_low_cm: float
    demand_p84_high_cm: float
    demand_room_cm: float
    p_beyond_clearance: float
    p_beyond_clearance_low: float
    p_beyond_clearance_high: float
    p_overturn: float
    p_overturn_low: float
    p_overturn_high: float
    suite_motions: int
    suite_histories: int
    theta_max_over_alpha: float
    demand_note: str
    demand_planar: bool
    demand_uplift: bool
    p_rocking_harm: float
    p_rocking_harm_low: float
    p_rocking_harm_high: float
    overturn_fraction: float  #: = ``p_overturn``

    def as_row(self) -> dict:
        """The row as a dict (field: value), for the summary and for the decisions, which take rows."""
        return {item.name: getattr(self, item.name) for item in fields(self)}


@dataclass(frozen=True)
class ItemDemand:
    """Per freestanding item (by id): its demand row (``rows``: :class:`GoverningDemand`) and whether it uplifts
    under any motion (``uplift``)."""

    rows: dict[str, GoverningDemand]
    uplift: dict[str, bool]

    def row_dicts(self) -> dict[str, dict]:
        """Each item's row as a dict, by id (what :func:`assess.decision.decisions.decide` takes)."""
        return {item_id: row.as_row() for item_id, row in self.rows.items()}


def item_rows(equipment: pd.DataFrame, cases: pd.DataFrame, demand: Demand,
              constants: RegressionConstants) -> ItemDemand:
    """Each freestanding item's demand row (:class:`ItemDemand`), ``cases`` those at the workbook's μ.

    ``mode`` is the governing demand's (``demand_mode``: the most severe mode any run of the suite reaches,
    so that it agrees with ``p_overturn`` and ``theta_max_over_alpha``), not the governing case's."""
    governing = governing_case(cases).set_index("id") if len(cases) else pd.DataFrame()
    rows, uplift = {}, {}
    for item in equipment[~equipment["anchored"]].itertuples(index=False):
        case = governing.loc[item.id]
        row = {column: case[column] for column in GOVERNING_CASE_COLUMNS}
        row["governing_direction"] = int(case["direction"])
        row["governing_motion"] = case["motion"]
        under_motion = cases[(cases["id"] == item.id) & (cases["motion_key"] == case["motion_key"])]
        row["regression_note"] = regression_note(float(case["pulse_share"]), float(case["im"]),
                                                 bool(under_motion["sim_uplift"].any()), constants)
        row["regression_applies"] = row["regression_note"] == ""
        row["pulse_share"] = float(case["pulse_share"])  # whether tp_s is a clear pulse's (the summary's tp_s)
        row.update(demand.governing.loc[item.id].to_dict())
        row["mode"] = row.pop("demand_mode") or row["mode"]
        row["overturn_fraction"] = row["p_overturn"]
        rows[item.id] = GoverningDemand(**row)
        uplift[item.id] = bool(cases.loc[cases["id"] == item.id, "sim_uplift"].any()) or bool(
            row.get("demand_uplift", False))
    return ItemDemand(rows, uplift)


def regression_demand(cases: pd.DataFrame, constants: RegressionConstants) -> pd.DataFrame:
    """Mode, IM, and the regression's sliding demand and Pf for each case.

    ``mode`` is the simulated one (``sim_mode``); ``mode_from_rest`` the mode
    the block enters first, by Shenton's criteria (:func:`initial_mode`). The
    regression's sliding demand applies where the simulation slides.
    """
    cases = cases.copy()
    cases["mode_from_rest"] = initial_mode(cases["pta_g"], cases["mu_static"], cases["b_over_h"],
                                           cases["inertia_ratio"])
    cases["mode"] = cases["sim_mode"]
    cases["im"] = intensity_measure(cases["pta_g"], cases["mu"])
    slides = cases["mode"].isin(SLIDING_MODES).to_numpy()
    im_sliding = np.where(slides, cases["im"], 0.0)  # no sliding from rest: zero demand
    median_m = sliding_quantile(im_sliding, cases["pta_g"], cases["tp_s"], constants, 0.5)
    p84_m = sliding_quantile(im_sliding, cases["pta_g"], cases["tp_s"], constants, 0.84)
    capacity = capacity_edp(cases["clearance_m"], cases["pta_g"], cases["tp_s"])
    pf = probability_of_exceedance(im_sliding, capacity, constants.zeta, constants.eta, constants.sigma)
    rocks_only = (cases["mode"] == ROCK).to_numpy()
    # A block that rocks without sliding has no sliding demand from this regression.
    cases["edp_median"] = np.where(rocks_only, np.nan, median_edp(im_sliding, constants.zeta, constants.eta))
    cases["sliding_median_cm"] = np.where(rocks_only, np.nan, median_m * CM_PER_M)
    cases["sliding_p84_cm"] = np.where(rocks_only, np.nan, p84_m * CM_PER_M)
    cases["capacity_edp"] = capacity
    cases["pf_sliding"] = np.where(rocks_only, np.nan, pf)
    cases["im_outside_fit"] = slides & ((cases["im"] < constants.im_min) | (cases["im"] > constants.im_max))
    return cases


def governing_case(cases: pd.DataFrame) -> pd.DataFrame:
    """Per item: the case that governs its summary row.

    Direction: the more slender one (smaller b/h). Motion: the one with the
    largest median sliding; where nothing slides, the strongest mode, then the
    largest PTA.
    """
    slender = cases.loc[cases.groupby("id")["b_over_h"].idxmin(), ["id", "direction"]]
    in_direction = cases.merge(slender, on=["id", "direction"])
    ranked = in_direction.assign(
        _severity=in_direction["mode"].map(MODE_SEVERITY),
        _sliding=in_direction["sliding_median_cm"].fillna(-1.0),
    ).sort_values(["id", "_sliding", "_severity", "pta_g"], ascending=[True, False, False, False],
                  kind="stable")
    worst_mode = in_direction.assign(_severity=in_direction["mode"].map(MODE_SEVERITY)) \
        .sort_values(["id", "_severity"], ascending=[True, False], kind="stable") \
        .drop_duplicates("id")[["id", "mode"]]
    governing = ranked.drop_duplicates("id").drop(columns=["_severity", "_sliding", "mode"])
    return governing.merge(worst_mode, on="id")
