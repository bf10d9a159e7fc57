"""Stage 7 of the assessment: the result, one row per item (``summary.csv``) and per case (``motions.csv``).

:func:`summarise` lays out, per item, what it is, the regression's numbers
for its governing case (empty where the regression does not apply: :func:`without_regression`)
and its governing demand (:mod:`assess.assessment.demand`), with the words of where its
time histories come from (:func:`floor_origins`, :func:`with_history_origin`),
and the decisions that follow from it (:mod:`assess.decision.decisions`); it decides
nothing. The columns are described in docs/outputs.md.
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from assess.assessment.motions import MEMORY
from assess.assessment.result import MOTION_COLUMNS, RegressionRecord
from assess.inventory.settings import Settings
from assess.inventory.units import CM_PER_M
from assess.decision import actions, decisions
from assess.fragility.regression import RegressionConstants
from assess.fragility.suite import PULSE_SHARE_MIN
from assess.mechanics.geometry import frequency_parameter, slenderness

UPLIFT_MODES = decisions.UPLIFT_MODES
#: The summary's numbers of the paper's regression for the governing case (Konstantinidis & Makris 2010,
#: eqs. 11, 20 and 21): empty where the regression does not apply to that case (``regression_applies``).
REGRESSION_COLUMNS = ("edp_median", "sliding_median_cm", "sliding_p84_cm", "pf_sliding")

#: Where a floor's time histories come from: the word an item's ``demand_source`` gives them (for the
#: engine under them, ``records`` in :mod:`assess.fragility.governing`) and the phrase a sentence gives them.
HISTORY_ORIGINS = {
    "workbook": ("records", "the workbook's records"),
    "site records": ("scaled records", "records selected from the site's records folder and scaled to the "
                                       "site's spectrum"),
    "site matched records": ("matched records", "records selected from the site's records folder and each "
                                                "matched to the site's spectrum"),
    "site synthetic": ("synthetic ground motions", "synthetic ground motions matched to the site's spectrum"),
}
#: Added to an origin (``site synthetic+building``) whose ground motions passed through the building to the floor.
THROUGH_BUILDING = "+building"
#: What :func:`assess.fragility.governing.governing_demand`'s demand note says of the motions simulated under
#: their own time histories, which :func:`with_history_origin` names by their origin.
GOVERNING_RECORD_WORDS = "simulated under their records"


def origin_words(origin: str) -> tuple[str, str]:
    """The ``demand_source`` word and the sentence's phrase of a floor's origin (:data:`HISTORY_ORIGINS`).

    >>> word, phrase = origin_words("site synthetic+building")
    >>> word
    'synthetic ground motions through the building'
    >>> phrase
    "synthetic ground motions matched to the site's spectrum, passed through the building"
    >>> origin_words("workbook")
    ('records', "the workbook's records")
    """
    ground, _, building = origin.partition(THROUGH_BUILDING)
    word, phrase = HISTORY_ORIGINS.get(ground, HISTORY_ORIGINS["workbook"])
    if origin.endswith(THROUGH_BUILDING):
        return f"{word} through the building", f"{phrase}, passed through the building"
    return word, phrase


def floor_origins(motions: pd.DataFrame, ground_method: str = "") -> dict:
    """Where each floor's time histories come from: floor (None for the hazard sheet's rows of every floor)
    -> an origin of :data:`HISTORY_ORIGINS` (``+building`` where the building passed them to the floor).

    ``motions``: the level's motions (:class:`assess.assessment.motions.LevelMotions` ``table``: ``floor``,
    ``all_floors``, ``record_path``, ``motion_key`` and, with a building, ``from_ground``); ``ground_method``
    the site's ground suite's (``records``, ``matched records`` or ``synthetic``; "" without one). A row with no
    record (PTA, Tp and vp) has no history of its own: the engine's synthetic histories of it are ``synthetic``.

    >>> table = pd.DataFrame({"motion_key": [0, 1, 2], "floor": [0, 2, 1], "all_floors": False,
    ...                       "record_path": ["memory:DE/1", "a.at2", ""], "from_ground": [-1, -1, 0]})
    >>> floor_origins(table, "synthetic")
    {0: 'site synthetic', 2: 'workbook', 1: 'site synthetic+building'}
    """
    of_key, of_floor = {}, {}
    for row in motions.to_dict("records"):
        path = str(row.get("record_path") or "")
        if path.startswith(MEMORY):
            of_key[row["motion_key"]] = f"site {ground_method}"
        elif path:
            of_key[row["motion_key"]] = "workbook"
    for row in motions.to_dict("records"):
        ground = row.get("from_ground", -1)
        if ground is not None and not pd.isna(ground) and int(ground) >= 0 and int(ground) in of_key:
            of_key[row["motion_key"]] = of_key[int(ground)] + THROUGH_BUILDING
        if row["motion_key"] in of_key:
            floor = None if bool(row.get("all_floors")) or pd.isna(row.get("floor")) else int(row["floor"])
            of_floor.setdefault(floor, of_key[row["motion_key"]])
    return of_floor


def with_history_origin(row: dict, origin: str) -> dict:
    """An item's demand row whose ``demand_source`` and ``demand_note`` name its time histories by their
    ``origin`` (:func:`origin_words`) instead of as the workbook's records."""
    if not origin or origin == "workbook":
        return row
    word, phrase = origin_words(origin)
    sources = row.get("demand_source")
    if isinstance(sources, tuple):
        row["demand_source"] = tuple(word if source == "records" else source for source in sources)
    if isinstance(row.get("demand_note"), str):
        row["demand_note"] = row["demand_note"].replace(GOVERNING_RECORD_WORDS,
                                                        f"simulated under their own histories, {phrase}")
    return row


