"""The assessment, step by step: inventory -> hazard -> mechanics -> fragility -> result.

Each step is a call to a pure function of the sub-packages; this module only
sequences them and gathers their outputs into an :class:`AssessmentResult`.
"""
from __future__ import annotations

from pathlib import Path
from typing import Callable

import functools
import warnings

import numpy as np
import pandas as pd

from dataclasses import replace

from assess.errors import InputError
from assess.fragility.governing import (
    PULSE, RECORD, SYNTHETIC, add_pulse_share, governing_demand, motion_sources, suite_runs,
)
from assess.fragility import (
    RegressionConstants, capacity_edp, intensity_measure, median_edp,
    probability_of_exceedance, sliding_quantile,
)
from assess.hazard.motions import motions_by_item, select_level
from assess.hazard.records import MIN_DURATION_S, Record, pulse_record, read_record
from assess.fragility.friction_range import expand_cases, with_mu_range
from assess.fragility.planar import planar_runs, with_planar_peaks
from assess.inventory import Inventory
from assess.mechanics.block import Block
from assess.mechanics.gateway import run_responses
from assess.mechanics.runner import LocalRunner
from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2, frequency_parameter, inertia_ratio, slenderness
from assess.mechanics.modes import MODE_SEVERITY, ROCK, SLIDE, SLIDE_ROCK, initial_mode
from assess.result import MOTION_COLUMNS, SUMMARY_COLUMNS, AssessmentResult, Flag

Progress = Callable[[str], None]
UPLIFT_MODES = (ROCK, SLIDE_ROCK)
SLIDING_MODES = (SLIDE, SLIDE_ROCK)
DIRECTIONS = {1: "width_m", 2: "depth_m"}
#: Pulse simulated for a motion given by PTA and Tp without a pulse type.
DEFAULT_PULSE = "B"


