"""The multiple-stripe fragility fitter (assess/fragility/msa.py) against what it did not write.

* outcomes drawn from a known lognormal capacity: the parameters come back
  within their standard errors, and the standard errors match the spread of
  the estimates over many seeds (coverage of the 95 % Wald interval);
* the maximum and the standard errors against an independent optimiser and a
  finite-difference Hessian of the binomial likelihood written here with
  scipy.stats.binom;
* a closed form: a rigid block under a rectangular pulse (Newmark 1965) slides
  u = g·a·T²·(a − μ)/(2μ) (a, μ in g), so with the pulse duration T lognormal
  the probability of sliding past a clearance c at amplitude a is known
  exactly; the fitted fragility of outcomes simulated with the repository's
  sliding kernel must reproduce it;
* the cases without a finite fit say so.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import optimize, stats

from assess.fragility.msa import (
    ALL_FAILED, DECREASING, FITTED, NO_FAILURES, ONE_INTENSITY, SEPARATED,
    fit_lognormal_fragilities, fit_lognormal_fragility, stripes_from_outcomes,
)
from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2
from assess.mechanics.sliding import sliding_peaks_batch

THETA_G, BETA = 0.6, 0.45
#: Eight stripes of PFA [g], geometric from 0.2 to 1.5 g, as a stripe design spanning a hazard curve.
STRIPES_G = np.geomspace(0.2, 1.5, 8)


def _draw(rng, n_per_stripe, theta_g=THETA_G, beta=BETA, stripes_g=STRIPES_G):
    """Binary outcomes at the stripes: fail when the stripe exceeds a lognormal capacity."""
    im = np.repeat(stripes_g, n_per_stripe)
    capacity = theta_g * np.exp(beta * rng.standard_normal(im.size))
    return stripes_from_outcomes(im, im > capacity)


def _z_scores(fit, theta_g=THETA_G, beta=BETA):
    return ((math.log(fit.median_g) - math.log(theta_g)) / fit.se_ln_median,
            (fit.beta - beta) / fit.se_beta)


@pytest.mark.parametrize("n_per_stripe", [10, 25, 100])
def test_known_lognormal_recovered_within_standard_errors(n_per_stripe):
    z_all = []
    for seed in range(1, 7):
        fit = fit_lognormal_fragility(*_draw(np.random.default_rng(seed), n_per_stripe))
        assert fit.status == FITTED, fit.message
        z = _z_scores(fit)
        assert max(abs(v) for v in z) < 3.0, (seed, n_per_stripe, fit.median_g, fit.beta, z)
        z_all.extend(z)
    # ~95 % of the |z| of a correct fit fall below 2; 12 draws here
    assert np.mean(np.abs(z_all) < 2.0) >= 10 / 12, z_all


def test_standard_errors_match_the_spread_over_seeds():
    """400 replications, 8 stripes × 20: the Wald 95 % intervals cover the truth ~95 %
    of the time and the mean standard error matches the standard deviation of the
    estimates (the observed information is the right curvature)."""
    ln_theta, beta, se_ln, se_beta = [], [], [], []
    for seed in range(400):
        fit = fit_lognormal_fragility(*_draw(np.random.default_rng(1000 + seed), 20))
        assert fit.status == FITTED
        ln_theta.append(math.log(fit.median_g))
        beta.append(fit.beta)
        se_ln.append(fit.se_ln_median)
        se_beta.append(fit.se_beta)
    ln_theta, beta, se_ln, se_beta = map(np.array, (ln_theta, beta, se_ln, se_beta))
    cover_theta = np.mean(np.abs(ln_theta - math.log(THETA_G)) < 1.96 * se_ln)
    cover_beta = np.mean(np.abs(beta - BETA) < 1.96 * se_beta)
    print(f"coverage ln(theta) {cover_theta:.3f}, beta {cover_beta:.3f}; sd/mean se: ln(theta) "
          f"{np.std(ln_theta) / np.mean(se_ln):.3f}, beta {np.std(beta) / np.mean(se_beta):.3f}; "
          f"mean beta {np.mean(beta):.4f} (true {BETA})")
    # binomial sd of a 95 % coverage over 400 draws is 1.1 %
    assert 0.91 <= cover_theta <= 0.985, cover_theta
    assert 0.90 <= cover_beta <= 0.985, cover_beta
    assert np.std(ln_theta) / np.mean(se_ln) == pytest.approx(1.0, abs=0.12)
    assert np.std(beta) / np.mean(se_beta) == pytest.approx(1.0, abs=0.15)
    # and no visible bias in the median (the dispersion's MLE is biased low by O(1/n))
    assert abs(np.mean(ln_theta) - math.log(THETA_G)) < 3 * np.std(ln_theta) / math.sqrt(400)


def _neg_log_likelihood(params, im, n, z):
    """−Σ ln binom.pmf(z; n, Φ(ln(x/θ)/β)) in (ln θ, β), written here from Baker (2015)."""
    ln_theta, beta = params
    if beta <= 0.0:
        return np.inf
    p = stats.norm.cdf((np.log(im) - ln_theta) / beta)
    return -np.sum(stats.binom.logpmf(z, n, p))


def test_maximum_and_standard_errors_against_an_independent_computation():
    im, n, z = _draw(np.random.default_rng(7), 15)
    fit = fit_lognormal_fragility(im, n, z)
    best = optimize.minimize(_neg_log_likelihood, x0=[math.log(0.5), 0.3], args=(im, n, z),
                             method="Nelder-Mead",
                             options=dict(xatol=1e-10, fatol=1e-12, maxiter=20000))
    assert math.log(fit.median_g) == pytest.approx(best.x[0], abs=1e-6)
    assert fit.beta == pytest.approx(best.x[1], abs=1e-6)
    assert fit.log_likelihood == pytest.approx(-best.fun, abs=1e-9)
    # central-difference Hessian of the negative log-likelihood at the maximum
    x0, h = np.array([math.log(fit.median_g), fit.beta]), 1e-4
    hess = np.empty((2, 2))
    for i in range(2):
        for j in range(2):
            ei, ej = np.eye(2)[i] * h, np.eye(2)[j] * h
            hess[i, j] = (_neg_log_likelihood(x0 + ei + ej, im, n, z)
                          - _neg_log_likelihood(x0 + ei - ej, im, n, z)
                          - _neg_log_likelihood(x0 - ei + ej, im, n, z)
                          + _neg_log_likelihood(x0 - ei - ej, im, n, z)) / (4 * h * h)
    cov = np.linalg.inv(hess)
    np.testing.assert_allclose(fit.covariance, cov, rtol=1e-4)
    assert fit.se_median_g == pytest.approx(fit.median_g * math.sqrt(cov[0, 0]), rel=1e-4)


def test_many_fits_at_once_equal_the_fits_one_by_one():
    """Rows of different designs, padded with empty stripes, with statuses mixed: each row
    comes out as its own fit (the batch's rows do not share a step or a stopping test)."""
    rng = np.random.default_rng(11)
    rows = [_draw(rng, 12), _draw(rng, 40, theta_g=0.3, beta=0.7),
            _draw(rng, 6, stripes_g=np.geomspace(0.3, 0.9, 4)),
            (np.array([0.1, 0.2, 0.4]), np.array([5, 5, 5]), np.array([0, 0, 5])),  # separated
            (np.array([0.1, 0.2]), np.array([5, 5]), np.array([0, 0]))]  # no failure
    width = max(r[0].size for r in rows)

    def padded(values, fill):
        return np.array([np.concatenate([v, np.full(width - v.size, fill)]) for v in values])

    fits = fit_lognormal_fragilities(padded([r[0] for r in rows], 1.0),
                                     padded([r[1] for r in rows], 0),
                                     padded([r[2] for r in rows], 0))
    for fit, row in zip(fits, rows):
        alone = fit_lognormal_fragility(*row)
        assert fit.status == alone.status and fit.n_trials == alone.n_trials
        assert fit.n_stripes == alone.n_stripes
        if alone.fitted:
            assert fit.median_g == pytest.approx(alone.median_g, rel=1e-9)
            assert fit.beta == pytest.approx(alone.beta, rel=1e-9)
            np.testing.assert_allclose(fit.covariance, alone.covariance, rtol=1e-7)
            assert fit.log_likelihood == pytest.approx(alone.log_likelihood, rel=1e-12)
    assert [f.status for f in fits] == [FITTED, FITTED, FITTED, SEPARATED, NO_FAILURES]


# ----------------------------------------------------------- closed form: Newmark's rectangular pulse

MU = 0.2                 # kinetic = static friction [-]
CLEARANCE_M = 0.2        # [m]
PULSE_MEDIAN_S = 0.3     # median pulse duration [s]
PULSE_BETA = 0.5         # lognormal dispersion of the pulse duration [-]


def _threshold_g(duration_s):
    """Amplitude a* [g] at which the rectangular pulse slides the block exactly the clearance.

    u = g a T² (a − μ)/(2μ) = c  ⇔  a² − μa − 2μc/(gT²) = 0  ⇔
    a* = [μ + √(μ² + 8μc/(gT²))]/2 (Newmark 1965; Konstantinidis & Makris 2010 eq. 1).
    """
    t = np.asarray(duration_s, dtype=float)
    return 0.5 * (MU + np.sqrt(MU**2 + 8.0 * MU * CLEARANCE_M / (STANDARD_GRAVITY_M_S2 * t**2)))


def _exact_fragility(a_g):
    """P(u > c | a) with T lognormal: u grows with T, so it is P(T > T*(a)), T*² = 2μc/(g a(a−μ))."""
    a = np.asarray(a_g, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        t_star = np.sqrt(2.0 * MU * CLEARANCE_M / (STANDARD_GRAVITY_M_S2 * a * (a - MU)))
        p = stats.norm.cdf(np.log(PULSE_MEDIAN_S / t_star) / PULSE_BETA)
    return np.where(a > MU, p, 0.0)


def test_threshold_of_the_closed_form_is_what_the_kernel_computes():
    # the kernel slides exactly the clearance at a*: the derivation above is the kernel's physics
    durations = np.array([0.1, 0.3, 0.8])
    a_star = _threshold_g(durations)
    peak, _ = sliding_peaks_batch([[a, a] for a in a_star], durations, [MU])
    np.testing.assert_allclose(peak[0], CLEARANCE_M, rtol=1e-10)


def test_fitted_fragility_of_simulated_pulses_matches_the_closed_form():
    rng = np.random.default_rng(2015)
    stripes_g = np.geomspace(0.22, 1.2, 12)
    amplitude = np.repeat(stripes_g, 200)
    duration = PULSE_MEDIAN_S * np.exp(PULSE_BETA * rng.standard_normal(amplitude.size))
    records = np.column_stack([amplitude, amplitude])  # the rectangle [a, a] with dt = T
    peak, _ = sliding_peaks_batch(records, duration, [MU])
    failed = peak[0] > CLEARANCE_M
    assert np.array_equal(failed, amplitude > _threshold_g(duration))  # no tie at this seed

    fit = fit_lognormal_fragility(*stripes_from_outcomes(amplitude, failed))
    assert fit.status == FITTED
    # a* is not exactly lognormal (a(a − μ) ∝ T⁻² is), so the fit converges to the lognormal
    # closest to the exact curve at these stripes (the maximiser of the expected binomial
    # log-likelihood, White 1982), computed here with an independent optimiser
    exact = _exact_fragility(stripes_g)

    def expected_nll(params):
        ln_theta, beta = params
        if beta <= 0.0:
            return np.inf
        p = np.clip(stats.norm.cdf((np.log(stripes_g) - ln_theta) / beta), 1e-300, 1 - 1e-16)
        return -np.sum(200 * (exact * np.log(p) + (1.0 - exact) * np.log1p(-p)))

    best = optimize.minimize(expected_nll, x0=[math.log(0.4), 0.3], method="Nelder-Mead",
                             options=dict(xatol=1e-10, fatol=1e-12, maxiter=20000)).x
    assert abs(math.log(fit.median_g) - best[0]) < 2.0 * fit.se_ln_median, (fit.median_g,
                                                                              math.exp(best[0]))
    assert abs(fit.beta - best[1]) < 2.0 * fit.se_beta, (fit.beta, best[1], fit.se_beta)
    # and against the closed form itself: its median a*(median T) (a* is monotone in T) within
    # 5 % (the lognormal's misfit: 4.0 % for the closest lognormal here), its dispersion read
    # from the ±1σ quantiles a*(T_m e^∓β) within 0.03
    median_exact = float(_threshold_g(PULSE_MEDIAN_S))
    assert fit.median_g == pytest.approx(median_exact, rel=0.05)
    beta_equivalent = 0.5 * math.log(_threshold_g(PULSE_MEDIAN_S * math.exp(-PULSE_BETA))
                                     / _threshold_g(PULSE_MEDIAN_S * math.exp(PULSE_BETA)))
    assert fit.beta == pytest.approx(beta_equivalent, abs=0.03)
    # and the curve: the closest lognormal departs from the exact curve by at most 0.046 (near
    # the median, where the exact one is steeper); the fitted one by no more than 0.02 beyond
    grid = np.geomspace(0.22, 1.2, 200)
    gap_best = np.max(np.abs(stats.norm.cdf((np.log(grid) - best[0]) / best[1])
                             - _exact_fragility(grid)))
    gap = np.max(np.abs(fit.probability(grid) - _exact_fragility(grid)))
    assert gap_best < 0.05, gap_best
    assert gap < gap_best + 0.02, (gap, gap_best)
    print(f"closed form: median {median_exact:.4f} g, beta~{beta_equivalent:.4f}; closest "
          f"lognormal {math.exp(best[0]):.4f} g, {best[1]:.4f}; fit {fit.median_g:.4f} g "
          f"(se ln {fit.se_ln_median:.4f}), {fit.beta:.4f} (se {fit.se_beta:.4f}); max gap "
          f"{gap:.4f} (closest lognormal {gap_best:.4f})")


# ----------------------------------------------------------- no finite fit


def test_all_survived_or_all_failed_gives_no_numbers():
    for z, status in (([0, 0, 0], NO_FAILURES), ([5, 5, 5], ALL_FAILED)):
        fit = fit_lognormal_fragility([0.1, 0.2, 0.4], [5, 5, 5], z)
        assert fit.status == status and not fit.fitted
        assert math.isnan(fit.median_g) and math.isnan(fit.beta) and math.isnan(fit.se_beta)
        assert np.all(np.isnan(fit.probability([0.1, 1.0])))
        assert "no finite fit" in fit.message


def test_separated_outcomes_give_the_bracket_not_a_fit():
    fit = fit_lognormal_fragility([0.1, 0.2, 0.4, 0.8], [5, 5, 5, 5], [0, 0, 5, 5])
    assert fit.status == SEPARATED and fit.separation_g == (0.2, 0.4)
    assert math.isnan(fit.median_g)
    # quasi-separation (mixed outcomes only at the boundary stripe) has no finite fit either
    fit = fit_lognormal_fragility([0.1, 0.2, 0.4], [5, 5, 5], [0, 2, 5])
    assert fit.status == SEPARATED and fit.separation_g == (0.1, 0.4)  # none failed at 0.1 g, all at 0.4 g
    assert fit.message.startswith("every simulation up to 0.1 g survived, 2 of 5 failed at 0.2 g and every one "
                                  "from 0.4 g failed")
    # one overlap is enough for a fit
    assert fit_lognormal_fragility([0.1, 0.2, 0.4], [5, 5, 5], [1, 2, 5]).status == FITTED


def test_one_intensity_and_decreasing_outcomes():
    assert fit_lognormal_fragility([0.3, 0.3], [5, 5], [1, 3]).status == ONE_INTENSITY
    assert fit_lognormal_fragility([0.1, 0.2, 0.4], [5, 5, 5], [5, 3, 0]).status == DECREASING
    assert fit_lognormal_fragility([0.1, 0.2, 0.4], [9, 9, 9], [6, 4, 3]).status == DECREASING


@pytest.mark.parametrize("args", [
    ([0.1, -0.2], [5, 5], [1, 2]),      # negative intensity
    ([0.1, 0.2], [5, 5], [1, 6]),       # more failures than trials
    ([0.1, 0.2], [5, 5.5], [1, 2]),     # fractional trials
    ([0.1, 0.2], [5, 5], [1]),          # lengths differ
])
def test_bad_stripes_are_refused(args):
    with pytest.raises(ValueError):
        fit_lognormal_fragility(*args)
