"""Each item's fragility from the engine, over stripes of floor acceleration, and its annual rate.

The level's suite answers "what happens at this level". Over the whole hazard
curve (PBEE) an item's annual rate of failure needs its fragility, P(fail | a),
at every floor acceleration a. Multiple-stripe analysis ([1]) gives it:

1. **Stripes.** For each floor, the histories of the floor's suite at the
   level (records, synthetic histories or pulses, as the level simulates
   them) are each scaled to a peak floor acceleration (PFA) x_j, for
   :data:`N_STRIPES` values spaced evenly in ln x over the floor's PFA for a
   ground acceleration of :data:`STRIPE_PGA_G` (:func:`stripe_levels_g`).
   Scaling a history to the stripe fixes the intensity exactly; the suite's
   shapes carry the record-to-record variability. The stripes do not depend
   on the hazard curve, so a new curve re-integrates the same fragilities
   without a simulation (a portfolio's cache keeps them); where the curve's
   rarest shaking lies beyond the top stripe, the note says the fragility is
   extrapolated there.
2. **Outcomes.** Every item runs under every scaled history in both base
   directions (the engine, as at the level). A history is one trial; it is a
   failure ``beyond_clearance`` when the peak sliding exceeds the clearance
   in either direction, ``overturn`` when the item overturns in either.
3. **Fit.** Where an item's failure share jumps between two stripes (by
   :data:`REFINE_JUMP` or more: a floor whose suite varies little fails all at
   once), :data:`REFINE_STRIPES` more stripes inside that gap are run for that
   item (:func:`refinement_plan`).
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

Where a building sheet gives the floors' motions, the stripes are of ground
acceleration passed through the building instead, and the fragility is in PGA
(:mod:`assess.fragility.ground_stripes`; steps 2 to 4 are the same,
:func:`fit_and_integrate`).

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
from scipy import stats

from assess.data import as_declared
from assess.fragility.agreement import AT_LEVEL_COLUMNS, level_comparison_sentence
from assess.fragility.msa import FITTED, FragilityFit, fit_lognormal_fragilities
from assess.hazard.openquake import OpenQuakeHazard
from assess.inventory.settings import Settings
from assess.inventory.units import CM_PER_M
from assess.quantity_text import floor_numbering_of, floor_text
from assess.hazard.risk_integral import curve_annual_rates, openquake_failure_rate, probability_in_years
from assess.mechanics.gateway import Cases

#: Number of stripes of floor acceleration.
N_STRIPES = 10
#: Ground accelerations [g] of the lowest and highest stripe: from shaking that moves little to the
#: strongest recorded (the floor's stripes are these times its PFA/PGA ratio).
STRIPE_PGA_G = (0.05, 2.0)
#: The curve's rarest shaking the report checks the stripes reach: the 10,000-year PGA.
RAREST_RATE_PER_YR = 1.0 / 10_000.0
MODES = ("beyond_clearance", "overturn")

#: Columns the fragility fits add to ``summary.csv`` (docs/outputs.md), then the fragilities they rest on.
FIT_COLUMNS = [
    "annual_rate_beyond_clearance", "annual_rate_overturn", "p50yr_beyond_clearance", "p50yr_overturn",
    "annual_rate_beyond_clearance_low", "annual_rate_beyond_clearance_high", "annual_rate_overturn_low",
    "annual_rate_overturn_high", "p50yr_beyond_clearance_low", "p50yr_beyond_clearance_high",
    "p50yr_overturn_low", "p50yr_overturn_high",
    "fragility_beyond_clearance_median_g", "fragility_beyond_clearance_beta",
    "fragility_beyond_clearance_se_ln_median", "fragility_overturn_median_g", "fragility_overturn_beta",
    "fragility_overturn_se_ln_median", "pfa_per_pga", "curve_note",
]
#: Columns the hazard curve adds to ``summary.csv`` (docs/outputs.md); the last, the fragilities at the level's
#: own accelerations (:data:`assess.fragility.agreement.AT_LEVEL_COLUMNS`), per level: added by the pipeline.
CURVE_COLUMNS = FIT_COLUMNS + AT_LEVEL_COLUMNS


@dataclass
class CurveRisk:
    """What the hazard curve added to an assessment.

    Attributes
    ----------
    table : DataFrame
        One row per freestanding item (``id``), :data:`FIT_COLUMNS`.
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
    notes : list of str
        About the curve as a whole (e.g. shaking beyond the top stripe).
    fit_p : dict
        ``{(id, mode): p}``: the p-value of each fitted lognormal's deviance (:func:`lognormal_fit_p`).
    intensity : str
        ``PFA`` or ``PGA``: the acceleration the stripes and the fragilities are in.
    """

    table: pd.DataFrame
    fits: dict
    stripes: pd.DataFrame
    floors: dict
    curve: str
    runs: int
    notes: list = field(default_factory=list)
    fit_p: dict = field(default_factory=dict)
    #: What the fragilities are in: ``PFA`` (stripes of floor acceleration) or ``PGA`` (stripes of ground
    #: acceleration passed through the building, :mod:`assess.fragility.ground_stripes`).
    intensity: str = "PFA"


def curve_rates_per_yr(hazard: OpenQuakeHazard) -> tuple[np.ndarray, np.ndarray]:
    """The curve's levels [g] and annual rates [1/yr] at its site, levels with a finite, non-zero rate only."""
    rates = curve_annual_rates(hazard)
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


