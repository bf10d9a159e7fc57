"""General rigid-block solver, event-driven: smooth equations per mode, located transitions.

Integrates the model of :mod:`assess.mechanics.block` (coordinates x, y, θ of
the centre of mass in the floor frame, θ > 0 when the top moves towards +x,
unilateral corners with Coulomb friction) as a sequence of **modes**, each a
set of smooth equations, joined at **events** located to round-off. Forces
are per unit mass; :math:`a = a_g(t)` [g]; corner σ = ±1 lies at
:math:`(r_x, r_y) = (R\\sin\\phi, -R\\cos\\phi)` from the centre of mass with
:math:`\\phi = \\sigma\\alpha - \\theta`; :math:`j = I_{cm}/m`,
:math:`p^2 = gR/(j + R^2)`.

``rest`` (both corners down, sticking): :math:`\\ddot x = \\ddot y = \\ddot\\theta = 0`,
total friction :math:`F = a g`, normal forces :math:`N_\\sigma = \\tfrac{g}{2}(1 - \\sigma a h/b)`.
Left when :math:`|a| > \\min(\\mu_s, b/h)` (found in closed form on the linear input).

``slide`` (both down, slipping with sign s): :math:`\\ddot x = -g(a + \\mu s)`,
:math:`N_\\sigma = \\tfrac{g}{2}(1 + \\sigma\\mu s h/b)`, independent of the
input (a corner can only lift at once, when μ > b/h). Left when ẋ = 0.

``rock`` (on corner σ, sticking; [3], [4]):

.. math::

    \\ddot\\theta = -p^2(\\sin\\phi + a\\cos\\phi), \\quad
    F = a g + R\\cos\\phi\\,\\ddot\\theta + R\\sin\\phi\\,\\dot\\theta^2, \\quad
    N = g + R\\sin\\phi\\,\\ddot\\theta - R\\cos\\phi\\,\\dot\\theta^2

Left at an impact (θ = 0), slip (:math:`|F| = \\mu_s N`), lift-off (N = 0) or
overturning (:math:`|\\theta| = \\pi/2`).

``slide-rock`` (on corner σ, slipping with sign s of the corner's velocity
:math:`v = \\dot x + r_y\\dot\\theta`; [1]): with :math:`c = r_x + \\mu s r_y`,

.. math::

    N = \\frac{j\\,(g + r_y\\dot\\theta^2)}{j + c\\,r_x}, \\quad
    \\ddot\\theta = -\\frac{c\\,N}{j}, \\quad \\ddot x = -a g - \\mu s N

Left when v = 0 (to rock if :math:`|F| \\le \\mu_s N` holds, else slipping
back), at an impact, lift-off or overturning. The denominator
:math:`j + c\\,r_x` can vanish (Painlevé's paradox) only for
:math:`\\mu \\ge (j + r_x^2)/|r_x r_y|`, at least 4/3 for a uniform block.

``flight``: :math:`\\ddot x = -a g`, :math:`\\ddot y = -g`, :math:`\\ddot\\theta = 0`
until a corner reaches the floor. Entered at lift-off when the free corner's
acceleration :math:`-g - r_y\\dot\\theta^2` is upward.

**Onset** (from sticking with both corners down, [2]): the first consistent
of rest (:math:`|a| \\le \\mu_s`, both N ≥ 0), rock (lifting, N > 0,
:math:`|F| \\le \\mu_s N`), slide (both N > 0, slip accelerating the way it
goes; only when neither sticking mode holds) and slide-rock (N > 0,
lifting, slip accelerating). From rest under a rectangular pulse this
reproduces Shenton's criteria (:func:`assess.mechanics.modes.initial_mode`).
On one corner (after an impact, at a slip or lift-off event, at release)
the first consistent of rock, slide-rock (either slip direction, the way
friction gives first) and flight is taken; where none is (only in
Painlevé's range of μ) a ``RuntimeError`` is raised.

**Impact** (a corner arriving): perfectly inelastic at that corner in the
normal direction, other corner free to leave. The impulses P_N, P_T make the
corner stick if :math:`|P_T| \\le \\mu_s P_N`; otherwise it slips with
:math:`|P_T| = \\mu P_N` in the direction of the sticking impulse. A sticking
impact of a rocking block at θ = 0 conserves angular momentum about the new
pivot, :math:`\\dot\\theta^+ = (1 - 2\\sin^2\\alpha/\\kappa)\\dot\\theta^-`
([3]); with ``Block.restitution`` given, that ratio is replaced by the
override (the new pivot at rest). If the other corner would then move into
the floor, both land (θ̇ = ẏ = 0; the horizontal impulse sticks within
:math:`\\mu_s P_N`, else :math:`\\dot x^+ = \\dot x^- - \\mu P_N\\mathrm{sign}\\,\\dot x^-`).
After a single-corner impact at θ = 0 leaving :math:`|\\dot\\theta|` below
:data:`assess.mechanics.rocking.REST_ANGULAR_VELOCITY_RATIO` · pα while the
floor pushes back, the block lands flat (the Zeno sequence of ever smaller
rocks has converged), as in the rocking kernel; such settlings and all
impacts are counted (``_simulate(...)[1].log``).

**Numerics.** Each sample interval (the input is linear in it) is integrated
with scipy's DOP853 at ``rtol`` in reduced coordinates (rock: θ; slide-rock:
x, θ; the contact constraint exact), with terminal events located by Brent's
method; an event that is zero where a mode starts is taken on the secant
g(t)/(t − t₀), so a mode can leave at once but never at its own start. The
integration also stops where an event function turns (θ̇ = 0, a slip
acceleration or a corner's velocity zero), so that no event can dip through
zero and back inside one step unseen (a short stick inside a sample
interval, a micro-rock).
Peaks of |θ| are located (θ̇ = 0); u changes only by slip. Thresholds are
relative (to α, pα, pR, g), so the solver keeps Froude similitude.

References
----------
.. [1] Shenton, H. W., Jones, N. P. (1991). Base excitation of rigid bodies.
   I: Formulation. J. Eng. Mech. 117(10):2286-2306.
   doi:10.1061/(ASCE)0733-9399(1991)117:10(2286)
.. [2] Shenton, H. W. (1996). Criteria for initiation of slide, rock, and
   slide-rock rigid-body modes. J. Eng. Mech. 122(7):690-693.
   doi:10.1061/(ASCE)0733-9399(1996)122:7(690)
.. [3] Housner, G. W. (1963). The behavior of inverted pendulum structures
   during earthquakes. Bull. Seismol. Soc. Am. 53(2):403-417.
.. [4] Makris, N., Roussos, Y. S. (2000). Rocking response of rigid blocks
   under near-source ground motions. Géotechnique 50(3):243-262.
   doi:10.1680/geot.2000.50.3.243
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Optional

import numpy as np
from scipy.integrate import solve_ivp

from .block import FLIGHT, Block, BlockResponse, sliding_displacement
from .case_records import checked_record
from .geometry import STANDARD_GRAVITY_M_S2
from .modes import REST, ROCK, SLIDE, SLIDE_ROCK
from .rocking import REST_ANGULAR_VELOCITY_RATIO

_HALF_PI = 0.5 * math.pi
#: Relative size below which an event value or a velocity counts as zero [-].
_TINY = 1e-12
#: Guard against an endless cascade of events inside one sample interval.
_MAX_EVENTS_PER_INTERVAL = 20_000
#: Largest DOP853 step, in units of 1/p [-] (so that no excursion hides inside a step).
_MAX_STEP_DIMENSIONLESS = 0.1


@dataclass(frozen=True)
class _Params:
    """Per-unit-mass constants of a block (SI)."""

    b: float
    h: float
    R: float
    alpha: float
    j: float
    p: float
    mu: float
    mu_s: float
    restitution: Optional[float]
    g: float = STANDARD_GRAVITY_M_S2

    @classmethod
    def of(cls, block: Block):
        return cls(block.contact_half_width_m, block.cg_height_m, block.size_m, block.alpha_rad,
                   block.inertia_cm_over_mass_m2, block.p_rad_s, block.mu, block.mu_static,
                   block.restitution)


# --------------------------------------------------------------------------- equations per mode
def _offset(theta, corner, par):
    """(r_x, r_y) [m] of corner ``corner`` (±1) from the centre of mass."""
    phi = corner * par.alpha - theta
    return par.R * math.sin(phi), -par.R * math.cos(phi)


def _rest_forces(accel_g, par):
    """Rest: total friction and normal forces (N₋, N₊) per unit mass [m/s²]."""
    lever = accel_g * par.h / par.b
    return accel_g * par.g, 0.5 * par.g * (1.0 + lever), 0.5 * par.g * (1.0 - lever)


def _slide_acceleration(accel_g, slip, par):
    """Slide with sign ``slip``: (ẍ, N₋, N₊) [m/s²]."""
    lever = par.mu * slip * par.h / par.b
    return -par.g * (accel_g + par.mu * slip), 0.5 * par.g * (1.0 - lever), 0.5 * par.g * (1.0 + lever)


def _rock_acceleration(theta, theta_dot, accel_g, corner, par):
    """Rock on ``corner``: (θ̈ [rad/s²], pivot friction F, normal N [m/s²])."""
    phi = corner * par.alpha - theta
    sin_phi, cos_phi = math.sin(phi), math.cos(phi)
    theta_ddot = -par.p**2 * (sin_phi + accel_g * cos_phi)
    friction = accel_g * par.g + par.R * (cos_phi * theta_ddot + sin_phi * theta_dot**2)
    normal = par.g + par.R * (sin_phi * theta_ddot - cos_phi * theta_dot**2)
    return theta_ddot, friction, normal


def _painleve(theta, corner, slip, par):
    """Whether slide-rock on ``corner`` slipping with sign ``slip`` has no finite contact force."""
    r_x, r_y = _offset(theta, corner, par)
    return par.j + (r_x + par.mu * slip * r_y) * r_x <= _TINY * par.j


def _slide_rock_acceleration(theta, theta_dot, accel_g, corner, slip, par):
    """Slide-rock on ``corner`` slipping with sign ``slip``: (ẍ, θ̈, F, N)."""
    if _painleve(theta, corner, slip, par):
        raise RuntimeError(f"Painlevé paradox in slide-rock (mu = {par.mu}): no consistent contact force")
    r_x, r_y = _offset(theta, corner, par)
    c = r_x + par.mu * slip * r_y
    denominator = par.j + c * r_x
    normal = par.j * (par.g + r_y * theta_dot**2) / denominator
    friction = -par.mu * slip * normal
    return -accel_g * par.g + friction, -c * normal / par.j, friction, normal


# --------------------------------------------------------------------------- phases
@dataclass
class _Phase:
    """A mode with its contact: pivot ``corner``, ``slip`` sign, rock's pivot position."""

    mode: str
    corner: int = 0
    slip: int = 0
    pivot_x: float = 0.0


