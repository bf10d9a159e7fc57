"""Newmark's average acceleration with Newton iterations: what the yielding models' kernels share.

The storey stick (:mod:`assess.building.nonlinear`) and the wall on its base hinge
(:mod:`assess.building.wall_hinge`) step the same way: Newmark's average-acceleration method
(γ = 1/2, β = 1/4, Newmark [2]_) with Newton iterations on the tangent stiffness at every substep
(Chopra [1]_ §15.3), the ground acceleration linear between the record's samples. Here: the substep
rules, Newton's tolerance, the linear solve of each iteration, the Rayleigh coefficients, and the
response both return.

References
----------
.. [1] Chopra, A. K. (2012). Dynamics of Structures, 4th ed. Pearson. §5.5 (Newmark's period error),
   §11.4 (Rayleigh damping), §15.3 (Newmark's method for nonlinear systems).
.. [2] Newmark, N. M. (1959). A method of computation for structural dynamics.
   J. Eng. Mech. Div. ASCE 85(EM3):67-94.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2

#: Longest substep [s] of the integration by default, and the fewest substeps per period of the
#: stick's shortest elastic mode (Newmark's period error is (π²/12)(Δt/T)², Chopra [1]_ §5.5:
#: 5e-3 at 40 steps; a stiff flexural mode of 0.02 s otherwise drifts out of phase in a long record).
DEFAULT_SUBSTEP_S = 0.001
STEPS_PER_SHORTEST_PERIOD = 40
#: Newton's tolerance on the norm of the displacement correction [m] and its iteration cap.
TOLERANCE_M = 1e-12
MAX_ITERATIONS = 50


@dataclass(frozen=True)
class YieldingResponse:
    """Response history of a yielding model (:class:`~assess.building.nonlinear.YieldingStick`,
    :class:`~assess.building.wall_hinge.HingedWall`) under one ground motion.

    Attributes
    ----------
    floor_accel_g : ndarray, (n + 1, n_samples)
        Absolute acceleration [g] of each floor, row 0 the ground.
    drift_m : ndarray, (n, n_samples)
        Storey drift (floor i minus floor i-1) [m].
    peak_drift_ratio : ndarray, (n,)
        max |drift_i| / h_i [-].
    ductility : ndarray, (n,)
        max |drift_i| / (F_y,i / k_0,i) [-]: below 1, the storey stayed elastic (a wall on its base
        hinge: its rotation ductility at the base in storey 1's place, NaN above).
    unconverged_steps : int
        Substeps where Newton's iterations stopped at their cap (0 expected).
    """

    floor_accel_g: np.ndarray
    drift_m: np.ndarray
    peak_drift_ratio: np.ndarray
    ductility: np.ndarray
    unconverged_steps: int


def rayleigh_coefficients(periods_s, damping=0.05, modes=(1, 3)):
    """(a_0, a_1) of Rayleigh damping with ratio ζ at two modes (1-based; capped at the last mode).

    .. math::  a_0 = \\zeta\\frac{2\\omega_i\\omega_j}{\\omega_i + \\omega_j},\\qquad
               a_1 = \\zeta\\frac{2}{\\omega_i + \\omega_j}

    (Chopra [1]_ eq. 11.4.9 with ζ_i = ζ_j). Examples: ω 10 and 30 rad/s, 5 %:
    a_0 = 0.05·600/40 = 0.75, a_1 = 0.1/40 = 0.0025:

    >>> a0, a1 = rayleigh_coefficients(2 * np.pi / np.array([10.0, 20.0, 30.0]), 0.05)
    >>> round(a0, 6), round(a1, 6)
    (0.75, 0.0025)
    """
    omega = 2.0 * np.pi / np.asarray(periods_s, dtype=float)
    if omega.size == 1:
        return 0.0, 2.0 * damping / omega[0]
    i = min(modes[0], omega.size) - 1
    j = min(modes[1], omega.size) - 1
    wi, wj = omega[i], omega[j]
    return float(damping * 2.0 * wi * wj / (wi + wj)), float(damping * 2.0 / (wi + wj))


@njit(cache=True)
def _solve(matrix, rhs, out):  # pragma: no cover - compiled
    """out = matrix⁻¹ rhs, Gaussian elimination without pivoting (SPD-dominant: M/βΔt²); overwrites matrix."""
    n = rhs.size
    b = rhs.copy()
    for k in range(n):
        pivot = matrix[k, k]
        for i in range(k + 1, n):
            factor = matrix[i, k] / pivot
            if factor != 0.0:
                for j in range(k, n):
                    matrix[i, j] -= factor * matrix[k, j]
                b[i] -= factor * b[k]
    for i in range(n - 1, -1, -1):
        total = b[i]
        for j in range(i + 1, n):
            total -= matrix[i, j] * out[j]
        out[i] = total / matrix[i, i]


#: Newmark's average acceleration: γ and β.
GAMMA, BETA = 0.5, 0.25


@njit(cache=True)
def _gains(h):  # pragma: no cover - compiled
    """``(c_mass, c_vel)``: what multiplies the mass and the damping matrices in Newton's matrix of a step of
    ``h`` [s] (Newmark's average acceleration, :data:`GAMMA`, :data:`BETA`)."""
    return 1.0 / (BETA * h * h), GAMMA / (BETA * h)


@njit(cache=True)
def _rates(u_new, u, v, a, a_new, v_new, h, count):  # pragma: no cover - compiled
    """Newmark's average acceleration (γ = 1/2, β = 1/4) at the trial displacements ``u_new`` of the first
    ``count`` degrees of freedom: the accelerations into ``a_new``, the velocities into ``v_new``."""
    c_mass = _gains(h)[0]
    for r in range(count):
        a_new[r] = c_mass * (u_new[r] - u[r]) - v[r] / (BETA * h) - (0.5 / BETA - 1.0) * a[r]
        v_new[r] = v[r] + h * ((1.0 - GAMMA) * a[r] + GAMMA * a_new[r])


@njit(cache=True)
def _record(accel_out, drift_out, column, ground_g, u, a, n):  # pragma: no cover - compiled
    """The sample ``column`` of the floors' absolute accelerations [g] (the ground's in row 0) and of the
    storeys' drifts [m], from the floors' displacements ``u`` [m] and relative accelerations ``a`` [m/s²]."""
    accel_out[0, column] = ground_g
    for r in range(n):
        accel_out[r + 1, column] = ground_g + a[r] / STANDARD_GRAVITY_M_S2
        drift_out[r, column] = u[r] - (u[r - 1] if r > 0 else 0.0)


def substeps_for(dt_s, substep_s=DEFAULT_SUBSTEP_S) -> int:
    """Substeps per record step so that each is at most ``substep_s``."""
    return max(1, int(np.ceil(float(dt_s) / float(substep_s) - 1e-9)))
