"""Storey springs with hysteresis: the force-drift laws of the yielding stick (:mod:`assess.building.nonlinear`).

Two laws, each a pure function of the spring's committed state and a trial drift
(path-dependent through that state only, as a finite-element material is):

* **Bilinear with kinematic hardening** (:func:`bilinear_trial`), for steel frames and
  braces: elastic stiffness k_0 up to the yield force F_y, then b k_0; unloading at
  k_0; the elastic range stays 2 F_y wide and travels with the hardening line. It is
  the bilinear hysteresis of Clough [1]_ without stiffness degradation, and OpenSees'
  ``Steel01`` with no isotropic hardening (a_1 = a_3 = 0), the bilinear limit of the
  Menegotto-Pinto law as Filippou et al. [2]_ use it.

  .. math::  F = \\min\\big(\\max(F_c + k_0\\,(d - d_c),\\; b k_0 d - (1-b)F_y),\\; b k_0 d + (1-b)F_y\\big)

* **Stiffness-degrading, pinching** (:func:`pinching_trial`), for concrete frames and
  walls: the same bilinear backbone (envelope), unloading at k_0 (d_max/d_y)^-β (the
  unloading rule of Takeda, Sozen & Nielsen [3]_, β = 0.4 there), reloading towards
  the largest drift reached in that direction through a pinching point at
  (pinch_x of the way, pinch_y of the force) — the rules of OpenSees' ``Hysteretic``
  material (a modified Clough/Takeda law after Park, Reinhorn & Kunnath [4]_) with a
  bilinear hardening backbone and no strength-damage terms (damage1 = damage2 = 0),
  re-written here from its published rules. Its degrading, pinched loops dissipate
  less energy per cycle than the bilinear ones at the same ductility.

References
----------
.. [1] Clough, R. W., Johnston, S. B. (1966). Effect of stiffness degradation on
   earthquake ductility requirements. Proc. 2nd Japan Earthquake Eng. Symp., 227-232.
.. [2] Filippou, F. C., Popov, E. P., Bertero, V. V. (1983). Effects of bond
   deterioration on hysteretic behavior of reinforced concrete joints. Report
   UCB/EERC-83/19, University of California, Berkeley.
.. [3] Takeda, T., Sozen, M. A., Nielsen, N. N. (1970). Reinforced concrete response
   to simulated earthquakes. J. Struct. Div. ASCE 96(ST12):2557-2573.
.. [4] Park, Y. J., Reinhorn, A. M., Kunnath, S. K. (1987). IDARC: Inelastic damage
   analysis of reinforced concrete frame-shear-wall structures. Report NCEER-87-0008.
   OpenSees ``Hysteretic`` material: https://opensees.berkeley.edu/wiki/index.php/Hysteretic_Material
"""
from __future__ import annotations

import numpy as np
from numba import njit

#: Law codes the compiled kernel dispatches on.
BILINEAR = 0
PINCHING = 1
LAWS = {"bilinear": BILINEAR, "pinching": PINCHING}

#: Slots of a pinching spring's state vector (committed or trial).
_STRAIN, _STRESS, _TANGENT, _ROT_MAX, _ROT_MIN, _ROT_PU, _ROT_NU, _LOAD = range(8)
STATE_SIZE = 8
_BIG = 1.0e16  # OpenSees' POS_INF_STRAIN


@njit(cache=True)
def bilinear_trial(drift, committed_drift, committed_force, stiffness, yield_force, hardening):  # pragma: no cover
    """(force, tangent) of the bilinear kinematic-hardening spring at a trial drift [m] from its committed state."""
    force = committed_force + stiffness * (drift - committed_drift)
    upper = hardening * stiffness * drift + (1.0 - hardening) * yield_force
    lower = hardening * stiffness * drift - (1.0 - hardening) * yield_force
    if force > upper:
        return upper, hardening * stiffness
    if force < lower:
        return lower, hardening * stiffness
    return force, stiffness


