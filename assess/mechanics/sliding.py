"""Two-way sliding of a rigid block on a floor with Coulomb friction (no rocking).

The block's displacement u relative to the floor, under a floor acceleration
:math:`a_g(t)` given in g, obeys ([1] §3.1; [2], [3]):

.. math::

    \\ddot u = -a_g(t)\\,g - \\mu g \\,\\mathrm{sign}(\\dot u)
    \\quad\\text{while sliding,}\\qquad
    \\dot u = 0 \\quad\\text{while stuck.}

A stuck block starts to slide when :math:`|a_g| > \\mu_s` (static coefficient,
:math:`\\mu_s \\ge \\mu`), in the direction :math:`-\\mathrm{sign}(a_g)`; a sliding
block stops when :math:`\\dot u` returns to zero, and sticks there if
:math:`|a_g| \\le \\mu_s`, or else slides back the other way.

The record is sampled at a constant step dt and taken **piecewise linear**
between samples. Within a step in which the block slides one way the relative
acceleration is linear in t, so the velocity is a quadratic and the displacement
a cubic: the kernel finds in closed form the instant at which :math:`\\dot u`
returns to zero (root of the quadratic inside the step) and the instant at
which :math:`|a_g|` crosses :math:`\\mu_s` (root of a linear function), stops
there, applies the stick/slip test and carries on. The result is exact for the
piecewise-linear input up to round-off; there is no time-step error.

Two conventions at the ends of the record make it an exact statement about a
finite motion:

* before the first sample the block rests on a floor at rest; the record starts
  with ``floor_accel_g[0]``, so a first sample above μs is a step at t = 0 (a
  rectangular pulse needs no ramp);
* after the last sample the floor is at rest (a_g = 0): a block still sliding
  then runs out, decelerating at μg, by :math:`\\dot u|\\dot u|/(2\\mu g)` over
  :math:`|\\dot u|/(\\mu g)`. Peaks, residual and slide time include this run-out.

Together these make a rectangular pulse of amplitude ap and duration Tp exactly
the record ``[ap, ap]`` with ``dt = Tp`` (Newmark 1965; [1] eq. 1 and 6).

Similitude: u scales with :math:`a\\,T^2`; a record compressed in time by 2 with
the same accelerations (the 1/4-scale shake-table motions of [1]) gives exactly
1/4 of the sliding.

References
----------
.. [1] Konstantinidis, D., Makris, N. (2010). Experimental and analytical
   studies on the response of 1/4-scale models of freestanding laboratory
   equipment subjected to strong earthquake shaking. Bull. Earthquake Eng.
   8:1457-1477, §3.1, eq. 1, eq. 4-6, Fig. 3. doi:10.1007/s10518-010-9192-8
.. [2] Newmark, N. M. (1965). Effects of earthquakes on dams and embankments.
   Géotechnique 15(2):139-160. doi:10.1680/geot.1965.15.2.139
.. [3] Younis, C. J., Tadjbakhsh, I. G. (1984). Response of sliding rigid
   structure to base excitation. J. Eng. Mech. 110(3):417-432.
   doi:10.1061/(ASCE)0733-9399(1984)110:3(417)
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

import numpy as np
from numba import njit

from assess.mechanics.case_records import checked_record
from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2
from assess.mechanics.stick_slip import COULOMB, stick_slip_record
from assess.mechanics.threads import run_case_ranges

@dataclass(frozen=True)
class SlidingResult:
    """Response of a sliding block to one floor motion.

    Attributes
    ----------
    sliding_max_m : float
        Peak relative displacement :math:`\\max_t |u|` [m] (Umax of [1]).
    sliding_residual_m : float
        Relative displacement where the block comes to rest after the record [m] (signed).
    sliding_max_positive_m, sliding_max_negative_m : float
        Peak slip in the positive and in the negative direction, as magnitudes [m]:
        :math:`\\max(0, \\max_t u)` and :math:`\\max(0, -\\min_t u)`.
    slide_time_s : float
        Total time the block spends sliding, run-out included [s].
    time_s, sliding_m, sliding_velocity_m_s : ndarray or None
        With ``return_history=True``: sample times [s], u [m] and u̇ [m/s] at the
        samples of the record (the run-out after the last sample is not sampled).
    """

    sliding_max_m: float
    sliding_residual_m: float
    sliding_max_positive_m: float
    sliding_max_negative_m: float
    slide_time_s: float
    time_s: Optional[np.ndarray] = None
    sliding_m: Optional[np.ndarray] = None
    sliding_velocity_m_s: Optional[np.ndarray] = None


@njit(cache=True)
def _slide_record(accel_g, n, dt, mu_k, mu_s, gravity, keep_history, u_out, v_out):
    """Exact event-driven integration over the first ``n`` samples of ``accel_g``
    (:func:`~assess.mechanics.stick_slip.stick_slip_record` under Coulomb friction), then the run-out.

    Returns (peak positive u, peak negative u as magnitude, residual u, slide time).
    If ``keep_history``, writes u and u̇ at the samples into ``u_out``, ``v_out``.
    """
    u, v, _, s, u_hi, u_lo, slide_time = stick_slip_record(accel_g, n, dt, COULOMB, mu_s,
                                                           (mu_k, gravity, 0.0, 0.0, 0.0, 0.0), keep_history,
                                                           u_out, v_out)
    if s != 0 and v != 0.0:  # run-out on a floor at rest after the record
        u += v * abs(v) / (2.0 * mu_k * gravity)
        slide_time += abs(v) / (mu_k * gravity)
        if u > u_hi:
            u_hi = u
        if u < u_lo:
            u_lo = u
    return u_hi, 0.0 - u_lo, u, slide_time


@njit(cache=True)
def _peaks_of_block(accel_2d, lengths, dt, mu_k, mu_s, gravity, peak, residual, i):
    dummy = np.empty(0)
    for r in range(accel_2d.shape[0]):
        hi, lo, res, _t = _slide_record(accel_2d[r], lengths[r], dt[r], mu_k[i], mu_s[i],
                                        gravity, False, dummy, dummy)
        peak[i, r] = max(hi, lo)
        residual[i, r] = res


@njit(cache=True, nogil=True)
def _peaks_of_blocks(start, stop, accel_2d, lengths, dt, mu_k, mu_s, gravity, peak, residual):
    """Blocks start to stop − 1 under every record (:func:`assess.mechanics.threads.run_case_ranges`)."""
    for i in range(start, stop):
        _peaks_of_block(accel_2d, lengths, dt, mu_k, mu_s, gravity, peak, residual, i)


def _check_friction(mu, mu_static):
    mu = np.asarray(mu, dtype=float)
    mu_static = mu if mu_static is None else np.asarray(mu_static, dtype=float)
    if not (np.all(np.isfinite(mu)) and np.all(mu > 0.0)):
        raise ValueError("mu must be finite and > 0 (a block on a frictionless floor never stops)")
    if mu_static.shape != mu.shape and mu_static.ndim and mu.ndim:
        raise ValueError("mu_static must have the shape of mu")
    if not (np.all(np.isfinite(mu_static)) and np.all(mu_static >= mu)):
        raise ValueError("mu_static must be finite and >= mu (kinetic)")
    return mu, np.broadcast_to(mu_static, mu.shape).astype(float)


def sliding_response(floor_accel_g, dt_s, mu, mu_static=None, return_history=False) -> SlidingResult:
    """Two-way sliding of a rigid block under a floor motion, exact for piecewise-linear input.

    .. math::

        \\ddot u = -a_g(t)\\,g - \\mu g\\,\\mathrm{sign}(\\dot u) \\;\\text{(sliding)},
        \\qquad \\text{stick while } \\dot u = 0,\\ |a_g| \\le \\mu_s

    ([1] §3.1; see the module docstring for the event-driven solution and the
    conventions at both ends of the record).

    Parameters
    ----------
    floor_accel_g : array-like, shape (n,)
        Floor acceleration [g] at t = 0, dt, ..., (n-1)dt; linear between samples.
    dt_s : float
        Sampling step [s].
    mu : float
        Kinetic friction coefficient μ [-], > 0.
    mu_static : float, optional
        Static friction coefficient μs [-], ≥ μ; defaults to ``mu``.
    return_history : bool
        Also return u and u̇ at the sample times.

    Returns
    -------
    SlidingResult
        Peaks [m], residual [m], slide time [s] and optionally the histories.

    Examples
    --------
    Newmark's rectangular pulse ([1] eq. 1), ap = 0.5 g for Tp = 1 s, μ = 0.25:
    the block slides at (ap - μg) for 1 s then decelerates at μg until t = 2 s,
    Umax = ap Tp² (ap - μg)/(2μg) = 0.25 g · 1 s² = 2.4516625 m, backwards.

    >>> r = sliding_response([0.5, 0.5], 1.0, 0.25)
    >>> round(r.sliding_max_m, 7), round(r.sliding_residual_m, 7), r.slide_time_s
    (2.4516625, -2.4516625, 2.0)
    """
    accel, _ = checked_record(floor_accel_g, dt_s)
    mu_arr, mu_s_arr = _check_friction(float(mu), mu_static if mu_static is None else float(mu_static))
    n = accel.shape[0]
    u_hist = np.empty(n if return_history else 0)
    v_hist = np.empty(n if return_history else 0)
    hi, lo, residual, slide_time = _slide_record(
        accel, n, float(dt_s), float(mu_arr), float(mu_s_arr), STANDARD_GRAVITY_M_S2,
        bool(return_history), u_hist, v_hist)
    history = {}
    if return_history:
        history = dict(time_s=np.arange(n) * float(dt_s), sliding_m=u_hist, sliding_velocity_m_s=v_hist)
    return SlidingResult(sliding_max_m=float(max(hi, lo)), sliding_residual_m=float(residual),
                         sliding_max_positive_m=float(hi), sliding_max_negative_m=float(lo),
                         slide_time_s=float(slide_time), **history)


def sliding_peaks_batch(floor_accel_g_2d, dt_s, mu_array, mu_static_array=None, record_lengths=None):
    """Peak and residual sliding of many blocks under many records (peaks only, in parallel).

    Each (block, record) pair is solved by the same exact kernel as
    :func:`sliding_response`; blocks are spread over threads
    (:func:`assess.mechanics.threads.run_case_ranges`).
    Memory is the two result arrays: nothing per time step is kept.

    Parameters
    ----------
    floor_accel_g_2d : 2-D array (n_records, n_samples) or sequence of 1-D arrays
        Floor accelerations [g]. A sequence of records of different lengths is
        padded internally; a 2-D array padded by the caller needs ``record_lengths``
        (padding is never read, so it does not alter the run-out after each record).
    dt_s : float or array-like (n_records,)
        Sampling step of every record, or one per record [s].
    mu_array : array-like (n_blocks,)
        Kinetic friction coefficient of each block [-], > 0.
    mu_static_array : array-like (n_blocks,), optional
        Static friction coefficients [-], ≥ ``mu_array``; default equal to it.
    record_lengths : array-like of int (n_records,), optional
        Samples of each row to use; default all of them (or each sequence's length).

    Returns
    -------
    peak_m, residual_m : ndarray (n_blocks, n_records)
        Peak |u| [m] and residual u [m].

    Examples
    --------
    Two blocks (μ = 0.25 and 0.5) under the rectangular pulse of
    :func:`sliding_response`; the second never slides (|a_g| ≤ μs).

    >>> peak, residual = sliding_peaks_batch([[0.5, 0.5]], 1.0, [0.25, 0.5])
    >>> peak.round(7).tolist()
    [[2.4516625], [0.0]]
    """
    if isinstance(floor_accel_g_2d, np.ndarray) and floor_accel_g_2d.ndim == 2:
        accel = np.ascontiguousarray(floor_accel_g_2d, dtype=float)
        lengths = np.full(accel.shape[0], accel.shape[1], dtype=np.int64)
    else:
        records = [np.asarray(r, dtype=float).ravel() for r in floor_accel_g_2d]
        lengths = np.array([r.size for r in records], dtype=np.int64)
        accel = np.zeros((len(records), int(lengths.max(initial=0))))
        for i, record in enumerate(records):
            accel[i, :record.size] = record
    if record_lengths is not None:
        lengths = np.asarray(record_lengths, dtype=np.int64)
        if lengths.shape != (accel.shape[0],) or np.any(lengths < 0) or np.any(lengths > accel.shape[1]):
            raise ValueError("record_lengths must give, per record, a length within the row")
    if not np.all(np.isfinite(accel)):
        raise ValueError("floor_accel_g_2d contains NaN or infinite values")
    dt = np.broadcast_to(np.asarray(dt_s, dtype=float), (accel.shape[0],)).copy()
    if not (np.all(np.isfinite(dt)) and np.all(dt > 0.0)):
        raise ValueError("dt_s must be finite and > 0")
    mu_k, mu_s = _check_friction(np.atleast_1d(np.asarray(mu_array, dtype=float)),
                                 None if mu_static_array is None
                                 else np.atleast_1d(np.asarray(mu_static_array, dtype=float)))
    peak = np.empty((mu_k.shape[0], accel.shape[0]))
    residual = np.empty_like(peak)
    run_case_ranges(_peaks_of_blocks, mu_k.shape[0], accel, lengths, dt, np.ascontiguousarray(mu_k),
                    np.ascontiguousarray(mu_s), STANDARD_GRAVITY_M_S2, peak, residual)
    return peak, residual
