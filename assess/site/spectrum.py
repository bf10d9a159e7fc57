"""Elastic response spectra of acceleration records.

The pseudo-acceleration :math:`S_a(T) = \\omega^2 \\max_t |u(t)|` of a linear
oscillator of period T and damping ratio ζ (5 % by default) under the ground
acceleration :math:`\\ddot u_g(t)`:

.. math:: \\ddot u + 2\\zeta\\omega\\dot u + \\omega^2 u = -\\ddot u_g(t), \\qquad \\omega = 2\\pi/T,

solved by the exact recursion of Nigam & Jennings [1]_ for a ground
acceleration linear between samples (:func:`nigam_jennings_coefficients`,
:func:`oscillator_displacements`), all periods at once.

Two horizontal components: :func:`rotd_spectrum` gives RotD50 (median over
rotation angles of the peak) and RotD100 (the maximum-direction spectrum) of
Boore [2]_; :func:`geometric_mean_spectrum` the older GMRotI-free geometric
mean of the two as-recorded spectra. ASCE 7-22 §16.2.3 compares a suite of
pairs with a maximum-direction target through each pair's RotD100, which is
what :mod:`assess.site.suite` uses for pairs.

References
----------
.. [1] Nigam, N. C., Jennings, P. C. (1969). Calculation of response spectra
   from strong-motion earthquake records. Bull. Seismol. Soc. Am. 59(2):909-922.
   (Coefficients as tabulated in Chopra, A. K., Dynamics of Structures, 4th ed.,
   Table 5.2.1.)
.. [2] Boore, D. M. (2010). Orientation-independent, nongeometric-mean measures
   of seismic intensity from two horizontal components of motion. Bull. Seismol.
   Soc. Am. 100(4):1830-1835. doi:10.1785/0120090400
"""
from __future__ import annotations

import numpy as np
from numba import njit

#: Damping ratio of design spectra (ASCE 7 §11.4, OpenQuake's SA).
DEFAULT_DAMPING = 0.05
#: Rotation angles [deg] of RotDnn: 0-179 in 1° steps (Boore 2010).
ROTATION_ANGLES_DEG = np.arange(180.0)
#: Periods stepped together by the compiled loop (11 arrays of this length fit a 32 kB first-level cache).
_PERIOD_BLOCK = 128


def nigam_jennings_coefficients(period_s, dt_s, damping=DEFAULT_DAMPING):
    """Coefficients of the exact step of a damped oscillator under a linear load.

    For :math:`\\ddot u + 2\\zeta\\omega\\dot u + \\omega^2 u = p(t)/m` with
    :math:`p` linear from :math:`p_i` to :math:`p_{i+1}` over a step Δt, the
    state after the step is ([1]_, Chopra Table 5.2.1, with k = mω² and
    :math:`\\omega_D = \\omega\\sqrt{1-\\zeta^2}`):

    .. math::

        u_{i+1} = A u_i + B \\dot u_i + C p_i + D p_{i+1}, \\qquad
        \\dot u_{i+1} = A' u_i + B' \\dot u_i + C' p_i + D' p_{i+1}.

    Parameters
    ----------
    period_s : array_like
        Oscillator periods [s], > 0.
    dt_s : float
        Step [s].
    damping : float or array_like
        Damping ratio ζ, 0 ≤ ζ < 1: one for all periods, or one per period (a building's modes).

    Returns
    -------
    ndarray, shape (8, periods)
        A, B, C, D, A', B', C', D' for unit mass (C..D' per unit p/m).

    Examples
    --------
    Undamped, Δt a quarter period: a unit displacement becomes velocity −ω
    (A = cos π/2 = 0, A' = −ω sin π/2):

    >>> c = nigam_jennings_coefficients([1.0], 0.25, 0.0)
    >>> round(float(c[0, 0]), 12), round(float(c[4, 0]), 6)
    (0.0, -6.283185)
    """
    period = np.atleast_1d(np.asarray(period_s, dtype=float))
    w = 2.0 * np.pi / period
    z = np.broadcast_to(np.asarray(damping, dtype=float), period.shape)
    root = np.sqrt(1.0 - z * z)
    wd = w * root
    e = np.exp(-z * w * dt_s)
    s, c = np.sin(wd * dt_s), np.cos(wd * dt_s)
    k = w * w  # unit mass
    a = e * (z / root * s + c)
    b = e * s / wd
    cc = (2.0 * z / (w * dt_s) + e * (((1.0 - 2.0 * z * z) / (wd * dt_s) - z / root) * s
                                       - (1.0 + 2.0 * z / (w * dt_s)) * c)) / k
    d = (1.0 - 2.0 * z / (w * dt_s) + e * ((2.0 * z * z - 1.0) / (wd * dt_s) * s + 2.0 * z / (w * dt_s) * c)) / k
    a1 = -e * w / root * s
    b1 = e * (c - z / root * s)
    c1 = (-1.0 / dt_s + e * ((w / root + z / (dt_s * root)) * s + c / dt_s)) / k
    d1 = (1.0 - e * (z / root * s + c)) / (k * dt_s)
    return np.array([a, b, cc, d, a1, b1, c1, d1])


