"""Trigonometric and rectangular acceleration pulses (Makris 1997; Makris & Chang 2000).

With ωp = 2π/Tp and acceleration amplitude ap (docs/commands.md, ``assess simulate``):

* ``rect``: ü = ap for 0 ≤ t ≤ Tp (Newmark 1965);
* ``A`` (one-sine, forward displacement): ü = ap sin(ωp t), 0 ≤ t ≤ Tp;
* ``B`` (one-cosine, forward-and-back displacement): ü = ap cos(ωp t), 0 ≤ t ≤ Tp;
* ``C`` (Type-C1): ü = ap cos(ωp t + φ), 0 ≤ t ≤ (3/2 − φ/π) Tp, with φ chosen
  so that the pulse ends with zero ground velocity and displacement.

and ü = 0 outside. The velocity amplitude vp (peak floor velocity of the pulse)
is ap/ωp for B, 2ap/ωp for A (u̇ = (ap/ωp)(1 − cos ωp t); the paper's
u_A = vp[ωp t − sin ωp t]/(2ωp)) and ap/ωp·(1 + sin φ) for C1.

References
----------
.. [1] Makris, N. (1997). Rigidity-plasticity-viscosity: can electrorheological
   dampers protect base-isolated structures from near-source ground motions?
   Earthquake Eng. Struct. Dyn. 26:571-591.
.. [2] Makris, N., Chang, S.-P. (2000). Response of damped oscillators to
   cycloidal pulses. J. Eng. Mech. 126(2):123-131.
.. [3] Konstantinidis & Makris (2010), section 6 and Fig. 3,
   doi:10.1007/s10518-010-9192-8.
"""
from __future__ import annotations

import numpy as np
from scipy import optimize

PULSE_TYPES = ("A", "B", "C", "rect")


def type_c_phase(cycles: int = 1) -> float:
    """Phase φ [rad] of a Type-Cn pulse ü = ap cos(ωp t + φ).

    The pulse lasts (n + 1/2 − φ/π)Tp, ending at zero velocity
    (u̇ = vp[sin(ωp t + φ) − sin φ]); φ makes the final displacement vanish:

    .. math:: 2\\cos\\varphi = [(2n + 1)\\pi - 2\\varphi]\\sin\\varphi

    >>> round(type_c_phase(1), 4)
    0.219
    """
    n = int(cycles)
    return float(optimize.brentq(
        lambda phi: 2.0 * np.cos(phi) - ((2 * n + 1) * np.pi - 2.0 * phi) * np.sin(phi), 1e-6, 1.0))


def pulse_duration(pulse: str, tp_s: float) -> float:
    """Duration [s] of a pulse of period ``tp_s``: Tp for rect, A and B; (3/2 − φ/π)Tp for C."""
    if pulse == "C":
        return (1.5 - type_c_phase(1) / np.pi) * tp_s
    if pulse in ("A", "B", "rect"):
        return float(tp_s)
    raise ValueError(f"unknown pulse type '{pulse}'; use one of {', '.join(PULSE_TYPES)}")


def pulse_acceleration(pulse: str, ap_g: float, tp_s: float, time_s):
    """Floor acceleration [g] of a pulse at times ``time_s`` [s] (zero outside the pulse).

    Examples
    --------
    >>> [round(float(a), 6) for a in pulse_acceleration("A", 0.5, 2.0, [0.5, 1.5, 2.5])]
    [0.5, -0.5, 0.0]
    >>> [round(float(a), 6) for a in pulse_acceleration("B", 0.5, 2.0, [0.0, 1.0, 2.5])]
    [0.5, -0.5, 0.0]
    """
    time_s = np.asarray(time_s, dtype=float)
    omega = 2.0 * np.pi / tp_s
    inside = (time_s >= 0.0) & (time_s <= pulse_duration(pulse, tp_s))
    if pulse == "rect":
        shape = np.ones_like(time_s)
    elif pulse == "A":
        shape = np.sin(omega * time_s)
    elif pulse == "B":
        shape = np.cos(omega * time_s)
    else:  # "C", validated by pulse_duration
        shape = np.cos(omega * time_s + type_c_phase(1))
    return np.where(inside, ap_g * shape, 0.0)
