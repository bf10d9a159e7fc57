"""An item's demand over its floor's suite of motions: the distribution, the probabilities, their intervals.

A hazard level gives each floor a *suite* of motions (records, or motions
described by PTA, Tp and vp). An item's demand at the level is a distribution
over that suite: every motion weighs the same, and a motion simulated under
several synthetic histories shares its weight among them. This module holds
the small statistics of such a distribution (weighted quantiles, the
lognormal mixture of the regression over a suite, exact binomial intervals
for probabilities estimated from few motions) and the test of where the
paper's regression may stand for a motion (:func:`regression_applies`).

Where the regression holds
--------------------------
The regression of Konstantinidis & Makris (2010) was fitted on 27
simulations under near-fault Loma Prieta motions, each described by a Type-B
pulse (Tp, vp) whose acceleration amplitude 2π|vp|/Tp is a large share of
the motion's PTA: 0.38 (Los Gatos at 0.60 g) to 0.78 (Corralitos) in Table 3.
Like the IM range, that share bounds the data the regression was fitted on:
its dimensional form makes the sliding scale with PTA·Tp², and for a motion
without a pulse the identified Tp is long and |vp| small, so the predicted
sliding grows with Tp² while the motion has no such pulse. Measured on
pyslammer's 18 records scaled to PGA 0.4 and 0.7 g with μ 0.1-0.3 (86 cases
that slide more than 5 mm; ``python benchmarks/estimators_vs_records.py``),
the regression's predicted over actual sliding has a geometric mean of 1.24,
σ(ln) 0.58 and 81 % of cases within a factor 2 where the pulse's share of
PTA is at least 0.38 (36 cases), against 19, σ(ln) 1.65 and 8 % below it
(50 cases). Hence :data:`PULSE_SHARE_MIN`, taken from the paper's data, not
from these records.

References
----------
.. [1] Konstantinidis, D., Makris, N. (2010). Bull. Earthquake Eng.
   8:1457-1477, Table 3 and section 6. doi:10.1007/s10518-010-9192-8
.. [2] Clopper, C. J., Pearson, E. S. (1934). The use of confidence or fiducial
   limits illustrated in the case of the binomial. Biometrika 26(4):404-413.
   doi:10.2307/2331986
"""
from __future__ import annotations

import numpy as np
from scipy import stats

from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2

#: Smallest share of PTA carried by the pulse (2π|vp|/(Tp·PTA·g)) among the paper's Table 3 motions.
PULSE_SHARE_MIN = 0.38
#: Confidence of the intervals on probabilities estimated from a suite.
INTERVAL_CONFIDENCE = 0.90


def pulse_acceleration_share(pta_g, tp_s, vp_m_s):
    """Share of the motion's PTA carried by its Type-B pulse: 2π|vp| / (Tp·PTA·g) [-].

    A Type-B pulse u̇ = vp sin(2πt/Tp) has the acceleration amplitude
    ap = 2π|vp|/Tp; the paper's Table 3 motions have ap/PTA from 0.42
    (Los Gatos) to 0.78 (Corralitos). NaN where vp is not known.

    >>> round(float(pulse_acceleration_share(0.54, 2.1, -0.75)), 3)  # Los Gatos, Table 3
    0.424
    """
    pta_g, tp_s, vp_m_s = (np.asarray(x, dtype=float) for x in (pta_g, tp_s, vp_m_s))
    return 2.0 * np.pi * np.abs(vp_m_s) / (tp_s * pta_g * STANDARD_GRAVITY_M_S2)


def regression_applies(pulse_share, im, im_min, im_max, uplift):
    """Where the paper's regression may govern a motion's sliding demand on an item.

    All of: the motion is a pulse that carries at least :data:`PULSE_SHARE_MIN`
    of its PTA, as the paper's motions do (a motion given by PTA and Tp alone *is* its pulse: pass a
    share of 1); IM lies inside the range the regression was fitted on; the
    item does not uplift (the regression describes pure sliding).

    >>> bool(regression_applies(0.42, 3.15, 1.71, 6.40, False)), bool(regression_applies(0.05, 3.15, 1.71, 6.40, False))
    (True, False)
    """
    pulse_share, im = np.asarray(pulse_share, dtype=float), np.asarray(im, dtype=float)
    return (pulse_share >= PULSE_SHARE_MIN) & (im >= im_min) & (im <= im_max) & ~np.asarray(uplift, dtype=bool)


