"""An independent rocking code for a box standing on two inset feet, for tests only.

Nothing here comes from ``assess.mechanics``: the geometry, the inertia, the
equation of motion and the impact are derived below from the box itself and
integrated in physical time with scipy's ``solve_ivp`` (DOP853) with events.

**The box.** Full width 2b, full height H, uniform, so its centre of mass
(CM) is at h = H/2 above the base (``cg_height_m`` may set another h; the
inertia stays that of the uniform box). Its feet are two line contacts at
x = ±c with c = (1 − d)·b, on the plane of the base: d is the inset as a
fraction of the half-width (the tool's ``foot_inset_m`` = d·b).

**Inertia about a foot** (derived, not taken from the tool). About the CM,
a uniform rectangle of sides 2b × H has I_cm = m((2b)² + H²)/12, which for
H = 2h is m(b² + h²)/3. The parallel-axis theorem moves it to the foot, at
distance √(c² + h²) from the CM:

.. math:: I_f = I_{cm} + m(c^2 + h^2)

(for c = b, H = 2h this is the corner's 4m(b² + h²)/3; with the feet inset
it is the corner's value minus m(b² − c²): the pivot is nearer the CM, the
box's own inertia about its CM is unchanged).

**Equation of motion** (Lagrange, one coordinate). θ is the box's rotation,
positive clockwise (top towards +x), pivoting on the foot at x = s·c with
s = sign θ. The vector from that foot to the CM is
r(θ) = (−s c cos θ + h sin θ, s c sin θ + h cos θ); gravity's potential is
m g r_y, the floor's acceleration a(t) [m/s²] acts as the force −m a along x
(generalised force −m a ∂r_x/∂θ), so

.. math:: I_f \\ddot\\theta = -m g (s c\\cos\\theta - h\\sin\\theta)
                              - m a(t)\\,(s c\\sin\\theta + h\\cos\\theta)

(Makris & Konstantinidis 2003, eq. 1, written with the foot's c and the
whole box's I_f instead of the corner's b and 4m(b² + h²)/3). At rest
(θ = 0) the box uplifts on the foot at +c when −a(t) h > g c, i.e. when
|a| exceeds g·c/h, and about the foot in the direction opposite to a.

**Impact** (Housner 1963, derived here for feet). When θ returns to 0 the
other foot, at −s·c, strikes the floor: an impulse acts there only, so the
angular momentum about that foot is conserved. It is computed from vectors
at the instant of impact, L_Q = I_cm ω − m[(r_CM − Q) × v_CM]_z (clockwise
positive), before (rotating about the old foot) and after (about the new one):

.. math:: \\omega^+ = \\frac{I_{cm} + m(h^2 - c^2)}{I_f}\\,\\omega^-

**The measured quantity** is the peak |θ| over α of the *declared* box,
atan(b/h): a table reads the rotation of the box and the workbook gives the
box, not its feet. Overturning is |θ| reaching π/2.

**The floor** is piecewise linear between samples, at rest after the last
sample (a step to zero), followed ``tail_s`` seconds more.

References
----------
Housner, G. W. (1963). The behavior of inverted pendulum structures during
earthquakes. Bull. Seismol. Soc. Am. 53(2):403-417.
Makris, N., Konstantinidis, D. (2003). The rocking spectrum and the
limitations of practical design methodologies. Earthquake Eng. Struct. Dyn.
32(2):265-289. doi:10.1002/eqe.223
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

G = 9.80665


@dataclass(frozen=True)
class FootedBox:
    """A uniform box of half-width b, height H, CM at h, on feet at ±(1 − d)·b (lengths in m)."""

    half_width_m: float
    height_m: float
    inset_fraction: float = 0.0
    cg_height_m: float | None = None

    @property
    def h(self) -> float:
        return self.height_m / 2.0 if self.cg_height_m is None else self.cg_height_m

    @property
    def c(self) -> float:
        """Half the distance between the feet [m]."""
        return (1.0 - self.inset_fraction) * self.half_width_m

    @property
    def inertia_cm_per_mass(self) -> float:
        """I_cm/m of the whole uniform box [m²]."""
        return ((2.0 * self.half_width_m) ** 2 + self.height_m ** 2) / 12.0

    @property
    def inertia_foot_per_mass(self) -> float:
        """I_f/m about a foot, parallel axis from the CM [m²]."""
        return self.inertia_cm_per_mass + self.c ** 2 + self.h ** 2

    @property
    def declared_alpha(self) -> float:
        """atan(b/h) of the box as declared (what a rotation is read against) [rad]."""
        return float(np.arctan2(self.half_width_m, self.h))

    def uplift_accel_m_s2(self) -> float:
        """Floor acceleration at which the box at rest lifts off a foot [m/s²]."""
        return G * self.c / self.h

    def theta_ddot(self, theta, accel_m_s2, side):
        """θ̈ [rad/s²] rocking on the foot at x = side·c under floor acceleration a."""
        c, h = self.c, self.h
        return (-G * (side * c * np.cos(theta) - h * np.sin(theta))
                - accel_m_s2 * (side * c * np.sin(theta) + h * np.cos(theta))) / self.inertia_foot_per_mass

    def omega_after_impact(self, omega_before, side_before):
        """ω⁺ from ω⁻ at θ = 0: angular momentum about the striking foot, from vectors [rad/s]."""
        c, h = self.c, self.h
        s = side_before
        # CM and its velocity at θ = 0 while rotating (clockwise ω) about the foot at (s c, 0)
        cm = np.array([0.0, h])
        pivot_old, pivot_new = np.array([s * c, 0.0]), np.array([-s * c, 0.0])
        arm = cm - pivot_old
        velocity = omega_before * np.array([arm[1], -arm[0]])  # clockwise ω: v = ω (r_y, −r_x)

        def clockwise_momentum(point, v, omega):
            d = cm - point
            return self.inertia_cm_per_mass * omega - (d[0] * v[1] - d[1] * v[0])

        before = clockwise_momentum(pivot_new, velocity, omega_before)
        # after: rotation ω⁺ about the new foot, whose momentum about it is I_f ω⁺
        return before / self.inertia_foot_per_mass


@dataclass
class FootedResponse:
    theta_max_rad: float
    overturned: bool
    uplift: bool
    impacts: int
    first_impact_s: float

    def theta_over_declared_alpha(self, box: FootedBox) -> float:
        return (0.5 * np.pi if self.overturned else self.theta_max_rad) / box.declared_alpha


def footed_rocking(box: FootedBox, accel_g, dt_s, *, tail_s=10.0, theta0=0.0, rtol=1e-9,
                   rest_omega_rad_s=1e-6) -> FootedResponse:
    """Rock ``box`` under the floor acceleration ``accel_g`` [g] sampled at ``dt_s`` [s]."""
    accel = np.asarray(accel_g, dtype=float) * G
    time_s = np.arange(accel.size) * dt_s
    t_record = time_s[-1]
    t_end = t_record + tail_s
    threshold = box.uplift_accel_m_s2()

    last = accel.size - 1

    def floor(t):  # linear between samples, at rest after the last one
        if t > t_record:
            return 0.0
        k = min(int(t / dt_s), last - 1) if last else 0
        if not last:
            return float(accel[0])
        frac = t / dt_s - k
        return float(accel[k] + frac * (accel[k + 1] - accel[k]))

    t, theta, omega = 0.0, float(theta0), 0.0
    resting = theta == 0.0
    side = 1.0 if theta >= 0.0 else -1.0
    out = FootedResponse(abs(theta), False, not resting, 0, np.nan)
    while t < t_end:
        if resting:
            t_up = _first_exceedance(t, time_s, accel, threshold)
            if t_up is None:
                break
            t = t_up
            side = -np.sign(floor(t))
            theta, omega, resting, out.uplift = 0.0, 0.0, False, True

        def rhs(tt, y, side=side):
            return [y[1], box.theta_ddot(y[0], floor(tt), side)]

        def impact(tt, y, side=side):
            return side * y[0]
        impact.terminal, impact.direction = True, -1

        def overturn(tt, y, side=side):
            return side * y[0] - 0.5 * np.pi
        overturn.terminal, overturn.direction = True, 1

        # a step to zero at the record's end: integrate the record and the tail separately
        stops = [t_record, t_end] if t < t_record else [t_end]
        y = [theta, omega]
        event = None
        for stop in stops:
            first = min(dt_s, 1e-3)
            sol = solve_ivp(rhs, (t, stop), y, method="DOP853", rtol=rtol, atol=1e-12,
                            events=[impact, overturn], max_step=dt_s, first_step=first, dense_output=False)
            out.theta_max_rad = max(out.theta_max_rad, float(np.max(np.abs(sol.y[0]))))
            if sol.t_events[1].size:
                event = "overturn"
                break
            if sol.t_events[0].size:
                event = ("impact", sol.t_events[0][0], sol.y_events[0][0])
                break
            t, y = stop, list(sol.y[:, -1])
        if event == "overturn":
            out.overturned = True
            break
        if event is None:
            break
        t_hit, state = event[1], event[2]
        if np.isnan(out.first_impact_s):
            out.first_impact_s = float(t_hit)
        out.impacts += 1
        omega = box.omega_after_impact(state[1], side)
        t, theta, side = float(t_hit), 0.0, -side
        # the new foot's side: the block keeps turning the same way, through θ = 0
        if abs(omega) < rest_omega_rad_s:
            resting, omega = True, 0.0
    return out


def _first_exceedance(t_from, time_s, accel, threshold):
    """First time ≥ t_from at which |a| > threshold on the linear interpolant (None if never)."""
    a_from = np.interp(t_from, time_s, accel)
    if abs(a_from) > threshold and t_from <= time_s[-1]:
        return t_from
    start = int(np.searchsorted(time_s, t_from, side="right"))
    above = np.flatnonzero(np.abs(accel[start:]) > threshold)
    if above.size == 0:
        return None
    j = start + int(above[0])
    t0 = t_from if j == start else time_s[j - 1]
    level = np.sign(accel[j]) * threshold
    return brentq(lambda tt: np.interp(tt, time_s, accel) - level, t0, time_s[j])
