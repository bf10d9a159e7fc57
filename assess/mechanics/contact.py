"""The contact of a rigid block's two base corners with a rigid floor, as impulses (Moreau–Jean).

The compiled pieces of :mod:`assess.mechanics.timestepping` that solve, at one
instant or over one step, the two corners' unilateral contact with Coulomb
friction: the contact vectors of a corner (body offset ξ = ±b, η = −h) at
rotation θ, :math:`w_N = (0, 1, -\\xi\\cos\\theta + h\\sin\\theta)` (gradient of
the gap :math:`g_N = y - \\xi\\sin\\theta - h\\cos\\theta`) and
:math:`w_T = (1, 0, -\\xi\\sin\\theta - h\\cos\\theta)` (:func:`lever_arms`,
:func:`corner_gap`); for the active corners, at the velocity level,

.. math::

    0 \\le v_{N,c}^{k+1} \\perp P_{N,c} \\ge 0, \\qquad
    v_{T,c}^{k+1} = 0 \\Rightarrow |P_{T,c}| \\le \\mu_s P_{N,c}, \\qquad
    v_{T,c}^{k+1} \\ne 0 \\Rightarrow P_{T,c} = -\\mu P_{N,c}\\,\\mathrm{sgn}\\,v_{T,c}^{k+1}

(Moreau's inelastic impact law, :math:`e_N = 0`, and the Coulomb law of the
model on the impulses, [1]).

**Contact problem.** With two corners it is solved exactly by enumerating
the states of the active corners (open, stick, slip +, slip −): each candidate
is a linear system of at most 2 unknowns, checked for consistency to
:math:`10^{-10} g\\Delta t`. "Both stick" means v = 0 (two fixed points of a
rigid body) with 4 impulses for 3 equations: the friction split is left free and
the candidate holds if some split lies in both cones (stick with slip, or
opposite slips, also give v = 0 and fall in this case). With μs > μ the law is
non-monotone, so candidates are tried in order of fewest changes from the
previous states: a slipping corner slips on while it can, a sticking one sticks
while μs holds it; this is the stick-slip rule of :mod:`assess.mechanics.sliding`.


**Impacts.** An arriving corner is put on the floor at the located instant
and the next step starts with the impact alone: the velocity is first made
consistent with the corners that stay closed (their contact problem with no
force, with the lever arms of the impact configuration rather than those of
the middle of the last step), then the two-corner contact problem is solved
with no force (Δt → 0: impulses only, the same laws), and the step is taken
from the velocity after it. The impact is thus exact for the state it is
given, and the step after it second order.


**Position drift.** The velocity-level constraints let the gap of a corner in
persistent contact drift by :math:`O(\\Delta t^2)` per step. After every step the
corners that carry load (closed in the contact solution), an arriving corner
and any corner below the floor are put back onto it, :math:`g_N = 0`: two
corners along :math:`M^{-1}\\nabla g_N` (y and θ) by Newton iteration, the
projected scheme of [4]; a single corner by a shift of y alone, so that the
correction leaves θ as integrated (along :math:`M^{-1}\\nabla g_N` it would turn
the block by :math:`O(\\Delta t^2)` each step, a first-order error in θ). A pivot
that sticks on through the step is put back where it stood by a shift of x.


**Restitution override.** If ``block.restitution`` is given, at every rocking
impact (a corner that was off the floor arrives and sticks while the pivot
lifts) the velocity after the impact is replaced by a rotation about the
arriving corner with :math:`\\dot\\theta^+ = e\\,\\dot\\theta^-` (θ̇ at the arrival).
Impacts at which the arriving corner slips keep the emergent law.


**Modes and uplift.** A corner is off the floor in a step if the contact
solution leaves it open and its gap at the end of the step exceeds
``UPLIFT_GAP_RATIO`` · R (1e-9 R) or its normal velocity in the middle of the
step exceeds ``VELOCITY_RATIO`` · √(gR) (1e-9 √(gR)) in size; a corner on the
floor that is not sticking slips if :math:`|v_T|` there exceeds 1e-9 √(gR). The
step's mode follows (:data:`assess.mechanics.block.MODES`) and a change is dated
at the start of the step (at the event where one was located); ``uplift`` is
true if a corner was ever off the floor. A block whose corners both stick in the
contact solution is at rest: a train of ever smaller rocks ends there once a
rock is shorter than the (refined) step, when the floor pushes the block back.
No filter is applied. After the record the floor is at rest; the run-out stops when both corners stick (v = 0, θ = 0)
or after ``tail_s``.


References
----------
[1]-[4] as in :mod:`assess.mechanics.timestepping`: Moreau (1988), the impact
and friction laws on impulses; Acary (2013), the projection onto the floor
(doi:10.1016/j.cma.2012.12.012).
"""
from __future__ import annotations

