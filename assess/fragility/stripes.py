"""Each item's fragility from the engine, over stripes of floor acceleration, and its annual rate.

The level's suite answers "what happens at this level". Over the whole hazard
curve (PBEE) an item's annual rate of failure needs its fragility, P(fail | a),
at every floor acceleration a. Multiple-stripe analysis ([1]) gives it:

1. **Stripes.** For each floor, the histories of the floor's suite at the
   level (records, synthetic histories or pulses, as the level simulates
   them) are each scaled to a peak floor acceleration (PFA) x_j, for
   :data:`N_STRIPES` values spaced evenly in ln x between the floor's PFA at
   the annual rates :data:`STRIPE_RATES_PER_YR` of the hazard curve
   (:func:`stripe_levels_g`). Scaling a history to the stripe fixes the
   intensity exactly; the suite's shapes carry the record-to-record
   variability.
2. **Outcomes.** Every item runs under every scaled history in both base
   directions (the engine, as at the level). A history is one trial; it is a
   failure ``beyond_clearance`` when the peak sliding exceeds the clearance
   in either direction, ``overturn`` when the item overturns in either.
3. **Fit.** Where an item's outcomes jump from none to all failing between two
   stripes (a floor whose suite varies little), :data:`REFINE_STRIPES` more
   stripes inside that step are run for that item (:func:`refinement_plan`).
   Per item and failure mode, a lognormal fragility in PFA by
   maximum likelihood on the binomial outcomes, with its standard error
   (:func:`assess.fragility.msa.fit_lognormal_fragilities`); where the
   outcomes admit no finite fit (nothing failed, everything failed, the
   failures separated from the survivals) the status says why and no number
   is invented.
4. **Rate.** The fragility, moved to the curve's PGA by the floor's PFA/PGA
   ratio (:func:`floor_pfa_per_pga`), integrated over the curve
   (:func:`assess.hazard.risk_integral.openquake_failure_rate`); the
   probability in 50 years follows (Poisson). Without a fit, the rate is
   bounded where the outcomes allow (:func:`item_rates`).

The risk class and the advice stay those of the level (the design
earthquake the facility plans for); the annual rates answer the owner's other
question, "how likely over the building's life", beside them.

References
----------
.. [1] Baker, J. W. (2015). Efficient analytical fragility function fitting
   using dynamic structural analysis. Earthquake Spectra 31(1):579-599.
   doi:10.1193/021113EQS025M
.. [2] American Society of Civil Engineers (2017). ASCE/SEI 7-16, eq. 13.3-1
   (the floor amplification 1 + 2z/h used where a floor's ratio cannot be
   read from the workbook).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable

import numpy as np
import pandas as pd

from assess.fragility.msa import FITTED, FragilityFit, fit_lognormal_fragilities
from assess.hazard.openquake import OpenQuakeHazard
from assess.hazard.risk_integral import annual_rates_of_curve, openquake_failure_rate, probability_in_years

#: Number of stripes of floor acceleration.
N_STRIPES = 10
#: Annual rates of exceedance [1/yr] of the curve's PGA at the lowest and highest stripe (5 to 10,000 years).
STRIPE_RATES_PER_YR = (1.0 / 5.0, 1.0 / 10_000.0)
MODES = ("beyond_clearance", "overturn")

#: Columns the hazard curve adds to ``summary.csv`` (SPEC §6), then the fragilities they rest on.
CURVE_COLUMNS = [
    "annual_rate_beyond_clearance", "annual_rate_overturn", "p50yr_beyond_clearance", "p50yr_overturn",
    "annual_rate_beyond_clearance_low", "annual_rate_beyond_clearance_high", "annual_rate_overturn_low",
    "annual_rate_overturn_high", "p50yr_beyond_clearance_low", "p50yr_beyond_clearance_high",
    "p50yr_overturn_low", "p50yr_overturn_high",
    "fragility_beyond_clearance_median_g", "fragility_beyond_clearance_beta",
    "fragility_beyond_clearance_se_ln_median", "fragility_overturn_median_g", "fragility_overturn_beta",
    "fragility_overturn_se_ln_median", "pfa_per_pga", "curve_note",
]


@dataclass
class CurveRisk:
    """What the hazard curve added to an assessment.

    Attributes
    ----------
    table : DataFrame
        One row per freestanding item (``id``), :data:`CURVE_COLUMNS`.
    fits : dict
        ``{(id, mode): FragilityFit}`` for the export and the report.
    stripes : DataFrame
        Per item, mode and stripe: ``pfa_g``, ``trials``, ``failures`` (the data of the fits).
    floors : dict
        Per floor: ``pfa_per_pga`` and the sentence saying where it comes from.
    curve : str
        The curve's file name and site, for the report.
    runs : int
        Simulations run for the stripes.
    """

    table: pd.DataFrame
    fits: dict
    stripes: pd.DataFrame
    floors: dict
    curve: str
    runs: int
    notes: list = field(default_factory=list)


def curve_rates_per_yr(hazard: OpenQuakeHazard) -> tuple[np.ndarray, np.ndarray]:
    """The curve's levels [g] and annual rates [1/yr] at its site, levels with a finite, non-zero rate only."""
    rates = annual_rates_of_curve(hazard.poes[hazard.site_index], hazard.investigation_time_yr)
    usable = np.isfinite(rates) & (rates > 0.0)
    return np.asarray(hazard.levels_g, dtype=float)[usable], rates[usable]


