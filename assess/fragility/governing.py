"""The governing demand: each item's sliding and overturning over its floor's suite, from the model that holds.

Every motion of the suite weighs the same (docs/workbook.md, Suites), and each motion
contributes the distribution of the model that governs for it:

* ``record`` — the engine under the record itself: exact for the rigid-block
  model, one value per motion;
* ``regression`` — the paper's lognormal regression (eqs. 7-21), only where
  :func:`~assess.fragility.suite.regression_applies` (a pulse that carries
  the motion's PTA, IM inside the fitted range, no uplift);
* ``synthetic`` — the engine under the motion's synthetic near-fault histories
  (each history an equal share of the motion's weight);
* ``pulse`` — the engine under the motion's pulse, where a motion given by
  PTA and Tp alone lies outside the regression's domain (no vp to synthesise from).

Per motion and history the sliding is the larger of the two base directions
and the item overturns if it does in either; where the motion gives both
horizontal components (``record`` and ``record_2``) and the item cannot
uplift, it is instead the peak distance from rest of the block sliding in the
plane under both at once (``planar``, :mod:`assess.fragility.planar`): the
physical answer where it applies, the one-way answers being each component
alone. An item with a μ range (:mod:`assess.fragility.friction_range`) runs
at several μ values: each run weighs its motion's weight × its history's
share × its μ value's weight, and the intervals count histories, not μ
values (the μ values are a quadrature of a known distribution, not draws).
Over the suite:
``demand_median_cm`` and ``demand_p84_cm`` are quantiles of the mixture,
``p_beyond_clearance`` and ``p_overturn`` its probabilities, with exact
binomial intervals (:func:`~assess.fragility.suite.binomial_interval`) for
the part estimated from simulated motions (records, histories, pulses): a
suite of 3 records cannot give a probability to two digits.
"""
from __future__ import annotations

import numpy as np
import pandas as pd
from scipy import stats

from assess.fragility.planar import planar_note
from assess.inventory.units import CM_PER_M
from assess.mechanics.gateway import pure_sliding_proved
from assess.mechanics.modes import MODE_SEVERITY
from assess.fragility.regression import RegressionConstants, probability_of_exceedance, capacity_edp, sliding_quantile
from assess.fragility.suite import (
    PULSE_SHARE_MIN, binomial_interval, effective_count, pulse_acceleration_share, quantile_interval,
    regression_applies, weighted_quantile,
)

RECORD, REGRESSION, SYNTHETIC, PULSE = "record", "regression", "synthetic", "pulse"
#: Points standing for one motion's lognormal regression demand in the suite's quantiles.
_LOGNORMAL_POINTS = 199
#: Columns of :func:`governing_demand`'s table, one row per item.
DEMAND_COLUMNS = [
    "demand_source", "demand_median_cm", "demand_p84_cm", "demand_median_low_cm", "demand_median_high_cm",
    "demand_p84_low_cm", "demand_p84_high_cm", "demand_room_cm", "p_beyond_clearance", "p_beyond_clearance_low",
    "p_beyond_clearance_high", "p_overturn", "p_overturn_low", "p_overturn_high", "suite_motions",
    "suite_histories", "theta_max_over_alpha", "demand_note", "demand_planar", "demand_uplift",
    "p_rocking_harm", "p_rocking_harm_low", "p_rocking_harm_high", "demand_mode",
]
#: Peak rotation θmax/α from which rocking that does not overturn counts as harming the item or its
#: contents (the default of the ``rocking_harm_theta_over_alpha`` setting; :func:`rocking_harm`).
ROCKING_HARM_THETA_OVER_ALPHA = 0.5


def _node_columns(cases: pd.DataFrame) -> pd.DataFrame:
    """``cases`` with ``mu_node`` and ``mu_weight`` (one node of weight 1 where no μ range was expanded)."""
    if "mu_node" in cases and "mu_weight" in cases:
        return cases
    return cases.assign(mu_node=0, mu_weight=1.0)