def _reduce(phase, full):
    """Integrated coordinates of ``phase`` from the full state (x, y, θ, ẋ, ẏ, θ̇)."""
    x, y, theta, x_dot, y_dot, theta_dot = full
    return {SLIDE: [x, x_dot], ROCK: [theta, theta_dot], SLIDE_ROCK: [x, theta, x_dot, theta_dot],
            FLIGHT: list(full), REST: []}[phase.mode]


def _expand(phase, z, par):
    """Full state (x, y, θ, ẋ, ẏ, θ̇) from the integrated coordinates (constraints exact)."""
    if phase.mode == SLIDE:
        return np.array([z[0], par.h, 0.0, z[1], 0.0, 0.0])
    if phase.mode == ROCK:
        theta, theta_dot = z
        r_x, r_y = _offset(theta, phase.corner, par)
        return np.array([phase.pivot_x - r_x, -r_y, theta, -r_y * theta_dot, r_x * theta_dot, theta_dot])
    if phase.mode == SLIDE_ROCK:
        x, theta, x_dot, theta_dot = z
        r_x, r_y = _offset(theta, phase.corner, par)
        return np.array([x, -r_y, theta, x_dot, r_x * theta_dot, theta_dot])
    return np.asarray(z, dtype=float)


def _rhs(phase, par, accel):
    """dz/dt of ``phase`` with the floor acceleration ``accel(t)`` [g]."""
    g, corner, slip = par.g, phase.corner, phase.slip
    if phase.mode == SLIDE:
        return lambda t, z: (z[1], -g * (accel(t) + par.mu * slip))
    if phase.mode == ROCK:
        return lambda t, z: (z[1], _rock_acceleration(z[0], z[1], accel(t), corner, par)[0])

    if phase.mode == SLIDE_ROCK:
        def slide_rock(t, z):
            x_ddot, theta_ddot, _, _ = _slide_rock_acceleration(z[1], z[3], accel(t), corner, slip, par)
            return z[2], z[3], x_ddot, theta_ddot
        return slide_rock
    return lambda t, z: (z[3], z[4], z[5], -g * accel(t), -g, 0.0)


