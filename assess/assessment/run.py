"""Stage 4 of the assessment: the engine. Every simulation the assessment asks for is started here.

This is the one place of the assessment that runs the rigid-body engine
(:mod:`assess.mechanics`): each case under every history of its motion through
the runner (:func:`simulate_cases`), the planar pairs of the items that cannot
uplift (:func:`planar`), the stripes of the hazard curve (:func:`curve`), the
items that rock or overturn again with their heavy contents low (:func:`lowered_contents`, the
actions' what-if) and the worst run of each item again with its time history (:func:`worst_histories`).
"""
from __future__ import annotations

from collections import Counter
from dataclasses import dataclass
from typing import Callable

import numpy as np
import pandas as pd

from assess.calibration.apply import case_block, theta_over_declared
from assess.fragility.ground_stripes import ground_curve_risk, ground_sources
from assess.fragility.planar import planar_runs
from assess.inventory.units import CM_PER_M
from assess.quantity_text import floor_numbering_of
from assess.fragility.stripes import curve_risk
from assess.hazard.records import Record
from assess.inventory.settings import Settings
from assess.mechanics.block import Block
from assess.mechanics.gateway import run_responses
from assess.mechanics.modes import MODE_SEVERITY

Progress = Callable[[str], None]


@dataclass
class Runs:
    """What the engine answered for the level.

    ``cases``: the cases with their ``sim_*`` columns and ``block``; ``runs``: one row per case x history
    (``case`` is the row of ``cases``); ``planar``: the planar peaks of the items that cannot uplift
    (:func:`assess.fragility.planar.planar_runs`).
    """

    cases: pd.DataFrame
    runs: pd.DataFrame
    planar: object


def run_level(cases: pd.DataFrame, motions, runner, progress: Progress, calibration=None) -> Runs:
    """Simulate every case under every history of its motion (``motions``:
    :class:`assess.assessment.motions.SimulatedMotions`), and the items that cannot uplift under both
    components of a pair of records at once (:func:`assess.fragility.planar.planar_runs`)."""
    simulated, runs = simulate_cases(cases, motions.histories, progress, runner, calibration, motions.record_pairs)
    return Runs(simulated, runs, planar_runs(simulated, motions.record_pairs, runner))


def lowered_contents(cases: pd.DataFrame, motions, runner, progress: Progress, calibration=None) -> Runs:
    """The what-if run of the actions (:mod:`assess.decision.actions`): ``cases`` are those of the items whose heavy
    contents would be moved low, with their centre of mass lowered
    (:func:`assess.assessment.cases.with_centre_of_mass_at`), simulated under the same histories as the
    level (:func:`run_level`), through the same runner."""
    count = cases["id"].nunique()
    progress(f"what if: {count} {'item that rocks or overturns' if count == 1 else 'items that rock or overturn'}, "
             f"with {'its' if count == 1 else 'their'} heavy contents low")
    return run_level(cases, motions, runner, progress, calibration)


def curve(cases: pd.DataFrame, motions, level_motions: pd.DataFrame, hazard_curve, settings: Settings, runner,
          progress: Progress, building=None, level_label: str = "", given=None):
    """The items' fragilities over stripes of the hazard curve, at the nominal μ: stripes of ground
    acceleration through the building where ``building`` (the level's
    :class:`~assess.building.BuildingModes`) gives every floor's motions from the ground suite
    (:func:`assess.fragility.ground_stripes.ground_curve_risk`), else stripes of floor acceleration
    (:func:`assess.fragility.stripes.curve_risk`). ``given``: another level's stripes of ground
    acceleration through the same building, taken as they are where this level's would be of that kind."""
    sources = ground_sources(cases, level_motions) if building is not None else None
    if sources is not None and given is not None and given.intensity == "PGA":
        progress(f"annual rates: the fragilities over stripes of ground acceleration of {given.curve} already "
                 "computed for another level (the stripes do not depend on the level)")
        return given
    if sources is not None:
        return ground_curve_risk(cases, motions.histories, sources, building, hazard_curve, runner, progress,
                                 record_pairs=motions.record_pairs, level_label=level_label,
                                 numbering=floor_numbering_of(settings))
    return curve_risk(cases, motions.histories, level_motions, hazard_curve, settings, runner, progress,
                      record_pairs=motions.record_pairs)


