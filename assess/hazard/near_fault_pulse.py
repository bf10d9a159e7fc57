"""The near-fault velocity pulse of Mavroeidis & Papageorgiou and its zero-displacement form.

With τ = t − t_peak, fp = 1/Tp and the window |τ| ≤ γ/(2fp), the Mavroeidis &
Papageorgiou (MP) pulse [1]_ is

.. math::

    v(t) = \\tfrac{V_p}{2}\\,[1 + \\cos(2\\pi f_p\\tau/\\gamma)]\\cos(2\\pi f_p\\tau + \\nu)

and Dabaghi & Der Kiureghian [2]_ subtract a smooth term that removes its
residual displacement D, so that the pulse ends at rest where it started:

.. math::

    v_p(t) = v(t) - \\frac{D f_p}{\\gamma}\\,[1 + \\cos(2\\pi f_p\\tau/\\gamma)]

Used by :mod:`assess.hazard.synthesis`.

References
----------
.. [1] Mavroeidis, G. P., Papageorgiou, A. S. (2003). A mathematical
   representation of near-fault ground motions. Bull. Seismol. Soc. Am.
   93(3):1099-1131. doi:10.1785/0120020100
.. [2] Dabaghi, M., Der Kiureghian, A. (2017). Stochastic model for simulation
   of near-fault ground motions. Earthquake Eng. Struct. Dyn. 46(6):963-984.
   doi:10.1002/eqe.2839
"""
from __future__ import annotations

import functools
import json
from importlib import resources
from pathlib import Path

import numpy as np
from scipy import optimize

def _pulse_window(time_s, tp_s, gamma, t_peak_s):
    """Phase θ = 2π fp (t − t_peak) and the mask of the window |θ| ≤ πγ."""
    theta = 2.0 * np.pi * (np.asarray(time_s, dtype=float) - t_peak_s) / tp_s
    return theta, np.abs(theta) <= np.pi * gamma


def mavroeidis_papageorgiou_velocity(time_s, vp_m_s, tp_s, gamma, nu, t_peak_s):
    """Velocity [m/s] of the Mavroeidis & Papageorgiou (2003) pulse.

    With fp = 1/Tp and τ = t − t_peak (the envelope's centre, t0 of [1]):

    .. math::

        v(t) = \\frac{V_p}{2}\\left[1 + \\cos\\left(\\frac{2\\pi f_p \\tau}{\\gamma}\\right)\\right]
               \\cos(2\\pi f_p \\tau + \\nu), \\qquad |\\tau| \\le \\frac{\\gamma}{2 f_p},

    and zero outside. The harmonic of period Tp has zeros every Tp/2; the bell
    envelope lasts γTp (γ > 1). For ν = 0 the peak is Vp at t_peak.

    Parameters
    ----------
    time_s : array_like
        Times [s].
    vp_m_s : float
        Amplitude Vp [m/s].
    tp_s : float
        Pulse period Tp = 1/fp [s].
    gamma : float
        Envelope parameter γ [-] (oscillatory character; > 1).
    nu : float
        Phase ν of the harmonic [rad].
    t_peak_s : float
        Centre of the envelope [s].

    References
    ----------
    .. [1] Mavroeidis & Papageorgiou (2003), velocity expression of their
       model, doi:10.1785/0120020100.

    Examples
    --------
    >>> float(mavroeidis_papageorgiou_velocity(3.0, 0.75, 2.0, 2.3, 0.0, 3.0))
    0.75
    >>> round(float(mavroeidis_papageorgiou_velocity(3.5, 0.75, 2.0, 2.3, 0.0, 3.0)), 12)  # τ = Tp/4
    0.0
    """
    theta, inside = _pulse_window(time_s, tp_s, gamma, t_peak_s)
    velocity = 0.5 * vp_m_s * (1.0 + np.cos(theta / gamma)) * np.cos(theta + nu)
    velocity = np.where(inside, velocity, 0.0)
    return velocity + 0.0  # -0.0 -> 0.0