def _events(phase, par, accel):
    """Terminal events {name: g(t, z)}, each > 0 while the mode holds (direction −1)."""
    corner, slip = phase.corner, phase.slip
    if phase.mode == SLIDE:
        return {"stop": lambda t, z: slip * z[1]}
    if phase.mode == ROCK:
        def cone(t, z, sign):
            _, friction, normal = _rock_acceleration(z[0], z[1], accel(t), corner, par)
            return par.mu_s * normal - sign * friction
        return {"impact": lambda t, z: corner * z[0],
                "lift-off": lambda t, z: _rock_acceleration(z[0], z[1], accel(t), corner, par)[2],
                "slip+": lambda t, z: cone(t, z, 1.0), "slip-": lambda t, z: cone(t, z, -1.0),
                "overturn": lambda t, z: _HALF_PI - corner * z[0]}
    if phase.mode == SLIDE_ROCK:
        def slip_velocity(t, z):
            return slip * (z[2] + _offset(z[1], corner, par)[1] * z[3])
        return {"stop": slip_velocity, "impact": lambda t, z: corner * z[1],
                "lift-off": lambda t, z: _slide_rock_acceleration(z[1], z[3], accel(t), corner, slip, par)[3],
                "overturn": lambda t, z: _HALF_PI - corner * z[1]}

    def lowest_corner(t, z):
        return min(z[1] + s * par.b * math.sin(z[2]) - par.h * math.cos(z[2]) for s in (-1.0, 1.0))
    return {"land": lowest_corner, "overturn": lambda t, z: _HALF_PI - abs(z[2])}


