"""OpenSeesPy model of the tool's wall on a base hinge (:mod:`assess.building.wall_hinge`): its test-only peer.

Built from the tool's numbers, element by element, not from its matrix: the shear-flexural elastic model
of :func:`~assess.building.modes.stiffness_matrix` (a flexural column beside a chain of storey shear
springs) standing on a ``zeroLength`` rotational hinge (node 0 fixed to node 100, ``-dir 6``, no
``-doRayleigh``: no damping on it) of ``Hysteretic`` (the pinching law: a bilinear backbone M_y at θ_y, then
b_s k_θ to 100 θ_y; pinchX, pinchY, β; no damage) or ``Steel01`` (bilinear).

* The flexural column: ``elasticBeamColumn`` elements (axially rigid) from node 100 up through the floors
  1..n, whose rotations are free: its base rotates with the hinge.
* The storey shear springs: a second chain of ``elasticBeamColumn`` elements on nodes 200 + i, each tied
  to floor i in translation (floor i follows node 200 + i, ``equalDOF`` 1: a constrained node takes one
  constraint here) and to the hinge's rotation (``equalDOF`` 3 from node 100),
  with EI = k_s L³/12: a beam whose ends turn together by θ resists V = 12EI/L³ (Δ − Lθ) = k_s (Δ − Lθ), a
  storey spring that a rigid rotation of the whole does not strain, as the tool's K (u − hθ) says.
* Rayleigh damping: ``rayleigh(a_0, 0, 0, a_1 (n + 1)/n)``, mass-proportional on the floors,
  stiffness-proportional on the elastic elements (the hinge has none).
* Newmark's average acceleration with Newton iterations (``NormDispIncr`` 1e-12) at the substep given,
  ``Transformation`` constraints.

The tool's matrix K_e is split into the column and the springs by the caller's α and storey stiffness
(:func:`hinge_floor_histories`).
"""
from __future__ import annotations

import numpy as np

from assess.building.modes import flexural_stiffness_matrix, shear_stiffness_matrix
from peers.opensees_shear import load_opensees
from peers.opensees_yielding import floor_histories


def _split(wall, alpha, storey_stiffness):
    """(EI of the column [N m²], the springs' k_s [N/m]) whose matrices sum to the wall's K_e."""
    n = wall.storeys
    h = float(np.mean(wall.storey_heights_m))
    relative = np.ones(n) if storey_stiffness is None else np.asarray(storey_stiffness, dtype=float)
    height = n * h
    bending = relative[0] * h * height ** 2 / alpha ** 2 if np.isfinite(alpha) else 0.0
    base = shear_stiffness_matrix(relative) + (flexural_stiffness_matrix(n, h, bending) if bending else 0.0)
    scale = float(wall.elastic_stiffness_n_m[-1, -1] / base[-1, -1])
    if not np.allclose(base * scale, wall.elastic_stiffness_n_m, rtol=1e-9, atol=1e-9 * abs(base * scale).max()):
        raise ValueError("the wall's K_e is not this α's shear-flexural model")
    return bending * scale, relative * scale


def build_hinged_wall(ops, wall, alpha, storey_stiffness=None):
    """The OpenSees model of ``wall`` (wiped first); returns nothing."""
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    n = wall.storeys
    z = wall.floor_heights_m
    bending, springs = _split(wall, alpha, storey_stiffness)
    ops.node(0, 0.0, 0.0)
    ops.fix(0, 1, 1, 1)
    ops.node(100, 0.0, 0.0)
    ops.fix(100, 1, 1, 0)
    k_theta, m_y = float(wall.hinge_stiffness_n_m_rad), float(wall.yield_moment_n_m)
    if wall.law == "bilinear":
        ops.uniaxialMaterial("Steel01", 1, m_y, k_theta, float(wall.hinge_hardening))
    else:
        theta_y = m_y / k_theta
        theta_3 = 100.0 * theta_y
        m_3 = m_y + wall.hinge_hardening * k_theta * (theta_3 - theta_y)
        ops.uniaxialMaterial("Hysteretic", 1, m_y, theta_y, m_3, theta_3, -m_y, -theta_y, -m_3, -theta_3,
                             float(wall.pinch_x), float(wall.pinch_y), 0.0, 0.0, float(wall.unloading_beta))
    ops.element("zeroLength", 1, 0, 100, "-mat", 1, "-dir", 6)
    ops.geomTransf("Linear", 1)
    below = 100
    for i in range(1, n + 1):
        ops.node(i, 0.0, float(z[i - 1]))
        ops.fix(i, 0, 1, 0)
        ops.mass(i, float(wall.floor_masses_kg[i - 1]), 0.0, 0.0)
        if bending > 0.0:
            ops.element("elasticBeamColumn", 10 + i, below, i, 1e12, 1.0, float(bending), 1)
        below = i
    below = 100
    for i in range(1, n + 1):
        length = float(wall.storey_heights_m[i - 1])
        ops.node(200 + i, 0.0, float(z[i - 1]))
        ops.fix(200 + i, 0, 1, 0)
        ops.equalDOF(200 + i, i, 1)
        ops.equalDOF(100, 200 + i, 3)
        ops.element("elasticBeamColumn", 300 + i, below, 200 + i, 1e12, 1.0, float(springs[i - 1] * length ** 3 / 12.0),
                    1)
        below = 200 + i


def hinge_floor_histories(wall, alpha, ground_accel_g, dt_s, substeps, storey_stiffness=None):
    """(absolute floor accelerations [g] (n + 1, samples), storey drifts [m] (n, samples), peak |θ| of the
    hinge at the samples [rad]) from OpenSees."""
    ops, why = load_opensees()
    if ops is None:
        raise RuntimeError(why)
    build_hinged_wall(ops, wall, alpha, storey_stiffness)
    a0, a1 = wall.rayleigh
    n_mod = wall.stiffness_ratio_n
    ops.rayleigh(float(a0), 0.0, 0.0, float(a1 * (n_mod + 1.0) / n_mod))
    rotation = [0.0]
    accel, drift = floor_histories(ops, wall.storeys, ground_accel_g, dt_s, substeps, 1e-12, True,
                                   each_sample=lambda o: rotation.append(abs(o.nodeDisp(100, 3))))
    return accel, drift, float(max(rotation))


def hinge_periods(wall, alpha, storey_stiffness=None, modes=3):
    """The OpenSees model's periods [s] with the hinge elastic."""
    ops, why = load_opensees()
    if ops is None:
        raise RuntimeError(why)
    build_hinged_wall(ops, wall, alpha, storey_stiffness)
    periods = 2.0 * np.pi / np.sqrt(np.array(ops.eigen("-fullGenLapack", modes)))
    ops.wipe()
    return periods