def run_assessment(inventory: Inventory, level_text: str, seed: int = 0,
                   progress: Progress = lambda message: None, oq_hazard=None,
                   derive_floors_roof: int | None = None, calibration=None, runner=None,
                   hazard_curve=None) -> AssessmentResult:
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
    change the level's motions (``oq_hazard`` does).

    Raises :class:`~assess.errors.InputError` when the level is missing, a
    floor has no motion, or a motion cannot be described by PTA and Tp.
    """
    runner = runner if runner is not None else LocalRunner()
    step = functools.partial(_assess, inventory, level_text, seed, progress, oq_hazard, derive_floors_roof,
                             runner=runner, hazard_curve=hazard_curve)
    # --- calibration (assess.calibration.apply): run twice, as declared and with the effect
    if calibration is not None:
        from assess.calibration.apply import check_applies, with_declared
        check_applies(calibration, inventory.equipment)
        # the curve's stripes run once, in the assessment that is returned (the declared one if no effect)
        declared_governs = calibration.effect == "none"
        declared = step(calibration=None, hazard_curve=hazard_curve if declared_governs else None)
        progress(f"again with the calibration {calibration.file}")
        calibrated = step(calibration=calibration, hazard_curve=None if declared_governs else hazard_curve)
        return with_declared(calibrated, declared, calibration)
    return step(calibration=None)


def _assess(inventory, level_text, seed, progress, oq_hazard, derive_floors_roof, calibration,
            runner, hazard_curve) -> AssessmentResult:
    """:func:`run_assessment` with ``calibration`` applied (None: as declared)."""
    workbook_name = inventory.path.name
    settings = inventory.settings
    constants = RegressionConstants.from_settings(settings)
    level, level_motions = select_level(inventory.hazard, level_text, workbook_name)
    level_label = str(level_motions["level_label"].iloc[0])
    level_motions, hazard_notes = _measure_pulse_parameters(level_motions, workbook_name)
    for note in hazard_notes:
        progress(note)
    if oq_hazard is not None:
        from assess.hazard.motions import require_probability, scale_to_pga
        from assess.hazard.openquake import pga_at_level
        require_probability(level, level_label, workbook_name, "--oq-hazard")
        pga_g = pga_at_level(oq_hazard, level)
        level_motions, _, note = scale_to_pga(level_motions, pga_g, workbook_name, Path(oq_hazard.path).name)
        hazard_notes.append(note)
        progress(note)
    if calibration is not None:  # input_scale: the motions (assess.calibration.apply)
        from assess.calibration.apply import scaled_motions
        level_motions, note = scaled_motions(level_motions, calibration)
        if note:
            hazard_notes.append(note)

    equipment = inventory.equipment
    freestanding = equipment[~equipment["anchored"]]
    if derive_floors_roof is not None:
        from assess.hazard.motions import derive_floor_motions
        level_motions = derive_floor_motions(level_motions, freestanding["floor"].unique(), derive_floors_roof,
                                             workbook_name)
        if level_motions["derived"].any():
            floors = sorted(set(int(f) for f in level_motions.loc[level_motions["derived"], "floor"]))
            note = (f"Floors {floors} have no motion in the workbook: their motions are the ground motions "
                    f"amplified by 1 + 2z/h (ASCE 7-16 eq. 13.3-1, roof = floor {derive_floors_roof}), "
                    f"with the ground's pulse period.")
            hazard_notes.append(note)
            progress(note)
    # one key per motion row: a motion named on several floors is a different motion on each
    level_motions = level_motions.reset_index(drop=True).assign(motion_key=lambda m: np.arange(len(m)))
    pairs = motions_by_item(freestanding, level_motions, level_label, workbook_name)
    progress(f"{len(freestanding)} freestanding items, {len(level_motions)} motions at level "
             f"{level_label}: {len(pairs) * len(DIRECTIONS)} item x motion x direction cases")

    cases = _item_motion_direction_cases(freestanding, pairs)
    progress("preparing the motions to simulate")
    simulated_motions, simulated_as = _simulated_motions(level_motions, workbook_name, settings, seed)
    record_pairs = _record_pairs(level_motions, simulated_motions, workbook_name, hazard_notes, progress)
    cases, runs = _add_simulation(cases, simulated_motions, progress, runner, calibration, record_pairs)
    cases = add_pulse_share(_add_demand(cases, constants))
    cases["demand_source"] = motion_sources(cases, simulated_as, constants)
    planar = planar_runs(cases, record_pairs, runner)  # items that cannot uplift, under both components at once
    room_quantile = 1.0 - float(settings["risk_pf_moderate"])
    demand = governing_demand(cases, runs, constants, room_quantile=room_quantile, planar=planar)
    nominal = cases["mu_nominal"].to_numpy()
    summary, flags = _summarise(equipment, cases[nominal], demand, constants, settings)
    summary = with_mu_range(summary, cases, runs, planar, constants, settings, room_quantile, classify_risk)
    curve = None
    summary_columns = SUMMARY_COLUMNS
    if hazard_curve is not None:  # the whole curve: fragilities over stripes, annual rates (at the nominal mu)
        from assess.fragility.stripes import CURVE_COLUMNS, curve_risk
        curve = curve_risk(cases[nominal], simulated_motions, level_motions, hazard_curve, settings, runner,
                           progress, record_pairs=record_pairs)
        summary = summary.merge(curve.table, on="id", how="left")
        summary_columns = SUMMARY_COLUMNS + CURVE_COLUMNS
    histories = _worst_histories(cases, runs[nominal[runs["case"].to_numpy()]], summary, simulated_motions,
                                 record_pairs, runner)
    regression = {"zeta": constants.zeta, "eta": constants.eta, "sigma": constants.sigma,
                  "im_min": constants.im_min, "im_max": constants.im_max,
                  "source": _regression_source(settings)}
    return AssessmentResult(
        workbook=inventory.path, facility=str(settings.get("facility", "")),
        site=str(settings.get("site", "")), level=level, level_label=level_label,
        summary=summary[summary_columns], motions=_motion_table(with_planar_peaks(cases[nominal], planar)),
        flags=flags,
        regression=regression, settings=dict(settings), simulated=True, seed=seed,
        histories=histories, hazard_notes=hazard_notes, suite_runs=suite_runs(cases, runs, planar),
        solver_runs={str(k): int(v) for k, v in runs["solver"].value_counts().items()}, curve_risk=curve,
    )


def _motion_record(record_path: str, scale: float, motion: str, row: int, workbook_name: str) -> Record:
    """The record of a hazard row, read (once per file and scale) and scaled; errors name the row."""
    try:
        return _read_scaled(record_path, float(scale))
    except InputError as error:
        raise InputError([replace(problem, message=f"the record of motion '{motion}' "
                                  f"({workbook_name}, sheet 'hazard', row {int(row)}): "
                                  f"{problem.message}") for problem in error.problems]) from None


@functools.lru_cache(maxsize=64)
def _read_scaled(path: str, scale: float) -> Record:
    return read_record(path, min_duration_s=MIN_DURATION_S, scale=scale)


def _measure_pulse_parameters(level_motions: pd.DataFrame, workbook_name: str) -> tuple[pd.DataFrame, list[str]]:
    """Fill PTA, Tp and vp that a motion with a record leaves empty, from the record.

    PTA is the record's peak absolute acceleration (after ``scale``); Tp and
    vp come from a Type-B pulse fitted to its velocity
    (:func:`assess.hazard.pulse_identification.identify_pulse`; the paper's
    regression was fitted with Type-B periods). ``pulse_source`` says, per
    motion, where its numbers came from; the notes go to the report.
    """
    from assess.hazard.pulse_identification import identify_pulse

    motions = level_motions.assign(pulse_source="workbook")
    notes = []
    for index, row in motions.iterrows():
        missing = [c for c in ("pta_g", "tp_s", "vp_m_s") if not np.isfinite(row[c])]
        if not row["record_path"] or not missing:
            continue
        record = _motion_record(row["record_path"], row["scale"], row["motion"], row["row"], workbook_name)
        measured = []
        if "pta_g" in missing:
            motions.at[index, "pta_g"] = record.pta_g
            measured.append(f"PTA {record.pta_g:.3f} g")
        if {"tp_s", "vp_m_s"} & set(missing):
            fit = identify_pulse(record.accel_g, record.dt_s, models=("B",))
            if "tp_s" in missing:
                motions.at[index, "tp_s"] = fit.tp_s
                measured.append(f"Tp {fit.tp_s:.2f} s")
            if "vp_m_s" in missing:
                motions.at[index, "vp_m_s"] = fit.vp_m_s
                measured.append(f"vp {fit.vp_m_s * 100:.0f} cm/s")
            clarity = "a clear pulse" if fit.is_pulse_like else "no clear pulse: Tp is only the best single pulse"
            source = f"measured from the record (Type-B fit explains {fit.fit_r2:.0%} of the velocity; {clarity})"
        else:
            source = "PTA measured from the record"
        motions.at[index, "pulse_source"] = source
        notes.append(f"Motion '{row['motion']}': {', '.join(measured)} {source}.")
    return motions, notes


def _simulated_motions(level_motions: pd.DataFrame, workbook_name: str, settings: dict,
                       seed: int) -> tuple[dict[int, list[tuple[Record, str]]], dict[int, str]]:
    """Per motion (``motion_key``): the floor accelerations the engine simulates, each with how it
    was obtained; and how each motion was simulated (``record``, ``synthetic`` or ``pulse``).

    A motion with a record is simulated under the record (times ``scale``).
    One given by PTA, Tp and vp is simulated under ``synthetic_realizations``
    near-fault histories synthesised to match them
    (:func:`assess.hazard.synthesis.synthesize_motion`, seeded by ``seed`` and
    the motion's place in the sheet) when ``simulate_motions`` is
    ``synthetic``, or under its pulse (:data:`DEFAULT_PULSE` where the workbook
    names none) when it is ``pulse`` or vp is not given.
    """
    from assess.hazard.synthesis import synthesize_motion

    synthetic = str(settings.get("simulate_motions", "synthetic")).strip().lower() == "synthetic"
    count = int(settings.get("synthetic_realizations", 5))
    motions, kinds = {}, {}
    for row in level_motions.itertuples(index=False):
        k = int(row.motion_key)
        if row.record_path:
            record = _motion_record(row.record_path, row.scale, row.motion, row.row, workbook_name)
            motions[k], kinds[k] = [(record, f"record {record.name} x {float(row.scale):g}")], RECORD
            continue
        pta, tp, vp = float(row.pta_g), float(row.tp_s), float(row.vp_m_s)
        if synthetic and np.isfinite(vp):
            with warnings.catch_warnings():  # a pulse above PTA is said in the record's name
                warnings.simplefilter("ignore")
                records = synthesize_motion(pta, tp, vp, n_realizations=count,
                                            seed=np.random.default_rng([seed, k]))
            motions[k], kinds[k] = [(r, r.name) for r in records], SYNTHETIC
            continue
        pulse = row.pulse or DEFAULT_PULSE
        record = pulse_record(pulse, pta, tp)
        note = f"Type-{pulse} pulse" if row.pulse else f"Type-{pulse} pulse (assumed: no pulse type given)"
        if synthetic:
            note += " (no vp given to synthesise from)"
        motions[k], kinds[k] = [(record, f"{note}, {pta:g} g, Tp {tp:g} s")], PULSE
    return motions, kinds


def _record_pairs(level_motions: pd.DataFrame, motions: dict, workbook_name: str, notes: list,
                  progress: Progress) -> dict[int, tuple[Record, Record]]:
    """Per motion with ``record_2``: its accelerations along the items' width and depth
    (:func:`assess.hazard.record_pairs.item_axes_pair`); ``motions`` then holds the width one."""
    from assess.hazard.record_pairs import item_axes_pair

    pairs = {}
    for row in level_motions.itertuples(index=False):
        second_path = str(getattr(row, "record_2_path", "") or "")
        if not second_path or not row.record_path:
            continue
        k = int(row.motion_key)
        first = _motion_record(row.record_path, row.scale, row.motion, row.row, workbook_name)
        try:
            second = _motion_record(second_path, row.scale, row.motion, row.row, workbook_name)
        except InputError as error:  # say which of the two components it is
            raise InputError([replace(problem, message=f"record_2: {problem.message}")
                              for problem in error.problems]) from None
        width, depth, note = item_axes_pair(first, second, float(row.azimuth_deg), row.motion, row.row,
                                            workbook_name)
        if note:
            notes.append(note)
            progress(note)
        pairs[k] = (width, depth)
        motions[k] = [(width, f"records {first.name} + {second.name} x {float(row.scale):g}"
                       + (f", turned {float(row.azimuth_deg):g} deg" if float(row.azimuth_deg) else ""))]
    return pairs


def _case_block(case, calibration=None) -> Block:
    block = Block(half_width_m=float(case.half_width_m), cg_height_m=float(case.cg_height_m),
                  height_m=float(case.height_m), mu=float(case.mu), mu_static=float(case.mu_static))
    if calibration is None:
        return block
    from assess.calibration.apply import case_block  # the calibration's effect, where it applies
    return case_block(block, case.id, calibration)


def _majority_mode(modes: pd.Series) -> str:
    """The most frequent mode; a tie goes to the more severe."""
    counts = modes.value_counts()
    tied = counts[counts == counts.max()].index
    return max(tied, key=lambda mode: MODE_SEVERITY[mode])


def _add_simulation(cases: pd.DataFrame, motions: dict[int, list[tuple[Record, str]]],
                    progress: Progress, runner, calibration=None,
                    record_pairs: dict | None = None) -> tuple[pd.DataFrame, pd.DataFrame]:
    """Simulate every case under every history of its motion: ``sim_*`` columns, and the runs.

    A case's ``sim_*`` values summarise its runs (one per history): the
    median peak sliding, residual and θmax/α, the share of runs that overturn
    (``sim_overturn_share``; ``sim_overturned`` when at least half do), uplift
    in any run, the most frequent mode. The second table holds every run.
    A motion in ``record_pairs`` runs direction 2 under its component along the items' depth.
    """
    record_pairs = record_pairs or {}
    histories = [(name, r, 1) for name in motions for r in range(len(motions[name]))] + [
        (name, 0, 2) for name in record_pairs]
    index_of = {key: j for j, key in enumerate(histories)}
    run_case, run_history = [], []
    for k, case in enumerate(cases.itertuples(index=False)):
        axis = 2 if case.motion_key in record_pairs and case.direction == 2 else 1
        for r in range(len(motions[case.motion_key])):
            run_case.append(k)
            run_history.append(index_of[(case.motion_key, r, axis)])
    run_case = np.asarray(run_case)
    blocks_by_case = [_case_block(case, calibration) for case in cases.itertuples(index=False)]
    cases = cases.assign(block=blocks_by_case)  # built once: the histories re-run these blocks
    if calibration is not None:  # the case's friction is its block's (the regression's IM uses it)
        cases = cases.assign(mu=[b.mu for b in blocks_by_case], mu_static=[b.mu_static for b in blocks_by_case])
    last = [-1.0]

    def report(done, total):
        if done == total or done - last[0] >= max(1, total // 10):
            last[0] = done
            progress(f"simulated {done} of {total} runs ({len(cases)} cases)")

    records = [motions[n][r][0] if axis == 1 else record_pairs[n][1] for n, r, axis in histories]
    peaks = runner.simulate_cases([blocks_by_case[k] for k in run_case],
                           [record.accel_g for record in records],
                           [record.dt_s for record in records], np.asarray(run_history),
                           progress=report)
    theta_max_over_alpha = peaks.theta_max_over_alpha
    if calibration is not None:  # over α of the declared box, feet or not (docs/calibration.md)
        from assess.calibration.apply import theta_over_declared
        theta_max_over_alpha = theta_over_declared(theta_max_over_alpha, [blocks_by_case[k] for k in run_case])
    runs = pd.DataFrame({
        "case": run_case, "realization": [histories[j][1] for j in run_history],
        "sliding_max_cm": peaks.sliding_max_m * 100.0, "sliding_residual_cm": peaks.sliding_residual_m * 100.0,
        "theta_max_over_alpha": theta_max_over_alpha, "uplift": peaks.uplift,
        "overturned": peaks.overturned, "mode": peaks.mode, "solver": peaks.solver})
    grouped = runs.groupby("case", sort=True)
    summary = pd.DataFrame({
        "sim_realizations": grouped.size(),
        "sim_sliding_max_cm": grouped["sliding_max_cm"].median(),
        "sim_sliding_residual_cm": grouped["sliding_residual_cm"].median(),
        "sim_theta_max_over_alpha": grouped["theta_max_over_alpha"].median(),
        "sim_overturn_share": grouped["overturned"].mean(),
        "sim_uplift": grouped["uplift"].any(),
        "sim_mode": grouped["mode"].agg(_majority_mode),
        "sim_solver": grouped["solver"].agg(lambda s: " | ".join(sorted(set(s)))),
    })
    summary["sim_overturned"] = summary["sim_overturn_share"] >= 0.5
    cases = cases.reset_index(drop=True).join(summary.reset_index(drop=True))
    cases["sim_motion"] = cases["motion_key"].map(
        {n: (motions[n][0][1] if len(motions[n]) == 1 else f"{len(motions[n])} synthetic histories: "
             + motions[n][0][1].split(",", 1)[1].strip().replace(", seed", "; first seed", 1))
         for n in motions})
    return cases, runs


def _worst_histories(cases: pd.DataFrame, runs: pd.DataFrame, summary: pd.DataFrame,
                     motions: dict[int, list[tuple[Record, str]]], record_pairs: dict | None = None,
                     runner=None) -> list[dict]:
    """Time histories of every item's worst run, worst items first (the report draws the first
    :data:`assess.report.render.HISTORY_FIGURES` as Fig. 7 of the paper, and every one small in the item's details).

    Worst: overturned first, then the largest θmax/α, then the largest
    simulated sliding over clearance; for each item, its worst run, run again with its histories
    through ``runner`` (all in one batch).
    """
    ranked = runs.assign(
        id=cases["id"].to_numpy()[runs["case"]],
        _over=runs["overturned"].astype(int),
        _ratio=runs["sliding_max_cm"] / (cases["clearance_m"].to_numpy()[runs["case"]] * 100.0),
    ).sort_values(["_over", "theta_max_over_alpha", "_ratio"], ascending=False, kind="stable")
    worst = ranked.drop_duplicates("id")
    names = summary.set_index("id")["name"]
    chosen = []
    for run in worst.itertuples(index=False):
        case = cases.iloc[int(run.case)]
        record, description = motions[case.motion_key][int(run.realization)]
        if record_pairs and case.motion_key in record_pairs and int(case.direction) == 2:
            record = record_pairs[case.motion_key][1]
        chosen.append((case, record, description))
    responses = run_responses([(case["block"], record.accel_g, record.dt_s) for case, record, _ in chosen],
                              runner, history=True)
    histories = []
    for (case, record, description), response in zip(chosen, responses):
        floor = np.zeros(response.time_s.size)
        floor[:min(record.accel_g.size, floor.size)] = record.accel_g[:floor.size]
        histories.append({
            "id": case.id, "name": names[case.id], "motion": case.motion, "direction": int(case.direction),
            "sim_motion": description, "mode": response.mode, "solver": response.solver,
            "alpha_rad": float(case.alpha_rad), "time_s": response.time_s,
            "sliding_cm": response.sliding_m * 100.0, "theta_over_alpha": response.theta_rad / case.alpha_rad,
            "floor_accel_g": floor, "overturned": bool(response.overturned),
            "clearance_cm": float(case.clearance_m) * 100.0,
        })
    return histories


def _item_motion_direction_cases(items: pd.DataFrame, pairs: pd.DataFrame) -> pd.DataFrame:
    """One row per item x motion x direction with the block's geometry in that direction."""
    item_columns = ["id", "floor", "height_m", "width_m", "depth_m", "cg_height_m", "mu",
                    "mu_static", "clearance_m"] + [c for c in ("mu_low", "mu_high") if c in items]
    motion_columns = ["id", "motion", "motion_key", "pta_g", "tp_s", "vp_m_s", "pulse_source"] + (
        ["derived"] if "derived" in pairs else [])
    base = pairs[motion_columns].assign(pair_index=range(len(pairs))) \
        .merge(items[item_columns], on="id", validate="many_to_one")
    frames = []
    for direction, dimension in DIRECTIONS.items():
        frame = base.assign(direction=direction, half_width_m=base[dimension] / 2.0)
        frames.append(frame)
    cases = pd.concat(frames, ignore_index=True)
    cases["b_over_h"] = cases["half_width_m"] / cases["cg_height_m"]
    cases["alpha_rad"] = slenderness(cases["half_width_m"], cases["cg_height_m"])
    cases["p_rad_s"] = frequency_parameter(cases["half_width_m"], cases["cg_height_m"], cases["height_m"])
    cases["inertia_ratio"] = inertia_ratio(cases["half_width_m"], cases["cg_height_m"], cases["height_m"])
    return expand_cases(cases)  # an item with a μ range: its cases at its μ values (friction_range)


def _add_demand(cases: pd.DataFrame, constants: RegressionConstants) -> pd.DataFrame:
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
    cases["sliding_median_cm"] = np.where(rocks_only, np.nan, median_m * 100.0)
    cases["sliding_p84_cm"] = np.where(rocks_only, np.nan, p84_m * 100.0)
    cases["capacity_edp"] = capacity
    cases["pf_sliding"] = np.where(rocks_only, np.nan, pf)
    cases["im_outside_fit"] = slides & ((cases["im"] < constants.im_min) | (cases["im"] > constants.im_max))
    return cases


def _governing(cases: pd.DataFrame) -> pd.DataFrame:
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


def _summarise(equipment: pd.DataFrame, cases: pd.DataFrame, demand: pd.DataFrame,
               constants: RegressionConstants, settings: dict) -> tuple[pd.DataFrame, list[Flag]]:
    """One row per item: its geometry, the regression's numbers for its governing case, the
    governing demand over its suite (``demand``), and the risk class and action that follow from it."""
    governing = _governing(cases).set_index("id") if len(cases) else pd.DataFrame()
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
                        "mode": "", "risk": "anchored", "action": "None: anchored (not analysed as freestanding)",
                        "action_kind": "anchored",
                        "flags": ""})
            rows.append(row)
            continue
        case = governing.loc[item.id]
        item_cases = cases[cases["id"] == item.id]
        row.update({column: case[column] for column in (
            "alpha_rad", "p_rad_s", "b_over_h", "mode", "pta_g", "tp_s", "im", "edp_median",
            "sliding_median_cm", "sliding_p84_cm", "pf_sliding", "sim_sliding_max_cm")})
        row["governing_direction"] = int(case["direction"])
        row["governing_motion"] = case["motion"]
        row.update(demand.loc[item.id].to_dict())
        row["overturn_fraction"] = row["p_overturn"]
        uplift = bool(item_cases["sim_uplift"].any()) or bool(row.get("demand_uplift", False))
        item_flags = _item_flags(item, item_cases, constants)
        flags.extend(item_flags)
        row["flags"] = "; ".join(flag.code for flag in item_flags)
        row["risk"] = classify_risk(row["p_beyond_clearance"], row["p_overturn"], uplift, settings)
        bounds = {classify_risk(p, row["p_overturn"], uplift, settings)
                  for p in (row["p_beyond_clearance_low"], row["p_beyond_clearance_high"])}
        row["risk_range"] = _risk_range(row["risk"], bounds)
        row["action"] = recommended_action(row, uplift, settings)
        row["action_kind"] = action_kind(row, uplift)
        row.update(anchorage_demand(item, row, settings))
        row["what_if"] = what_if(row, settings)
        row["priority_score"] = priority_score(row["consequence"], row["p_overturn"], row["p_beyond_clearance"],
                                               uplift)
        rows.append(row)
    summary = pd.DataFrame(rows)
    summary["priority"] = priorities(summary)
    return summary, flags


