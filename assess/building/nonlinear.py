"""A building that yields: response history of a stick of storey springs with hysteresis.

The masses are lumped at the floors, one horizontal degree of freedom each; storey i
is a spring between floors i-1 and i whose force follows a hysteresis law
(:mod:`assess.building.hysteresis`: bilinear for steel, pinching and
stiffness-degrading for concrete, a pulled and a pushed brace for braces that
buckle); beside the springs an elastic part K_lin (the
flexural column of the shear-flexural model of :mod:`assess.building.modes`, and,
where asked, the P-Delta geometric stiffness, -P_i/h_i per storey) stays linear.
Each spring's yield force is its share of the code's distribution of the strength,
raised where the design makes the storey stronger (:data:`STRENGTH_BY_SYSTEM`):
frames as strong as they are stiff at one yield drift ratio, the storey whose share
asks most yielding first at the given strength (:func:`stiffness_strength`, after
Priestley et al. [4]_), walls on the linear moment
envelope of capacity design (:func:`capacity_design_strength`, Paulay & Priestley [6]_).
With every spring elastic, K = K_springs + K_lin is exactly the stiffness of
:func:`~assess.building.modes.building_modes`, so that the elastic limit is the
elastic route's model.

Equation of motion, u the floors' displacements relative to the ground:

.. math::  M\\ddot u + C\\dot u + f_s(u) + K_{lin}u = -M\\,1\\,\\ddot u_g(t)

Damping is Rayleigh's, C = a_0 M + a_1 K_T, with ζ at two modes of the elastic
model (:func:`rayleigh_coefficients`). K_T is the **tangent** stiffness at the start
of each step (OpenSees' ``betaKcomm``): as the springs yield their damping force falls
with their stiffness, whereas damping on the initial stiffness keeps a yielded
storey's damping force growing with its velocity, spurious forces that Charney [2]_
shows overstate damping in yielding structures. ``damping_stiffness="initial"`` gives
the other choice.

Time integration: Newmark's average-acceleration method (γ = 1/2, β = 1/4) with
Newton iterations on the tangent stiffness at every step (Chopra [1]_ §15.3 and
Table 15.3.3, there with modified Newton), at substeps of the record's step (≤ 1 ms
by default: its error falls as Δt²) with the ground acceleration linear between the
record's samples. Output: each floor's absolute acceleration, each storey's drift,
at the record's samples.

References
----------
.. [1] Chopra, A. K. (2012). Dynamics of Structures, 4th ed. Pearson. §11.4
   (Rayleigh damping), §15.3 (Newmark's method for nonlinear systems).
.. [2] Charney, F. A. (2008). Unintended consequences of modeling damping in
   structures. J. Struct. Eng. 134(4):581-592.
   doi:10.1061/(ASCE)0733-9445(2008)134:4(581)
.. [3] Newmark, N. M. (1959). A method of computation for structural dynamics.
   J. Eng. Mech. Div. ASCE 85(EM3):67-94.
.. [4] Priestley, M. J. N., Calvi, G. M. and Kowalsky, M. J. (2007). Displacement-Based
   Seismic Design of Structures. IUSS Press, Pavia. Yield drift of frames (RC
   θ_y ≈ 0.5 ε_y L_b/h_b, steel ≈ 0.65 ε_y L_b/h_b: geometry, not strength).
.. [5] Priestley, M. J. N. (2003). Myths and Fallacies in Earthquake Engineering,
   Revisited. The Mallet Milne Lecture. IUSS Press, Pavia. (Strength and stiffness
   are not independent.)
.. [6] Paulay, T. and Priestley, M. J. N. (1992). Seismic Design of Reinforced Concrete and
   Masonry Buildings. Wiley. Ch. 5 (capacity design of cantilever walls: the moment envelope).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit
from scipy.linalg import eigh

from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2

from .design import DEFAULT_HARDENING, LAW_BY_SYSTEM, vertical_distribution
from .hysteresis import LAWS, STATE_SIZE, spring_parameters, spring_trial
from .modes import ALPHA_BY_SYSTEM, stiffness_matrix
from .newmark import (DEFAULT_SUBSTEP_S, MAX_ITERATIONS, STEPS_PER_SHORTEST_PERIOD, TOLERANCE_M,  # noqa: F401
                      YieldingResponse, _gains, _rates, _record, _solve, rayleigh_coefficients, substeps_for)
from .period import approximate_period
from .wall_hinge import hinged_wall

#: Standard gravity [m/s²], the engine's (:data:`assess.mechanics.geometry.STANDARD_GRAVITY_M_S2`).
GRAVITY_M_S2 = STANDARD_GRAVITY_M_S2
#: How the stick carries the elastic model's flexure, per system (:func:`yielding_stick`): frames and
#: braced frames yield in a storey mechanism while their overall flexure (the columns' axial
#: strains) stays elastic, so their column is kept elastic beside the yielding springs; a
#: capacity-designed wall yields in flexure at its base and stays elastic above (Paulay & Priestley
#: [6]_ ch. 5): the elastic model on a base hinge (:mod:`assess.building.wall_hinge`). ``other``
#: systems keep the equivalent shear stick.
FLEXURE_BY_SYSTEM = {
    "steel moment frame": "elastic column",
    "concrete moment frame": "elastic column",
    "eccentrically braced frame": "elastic column",
    "braced frame": "elastic column",
    "shear wall": "base hinge",
    "other": "equivalent shear",
}

#: How the storeys' strength rises above the code's distribution of it, per system
#: (:func:`stiffness_strength`, :func:`capacity_design_strength`; docs/workbook.md): a frame's or a
#: brace's storey is as strong as it is stiff, a wall is capacity-designed to yield at its base.
STRENGTH_BY_SYSTEM = {
    "steel moment frame": "stiffness",
    "concrete moment frame": "stiffness",
    "eccentrically braced frame": "stiffness",
    "braced frame": "stiffness",
    "shear wall": "capacity design",
    "other": "stiffness",
}


@dataclass(frozen=True)
class YieldingStick:
    """The yielding building as the integrator takes it (SI units).

    Attributes
    ----------
    floor_masses_kg : ndarray, (n,)
        m_i, floor 1 to the roof.
    storey_heights_m : ndarray, (n,)
        h_i.
    stiffness_n_m : ndarray, (n,)
        Initial stiffness k_0 of each storey spring.
    yield_force_n : ndarray, (n,)
        F_y of each storey spring (its yield drift is F_y/k_0).
    hardening : ndarray, (n,)
        Post-yield stiffness ratio b of each spring [-].
    law : str
        ``"bilinear"``, ``"pinching"`` or ``"buckling"`` (:mod:`assess.building.hysteresis`).
    linear_stiffness_n_m : ndarray, (n, n)
        K_lin, the part that stays elastic (zeros for a shear building).
    rayleigh : (float, float)
        a_0 [1/s], a_1 [s].
    pinch_x, pinch_y, unloading_beta : float
        Parameters of the pinching law.
    damping_stiffness : str
        ``"tangent"`` (at the start of each step) or ``"initial"``.
    modal_damping_n_s_m : ndarray (n, n), optional
        A constant damping matrix added to the Rayleigh one (:func:`modal_damping_matrix`).
    bending_rigidity_n_m2 : float, optional
        EI of the elastic column whose condensed stiffness is ``linear_stiffness_n_m`` (record only).
    """

    floor_masses_kg: np.ndarray
    storey_heights_m: np.ndarray
    stiffness_n_m: np.ndarray
    yield_force_n: np.ndarray
    hardening: np.ndarray
    law: str
    linear_stiffness_n_m: np.ndarray
    rayleigh: tuple
    pinch_x: float = 0.8
    pinch_y: float = 0.4
    unloading_beta: float = 0.4
    damping_stiffness: str = "tangent"
    modal_damping_n_s_m: np.ndarray | None = None
    bending_rigidity_n_m2: float | None = None

    @property
    def storeys(self) -> int:
        return self.floor_masses_kg.size

    @property
    def yield_drift_m(self) -> np.ndarray:
        return self.yield_force_n / self.stiffness_n_m


def rayleigh_modal_damping(periods_s, a0, a1):
    """ζ_j = a_0/(2ω_j) + a_1 ω_j/2 of each mode [-] (for the elastic modal route)."""
    omega = 2.0 * np.pi / np.asarray(periods_s, dtype=float)
    return a0 / (2.0 * omega) + a1 * omega / 2.0


def modal_damping_matrix(stiffness_n_m, floor_masses_kg, damping=0.05):
    """Damping matrix [N s/m] giving ζ in every mode of (K, M): C = M Φ diag(2ζω_j) Φᵀ M, ΦᵀMΦ = I.

    (Chopra [1]_ §11.5; OpenSees' ``modalDamping`` builds the same from the initial
    stiffness.) Constant: as the springs yield it keeps the initial modes' damping.

    Examples
    --------
    One degree of freedom, k = 4 N/m, m = 1 kg (ω = 2 rad/s), 5 %: c = 2 × 0.05 × 2 = 0.2 N s/m:

    >>> modal_damping_matrix([[4.0]], [1.0]).round(12).tolist()
    [[0.2]]
    """
    masses = np.asarray(floor_masses_kg, dtype=float)
    omega2, shapes = eigh(np.asarray(stiffness_n_m, dtype=float), np.diag(masses))
    mass_shapes = masses[:, None] * shapes
    return mass_shapes @ np.diag(2.0 * damping * np.sqrt(omega2)) @ mass_shapes.T


def shear_chain_matrix(storey_stiffness):
    """Stiffness matrix [N/m] of a chain of storey springs (floor 1 to roof)."""
    k = np.asarray(storey_stiffness, dtype=float)
    n = k.size
    matrix = np.zeros((n, n))
    for i in range(n):
        matrix[i, i] += k[i]
        if i > 0:
            matrix[i - 1, i - 1] += k[i]
            matrix[i - 1, i] -= k[i]
            matrix[i, i - 1] -= k[i]
    return matrix


def elastic_periods(stick: YieldingStick) -> np.ndarray:
    """Periods [s] of the stick with every spring at k_0."""
    stiffness = shear_chain_matrix(stick.stiffness_n_m) + stick.linear_stiffness_n_m
    omega2 = eigh(stiffness, np.diag(stick.floor_masses_kg), eigvals_only=True)
    return 2.0 * np.pi / np.sqrt(omega2)


def p_delta_stiffness(floor_masses_kg, storey_heights_m):
    """Geometric stiffness [N/m] of the gravity loads: a storey spring of -P_i/h_i, P_i the weight above storey i.

    (The linearised P-Delta effect of a shear building, e.g. Chopra [1]_ §18.6.)

    Two floors of 1 kg, storeys g metres high: P/h = 2 and 1 N/m, so -[[2 + 1, -1], [-1, 1]]:

    >>> p_delta_stiffness([1.0, 1.0], [9.80665, 9.80665]).round(6).tolist()
    [[-3.0, 1.0], [1.0, -1.0]]
    """
    masses = np.asarray(floor_masses_kg, dtype=float)
    above = np.cumsum(masses[::-1])[::-1] * GRAVITY_M_S2
    return -shear_chain_matrix(above / np.asarray(storey_heights_m, dtype=float))


@njit(cache=True)
def _spring_states(u, law, committed, trial, k0, fy, hardening, parameters, force,
                   tangent):  # pragma: no cover - compiled
    """Trial force and tangent of every storey spring at floor displacements u."""
    n = u.size
    for i in range(n):
        drift = u[i] - (u[i - 1] if i > 0 else 0.0)
        force[i], tangent[i] = spring_trial(law, committed[i], trial[i], drift, k0[i], fy[i], hardening[i],
                                            parameters[i])


@njit(cache=True, nogil=True)  # released so that a suite's motions run on threads (assess.building.yielding)
def _history(ground_g, dt_s, substeps, masses, k0, fy, hardening, law, parameters,
             k_lin, c_extra, a0, a1, damping_on_initial, tolerance, max_iterations):  # pragma: no cover - compiled
    n = masses.size
    n_samples = ground_g.size
    g = GRAVITY_M_S2
    h = dt_s / substeps
    c_mass, c_vel = _gains(h)
    committed = np.zeros((n, STATE_SIZE))
    for i in range(n):
        committed[i, 2] = k0[i]
    trial = committed.copy()
    force = np.zeros(n)
    tangent = k0.copy()
    damping_tangent = k0.copy()  # spring stiffness the damping matrix uses in this step
    u = np.zeros(n)
    v = np.zeros(n)
    a = np.zeros(n)
    for i in range(n):
        a[i] = -ground_g[0] * g
    u_new = np.zeros(n)
    v_new = np.zeros(n)
    a_new = np.zeros(n)
    du = np.zeros(n)
    residual = np.zeros(n)
    damping = np.zeros((n, n))
    matrix = np.zeros((n, n))
    accel_out = np.empty((n + 1, n_samples))
    drift_out = np.empty((n, n_samples))
    _record(accel_out, drift_out, 0, ground_g[0], u, a, n)
    unconverged = 0
    for step in range(n_samples - 1):
        g0 = ground_g[step]
        g1 = ground_g[step + 1]
        for sub in range(substeps):
            ground = (g0 + (g1 - g0) * (sub + 1) / substeps) * g
            # damping matrix C = a0 M + a1 (K_springs + K_lin), springs at their committed (or initial) tangent
            for r in range(n):
                for c in range(n):
                    damping[r, c] = a1 * k_lin[r, c] + c_extra[r, c]
                damping[r, r] += a0 * masses[r]
            for s in range(n):
                ks = a1 * (k0[s] if damping_on_initial else damping_tangent[s])
                damping[s, s] += ks
                if s > 0:
                    damping[s - 1, s - 1] += ks
                    damping[s - 1, s] -= ks
                    damping[s, s - 1] -= ks
            # predictor: the last step's displacement
            for r in range(n):
                u_new[r] = u[r]
            converged = False
            for iteration in range(max_iterations):
                _rates(u_new, u, v, a, a_new, v_new, h, n)
                _spring_states(u_new, law, committed, trial, k0, fy, hardening, parameters, force, tangent)
                for r in range(n):
                    total = -masses[r] * ground - masses[r] * a_new[r]
                    total -= force[r] - (force[r + 1] if r + 1 < n else 0.0)
                    for c in range(n):
                        total -= damping[r, c] * v_new[c] + k_lin[r, c] * u_new[c]
                    residual[r] = total
                for r in range(n):
                    for c in range(n):
                        matrix[r, c] = k_lin[r, c] + c_vel * damping[r, c]
                    matrix[r, r] += c_mass * masses[r]
                for s in range(n):
                    ks = tangent[s]
                    matrix[s, s] += ks
                    if s > 0:
                        matrix[s - 1, s - 1] += ks
                        matrix[s - 1, s] -= ks
                        matrix[s, s - 1] -= ks
                _solve(matrix, residual, du)
                norm = 0.0
                for r in range(n):
                    u_new[r] += du[r]
                    norm += du[r] * du[r]
                if np.sqrt(norm) <= tolerance:
                    converged = True
                    break
            if not converged:
                unconverged += 1
            # the state at the converged displacements, then commit
            _rates(u_new, u, v, a, a_new, v_new, h, n)
            _spring_states(u_new, law, committed, trial, k0, fy, hardening, parameters, force, tangent)
            for r in range(n):
                for s in range(STATE_SIZE):
                    committed[r, s] = trial[r, s]
                damping_tangent[r] = tangent[r]
                u[r] = u_new[r]
                v[r] = v_new[r]
                a[r] = a_new[r]
        _record(accel_out, drift_out, step + 1, g1, u, a, n)
    return accel_out, drift_out, unconverged


def yielding_response(stick: YieldingStick, ground_accel_g, dt_s, *, substep_s=DEFAULT_SUBSTEP_S,
                      substeps=None) -> YieldingResponse:
    """Every floor's absolute acceleration and every storey's drift under one ground motion.

    Parameters
    ----------
    stick : YieldingStick
    ground_accel_g : array-like
        Ground acceleration [g], linear between samples.
    dt_s : float
        Record step [s].
    substep_s : float
        Longest integration step [s] (shortened to 1/:data:`STEPS_PER_SHORTEST_PERIOD` of the
        stick's shortest elastic period); ``substeps`` (per record step) overrides both.

    Returns
    -------
    YieldingResponse
    """
    ground = np.ascontiguousarray(ground_accel_g, dtype=float)
    if substeps is None:
        shortest = float(elastic_periods(stick)[-1]) / STEPS_PER_SHORTEST_PERIOD
        substeps = substeps_for(dt_s, min(substep_s, shortest))
    if stick.law not in LAWS:
        raise ValueError(f"law must be one of {', '.join(LAWS)}, not {stick.law!r}")
    if stick.damping_stiffness not in ("tangent", "initial"):
        raise ValueError("damping_stiffness must be 'tangent' or 'initial'")
    n = stick.storeys
    k0 = np.ascontiguousarray(stick.stiffness_n_m, dtype=float)
    fy = np.ascontiguousarray(stick.yield_force_n, dtype=float)
    hardening = np.array(np.broadcast_to(stick.hardening, (n,)), dtype=float)
    parameters = np.array([spring_parameters(stick.law, k0[i], fy[i], hardening[i], stick.pinch_x, stick.pinch_y,
                                             stick.unloading_beta) for i in range(n)])
    accel, drift, unconverged = _history(
        ground, float(dt_s), int(substeps), np.ascontiguousarray(stick.floor_masses_kg, dtype=float), k0, fy,
        hardening, LAWS[stick.law], parameters,
        np.ascontiguousarray(stick.linear_stiffness_n_m, dtype=float),
        np.zeros((n, n)) if stick.modal_damping_n_s_m is None
        else np.ascontiguousarray(stick.modal_damping_n_s_m, dtype=float), float(stick.rayleigh[0]),
        float(stick.rayleigh[1]), stick.damping_stiffness == "initial", TOLERANCE_M, MAX_ITERATIONS)
    peak = np.abs(drift).max(axis=1)
    return YieldingResponse(floor_accel_g=accel, drift_m=drift,
                            peak_drift_ratio=peak / np.asarray(stick.storey_heights_m, dtype=float),
                            ductility=peak / stick.yield_drift_m, unconverged_steps=int(unconverged))



def stiffness_strength(code_force_n, storey_stiffness_n_m, storey_heights_m):
    """Each storey spring's yield force [N]: every spring at one yield drift ratio, the first to yield at its share.

    .. math::  F_{y,i} = k_i h_i\\,\\theta_y,\\qquad
               \\theta_y = \\max_j \\frac{F^{code}_{y,j}}{k_j h_j}

    The yield drift of a frame storey is set by its geometry and the steel's yield strain,
    not by its strength (Priestley, Calvi & Kowalsky [4]_; Priestley [5]_): a storey sized
    for drift, gravity or least member sizes is as strong as it is stiff, so every storey
    carries k_i θ_y h_i at one yield drift ratio θ_y. θ_y is the least that keeps every storey
    at least as strong as the code's share of the strength asks (each storey is designed for
    its own shear, ASCE 7-22 §12.8.4): under the code's forces the storey whose share asks
    most of its stiffness yields first, exactly at the given strength (``yield_base_shear_g``:
    a pushover's base shear when its first storey, whichever, yields), and every other storey
    later. Where the code's shares follow the stiffness (a stick whose springs are the elastic
    model's under the code's forces, :func:`yielding_stick`'s ``"equivalent shear"``) every
    storey yields at once and the rule changes nothing; where a storey is stiffer than its
    share (uniform storeys, a continuous column that carries much of the lower storeys'
    shear) it is stronger in proportion.

    Examples
    --------
    Equal springs and storeys, code shares 1, 0.7, 0.4: every storey as strong as the first:

    >>> stiffness_strength([10.0, 7.0, 4.0], [5.0, 5.0, 5.0], [3.0, 3.0, 3.0]).tolist()
    [10.0, 10.0, 10.0]

    Springs that follow the shares: the shares themselves:

    >>> stiffness_strength([8.0, 4.0, 2.0], [2.0, 1.0, 0.5], [2.0, 2.0, 2.0]).tolist()
    [8.0, 4.0, 2.0]

    A first storey whose spring carries little of its share (a continuous column beside it): the
    second, whose share asks most of its stiffness, yields first at its share; the first is as strong
    as it is stiff at that yield drift:

    >>> stiffness_strength([4.0, 7.0, 4.0], [1.0, 1.0, 1.0], [3.0, 3.0, 3.0]).tolist()
    [7.0, 7.0, 7.0]
    """
    return given_strength(code_force_n, np.asarray(storey_stiffness_n_m, dtype=float)
                          * np.asarray(storey_heights_m, dtype=float))


def given_strength(code_force_n, relative_strength):
    """Each storey spring's yield force [N]: the storeys' strengths as given, relative, the first to yield at its share.

    .. math::  F_{y,i} = r_i\\,\\max_j \\frac{F^{code}_{y,j}}{r_j}

    ``relative_strength`` r gives the storeys' strengths against each other only (a model's storey
    springs, or its storeys' shears at yield, in any one unit). The scale is the least that keeps every
    storey at least as strong as the code's share of the strength asks: under the code's forces the
    storey whose share asks most of its strength yields first, exactly at the given strength
    (``yield_base_shear_g``), and every other storey later, as :func:`stiffness_strength` does with
    r_i = k_i h_i.

    Examples
    --------
    Code shares 10, 7, 4 and storeys as strong as 1, 0.5, 0.5: the second's share asks most of it
    (7/0.5 = 14 against 10 and 8), so it yields first at its share and the others are stronger:

    >>> given_strength([10.0, 7.0, 4.0], [1.0, 0.5, 0.5]).tolist()
    [14.0, 7.0, 7.0]

    Strengths in proportion to the shares give the shares themselves (every storey yields at once):

    >>> given_strength([8.0, 4.0, 2.0], [4.0, 2.0, 1.0]).tolist()
    [8.0, 4.0, 2.0]
    """
    code = np.asarray(code_force_n, dtype=float)
    relative = np.asarray(relative_strength, dtype=float)
    if relative.shape != code.shape or np.any(~(relative > 0.0)):
        raise ValueError("relative_strength must give one positive strength per storey")
    return relative * float(np.max(code / relative))


def capacity_design_strength(code_force_n, floor_forces, floor_heights_m):
    """Each storey spring's yield force [N] in a capacity-designed wall: its code share, or the moment envelope's.

    A cantilever wall is designed to yield in flexure at its base only: above the base its
    flexural strength follows a linear envelope from the base's strength to zero at the top
    (Paulay & Priestley [6]_ ch. 5; EN 1998-1 §5.5.2.4.1, there shifted up by the tension
    shift, left out here), which lies above the moment of the code's lateral forces. In a
    stick of storey springs, storey i (its base at z_{i-1}) yields when the moment there
    reaches the envelope, under the code's forces scaled up:

    .. math::  F_{y,i} = \\max\\Big(F^{code}_{y,i},\\; F^{code}_{y,1}\\,\\frac{V_i}{V_1}\\,
               \\frac{1 - z_{i-1}/H}{M_i/M_1}\\Big),\\qquad M_i = \\sum_{j \\ge i} F_j (z_j - z_{i-1})

    Examples
    --------
    Two storeys of 1 m, forces 1 and 2 at z 1 and 2: V = 3, 2; M = 5, 2 (over the base: 1·1 + 2·2);
    the top storey yields at 3 × (2/3) × (1/2)/(2/5) = 2.5 where its share is 2:

    >>> capacity_design_strength([3.0, 2.0], [1.0, 2.0], [1.0, 2.0]).tolist()
    [3.0, 2.5]
    """
    code = np.asarray(code_force_n, dtype=float)
    forces = np.asarray(floor_forces, dtype=float)
    heights = np.asarray(floor_heights_m, dtype=float)
    bases = np.concatenate([[0.0], heights[:-1]])
    shears = np.cumsum(forces[::-1])[::-1]
    moments = np.array([np.sum(forces[i:] * (heights[i:] - bases[i])) for i in range(heights.size)])
    envelope = 1.0 - bases / heights[-1]
    return np.maximum(code, code[0] * shears / shears[0] * envelope / (moments / moments[0]))


def yielding_stick(storeys, storey_height_m, storey_yield_ratio, *, system="other", period_s=None, alpha=None,
                   storey_stiffness=None, floor_masses_kg=None, law=None, hardening=None, damping=0.05,
                   rayleigh_modes=(1, 3), flexure=None, p_delta=False,
                   damping_stiffness="tangent", damping_model="rayleigh",
                   strength_profile=None):
    """The yielding stick of a building described as :func:`~assess.building.modes.building_modes` takes it.

    A :class:`YieldingStick`, or with ``flexure="base hinge"`` a
    :class:`~assess.building.wall_hinge.HingedWall`.

    Parameters
    ----------
    storeys, storey_height_m, system, period_s, alpha, storey_stiffness :
        As :func:`~assess.building.modes.building_modes`: the elastic model whose stiffness
        (scaled to T_1) the springs start from.
    storey_yield_ratio : array-like, (n,)
        Each storey's yield shear over the building's weight [-]
        (:func:`~assess.building.design.design_strength`).
    floor_masses_kg : array-like, optional
        Floor masses (equal, 10⁵ kg, by default; accelerations and drifts do not depend on the scale).
    law : str, optional
        ``"bilinear"``, ``"pinching"`` or ``"buckling"`` (braces); by default the system's
        (:data:`~assess.building.design.LAW_BY_SYSTEM`).
    hardening : float, optional
        Post-yield stiffness ratio b; :data:`DEFAULT_HARDENING`.
    damping : float
        ζ of the Rayleigh damping at ``rayleigh_modes`` of the elastic model, or of every
        mode with ``damping_model="modal"``.
    damping_model : str
        ``"rayleigh"`` (default: a_0 M + a_1 K_T, see the module's text) or ``"modal"``
        (:func:`modal_damping_matrix` of the initial stiffness, ζ in every mode as the elastic
        route takes it: then the elastic limit is the elastic route's answer itself).
    flexure : str, optional
        By default the system's (:data:`FLEXURE_BY_SYSTEM`). ``"equivalent shear"``: a shear
        stick whose storey stiffness is the elastic model's under the code's lateral forces
        (k_i = V_i/Δ_i, then scaled to T_1): every storey yields at its own storey shear, the elastic limit is a shear
        building with the same T_1 and drift profile under those forces (identical to the
        elastic model for a shear building, α = ∞). ``"elastic column"``: the elastic
        model's flexural column kept beside the springs, linear: the elastic limit is the
        elastic model itself, but the column never yields, so a flexure-dominated
        building (small α) then barely yields (at α = 1 its first storey's spring carries
        2-8 % of the storey shear under the code's forces, 3 to 12 storeys). ``"base hinge"``: the
        elastic model (scaled to T_1) rotating on a plastic hinge at its base, the wall above elastic
        (:func:`~assess.building.wall_hinge.hinged_wall`): the hinge yields at the moment of the code's
        forces at a base shear of ``storey_yield_ratio[0]`` times the weight (the other storeys' ratios
        and ``strength_profile`` do not enter, ``damping_model`` must be ``"rayleigh"``); the elastic
        limit has the elastic model's T_1 and its roof displacement under a load at the roof.
    p_delta : bool
        Add the gravity loads' geometric stiffness (:func:`p_delta_stiffness`); T_1 stays that without it.
    strength_profile : str or array-like, optional
        How the springs' strength rises above their share of ``storey_yield_ratio`` (under the code's
        forces the first spring to yield does so at its share): by default the system's
        (:data:`STRENGTH_BY_SYSTEM`); ``"stiffness"`` (:func:`stiffness_strength`), ``"capacity design"``
        (:func:`capacity_design_strength`), ``"code"`` (the shares as given), or the storeys' strengths
        against each other, one positive number per storey (:func:`given_strength`: a model's).
    """
    n = int(storeys)
    flexure = FLEXURE_BY_SYSTEM[system] if flexure is None else flexure
    heights = np.broadcast_to(np.asarray(storey_height_m, dtype=float), (n,)).copy()
    floor_heights = np.cumsum(heights)
    masses = np.full(n, 1.0e5) if floor_masses_kg is None else np.asarray(floor_masses_kg, dtype=float)
    alpha = ALPHA_BY_SYSTEM[system] if alpha is None else float(alpha)
    if alpha == 0.0 and flexure != "base hinge":
        raise ValueError("a flexural cantilever (alpha 0) has no storey springs to yield")
    if period_s is None:
        period_s = approximate_period(floor_heights[-1], system)
    relative = np.ones(n) if storey_stiffness is None else np.asarray(storey_stiffness, dtype=float)
    full = stiffness_matrix(n, float(np.mean(heights)), alpha, relative)
    forces = vertical_distribution(masses, floor_heights, period_s)
    shears = np.cumsum(forces[::-1])[::-1]
    if flexure == "base hinge":
        ratio = np.asarray(storey_yield_ratio, dtype=float)
        if ratio.shape != (n,) or np.any(~(ratio > 0.0)):
            raise ValueError("storey_yield_ratio must give one positive ratio per storey")
        if damping_model != "rayleigh":
            raise ValueError("a wall on a base hinge takes Rayleigh damping on its elastic part only")
        base_shear_n = float(ratio[0]) * masses.sum() * GRAVITY_M_S2
        return hinged_wall(full, heights, masses, period_s, base_shear_n, forces,
                           law=LAW_BY_SYSTEM[system] if law is None else law,
                           hardening=DEFAULT_HARDENING if hardening is None else float(hardening),
                           damping=damping, rayleigh_modes=rayleigh_modes,
                           geometric_stiffness_n_m=p_delta_stiffness(masses, heights) if p_delta else None)
    if flexure == "equivalent shear":
        drifts = np.diff(np.concatenate([[0.0], np.linalg.solve(full, forces)]))
        springs = shears / drifts
        linear = np.zeros((n, n))
        share = np.ones(n)
    elif flexure == "elastic column":
        springs = relative
        linear = full - shear_chain_matrix(relative)
        drifts = np.diff(np.concatenate([[0.0], np.linalg.solve(full, forces)]))
        share = springs * drifts / shears
    else:
        raise ValueError("flexure must be 'equivalent shear', 'elastic column' or 'base hinge'")
    omega2 = eigh(shear_chain_matrix(springs) + linear, np.diag(masses), eigvals_only=True)
    scale = (2.0 * np.pi / np.sqrt(omega2[0]) / float(period_s)) ** 2
    springs, linear = springs * scale, linear * scale
    bending = None
    if flexure == "elastic column" and np.isfinite(alpha):
        bending = float(scale * relative[0] * np.mean(heights) * (n * np.mean(heights)) ** 2 / alpha ** 2)
    periods = 2.0 * np.pi / np.sqrt(omega2 * scale)
    if p_delta:
        linear = linear + p_delta_stiffness(masses, heights)
    weight = masses.sum() * GRAVITY_M_S2
    yield_force = np.asarray(storey_yield_ratio, dtype=float) * weight * share
    if yield_force.shape != (n,) or np.any(~(yield_force > 0.0)):
        raise ValueError("storey_yield_ratio must give one positive ratio per storey")
    strength_profile = STRENGTH_BY_SYSTEM[system] if strength_profile is None else strength_profile
    if not isinstance(strength_profile, str):
        yield_force = given_strength(yield_force, strength_profile)
    elif strength_profile == "stiffness":
        yield_force = stiffness_strength(yield_force, springs, heights)
    elif strength_profile == "capacity design":
        yield_force = capacity_design_strength(yield_force, forces, floor_heights)
    elif strength_profile != "code":
        raise ValueError("strength_profile must be 'stiffness', 'capacity design' or 'code'")
    law = LAW_BY_SYSTEM[system] if law is None else law
    if damping_model == "rayleigh":
        rayleigh, modal = rayleigh_coefficients(periods, damping, rayleigh_modes), None
    elif damping_model == "modal":
        rayleigh = (0.0, 0.0)
        modal = modal_damping_matrix(shear_chain_matrix(springs) + linear - (p_delta_stiffness(masses, heights)
                                                                             if p_delta else 0.0), masses, damping)
    else:
        raise ValueError("damping_model must be 'rayleigh' or 'modal'")
    return YieldingStick(floor_masses_kg=masses, storey_heights_m=heights, stiffness_n_m=springs,
                         yield_force_n=yield_force,
                         hardening=np.full(n, DEFAULT_HARDENING if hardening is None else float(hardening)),
                         law=law, linear_stiffness_n_m=linear,
                         rayleigh=rayleigh, damping_stiffness=damping_stiffness, modal_damping_n_s_m=modal,
                         bending_rigidity_n_m2=bending)
