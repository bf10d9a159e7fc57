"""Each floor's absolute acceleration in time: linear modal response history of the building.

Each mode j is a damped oscillator (period T_j, damping ratio ζ_j) under the
ground acceleration; its relative displacement D_j solves

.. math::  \\ddot D_j + 2\\zeta_j\\omega_j\\dot D_j + \\omega_j^2 D_j = -\\ddot u_g(t)

and the floor's absolute acceleration is the ground's plus the modes' relative ones
(Chopra [2]_ §13.1):

.. math::  a(z, t) = \\ddot u_g(t) + \\sum_j \\Gamma_j\\,\\phi_j(z)\\,\\ddot D_j(t),
           \\qquad \\ddot D_j = -\\ddot u_g - 2\\zeta_j\\omega_j\\dot D_j - \\omega_j^2 D_j

The modes not kept are taken as rigid (they move with the ground), which is what
this sum does with them. The ground acceleration is linear between its samples,
as everywhere in assess, and the oscillators are stepped by the exact recursion
for that input (Nigam & Jennings [1]_; Chopra [2]_ §5.2, Table 5.2.1): no
discretisation error beyond the record's own. The building is linear (elastic):
see :mod:`assess.building` for what that means for the floors' peaks.

References
----------
.. [1] Nigam, N. C., Jennings, P. C. (1969). Calculation of response spectra
   from strong-motion earthquake records. Bull. Seismol. Soc. Am. 59(2):909-922.
.. [2] Chopra, A. K. (2012). Dynamics of Structures, 4th ed. Pearson. §5.2
   (Table 5.2.1), §13.1.
"""
from __future__ import annotations

from typing import Optional, Sequence

import numpy as np
from numba import njit

from assess.hazard.records import Record
from assess.site.spectrum import nigam_jennings_coefficients  # the one exact step of a linear oscillator

from .modes import BuildingModes


@njit(cache=True)
def _relative_accelerations(ground, coefficients, omega, zeta):  # pragma: no cover - compiled
    """Relative accelerations D̈_j(t_i) of the oscillators, from rest, under ground acceleration ``ground``."""
    n_modes = omega.size
    n = ground.size
    out = np.empty((n, n_modes))
    for j in range(n_modes):
        a, b, c, d, a1, b1, c1, d1 = (coefficients[0, j], coefficients[1, j], coefficients[2, j],
                                      coefficients[3, j], coefficients[4, j], coefficients[5, j],
                                      coefficients[6, j], coefficients[7, j])
        w2 = omega[j] * omega[j]
        cw = 2.0 * zeta[j] * omega[j]
        u = 0.0
        v = 0.0
        out[0, j] = -ground[0]
        for i in range(n - 1):
            p0 = -ground[i]
            p1 = -ground[i + 1]
            u_next = a * u + b * v + c * p0 + d * p1
            v = a1 * u + b1 * v + c1 * p0 + d1 * p1
            u = u_next
            out[i + 1, j] = p1 - cw * v - w2 * u
    return out


@njit(cache=True)
def _floor_sum(ground, relative, contributions):  # pragma: no cover - compiled
    """ü_g(t) + Σ_j c[k, j] D̈_j(t) for every floor k (a plain loop: faster here than a BLAS call on a busy
    machine)."""
    n_floors, n_modes = contributions.shape
    n = ground.size
    out = np.empty((n_floors, n))
    for k in range(n_floors):
        for i in range(n):
            total = ground[i]
            for j in range(n_modes):
                total += contributions[k, j] * relative[i, j]
            out[k, i] = total
    return out


