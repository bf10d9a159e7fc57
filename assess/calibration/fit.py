"""Errors of a model against measured tests, fitting an effect, and choosing one (docs/calibration.md).

**Error measures** (:func:`error_measures`):

* ``sliding_rms_log``: RMS over the tests with a measured sliding of
  :math:`\\ln(\\max(u_{pred}, u_0)/\\max(u_{meas}, u_0))` with the floor
  :math:`u_0` = :data:`SLIDING_FLOOR_M` = 1 mm: a peak below 1 mm counts as
  1 mm, about the resolution of a table test's displacement transducer, so a
  model that predicts no sliding for a test that slid 1 cm is 2.3 off, not
  infinitely; a test measured at 0 sliding counts too (at 1 mm).
* ``overturn_misclassified``: how many tests with an observed ``overturned``
  the model gets wrong.
* ``theta_rms``: RMS of predicted minus measured θmax/α over the tests where
  it was measured, both capped at 1 (at 1 the block overturns).
* ``theta_rms_band``: RMS of how far the measured θmax/α lies outside the
  range the model predicts over the amplitudes × (1 − δ, 1, 1 + δ),
  δ = :data:`AMPLITUDE_BAND` = 1 % (:func:`theta_outside_band`).

**Rocking is chaotic**, so rotations are compared with a range. Under a real
record the peak rotation of a rocking block can change by 15 % of α for 0.3 %
of amplitude, and overturn or not within ±0.5 % (the impacts fall at other
instants of the record and the rest of the response follows them;
docs/calibration.md counts 17 of 48 tests of a footed lab moving by more
than 0.05 of α for ±0.5 %). A table does not play a record at exactly the
commanded amplitude, so a measured rotation fixes the model only to within
what ±1 % of amplitude can do: the right model at the right parameters was
0.12 off in θ/α RMS on such a lab, and an effect with the amplitude for a
parameter (``input_scale``) could then fit the chaos better than the right one
and be selected. Each model is therefore charged only for what no amplitude
of the range explains: the θ term of the objective is the distance outside
the range, and an overturning counts as misclassified only when no amplitude
of the range predicts it. The range is made (two more simulations) only for
tests that measured a rotation or an overturning and whose nominal prediction
uplifted; sliding, which is not chaotic, is compared at the nominal
amplitude. ``theta_rms`` and ``overturn_misclassified`` are still reported
at the nominal amplitude.

**Objective** (:func:`objective`): the mean squared, standardised residual
per measure,

.. math:: J = \\frac{\\sum_i \\left[\\ln^2 r_i + (\\Delta_i/0.25)^2 + 1\\cdot m_i\\right]}
                 {\\text{number of measures}}

with :math:`r_i` the sliding ratio above, :math:`\\Delta_i` the distance of
the measured θmax/α outside the predicted range (:data:`THETA_SCALE` = 0.25: an error of a quarter of the way to
overturning weighs as much as a factor e on sliding) and :math:`m_i` = 1 for
an overturning no amplitude of the range predicts (:data:`OVERTURN_WEIGHT`: as much as a factor e on
sliding); each term only where that measure exists.

**Fitting** (:func:`fit_effect`): the objective on a grid over each
parameter's bounds (:data:`GRID_POINTS_1D` values for one parameter,
:data:`GRID_POINTS_2D` per axis for two), then a bounded scipy refinement
within the grid cells around the best point.

**Cross-validation**: leave-one-out refits choose, for each held-out test,
the best point for the other tests among the grid, a finer grid over the
cells around the full-data optimum (:data:`LOCAL_POINTS_1D` values, or
:data:`LOCAL_POINTS_2D` per axis) and that optimum itself. Overturning can
switch on and off within one grid step of the motion or geometry (rocking
responses are fragmented), so a coarse grid alone would charge the true effect
with misfits it does not have. The finer grid sits where all the tests put it,
which slightly favours every effect with parameters alike (a small optimistic
bias that the 10 % margin over ``none`` absorbs).

**Selection** (:func:`select_effect`): each effect is scored by leave-one-out
cross-validation: every test is predicted with the parameters fitted (on the
grid) to the other tests, and the score is :math:`J` of those predictions.
``none`` has nothing to fit, so its score is its error. An effect earns its
parameters only if its score is below ``(1 − margin)`` × the score of
``none`` (:data:`MARGIN` = 10 %) and it is fitted away from the declared
model: some parameter lies more than :data:`NEUTRAL_STANDARD_ERRORS` = 2
jackknife standard errors from its neutral value (:func:`departs_from_declared`;
a rocking response near a threshold can change by 15 % with the input
amplitude changed by 0.3 %, so an effect fitted at s = 0.997 can beat the
declared model on noise alone). Among the effects that do, those within
``margin`` of the best score fit equally well; the one with the fewest
parameters is selected (then the lower score). ``indistinguishable_from``
lists the other effects whose score is within ``margin`` of the selected one's
(with ``none`` selected: the effects that did no better than 10 % below
``none`` and no worse than 10 % above: the data cannot tell them from the
declared model). Peaks alone often cannot separate effects: for pure sliding
under pulses, ``friction_scale`` and ``input_scale`` are nearly degenerate.
"""
from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from typing import Mapping, Sequence

