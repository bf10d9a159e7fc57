"""Sliding of a block on interfaces richer than Coulomb friction (no rocking).

Section 5 of [1] traces part of the misfit of the rigid-plastic (Coulomb)
model to two effects it lacks: a friction coefficient that is not constant
(pressure and velocity dependence of a PTFE-like interface, [2], [3]) and the
elasticity of the equipment legs, which makes the interface elastoplastic
rather than rigid-plastic ([1] §5; Makris & Black 2004). This module gives one
kernel for each; both return :class:`assess.mechanics.sliding.SlidingResult`
and follow the conventions of :func:`assess.mechanics.sliding.sliding_response`
so that callers can swap them:

* the floor acceleration :math:`a_g` is given in g, sampled at a constant step
  dt and taken piecewise linear between samples; a positive :math:`a_g` drives
  a negative relative displacement u;
* before the first sample the block rests on a floor at rest; after the last
  sample the floor is at rest (a_g = 0) and the block runs out until it rests.

Velocity-dependent friction (:func:`velocity_friction_response`)
----------------------------------------------------------------
The kinetic coefficient rises from μmin at vanishing velocity to μmax at large
velocity ([2] eq. 1, [3]):

.. math::

    \\mu(\\dot u) = \\mu_{max} - (\\mu_{max} - \\mu_{min})\\,e^{-a|\\dot u|},
    \\qquad
    \\ddot u = -a_g g - \\mu(\\dot u)\\, g\\,\\mathrm{sign}(\\dot u)
    \\ \\text{(sliding)}.

A stuck block starts to slide when :math:`|a_g| > \\mu_s`; :math:`\\mu_s`
defaults to μ(0) = μmin (so the law is continuous at the start of a slide).
While sliding one way, the state is advanced by classical fourth-order
Runge-Kutta on fixed sub-steps of at most 1 ms (and at most
0.25/(g(μmax - μmin)a), the stability limit of the velocity term); the instant
at which :math:`\\dot u` returns to zero is located by bisection on the
sub-step (to round-off), and the stick/slip test of ``sliding.py`` is applied
there. With μmin = μmax the sliding acceleration is linear in t and RK4 is
exact: the kernel reproduces the exact Coulomb kernel to round-off. The run-out
after the record is integrated in the velocity (composite Simpson):
:math:`\\Delta u = \\frac{1}{g}\\int_0^{|\\dot u|} \\frac{w\\,dw}{\\mu(w)}`,
:math:`\\Delta t = \\frac{1}{g}\\int_0^{|\\dot u|} \\frac{dw}{\\mu(w)}`.

Elastic-perfectly-plastic interface (:func:`elastic_interface_response`)
------------------------------------------------------------------------
The block (mass m) is held by an interface with initial stiffness
:math:`k = \\mu m g / u_y` that yields at the friction force μmg (a Bouc-Wen
element with a very large exponent; Makris & Black 2004). The relative
displacement is :math:`u = e + z`, elastic part :math:`|e| \\le u_y` plus
plastic slip z, with :math:`\\omega^2 = k/m = \\mu g / u_y`:

.. math::

    \\ddot u = -a_g g - \\omega^2 e - 2\\zeta\\omega\\,\\dot e,
    \\qquad \\dot e = \\dot u,\\ \\dot z = 0 \\ \\text{(elastic, } |e| < u_y),

    \\ddot u = -a_g g - \\mu g\\,\\mathrm{sign}(e),
    \\qquad \\dot e = 0,\\ \\dot z = \\dot u \\ \\text{(slipping, } |e| = u_y,
    \\ \\dot u\\,e > 0).

The viscous damping ratio ζ acts on the elastic stiffness only, i.e. it is
proportional to the current *tangent* stiffness (zero while slipping; cf.
Charney 2008 [4] on why damping proportional to the initial stiffness would
add a spurious dashpot during slip). Hence as :math:`u_y \\to 0` the model
tends to the Coulomb block whatever ζ. Elastic and slipping phases are
advanced by RK4 on fixed sub-steps of at most T/``steps_per_period``
(T = 2π/ω) that divide dt; the yield instant (|e| reaching u_y) and the end of
a slip (:math:`\\dot u` back to zero) are located by bisection.

After the record the floor is at rest. The run-out is integrated until the
interface is elastic with energy :math:`\\frac12\\dot u^2 + \\frac12\\omega^2 e^2
\\le \\frac12\\omega^2 u_y^2` (it can never yield again), and then one more
period to catch the last peak of |u|. **The residual is the plastic slip z at
that point**: the position at which the spring is unstressed and where a
damped block (ζ > 0) comes to rest; with ζ = 0 the block oscillates about it
forever with amplitude ≤ u_y. Peaks are taken over the sub-steps (sampling
error at most (π/steps_per_period)²/2 of the elastic amplitude).

References
----------
.. [1] Konstantinidis, D., Makris, N. (2010). Experimental and analytical
   studies on the response of 1/4-scale models of freestanding laboratory
   equipment subjected to strong earthquake shaking. Bull. Earthquake Eng.
   8:1457-1477, §5. doi:10.1007/s10518-010-9192-8
.. [2] Constantinou, M., Mokha, A., Reinhorn, A. (1990). Teflon bearings in
   base isolation. II: Modeling. J. Struct. Eng. 116(2):455-474.
   doi:10.1061/(ASCE)0733-9445(1990)116:2(455)
.. [3] Makris, N., Black, C. J. (2004). Dimensional analysis of bilinear
   oscillators under pulse-type excitations. J. Eng. Mech. 130(9):1019-1031.
   doi:10.1061/(ASCE)0733-9399(2004)130:9(1019)
.. [4] Charney, F. A. (2008). Unintended consequences of modeling damping in
   structures. J. Struct. Eng. 134(4):581-592.
   doi:10.1061/(ASCE)0733-9445(2008)134:4(581)
"""
from __future__ import annotations

