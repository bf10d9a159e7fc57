"""The assessment, stage by stage; this module sequences the stages and decides nothing.

1. inputs: the workbook's hazard sheet checked (:mod:`assess.assessment.inputs`)
2. motions per floor: the level's motions, and what the engine runs for each
   (:mod:`assess.assessment.motions`)
3. cases: item x motion x direction (x μ node) (:mod:`assess.assessment.cases`)
4. run: the engine, through the runner (:mod:`assess.assessment.run`, the only stage that simulates)
5. demand: the regression per case and the governing demand per item (:mod:`assess.assessment.demand`)
   5b. what-if: the items that rock or overturn again with their heavy contents low
   (:func:`assess.assessment.run.lowered_contents`, for :mod:`assess.decision.actions`)
6. decisions: risk class, action, priority, anchorage, what-if, flags (:mod:`assess.decision.decisions`)
7. result: the summary and motion tables in an :class:`~assess.assessment.result.AssessmentResult`
   (:mod:`assess.assessment.summary`)
8. costs: expected loss, expected annual loss and the actions' benefit-cost ratios where the equipment
   gives a ``value`` (:mod:`assess.decision.costs`)
9. with ``--alpha-range``: stages 2 to 8 again at both ends of the building's α, for the items on the
   floors its motions reach (:mod:`assess.assessment.alpha_range`)

The outputs (CSV, xlsx, report) are made from the result by :mod:`assess.command.output`.
"""
from __future__ import annotations

import functools
from typing import Callable

import pandas as pd

from assess.anchorage import anchorage_site
from assess.assessment import alpha_range as alpha_ranges
from assess.assessment import cases as case_stage
from assess.assessment import demand as demand_stage
from assess.assessment import inputs, motions as motion_stage, run as run_stage, summary as result_stage
from assess.assessment.result import SUMMARY_COLUMNS, WORD_COLUMNS, AssessmentResult
from assess.calibration.apply import check_applies, with_declared
from assess.decision import actions, costs, decisions
from assess.fragility import RegressionConstants
from assess.fragility.agreement import fragility_at_level
from assess.fragility.governing import suite_runs
from assess.fragility.planar import with_planar_peaks
from assess.fragility.stripes import CURVE_COLUMNS
from assess.inventory import Inventory
from assess.mechanics.runner import LocalRunner

Progress = Callable[[str], None]