import numpy as np
import pandas as pd

from assess.calibration.effects import Effect, Prediction, prediction
from assess.mechanics.gateway import run_responses
from assess.hazard.records import Record
from assess.mechanics.modes import ROCK, SLIDE_ROCK

#: Peak sliding below which a prediction or measurement counts as this value [m].
SLIDING_FLOOR_M = 0.001
#: θmax/α difference that weighs as much as a factor e on sliding [-].
THETA_SCALE = 0.25
#: Weight of one misclassified overturning in the objective [-].
OVERTURN_WEIGHT = 1.0
#: Relative margin by which an effect's cross-validated score must beat ``none``'s.
MARGIN = 0.10
#: Relative change of the motion's amplitude over which a rocking prediction is taken as a range [-].
AMPLITUDE_BAND = 0.01
GRID_POINTS_1D = 21
GRID_POINTS_2D = 9
LOCAL_POINTS_1D = 11
LOCAL_POINTS_2D = 5


@dataclass(frozen=True)
class Case:
    """One test as the model sees it: the item, the half-width shaken and the motion played."""

    specimen: str
    motion: str
    direction: int
    item: Mapping
    half_width_m: float
    record: Record
    #: Whether the test measured a rotation or an overturning: only then is the rocking
    #: prediction also made at ±:data:`AMPLITUDE_BAND` of the amplitude (:func:`predict_cases`).
    rocking_measured: bool = False

    def key(self) -> tuple:
        """Identifies the simulation inputs (for the prediction cache)."""
        fields = ("height_m", "cg_height_m", "mu", "mu_static")
        return (self.specimen, self.motion, self.direction, self.half_width_m,
                tuple(float(self.item[f]) for f in fields), self.record.dt_s, self.record.accel_g.size,
                float(np.sum(np.abs(self.record.accel_g))))


@dataclass(frozen=True)
class Measured:
    """Measured peaks per test as arrays (NaN where not measured; ``overturned`` 1/0/NaN)."""

    sliding_m: np.ndarray
    theta_max_over_alpha: np.ndarray
    overturned: np.ndarray

    @classmethod
    def from_table(cls, table: pd.DataFrame) -> "Measured":
        over = np.array([np.nan if v is None or (isinstance(v, float) and np.isnan(v)) else float(bool(v))
                         for v in table["overturned"]], dtype=float)
        return cls(table["sliding_m"].to_numpy(float), table["theta_max_over_alpha"].to_numpy(float), over)

    @property
    def counts(self) -> np.ndarray:
        """Number of measures of each test."""
        return (np.isfinite(self.sliding_m).astype(int) + np.isfinite(self.theta_max_over_alpha)
                + np.isfinite(self.overturned))

    def subset(self, index) -> "Measured":
        return Measured(self.sliding_m[index], self.theta_max_over_alpha[index], self.overturned[index])


