"""Predominant velocity pulse of a record: its period Tp and velocity amplitude vp.

The regression of Konstantinidis & Makris (2010) [3]_ needs, for every motion,
the period Tp of the pulse that approximates its predominant pulse (ωp = 2π/Tp
enters the EDP, eq. 8) and its velocity amplitude vp (Table 3, column 3, which
lists Type-B pulses). This module finds them by fitting closed-form pulses to
the record's **velocity** history by nonlinear least squares.

Velocity pulses fitted
----------------------
With τ = t − t0 (t0 the arrival time) and ωp = 2π/Tp, each pulse is zero
outside the interval given:

* ``"A"`` — one-sine acceleration pulse, forward displacement (Makris 1997 [1]_):

  .. math:: \\dot u_g = \\tfrac{v_p}{2}\\,[1 - \\cos(\\omega_p \\tau)], \\quad 0 \\le \\tau \\le T_p

  (the paper's u_A = vp[ωp t − sin ωp t]/(2ωp)); one velocity lobe of
  duration Tp and peak vp; acceleration amplitude ap = vp ωp / 2.
* ``"B"`` — one-cosine acceleration pulse, forward-and-back displacement ([1]_,
  the pulse of Table 3 of [3]_, u_B = vp[1 − cos ωp t]/ωp):

  .. math:: \\dot u_g = v_p \\sin(\\omega_p \\tau), \\quad 0 \\le \\tau \\le T_p

  two opposite lobes of Tp/2 each; ap = vp ωp.
* ``"C"`` — Type-C1 pulse (Makris & Chang 2000 [2]_), ü = ap cos(ωp τ + φ),
  φ = 0.2190 (:func:`~assess.hazard.pulses.type_c_phase`), ending at rest
  and at its starting position:

  .. math:: \\dot u_g = v_c\\,[\\sin(\\omega_p \\tau + \\varphi) - \\sin\\varphi],
            \\quad 0 \\le \\tau \\le (3/2 - \\varphi/\\pi)\\,T_p

  with v_c = ap/ωp; three lobes, the middle one the largest, of peak
  −v_c (1 + sin φ).
* ``"MP"`` — Mavroeidis & Papageorgiou (2003) [4]_ pulse, a harmonic under a
  bell envelope, t0 being the envelope's centre:

  .. math:: \\dot u_g = \\tfrac{A}{2}\\,[1 + \\cos(2\\pi f_p \\tau/\\gamma)]\\,
            \\cos(2\\pi f_p \\tau + \\nu), \\quad |\\tau| \\le \\gamma/(2 f_p)

  with Tp = 1/fp, 1 ≤ γ ≤ ``MP_GAMMA_MAX`` (number of half-cycles under the
  envelope ≈ 2γ) and phase ν.

Sign convention of vp
---------------------
``vp_m_s`` is the signed peak velocity of the fitted pulse, the value of
u̇ where |u̇| is largest (for Type B, whose two lobes tie, the first lobe:
exactly the vp of u̇ = vp sin ωp t). Its sign is the sign of the record as
given: flipping the record's polarity flips vp. Table 3 of [3]_ prints vp
negative (−75 cm/s for Los Gatos, −61 cm/s for Corralitos): a Type-B pulse
whose first velocity lobe is negative, which this module would report as
``pulse_type="B"``, ``vp_m_s=-0.75``. For Type A vp is the one lobe's peak;
for Type C1 it is the middle lobe's, −v_c(1 + sin φ) (as
:mod:`assess.hazard.pulses` defines vp for C1); for MP the largest extreme,
≈ ±A.

Method
------
1. Velocity: :func:`_velocity_m_s` (pre-event mean removed, trapezoidal
   integration, least-squares linear trend removed — see there).
2. Starting points, from two sources: (a) the velocity's half-cycles (lobes
   between zero crossings), the ``_START_LOBES`` with the largest peaks. A lobe
   of duration d suggests Tp ≈ d (Type A), 2d (B, either lobe), d/(1/2 + φ/π)
   (C1, middle lobe) or d/(1/2 − φ/π) (C1, outer lobes), 2d (MP, γ = 1.5
   and 2.5), each also ×0.8 and ×1.25, with the arrival placing the lobe
   where that pulse has it; (b) a scan over Tp (:func:`_scan_starts`) of each
   pulse's best arrival by cross-correlation with the velocity.
3. Every start is scored by linear least squares (amplitude and a linear
   velocity baseline a + b t solved exactly for the given Tp, t0, γ: the
   baseline makes the fit indifferent to whatever linear trend step 1
   removed); the best ``_REFINED_STARTS`` of each model are refined by
   :func:`scipy.optimize.least_squares` over (Tp, t0[, γ]) with the linear
   coefficients projected out (variable projection). For MP, ν enters
   linearly too: A cos(x + ν) = A cos ν cos x − A sin ν sin x.
4. Quality: ``fit_r2`` = 1 − Σ(u̇ − fit)² / Σu̇², the share of the velocity
   history's energy (∫u̇²dt) the pulse explains, over the whole record.
   ``residual_pgv_ratio`` = PGV of the record minus the pulse over PGV.
5. Selection: the best of A, B, C1 by ``fit_r2``; MP (five parameters against
   three) only if it explains at least ``MP_MARGIN`` more of the energy.

Tp depends on the shape: a velocity lobe lasts Tp in Type A but Tp/2 in
Type B, so one record gives different Tp for different models. The
regression constants of [3]_ were obtained with the Type-B Tp of its Table 3:
for its IM and EDP, call ``identify_pulse(..., models=("B",))``.

Not used: Baker (2007) [5]_ extracts the pulse with a continuous wavelet
transform (Daubechies 4), takes Tp as the pseudo-period of the largest
coefficient's wavelet and classifies the record from the residual's PGV and
energy ratios. It needs a wavelet library and gives a wavelet, not a Makris
pulse whose ωp the paper's EDP uses; the two ratios are reported here too,
as ``residual_pgv_ratio`` and 1 − ``fit_r2``, without Baker's calibrated
classifier (it was calibrated on his wavelet extraction of fault-normal
components).

References
----------
.. [1] Makris, N. (1997). Rigidity-plasticity-viscosity: can electrorheological
   dampers protect base-isolated structures from near-source ground motions?
   Earthquake Eng. Struct. Dyn. 26:571-591.
.. [2] Makris, N., Chang, S.-P. (2000). Response of damped oscillators to
   cycloidal pulses. J. Eng. Mech. 126(2):123-131.
.. [3] Konstantinidis, D., Makris, N. (2010). Experimental and analytical
   studies on the response of freestanding laboratory equipment to
   earthquake shaking. Bull. Earthquake Eng. 8:1457-1477, section 6 and
   Table 3, doi:10.1007/s10518-010-9192-8.
.. [4] Mavroeidis, G. P., Papageorgiou, A. S. (2003). A mathematical
   representation of near-fault ground motions. Bull. Seismol. Soc. Am.
   93(3):1099-1131.
.. [5] Baker, J. W. (2007). Quantitative classification of near-fault ground
   motions using wavelet analysis. Bull. Seismol. Soc. Am. 97(5):1486-1501,
   doi:10.1785/0120060255.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from scipy import integrate, optimize, signal

from assess.hazard.pulses import pulse_acceleration, type_c_phase
from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2

#: Pulse models fitted, in the order they are reported.
PULSE_MODELS = ("A", "B", "C", "MP")
#: Shortest and longest pulse period searched [s].
TP_MIN_S, TP_MAX_S = 0.2, 20.0
#: Upper bound of the MP envelope parameter γ (γ ≥ 1 by definition).
MP_GAMMA_MAX = 3.0
#: MP is preferred to the best three-parameter Makris pulse only if its fit_r2 is this much higher.
#: On synthetic records (docs/records.md) 0.01 recovered the embedded type in 392 of 400 cases;
#: 0.03 took 15 of the 100 MP pulses for C1 pulses, of a Tp up to 13 % shorter.
MP_MARGIN = 0.01
#: A record is called pulse-like when the pulse explains at least this share of the velocity energy...
PULSE_LIKE_R2 = 0.5
#: ...and the residual keeps at most this share of the PGV.
PULSE_LIKE_PGV_RATIO = 0.7
#: Step [s] of the (block-averaged) velocity the fit works on; records sampled finer are averaged.
FIT_STEP_S = 0.01
#: Samples of the pre-event segment needed before its mean is removed.
_MIN_PRE_EVENT_SAMPLES = 10
#: Fraction of PGA whose first exceedance ends the pre-event segment.
_PRE_EVENT_FRACTION = 0.05
_START_LOBES = 4
_REFINED_STARTS = 3
_TP_FACTORS = (0.8, 1.0, 1.25)
#: Periods of the coarse scan: geometric, this ratio apart.
_GRID_TP_RATIO = 1.08
#: γ values of the MP scan.
_GRID_GAMMAS = (1.5, 2.25, 3.0)
#: Distinct scan optima kept as starting points per model.
_GRID_STARTS = 4


@dataclass(frozen=True)
class PulseFit:
    """The pulse that best approximates a record's velocity history.

    Attributes
    ----------
    pulse_type : str
        ``"A"``, ``"B"``, ``"C"`` (Type C1) or ``"MP"``.
    tp_s : float
        Pulse period Tp [s] (ωp = 2π/Tp); for MP, 1/fp.
    vp_m_s : float
        Signed peak velocity of the pulse [m/s] (module docstring: for Type B
        the vp of u̇ = vp sin ωp t, as in Table 3 of the paper).
    sign : int
        Sign of ``vp_m_s`` (+1 or −1).
    arrival_time_s : float
        Time the pulse starts [s], from the record's first sample.
    fit_r2 : float
        Share of the velocity history's energy the pulse explains, 1 − Σ(u̇ − fit)²/Σu̇².
    residual_pgv_ratio : float
        PGV of (record − pulse − baseline) over the record's PGV.
    pgv_m_s : float
        Peak absolute velocity of the record [m/s] (from :func:`_velocity_m_s`).
    pga_g : float
        Peak absolute acceleration of the record [g].
    ap_g : float
        Signed acceleration amplitude of the pulse [g] as
        :func:`assess.hazard.pulses.pulse_acceleration` takes it (A, B, C); NaN for MP.
    gamma : float
        MP envelope parameter γ [-]; NaN for the other pulses.
    nu_rad : float
        MP phase ν [rad] in [0, 2π); NaN for the other pulses.
    by_model : tuple of PulseFit
        The best fit of every model tried (the selected one included), in the
        order asked; empty in those fits themselves.
    """

    pulse_type: str
    tp_s: float
    vp_m_s: float
    sign: int
    arrival_time_s: float
    fit_r2: float
    residual_pgv_ratio: float
    pgv_m_s: float
    pga_g: float
    ap_g: float = float("nan")
    gamma: float = float("nan")
    nu_rad: float = float("nan")
    by_model: tuple = ()

    @property
    def omega_p_rad_s(self) -> float:
        """ωp = 2π/Tp [rad/s]."""
        return 2.0 * np.pi / self.tp_s

    @property
    def is_pulse_like(self) -> bool:
        """fit_r2 ≥ ``PULSE_LIKE_R2`` and residual_pgv_ratio ≤ ``PULSE_LIKE_PGV_RATIO``."""
        return bool(self.fit_r2 >= PULSE_LIKE_R2 and self.residual_pgv_ratio <= PULSE_LIKE_PGV_RATIO)

    def fit_for(self, pulse_type: str) -> "PulseFit":
        """The best fit of one model (``by_model`` entry); KeyError if it was not tried."""
        for fit in self.by_model:
            if fit.pulse_type == pulse_type:
                return fit
        raise KeyError(f"model '{pulse_type}' was not fitted; fitted: "
                       f"{', '.join(f.pulse_type for f in self.by_model)}")

    def velocity_m_s(self, time_s):
        """Velocity of the fitted pulse [m/s] at record times ``time_s`` [s] (no baseline)."""
        time_s = np.asarray(time_s, dtype=float)
        if self.pulse_type == "MP":
            centre_s = self.arrival_time_s + self.gamma * self.tp_s / 2.0
            columns = _mp_columns(time_s - centre_s, self.tp_s, self.gamma)
            amplitude = self.vp_m_s / _mp_peak_factor(self.gamma, self.nu_rad)
            return amplitude * (np.cos(self.nu_rad) * columns[0] - np.sin(self.nu_rad) * columns[1])
        shape = _makris_shape(self.pulse_type, time_s - self.arrival_time_s, self.tp_s)
        return self.vp_m_s / _MAKRIS_PEAK_FACTOR[self.pulse_type] * shape

    def acceleration_g(self, time_s):
        """Acceleration of the fitted pulse [g] at record times ``time_s`` [s]."""
        time_s = np.asarray(time_s, dtype=float)
        if self.pulse_type != "MP":
            return pulse_acceleration(self.pulse_type, self.ap_g, self.tp_s, time_s - self.arrival_time_s)
        centre_s = self.arrival_time_s + self.gamma * self.tp_s / 2.0
        tau = time_s - centre_s
        omega = 2.0 * np.pi / self.tp_s
        inside = np.abs(tau) <= self.gamma * self.tp_s / 2.0
        amplitude = self.vp_m_s / _mp_peak_factor(self.gamma, self.nu_rad)
        envelope = 0.5 * (1.0 + np.cos(omega * tau / self.gamma))
        envelope_rate = -0.5 * omega / self.gamma * np.sin(omega * tau / self.gamma)
        carrier = np.cos(omega * tau + self.nu_rad)
        carrier_rate = -omega * np.sin(omega * tau + self.nu_rad)
        accel = amplitude * (envelope_rate * carrier + envelope * carrier_rate)
        return np.where(inside, accel, 0.0) / STANDARD_GRAVITY_M_S2


def identify_pulse(accel_g, dt_s: float, *, models=PULSE_MODELS) -> PulseFit:
    """Period Tp and velocity amplitude vp of a record's predominant pulse.

    Fits each pulse of ``models`` (module docstring: equations, method, sign
    of vp) to the velocity history and returns the best.

    Parameters
    ----------
    accel_g : array_like
        Acceleration [g] at 0, dt, 2dt, ...
    dt_s : float
        Time step [s].
    models : iterable of str
        Pulses to fit, among ``"A"``, ``"B"``, ``"C"``, ``"MP"``. Give
        ``("B",)`` for the Type-B pulses of Table 3 of Konstantinidis & Makris (2010).

    Returns
    -------
    PulseFit
        The selected pulse, with every model's best fit in ``by_model``.

    Examples
    --------
    A Type-B pulse of Tp = 1.5 s and first velocity lobe −0.84 m/s (Table 3,
    Gilroy Historic Bldg.), ap = vp ωp, arriving at 2 s in a 12 s record:

    >>> t = np.arange(0.0, 12.0, 0.01)
    >>> vp, tp = -0.84, 1.5
    >>> a = pulse_acceleration("B", vp * 2 * np.pi / tp / 9.80665, tp, t - 2.0)
    >>> fit = identify_pulse(a, 0.01, models=("B",))
    >>> fit.pulse_type, round(fit.tp_s, 2), round(fit.vp_m_s, 2), round(fit.arrival_time_s, 2)
    ('B', 1.5, -0.84, 2.0)
    """
    models = tuple(models)
    unknown = [m for m in models if m not in PULSE_MODELS]
    if unknown or not models:
        raise ValueError(f"unknown pulse model(s) {unknown}; use some of {', '.join(PULSE_MODELS)}")
    accel_g = np.asarray(accel_g, dtype=float)
    if accel_g.ndim != 1 or accel_g.size < 8:
        raise ValueError(f"accel_g must be a 1-D record of at least 8 samples, got shape {accel_g.shape}")
    if not np.all(np.isfinite(accel_g)):
        raise ValueError("accel_g contains NaN or infinite values")
    if not np.any(accel_g):
        raise ValueError("accel_g is zero throughout: there is no pulse to find")
    if not (np.isfinite(dt_s) and dt_s > 0.0):
        raise ValueError(f"dt_s must be positive, got {dt_s!r}")
    if dt_s > TP_MIN_S or (accel_g.size - 1) * dt_s < TP_MIN_S:
        raise ValueError(f"a record of {accel_g.size} samples at {dt_s:g} s cannot hold a pulse of "
                         f"{TP_MIN_S:g} to {TP_MAX_S:g} s (the periods searched)")
    # Fit a record of unit size: a record scaled by 1e-300 (a workbook's scale) has the same pulse,
    # and its squares would underflow. A power of two scales every operation exactly.
    unit_g = 2.0 ** float(np.floor(np.log2(np.max(np.abs(accel_g)))))
    return _rescaled(_identify_unit_pulse(accel_g / unit_g, dt_s, models), unit_g)


def _rescaled(fit: "PulseFit", unit_g: float) -> "PulseFit":
    """``fit`` of a record divided by ``unit_g``, as the fit of the record itself (amplitudes × unit_g)."""
    def scale(one):
        return replace(one, vp_m_s=one.vp_m_s * unit_g, pgv_m_s=one.pgv_m_s * unit_g,
                       pga_g=one.pga_g * unit_g, ap_g=one.ap_g * unit_g)
    return replace(scale(fit), by_model=tuple(scale(one) for one in fit.by_model))


def _identify_unit_pulse(accel_g, dt_s, models) -> PulseFit:
    """:func:`identify_pulse` of a checked record whose peak is between 1 and 2 g."""
    velocity = _velocity_m_s(accel_g, dt_s)
    time_s = np.arange(velocity.size) * dt_s
    fit_time_s, fit_velocity = _block_average(time_s, velocity, dt_s)
    problem = _FitProblem(fit_time_s, fit_velocity)
    record = {"pgv_m_s": float(np.max(np.abs(velocity))), "pga_g": float(np.max(np.abs(accel_g)))}

    lobes = _largest_lobes(fit_time_s, fit_velocity, _START_LOBES)
    fits = []
    for model in models:
        starts = _starting_points(model, lobes, problem.tp_bounds_s)
        starts += _scan_starts(model, fit_time_s, fit_velocity, problem.tp_bounds_s)
        scored = sorted(((problem.cost(model, x), tuple(x)) for x in starts), key=lambda s: s[0])
        refined = [problem.refine(model, np.array(x)) for _, x in scored[:_REFINED_STARTS]]
        best = min(refined, key=lambda x: problem.cost(model, x))
        fits.append(_pulse_fit(model, best, problem, time_s, velocity, record))
    return _select(fits)


def _velocity_m_s(accel_g, dt_s):
    """Ground velocity [m/s] of an acceleration record [g], baseline-corrected.

    Not :func:`assess.hazard.processing.velocity_displacement`: its high-pass
    filter takes about 10 % off a 5 s Type-A pulse, and the fit here carries
    its own baseline term, so only this light correction is wanted.

    1. Remove the mean of the pre-event segment (the samples before |ü| first
       reaches 5 % of the PGA), if it has at least 10 samples: a constant
       offset of the instrument.
    2. Integrate by the cumulative trapezoid rule from u̇(0) = 0.
    3. Remove the least-squares straight line a + b t from u̇: a residual
       constant acceleration offset b (and the initial velocity a). The
       pulse fit carries its own linear baseline, so what this step removes
       does not bias Tp or vp; it affects only the PGV reported (and, for
       records that are not baseline-corrected, is no substitute for
       filtering).
    """
    accel_m_s2 = np.asarray(accel_g, dtype=float) * STANDARD_GRAVITY_M_S2
    peak = np.max(np.abs(accel_m_s2))
    if peak > 0.0:
        first = int(np.argmax(np.abs(accel_m_s2) >= _PRE_EVENT_FRACTION * peak))
        if first >= _MIN_PRE_EVENT_SAMPLES:
            accel_m_s2 = accel_m_s2 - np.mean(accel_m_s2[:first])
    velocity = integrate.cumulative_trapezoid(accel_m_s2, dx=dt_s, initial=0.0)
    time_s = np.arange(velocity.size) * dt_s
    slope, intercept = np.polyfit(time_s, velocity, 1)
    return velocity - (intercept + slope * time_s)


def _block_average(time_s, velocity, dt_s):
    """Velocity averaged over blocks of ~``FIT_STEP_S`` (a low-pass before decimation)."""
    q = max(1, int(round(FIT_STEP_S / dt_s)))
    n = velocity.size // q
    if q == 1 or n < 8:
        return time_s, velocity
    blocks = velocity[: n * q].reshape(n, q).mean(axis=1)
    return time_s[: n * q].reshape(n, q).mean(axis=1), blocks


# ----------------------------------------------------------------------------- pulse shapes

_PHI = type_c_phase(1)
#: Peak velocity of each unit Makris shape (signed, its largest lobe; B: its first lobe).
_MAKRIS_PEAK_FACTOR = {"A": 1.0, "B": 1.0, "C": -(1.0 + np.sin(_PHI))}
#: Velocity amplitude → acceleration amplitude, ap = factor · (linear coefficient) · ωp.
_MAKRIS_AP_FACTOR = {"A": 0.5, "B": 1.0, "C": 1.0}


def _makris_duration(model, tp_s):
    return (1.5 - _PHI / np.pi) * tp_s if model == "C" else tp_s


def _makris_shape(model, tau_s, tp_s):
    """Unit velocity shape of a Makris pulse (coefficient: vp for A and B, v_c = ap/ωp for C)."""
    omega = 2.0 * np.pi / tp_s
    inside = (tau_s >= 0.0) & (tau_s <= _makris_duration(model, tp_s))
    if model == "A":
        shape = 0.5 * (1.0 - np.cos(omega * tau_s))
    elif model == "B":
        shape = np.sin(omega * tau_s)
    else:
        shape = np.sin(omega * tau_s + _PHI) - np.sin(_PHI)
    return np.where(inside, shape, 0.0)


def _mp_columns(tau_s, tp_s, gamma):
    """The two MP columns e(τ)cos(ωτ), e(τ)sin(ωτ); τ from the envelope's centre."""
    omega = 2.0 * np.pi / tp_s
    inside = np.abs(tau_s) <= gamma * tp_s / 2.0
    envelope = np.where(inside, 0.5 * (1.0 + np.cos(omega * tau_s / gamma)), 0.0)
    return envelope * np.cos(omega * tau_s), envelope * np.sin(omega * tau_s)


