"""Processing of acceleration records: velocity and displacement, intensity measures, scaling.

Pure functions on numpy arrays (accelerations in g, steps in s); the two that
transform a whole :class:`~assess.hazard.records.Record` return a new one.

Velocity and displacement: the method and why
---------------------------------------------
Integrated twice, a small offset in a record's baseline grows into a large,
spurious displacement (0.005 g over 30 s: 22 m). :func:`velocity_displacement`
removes it as PEER's processing does, after Boore (2005) [1]_ and Boore &
Bommer (2005) [2]_:

1. subtract the mean acceleration, of the pre-event part when the record has
   one (``pre_event_s``), else of the whole record. The mean is the
   trapezoidal one, so the uncorrected velocity ends at zero: the ground ends
   at rest;
2. pad zeros at both ends, each pad 1.5 n / f_c long (the total pad
   T_zpad = 1.5 n_t / f_c of Converse & Brady [3]_ and Boore [1]_ for the
   order n_t = 2n of two passes, at each end: generous, never too short);
3. filter with an acausal (zero-phase) Butterworth high-pass: order n
   forward, then backward, so |H(f)| = 1 / (1 + (f_c/f)^(2n)) and no phase
   shift. A causal filter would shift and reshape a velocity pulse; the
   acausal one leaves its timing and symmetry alone;
4. integrate the padded, filtered acceleration (trapezoidal rule) and only then
   cut the record's window out, so acceleration, velocity and displacement
   stay consistent (Boore [1]_: the pads are part of the processed record).

Not a polynomial baseline fitted to the displacement: such a fit depends on
the record's length and the polynomial's order and can bend a long pulse
unpredictably; the filter removes what lies below one declared frequency and
nothing else, as in the PEER databases most hazard records come from.

Why f_c = 0.02 Hz (50 s) by default, lower than the 0.05-0.1 Hz often seen:
the records this tool reads are mostly processed already (PEER records, floor
motions computed by a structural analysis, synthetic pulses), so the filter
here need only remove drift, and near-fault pulses must survive it. At
0.02 Hz a Type-B pulse keeps its peak velocity within 1 % and a Type-A pulse
within 11 % for Tp up to 5 s (``tests/verification/test_processing.py``); at 0.05 Hz a
Type-A pulse of Tp = 5 s would lose a quarter of it. A Type-A pulse has a
permanent displacement (fling) that no high-pass filter keeps: for synthetic
pulses use ``method="none"``. A raw record with a baseline shift inside it
(an offset starting mid-record) needs a record-specific, higher corner (0.05
to 0.1 Hz), chosen record by record as PEER does.

References
----------
.. [1] Boore, D. M. (2005). On pads and filters: processing strong-motion
   data. Bull. Seismol. Soc. Am. 95(2):745-750, doi:10.1785/0120040160.
.. [2] Boore, D. M., Bommer, J. J. (2005). Processing of strong-motion
   accelerograms: needs, options and consequences. Soil Dyn. Earthq. Eng.
   25(2):93-115, doi:10.1016/j.soildyn.2004.10.007.
.. [3] Converse, A. M., Brady, A. G. (1992). BAP: basic strong-motion
   accelerogram processing software, version 1.0. U.S. Geological Survey
   Open-File Report 92-296A.
.. [4] Arias, A. (1970). A measure of earthquake intensity. In R. J. Hansen
   (ed.), Seismic Design for Nuclear Power Plants, MIT Press, 438-483.
.. [5] Trifunac, M. D., Brady, A. G. (1975). A study on the duration of strong
   earthquake ground motion. Bull. Seismol. Soc. Am. 65(3):581-626,
   doi:10.1785/BSSA0650030581.
.. [6] Konstantinidis, D., Makris, N. (2010). Experimental and analytical
   studies on the response of 1/4-scale models of freestanding laboratory
   equipment subjected to strong earthquake shaking. Bull. Earthq. Eng.
   8:1457-1477, doi:10.1007/s10518-010-9192-8.
"""
from __future__ import annotations