def motion_sources(cases: pd.DataFrame, simulated_as: dict, constants: RegressionConstants) -> pd.Series:
    """The model that governs each case's motion for its item (:data:`RECORD`, ...), as a Series on ``cases``.

    ``simulated_as`` maps a case's ``motion_key`` to how the engine simulated
    it: ``record``, ``synthetic`` or ``pulse``. A motion given by parameters
    takes the regression where it applies to the item under that motion in
    both directions; ``cases`` needs ``pulse_share``, ``im`` and ``sim_uplift``.
    """
    kind = cases["motion_key"].map(simulated_as)
    node = _node_columns(cases)["mu_node"]
    keys = [cases["id"], cases["motion_key"], node]
    uplift = cases["sim_uplift"].groupby(keys).transform("any")
    applies = regression_applies(cases["pulse_share"].fillna(1.0), cases["im"], constants.im_min,
                                 constants.im_max, uplift)
    applies = pd.Series(applies, index=cases.index).groupby(keys).transform("all")
    return pd.Series(np.where(kind == RECORD, RECORD, np.where(applies, REGRESSION, kind)), index=cases.index)


def add_pulse_share(cases: pd.DataFrame) -> pd.DataFrame:
    """``pulse_share`` = 2π|vp|/(Tp·PTA·g) of each case's motion (1 where vp is not given: the motion is its pulse;
    0 where neither Tp is: a synthetic or floor motion, which has no pulse)."""
    share = pulse_acceleration_share(cases["pta_g"], cases["tp_s"], cases["vp_m_s"])
    no_vp = np.where(np.isfinite(cases["tp_s"]), 1.0, 0.0)
    return cases.assign(pulse_share=np.where(np.isfinite(cases["vp_m_s"]), share, no_vp))


def governing_demand(cases: pd.DataFrame, runs: pd.DataFrame, constants: RegressionConstants,
                     room_quantile: float = 0.9, planar: pd.DataFrame | None = None,
                     harm_theta_over_alpha: float = ROCKING_HARM_THETA_OVER_ALPHA) -> pd.DataFrame:
    """One row per item (index ``id``): :data:`DEMAND_COLUMNS`.

    ``demand_room_cm`` is the ``room_quantile`` quantile of the suite's
    sliding: the room that leaves a chance 1 − ``room_quantile`` of sliding past it.
    ``p_rocking_harm`` is the share of the suite, weighted as ``p_overturn``, whose runs rock to
    ``harm_theta_over_alpha`` or more without overturning (:func:`rocking_harm`), with its interval;
    ``demand_mode`` the most severe mode any run of the suite reaches (:func:`suite_mode`).

    Parameters
    ----------
    cases : DataFrame
        One row per item × motion × direction with ``id``, ``motion_key``,
        ``direction``, ``demand_source`` (:func:`motion_sources`), ``pta_g``,
        ``tp_s``, ``im``, ``mode``, ``clearance_m``, ``pulse_share``, ``mu_static`` and ``b_over_h``
        (an item with μ_s < b/h in every case cannot uplift: its chances of overturning and of rocking
        harm are then exactly 0, without an interval).
    runs : DataFrame
        One row per case × history: ``case`` (row of ``cases``),
        ``realization``, ``sliding_max_cm``, ``overturned``, ``theta_max_over_alpha``.
    planar : DataFrame, optional
        2-D peaks (:func:`assess.fragility.planar.planar_runs`): ``id``,
        ``motion_key``, ``mu_node``, ``realization``, ``sliding_cm``; they take
        the place of the larger one-way sliding of those runs.

    ``cases`` may carry ``mu_node`` and ``mu_weight``
    (:func:`assess.fragility.friction_range.expand_cases`).
    """
    cases = _node_columns(cases)
    per_history = _per_history(cases, runs, planar)
    regression = _regression_by_motion(cases, constants)
    rows = {}
    for item_id, item_cases in cases.groupby("id", sort=False):
        rows[item_id] = _item_demand(item_cases, per_history.get(item_id), regression.get(item_id), constants,
                                     room_quantile, harm_theta_over_alpha)
    return pd.DataFrame.from_dict(rows, orient="index")[DEMAND_COLUMNS]