import numpy as np
from numba import njit

from assess.mechanics.case_records import checked_record
from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2
from assess.mechanics.sliding import SlidingResult
from assess.mechanics.stick_slip import ELASTIC, VELOCITY, _friction, _interface_substep, stick_slip_record

#: Longest RK4 sub-step of the velocity-friction kernel [s].
_MAX_SUBSTEP_S = 1.0e-3
#: Bound on the velocity term's stiffness times the sub-step, g Δμ a h (RK4 is stable below 2.78).
_STIFFNESS_STEP = 0.25
#: Simpson intervals of the run-out quadrature (each of two pieces).
_RUNOUT_INTERVALS = 2000
#: Cap on the sub-steps of the run-out of the elastic interface.
_MAX_TAIL_SUBSTEPS = 50_000_000


# ----------------------------------------------------------------------------- shared
def _result(hi, lo, residual, slide_time, n, dt_s, return_history, u_hist, v_hist):
    history = {}
    if return_history:
        history = dict(time_s=np.arange(n) * dt_s, sliding_m=u_hist, sliding_velocity_m_s=v_hist)
    return SlidingResult(sliding_max_m=float(max(hi, lo)), sliding_residual_m=float(residual),
                         sliding_max_positive_m=float(hi), sliding_max_negative_m=float(lo),
                         slide_time_s=float(slide_time), **history)


# ----------------------------------------------------------------------------- velocity-dependent friction
@njit(cache=True)
def _simpson_runout(w_from, w_to, mu_min, mu_max, rate, intervals):
    """(∫ w/μ(w) dw, ∫ 1/μ(w) dw) over [w_from, w_to] by composite Simpson."""
    if w_to <= w_from:
        return 0.0, 0.0
    h = (w_to - w_from) / intervals
    dist = 0.0
    time = 0.0
    for i in range(intervals + 1):
        w = w_from + i * h
        weight = 1.0 if (i == 0 or i == intervals) else (4.0 if i % 2 == 1 else 2.0)
        inv = 1.0 / _friction(w, mu_min, mu_max, rate)
        dist += weight * w * inv
        time += weight * inv
    return dist * h / 3.0, time * h / 3.0


@njit(cache=True)
def _velocity_record(accel_g, n, dt, mu_min, mu_max, rate, mu_s, gravity, substep,
                     keep_history, u_out, v_out):
    """Stick-slip integration with μ(u̇) (:func:`~assess.mechanics.stick_slip.stick_slip_record`), then the
    run-out; returns (peak +u, peak -u magnitude, residual u, slide time)."""
    m = max(1, int(np.ceil(dt / substep - 1e-9)))
    h_sub = dt / m
    u, v, _, s, u_hi, u_lo, slide_time = stick_slip_record(accel_g, n, dt, VELOCITY, mu_s,
                                                           (mu_min, mu_max, rate, gravity, h_sub, 0.0),
                                                           keep_history, u_out, v_out)
    if s != 0 and v != 0.0:  # run-out on a floor at rest
        speed = abs(v)
        w_split = speed if rate <= 0.0 else min(speed, 30.0 / rate)  # resolve the e^{-a w} layer
        d1, t1 = _simpson_runout(0.0, w_split, mu_min, mu_max, rate, _RUNOUT_INTERVALS)
        d2, t2 = _simpson_runout(w_split, speed, mu_min, mu_max, rate, _RUNOUT_INTERVALS)
        u += np.sign(v) * (d1 + d2) / gravity
        slide_time += (t1 + t2) / gravity
        if u > u_hi:
            u_hi = u
        if u < u_lo:
            u_lo = u
    return u_hi, 0.0 - u_lo, u, slide_time