def _mp_peak_factor(gamma, nu_rad):
    """Signed peak of the unit MP pulse (A = 1): earliest extreme of largest magnitude."""
    x = np.linspace(-0.5, 0.5, 4001) * gamma  # τ/Tp
    shape = 0.5 * (1.0 + np.cos(2.0 * np.pi * x / gamma)) * np.cos(2.0 * np.pi * x + nu_rad)
    magnitude = np.abs(shape)
    first = int(np.argmax(magnitude >= (1.0 - 1e-9) * magnitude.max()))
    return float(shape[first])


# ----------------------------------------------------------------------------- the fit

class _FitProblem:
    """Least squares of one velocity history against pulse + a + b t, linear parts projected out."""

    def __init__(self, time_s, velocity):
        self.time_s = time_s
        self.velocity = velocity
        span = max(time_s[-1] - time_s[0], 1e-9)
        self.baseline = np.column_stack([np.ones_like(time_s), (time_s - time_s[0]) / span - 0.5])
        self.energy = float(np.sum(velocity**2))
        duration = time_s[-1] - time_s[0]
        self.tp_bounds_s = (TP_MIN_S, max(TP_MIN_S * 1.01, min(TP_MAX_S, duration)))

    def columns(self, model, x):
        tp_s, t0_s = x[0], x[1]
        if model == "MP":
            return np.column_stack(_mp_columns(self.time_s - t0_s, tp_s, x[2]))
        return _makris_shape(model, self.time_s - t0_s, tp_s)[:, None]

    def solve(self, model, x):
        """Linear coefficients (pulse columns first, then baseline) and residual for parameters x."""
        design = np.column_stack([self.columns(model, x), self.baseline])
        coefficients, *_ = np.linalg.lstsq(design, self.velocity, rcond=None)
        return coefficients, self.velocity - design @ coefficients

    def cost(self, model, x):
        return float(np.sum(self.solve(model, x)[1] ** 2))

    def bounds(self, model):
        low_tp, high_tp = self.tp_bounds_s
        t_first, t_last = self.time_s[0], self.time_s[-1]
        if model == "MP":
            return ([low_tp, t_first, 1.0], [high_tp, t_last, MP_GAMMA_MAX])
        return ([low_tp, t_first - high_tp], [high_tp, t_last])

    def refine(self, model, x):
        low, high = self.bounds(model)
        x0 = np.clip(x, np.array(low) + 1e-9, np.array(high) - 1e-9)
        scale = np.array([x0[0], x0[0]] + ([1.0] if model == "MP" else []))
        result = optimize.least_squares(lambda p: self.solve(model, p)[1], x0, bounds=(low, high),
                                        x_scale=scale, diff_step=1e-4, xtol=1e-8, ftol=1e-10,
                                        max_nfev=200)
        return result.x