def pga_at_rate_g(levels_g, rates_per_yr, rate_per_yr: float) -> float:
    """PGA [g] exceeded at ``rate_per_yr``, log-log between the curve's levels, clipped to its range.

    >>> round(pga_at_rate_g([0.1, 0.4], [1e-2, 1e-4], 1e-3), 6)  # halfway in log: sqrt(0.1*0.4)
    0.2
    >>> [round(pga_at_rate_g([0.1, 0.4], [1e-2, 1e-4], rate), 12) for rate in (1.0, 1e-9)]
    [0.1, 0.4]
    """
    levels, rates = np.log(np.asarray(levels_g, dtype=float)), np.log(np.asarray(rates_per_yr, dtype=float))
    # np.interp needs increasing x: the rates fall with the level
    return float(np.exp(np.interp(math.log(rate_per_yr), rates[::-1], levels[::-1])))


def stripe_levels_g(levels_g, rates_per_yr, pfa_per_pga: float, n_stripes: int = N_STRIPES,
                    rates=STRIPE_RATES_PER_YR) -> np.ndarray:
    """The stripes' peak floor accelerations [g]: evenly spaced in ln PFA between the floor's PFA at the
    curve's annual ``rates`` (PGA at those rates times ``pfa_per_pga``).

    >>> stripe_levels_g([0.1, 0.4], [1e-2, 1e-4], 1.5, n_stripes=3).round(4).tolist()
    [0.15, 0.3, 0.6]
    """
    low = pga_at_rate_g(levels_g, rates_per_yr, rates[0]) * pfa_per_pga
    high = pga_at_rate_g(levels_g, rates_per_yr, rates[1]) * pfa_per_pga
    if not high > low:
        raise ValueError("the curve does not span the stripes' rates")
    return np.exp(np.linspace(math.log(low), math.log(high), n_stripes))