import numpy as np
from numba import njit

#: A corner is off the floor above this gap, as a fraction of R [-].
UPLIFT_GAP_RATIO = 1e-9
#: Opening and slip velocities below this fraction of √(gR) count as zero [-].
VELOCITY_RATIO = 1e-9
#: States of a corner: off the floor (or not pressing on it), sticking, slipping towards +x, towards −x.
OPEN, STICK, SLIP_POS, SLIP_NEG = 0, 1, 2, 3
#: Codes of the step modes, in the order of :data:`assess.mechanics.block.MODES`.
CODE_REST, CODE_SLIDE, CODE_ROCK, CODE_SLIDE_ROCK, CODE_FLIGHT = 0, 1, 2, 3, 4
#: Candidate states (minus corner, plus corner) with both corners active, in order of preference.
#: (Tuples, not arrays: the compiled code reads them without reference counting.)
_PAIR_MINUS = (1, 0, 1, 2, 3, 0, 0, 2, 3, 0)
_PAIR_PLUS = (1, 1, 0, 2, 3, 2, 3, 0, 0, 0)
#: States of a single active corner, in order of preference.
_SINGLE = (1, 2, 3, 0)


@njit(cache=True)
def lever_arms_at(xi, sin_t, cos_t, hcg):
    """:func:`lever_arms` from sin θ and cos θ (worked out once per angle by the time loop) [m]."""
    return -xi * cos_t + hcg * sin_t, -xi * sin_t - hcg * cos_t


@njit(cache=True)
def corner_gap_at(y, sin_t, cos_t, xi, hcg):
    """:func:`corner_gap` from sin θ and cos θ [m]."""
    return y - xi * sin_t - hcg * cos_t


@njit(cache=True)
def corner_x_at(x, sin_t, cos_t, xi, hcg):
    """:func:`corner_x` from sin θ and cos θ [m]."""
    return x + xi * cos_t - hcg * sin_t


@njit(cache=True)
def lever_arms(xi, theta, hcg):
    """θ-components of w_N and w_T of the corner at body offset (ξ, −h) [m]."""
    return lever_arms_at(xi, np.sin(theta), np.cos(theta), hcg)


@njit(cache=True)
def corner_gap(y, theta, xi, hcg):
    """Height of the corner at body offset (ξ, −h) above the floor [m]."""
    return corner_gap_at(y, np.sin(theta), np.cos(theta), xi, hcg)


@njit(cache=True)
def corner_x(x, theta, xi, hcg):
    """Horizontal position of the corner at body offset (ξ, −h) [m]."""
    return corner_x_at(x, np.sin(theta), np.cos(theta), xi, hcg)


@njit(cache=True)
def _dot(row, direction, inv_j):
    """row · M⁻¹ direction for (x, y, θ) triples, M = diag(1, 1, 1/inv_j)."""
    return row[0] * direction[0] + row[1] * direction[1] + row[2] * direction[2] * inv_j


@njit(cache=True)
def _direction(state, rn, rt, mu):
    """Impulse direction (x, y, θ) of one unknown P_N of a slipping corner: w_N − μ s w_T."""
    s = 1.0 if state == SLIP_POS else -1.0
    return -mu * s, 1.0, rn - mu * s * rt