def what_if(row: dict, settings: dict) -> str:
    """The item's risk if the action is taken, in one sentence from its own numbers (its governing demand).

    >>> what_if({"action_kind": "room", "demand_room_cm": 54.2, "clearance_cm": 20.0, "p_overturn": 0.0},
    ...         {"risk_pf_moderate": 0.1})
    'Anchored or restrained, it would neither slide nor overturn. Given 55 cm of room (it has 20 cm), its chance of sliding past it would be 10%: low risk.'
    """
    kind = row.get("action_kind")
    if kind not in ("anchor", "restrain", "room"):
        return ""
    anchored = "Anchored or restrained, it would neither slide nor overturn."
    if kind == "anchor":
        return anchored + (" Giving it room does not help: it overturns or rocks where it stands.")
    room = float(np.ceil(row["demand_room_cm"]))
    return (f"{anchored} Given {room:.0f} cm of room (it has {np.floor(row['clearance_cm']):.0f} cm), its chance of "
            f"sliding past it would be {float(settings['risk_pf_moderate']):.0%}: low risk.")


def anchorage_demand(item, row: dict, settings: dict) -> dict:
    """For an item to anchor or restrain: the ASCE 7-16 §13.3.1 design force and what it does at the base
    (:mod:`assess.fragility.anchorage`), about the base edge of the more slender direction.

    ``anchor_force_kn`` (F_p, per unit), ``anchor_moment_knm``, ``anchor_tension_kn`` and
    ``anchor_basis`` (the factors used, in words); NaN and a sentence saying what is missing where
    ``sds_g`` is not in the settings.
    """
    from assess.fragility.anchorage import (
        COMPONENT_AMPLIFICATION, COMPONENT_RESPONSE_MODIFICATION, base_overturning, component_design_force,
        importance_factor,
    )

    empty = {"anchor_force_kn": np.nan, "anchor_moment_knm": np.nan, "anchor_tension_kn": np.nan,
             "anchor_basis": ""}
    if row.get("action_kind") not in ("anchor", "restrain"):
        return empty
    sds_g = float(settings.get("sds_g", 0.0))
    if not sds_g > 0.0:
        return {**empty, "anchor_basis": "add sds_g (and roof_floor) to the settings for the ASCE 7-16 design force"}
    roof = float(settings.get("roof_floor", 0.0))
    z_over_h = min(max(float(item.floor) / roof, 0.0), 1.0) if roof > 0.0 else 1.0
    importance = importance_factor(row.get("consequence", "ordinary"))
    weight_n = float(item.mass_kg) * STANDARD_GRAVITY_M_S2
    force_n = float(component_design_force(weight_n, sds_g, z_over_h, importance))
    half_width_m = min(float(item.width_m), float(item.depth_m)) / 2.0
    moment_nm, tension_n = (float(x) for x in base_overturning(force_n, float(item.cg_height_m), weight_n,
                                                               half_width_m, sds_g))
    basis = (f"ASCE 7-16 eqs. 13.3-1 to 13.3-3: a_p {COMPONENT_AMPLIFICATION:g}, R_p "
             f"{COMPONENT_RESPONSE_MODIFICATION:g} (Table 13.5-1), I_p {importance:g} (§13.1.3), S_DS {sds_g:g} g, "
             f"z/h {z_over_h:.2f}{'' if roof > 0.0 else ' (roof_floor not given: z/h = 1)'}; W_p "
             f"{weight_n / 1000:.2f} kN per unit; tension from 0.9D - 1.0E with E_v = 0.2 S_DS D, "
             "without the overstrength factor for anchors in concrete (§13.4.2)")
    return {"anchor_force_kn": force_n / 1000.0, "anchor_moment_knm": moment_nm / 1000.0,
            "anchor_tension_kn": tension_n / 1000.0, "anchor_basis": basis}