def _turning_points(phase, par, accel):
    """{name: (d/dt of an event function, its scale)}: the integration is split where one
    vanishes, so that no event function can dip through zero and back inside a step."""
    corner, slip = phase.corner, phase.slip
    spin = par.p * par.alpha
    if phase.mode == SLIDE:
        return {"turn-stop": (lambda t, z: accel(t) + par.mu * slip, 1.0)}
    if phase.mode == ROCK:
        return {"turn-theta": (lambda t, z: z[1], spin)}
    if phase.mode == SLIDE_ROCK:
        def slip_acceleration(t, z):
            r_x, r_y = _offset(z[1], corner, par)
            x_ddot, theta_ddot, _, _ = _slide_rock_acceleration(z[1], z[3], accel(t), corner, slip, par)
            return x_ddot + r_y * theta_ddot - r_x * z[3] ** 2
        return {"turn-theta": (lambda t, z: z[3], spin), "turn-stop": (slip_acceleration, par.g)}

    def corner_velocity(t, z, sign):  # Ẏ = ẏ − r_x θ̇
        return z[4] - (sign * par.b * math.cos(z[2]) - par.h * math.sin(z[2])) * z[5]
    return {"turn-land-": (lambda t, z: corner_velocity(t, z, -1.0), par.p * par.R),
            "turn-land+": (lambda t, z: corner_velocity(t, z, 1.0), par.p * par.R)}


def _event_scale(name, par):
    """Magnitude of an event function, for 'zero' tests."""
    if name in ("impact", "overturn"):
        return par.alpha
    if name in ("stop",):
        return par.p * par.R
    if name == "land":
        return par.R
    return par.g


def _secant(fun, t_start):
    """The event ``fun`` seen as fun(t)/(t − t_start): positive at t_start, same sign after."""
    def wrapped(t, z):
        return 1.0 if t <= t_start else fun(t, z) / (t - t_start)
    return wrapped


# --------------------------------------------------------------------------- transitions
def _contact_forces(phase, full, accel_g, par):
    """(N₋, N₊, F₋, F₊) per unit mass [m/s²] of ``phase`` at ``full``."""
    forces = [0.0, 0.0, 0.0, 0.0]
    if phase.mode == REST:
        friction, n_minus, n_plus = _rest_forces(accel_g, par)
        return [n_minus, n_plus, friction * n_minus / par.g, friction * n_plus / par.g]
    if phase.mode == SLIDE:
        _, n_minus, n_plus = _slide_acceleration(accel_g, phase.slip, par)
        return [n_minus, n_plus, -par.mu * phase.slip * n_minus, -par.mu * phase.slip * n_plus]
    if phase.mode == ROCK:
        _, friction, normal = _rock_acceleration(full[2], full[5], accel_g, phase.corner, par)
    elif phase.mode == SLIDE_ROCK:
        _, _, friction, normal = _slide_rock_acceleration(full[2], full[5], accel_g, phase.corner,
                                                         phase.slip, par)
    else:
        return forces
    k = (phase.corner + 1) // 2
    forces[k], forces[2 + k] = normal, friction
    return forces


def _select_flat(full, accel_g, par):
    """Mode of a block with both corners on the floor (θ = θ̇ = ẏ = 0), sliding at ẋ or not."""
    x, x_dot = full[0], full[3]
    flat = np.array([x, par.h, 0.0, x_dot, 0.0, 0.0])
    if abs(x_dot) > _TINY * par.p * par.R:
        slip = 1 if x_dot > 0.0 else -1
        _, n_minus, n_plus = _slide_acceleration(accel_g, slip, par)
        if min(n_minus, n_plus) >= 0.0:
            return _Phase(SLIDE, slip=slip), flat
        return _Phase(SLIDE_ROCK, corner=slip, slip=slip), flat
    flat[3] = 0.0
    friction, n_minus, n_plus = _rest_forces(accel_g, par)
    if abs(friction) <= par.mu_s * par.g and min(n_minus, n_plus) >= 0.0:
        return _Phase(REST), flat
    lean = -1 if accel_g > 0.0 else 1  # the way the inertial force pushes
    for corner in (lean, -lean):
        theta_ddot, friction, normal = _rock_acceleration(0.0, 0.0, accel_g, corner, par)
        if corner * theta_ddot > 0.0 and normal > 0.0 and abs(friction) <= par.mu_s * normal:
            return _Phase(ROCK, corner=corner, pivot_x=x + corner * par.b), flat
    for slip in (lean, -lean):
        x_ddot, n_minus, n_plus = _slide_acceleration(accel_g, slip, par)
        if slip * x_ddot > 0.0 and min(n_minus, n_plus) > 0.0:
            return _Phase(SLIDE, slip=slip), flat
    for corner in (lean, -lean):
        for slip in (lean, -lean):
            if _painleve(0.0, corner, slip, par):
                continue
            x_ddot, theta_ddot, _, normal = _slide_rock_acceleration(0.0, 0.0, accel_g, corner, slip, par)
            slip_accel = x_ddot - par.h * theta_ddot
            if corner * theta_ddot > 0.0 and normal > 0.0 and slip * slip_accel > 0.0:
                return _Phase(SLIDE_ROCK, corner=corner, slip=slip), flat
    raise RuntimeError(f"no consistent mode for a block leaving rest at a_g = {accel_g} g")


