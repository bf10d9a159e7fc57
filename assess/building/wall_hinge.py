"""A wall that yields at its base: the elastic model rotating on a plastic hinge.

A capacity-designed cantilever wall forms its plastic hinge at the base and stays elastic above
it (Paulay & Priestley [1]_ ch. 5). The building's elastic model (the lateral stiffness K of
:func:`~assess.building.modes.stiffness_matrix`, the elastic route's, to the scale of T_1) stands on
a rotational spring at its base: the floors move as the elastic model deforms, plus a rigid rotation
θ of the whole about the base,

.. math::  u = r + h\\,\\theta,\\qquad
           K_T = \\begin{bmatrix} K_e & -K_e h \\\\ -h^T K_e & h^T K_e h + k_{\\theta,T}\\end{bmatrix}

with r the elastic model's own deformation, h the floors' heights, degrees of freedom (u_1..u_n, θ)
and no mass at θ. Statics makes the hinge carry the base moment Σ F_x h_x of any lateral forces F,
so the hinge yields at M_y = V_y Σ F_x h_x / Σ F_x under the code's lateral forces F (ASCE 7-22
§12.8.3) with V_y the base shear at yield.

**The hinge's stiffness** is set as concentrated-plasticity models set it (Ibarra & Krawinkler [2]_
App. B, as the OpenSees examples [3]_ apply it, n = :data:`STIFFNESS_RATIO_N`): the hinge n + 1 times
a reference rotational stiffness k_ref, the elastic part (n + 1)/n times the elastic model, so that
the assembly is as stiff as the elastic model. k_ref is the elastic model's stiffness as a rigid bar
rotating on its base with the same roof displacement under a load at the roof, k_ref = H²/f_rr (f_rr
the roof's flexibility; 3EI/H for a flexural cantilever): under a roof load the assembly's roof
displacement is then the elastic model's exactly; the whole assembly is then scaled so that its T_1
is the elastic model's (:func:`hinged_wall`). The hinge's hardening b_s = b/(1 + n(1 − b)) gives the
assembly the hardening b ([3]_, the corrected eq. B.5 of [2]_).

**Damping** (Zareian & Medina [4]_): Rayleigh, a_0 M on the floors and a_1 (n + 1)/n K_e on the
elastic part only, none on the hinge: a yielding hinge gets no spurious damping force, and at small
amplitudes the assembly has the damping of a_0 M + a_1 K (the Kelvin element in series with the stiff
hinge carries n/(n + 1) of a_1). The matrix is constant; only the hinge's tangent changes (so Newton's
matrix is inverted once and updated by Sherman-Morrison at each iteration).

**Integration** as the storey stick's (:mod:`assess.building.nonlinear`): Newmark's average
acceleration with Newton iterations at substeps, the ground linear between samples; the hinge's law
is the system's (:mod:`assess.building.hysteresis`).

**Ductility**: the wall's rotation ductility at its base, 1 + θ_p/θ_y with θ_p the hinge's peak
rotation beyond its yield rotation and θ_y = M_y/k_ref the elastic model's rotation at yield (the
hinge's own elastic rotation is only the device's 1/(n + 1) of it, so its own ductility would depend
on n).

References
----------
.. [1] Paulay, T. and Priestley, M. J. N. (1992). Seismic Design of Reinforced Concrete and Masonry
   Buildings. Wiley. Ch. 5 (cantilever walls: the plastic hinge at the base, the wall above elastic).
.. [2] Ibarra, L. F. and Krawinkler, H. (2005). Global collapse of frame structures under seismic
   excitations. Report 152, John A. Blume Earthquake Engineering Center, Stanford. App. B (stiffness
   modification of an elastic element and its end springs). Its rule as the OpenSees examples [3]_
   state it.
.. [3] Eads, L. (2010-2012). OpenSees examples "Pushover Analysis of 2-Story Moment Frame" (springs n times
   the element's rotational stiffness, the element (n + 1)/n, the springs' hardening
   α/(1 + n(1 − α))) and "Pushover and Dynamic Analyses of 2-Story Moment Frame with Panel Zones and RBS"
   (n = 10; stiffness-proportional damping (n + 1)/n on the modified elements, none on the springs).
   https://opensees.berkeley.edu/wiki
.. [4] Zareian, F. and Medina, R. A. (2010). A practical method for proper modeling of structural damping
   in inelastic plane structural systems. Computers & Structures 88(1-2):45-53.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit
from scipy.linalg import eigh

from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2

from .hysteresis import LAWS, STATE_SIZE, spring_parameters, spring_trial
from .newmark import (DEFAULT_SUBSTEP_S, MAX_ITERATIONS, STEPS_PER_SHORTEST_PERIOD, TOLERANCE_M,
                      YieldingResponse, _gains, _rates, _record, _solve, rayleigh_coefficients, substeps_for)

#: n of the stiffness modification: the hinge's elastic stiffness over the reference k_ref is n + 1 (Ibarra &
#: Krawinkler [2]_'s n = 10, the OpenSees examples' [3]_).
STIFFNESS_RATIO_N = 10.0


@dataclass(frozen=True)
class HingedWall:
    """The yielding wall as the integrator takes it (SI units; module text).

    Attributes
    ----------
    floor_masses_kg : ndarray, (n,)
        m_i, floor 1 to the roof.
    storey_heights_m : ndarray, (n,)
        h_i.
    elastic_stiffness_n_m : ndarray, (n, n)
        K_e, the elastic part's lateral stiffness (the elastic model's, times (n + 1)/n, to the scale of T_1).
    hinge_stiffness_n_m_rad : float
        k_θ, the hinge's elastic stiffness [N m/rad], (n + 1) k_ref.
    reference_stiffness_n_m_rad : float
        k_ref [N m/rad].
    yield_moment_n_m : float
        M_y.
    hinge_hardening : float
        b_s, the hinge's post-yield stiffness ratio [-].
    hardening : float
        b, the assembly's [-].
    law : str
        ``"bilinear"`` or ``"pinching"``.
    rayleigh : (float, float)
        a_0 [1/s] on the floors' masses, a_1 [s] of the assembly (the elastic part takes a_1 (n + 1)/n).
    stiffness_ratio_n : float
        n.
    pinch_x, pinch_y, unloading_beta : float
        Parameters of the pinching law.
    geometric_stiffness_n_m : ndarray (n, n), optional
        The gravity loads' P-Delta stiffness on the floors' displacements
        (:func:`~assess.building.nonlinear.p_delta_stiffness`), where asked.
    """

    floor_masses_kg: np.ndarray
    storey_heights_m: np.ndarray
    elastic_stiffness_n_m: np.ndarray
    hinge_stiffness_n_m_rad: float
    reference_stiffness_n_m_rad: float
    yield_moment_n_m: float
    hinge_hardening: float
    hardening: float
    law: str
    rayleigh: tuple
    stiffness_ratio_n: float = STIFFNESS_RATIO_N
    pinch_x: float = 0.8
    pinch_y: float = 0.4
    unloading_beta: float = 0.4
    geometric_stiffness_n_m: np.ndarray | None = None

    @property
    def storeys(self) -> int:
        return self.floor_masses_kg.size

    @property
    def floor_heights_m(self) -> np.ndarray:
        return np.cumsum(self.storey_heights_m)

    @property
    def yield_rotation_rad(self) -> float:
        """θ_y = M_y/k_ref, the elastic model's base rotation at yield (module text)."""
        return self.yield_moment_n_m / self.reference_stiffness_n_m_rad

    def assembled_stiffness(self, hinge_tangent_n_m_rad=None, p_delta=True) -> np.ndarray:
        """K_T of the module text, (n + 1, n + 1), the hinge at k_θ unless a tangent is given, with the
        P-Delta stiffness where the wall has it (and ``p_delta``)."""
        matrix = _assembled(self.elastic_stiffness_n_m, self.floor_heights_m,
                            self.hinge_stiffness_n_m_rad if hinge_tangent_n_m_rad is None
                            else float(hinge_tangent_n_m_rad))
        if p_delta and self.geometric_stiffness_n_m is not None:
            matrix[:-1, :-1] += self.geometric_stiffness_n_m
        return matrix