def mavroeidis_papageorgiou_acceleration(time_s, vp_m_s, tp_s, gamma, nu, t_peak_s):
    """Acceleration [m/s²] of the Mavroeidis & Papageorgiou (2003) pulse, dv/dt.

    .. math::

        a(t) = -\\pi f_p V_p\\left[\\frac{1}{\\gamma}\\sin\\left(\\frac{2\\pi f_p\\tau}{\\gamma}\\right)
               \\cos(2\\pi f_p\\tau + \\nu) + \\left(1 + \\cos\\frac{2\\pi f_p\\tau}{\\gamma}\\right)
               \\sin(2\\pi f_p\\tau + \\nu)\\right], \\qquad |\\tau| \\le \\frac{\\gamma}{2 f_p},

    zero outside; continuous at the window's ends. Arguments as
    :func:`mavroeidis_papageorgiou_velocity`.

    Examples
    --------
    At τ = Tp/4 with ν = 0 (a zero of the velocity):
    -π fp Vp [sin(π/(2γ))·0 + (1 + cos(π/(2γ)))·1], here γ = 2:

    >>> round(float(mavroeidis_papageorgiou_acceleration(0.5, 1.0, 2.0, 2.0, 0.0, 0.0)), 6)
    -2.681517
    """
    theta, inside = _pulse_window(time_s, tp_s, gamma, t_peak_s)
    accel = -np.pi * vp_m_s / tp_s * (np.sin(theta / gamma) * np.cos(theta + nu) / gamma
                                       + (1.0 + np.cos(theta / gamma)) * np.sin(theta + nu))
    return np.where(inside, accel, 0.0) + 0.0


def mavroeidis_papageorgiou_residual_displacement(vp_m_s, tp_s, gamma, nu):
    """Displacement [m] the Mavroeidis & Papageorgiou pulse leaves, ∫v dt over its window.

    .. math::

        D = \\frac{V_p \\cos\\nu\\,\\sin(\\pi\\gamma)}{2\\pi f_p(1 - \\gamma^2)}
          = \\frac{V_p T_p \\cos\\nu}{2(\\gamma + 1)}\\,\\mathrm{sinc}(\\gamma - 1),

    with sinc x = sin(πx)/(πx) (the second form is finite at γ = 1). This is the
    correction term of Dabaghi & Der Kiureghian (2017) [1]_.

    References
    ----------
    .. [1] Dabaghi & Der Kiureghian (2017), modified MP pulse,
       doi:10.1002/eqe.2839.

    Examples
    --------
    γ = 2 leaves no displacement (sin 2π = 0); γ = 1, ν = 0: Vp Tp/4.

    >>> round(float(mavroeidis_papageorgiou_residual_displacement(1.0, 2.0, 2.0, 0.0)), 12)
    0.0
    >>> round(float(mavroeidis_papageorgiou_residual_displacement(1.0, 2.0, 1.0, 0.0)), 12)
    0.5
    """
    return vp_m_s * tp_s * np.cos(nu) * np.sinc(np.asarray(gamma, dtype=float) - 1.0) / (2.0 * (gamma + 1.0))


def modified_mavroeidis_papageorgiou_velocity(time_s, vp_m_s, tp_s, gamma, nu, t_peak_s):
    """Velocity [m/s] of the modified MP pulse of Dabaghi & Der Kiureghian (2017).

    The MP pulse minus a bell of the same window whose integral is the MP
    pulse's residual displacement D, so that the pulse ends where it started:

    .. math::

        v(t) = v_{MP}(t) - \\frac{D}{\\gamma T_p}\\left[1 + \\cos\\left(\\frac{2\\pi\\tau}{\\gamma T_p}\\right)\\right],
        \\qquad |\\tau| \\le \\frac{\\gamma T_p}{2}

    (D from :func:`mavroeidis_papageorgiou_residual_displacement`). Arguments
    as :func:`mavroeidis_papageorgiou_velocity`.

    Examples
    --------
    γ = 2: D = 0, the MP pulse itself.

    >>> float(modified_mavroeidis_papageorgiou_velocity(3.0, 0.75, 2.0, 2.0, 0.0, 3.0))
    0.75
    """
    theta, inside = _pulse_window(time_s, tp_s, gamma, t_peak_s)
    correction = (mavroeidis_papageorgiou_residual_displacement(vp_m_s, tp_s, gamma, nu)
                  / (gamma * tp_s) * (1.0 + np.cos(theta / gamma)))
    return (mavroeidis_papageorgiou_velocity(time_s, vp_m_s, tp_s, gamma, nu, t_peak_s)
            - np.where(inside, correction, 0.0))