def _select_on_corner(full, corner, accel_g, par, allow_rock=True):
    """Mode of a block touching the floor with ``corner`` only, its normal velocity zero.

    The first consistent of rock (N ≥ 0, |F| ≤ μs N), slide-rock (N ≥ 0; from
    sticking, the slip accelerating the way it starts, the way friction gives
    first) and flight (the corner accelerating off the floor).
    """
    theta, theta_dot = full[2], full[5]
    r_x, r_y = _offset(theta, corner, par)
    slip_velocity = full[3] + r_y * theta_dot
    if abs(slip_velocity) <= _TINY * par.p * par.R:
        _, friction, normal = _rock_acceleration(theta, theta_dot, accel_g, corner, par)
        if allow_rock and normal >= 0.0 and abs(friction) <= par.mu_s * normal:
            return _Phase(ROCK, corner=corner, pivot_x=full[0] + r_x), full
        lean = -1 if friction > 0.0 else 1
        candidates = ((lean, True), (-lean, True))
    else:
        candidates = ((1 if slip_velocity > 0.0 else -1, False),)
    for slip, starting in candidates:
        if _painleve(theta, corner, slip, par):
            continue
        x_ddot, theta_ddot, _, normal = _slide_rock_acceleration(theta, theta_dot, accel_g, corner, slip, par)
        slip_accel = x_ddot + r_y * theta_ddot - r_x * theta_dot**2
        # starting at the cone's edge with μ = μs the slip acceleration is zero: allow round-off
        if normal >= 0.0 and (not starting or slip * slip_accel > -_TINY * par.g):
            return _Phase(SLIDE_ROCK, corner=corner, slip=slip), full
    if -par.g - r_y * theta_dot**2 >= 0.0:  # the free corner's vertical acceleration
        return _Phase(FLIGHT), full
    raise RuntimeError(f"no consistent mode on corner {corner:+d} at theta = {theta:.6g} rad, "
                       f"theta_dot = {theta_dot:.6g} rad/s, a_g = {accel_g:.6g} g (mu = {par.mu})")


def _corner_impulse(full, corner, par):
    """Impulse (P_T, P_N) per unit mass [m/s] at an arriving ``corner``, and whether it sticks."""
    theta, x_dot, y_dot, theta_dot = full[2], full[3], full[4], full[5]
    r_x, r_y = _offset(theta, corner, par)
    v_t, v_n = x_dot + r_y * theta_dot, y_dot - r_x * theta_dot
    # Δ(v_t, v_n) = W (P_T, P_N), W the corner's inverse effective mass
    w11, w12, w22 = 1.0 + r_y**2 / par.j, -r_x * r_y / par.j, 1.0 + r_x**2 / par.j
    det = w11 * w22 - w12 * w12
    p_t, p_n = (-v_t * w22 + v_n * w12) / det, (-v_n * w11 + v_t * w12) / det
    if abs(p_t) <= par.mu_s * p_n:
        return p_t, p_n, True
    slip = -1.0 if p_t > 0.0 else 1.0
    denominator = w22 - par.mu * slip * w12
    if denominator <= _TINY:
        raise RuntimeError(f"Painlevé paradox at an impact (mu = {par.mu}): no consistent impulse")
    p_n = -v_n / denominator
    return -par.mu * slip * p_n, p_n, False


def _apply_impulse(full, corner, p_t, p_n, par):
    """State after impulses (P_T, P_N) per unit mass [m/s] at ``corner``."""
    r_x, r_y = _offset(full[2], corner, par)
    after = full.copy()
    after[3] += p_t
    after[4] += p_n
    after[5] -= (r_x * p_n - r_y * p_t) / par.j
    return after


def _impact(full, corner, accel_g, par, log):
    """(state after ``corner`` arrives on the floor, whether the block is now flat).

    ``log`` counts the impacts and the settlings that end a Zeno sequence.
    """
    p_t, p_n, sticks = _corner_impulse(full, corner, par)
    after = _apply_impulse(full, corner, p_t, p_n, par)
    log["impacts"] += 1
    at_zero = abs(full[2]) <= _TINY * par.alpha
    if at_zero:
        after[2] = 0.0
        if sticks and par.restitution is not None:  # override: ratio e, new pivot at rest
            r_x, r_y = _offset(0.0, corner, par)
            after[5] = par.restitution * full[5]
            after[3], after[4] = -r_y * after[5], r_x * after[5]
        other_r_x = _offset(0.0, -corner, par)[0]
        if after[4] - other_r_x * after[5] < 0.0:  # the other corner would sink: lands flat
            return _land_flat(full, par), True
        if abs(after[5]) < REST_ANGULAR_VELOCITY_RATIO * par.p * par.alpha:
            theta_ddot = _rock_acceleration(0.0, 0.0, accel_g, corner, par)[0]
            if corner * theta_ddot <= 0.0:  # floor pushes back: the Zeno sequence has converged
                log["settlings"] += 1
                after[3] += _offset(0.0, corner, par)[1] * after[5]  # base moves as the corner slips
                after[4] = after[5] = 0.0
                return after, True
    return after, False


