"""Synthetic near-fault floor accelerations from PTA, Tp and vp alone.

Where the workbook describes a motion only by its peak acceleration PTA, the
period Tp and the velocity amplitude vp of its predominant pulse (docs/workbook.md), this
module generates acceleration histories with the stochastic near-fault model of
Dabaghi & Der Kiureghian [1]_ [2]_: a velocity pulse plus a stochastic
high-frequency residual.

Model
-----
**Pulse** — the modified Mavroeidis & Papageorgiou (MP) velocity pulse of [1]_,
with τ = t − t_peak, fp = 1/Tp and window |τ| ≤ γ/(2fp):

.. math::

    v_p(t) = \\tfrac{V_p}{2}\\,[1 + \\cos(2\\pi f_p\\tau/\\gamma)]\\cos(2\\pi f_p\\tau + \\nu)
             - \\frac{D f_p}{\\gamma}\\,[1 + \\cos(2\\pi f_p\\tau/\\gamma)]

The first term is the MP pulse [3]_ (:func:`mavroeidis_papageorgiou_velocity`);
the second removes its residual displacement D
(:func:`mavroeidis_papageorgiou_residual_displacement`), so the pulse ends at
rest where it started (:func:`modified_mavroeidis_papageorgiou_velocity`).

**Residual** — the filtered white noise of Rezaeian & Der Kiureghian [4]_
(:func:`rezaeian_residual`): unit-variance white noise through a linear filter
whose frequency varies in time (ω_mid, ω', ζ_f), normalised to unit variance,
times a gamma-shaped modulating function q(t) (set by the Arias intensity Ia,
the significant duration D5-95 and the time t_mid of 45 % of Ia), then
high-pass filtered by a critically damped oscillator (corner 0.2 Hz in [4]_,
max(0.2 Hz, 1/Tp) here, see below) so that the residual's velocity and
displacement return to zero.

**Matching the workbook** (:func:`simulate_near_fault_motion`):

* the pulse's peak velocity (its value where |v_p| is largest) equals vp, sign
  included: the paper's Table 3 prints vp negative, a pulse whose largest lobe
  is negative. Vp of the equation is set to make this so (for ν = 0 and
  γ = 2, Vp = vp exactly); the sign convention is that of
  :mod:`assess.hazard.pulse_identification`;
* PTA is met by the residual's intensity: the residual is scaled by the one
  factor c ≥ 0 that makes max|pulse + c·residual| = PTA (a root of a convex
  function of c, unique when the pulse alone stays below PTA). The pulse is
  not scaled, so **both PTA and vp hold**: PTA exactly (a last factor of
  1 ± 1e-12 removes the root finder's tolerance; it changes vp by the same,
  negligible, factor) and vp exactly for the pulse. The velocity of the whole
  motion is the pulse's plus the residual's, so its peak differs from |vp| by
  the residual's velocity near the pulse peak: for the four motions of the
  paper's Table 3, 8 realisations each, the velocity low-passed at 2/Tp
  peaks at 0.81-1.06 |vp| and the raw PGV is 0.86-1.22 |vp| (tests);
* where the pulse alone already exceeds PTA (PTA < about 0.9 · 2π|vp|/Tp,
  depending on γ and ν), Tp, vp and PTA cannot all hold with this pulse
  shape: the residual is kept at ``RESIDUAL_SHARE_WHEN_PULSE_EXCEEDS_PTA`` of
  the pulse's peak acceleration and the sum is scaled down to PTA, which
  scales the pulse's vp by the same factor (below 1). A warning gives the vp
  reached.

Parameter choices
-----------------
We have no magnitude, distance or site class, so the residual's parameters are
not predicted from the model's regressions ([1]_ eq. 12, as [7]_ cites it) but fixed to values
typical of the model's data sets, or tied to Tp. Every one can be overridden.

=====================  ========================  =========================================
parameter              default                   source / reason
=====================  ========================  =========================================
γ (pulse)              2.3                       mean of the marginal distribution of γ
                                                 of [1]_ as SimCenter's ``smelt`` [7]_
                                                 transcribes it: 2 + 1.2·Beta(1.303,
                                                 3.969), on [2, 3.2] (mean 2.297,
                                                 median 2.257)
ν (pulse)              uniform on [0, 2π), one   the marginal of ν in ``smelt`` [7]_
                       draw per realisation      (uniform on [0, 2π))
t_peak (pulse)         t_mid of the residual,    the pulse arrives with the strong
                       at least γTp/2            shaking: in the correlation matrix of
                                                 [7]_, t_max,p correlates 0.73 and 0.79
                                                 with the residual's D0-5 and D0-30;
                                                 γTp/2 makes the pulse start at t ≥ 0
D5-95 (residual)       max(10 s, 2γTp)           10 s lies between the median D5-95 of
                                                 Bommer et al. [6]_ for M 6.5 (9.8 s) and
                                                 M 6.9 (12.4 s) at Rrup = 5 km, Vs30 =
                                                 400 m/s; 2γTp keeps the pulse (γTp long)
                                                 inside the strong phase for long pulses
t_mid (residual)       0.45 · D5-95              makes q(t) ∝ t·exp(−α3 t) (α2 = 2): the
                                                 envelope rises from t = 0, as a
                                                 synthetic motion needs no pre-event lead
ω_mid/2π               5.0 Hz                    round value near the sample mean of [5]_
ω'/2π                  −0.1 Hz/s                 round value near the sample mean of [5]_
ζ_f                    0.2                       round value near the sample mean of [5]_
filter frequency       ≥ 0.3 Hz                  floor of the ``smelt`` implementation
                                                 [7]_, keeps ω_f > 0 late in long records
high-pass corner       max(0.2 Hz, 1/Tp)         0.2 Hz is the oscillator of [4]_; see below
Ia (residual)          set by PTA                see "Matching the workbook"
=====================  ========================  =========================================

The residual's high-pass corner is raised to fp = 1/Tp for pulses shorter
than 5 s. The filter of [4]_ passes white noise unattenuated below ω_f, so
with a 0.2 Hz corner the residual keeps a flat acceleration spectrum from
0.2 Hz up: scaled to fill PTA, its own PGV was 0.16-0.80 m/s for the four
motions of the paper's Table 3 (8 realisations each), as large as the pulse's
vp. For Corralitos (Tp 0.6 s, vp −61 cm/s, PTA 0.84 g) the pulse identifier
(:mod:`assess.hazard.pulse_identification`) then found Tp up to 6 times too
long in 2 of 8 realisations, with fits explaining 26-76 % of the velocity
energy: the synthetic motions no longer had the workbook's Tp. With the
corner at fp the residual's PGV is 0.08-0.44 m/s and the identified Tp is
within 5 % (tests). In [1]_ the residual is the record minus its pulse, so
the pulse carries the motion's content at and below fp; a corner at fp keeps
it so (``high_pass_hz=0.2`` restores [4]_).

The sample means of [5]_ quoted for ω_mid, ω' and ζ_f (about 5.9 Hz,
−0.09 Hz/s and 0.21, for far-field NGA records) are recalled from the paper's
table, not re-read for this module.

Simplifications against [1]_
----------------------------
* [1]_ modulate the residual with a piecewise power/exponential function
  fitted to D0-5, D0-30 and D5-95, take the filter's reference time at 30 %
  of Ia and high-pass the residual with an acausal Butterworth filter whose
  corner depends on magnitude; here the residual is that of [4]_ as it stands
  (gamma modulating function, reference time t_mid at 45 % of Ia,
  critically damped oscillator), with the corner raised to 1/Tp (above).
* The model's parameters are random in [1]_ [2]_ (drawn from joint
  distributions conditioned on the earthquake); here only ν and the white
  noise vary between realisations, so the realisations show the residual's
  and the phase's variability, not the variability of Tp, vp or durations.
* The fault-normal component only: no second, orthogonal component [2]_.

References
----------
.. [1] Dabaghi, M., Der Kiureghian, A. (2017). Stochastic model for simulation
   of near-fault ground motions. Earthquake Eng. Struct. Dyn. 46(6):963-984.
   doi:10.1002/eqe.2839
.. [2] Dabaghi, M., Der Kiureghian, A. (2018). Simulation of orthogonal
   horizontal components of near-fault ground motion for specified earthquake
   source and site characteristics. Earthquake Eng. Struct. Dyn.
   47(6):1369-1393. doi:10.1002/eqe.3021
.. [3] Mavroeidis, G. P., Papageorgiou, A. S. (2003). A mathematical
   representation of near-fault ground motions. Bull. Seismol. Soc. Am.
   93(3):1099-1131. doi:10.1785/0120020100
.. [4] Rezaeian, S., Der Kiureghian, A. (2008). A stochastic ground motion
   model with separable temporal and spectral nonstationarities. Earthquake
   Eng. Struct. Dyn. 37:1565-1584. doi:10.1002/eqe.831
.. [5] Rezaeian, S., Der Kiureghian, A. (2010). Simulation of synthetic ground
   motions for specified earthquake and site characteristics. Earthquake Eng.
   Struct. Dyn. 39:1155-1180. doi:10.1002/eqe.997
.. [6] Bommer, J. J., Stafford, P. J., Alarcón, J. E. (2009). Empirical
   equations for the prediction of the significant, bracketed, and uniform
   duration of earthquake ground motion. Bull. Seismol. Soc. Am.
   99(6):3217-3233. doi:10.1785/0120080298
.. [7] NHERI SimCenter, smelt (stochastic, modular, and extensible library for
   time histories), ``src/dabaghi_der_kiureghian.cc``,
   https://github.com/NHERI-SimCenter/smelt
"""
from __future__ import annotations