def _largest_lobes(time_s, velocity, count):
    """(start, end, peak time) of the ``count`` half-cycles of largest |peak|, largest first."""
    negative = velocity < 0.0
    cuts = np.flatnonzero(negative[1:] != negative[:-1]) + 1
    edges = np.concatenate([[0], cuts, [velocity.size]])
    lobes = []
    for begin, end in zip(edges[:-1], edges[1:]):
        k = begin + int(np.argmax(np.abs(velocity[begin:end])))
        lobes.append((abs(velocity[k]), _crossing(time_s, velocity, begin),
                      _crossing(time_s, velocity, end), time_s[k]))
    lobes.sort(key=lambda lobe: -lobe[0])
    return [lobe[1:] for lobe in lobes[:count]]


def _crossing(time_s, velocity, index):
    """Time of the zero crossing between samples index − 1 and index (record ends as they are)."""
    if index <= 0:
        return time_s[0]
    if index >= velocity.size:
        return time_s[-1]
    v0, v1 = velocity[index - 1], velocity[index]
    return time_s[index - 1] + (time_s[index] - time_s[index - 1]) * v0 / (v0 - v1)


def _starting_points(model, lobes, tp_bounds_s):
    """Starting (Tp, t0[, γ]) for one model from the largest half-cycles (module docstring, step 2)."""
    starts = []
    c_middle = 0.5 + _PHI / np.pi  # share of Tp taken by the middle lobe of C1
    c_outer = 0.5 - _PHI / np.pi  # ... and by each outer lobe
    for begin_s, end_s, peak_s in lobes:
        d = max(end_s - begin_s, 1e-3)
        for factor in _TP_FACTORS:
            if model == "A":
                tp = factor * d
                candidates = [(tp, begin_s - 0.5 * (tp - d))]
            elif model == "B":
                tp = factor * 2.0 * d
                candidates = [(tp, begin_s - 0.25 * tp + 0.5 * d), (tp, begin_s - 0.75 * tp + 0.5 * d)]
            elif model == "C":
                tp_mid, tp_out = factor * d / c_middle, factor * d / c_outer
                candidates = [(tp_mid, 0.5 * (begin_s + end_s) - (0.5 - _PHI / np.pi + c_middle / 2) * tp_mid),
                              (tp_out, 0.5 * (begin_s + end_s) - c_outer / 2 * tp_out),
                              (tp_out, 0.5 * (begin_s + end_s) - (1.0 + c_outer / 2) * tp_out)]
            else:
                tp = factor * 2.0 * d
                candidates = [(tp, peak_s, 1.5), (tp, peak_s, 2.5)]
            for candidate in candidates:
                tp = float(np.clip(candidate[0], *tp_bounds_s))
                starts.append((tp,) + tuple(candidate[1:]))
    return starts