def _land_flat(full, par):
    """Both corners land at θ = 0: ẏ = θ̇ = 0, horizontal impulse within the friction cone."""
    p_n = max(0.0, -full[4])
    x_dot = full[3]
    if abs(x_dot) <= par.mu_s * p_n:
        x_dot = 0.0
    else:
        x_dot -= math.copysign(par.mu * p_n, x_dot)
    return np.array([full[0], par.h, 0.0, x_dot, 0.0, 0.0])


def _after_event(phase, name, full, accel_g, par, log):
    """(phase, full) after terminal event ``name`` of ``phase``; None when overturned."""
    if name == "overturn":
        return None
    if phase.mode == SLIDE:  # stop
        return _select_flat(full, accel_g, par)
    if name == "lift-off" and -par.g - _offset(full[2], phase.corner, par)[1] * full[5]**2 >= -_TINY * par.g:
        return _Phase(FLIGHT), full  # the corner's acceleration off the floor, were it free, ≥ 0
    if name in ("lift-off", "slip+", "slip-"):
        return _select_on_corner(full, phase.corner, accel_g, par, allow_rock=False)
    if name == "stop":
        return _select_on_corner(full, phase.corner, accel_g, par)
    if name == "impact":
        full = full.copy()
        full[2] = 0.0
        after, flat = _impact(full, -phase.corner, accel_g, par, log)
        if flat:
            return _select_flat(after, accel_g, par)
        return _select_on_corner(after, -phase.corner, accel_g, par)
    # land (from flight): the lower corner arrives, or both when flat
    if abs(full[2]) <= _TINY * par.alpha:
        log["impacts"] += 1
        return _select_flat(_land_flat(full, par), accel_g, par)
    corner = 1 if full[2] > 0.0 else -1
    after, _ = _impact(full, corner, accel_g, par, log)
    return _select_on_corner(after, corner, accel_g, par)


def _rest_onset(t_from, t_to, accel_start, slope, t_start, threshold):
    """First t in [t_from, t_to) with |a| > threshold on the linear input, and a there; or None."""
    a_from = accel_start + slope * (t_from - t_start)
    if abs(a_from) > threshold:
        return t_from, a_from
    a_to = accel_start + slope * (t_to - t_start)
    if abs(a_to) <= threshold:
        return None
    level = math.copysign(threshold, a_to)
    t_cross = min(max(t_start + (level - accel_start) / slope, t_from), t_to)
    return t_cross, level * (1.0 + _TINY)


# --------------------------------------------------------------------------- driver
@dataclass
class _Run:
    """What the driver accumulates."""

    theta_max: float = 0.0
    u_max: float = 0.0
    uplift: bool = False
    overturn_time_s: float = math.nan
    modes: list = field(default_factory=list)
    log: dict = field(default_factory=lambda: {"impacts": 0, "settlings": 0})
    trace: Optional[list] = None
    impacts: Optional[list] = None

    def enter(self, t, phase):
        if not self.modes or self.modes[-1][1] != phase.mode:
            self.modes.append((float(t), phase.mode))
        self.uplift |= phase.mode in (ROCK, SLIDE_ROCK, FLIGHT)

    def see(self, full, par):
        self.theta_max = max(self.theta_max, abs(full[2]))
        self.u_max = max(self.u_max, abs(float(sliding_displacement(full[0], full[2], par.b, par.h))))

    def note(self, t, phase, full, accel_g, par):
        if self.trace is not None:
            self.trace.append((t, phase.mode, *full, *_contact_forces(phase, full, accel_g, par)))


def _advance(phase, full, t, t_end, floor, par, rtol, run, turns=True):
    """Integrate ``phase`` from (t, full) towards t_end: (t, full, name of the event or None).

    An event already violated at t (the input jumps at the ends of the record)
    fires at once; one that is zero at t is taken on its secant, so the mode
    may leave at once but not at its own start. The integration also stops at
    the turning points of the event functions (:func:`_turning_points`),
    peaks of |θ| among them; peaks of |θ| and |u| are passed to ``run``.
    """
    z0 = _reduce(phase, full)
    funs = []
    for name, fun in _events(phase, par, floor).items():
        value, scale = fun(t, z0), _event_scale(name, par)
        if value < -1e-9 * scale:
            return t, full, name
        if value <= _TINY * scale:
            fun = _secant(fun, t)
        fun.terminal, fun.direction, fun.name = True, -1.0, name
        funs.append(fun)
    for name, (fun, scale) in _turning_points(phase, par, floor).items() if turns else ():
        if abs(fun(t, z0)) > _TINY * scale:  # not the turning point just split at
            fun.terminal, fun.direction, fun.name = True, 0.0, name
            funs.append(fun)
    rhs = _rhs(phase, par, floor)
    options = dict(method="DOP853", rtol=rtol, atol=[1e-3 * rtol * s for s in _state_scales(phase.mode, par)],
                   max_step=min(t_end - t, _MAX_STEP_DIMENSIONLESS / par.p))
    sol = solve_ivp(rhs, (t, t_end), z0, events=funs, **options)
    name = _fired(sol, funs)
    if name is not None and name.startswith("turn"):
        mode_events = [f for f in funs if not f.name.startswith("turn")]
        if any(f(sol.t[-1], sol.y[:, -1]) < 0.0 for f in mode_events):
            # an event function went through zero inside the last step and is at its
            # minimum here: from the step's start it only falls, so locate the crossing
            again = solve_ivp(rhs, (sol.t[-2], sol.t[-1]), sol.y[:, -2], events=mode_events, **options)
            if _fired(again, mode_events) is not None:
                sol, name = again, _fired(again, mode_events)
    for z in sol.y.T:  # the last point is the event, peaks of |θ| included
        run.see(_expand(phase, z, par), par)
    full_end = _expand(phase, sol.y[:, -1], par)
    return (t_end, full_end, None) if name is None else (float(sol.t[-1]), full_end, name)