def suite_runs(cases: pd.DataFrame, runs: pd.DataFrame, planar: pd.DataFrame | None = None) -> pd.DataFrame:
    """One row per item × motion × μ value × history: ``id``, ``motion_key``, ``mu_node``, ``motion``,
    ``realization``, the larger sliding of the two directions (``sliding_cm``; the 2-D peak distance from
    rest where ``planar`` gives it, then ``planar`` is True), ``overturned`` in either, the larger
    ``theta`` (θmax/α), ``mu`` and ``mu_weight`` (the μ value and its weight; 1 without a μ range) and
    ``severity``, the :data:`~assess.mechanics.modes.MODE_SEVERITY` of the more severe mode of the two."""
    cases = _node_columns(cases)
    case = runs["case"].to_numpy()
    table = runs if "uplift" in runs else runs.assign(uplift=False)
    table = table.assign(_severity=(table["mode"].map(MODE_SEVERITY) if "mode" in table else 0))
    table = table.assign(id=cases["id"].to_numpy()[case], motion_key=cases["motion_key"].to_numpy()[case],
                        motion=cases["motion"].to_numpy()[case], mu_node=cases["mu_node"].to_numpy()[case],
                        mu=(cases["mu"].to_numpy()[case] if "mu" in cases else np.nan),
                        mu_weight=cases["mu_weight"].to_numpy()[case])
    keys = ["id", "motion_key", "mu_node", "realization"]
    out = table.groupby(keys, sort=False).agg(
        motion=("motion", "first"), sliding_cm=("sliding_max_cm", "max"), overturned=("overturned", "any"),
        theta=("theta_max_over_alpha", "max"), mu=("mu", "first"), mu_weight=("mu_weight", "first"),
        uplift=("uplift", "any"), severity=("_severity", "max")).reset_index()
    out["planar"] = False
    if planar is not None and len(planar):
        in_plane = out[keys].merge(planar[keys + ["sliding_cm"]], on=keys, how="left")["sliding_cm"].to_numpy()
        found = np.isfinite(in_plane)
        out.loc[found, "sliding_cm"] = in_plane[found]
        out.loc[found, "planar"] = True
    return out


def _per_history(cases: pd.DataFrame, runs: pd.DataFrame, planar: pd.DataFrame | None = None) -> dict:
    """Per item: :func:`suite_runs` indexed by (motion_key, mu_node, realization)."""
    table = suite_runs(cases, runs, planar).set_index(["motion_key", "mu_node", "realization"]).sort_index()
    return {item_id: frame.drop(columns="id") for item_id, frame in table.groupby("id", sort=False)}


def _regression_by_motion(cases: pd.DataFrame, constants: RegressionConstants) -> dict:
    """Per item and motion: the regression's median sliding [cm] (larger of the directions that slide) and
    P(> clearance)."""
    slides = cases["mode"].isin(("slide", "slide-rock"))
    im = np.where(slides, cases["im"], 0.0)
    median_cm = np.asarray(sliding_quantile(im, cases["pta_g"], cases["tp_s"], constants, 0.5)) * CM_PER_M
    pf = np.asarray(probability_of_exceedance(im, capacity_edp(cases["clearance_m"], cases["pta_g"], cases["tp_s"]),
                                              constants.zeta, constants.eta, constants.sigma))
    table = pd.DataFrame({"id": cases["id"], "motion_key": cases["motion_key"], "mu_node": cases["mu_node"],
                          "median_cm": median_cm, "pf": pf})
    grouped = table.groupby(["id", "motion_key", "mu_node"], sort=False).max()
    return {item_id: frame.reset_index(level=0, drop=True) for item_id, frame in grouped.groupby(level=0)}


def rocking_harm(theta_over_alpha, overturned, harm_theta_over_alpha: float = ROCKING_HARM_THETA_OVER_ALPHA):
    """Whether a run's rocking harms the item or its contents without overturning it: its peak rotation
    θmax/α reaches ``harm_theta_over_alpha`` and it did not overturn [bool, same shape].

    Why the rotation: a block that rocks to θ0 and falls back strikes its base with the potential energy
    it gained, m g R [cos(α − θ0) − cos α] (Housner 1963, eq. 3 for the energy, doi:10.1785/BSSA0530020403);
    over the energy that tips it, m g R (1 − cos α), that is ≈ r(2 − r) with r = θ0/α for a slender block:
    at r = 0.5 each impact carries three quarters of the energy that would overturn it, and the item has
    lost half its margin to tip. θmax/α is the damage measure of rocking building contents in the
    fragility literature (e.g. D'Angela et al. 2026, Procedia Struct. Integrity 78:1617-1624, damage
    states from θmax/α = 0.01 to 1); the engine gives the peak rotation, not the impact velocity, so the
    rotation is the measure here, and 0.5 is a judgement, stated as the default of the setting.

    >>> rocking_harm(np.array([0.05, 0.6, 4.2]), np.array([False, False, True])).tolist()
    [False, True, False]
    """
    return (np.asarray(theta_over_alpha, dtype=float) >= harm_theta_over_alpha) & ~np.asarray(overturned, dtype=bool)