def run_assessment(inventory: Inventory, level_text: str, seed: int = 0,
                   progress: Progress = lambda message: None, oq_hazard=None,
                   derive_floors_roof: int | None = None, calibration=None, runner=None,
                   hazard_curve=None, allow_records_outside: bool = False, curve_risk=None,
                   alpha_range: tuple[float, float] | None = None) -> AssessmentResult:
    """Assess every item of ``inventory`` under the motions of hazard level ``level_text``.

    ``oq_hazard`` (an :class:`~assess.hazard.openquake.OpenQuakeHazard`)
    scales the level's motions to the site's PGA at that level
    (:func:`~assess.hazard.motions.scale_to_pga`). ``derive_floors_roof``
    (the roof's floor number) lets floors without a motion take their ground
    motions amplified by ASCE 7-16 eq. 13.3-1
    (:func:`~assess.hazard.motions.derive_floor_motions`); such items are flagged.

    ``calibration`` (an :class:`~assess.calibration.apply.AppliedCalibration`,
    ``--calibration``) switches its effect on for the items it applies to; the
    assessment then runs twice, as declared and with it, and each affected
    item's result both ways is flagged (:func:`~assess.calibration.apply.with_declared`).

    ``runner`` runs the engine's cases (:mod:`assess.mechanics.runner`; default: this machine's threads).

    ``hazard_curve`` (an OpenQuake hazard *curve*) adds each item's fragilities over stripes of floor
    acceleration and their annual rates over the curve (:mod:`assess.fragility.stripes`); it does not
    change the level's motions (``oq_hazard`` does). ``curve_risk`` (a
    :class:`~assess.fragility.stripes.CurveRisk` of stripes of ground acceleration through the building,
    from another level of the same workbook and curve) is taken as it is, simulating no stripe: the
    stripes are fixed in ground acceleration, so one level's serve every level
    (:mod:`assess.fragility.ground_stripes`).

    ``alpha_range`` (low, high: :func:`assess.assessment.alpha_range.alpha_ends`) runs the level again with the
    building's lateral stiffness ratio α at each, for the items on the floors its motions reach, and puts their
    risk classes and chances there beside the level's (:func:`~assess.assessment.alpha_range.with_alpha_range`).

    Raises :class:`~assess.errors.InputError` when the hazard sheet breaks a rule
    (:func:`assess.assessment.inputs.hazard_problems`: a record outside the workbook's folder unless
    ``allow_records_outside``, a vp of 0), the level is missing, a floor has no motion, or a motion
    cannot be described by PTA and Tp.
    """
    inputs.check_inputs(inventory, allow_records_outside)
    runner = runner if runner is not None else LocalRunner()
    step = functools.partial(_assess, inventory, level_text, seed, progress, oq_hazard, derive_floors_roof,
                             runner=runner, given_curve=curve_risk)
    applied = None if calibration is None or calibration.effect == "none" else calibration
    if calibration is None:
        result = step(calibration=None, hazard_curve=hazard_curve)
    else:  # a calibration (assess.calibration.apply): run twice, as declared and with the effect
        check_applies(calibration, inventory.equipment)
        # the curve's stripes run once, in the assessment that is returned (the declared one if no effect)
        declared = step(calibration=None, hazard_curve=hazard_curve if applied is None else None)
        progress(f"again with the calibration {calibration.file}")
        calibrated = step(calibration=calibration, hazard_curve=None if applied is None else hazard_curve)
        result = with_declared(calibrated, declared, calibration)
    if alpha_range is None:
        return result
    # the level again at both ends of the building's α, for the items its motions reach (no what-if, no curve)
    ids = alpha_ranges.items_through_building(result)
    at_ends = {}
    for alpha in alpha_range if ids else ():
        progress(f"again at the building's α {alpha:.3g} ({len(ids)} items on its floors)")
        at_ends[alpha] = _assess(alpha_ranges.at_alpha(inventory, ids, alpha), level_text, seed,
                                 _prefixed(progress, f"α {alpha:.3g}: "), oq_hazard, derive_floors_roof,
                                 calibration=applied, runner=runner, hazard_curve=None, what_if=False)
    return alpha_ranges.with_alpha_range(result, inventory.building, alpha_range, at_ends)


def _prefixed(progress: Progress, prefix: str) -> Progress:
    """``progress`` with every message after ``prefix``."""
    return lambda message: progress(prefix + message)