def _fired(sol, funs):
    """Name of the terminal event that stopped ``sol``, or None."""
    if sol.status != 1:
        return None
    return next(f.name for f, te in zip(funs, sol.t_events) if te.size and te[-1] == sol.t[-1])


def _state_scales(mode, par):
    """Magnitudes of the integrated coordinates of ``mode`` (for the absolute tolerance)."""
    length, angle, speed, spin = par.R, par.alpha, par.p * par.R, par.p * par.alpha
    return {SLIDE: (length, speed), ROCK: (angle, spin), SLIDE_ROCK: (length, angle, speed, spin),
            FLIGHT: (length, length, angle, speed, speed, spin)}[mode]


def _interval(phase, full, t_start, t_end, a_start, a_end, par, rtol, run):
    """Carry the block over one sample interval, the input linear in it: (phase, full) at t_end.

    Returns (None, full) if the block overturns in the interval.
    """
    slope = (a_end - a_start) / (t_end - t_start)

    def floor(t_s):
        return a_start + slope * (t_s - t_start)
    t = t_start
    for _ in range(_MAX_EVENTS_PER_INTERVAL):
        if t_end - t <= 1e-12 * (t_end - t_start):
            break
        if phase.mode == REST:
            threshold = min(par.mu_s, par.b / par.h)
            onset = _rest_onset(t, t_end, a_start, slope, t_start, threshold)
            if onset is None:
                break
            t, a_onset = onset
            run.note(t, phase, full, math.copysign(threshold, a_onset), par)  # last state at rest
            phase, full = _select_flat(full, a_onset, par)
            run.enter(t, phase)
            run.note(t, phase, full, a_onset, par)
            continue
        t_event, full_event, name = _advance(phase, full, t, t_end, floor, par, rtol, run)
        if name is None:
            full = full_event
            break
        if name.startswith("turn"):  # a turning point: carry on in the same mode
            if t_event == t:  # no progress (round-off at the turning point): step on without
                t_event, full_event, name = _advance(phase, full, t, t_end, floor, par, rtol, run, False)
                if name is None:
                    full = full_event
                    break
            if name.startswith("turn"):
                t, full = t_event, full_event
                continue
        t, a_event = t_event, floor(t_event)
        run.note(t, phase, full_event, a_event, par)
        outcome = _after_event(phase, name, full_event, a_event, par, run.log)
        if outcome is None:
            run.theta_max, run.overturn_time_s = _HALF_PI, t
            return None, full_event
        phase, full = outcome
        if run.impacts is not None and name in ("impact", "land"):
            run.impacts.append((t, full_event, full.copy()))
        run.enter(t, phase)
        run.see(full, par)
        run.note(t, phase, full, a_event, par)
    else:
        raise RuntimeError(f"more than {_MAX_EVENTS_PER_INTERVAL} events in the interval at t = {t:.6g} s")
    run.note(t_end, phase, full, a_end, par)
    return phase, full


def _check_inputs(floor_accel_g, dt_s, tail_s, initial_theta_rad, rtol):
    accel, _ = checked_record(floor_accel_g, dt_s, min_samples=2)
    if not (np.isfinite(tail_s) and tail_s >= 0.0):
        raise ValueError("tail_s must be finite and >= 0")
    if not abs(initial_theta_rad) < _HALF_PI:
        raise ValueError("initial_theta_rad must lie in (-pi/2, pi/2)")
    if not 0.0 < rtol < 1e-3:
        raise ValueError("rtol must lie in (0, 1e-3)")
    return accel