def floor_pfa_per_pga(floor: int, suite_pta_g: dict, settings: dict) -> tuple[float, str]:
    """The floor's peak floor acceleration per peak ground acceleration, and where it comes from.

    The ground floor's is 1. Another floor's is the median PTA of its suite
    over the ground suite's median at the level, where the workbook gives
    both (the building's own amplification); otherwise ASCE 7-16 eq. 13.3-1,
    1 + 2 z/h with z/h = floor / ``roof_floor`` ([2]), an envelope; without
    ``roof_floor``, 3 (the roof's), the upper bound.

    ``suite_pta_g`` maps floor -> the PTAs [g] of its suite's motions.

    >>> floor_pfa_per_pga(2, {0: [0.5, 0.7], 2: [0.9]}, {})[0]
    1.5
    >>> floor_pfa_per_pga(2, {2: [0.9]}, {"roof_floor": 4})[0]
    2.0
    """
    if int(floor) == 0:
        return 1.0, "the ground floor: PFA = PGA"
    if 0 in suite_pta_g and floor in suite_pta_g:
        ratio = float(np.median(suite_pta_g[floor]) / np.median(suite_pta_g[0]))
        return ratio, (f"floor {floor}: PFA/PGA {ratio:.2f}, the median PTA of its motions over the ground "
                       "motions' at the level (the workbook's)")
    roof = float(settings.get("roof_floor", 0.0) or 0.0)
    if roof > 0.0:
        ratio = 1.0 + 2.0 * min(max(floor / roof, 0.0), 1.0)
        return ratio, (f"floor {floor}: PFA/PGA {ratio:.2f} by ASCE 7-16 eq. 13.3-1, 1 + 2z/h with roof = floor "
                       f"{roof:g} (no ground motion at the level to read it from)")
    return 3.0, (f"floor {floor}: PFA/PGA 3, the roof's by ASCE 7-16 eq. 13.3-1 (an upper bound: give "
                 "roof_floor in the settings, or the ground motions at the level)")


def stripe_runs(cases: pd.DataFrame, motions: dict, plan, runner,
                progress: Callable[[int, int], None] | None = None) -> pd.DataFrame:
    """Simulate items under their floor's suite scaled to stripes; one row per run.

    ``cases`` are the level's item x motion x direction cases (with their
    ``block``); ``motions`` the level's histories per ``motion_key``; ``plan``
    a list of ``(floor, pfa_g, ids)``: the floor's histories scaled to
    ``pfa_g`` [g], run by the items ``ids`` of that floor (None: all of them).
    Returns ``id``, ``direction``, ``pfa_g``, ``history`` (per floor),
    ``sliding_max_cm``, ``overturned``.
    """
    blocks, records, dts, index, rows = [], [], [], [], []
    per_item = cases.drop_duplicates(["id", "direction"])
    histories_of = {}
    for floor, pfa_g, ids in plan:
        if floor not in histories_of:
            keys = sorted(set(cases.loc[cases["floor"] == floor, "motion_key"]))
            histories_of[floor] = [record for key in keys for record, _ in motions[key]]
        on_floor = per_item[per_item["floor"] == floor]
        if ids is not None:
            on_floor = on_floor[on_floor["id"].isin(ids)]
        for h, record in enumerate(histories_of[floor]):
            peak_g = float(np.max(np.abs(record.accel_g)))
            records.append(record.accel_g * (pfa_g / peak_g))
            dts.append(record.dt_s)
            for case in on_floor.itertuples(index=False):
                blocks.append(case.block)
                index.append(len(records) - 1)
                rows.append((case.id, int(case.direction), float(pfa_g), h))
    if not blocks:
        return pd.DataFrame(columns=["id", "direction", "pfa_g", "history", "sliding_max_cm", "overturned"])
    peaks = runner.simulate_cases(blocks, records, dts, np.asarray(index), progress=progress)
    runs = pd.DataFrame(rows, columns=["id", "direction", "pfa_g", "history"])
    runs["sliding_max_cm"] = peaks.sliding_max_m * 100.0
    runs["overturned"] = peaks.overturned
    return runs


#: Stripes added inside a step (outcomes separated between two stripes) to find where it rises.
REFINE_STRIPES = 4


def refinement_plan(fits: dict, stripes_by_floor: dict, floor_of) -> list:
    """Stripes to add where an item's outcomes are a step (``separated``): :data:`REFINE_STRIPES`
    levels evenly in ln PFA strictly between the stripes on either side of the step, so that a
    failure mode that rises within one stripe spacing gets outcomes on its slope.
    """
    extra = {}
    for (item_id, _mode), fit in fits.items():
        if fit.status != "separated":
            continue
        floor = int(floor_of[item_id])
        levels = np.asarray(stripes_by_floor[floor])
        survived_g, failed_g = fit.separation_g
        below = levels[levels < survived_g * (1 - 1e-9)]
        above = levels[levels > failed_g * (1 + 1e-9)]
        low = survived_g if survived_g < failed_g else (below[-1] if below.size else survived_g / 1.5)
        high = failed_g if survived_g < failed_g else (above[0] if above.size else failed_g * 1.5)
        new = np.exp(np.linspace(math.log(low), math.log(high), REFINE_STRIPES + 2)[1:-1])
        extra.setdefault((floor, item_id), set()).update(float(x) for x in new)
    return [(floor, pfa_g, [item_id]) for (floor, item_id), levels in sorted(extra.items())
            for pfa_g in sorted(levels)]