import functools
import warnings
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
from numba import njit
from scipy import optimize, signal, special

from assess.hazard.near_fault_pulse import (  # noqa: F401 - part of this module's API
    _pulse_window, mavroeidis_papageorgiou_acceleration, mavroeidis_papageorgiou_residual_displacement,
    mavroeidis_papageorgiou_velocity, modified_mavroeidis_papageorgiou_acceleration,
    modified_mavroeidis_papageorgiou_velocity, pulse_peak_factor, type_b_reading,
)
from assess.hazard.processing import arias_intensity_m_s
from assess.hazard.records import Record
from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2

#: Envelope parameter γ of the pulse (mean of [1]'s fitted distribution, see the module docstring).
DEFAULT_PULSE_GAMMA = 2.3
#: Shortest residual significant duration D5-95 [s] (Bommer et al. 2009, M 6.5-6.9, Rrup 5 km).
DEFAULT_MIN_D5_95_S = 10.0
#: D5-95 is at least this many pulse windows (γTp): the pulse stays inside the strong phase.
D5_95_PER_PULSE_WINDOW = 2.0
#: t_mid / D5-95 of the residual: q(t) ∝ t·exp(−α3 t) (α2 = 2).
DEFAULT_T_MID_OVER_D5_95 = 0.45
#: Residual filter frequency at t_mid [Hz], its slope [Hz/s] and damping ratio (Rezaeian & Der Kiureghian 2010).
DEFAULT_FILTER_FREQUENCY_HZ = 5.0
DEFAULT_FILTER_SLOPE_HZ_S = -0.1
DEFAULT_FILTER_DAMPING = 0.2
#: Lowest filter frequency [Hz] (floor of the smelt implementation of Dabaghi & Der Kiureghian).
MINIMUM_FILTER_FREQUENCY_HZ = 0.3
#: Corner of the critically damped high-pass oscillator [Hz] (Rezaeian & Der Kiureghian 2008).
DEFAULT_HIGH_PASS_HZ = 0.2
#: Where the pulse alone exceeds PTA, the residual's peak kept, as a share of the pulse's peak acceleration.
RESIDUAL_SHARE_WHEN_PULSE_EXCEEDS_PTA = 0.25
#: Quiet time after the residual [in units of 1/ωc of the high-pass]: (1 + 10) e^-10 = 5e-4.
_SETTLE_TIME_CONSTANTS = 10.0
#: Impulse responses are cut after this many decay times 1/(ζ ω): the neglected share of h² is e^-24.
_FILTER_MEMORY_DECAY_TIMES = 12.0
MODEL_LABEL = "Dabaghi & Der Kiureghian 2017"