from dataclasses import asdict, dataclass
from typing import NamedTuple

import numpy as np
from scipy import signal

from assess.hazard.records import Record
from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2

#: Default high-pass corner [Hz] (see the module docstring for the choice).
DEFAULT_CORNER_FREQUENCY_HZ = 0.02
#: Default Butterworth order of each of the two passes.
DEFAULT_FILTER_ORDER = 4
#: Accepted values of ``method``.
PROCESSING_METHODS = ("butterworth", "none")


class VelocityDisplacement(NamedTuple):
    """Velocity and displacement histories at the record's samples."""

    velocity_m_s: np.ndarray
    displacement_m: np.ndarray


def _history(accel_g, dt_s) -> tuple[np.ndarray, float]:
    """Checked copy of an acceleration history [g] and its step [s] (programming errors raise ValueError)."""
    accel = np.asarray(accel_g, dtype=float)
    if accel.ndim != 1 or accel.size < 2:
        raise ValueError(f"accel_g must be a 1-D history of at least 2 samples, got shape {accel.shape}")
    if not np.all(np.isfinite(accel)):
        raise ValueError("accel_g holds NaN or infinite values")
    dt = float(dt_s)
    if not (np.isfinite(dt) and dt > 0.0):
        raise ValueError(f"dt_s must be a positive number of seconds, got {dt_s!r}")
    return accel, dt


def _integrate(values, dt_s) -> np.ndarray:
    """Cumulative trapezoidal integral from 0 at the first sample."""
    out = np.empty_like(values)
    out[0] = 0.0
    np.cumsum(0.5 * (values[1:] + values[:-1]) * dt_s, out=out[1:])
    return out


def remove_mean(accel_g, dt_s, *, pre_event_s: float | None = None) -> np.ndarray:
    """Acceleration [g] less its mean: of the first ``pre_event_s`` seconds, or of the whole record.

    .. math:: \\ddot u_c(t) = \\ddot u(t) - \\frac{1}{T}\\int_0^T \\ddot u\\,dt

    with T the pre-event window, or the record's length when ``pre_event_s``
    is None (Boore & Bommer 2005 [2]_, section 3). The integral is the
    trapezoidal one, so over the whole record the velocity then ends at zero.

    Parameters
    ----------
    accel_g : array-like
        Acceleration [g] at a constant step.
    dt_s : float
        Step [s].
    pre_event_s : float, optional
        Length [s] of the record's pre-event part: the samples at
        t <= pre_event_s, which must all precede the shaking.

    Returns
    -------
    ndarray
        Acceleration [g].

    Examples
    --------
    >>> remove_mean([1.0, 2.0, 3.0], 1.0)  # trapezoidal mean (1.5 + 2.5)/2 = 2
    array([-1.,  0.,  1.])
    """
    accel, dt = _history(accel_g, dt_s)
    window = accel if pre_event_s is None else accel[:max(2, int(round(pre_event_s / dt)) + 1)]
    return accel - np.trapezoid(window, dx=dt) / ((window.size - 1) * dt)


def zero_pad_duration_s(corner_frequency_hz: float, order: int = DEFAULT_FILTER_ORDER) -> float:
    """Length [s] of the zeros padded at each end before the two-pass filter.

    .. math:: T_{pad} = 1.5\\,n / f_c

    the total pad 1.5 n_t / f_c that Converse & Brady [3]_ and Boore (2005)
    [1]_ ask for an acausal filter of order n_t = 2n (two passes of order n),
    put at each end rather than split between them.

    Examples
    --------
    >>> zero_pad_duration_s(0.02, 4)
    300.0
    """
    return 1.5 * int(order) / float(corner_frequency_hz)