#: Weight of what an item's failure costs (the workbook's ``consequence``), for the order of action.
CONSEQUENCE_WEIGHTS = {"life-safety": 5.0, "hazardous": 4.0, "critical": 3.0, "valuable": 2.0, "ordinary": 1.0}
#: Share of an overturning's cost that sliding past the room carries (it hits, pulls its lines, blocks).
SLIDING_SEVERITY = 0.5
#: Stand-in probability of overturning for an item that rocks but did not overturn under its motions.
UPLIFT_SEVERITY = 0.25


def priority_score(consequence: str, p_overturn: float, p_beyond_clearance: float, uplift: bool) -> float:
    """How urgent an item is: its consequence weight times the worst of its chances, overturning
    counting fully, sliding past its room by :data:`SLIDING_SEVERITY`, rocking without overturning by
    :data:`UPLIFT_SEVERITY`.

    >>> priority_score("hazardous", 0.2, 0.0, True), priority_score("ordinary", 0.0, 1.0, False)
    (1.0, 0.5)
    """
    weight = CONSEQUENCE_WEIGHTS.get(str(consequence), 1.0)
    return weight * max(p_overturn, SLIDING_SEVERITY * p_beyond_clearance, UPLIFT_SEVERITY if uplift else 0.0)


def priorities(summary: pd.DataFrame) -> pd.Series:
    """``priority``: 1 = act first, by ``priority_score`` (ties by id); items that need no action and
    anchored items come last, in id order."""
    needs = ~summary["action_kind"].isin(["none", "anchored"])
    score = summary["priority_score"].where(needs, -1.0).fillna(-1.0)
    order = pd.DataFrame({"score": -score, "id": summary["id"].astype(str)}).sort_values(
        ["score", "id"], kind="mergesort").index
    ranks = pd.Series(0, index=summary.index)
    ranks.loc[order] = np.arange(1, len(order) + 1)
    return ranks