# --------------------------------------------------------------------------- residual


class ModulatingParameters(NamedTuple):
    """Parameters of q(t) = α1 t^(α2−1) exp(−α3 t): α1 [m/s^(α2+1)], α2 [-], α3 [1/s]."""

    alpha1: float
    alpha2: float
    alpha3: float


def gamma_modulating_function(time_s, parameters: ModulatingParameters):
    """Gamma modulating function of Rezaeian & Der Kiureghian (2008) [m/s²]:

    .. math:: q(t) = \\alpha_1 t^{\\alpha_2 - 1} e^{-\\alpha_3 t}, \\qquad t \\ge 0.

    Examples
    --------
    >>> p = ModulatingParameters(1.0, 2.0, 0.5)
    >>> round(float(gamma_modulating_function(2.0, p)), 6)  # 2 e^-1
    0.735759
    """
    time_s = np.asarray(time_s, dtype=float)
    alpha1, alpha2, alpha3 = parameters
    positive = time_s > 0.0
    safe = np.where(positive, time_s, 1.0)
    log_q = np.log(alpha1) + (alpha2 - 1.0) * np.log(safe) - alpha3 * safe
    return np.where(positive, np.exp(log_q), 0.0)


def gamma_modulating_parameters(arias_intensity_m_s, d5_95_s, t_mid_s) -> ModulatingParameters:
    """(α1, α2, α3) of q(t) from the expected Arias intensity, D5-95 and t_mid.

    The process is q(t) times a unit-variance process, so its expected
    cumulative Arias intensity is (π/2g)∫q² dt, and q² ∝ t^(2α2−2) e^(−2α3 t)
    is a gamma density of shape k = 2α2 − 1 and rate 2α3. With G_k⁻¹ the
    gamma quantile function of shape k (unit rate):

    .. math::

        \\frac{D_{5-95}}{t_{mid}} = \\frac{G_k^{-1}(0.95) - G_k^{-1}(0.05)}{G_k^{-1}(0.45)}, \\quad
        2\\alpha_3 = \\frac{G_k^{-1}(0.45)}{t_{mid}}, \\quad
        I_a = \\frac{\\pi}{2g}\\,\\alpha_1^2\\,\\frac{\\Gamma(k)}{(2\\alpha_3)^k}.

    The first equation fixes k (the ratio falls from 4.925 at k = 1 towards 0),
    the others α3 and α1. t_mid is the time of 45 % of Ia, as in [1]_.

    Parameters
    ----------
    arias_intensity_m_s : float
        Expected Arias intensity Ia = (π/2g)∫a² dt [m/s].
    d5_95_s : float
        Significant duration, from 5 % to 95 % of Ia [s].
    t_mid_s : float
        Time of 45 % of Ia [s].

    Raises
    ------
    ValueError
        D5-95/t_mid ≥ 4.925: no gamma function with α2 > 1 has it.

    References
    ----------
    .. [1] Rezaeian & Der Kiureghian (2008), doi:10.1002/eqe.831.

    Examples
    --------
    D5-95 = 0.45⁻¹ t_mid gives α2 ≈ 2 (q ∝ t e^(−α3 t)):

    >>> p = gamma_modulating_parameters(1.0, 10.0, 4.52)
    >>> round(p.alpha2, 2)
    2.0
    """
    if not (arias_intensity_m_s > 0.0 and d5_95_s > 0.0 and t_mid_s > 0.0):
        raise ValueError("Ia, D5-95 and t_mid must be positive, got "
                         f"{arias_intensity_m_s!r}, {d5_95_s!r}, {t_mid_s!r}")
    ratio = d5_95_s / t_mid_s

    def excess(log_k):
        k = np.exp(log_k)
        return (special.gammaincinv(k, 0.95) - special.gammaincinv(k, 0.05)) / special.gammaincinv(k, 0.45) - ratio

    low, high = 0.0, np.log(1e6)  # shape k from 1 (α2 = 1) to 1e6
    if not excess(low) > 0.0 > excess(high):
        raise ValueError(f"D5-95/t_mid = {ratio:.3g} has no gamma modulating function with α2 > 1 "
                         "(the ratio must lie between 0.0033 and 4.925): change t_mid or D5-95.")
    k = float(np.exp(optimize.brentq(excess, low, high, xtol=1e-14, rtol=1e-14)))
    rate = float(special.gammaincinv(k, 0.45)) / t_mid_s  # 2 α3
    log_alpha1 = 0.5 * (np.log(2.0 * STANDARD_GRAVITY_M_S2 * arias_intensity_m_s / np.pi)
                        + k * np.log(rate) - special.gammaln(k))
    return ModulatingParameters(float(np.exp(log_alpha1)), 0.5 * (k + 1.0), 0.5 * rate)