def without_regression(row: dict) -> dict:
    """An item's row with the regression's numbers (:data:`REGRESSION_COLUMNS`) empty where the regression
    does not apply to its governing case, and ``tp_s`` empty where that motion has no clear pulse (its pulse
    carries less than :data:`~assess.fragility.suite.PULSE_SHARE_MIN` of its PTA: a best single pulse's
    period, not the motion's). Where the item does not slide from rest (IM ≤ 0: PTA ≤ μg) the regression's
    zeros stay: no sliding and P_f = 0 (eq. 20 at IM ≤ 0), whatever the motion, not an extrapolation.

    >>> row = {"regression_applies": False, "pulse_share": 0.02, "tp_s": 20.0, "im": 0.4, "pf_sliding": 1.0,
    ...        "edp_median": 0.3, "sliding_median_cm": 900.0, "sliding_p84_cm": 1400.0}
    >>> without_regression(row)["pf_sliding"], row["tp_s"]
    (nan, nan)
    >>> without_regression({"regression_applies": False, "pulse_share": 1.0, "im": -0.2, "pf_sliding": 0.0})
    {'regression_applies': False, 'pulse_share': 1.0, 'im': -0.2, 'pf_sliding': 0.0}
    """
    applies = row.get("regression_applies")
    at_rest = row.get("im") is not None and float(row["im"]) <= 0.0
    if (applies is False or applies is np.False_) and not at_rest:
        row.update({column: np.nan for column in REGRESSION_COLUMNS})
    share = row.get("pulse_share")
    if share is not None and np.isfinite(share) and share < PULSE_SHARE_MIN:
        row["tp_s"] = np.nan
    return row


