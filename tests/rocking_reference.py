"""Independent reference for the rocking kernel, for tests only.

scipy's DOP853 (rtol 1e-10) integrates the same equation of motion
(Makris & Roussos 2000, eq. 1) in seconds with the floor acceleration
interpolated linearly by ``numpy.interp``; terminal events stop it at an
impact (θ = 0) and at overturning (|θ| = π/2), and it is restarted after each
impact with θ̇ ← e·θ̇. A block at rest restarts when |ü_g| first exceeds
g tan α, found on the piecewise linear record. Peaks come from a non-terminal
event at θ̇ = 0. Nothing here is shared with ``assess.mechanics.rocking``.
"""
from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp


def _next_uplift(t_from, time_s, accel_g, tan_alpha):
    """First time ≥ t_from at which |ü_g/g| > tan α on the linear interpolant, or None."""
    a_from = np.interp(t_from, time_s, accel_g)
    if abs(a_from) > tan_alpha:
        return t_from
    start = np.searchsorted(time_s, t_from, side="right")
    above = np.flatnonzero(np.abs(accel_g[start:]) > tan_alpha)
    if above.size == 0:
        return None
    j = start + above[0]
    t0, a0 = (t_from, a_from) if j == start else (time_s[j - 1], accel_g[j - 1])
    level = np.sign(accel_g[j]) * tan_alpha
    return t0 + (level - a0) / (accel_g[j] - a0) * (time_s[j] - t0)


def reference_rocking(accel_g, dt_s, alpha, p, e, theta0=0.0, rest_ratio=1e-5):
    """Return dict(theta_max_over_alpha, overturned, overturn_time_s, impacts, uplift, peaks)."""
    accel_g = np.asarray(accel_g, dtype=float)
    time_s = np.arange(accel_g.size) * dt_s
    t_end = time_s[-1]
    tan_alpha = np.tan(alpha)
    t, theta, omega = 0.0, float(theta0), 0.0
    resting = theta == 0.0
    side = np.sign(theta) if theta else 1.0
    out = dict(theta_max_over_alpha=abs(theta) / alpha, overturned=False, overturn_time_s=np.nan,
               impacts=0, uplift=not resting, peaks=[])

    while t < t_end:
        if resting:
            t_up = _next_uplift(t, time_s, accel_g, tan_alpha)
            if t_up is None or t_up >= t_end:
                break
            t = t_up
            side = -np.sign(np.interp(t, time_s, accel_g))
            theta, omega, resting, out["uplift"] = 0.0, 0.0, False, True

        def rhs(tt, y, side=side):
            phi = alpha * side - y[0]
            return [y[1], -p * p * (np.sin(phi) + np.interp(tt, time_s, accel_g) * np.cos(phi))]

        def impact(tt, y, side=side):
            return side * y[0]
        impact.terminal, impact.direction = True, -1

        def overturn(tt, y, side=side):
            return side * y[0] - 0.5 * np.pi
        overturn.terminal, overturn.direction = True, 1

        def peak(tt, y):
            return y[1]

        first_step = dt_s
        if theta == 0.0 and omega != 0.0:
            thdd0 = rhs(t, [0.0, omega])[1]
            if side * thdd0 < 0.0:
                first_step = min(dt_s, 0.1 * abs(omega / thdd0))
        sol = solve_ivp(rhs, (t, t_end), [theta, omega], method="DOP853", rtol=1e-10, atol=1e-13 * alpha,
                        events=[impact, overturn, peak], max_step=dt_s, first_step=first_step)
        out["theta_max_over_alpha"] = max(out["theta_max_over_alpha"], np.max(np.abs(sol.y[0])) / alpha)
        for y_peak in sol.y_events[2]:
            out["theta_max_over_alpha"] = max(out["theta_max_over_alpha"], abs(y_peak[0]) / alpha)
            out["peaks"].append(y_peak[0])
        if sol.t_events[1].size:
            out.update(overturned=True, overturn_time_s=sol.t_events[1][0],
                       theta_max_over_alpha=0.5 * np.pi / alpha)
            break
        if not sol.t_events[0].size:
            break
        t_impact = sol.t_events[0][0]
        omega = e * sol.y_events[0][0][1]
        out["impacts"] += 1
        if t_impact - t <= 1e-12:
            omega = 0.0  # a rock shorter than the solver can resolve: settle
        t, theta, side = t_impact, 0.0, -side
        if abs(omega) < rest_ratio * p * alpha:
            thdd0 = rhs(t, [0.0, 0.0])[1]
            if side * thdd0 <= 0.0 or omega == 0.0:
                resting, omega = True, 0.0
    return out