def _scan_starts(model, time_s, velocity, tp_bounds_s):
    """Starting (Tp, t0[, γ]) from a scan over Tp of the pulse's best arrival (module docstring, step 2).

    For each Tp on a geometric grid (and each γ of ``_GRID_GAMMAS`` for MP)
    the unit shape is cross-correlated with the velocity at every shift
    (zeros outside the record, no baseline); the energy a shift explains is
    Σ (column·u̇)²/(column·column), the MP columns being orthogonal. The best
    shift of every Tp is a candidate; the ``_GRID_STARTS`` best that differ
    (Tp by more than 15 % or t0 by more than Tp/2) are returned.
    """
    step_s = time_s[1] - time_s[0]
    low, high = tp_bounds_s
    periods = np.exp(np.arange(np.log(low), np.log(high) + 1e-9, np.log(_GRID_TP_RATIO)))
    scored = []
    for tp in periods:
        for gamma in (_GRID_GAMMAS if model == "MP" else (None,)):
            if model == "MP":
                tau = np.arange(-0.5 * gamma * tp, 0.5 * gamma * tp + step_s / 2, step_s)
                columns = _mp_columns(tau, tp, gamma)
            else:
                tau = np.arange(0.0, _makris_duration(model, tp) + step_s / 2, step_s)
                columns = (_makris_shape(model, tau, tp),)
            if tau.size >= velocity.size:
                continue
            padded = np.pad(velocity, tau.size)
            explained = sum(signal.correlate(padded, c, mode="valid", method="fft") ** 2 / np.dot(c, c)
                            for c in columns)
            k = int(np.argmax(explained))
            t0 = time_s[0] + (k - tau.size) * step_s - tau[0]
            scored.append((explained[k], (tp, t0) if gamma is None else (tp, t0, gamma)))
    scored.sort(key=lambda s: -s[0])
    chosen = []
    for _, x in scored:
        if all(abs(np.log(x[0] / y[0])) > 0.15 or abs(x[1] - y[1]) > 0.5 * y[0] for y in chosen):
            chosen.append(x)
        if len(chosen) == _GRID_STARTS:
            break
    return chosen