def classify_risk(p_beyond_clearance: float, p_overturn: float, uplift: bool, settings: dict) -> str:
    """Risk class from the governing demand.

    ``high`` when the item overturns under any motion of its suite
    (``p_overturn`` > 0), uplifts (rocks) under any, or slides past its
    clearance with probability ≥ ``risk_pf_high``; ``moderate`` when that
    probability ≥ ``risk_pf_moderate``; else ``low``.

    >>> settings = {"risk_pf_high": 0.5, "risk_pf_moderate": 0.1}
    >>> classify_risk(0.2, 0.0, False, settings), classify_risk(0.0, 0.1, True, settings)
    ('moderate', 'high')
    """
    if p_overturn > 0.0 or uplift or p_beyond_clearance >= float(settings["risk_pf_high"]):
        return "high"
    if p_beyond_clearance >= float(settings["risk_pf_moderate"]):
        return "moderate"
    return "low"


def _risk_range(risk: str, classes: set) -> str:
    """The classes the 90 % interval of P(sliding > clearance) spans, when it spans more than ``risk``."""
    classes = classes | {risk}
    if len(classes) == 1:
        return ""
    order = ["low", "moderate", "high"]
    spanned = sorted(classes, key=order.index)
    return f"{spanned[0]} to {spanned[-1]}"