@dataclass(frozen=True)
class Predicted:
    """Predicted peaks per test (arrays of the same length as the tests); ``mode`` per test."""

    sliding_m: np.ndarray
    theta_max_over_alpha: np.ndarray
    overturned: np.ndarray
    mode: np.ndarray
    #: θmax/α (capped at 1) lowest and highest over the amplitudes × (1 − δ, 1, 1 + δ), and whether
    #: the block overturned at any and at all of them (:func:`predict_cases`); the nominal
    #: prediction where no band was made.
    theta_low: np.ndarray = None
    theta_high: np.ndarray = None
    overturned_any: np.ndarray = None
    overturned_all: np.ndarray = None

    def __post_init__(self):
        capped = np.minimum(np.asarray(self.theta_max_over_alpha, float), 1.0)
        for name, default in (("theta_low", capped), ("theta_high", capped), ("overturned_any", self.overturned),
                              ("overturned_all", self.overturned)):
            if getattr(self, name) is None:
                object.__setattr__(self, name, np.array(default))

    @classmethod
    def from_predictions(cls, predictions: Sequence[Prediction],
                         bands: Sequence[Sequence[Prediction]] = ()) -> "Predicted":
        """The nominal ``predictions``; ``bands`` (one list per test: the predictions at every amplitude
        of its band, the nominal one included, or empty) make the ranges."""
        nominal = cls(np.array([p.sliding_max_m for p in predictions], float),
                      np.array([p.theta_max_over_alpha for p in predictions], float),
                      np.array([p.overturned for p in predictions], bool),
                      np.array([p.mode for p in predictions], object))
        for k, band in enumerate(bands):
            if band:
                theta = np.minimum([p.theta_max_over_alpha for p in band], 1.0)
                over = [bool(p.overturned) for p in band]
                nominal.theta_low[k], nominal.theta_high[k] = theta.min(), theta.max()
                nominal.overturned_any[k], nominal.overturned_all[k] = any(over), all(over)
        return nominal


def sliding_log_ratio(predicted_m, measured_m):
    """ln(max(pred, 1 mm)/max(meas, 1 mm)) [-]; NaN where not measured.

    >>> round(float(sliding_log_ratio(0.02, 0.01)), 4), float(sliding_log_ratio(0.0, 0.0005))
    (0.6931, 0.0)
    """
    predicted_m, measured_m = np.asarray(predicted_m, float), np.asarray(measured_m, float)
    return np.log(np.maximum(predicted_m, SLIDING_FLOOR_M) / np.maximum(measured_m, SLIDING_FLOOR_M))


def theta_difference(predicted, measured):
    """Predicted minus measured θmax/α, both capped at 1 [-]; NaN where not measured."""
    return np.minimum(np.asarray(predicted, float), 1.0) - np.minimum(np.asarray(measured, float), 1.0)


def theta_outside_band(low, high, measured):
    """How far the measured θmax/α (capped at 1) lies outside the predicted range [low, high] [-].

    0 inside it; NaN where not measured.

    >>> theta_outside_band(np.array([0.2, 0.2, 0.2]), np.array([0.5, 0.5, 0.5]), np.array([0.1, 0.3, 1.4])).tolist()
    [-0.1, 0.0, 0.5]
    """
    measured = np.minimum(np.asarray(measured, float), 1.0)
    low, high = np.asarray(low, float), np.asarray(high, float)
    return np.where(measured < low, measured - low, np.where(measured > high, measured - high, 0.0))


def test_losses(predicted: Predicted, measured: Measured) -> np.ndarray:
    """Each test's term of the objective's numerator (0 for a measure that is missing).

    Works on arrays of shape (..., n_tests), e.g. (n_grid, n_tests).
    """
    ratio = sliding_log_ratio(predicted.sliding_m, measured.sliding_m)
    theta = theta_outside_band(predicted.theta_low, predicted.theta_high, measured.theta_max_over_alpha) / THETA_SCALE
    wrong = overturn_wrong(predicted, measured)
    return (np.nan_to_num(ratio**2) + np.nan_to_num(theta**2) + OVERTURN_WEIGHT * np.nan_to_num(wrong))


