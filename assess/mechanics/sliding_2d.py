"""Sliding of a rigid block in the plane under both horizontal floor components (no uplift).

A block that cannot rock slides on the floor under the two horizontal floor
accelerations :math:`\\mathbf a_g(t) = (a_x, a_y)` [g] with isotropic Coulomb
friction: the friction force has magnitude μmg and opposes the relative velocity
**vector** (not μmg per axis) [1]. The relative displacement
:math:`\\mathbf u` (block minus floor) obeys

.. math::

    \\ddot{\\mathbf u} = -g\\,\\mathbf a_g(t) - \\mu g\\,
    \\frac{\\dot{\\mathbf u}}{|\\dot{\\mathbf u}|} \\quad\\text{while sliding},\\qquad
    \\dot{\\mathbf u} = 0 \\quad\\text{while stuck}.

A stuck block starts to slide when :math:`|\\mathbf a_g| > \\mu_s` (the static
friction cone), along :math:`-\\mathbf a_g/|\\mathbf a_g|`; a sliding block stops
when :math:`\\dot{\\mathbf u}` reaches zero, and sticks there while
:math:`|\\mathbf a_g| \\le \\mu_s`.

Integration
-----------
The record is taken piecewise linear between samples, as in the one-way kernel
(:mod:`assess.mechanics.sliding`), with the same end conventions: the first
sample acts from t = 0, the floor is at rest after the last sample and a block
still sliding then runs out along a straight line (friction is the only force),
by :math:`|\\dot{\\mathbf u}|^2/(2\\mu g)`.

In one direction the friction force is constant while the block slides, which
makes the one-way problem exactly solvable per step. In the plane the velocity
direction turns and no closed form per step exists. Each record step is cut
into substeps no longer than ``max_substep_s``; in a substep the friction
direction is held fixed, so that the relative acceleration is linear in time,
the velocity a quadratic and the displacement a cubic, exactly as in the
one-way kernel. The held direction is the mean of the velocities at the start
and at the end of the substep, the end taken implicitly (trapezoidal): along
:math:`2\\dot{\\mathbf u} - g\\int \\mathbf a_g\\,dt` over the substep. (Holding
the direction of the velocity at the start, an explicit choice, is unstable at
low speed, where friction turns the velocity fastest: it drifted off the line of
a one-directional motion by up to 0.5 %.) Events are located in closed form
inside the substep:

* a stuck block starts to slide where :math:`|\\mathbf a_g(t)|` reaches μs (a
  quadratic in t, since :math:`\\mathbf a_g` is linear in the substep), along
  :math:`-\\mathbf a_g/|\\mathbf a_g|` held for the rest of the substep;
* a sliding block's velocity component along the held direction reaches zero
  (a quadratic); if the velocity left across that direction is
  negligible the block stops there (and sticks, or sets off again along
  :math:`-\\mathbf a_g`), otherwise it carries on in the new direction.

When the floor motion stays on one line (one component, or both proportional)
the velocity never turns and the kernel is the one-way exact kernel, step for
step: agreement to round-off (4e-15 on pyslammer's 18 records) with
:func:`assess.mechanics.sliding.sliding_response`. In the plane the error comes
from holding the direction in a substep; measured (tests/verification/test_sliding_2d.py)
with the default 1 ms substep: the steady circle of a circular floor motion
within 4e-5 of its closed form; on 18 pairs of real records × 3 μ, peaks within
1.5e-3 (median 5e-5) of a run with 16 times finer substeps, and within 1.5e-3 of
an independent implicit (Moreau) time stepping on dt/200. On smooth input the
error falls about fourfold per halving of the substep (second order); near
stops on records, less regularly.

The peak distance from rest is :math:`\\max_t |\\mathbf u(t)|`, taken at the
substep ends and at the events (stops, starts), and at both ends of the
run-out; a maximum of :math:`|\\mathbf u|` inside a substep is missed by at
most :math:`|\\ddot{\\mathbf u}|\\,h^2/8 \\le g(|\\mathbf a_g| + \\mu)\\,h^2/8`
(at a maximum :math:`\\mathbf u\\cdot\\dot{\\mathbf u} = 0` and the curvature of
:math:`|\\mathbf u|(t)` is at most :math:`|\\ddot{\\mathbf u}|`): 1.6 µm for
:math:`|\\mathbf a_g| + \\mu = 1.3` and h = 1 ms.

References
----------
.. [1] Younis, C. J., Tadjbakhsh, I. G. (1984). Response of sliding rigid
   structure to base excitation. J. Eng. Mech. 110(3):417-432.
   doi:10.1061/(ASCE)0733-9399(1984)110:3(417)
.. [2] Konstantinidis, D., Makris, N. (2010). Experimental and analytical
   studies on the response of 1/4-scale models of freestanding laboratory
   equipment subjected to strong earthquake shaking. Bull. Earthquake Eng.
   8:1457-1477, §3.1, eq. 1. doi:10.1007/s10518-010-9192-8
.. [3] Newmark, N. M. (1965). Effects of earthquakes on dams and embankments.
   Géotechnique 15(2):139-160. doi:10.1680/geot.1965.15.2.139
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Optional

import numpy as np
from numba import njit

from assess.mechanics.case_records import checked_record
from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2
from assess.mechanics.sliding import _check_friction
from assess.mechanics.stick_slip import _velocity_root
from assess.mechanics.threads import run_case_ranges

#: Default longest substep [s]; measured accuracy in the module docstring.
DEFAULT_MAX_SUBSTEP_S = 1.0e-3

#: Events (start, turn of the held direction, stop) resolved inside one substep.
#: Near a stop the velocity left across the held direction shrinks geometrically
#: from one event to the next. The bound ends a chatter of starts and stops at the
#: edge of the static cone while the floor acceleration turns (the block barely
#: moving): the block is then held for the rest of that substep. Measured: reached
#: twice in 8 runs on real record pairs, with |u̇| < 1e-34 m/s.
_MAX_EVENTS_PER_SUBSTEP = 64

#: A velocity left across the held direction below this fraction of μ g h (the
#: velocity friction removes in one substep) counts as a stop. 1e-6 instead left
#: the accuracy against 16x finer substeps as it is (largest 1.5e-3, median 5e-5
#: on 18 record pairs) and took more events.
_STOP_FRACTION = 1.0e-3

_NO_ROOT = -1.0


@dataclass(frozen=True)
class Sliding2DResult:
    """Response of a block sliding in the plane to one two-component floor motion.

    Attributes
    ----------
    sliding_max_m : float
        Peak distance from rest :math:`\\max_t |\\mathbf u(t)|` [m].
    sliding_residual_m : float
        Distance from the start where the block comes to rest after the record [m].
    sliding_residual_x_m, sliding_residual_y_m : float
        Components of the residual displacement [m] (signed).
    slide_time_s : float
        Total time the block spends sliding, run-out included [s].
    time_s : ndarray (n,) or None
        With ``return_history=True``: sample times [s].
    sliding_m, sliding_velocity_m_s : ndarray (n, 2) or None
        With ``return_history=True``: the path u [m] and velocity u̇ [m/s] at the
        samples (the run-out after the last sample is not sampled).
    """

    sliding_max_m: float
    sliding_residual_m: float
    sliding_residual_x_m: float
    sliding_residual_y_m: float
    slide_time_s: float
    time_s: Optional[np.ndarray] = None
    sliding_m: Optional[np.ndarray] = None
    sliding_velocity_m_s: Optional[np.ndarray] = None


@njit(cache=True)
def _cone_crossing(ax, ay, sx, sy, mu_s, h):
    """First σ in [0, h] at which |a + s σ| reaches μs from inside the cone, or -1.

    ``|a| ≤ μs``; :math:`|\\mathbf a + \\mathbf s\\sigma|^2 = \\mu_s^2` has at most one
    positive root (the product of the roots is ≤ 0), taken in the
    cancellation-free form :math:`(\\mu_s^2 - |a|^2)/(p + \\sqrt{p^2 + |s|^2(\\mu_s^2 - |a|^2)})`
    with :math:`p = \\mathbf a\\cdot\\mathbf s`.
    """
    ss = sx * sx + sy * sy
    if ss == 0.0:
        return _NO_ROOT
    p = ax * sx + ay * sy
    gap = mu_s * mu_s - (ax * ax + ay * ay)
    if gap < 0.0:
        gap = 0.0
    den = p + math.sqrt(p * p + ss * gap)
    if den <= 0.0:
        return _NO_ROOT  # on the cone and moving inwards (or not at all)
    root = gap / den  # 0 on the cone moving outwards: sets off now
    return root if root <= h else _NO_ROOT


@njit(cache=True)
def _slide_record_2d(ax_g, ay_g, n, dt, mu_k, mu_s, gravity, max_substep, keep_history, u_out, v_out):
    """Substepped event-located integration over the first ``n`` samples.

    Returns (peak |u|, residual u_x, residual u_y, slide time). If ``keep_history``,
    writes u and u̇ at the samples into ``u_out``, ``v_out`` (shape (n, 2)).
    """
    ux = uy = vx = vy = 0.0
    sliding = False
    peak2 = 0.0
    slide_time = 0.0
    mu_s2 = mu_s * mu_s
    n_sub = max(1, int(math.ceil(dt / max_substep - 1e-9)))
    h = dt / n_sub
    v_tol = _STOP_FRACTION * mu_k * gravity * h
    if keep_history and n > 0:
        u_out[0, 0] = u_out[0, 1] = v_out[0, 0] = v_out[0, 1] = 0.0
    for k in range(n - 1):
        a0x = ax_g[k]
        a0y = ay_g[k]
        a1x = ax_g[k + 1]
        a1y = ay_g[k + 1]
        # |a_g| is convex along the step: below μs at both ends means below it throughout
        if (not sliding and a0x * a0x + a0y * a0y <= mu_s2 and a1x * a1x + a1y * a1y <= mu_s2):
            if keep_history:
                u_out[k + 1, 0] = ux
                u_out[k + 1, 1] = uy
                v_out[k + 1, 0] = v_out[k + 1, 1] = 0.0
            continue
        slope_x = (a1x - a0x) / dt  # [g/s]
        slope_y = (a1y - a0y) / dt
        cx = -0.5 * gravity * slope_x  # relative acceleration = b + 2 c σ
        cy = -0.5 * gravity * slope_y
        for j in range(n_sub):
            tau = 0.0  # time into the substep [s]
            t0 = j * h
            ahx = a0x + slope_x * t0  # a_g at tau [g]
            ahy = a0y + slope_y * t0
            for event in range(_MAX_EVENTS_PER_SUBSTEP):
                if not sliding:
                    if ahx * ahx + ahy * ahy <= mu_s2:
                        sigma = _cone_crossing(ahx, ahy, slope_x, slope_y, mu_s, h - tau)
                        if sigma < 0.0:
                            break  # stuck for the rest of the substep
                        tau += sigma
                        ahx = a0x + slope_x * (t0 + tau)
                        ahy = a0y + slope_y * (t0 + tau)
                        if tau >= h:
                            break  # sets off at the next substep
                    sliding = True
                    vx = vy = 0.0
                rem = h - tau
                speed = math.sqrt(vx * vx + vy * vy)
                if speed > 0.0:
                    e0x = vx / speed
                    e0y = vy / speed
                else:  # setting off, along -a_g
                    amag = math.sqrt(ahx * ahx + ahy * ahy)
                    e0x = -ahx / amag
                    e0y = -ahy / amag
                ex = e0x
                ey = e0y
                if speed > 0.0:
                    # held direction: the mean of the start and end velocities, end taken
                    # implicitly (trapezoidal), i.e. along 2 u' - g ∫ a_g over the substep;
                    # stable at low speed, where the start direction alone is not
                    wx = 2.0 * vx - gravity * (ahx + 0.5 * slope_x * rem) * rem
                    wy = 2.0 * vy - gravity * (ahy + 0.5 * slope_y * rem) * rem
                    if wx * vx + wy * vy > 0.0:
                        wm = math.sqrt(wx * wx + wy * wy)
                        ex = wx / wm
                        ey = wy / wm
                bx = -gravity * (ahx + mu_k * ex)
                by = -gravity * (ahy + mu_k * ey)
                sigma = _velocity_root(vx * ex + vy * ey, bx * ex + by * ey, cx * ex + cy * ey, rem)
                if sigma < 0.0:  # slides to the end of the substep
                    ux += (vx + (0.5 * bx + cx * rem / 3.0) * rem) * rem
                    uy += (vy + (0.5 * by + cy * rem / 3.0) * rem) * rem
                    vx += (bx + cx * rem) * rem
                    vy += (by + cy * rem) * rem
                    slide_time += rem
                    if vx * ex + vy * ey <= 0.0:  # the root fell on the substep end (round-off)
                        vx = vy = 0.0
                        sliding = False
                    p2 = ux * ux + uy * uy
                    if p2 > peak2:
                        peak2 = p2
                    break
                ux += (vx + (0.5 * bx + cx * sigma / 3.0) * sigma) * sigma
                uy += (vy + (0.5 * by + cy * sigma / 3.0) * sigma) * sigma
                vx += (bx + cx * sigma) * sigma
                vy += (by + cy * sigma) * sigma
                along = vx * ex + vy * ey  # zero but for round-off
                vx -= along * ex
                vy -= along * ey
                slide_time += sigma
                tau += sigma
                ahx = a0x + slope_x * (t0 + tau)
                ahy = a0y + slope_y * (t0 + tau)
                p2 = ux * ux + uy * uy
                if p2 > peak2:
                    peak2 = p2
                if vx * vx + vy * vy <= v_tol * v_tol or event == _MAX_EVENTS_PER_SUBSTEP - 1:
                    vx = vy = 0.0  # stopped: sticks, or sets off again along -a_g
                    sliding = False
                if tau >= h:
                    break
        if keep_history:
            u_out[k + 1, 0] = ux
            u_out[k + 1, 1] = uy
            v_out[k + 1, 0] = vx
            v_out[k + 1, 1] = vy
    speed = math.sqrt(vx * vx + vy * vy)
    if sliding and speed > 0.0:  # run-out on a floor at rest: a straight line at μg
        run = speed / (2.0 * mu_k * gravity)  # distance / speed
        ux += vx * run
        uy += vy * run
        slide_time += speed / (mu_k * gravity)
        p2 = ux * ux + uy * uy  # |u| is convex along the line: its ends hold the peak
        if p2 > peak2:
            peak2 = p2
    return math.sqrt(peak2), ux, uy, slide_time


def _check_two_components(floor_accel_x_g, floor_accel_y_g, dt_s):
    ax, _ = checked_record(floor_accel_x_g, dt_s)
    ay, _ = checked_record(floor_accel_y_g, dt_s)
    if ay.shape != ax.shape:
        raise ValueError("floor_accel_x_g and floor_accel_y_g must be of one length")
    return ax, ay


def _check_substep(max_substep_s):
    max_substep_s = float(max_substep_s)
    if not (np.isfinite(max_substep_s) and max_substep_s > 0.0):
        raise ValueError("max_substep_s must be finite and > 0")
    return max_substep_s


def sliding_response_2d(floor_accel_x_g, floor_accel_y_g, dt_s, mu, mu_static=None,
                        max_substep_s=DEFAULT_MAX_SUBSTEP_S, return_history=False) -> Sliding2DResult:
    """Sliding in the plane under two horizontal floor components, isotropic Coulomb friction.

    .. math::

        \\ddot{\\mathbf u} = -g\\,\\mathbf a_g(t) - \\mu g\\,\\hat{\\dot{\\mathbf u}} \\;\\text{(sliding)},
        \\qquad \\text{stick while } \\dot{\\mathbf u} = 0,\\ |\\mathbf a_g| \\le \\mu_s

    ([1]; [2] eq. 1 on one axis; see the module docstring for the substepped solution, its measured
    accuracy and the conventions at both ends of the record).

    Parameters
    ----------
    floor_accel_x_g, floor_accel_y_g : array-like, shape (n,)
        The two horizontal floor acceleration components [g] at t = 0, dt, ...,
        (n-1)dt; linear between samples.
    dt_s : float
        Sampling step [s].
    mu : float
        Kinetic friction coefficient μ [-], > 0.
    mu_static : float, optional
        Static friction coefficient μs [-], ≥ μ; defaults to ``mu``.
    max_substep_s : float
        Longest substep [s] over which the friction direction is held.
    return_history : bool
        Also return the path u and velocity u̇ at the sample times.

    Returns
    -------
    Sliding2DResult
        Peak distance from rest [m], residual [m], slide time [s], optionally the path.

    Examples
    --------
    Newmark's rectangular pulse ([3]) of 0.5 g for 1 s, μ = 0.25, along the diagonal
    (0.3 g, 0.4 g): the block slides back along the diagonal by
    ap Tp² (ap - μg)/(2μg) = 0.25 g · 1 s² = 2.4516625 m, i.e. -1.4709975 m in x
    and -1.96133 m in y.

    >>> r = sliding_response_2d([0.3, 0.3], [0.4, 0.4], 1.0, 0.25)
    >>> round(r.sliding_max_m, 7), round(r.sliding_residual_x_m, 7), round(r.sliding_residual_y_m, 7)
    (2.4516625, -1.4709975, -1.96133)
    """
    ax, ay = _check_two_components(floor_accel_x_g, floor_accel_y_g, float(dt_s))
    mu_arr, mu_s_arr = _check_friction(float(mu), mu_static if mu_static is None else float(mu_static))
    n = ax.shape[0]
    u_hist = np.empty((n if return_history else 0, 2))
    v_hist = np.empty((n if return_history else 0, 2))
    peak, res_x, res_y, slide_time = _slide_record_2d(
        ax, ay, n, float(dt_s), float(mu_arr), float(mu_s_arr), STANDARD_GRAVITY_M_S2,
        _check_substep(max_substep_s), bool(return_history), u_hist, v_hist)
    history = {}
    if return_history:
        history = dict(time_s=np.arange(n) * float(dt_s), sliding_m=u_hist, sliding_velocity_m_s=v_hist)
    return Sliding2DResult(sliding_max_m=float(peak), sliding_residual_m=float(math.hypot(res_x, res_y)),
                           sliding_residual_x_m=float(res_x), sliding_residual_y_m=float(res_y),
                           slide_time_s=float(slide_time), **history)


@njit(cache=True)
def _peaks_of_block_2d(ax_2d, ay_2d, lengths, dt, mu_k, mu_s, gravity, max_substep, peak, residual, i):
    dummy = np.empty((0, 2))
    for r in range(ax_2d.shape[0]):
        top, res_x, res_y, _t = _slide_record_2d(ax_2d[r], ay_2d[r], lengths[r], dt[r], mu_k[i], mu_s[i],
                                                 gravity, max_substep, False, dummy, dummy)
        peak[i, r] = top
        residual[i, r] = math.sqrt(res_x * res_x + res_y * res_y)


@njit(cache=True, nogil=True)
def _peaks_of_blocks_2d(start, stop, ax_2d, ay_2d, lengths, dt, mu_k, mu_s, gravity, max_substep, peak, residual):
    """Blocks start to stop − 1 under every record pair (:func:`assess.mechanics.threads.run_case_ranges`)."""
    for i in range(start, stop):
        _peaks_of_block_2d(ax_2d, ay_2d, lengths, dt, mu_k, mu_s, gravity, max_substep, peak, residual, i)


def _pad(records):
    if isinstance(records, np.ndarray) and records.ndim == 2:
        return np.ascontiguousarray(records, dtype=float), np.full(records.shape[0], records.shape[1], np.int64)
    rows = [np.asarray(r, dtype=float).ravel() for r in records]
    lengths = np.array([r.size for r in rows], dtype=np.int64)
    padded = np.zeros((len(rows), int(lengths.max(initial=0))))
    for i, row in enumerate(rows):
        padded[i, :row.size] = row
    return padded, lengths


def sliding_2d_peaks_batch(floor_accel_x_g_2d, floor_accel_y_g_2d, dt_s, mu_array, mu_static_array=None,
                           record_lengths=None, max_substep_s=DEFAULT_MAX_SUBSTEP_S):
    """Peak distance from rest and residual distance of many blocks under many two-component records.

    Each (block, record pair) is solved by the kernel of :func:`sliding_response_2d`;
    blocks are spread over threads (:func:`assess.mechanics.threads.run_case_ranges`), as in
    :func:`assess.mechanics.sliding.sliding_peaks_batch`.

    Parameters
    ----------
    floor_accel_x_g_2d, floor_accel_y_g_2d : 2-D arrays (n_records, n_samples) or sequences of 1-D arrays
        The two floor acceleration components [g] of each record; row r of one
        goes with row r of the other (same length).
    dt_s : float or array-like (n_records,)
        Sampling step of every record, or one per record [s].
    mu_array : array-like (n_blocks,)
        Kinetic friction coefficient of each block [-], > 0.
    mu_static_array : array-like (n_blocks,), optional
        Static friction coefficients [-], ≥ ``mu_array``; default equal to it.
    record_lengths : array-like of int (n_records,), optional
        Samples of each row to use; default all of them (or each sequence's length).
    max_substep_s : float
        Longest substep [s].

    Returns
    -------
    peak_m, residual_m : ndarray (n_blocks, n_records)
        Peak distance from rest [m] and residual distance [m].

    Examples
    --------
    Two blocks (μ = 0.25 and 0.6) under the diagonal pulse of
    :func:`sliding_response_2d` (|a_g| = 0.5 g); the second never slides.

    >>> peak, residual = sliding_2d_peaks_batch([[0.3, 0.3]], [[0.4, 0.4]], 1.0, [0.25, 0.6])
    >>> peak.round(7).tolist()
    [[2.4516625], [0.0]]
    """
    ax, lengths_x = _pad(floor_accel_x_g_2d)
    ay, lengths_y = _pad(floor_accel_y_g_2d)
    if ax.shape != ay.shape or np.any(lengths_x != lengths_y):
        raise ValueError("the two components must have one row per record, of equal lengths")
    lengths = lengths_x
    if record_lengths is not None:
        lengths = np.asarray(record_lengths, dtype=np.int64)
        if lengths.shape != (ax.shape[0],) or np.any(lengths < 0) or np.any(lengths > ax.shape[1]):
            raise ValueError("record_lengths must give, per record, a length within the row")
    if not (np.all(np.isfinite(ax)) and np.all(np.isfinite(ay))):
        raise ValueError("the floor accelerations contain NaN or infinite values")
    dt = np.broadcast_to(np.asarray(dt_s, dtype=float), (ax.shape[0],)).copy()
    if not (np.all(np.isfinite(dt)) and np.all(dt > 0.0)):
        raise ValueError("dt_s must be finite and > 0")
    mu_k, mu_s = _check_friction(np.atleast_1d(np.asarray(mu_array, dtype=float)),
                                 None if mu_static_array is None
                                 else np.atleast_1d(np.asarray(mu_static_array, dtype=float)))
    peak = np.empty((mu_k.shape[0], ax.shape[0]))
    residual = np.empty_like(peak)
    run_case_ranges(_peaks_of_blocks_2d, mu_k.shape[0], ax, ay, lengths, dt, np.ascontiguousarray(mu_k),
                    np.ascontiguousarray(mu_s), STANDARD_GRAVITY_M_S2, _check_substep(max_substep_s), peak, residual)
    return peak, residual
