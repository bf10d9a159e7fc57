"""The documented result of an assessment (what the report and the CSVs show)."""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import pandas as pd

from assess.decision.costs import COST_COLUMNS
from assess.decision.decisions import ItemDecision
from assess.decision.flags import Flag
from assess.hazard.levels import HazardLevel
from assess.inventory.settings import Settings

if TYPE_CHECKING:  # the annotations only (the result's producers import this module)
    from assess.anchorage.item import AnchorageSite
    from assess.fragility.stripes import CurveRisk
    from assess.site.asce7 import DesignSpectrum

#: Columns of ``summary.csv`` in order, each documented in docs/outputs.md (tests/project/test_docs.py).
SUMMARY_COLUMNS = [
    "id", "name", "room", "floor", "quantity", "alpha_rad", "p_rad_s", "b_over_h",
    "governing_direction", "mu", "mode", "governing_motion", "pta_g", "tp_s", "im",
    "edp_median", "sliding_median_cm", "sliding_p84_cm", "clearance_cm", "pf_sliding",
    "overturn_fraction", "theta_max_over_alpha", "risk", "action", "flags", "sim_sliding_max_cm",
    "demand_source", "demand_median_cm", "demand_p84_cm", "p_beyond_clearance", "p_overturn",
    "demand_room_cm", "demand_median_low_cm", "demand_median_high_cm", "demand_p84_low_cm", "demand_p84_high_cm",
    "p_beyond_clearance_low", "p_beyond_clearance_high", "p_overturn_low", "p_overturn_high",
    "risk_range", "suite_motions", "suite_histories", "demand_note", "action_kind", "priority", "consequence",
    "priority_score", "component_type", "ip", "anchor_force_kn", "anchor_force_kip", "anchor_moment_knm",
    "anchor_moment_kip_ft", "anchor_tension_kn", "anchor_tension_kip", "anchor_omega0", "anchor_shear_omega_kn",
    "anchor_shear_omega_kip", "anchor_tension_omega_kn", "anchor_tension_omega_kip", "anchor_basis", "what_if",
    "p_overturn_after", "p_beyond_clearance_after", "action_mode", "action_analysis", "action_detail",
    "action_reference", "contents", "type_source", "connections", "connection_detail", "connection_reference",
    "demand_planar", "mu_low", "mu_high", "risk_mu_low", "risk_mu_high", "p_beyond_clearance_mu_low",
    "p_beyond_clearance_mu_high", "mu_range_note", "mu_source",
    "p_rocking_harm", "p_rocking_harm_low", "p_rocking_harm_high", "performance_objective", "risk_reason",
    "regression_applies", "regression_note",
] + COST_COLUMNS  # what failures cost and actions buy (assess/decision/costs.py); empty where no value is given

#: The summary's columns that are words or US forces: the report makes them from ``decisions`` in its units
#: (:func:`assess.report.advice.with_words`); until then ``cost_note`` holds the cost stage's kinds
#: (:class:`assess.decision.costs.CostNote`) and the others are absent.
WORD_COLUMNS = ("action", "what_if", "risk_reason", "anchor_basis", "cost_note", "anchor_force_kip",
                "anchor_moment_kip_ft", "anchor_tension_kip", "anchor_shear_omega_kip", "anchor_tension_omega_kip")

#: Columns of ``motions.csv`` in order, each documented in docs/outputs.md (tests/project/test_docs.py).
MOTION_COLUMNS = [
    "id", "motion", "direction", "pta_g", "tp_s", "im", "edp_median", "sliding_median_cm",
    "pf_sliding", "sim_sliding_max_cm", "sim_theta_max_over_alpha", "sim_overturned",
    "floor", "vp_cm_s", "b_over_h", "alpha_rad", "mode", "sliding_p84_cm", "capacity_edp",
    "flags", "mode_from_rest", "sim_sliding_residual_cm", "sim_uplift", "sim_motion", "sim_solver",
    "sim_realizations", "sim_overturn_share", "pulse_source", "pulse_share", "demand_source",
    "planar_sliding_cm",
]

RISK_CLASSES = ("high", "moderate", "low", "anchored")


@dataclass(frozen=True)
class RegressionRecord:
    """The regression's constants as used, Pi = zeta IM**eta Z, ln Z ~ N(0, sigma**2), and the IM range it was
    fitted on (Konstantinidis & Makris 2010, eqs. 11 and 21, Table 3), and where they come from (``source``:
    the paper, or the workbook's settings sheet; "" when not known). The defaults are the paper's."""

    zeta: float = Settings().zeta
    eta: float = Settings().eta
    sigma: float = Settings().sigma
    im_min: float = Settings().im_min
    im_max: float = Settings().im_max
    source: str = ""


