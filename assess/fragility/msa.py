"""Lognormal fragility fitted by maximum likelihood on multiple-stripe outcomes.

An item is simulated at several *stripes* of an intensity measure (here the
floor's peak acceleration, PFA [g]); at stripe j, :math:`z_j` of the
:math:`n_j` simulations fail (slide past the clearance, or overturn). The
fragility is the lognormal CDF

.. math::

    P(\\mathrm{fail} \\mid x) = \\Phi\\!\\left(\\frac{\\ln(x/\\theta)}{\\beta}\\right)

and :math:`(\\theta, \\beta)` maximise the binomial likelihood over the
stripes ([1], section "Multiple stripes analysis")

.. math::

    L(\\theta, \\beta) = \\prod_j \\binom{n_j}{z_j}\\, p_j^{z_j} (1 - p_j)^{n_j - z_j},
    \\qquad p_j = \\Phi\\!\\left(\\frac{\\ln(x_j/\\theta)}{\\beta}\\right).

This is a probit regression on :math:`\\ln x` ([2] §3.3, §4.3): with
:math:`\\eta = \\alpha + \\gamma \\ln x`, :math:`\\gamma = 1/\\beta`,
:math:`\\alpha = -\\ln\\theta/\\beta`. Its log-likelihood is concave in
:math:`(\\alpha, \\gamma)` (:math:`\\ln\\Phi` is log-concave), so Newton's
method with a line search finds the maximum whenever one exists, and it exists
exactly when the failures and the survivals *overlap* in intensity ([3]):
no level separates them. Otherwise there is no finite fit, and
:func:`fit_lognormal_fragility` says so (``status``) instead of returning
numbers:

* ``"no_failures"`` / ``"all_failed"``: every simulation survived / failed;
  the data bound the median from one side only;
* ``"separated"``: every survival lies at or below some level and every failure
  at or above it: the likelihood grows without bound as β → 0 and the median
  is only known to lie in ``separation_g``;
* ``"one_intensity"``: mixed outcomes at a single intensity: β cannot be
  estimated;
* ``"decreasing"``: failures are likelier at *lower* intensity (γ̂ ≤ 0): no
  fragility describes that.

Standard errors come from the observed information (minus the Hessian of the
log-likelihood at the maximum), inverted, in the parameters
:math:`(\\ln\\theta, \\beta)`. The information is computed in
:math:`(\\alpha, \\gamma)`, where it has a closed form, and carried over by the
Jacobian of :math:`(\\ln\\theta, \\beta) = (-\\alpha/\\gamma, 1/\\gamma)`; at the
maximum the gradient vanishes, so this *is* the inverse Hessian in
:math:`(\\ln\\theta, \\beta)`. ``se_ln_median`` is therefore the standard error
of :math:`\\ln\\theta` (≈ the relative standard error of θ), and
``se_median_g`` its delta-method value :math:`\\theta\\,\\mathrm{se}(\\ln\\theta)`.
They are asymptotic: with few failures they understate the uncertainty.

References
----------
.. [1] Baker, J. W. (2015). Efficient analytical fragility function fitting
   using dynamic structural analysis. Earthquake Spectra 31(1):579-599.
   doi:10.1193/021113EQS025M
.. [2] McCullagh, P., Nelder, J. A. (1989). Generalized Linear Models, 2nd ed.
   Chapman & Hall. (binary data, probit link, Fisher information)
.. [3] Albert, A., Anderson, J. A. (1984). On the existence of maximum
   likelihood estimates in logistic regression models. Biometrika 71(1):1-10.
   doi:10.1093/biomet/71.1.1
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import special, stats

#: Newton iterations before the fit is declared not converged (it converges in < 15 when it can).
MAX_ITERATIONS = 100
#: Convergence: the Newton step in (α, γ) is below this (relative to 1 + |parameter|).
STEP_TOL = 1e-10

FITTED = "fitted"
NO_FAILURES = "no_failures"
ALL_FAILED = "all_failed"
SEPARATED = "separated"
ONE_INTENSITY = "one_intensity"
DECREASING = "decreasing"
NOT_CONVERGED = "not_converged"


@dataclass(frozen=True, eq=False)
class FragilityFit:
    """A lognormal fragility fitted on stripes, or why there is none.

    Attributes
    ----------
    status : str
        ``"fitted"``, or why no finite fit exists: ``"no_failures"``,
        ``"all_failed"``, ``"separated"``, ``"one_intensity"``,
        ``"decreasing"``, ``"not_converged"`` (see the module docstring).
    median_g : float
        θ [g], the intensity at which failure has probability 0.5; NaN unless fitted.
    beta : float
        β [-], the logarithmic standard deviation; NaN unless fitted.
    se_ln_median : float
        Standard error of ln θ [-] (observed information); NaN unless fitted.
    se_beta : float
        Standard error of β [-]; NaN unless fitted.
    covariance : ndarray (2, 2)
        Covariance of (ln θ, β): the inverse observed information; NaN unless fitted.
    log_likelihood : float
        The maximised binomial log-likelihood (binomial coefficients included);
        NaN unless fitted.
    n_stripes, n_trials, n_failures : int
        Distinct intensities, simulations and failures used.
    separation_g : tuple of float
        For ``"separated"``: the highest intensity [g] with a survival and the
        lowest with a failure; the median lies between. NaN otherwise.
    message : str
        One sentence for a person: the fit, or why there is none.
    """

    status: str
    median_g: float
    beta: float
    se_ln_median: float
    se_beta: float
    covariance: np.ndarray
    log_likelihood: float
    n_stripes: int
    n_trials: int
    n_failures: int
    separation_g: tuple[float, float]
    message: str

    @property
    def fitted(self) -> bool:
        return self.status == FITTED

    @property
    def se_median_g(self) -> float:
        """Standard error of θ [g] by the delta method, θ·se(ln θ)."""
        return self.median_g * self.se_ln_median

    def probability(self, im_g):
        """P(fail | im) = Φ(ln(im/θ)/β) of the fit; NaN where there is no fit."""
        return lognormal_fragility(im_g, self.median_g, self.beta)


def lognormal_fragility(im_g, median_g, beta):
    """Lognormal fragility Φ(ln(x/θ)/β) [-] ([1] eq. of the fragility function).

    Parameters
    ----------
    im_g : float or array-like
        Intensity x [g], ≥ 0 (0 gives 0).
    median_g : float
        Median θ [g].
    beta : float
        Dispersion β [-], > 0.

    >>> round(float(lognormal_fragility(0.5, 0.5, 0.4)), 6)
    0.5
    >>> round(float(lognormal_fragility(0.5 * math.exp(0.4), 0.5, 0.4)), 4)  # one β above: Φ(1)
    0.8413
    """
    im = np.asarray(im_g, dtype=float)
    with np.errstate(divide="ignore"):
        return special.ndtr(np.log(im / median_g) / beta)


def stripes_from_outcomes(im_g, failed):
    """Group binary outcomes by intensity: (distinct im [g], trials, failures).

    >>> x, n, z = stripes_from_outcomes([0.2, 0.4, 0.2, 0.4, 0.4], [0, 1, 1, 1, 0])
    >>> x.tolist(), n.tolist(), z.tolist()
    ([0.2, 0.4], [2, 3], [1, 2])
    """
    im = np.asarray(im_g, dtype=float).ravel()
    outcome = np.asarray(failed).ravel()
    if im.shape != outcome.shape:
        raise ValueError("im_g and failed must have the same length")
    if not np.all(np.isin(outcome, (0, 1, True, False))):
        raise ValueError("failed must hold 0/1 or booleans")
    levels, index = np.unique(im, return_inverse=True)
    trials = np.bincount(index, minlength=levels.size)
    failures = np.bincount(index, weights=outcome.astype(float), minlength=levels.size)
    return levels, trials.astype(np.int64), failures.astype(np.int64)


def binomial_log_likelihood(im_g, n_trials, n_failures, median_g, beta) -> float:
    """Σ_j ln binom.pmf(z_j; n_j, Φ(ln(x_j/θ)/β)), the log of [1]'s MSA likelihood.

    >>> round(binomial_log_likelihood([0.5], [4], [2], 0.5, 0.3), 6)  # ln(6/16)
    -0.980829
    """
    p = lognormal_fragility(im_g, median_g, beta)
    return float(np.sum(stats.binom.logpmf(np.asarray(n_failures), np.asarray(n_trials), p)))


def fit_lognormal_fragility(im_g, n_trials, n_failures) -> FragilityFit:
    """Maximum-likelihood lognormal fragility over stripes (multiple-stripe analysis, [1]).

    Parameters
    ----------
    im_g : array-like (m,)
        Intensity of each stripe [g] (the floor's peak acceleration), > 0.
        Stripes may repeat an intensity; single outcomes are stripes of one.
    n_trials : array-like of int (m,)
        Simulations at each stripe, ≥ 1.
    n_failures : array-like of int (m,)
        Failures among them, 0 ≤ z ≤ n.

    Returns
    -------
    FragilityFit
        θ [g], β, their standard errors and covariance in (ln θ, β), or a
        status saying why no finite fit exists (then the numbers are NaN).

    Examples
    --------
    Symmetric outcomes about 0.4 g give θ = 0.4 g exactly (1/2 at the
    middle stripe, 1/4 and 3/4 one step of ln 2 either side, so
    β = ln 2 / Φ⁻¹(3/4) = 0.693147/0.674490 = 1.027662):

    >>> fit = fit_lognormal_fragility([0.2, 0.4, 0.8], [40, 40, 40], [10, 20, 30])
    >>> fit.status, round(fit.median_g, 6), round(fit.beta, 5)
    ('fitted', 0.4, 1.02766)
    >>> fit_lognormal_fragility([0.2, 0.4], [5, 5], [0, 0]).status
    'no_failures'
    """
    x_g, n, z = _check_stripes(im_g, n_trials, n_failures)
    totals = dict(n_stripes=int(np.unique(x_g).size), n_trials=int(n.sum()),
                  n_failures=int(z.sum()))
    refusal = _no_finite_fit(x_g, n, z)
    if refusal is not None:
        status, separation, message = refusal
        return _empty(status, message, separation, **totals)

    log_x = np.log(x_g)
    shift = float(np.average(log_x, weights=n))  # centring conditions the Newton matrix
    t = log_x - shift
    params, converged = _newton_probit(t, n, z)
    alpha, gamma = (float(v) for v in params)
    if not converged:
        return _empty(NOT_CONVERGED, "the likelihood maximisation did not converge.", **totals)
    if not gamma > 0.0:
        return _empty(DECREASING, "failures are not likelier at higher intensity: the "
                      "outcomes fit no fragility.", **totals)
    info = _observed_information(alpha, gamma, t, n, z)
    jac = np.array([[-1.0 / gamma, alpha / gamma**2], [0.0, -1.0 / gamma**2]])
    cov = jac @ np.linalg.inv(info) @ jac.T
    median_g = math.exp(shift - alpha / gamma)
    beta = float(1.0 / gamma)
    se_ln, se_beta = (float(math.sqrt(v)) for v in np.diag(cov))
    loglik = binomial_log_likelihood(x_g, n, z, median_g, beta)
    message = (f"median {median_g:.3g} g (standard error of ln θ {se_ln:.2g}), β {beta:.2f} "
               f"(± {se_beta:.2f}), from {totals['n_failures']} failures in "
               f"{totals['n_trials']} simulations over {totals['n_stripes']} intensities.")
    return FragilityFit(status=FITTED, median_g=median_g, beta=beta, se_ln_median=se_ln,
                        se_beta=se_beta, covariance=cov, log_likelihood=loglik,
                        separation_g=(math.nan, math.nan), message=message, **totals)


# --------------------------------------------------------------------------- helpers


def _check_stripes(im_g, n_trials, n_failures):
    x = np.atleast_1d(np.asarray(im_g, dtype=float))
    n = np.atleast_1d(np.asarray(n_trials))
    z = np.atleast_1d(np.asarray(n_failures))
    if not (x.ndim == 1 and x.shape == n.shape == z.shape and x.size):
        raise ValueError("im_g, n_trials and n_failures must be 1-D, of one non-zero length")
    if not (np.all(np.isfinite(x)) and np.all(x > 0.0)):
        raise ValueError("every intensity must be finite and > 0 g")
    if not (np.all(np.mod(n, 1) == 0) and np.all(np.mod(z, 1) == 0)):
        raise ValueError("n_trials and n_failures must be whole numbers")
    n = n.astype(np.int64)
    z = z.astype(np.int64)
    if np.any(n < 1) or np.any(z < 0) or np.any(z > n):
        raise ValueError("each stripe needs n_trials >= 1 and 0 <= n_failures <= n_trials")
    return x, n, z


def _no_finite_fit(x_g, n, z):
    """(status, separation_g, message) when the MLE does not exist, else None ([3])."""
    if z.sum() == 0:
        return (NO_FAILURES, (math.nan, math.nan),
                f"no failure in {n.sum()} simulations up to {x_g.max():.3g} g: the median lies "
                "above the highest intensity simulated; there is no finite fit.")
    if z.sum() == n.sum():
        return (ALL_FAILED, (math.nan, math.nan),
                f"every one of {n.sum()} simulations failed, down to {x_g.min():.3g} g: the "
                "median lies below the lowest intensity simulated; there is no finite fit.")
    if np.unique(x_g).size < 2:
        return (ONE_INTENSITY, (math.nan, math.nan),
                f"all simulations are at one intensity ({x_g[0]:.3g} g): the dispersion cannot "
                "be estimated; simulate at least two intensities.")
    survived_max = float(x_g[z < n].max())
    failed_min = float(x_g[z > 0].min())
    if survived_max <= failed_min:
        return (SEPARATED, (survived_max, failed_min),
                f"every simulation up to {survived_max:.3g} g survived and every one from "
                f"{failed_min:.3g} g failed: the median lies between and the data cannot "
                "estimate a dispersion (β → 0); simulate intensities between these two.")
    if float(x_g[z > 0].max()) <= float(x_g[z < n].min()):
        return (DECREASING, (math.nan, math.nan),
                "every failure is at a lower intensity than every survival: the outcomes fit "
                "no fragility.")
    return None


def _empty(status, message, separation=(math.nan, math.nan), **totals) -> FragilityFit:
    nan = math.nan
    return FragilityFit(status=status, median_g=nan, beta=nan, se_ln_median=nan, se_beta=nan,
                        covariance=np.full((2, 2), nan), log_likelihood=nan,
                        separation_g=tuple(separation), message=message, **totals)


def _probit_terms(alpha, gamma, t, n, z):
    """Log-likelihood (without the binomial coefficients), dl/dη and w = -d²l/dη² per stripe.

    With λ₁ = φ(η)/Φ(η) and λ₀ = φ(η)/Φ(-η) (inverse Mills ratios):
    dl/dη = zλ₁ - (n-z)λ₀ and -d²l/dη² = zλ₁(λ₁+η) + (n-z)λ₀(λ₀-η) > 0 ([2] §4.3).
    """
    eta = alpha + gamma * t
    log_cdf = special.log_ndtr(eta)
    log_sf = special.log_ndtr(-eta)
    log_pdf = -0.5 * eta * eta - 0.5 * math.log(2.0 * math.pi)
    lam1 = np.exp(log_pdf - log_cdf)
    lam0 = np.exp(log_pdf - log_sf)
    loglik = float(np.sum(z * log_cdf + (n - z) * log_sf))
    score = z * lam1 - (n - z) * lam0
    weight = z * lam1 * (lam1 + eta) + (n - z) * lam0 * (lam0 - eta)
    return loglik, score, weight


def _observed_information(alpha, gamma, t, n, z) -> np.ndarray:
    """Minus the Hessian of the log-likelihood in (α, γ): Σ w [1 t; t t²]."""
    _, _, w = _probit_terms(alpha, gamma, t, n, z)
    return np.array([[w.sum(), (w * t).sum()], [(w * t).sum(), (w * t * t).sum()]])


def _newton_probit(t, n, z):
    """Maximise the concave probit log-likelihood in (α, γ) by Newton with step halving."""
    spread = float(np.sqrt(np.average(t * t, weights=n))) or 1.0
    params = np.array([0.0, 1.0 / spread])  # θ at the weighted mean intensity, β = the spread
    loglik, score, weight = _probit_terms(*params, t, n, z)
    for _ in range(MAX_ITERATIONS):
        grad = np.array([score.sum(), (score * t).sum()])
        info = np.array([[weight.sum(), (weight * t).sum()],
                         [(weight * t).sum(), (weight * t * t).sum()]])
        try:
            step = np.linalg.solve(info, grad)
        except np.linalg.LinAlgError:
            return params, False
        scale = 1.0
        for _halving in range(60):
            trial = params + scale * step
            trial_loglik, trial_score, trial_weight = _probit_terms(*trial, t, n, z)
            if trial_loglik >= loglik - 1e-12 * abs(loglik):
                break
            scale *= 0.5
        else:
            return params, False
        done = np.all(np.abs(scale * step) <= STEP_TOL * (1.0 + np.abs(params)))
        params, loglik, score, weight = trial, trial_loglik, trial_score, trial_weight
        if done:
            return params, True
    return params, False