def stripe_outcomes(runs: pd.DataFrame, clearance_cm: pd.Series) -> pd.DataFrame:
    """Per item, stripe and history: failed ``beyond_clearance`` / ``overturn`` in either direction."""
    per_history = runs.assign(beyond_clearance=runs["sliding_max_cm"] > runs["id"].map(clearance_cm)) \
        .groupby(["id", "pfa_g", "history"], sort=True)[["beyond_clearance", "overturned"]].any()
    return per_history.rename(columns={"overturned": "overturn"}).reset_index()


def fit_items(outcomes: pd.DataFrame) -> tuple[dict, pd.DataFrame]:
    """Fit every item's two fragilities; ``({(id, mode): FragilityFit}, stripes table)``."""
    stripes = outcomes.groupby(["id", "pfa_g"], sort=True)[list(MODES)].agg(["size", "sum"])
    ids = list(dict.fromkeys(stripes.index.get_level_values("id")))
    n_stripes = stripes.groupby(level="id").size().max()
    fits, table = {}, []
    for mode in MODES:
        x = np.ones((len(ids), n_stripes))
        n = np.zeros((len(ids), n_stripes), dtype=np.int64)
        z = np.zeros_like(n)
        for i, item_id in enumerate(ids):
            item = stripes.loc[item_id]
            k = len(item)
            x[i, :k] = item.index.to_numpy(dtype=float)
            n[i, :k] = item[(mode, "size")].to_numpy()
            z[i, :k] = item[(mode, "sum")].to_numpy()
            table.append(pd.DataFrame({"id": item_id, "mode": mode, "pfa_g": x[i, :k], "trials": n[i, :k],
                                       "failures": z[i, :k]}))
        for item_id, fit in zip(ids, fit_lognormal_fragilities(x, n, z)):
            fits[(item_id, mode)] = fit
    return fits, pd.concat(table, ignore_index=True)


#: z of the two-sided 90 % interval the rates carry (from the fit's standard error of ln θ).
Z_90 = 1.6448536269514722