def _assembled(elastic, heights, hinge):
    n = heights.size
    matrix = np.zeros((n + 1, n + 1))
    kh = elastic @ heights
    matrix[:n, :n] = elastic
    matrix[:n, n] = -kh
    matrix[n, :n] = -kh
    matrix[n, n] = heights @ kh + hinge
    return matrix


def lateral_stiffness(wall: HingedWall, hinge_tangent_n_m_rad=None) -> np.ndarray:
    """The floors' lateral stiffness [N/m] (n, n) of the assembly, θ condensed out (massless)."""
    full = wall.assembled_stiffness(hinge_tangent_n_m_rad)
    n = wall.storeys
    return full[:n, :n] - np.outer(full[:n, n], full[n, :n]) / full[n, n]


def hinged_periods(wall: HingedWall) -> np.ndarray:
    """Periods [s] of the assembly with the hinge elastic."""
    omega2 = eigh(lateral_stiffness(wall), np.diag(wall.floor_masses_kg), eigvals_only=True)
    return 2.0 * np.pi / np.sqrt(omega2)


def reference_stiffness(stiffness_n_m, floor_heights_m) -> float:
    """k_ref = H²/f_rr [N m/rad]: the elastic model as a rigid bar on its base with its roof displacement
    under a roof load (module text).

    A cantilever of EI = 3 N m², 1 m high, one floor: 3EI/H³ = 9 N/m, k_ref = 3EI/H = 9 N m/rad:

    >>> reference_stiffness([[9.0]], [1.0])
    9.0
    """
    flexibility = np.linalg.inv(np.asarray(stiffness_n_m, dtype=float))
    height = float(np.asarray(floor_heights_m, dtype=float)[-1])
    return height ** 2 / float(flexibility[-1, -1])