def velocity_friction_response(floor_accel_g, dt_s, mu_min, mu_max, rate_s_m, mu_static=None,
                               return_history=False, *, max_substep_s=None) -> SlidingResult:
    """Two-way sliding with a velocity-dependent kinetic friction coefficient (no rocking).

    .. math::

        \\mu(\\dot u) = \\mu_{max} - (\\mu_{max} - \\mu_{min})\\,e^{-a|\\dot u|},
        \\qquad
        \\ddot u = -a_g(t)\\,g - \\mu(\\dot u)\\,g\\,\\mathrm{sign}(\\dot u)\\ \\text{(sliding)},
        \\qquad \\text{stick while } \\dot u = 0,\\ |a_g| \\le \\mu_s

    ([2] eq. 1 with a = ``rate_s_m``; see the module docstring for the
    integration and the conventions at both ends of the record).

    Parameters
    ----------
    floor_accel_g : array-like, shape (n,)
        Floor acceleration [g] at t = 0, dt, ..., (n-1)dt; linear between samples.
    dt_s : float
        Sampling step [s].
    mu_min : float
        Kinetic friction coefficient at vanishing sliding velocity [-], > 0.
    mu_max : float
        Kinetic friction coefficient at large sliding velocity [-], ≥ ``mu_min``
        (friction rising with velocity, as for PTFE on steel [2]).
    rate_s_m : float
        Rate parameter a [s/m], ≥ 0 (PTFE: about 20-40 s/m [2]); a = 0 gives
        Coulomb friction μmin.
    mu_static : float, optional
        Static coefficient μs [-] for the start of a slide, ≥ ``mu_min``;
        defaults to μ(0) = ``mu_min``.
    return_history : bool
        Also return u and u̇ at the sample times.
    max_substep_s : float, optional
        Longest RK4 sub-step [s]; default min(1 ms, 0.25/(g(μmax - μmin)a)).

    Returns
    -------
    SlidingResult
        Peaks [m], residual [m], slide time [s] and optionally the histories.

    Examples
    --------
    With μmin = μmax the law is Coulomb: Newmark's rectangular pulse ap = 0.5 g,
    Tp = 1 s, μ = 0.25 gives Umax = ap Tp² (ap - μ)g/(2μ) = 2.4516625 m.

    >>> r = velocity_friction_response([0.5, 0.5], 1.0, 0.25, 0.25, 30.0)
    >>> round(r.sliding_max_m, 7), round(r.slide_time_s, 7)
    (2.4516625, 2.0)
    """
    accel, dt_s = checked_record(floor_accel_g, dt_s)
    mu_min = float(mu_min)
    mu_max = float(mu_max)
    rate = float(rate_s_m)
    mu_s = mu_min if mu_static is None else float(mu_static)
    if not (np.isfinite(mu_min) and mu_min > 0.0):
        raise ValueError("mu_min must be finite and > 0 (a block on a frictionless floor never stops)")
    if not (np.isfinite(mu_max) and mu_max >= mu_min):
        raise ValueError("mu_max must be finite and >= mu_min")
    if not (np.isfinite(rate) and rate >= 0.0):
        raise ValueError("rate_s_m must be finite and >= 0")
    if not (np.isfinite(mu_s) and mu_s >= mu_min):
        raise ValueError("mu_static must be finite and >= mu_min")
    if max_substep_s is None:
        stiffness = STANDARD_GRAVITY_M_S2 * (mu_max - mu_min) * rate
        substep = _MAX_SUBSTEP_S if stiffness <= 0.0 else min(_MAX_SUBSTEP_S, _STIFFNESS_STEP / stiffness)
    else:
        substep = float(max_substep_s)
        if not (np.isfinite(substep) and substep > 0.0):
            raise ValueError("max_substep_s must be finite and > 0")
    n = accel.shape[0]
    u_hist = np.empty(n if return_history else 0)
    v_hist = np.empty(n if return_history else 0)
    hi, lo, residual, slide_time = _velocity_record(
        accel, n, dt_s, mu_min, mu_max, rate, mu_s, STANDARD_GRAVITY_M_S2, substep,
        bool(return_history), u_hist, v_hist)
    return _result(hi, lo, residual, slide_time, n, dt_s, return_history, u_hist, v_hist)