def stripe_levels_g(pfa_per_pga: float, n_stripes: int = N_STRIPES, pga_g=STRIPE_PGA_G) -> np.ndarray:
    """The stripes' peak floor accelerations [g]: evenly spaced in ln PFA over ``pga_g`` times the floor's
    PFA/PGA ratio.

    >>> stripe_levels_g(1.5, n_stripes=3, pga_g=(0.1, 0.4)).round(4).tolist()
    [0.15, 0.3, 0.6]
    """
    low, high = pga_g[0] * pfa_per_pga, pga_g[1] * pfa_per_pga
    return np.exp(np.linspace(math.log(low), math.log(high), n_stripes))


def floor_pfa_per_pga(floor: int, suite_pta_g: dict, settings: Settings) -> tuple[float, str]:
    """The floor's peak floor acceleration per peak ground acceleration, and where it comes from.

    The ground floor's is 1. Another floor's is the median PTA of its suite
    over the ground suite's median at the level, where the workbook gives
    both (the building's own amplification); otherwise ASCE 7-16 eq. 13.3-1,
    1 + 2 z/h with z/h = floor / ``roof_floor`` ([2]), an envelope; without
    ``roof_floor``, 3 (the roof's), the upper bound.

    ``suite_pta_g`` maps floor -> the PTAs [g] of its suite's motions.

    >>> floor_pfa_per_pga(2, {0: [0.5, 0.7], 2: [0.9]}, Settings())[0]
    1.5
    >>> floor_pfa_per_pga(2, {2: [0.9]}, Settings(roof_floor=4))[0]
    2.0
    """
    if int(floor) == 0:
        return 1.0, "the ground floor: PFA = PGA"
    numbering = floor_numbering_of(settings)  # the labels; z/h counts the workbook's numbers
    label = floor_text(floor, numbering)
    if 0 in suite_pta_g and floor in suite_pta_g:
        ratio = float(np.median(suite_pta_g[floor]) / np.median(suite_pta_g[0]))
        return ratio, (f"floor {label}: PFA/PGA {ratio:.2f}, the median PTA of its motions over the ground "
                       "motions' at the level (the workbook's)")
    roof = settings.roof_floor
    if roof > 0.0:
        ratio = 1.0 + 2.0 * min(max(floor / roof, 0.0), 1.0)
        return ratio, (f"floor {label}: PFA/PGA {ratio:.2f} by ASCE 7-16 eq. 13.3-1, 1 + 2z/h with roof = floor "
                       f"{floor_text(roof, numbering)} (no ground motion at the level to read it from)")
    return 3.0, (f"floor {label}: PFA/PGA 3, the roof's by ASCE 7-16 eq. 13.3-1 (an upper bound: give "
                 "roof_floor in the settings, or the ground motions at the level)")