@njit(cache=True)
def _peak_displacements(coefficients, load):
    """max_t |u| per period of the recursion, from rest (u = u̇ = 0 at the first sample).

    Time in the outer loop, periods in the inner one: the periods' recursions are independent,
    so the inner loop runs on the processor's vector lanes instead of waiting on one period's
    chain of dependent products. Each period's sums are evaluated in the same order as the
    one-period-at-a-time loop (no fused or reordered operations: Numba's default IEEE mode), so
    the peaks are the same numbers, bit for bit, on any processor and thread count.
    """
    n_periods = coefficients.shape[1]
    peaks = np.zeros(n_periods)
    for start in range(0, n_periods, _PERIOD_BLOCK):  # a block's state stays in the first-level cache
        stop = min(start + _PERIOD_BLOCK, n_periods)
        a, b, c, d = (coefficients[0, start:stop].copy(), coefficients[1, start:stop].copy(),
                      coefficients[2, start:stop].copy(), coefficients[3, start:stop].copy())
        a1, b1, c1, d1 = (coefficients[4, start:stop].copy(), coefficients[5, start:stop].copy(),
                          coefficients[6, start:stop].copy(), coefficients[7, start:stop].copy())
        m = stop - start
        u = np.zeros(m)
        v = np.zeros(m)
        peak = np.zeros(m)
        for i in range(load.size - 1):
            p0, p1 = load[i], load[i + 1]
            for j in range(m):
                uj, vj = u[j], v[j]
                un = a[j] * uj + b[j] * vj + c[j] * p0 + d[j] * p1
                v[j] = a1[j] * uj + b1[j] * vj + c1[j] * p0 + d1[j] * p1
                u[j] = un
                size = abs(un)
                peak[j] = size if size > peak[j] else peak[j]
        peaks[start:stop] = peak
    return peaks


@njit(cache=True)
def _displacements(coefficients, load):
    """u(t) per period (rows) of the recursion, from rest."""
    n_periods = coefficients.shape[1]
    out = np.zeros((n_periods, load.size))
    for j in range(n_periods):
        a, b, c, d, a1, b1, c1, d1 = coefficients[:, j]
        u, v = 0.0, 0.0
        for i in range(load.size - 1):
            u, v = (a * u + b * v + c * load[i] + d * load[i + 1],
                    a1 * u + b1 * v + c1 * load[i] + d1 * load[i + 1])
            out[j, i + 1] = u
    return out


def _load(accel_g, free_vibration_s, dt_s):
    """−üg [g] with zeros appended so the oscillator's free vibration after the record counts."""
    accel = np.asarray(accel_g, dtype=float)
    tail = int(np.ceil(free_vibration_s / dt_s)) if free_vibration_s > 0 else 0
    return np.concatenate([-accel, np.zeros(tail)])


def oscillator_displacements(accel_g, dt_s, period_s, damping=DEFAULT_DAMPING):
    """Relative displacement histories u(t) [g·s²] of oscillators under a ground acceleration.

    Exact for an acceleration linear between samples (:func:`nigam_jennings_coefficients`),
    from rest. Multiply by g [m/s²] for metres.

    Returns
    -------
    ndarray, shape (periods, samples)
    """
    coefficients = nigam_jennings_coefficients(period_s, dt_s, damping)
    return _displacements(np.ascontiguousarray(coefficients), _load(accel_g, 0.0, dt_s))


def pseudo_acceleration_spectrum(accel_g, dt_s, period_s, damping=DEFAULT_DAMPING,
                                 free_vibration_s=None):
    """Pseudo-spectral acceleration [g] of a record at each period.

    .. math:: S_a(T) = \\omega^2 \\max_t |u(t)|, \\qquad \\omega = 2\\pi / T,

    with u(t) the exact response of :func:`nigam_jennings_coefficients` [1]_
    from rest. A period of 0 gives the peak ground acceleration (the limit
    T → 0). The oscillator keeps vibrating after the record: by default the
    record is followed by zeros for max(T) (the free vibration's peak comes
    within a period).

    Parameters
    ----------
    accel_g : array_like
        Ground acceleration [g] at a constant step.
    dt_s : float
        Step [s].
    period_s : array_like
        Periods [s], ≥ 0.
    damping : float
        Damping ratio (default 0.05).
    free_vibration_s : float, optional
        Zeros appended [s]; default max(period_s).

    Returns
    -------
    ndarray
        Sa [g], one per period.

    Examples
    --------
    A sine of the oscillator's own period, 40 cycles, 5 % damping: the
    steady state reaches 1/(2ζ) = 10 times the input (within 1 %):

    >>> t = np.arange(0, 40.0, 0.01)
    >>> sa = pseudo_acceleration_spectrum(0.1 * np.sin(2 * np.pi * t), 0.01, [1.0])
    >>> round(float(sa[0]), 2)
    1.0
    """
    period = np.atleast_1d(np.asarray(period_s, dtype=float))
    if np.any(period < 0) or not np.all(np.isfinite(period)):
        raise ValueError("periods must be finite and >= 0")
    accel = np.asarray(accel_g, dtype=float)
    out = np.full(period.shape, float(np.max(np.abs(accel))) if accel.size else 0.0)
    positive = period > 0
    if np.any(positive):
        t = period[positive]
        tail = float(np.max(t)) if free_vibration_s is None else float(free_vibration_s)
        coefficients = np.ascontiguousarray(nigam_jennings_coefficients(t, dt_s, damping))
        peaks = _peak_displacements(coefficients, _load(accel, tail, dt_s))
        out[positive] = (2.0 * np.pi / t) ** 2 * peaks
    return out


