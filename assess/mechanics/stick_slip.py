"""One-way sliding with stick and slip: the sample loop written once, and each interface law over one interval.

A block that cannot uplift slides on the floor along one direction: u is its
displacement relative to the floor, the floor acceleration :math:`a_g` [g] is
sampled at a constant step dt and linear between samples, and a positive
:math:`a_g` drives a negative u. :func:`stick_slip_record` walks the samples
once for every interface law; inside a sample interval the law's own kernel
advances the block, event by event:

* ``COULOMB``: rigid-plastic friction, μ kinetic and μs static, integrated
  exactly (:func:`_coulomb_interval`; :mod:`assess.mechanics.sliding`);
* ``VELOCITY``: kinetic friction rising with the slip speed, RK4 on sub-steps
  with the end of a slide located by bisection (:func:`_velocity_interval`;
  :func:`assess.mechanics.interface.velocity_friction_response`);
* ``ELASTIC``: an elastic-perfectly-plastic interface, RK4 on sub-steps with
  yield and end of slip located by bisection (:func:`_elastic_interval`;
  :func:`assess.mechanics.interface.elastic_interface_response`).

A block at rest under the first two laws stays at rest over an interval whose
two samples are within ±μs (the floor is linear between them) and starts to
slide where :math:`|a_g|` first exceeds μs (:func:`slide_onset`: the
stick-slip rule of all three). The run-out after the last sample is each
law's own (the callers').
"""
from __future__ import annotations

import numpy as np
from numba import njit

#: Interface laws of :func:`stick_slip_record`.
COULOMB, VELOCITY, ELASTIC = 0, 1, 2
#: Events (stop, start, reversal) the exact Coulomb kernel resolves inside one interval. With a linear
#: a_g at most four occur (stop, stick, start, stop); the bound only guards against a round-off cycle.
_MAX_COULOMB_EVENTS = 16
#: Events (stop, start, yield, end of slip) the RK4 kernels resolve in one interval before they move on:
#: a guard against a round-off cycle only.
_MAX_INTERFACE_EVENTS = 64
_BISECTIONS = 60
_NO_ROOT = -1.0


@njit(cache=True)
def _velocity_root(v0, b, c, h):
    """First σ in (0, h] where v0 + bσ + cσ² reaches zero, or -1.

    ``v0`` is nonzero, or zero at the start of a slide (then the root at σ = 0 is
    not counted). Roots by the cancellation-free form q = -(b + sign(b)√Δ)/2.
    """
    if v0 == 0.0:
        if c == 0.0:
            return _NO_ROOT
        root = -b / c
        return root if 0.0 < root <= h else _NO_ROOT
    if c == 0.0:
        if b == 0.0:
            return _NO_ROOT
        root = -v0 / b
        return root if 0.0 < root <= h else _NO_ROOT
    disc = b * b - 4.0 * c * v0
    if disc < 0.0:
        return _NO_ROOT
    sq = np.sqrt(disc)
    q = -0.5 * (b + sq) if b >= 0.0 else -0.5 * (b - sq)
    best = _NO_ROOT
    r1 = q / c
    if 0.0 < r1 <= h:
        best = r1
    if q != 0.0:
        r2 = v0 / q
        if 0.0 < r2 <= h and (best < 0.0 or r2 < best):
            best = r2
    return best


@njit(cache=True, inline="always")
def slide_onset(a_here, a0, a1, mu_s, tau, dt):
    """The stick-slip rule for a block at rest ``tau`` seconds into a sample interval [s].

    The floor acceleration [g] is ``a0`` at the start of the interval, ``a1``
    at its end (``dt`` later), linear between, and ``a_here`` at ``tau``. The
    block stays stuck while :math:`|a_g| \\le \\mu_s`; it starts to slide, away
    from the floor's push, at the first instant :math:`|a_g|` exceeds μs: at
    once if it does at ``tau``, else where the line reaches ±μs. Returns
    (direction of sliding s: −1 for a_g > μs, +1 for a_g < −μs; the time it
    starts [s]; a_g then [g]; whether it stays stuck for the rest of the
    interval). The Coulomb and the velocity-friction kernels start a slide by it.

    The floor rises from 0 to 0.5 g over 1 s: it reaches μs = 0.25 halfway, and
    the block slides away from the push from then on:

    >>> slide_onset(0.0, 0.0, 0.5, 0.25, 0.0, 1.0)
    (-1, 0.5, 0.25, False)
    """
    if a_here > mu_s:
        return -1, tau, a_here, False
    if a_here < -mu_s:
        return 1, tau, a_here, False
    if a1 > mu_s:
        t_cross = (mu_s - a0) / (a1 - a0) * dt
        a_cross = mu_s
        s_new = -1
    elif a1 < -mu_s:
        t_cross = (-mu_s - a0) / (a1 - a0) * dt
        a_cross = -mu_s
        s_new = 1
    else:
        return 0, tau, a_here, True  # stuck for the rest of the interval
    if t_cross < tau:
        t_cross = tau
    if t_cross >= dt:
        return 0, tau, a_here, True  # starts at the next sample (round-off at the interval's end)
    return s_new, t_cross, a_cross, False