def stripe_runs(cases: pd.DataFrame, motions: dict, plan, runner,
                progress: Callable[[int, int], None] | None = None, record_pairs: dict | None = None) -> pd.DataFrame:
    """Simulate items under their floor's suite scaled to stripes; one row per run.

    ``cases`` are the level's item x motion x direction cases (with their
    ``block``); ``motions`` the level's histories per ``motion_key``; ``plan``
    a list of ``(floor, pfa_g, ids)``: the floor's histories scaled to
    ``pfa_g`` [g], run by the items ``ids`` of that floor (None: all of them).
    A motion of ``record_pairs`` (``motion_key`` -> its components along the
    items' width and depth) runs direction 1 under the first and direction 2
    under the second, both scaled by one factor that brings the larger peak
    to the stripe. ``runner`` runs them (:mod:`assess.mechanics.gateway`). Returns ``id``, ``direction``, ``pfa_g``,
    ``history`` (per floor), ``sliding_max_cm``, ``overturned``.
    """
    record_pairs = record_pairs or {}
    batch = StripeBatch()
    per_item = cases.drop_duplicates(["id", "direction"])
    histories_of = {}
    for floor, pfa_g, ids in plan:
        if floor not in histories_of:
            keys = sorted(set(cases.loc[cases["floor"] == floor, "motion_key"]))
            histories_of[floor] = [record_pairs[key] if key in record_pairs else (record, record)
                                   for key in keys for record, _ in motions[key]]
        on_floor = per_item[per_item["floor"] == floor]
        if ids is not None:
            on_floor = on_floor[on_floor["id"].isin(ids)]
        on_floor = FloorItems.of(on_floor)
        for h, (first, second) in enumerate(histories_of[floor]):
            factor = pfa_g / max(float(np.max(np.abs(first.accel_g))), float(np.max(np.abs(second.accel_g))))
            batch.add(first, second, on_floor, pfa_g, h, factor)
    return batch.run(runner, progress)


@dataclass(frozen=True)
class FloorItems:
    """The items of a floor a stripe runs, read once from their cases (one row per item and direction):
    each one's ``block``, ``id`` and ``direction``, in the cases' order."""

    blocks: tuple
    ids: tuple
    directions: tuple

    @classmethod
    def of(cls, on_floor: pd.DataFrame) -> "FloorItems":
        return cls(tuple(on_floor["block"]), tuple(on_floor["id"]),
                   tuple(int(d) for d in on_floor["direction"]))


class StripeBatch:
    """The stripe runs of every item, gathered into one batch for the runner (both stripe routes)."""

    def __init__(self):
        self.blocks, self.records, self.dts, self.index, self.rows = [], [], [], [], []

    def add(self, first, second, on_floor: FloorItems, level_g: float, history: int, factor: float = 1.0):
        """The items ``on_floor`` under one history at a stripe: direction 1 under ``first``, 2 under ``second``
        (the same record where the history is one component), both times ``factor``."""
        slot = {1: len(self.records)}
        self.records.append(first.accel_g * factor if factor != 1.0 else first.accel_g)
        self.dts.append(first.dt_s)
        if second is first:
            slot[2] = slot[1]
        else:
            slot[2] = len(self.records)
            self.records.append(second.accel_g * factor if factor != 1.0 else second.accel_g)
            self.dts.append(second.dt_s)
        self.blocks.extend(on_floor.blocks)
        self.index.extend(slot[direction] for direction in on_floor.directions)
        self.rows.extend((item_id, direction, float(level_g), history)
                         for item_id, direction in zip(on_floor.ids, on_floor.directions))

    def run(self, runner, progress=None) -> pd.DataFrame:
        """One row per run: ``id``, ``direction``, ``pfa_g`` (the stripe), ``history``, ``sliding_max_cm``,
        ``overturned``."""
        if not self.blocks:
            return pd.DataFrame(columns=["id", "direction", "pfa_g", "history", "sliding_max_cm", "overturned"])
        peaks = runner.run(Cases.peaks(self.blocks, self.records, self.dts, np.asarray(self.index)),
                           progress=progress)
        runs = pd.DataFrame(self.rows, columns=["id", "direction", "pfa_g", "history"])
        runs["sliding_max_cm"] = peaks.sliding_max_m * CM_PER_M
        runs["overturned"] = peaks.overturned
        return runs


#: Stripes added inside a gap between two stripes where the failure share jumps.
REFINE_STRIPES = 3


#: A failure share that changes by this much or more between two neighbouring stripes is refined.
REFINE_JUMP = 0.25