def acausal_highpass(accel_g, dt_s, *, corner_frequency_hz: float = DEFAULT_CORNER_FREQUENCY_HZ,
                     order: int = DEFAULT_FILTER_ORDER) -> np.ndarray:
    """Zero-phase Butterworth high-pass [g]: order ``order`` forward, then backward.

    .. math:: |H(f)| = \\frac{1}{1 + (f_c/f)^{2n}}, \\qquad \\arg H(f) = 0

    The input is filtered as given: pad it first (:func:`zero_pad_duration_s`)
    or the ends will ring; :func:`velocity_displacement` does both
    (Boore 2005 [1]_).

    Parameters
    ----------
    accel_g : array-like
        Acceleration [g] at a constant step.
    dt_s : float
        Step [s].
    corner_frequency_hz : float
        f_c [Hz], where the gain is 1/2; below the Nyquist frequency 1/(2 dt).
    order : int
        Butterworth order n of each pass.

    Returns
    -------
    ndarray
        Filtered acceleration [g].

    Examples
    --------
    A constant is removed, a 1 Hz sine (50 times f_c) passes unchanged, once
    the transients of the unpadded ends (300 s here) have died out:

    >>> t = np.arange(0.0, 1000.0, 0.05)
    >>> out = acausal_highpass(0.1 + np.sin(2 * np.pi * t), 0.05)
    >>> middle = (t > 300.0) & (t < 700.0)
    >>> bool(np.allclose(out[middle], np.sin(2 * np.pi * t[middle]), atol=1e-6))
    True
    """
    accel, dt = _history(accel_g, dt_s)
    nyquist_hz = 0.5 / dt
    if not (0.0 < corner_frequency_hz < nyquist_hz):
        raise ValueError(f"corner_frequency_hz must lie between 0 and the Nyquist frequency "
                         f"{nyquist_hz:g} Hz, got {corner_frequency_hz!r}")
    if int(order) < 1:
        raise ValueError(f"order must be a positive integer, got {order!r}")
    sos = signal.butter(int(order), corner_frequency_hz, btype="highpass", fs=1.0 / dt, output="sos")
    return signal.sosfiltfilt(sos, accel, padtype=None)