def _suite_share_text(probability: float, row: dict) -> str:
    """"2 of its 3 motions" for records, "12 % of its 30 synthetic histories" otherwise."""
    motions, histories = int(row["suite_motions"]), int(row["suite_histories"])
    if histories == motions:
        count = probability * motions
        if abs(count - round(count)) > 1e-9:  # runs weighted over a range of mu
            return f"a weighted {probability:.0%} of its {motions} motion{'s' if motions != 1 else ''} over its range of mu"
        return f"{int(round(count))} of its {motions} motion{'s' if motions != 1 else ''}"
    return f"{probability:.0%} of its {histories} simulated histories ({motions} motion{'s' if motions != 1 else ''})"


def action_kind(row: dict, uplift: bool) -> str:
    """What the action asks for, in one word the report groups by: ``anchor`` (it overturns or
    rocks), ``restrain`` (high risk of sliding past its room), ``room`` (moderate), ``none``.

    >>> action_kind({"p_overturn": 0.0, "risk": "moderate"}, False)
    'room'
    """
    if row["p_overturn"] > 0.0 or uplift:
        return "anchor"
    return {"high": "restrain", "moderate": "room"}.get(row["risk"], "none")


def recommended_action(row: dict, uplift: bool, settings: dict) -> str:
    """A plain sentence a facility manager can act on, from the item's governing demand.

    The room to give is the sliding that is exceeded with probability
    ``risk_pf_moderate`` (``demand_room_cm``): with that much room the item
    would be low risk on sliding. It is rounded up and the clearance down, so
    the two never read alike.
    """
    if row["p_overturn"] > 0.0:
        return f"Anchor: it overturns under {_suite_share_text(row['p_overturn'], row)}"
    if uplift:
        return (f"Anchor or restrain: it uplifts and rocks (peak rotation {row['theta_max_over_alpha']:.2f} of "
                f"its overturning angle alpha) but did not overturn under its {int(row['suite_motions'])} "
                f"motion{'s' if row['suite_motions'] != 1 else ''}")
    if row["risk"] in ("high", "moderate"):
        verb = "Restrain it, or give it room" if row["risk"] == "high" else "Give it room, or restrain it"
        return (f"{verb}: it needs {np.ceil(row['demand_room_cm']):.0f} cm to be low risk and has "
                f"{np.floor(row['clearance_cm']):.0f} cm ({row['p_beyond_clearance']:.0%} chance of sliding past it)")
    return "No action needed"