def weighted_quantile(values, weights, quantile):
    """Quantile of a discrete distribution of ``values`` with ``weights`` (midpoint rule).

    Each value stands at the middle of its weight on the cumulative axis and
    the quantile function is linear between them (Hazen's rule for equal
    weights), flat beyond the ends.

    >>> weighted_quantile([1.0, 2.0, 3.0], [1, 1, 1], 0.5)
    2.0
    >>> weighted_quantile([1.0, 3.0], [1, 1], 0.5)
    2.0
    """
    values, weights = np.asarray(values, dtype=float), np.asarray(weights, dtype=float)
    order = np.argsort(values, kind="stable")
    values, weights = values[order], weights[order]
    cumulative = (np.cumsum(weights) - 0.5 * weights) / weights.sum()
    return float(np.interp(quantile, cumulative, values))


def effective_count(weights) -> float:
    """Kish's effective sample size (Σw)² / Σw² of weighted draws.

    >>> effective_count([1, 1, 1]), effective_count([0.5, 0.5, 1.0])
    (3.0, 2.6666666666666665)
    """
    weights = np.asarray(weights, dtype=float)
    return float(weights.sum() ** 2 / np.sum(weights * weights))


def binomial_interval(probability, count, confidence=INTERVAL_CONFIDENCE):
    """Exact (Clopper-Pearson) interval of a probability seen as a share of ``count`` draws [2]_.

    ``probability`` × ``count`` need not be whole (weighted draws: pass
    :func:`effective_count`); the beta quantiles take it as it is.

    >>> [round(x, 3) for x in binomial_interval(0.0, 3)]  # none of 3 motions: up to 63 %
    [0.0, 0.632]
    >>> [round(x, 3) for x in binomial_interval(1.0, 3)]
    [0.368, 1.0]
    """
    successes = float(probability) * float(count)
    tail = 0.5 * (1.0 - confidence)
    low = 0.0 if successes <= 0.0 else float(stats.beta.ppf(tail, successes, count - successes + 1.0))
    high = 1.0 if successes >= count else float(stats.beta.ppf(1.0 - tail, successes + 1.0, count - successes))
    return low, high


def quantile_interval(values, weights, quantile, count, confidence=INTERVAL_CONFIDENCE):
    """Distribution-free interval of a quantile estimated from ``count`` (effective) draws.

    Classical order-statistic interval (Conover 1999, §3.2): with n draws,
    the true q-quantile lies between the r-th and the s-th smallest with
    probability P(r ≤ Bin(n, q) < s), r and s taken from the binomial's
    tails. Weighted draws are read as n = ⌊count⌋ draws of their weighted
    distribution. Where n draws cannot bound the quantile on a side, that
    end is 0 (sliding is not negative) or infinity.

    >>> quantile_interval([1.0, 2.0, 3.0], [1, 1, 1], 0.5, 3)  # 3 motions cannot bound a median at 90 %
    (0.0, inf)
    >>> [round(x, 2) for x in quantile_interval(np.arange(1.0, 31.0), np.ones(30), 0.5, 30)]
    [11.0, 20.0]
    """
    n = max(int(np.floor(count + 1e-9)), 1)
    tail = 0.5 * (1.0 - confidence)
    r = int(stats.binom.ppf(tail, n, quantile))
    s = int(stats.binom.ppf(1.0 - tail, n, quantile)) + 1
    values, weights = np.asarray(values, dtype=float), np.asarray(weights, dtype=float)
    order = np.argsort(values, kind="stable")
    values, cumulative = values[order], np.cumsum(weights[order]) / weights.sum()

    def order_statistic(k):
        return float(values[min(int(np.searchsorted(cumulative, k / n - 1e-12)), values.size - 1)])

    low = order_statistic(r) if r >= 1 else 0.0
    high = order_statistic(s) if s <= n else float("inf")
    return low, high