def hinged_wall(stiffness, storey_heights_m, floor_masses_kg, period_s, yield_base_shear_n, floor_forces, *,
                law="pinching", hardening=0.03, damping=0.05, rayleigh_modes=(1, 3),
                stiffness_ratio_n=STIFFNESS_RATIO_N, geometric_stiffness_n_m=None) -> HingedWall:
    """The elastic model of lateral stiffness ``stiffness`` (any scale) on a base hinge (module text).

    Parameters
    ----------
    stiffness : array-like, (n, n)
        The elastic model's lateral stiffness (:func:`~assess.building.modes.stiffness_matrix`), any scale.
    storey_heights_m, floor_masses_kg : array-like, (n,)
    period_s : float
        T_1 the assembly is scaled to.
    yield_base_shear_n : float
        V_y, the base shear at which the hinge yields under ``floor_forces``'s pattern.
    floor_forces : array-like, (n,)
        The lateral forces' pattern (ASCE 7-22 §12.8.3's C_vx).
    law, hardening :
        The hinge's law and the assembly's post-yield stiffness ratio b.
    damping, rayleigh_modes :
        ζ at the assembly's modes ``rayleigh_modes`` (1-based), without P-Delta.
    geometric_stiffness_n_m : array-like (n, n), optional
        P-Delta's (:func:`~assess.building.nonlinear.p_delta_stiffness`); T_1 stays that without it.
    """
    heights = np.cumsum(np.asarray(storey_heights_m, dtype=float))
    masses = np.asarray(floor_masses_kg, dtype=float)
    base = np.asarray(stiffness, dtype=float)
    n_mod = float(stiffness_ratio_n)
    forces = np.asarray(floor_forces, dtype=float)
    b = float(hardening)
    unscaled = HingedWall(masses, np.diff(np.concatenate([[0.0], heights])), base * (n_mod + 1.0) / n_mod,
                          (n_mod + 1.0) * reference_stiffness(base, heights), reference_stiffness(base, heights),
                          1.0, b / (1.0 + n_mod * (1.0 - b)), b, law, (0.0, 0.0), n_mod)
    scale = (hinged_periods(unscaled)[0] / float(period_s)) ** 2
    periods = hinged_periods(unscaled) / np.sqrt(scale)
    a0, a1 = rayleigh_coefficients(periods, damping, rayleigh_modes)
    moment = float(yield_base_shear_n) * float(forces @ heights / forces.sum())
    if not moment > 0.0:
        raise ValueError("the yield base shear must be positive")
    return HingedWall(masses, unscaled.storey_heights_m, unscaled.elastic_stiffness_n_m * scale,
                      unscaled.hinge_stiffness_n_m_rad * scale, unscaled.reference_stiffness_n_m_rad * scale,
                      moment, unscaled.hinge_hardening, b, law, (a0, a1), n_mod,
                      geometric_stiffness_n_m=None if geometric_stiffness_n_m is None
                      else np.asarray(geometric_stiffness_n_m, dtype=float))