def rotd_spectrum(accel_1_g, accel_2_g, dt_s, period_s, damping=DEFAULT_DAMPING,
                  percentile=(50.0, 100.0)):
    """RotDnn spectra [g] of two orthogonal horizontal components (Boore 2010 [2]_).

    The oscillator is linear, so its response to the motion along azimuth θ is
    :math:`u_\\theta(t) = u_1(t)\\cos\\theta + u_2(t)\\sin\\theta`; RotDnn is
    the nn-th percentile over θ ∈ [0°, 180°) (1° steps) of
    :math:`\\omega^2 \\max_t |u_\\theta(t)|`. RotD100 is the maximum-direction
    spectrum, :math:`\\omega^2 \\max_t \\sqrt{u_1^2 + u_2^2}` (computed so, not
    on the 1° grid); RotD50 the median.

    Returns
    -------
    dict
        ``{percentile: ndarray of Sa [g]}``.

    Examples
    --------
    The same record on both axes is a record along 45°, √2 times larger:

    >>> t = np.arange(0, 20.0, 0.01); a = 0.1 * np.sin(2 * np.pi * t / 0.5)
    >>> r = rotd_spectrum(a, a, 0.01, [1.0])
    >>> one = pseudo_acceleration_spectrum(a, 0.01, [1.0])
    >>> round(float(r[100.0][0] / one[0]), 4)
    1.4142
    """
    a1, a2 = _same_length(accel_1_g, accel_2_g)
    period = np.atleast_1d(np.asarray(period_s, dtype=float))
    result = {float(p): np.zeros(period.size) for p in percentile}
    angles = np.deg2rad(ROTATION_ANGLES_DEG)
    positive = period > 0
    tail = int(np.ceil(float(np.max(period)) / dt_s)) if period.size else 0
    a1p, a2p = np.concatenate([a1, np.zeros(tail)]), np.concatenate([a2, np.zeros(tail)])
    u1 = np.empty((period.size, a1p.size))
    u2 = np.empty((period.size, a1p.size))
    u1[~positive], u2[~positive] = a1p, a2p  # T = 0: the ground acceleration itself
    if np.any(positive):
        omega2 = (2.0 * np.pi / period[positive])[:, None] ** 2
        u1[positive] = omega2 * oscillator_displacements(a1p, dt_s, period[positive], damping)
        u2[positive] = omega2 * oscillator_displacements(a2p, dt_s, period[positive], damping)
    for j in range(period.size):
        for p in result:
            if p == 100.0:
                result[p][j] = float(np.max(np.hypot(u1[j], u2[j])))
            else:
                peaks = np.max(np.abs(np.cos(angles)[:, None] * u1[j] + np.sin(angles)[:, None] * u2[j]), axis=1)
                result[p][j] = float(np.percentile(peaks, p))
    return result


def _same_length(accel_1_g, accel_2_g):
    """The two components, the shorter padded with zeros (records of a pair may differ by a sample)."""
    a1 = np.asarray(accel_1_g, dtype=float)
    a2 = np.asarray(accel_2_g, dtype=float)
    n = max(a1.size, a2.size)
    return np.pad(a1, (0, n - a1.size)), np.pad(a2, (0, n - a2.size))


def geometric_mean_spectrum(accel_1_g, accel_2_g, dt_s, period_s, damping=DEFAULT_DAMPING):
    """Geometric mean [g] of the two as-recorded components' spectra, √(Sa₁ Sa₂).

    The measure of ASCE 7-10 §16.1.3.2's SRSS predecessors and of older GMPEs;
    kept for comparison: ASCE 7-22 uses maximum-direction spectra
    (:func:`rotd_spectrum`).

    >>> t = np.arange(0, 20.0, 0.01); a = 0.1 * np.sin(2 * np.pi * t / 0.5)
    >>> gm = geometric_mean_spectrum(a, 2 * a, 0.01, [1.0])
    >>> round(float(gm[0] / pseudo_acceleration_spectrum(a, 0.01, [1.0])[0]), 6)  # sqrt(2)
    1.414214
    """
    s1 = pseudo_acceleration_spectrum(accel_1_g, dt_s, period_s, damping)
    s2 = pseudo_acceleration_spectrum(accel_2_g, dt_s, period_s, damping)
    return np.sqrt(s1 * s2)