@njit(cache=True)
def _envelope(strain, k0, fy, hardening):  # pragma: no cover - compiled
    """Backbone force and tangent (symmetric bilinear, positive hardening)."""
    dy = fy / k0
    if strain >= 0.0:
        if strain <= dy:
            return k0 * strain, k0
        return fy + hardening * k0 * (strain - dy), hardening * k0
    if strain >= -dy:
        return k0 * strain, k0
    return -fy + hardening * k0 * (strain + dy), hardening * k0


@njit(cache=True)
def pinching_trial(committed, trial, strain, k0, fy, hardening, pinch_x, pinch_y, beta):  # pragma: no cover
    """Trial state (written into ``trial``) of the pinching, stiffness-degrading spring at drift ``strain``.

    ``committed`` and ``trial`` are state vectors of :data:`STATE_SIZE`; the rules are
    those of OpenSees' Hysteretic material with a bilinear backbone (rot1 = F_y/k_0,
    E_2 = E_3 = b k_0 > 0) and no damage terms.
    """
    for s in range(STATE_SIZE):
        trial[s] = committed[s]
    load = committed[_LOAD]
    if load == 0.0 and strain == 0.0:
        return
    d_strain = strain - committed[_STRAIN]
    if abs(d_strain) < 2.220446049250313e-16:
        return
    trial[_STRAIN] = strain
    if load == 0.0:
        load = 2.0 if d_strain < 0.0 else 1.0
    rot1 = fy / k0
    if strain >= committed[_ROT_MAX]:
        trial[_ROT_MAX] = strain
        trial[_STRESS], trial[_TANGENT] = _envelope(strain, k0, fy, hardening)
        if strain < 0.0:  # the envelope's tangent for a negative strain on the positive side
            trial[_TANGENT] = k0 * 1.0e-9
        trial[_LOAD] = 1.0
        return
    if strain <= committed[_ROT_MIN]:
        trial[_ROT_MIN] = strain
        trial[_STRESS], trial[_TANGENT] = _envelope(strain, k0, fy, hardening)
        if strain > 0.0:
            trial[_TANGENT] = k0 * 1.0e-9
        trial[_LOAD] = 2.0
        return
    kn = (committed[_ROT_MIN] / -rot1) ** beta
    kn = 1.0 if kn < 1.0 else 1.0 / kn
    kp = (committed[_ROT_MAX] / rot1) ** beta
    kp = 1.0 if kp < 1.0 else 1.0 / kp
    c_stress = committed[_STRESS]
    c_strain = committed[_STRAIN]
    if d_strain > 0.0:
        if load == 2.0 and c_stress <= 0.0:
            trial[_ROT_NU] = c_strain - c_stress / (k0 * kn)
        trial[_LOAD] = 1.0
        rot_max = min(max(trial[_ROT_MAX], rot1), _BIG)
        trial[_ROT_MAX] = rot_max
        max_force = _envelope(rot_max, k0, fy, hardening)[0]
        rot_rel = trial[_ROT_NU]
        rot_mp2 = rot_max - (1.0 - pinch_y) * max_force / (k0 * kp)
        rot_ch = rot_rel + (rot_mp2 - rot_rel) * pinch_x
        if strain < trial[_ROT_NU]:
            tangent = k0 * kn
            stress = c_stress + tangent * d_strain
            if stress >= 0.0:
                stress, tangent = 0.0, k0 * 1.0e-9
        elif strain < rot_ch:
            if strain <= rot_rel:
                stress, tangent = 0.0, k0 * 1.0e-9
            else:
                tangent = max_force * pinch_y / (rot_ch - rot_rel)
                unloading = c_stress + k0 * kp * d_strain
                stress = (strain - rot_rel) * tangent
                if unloading < stress:
                    stress, tangent = unloading, k0 * kp
        else:
            tangent = (1.0 - pinch_y) * max_force / (rot_max - rot_ch)
            unloading = c_stress + k0 * kp * d_strain
            stress = pinch_y * max_force + (strain - rot_ch) * tangent
            if unloading < stress:
                stress, tangent = unloading, k0 * kp
    else:
        if load == 1.0 and c_stress >= 0.0:
            trial[_ROT_PU] = c_strain - c_stress / (k0 * kp)
        trial[_LOAD] = 2.0
        rot_min = max(min(trial[_ROT_MIN], -rot1), -_BIG)
        trial[_ROT_MIN] = rot_min
        min_force = _envelope(rot_min, k0, fy, hardening)[0]
        rot_rel = trial[_ROT_PU]
        rot_mp2 = rot_min - (1.0 - pinch_y) * min_force / (k0 * kn)
        rot_ch = rot_rel + (rot_mp2 - rot_rel) * pinch_x
        if strain > trial[_ROT_PU]:
            tangent = k0 * kp
            stress = c_stress + tangent * d_strain
            if stress <= 0.0:
                stress, tangent = 0.0, k0 * 1.0e-9
        elif strain > rot_ch:
            if strain >= rot_rel:
                stress, tangent = 0.0, k0 * 1.0e-9
            else:
                tangent = min_force * pinch_y / (rot_ch - rot_rel)
                unloading = c_stress + k0 * kn * d_strain
                stress = (strain - rot_rel) * tangent
                if unloading > stress:
                    stress, tangent = unloading, k0 * kn
        else:
            tangent = (1.0 - pinch_y) * min_force / (rot_min - rot_ch)
            unloading = c_stress + k0 * kn * d_strain
            stress = pinch_y * min_force + (strain - rot_ch) * tangent
            if unloading > stress:
                stress, tangent = unloading, k0 * kn
    trial[_STRESS] = stress
    trial[_TANGENT] = tangent