def suite_mode(severities) -> str:
    """The most severe mode (:data:`~assess.mechanics.modes.MODE_SEVERITY`) among the severities of a suite's
    runs; ``""`` for none.

    >>> suite_mode([1, 3, 2])
    'rock'
    """
    values = [int(v) for v in severities if np.isfinite(v)]
    if not values:
        return ""
    by_severity = {severity: mode for mode, severity in MODE_SEVERITY.items()}
    return by_severity[max(values)]


def _item_demand(item_cases: pd.DataFrame, histories: pd.DataFrame | None, regression: pd.DataFrame | None,
                 constants: RegressionConstants, room_quantile: float,
                 harm_theta_over_alpha: float = ROCKING_HARM_THETA_OVER_ALPHA) -> dict:
    clearance_cm = float(item_cases["clearance_m"].iloc[0]) * CM_PER_M
    units = item_cases.drop_duplicates(["motion_key", "mu_node"]).set_index(["motion_key", "mu_node"])
    source_of = item_cases.sort_values("mu_weight", ascending=False, kind="stable") \
        .drop_duplicates("motion_key").set_index("motion_key")["demand_source"].reindex(
            item_cases["motion_key"].drop_duplicates())
    n_motions = len(source_of)
    values, weights = [], []
    # per run of a simulated motion: its history (motion, realization), that history's share, its μ weight
    history_parts = []
    exact_beyond, exact_weight = 0.0, 0.0
    theta = 0.0
    severities = []
    planar_motions, uplift = set(), False
    simulated = _runs_by_unit(histories)
    regressed = {} if regression is None else dict(zip(
        regression.index, zip(regression["median_cm"].to_numpy(), regression["pf"].to_numpy())))
    lognormal = np.exp(constants.sigma * stats.norm.ppf((np.arange(_LOGNORMAL_POINTS) + 0.5) / _LOGNORMAL_POINTS))
    for (key, node), source, mu_weight in zip(units.index, units["demand_source"].to_numpy(),
                                              units["mu_weight"].to_numpy()):
        mu_weight = float(mu_weight)
        runs = simulated.get((key, node))
        if runs is not None:
            theta = max(theta, float(np.fmax.reduce(runs["theta"])))  # NaN skipped, as pandas' max
            severities.extend(runs["severity"][runs["mu_weight"] > 0.0].tolist())
        if source == REGRESSION:
            weight = mu_weight / n_motions
            median_cm, pf = regressed[(key, node)]
            if median_cm > 0.0:
                values.extend(median_cm * lognormal)
            else:
                values.extend(np.zeros(_LOGNORMAL_POINTS))
            weights.extend(np.full(_LOGNORMAL_POINTS, weight / _LOGNORMAL_POINTS))
            exact_beyond += float(pf) * weight
            exact_weight += weight
            continue
        count = len(runs["realization"])
        share = 1.0 / (n_motions * count)
        if runs["planar"].any():
            planar_motions.add(key)
        uplift = uplift or bool((runs["uplift"] & (runs["mu_weight"] > 0.0)).any())
        values.extend(runs["sliding_cm"])
        weights.extend(np.full(count, share * mu_weight))
        history_parts.append({
            "motion_key": np.full(count, key), "realization": runs["realization"], "share": np.full(count, share),
            "mass": np.full(count, mu_weight),
            "beyond": mu_weight * (runs["sliding_cm"] > clearance_cm),
            "overturn": mu_weight * runs["overturned"].astype(float),
            "harm": mu_weight * rocking_harm(runs["theta"], runs["overturned"], harm_theta_over_alpha).astype(float)})
    # per history: its weight (share × the μ weight of its simulated runs), and the μ-weighted share of its
    # runs beyond the clearance / overturned; the intervals count histories, not μ values
    sampled_weights, sampled_beyond, sampled_overturn, sampled_harm = [], [], [], []
    if history_parts:
        per_history = pd.DataFrame({column: np.concatenate([part[column] for part in history_parts])
                                    for column in history_parts[0]}).groupby(["motion_key", "realization"],
                                                                             sort=False).agg(
            share=("share", "first"), mass=("mass", "sum"), beyond=("beyond", "sum"), overturn=("overturn", "sum"),
            harm=("harm", "sum"))
        sampled_weights = (per_history["share"] * per_history["mass"]).tolist()
        sampled_beyond = (per_history["beyond"] / per_history["mass"]).tolist()
        sampled_overturn = (per_history["overturn"] / per_history["mass"]).tolist()
        sampled_harm = (per_history["harm"] / per_history["mass"]).tolist()
    p_beyond, p_beyond_interval = _probability(exact_beyond, exact_weight, sampled_beyond, sampled_weights)
    p_overturn, p_overturn_interval = _probability(0.0, exact_weight, sampled_overturn, sampled_weights)
    # the regression's motions are those where the item does not uplift: no rocking harm from them
    p_harm, p_harm_interval = _probability(0.0, exact_weight, sampled_harm, sampled_weights)
    if bool(np.all(pure_sliding_proved(item_cases["mu_static"], item_cases["b_over_h"]))):
        # it cannot uplift at any of its mu values (mu_s < b/h both ways): it neither rocks nor overturns,
        # whatever the histories, so these chances are exactly 0, not a sample's 0 with an interval
        p_overturn_interval = p_harm_interval = (0.0, 0.0)
    intervals = _quantile_intervals(values, weights, sampled_weights, exact_weight)
    sources = [s for s in (RECORD, REGRESSION, SYNTHETIC, PULSE) if s in set(units["demand_source"])]
    return {
        "demand_source": tuple("records" if s == RECORD else s for s in sources),
        "demand_median_cm": weighted_quantile(values, weights, 0.5),
        "demand_p84_cm": weighted_quantile(values, weights, 0.84),
        "demand_room_cm": weighted_quantile(values, weights, room_quantile),
        **intervals,
        "p_beyond_clearance": p_beyond, "p_beyond_clearance_low": p_beyond_interval[0],
        "p_beyond_clearance_high": p_beyond_interval[1],
        "p_overturn": p_overturn, "p_overturn_low": p_overturn_interval[0], "p_overturn_high": p_overturn_interval[1],
        "suite_motions": n_motions, "suite_histories": len(sampled_weights),
        "theta_max_over_alpha": theta,
        "demand_note": _source_note(item_cases, source_of, constants) + (
            " " + planar_note(len(planar_motions), n_motions) if planar_motions else ""),
        "demand_planar": bool(planar_motions),
        "demand_uplift": uplift,
        "p_rocking_harm": p_harm, "p_rocking_harm_low": p_harm_interval[0], "p_rocking_harm_high": p_harm_interval[1],
        "demand_mode": suite_mode(severities),
    }