def refinement_plan(stripes: pd.DataFrame, floor_of) -> list:
    """Stripes to add where an item's failure share rises steeply: between two neighbouring stripes
    whose shares differ by :data:`REFINE_JUMP` or more, :data:`REFINE_STRIPES` levels evenly in ln PFA
    strictly between them. On a hazard curve whose rate falls as a⁻³ to a⁻⁴, one stripe spacing
    (a factor 1.5) is a factor 3 to 5 in rate: where the fragility rises within it, where it rises
    matters, and a lognormal fitted across the gap cannot tell.
    """
    extra = {}
    for (item_id, _mode), group in stripes.groupby(["id", "mode"], sort=False):
        group = group[group["trials"] > 0].sort_values("pfa_g")
        x = group["pfa_g"].to_numpy(dtype=float)
        share = (group["failures"] / group["trials"]).to_numpy(dtype=float)
        for k in np.flatnonzero(np.abs(np.diff(share)) >= REFINE_JUMP):
            new = np.exp(np.linspace(math.log(x[k]), math.log(x[k + 1]), REFINE_STRIPES + 2)[1:-1])
            extra.setdefault((int(floor_of[item_id]), item_id), set()).update(float(v) for v in new)
    return [(floor, pfa_g, [item_id]) for (floor, item_id), levels in sorted(extra.items())
            for pfa_g in sorted(levels)]


def stripe_outcomes(runs: pd.DataFrame, clearance_cm: pd.Series) -> pd.DataFrame:
    """Per item, stripe and history: failed ``beyond_clearance`` / ``overturn`` in either direction."""
    per_history = runs.assign(beyond_clearance=runs["sliding_max_cm"] > runs["id"].map(clearance_cm)) \
        .groupby(["id", "pfa_g", "history"], sort=True)[["beyond_clearance", "overturned"]].any()
    return per_history.rename(columns={"overturned": "overturn"}).reset_index()


def fit_items(outcomes: pd.DataFrame) -> tuple[dict, pd.DataFrame]:
    """Fit every item's two fragilities; ``({(id, mode): FragilityFit}, stripes table)``.

    The stripes table has one row per item, mode and stripe: ``pfa_g``, ``trials``, ``failures``.
    """
    counts = outcomes.groupby(["id", "pfa_g"], sort=True)[list(MODES)].agg(["size", "sum"])
    counts.columns = [f"{mode}_{stat}" for mode, stat in counts.columns]
    counts = counts.reset_index()
    ids = list(dict.fromkeys(counts["id"]))
    row = counts.groupby("id", sort=False).cumcount().to_numpy()  # the stripe's place in its item's row
    item = pd.Index(ids).get_indexer(counts["id"])
    width = int(row.max()) + 1
    fits, tables = {}, []
    for mode in MODES:
        x = np.ones((len(ids), width))  # padding: stripes of 0 trials
        n = np.zeros((len(ids), width), dtype=np.int64)
        z = np.zeros_like(n)
        x[item, row] = counts["pfa_g"].to_numpy(dtype=float)
        n[item, row] = counts[f"{mode}_size"].to_numpy()
        z[item, row] = counts[f"{mode}_sum"].to_numpy()
        for item_id, fit in zip(ids, fit_lognormal_fragilities(x, n, z)):
            fits[(item_id, mode)] = fit
        tables.append(pd.DataFrame({"id": counts["id"].to_numpy(), "mode": mode, "pfa_g": x[item, row],
                                    "trials": n[item, row], "failures": z[item, row]}))
    return fits, pd.concat(tables, ignore_index=True)


#: z of the two-sided 90 % interval the rates carry (from the fit's standard error of ln θ).
Z_90 = 1.6448536269514722


#: Below this p-value of the fit's deviance the lognormal is said not to fit the outcomes.
MISFIT_P = 0.01


def lognormal_fit_p(fit: FragilityFit, pfa_g, trials, failures) -> float:
    """p-value of the fitted lognormal's deviance against the stripes' own failure shares.

    The deviance :math:`D = 2\\sum_j [z_j \\ln(z_j/(n_j p_j)) + (n_j - z_j)\\ln((n_j - z_j)/(n_j (1 - p_j)))]`
    is χ² with (stripes − 2) degrees of freedom when the lognormal is the true fragility
    (McCullagh & Nelder 1989, binary data). NaN without a fit or without a spare degree of freedom.

    >>> from assess.fragility.msa import fit_lognormal_fragility
    >>> x, n = [0.2, 0.4, 0.8, 1.6], [40, 40, 40, 40]
    >>> round(lognormal_fit_p(fit_lognormal_fragility(x, n, [4, 20, 36, 40]), x, n, [4, 20, 36, 40]), 2) > 0.01
    True
    >>> lognormal_fit_p(fit_lognormal_fragility(x, n, [0, 20, 20, 22]), x, n, [0, 20, 20, 22]) < 0.01  # a plateau
    True
    """
    x, n, z = (np.asarray(v, dtype=float) for v in (pfa_g, trials, failures))
    used = n > 0
    x, n, z = x[used], n[used], z[used]
    if fit.status != FITTED or x.size < 3:
        return math.nan
    p = np.clip(fit.probability(x), 1e-300, 1.0 - 1e-16)
    with np.errstate(divide="ignore", invalid="ignore"):
        terms = np.where(z > 0, z * np.log(z / (n * p)), 0.0) + np.where(
            n - z > 0, (n - z) * np.log((n - z) / (n * (1.0 - p))), 0.0)
    return float(stats.chi2.sf(2.0 * terms.sum(), x.size - 2))