def _pulse_fit(model, x, problem, time_s, velocity, record):
    """PulseFit of parameters x, its quality measured on the full-rate velocity."""
    coefficients, _ = problem.solve(model, x)
    tp_s = float(x[0])
    if model == "MP":
        gamma = float(x[2])
        amplitude = float(np.hypot(coefficients[0], coefficients[1]))
        nu_rad = float(np.arctan2(-coefficients[1], coefficients[0]) % (2.0 * np.pi))
        vp = amplitude * _mp_peak_factor(gamma, nu_rad)
        arrival_s, ap_g = float(x[1]) - gamma * tp_s / 2.0, float("nan")
        n_linear = 2
    else:
        gamma = nu_rad = float("nan")
        vp = float(coefficients[0]) * _MAKRIS_PEAK_FACTOR[model]
        ap_g = float(coefficients[0]) * _MAKRIS_AP_FACTOR[model] * 2.0 * np.pi / tp_s / STANDARD_GRAVITY_M_S2
        arrival_s = float(x[1])
        n_linear = 1
    fit = PulseFit(pulse_type=model, tp_s=tp_s, vp_m_s=float(vp), sign=1 if vp >= 0 else -1,
                   arrival_time_s=arrival_s, fit_r2=float("nan"), residual_pgv_ratio=float("nan"),
                   ap_g=ap_g, gamma=gamma, nu_rad=nu_rad, **record)
    # Baseline coefficients refer to the fit grid's normalised time; rebuild it on the full-rate one.
    span = max(problem.time_s[-1] - problem.time_s[0], 1e-9)
    base = coefficients[n_linear] + coefficients[n_linear + 1] * ((time_s - problem.time_s[0]) / span - 0.5)
    residual = velocity - fit.velocity_m_s(time_s) - base
    energy = float(np.sum(velocity**2))
    r2 = 1.0 - float(np.sum(residual**2)) / energy if energy > 0.0 else 0.0
    ratio = float(np.max(np.abs(residual)) / record["pgv_m_s"]) if record["pgv_m_s"] > 0.0 else 1.0
    return replace(fit, fit_r2=r2, residual_pgv_ratio=ratio)


def _select(fits):
    """Best Makris pulse by fit_r2; MP only if it beats that by ``MP_MARGIN`` (module docstring)."""
    makris = [f for f in fits if f.pulse_type != "MP"]
    mp = [f for f in fits if f.pulse_type == "MP"]
    best = max(makris, key=lambda f: f.fit_r2) if makris else mp[0]
    if makris and mp and mp[0].fit_r2 > best.fit_r2 + MP_MARGIN:
        best = mp[0]
    return replace(best, by_model=tuple(fits))