def modified_mavroeidis_papageorgiou_acceleration(time_s, vp_m_s, tp_s, gamma, nu, t_peak_s):
    """Acceleration [m/s²] of the modified MP pulse, dv/dt:

    .. math::

        a(t) = a_{MP}(t) + \\frac{2\\pi D}{\\gamma^2 T_p^2}\\sin\\left(\\frac{2\\pi\\tau}{\\gamma T_p}\\right),
        \\qquad |\\tau| \\le \\frac{\\gamma T_p}{2}.

    Examples
    --------
    >>> float(modified_mavroeidis_papageorgiou_acceleration(3.0, 0.75, 2.0, 2.3, 0.0, 3.0))
    0.0
    """
    theta, inside = _pulse_window(time_s, tp_s, gamma, t_peak_s)
    correction = (2.0 * np.pi * mavroeidis_papageorgiou_residual_displacement(vp_m_s, tp_s, gamma, nu)
                  / (gamma * tp_s) ** 2 * np.sin(theta / gamma))
    return (mavroeidis_papageorgiou_acceleration(time_s, vp_m_s, tp_s, gamma, nu, t_peak_s)
            + np.where(inside, correction, 0.0))


def pulse_peak_factor(gamma, nu):
    """Signed extreme of the modified MP velocity for Vp = 1, Tp = 1 (its value where |v| is largest).

    The pulse's peak velocity is ``Vp * pulse_peak_factor(gamma, nu)``; it does
    not depend on Tp or t_peak. Found on a grid of 4001 points over the window,
    refined by bounded scalar minimisation.

    Examples
    --------
    >>> round(pulse_peak_factor(2.0, 0.0), 12)
    1.0
    """
    tau = np.linspace(-0.5 * gamma, 0.5 * gamma, 4001)
    velocity = modified_mavroeidis_papageorgiou_velocity(tau, 1.0, 1.0, gamma, nu, 0.0)
    k = int(np.argmax(np.abs(velocity)))
    sign = 1.0 if velocity[k] >= 0.0 else -1.0
    step = tau[1] - tau[0]
    best = optimize.minimize_scalar(
        lambda t: -sign * float(modified_mavroeidis_papageorgiou_velocity(t, 1.0, 1.0, gamma, nu, 0.0)),
        bounds=(max(tau[0], tau[k] - step), min(tau[-1], tau[k] + step)), method="bounded",
        options={"xatol": 1e-12})
    return float(sign * max(-best.fun, sign * velocity[k]))


def type_b_approximation(gamma, nu):
    """The Type-B pulse that best approximates the modified MP pulse of Vp = 1, Tp = 1.

    The workbook's and the identifier's (Tp, vp) describe a motion's pulse
    by the Type-B pulse u̇ = vp·sin(2π(t − t0)/T_B), t0 ≤ t ≤ t0 + T_B, that
    approximates it (the paper's Table 3, third column; the least-squares
    fit of :func:`assess.hazard.pulse_identification.identify_pulse`). This
    is that fit for the modified MP velocity pulse itself: the signed
    amplitude and the period of the Type-B pulse closest to it in the
    least-squares sense, over (T_B, t0) with the amplitude solved exactly.
    The synthesis divides the workbook's (Tp, vp) by these to find the MP
    pulse whose Type-B approximation they are.

    Returns
    -------
    (amplitude, period) : tuple of float
        Signed vp of the Type-B approximation [per unit Vp] and T_B [per unit Tp].

    Examples
    --------
    For γ = 2.3 the Type-B approximation reads 0.80-1.00 of the MP pulse's
    peak velocity, depending on the phase ν (measured independently with
    ``identify_pulse(models=("B",))`` on the sampled pulses: the same to 0.01):

    >>> [round(abs(type_b_approximation(2.3, nu)[0] / pulse_peak_factor(2.3, nu)), 2) for nu in (0.0, np.pi / 2)]
    [0.8, 1.0]
    """
    tau = np.linspace(-0.5 * gamma - 1.5, 0.5 * gamma + 1.5, 2401)
    step = tau[1] - tau[0]
    velocity = modified_mavroeidis_papageorgiou_velocity(tau, 1.0, 1.0, gamma, nu, 0.0)

    def fit(parameters):
        period, start = parameters
        phase = (tau - start) / period
        shape = np.where((phase >= 0.0) & (phase <= 1.0), np.sin(2.0 * np.pi * phase), 0.0)
        norm = float(shape @ shape)
        amplitude = float(shape @ velocity) / norm if norm > 0.0 else 0.0
        return amplitude, float(np.sum((velocity - amplitude * shape) ** 2)) * step

    starts = [(period, start) for period in (0.7, 0.9, 1.1, 1.3)
              for start in np.arange(-0.5 * gamma - 0.5, 0.5 * gamma, 0.1)]
    best = min(starts, key=lambda x: fit(x)[1])
    refined = optimize.minimize(lambda x: fit(x)[1], best, method="Nelder-Mead",
                                options={"xatol": 1e-6, "fatol": 1e-12, "maxiter": 2000})
    amplitude, _ = fit(refined.x)
    return amplitude, float(refined.x[0])