def outcome_rates(pfa_g, trials, failures, levels_g, rates_per_yr, pfa_per_pga: float,
                  onset_g: float = 0.0) -> tuple[float, float, float]:
    """Annual rate [1/yr] of the outcomes' own fragility, with its 90 % interval: the failure share of
    each stripe, linear in ln PFA between stripes, held at the top stripe's above it and at the lowest
    stripe's below, integrated over the curve; the interval integrates each stripe's exact binomial
    bounds the same way. Below ``onset_g`` [g] of floor acceleration the item stays at rest (it can
    neither slide, below μ_s g, nor uplift, below g b/h): there every bound is 0. Used where no
    lognormal fits the outcomes.

    >>> levels, rates = [0.1, 1.0], [1e-2, 1e-4]
    >>> round(outcome_rates([0.3], [10], [10], levels, rates, 1.0)[0] / 1e-2, 6)  # always fails: λ(lowest level)
    1.0
    >>> # at rest below 0.2 g; the upper bound rises from 0 there to 1 at 0.3 g (all 10 failed): on
    >>> # λ = 1e-2 (a/0.1)^-2, ∫ p dλ by quadrature gives 0.001706
    >>> round(outcome_rates([0.05, 0.3], [10, 10], [0, 10], levels, rates, 1.0, onset_g=0.2)[2], 5)
    0.00171
    """
    from assess.fragility.suite import binomial_interval

    x, n, z = (np.asarray(v, dtype=float) for v in (pfa_g, trials, failures))
    order = np.argsort(x)
    x, n, z = x[order], n[order], z[order]
    shares = z / n
    bounds = np.array([binomial_interval(share, count) for share, count in zip(shares, n)])
    at_rest = x < onset_g
    bounds[at_rest] = 0.0
    if at_rest.any():  # from rest, the first stripe that can move it: start from 0 at the onset itself
        x, n = np.concatenate([[onset_g], x[~at_rest]]), np.concatenate([[1.0], n[~at_rest]])
        shares = np.concatenate([[0.0], shares[~at_rest]])
        bounds = np.vstack([[0.0, 0.0], bounds[~at_rest]])
    ln_pga = np.log(x / pfa_per_pga)
    ln_lo = min(math.log(levels_g[0]), ln_pga[0])
    ln_hi = max(math.log(levels_g[-1]), ln_pga[-1]) + 1.0
    grid = np.linspace(ln_lo, ln_hi, 4001)
    rate = np.array([_rate_at_pga(levels_g, rates_per_yr, math.exp(y)) for y in grid])
    below_first = rates_per_yr[0] - _rate_at_pga(levels_g, rates_per_yr, math.exp(ln_lo)) \
        if ln_lo < math.log(levels_g[0]) else 0.0  # the curve starts at its first level
    mid = 0.5 * (grid[1:] + grid[:-1])

    def integral(p):
        share = np.interp(mid, ln_pga, p, left=p[0], right=p[-1])
        return float(np.sum(share * -np.diff(rate)) + p[-1] * rate[-1] + p[0] * max(below_first, 0.0))

    return integral(shares), integral(bounds[:, 0]), integral(bounds[:, 1])