def item_rates(fit: FragilityFit, mode: str, hazard: OpenQuakeHazard, levels_g, rates_per_yr,
               pfa_per_pga: float, stripes_g) -> dict:
    """Annual rate of one failure mode, its 90 % interval and probability in 50 years, and a sentence.

    * fitted: the fragility integrated over the curve; the interval moves θ by ±1.645 standard errors
      of ln θ (β held);
    * separated (every failure above every survival, so the fragility is a step somewhere between the
      highest survival x_s and the lowest failure x_f): a step at θ has the rate of the curve at θ, so
      the rate lies between λ(x_f) and λ(x_s); the value given is λ at their geometric mean;
    * never failed: below about λ at the top stripe (upper value only);
    * failed at every stripe: at least λ at the lowest stripe (lower value only).

    Keys: ``annual_rate_<mode>`` (+ ``_low``, ``_high``), ``p50yr_<mode>`` (+ ``_low``, ``_high``), ``note``.
    """
    def rate_at(pfa_g):  # a step fragility at pfa_g: the curve's rate at that PGA
        return _rate_at_pga(levels_g, rates_per_yr, pfa_g / pfa_per_pga)

    words = {"beyond_clearance": "slid past its clearance", "overturn": "overturned"}[mode]
    central = low = high = math.nan
    if fit.status == FITTED:
        rate = openquake_failure_rate(hazard, fit.median_g, fit.beta, pfa_per_pga=pfa_per_pga)
        central = rate.annual_rate
        shift = math.exp(Z_90 * fit.se_ln_median) if math.isfinite(fit.se_ln_median) else math.nan
        if math.isfinite(shift):
            low = openquake_failure_rate(hazard, fit.median_g * shift, fit.beta, pfa_per_pga=pfa_per_pga).annual_rate
            high = openquake_failure_rate(hazard, fit.median_g / shift, fit.beta, pfa_per_pga=pfa_per_pga).annual_rate
        note = f"{mode}: median {fit.median_g:.2g} g, beta {fit.beta:.2f}"
        note += "".join(f"; {text}" for text in rate.notes)
    elif fit.status == "separated":
        survived_g, failed_g = fit.separation_g
        central, low, high = rate_at(math.sqrt(survived_g * failed_g)), rate_at(failed_g), rate_at(survived_g)
        note = (f"{mode}: {words} in every simulation above {survived_g:.2g} g and in none below {failed_g:.2g} g "
                f"(a step, no fitted slope): the rate of a step between them")
        if survived_g == failed_g:
            note = (f"{mode}: {words} in every simulation above {survived_g:.2g} g and in none below it "
                    "(a step there, no fitted slope)")
    elif fit.status == "no_failures":
        top_g = float(np.max(stripes_g))
        high = rate_at(top_g) if math.isfinite(top_g) else math.nan
        note = f"{mode}: never {words} in {fit.n_trials} simulations up to the top stripe; rate below about that stripe's"
    elif fit.status == "all_failed":
        bottom_g = float(np.min(stripes_g))
        low = rate_at(bottom_g) if math.isfinite(bottom_g) else math.nan
        note = f"{mode}: {words} in every simulation down to the lowest stripe; rate at least that stripe's"
    else:
        note = f"{mode}: no fragility ({fit.message})"
    return {f"annual_rate_{mode}": central, f"annual_rate_{mode}_low": low, f"annual_rate_{mode}_high": high,
            f"p50yr_{mode}": probability_in_years(central, 50.0),
            f"p50yr_{mode}_low": probability_in_years(low, 50.0),
            f"p50yr_{mode}_high": probability_in_years(high, 50.0), "note": note}


def _rate_at_pga(levels_g, rates_per_yr, pga_g: float) -> float:
    """The curve's annual rate [1/yr] of exceeding ``pga_g``, log-log between levels, power-law beyond."""
    x, y = np.log(np.asarray(levels_g, dtype=float)), np.log(np.asarray(rates_per_yr, dtype=float))
    t = math.log(pga_g)
    if t <= x[0]:
        k = (y[1] - y[0]) / (x[1] - x[0])
        return float(math.exp(y[0] + k * (t - x[0])))
    if t >= x[-1]:
        k = (y[-1] - y[-2]) / (x[-1] - x[-2])
        return float(math.exp(y[-1] + k * (t - x[-1])))
    return float(math.exp(np.interp(t, x, y)))