@njit(cache=True, nogil=True)  # released so that a suite's motions run on threads (assess.building.yielding)
def _hinge_history(ground_g, dt_s, substeps, masses, k_full, damping, k_theta, m_y, hardening, law, parameters,
                   tolerance, max_iterations):  # pragma: no cover - compiled
    """Floors' absolute accelerations [g] (n + 1, samples), storey drifts [m] (n, samples), peak |θ| at the
    samples [rad], unconverged substeps. ``k_full``, ``damping``: the linear part's (n + 1)² stiffness (the
    hinge left out) and the damping matrix on (u, θ)."""
    n = masses.size
    m = n + 1
    n_samples = ground_g.size
    g = STANDARD_GRAVITY_M_S2
    h = dt_s / substeps
    c_mass, c_vel = _gains(h)
    mass = np.zeros(m)
    for i in range(n):
        mass[i] = masses[i]
    committed = np.zeros(STATE_SIZE)
    committed[2] = k_theta
    trial = committed.copy()
    u = np.zeros(m)
    v = np.zeros(m)
    a = np.zeros(m)
    for i in range(n):
        a[i] = -ground_g[0] * g
    u_new = np.zeros(m)
    v_new = np.zeros(m)
    a_new = np.zeros(m)
    du = np.zeros(m)
    residual = np.zeros(m)
    # Newton's matrix is K_lin + c_vel C + c_mass M (constant) plus the hinge's tangent at (θ, θ): its inverse
    # once (_solve per column), then each iteration by Sherman-Morrison, a rank-one update (O(m²), not O(m³))
    constant = np.zeros((m, m))
    for r in range(m):
        for c in range(m):
            constant[r, c] = k_full[r, c] + c_vel * damping[r, c]
        constant[r, r] += c_mass * mass[r]
    inverse = np.zeros((m, m))
    unit = np.zeros(m)
    column = np.zeros(m)
    for c in range(m):
        unit[:] = 0.0
        unit[c] = 1.0
        _solve(constant.copy(), unit, column)
        for r in range(m):
            inverse[r, c] = column[r]
    solved = np.zeros(m)
    accel_out = np.empty((n + 1, n_samples))
    drift_out = np.empty((n, n_samples))
    _record(accel_out, drift_out, 0, ground_g[0], u, a, n)
    peak_theta = 0.0
    unconverged = 0
    for step in range(n_samples - 1):
        g0 = ground_g[step]
        g1 = ground_g[step + 1]
        for sub in range(substeps):
            ground = (g0 + (g1 - g0) * (sub + 1) / substeps) * g
            for r in range(m):
                u_new[r] = u[r]
            converged = False
            for iteration in range(max_iterations):
                _rates(u_new, u, v, a, a_new, v_new, h, m)
                moment, tangent = spring_trial(law, committed, trial, u_new[n], k_theta, m_y, hardening, parameters)
                for r in range(m):
                    total = -mass[r] * (ground + a_new[r]) if r < n else -moment
                    for c in range(m):
                        total -= damping[r, c] * v_new[c] + k_full[r, c] * u_new[c]
                    residual[r] = total
                for r in range(m):
                    total = 0.0
                    for c in range(m):
                        total += inverse[r, c] * residual[c]
                    solved[r] = total
                factor = tangent * solved[n] / (1.0 + tangent * inverse[n, n])
                for r in range(m):
                    du[r] = solved[r] - factor * inverse[r, n]
                norm = 0.0
                for r in range(m):
                    u_new[r] += du[r]
                    norm += du[r] * du[r]
                if np.sqrt(norm) <= tolerance:
                    converged = True
                    break
            if not converged:
                unconverged += 1
            _rates(u_new, u, v, a, a_new, v_new, h, m)
            spring_trial(law, committed, trial, u_new[n], k_theta, m_y, hardening, parameters)
            for s in range(STATE_SIZE):
                committed[s] = trial[s]
            for r in range(m):
                u[r] = u_new[r]
                v[r] = v_new[r]
                a[r] = a_new[r]
        _record(accel_out, drift_out, step + 1, g1, u, a, n)
        if abs(u[n]) > peak_theta:
            peak_theta = abs(u[n])
    return accel_out, drift_out, peak_theta, unconverged


