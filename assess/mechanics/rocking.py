"""Pure rocking of a rigid block on a moving floor: Housner impacts and overturning.

A rigid block of slenderness α and frequency parameter p (see
:mod:`assess.mechanics.geometry`) rocks about one base corner or the other
without sliding. With θ > 0 rocking about one corner and θ < 0 about the
other, its equation of motion is ([1], eq. 1; [2]):

.. math::

    \\ddot\\theta = -p^2 \\left[ \\sin(\\alpha\\,\\mathrm{sgn}\\,\\theta - \\theta)
    + \\frac{\\ddot u_g}{g} \\cos(\\alpha\\,\\mathrm{sgn}\\,\\theta - \\theta) \\right]

**Sign convention.** A positive floor acceleration :math:`\\ddot u_g` drives a
*negative* rotation: its inertial force :math:`-m\\ddot u_g` pushes the centre
of mass backwards, so a block at rest uplifts to θ < 0 when
:math:`\\ddot u_g > g\\tan\\alpha` and to θ > 0 when
:math:`\\ddot u_g < -g\\tan\\alpha` ([1], eq. 2, for a block whose centre of
mass lies on the diagonal of its base corners, as a uniform block).

**Impact.** When θ returns to zero the block hits the floor with its other
corner; the angular velocity keeps its sign and is multiplied by the
coefficient of restitution, by default Housner's value for a uniform block
(:func:`assess.mechanics.geometry.housner_restitution`, [3] eq. 11):

.. math:: \\dot\\theta^+ = e\\,\\dot\\theta^-, \\qquad e = 1 - \\tfrac{3}{2}\\sin^2\\alpha

**Overturning** is :math:`|\\theta| \\ge \\pi/2` (the block lies on its side).
Exceeding α alone is not overturning: the floor can still bring the block back
(the FORMA incubator of [4], Fig. 7, passes α at t ≈ 7.5 s and survives).

**Contact forces.** Pure rocking holds only while the pivot neither slips
nor lifts. With φ = θ − α sgn θ, w = θ̇/p and κ = I_O/(mR²) (so that
:math:`p^2 = g/(\\kappa R)`), Newton's law for the centre of mass, which moves
on a circle of radius R about the pivot, gives the pivot's friction and normal
forces ([2]; [5], eq. 14 at θ = 0):

.. math::

    \\frac{F}{mg} = \\frac{\\theta''\\cos\\varphi - w^2\\sin\\varphi}{\\kappa} + \\frac{\\ddot u_g}{g},
    \\qquad
    \\frac{N}{mg} = 1 - \\frac{\\theta''\\sin\\varphi + w^2\\cos\\varphi}{\\kappa}

with θ'' = d²θ/d(pt)². The kernel reports the largest |F|/N and the smallest
N/(mg) over the rocking phases, evaluated at the end of every integration step
and just before and just after every impact, where |θ̇| and with it the
centripetal term w² peak (at the step ends alone, the largest demand was
missed by 1.5 % in one run of 100 with steps p·h ≤ 0.01, against 0.001 % with
these, on the runs of the comparison below); a caller that must be sure the
block rocked compares them with μ_s and 0 (:mod:`assess.mechanics.engine`). A Housner
impact needs a friction impulse ratio of :math:`(1-e)/((1+e)\\tan\\alpha)`,
which never exceeds tan α (for κ ≥ 1), so a block with μ_s ≥ tan α cannot slip
at an impact.

**Rest.** A block at rest stays at rest while :math:`|\\ddot u_g| \\le g\\tan\\alpha`.
After an impact whose outgoing angular velocity is below
``REST_ANGULAR_VELOCITY_RATIO`` · pα while the floor pushes the block back
towards θ = 0, the block is put back at rest (the Zeno sequence of ever
smaller rocks has converged); the impacts of that sequence are counted.

**End of the record.** After the last sample the floor is at rest (its
acceleration is zero after the record, or after Tp for a pulse): the acceleration steps to zero there, as
in the sliding kernel and both general solvers, and ``tail_s`` more seconds
are followed. (Appending zeros to the samples instead would ramp the floor
down over one more sample interval: a pulse that ends at full amplitude, as
Type B does, would push the block for half an interval longer.)

**Numerics.** The floor acceleration is piecewise linear between samples. Each
sample interval is integrated with the classical Runge-Kutta scheme in the
dimensionless time τ = p t, with sub-steps of at most
``MAX_STEP_DIMENSIONLESS`` (so p·h ≤ 0.1: one step per sample for most
blocks and records, p·dt being 0.01-0.08 for blocks of 0.8-2.4 m under
records sampled at 0.005-0.02 s) and, in a small rock, of at most
``ROCK_STEP_FRACTION`` = 0.1 of its time scale
:math:`\\sqrt{2|\\theta|/\\alpha + (\\dot\\theta/p\\alpha)^2}` (its duration is
about twice that, in τ), down to 1/16 of the first bound. Impacts (θ = 0), overturning
(|θ| = π/2) and uplift (|ü_g| = g tan α, from the linear input) are located
inside a step (the first two by safeguarded Newton iteration on the length of
a single Runge-Kutta step), and the remainder of the step is integrated
afresh from the event. Peaks of |θ| inside a step are found from the cubic
Hermite interpolant of (θ, θ̇) at the ends of the step. Because the kernel
runs in τ = p t with thresholds relative to α, it respects Froude similitude
exactly: a block with all lengths scaled by λ under the same accelerations
compressed in time by √λ gives the same θ/α history. Against steps of
p·h ≤ 0.002, on 300 blocks (0.8-2.4 m, b/h 0.17-1.5) under the 18 pyslammer
records at their scale and three times it (10,800 runs, 5,900 of them rocking
to the end), θmax/α differs by 3e-9 in the median run, 4e-5 in one run of
100 and by more than 0.01 in 9 (with steps of p·h ≤ 0.01 alone: 2e-10, 2e-5,
9; of 0.1 alone: 7e-9, 6e-4, 21), long trains of small rocks or rocks past
0.6α whose outcome any step moves (p·h ≤ 0.01 moves it by up to 0.43); 6
overturning verdicts of 1,892 differ (6 and 8), every one after a rock to
0.65α-1.0α. On the Kobe train of small rocks of
:mod:`assess.mechanics.timestepping`, θmax/α is 0.02600 as by the
event-driven solver (0.02602 with steps of 0.01 alone, 0.0272 with 0.1 alone).

References
----------
.. [1] Makris, N., Roussos, Y. S. (2000). Rocking response of rigid blocks
   under near-source ground motions. Géotechnique 50(3):243-262,
   eq. 1 and 2. doi:10.1680/geot.2000.50.3.243
.. [2] Zhang, J., Makris, N. (2001). Rocking response of free-standing blocks
   under cycloidal pulses. J. Eng. Mech. 127(5):473-483.
   doi:10.1061/(ASCE)0733-9399(2001)127:5(473)
.. [3] Housner, G. W. (1963). The behavior of inverted pendulum structures
   during earthquakes. Bull. Seismol. Soc. Am. 53(2):403-417, eq. 11.
.. [4] Konstantinidis, D., Makris, N. (2010). Bull. Earthquake Eng.
   8:1457-1477, section 3.2, Figs. 5-7. doi:10.1007/s10518-010-9192-8
.. [5] Shenton, H. W. (1996). Criteria for initiation of slide, rock, and
   slide-rock rigid-body modes. J. Eng. Mech. 122(7):690-693.
   doi:10.1061/(ASCE)0733-9399(1996)122:7(690)
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

from .case_records import checked_record, checked_records
from .geometry import housner_restitution
from .threads import run_case_ranges

#: Largest Runge-Kutta step in dimensionless time p·h [-].
MAX_STEP_DIMENSIONLESS = 0.1
#: Largest Runge-Kutta step as a fraction of the time scale of the current rock,
#: :math:`\sqrt{2|\theta|/\alpha + (\dot\theta/p\alpha)^2}` [-].
ROCK_STEP_FRACTION = 0.1
#: Most times a step is cut for a small rock [-].
MAX_REFINEMENT = 16
#: An impact leaving |θ̇| below this multiple of p·α, with the floor pushing the
#: block back, puts the block at rest [-].
REST_ANGULAR_VELOCITY_RATIO = 1e-5
#: Safety limit on the number of steps and events inside one sample interval.
_MAX_EVENTS_PER_INTERVAL = 200_000
_HALF_PI = 0.5 * np.pi


# --------------------------------------------------------------------------- kernel
@njit(cache=True)
def _rhs(theta, side, accel_g, alpha):
    """θ'' in τ = p t for a block pivoting on corner ``side`` (±1)."""
    phi = alpha * side - theta
    return -(np.sin(phi) + accel_g * np.cos(phi))


@njit(cache=True)
def _pivot_forces_and_rhs(theta, w, side, accel_g, alpha, kappa):
    """(F, N)/(m g) at the pivot of a block rocking on corner ``side`` without slipping, and θ''.

    See "Contact forces" in the module docstring; ``w`` = θ̇/p. θ'' is
    :func:`_rhs` of the same state, to the bit (sin and cos of −φ and φ).
    """
    phi = theta - side * alpha
    sin_phi, cos_phi = np.sin(phi), np.cos(phi)
    thdd = -(-sin_phi + accel_g * cos_phi)
    friction = (cos_phi * thdd - sin_phi * w * w) / kappa + accel_g
    normal = 1.0 + (-sin_phi * thdd - cos_phi * w * w) / kappa
    return friction, normal, thdd


@njit(cache=True)
def _track_pivot_forces(forces, theta, w, side, accel_g, alpha, kappa):
    """Update ``forces`` = (max |F|/N, min N/(mg)) with the pivot forces of this state; returns its θ''."""
    friction, normal, thdd = _pivot_forces_and_rhs(theta, w, side, accel_g, alpha, kappa)
    forces[1] = min(forces[1], normal)
    forces[0] = max(forces[0], abs(friction) / normal if normal > 0.0 else np.inf)
    return thdd


@njit(cache=True)
def _rk4(theta, w, side, alpha, accel_start, slope, h):
    """One classical Runge-Kutta step of length h (τ units), floor accel linear in τ."""
    return _rk4_from(theta, w, side, alpha, accel_start, slope, h, _rhs(theta, side, accel_start, alpha))


@njit(cache=True)
def _rk4_from(theta, w, side, alpha, accel_start, slope, h, k1w):
    """:func:`_rk4` given θ'' at the start of the step, ``k1w`` (the pivot forces' own, once tracked)."""
    accel_mid = accel_start + slope * 0.5 * h
    k1t = w
    k2t = w + 0.5 * h * k1w
    k2w = _rhs(theta + 0.5 * h * k1t, side, accel_mid, alpha)
    k3t = w + 0.5 * h * k2w
    k3w = _rhs(theta + 0.5 * h * k2t, side, accel_mid, alpha)
    k4t = w + h * k3w
    k4w = _rhs(theta + h * k3t, side, accel_start + slope * h, alpha)
    theta_new = theta + h / 6.0 * (k1t + 2.0 * k2t + 2.0 * k3t + k4t)
    w_new = w + h / 6.0 * (k1w + 2.0 * k2w + 2.0 * k3w + k4w)
    return theta_new, w_new


@njit(cache=True)
def _first_root_of_quadratic(a, b, c, h):
    """Smallest root in (0, h) of a x² + b x + c (−1 if there is none).

    Taylor's quadratic of side·θ − target about the start of a step, a first guess at
    the event that does not fall back on the wrong side of the peak of a small rock, as
    the chord does (Newton from there would step away from the root).
    """
    best = -1.0
    if a == 0.0:
        if b != 0.0:
            best = -c / b
    else:
        disc = b * b - 4.0 * a * c
        if disc >= 0.0:
            q = -0.5 * (b + np.copysign(np.sqrt(disc), b))
            for x in (q / a, c / q if q != 0.0 else -1.0):
                if 0.0 < x < h and (best < 0.0 or x < best):
                    best = x
    return best if 0.0 < best < h else -1.0


@njit(cache=True)
def _locate(theta, w, side, alpha, accel_start, slope, h, g_end, target):
    """Step length in (0, h] at which side·θ = target, by safeguarded Newton.

    ``g_end`` is side·θ − target at the end of the full step (opposite sign to
    the start). Returns (tau, theta, w) at the event.
    """
    g_lo = side * theta - target
    lo, hi = 0.0, h
    tau = _first_root_of_quadratic(0.5 * side * _rhs(theta, side, accel_start, alpha), side * w, g_lo, h)
    if not (lo < tau < hi):  # the chord
        tau = h * g_lo / (g_lo - g_end)
    if not (lo < tau < hi):
        tau = 0.5 * h
    th, wt = theta, w
    for _ in range(60):
        th, wt = _rk4(theta, w, side, alpha, accel_start, slope, tau)
        g = side * th - target
        if g == 0.0:
            break
        if (g > 0.0) == (g_lo > 0.0):
            lo = tau
        else:
            hi = tau
        dg = side * wt
        tau_new = tau - g / dg if dg != 0.0 else 0.5 * (lo + hi)
        if abs(tau_new - tau) <= 1e-15 * h:  # converged (before the bracket, whose end tau now is)
            tau_new = min(max(tau_new, lo), hi)
            if tau_new != tau:
                tau = tau_new
                th, wt = _rk4(theta, w, side, alpha, accel_start, slope, tau)
            break
        if not (lo < tau_new < hi):
            tau_new = 0.5 * (lo + hi)
        if abs(tau_new - tau) <= 1e-15 * h:
            tau = tau_new
            th, wt = _rk4(theta, w, side, alpha, accel_start, slope, tau)
            break
        tau = tau_new
    return tau, th, wt


@njit(cache=True)
def _hermite_extremum(th0, w0, th1, w1, h):
    """(offset, θ) of the interior extremum of the cubic Hermite interpolant, w0·w1 < 0."""
    c1 = h * w0
    c2 = 3.0 * (th1 - th0) - 2.0 * h * w0 - h * w1
    c3 = 2.0 * (th0 - th1) + h * w0 + h * w1
    qa, qb, qc = 3.0 * c3, 2.0 * c2, c1
    x = 0.5
    if abs(qa) <= 1e-14 * (abs(qb) + abs(qc)):
        if qb != 0.0:
            x = -qc / qb
    else:
        disc = max(qb * qb - 4.0 * qa * qc, 0.0)
        q = -0.5 * (qb + np.copysign(np.sqrt(disc), qb))
        x1 = q / qa
        x2 = qc / q if q != 0.0 else -1.0
        x = x1 if 0.0 <= x1 <= 1.0 else x2
    x = min(max(x, 0.0), 1.0)
    return x * h, th0 + x * (c1 + x * (c2 + x * c3))


@njit(cache=True)
def _simulate(accel_g, dt_s, n_tail, alpha, p, e, kappa, theta_init, theta_dot_init,
              hist_theta, hist_theta_dot, impact_t, impact_w, peak_t, peak_theta, counts, forces, friction_stop):
    """Integrate one block over one record and ``n_tail`` intervals of floor at rest after it.

    The floor is linear between the record's samples and zero from the last
    sample on (a step there, never a ramp into the tail). History arrays of
    size 0 are not written (otherwise of size n + n_tail). Returns
    (theta_max_rad, uplift, overturned, overturn_time_s, impacts); ``forces``
    receives (max |F|/N, min N/(mg)) over the rocking phases. The run stops
    (without history) as soon as max |F|/N exceeds ``friction_stop`` or N
    reaches zero: pure rocking is then disproved (``inf``: never stops).
    """
    n_record = accel_g.size
    n = n_record + n_tail
    tan_alpha = np.tan(alpha)
    dtau = p * dt_s
    nsub = max(1, int(np.ceil(dtau / MAX_STEP_DIMENSIONLESS - 1e-9)))
    h_nominal = dtau / nsub
    w_rest = REST_ANGULAR_VELOCITY_RATIO * alpha
    record = hist_theta.size > 0
    theta = theta_init
    w = theta_dot_init / p
    resting = theta == 0.0 and w == 0.0
    side = 1.0
    if theta != 0.0:
        side = np.sign(theta)
    elif w != 0.0:
        side = np.sign(w)
    uplift = not resting
    overturned = False
    overturn_time = np.nan
    theta_max = abs(theta)
    impacts = 0
    disproved, stopping = False, friction_stop < np.inf
    forces[0] = 0.0
    forces[1] = 1.0
    theta_k1, w_k1, side_k1, accel_k1, thdd_k1 = np.nan, np.nan, 0.0, np.nan, np.nan  # no θ'' known yet
    if record:
        hist_theta[0] = theta
        hist_theta_dot[0] = w * p
    k = 0
    while k < n - 1:
        if resting and k < n_record - 1:
            # at rest at a sample: every following interval whose two samples are within g tan(alpha)
            # leaves it so (the floor is linear between them), skipped at once
            k_rest = k
            while k_rest < n_record - 1 and abs(accel_g[k_rest]) <= tan_alpha and abs(
                    accel_g[k_rest + 1]) <= tan_alpha:
                k_rest += 1
            if k_rest > k:
                if record:
                    hist_theta[k + 1:k_rest + 1] = 0.0
                    hist_theta_dot[k + 1:k_rest + 1] = 0.0
                k = k_rest
                continue
        if k < n_record - 1:
            a0 = accel_g[k]
            a1 = accel_g[k + 1]
        else:  # after the record: the floor is at rest
            a0 = 0.0
            a1 = 0.0
            if resting:  # and so is the block, for good
                if record:
                    hist_theta[k + 1:] = 0.0
                    hist_theta_dot[k + 1:] = 0.0
                break
        slope = (a1 - a0) / dtau
        tau0 = k * dtau
        s = 0.0
        guard = 0
        while dtau - s > 1e-12 * dtau:
            if stopping and (forces[0] > friction_stop or not forces[1] > 0.0):
                disproved = True
                break
            guard += 1
            if guard > _MAX_EVENTS_PER_INTERVAL:
                resting, theta, w = True, 0.0, 0.0
                break
            accel_s = a0 + slope * s
            if resting:
                if abs(accel_s) <= tan_alpha:
                    if a1 > tan_alpha:
                        s_up = (tan_alpha - a0) / slope
                    elif a1 < -tan_alpha:
                        s_up = (-tan_alpha - a0) / slope
                    else:
                        break
                    s = min(max(s, s_up), dtau)
                    accel_s = a0 + slope * s
                side = -1.0 if accel_s > 0.0 else 1.0
                theta, w, resting, uplift = 0.0, 0.0, False, True
                _track_pivot_forces(forces, 0.0, 0.0, side, accel_s, alpha, kappa)
                continue
            # next sub-step boundary
            s_end = (np.floor(s / h_nominal) + 1.0) * h_nominal
            if s_end - s < 1e-9 * h_nominal:
                s_end += h_nominal
            s_end = min(s_end, dtau)
            h = s_end - s
            full = True
            h_rock = max(ROCK_STEP_FRACTION * np.sqrt(2.0 * abs(theta) / alpha + (w / alpha) ** 2),
                         h_nominal / MAX_REFINEMENT)
            if h_rock < h:  # a small rock: steps of at most a fraction of its time scale
                h = h_rock
                full = False
            if theta == 0.0 and w != 0.0:
                # leaving the floor: do not step over a whole micro-rock
                thdd0 = _rhs(0.0, side, accel_s, alpha)
                if side * thdd0 < 0.0 and 0.5 * abs(w / thdd0) < h:
                    h = 0.5 * abs(w / thdd0)
                    full = False
            if theta == theta_k1 and w == w_k1 and side == side_k1 and accel_s == accel_k1:
                k1w = thdd_k1  # θ'' of this state, worked out with its pivot forces
            else:
                k1w = _rhs(theta, side, accel_s, alpha)
            th1, w1 = _rk4_from(theta, w, side, alpha, accel_s, slope, h, k1w)
            attempt = 0
            while theta == 0.0 and w != 0.0 and side * th1 < 0.0 and attempt < 12:
                h *= 0.25
                full = False
                attempt += 1
                th1, w1 = _rk4_from(theta, w, side, alpha, accel_s, slope, h, k1w)
            if side * th1 >= _HALF_PI:
                tau = _locate(theta, w, side, alpha, accel_s, slope, h, side * th1 - _HALF_PI, _HALF_PI)[0]
                overturned = True
                overturn_time = (tau0 + s + tau) / p
                theta_max = _HALF_PI
                break
            if side * th1 < 0.0:
                if theta == 0.0:
                    # failed uplift or unresolved micro-rock: the block is at rest
                    resting, theta, w = True, 0.0, 0.0
                    s += h
                    continue
                tau, _, w_e = _locate(theta, w, side, alpha, accel_s, slope, h, side * th1, 0.0)
                if w * w_e < 0.0:
                    tp, thp = _hermite_extremum(theta, w, 0.0, w_e, tau)
                    theta_max = max(theta_max, abs(thp))
                    if counts[1] < peak_t.size:
                        peak_t[counts[1]] = (tau0 + s + tp) / p
                        peak_theta[counts[1]] = thp
                    counts[1] += 1
                if counts[0] < impact_t.size:
                    impact_t[counts[0]] = (tau0 + s + tau) / p
                    impact_w[counts[0]] = w_e * p
                counts[0] += 1
                impacts += 1
                s += tau
                # the pivot forces just before the impact and just after it, where |θ̇| is largest
                _track_pivot_forces(forces, 0.0, w_e, side, a0 + slope * s, alpha, kappa)
                theta = 0.0
                w = e * w_e
                side = -side
                if abs(w) < w_rest:
                    thdd0 = _rhs(0.0, side, a0 + slope * s, alpha)
                    if side * thdd0 <= 0.0:
                        resting, w = True, 0.0
                if not resting:
                    _track_pivot_forces(forces, 0.0, w, side, a0 + slope * s, alpha, kappa)
                continue
            if w * w1 < 0.0:
                tp, thp = _hermite_extremum(theta, w, th1, w1, h)
                theta_max = max(theta_max, abs(thp))
                if counts[1] < peak_t.size:
                    peak_t[counts[1]] = (tau0 + s + tp) / p
                    peak_theta[counts[1]] = thp
                counts[1] += 1
            theta, w = th1, w1
            theta_max = max(theta_max, abs(theta))
            s = s_end if full else s + h
            # at the end of the interval the floor is at the next sample, where the next step starts
            theta_k1, w_k1, side_k1, accel_k1 = theta, w, side, (a1 if s >= dtau else a0 + slope * s)
            thdd_k1 = _track_pivot_forces(forces, theta, w, side, accel_k1, alpha, kappa)
        if disproved:
            break
        if overturned:
            if record:
                hist_theta[k + 1:] = np.nan
                hist_theta_dot[k + 1:] = np.nan
            break
        if record:
            hist_theta[k + 1] = theta
            hist_theta_dot[k + 1] = w * p
        k += 1
    return theta_max, uplift, overturned, overturn_time, impacts


@njit(cache=True, nogil=True)
def _cases(start, stop, accel_flat, offsets, dts, tails, record_index, alpha, p, e, kappa, friction_stop, theta_max,
           uplift, overturned, overturn_time, impacts, friction_demand, normal_min):
    """Cases start to stop − 1: case i is block (alpha[i], p[i], e[i], kappa[i]) from rest under record
    ``record_index[i]`` (:func:`assess.mechanics.threads.run_case_ranges`)."""
    empty = np.empty(0)
    for i in range(start, stop):
        j = record_index[i]
        counts = np.zeros(2, dtype=np.int64)
        forces = np.empty(2)
        out = _simulate(accel_flat[offsets[j]:offsets[j + 1]], dts[j], tails[j], alpha[i], p[i], e[i], kappa[i],
                        0.0, 0.0, empty, empty, empty, empty, empty, empty, counts, forces, friction_stop[i])
        theta_max[i] = out[0] / alpha[i]
        uplift[i] = out[1]
        overturned[i] = out[2]
        overturn_time[i] = out[3]
        impacts[i] = out[4]
        friction_demand[i] = forces[0]
        normal_min[i] = forces[1]


# --------------------------------------------------------------------------- API
@dataclass(frozen=True)
class RockingResult:
    """Response of one block to one floor motion (:func:`rocking_response`).

    Attributes
    ----------
    theta_max_over_alpha : float
        Peak |θ|/α over the motion [-]; (π/2)/α if the block overturned.
    uplift : bool
        Whether the block left rest at any time.
    overturned : bool
        Whether |θ| reached π/2.
    overturn_time_s : float
        Time [s] at which |θ| reached π/2; NaN if it did not.
    impacts : int
        Number of impacts (θ returning to zero), those of the final settling included.
    time_s, theta_rad, theta_dot_rad_s : ndarray or None
        With ``return_history``: sample times [s], rotation θ [rad] and angular
        velocity θ̇ [rad/s] at those times (NaN after overturning).
    impact_time_s, impact_theta_dot_rad_s : ndarray or None
        With ``return_history``: time [s] of each impact and θ̇ [rad/s] just
        before it (before the restitution). At most 4n + 4096 are kept
        (n samples); ``impacts`` counts them all.
    peak_time_s, peak_theta_rad : ndarray or None
        With ``return_history``: time [s] and signed θ [rad] of each local
        extremum of θ between impacts (θ̇ = 0), excluding the initial state.
    friction_demand_max : float
        Largest |F|/N the pivot needed while the block rocked [-] (0 if it
        never uplifted; inf if N reached zero). Pure rocking is the block's
        true motion only while this stays within μ_s.
    normal_force_min_over_weight : float
        Smallest N/(mg) at the pivot while the block rocked [-] (1 if it never
        uplifted); at or below zero the block would have left the floor.
    """

    theta_max_over_alpha: float
    uplift: bool
    overturned: bool
    overturn_time_s: float
    impacts: int
    friction_demand_max: float = 0.0
    normal_force_min_over_weight: float = 1.0
    time_s: np.ndarray | None = None
    theta_rad: np.ndarray | None = None
    theta_dot_rad_s: np.ndarray | None = None
    impact_time_s: np.ndarray | None = None
    impact_theta_dot_rad_s: np.ndarray | None = None
    peak_time_s: np.ndarray | None = None
    peak_theta_rad: np.ndarray | None = None


@dataclass(frozen=True)
class RockingPeaks:
    """Peak responses of many blocks to many records.

    Every field has shape (n_blocks, n_records) from :func:`rocking_peaks_batch`,
    (n_cases,) from :func:`rocking_case_peaks`; meanings and units as in
    :class:`RockingResult`.
    """

    theta_max_over_alpha: np.ndarray
    uplift: np.ndarray
    overturned: np.ndarray
    overturn_time_s: np.ndarray
    impacts: np.ndarray
    friction_demand_max: np.ndarray
    normal_force_min_over_weight: np.ndarray


def _check_block(alpha_rad, p_rad_s, restitution, inertia_ratio_value=4.0 / 3.0):
    alpha = np.atleast_1d(np.asarray(alpha_rad, dtype=float))
    p = np.atleast_1d(np.asarray(p_rad_s, dtype=float))
    kappa = np.atleast_1d(np.asarray(inertia_ratio_value, dtype=float))
    e = housner_restitution(alpha, kappa) if restitution is None else restitution
    alpha, p, e, kappa = np.broadcast_arrays(alpha, p, np.atleast_1d(np.asarray(e, dtype=float)), kappa)
    if alpha.ndim != 1:
        raise ValueError("alpha_rad, p_rad_s, restitution and inertia_ratio_value must be scalars "
                         "or 1-D arrays")
    if not np.all(np.isfinite(kappa) & (kappa >= 1.0)):
        raise ValueError("inertia_ratio_value (I_O/mR^2) must be >= 1")
    if not np.all((alpha > 0.0) & (alpha < _HALF_PI)):
        raise ValueError("alpha_rad must lie in (0, pi/2)")
    if not np.all(np.isfinite(p) & (p > 0.0)):
        raise ValueError("p_rad_s must be positive and finite")
    if not np.all((e >= 0.0) & (e <= 1.0)):
        raise ValueError("restitution must lie in [0, 1]")
    return (np.ascontiguousarray(alpha), np.ascontiguousarray(p), np.ascontiguousarray(e),
            np.ascontiguousarray(kappa))


def tail_intervals(tail_s, dt_s) -> int:
    """Sample intervals of floor at rest that cover ``tail_s`` seconds after a record.

    >>> tail_intervals(10.0, 0.005), tail_intervals(0.0, 0.01)
    (2000, 0)
    """
    tail_s = float(tail_s)
    if not (np.isfinite(tail_s) and tail_s >= 0.0):
        raise ValueError("tail_s must be finite and >= 0")
    return int(np.ceil(tail_s / float(dt_s) - 1e-9))


def rocking_response(floor_accel_g, dt_s, alpha_rad, p_rad_s, restitution=None, return_history=False,
                     initial_theta_rad=0.0, initial_theta_dot_rad_s=0.0,
                     inertia_ratio_value=4.0 / 3.0, tail_s=0.0) -> RockingResult:
    """Pure-rocking response of a rigid block to a floor acceleration record.

    Integrates the equation of motion of the module docstring ([1], eq. 1)
    with Housner impacts; see there for the sign convention (positive floor
    acceleration drives negative θ), rest and overturning.

    Parameters
    ----------
    floor_accel_g : array-like
        Floor acceleration ü_g/g [g] at times 0, dt, 2dt, ...; linear between
        samples, and zero from the last sample on (the floor is at
        rest after the record, a step at the last sample, as in every solver
        of :mod:`assess.mechanics.engine`).
    dt_s : float
        Sample interval [s].
    alpha_rad : float
        Slenderness α [rad], 0 < α < π/2.
    p_rad_s : float
        Frequency parameter p [rad/s].
    restitution : float, optional
        Coefficient of restitution of angular velocity e [-]; default Housner's
        value for the block's inertia ratio, 1 − (2/κ) sin²α (1 − 1.5 sin²α
        for a uniform block).
    return_history : bool
        Also return θ and θ̇ at the samples and the impacts and peaks.
    initial_theta_rad, initial_theta_dot_rad_s : float
        Initial rotation [rad] and angular velocity [rad/s]; default at rest.
    inertia_ratio_value : float
        κ = I_O/(mR²) [-], 4/3 for a uniform block; used for the pivot forces
        and the default restitution (p already contains it).
    tail_s : float
        Seconds followed after the last sample with the floor at rest
        (ceil(tail_s/dt) more intervals; the history covers them too).

    Returns
    -------
    RockingResult

    Examples
    --------
    A block with α = 0.16 rad needs ü_g > g tan α = 0.161 g to uplift; a
    floor at 0.15 g leaves it at rest, one at 0.3 g for 0.5 s makes it rock:

    >>> r = rocking_response([0.15] * 101, 0.01, 0.16, 1.25)
    >>> r.uplift, r.theta_max_over_alpha
    (False, 0.0)
    >>> r = rocking_response([0.3] * 51, 0.01, 0.16, 1.25, tail_s=5.0)
    >>> r.uplift, r.overturned, r.theta_max_over_alpha < 1.0
    (True, False, True)
    """
    accel, dt = checked_record(floor_accel_g, dt_s, min_samples=2)
    alpha, p, e, kappa = _check_block(alpha_rad, p_rad_s, restitution, inertia_ratio_value)
    if alpha.size != 1:
        raise ValueError("rocking_response takes one block; use rocking_peaks_batch for many")
    n_tail = tail_intervals(tail_s, dt)
    n = accel.size + n_tail
    counts = np.zeros(2, dtype=np.int64)
    if return_history:
        capacity = 4 * n + 4096
        hist_theta, hist_theta_dot = np.empty(n), np.empty(n)
        impact_t, impact_w = np.empty(capacity), np.empty(capacity)
        peak_t, peak_theta = np.empty(capacity), np.empty(capacity)
    else:
        hist_theta = hist_theta_dot = impact_t = impact_w = peak_t = peak_theta = np.empty(0)
    forces = np.empty(2)
    theta_max, uplift, overturned, overturn_time, impacts = _simulate(
        accel, dt, n_tail, alpha[0], p[0], e[0], kappa[0], float(initial_theta_rad), float(initial_theta_dot_rad_s),
        hist_theta, hist_theta_dot, impact_t, impact_w, peak_t, peak_theta, counts, forces, np.inf)
    extra = {}
    if return_history:
        n_imp, n_peak = min(counts[0], impact_t.size), min(counts[1], peak_t.size)
        extra = dict(time_s=np.arange(n) * dt, theta_rad=hist_theta, theta_dot_rad_s=hist_theta_dot,
                     impact_time_s=impact_t[:n_imp].copy(), impact_theta_dot_rad_s=impact_w[:n_imp].copy(),
                     peak_time_s=peak_t[:n_peak].copy(), peak_theta_rad=peak_theta[:n_peak].copy())
    return RockingResult(theta_max_over_alpha=float(theta_max / alpha[0]), uplift=bool(uplift),
                         overturned=bool(overturned), overturn_time_s=float(overturn_time),
                         impacts=int(impacts), friction_demand_max=float(forces[0]),
                         normal_force_min_over_weight=float(forces[1]), **extra)


def rocking_peaks_batch(records_g, dt_s, alpha_rad, p_rad_s, restitution=None,
                        inertia_ratio_value=4.0 / 3.0, tail_s=0.0) -> RockingPeaks:
    """Peak rocking responses of many blocks to one or more records, in parallel.

    Same model as :func:`rocking_response`, started from rest; only the peaks
    are kept, so memory grows with n_blocks × n_records, not with the record
    length. Runs on all numba threads (``numba.set_num_threads`` to limit).

    Parameters
    ----------
    records_g : array-like or sequence of array-like
        One floor acceleration record [g] (1-D) or a sequence of records of
        any lengths.
    dt_s : float or sequence of float
        Sample interval [s], one for all records or one per record.
    alpha_rad, p_rad_s, restitution, inertia_ratio_value : float or 1-D array-like
        Slenderness α [rad], frequency parameter p [rad/s], coefficient of
        restitution e [-] (default 1 − (2/κ) sin²α) and inertia ratio κ [-]
        (default 4/3) of each block, broadcast.
    tail_s : float
        Seconds followed after each record's last sample with the floor at rest.

    Returns
    -------
    RockingPeaks
        Fields of shape (n_blocks, n_records).

    Examples
    --------
    >>> peaks = rocking_peaks_batch([0.3] * 51, 0.01, [0.16, 0.4], 1.25, tail_s=5.0)
    >>> peaks.uplift[:, 0].tolist()
    [True, False]
    """
    records, dts = checked_records(records_g, dt_s, min_samples=2)
    alpha, p, e, kappa = _check_block(alpha_rad, p_rad_s, restitution, inertia_ratio_value)
    shape = (alpha.size, dts.size)
    block_index = np.repeat(np.arange(alpha.size), dts.size)
    record_index = np.tile(np.arange(dts.size), alpha.size)
    peaks = _run_cases(records, dts, record_index, alpha[block_index], p[block_index], e[block_index],
                       kappa[block_index], tail_s, np.full(block_index.size, np.inf))
    return RockingPeaks(**{name: value.reshape(shape) for name, value in vars(peaks).items()})


def rocking_case_peaks(records_g, dt_s, record_index, alpha_rad, p_rad_s, restitution=None,
                       inertia_ratio_value=4.0 / 3.0, tail_s=0.0, mu_static=None) -> RockingPeaks:
    """Peak rocking responses of many cases, case i a block under record ``record_index[i]``, in parallel.

    As :func:`rocking_peaks_batch`, for a list of (block, record) cases rather
    than every block under every record; the cases are spread over the threads
    a few at a time, so that long and short runs balance.

    Parameters
    ----------
    records_g : sequence of array-like
        Floor acceleration records [g], of any lengths.
    dt_s : float or sequence of float
        Sample interval [s], one for all records or one per record.
    record_index : array-like of int, shape (n_cases,)
        The record of each case.
    alpha_rad, p_rad_s, restitution, inertia_ratio_value : float or array-like (n_cases,)
        As in :func:`rocking_peaks_batch`, one per case (or one for all).
    tail_s : float
        Seconds followed after each record's last sample with the floor at rest.
    mu_static : float or array-like (n_cases,), optional
        Static friction coefficient of each case. With it, a run stops as soon as
        its pivot's friction demand |F|/N exceeds μ_s or its normal force
        reaches zero: pure rocking is then not the block's motion, which
        ``friction_demand_max > mu_static`` or ``normal_force_min_over_weight <= 0``
        says, and its other peaks are those up to that instant only.

    Returns
    -------
    RockingPeaks
        Fields of shape (n_cases,).

    Examples
    --------
    Two blocks under 0.3 g for 0.5 s: the slender one rocks, unless its
    friction cannot hold the pivot (μ_s = 0.05):

    >>> peaks = rocking_case_peaks([[0.3] * 51], 0.01, [0, 0, 0], [0.16, 0.4, 0.16], 1.25, tail_s=5.0,
    ...                            mu_static=[0.7, 0.7, 0.05])
    >>> peaks.uplift.tolist(), (peaks.friction_demand_max <= [0.7, 0.7, 0.05]).tolist()
    ([True, False, True], [True, True, False])
    """
    records, dts = checked_records(records_g, dt_s, min_samples=2)
    index = np.ascontiguousarray(np.asarray(record_index, dtype=np.int64))
    if index.ndim != 1 or (index.size and (index.min() < 0 or index.max() >= dts.size)):
        raise ValueError("record_index must be a 1-D array of indices into records_g")
    alpha, p, e, kappa = _check_block(alpha_rad, p_rad_s, restitution, inertia_ratio_value)
    stop = np.full(index.size, np.inf) if mu_static is None else np.asarray(mu_static, dtype=float)
    # a writable copy each: numba compiles the kernel again for a read-only array (np.broadcast_to's view
    # of an array already of the cases' shape is one), so one kernel serves every call
    alpha, p, e, kappa, stop = (np.array(np.broadcast_to(x, index.shape), dtype=float)
                                for x in (alpha, p, e, kappa, stop))
    return _run_cases(records, dts, index, alpha, p, e, kappa, tail_s, stop)


def _run_cases(records, dts, record_index, alpha, p, e, kappa, tail_s, friction_stop) -> RockingPeaks:
    accel_flat = np.ascontiguousarray(np.concatenate(records))
    offsets = np.zeros(len(records) + 1, dtype=np.int64)
    offsets[1:] = np.cumsum([r.size for r in records])
    tails = np.array([tail_intervals(tail_s, d) for d in dts], dtype=np.int64)
    n = record_index.size
    theta_max, overturn_time = np.empty(n), np.empty(n)
    uplift, overturned = np.zeros(n, dtype=np.bool_), np.zeros(n, dtype=np.bool_)
    impacts = np.zeros(n, dtype=np.int64)
    friction_demand, normal_min = np.empty(n), np.empty(n)
    run_case_ranges(_cases, n, accel_flat, offsets, dts, tails, record_index, alpha, p, e, kappa, friction_stop,
                    theta_max, uplift, overturned, overturn_time, impacts, friction_demand, normal_min)
    return RockingPeaks(theta_max_over_alpha=theta_max, uplift=uplift, overturned=overturned,
                        overturn_time_s=overturn_time, impacts=impacts,
                        friction_demand_max=friction_demand, normal_force_min_over_weight=normal_min)