def filter_frequency_hz(time_s, f_mid_hz, f_slope_hz_s, t_mid_s, minimum_hz=MINIMUM_FILTER_FREQUENCY_HZ):
    """Frequency [Hz] of the residual's filter at time τ [1]_, floored at ``minimum_hz``:

    .. math:: \\omega_f(\\tau)/2\\pi = f_{mid} + f'\\,(\\tau - t_{mid}).

    Examples
    --------
    >>> [float(f) for f in filter_frequency_hz([0.0, 4.5, 60.0], 5.0, -0.1, 4.5)]
    [5.45, 5.0, 0.3]
    """
    frequency = f_mid_hz + f_slope_hz_s * (np.asarray(time_s, dtype=float) - t_mid_s)
    return np.maximum(frequency, minimum_hz)


def critically_damped_high_pass(accel, dt_s, corner_hz=DEFAULT_HIGH_PASS_HZ):
    """High-pass a record with a critically damped oscillator (Rezaeian & Der Kiureghian 2008).

    The record x(t) drives ü + 2ωc u̇ + ωc² u = x(t) from rest, ωc = 2π·corner;
    the filtered record is ü = x − 2ωc u̇ − ωc² u, whose integrals are u̇ and
    u: the oscillator's velocity and displacement, which return to zero once
    it comes to rest after the record. Transfer function s²/(s + ωc)², solved
    exactly for a record linear between samples (first-order hold), the input
    being zero before the first sample.

    Examples
    --------
    A step of 1 is removed once the oscillator settles, (1 − ωc t) e^(−ωc t),
    leaving no velocity (∫ü dt = u̇ → 0):

    >>> a = critically_damped_high_pass(np.r_[0.0, np.ones(4000)], 0.005, 0.2)
    >>> abs(float(a[-1])) < 1e-9, abs(float(np.sum(a) * 0.005)) < 1e-6
    (True, True)
    """
    numerator, denominator = _high_pass_coefficients(float(dt_s), float(corner_hz))
    return signal.lfilter(numerator, denominator, np.asarray(accel, dtype=float))


@functools.lru_cache(maxsize=64)
def _high_pass_coefficients(dt_s, corner_hz):
    """The oscillator s²/(s + ωc)² discretised with a first-order hold (computed once per dt and corner)."""
    omega = 2.0 * np.pi * corner_hz
    numerator, denominator, _ = signal.cont2discrete(([1.0, 0.0, 0.0], [1.0, 2.0 * omega, omega * omega]),
                                                     dt_s, method="foh")
    return np.ravel(numerator), np.asarray(denominator)