def overturn_wrong(predicted: Predicted, measured: Measured) -> np.ndarray:
    """1 where no amplitude of the band predicts the observed overturning (yes or no), else 0; NaN where
    not observed."""
    observed = measured.overturned
    wrong = np.where(observed == 1.0, ~np.asarray(predicted.overturned_any, bool),
                     np.asarray(predicted.overturned_all, bool)).astype(float)
    return np.where(np.isfinite(observed), wrong, np.nan)


test_losses.__test__ = False  # not a pytest test despite its name


def objective(losses, counts) -> float:
    """J: the sum of the losses over the number of measures."""
    return float(np.sum(losses, axis=-1) / max(int(np.sum(counts)), 1))


def error_measures(predicted: Predicted, measured: Measured) -> dict:
    """``sliding_rms_log``, ``overturn_misclassified``, ``theta_rms`` (None where nothing measured), counts."""
    ratio = sliding_log_ratio(predicted.sliding_m, measured.sliding_m)
    ratio = ratio[np.isfinite(measured.sliding_m)]
    theta = theta_difference(predicted.theta_max_over_alpha, measured.theta_max_over_alpha)
    theta = theta[np.isfinite(measured.theta_max_over_alpha)]
    band = theta_outside_band(predicted.theta_low, predicted.theta_high, measured.theta_max_over_alpha)
    band = band[np.isfinite(measured.theta_max_over_alpha)]
    observed = np.isfinite(measured.overturned)
    wrong = int(np.sum(predicted.overturned[observed].astype(float) != measured.overturned[observed]))
    losses = test_losses(predicted, measured)
    return {"sliding_rms_log": float(np.sqrt(np.mean(ratio**2))) if ratio.size else None,
            "overturn_misclassified": wrong if observed.any() else None,
            "theta_rms": float(np.sqrt(np.mean(theta**2))) if theta.size else None,
            "theta_rms_band": float(np.sqrt(np.mean(band**2))) if band.size else None,
            "objective": objective(losses, measured.counts),
            "tests_sliding": int(ratio.size), "tests_theta": int(theta.size),
            "tests_overturned": int(observed.sum())}


def predict_cases(effect: Effect, cases: Sequence[Case], parameters: Mapping[str, float],
                  cache: dict | None = None, runner=None) -> Predicted:
    """The effect's predictions for every test, from ``cache`` where it has them; the others are simulated
    in one batch through ``runner`` (:mod:`assess.mechanics.gateway`; default this machine)."""
    cache = {} if cache is None else cache
    values = tuple(round(float(parameters[p.name]), 12) for p in effect.parameters)

    def run(wanted):
        """Predictions for ``wanted`` (case, amplitude factor) pairs: the ones not in ``cache`` in one batch."""
        keys = [(effect.name, values, case.key(), factor) for case, factor in wanted]
        todo = {}
        for key, (case, factor) in zip(keys, wanted):
            if key not in cache and key not in todo:
                todo[key] = (case, factor)
        if todo:
            models = [effect.model(case.item, case.half_width_m,
                                   case.record if factor == 1.0 else case.record.scaled(factor), dict(parameters))
                      for case, factor in todo.values()]
            responses = run_responses([(block, motion.accel_g, motion.dt_s) for block, motion in models], runner)
            for key, (block, _), response in zip(todo, models, responses):
                cache[key] = prediction(block, response)
        return [cache[key] for key in keys]

    out = run([(case, 1.0) for case in cases])
    rocking = [case.rocking_measured and (nominal.overturned or nominal.mode in (ROCK, SLIDE_ROCK))
               for case, nominal in zip(cases, out)]
    factors = (1.0 - AMPLITUDE_BAND, 1.0 + AMPLITUDE_BAND)
    banded = iter(run([(case, f) for case, rocks in zip(cases, rocking) if rocks for f in factors]))
    bands = [[next(banded), nominal, next(banded)] if rocks else [] for nominal, rocks in zip(out, rocking)]
    return Predicted.from_predictions(out, bands)