def item_rates(fit: FragilityFit, mode: str, hazard: OpenQuakeHazard, levels_g, rates_per_yr,
               pfa_per_pga: float, stripes_g, outcomes: pd.DataFrame, onset_g: float = 0.0) -> dict:
    """Annual rate of one failure mode, its 90 % interval and probability in 50 years, and a sentence.

    * fitted: the fragility integrated over the curve; the interval moves θ by ±1.645 standard errors
      of ln θ (β held). Where the lognormal does not fit the outcomes (deviance p-value below
      :data:`MISFIT_P`: e.g. some motions of the suite fail at half the acceleration others need), the
      rate is integrated from the outcomes themselves (:func:`outcome_rates`), which governs, and the
      note gives the lognormal's rate beside it;
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
    central = low = high = fit_p = math.nan
    if fit.status == FITTED:
        rate = openquake_failure_rate(hazard, fit.median_g, fit.beta, pfa_per_pga=pfa_per_pga)
        central = rate.annual_rate
        shift = math.exp(Z_90 * fit.se_ln_median) if math.isfinite(fit.se_ln_median) else math.nan
        if math.isfinite(shift):
            low = openquake_failure_rate(hazard, fit.median_g * shift, fit.beta, pfa_per_pga=pfa_per_pga).annual_rate
            high = openquake_failure_rate(hazard, fit.median_g / shift, fit.beta, pfa_per_pga=pfa_per_pga).annual_rate
        note = f"{mode}: median {fit.median_g:.2g} g, beta {fit.beta:.2f}"
        note += "".join(f"; {text}" for text in rate.notes)
        fit_p = lognormal_fit_p(fit, outcomes["pfa_g"], outcomes["trials"], outcomes["failures"])
        if fit_p < MISFIT_P:
            lognormal_rate = central
            central, low, high = outcome_rates(outcomes["pfa_g"], outcomes["trials"], outcomes["failures"],
                                               levels_g, rates_per_yr, pfa_per_pga, onset_g)
            note += (f"; the lognormal does not fit the outcomes (deviance p = {fit_p:.2g}): the rate is integrated "
                     f"from the outcomes themselves ({central:.2g} per year; the lognormal would give "
                     f"{lognormal_rate:.2g})")
    elif fit.status == "separated":
        survived_g, failed_g = fit.separation_g
        central, low, high = rate_at(math.sqrt(survived_g * failed_g)), rate_at(failed_g), rate_at(survived_g)
        mixed = outcomes[(outcomes["failures"] > 0) & (outcomes["failures"] < outcomes["trials"])]
        between = "".join(f", {int(r.failures)} of {int(r.trials)} at {r.pfa_g:.2g} g"
                          for r in mixed.itertuples(index=False))
        note = (f"{mode}: {words} in no simulation up to {survived_g:.2g} g{between} and in every one from "
                f"{failed_g:.2g} g (a step, no fitted slope): the rate of a step between them")
        if survived_g == failed_g:
            note = (f"{mode}: {words} in no simulation below {survived_g:.2g} g{between} and in every one above "
                    "(a step there, no fitted slope)")
    elif fit.status == "no_failures":
        top_g = float(np.max(stripes_g))
        high = rate_at(top_g) if math.isfinite(top_g) else math.nan
        note = (f"{mode}: never {words} in {fit.n_trials} simulations up to the top stripe; "
                "rate below about that stripe's")
    elif fit.status == "all_failed":
        bottom_g = float(np.min(stripes_g))
        low = rate_at(bottom_g) if math.isfinite(bottom_g) else math.nan
        note = f"{mode}: {words} in every simulation down to the lowest stripe; rate at least that stripe's"
    else:
        note = f"{mode}: no fragility ({fit.message})"
    return {f"annual_rate_{mode}": central, f"annual_rate_{mode}_low": low, f"annual_rate_{mode}_high": high,
            f"p50yr_{mode}": probability_in_years(central, 50.0),
            f"p50yr_{mode}_low": probability_in_years(low, 50.0),
            f"p50yr_{mode}_high": probability_in_years(high, 50.0), "note": note, "fit_p": fit_p}


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


def checked_curve(hazard: OpenQuakeHazard) -> tuple[np.ndarray, np.ndarray]:
    """The curve's usable levels [g] and annual rates [1/yr] (:func:`curve_rates_per_yr`); a curve with
    nothing to integrate over is refused (:class:`~assess.errors.InputError`)."""
    if hazard.kind != "curve":
        raise ValueError("a hazard map has no curve to integrate")
    levels_g, rates_per_yr = curve_rates_per_yr(hazard)
    if levels_g.size < 2 or not rates_per_yr[0] > rates_per_yr[-1]:
        from assess.errors import InputError, Problem
        raise InputError([Problem(file=_file_name(hazard.path), message=(
            "the hazard curve has fewer than two levels with a finite, non-zero rate of exceedance (a probability "
            "between 0 and 1), or does not fall with the level: there is no curve to integrate the fragilities over."),
            fix=f"export the site's mean PGA hazard curve from {hazard.source} with levels spanning 0.005 to 3 g.")])
    return levels_g, rates_per_yr


def curve_risk(cases: pd.DataFrame, motions: dict, level_motions: pd.DataFrame, hazard: OpenQuakeHazard,
               settings: Settings, runner, progress=lambda message: None,
               record_pairs: dict | None = None) -> CurveRisk:
    """Fragility per item and failure mode over stripes, integrated over ``hazard`` (module docstring)."""
    levels_g, rates_per_yr = checked_curve(hazard)
    suite_pta_g = {int(f): group["pta_g"].to_numpy(dtype=float)
                   for f, group in level_motions.groupby("floor")}
    floors = {}
    stripes_by_floor = {}
    for floor in sorted(set(int(f) for f in cases["floor"])):
        ratio, basis = floor_pfa_per_pga(floor, suite_pta_g, settings)
        floors[floor] = {"pfa_per_pga": ratio, "basis": basis}
        stripes_by_floor[floor] = stripe_levels_g(ratio)
    total = sum(len(v) for v in stripes_by_floor.values())
    progress(f"fragilities over the hazard curve: {total} stripes of floor acceleration "
             f"({N_STRIPES} per floor, for ground accelerations of {STRIPE_PGA_G[0]:g} to {STRIPE_PGA_G[1]:g} g)")

    def run_plan(plan, report=None):
        return stripe_runs(cases, motions, plan, runner, progress=report, record_pairs=record_pairs)

    return fit_and_integrate(cases, hazard, levels_g, rates_per_yr, floors, stripes_by_floor, run_plan, progress)


def fit_and_integrate(cases: pd.DataFrame, hazard: OpenQuakeHazard, levels_g, rates_per_yr, floors: dict,
                      stripes_by_floor: dict, run_plan, progress, intensity: str = "PFA",
                      note_prefix: str = "") -> CurveRisk:
    """Steps 2 to 4 of the module docstring over the stripes ``stripes_by_floor`` (floor -> its stripes [g]).

    ``run_plan(plan, report)`` simulates a plan of ``(floor, x_g, ids)`` (:func:`stripe_runs`'s table);
    ``floors`` gives each floor's ``pfa_per_pga``, the ratio that moves its stripes to the curve's PGA (1
    where the stripes are already of ground acceleration, ``intensity`` ``PGA``). ``note_prefix`` opens
    every item's ``curve_note``.
    """
    curve_notes = []
    rarest_g = pga_at_rate_g(levels_g, rates_per_yr, RAREST_RATE_PER_YR)
    if rarest_g > STRIPE_PGA_G[1]:
        curve_notes.append(f"the curve's 10,000-year ground acceleration, {rarest_g:.2f} g, lies above the top stripe "
                     f"({STRIPE_PGA_G[1]:g} g): the fragilities are extrapolated there")
    def reporter(what: str):
        """``report(done, total)``: says ``stripes: simulated done of total what`` at every fifth, and at the end."""
        last = [-1]

        def report(done, total_runs):
            if done == total_runs or done - last[0] >= max(1, total_runs // 5):
                last[0] = done
                progress(f"stripes: simulated {done} of {total_runs} {what}")
        return report

    plan = [(floor, float(x), None) for floor, levels in stripes_by_floor.items() for x in levels]
    runs = run_plan(plan, reporter("runs"))
    clearance_cm = cases.drop_duplicates("id").set_index("id")["clearance_m"] * CM_PER_M
    floor_of = cases.drop_duplicates("id").set_index("id")["floor"]
    fits, stripes = fit_items(stripe_outcomes(runs, clearance_cm))
    # floor acceleration [g] below which the item stays at rest: it slides from μ_s g, uplifts from g b/h
    onset_g = cases.assign(onset=np.minimum(cases["mu_static"], cases["b_over_h"])).groupby("id")["onset"].min()
    if intensity != "PFA":  # stripes of ground acceleration: the floor's onset moved to the ground by the
        # largest floor/ground peak ratio of the floor's histories (below it, no history moves the item)
        onset_g = onset_g / floor_of.reindex(onset_g.index).map(lambda f: floors[int(f)]["max_peak_ratio"])
    refine = refinement_plan(stripes, floor_of)
    if refine:  # steep rises between two stripes: look inside them
        progress(f"stripes: {len(refine)} more where the failures of {len({p[2][0] for p in refine})} items "
                 "rise steeply")
        runs = pd.concat([runs, run_plan(refine, reporter("more runs"))], ignore_index=True)
        fits, stripes = fit_items(stripe_outcomes(runs, clearance_cm))
    rows, fit_p = [], {}
    outcomes_of = {key: group for key, group in stripes.groupby(["id", "mode"], sort=False)}
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
                               stripes_by_floor[int(floor_of[item_id])],
                               outcomes_of[(item_id, mode)],
                               onset_g=float(onset_g[item_id]))
            notes.append(rates.pop("note"))
            fit_p[(item_id, mode)] = rates.pop("fit_p")
            row.update(rates)
        row["curve_note"] = note_prefix + "; ".join(notes)
        rows.append(row)
    name = f"{_curve_name(hazard)}, site {hazard.site.label()}"
    return CurveRisk(table=pd.DataFrame(rows)[["id"] + FIT_COLUMNS], fits=fits, stripes=stripes,
                     floors=floors, curve=name, runs=len(runs), notes=curve_notes, fit_p=fit_p,
                     intensity=intensity)


def _file_name(path) -> str:
    from pathlib import Path
    return Path(str(path)).name


def _curve_name(hazard: OpenQuakeHazard) -> str:
    """The curve as the report names it: its file name; with its folder and program for nshmp-haz, whose
    files are all ``curves.csv`` and named by their folder (``PGA/curves.csv (USGS nshmp-haz)``)."""
    from pathlib import Path
    if hazard.annual_rates is None:
        return _file_name(hazard.path)
    path = Path(str(hazard.path))
    return f"{path.parent.name}/{path.name} ({hazard.source})"


def export_items(curve: CurveRisk, summary: pd.DataFrame) -> list:
    """The items' fragilities as pelicun components (:mod:`assess.fragility.pelicun_export`), in summary order.

    A limit state without a fitted fragility is exported without numbers, with the reason.
    """
    from assess.fragility.pelicun_export import ItemFragilities, LimitStateFragility, pelicun_component_id

    items = []
    for row in summary.itertuples(index=False):
        if (row.id, MODES[0]) not in curve.fits:
            continue  # anchored: not a freestanding component
        states = []
        for mode in MODES:
            state = LimitStateFragility.from_fit(curve.fits[(row.id, mode)])
            p = curve.fit_p.get((row.id, mode), math.nan)
            if p < MISFIT_P:  # say so where the numbers are read
                state = LimitStateFragility(state.median_g, state.beta, state.note + (
                    f" The lognormal does not fit the simulated outcomes (deviance p = {p:.2g}): assess "
                    "integrates the outcomes themselves for the annual rate (its summary.csv, curve_note)."))
            states.append(state)
        items.append(ItemFragilities(component_id=pelicun_component_id(row.id),
                                     description=f"{row.name} ({row.id}), floor {row.floor}",
                                     beyond_clearance=states[0],
                                     overturn=states[1], floor=int(row.floor), quantity=int(row.quantity),
                                     comment=_level_comment(row._asdict(), level_comparison_sentence)))
    return items


def _level_comment(row: dict, sentence) -> str:
    """The item's sentence on the level's answer beside this fragility (``sentence``:
    :func:`assess.fragility.agreement.level_comparison_sentence`), where the summary has the columns."""
    if not all(column in row for column in AT_LEVEL_COLUMNS):
        return ""
    text = sentence(row)
    return f"At the level assessed: {text}" if text else ""


def fragility_files(curve: CurveRisk, summary: pd.DataFrame) -> dict[str, bytes]:
    """``fragility/fragility.csv`` + ``.json`` (pelicun's format), ``fragility/cmp_marginals.csv`` (the items at
    the stories pelicun counts) and ``fragility/stripes.csv`` (the outcomes
    the fits rest on; its stripes ``pga_g`` where they are of ground acceleration), by path, as bytes."""
    from assess.fragility.pelicun_export import pelicun_fragility_files

    files = {f"fragility/{name}": content
             for name, content in pelicun_fragility_files(export_items(curve, summary),
                                                          demand=curve.intensity).items()}
    stripes = curve.stripes if curve.intensity == "PFA" else curve.stripes.rename(columns={"pfa_g": "pga_g"})
    files["fragility/stripes.csv"] = as_declared("fragility/stripes.csv", stripes).to_csv(
        index=False, float_format="%.6g", lineterminator="\n").encode()
    return files