def _runs_by_unit(histories: pd.DataFrame | None) -> dict:
    """An item's :func:`_per_history` table as ``(motion_key, mu_node) -> {column: array}`` (the runs of each
    motion and μ value, in the table's order; ``realization`` from its index)."""
    if histories is None:
        return {}
    columns = ("theta", "severity", "mu_weight", "planar", "uplift", "sliding_cm", "overturned")
    arrays = {column: histories[column].to_numpy() for column in columns}
    arrays["realization"] = histories.index.get_level_values(2).to_numpy()
    return {unit: {column: array[rows] for column, array in arrays.items()}
            for unit, rows in histories.groupby(level=[0, 1], sort=False).indices.items()}


def _quantile_intervals(values, weights, sampled_weights, exact_weight: float) -> dict:
    """90 % intervals of the median and the 84th percentile: distribution-free over the simulated draws
    (their effective count); none where the regression gives the whole distribution."""
    out = {}
    for name, q in (("median", 0.5), ("p84", 0.84)):
        if len(sampled_weights) and exact_weight < 1.0:
            low, high = quantile_interval(values, weights, q, effective_count(sampled_weights))
        else:
            low = high = weighted_quantile(values, weights, q)
        out[f"demand_{name}_low_cm"], out[f"demand_{name}_high_cm"] = low, high
    return out


def _probability(exact: float, exact_weight: float, sampled, sampled_weights) -> tuple[float, tuple[float, float]]:
    """The suite's probability: the regression's part exactly, the simulated part with its interval."""
    if not len(sampled_weights):
        return exact, (exact, exact)
    weights = np.asarray(sampled_weights, dtype=float)
    share = float(np.sum(weights * np.asarray(sampled, dtype=float)) / weights.sum())
    low, high = binomial_interval(share, effective_count(weights))
    sampled_weight = 1.0 - exact_weight
    return (exact + sampled_weight * share,
            (exact + sampled_weight * low, exact + sampled_weight * high))