def velocity_displacement(accel_g, dt_s, *, method: str = "butterworth",
                          corner_frequency_hz: float = DEFAULT_CORNER_FREQUENCY_HZ,
                          order: int = DEFAULT_FILTER_ORDER,
                          pre_event_s: float | None = None) -> VelocityDisplacement:
    """Velocity [m/s] and displacement [m] of an acceleration record, baseline-corrected.

    .. math:: \\dot u(t) = g\\int_{-T_{pad}}^{t} \\ddot u_f\\,d\\tau, \\qquad
              u(t) = \\int_{-T_{pad}}^{t} \\dot u\\,d\\tau

    with ü_f the mean-removed, zero-padded, acausally high-passed acceleration
    [g] (steps 1-4 of the module docstring; Boore 2005 [1]_, Boore & Bommer
    2005 [2]_), integrated by the trapezoidal rule from the start of the
    front pad. The histories are returned at the record's samples only; they
    need not start at exactly zero (the acausal filter reaches before the
    first sample).

    Parameters
    ----------
    accel_g : array-like
        Acceleration [g] at a constant step.
    dt_s : float
        Step [s].
    method : {"butterworth", "none"}
        ``"butterworth"``: the correction above. ``"none"``: plain
        integration from rest, for synthetic motions without noise (pulses).
    corner_frequency_hz : float, default 0.02
        High-pass corner f_c [Hz]; raise it (0.05-0.1 Hz) for raw records.
    order : int, default 4
        Butterworth order of each pass.
    pre_event_s : float, optional
        Length [s] of the pre-event part whose mean is removed (default: the
        mean of the whole record).

    Returns
    -------
    VelocityDisplacement
        ``(velocity_m_s, displacement_m)``, arrays as long as ``accel_g``.

    Examples
    --------
    0.1 g held for 1 s, integrated plainly: v = 0.1 g t, u = 0.1 g t²/2.

    >>> v, u = velocity_displacement([0.1, 0.1, 0.1], 0.5, method="none")
    >>> [round(float(x), 6) for x in v], [round(float(x), 6) for x in u]
    ([0.0, 0.490333, 0.980665], [0.0, 0.122583, 0.490333])

    A Type-B pulse (ap = 0.5 g, Tp = 2 s) in 20 s of record keeps its peak
    velocity ap/ωp = 0.5 g · 2 s / 2π = 1.561 m/s through the filter:

    >>> from assess.hazard.pulses import pulse_acceleration
    >>> a = pulse_acceleration("B", 0.5, 2.0, np.arange(0.0, 20.0, 0.01) - 5.0)
    >>> round(float(np.max(np.abs(velocity_displacement(a, 0.01).velocity_m_s))), 2)
    1.56
    """
    accel, dt = _history(accel_g, dt_s)
    if method == "none":
        velocity = _integrate(accel * STANDARD_GRAVITY_M_S2, dt)
        return VelocityDisplacement(velocity, _integrate(velocity, dt))
    if method != "butterworth":
        raise ValueError(f"unknown method {method!r}; use one of {', '.join(PROCESSING_METHODS)}")
    n_pad = int(np.ceil(zero_pad_duration_s(corner_frequency_hz, order) / dt))
    padded = np.concatenate([np.zeros(n_pad), remove_mean(accel, dt, pre_event_s=pre_event_s),
                             np.zeros(n_pad)])
    filtered = acausal_highpass(padded, dt, corner_frequency_hz=corner_frequency_hz, order=order)
    velocity = _integrate(filtered * STANDARD_GRAVITY_M_S2, dt)
    displacement = _integrate(velocity, dt)
    window = slice(n_pad, n_pad + accel.size)
    return VelocityDisplacement(velocity[window], displacement[window])


# ------------------------------------------------------------------ intensity measures

def peak_acceleration_g(accel_g) -> float:
    """Peak absolute acceleration [g]: PGA of a ground record, PTA/PFA of a table or floor record.

    .. math:: PGA = \\max_t |\\ddot u(t)|

    Examples
    --------
    >>> peak_acceleration_g([0.1, -0.3, 0.2])
    0.3
    """
    accel = np.asarray(accel_g, dtype=float)
    if accel.size == 0:
        raise ValueError("accel_g is empty")
    return float(np.max(np.abs(accel)))


def peak_velocity_m_s(accel_g, dt_s, **processing) -> float:
    """Peak absolute velocity [m/s] (PGV) of the corrected record.

    .. math:: PGV = \\max_t |\\dot u(t)|

    with u̇ from :func:`velocity_displacement`, whose keyword arguments
    ``processing`` are passed on (method, corner frequency, ...).

    Examples
    --------
    0.1 g for 1 s from rest, plain integration: 0.1 × 9.80665 × 1 = 0.981 m/s.

    >>> round(peak_velocity_m_s([0.1, 0.1, 0.1], 0.5, method="none"), 6)
    0.980665
    """
    return float(np.max(np.abs(velocity_displacement(accel_g, dt_s, **processing).velocity_m_s)))


def peak_displacement_m(accel_g, dt_s, **processing) -> float:
    """Peak absolute displacement [m] (PGD) of the corrected record.

    .. math:: PGD = \\max_t |u(t)|

    with u from :func:`velocity_displacement` (keyword arguments passed on).

    Examples
    --------
    0.1 g for 1 s from rest, plain integration: 0.1 × 9.80665 × 1²/2 = 0.490 m.

    >>> round(peak_displacement_m([0.1, 0.1, 0.1], 0.5, method="none"), 6)
    0.490333
    """
    return float(np.max(np.abs(velocity_displacement(accel_g, dt_s, **processing).displacement_m)))


