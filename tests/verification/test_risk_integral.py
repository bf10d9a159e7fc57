"""Annual failure rate over a hazard curve (assess/hazard/risk_integral.py) against what it did not write.

* the closed form of Cornell et al. (2002): a lognormal fragility on a power-law
  curve λ(a) = k0·a^(−k) fails at λ_f = k0·θ^(−k)·exp(k²β²/2), to 1 %, on a
  curve sampled at OpenQuake's usual PGA levels and written as OpenQuake
  writes it (probabilities in 50 years, 7 significant digits);
* the exact per-segment integral against scipy's adaptive quadrature of the
  same log–log interpolated curve (a real OpenQuake curve, not a power law);
* real OpenQuake curves from tests/data/openquake: a step fragility returns the
  hazard at its median (read independently by pga_at_level), the tails are
  reported and bounded, and the rate behaves as a rate must.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy import integrate, stats

from assess.hazard.levels import HazardLevel
from assess.hazard.openquake import pga_at_level, read_openquake_hazard
from assess.hazard.risk_integral import (
    TRUNCATE, annual_rates_of_curve, cornell_failure_rate, lognormal_failure_rate,
    openquake_failure_rate, probability_in_years,
)

DATA = Path(__file__).resolve().parents[1] / "data" / "openquake"
CURVE_ONE_SITE = DATA / "case_23-hazard_curve-mean-PGA_953.csv"  # 1 site, 1 yr, 0.005-2.13 g
CURVE_50YR = DATA / "case_14-hazard_curve-rlz-000_PGA.csv"  # 10 sites, 50 yr, poe 0 at 0.284 g
CURVE_FLAT_FOOT = DATA / "case_13-hazard_curve-mean-PGA.csv"  # equal poes at its lowest levels

#: The PGA levels [g] of OpenQuake's demo jobs (intensity_measure_types_and_levels).
OQ_LEVELS_G = np.array([0.005, 0.007, 0.0098, 0.0137, 0.0192, 0.0269, 0.0376, 0.0527, 0.0738,
                        0.103, 0.145, 0.203, 0.284, 0.397, 0.556, 0.778, 1.09, 1.52, 2.13])


def _as_openquake_writes(rates, investigation_time_yr=50.0):
    """Annual rates -> poes in the investigation time, rounded as the engine writes them (%.6E)."""
    poes = -np.expm1(-np.asarray(rates) * investigation_time_yr)
    return np.array([float(f"{p:.6E}") for p in poes])


@pytest.mark.parametrize("k0, k, theta_g, beta", [
    (1e-4, 2.5, 0.6, 0.5),
    (4e-5, 3.0, 0.4, 0.6),
    (2e-4, 1.8, 0.9, 0.3),
    (1e-4, 2.0, 0.25, 0.45),
])
def test_power_law_curve_matches_cornell_closed_form(k0, k, theta_g, beta):
    rates = k0 * OQ_LEVELS_G ** (-k)
    poes = _as_openquake_writes(rates)
    result = lognormal_failure_rate(OQ_LEVELS_G, annual_rates_of_curve(poes, 50.0), theta_g, beta)
    exact = k0 * theta_g ** (-k) * math.exp(0.5 * k * k * beta * beta)  # Cornell et al. (2002)
    assert exact == pytest.approx(cornell_failure_rate(k0, k, theta_g, beta), rel=1e-12)
    assert result.annual_rate == pytest.approx(exact, rel=0.01)
    print(f"k0={k0:g} k={k:g} theta={theta_g:g} beta={beta:g}: lambda_f {result.annual_rate:.6e}"
          f" vs Cornell {exact:.6e} (rel {result.annual_rate / exact - 1:+.1e})")
    # from the exact rates (no 7-digit poes; with a 50-year window poes near 1 lose digits)
    unrounded = lognormal_failure_rate(OQ_LEVELS_G, rates, theta_g, beta)
    assert unrounded.annual_rate == pytest.approx(exact, rel=1e-9)
    assert result.p50yr == pytest.approx(1.0 - math.exp(-50.0 * exact), rel=0.01)
    # the part above the last level lies in its model-free bounds
    low, high = result.above_curve_bounds
    assert low <= result.rate_above_curve <= high


def test_truncation_is_reported_and_bounded():
    """θ = 0.6 g, β = 0.5 on k = 2.5: the curve's last level (2.13 g) leaves 1.9 % of λ_f above it."""
    k0, k, theta_g, beta = 1e-4, 2.5, 0.6, 0.5
    rates = k0 * OQ_LEVELS_G ** (-k)
    exact = cornell_failure_rate(k0, k, theta_g, beta)
    cut = lognormal_failure_rate(OQ_LEVELS_G, rates, theta_g, beta, tails=TRUNCATE)
    assert cut.rate_below_curve == 0.0 and cut.rate_above_curve == 0.0
    missing = exact - cut.annual_rate
    assert 0.01 < missing / exact < 0.03
    low, high = cut.above_curve_bounds  # what a caller can add without extrapolating
    assert low <= missing <= high + 1e-12 * exact
    assert any("not integrated" in note for note in cut.notes)
    # the above-curve part is ∫ Φ over λ beyond 2.13 g: ≈ λ(2.13)·P(2.13), P(2.13) = Φ(2.53)
    assert missing == pytest.approx(k0 * 2.13 ** -k * stats.norm.cdf(math.log(2.13 / 0.6) / 0.5),
                                    rel=0.01)