def rotation_ductility(wall: HingedWall, peak_rotation_rad: float) -> float:
    """The wall's rotation ductility at its base, 1 + θ_p/θ_y (module text), from the hinge's peak rotation;
    below yield, the peak rotation over the hinge's yield rotation (below 1: it stayed elastic).

    θ_y,hinge = M_y/k_θ; beyond it θ_p = θ_peak − θ_y,hinge over θ_y = M_y/k_ref = (n + 1) θ_y,hinge.
    """
    hinge_yield = wall.yield_moment_n_m / wall.hinge_stiffness_n_m_rad
    if peak_rotation_rad <= hinge_yield:
        return float(peak_rotation_rad / hinge_yield)
    return float(1.0 + (peak_rotation_rad - hinge_yield) / wall.yield_rotation_rad)


def damping_matrix(wall: HingedWall) -> np.ndarray:
    """C = a_0 M + a_1 (n + 1)/n K_e on (u, θ) [N s/m] (module text): none on the hinge, none from P-Delta."""
    a0, a1 = wall.rayleigh
    n_mod = wall.stiffness_ratio_n
    matrix = a1 * (n_mod + 1.0) / n_mod * wall.assembled_stiffness(0.0, p_delta=False)
    matrix[:-1, :-1] += a0 * np.diag(np.asarray(wall.floor_masses_kg, dtype=float))
    return np.ascontiguousarray(matrix)


def hinged_wall_response(wall: HingedWall, ground_accel_g, dt_s, *, substep_s=DEFAULT_SUBSTEP_S,
                         substeps=None) -> YieldingResponse:
    """Every floor's absolute acceleration and every storey's drift under one ground motion.

    As :func:`~assess.building.nonlinear.yielding_response`; ``ductility`` is the wall's rotation ductility at
    its base (module text) in the first storey's place, NaN for the storeys above (they do not yield).
    """
    ground = np.ascontiguousarray(ground_accel_g, dtype=float)
    if wall.law not in LAWS:
        raise ValueError(f"law must be one of {', '.join(LAWS)}, not {wall.law!r}")
    if substeps is None:
        shortest = float(hinged_periods(wall)[-1]) / STEPS_PER_SHORTEST_PERIOD
        substeps = substeps_for(dt_s, min(substep_s, shortest))
    n = wall.storeys
    accel, drift, peak_theta, unconverged = _hinge_history(
        ground, float(dt_s), int(substeps), np.ascontiguousarray(wall.floor_masses_kg, dtype=float),
        np.ascontiguousarray(wall.assembled_stiffness(0.0)), damping_matrix(wall),
        float(wall.hinge_stiffness_n_m_rad), float(wall.yield_moment_n_m), float(wall.hinge_hardening),
        LAWS[wall.law], spring_parameters(wall.law, float(wall.hinge_stiffness_n_m_rad), float(wall.yield_moment_n_m),
                                          float(wall.hinge_hardening), wall.pinch_x, wall.pinch_y,
                                          wall.unloading_beta), TOLERANCE_M, MAX_ITERATIONS)
    ductility = np.full(n, np.nan)
    ductility[0] = rotation_ductility(wall, peak_theta)
    peak = np.abs(drift).max(axis=1)
    return YieldingResponse(floor_accel_g=accel, drift_m=drift,
                            peak_drift_ratio=peak / np.asarray(wall.storey_heights_m, dtype=float),
                            ductility=ductility, unconverged_steps=int(unconverged))