def rezaeian_residual(n_samples, dt_s, arias_intensity_m_s, d5_95_s, t_mid_s, rng, *,
                      f_mid_hz=DEFAULT_FILTER_FREQUENCY_HZ, f_slope_hz_s=DEFAULT_FILTER_SLOPE_HZ_S,
                      zeta=DEFAULT_FILTER_DAMPING, high_pass_hz=DEFAULT_HIGH_PASS_HZ):
    """One realisation of the Rezaeian & Der Kiureghian (2008) ground motion [m/s²].

    With u_i independent standard normal variables at t_i = i·dt and the
    impulse response of an oscillator of frequency ω_f(τ)
    (:func:`filter_frequency_hz`) and damping ζ_f,

    .. math::

        h(t - \\tau; \\tau) = \\frac{\\omega_f(\\tau)}{\\sqrt{1 - \\zeta_f^2}}
            e^{-\\zeta_f \\omega_f(\\tau)(t - \\tau)}
            \\sin\\left[\\omega_f(\\tau)\\sqrt{1 - \\zeta_f^2}(t - \\tau)\\right],

    the process is (discretised form of [1]_)

    .. math::

        \\hat x(t) = q(t)\\,\\frac{\\sum_{t_i \\le t} h(t - t_i; t_i)\\,u_i}
                                {\\sqrt{\\sum_{t_i \\le t} h^2(t - t_i; t_i)}},

    unit-variance filtered noise modulated by q(t)
    (:func:`gamma_modulating_parameters`), then high-passed by
    :func:`critically_damped_high_pass`. Impulse responses are cut after 12
    decay times 1/(ζ_f ω_f(t_i)) of their own frequency (the neglected share of
    h² is e⁻²⁴), computed by :func:`_filtered_noise_sums`.

    The expected Arias intensity before the high-pass is Ia; the high-pass
    removes the energy below its corner, as in [1]_ (measured for Ia 1 m/s,
    D5-95 10 s, t_mid 4.5 s and the default filter: 2 % at 0.2 Hz, 7 % at
    0.5 Hz, 17 % at 1 Hz).

    Parameters
    ----------
    n_samples : int
        Samples, at t = 0, dt, ...
    dt_s : float
        Step [s].
    arias_intensity_m_s, d5_95_s, t_mid_s : float
        Modulating function's parameters (see :func:`gamma_modulating_parameters`).
    rng : numpy.random.Generator
        Source of the white noise (n_samples normal draws).
    f_mid_hz, f_slope_hz_s, zeta : float
        Filter frequency at t_mid [Hz], its rate of change [Hz/s], damping ratio.
    high_pass_hz : float or None
        Corner of the high-pass oscillator [Hz]; None leaves it out.

    References
    ----------
    .. [1] Rezaeian & Der Kiureghian (2008), doi:10.1002/eqe.831.
    """
    if not 0.0 < zeta < 1.0:
        raise ValueError(f"the filter's damping ratio must be in (0, 1), got {zeta!r}")
    n = int(n_samples)
    time_s = np.arange(n) * dt_s
    omega = 2.0 * np.pi * filter_frequency_hz(time_s, f_mid_hz, f_slope_hz_s, t_mid_s)
    noise = rng.standard_normal(n)
    numerator, energy = _filtered_noise_sums(omega, noise, float(zeta), float(dt_s), _FILTER_MEMORY_DECAY_TIMES)
    unit = np.divide(numerator, np.sqrt(energy), out=np.zeros(n), where=energy > 0.0)
    accel = gamma_modulating_function(time_s, gamma_modulating_parameters(
        arias_intensity_m_s, d5_95_s, t_mid_s)) * unit
    if high_pass_hz is not None:
        accel = critically_damped_high_pass(accel, dt_s, high_pass_hz)
    return accel


@njit(cache=True, nogil=True)
def _filtered_noise_sums(omega, noise, zeta, dt_s, memory_decay_times):
    """Σ h(t − t_i; t_i) u_i and Σ h²(t − t_i; t_i) at every sample (see :func:`rezaeian_residual`).

    Each impulse response is followed from its source for
    ``memory_decay_times`` decay times 1/(ζ ω(t_i)) of its own frequency; its
    damped sine is stepped by the exact rotation e^{(−ζω + iω_d)Δt}, so a
    sample costs one complex product instead of an exponential and a sine.

    The sums are gathered sample by sample: every source still ringing at
    sample j steps its own rotation once and adds to j's two sums, in the
    order of the sources. The rotations of different sources do not wait on
    one another (only the sums do), which makes this about 1.8 times faster
    than following one source to its end before the next, and it adds the
    same terms in the same order, so the sums are the same to the last bit
    (tests/hazard/test_synthesis_kernel.py).
    """
    n = omega.size
    numerator = np.zeros(n)
    energy = np.zeros(n)
    root = np.sqrt(1.0 - zeta * zeta)
    end = np.empty(n, np.int64)  # source i rings at samples i+1 … end[i]-1
    c_re, c_im, gain = np.empty(n), np.empty(n), np.empty(n)
    for i in range(n):
        w = omega[i]
        end[i] = i + min(n - i, int(np.ceil(memory_decay_times / (zeta * w * dt_s))) + 1)
        decay = np.exp(-zeta * w * dt_s)
        c_re[i], c_im[i] = decay * np.cos(w * root * dt_s), decay * np.sin(w * root * dt_s)
        gain[i] = w / root
    z_re, z_im = np.ones(n), np.zeros(n)  # e^{(−ζω + iω_d)(t_j − t_i)} of each source, h(0) = 0
    first = 0  # the sources before it have ended
    for j in range(1, n):
        while end[first] <= j:
            first += 1
        total, squares = 0.0, 0.0
        for i in range(first, j):
            if j < end[i]:
                re = z_re[i] * c_re[i] - z_im[i] * c_im[i]
                im = z_re[i] * c_im[i] + z_im[i] * c_re[i]
                z_re[i], z_im[i] = re, im
                h = gain[i] * im
                total += h * noise[i]
                squares += h * h
        numerator[j], energy[j] = total, squares
    return numerator, energy


# --------------------------------------------------------------------------- synthesis


@dataclass(frozen=True)
class SyntheticMotion:
    """One synthetic near-fault motion and its parts.

    Attributes
    ----------
    accel_g : ndarray
        Acceleration [g], pulse plus residual, at 0, dt, ...; max |accel_g| = PTA.
    dt_s : float
        Step [s].
    pulse_accel_g, residual_accel_g : ndarray
        The two parts as they enter ``accel_g`` [g] (their sum is ``accel_g``).
    pulse_vp_m_s : float
        Signed peak velocity of the pulse as included [m/s]: the asked vp,
        unless the pulse alone exceeded PTA.
    pulse_gamma, pulse_nu_rad, pulse_t_peak_s, tp_s : float
        The pulse's γ, ν [rad], envelope centre [s] and period [s].
    residual_arias_m_s : float
        Arias intensity of the residual as included [m/s].
    residual_d5_95_s, residual_t_mid_s : float
        The modulating function's D5-95 and t_mid [s].
    high_pass_hz : float
        Corner of the residual's high-pass oscillator [Hz].
    """

    accel_g: np.ndarray
    dt_s: float
    pulse_accel_g: np.ndarray
    residual_accel_g: np.ndarray
    pulse_vp_m_s: float
    pulse_gamma: float
    pulse_nu_rad: float
    pulse_t_peak_s: float
    tp_s: float
    residual_arias_m_s: float
    residual_d5_95_s: float
    residual_t_mid_s: float
    high_pass_hz: float