# ----------------------------------------------------------------------------- elastoplastic interface
@njit(cache=True)
def _interface_record(accel_g, n, dt, mu, u_y, damping_ratio, gravity, steps_per_period,
                      keep_history, u_out, v_out):
    """The record (:func:`~assess.mechanics.stick_slip.stick_slip_record`), then the run-out; returns
    (peak +u, peak -u magnitude, residual slip z, slip time)."""
    omega2 = mu * gravity / u_y
    omega = np.sqrt(omega2)
    c_elastic = 2.0 * damping_ratio * omega
    mu_g = mu * gravity
    period = 2.0 * np.pi / omega
    h_target = period / steps_per_period
    m = max(1, int(np.ceil(dt / h_target - 1e-9)))
    h_sub = dt / m
    u, v, z, s, u_hi, u_lo, slip_time = stick_slip_record(accel_g, n, dt, ELASTIC, 0.0,
                                                          (u_y, omega2, c_elastic, mu_g, gravity, h_sub),
                                                          keep_history, u_out, v_out)
    # run-out on a floor at rest: until elastic below yield energy, then one more period for the peak
    energy_cap = 0.5 * omega2 * u_y * u_y * (1.0 + 1e-9)
    settled_time = -1.0
    for _i in range(_MAX_TAIL_SUBSTEPS):
        if s == 0 and settled_time < 0.0 and 0.5 * v * v + 0.5 * omega2 * (u - z) ** 2 <= energy_cap:
            settled_time = 0.0
        if settled_time >= period:
            break
        u, v, z, s_new, adv, event = _interface_substep(
            u, v, z, s, 0.0, 0.0, h_sub, u_y, omega2, c_elastic, mu_g, gravity)
        if s != 0:
            slip_time += adv
        s = s_new
        if settled_time >= 0.0:
            settled_time += adv
        if u > u_hi:
            u_hi = u
        if u < u_lo:
            u_lo = u
    return u_hi, 0.0 - u_lo, z, slip_time


def elastic_interface_response(floor_accel_g, dt_s, mu, yield_displacement_m, return_history=False, *,
                               damping_ratio=0.05, steps_per_period=200) -> SlidingResult:
    """Sliding of a block held by an elastic-perfectly-plastic interface ("elastic legs").

    .. math::

        \\ddot u = -a_g g - \\omega^2 e - 2\\zeta\\omega\\dot e, \\quad
        \\omega^2 = \\frac{\\mu g}{u_y}, \\quad u = e + z, \\quad |e| \\le u_y,

    with :math:`\\dot z = \\dot u` (slip) only while :math:`|e| = u_y` and
    :math:`\\dot u e > 0`: initial stiffness k = μmg/u_y, yield force μmg
    ([1] §5; [3]). See the module docstring for the damping, integration and
    the residual.

    Parameters
    ----------
    floor_accel_g : array-like, shape (n,)
        Floor acceleration [g] at t = 0, dt, ..., (n-1)dt; linear between samples.
    dt_s : float
        Sampling step [s].
    mu : float
        Friction coefficient [-], > 0: yield force / weight.
    yield_displacement_m : float
        Yield displacement u_y [m], > 0 (elastic deformation of the legs at the
        friction force). u_y → 0 gives the rigid-plastic (Coulomb) block.
    return_history : bool
        Also return u and u̇ at the sample times.
    damping_ratio : float
        Viscous damping ratio ζ [-] ≥ 0 of the elastic interface (on the tangent
        stiffness: no damping while slipping). Default 0.05.
    steps_per_period : int
        Minimum RK4 sub-steps per elastic period 2π√(u_y/(μg)); default 200.

    Returns
    -------
    SlidingResult
        ``sliding_max_m`` is the peak total |u| = |e + z| [m];
        ``sliding_residual_m`` is the plastic slip z after the run-out [m];
        ``slide_time_s`` the time spent slipping [s].

    Examples
    --------
    A quasi-static push of 0.1 g, below μ = 0.2: no slip, the legs deflect and
    spring back (peak |u| < 0.1/0.2 · u_y · 2 = u_y, the dynamic overshoot bound).

    >>> r = elastic_interface_response([0.1] * 11, 0.1, 0.2, 0.001)
    >>> r.sliding_residual_m, r.slide_time_s, r.sliding_max_m <= 0.001
    (0.0, 0.0, True)
    """
    accel, dt_s = checked_record(floor_accel_g, dt_s)
    mu = float(mu)
    u_y = float(yield_displacement_m)
    zeta = float(damping_ratio)
    if not (np.isfinite(mu) and mu > 0.0):
        raise ValueError("mu must be finite and > 0")
    if not (np.isfinite(u_y) and u_y > 0.0):
        raise ValueError("yield_displacement_m must be finite and > 0")
    if not (np.isfinite(zeta) and zeta >= 0.0):
        raise ValueError("damping_ratio must be finite and >= 0")
    if int(steps_per_period) < 8:
        raise ValueError("steps_per_period must be >= 8")
    n = accel.shape[0]
    u_hist = np.empty(n if return_history else 0)
    v_hist = np.empty(n if return_history else 0)
    hi, lo, residual, slip_time = _interface_record(
        accel, n, dt_s, mu, u_y, zeta, STANDARD_GRAVITY_M_S2, int(steps_per_period),
        bool(return_history), u_hist, v_hist)
    return _result(hi, lo, residual, slip_time, n, dt_s, return_history, u_hist, v_hist)