@njit(cache=True)
def _violation(state, pn, pt, vn, vt, mu_s):
    """How far one corner's impulse and velocity are from its assumed state (≥ 0) [m/s]."""
    if state == OPEN:
        return max(0.0, -vn)
    if state == STICK:
        return max(0.0, -pn, abs(pt) - mu_s * pn)
    s = 1.0 if state == SLIP_POS else -1.0
    return max(0.0, -pn, -s * vt)


@njit(cache=True)
def _both_stick(vf, rn_m, rt_m, rn_p, rt_p, inv_j, mu_s):
    """Both corners sticking: v⁺ = 0; returns (violation, pn_m, pt_m, pn_p, pt_p).

    The 3 equations Wᵀ P = −M v_free leave the friction split t = P_T+ free:
    P_T− = −v_x − t and the normal impulses are linear in t. Each of the six
    cone inequalities a + b t ≥ 0 bounds t; the middle of the feasible interval is
    taken, or, if it is empty, the point of least violation.
    """
    a0 = (rt_m * vf[0] + rn_p * vf[1] - vf[2] / inv_j) / (rn_m - rn_p)  # P_N− = a0 + a1 t
    a1 = (rt_m - rt_p) / (rn_m - rn_p)
    an = -vf[1] - a0  # P_N+ = an − a1 t, P_T− = −v_x − t, P_T+ = t
    lo, hi = -np.inf, np.inf
    for c, d in ((a0, a1), (an, -a1), (mu_s * a0 + vf[0], mu_s * a1 + 1.0), (mu_s * a0 - vf[0], mu_s * a1 - 1.0),
                 (mu_s * an, -mu_s * a1 - 1.0), (mu_s * an, 1.0 - mu_s * a1)):
        if d > 0.0:
            lo = max(lo, -c / d)
        elif d < 0.0:
            hi = min(hi, -c / d)
        elif c < 0.0:
            lo, hi = np.inf, -np.inf
    t = 0.5 * (lo + hi) if np.isfinite(lo) and np.isfinite(hi) else (lo if np.isfinite(lo) else hi)
    t = t if np.isfinite(t) else 0.0
    pnm, ptm, pnp = a0 + a1 * t, -vf[0] - t, an - a1 * t
    violation = max(0.0, -pnm, -pnp, abs(ptm) - mu_s * pnm, abs(t) - mu_s * pnp)
    return violation, pnm, ptm, pnp, t


@njit(cache=True)
def _lone_pivot(minus, act_m, act_p, vf, rn_m, rt_m, rn_p, rt_p, inv_j, mu_s):
    """:func:`contact_candidate` of one sticking corner, the other open: its two equations written out
    (the general path's terms with a zero factor dropped; the same operations otherwise)."""
    rn, rt = (rn_m, rt_m) if minus else (rn_p, rt_p)
    a11, b1 = 1.0 + rn * rn * inv_j, -(vf[1] + rn * vf[2])
    a12, a21, a22, b2 = rn * rt * inv_j, rt * rn * inv_j, 1.0 + rt * rt * inv_j, -(vf[0] + rt * vf[2])
    det = a11 * a22 - a12 * a21
    if abs(det) <= 1e-14 * (abs(a11 * a22) + abs(a12 * a21)):
        return np.inf, vf, 0.0, 0.0, 0.0, 0.0
    lam1, lam2 = (b1 * a22 - a12 * b2) / det, (a11 * b2 - a21 * b1) / det
    v = (vf[0] + lam2, vf[1] + lam1, vf[2] + (rn * lam1 + rt * lam2) * inv_j)
    violation = 0.0
    if minus:
        if act_m:
            violation = max(0.0, -lam1, abs(lam2) - mu_s * lam1)
        if act_p:
            violation = max(violation, max(0.0, -(v[1] + rn_p * v[2])))
        return violation, v, lam1, lam2, 0.0, 0.0
    if act_m:
        violation = max(0.0, -(v[1] + rn_m * v[2]))
    if act_p:
        violation = max(violation, max(0.0, -lam1, abs(lam2) - mu_s * lam1))
    return violation, v, 0.0, 0.0, lam1, lam2