def _simulate(block, floor_accel_g, dt_s, tail_s=10.0, return_history=False, initial_theta_rad=0.0,
              rtol=1e-9, keep_trace=False):
    """Integrate; returns (BlockResponse, _Run). See :func:`simulate_event_driven`."""
    accel = _check_inputs(floor_accel_g, dt_s, tail_s, initial_theta_rad, rtol)
    par = _Params.of(block)
    dt = float(dt_s)
    n_record, n_tail = accel.size, int(math.ceil(tail_s / dt - 1e-9))
    run = _Run(trace=[] if keep_trace else None, impacts=[] if keep_trace else None)

    full = np.array([0.0, par.h, 0.0, 0.0, 0.0, 0.0])
    phase = _Phase(REST)
    run.enter(0.0, phase)
    if initial_theta_rad != 0.0:
        corner = 1 if initial_theta_rad > 0.0 else -1
        r_x, r_y = _offset(initial_theta_rad, corner, par)
        full = np.array([corner * par.b - r_x, -r_y, initial_theta_rad, 0.0, 0.0, 0.0])
        phase, full = _select_on_corner(full, corner, accel[0], par)
        run.modes = []
        run.enter(0.0, phase)
        run.uplift = True
    run.see(full, par)
    run.note(0.0, phase, full, 0.0 if phase.mode == REST else accel[0], par)  # floor at rest before 0
    history_u, history_theta = [float(sliding_displacement(full[0], full[2], par.b, par.h))], [full[2]]

    for k in range(n_record - 1 + n_tail):
        a_start, a_end = (accel[k], accel[k + 1]) if k < n_record - 1 else (0.0, 0.0)
        phase, full = _interval(phase, full, k * dt, (k + 1) * dt, a_start, a_end, par, rtol, run)
        if phase is None:
            break
        history_u.append(float(sliding_displacement(full[0], full[2], par.b, par.h)))
        history_theta.append(full[2])
        if k >= n_record - 2 and phase.mode == REST:
            break

    overturned = not math.isnan(run.overturn_time_s)
    history = {}
    if return_history:
        n_total = n_record + n_tail
        u, theta = np.full(n_total, np.nan), np.full(n_total, np.nan)
        u[:len(history_u)], theta[:len(history_theta)] = history_u, history_theta
        if not overturned:  # at rest before the end of the tail: it stays there
            u[len(history_u):], theta[len(history_theta):] = history_u[-1], history_theta[-1]
        history = dict(time_s=np.arange(n_total) * dt, sliding_m=u, theta_rad=theta)
    residual = float(sliding_displacement(full[0], full[2], par.b, par.h))
    response = BlockResponse(sliding_max_m=run.u_max, sliding_residual_m=residual,
                             theta_max_over_alpha=float(run.theta_max / par.alpha), uplift=run.uplift,
                             overturned=overturned, overturn_time_s=run.overturn_time_s,
                             mode_sequence=tuple(run.modes), **history)
    return response, run


def simulate_event_driven(block: Block, floor_accel_g, dt_s, *, tail_s=10.0, return_history=False,
                          initial_theta_rad=0.0, rtol=1e-9) -> BlockResponse:
    """Response of a rigid block to a floor motion, by the event-driven method.

    Integrates the block model of :mod:`assess.mechanics.block` mode by mode
    (rest, slide, rock, slide-rock, flight), locating every transition; see
    the module docstring for the equations, the onset rules and the impacts.

    Parameters
    ----------
    block : Block
        Geometry, friction (μ, μ_s) and optional restitution override.
    floor_accel_g : array-like
        Floor acceleration [g] at 0, dt, 2dt, ..., linear between samples;
        the floor is at rest before t = 0 and after the last sample.
    dt_s : float
        Sample interval [s].
    tail_s : float
        Run-out followed after the record, floor at rest [s]; the run stops
        earlier once the block is at rest (flat, sticking).
    return_history : bool
        Also return u [m] and θ [rad] at the samples of the record and of the
        run-out (the resting values once the block is at rest; NaN after
        overturning).
    initial_theta_rad : float
        Released at rest on one corner with this rotation [rad]; 0: flat.
    rtol : float
        Relative tolerance of the DOP853 integration [-].

    Returns
    -------
    BlockResponse

    Examples
    --------
    The FORMA incubator (b/h = 0.272) on a rectangular pulse of 0.3 g for
    0.5 s: with μ = 0.13 it slides, by Newmark's
    ap Tp² (ap − μg)/(2μg) = 0.4809 m, and stops at ap Tp/(μg) = 1.154 s;
    with μ = 0.68 it rocks, then settles:

    >>> forma = dict(half_width_m=0.311, cg_height_m=1.143, height_m=2.286)
    >>> r = simulate_event_driven(Block(mu=0.13, **forma), [0.3, 0.3], 0.5)
    >>> r.mode, round(r.sliding_max_m, 4), r.uplift, round(r.mode_sequence[-1][0], 3)
    ('slide', 0.4809, False, 1.154)
    >>> r = simulate_event_driven(Block(mu=0.68, **forma), [0.3, 0.3], 0.5)
    >>> [mode for _, mode in r.mode_sequence], r.sliding_max_m < 1e-12
    (['rest', 'rock', 'rest'], True)
    """
    return _simulate(block, floor_accel_g, dt_s, tail_s=tail_s, return_history=return_history,
                     initial_theta_rad=initial_theta_rad, rtol=rtol)[0]