@njit(cache=True)
def _friction(speed, mu_min, mu_max, rate):
    """μ at sliding speed ``speed`` [m/s] ([2] eq. 1); continued smoothly for speed < 0."""
    return mu_max - (mu_max - mu_min) * np.exp(-rate * speed)


@njit(cache=True)
def _rk4_sliding(u, v, a_start, slope, h, s, mu_min, mu_max, rate, gravity):
    """One RK4 step of u' = v, v' = -g(a_g + s μ(s v)), a_g = a_start + slope t [g]."""
    a_mid = a_start + slope * 0.5 * h
    a_end = a_start + slope * h
    k1 = -gravity * (a_start + s * _friction(s * v, mu_min, mu_max, rate))
    v2 = v + 0.5 * h * k1
    k2 = -gravity * (a_mid + s * _friction(s * v2, mu_min, mu_max, rate))
    v3 = v + 0.5 * h * k2
    k3 = -gravity * (a_mid + s * _friction(s * v3, mu_min, mu_max, rate))
    v4 = v + h * k3
    k4 = -gravity * (a_end + s * _friction(s * v4, mu_min, mu_max, rate))
    u_new = u + h / 6.0 * (v + 2.0 * v2 + 2.0 * v3 + v4)
    v_new = v + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
    return u_new, v_new


@njit(cache=True)
def _rhs_interface(u, v, z, a_g, s, omega2, c_elastic, mu_g, gravity):
    """u'' of the interface: elastic (s = 0) or slipping with e = s u_y (s = ±1)."""
    if s == 0:
        return -gravity * a_g - omega2 * (u - z) - c_elastic * v
    return -gravity * a_g - s * mu_g


@njit(cache=True)
def _rk4_interface(u, v, z, a_start, slope, h, s, omega2, c_elastic, mu_g, gravity):
    a_mid = a_start + slope * 0.5 * h
    a_end = a_start + slope * h
    k1 = _rhs_interface(u, v, z, a_start, s, omega2, c_elastic, mu_g, gravity)
    u2 = u + 0.5 * h * v
    v2 = v + 0.5 * h * k1
    k2 = _rhs_interface(u2, v2, z, a_mid, s, omega2, c_elastic, mu_g, gravity)
    u3 = u + 0.5 * h * v2
    v3 = v + 0.5 * h * k2
    k3 = _rhs_interface(u3, v3, z, a_mid, s, omega2, c_elastic, mu_g, gravity)
    u4 = u + h * v3
    v4 = v + h * k3
    k4 = _rhs_interface(u4, v4, z, a_end, s, omega2, c_elastic, mu_g, gravity)
    return (u + h / 6.0 * (v + 2.0 * v2 + 2.0 * v3 + v4),
            v + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4))