# Not inlined at numba's IR level (inline="always"): it is called at six sites, inside functions that are
# themselves inlined, and retyping each copy made compiling the general solver take ~4x longer (100 s vs 26 s
# under load; benchmarks/bench_assessment.py: the runs cost 4 % more CPU without it). LLVM still inlines it.
@njit(cache=True)
def contact_candidate(st_m, st_p, act_m, act_p, vf, rn_m, rt_m, rn_p, rt_p, inv_j, mu, mu_s):
    """Velocity and impulses for assumed corner states; returns (violation, v⁺, P_N−, P_T−, P_N+, P_T+)."""
    if act_m and act_p and st_m == STICK and st_p == STICK:
        violation, pnm, ptm, pnp, ptp = _both_stick(vf, rn_m, rt_m, rn_p, rt_p, inv_j, mu_s)
        return violation, (0.0, 0.0, 0.0), pnm, ptm, pnp, ptp
    if (st_m == STICK and st_p == OPEN) or (st_m == OPEN and st_p == STICK):
        return _lone_pivot(st_m == STICK, act_m, act_p, vf, rn_m, rt_m, rn_p, rt_p, inv_j, mu_s)
    # up to two (row, direction) pairs: row · v⁺ = 0 with an impulse λ along the direction
    n = 0
    r1 = d1 = r2 = d2 = (0.0, 0.0, 0.0)
    for side in range(2):
        st, rn, rt = (st_m, rn_m, rt_m) if side == 0 else (st_p, rn_p, rt_p)
        if st == STICK:
            r1 = d1 = (0.0, 1.0, rn)
            r2 = d2 = (1.0, 0.0, rt)
            n = 2
        elif st != OPEN:
            if n == 0:
                r1, d1 = (0.0, 1.0, rn), _direction(st, rn, rt, mu)
            else:
                r2, d2 = (0.0, 1.0, rn), _direction(st, rn, rt, mu)
            n += 1
    if n > 2:
        return np.inf, vf, 0.0, 0.0, 0.0, 0.0  # stick with slip: v = 0, covered by "both stick"
    lam1 = lam2 = 0.0
    a11, b1 = _dot(r1, d1, inv_j), -_dot(r1, vf, 1.0)
    if n == 1:
        if a11 <= 0.0:
            return np.inf, vf, 0.0, 0.0, 0.0, 0.0
        lam1 = b1 / a11
    elif n == 2:
        a12, a21, a22, b2 = _dot(r1, d2, inv_j), _dot(r2, d1, inv_j), _dot(r2, d2, inv_j), -_dot(r2, vf, 1.0)
        det = a11 * a22 - a12 * a21
        if abs(det) <= 1e-14 * (abs(a11 * a22) + abs(a12 * a21)):
            return np.inf, vf, 0.0, 0.0, 0.0, 0.0
        lam1, lam2 = (b1 * a22 - a12 * b2) / det, (a11 * b2 - a21 * b1) / det
    v = (vf[0] + d1[0] * lam1 + d2[0] * lam2, vf[1] + d1[1] * lam1 + d2[1] * lam2,
         vf[2] + (d1[2] * lam1 + d2[2] * lam2) * inv_j)
    # impulses per corner: a sticking corner owns both unknowns, a slipping one the next
    pnm = ptm = pnp = ptp = 0.0
    used = 0
    for side in range(2):
        st = st_m if side == 0 else st_p
        if st == OPEN:
            continue
        if st == STICK:
            pn, pt = lam1, lam2
        else:
            pn = lam1 if used == 0 else lam2
            pt = -mu * (1.0 if st == SLIP_POS else -1.0) * pn
            used += 1
        if side == 0:
            pnm, ptm = pn, pt
        else:
            pnp, ptp = pn, pt
    violation = 0.0
    if act_m:
        violation = max(violation, _violation(st_m, pnm, ptm, v[1] + rn_m * v[2], v[0] + rt_m * v[2], mu_s))
    if act_p:
        violation = max(violation, _violation(st_p, pnp, ptp, v[1] + rn_p * v[2], v[0] + rt_p * v[2], mu_s))
    return violation, v, pnm, ptm, pnp, ptp