def _case_block(case, calibration=None) -> Block:
    block = Block(half_width_m=float(case.half_width_m), cg_height_m=float(case.cg_height_m),
                  height_m=float(case.height_m), mu=float(case.mu), mu_static=float(case.mu_static))
    if calibration is None:
        return block
    return case_block(block, case.id, calibration)  # the calibration's effect, where it applies


def majority_modes(case: np.ndarray, mode) -> pd.Series:
    """Each case's most frequent mode over its runs (a tie goes to the more severe), by case in order."""
    counts: dict[int, Counter] = {}
    for k, m in zip(case.tolist(), mode):
        counts.setdefault(k, Counter())[m] += 1
    return pd.Series({k: max(c, key=lambda m: (c[m], MODE_SEVERITY[m])) for k, c in sorted(counts.items())})


def simulate_cases(cases: pd.DataFrame, motions: dict[int, list[tuple[Record, str]]],
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
    if calibration is not None:  # over α of the declared box, feet or not (docs/outputs.md)
        theta_max_over_alpha = theta_over_declared(theta_max_over_alpha, [blocks_by_case[k] for k in run_case])
    runs = pd.DataFrame({
        "case": run_case, "realization": [histories[j][1] for j in run_history],
        "sliding_max_cm": peaks.sliding_max_m * CM_PER_M, "sliding_residual_cm": peaks.sliding_residual_m * CM_PER_M,
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
        "sim_mode": majority_modes(run_case, peaks.mode),
        "sim_solver": grouped["solver"].agg(lambda s: " | ".join(sorted(set(s)))),
    })
    summary["sim_overturned"] = summary["sim_overturn_share"] >= 0.5
    cases = cases.reset_index(drop=True).join(summary.reset_index(drop=True))
    cases["sim_motion"] = cases["motion_key"].map(
        {n: (motions[n][0][1] if len(motions[n]) == 1 else f"{len(motions[n])} synthetic histories: "
             + motions[n][0][1].split(",", 1)[1].strip().replace(", seed", "; first seed", 1))
         for n in motions})
    return cases, runs


def worst_histories(cases: pd.DataFrame, runs: pd.DataFrame, equipment: pd.DataFrame, motions,
                    runner=None) -> list[dict]:
    """Time histories of every item's worst run, worst items first (the report draws the first
    :data:`assess.report.render.HISTORY_FIGURES` as Fig. 7 of the paper, and every one small in the item's details).

    Worst: overturned first, then the largest θmax/α, then the largest
    simulated sliding over clearance; for each item, its worst run, run again with its histories through
    ``runner`` (all in one batch). ``motions``: :class:`assess.assessment.motions.SimulatedMotions`;
    ``equipment`` gives the items' names.
    """
    record_pairs = motions.record_pairs
    motions = motions.histories
    ranked = runs.assign(
        id=cases["id"].to_numpy()[runs["case"]],
        _over=runs["overturned"].astype(int),
        _ratio=runs["sliding_max_cm"] / (cases["clearance_m"].to_numpy()[runs["case"]] * CM_PER_M),
    ).sort_values(["_over", "theta_max_over_alpha", "_ratio"], ascending=False, kind="stable")
    worst = ranked.drop_duplicates("id")
    names = equipment.set_index("id")["name"]
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
            "sliding_cm": response.sliding_m * CM_PER_M, "theta_over_alpha": response.theta_rad / case.alpha_rad,
            "floor_accel_g": floor, "overturned": bool(response.overturned),
            "clearance_cm": float(case.clearance_m) * CM_PER_M,
        })
    return histories