#: Phases ν on [0, π) at which :func:`type_b_reading` tabulates the Type-B approximation.
_READING_PHASES = 24


#: The file of :func:`type_b_reading_table` at the synthesis' default γ 2.3 (``python -m
#: assess.hazard.near_fault_pulse`` writes it; tests/verification/test_synthesis.py recomputes it): the 24 fits take
#: about 0.25 s, which every run that synthesises motions would spend again.
READING_TABLE_FILE = "type_b_reading.json"


def type_b_reading_table(gamma) -> tuple[np.ndarray, np.ndarray]:
    """(phases ν, readings): :func:`type_b_approximation` at 24 phases on [0, π), each as
    (|vp_B| / peak velocity, T_B / Tp), worked out."""
    phases = np.linspace(0.0, np.pi, _READING_PHASES, endpoint=False)
    readings = []
    for nu in phases:
        amplitude, period = type_b_approximation(gamma, nu)
        readings.append((abs(amplitude) / abs(pulse_peak_factor(gamma, nu)), period))
    return phases, np.array(readings)


@functools.lru_cache(maxsize=16)
def _type_b_reading_table(gamma):
    """:func:`type_b_reading_table`, read from :data:`READING_TABLE_FILE` where it holds ``gamma``."""
    with resources.files("assess.data").joinpath(READING_TABLE_FILE).open("r") as handle:
        stored = json.load(handle)
    if float(stored["gamma"]) == gamma:
        return np.asarray(stored["phases"], dtype=float), np.asarray(stored["readings"], dtype=float)
    return type_b_reading_table(gamma)


def type_b_reading(gamma, nu):
    """How a Type-B approximation reads the modified MP pulse: (|vp_B| / peak velocity, T_B / Tp).

    :func:`type_b_approximation` tabulated at 24 phases on [0, π) and
    interpolated periodically (both ratios repeat with period π in ν: the
    pulse of ν + π is the pulse of ν reversed).

    >>> [round(x, 3) for x in type_b_reading(2.3, 0.0)]
    [0.8, 0.955]
    """
    phases, readings = _type_b_reading_table(float(gamma))
    nu = float(np.mod(nu, np.pi))
    period = np.pi
    extended = np.concatenate([phases, [period]])
    values = np.vstack([readings, readings[:1]])
    return float(np.interp(nu, extended, values[:, 0])), float(np.interp(nu, extended, values[:, 1]))


# writes READING_TABLE_FILE again, for its γ (floats as Python writes them: read back exactly)
if __name__ == "__main__":
    path = Path(__file__).resolve().parents[1] / "data" / READING_TABLE_FILE
    gamma = float(json.loads(path.read_text())["gamma"])
    phases, readings = type_b_reading_table(gamma)
    text = json.dumps({"gamma": gamma, "phases": phases.tolist(), "readings": readings.tolist()}, indent=1)
    path.write_text(text + "\n")