@njit(cache=True, inline="always")
def solve_contacts(prev_m, prev_p, act_m, act_p, vf, rn_m, rt_m, rn_p, rt_p, inv_j, mu, mu_s, tol):
    """Exact solution of the two-corner contact problem by enumeration of states.

    Candidates are tried with 0, 1, then 2 state changes from the previous step
    (inactive corners are open and not counted); the first consistent one is
    kept, else the least inconsistent. Returns (state−, state+, v⁺, P_N−, P_N+).
    """
    best = (np.inf, 0, 0, vf, 0.0, 0.0)
    n_cand = len(_PAIR_MINUS) if (act_m and act_p) else len(_SINGLE)
    for level in range(3):
        for i in range(n_cand):
            if act_m and act_p:
                st_m, st_p = _PAIR_MINUS[i], _PAIR_PLUS[i]
            elif act_m:
                st_m, st_p = _SINGLE[i], OPEN
            else:
                st_m, st_p = OPEN, _SINGLE[i]
            changes = (act_m and st_m != prev_m) + (act_p and st_p != prev_p)
            if changes != level:
                continue
            violation, v, pnm, _, pnp, _ = contact_candidate(st_m, st_p, act_m, act_p, vf, rn_m, rt_m, rn_p, rt_p,
                                                             inv_j, mu, mu_s)
            if violation <= tol:
                return st_m, st_p, v, pnm, pnp
            if violation < best[0]:
                best = (violation, st_m, st_p, v, pnm, pnp)
    return best[1], best[2], best[3], best[4], best[5]


@njit(cache=True)
def first_candidate(prev_m, prev_p, act_m, act_p, vf, rn_m, rt_m, rn_p, rt_p, inv_j, mu, mu_s, tol):
    """The candidate :func:`solve_contacts` tries first, the previous states (no change), solved.

    Returns (whether it is one of the candidates and holds to ``tol``, v⁺, P_N−, P_T−, P_N+, P_T+): where
    it holds, :func:`solve_contacts` returns it; its impulses are the pivot's cone margin
    (:func:`cone_margin`) all the same.
    """
    violation, v, pnm, ptm, pnp, ptp = contact_candidate(prev_m, prev_p, act_m, act_p, vf, rn_m, rt_m, rn_p, rt_p,
                                                         inv_j, mu, mu_s)
    listed = not (act_m and act_p) or prev_m == OPEN or prev_p == OPEN or prev_m == prev_p
    return listed and violation <= tol, v, pnm, ptm, pnp, ptp


@njit(cache=True, inline="always")
def project_onto_floor(y, theta, fix_m, fix_p, b, hcg, inv_j, gap_tol):
    """Put the fixed corners back on the floor: both along M⁻¹∇g by Newton iteration (y and θ
    move), a single one by a vertical shift (θ, the rocking coordinate, is left as integrated)."""
    if fix_m != fix_p:
        return y - corner_gap(y, theta, -b if fix_m else b, hcg), theta
    for _ in range(6):
        g_m, g_p = corner_gap(y, theta, -b, hcg), corner_gap(y, theta, b, hcg)
        if abs(g_m) <= gap_tol and abs(g_p) <= gap_tol:
            break
        rn_m, _ = lever_arms(-b, theta, hcg)
        rn_p, _ = lever_arms(b, theta, hcg)
        a11, a12, a22 = 1.0 + rn_m * rn_m * inv_j, 1.0 + rn_m * rn_p * inv_j, 1.0 + rn_p * rn_p * inv_j
        det = a11 * a22 - a12 * a12
        lam_m = (-g_m * a22 + a12 * g_p) / det
        lam_p = (-a11 * g_p + a12 * g_m) / det
        y += lam_m + lam_p
        theta += (rn_m * lam_m + rn_p * lam_p) * inv_j
    return y, theta