def summarise(equipment: pd.DataFrame, demand, decided, origins: dict | None = None) -> pd.DataFrame:
    """One row per item, made of the pieces of the stages that own its columns (the ``stage`` of
    ``assess/data/columns.csv``): what it is (:func:`inventory_piece`, stage ``inventory``), its demand
    (:func:`demand_piece`, stage ``demand``, from ``demand``: :class:`assess.assessment.demand.ItemDemand`; an
    anchored item: :func:`anchored_piece`, its geometry about the more slender direction) and its decisions
    (``decided``: :class:`assess.decision.decisions.Decisions`, stages ``decision`` and ``anchorage``), each
    piece after the one before (a decision may complete a demand column: ``demand_note`` with a μ range).
    ``origins`` (:func:`floor_origins`) names each item's time histories by where its floor's come from."""
    origins = origins or {}
    rows = []
    for item in equipment.itertuples(index=False):
        if item.anchored:
            measured = anchored_piece(item)
        else:
            measured = demand_piece(demand.rows[item.id], origins.get(int(item.floor), origins.get(None, "")))
        rows.append({**inventory_piece(item), **measured, **decided.by_item[item.id]})
    return pd.DataFrame(rows)


def inventory_piece(item) -> dict:
    """The columns of an item's row that the workbook gives (stage ``inventory``), the clearance in cm."""
    return {"id": item.id, "name": item.name, "room": item.room, "floor": item.floor, "quantity": item.quantity,
            "consequence": decisions.item_consequence(item), "mu": item.mu,
            "contents": str(getattr(item, "contents", "") or actions.DEFAULT_CONTENTS),
            "type_source": str(getattr(item, "type_source", "") or "default"),
            "connections": str(getattr(item, "connections", "") or "none"),
            "mu_source": getattr(item, "mu_source", "workbook"), "clearance_cm": item.clearance_m * CM_PER_M}


def anchored_piece(item) -> dict:
    """An anchored item's demand columns (stage ``demand``): its geometry about its more slender direction, and
    no demand (it is not analysed as freestanding)."""
    half_width_m = min(item.width_m, item.depth_m) / 2.0
    return {"overturn_fraction": np.nan, "theta_max_over_alpha": np.nan,
            "alpha_rad": float(slenderness(half_width_m, item.cg_height_m)),
            "p_rad_s": float(frequency_parameter(half_width_m, item.cg_height_m, item.height_m)),
            "b_over_h": half_width_m / item.cg_height_m,
            "governing_direction": 1 if item.width_m <= item.depth_m else 2}


def demand_piece(governing, origin: str) -> dict:
    """A freestanding item's demand columns (stage ``demand``): its governing demand
    (:class:`assess.assessment.demand.GoverningDemand`), the regression's numbers only where it applies
    (:func:`without_regression`), its histories named by where its floor's come from (``origin``,
    :func:`with_history_origin`)."""
    return with_history_origin(without_regression(governing.as_row()), origin)


def motion_table(cases: pd.DataFrame) -> pd.DataFrame:
    """``motions.csv``: one row per case at the workbook's μ, in workbook order (:data:`MOTION_COLUMNS`)."""
    table = cases.assign(
        vp_cm_s=cases["vp_m_s"] * CM_PER_M,
        flags=np.where(cases["im_outside_fit"], "im_outside_fit", ""),
    )
    table["flags"] = np.where(table["mode"].isin(UPLIFT_MODES),
                              np.where(table["flags"] == "", "uplift", table["flags"] + ";uplift"), table["flags"])
    table = table.sort_values(["pair_index", "direction"], kind="stable")  # workbook order
    return table[MOTION_COLUMNS].reset_index(drop=True)


def regression_record(constants: RegressionConstants, settings: Settings) -> RegressionRecord:
    """The regression's constants as used, and where they come from (:attr:`AssessmentResult.regression`)."""
    return RegressionRecord(constants.zeta, constants.eta, constants.sigma, constants.im_min, constants.im_max,
                            regression_source(settings))


def regression_source(settings: Settings) -> str:
    """Where the regression's constants come from, for the report."""
    defaults = Settings()
    if (settings.zeta, settings.eta, settings.sigma) == (defaults.zeta, defaults.eta, defaults.sigma):
        return "Konstantinidis & Makris (2010), eq. 21 (Table 3 simulations)"
    return "the workbook's settings sheet"