def default_d5_95_s(tp_s, gamma=DEFAULT_PULSE_GAMMA):
    """Default significant duration of the residual [s]: max(10 s, 2γTp).

    >>> default_d5_95_s(2.1), round(default_d5_95_s(4.0), 6)
    (10.0, 18.4)
    """
    return float(max(DEFAULT_MIN_D5_95_S, D5_95_PER_PULSE_WINDOW * gamma * tp_s))


def _check_inputs(pta_g, tp_s, vp_m_s, dt_s, gamma):
    for name, value in (("pta_g", pta_g), ("tp_s", tp_s), ("dt_s", dt_s)):
        if not (np.isfinite(value) and value > 0.0):
            raise ValueError(f"{name} must be positive, got {value!r}")
    if not (np.isfinite(vp_m_s) and vp_m_s != 0.0):
        raise ValueError(f"vp_m_s must be a non-zero velocity, got {vp_m_s!r}")
    if not (np.isfinite(gamma) and gamma > 1.0):
        raise ValueError(f"pulse_gamma must be larger than 1, got {gamma!r}")
    if dt_s > tp_s / 20.0:
        raise ValueError(f"dt_s = {dt_s:g} s is too coarse for a pulse of Tp = {tp_s:g} s: "
                         "give at most Tp/20.")


def _residual_scale(pulse, residual, target):
    """c ≥ 0 with max|pulse + c·residual| = target (pulse alone below target)."""
    def excess(c):
        return float(np.max(np.abs(pulse + c * residual))) - target
    upper = (target + float(np.max(np.abs(pulse)))) / float(np.max(np.abs(residual)))
    return optimize.brentq(excess, 0.0, upper, xtol=1e-15, rtol=1e-14)


def end_velocity_displacement(accel, dt_s):
    """Velocity and displacement at the last sample of a record taken linear between samples.

    Exact integrals from rest of the piecewise-linear acceleration the
    mechanics engine reads (units of ``accel`` times s and s²):

    .. math::

        v_n = \\sum_k \\frac{a_{k-1} + a_k}{2}\\,\\Delta t, \\qquad
        u_n = \\sum_k \\left[v_{k-1}\\Delta t + \\frac{2a_{k-1} + a_k}{6}\\,\\Delta t^2\\right].

    Examples
    --------
    A ramp from 0 to 1 over 1 s, then 1 for 1 s: v = 1/2 + 1, u = 1/6 + (1/2 + 1/2):

    >>> [round(x, 6) for x in end_velocity_displacement(np.array([0.0, 1.0, 1.0]), 1.0)]
    [1.5, 1.166667]
    """
    a = np.asarray(accel, dtype=float)
    velocity = np.concatenate(([0.0], np.cumsum(0.5 * (a[:-1] + a[1:]) * dt_s)))
    displacement = float(np.sum(velocity[:-1] * dt_s + (2.0 * a[:-1] + a[1:]) * dt_s * dt_s / 6.0))
    return float(velocity[-1]), displacement


def _sampled_pulse(time_s, dt_s, amplitude, tp_s, gamma, nu, t_peak_s):
    """The modified MP acceleration at the samples, corrected to end at rest where it started.

    The analytic pulse ends at rest at its start; sampled and taken linear
    between samples it keeps a velocity of order 1e-5 m/s (Tp 0.6 s, dt 5 ms).
    Two smooth shapes of the window, (1 + cos θ/γ) and sin(θ/γ)(1 + cos θ/γ),
    are subtracted in the amounts that make the final velocity and
    displacement (:func:`end_velocity_displacement`) zero.
    """
    pulse = modified_mavroeidis_papageorgiou_acceleration(time_s, amplitude, tp_s, gamma, nu, t_peak_s)
    theta, inside = _pulse_window(time_s, tp_s, gamma, t_peak_s)
    bell = np.where(inside, 1.0 + np.cos(theta / gamma), 0.0)
    shapes = (bell, bell * np.sin(theta / gamma))
    matrix = np.array([end_velocity_displacement(shape, dt_s) for shape in shapes]).T
    amounts = np.linalg.solve(matrix, np.array(end_velocity_displacement(pulse, dt_s)))
    return pulse - amounts[0] * shapes[0] - amounts[1] * shapes[1]


def default_high_pass_hz(tp_s):
    """Default corner of the residual's high-pass oscillator [Hz]: max(0.2 Hz, 1/Tp).

    >>> default_high_pass_hz(2.0), default_high_pass_hz(8.0)
    (0.5, 0.2)
    """
    return float(max(DEFAULT_HIGH_PASS_HZ, 1.0 / tp_s))


def _end_taper(time_s, end_s, length_s):
    """1 until end − length, a half-cosine down to 0 at end, 0 after."""
    x = np.clip((np.asarray(time_s) - (end_s - length_s)) / length_s, 0.0, 1.0)
    return 0.5 * (1.0 + np.cos(np.pi * x))


