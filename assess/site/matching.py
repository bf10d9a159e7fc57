"""Spectral matching: a motion's Fourier amplitudes scaled, pass after pass, until its 5 %-damped spectrum is the
target's over a period range, its phases kept (Gasparini & Vanmarcke 1976, SIMQKE), and the linear baseline
correction that brings it back to rest.

What the site's suites match with (:mod:`assess.site.suite`): a synthetic realisation, or a pair of recorded
components whose maximum-direction (RotD100) spectrum is matched, the same gain on both
(:func:`match_pair`, for records matched to the target rather than amplitude-scaled).
"""
from __future__ import annotations

from functools import lru_cache
from typing import Callable

import numpy as np

from assess.site.spectrum import pseudo_acceleration_spectrum, rotd_spectrum

#: Periods [s] of the checks (log-spaced over the range).
CHECK_POINTS = 100


def check_periods_s(lower_s, upper_s, points=CHECK_POINTS):
    """Log-spaced periods [s] from ``lower_s`` to ``upper_s`` where the suite is checked."""
    return np.geomspace(lower_s, upper_s, points)


def _end_velocity_displacement(accel, dt_s):
    """v(T) and d(T) of an acceleration from rest (trapezoidal integration)."""
    v = np.concatenate([[0.0], np.cumsum(0.5 * (accel[1:] + accel[:-1]) * dt_s)])
    d = np.concatenate([[0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * dt_s)])
    return v[-1], d[-1]


@lru_cache(maxsize=16)
def _baseline_matrix(samples, dt_s):
    """End velocity and displacement of a unit constant and a unit ramp (columns): the system of
    :func:`baseline_corrected`, the same for every motion of a length and step."""
    unit_v = _end_velocity_displacement(np.ones(samples), dt_s)
    unit_d = _end_velocity_displacement(np.arange(samples) * dt_s, dt_s)
    return np.array([[unit_v[0], unit_d[0]], [unit_v[1], unit_d[1]]])


def baseline_corrected(accel_g, dt_s):
    """Acceleration [g] less the line c0 + c1 t that brings end velocity and displacement to zero.

    With v(T) = ∫a dt and d(T) = ∫∫a (trapezoidal, from rest), c0 and c1 solve

    .. math:: c_0 T + c_1 T^2/2 = v(T), \\qquad c_0 T^2/2 + c_1 T^3/6 = d(T)

    (a linear baseline of the acceleration, the lowest-order correction of Boore 2001).

    >>> a = baseline_corrected(np.full(101, 0.01), 0.01)
    >>> v = np.concatenate([[0], np.cumsum(0.5 * (a[1:] + a[:-1]) * 0.01)])
    >>> abs(float(v[-1])) < 1e-12
    True
    """
    a = np.asarray(accel_g, dtype=float)
    t = np.arange(a.size) * dt_s
    v_end, d_end = _end_velocity_displacement(a, dt_s)
    c0, c1 = np.linalg.solve(_baseline_matrix(a.size, float(dt_s)), [v_end, d_end])
    return a - c0 - c1 * t


#: Periods of :func:`match_spectrum`'s band (log-spaced over 2.25 times the range's span in log period:
#: about 39 per decade for 0.07-2.8 s). Measured on 22 motions (level DE's seeds 0-21, SDS 1.0 g,
#: SD1 0.6 g, 0.07-2.8 s): 80 periods needed 176 realisations in all, 120 needed 59, 160 needed 53,
#: 200 56, 320 67 (a coarse band leaves narrow peaks between its periods for the dense check to find,
#: a fine one chases them pass after pass).
MATCH_POINTS = 160
#: The dense check of :func:`match_spectrum` looks at every ``_CHECK_SUBSET``-th period first.
_CHECK_SUBSET = 4


def _spectrum(components, dt_s, period_s, free_vibration_s=None):
    """5 %-damped Sa [g] of one component (free vibration after it as :func:`pseudo_acceleration_spectrum` takes
    ``free_vibration_s``), RotD100 of two (:func:`assess.site.spectrum.rotd_spectrum`, which lets the oscillator
    vibrate freely for its longest period after the motion)."""
    if len(components) == 1:
        return pseudo_acceleration_spectrum(components[0], dt_s, period_s, free_vibration_s=free_vibration_s)
    return rotd_spectrum(components[0], components[1], dt_s, period_s, percentile=(100.0,))[100.0]


def _largest_error(components, dt_s, period_s, target_g, free_vibration_s):
    """Largest |Sa/target − 1| over ``period_s`` (the exact spectrum; each period's Sa is the same
    number whichever other periods are computed with it, so a grid checked in parts gives its max)."""
    sa = _spectrum(components, dt_s, period_s, free_vibration_s=free_vibration_s)
    return float(np.max(np.abs(sa / target_g - 1.0)))