def curve_risk(cases: pd.DataFrame, motions: dict, level_motions: pd.DataFrame, hazard: OpenQuakeHazard,
               settings: dict, runner, progress=lambda message: None) -> CurveRisk:
    """Fragility per item and failure mode over stripes, integrated over ``hazard`` (module docstring)."""
    if hazard.kind != "curve":
        raise ValueError("a hazard map has no curve to integrate")
    levels_g, rates_per_yr = curve_rates_per_yr(hazard)
    if levels_g.size < 2 or not rates_per_yr[0] > rates_per_yr[-1]:
        from assess.errors import InputError, Problem
        raise InputError([Problem(file=_file_name(hazard.path), message=(
            "the hazard curve has fewer than two levels with a probability of exceedance between 0 and 1, "
            "or does not fall with the level: there is no curve to integrate the fragilities over."),
            fix="export the site's mean PGA hazard curve from OpenQuake with levels spanning 0.005 to 3 g.")])
    suite_pta_g = {int(f): group["pta_g"].to_numpy(dtype=float)
                   for f, group in level_motions.groupby("floor")}
    floors = {}
    stripes_by_floor = {}
    for floor in sorted(set(int(f) for f in cases["floor"])):
        ratio, basis = floor_pfa_per_pga(floor, suite_pta_g, settings)
        floors[floor] = {"pfa_per_pga": ratio, "basis": basis}
        stripes_by_floor[floor] = stripe_levels_g(levels_g, rates_per_yr, ratio)
    total = sum(len(v) for v in stripes_by_floor.values())
    progress(f"fragilities over the hazard curve: {total} stripes of floor acceleration "
             f"({N_STRIPES} per floor, from the {1 / STRIPE_RATES_PER_YR[0]:.0f}- to the "
             f"{1 / STRIPE_RATES_PER_YR[1]:,.0f}-year shaking)")
    last = [-1]

    def report(done, total_runs):
        if done == total_runs or done - last[0] >= max(1, total_runs // 5):
            last[0] = done
            progress(f"stripes: simulated {done} of {total_runs} runs")

    plan = [(floor, float(x), None) for floor, levels in stripes_by_floor.items() for x in levels]
    runs = stripe_runs(cases, motions, plan, runner, progress=report)
    clearance_cm = cases.drop_duplicates("id").set_index("id")["clearance_m"] * 100.0
    floor_of = cases.drop_duplicates("id").set_index("id")["floor"]
    fits, stripes = fit_items(stripe_outcomes(runs, clearance_cm))
    refine = refinement_plan(fits, stripes_by_floor, floor_of)
    if refine:  # steps between two stripes: look inside them
        progress(f"stripes: {len(refine)} more inside the steps of {len({p[2][0] for p in refine})} items")
        runs = pd.concat([runs, stripe_runs(cases, motions, refine, runner)], ignore_index=True)
        fits, stripes = fit_items(stripe_outcomes(runs, clearance_cm))
    rows = []
    for item_id in dict.fromkeys(cases["id"]):
        ratio = floors[int(floor_of[item_id])]["pfa_per_pga"]
        row = {"id": item_id, "pfa_per_pga": ratio}
        notes = []
        for mode in MODES:
            fit = fits[(item_id, mode)]
            row[f"fragility_{mode}_median_g"] = fit.median_g
            row[f"fragility_{mode}_beta"] = fit.beta
            row[f"fragility_{mode}_se_ln_median"] = fit.se_ln_median
            rates = item_rates(fit, mode, hazard, levels_g, rates_per_yr, ratio,
                               stripes_by_floor[int(floor_of[item_id])])
            notes.append(rates.pop("note"))
            row.update(rates)
        row["curve_note"] = "; ".join(notes)
        rows.append(row)
    name = f"{_file_name(hazard.path)}, site {hazard.site.label()}"
    return CurveRisk(table=pd.DataFrame(rows)[["id"] + CURVE_COLUMNS], fits=fits, stripes=stripes,
                     floors=floors, curve=name, runs=len(runs))


def _file_name(path) -> str:
    from pathlib import Path
    return Path(str(path)).name


def export_items(curve: CurveRisk, summary: pd.DataFrame) -> list:
    """The items' fragilities as pelicun components (:mod:`assess.fragility.pelicun_export`), in summary order.

    A limit state without a fitted fragility is exported without numbers, with the reason.
    """
    from assess.fragility.pelicun_export import ItemFragilities, LimitStateFragility, pelicun_component_id

    items = []
    for row in summary.itertuples(index=False):
        if (row.id, MODES[0]) not in curve.fits:
            continue  # anchored: not a freestanding component
        states = [LimitStateFragility.from_fit(curve.fits[(row.id, mode)]) for mode in MODES]
        items.append(ItemFragilities(component_id=pelicun_component_id(row.id),
                                     description=f"{row.name} ({row.id}), floor {row.floor}", beyond_clearance=states[0],
                                     overturn=states[1]))
    return items


def fragility_files(curve: CurveRisk, summary: pd.DataFrame) -> dict[str, bytes]:
    """``fragility/fragility.csv`` + ``.json`` (pelicun's format) and ``fragility/stripes.csv`` (the outcomes
    the fits rest on), by path, as bytes."""
    from assess.fragility.pelicun_export import pelicun_fragility_files

    files = {f"fragility/{name}": content
             for name, content in pelicun_fragility_files(export_items(curve, summary)).items()}
    files["fragility/stripes.csv"] = curve.stripes.to_csv(index=False, float_format="%.6g",
                                                          lineterminator="\n").encode()
    return files
