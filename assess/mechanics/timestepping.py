"""General rigid-block solver by time-stepping complementarity (Moreau–Jean scheme).

Integrates the model of :mod:`assess.mechanics.block` (coordinates x, y, θ of
the centre of mass in the floor frame, two base corners with unilateral contact
and Coulomb friction) without assuming a mode: rest, sliding, rocking,
slide-rock and flight follow from the contact problem solved at every step.
Per unit mass, with :math:`q = (x, y, \\theta)`, :math:`M = \\mathrm{diag}(1, 1, J)`,
:math:`J = I_{cm}/m` and the generalised forces
:math:`f(t) = (-a_g(t)\\,g, -g, 0)`, a step of length Δt from :math:`t_k` is ([1]-[3])

.. math::

    q_{k+1/2} = q_k + \\tfrac{\\Delta t}{2} v_k, \\qquad
    M (v_{k+1} - v_k) = \\Delta t\\, f(t_k + \\tfrac{\\Delta t}{2})
        + \\sum_{c \\in I} \\left(w_{N,c} P_{N,c} + w_{T,c} P_{T,c}\\right), \\qquad
    q_{k+1} = q_k + \\tfrac{\\Delta t}{2} (v_k + v^*_{k+1})

where :math:`v^*_{k+1}` is :math:`v_{k+1}` computed with the same contact
states but the floor acceleration of :math:`t_k + \\Delta t/3` (for a force
linear in time,
:math:`q_k + \\Delta t\\,v_k + \\tfrac{\\Delta t^2}{2}\\ddot q(t_k + \\Delta t/3)` is
exact: the plain trapezoid leaves an error :math:`\\Delta t^3 \\dddot q/12` per
step, which dominates small rocks driven by a fast-changing input), with the
contact vectors of corner c (body offset ξ = ±b, η = −h) at :math:`q_{k+1/2}`:
:math:`w_N = (0, 1, -\\xi\\cos\\theta + h\\sin\\theta)` (gradient of the gap
:math:`g_N = y - \\xi\\sin\\theta - h\\cos\\theta`) and
:math:`w_T = (1, 0, -\\xi\\sin\\theta - h\\cos\\theta)` (tangential velocity
:math:`v_T = w_T\\cdot v`). A corner is *active* (c ∈ I) when it is on the floor at
the start of the step, :math:`g_N(q_k) \\le 10^{-12}R`, or would be at the middle
of the step, :math:`g_N(q_{k+1/2}) \\le 0` (Moreau's active set). For active
corners the impulses obey, at the velocity level,

.. math::

    0 \\le v_{N,c}^{k+1} \\perp P_{N,c} \\ge 0, \\qquad
    v_{T,c}^{k+1} = 0 \\Rightarrow |P_{T,c}| \\le \\mu_s P_{N,c}, \\qquad
    v_{T,c}^{k+1} \\ne 0 \\Rightarrow P_{T,c} = -\\mu P_{N,c}\\,\\mathrm{sgn}\\,v_{T,c}^{k+1}

i.e. Moreau's inelastic impact law (Newton restitution :math:`e_N = 0`) and the
Coulomb law of the model on the impulses. Housner's restitution is **not**
imposed: a rocking impact is the arrival of a corner with :math:`e_N = 0` while
the old pivot lifts, which conserves the angular momentum about the arriving
corner when it sticks, so :math:`e = 1 - (2/\\kappa)\\sin^2\\alpha` emerges.
The contact problem of a step, impacts, the projection back onto the floor
and the step's mode are those of :mod:`assess.mechanics.contact`.

**Events inside a step.** Four instants are located inside the step, which
is cut there and finished from them, so that the scheme keeps its accuracy
through them (event capturing with event location, as discussed in [3]):
a block at rest starts moving where :math:`|a_g|` crosses
:math:`\\min(\\mu_s, b/h)` (it is not stepped below that: it cannot move); a
corner arrives on the floor where its gap, quadratic in time under the
previous contact states, reaches zero (also a corner outside the active set
that would be below the floor at the end of the step); a slipping corner stops
where its tangential velocity, linear in time, passes zero, and is then tested
for sticking with μs on the rest of the step only; a lone sticking pivot starts
to slip where its cone margin :math:`\\mu_s P_N - |P_T|`, linear in
:math:`a_g` (from its values in the middle of the step and at its start or
end), passes zero.
The step up to an arrival or a slip onset is taken afresh with its own middle.


**Time step.** Each sample interval is cut into
:math:`n = \\max(k, \\lceil p\\,dt/\\epsilon\\rceil)` equal steps, ε =
``STEP_DIMENSIONLESS`` = 2e-3, k = ``MIN_STEPS_PER_SAMPLE`` = 4. While a corner
is off the floor, a step is cut further, into at most ``MAX_REFINEMENT`` = 16,
so that :math:`p\\Delta t \\le c\\,\\tau` with c = ``ROCK_STEP_FRACTION`` = 0.03
and :math:`\\tau = \\sqrt{2|\\theta|/\\alpha + (\\dot\\theta/p\\alpha)^2}` the
dimensionless time scale of the current rock (its duration is about 2τ/p under
the restoring acceleration p²α): a small rock gets some 60 steps, down to
rocks 16 times shorter than the ones that need no refinement.
With the located events the scheme is second order; at these steps peak
rotations under pulses and records agree with the rocking kernel to ~1e-6
(≤ 5e-4 on all 18 pyslammer records but one ill-conditioned) and sliding with
the exact kernel to ~1e-4 (see the tests). p·Δt, τ and the tolerances being
dimensionless, a block scaled by λ under the same accelerations compressed in
time by √λ takes the same steps (Froude similitude to round-off).


**Rocking on one sticking pivot.** At the start of a sample interval in
which the block rocks on one sticking corner with the other off the floor,
the interval is first integrated by the rocking kernel's equation of motion
and Runge-Kutta steps (:mod:`assess.mechanics.rocking`, for a block with p·dt
at most its largest step, 0.1; steps of at most 0.1 of the time scale τ of
the rock above, as the kernel takes them). The interval is kept if after
every step the other corner has stayed off the floor (θ keeps its sign on the
cubic Hermite interpolant of the step), the block has not reached π/2, and,
there and at the start, the pivot's normal force is positive and its friction
within μs N (the kernel's pivot forces); otherwise the Moreau–Jean steps take the interval,
locating the arrival, the slip onset or the lift-off as above. Such phases,
~94 % of the steps before, then take one step a sample (more in small rocks)
instead of 6-40. Against the event-driven solver, on the runs that the
rocking kernel hands on of 600 blocks (0.8-2.4 m, b/h 0.17-1.5, μ 0.1-0.7)
under the 18 pyslammer records (387 and 363 runs, two draws): θmax/α within
1e-6 and 7e-7 in the median run, 0.011 and 0.002 in one of 100, 0.022 and
0.013 at most (Moreau–Jean steps alone: 2e-6 and 1e-6, 0.016 and 0.003,
0.036 and 0.013), sliding within 0.5 mm in one of 100 and 0.7 mm at most
(steps alone 0.7 mm, 1.7 mm), overturning verdicts the same in all 750 (two
differ with the steps alone). The steps alone are taken when ``time_step_s``
is given.

**Trains of small rocks.** A block rocking a little near the uplift threshold
makes long trains of micro-rocks (the Kobe Takatori record at 0.6 on a 1.8 m
block with b/h = 0.3, μ = 0.33: θmax/α = 0.026, some 230 impacts). Energy is
neither gained nor lost there by the scheme because the arrival of every
corner off the floor is located (Moreau's active set alone, with the gap at the
middle of the step, misses a corner arriving in its second half), the impact
is an impulse at the start of the next step from a consistent velocity, a
single corner is projected vertically, the position update is exact for
linear forcing, slip onsets are located and small rocks get shorter steps.
The solver then converges at second order to the event-driven solver
(θmax/α 0.02606 at the default step without the rocking steps above, 0.02600
with steps of dt/1000, the event-driven 0.02600, same rests; with them
0.02599). Such responses stay ill-conditioned: the
event-driven θmax/α moves by 3 % when the record is scaled by 1 ± 1e-7, by a
factor 2 at 1 ± 1e-5, and the block overturns at 1 − 1e-4; a comparison on
them is meaningful to that extent only.

References
----------
.. [1] Moreau, J. J. (1988). Unilateral contact and dry friction in finite freedom
   dynamics. In: Nonsmooth Mechanics and Applications, CISM Courses and Lectures
   302, Springer, pp. 1-82. doi:10.1007/978-3-7091-2624-0_1
.. [2] Jean, M. (1999). The non-smooth contact dynamics method. Comput. Methods
   Appl. Mech. Eng. 177(3-4):235-257. doi:10.1016/S0045-7825(98)00383-1
.. [3] Acary, V., Brogliato, B. (2008). Numerical Methods for Nonsmooth Dynamical
   Systems. Lecture Notes in Applied and Computational Mechanics 35, Springer.
   doi:10.1007/978-3-540-75392-6
.. [4] Acary, V. (2013). Projected event-capturing time-stepping schemes for
   nonsmooth mechanical systems with unilateral contact and Coulomb's friction.
   Comput. Methods Appl. Mech. Eng. 256:224-250. doi:10.1016/j.cma.2012.12.012
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

from .block import MODES, Block, BlockResponse, summary_mode
from .case_records import checked_record, checked_records
from .contact import (CODE_REST, CODE_ROCK, CODE_SLIDE, OPEN, SLIP_POS, STICK, VELOCITY_RATIO, cone_margin,
                      contact_candidate,
                      corner_gap_at, corner_x_at, first_candidate, impact, lever_arms_at, project_onto_floor,
                      solve_contacts, step_mode)
from .geometry import STANDARD_GRAVITY_M_S2
from .rocking import MAX_STEP_DIMENSIONLESS as ROCKING_STEP_DIMENSIONLESS
from .rocking import MAX_REFINEMENT as _RIGID_MAX_REFINEMENT
from .rocking import ROCK_STEP_FRACTION as ROCKING_STEP_FRACTION
from .rocking import _hermite_extremum, _pivot_forces_and_rhs, _rk4_from
from .threads import run_case_ranges

#: Largest time step in dimensionless time, p·Δt [-].
STEP_DIMENSIONLESS = 2e-3
#: Fewest time steps per sample interval of the record [-].
MIN_STEPS_PER_SAMPLE = 4
#: Consistency tolerance of the contact problem, as a fraction of gΔt [-].
_CONTACT_TOLERANCE = 1e-10
#: A corner within this fraction of R of the floor at the start of a step is active [-].
_ACTIVE_GAP_RATIO = 1e-12
#: Arrivals located in one time step, at most (then Moreau's active set alone) [-].
_MAX_ARRIVALS_PER_STEP = 4
#: While a corner is off the floor, largest p·Δt as a fraction of the rock's time scale
#: :math:`\sqrt{2|\theta|/\alpha + (\dot\theta/p\alpha)^2}` [-].
ROCK_STEP_FRACTION = 0.03
#: Most steps a step is cut into for small rocks [-].
MAX_REFINEMENT = 16
_HALF_PI = 0.5 * np.pi


# --------------------------------------------------------------------------- time loop
@njit(cache=True)
def _rocking_step(q, hs, a_start, a_end, b, hcg, alpha, p, kappa, mu_s, act_tol):
    """The exact rocking equation over ``hs`` [s] for a block on one sticking pivot.

    The rocking kernel's Runge-Kutta steps (:mod:`assess.mechanics.rocking`) in τ = p t,
    as the kernel takes them (at most ``ROCK_STEP_FRACTION`` of the rock's time scale,
    down to 1/16 of p·hs), from θ, θ̇ of ``q``, the pivot (the corner on the side of θ)
    held where it is; taken only if the pivot's normal force is positive and its
    friction within μs N at the start and after every step, and after every step the
    other corner has stayed off the floor (the cubic Hermite interpolant of the step
    keeps θ on its side) and |θ| < π/2.
    Then ``q`` is updated and the largest |θ| returned; else ``q`` is left as it was
    and −1 returned, for the Moreau–Jean steps to take the interval with its events.
    """
    theta, w = q[2], q[5] / p
    side = 1.0 if theta > 0.0 else -1.0
    xi = side * b
    if theta == 0.0 or corner_gap_at(q[1], q[6], q[7], -xi, hcg) <= act_tol:
        return -1.0
    friction, normal, thdd = _pivot_forces_and_rhs(theta, w, side, a_start, alpha, kappa)
    if not (normal > 0.0 and abs(friction) <= mu_s * normal):
        return -1.0
    tau_all = p * hs
    slope = (a_end - a_start) / tau_all
    done, peak = 0.0, abs(theta)
    for _ in range(4 * _RIGID_MAX_REFINEMENT):
        if tau_all - done <= 1e-12 * tau_all:
            break
        h = min(tau_all - done, max(ROCKING_STEP_FRACTION * np.sqrt(2.0 * abs(theta) / alpha + (w / alpha) ** 2),
                                    tau_all / _RIGID_MAX_REFINEMENT))
        accel = a_start + slope * done
        th1, w1 = _rk4_from(theta, w, side, alpha, accel, slope, h, thdd)  # θ'' known with the pivot forces
        if not (0.0 < side * th1 < _HALF_PI):
            return -1.0
        if w * w1 < 0.0:
            thp = _hermite_extremum(theta, w, th1, w1, h)[1]
            if side * thp <= 0.0:
                return -1.0
            peak = max(peak, abs(thp))
        friction, normal, thdd = _pivot_forces_and_rhs(th1, w1, side, a_start + slope * (done + h), alpha, kappa)
        if not (normal > 0.0 and abs(friction) <= mu_s * normal):
            return -1.0
        theta, w, done = th1, w1, done + h
        peak = max(peak, abs(theta))
    else:
        return -1.0
    pivot_x = corner_x_at(q[0], q[6], q[7], xi, hcg)
    sin_t, cos_t = np.sin(theta), np.cos(theta)
    rate = w * p
    q[0], q[1], q[2] = pivot_x - xi * cos_t + hcg * sin_t, xi * sin_t + hcg * cos_t, theta
    q[3], q[4], q[5] = (xi * sin_t + hcg * cos_t) * rate, (xi * cos_t - hcg * sin_t) * rate, rate
    q[6], q[7] = sin_t, cos_t
    return peak


@njit(cache=True, inline="always")
def _event_fraction(pm, pp, relocate, v, vcc, pnm, pnp, g0_m, g0_p, vx, vy, w, h, rn_m, rn_p, rt_m, rt_p, tol):
    """Fraction of the step at which a corner arrives or a slip reverses (1 if neither).

    With ``relocate`` (the contact states changed in the step) the velocity is
    that of the previous contact states ("carry on"), else the solved one ``v``;
    (``vcc``, with its normal impulses ``pnm`` and ``pnp``, from :func:`contact_candidate`);
    either is linear in the step, so an open corner's gap is quadratic in the
    fraction τ (its first zero found by bisection) and a slipping corner's
    tangential velocity passes zero at :math:`\\tau = v_{T,k}/(v_{T,k} - v_{T,k+1})`.
    Open corners include those off the floor and outside Moreau's active set
    (one that arrives in the second half of the step).
    Returns (τ, end velocity, whether it is "carry on", arriving corner: −1, +1, or 0 for a slip reversal).
    """
    vc, carry = v, False
    if relocate:
        if min(pnm, pnp) >= -tol:  # else a lift-off: no velocity jump, only arrivals to locate
            vc, carry = vcc, True
    frac, arrived = 1.0, 0
    for side, g0, st, rn, rt in ((-1, g0_m, pm, rn_m, rt_m), (1, g0_p, pp, rn_p, rt_p)):
        if st == OPEN:
            vn0, vn1 = vy + rn * w, vc[1] + rn * vc[2]
            if g0 > 0.0 and g0 + 0.5 * h * (vn0 + vn1) < 0.0:
                lo, hi = 0.0, 1.0
                for _ in range(40):
                    mid = 0.5 * (lo + hi)
                    if g0 + h * mid * (vn0 + 0.5 * mid * (vn1 - vn0)) > 0.0:
                        lo = mid
                    else:
                        hi = mid
                if lo < frac:
                    frac, arrived = lo, side
        elif carry and st != STICK:
            s = 1.0 if st == SLIP_POS else -1.0
            vt0, vt1 = vx + rt * w, vc[0] + rt * vc[2]
            if s * vt0 > 0.0 and s * vt1 < 0.0 and vt0 / (vt0 - vt1) < frac:
                frac, arrived = vt0 / (vt0 - vt1), 0
    return frac, vc, carry, arrived


@njit(cache=True)
def _step(q, h, a_mid, a_change, prev_m, prev_p, b, hcg, radius, inv_j, mu, mu_s, gravity, e_override, split,
          locate):
    """One Moreau–Jean step of length h from q = [x, y, θ, ẋ, ẏ, θ̇], updated in place.

    The floor acceleration is ``a_mid`` in the middle of the step and changes by
    ``a_change`` over it. A corner that starts the step on the floor, open and
    moving into it, is an impact: its impulses are applied first
    (:func:`impact`), then the step is taken from the velocity after it. With
    ``split``, a step in which the contact states change because a corner
    arrives on the floor, the slip of a slipping corner would reverse or a lone
    sticking pivot leaves its friction cone is taken only up to that instant;
    with ``locate``, so is a step in which a corner off the floor would arrive
    (:func:`_event_fraction`). The impact, the slip, or the stick test of the
    stopped corner (handed on as sticking, so μs applies to the rest of the step
    alone, as in the exact sliding kernel) is left to the rest of the step.
    ``q[6]``, ``q[7]`` hold sin θ and cos θ, kept so (each angle's sine and
    cosine are worked out once).
    ``radius`` is R = √(b² + h²) [m]. Returns (state−, state+, fraction of the step taken, mode).
    """
    tol = _CONTACT_TOLERANCE * gravity * h
    x, y, theta, vx, vy, w = q[0], q[1], q[2], q[3], q[4], q[5]
    act_tol = _ACTIVE_GAP_RATIO * radius
    sin_t, cos_t = q[6], q[7]
    g0_m, g0_p = corner_gap_at(y, sin_t, cos_t, -b, hcg), corner_gap_at(y, sin_t, cos_t, b, hcg)
    on_m, on_p = g0_m <= act_tol, g0_p <= act_tol
    if (on_m and prev_m == OPEN) or (on_p and prev_p == OPEN):
        prev_m, prev_p, vx, vy, w = impact(vx, vy, w, theta, prev_m, prev_p, on_m, on_p, b, hcg, inv_j, mu, mu_s,
                                           e_override, tol, VELOCITY_RATIO * np.sqrt(gravity * radius))
    theta_mid, y_mid = theta + 0.5 * h * w, y + 0.5 * h * vy
    sin_mid, cos_mid = np.sin(theta_mid), np.cos(theta_mid)
    act_m = on_m or corner_gap_at(y_mid, sin_mid, cos_mid, -b, hcg) <= 0.0
    act_p = on_p or corner_gap_at(y_mid, sin_mid, cos_mid, b, hcg) <= 0.0
    rn_m, rt_m = lever_arms_at(-b, sin_mid, cos_mid, hcg)
    rn_p, rt_p = lever_arms_at(b, sin_mid, cos_mid, hcg)
    vf = (vx - h * a_mid * gravity, vy - h * gravity, w)
    pm, pp = (prev_m if act_m else OPEN), (prev_p if act_p else OPEN)
    # the previous states' candidate, the first that solve_contacts tries: kept if it holds
    v0, pnm0, ptm0, pnp0, ptp0 = vf, 0.0, 0.0, 0.0, 0.0
    if act_m or act_p:
        held, v0, pnm0, ptm0, pnp0, ptp0 = first_candidate(pm, pp, act_m, act_p, vf, rn_m, rt_m, rn_p, rt_p, inv_j,
                                                           mu, mu_s, tol)
        if held:
            st_m, st_p, v = pm, pp, v0
        else:
            st_m, st_p, v, _, _ = solve_contacts(pm, pp, act_m, act_p, vf, rn_m, rt_m, rn_p, rt_p, inv_j, mu, mu_s,
                                                 tol)
    else:
        st_m, st_p, v = OPEN, OPEN, vf
    frac, event = 1.0, 0  # event: 0 none or a slip reversal, ±1 the corner that arrives, 2 a slip onset
    relocate = split and (st_m != pm or st_p != pp)
    if relocate or (locate and (pm == OPEN or pp == OPEN)):
        frac, vc, carry, event = _event_fraction(pm, pp, relocate, v, v0, pnm0, pnp0, g0_m, g0_p, vx, vy, w, h,
                                                 rn_m, rn_p, rt_m, rt_p, tol)
        if frac < 1.0:
            if carry:
                st_m, st_p = pm, pp
            elif event == -1:  # (after a lift-off) the arriving corner is off the floor up to its arrival
                st_m = OPEN
            elif event == 1:
                st_p = OPEN
            if event == 0:  # a slip reverses: its corner stops at the end of the (linear) velocity
                v = (vx + frac * (vc[0] - vx), vy + frac * (vc[1] - vy), w + frac * (vc[2] - w))
    if split and frac == 1.0 and ((pm == STICK and pp == OPEN and st_p == OPEN and st_m != OPEN)
                                  or (pp == STICK and pm == OPEN and st_m == OPEN and st_p != OPEN)):
        # a lone sticking pivot: where does its cone margin, linear in the floor acceleration, change sign?
        kept = (st_m if pm == STICK else st_p) == STICK
        c_mid = mu_s * pnm0 - abs(ptm0) if pm == STICK else mu_s * pnp0 - abs(ptp0)  # cone_margin at vf
        a_end = a_mid + (0.5 if kept else -0.5) * a_change  # the end of the step, or its start
        c_end = cone_margin(pm, pp, (vx - h * a_end * gravity, vf[1], w), rn_m, rt_m, rn_p, rt_p, inv_j, mu, mu_s)
        if kept and c_mid >= 0.0 > c_end:
            frac, event = 0.5 + 0.5 * c_mid / (c_mid - c_end), 2
        elif not kept and c_end > 0.0 > c_mid:
            frac, event = 0.5 * c_end / (c_end - c_mid), 2
        if event == 2:
            st_m, st_p = pm, pp
    if frac < 1.0:
        h *= frac
    a_step = a_mid - 0.5 * (1.0 - frac) * a_change  # the floor acceleration in the middle of the step taken
    if event != 0:  # taken up to an arrival or a slip onset: afresh, with its own middle
        theta_mid = theta + 0.5 * h * w
        sin_mid, cos_mid = np.sin(theta_mid), np.cos(theta_mid)
        rn_m, rt_m = lever_arms_at(-b, sin_mid, cos_mid, hcg)
        rn_p, rt_p = lever_arms_at(b, sin_mid, cos_mid, hcg)
        vf = (vx - h * a_step * gravity, vy - h * gravity, w)
        _, v, _, _, _, _ = contact_candidate(st_m, st_p, True, True, vf, rn_m, rt_m, rn_p, rt_p, inv_j, mu, mu_s)
    override = e_override >= 0.0 and ((st_m == STICK and pm == OPEN and st_p == OPEN and pp != OPEN)
                                      or (st_p == STICK and pp == OPEN and st_m == OPEN and pm != OPEN))
    if override:  # rocking impact inside the step (not located): rotation about the arriving corner at e θ̇ before
        rn, rt = (rn_m, rt_m) if st_m == STICK else (rn_p, rt_p)
        v = (-rt * e_override * w, -rn * e_override * w, e_override * w)
    # positions: the velocity at the end of the step with the floor acceleration of t + Δt/3 instead
    # of t + Δt/2 (same contact states), so that a force linear in time is integrated exactly
    vq = v
    if a_change != 0.0 and not override and not (frac < 1.0 and event == 0) and not (
            st_m == STICK and st_p == STICK):
        vfq = (vx - h * (a_step - a_change * frac / 6.0) * gravity, vy - h * gravity, w)
        _, vq, _, _, _, _ = contact_candidate(st_m, st_p, True, True, vfq, rn_m, rt_m, rn_p, rt_p, inv_j, mu, mu_s)
    # a pivot that sticks on keeps its place on the floor
    keep_m = pm == STICK and st_m == STICK and st_p == OPEN
    keep_p = pp == STICK and st_p == STICK and st_m == OPEN
    anchor = corner_x_at(x, sin_t, cos_t, b if keep_p else -b, hcg)
    x += 0.5 * h * (vx + vq[0])
    y += 0.5 * h * (vy + vq[1])
    theta += 0.5 * h * (w + vq[2])
    sin_t, cos_t = np.sin(theta), np.cos(theta)
    # an arriving corner is put on the floor, to be taken as an impact by the next step
    fix_m = st_m != OPEN or event == -1 or corner_gap_at(y, sin_t, cos_t, -b, hcg) < 0.0
    fix_p = st_p != OPEN or event == 1 or corner_gap_at(y, sin_t, cos_t, b, hcg) < 0.0
    if fix_m != fix_p:  # one corner: a vertical shift (project_onto_floor), θ as integrated
        y -= corner_gap_at(y, sin_t, cos_t, -b if fix_m else b, hcg)
    elif fix_m:
        y, theta = project_onto_floor(y, theta, True, True, b, hcg, inv_j, 1e-15 * radius)
        sin_t, cos_t = np.sin(theta), np.cos(theta)
    if keep_m or keep_p:
        x += anchor - corner_x_at(x, sin_t, cos_t, b if keep_p else -b, hcg)
    # contact states of the step, gaps at its end, velocities in its middle
    v_mid = (0.5 * (vx + v[0]), 0.5 * (vy + v[1]), 0.5 * (w + v[2]))
    mode = step_mode(st_m, st_p, v_mid, rn_m, rt_m, rn_p, rt_p, corner_gap_at(y, sin_t, cos_t, -b, hcg),
                     corner_gap_at(y, sin_t, cos_t, b, hcg), radius, gravity)
    if st_m == STICK and st_p == STICK:
        v = (0.0, 0.0, 0.0)
    if frac < 1.0 and event == 0:  # the reversing corners have stopped
        st_m = STICK if st_m >= SLIP_POS and abs(v[0] + rt_m * v[2]) <= 1e-9 * abs(vx) + tol else st_m
        st_p = STICK if st_p >= SLIP_POS and abs(v[0] + rt_p * v[2]) <= 1e-9 * abs(vx) + tol else st_p
    q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7] = x, y, theta, v[0], v[1], v[2], sin_t, cos_t
    return st_m, st_p, frac, mode


@njit(cache=True)
def _simulate(accel_g, dt_s, n_sub, tail_steps, b, hcg, inv_j, mu, mu_s, gravity, e_override, theta0,
              hist_u, hist_theta, mode_t, mode_c, rocking_steps):
    """Integrate one block over one record and its run-out.

    History arrays of size 0 are not written; ``mode_t``/``mode_c`` of size 0
    keep no mode sequence (otherwise they grow as needed). A block at rest is
    not stepped while :math:`|a_g| \\le \\min(\\mu_s, b/h)` (it cannot move); the
    step in which that bound is crossed starts at the crossing. Returns (u_max,
    u_residual, θ_max, uplift, overturned, overturn time, visited-mode bit mask,
    samples written, mode_t, mode_c, modes written).
    """
    h = dt_s / n_sub
    hold = min(mu_s, b / hcg)
    alpha, radius = np.arctan(b / hcg), np.hypot(b, hcg)
    p = np.sqrt(gravity * radius / (1.0 / inv_j + radius * radius))
    kappa = (1.0 / inv_j + radius * radius) / (radius * radius)
    hybrid = rocking_steps and p * dt_s <= ROCKING_STEP_DIMENSIONLESS
    keep_hist, keep_modes = hist_u.size > 0, mode_t.size > 0
    n = accel_g.size
    # at rest flat, or at rest on one corner at θ0 with that corner where it stood
    side0 = 1.0 if theta0 >= 0.0 else -1.0
    q = np.array([hcg * np.sin(theta0) + side0 * b * (1.0 - np.cos(theta0)),
                  side0 * b * np.sin(theta0) + hcg * np.cos(theta0), theta0, 0.0, 0.0, 0.0, np.sin(theta0),
                  np.cos(theta0)])  # and sin θ, cos θ (:func:`_step`)
    st_m = STICK if theta0 <= 0.0 else OPEN
    st_p = STICK if theta0 >= 0.0 else OPEN
    resting = theta0 == 0.0
    mode = CODE_REST if resting else CODE_ROCK
    u = q[0] - hcg * np.sin(theta0) - b * np.sign(theta0) * (1.0 - np.cos(theta0))
    u_max, theta_max = abs(u), abs(theta0)
    uplift, overturned, t_over = not resting, False, np.nan
    visited = 1 << mode
    n_hist = n_modes = 0
    if keep_hist:
        hist_u[0], hist_theta[0] = u, theta0
        n_hist = 1
    if keep_modes:
        mode_t[0], mode_c[0] = 0.0, mode
        n_modes = 1
    # a block at rest at a sample stays so over every following interval whose two samples are within the
    # bound (the floor is linear between them); the margin covers the round-off of the per-step interpolation
    hold_whole = hold * (1.0 - 1e-12)
    n_steps = (n - 1) * n_sub + tail_steps
    step = 0
    while step < n_steps:
        k = step // n_sub
        if resting and step % n_sub == 0 and k < n - 1:
            k_rest = k
            while k_rest < n - 1 and abs(accel_g[k_rest]) < hold_whole and abs(accel_g[k_rest + 1]) < hold_whole:
                k_rest += 1
            if k_rest > k:  # skipped at once, as the steps would leave it: unmoved
                while keep_hist and k < k_rest and n_hist < hist_u.size:
                    hist_u[n_hist], hist_theta[n_hist] = u, q[2]
                    n_hist += 1
                    k += 1
                step = k_rest * n_sub
                continue
        if k < n - 1:
            a0 = accel_g[k] + (accel_g[k + 1] - accel_g[k]) * (step - k * n_sub) / n_sub
            a1 = accel_g[k] + (accel_g[k + 1] - accel_g[k]) * (step - k * n_sub + 1) / n_sub
        else:
            a0 = a1 = 0.0
        start = 0.0
        if hybrid and step % n_sub == 0 and ((st_m == STICK and st_p == OPEN) or (st_p == STICK and st_m == OPEN)):
            # rocking on one sticking pivot: the exact rocking equation over the sample interval, if it holds
            span = min(n_sub, n_steps - step)
            a_end = accel_g[k + 1] if k < n - 1 else 0.0
            peak = _rocking_step(q, span * h, a0, a_end, b, hcg, alpha, p, kappa, mu_s, _ACTIVE_GAP_RATIO * radius)
            if peak >= 0.0:
                visited |= 1 << CODE_ROCK
                if keep_modes and mode_c[n_modes - 1] != CODE_ROCK:
                    if n_modes == mode_t.size:
                        mode_t = np.concatenate((mode_t, np.empty_like(mode_t)))
                        mode_c = np.concatenate((mode_c, np.empty_like(mode_c)))
                    mode_t[n_modes], mode_c[n_modes] = step * h, CODE_ROCK
                    n_modes += 1
                theta_max = max(theta_max, peak)
                step += span
                if keep_hist and step % n_sub == 0 and n_hist < hist_u.size:
                    hist_u[n_hist], hist_theta[n_hist] = u, q[2]
                    n_hist += 1
                continue
        if resting:
            if k >= n - 1 and step % n_sub == 0:
                break  # at rest after the record: the run-out is over
            if abs(a0) <= hold and abs(a1) <= hold:
                start = 1.0
            elif abs(a0) <= hold:
                start = ((hold if a1 > hold else -hold) - a0) / (a1 - a0)
        sub, end = 0, 1.0
        while start < 1.0 and not overturned:
            if sub == 0:  # a new (sub)step: refined while the block rocks a little
                m = 1
                if st_m == OPEN or st_p == OPEN:
                    scale = np.sqrt(2.0 * abs(q[2]) / alpha + (q[5] / (p * alpha)) ** 2)
                    m = MAX_REFINEMENT
                    if p * h < MAX_REFINEMENT * ROCK_STEP_FRACTION * scale:
                        m = max(1, int(np.ceil(p * h / (ROCK_STEP_FRACTION * scale))))
                end = min(1.0, (np.floor(start * m + 1e-9) + 1.0) / m)
            theta_start = q[2]
            a_start, a_end = a0 + (a1 - a0) * start, a0 + (a1 - a0) * end
            st_m, st_p, frac, mode = _step(q, (end - start) * h, 0.5 * (a_start + a_end), a_end - a_start, st_m, st_p,
                                           b, hcg, radius, inv_j, mu, mu_s, gravity, e_override, sub == 0,
                                           sub < _MAX_ARRIVALS_PER_STEP)
            t_start = (step + start) * h
            start, sub = (end, 0) if frac == 1.0 else (start + frac * (end - start), sub + 1)
            resting = st_m == STICK and st_p == STICK
            visited |= 1 << mode
            uplift = uplift or (mode != CODE_REST and mode != CODE_SLIDE)
            if keep_modes and mode != mode_c[n_modes - 1]:
                if n_modes == mode_t.size:
                    mode_t = np.concatenate((mode_t, np.empty_like(mode_t)))
                    mode_c = np.concatenate((mode_c, np.empty_like(mode_c)))
                mode_t[n_modes], mode_c[n_modes] = t_start, mode
                n_modes += 1
            if abs(q[2]) >= _HALF_PI:
                reach = (_HALF_PI - abs(theta_start)) / (abs(q[2]) - abs(theta_start))
                overturned, theta_max = True, _HALF_PI
                t_over = t_start + (step * h + start * h - t_start) * min(1.0, max(0.0, reach))
            else:
                u = q[0] - hcg * q[6] - b * np.sign(q[2]) * (1.0 - q[7])
                u_max, theta_max = max(u_max, abs(u)), max(theta_max, abs(q[2]))
        if overturned:
            break
        if keep_hist and (step + 1) % n_sub == 0 and n_hist < hist_u.size:
            hist_u[n_hist], hist_theta[n_hist] = u, q[2]
            n_hist += 1
        step += 1
    return u_max, u, theta_max, uplift, overturned, t_over, visited, n_hist, mode_t, mode_c, n_modes


@njit(cache=True, nogil=True)
def _cases(start, stop, accel_flat, offsets, dts, record_index, n_sub, tail_steps, b, hcg, inv_j, mu, mu_s, gravity,
           e_override, rocking_steps, u_max, u_res, theta_max, uplift, overturned, t_over, visited):
    """Cases start to stop − 1: case i is block i (its constants at index i) from rest under record
    ``record_index[i]`` (:func:`assess.mechanics.threads.run_case_ranges`)."""
    empty, empty_c = np.empty(0), np.empty(0, dtype=np.int64)
    for i in range(start, stop):
        j = record_index[i]
        out = _simulate(accel_flat[offsets[j]:offsets[j + 1]], dts[j], n_sub[i], tail_steps[i], b[i],
                        hcg[i], inv_j[i], mu[i], mu_s[i], gravity, e_override[i], 0.0, empty, empty, empty,
                        empty_c, rocking_steps[i])
        u_max[i], u_res[i], theta_max[i] = out[0], out[1], out[2]
        uplift[i], overturned[i], t_over[i], visited[i] = out[3], out[4], out[5], out[6]


# --------------------------------------------------------------------------- API
def _steps(block, dt_s, time_step_s, tail_s):
    """Steps per sample interval and steps of run-out for one block and one record."""
    if time_step_s is None:
        n_sub = max(MIN_STEPS_PER_SAMPLE, int(np.ceil(block.p_rad_s * dt_s / STEP_DIMENSIONLESS - 1e-9)))
    else:
        if not (np.isfinite(time_step_s) and time_step_s > 0.0):
            raise ValueError("time_step_s must be finite and > 0")
        n_sub = max(1, int(np.ceil(dt_s / time_step_s - 1e-9)))
    if not (np.isfinite(tail_s) and tail_s >= 0.0):
        raise ValueError("tail_s must be finite and >= 0")
    return n_sub, int(np.ceil(tail_s / (dt_s / n_sub) - 1e-9))


def _block_constants(block):
    """(b_c, h, 1/J, μ, μs, restitution override or −1) of a block; b_c is where it stands (feet)."""
    e = -1.0 if block.restitution is None else float(block.restitution)
    return (block.contact_half_width_m, block.cg_height_m, 1.0 / block.inertia_cm_over_mass_m2, block.mu,
            block.mu_static, e)


def simulate_time_stepping(block: Block, floor_accel_g, dt_s, *, time_step_s=None, tail_s=10.0,
                           return_history=False, initial_theta_rad=0.0) -> BlockResponse:
    """Response of a rigid block to a floor motion by Moreau–Jean time-stepping.

    .. math::

        M(v_{k+1} - v_k) = \\Delta t\\,f(t_{k+1/2}) + W^T P, \\qquad
        q_{k+1} = q_k + \\tfrac{\\Delta t}{2}(v_k + v_{k+1}),

    with unilateral contact (impact law :math:`e_N = 0`) and Coulomb friction on
    the impulses P of the active corners (see the module docstring).

    Parameters
    ----------
    block : Block
        The block; ``block.restitution``, if given, replaces the emergent
        restitution at rocking impacts (module docstring).
    floor_accel_g : array-like, shape (n,)
        Floor acceleration [g] at t = 0, dt, ..., (n-1)dt; linear between samples.
        The floor and the block are at rest before t = 0 and the floor after the
        last sample.
    dt_s : float
        Sampling step [s].
    time_step_s : float, optional
        Largest time step [s]; each sample interval is cut into equal steps no
        longer than this. Default: ``max(4, ceil(p dt / 2e-3))`` steps a sample.
        Either way, steps are cut further while the block rocks a little
        (module docstring, *Time step*). Given, the Moreau–Jean steps alone
        are taken (by default, intervals of rocking on one sticking pivot are
        integrated by the rocking equation: *Rocking on one sticking pivot*).
    tail_s : float
        Longest run-out after the record [s]; it stops earlier when the block is at rest.
    return_history : bool
        Also return u and θ at the sample times (record and run-out).
    initial_theta_rad : float
        Initial rotation [rad], the block at rest on the corner it leans on
        (that corner where it stands at rest, u = 0); default flat.

    Returns
    -------
    BlockResponse
        Peaks, residual, uplift, overturning and the mode sequence. An overturned
        block is followed to |θ| = π/2 only: its residual is u there and its
        history is NaN after that.

    Examples
    --------
    Newmark's rectangular pulse of :func:`assess.mechanics.sliding.sliding_response`
    (0.5 g for 1 s, μ = 0.25, Umax = 0.25 g · 1 s² = 2.4517 m) on a squat block
    (b/h = 0.5 > μ: it slides without uplift):

    >>> block = Block(half_width_m=0.5, cg_height_m=1.0, height_m=2.0, mu=0.25)
    >>> r = simulate_time_stepping(block, [0.5, 0.5], 1.0)
    >>> round(r.sliding_max_m, 4), r.uplift, [(round(t, 2), mode) for t, mode in r.mode_sequence]
    (2.4517, False, [(0.0, 'rest'), (0.0, 'slide'), (2.0, 'rest')])
    """
    accel, dt = checked_record(floor_accel_g, dt_s, min_samples=1)
    theta0 = float(initial_theta_rad)
    if not (np.isfinite(theta0) and abs(theta0) < 0.5 * np.pi):
        raise ValueError("initial_theta_rad must lie in (-pi/2, pi/2)")
    n_sub, tail_steps = _steps(block, dt, time_step_s, float(tail_s))
    n_samples = accel.size + (tail_steps + n_sub - 1) // n_sub if return_history else 0
    hist_u, hist_theta = np.full(n_samples, np.nan), np.full(n_samples, np.nan)
    b, hcg, inv_j, mu, mu_s, e = _block_constants(block)
    out = _simulate(accel, dt, n_sub, tail_steps, b, hcg, inv_j, mu, mu_s, STANDARD_GRAVITY_M_S2, e, theta0,
                    hist_u, hist_theta, np.empty(64), np.empty(64, dtype=np.int64), time_step_s is None)
    u_max, u_res, theta_max, uplift, overturned, t_over, _, n_hist, mode_t, mode_c, n_modes = out
    modes = tuple((float(t), MODES[c]) for t, c in zip(mode_t[:n_modes], mode_c[:n_modes]))
    history = {}
    if return_history:
        n_keep = max(n_hist, accel.size) if overturned else n_hist
        history = dict(time_s=np.arange(n_keep) * dt, sliding_m=hist_u[:n_keep], theta_rad=hist_theta[:n_keep])
    return BlockResponse(sliding_max_m=float(u_max), sliding_residual_m=float(u_res),
                         theta_max_over_alpha=float(theta_max / block.alpha_rad), uplift=bool(uplift),
                         overturned=bool(overturned), overturn_time_s=float(t_over), mode_sequence=modes,
                         **history)


@dataclass(frozen=True)
class TimeSteppingPeaks:
    """Peak responses of many blocks to many records.

    Every field has shape (n_blocks, n_records) from :func:`time_stepping_peaks_batch`,
    (n_cases,) from :func:`time_stepping_case_peaks`; meanings and units as in
    :class:`assess.mechanics.block.BlockResponse`; ``mode`` is the run's
    :func:`assess.mechanics.block.summary_mode`.
    """

    sliding_max_m: np.ndarray
    sliding_residual_m: np.ndarray
    theta_max_over_alpha: np.ndarray
    uplift: np.ndarray
    overturned: np.ndarray
    overturn_time_s: np.ndarray
    mode: np.ndarray


def time_stepping_peaks_batch(blocks, records_g, dt_s, *, time_step_s=None, tail_s=10.0) -> TimeSteppingPeaks:
    """Peaks of many blocks under many records, in parallel (threads over pairs).

    Each (block, record) pair is integrated as by :func:`simulate_time_stepping`
    from rest; only peaks are kept, so memory grows with n_blocks × n_records.

    Parameters
    ----------
    blocks : sequence of Block
    records_g : array-like (n,) or sequence of array-like
        One floor acceleration record [g] or a sequence of records of any lengths.
    dt_s : float or sequence of float
        Sampling step [s], one for all records or one per record.
    time_step_s, tail_s : float
        As in :func:`simulate_time_stepping`.

    Returns
    -------
    TimeSteppingPeaks

    Examples
    --------
    A squat block slides and a slender one rocks under 0.3 g for 0.5 s:

    >>> squat = Block(half_width_m=0.5, cg_height_m=1.0, height_m=2.0, mu=0.25)
    >>> slender = Block.uniform(0.16, 1.25, mu=0.7)
    >>> peaks = time_stepping_peaks_batch([squat, slender], [[0.3] * 51], 0.01)
    >>> peaks.mode[:, 0].tolist(), peaks.uplift[:, 0].tolist(), peaks.overturned[:, 0].tolist()
    (['slide', 'rock'], [False, True], [False, False])
    """
    records, dts = checked_records(records_g, dt_s, min_samples=1)
    blocks = list(blocks)
    if not blocks:
        raise ValueError("blocks is empty")
    shape = (len(blocks), dts.size)
    peaks = _run_cases([blk for blk in blocks for _ in range(dts.size)], records, dts,
                       np.tile(np.arange(dts.size), len(blocks)), time_step_s, tail_s)
    return TimeSteppingPeaks(**{name: value.reshape(shape) for name, value in vars(peaks).items()})


def time_stepping_case_peaks(blocks, records_g, dt_s, record_index, *, time_step_s=None,
                             tail_s=10.0) -> TimeSteppingPeaks:
    """Peaks of many cases, case i ``blocks[i]`` under record ``record_index[i]``, in parallel.

    As :func:`time_stepping_peaks_batch`, for a list of (block, record) cases
    rather than every block under every record; the cases are spread over the
    threads a few at a time, so that long and short runs balance.

    Returns
    -------
    TimeSteppingPeaks
        Fields of shape (n_cases,).

    Examples
    --------
    >>> squat = Block(half_width_m=0.5, cg_height_m=1.0, height_m=2.0, mu=0.25)
    >>> slender = Block.uniform(0.16, 1.25, mu=0.7)
    >>> peaks = time_stepping_case_peaks([squat, slender, squat], [[0.3] * 51, [0.1] * 51], 0.01, [0, 0, 1])
    >>> peaks.mode.tolist(), peaks.uplift.tolist()
    (['slide', 'rock', 'rest'], [False, True, False])
    """
    records, dts = checked_records(records_g, dt_s, min_samples=1)
    blocks = list(blocks)
    index = np.ascontiguousarray(np.asarray(record_index, dtype=np.int64))
    if index.shape != (len(blocks),) or (index.size and (index.min() < 0 or index.max() >= dts.size)):
        raise ValueError("record_index must give one index into records_g per block")
    return _run_cases(blocks, records, dts, index, time_step_s, tail_s)


def _run_cases(blocks, records, dts, record_index, time_step_s, tail_s) -> TimeSteppingPeaks:
    n = len(blocks)
    accel_flat = np.ascontiguousarray(np.concatenate(records)) if records else np.empty(0)
    offsets = np.concatenate(([0], np.cumsum([r.size for r in records]))).astype(np.int64)
    steps = np.array([_steps(blk, dts[j], time_step_s, float(tail_s)) for blk, j in zip(blocks, record_index)],
                     dtype=np.int64).reshape(n, 2)
    b, hcg, inv_j, mu, mu_s, e = (np.array(col, dtype=float).reshape(n)
                                  for col in (zip(*map(_block_constants, blocks)) if n else [()] * 6))
    u_max, u_res, theta_max, t_over = (np.empty(n) for _ in range(4))
    uplift, overturned = np.zeros(n, dtype=np.bool_), np.zeros(n, dtype=np.bool_)
    visited = np.zeros(n, dtype=np.int64)
    run_case_ranges(_cases, n, accel_flat, offsets, dts, record_index, np.ascontiguousarray(steps[:, 0]),
                    np.ascontiguousarray(steps[:, 1]), b, hcg, inv_j, mu, mu_s, STANDARD_GRAVITY_M_S2, e,
                    np.full(n, time_step_s is None), u_max, u_res, theta_max, uplift, overturned, t_over, visited)
    alpha = np.array([blk.alpha_rad for blk in blocks], dtype=float)
    mode = np.array([_summary_of(mask) for mask in visited.tolist()], dtype=object)
    return TimeSteppingPeaks(sliding_max_m=u_max, sliding_residual_m=u_res, theta_max_over_alpha=theta_max / alpha,
                             uplift=uplift, overturned=overturned, overturn_time_s=t_over, mode=mode)


def _summary_of(mask):
    """The run's summary mode from the bit mask of the step modes it visited."""
    return summary_mode(m for bit, m in enumerate(MODES) if mask >> bit & 1)