def simulate_near_fault_motion(pta_g, tp_s, vp_m_s, rng, *, dt_s=0.005, duration_s=None,
                               pulse_gamma=DEFAULT_PULSE_GAMMA, pulse_nu_rad=None, pulse_t_peak_s=None,
                               residual_d5_95_s=None, residual_t_mid_s=None,
                               residual_f_mid_hz=DEFAULT_FILTER_FREQUENCY_HZ,
                               residual_f_slope_hz_s=DEFAULT_FILTER_SLOPE_HZ_S,
                               residual_zeta=DEFAULT_FILTER_DAMPING,
                               high_pass_hz=None, vp_reading="type-b") -> SyntheticMotion:
    """One realisation of a near-fault motion with peak acceleration PTA and pulse (Tp, vp).

    See the module docstring for the model, the defaults and how PTA and vp
    are both met. Draws from ``rng``: ν (when ``pulse_nu_rad`` is None, one
    uniform draw), then the residual's white noise.

    The residual's modulating function is tapered to zero by a half-cosine
    between the times of 99 % and 99.95 % of its expected Arias intensity
    (or over the same length before the record's end, if that comes first),
    and the record goes on, quiet, for 10/ωc of the high-pass oscillator: the
    oscillator's velocity and displacement, which are the residual's, then
    decay to about 5e-4 of what they were, and the motion ends at rest near
    where it started.

    Parameters
    ----------
    pta_g : float
        Peak absolute acceleration of the motion [g].
    tp_s : float
        Pulse period Tp [s].
    vp_m_s : float
        Signed peak velocity of the pulse [m/s] (Table 3 prints it negative).
    rng : numpy.random.Generator
        Source of randomness.
    dt_s : float
        Step [s], at most Tp/20.
    duration_s : float or None
        Length of the record [s]; default: until the taper's end or the
        pulse's end, whichever is later, plus the quiet 10/ωc.
    pulse_gamma, pulse_nu_rad, pulse_t_peak_s : float
        γ, ν [rad] (None: uniform on [0, 2π)) and envelope centre [s] (None:
        the residual's t_mid, at least γTp/2).
    residual_d5_95_s, residual_t_mid_s : float or None
        Residual's significant duration and time of 45 % of Ia [s] (None:
        :func:`default_d5_95_s`, and 0.45 · D5-95).
    residual_f_mid_hz, residual_f_slope_hz_s, residual_zeta : float
        Residual filter (see :func:`rezaeian_residual`).
    high_pass_hz : float or None
        Corner of the residual's high-pass oscillator [Hz]; None:
        :func:`default_high_pass_hz`.
    """
    _check_inputs(pta_g, tp_s, vp_m_s, dt_s, pulse_gamma)
    d5_95 = default_d5_95_s(tp_s, pulse_gamma) if residual_d5_95_s is None else float(residual_d5_95_s)
    t_mid = DEFAULT_T_MID_OVER_D5_95 * d5_95 if residual_t_mid_s is None else float(residual_t_mid_s)
    corner_hz = default_high_pass_hz(tp_s) if high_pass_hz is None else float(high_pass_hz)
    nu = float(rng.uniform(0.0, 2.0 * np.pi)) if pulse_nu_rad is None else float(pulse_nu_rad)
    if vp_reading == "type-b":
        vp_ratio, tp_ratio = type_b_reading(pulse_gamma, nu)
    elif vp_reading == "peak":
        vp_ratio, tp_ratio = 1.0, 1.0
    else:
        raise ValueError(f"vp_reading must be 'type-b' or 'peak', got {vp_reading!r}")
    pulse_tp_s, pulse_peak_m_s = tp_s / tp_ratio, vp_m_s / vp_ratio
    half_window = 0.5 * pulse_gamma * pulse_tp_s
    t_peak = max(t_mid, half_window) if pulse_t_peak_s is None else float(pulse_t_peak_s)
    if t_peak < half_window:
        raise ValueError(f"pulse_t_peak_s = {t_peak:g} s starts the pulse before t = 0: give at least "
                         f"γTp/2 = {half_window:g} s.")
    pulse_end = t_peak + half_window

    modulating = gamma_modulating_parameters(1.0, d5_95, t_mid)
    k, rate = 2.0 * modulating.alpha2 - 1.0, 2.0 * modulating.alpha3
    taper_start, taper_end = (float(special.gammaincinv(k, p)) / rate for p in (0.99, 0.9995))
    taper_length = taper_end - taper_start
    settle = _SETTLE_TIME_CONSTANTS / (2.0 * np.pi * corner_hz)
    if duration_s is None:
        duration_s = max(taper_end, pulse_end) + settle
    if duration_s < pulse_end:
        raise ValueError(f"duration_s = {duration_s:g} s ends before the pulse does ({pulse_end:g} s).")
    n = int(np.floor(duration_s / dt_s + 1e-9)) + 1
    time_s = np.arange(n) * dt_s
    taper_end = min(taper_end, time_s[-1])

    amplitude = pulse_peak_m_s / pulse_peak_factor(pulse_gamma, nu)
    pulse = _sampled_pulse(time_s, dt_s, amplitude, pulse_tp_s, pulse_gamma, nu, t_peak)
    residual = rezaeian_residual(n, dt_s, 1.0, d5_95, t_mid, rng, f_mid_hz=residual_f_mid_hz,
                                 f_slope_hz_s=residual_f_slope_hz_s, zeta=residual_zeta, high_pass_hz=None)
    residual = critically_damped_high_pass(
        residual * _end_taper(time_s, taper_end, taper_length), dt_s, corner_hz)

    target = pta_g * STANDARD_GRAVITY_M_S2
    pulse_peak = float(np.max(np.abs(pulse)))
    if pulse_peak < target:
        c = _residual_scale(pulse, residual, target)
    else:
        c = RESIDUAL_SHARE_WHEN_PULSE_EXCEEDS_PTA * pulse_peak / float(np.max(np.abs(residual)))
    total_g = (pulse + c * residual) / STANDARD_GRAVITY_M_S2
    factor = pta_g / float(np.max(np.abs(total_g)))
    if pulse_peak >= target:
        warnings.warn(f"a pulse of Tp {tp_s:g} s and vp {vp_m_s * 100:g} cm/s alone reaches "
                      f"{pulse_peak / STANDARD_GRAVITY_M_S2:.3g} g, more than PTA {pta_g:g} g: the motion "
                      f"is scaled to PTA and its pulse's vp becomes {vp_m_s * factor * 100:.3g} cm/s.",
                      stacklevel=2)
    return SyntheticMotion(
        accel_g=total_g * factor, dt_s=float(dt_s),
        pulse_accel_g=pulse / STANDARD_GRAVITY_M_S2 * factor,
        residual_accel_g=c * residual / STANDARD_GRAVITY_M_S2 * factor,
        pulse_vp_m_s=float(pulse_peak_m_s * factor), pulse_gamma=float(pulse_gamma), pulse_nu_rad=nu,
        pulse_t_peak_s=float(t_peak), tp_s=float(pulse_tp_s),
        residual_arias_m_s=arias_intensity_m_s(c * factor * residual / STANDARD_GRAVITY_M_S2, dt_s),
        residual_d5_95_s=d5_95, residual_t_mid_s=t_mid, high_pass_hz=corner_hz)