def _assess(inventory, level_text, seed, progress, oq_hazard, derive_floors_roof, calibration,
            runner, hazard_curve, given_curve=None, what_if: bool = True) -> AssessmentResult:
    """:func:`run_assessment` with ``calibration`` applied (None: as declared); ``what_if`` False leaves out the
    run of the items with their heavy contents low (stage 5b)."""
    workbook_name = inventory.path.name
    settings = inventory.settings
    constants = RegressionConstants.from_settings(settings)
    # 2. motions per floor (the site's ground suite and the building's floors included)
    level = motion_stage.level_motions(inventory, level_text, progress, oq_hazard, derive_floors_roof,
                                       calibration, seed)
    simulated = motion_stage.simulated_motions(level, workbook_name, settings, seed, progress)
    # 3. cases
    cases = case_stage.build_cases(inventory.equipment, level, workbook_name, progress)
    # 4. run (every engine call of the assessment)
    ran = run_stage.run_level(cases.table, simulated, runner, progress, calibration)
    nominal = ran.cases["mu_nominal"].to_numpy()
    curve = None
    if hazard_curve is not None:  # the whole curve: fragilities over stripes, annual rates (at the nominal mu)
        curve = run_stage.curve(ran.cases[nominal], simulated, level.table, hazard_curve, settings, runner,
                                progress, building=level.building, level_label=level.level_label,
                                given=given_curve)
    histories = run_stage.worst_histories(ran.cases, ran.runs[nominal[ran.runs["case"].to_numpy()]],
                                          inventory.equipment, simulated, runner)
    # 5. demand
    demand = demand_stage.item_demand(ran.cases, ran.runs, ran.planar, simulated.kinds, constants, settings)
    at_mu = demand.cases[nominal]
    rows = demand_stage.item_rows(inventory.equipment, at_mu, demand, constants)
    # 5b. what if the items that rock or overturn had their heavy contents low (the engine again)
    lowered = _lowered_contents(inventory.equipment, cases.table, rows, simulated, runner, progress, calibration,
                                constants, settings) if what_if else {}
    # 6. decisions
    anchorage = anchorage_site(inventory.site, inventory.building, settings)
    decided = decisions.decide(inventory.equipment, rows.row_dicts(), rows.uplift, at_mu, demand.at_mu_ends, constants,
                               settings, anchorage, lowered=lowered)
    decided = decisions.with_input_warnings(decided, inventory.warnings)  # sizes no equipment has
    # 7. result
    ground_method = "" if level.site is None else str(level.site.suite.method)
    origins = result_stage.floor_origins(level.table, ground_method)
    summary = result_stage.summarise(inventory.equipment, rows, decided, origins)
    summary_columns = SUMMARY_COLUMNS
    if curve is not None:
        summary = summary.merge(curve.table, on="id", how="left")
        # the fragilities at this level's accelerations, beside the level's answer (the report says which governs)
        summary = summary.merge(fragility_at_level(at_mu, level.table, curve), on="id", how="left")
        summary_columns = SUMMARY_COLUMNS + CURVE_COLUMNS
    # 8. costs: expected losses and the actions' benefit-cost ratios, where the equipment gives a value
    summary = pd.concat([summary, costs.cost_table(summary, inventory.equipment, settings, curve is not None)],
                        axis=1)
    return AssessmentResult(
        workbook=inventory.path, facility=settings.facility,
        site=settings.site, level=level.level, level_label=level.level_label,
        summary=summary[[column for column in summary_columns if column in summary or column not in WORD_COLUMNS]],
        motions=result_stage.motion_table(with_planar_peaks(at_mu, ran.planar)),
        flags=decided.flags, regression=result_stage.regression_record(constants, settings),
        settings=settings, simulated=True, seed=seed, histories=histories, hazard_notes=level.notes,
        suite_runs=suite_runs(demand.cases, ran.runs, ran.planar),
        solver_runs={str(k): int(v) for k, v in ran.runs["solver"].value_counts().items()}, curve_risk=curve,
        ground_motions=None if level.site is None else level.site.suite.ground_motions,
        spectrum=None if level.site is None else level.site.suite.spectrum, floors=simulated.floors,
        anchorage=anchorage, ground_method=ground_method,
        design_spectrum=None if level.site is None else level.site.design,
        site_class=str(getattr(inventory.site, "site_class", None) or ""), floor_origins=origins,
        decisions=decided.items,
    )


def _lowered_contents(equipment, case_table, rows, simulated, runner, progress, calibration, constants,
                      settings) -> dict:
    """The demand of the items that rock or overturn with their heavy contents low
    (:func:`assess.decision.actions.lowered_contents_items`): their cases with the centre of mass at
    ``lower_contents_cg_fraction`` of the height, run and reduced like the level's
    (:func:`assess.decision.actions.lowered_rows`); {} when no item rocks or overturns."""
    ids = actions.lowered_contents_items(equipment, rows.row_dicts(), rows.uplift, settings)
    if not ids:
        return {}
    lowered_cases = case_stage.with_centre_of_mass_at(case_table, ids, settings.lower_contents_cg_fraction)
    ran = run_stage.lowered_contents(lowered_cases, simulated, runner, progress, calibration)
    demand = demand_stage.item_demand(ran.cases, ran.runs, ran.planar, simulated.kinds, constants, settings)
    nominal = ran.cases["mu_nominal"].to_numpy()
    found = demand_stage.item_rows(equipment[equipment["id"].isin(ids)], demand.cases[nominal], demand, constants)
    return actions.lowered_rows(equipment, found.row_dicts(), found.uplift, settings)