def initial_state(stiffness):
    """Committed state vector of springs at rest, shape (n, :data:`STATE_SIZE`)."""
    k0 = np.asarray(stiffness, dtype=float)
    state = np.zeros((k0.size, STATE_SIZE))
    state[:, _TANGENT] = k0
    return state


@njit(cache=True)
def _cycle(drifts, law, k0, fy, hardening, pinch_x, pinch_y, beta):  # pragma: no cover - compiled
    """Forces of one spring along a drift path (every point committed)."""
    committed = np.zeros(STATE_SIZE)
    committed[_TANGENT] = k0
    trial = np.zeros(STATE_SIZE)
    out = np.empty(drifts.size)
    for i in range(drifts.size):
        if law == BILINEAR:
            force, tangent = bilinear_trial(drifts[i], committed[_STRAIN], committed[_STRESS], k0, fy, hardening)
            committed[_STRAIN], committed[_STRESS], committed[_TANGENT] = drifts[i], force, tangent
        else:
            pinching_trial(committed, trial, drifts[i], k0, fy, hardening, pinch_x, pinch_y, beta)
            committed[:] = trial
        out[i] = committed[_STRESS]
    return out


def spring_forces(drift_path_m, law, stiffness_n_m, yield_force_n, hardening=0.03, pinch_x=0.8,
                  pinch_y=0.4, beta=0.4):
    """Force [N] of one storey spring along a drift path [m] (each point a committed state).

    Examples
    --------
    A bilinear spring, k_0 = 100 N/m, F_y = 10 N (d_y = 0.1 m), b = 0.1, pushed to 0.3 m
    (F = 10 + 0.1·100·0.2 = 12 N), then back to 0.1 m (12 - 100·0.2 = -8 N):

    >>> spring_forces([0.1, 0.3, 0.1], "bilinear", 100.0, 10.0, hardening=0.1).round(6).tolist()
    [10.0, 12.0, -8.0]
    """
    path = np.ascontiguousarray(drift_path_m, dtype=float)
    return _cycle(path, LAWS[law], float(stiffness_n_m), float(yield_force_n), float(hardening),
                  float(pinch_x), float(pinch_y), float(beta))
