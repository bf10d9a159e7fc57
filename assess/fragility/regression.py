"""Sliding demand and fragility from the regression of Konstantinidis & Makris (2010).

Dimensional analysis of a block sliding under a pulse of amplitude ap and
period Tp reduces Umax = f(ap, ωp, μg) to two Π-groups ([1], eqs. 2-6). The
paper takes

.. math::

    IM = \\frac{PTA}{\\mu g} - 1 \\quad (7), \\qquad
    \\Pi = \\frac{U_{max}\\,\\omega_p^2}{PTA} \\quad (8), \\qquad
    \\Pi = \\zeta\\, IM^{\\eta} Z \\quad (9)

with :math:`\\ln Z \\sim N(0, \\sigma_X^2)`, fits ζ, η by ordinary least squares
on :math:`\\ln\\Pi = \\ln\\zeta + \\eta \\ln IM` (10), σ_X by eq. (15), and gets
the fragility

.. math::  P_f = P(\\Pi > c \\mid IM) = 1 - \\Phi\\left(\\frac{1}{\\sigma_X}
           \\ln\\frac{c}{\\zeta IM^{\\eta}}\\right) \\quad (20)

with ζ = 0.370, η = 0.953, σ_X = 0.445 (21). A clearance (room to slide)
``clearance_m`` becomes the capacity :math:`c = \\text{clearance}\\,\\omega_p^2/PTA`.

References
----------
.. [1] Konstantinidis, D., Makris, N. (2010). Bull. Earthquake Eng.
   8:1457-1477, section 6, Table 3 (p. 1467). doi:10.1007/s10518-010-9192-8
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd
from scipy import stats

from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2
from assess.inventory.settings import Settings


@dataclass(frozen=True)
class RegressionConstants:
    """ζ, η, σ_X of eq. (9) and the IM range they were fitted on."""

    zeta: float
    eta: float
    sigma: float
    im_min: float
    im_max: float

    @classmethod
    def from_settings(cls, settings: Settings) -> "RegressionConstants":
        """Constants from merged settings (defaults: the paper's eq. 21, Table 3)."""
        return cls(settings.zeta, settings.eta, settings.sigma, settings.im_min, settings.im_max)


@dataclass(frozen=True)
class RegressionFit:
    """Result of :func:`fit_regression`."""

    zeta: float
    eta: float
    sigma: float  # eq. (15), n - 1 in the denominator
    ks_distance: float  # eq. (18), S
    n: int
    im_min: float
    im_max: float

    def constants(self) -> RegressionConstants:
        return RegressionConstants(self.zeta, self.eta, self.sigma, self.im_min, self.im_max)


def pulse_frequency(tp_s):
    """Circular frequency of the pulse ωp = 2π/Tp [rad/s].

    >>> round(float(pulse_frequency(2.0)), 6)
    3.141593
    """
    return 2.0 * np.pi / np.asarray(tp_s, dtype=float)


def intensity_measure(pta_g, mu):
    """IM = PTA/(μg) − 1 [-], eq. (7) of [1].

    Parameters
    ----------
    pta_g : peak table (floor) acceleration [g]
    mu : kinetic friction coefficient [-]

    Examples
    --------
    Table 3 of [1], FORMA, μ = 0.13, Corralitos at PTA = 0.83 g: IM = 5.38.

    >>> round(float(intensity_measure(0.83, 0.13)), 2)
    5.38
    """
    return np.asarray(pta_g, dtype=float) / np.asarray(mu, dtype=float) - 1.0


def engineering_demand(sliding_max_m, pta_g, tp_s):
    """Π = Umax ωp² / PTA [-], eq. (8) of [1].

    Examples
    --------
    Table 3 of [1], FORMA, Los Gatos PC at 0.54 g, Tp = 2.10 s, Umax = 45.6 cm:
    Π = 0.77.

    >>> round(float(engineering_demand(0.456, 0.54, 2.10)), 2)
    0.77
    """
    pta_m_s2 = np.asarray(pta_g, dtype=float) * STANDARD_GRAVITY_M_S2
    return np.asarray(sliding_max_m, dtype=float) * pulse_frequency(tp_s) ** 2 / pta_m_s2


def sliding_from_edp(edp, pta_g, tp_s):
    """Umax [m] from Π, the inverse of eq. (8): Umax = Π·PTA/ωp²."""
    pta_m_s2 = np.asarray(pta_g, dtype=float) * STANDARD_GRAVITY_M_S2
    return np.asarray(edp, dtype=float) * pta_m_s2 / pulse_frequency(tp_s) ** 2


def median_edp(im, zeta, eta):
    """Median Π = ζ IM^η [-], eq. (11) of [1]; 0 where IM ≤ 0 (no sliding).

    >>> round(float(median_edp(3.0, 0.370, 0.953)), 4)
    1.0541
    """
    im = np.asarray(im, dtype=float)
    positive = np.where(im > 0, im, 1.0)
    return np.where(im > 0, zeta * positive**eta, 0.0)


def sliding_quantile(im, pta_g, tp_s, constants: RegressionConstants, quantile=0.5):
    """Quantile of peak sliding Umax [m] given IM, from the lognormal Π.

    .. math:: U_q = \\zeta IM^{\\eta} e^{\\sigma_X \\Phi^{-1}(q)} \\, PTA/\\omega_p^2

    ``quantile=0.5`` is the median, 0.84 (≈ Φ(1)) the 84th percentile. Zero
    where IM ≤ 0.
    """
    factor = np.exp(constants.sigma * stats.norm.ppf(quantile))
    edp = median_edp(im, constants.zeta, constants.eta) * factor
    return sliding_from_edp(edp, pta_g, tp_s)


def capacity_edp(clearance_m, pta_g, tp_s):
    """Capacity c = clearance·ωp²/PTA [-]: the clearance as a value of Π ([1], eq. 19)."""
    return engineering_demand(clearance_m, pta_g, tp_s)


def probability_of_exceedance(im, capacity, zeta, eta, sigma):
    """P(Π > c | IM) = 1 − Φ(ln(c/(ζ IM^η))/σ_X), eq. (20) of [1].

    IM ≤ 0 means the block does not slide: P = 0. A capacity of zero
    (no room at all) with IM > 0 gives P = 1. NaN in gives NaN out.

    Parameters
    ----------
    im : float, array-like or Series
        Intensity measure PTA/(μg) − 1 [-].
    capacity : float, array-like or Series
        Capacity c = clearance·ωp²/PTA [-], broadcast against ``im``.
    zeta, eta, sigma : float
        Regression constants ζ, η, σ_X [-].

    Returns
    -------
    float, ndarray or Series (the kind of ``im``; a float when both inputs are scalars)

    Examples
    --------
    ζ IM^η = 0.370 · 3^0.953 = 1.0541; ln(0.4/1.0541)/0.445 = −2.1776;
    1 − Φ(−2.1776) = 0.9853:

    >>> round(probability_of_exceedance(3.0, 0.4, 0.370, 0.953, 0.445), 4)
    0.9853
    """
    im_b, capacity_b = np.broadcast_arrays(np.asarray(im, dtype=float), np.asarray(capacity, dtype=float))
    median = median_edp(im_b, zeta, eta)
    with np.errstate(divide="ignore", invalid="ignore"):
        z = np.log(capacity_b / np.where(median > 0, median, 1.0)) / sigma
    probability = np.where(im_b > 0, stats.norm.sf(z), 0.0)  # sf: accurate in the upper tail
    probability = np.where(np.isnan(im_b) | np.isnan(capacity_b), np.nan, probability)
    if isinstance(im, pd.Series):
        return pd.Series(probability, index=im.index, name="pf_sliding")
    if probability.ndim == 0:
        return float(probability)
    return probability


def ks_distance(standardised_residuals):
    """Kolmogorov-Smirnov distance S between the sample and N(0, 1), eq. (18) of [1].

    Two-sided: the largest gap between the empirical CDF (steps at i/n and
    (i−1)/n) and Φ.
    """
    return float(stats.kstest(np.asarray(standardised_residuals, dtype=float), "norm").statistic)


def fit_regression(im, edp) -> RegressionFit:
    """Fit Π = ζ IM^η Z to (IM, Π) pairs, as section 6.2 of [1] does.

    Ordinary least squares on :math:`\\ln\\Pi = \\ln\\zeta + \\eta\\ln IM` (eq. 10),
    :math:`\\sigma_X = \\sqrt{\\sum(\\ln(\\Pi_i/(\\zeta IM_i^\\eta)))^2/(n-1)}`
    (eq. 15) and the KS distance of the standardised residuals (eq. 18).
    Pairs with IM ≤ 0 or Π ≤ 0 (no sliding) cannot enter a log-log fit and
    must be removed by the caller; they raise ``ValueError`` here.
    """
    im = np.asarray(im, dtype=float)
    edp = np.asarray(edp, dtype=float)
    if im.shape != edp.shape or im.size < 3:
        raise ValueError("fit_regression needs at least 3 (IM, EDP) pairs of equal length")
    if np.any(im <= 0) or np.any(edp <= 0):
        raise ValueError("fit_regression needs IM > 0 and EDP > 0 (sliding cases only)")
    log_im, log_edp = np.log(im), np.log(edp)
    slope, intercept = np.polyfit(log_im, log_edp, 1)
    residuals = log_edp - (intercept + slope * log_im)
    sigma = float(np.sqrt(np.sum(residuals**2) / (im.size - 1)))
    return RegressionFit(
        zeta=float(np.exp(intercept)), eta=float(slope), sigma=sigma,
        ks_distance=ks_distance(residuals / sigma), n=int(im.size),
        im_min=float(im.min()), im_max=float(im.max()),
    )