@dataclass
class AssessmentResult:
    """Everything one ``assess WORKBOOK --hazard LEVEL`` run computed.

    Attributes
    ----------
    workbook : Path
    facility, site : str
        From the workbook's settings ("" when not given).
    level : HazardLevel
        The level assessed; ``level_label`` is the spelling the workbook uses.
    summary : DataFrame
        One row per item, :data:`SUMMARY_COLUMNS`; lengths in cm, accelerations in g.
        ``mode``, ``overturn_fraction``, ``theta_max_over_alpha`` and
        ``sim_sliding_max_cm`` come from the time-history simulation. ``flags`` (the codes of the
        item's :attr:`flags`) and ``demand_source`` (what its governing demand comes from) are tuples;
        the files join them into text (:func:`assess.report.tables.summary_text`).
    motions : DataFrame
        One row per freestanding item x motion x direction, :data:`MOTION_COLUMNS`.
        ``direction`` is 1 (along width) or 2 (along depth); ``sim_*`` from the
        engine (``sim_motion`` says what was simulated, ``sim_solver`` which
        solver answered); a motion simulated under ``sim_realizations``
        synthetic histories gives the medians of its runs and the share that
        overturn (``sim_overturn_share``; ``sim_overturned`` if at least half); ``mode`` is the simulated mode,
        ``mode_from_rest`` the mode entered first by Shenton's criteria.
    flags : list[Flag]
    regression : RegressionRecord
        ``zeta``, ``eta``, ``sigma``, ``im_min``, ``im_max`` as used, and ``source`` (the paper, or the
        workbook's settings sheet).
    settings : Settings
        The settings used (:class:`assess.inventory.settings.Settings`: the defaults and the workbook's).
    simulated : bool
        Whether the time-history engine ran.
    seed : int
    histories : list of dict
        Time histories of the worst items (Fig. 7 of the paper): ``id``,
        ``name``, ``motion``, ``direction``, ``time_s``, ``sliding_cm``,
        ``theta_over_alpha``, ``floor_accel_g`` and what was simulated.
    hazard_notes : list of str
        How the motions were changed from the workbook's (e.g. scaled to an
        OpenQuake PGA), for the report.
    suite_runs : DataFrame or None
        What the governing demand is made of: one row per item × motion × history
        (:func:`assess.fragility.governing.suite_runs`), for the report's item details.
    solver_runs : dict or None
        How many runs each solver answered.
    comparison : DataFrame or None
        Against a previous run (:func:`assess.assessment.comparison.compare_summaries`):
        which items changed risk class and why; written as comparison.csv.
    curve_risk : CurveRisk or None
        With a hazard curve: each item's fragilities over stripes of floor acceleration and their
        annual rates (:class:`assess.fragility.stripes.CurveRisk`); its columns are also in ``summary``.
    anchorage : AnchorageSite or None
        What the anchorage design forces took from the site, the building and the settings
        (:class:`assess.anchorage.AnchorageSite`): the edition, S_DS, the Risk Category, z/h and T_a.
    ground_motions, spectrum : DataFrame or None
        With a ``site`` sheet that gives the level's ground suite: one row per ground motion, and one per
        period of the suite's spectrum against its target (``ground_motions.csv``, ``spectrum.csv``).
    floors : DataFrame or None
        With a ``building`` sheet: the modes used and each floor's PFA and PFA/PGA over the suite
        (``floors.csv``).
    ground_method : str
        How the site made the level's ground suite (:attr:`assess.site.suite.GroundSuite.method`:
        ``records``, ``matched records`` or ``synthetic``); "" where the level's motions are the hazard sheet's.
    design_spectrum : DesignSpectrum or None
        The site's ASCE 7 spectrum (:class:`assess.site.asce7.DesignSpectrum`) where the site sheet gives one;
        ``site_class`` the site sheet's site class ("" where it gives none).
    decisions : dict[str, ItemDecision]
        id -> :class:`assess.decision.decisions.ItemDecision`: what was decided for each item, in numbers and
        kinds; the summary's columns that are words or US forces are made from it by the report
        (:func:`assess.report.advice.with_words`), absent from ``summary`` until then.
    floor_origins : dict
        Where each floor's time histories come from (:func:`assess.assessment.summary.floor_origins`):
        floor (None: every floor) -> ``workbook``, ``site records``, ``site matched records``, ``site synthetic``, with
        ``+building`` where they passed through the building.
    """

    workbook: Path
    facility: str
    site: str
    level: HazardLevel
    level_label: str
    summary: pd.DataFrame
    motions: pd.DataFrame
    flags: list[Flag] = field(default_factory=list)
    regression: RegressionRecord = field(default_factory=RegressionRecord)
    settings: Settings = field(default_factory=Settings)
    simulated: bool = False
    seed: int = 0
    histories: list = field(default_factory=list)
    hazard_notes: list = field(default_factory=list)
    comparison: pd.DataFrame | None = None
    suite_runs: pd.DataFrame | None = None
    solver_runs: dict | None = None
    curve_risk: CurveRisk | None = None
    ground_motions: pd.DataFrame | None = None
    spectrum: pd.DataFrame | None = None
    floors: pd.DataFrame | None = None
    anchorage: AnchorageSite | None = None
    decisions: dict[str, ItemDecision] = field(default_factory=dict)
    ground_method: str = ""
    design_spectrum: DesignSpectrum | None = None
    site_class: str = ""
    floor_origins: dict = field(default_factory=dict)

    def work_orders(self) -> pd.DataFrame:
        """The actions grouped by floor, room and action (work_orders.csv,
        :func:`assess.decision.actions.work_orders`)."""
        from assess.decision.actions import work_orders
        from assess.quantity_text import floor_numbering_of
        return work_orders(self.summary, floor_numbering_of(self.settings))

    def risk_counts(self) -> dict[str, int]:
        """Number of items (rows, not quantity) in each risk class."""
        counts = self.summary["risk"].value_counts()
        return {risk: int(counts.get(risk, 0)) for risk in RISK_CLASSES}
