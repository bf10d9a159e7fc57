"""Annual rate of failure: a lognormal fragility integrated over a hazard curve.

The mean annual rate at which an item fails (slides past its clearance,
overturns) is the fragility integrated over the hazard curve (the total
probability theorem of performance-based earthquake engineering; [1], [2]):

.. math::

    \\lambda_f = \\int_0^\\infty P(\\mathrm{fail} \\mid a)\\, |\\mathrm{d}\\lambda(a)|,
    \\qquad P(\\mathrm{fail} \\mid a) = \\Phi\\!\\left(\\frac{\\ln(a/\\theta)}{\\beta}\\right)

with :math:`\\lambda(a)` the annual rate at which the intensity exceeds
:math:`a`. The probability of at least one failure in ``t`` years follows
from Poisson occurrence, :math:`1 - e^{-\\lambda_f t}`.

The curve
---------
An OpenQuake curve gives probabilities of exceedance in its investigation time
at a list of PGA levels (:mod:`assess.hazard.openquake`); they become annual
rates by the Poisson relation of that module
(:func:`~assess.hazard.openquake.annual_rate_of_poe`). A USGS nshmp-haz curve
gives the annual rates themselves (:mod:`assess.hazard.usgs`), used as they
are (:func:`curve_annual_rates`). Levels with a
probability of 1 (an infinite rate) are left out at the bottom and levels with
a probability of 0 at the top: the curve used runs from the first level with a
finite rate to the last with a non-zero one.

Between two levels the curve is interpolated log–log, i.e. as a power law
:math:`\\lambda(a) = \\lambda_i (a/a_i)^{-k_i}` (as OpenQuake interpolates its
own curves). On such a segment the integral has a closed form (integration by
parts, then a Gaussian integral; :func:`segment_failure_rate`), so the integral
of the interpolated curve is exact, with no quadrature error.

The tails (a choice, reported)
------------------------------
``tails="extrapolate"`` (default) continues the first segment's power law down
to a = 0 and the last segment's up to a = ∞, where the closed form also holds;
``tails="truncate"`` integrates between the curve's first and last levels
only. Either way the result reports the three parts (below, within, above the
curve) so a caller can say how much rests on the extrapolation, and bounds
that need no extrapolation for the part above the curve: every event beyond
the last level :math:`a_N` fails with a probability between
:math:`P(\\mathrm{fail}\\mid a_N)` and 1 (or :math:`P(\\mathrm{fail}\\mid a_Z)`
when the file gives a zero probability at a higher level :math:`a_Z`), so that
part lies in :math:`[P(a_N)\\lambda_N,\\ \\lambda_N]`; the extrapolated value is
clipped into those bounds (a flat last segment, :math:`k = 0`, carries no
decay to extrapolate, and takes the upper bound). Below the first level no
such bound exists (the rate of small motions is unbounded).

Intensity measure
-----------------
The fragility must be in the curve's intensity measure. A fragility in the
floor's peak acceleration (PFA) on a PGA curve needs the floor's ratio
``pfa_per_pga`` (PFA = ratio · PGA), which divides the median:
:math:`\\theta_{PGA} = \\theta_{PFA}/\\text{ratio}`, β unchanged.

References
----------
.. [1] Cornell, C. A., Jalayer, F., Hamburger, R. O., Foutch, D. A. (2002).
   Probabilistic basis for 2000 SAC Federal Emergency Management Agency steel
   moment frame guidelines. J. Struct. Eng. 128(4):526-533.
   doi:10.1061/(ASCE)0733-9445(2002)128:4(526)
.. [2] Baker, J. W. (2015). Efficient analytical fragility function fitting
   using dynamic structural analysis. Earthquake Spectra 31(1):579-599
   (the fragility integrated with a hazard curve). doi:10.1193/021113EQS025M
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import special

from assess.hazard.openquake import OpenQuakeHazard, annual_rate_of_poe

EXTRAPOLATE = "extrapolate"
TRUNCATE = "truncate"
#: A tail holding more than this share of the rate gets a note: the curve does not cover the fragility.
TAIL_SHARE_NOTE = 0.01


@dataclass(frozen=True)
class FailureRate:
    """Annual rate of failure of one fragility over one hazard curve.

    Attributes
    ----------
    annual_rate : float
        λ_f [1/yr] with the chosen treatment of the tails.
    rate_below_curve, rate_within_curve, rate_above_curve : float
        The three parts [1/yr]: below the first level (0 when truncated),
        between the first and last levels (exact for the log–log interpolated
        curve), above the last level (0 when truncated).
    above_curve_bounds : tuple of float
        Lower and upper bound [1/yr] of the part above the last level that need
        no extrapolation (module docstring).
    tails : str
        ``"extrapolate"`` or ``"truncate"``.
    levels_g : tuple of float
        First and last level [g] of the curve used.
    notes : tuple of str
        Levels left out, tails holding more than 1 % of the rate.
    """

    annual_rate: float
    rate_below_curve: float
    rate_within_curve: float
    rate_above_curve: float
    above_curve_bounds: tuple[float, float]
    tails: str
    levels_g: tuple[float, float]
    notes: tuple[str, ...] = ()

    def probability_in(self, years: float) -> float:
        """Probability [-] of at least one failure in ``years`` (Poisson)."""
        return probability_in_years(self.annual_rate, years)

    @property
    def p50yr(self) -> float:
        """Probability [-] of at least one failure in 50 years."""
        return probability_in_years(self.annual_rate, 50.0)


def probability_in_years(annual_rate, years=50.0):
    """Probability of at least one occurrence in ``years`` of a Poisson rate [1/yr].

    .. math::  P = 1 - e^{-\\lambda t}

    >>> round(probability_in_years(1.0 / 2475.0, 50.0), 5)  # the 2 %-in-50-years level
    0.02
    """
    if np.ndim(annual_rate):
        return -np.expm1(-np.asarray(annual_rate, dtype=float) * years)
    return -math.expm1(-float(annual_rate) * years)


def cornell_failure_rate(k0, k, median_g, beta) -> float:
    """Closed-form λ_f [1/yr] of a lognormal fragility on a power-law hazard curve ([1]).

    With :math:`\\lambda(a) = k_0 a^{-k}` and :math:`P = \\Phi(\\ln(a/\\theta)/\\beta)`:

    .. math::  \\lambda_f = k_0\\,\\theta^{-k}\\,\\exp\\!\\left(\\tfrac12 k^2 \\beta^2\\right)

    i.e. the hazard at the median, amplified by the dispersion ([1], the
    closed form behind the SAC/FEMA confidence format).

    Parameters
    ----------
    k0 : float
        Rate [1/yr] of exceeding 1 g.
    k : float
        Slope of the curve in log–log [-], > 0.
    median_g, beta : float
        The fragility's θ [g] and β [-].

    >>> round(cornell_failure_rate(1e-4, 2.0, 0.5, 0.5), 8)  # 1e-4·4·e^0.5
    0.00065949
    """
    return float(k0 * median_g ** (-k) * math.exp(0.5 * k * k * beta * beta))


def annual_rates_of_curve(poes, investigation_time_yr):
    """Annual rates [1/yr] of probabilities of exceedance in ``investigation_time_yr`` (Poisson).

    Element-wise :func:`~assess.hazard.openquake.annual_rate_of_poe`; a
    probability of 1 gives an infinite rate.

    >>> annual_rates_of_curve([0.02, 0.1], 50.0).round(7).tolist()  # -ln(0.98)/50, -ln(0.9)/50
    [0.0004041, 0.0021072]
    """
    poes = np.asarray(poes, dtype=float)
    with np.errstate(divide="ignore"):
        return np.array([annual_rate_of_poe(p, investigation_time_yr) if p < 1.0 else np.inf
                         for p in poes.ravel()]).reshape(poes.shape)


def curve_annual_rates(hazard: OpenQuakeHazard) -> np.ndarray:
    """Annual rates of exceedance [1/yr] of a curve's levels at its chosen site.

    The file's own rates where it gives them (a USGS nshmp-haz curve), else its
    probabilities turned into rates (:func:`annual_rates_of_curve`): one
    meaning for both, so a curve gives the same rates whichever program wrote it.
    """
    if hazard.annual_rates is not None:
        return np.array(hazard.annual_rates[hazard.site_index], dtype=float)
    return annual_rates_of_curve(hazard.poes[hazard.site_index], hazard.investigation_time_yr)


def segment_failure_rate(level_lo_g, level_hi_g, anchor_level_g, anchor_rate, slope_k,
                         median_g, beta) -> float:
    """∫ Φ(ln(a/θ)/β) |dλ| over one power-law segment of a hazard curve [1/yr].

    On the segment, :math:`\\lambda(a) = c\\,a^{-k}`, the power law through
    (``anchor_level_g``, ``anchor_rate``): :math:`c = \\lambda_0 a_0^{k}`. With :math:`y = \\ln a`,
    :math:`m = \\ln\\theta`, :math:`z = (y - m)/\\beta`, integration by parts and the Gaussian integral
    :math:`\\int e^{-ky}\\varphi(z)\\,dy/\\beta = e^{-km + k^2\\beta^2/2}\\Phi(z + k\\beta)` give

    .. math::

        \\int_{y_1}^{y_2} \\Phi(z)\\, k c\\, e^{-ky} dy
        = c\\left[e^{-ky_1}\\Phi(z_1) - e^{-ky_2}\\Phi(z_2)\\right]
        + c\\, e^{-km + k^2\\beta^2/2}\\left[\\Phi(z_2 + k\\beta) - \\Phi(z_1 + k\\beta)\\right]

    ``level_lo_g`` may be 0 and ``level_hi_g`` infinite (the tails); over the
    whole line the sum is :func:`cornell_failure_rate`.

    >>> rate = segment_failure_rate(0.0, math.inf, 1.0, 1e-4, 2.0, 0.5, 0.5)
    >>> round(rate, 8)  # whole line, = cornell_failure_rate(1e-4, 2.0, 0.5, 0.5)
    0.00065949
    """
    if slope_k < 0.0:
        raise ValueError("a hazard curve's rate cannot grow with the level (k < 0)")
    if not level_hi_g > level_lo_g:
        return 0.0
    log_c = math.log(anchor_rate) + slope_k * math.log(anchor_level_g)
    m = math.log(median_g)

    def boundary(level_g):  # ln(c e^{-ky} Φ(z)) at a level, -inf where the term vanishes
        if level_g == 0.0:
            return -math.inf
        if math.isinf(level_g):
            return -math.inf if slope_k > 0.0 else 0.0  # flat: e^0·Φ(∞) = 1 (times c)
        y = math.log(level_g)
        return -slope_k * y + float(special.log_ndtr((y - m) / beta))

    z_lo = -math.inf if level_lo_g == 0.0 else (math.log(level_lo_g) - m) / beta
    z_hi = math.inf if math.isinf(level_hi_g) else (math.log(level_hi_g) - m) / beta
    shift = slope_k * beta
    first = math.exp(log_c + boundary(level_lo_g)) - math.exp(log_c + boundary(level_hi_g))
    exponent = log_c - slope_k * m + 0.5 * shift * shift
    if exponent < _LARGEST_EXPONENT:
        gauss = math.exp(exponent) * _phi_difference(z_lo + shift, z_hi + shift)
    else:  # a steep segment: e^{k²β²/2} overflows while the Φ difference underflows, so in logarithms
        log_difference = _log_phi_difference(z_lo + shift, z_hi + shift)
        gauss = 0.0 if log_difference == -math.inf else math.exp(exponent + log_difference)
    return max(first + gauss, 0.0)


def lognormal_failure_rate(levels_g, annual_rates, median_g, beta, tails=EXTRAPOLATE,
                           zero_level_g=None) -> FailureRate:
    """Annual rate of failure of a lognormal fragility over a hazard curve (λ_f, [1], [2]).

    Parameters
    ----------
    levels_g : array-like (n,)
        Intensity levels [g], increasing, > 0.
    annual_rates : array-like (n,)
        Annual rate of exceeding each level [1/yr], non-increasing; levels
        with an infinite rate at the bottom or a zero rate at the top are left
        out (``notes``).
    median_g, beta : float
        The fragility's θ [g] (in the curve's intensity measure) and β [-].
    tails : {"extrapolate", "truncate"}
        Treatment below the first and above the last level (module docstring).
    zero_level_g : float, optional
        A level above the curve where the hazard is known to be 0 (the first
        zero-probability level of an OpenQuake curve); tightens the upper
        bound of the part above the curve to P(fail | zero_level)·λ_N.

    Returns
    -------
    FailureRate

    Examples
    --------
    A power-law curve λ = 1e-4·a⁻² sampled at three levels: the closed form of
    :func:`cornell_failure_rate`, 1e-4·0.5⁻²·e^(0.5) = 6.5949e-4 per year.

    >>> a = np.array([0.1, 0.5, 2.0])
    >>> r = lognormal_failure_rate(a, 1e-4 * a**-2.0, 0.5, 0.5)
    >>> round(r.annual_rate, 8), round(r.p50yr, 5)
    (0.00065949, 0.03244)
    """
    if tails not in (EXTRAPOLATE, TRUNCATE):
        raise ValueError(f"tails must be '{EXTRAPOLATE}' or '{TRUNCATE}'")
    if not (median_g > 0.0 and beta > 0.0 and math.isfinite(median_g) and math.isfinite(beta)):
        raise ValueError("the fragility needs a finite median > 0 and beta > 0")
    levels, rates, notes, zero_level = _usable_curve(levels_g, annual_rates)
    if zero_level_g is not None:
        zero_level = zero_level_g if zero_level is None else min(zero_level, zero_level_g)
    slopes = -np.diff(np.log(rates)) / np.diff(np.log(levels))
    slopes = np.maximum(slopes, 0.0)  # equal rates rounded in the file: a flat segment

    within = sum(segment_failure_rate(levels[i], levels[i + 1], levels[i], rates[i], slopes[i],
                                      median_g, beta) for i in range(levels.size - 1))
    p_top = _fragility(levels[-1], median_g, beta)
    p_cap = 1.0 if zero_level is None else _fragility(zero_level, median_g, beta)
    bounds = (p_top * rates[-1], p_cap * rates[-1])
    below = above = 0.0
    if tails == EXTRAPOLATE:
        below = segment_failure_rate(0.0, levels[0], levels[0], rates[0], slopes[0], median_g,
                                     beta)
        if slopes[-1] > 0.0:
            above = segment_failure_rate(levels[-1], math.inf, levels[-1], rates[-1],
                                         slopes[-1], median_g, beta)
            above = min(max(above, bounds[0]), bounds[1])
        else:
            above = bounds[1]
            notes.append("the curve is flat at its last level: the rate above it is taken "
                         "as its upper bound.")
    total = below + within + above
    for name, part in (("below the curve's first level", below),
                       ("above the curve's last level", above)):
        if total > 0.0 and part > TAIL_SHARE_NOTE * total:
            notes.append(f"{part / total:.0%} of the rate lies {name} (extrapolated): the "
                         "curve does not cover the fragility; rerun the hazard with a wider "
                         "range of levels.")
    if tails == TRUNCATE and total > 0.0 and bounds[1] > TAIL_SHARE_NOTE * total:
        notes.append(f"up to {bounds[1] / total:.0%} more may come from above the curve's "
                     f"last level ({levels[-1]:g} g), which was not integrated.")
    return FailureRate(annual_rate=float(total), rate_below_curve=float(below),
                       rate_within_curve=float(within), rate_above_curve=float(above),
                       above_curve_bounds=(float(bounds[0]), float(bounds[1])), tails=tails,
                       levels_g=(float(levels[0]), float(levels[-1])), notes=tuple(notes))


def openquake_failure_rate(hazard: OpenQuakeHazard, median_g, beta, pfa_per_pga=1.0,
                           tails=EXTRAPOLATE) -> FailureRate:
    """λ_f over the PGA hazard curve of an OpenQuake or USGS nshmp-haz file, at its chosen site.

    Parameters
    ----------
    hazard : OpenQuakeHazard
        A curve read by :func:`~assess.hazard.usgs.read_hazard_curve_file`
        (not a map: a map has no curve to integrate); its annual rates are
        :func:`curve_annual_rates`.
    median_g, beta : float
        The fragility in the floor's peak acceleration: θ [g], β [-].
    pfa_per_pga : float
        The floor's ratio of peak floor to peak ground acceleration [-]; the
        median on PGA is θ / ratio (module docstring).
    tails : {"extrapolate", "truncate"}
    """
    if hazard.kind != "curve":
        raise ValueError("a hazard map has no curve to integrate: give the hazard curve")
    if not pfa_per_pga > 0.0:
        raise ValueError("pfa_per_pga must be > 0")
    rates = curve_annual_rates(hazard)
    return lognormal_failure_rate(hazard.levels_g, rates, median_g / pfa_per_pga, beta,
                                  tails=tails)


# --------------------------------------------------------------------------- helpers


def _fragility(level_g, median_g, beta) -> float:
    return float(special.ndtr(math.log(level_g / median_g) / beta))


def _phi_difference(lower, upper) -> float:
    """Φ(upper) - Φ(lower) without cancellation (by the survival function above 0)."""
    if lower >= 0.0:
        return float(special.ndtr(-lower) - special.ndtr(-upper))
    return float(special.ndtr(upper) - special.ndtr(lower))


#: Largest exponent whose exponential the risk integral takes directly (e^709 is the largest float's order).
_LARGEST_EXPONENT = 700.0


def _log_phi_difference(lower, upper) -> float:
    """ln(Φ(upper) - Φ(lower)) for lower <= upper, also where the difference underflows a float.

    By the tail on the side away from 0: ln Φ(b) + ln(1 - e^{ln Φ(a) - ln Φ(b)}) below 0,
    the same with the survival function above it.

    >>> round(_log_phi_difference(-1.0, 1.0), 6), round(_log_phi_difference(40.0, 41.0), 1)
    (-0.381715, -804.6)
    """
    if not upper > lower:
        return -math.inf
    if lower >= 0.0:  # both above 0: Q(lower) - Q(upper), Q = 1 - Φ = Φ(-x)
        high, low = float(special.log_ndtr(-lower)), float(special.log_ndtr(-upper))
    elif upper <= 0.0:
        high, low = float(special.log_ndtr(upper)), float(special.log_ndtr(lower))
    else:
        return math.log(_phi_difference(lower, upper))
    if high == -math.inf:
        return -math.inf
    return high + math.log1p(-math.exp(low - high)) if low < high else -math.inf


def _usable_curve(levels_g, annual_rates):
    """Levels with a finite, non-zero rate; the first zero-rate level above them (or None)."""
    levels = np.asarray(levels_g, dtype=float)
    rates = np.asarray(annual_rates, dtype=float)
    if levels.ndim != 1 or levels.shape != rates.shape:
        raise ValueError("levels_g and annual_rates must be 1-D, of one length")
    if not (np.all(np.isfinite(levels)) and np.all(levels > 0.0)
            and np.all(np.diff(levels) > 0.0)):
        raise ValueError("the levels must be finite, > 0 and increasing")
    if np.any(np.isnan(rates)) or np.any(rates < 0.0) or np.any(rates[1:] > rates[:-1]):
        raise ValueError("the annual rates must be >= 0 and non-increasing with the level")
    keep = np.isfinite(rates) & (rates > 0.0)
    notes = []
    if not keep.any() or keep.sum() < 2:
        raise ValueError("the curve needs at least two levels with a finite, non-zero rate")
    if not keep[0]:
        notes.append(f"{int(np.argmax(keep))} level(s) at the bottom have probability 1 (an "
                     "infinite rate) and were left out.")
    zero_level = None
    top = int(np.flatnonzero(keep)[-1])
    if top < levels.size - 1:
        zero_level = float(levels[top + 1])
        notes.append(f"{levels.size - 1 - top} level(s) from {zero_level:g} g at the top have "
                     "probability 0 and were left out.")
    return levels[keep], rates[keep], notes, zero_level