def arias_intensity_m_s(accel_g, dt_s) -> float:
    """Arias intensity [m/s] of the record as given (Arias 1970 [4]_).

    .. math:: I_a = \\frac{\\pi}{2g}\\int_0^{T} \\ddot u^2\\,dt

    with ü in m/s² (trapezoidal rule).

    Examples
    --------
    1 g held for 1 s: I_a = π g / 2 = 15.404 m/s.

    >>> round(arias_intensity_m_s(np.ones(101), 0.01), 3)
    15.404
    """
    accel, dt = _history(accel_g, dt_s)
    return float(np.pi / (2.0 * STANDARD_GRAVITY_M_S2)
                 * np.trapezoid((accel * STANDARD_GRAVITY_M_S2) ** 2, dx=dt))


def husid(accel_g, dt_s) -> np.ndarray:
    """Husid plot: the share [–] of the Arias intensity reached at each sample (0 to 1).

    .. math:: H(t) = \\int_0^t \\ddot u^2\\,d\\tau \\Big/ \\int_0^T \\ddot u^2\\,d\\tau

    All zeros for a record without motion.

    Examples
    --------
    >>> husid([1.0, 1.0, 1.0], 0.5)
    array([0. , 0.5, 1. ])
    """
    accel, dt = _history(accel_g, dt_s)
    cumulative = _integrate(accel ** 2, dt)
    return cumulative / cumulative[-1] if cumulative[-1] > 0.0 else cumulative


def significant_duration_s(accel_g, dt_s, *, start_fraction: float = 0.05,
                           end_fraction: float = 0.95) -> float:
    """Significant duration [s]: time between two shares of the Arias intensity (D5-95 by default).

    .. math:: D = t(H = f_{end}) - t(H = f_{start})

    on the Husid plot H (:func:`husid`), each time found by linear
    interpolation between samples (Trifunac & Brady 1975 [5]_, who used 5 and
    95 %). Zero for a record without motion.

    Examples
    --------
    A constant amplitude over 10 s: H is linear, D5-95 = 0.9 × 10 s.

    >>> round(significant_duration_s(np.ones(1001), 0.01), 9)
    9.0
    """
    if not 0.0 <= start_fraction < end_fraction <= 1.0:
        raise ValueError(f"need 0 <= start_fraction < end_fraction <= 1, got {start_fraction}, {end_fraction}")
    accel, dt = _history(accel_g, dt_s)
    share = husid(accel, dt)
    if share[-1] == 0.0:
        return 0.0
    return float(_time_reaching(share, end_fraction, dt) - _time_reaching(share, start_fraction, dt))


def _time_reaching(share, fraction, dt_s) -> float:
    """First time [s] at which the non-decreasing ``share`` reaches ``fraction`` (linear between samples)."""
    k = int(np.searchsorted(share, fraction, side="left"))
    if k == 0:
        return 0.0
    return (k - 1 + (fraction - share[k - 1]) / (share[k] - share[k - 1])) * dt_s


# ------------------------------------------------------------------ transforming records

def scale(record: Record, factor: float) -> Record:
    """The record with every acceleration multiplied by ``factor`` (> 0), same step.

    .. math:: \\ddot u'(t) = \\lambda\\,\\ddot u(t)

    Velocity, displacement and PGA scale by λ, the Arias intensity by λ².

    Examples
    --------
    >>> r = scale(Record(np.array([0.0, 0.2, -0.1]), 0.01, "floor.csv"), 2.0)
    >>> r.pta_g, r.dt_s, r.name
    (0.4, 0.01, 'floor.csv x 2')
    """
    factor = _positive("factor", factor)
    return Record(np.asarray(record.accel_g, dtype=float) * factor, record.dt_s, f"{record.name} x {factor:g}")