@njit(cache=True)
def _interface_substep(u, v, z, s, a_start, slope, h, u_y, omega2, c_elastic, mu_g, gravity):
    """Advance one sub-step, stopping at the first yield or end-of-slip event.

    Returns (u, v, z, s, time advanced, event flag).
    """
    u1, v1 = _rk4_interface(u, v, z, a_start, slope, h, s, omega2, c_elastic, mu_g, gravity)
    if s == 0:
        e1 = u1 - z
        if abs(e1) <= u_y:
            return u1, v1, z, 0, h, False
        s_new = 1 if e1 > 0.0 else -1
        lo_s = 0.0
        hi_s = h
        for _ in range(_BISECTIONS):
            mid = 0.5 * (lo_s + hi_s)
            um, _vm = _rk4_interface(u, v, z, a_start, slope, mid, s, omega2, c_elastic, mu_g, gravity)
            if s_new * (um - z) < u_y:
                lo_s = mid
            else:
                hi_s = mid
        um, vm = _rk4_interface(u, v, z, a_start, slope, hi_s, s, omega2, c_elastic, mu_g, gravity)
        return um, vm, um - s_new * u_y, s_new, hi_s, True
    if s * v1 > 0.0:
        return u1, v1, u1 - s * u_y, s, h, False
    lo_s = 0.0
    hi_s = h
    for _ in range(_BISECTIONS):
        mid = 0.5 * (lo_s + hi_s)
        _um, vm = _rk4_interface(u, v, z, a_start, slope, mid, s, omega2, c_elastic, mu_g, gravity)
        if s * vm > 0.0:
            lo_s = mid
        else:
            hi_s = mid
    um, _vm = _rk4_interface(u, v, z, a_start, slope, hi_s, s, omega2, c_elastic, mu_g, gravity)
    return um, 0.0, um - s * u_y, 0, hi_s, True


@njit(cache=True)
def _coulomb_interval(a0, a1, dt, mu_s, u, v, s, u_hi, u_lo, slide_time, mu_k, gravity):
    """Exact Coulomb sliding over one interval (floor a0 to a1 [g] over dt [s]); returns the state after it,
    (u, u̇, s, peak +u, peak −u, slide time): s is 0 stuck, +1 / −1 sliding towards +u / −u."""
    slope = (a1 - a0) / dt  # [g/s]
    tau = 0.0  # time into the step [s]
    a_here = a0  # a_g at tau [g]; set exactly to ±mu_s when a slide starts at a crossing
    for _event in range(_MAX_COULOMB_EVENTS):
        if s == 0:
            s, tau, a_here, stuck = slide_onset(a_here, a0, a1, mu_s, tau, dt)
            if stuck:
                break
        # sliding in direction s from tau with velocity v (sign s, or 0 at a start)
        h = dt - tau
        b = -gravity * (a_here + s * mu_k)
        c = -0.5 * gravity * slope
        sigma = _velocity_root(v, b, c, h)
        if sigma < 0.0:
            v_end = v + (b + c * h) * h
            u += (v + (0.5 * b + c * h / 3.0) * h) * h
            slide_time += h
            if v_end * s <= 0.0:  # the root fell on the step end (round-off)
                v = 0.0
                s = 0
            else:
                v = v_end
            if u > u_hi:
                u_hi = u
            if u < u_lo:
                u_lo = u
            break
        u += (v + (0.5 * b + c * sigma / 3.0) * sigma) * sigma
        v = 0.0
        s = 0
        slide_time += sigma
        tau += sigma
        a_here = a0 + slope * tau
        if u > u_hi:
            u_hi = u
        if u < u_lo:
            u_lo = u
        if tau >= dt:
            break
    return u, v, s, u_hi, u_lo, slide_time


@njit(cache=True)
def _velocity_interval(a0, a1, dt, mu_s, u, v, s, u_hi, u_lo, slide_time, mu_min, mu_max, rate, gravity, h_sub):
    """Sliding with μ(u̇) over one interval, RK4 on sub-steps of at most ``h_sub`` [s]; state as
    :func:`_coulomb_interval`."""
    slope = (a1 - a0) / dt
    tau = 0.0
    events = 0
    while tau < dt and events < _MAX_INTERFACE_EVENTS:
        if s == 0:
            s, tau, _, stuck = slide_onset(a0 + slope * tau, a0, a1, mu_s, tau, dt)
            if stuck:
                break
            events += 1
        h = min(h_sub, dt - tau)
        if h <= 1e-12 * dt:
            break
        a_start = a0 + slope * tau
        u1, v1 = _rk4_sliding(u, v, a_start, slope, h, s, mu_min, mu_max, rate, gravity)
        if s * v1 > 0.0:
            u = u1
            v = v1
            tau += h
            slide_time += h
        else:  # u̇ back to zero inside the sub-step: bisect on the sub-step length
            lo_s = 0.0
            hi_s = h
            for _ in range(_BISECTIONS):
                mid = 0.5 * (lo_s + hi_s)
                _um, vm = _rk4_sliding(u, v, a_start, slope, mid, s, mu_min, mu_max, rate, gravity)
                if s * vm > 0.0:
                    lo_s = mid
                else:
                    hi_s = mid
            u, _vm = _rk4_sliding(u, v, a_start, slope, hi_s, s, mu_min, mu_max, rate, gravity)
            v = 0.0
            s = 0
            tau += hi_s
            slide_time += hi_s
            events += 1
        if u > u_hi:
            u_hi = u
        if u < u_lo:
            u_lo = u
    return u, v, s, u_hi, u_lo, slide_time