def _item_flags(item, item_cases: pd.DataFrame, constants: RegressionConstants) -> list[Flag]:
    flags = []
    uplift = item_cases[item_cases["mode"].isin(UPLIFT_MODES)]
    if len(uplift):
        # the most slender direction, then the strongest motion
        worst = uplift.sort_values(["b_over_h", "pta_g"], ascending=[True, False], kind="stable").iloc[0]
        flags.append(Flag(item.id, "uplift", (
            f"{worst['mode']} under {worst['motion']} in direction {int(worst['direction'])} "
            f"(simulated; peak theta/alpha {worst['sim_theta_max_over_alpha']:.2f}"
            f"{', overturned' if worst['sim_overturned'] else ''}): "
            f"mu_static = {item.mu_static:.2f} >= b/h = {worst['b_over_h']:.2f} and PTA = {worst['pta_g']:.2f} g "
            f"> g b/h. The sliding regression assumes no uplift; the simulation answers for this item.")))
    outside = item_cases[item_cases["im_outside_fit"]]
    if len(outside):
        ims = ", ".join(f"{im:.2f}" for im in sorted(set(outside["im"].round(2))))
        flags.append(Flag(item.id, "im_outside_fit", (
            f"IM = {ims} lies outside the range {constants.im_min:.2f}-{constants.im_max:.2f} the "
            f"regression was fitted on: its numbers shown beside are an extrapolation, and the governing "
            f"demand does not use them for those motions.")))
    if "derived" in item_cases and item_cases["derived"].any():
        flags.append(Flag(item.id, "derived_floor_motion", (
            f"floor {item.floor} has no motion in the workbook: it was assessed under the ground motions "
            f"amplified by ASCE 7-16 eq. 13.3-1 (--derive-floors), an envelope rule, not a floor "
            f"response analysis.")))
    if not np.isclose(item.cg_height_m, item.height_m / 2.0):
        flags.append(Flag(item.id, "cg_not_mid_height", (
            f"centre of mass at {item.cg_height_m * 100:.0f} cm, not mid-height: alpha and b/h use it; "
            "p assumes the mass spread over the whole box.")))
    return flags


def _motion_table(cases: pd.DataFrame) -> pd.DataFrame:
    table = cases.assign(
        vp_cm_s=cases["vp_m_s"] * 100.0,
        flags=np.where(cases["im_outside_fit"], "im_outside_fit", ""),
    )
    table["flags"] = np.where(table["mode"].isin(UPLIFT_MODES),
                              np.where(table["flags"] == "", "uplift", table["flags"] + ";uplift"), table["flags"])
    table = table.sort_values(["pair_index", "direction"], kind="stable")  # workbook order
    return table[MOTION_COLUMNS].reset_index(drop=True)


def _regression_source(settings: dict) -> str:
    from assess.data import default_settings

    defaults = default_settings()
    if all(float(settings[key]) == float(defaults[key]) for key in ("zeta", "eta", "sigma")):
        return "Konstantinidis & Makris (2010), eq. 21 (Table 3 simulations)"
    return "the workbook's settings sheet"