def compress_time(record: Record, factor: float) -> Record:
    """The record played ``factor`` (> 0) times faster: same accelerations, step dt/factor.

    .. math:: \\ddot u'(t) = \\ddot u(\\lambda t)

    Under Froude similitude a model at length scale 1/L keeps the
    accelerations and runs √L times faster; Konstantinidis & Makris (2010)
    [6]_ compressed their records by 2 for 1/4-scale blocks (section 2).
    Duration and velocity shrink by λ, displacement by λ², the Arias
    intensity by λ.

    Examples
    --------
    >>> r = compress_time(Record(np.array([0.0, 0.2, -0.1]), 0.01, "lg.csv"), 2.0)
    >>> r.dt_s, r.pta_g, r.duration_s, r.name
    (0.005, 0.2, 0.01, 'lg.csv, time compressed by 2')
    """
    factor = _positive("factor", factor)
    return Record(np.asarray(record.accel_g, dtype=float).copy(), record.dt_s / factor,
                  f"{record.name}, time compressed by {factor:g}")


def _positive(name, value) -> float:
    value = float(value)
    if not (np.isfinite(value) and value > 0.0):
        raise ValueError(f"{name} must be a positive number, got {value!r}")
    return value


# ------------------------------------------------------------------ summary

@dataclass(frozen=True)
class MotionSummary:
    """The measures of a record shown in reports.

    Attributes: ``name``; ``pta_g`` peak acceleration [g]; ``pgv_m_s`` peak
    velocity [m/s] and ``pgd_m`` peak displacement [m], after processing;
    ``arias_intensity_m_s`` [m/s]; ``significant_duration_s`` D5-95 [s];
    ``duration_s`` length of the record [s]; ``dt_s`` step [s];
    ``processing``: how velocity and displacement were obtained.
    """

    name: str
    pta_g: float
    pgv_m_s: float
    pgd_m: float
    arias_intensity_m_s: float
    significant_duration_s: float
    duration_s: float
    dt_s: float
    processing: str

    def as_dict(self) -> dict:
        """The fields as a plain dict (for JSON and tables)."""
        return asdict(self)


def summary(record: Record, **processing) -> MotionSummary:
    """Intensity measures of a record; ``processing`` goes to :func:`velocity_displacement`.

    Examples
    --------
    One cycle of a 1 Hz sine of 0.3 g amplitude, then rest, plain integration:
    PGV = 2 × 0.3 g / 2π = 0.936 m/s; I_a = π (0.3 g)² (1 s) / (4 g) = 0.693 m/s.

    >>> from assess.hazard.pulses import pulse_acceleration
    >>> t = np.arange(0.0, 3.0001, 0.001)
    >>> s = summary(Record(pulse_acceleration("A", 0.3, 1.0, t), 0.001, "A"), method="none")
    >>> round(s.pta_g, 3), round(s.pgv_m_s, 3), round(s.arias_intensity_m_s, 3), s.duration_s
    (0.3, 0.936, 0.693, 3.0)
    """
    accel, dt = _history(record.accel_g, record.dt_s)
    velocity, displacement = velocity_displacement(accel, dt, **processing)
    corner_hz = processing.get("corner_frequency_hz", DEFAULT_CORNER_FREQUENCY_HZ)
    how = ("plain integration, no correction" if processing.get("method") == "none" else
           f"mean removed, acausal Butterworth high-pass {corner_hz:g} Hz, order "
           f"{processing.get('order', DEFAULT_FILTER_ORDER)} x 2 passes, zero pads (Boore 2005)")
    return MotionSummary(
        name=record.name, pta_g=peak_acceleration_g(accel),
        pgv_m_s=float(np.max(np.abs(velocity))), pgd_m=float(np.max(np.abs(displacement))),
        arias_intensity_m_s=arias_intensity_m_s(accel, dt),
        significant_duration_s=significant_duration_s(accel, dt),
        duration_s=(accel.size - 1) * dt, dt_s=dt, processing=how)