def _realization_generators(seed, n):
    """Independent generators, one per realisation; realisation i does not depend on n."""
    if isinstance(seed, np.random.Generator):
        return [np.random.default_rng(s) for s in seed.integers(0, 2**63, size=n)]
    return [np.random.default_rng(s) for s in np.random.SeedSequence(seed).spawn(n)]


def synthesize_motion(pta_g, tp_s, vp_m_s, *, n_realizations=5, seed=0, dt_s=0.005, duration_s=None,
                      pulse_gamma=DEFAULT_PULSE_GAMMA, pulse_nu_rad=None, pulse_t_peak_s=None,
                      residual_d5_95_s=None, residual_t_mid_s=None,
                      residual_f_mid_hz=DEFAULT_FILTER_FREQUENCY_HZ,
                      residual_f_slope_hz_s=DEFAULT_FILTER_SLOPE_HZ_S,
                      residual_zeta=DEFAULT_FILTER_DAMPING,
                      high_pass_hz=None, vp_reading="type-b") -> list[Record]:
    """Synthetic acceleration histories of a motion given by PTA [g], Tp [s] and vp [m/s].

    Each :class:`~assess.hazard.records.Record` is a pulse (modified
    Mavroeidis-Papageorgiou, peak velocity vp, period Tp) plus a stochastic
    residual (Rezaeian & Der Kiureghian) whose intensity makes the peak
    absolute acceleration exactly PTA (module docstring: "Matching the
    workbook"; the final scaling to PTA changes the pulse's vp by the same
    factor, 1 ± 1e-12, except where the pulse alone exceeds PTA, which warns).

    ``seed`` is an integer (the same seed gives the same records bit for bit;
    realisation i is the same whatever ``n_realizations``) or a
    :class:`numpy.random.Generator` (drawn from: one integer per realisation).
    Other arguments: :func:`simulate_near_fault_motion`.

    Examples
    --------
    >>> records = synthesize_motion(0.54, 2.1, -0.75, n_realizations=2)
    >>> [round(r.pta_g, 12) for r in records]
    [0.54, 0.54]
    >>> records[0].name
    'synthetic 1/2 (Dabaghi & Der Kiureghian 2017), PTA 0.54 g, Tp 2.1 s, vp -75 cm/s, seed 0'
    """
    n = int(n_realizations)
    if n < 1:
        raise ValueError(f"n_realizations must be at least 1, got {n_realizations!r}")
    seed_text = f"seed {seed}" if not isinstance(seed, np.random.Generator) else "seeded generator"
    records = []
    for i, rng in enumerate(_realization_generators(seed, n), start=1):
        motion = simulate_near_fault_motion(
            pta_g, tp_s, vp_m_s, rng, dt_s=dt_s, duration_s=duration_s, pulse_gamma=pulse_gamma,
            pulse_nu_rad=pulse_nu_rad, pulse_t_peak_s=pulse_t_peak_s, residual_d5_95_s=residual_d5_95_s,
            residual_t_mid_s=residual_t_mid_s, residual_f_mid_hz=residual_f_mid_hz,
            residual_f_slope_hz_s=residual_f_slope_hz_s, residual_zeta=residual_zeta,
            high_pass_hz=high_pass_hz, vp_reading=vp_reading)
        name = (f"synthetic {i}/{n} ({MODEL_LABEL}), PTA {pta_g:g} g, Tp {tp_s:g} s, "
                f"vp {vp_m_s * 100:g} cm/s, {seed_text}")
        records.append(Record(accel_g=motion.accel_g, dt_s=motion.dt_s, name=name))
    return records