@dataclass
class EffectFit:
    """An effect fitted to the tests.

    ``parameters`` are the refined best fit; ``error`` its error measures on
    all tests; ``score`` the leave-one-out cross-validated objective;
    ``predicted`` the predictions at ``parameters``; ``cv_losses`` each test's
    held-out loss; ``standard_error`` the jackknife standard error of each
    parameter (:func:`jackknife_standard_error`).
    """

    effect: Effect
    parameters: dict
    error: dict
    score: float
    predicted: Predicted
    cv_losses: np.ndarray = field(repr=False)
    standard_error: dict = field(default_factory=dict)
    not_determined: dict = field(default_factory=dict)
    """Parameters the tests cannot fix, each with the reason (:func:`undetermined_parameters`)."""


def parameter_grid(effect: Effect) -> list[dict]:
    """The grid points of :func:`fit_effect` (one empty point for an effect without parameters)."""
    count = GRID_POINTS_1D if len(effect.parameters) == 1 else GRID_POINTS_2D
    axes = [p.grid(count) for p in effect.parameters]
    return [dict(zip([p.name for p in effect.parameters], point)) for point in itertools.product(*axes)]


def leave_one_out(losses: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Held-out loss of each test and the grid point chosen without it.

    ``losses`` has shape (n_grid, n_tests). Test i is predicted at the grid
    point that minimises the summed loss of the other tests.

    >>> held, chosen = leave_one_out(np.array([[0.0, 0.0, 9.0], [1.0, 1.0, 0.0]]))
    >>> held.tolist(), chosen.tolist()
    ([1.0, 1.0, 9.0], [1, 1, 0])
    """
    total = losses.sum(axis=1)
    chosen = np.argmin(total[:, None] - losses, axis=0)
    return losses[chosen, np.arange(losses.shape[1])], chosen


def fit_effect(effect: Effect, cases: Sequence[Case], measured: Measured, cache: dict | None = None,
               refine: bool = True, runner=None) -> EffectFit:
    """Fit the effect's parameters to the tests and cross-validate it (module docstring); ``runner`` runs
    the simulations (:func:`predict_cases`)."""
    cache = {} if cache is None else cache
    counts = measured.counts
    grid = parameter_grid(effect)
    losses = [test_losses(predict_cases(effect, cases, point, cache, runner), measured) for point in grid]
    not_determined = undetermined_parameters(effect, grid, [objective(loss, counts) for loss in losses])
    best = int(np.argmin(np.sum(losses, axis=1)))
    parameters = {k: float(v) for k, v in grid[best].items()}
    if refine and effect.parameters:
        parameters = _refine(effect, cases, measured, cache, parameters, objective(losses[best], counts), runner)
        local = _local_grid(effect, parameters) + [parameters]
        grid += local
        losses += [test_losses(predict_cases(effect, cases, point, cache, runner), measured) for point in local]
    held, chosen = leave_one_out(np.array(losses))
    predicted = predict_cases(effect, cases, parameters, cache, runner)
    error = jackknife_standard_error([grid[k] for k in chosen])
    if refine and effect.parameters:  # the held-out estimates are grid points: add their quantisation
        for p, (low, high) in zip(effect.parameters, _cell_bounds(effect, parameters)):
            count = LOCAL_POINTS_1D if len(effect.parameters) == 1 else LOCAL_POINTS_2D
            step = (np.exp(high) - np.exp(low) if p.log else high - low) / (count - 1)
            error[p.name] = float(np.hypot(error[p.name], step / np.sqrt(12.0)))
    for name in not_determined:
        error[name] = None
    return EffectFit(effect, parameters, error_measures(predicted, measured), objective(held, counts),
                     predicted, held, error, not_determined)


#: Objective values closer than this (relative, and absolute below 1) count as equal [-].
FLAT_TOLERANCE = 1e-9


def undetermined_parameters(effect: Effect, grid: Sequence[Mapping[str, float]], values: Sequence[float]) -> dict:
    """The parameters these tests cannot fix, each with a sentence saying why.

    A parameter is not determined when the objective's minimum over the grid
    is reached (within :data:`FLAT_TOLERANCE`) at three or more of its grid
    values: the tests then fit a whole interval of it equally well, e.g.
    the restitution when no tested specimen rocks (every e predicts the same
    peaks), or the rate of velocity friction when its low-speed factor is 1.
    A fitted value and a jackknife error would then be artefacts of the grid.

    >>> from assess.calibration.effects import EFFECTS
    >>> grid = [{"e": v} for v in (0.0, 0.5, 1.0)]
    >>> undetermined_parameters(EFFECTS["restitution"], grid, [0.3, 0.3, 0.3])["e"][:52]
    'every value from 0 to 1 predicts these tests alike: '
    >>> undetermined_parameters(EFFECTS["restitution"], grid, [0.3, 0.1, 0.3])
    {}
    """
    values = np.asarray(values, dtype=float)
    if values.size == 0 or not effect.parameters:
        return {}
    best = float(np.min(values))
    tied = values <= best + FLAT_TOLERANCE * max(1.0, abs(best))
    out = {}
    for p in effect.parameters:
        tied_values = np.unique([float(point[p.name]) for point, t in zip(grid, tied) if t])
        if tied_values.size < 3:
            continue
        low, high = tied_values.min(), tied_values.max()
        span = ("every value from {0} to {1}" if (low, high) == (p.lower, p.upper) or tied.all()
                else "every value from {0} to {1} (of {2} to {3})").format(
                    _plain(low), _plain(high), _plain(p.lower), _plain(p.upper))
        out[p.name] = f"{span} predicts these tests alike: {p.determined_by}."
    return out


def _plain(value: float) -> str:
    return f"{value:.3g}"


def jackknife_standard_error(leave_one_out_parameters: Sequence[Mapping[str, float]]) -> dict:
    """Standard error of each parameter from its leave-one-out estimates (Efron & Stein 1981).

    .. math:: SE = \\sqrt{\\tfrac{n-1}{n}\\sum_i (\\hat\\theta_{(i)} - \\bar\\theta)^2}

    The held-out estimates are the grid points chosen without each test, so
    :func:`fit_effect` adds the quantisation of the local grid, spacing/√12.

    >>> jackknife_standard_error([{"k": 1.0}, {"k": 1.0}, {"k": 1.3}])
    {'k': 0.2}
    """
    if not leave_one_out_parameters:
        return {}
    n = len(leave_one_out_parameters)
    out = {}
    for name in leave_one_out_parameters[0]:
        values = np.array([float(p[name]) for p in leave_one_out_parameters])
        out[name] = round(float(np.sqrt((n - 1) / n * np.sum((values - values.mean()) ** 2))), 12)
    return out


def _cell_bounds(effect: Effect, point: Mapping[str, float]) -> list[tuple[float, float]]:
    """Per parameter, the grid values either side of ``point`` (log scale where the parameter is)."""
    count = GRID_POINTS_1D if len(effect.parameters) == 1 else GRID_POINTS_2D
    bounds = []
    for p in effect.parameters:
        axis = p.grid(count)
        axis = np.log(axis) if p.log else axis
        value = np.log(point[p.name]) if p.log else point[p.name]
        k = int(np.argmin(np.abs(axis - value)))
        bounds.append((axis[max(k - 1, 0)], axis[min(k + 1, axis.size - 1)]))
    return bounds


def _local_grid(effect: Effect, point: Mapping[str, float]) -> list[dict]:
    """A finer grid over the grid cells around ``point`` (11 values for one parameter, 5 x 5 for two)."""
    count = LOCAL_POINTS_1D if len(effect.parameters) == 1 else LOCAL_POINTS_2D
    axes = []
    for p, (low, high) in zip(effect.parameters, _cell_bounds(effect, point)):
        values = np.linspace(low, high, count)
        axes.append(np.exp(values) if p.log else values)
    return [dict(zip([p.name for p in effect.parameters], map(float, v))) for v in itertools.product(*axes)]


def _refine(effect, cases, measured, cache, start: dict, start_value: float, runner=None) -> dict:
    """Minimise the objective within the grid cells around ``start``; keep ``start`` unless it improves."""
    from scipy.optimize import minimize, minimize_scalar

    forward = [np.log if p.log else (lambda v: v) for p in effect.parameters]
    backward = [np.exp if p.log else (lambda v: v) for p in effect.parameters]
    bounds = _cell_bounds(effect, start)
    counts = measured.counts

    def value(x):
        point = {p.name: float(back(v)) for p, back, v in zip(effect.parameters, backward, np.atleast_1d(x))}
        return objective(test_losses(predict_cases(effect, cases, point, cache, runner), measured), counts)

    x0 = np.array([fwd(start[p.name]) for p, fwd in zip(effect.parameters, forward)])
    if len(effect.parameters) == 1:
        if bounds[0][0] == bounds[0][1]:
            return start
        result = minimize_scalar(value, bounds=bounds[0], method="bounded",
                                 options={"maxiter": 20, "xatol": 1e-3 * (bounds[0][1] - bounds[0][0])})
        x, found = np.atleast_1d(result.x), float(result.fun)
    else:
        result = minimize(value, x0, method="Nelder-Mead", bounds=bounds,
                          options={"maxfev": 40, "xatol": 1e-3, "fatol": 1e-6})
        x, found = np.atleast_1d(result.x), float(result.fun)
    if not found < start_value:
        return start
    return {p.name: float(back(v)) for p, back, v in zip(effect.parameters, backward, x)}


#: How many standard errors from its neutral value a parameter must be fitted to count as an effect.
NEUTRAL_STANDARD_ERRORS = 2.0


def departs_from_declared(fit) -> bool:
    """Whether some parameter of ``fit`` lies more than 2 standard errors from its neutral value.

    A parameter without a neutral value (``restitution``: Housner's e differs
    per item) or without a standard error counts as departing; one the tests
    cannot fix (``not_determined``) does not.

    >>> from types import SimpleNamespace
    >>> from assess.calibration.effects import EFFECTS
    >>> fit = SimpleNamespace(effect=EFFECTS["input_scale"], parameters={"s": 0.997},
    ...                       standard_error={"s": 0.004}, not_determined={})
    >>> departs_from_declared(fit), departs_from_declared(SimpleNamespace(**{**vars(fit), "parameters": {"s": 0.7}}))
    (False, True)
    """
    parameters = getattr(fit, "parameters", None)
    errors = getattr(fit, "standard_error", None) or {}
    missing = getattr(fit, "not_determined", None) or {}
    if not parameters:
        return True
    for p in fit.effect.parameters:
        if p.name in missing:
            continue
        error = errors.get(p.name)
        if p.neutral is None or error is None:
            return True
        if abs(float(parameters[p.name]) - p.neutral) > NEUTRAL_STANDARD_ERRORS * float(error):
            return True
    return False


def select_effect(fits: Sequence[EffectFit], margin: float = MARGIN) -> tuple[str, list[str]]:
    """The selected effect's name and the names it cannot be told from (module docstring)."""
    scores = {f.effect.name: f.score for f in fits}
    sizes = {f.effect.name: len(f.effect.parameters) for f in fits}
    reference = scores["none"]
    departs = {f.effect.name: departs_from_declared(f) for f in fits}
    earning = [n for n in scores if n != "none" and scores[n] < (1.0 - margin) * reference and departs[n]]
    if earning:
        best = min(scores[n] for n in earning)
        equal = [n for n in earning if scores[n] <= (1.0 + margin) * best]
        selected = min(equal, key=lambda n: (sizes[n], scores[n]))
    else:
        selected = "none"
    level = scores[selected]
    similar = [n for n in scores if n != selected and n != "none" and abs(scores[n] - level) <= margin * level]
    return selected, similar