def modal_relative_accelerations(ground_accel_g, dt_s, periods_s, damping):
    """D̈_j(t) [g] of each mode's oscillator, from rest, at the ground record's samples.

    Parameters
    ----------
    ground_accel_g : array-like, (n_samples,)
        Ground acceleration [g], linear between samples.
    dt_s : float
        Step [s].
    periods_s, damping : array-like, (n_modes,)
        T_j [s] and ζ_j.

    Returns
    -------
    ndarray, (n_samples, n_modes)
        Relative acceleration [g] of each oscillator (the units of the input: the
        recursion is linear).

    Examples
    --------
    A very flexible oscillator stays where it is: its relative acceleration is -ü_g;
    a very stiff one moves with the ground, its relative acceleration near 0:

    >>> ground = np.sin(np.linspace(0, 3, 301))
    >>> out = modal_relative_accelerations(ground, 0.01, [1e5, 0.001], [0.05, 0.05])
    >>> bool(np.allclose(out[:, 0], -ground, atol=1e-3)), bool(np.abs(out[:, 1]).max() < 1e-3)
    (True, True)
    """
    ground = np.ascontiguousarray(ground_accel_g, dtype=float)
    periods = np.ascontiguousarray(periods_s, dtype=float)
    zeta = np.array(np.broadcast_to(np.asarray(damping, dtype=float), periods.shape))  # writable: one kernel
    coefficients = np.ascontiguousarray(nigam_jennings_coefficients(periods, dt_s, zeta))
    return _relative_accelerations(ground, coefficients, 2.0 * np.pi / periods, zeta)


def floor_accelerations(modes: BuildingModes, ground_accel_g, dt_s):
    """Absolute acceleration [g] of every floor in time under one ground motion.

    .. math::  a(z_k, t) = \\ddot u_g(t) + \\sum_j \\Gamma_j\\phi_j(z_k)\\ddot D_j(t)

    Returns
    -------
    ndarray, (storeys + 1, n_samples)
        Row k is floor k (row 0 the ground, the ground motion itself).

    Examples
    --------
    >>> from assess.building.modes import building_modes
    >>> modes = building_modes(3, 3.5, period_s=0.35, alpha=np.inf)
    >>> a = floor_accelerations(modes, np.zeros(10), 0.01)
    >>> a.shape, float(abs(a).max())
    ((4, 10), 0.0)
    """
    ground = np.ascontiguousarray(ground_accel_g, dtype=float)
    relative = modal_relative_accelerations(ground, dt_s, modes.periods_s, modes.damping)
    return _floor_sum(ground, relative, np.ascontiguousarray(modes.floor_participation()))


def floor_records(modes: BuildingModes, ground_motions: Sequence[Record],
                  floors: Optional[Sequence[int]] = None) -> dict[int, list[Record]]:
    """Absolute acceleration histories of the floors asked for, under every ground motion, as records.

    Parameters
    ----------
    modes : BuildingModes
    ground_motions : sequence of Record
        The ground suite (accelerations [g]); each keeps its own step.
    floors : sequence of int, optional
        Floors wanted (0 = ground to ``modes.storeys`` = roof); by default every floor.
        Only those are computed (memory grows with floors x samples).

    Returns
    -------
    dict of int to list of Record
        ``result[k][m]``: floor k under ground motion m, at the ground motion's
        step, named ``"<ground name> @ floor k"``; floor 0 is (a copy of) the ground motion.
    """
    wanted = list(range(modes.storeys + 1)) if floors is None else [int(k) for k in floors]
    if any(not 0 <= k <= modes.storeys for k in wanted):
        raise ValueError(f"floors must lie between 0 and {modes.storeys}")
    contributions = np.ascontiguousarray(modes.floor_participation()[wanted])
    out = {k: [] for k in wanted}
    for motion in ground_motions:
        ground = np.ascontiguousarray(motion.accel_g, dtype=float)
        relative = modal_relative_accelerations(ground, motion.dt_s, modes.periods_s, modes.damping)
        history = _floor_sum(ground, relative, contributions)
        for row, k in enumerate(wanted):
            accel = ground.copy() if k == 0 else history[row]
            out[k].append(Record(accel, motion.dt_s, motion.name if k == 0 else f"{motion.name} @ floor {k}"))
    return out