def _source_note(item_cases: pd.DataFrame, source_of: pd.Series, constants: RegressionConstants) -> str:
    """Why each motion's demand comes from where it comes from, in one sentence."""
    parts = []
    counts = source_of.value_counts()
    n = len(source_of)
    if counts.get(RECORD, 0):
        parts.append(f"{_of(counts[RECORD], n)} simulated under their records (exact for the rigid-block model)")
    if counts.get(REGRESSION, 0):
        parts.append(f"{_of(counts[REGRESSION], n)} from the paper's regression (a pulse carrying at least "
                     f"{PULSE_SHARE_MIN:.0%} of PTA, IM within {constants.im_min:g}-{constants.im_max:g}, no uplift)")
    for source, what in ((SYNTHETIC, "synthetic near-fault histories"), (PULSE, "the motion's pulse")):
        if counts.get(source, 0):
            keys = source_of.index[source_of == source]
            outside = item_cases[item_cases["motion_key"].isin(keys)].drop_duplicates("motion_key")
            reasons = _outside_reasons(item_cases[item_cases["motion_key"].isin(keys)], outside, constants)
            parts.append(f"{_of(counts[source], n)} simulated under {what}"
                         + (f" (the regression does not hold: {reasons})" if reasons else ""))
    return "; ".join(parts) + "."


#: The words of each reason why the regression does not apply, as :func:`regression_note` writes them (the
#: report's table finds its short words by them: :data:`assess.report.items_table.REGRESSION_SHORT`).
NO_PULSE_WORDS, OUTSIDE_WORDS, UPLIFT_WORDS = "no clear pulse", "outside", "the item uplifts"


def regression_note(pulse_share: float, im: float, uplift: bool, constants: RegressionConstants) -> str:
    """Why the paper's regression does not apply to one case (""  where it does,
    :func:`~assess.fragility.suite.regression_applies`): "not applicable: ..." with each reason.

    >>> c = RegressionConstants(zeta=0.37, eta=0.953, sigma=0.445, im_min=1.71, im_max=6.4)
    >>> regression_note(0.5, 3.0, False, c), regression_note(0.2, 9.1, True, c)
    ('', 'not applicable: pulse share 0.2 < 0.38 (no clear pulse), IM 9.1 outside 1.71-6.4, the item uplifts')
    """
    share = 1.0 if not np.isfinite(pulse_share) else float(pulse_share)
    reasons = []
    if share < PULSE_SHARE_MIN:
        reasons.append(f"pulse share {share:.2g} < {PULSE_SHARE_MIN:g} ({NO_PULSE_WORDS})")
    if not constants.im_min <= im <= constants.im_max:
        reasons.append(f"IM {im:.2g} {OUTSIDE_WORDS} {constants.im_min:g}-{constants.im_max:g}")
    if uplift:
        reasons.append(UPLIFT_WORDS)
    return "not applicable: " + ", ".join(reasons) if reasons else ""


def _outside_reasons(cases: pd.DataFrame, motions: pd.DataFrame, constants: RegressionConstants) -> str:
    reasons = []
    weak = motions[motions["pulse_share"] < PULSE_SHARE_MIN]
    if len(weak):
        reasons.append(f"pulse share {_range(weak['pulse_share'])} < {PULSE_SHARE_MIN:g}, no clear pulse")
    outside = motions[(motions["im"] < constants.im_min) | (motions["im"] > constants.im_max)]
    if len(outside):
        reasons.append(f"IM {_range(outside['im'])} outside {constants.im_min:g}-{constants.im_max:g}")
    if cases["sim_uplift"].any():
        reasons.append("the item uplifts")
    return ", ".join(reasons)


def _range(values: pd.Series) -> str:
    low, high = float(values.min()), float(values.max())
    return f"{low:.2g}" if np.isclose(low, high, rtol=0.005) else f"{low:.2g}-{high:.2g}"


def _of(count: int, total: int) -> str:
    if total == 1:
        return "its one motion"
    return f"{count} of its {total} motions" if count < total else f"all {total} motions"