def match_spectrum(accel_g, dt_s, target: Callable, lower_s: float, upper_s: float, *,
                   tolerance: float = 0.05, max_iterations: int = 30, points: int = MATCH_POINTS,
                   check_points: int = 8 * CHECK_POINTS):
    """Acceleration [g] matched to ``target`` over [lower_s, upper_s] by iterative Fourier scaling.

    Each pass (Gasparini & Vanmarcke 1976, SIMQKE): Sa at ``points`` log-spaced periods from
    lower_s/1.5 to 1.5 upper_s (clipped to the target's domain), the ratio R = target/Sa,
    interpolated in log frequency at f = 1/T (held at its last value above the band, 1 below it:
    periods longer than the band are left as generated), multiplies the
    Fourier amplitudes (phases kept, mean removed); then :func:`baseline_corrected`. The
    largest |Sa/target − 1| is measured on ``check_points`` log-spaced periods over
    [lower_s, upper_s] (the exact Nigam-Jennings spectrum; only for a pass whose band is
    within ``tolerance``, and on every fourth of those periods first: a pass is ranked by the
    largest error found, the band's or the dense one's); the best pass is returned, early once
    the dense check is within ``tolerance``.

    Returns
    -------
    (ndarray, float)
        The matched acceleration [g] and its largest |Sa/target − 1| over the range.
    """
    (matched,), error = _match([accel_g], dt_s, target, lower_s, upper_s, tolerance=tolerance,
                               max_iterations=max_iterations, points=points, check_points=check_points)
    return matched, error


def match_pair(accel_1_g, accel_2_g, dt_s, target: Callable, lower_s: float, upper_s: float, *,
               tolerance: float = 0.05, max_iterations: int = 30, points: int = MATCH_POINTS,
               check_points: int = 8 * CHECK_POINTS):
    """Two horizontal components whose maximum-direction spectrum (RotD100) is matched to ``target``: as
    :func:`match_spectrum`, the pass's gain (target over the pair's RotD100) multiplying both components'
    Fourier amplitudes, so that their relative amplitude and phases, and so the motion's polarisation, are
    kept. The shorter component is taken as zero after its end, as a floor motion's pair is.

    Returns
    -------
    ((ndarray, ndarray), float)
        The matched components [g] and the pair's largest |RotD100/target − 1| over the range.
    """
    n = max(len(accel_1_g), len(accel_2_g))
    padded = [np.concatenate([np.asarray(a, dtype=float), np.zeros(n - len(a))]) for a in (accel_1_g, accel_2_g)]
    return _match(padded, dt_s, target, lower_s, upper_s, tolerance=tolerance, max_iterations=max_iterations,
                  points=points, check_points=check_points)


def _match(components, dt_s, target, lower_s, upper_s, *, tolerance, max_iterations, points, check_points):
    """:func:`match_spectrum` of one component, or of a pair's RotD100 (:func:`match_pair`): the matched
    components (a tuple) and the largest error."""
    max_period = getattr(target, "max_period_s", np.inf)
    band = np.geomspace(max(lower_s / 1.5, 2.0 * dt_s), min(upper_s * 1.5, max_period), points)
    goal = np.asarray(target(band), dtype=float)
    check = check_periods_s(lower_s, upper_s, check_points)
    check_goal = np.asarray(target(check), dtype=float)
    coarse = np.arange(check.size) % _CHECK_SUBSET == 0
    accel = tuple(np.asarray(a, dtype=float).copy() for a in components)
    n = accel[0].size
    frequency = np.fft.rfftfreq(n, dt_s)
    band_frequency = 1.0 / band[::-1]
    inside = (band >= lower_s * (1 - 1e-9)) & (band <= upper_s * (1 + 1e-9))
    best_error, best, best_checked = np.inf, accel, False
    for _ in range(max_iterations):
        sa = _spectrum(accel, dt_s, band)
        error = float(np.max(np.abs(sa[inside] / goal[inside] - 1.0)))
        checked = False
        # the dense check (it costs most) only when the band's own periods are within tolerance, first on
        # every SUBSET-th of its periods, then on the rest once those are within tolerance too; otherwise
        # the largest error found so far, close to a lower bound of the dense one, ranks the pass
        if error <= tolerance:
            error = max(error, _largest_error(accel, dt_s, check[coarse], check_goal[coarse], upper_s))
            if error <= tolerance:
                error = max(error, _largest_error(accel, dt_s, check[~coarse], check_goal[~coarse], upper_s))
                checked = True
        if error < best_error:
            best_error, best, best_checked = error, accel, checked
        if error <= tolerance:
            break
        gain = np.interp(np.log(np.maximum(frequency, 1e-12)), np.log(band_frequency), (goal / sa)[::-1])
        gain[frequency < band_frequency[0]] = 1.0  # below the band: left as it is, never pumped up pass after pass
        scaled = []
        for component in accel:
            spectrum = np.fft.rfft(component) * gain
            spectrum[0] = 0.0
            scaled.append(baseline_corrected(np.fft.irfft(spectrum, n), dt_s))
        accel = tuple(scaled)
    if not best_checked:  # never checked densely: say what the dense grid says
        best_error = _largest_error(best, dt_s, check, check_goal, upper_s)
    return best, best_error