def _quadrature_rate(levels_g, rates, theta_g, beta):
    """∫ Φ(ln(a/θ)/β) |dλ/da| da of the log–log interpolated curve, by scipy.integrate.quad."""
    log_a, log_rate = np.log(levels_g), np.log(rates)
    total = 0.0
    for i in range(levels_g.size - 1):
        slope = -(log_rate[i + 1] - log_rate[i]) / (log_a[i + 1] - log_a[i])

        def integrand(y, i=i, slope=slope):  # in y = ln a: Φ · k · λ(y)
            rate = math.exp(log_rate[i] - slope * (y - log_a[i]))
            return stats.norm.cdf((y - math.log(theta_g)) / beta) * slope * rate

        total += integrate.quad(integrand, log_a[i], log_a[i + 1], epsabs=0.0, epsrel=1e-11)[0]
    return total


@pytest.mark.parametrize("theta_g, beta", [(0.05, 0.4), (0.3, 0.6), (1.5, 0.25)])
def test_exact_segments_against_quadrature_on_a_real_curve(theta_g, beta):
    hazard = read_openquake_hazard(CURVE_ONE_SITE)
    rates = annual_rates_of_curve(hazard.poes[0], hazard.investigation_time_yr)
    result = lognormal_failure_rate(hazard.levels_g, rates, theta_g, beta)
    assert result.rate_within_curve == pytest.approx(
        _quadrature_rate(hazard.levels_g, rates, theta_g, beta), rel=1e-8)


def test_step_fragility_returns_the_hazard_at_its_median():
    """β → 0: P(fail | a) is a step at θ and λ_f the curve's rate at θ. θ is the PGA that
    pga_at_level reads for 1 % in 50 years (rate −ln(0.99)/50 = 2.0101e-4 per year)."""
    hazard = read_openquake_hazard(CURVE_ONE_SITE)
    level = HazardLevel(0.01, 50.0)
    theta_g = pga_at_level(hazard, level)
    result = openquake_failure_rate(hazard, theta_g, 0.005)
    assert result.annual_rate == pytest.approx(level.annual_rate, rel=1e-3)
    assert result.p50yr == pytest.approx(0.01, rel=1e-3)
    # every event beyond the last level (2.13 g) exceeds θ: the part above is λ(2.13 g)
    assert result.rate_below_curve < 1e-15
    assert result.rate_above_curve == pytest.approx(-math.log1p(-hazard.poes[0][-1]), rel=1e-9)


def test_rate_on_a_real_curve_behaves_as_a_rate():
    hazard = read_openquake_hazard(CURVE_ONE_SITE)
    rates = annual_rates_of_curve(hazard.poes[0], 1.0)
    medians = [0.02, 0.05, 0.1, 0.2, 0.5, 1.0]
    lam = [openquake_failure_rate(hazard, m, 0.4).annual_rate for m in medians]
    assert all(a > b for a, b in zip(lam, lam[1:]))  # a stronger item fails less often
    assert lam[0] < rates[0]  # never more often than the smallest level is exceeded
    # the floor's amplification divides the median: PFA = 2·PGA, θ_PFA = 0.4 g ≡ θ_PGA = 0.2 g
    assert openquake_failure_rate(hazard, 0.4, 0.4, pfa_per_pga=2.0).annual_rate == \
        pytest.approx(lam[3], rel=1e-12)
    # a wider dispersion on a concave-down curve shifts the rate as Cornell's factor does:
    # up for a fragility above the curve's bulk
    assert openquake_failure_rate(hazard, 1.0, 0.6).annual_rate > lam[5]


def test_curve_with_zero_probabilities_at_the_top_is_bounded_by_them():
    """case_14 site 0 (50 yr): poe 0 at 0.284 g. Events beyond 0.203 g fail with at most
    P(fail | 0.284 g), so the part above the curve is at most that times λ(0.203 g)."""
    hazard = read_openquake_hazard(CURVE_50YR, site=0)
    result = openquake_failure_rate(hazard, 0.25, 0.3)
    rate_top = -math.log1p(-hazard.poes[0][-2]) / 50.0
    assert result.levels_g == (0.005, 0.203)
    assert result.above_curve_bounds[1] == pytest.approx(
        stats.norm.cdf(math.log(0.284 / 0.25) / 0.3) * rate_top, rel=1e-12)
    assert any("probability 0" in note for note in result.notes)
    assert any("above the curve's last level" in note for note in result.notes)


def test_flat_foot_of_a_curve_adds_nothing():
    """case_13 site 0 repeats one poe at its three lowest levels: no events between them."""
    hazard = read_openquake_hazard(CURVE_FLAT_FOOT, site=0)
    rates = annual_rates_of_curve(hazard.poes[0], 1.0)
    full = lognormal_failure_rate(hazard.levels_g, rates, 0.3, 0.5)
    without_foot = lognormal_failure_rate(hazard.levels_g[2:], rates[2:], 0.3, 0.5)
    assert full.annual_rate == pytest.approx(without_foot.annual_rate, rel=1e-12)


def test_probability_in_years_and_refusals():
    assert probability_in_years(0.0021072, 50.0) == pytest.approx(0.1, rel=1e-4)
    np.testing.assert_allclose(probability_in_years(np.array([0.0, 1e-3]), 50.0),
                               [0.0, 1.0 - math.exp(-0.05)])
    with pytest.raises(ValueError):
        lognormal_failure_rate([0.1, 0.2], [1e-3, 2e-3], 0.3, 0.5)  # rate grows
    with pytest.raises(ValueError):
        lognormal_failure_rate([0.1, 0.2], [1e-3, 1e-4], 0.3, 0.0)  # no dispersion
    with pytest.raises(ValueError):
        lognormal_failure_rate([0.1, 0.2], [1e-3, 1e-4], 0.3, 0.5, tails="clamp")
    with pytest.raises(ValueError):
        lognormal_failure_rate([0.1, 0.2], [1e-3, 0.0], 0.3, 0.5)  # one usable level