@njit(cache=True, inline="always")
def step_mode(st_m, st_p, v, rn_m, rt_m, rn_p, rt_p, g_m, g_p, radius, gravity):
    """Mode code of a step from the contact states, the gaps at its end and a velocity in it."""
    gap_tol, v_tol = UPLIFT_GAP_RATIO * radius, VELOCITY_RATIO * np.sqrt(gravity * radius)
    off_m = st_m == OPEN and (g_m > gap_tol or abs(v[1] + rn_m * v[2]) > v_tol)
    off_p = st_p == OPEN and (g_p > gap_tol or abs(v[1] + rn_p * v[2]) > v_tol)
    slip_m = not off_m and st_m != STICK and abs(v[0] + rt_m * v[2]) > v_tol
    slip_p = not off_p and st_p != STICK and abs(v[0] + rt_p * v[2]) > v_tol
    if off_m and off_p:
        return CODE_FLIGHT
    if off_m or off_p:
        return CODE_SLIDE_ROCK if (slip_m or slip_p) else CODE_ROCK
    return CODE_SLIDE if (slip_m or slip_p) else CODE_REST


@njit(cache=True, inline="always")
def cone_margin(pm, pp, vf, rn_m, rt_m, rn_p, rt_p, inv_j, mu, mu_s):
    """μs P_N − |P_T| of the sticking pivot of a block on one corner (pm, pp: stick and open)."""
    _, _, pnm, ptm, pnp, ptp = contact_candidate(pm, pp, True, True, vf, rn_m, rt_m, rn_p, rt_p, inv_j, mu, mu_s)
    return mu_s * pnm - abs(ptm) if pm == STICK else mu_s * pnp - abs(ptp)


@njit(cache=True)
def impact(vx, vy, w, theta, prev_m, prev_p, on_m, on_p, b, hcg, inv_j, mu, mu_s, e_override, tol, v_tol):
    """Impulses at the start of a step where an open corner on the floor moves into it.

    The velocity is first made consistent with the corners that stay closed
    (their contact problem with no force, lever arms at the impact), then the
    contact problem is solved with no force (Δt → 0: Moreau's impact law,
    :math:`e_N = 0`, and Coulomb's law on the impulses); the restitution
    override, if any, replaces a rocking impact's outcome. Returns (state−,
    state+, ẋ, ẏ, θ̇) after it (unchanged if no corner arrives).
    """
    rn_m, rt_m = lever_arms(-b, theta, hcg)
    rn_p, rt_p = lever_arms(b, theta, hcg)
    hit_m = on_m and prev_m == OPEN and vy + rn_m * w < -v_tol
    hit_p = on_p and prev_p == OPEN and vy + rn_p * w < -v_tol
    if not (hit_m or hit_p):
        return prev_m, prev_p, vx, vy, w
    pm, pp = (prev_m if on_m else OPEN), (prev_p if on_p else OPEN)
    if pm != OPEN or pp != OPEN:
        # the velocity of the last step keeps the closed corner at rest with its lever arms in that step's
        # middle: make it do so with those of the impact (an O(Δt) correction), then strike
        _, v, _, _, _, _ = contact_candidate(pm, pp, on_m, on_p, (vx, vy, w), rn_m, rt_m, rn_p, rt_p, inv_j, mu, mu_s)
        vx, vy, w = v
    st_m, st_p, v, _, _ = solve_contacts(pm, pp, on_m, on_p, (vx, vy, w), rn_m, rt_m, rn_p, rt_p, inv_j, mu, mu_s,
                                         tol)
    if e_override >= 0.0 and ((st_m == STICK and hit_m and st_p == OPEN and pp != OPEN)
                              or (st_p == STICK and hit_p and st_m == OPEN and pm != OPEN)):
        # rocking impact: rotation about the arriving corner at e times θ̇ before
        rn, rt = (rn_m, rt_m) if st_m == STICK else (rn_p, rt_p)
        v = (-rt * e_override * w, -rn * e_override * w, e_override * w)
    return st_m, st_p, v[0], v[1], v[2]