@njit(cache=True)
def _elastic_interval(a0, a1, dt, u, v, z, s, u_hi, u_lo, slip_time, u_y, omega2, c_elastic, mu_g, gravity, h_sub):
    """The elastic-perfectly-plastic interface over one interval, RK4 on sub-steps of ``h_sub`` [s]; state
    (u, u̇, plastic slip z, s: 0 elastic or ±1 slipping with e = s u_y, peaks, slip time)."""
    slope = (a1 - a0) / dt
    tau = 0.0
    events = 0
    while tau < dt:
        h = min(h_sub, dt - tau)
        if h <= 1e-12 * dt:
            break
        u, v, z, s_new, adv, event = _interface_substep(
            u, v, z, s, a0 + slope * tau, slope, h, u_y, omega2, c_elastic, mu_g, gravity)
        if s != 0:
            slip_time += adv
        s = s_new
        tau += adv
        if event:
            events += 1
            if events > _MAX_INTERFACE_EVENTS:  # round-off cycle: finish the step unresolved
                tau = dt
        if u > u_hi:
            u_hi = u
        if u < u_lo:
            u_lo = u
    return u, v, z, s, u_hi, u_lo, slip_time


@njit(cache=True)
def stick_slip_record(accel_g, n, dt, law, mu_s, constants, keep_history, u_out, v_out):
    """Integrate the block over the first ``n`` samples of ``accel_g`` [g] (step ``dt`` [s]) under ``law``.

    ``constants`` (six floats) are the law's: ``COULOMB`` (μ, g), ``VELOCITY``
    (μmin, μmax, rate a [s/m], g, sub-step [s]), ``ELASTIC`` (u_y [m], ω² [1/s²],
    2ζω [1/s], μg [m/s²], g, sub-step [s]), padded with zeros; ``mu_s`` is the
    static coefficient (unused by ``ELASTIC``, which has no rest state). If
    ``keep_history``, u and u̇ at the samples go to ``u_out`` and ``v_out``.
    Returns the state after the last sample: (u, u̇, z, s, peak +u, peak −u,
    slide time), for the law's run-out.
    """
    u = 0.0
    v = 0.0
    z = 0.0
    s = 0
    u_hi = 0.0
    u_lo = 0.0
    slide_time = 0.0
    if keep_history and n > 0:
        u_out[0] = 0.0
        v_out[0] = 0.0
    for k in range(n - 1):
        a0 = accel_g[k]
        a1 = accel_g[k + 1]
        if law != ELASTIC and s == 0 and abs(a0) <= mu_s and abs(a1) <= mu_s:  # stuck all step (a_g is linear)
            if keep_history:
                u_out[k + 1] = u
                v_out[k + 1] = 0.0
            continue
        if law == COULOMB:
            u, v, s, u_hi, u_lo, slide_time = _coulomb_interval(a0, a1, dt, mu_s, u, v, s, u_hi, u_lo, slide_time,
                                                                constants[0], constants[1])
        elif law == VELOCITY:
            u, v, s, u_hi, u_lo, slide_time = _velocity_interval(
                a0, a1, dt, mu_s, u, v, s, u_hi, u_lo, slide_time, constants[0], constants[1], constants[2],
                constants[3], constants[4])
        else:
            u, v, z, s, u_hi, u_lo, slide_time = _elastic_interval(
                a0, a1, dt, u, v, z, s, u_hi, u_lo, slide_time, constants[0], constants[1], constants[2],
                constants[3], constants[4], constants[5])
        if keep_history:
            u_out[k + 1] = u
            v_out[k + 1] = v
    return u, v, z, s, u_hi, u_lo, slide_time
