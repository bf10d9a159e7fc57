"""Pure rocking kernel (assess.mechanics.rocking) against closed forms, the paper and scipy.

Block of Konstantinidis & Makris (2010), section 3.2, Figs. 5 and 6:
α = 0.16 rad, p = 1.25 rad/s, Housner restitution e = 1 − 1.5 sin²α.
The independent reference (scipy DOP853 with impact events) is in
``tests/rocking_reference.py``.
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy import integrate

from assess.hazard.pulses import pulse_acceleration
from assess.mechanics.geometry import housner_restitution
from assess.mechanics.rocking import rocking_peaks_batch, rocking_response
from rocking_reference import reference_rocking

ALPHA = 0.16
P = 1.25
E = float(housner_restitution(ALPHA))


def synthetic_record(seed, pga_g, n=1500, dt_s=0.01):
    """Sum of 12 sines (0.3-5 Hz, seeded phases and amplitudes) under a build-up/decay envelope [g]."""
    rng = np.random.default_rng(seed)
    time_s = np.arange(n) * dt_s
    freq, phase, amp = rng.uniform(0.3, 5.0, 12), rng.uniform(0, 2 * np.pi, 12), rng.uniform(0.2, 1.0, 12)
    accel = (amp[:, None] * np.sin(2 * np.pi * freq[:, None] * time_s + phase[:, None])).sum(axis=0)
    accel *= np.minimum(1.0, time_s / 2.0) * np.exp(-np.maximum(time_s - 8.0, 0.0) / 3.0)
    return pga_g * accel / np.abs(accel).max()


def pulse_record(pulse, omega_ratio, ap_over_alpha_g, free_s=12.0):
    """Pulse of frequency ωp = omega_ratio·p and amplitude ap = (ap/αg)·α g, then free rocking."""
    tp_s = 2 * np.pi / (omega_ratio * P)
    dt_s = min(tp_s / 200.0, 0.01)
    time_s = np.arange(0.0, tp_s + free_s / P, dt_s)
    return pulse_acceleration(pulse, ap_over_alpha_g * ALPHA, tp_s, time_s), dt_s


# ------------------------------------------------------------------ free rocking (Housner 1963)
def exact_quarter_period(theta0, alpha, p):
    """Time [s] from release at θ0 (at rest) to θ = 0, free rocking, by quadrature.

    Energy: ½θ̇² = p²[cos(α − θ) − cos(α − θ0)], so
    T/4 = (1/p)∫₀^θ0 dθ / sqrt(2[cos(α−θ) − cos(α−θ0)]); the inverse square-root
    singularity at θ0 is taken by the algebraic weight of QUADPACK's QAWS.
    """
    def smooth(theta):  # sqrt(θ0 − θ) / sqrt(2[cos(α−θ) − cos(α−θ0)])
        return 1.0 / np.sqrt(2.0 * np.sin((2 * alpha - theta - theta0) / 2)
                             * np.sinc((theta0 - theta) / (2 * np.pi)))
    value, _ = integrate.quad(smooth, 0.0, theta0, weight="alg", wvar=(0.0, -0.5), epsabs=1e-14, epsrel=1e-13)
    return value / p


@pytest.mark.parametrize("dt_s", [0.01, 0.2])  # 0.2 s: p·dt = 0.25, the kernel must sub-step
def test_quarter_period_of_free_rocking(dt_s):
    theta0 = ALPHA / 2
    linearised = np.arccosh(1.0 / (1.0 - theta0 / ALPHA)) / P  # θ'' = p²(θ − α): Housner's closed form
    exact = exact_quarter_period(theta0, ALPHA, P)
    assert linearised == pytest.approx(1.0536, abs=1e-4)
    assert exact == pytest.approx(1.0544, abs=1e-4)
    assert exact - linearised > 5e-4  # the nonlinearity (sin, cos kept) lengthens the quarter period

    result = rocking_response(np.zeros(round(3.0 / dt_s) + 1), dt_s, ALPHA, P, initial_theta_rad=theta0,
                              return_history=True)
    first_impact_s = result.impact_time_s[0]
    assert abs(first_impact_s - 1.0544) < 1e-3
    assert first_impact_s == pytest.approx(exact, abs=1e-6)
    assert abs(first_impact_s - linearised) > 5e-4


def test_free_rocking_decay_follows_restitution_and_energy():
    theta0 = ALPHA / 2
    result = rocking_response(np.zeros(1501), 0.01, ALPHA, P, initial_theta_rad=theta0, return_history=True)
    omega = result.impact_theta_dot_rad_s[:8]  # just before each impact
    # first impact velocity from energy conservation: ½θ̇² = p²[cos(α − θ0) − cos α]
    omega_1 = -P * np.sqrt(2.0 * (np.cos(ALPHA - theta0) - np.cos(ALPHA)))
    assert omega[0] == pytest.approx(omega_1, rel=1e-6)
    # free rocking conserves energy between impacts, so each impact scales |θ̇| by e, sign alternating
    np.testing.assert_allclose(omega[1:] / omega[:-1], -E, rtol=1e-6)
    # peak after impact n: cos(α − |θ_peak|) = cos α + ½(e θ̇_n / p)²
    expected_peaks = ALPHA - np.arccos(np.cos(ALPHA) + 0.5 * (E * omega[:7] / P) ** 2)
    peaks = result.peak_theta_rad[:7]
    np.testing.assert_allclose(np.abs(peaks), expected_peaks, rtol=1e-6)
    assert np.all(np.sign(peaks) == np.sign(omega[:7]))  # θ̇ keeps its sign through the impact
    assert result.theta_max_over_alpha == pytest.approx(0.5, rel=1e-12)


@pytest.mark.parametrize("kappa", [4.0 / 3.0, 1.6])
def test_restitution_override(kappa):
    e = float(housner_restitution(ALPHA, kappa))
    result = rocking_response(np.zeros(801), 0.01, ALPHA, P, restitution=e, initial_theta_rad=ALPHA / 2,
                              return_history=True)
    omega = result.impact_theta_dot_rad_s[:5]
    np.testing.assert_allclose(omega[1:] / omega[:-1], -e, rtol=1e-6)
    elastic = rocking_response(np.zeros(801), 0.01, ALPHA, P, restitution=1.0, initial_theta_rad=ALPHA / 2,
                               return_history=True)
    np.testing.assert_allclose(np.abs(elastic.peak_theta_rad), ALPHA / 2, rtol=1e-6)


# ------------------------------------------------------------------ uplift, sign convention, rest
@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_no_uplift_below_tan_alpha(sign):
    time_s = np.arange(0.0, 10.0, 0.01)
    below = sign * 0.999 * np.tan(ALPHA) * np.sin(2 * np.pi * 0.5 * time_s)
    result = rocking_response(below, 0.01, ALPHA, P, return_history=True)
    assert result.uplift is False and result.overturned is False
    assert result.theta_max_over_alpha == 0.0 and result.impacts == 0
    assert np.all(result.theta_rad == 0.0)
    above = rocking_response(below * 1.01 / 0.999, 0.01, ALPHA, P)
    assert above.uplift is True and above.theta_max_over_alpha > 0.0


def test_sign_convention_positive_floor_acceleration_drives_negative_rotation():
    dt = 0.01
    accel = np.where(np.arange(300) * dt < 0.3, 1.5 * np.tan(ALPHA), 0.0)
    result = rocking_response(accel, dt, ALPHA, P, return_history=True)
    first_motion = result.theta_rad[np.flatnonzero(result.theta_rad)[0]]
    assert first_motion < 0.0
    mirrored = rocking_response(-accel, dt, ALPHA, P, return_history=True)
    np.testing.assert_allclose(mirrored.theta_rad, -result.theta_rad, rtol=0, atol=1e-15)


def test_block_settles_and_stays_at_rest_until_threshold_is_exceeded():
    dt = 0.01
    time_s = np.arange(0.0, 70.0, dt)
    accel = np.zeros_like(time_s)
    accel[time_s < 0.5] = 0.3  # uplift, then free rocking until the block settles
    quiet = (time_s > 50.0) & (time_s < 60.0)
    accel[quiet] = 0.95 * np.tan(ALPHA) * np.sin(2 * np.pi * time_s[quiet])  # never enough to uplift
    accel[(time_s >= 60.0) & (time_s < 60.5)] = 1.2 * np.tan(ALPHA)  # enough again
    result = rocking_response(accel, dt, ALPHA, P, return_history=True)
    assert np.all(result.theta_rad[(time_s > 45.0) & (time_s < 59.9)] == 0.0)
    assert np.all(result.theta_rad[(time_s > 60.05) & (time_s < 60.6)] < 0.0)
    assert result.uplift and not result.overturned


def test_exceeding_alpha_is_not_overturning():
    """Like the FORMA incubator of the paper's Fig. 7: θ passes α and the block recovers."""
    accel, dt = pulse_record("A", 6.0, 9.5)
    result = rocking_response(accel, dt, ALPHA, P)
    reference = reference_rocking(accel, dt, ALPHA, P, E)
    assert result.theta_max_over_alpha > 1.2 and not result.overturned
    assert reference["theta_max_over_alpha"] > 1.2 and not reference["overturned"]


# ------------------------------------------------------------------ kernel vs independent reference
STRONG_MOTIONS = [("A", 2.0, 1.2), ("A", 4.0, 3.0), ("B", 2.0, 1.2), ("B", 4.0, 3.0),
                  ("C", 2.0, 2.0), ("C", 4.0, 3.0), ("synthetic", 0, 0.3), ("synthetic", 0, 0.6),
                  ("synthetic", 2, 0.6)]


@pytest.mark.parametrize("kind, parameter, amplitude", STRONG_MOTIONS)
def test_kernel_matches_independent_reference(kind, parameter, amplitude):
    if kind == "synthetic":
        accel, dt = synthetic_record(parameter, amplitude), 0.01
    else:
        accel, dt = pulse_record(kind, parameter, amplitude)
    result = rocking_response(accel, dt, ALPHA, P)
    reference = reference_rocking(accel, dt, ALPHA, P, E)
    inputs = f"{kind} {parameter} {amplitude}"
    assert result.uplift, inputs
    assert result.overturned == reference["overturned"], inputs
    if result.overturned:
        assert result.overturn_time_s == pytest.approx(reference["overturn_time_s"], abs=1e-3), inputs
    else:
        assert result.theta_max_over_alpha == pytest.approx(reference["theta_max_over_alpha"], rel=0.01), inputs


def test_small_stiff_block_on_coarse_record_matches_reference():
    """p·dt = 0.25: the sample interval is split into Runge-Kutta sub-steps."""
    accel, dt, alpha, p = synthetic_record(5, 0.33, n=750, dt_s=0.02), 0.02, 0.25, 12.5
    result = rocking_response(accel, dt, alpha, p)
    reference = reference_rocking(accel, dt, alpha, p, float(housner_restitution(alpha)))
    assert result.uplift and not reference["overturned"] and not result.overturned
    assert result.theta_max_over_alpha == pytest.approx(reference["theta_max_over_alpha"], rel=1e-6)


# ------------------------------------------------------------------ Froude similitude
def test_froude_similitude():
    accel = synthetic_record(3, 0.6)
    full = rocking_response(accel, 0.01, 0.2, P, return_history=True)
    # lengths × 1/4: R/4, so p = sqrt(3g/4R) doubles, α unchanged; time compressed by 2
    model = rocking_response(accel, 0.005, 0.2, 2 * P, return_history=True)
    assert full.uplift and full.impacts > 5
    assert model.theta_max_over_alpha == pytest.approx(full.theta_max_over_alpha, rel=1e-9)
    assert model.impacts == full.impacts and model.overturned == full.overturned
    np.testing.assert_allclose(model.theta_rad / 0.2, full.theta_rad / 0.2, rtol=0, atol=1e-9)
    np.testing.assert_allclose(model.impact_time_s, full.impact_time_s / 2, rtol=1e-9)


# ------------------------------------------------------------------ batch
def test_batch_equals_single_runs():
    records = [synthetic_record(1, 0.6), pulse_record("A", 4.0, 3.0)[0][::2]]
    dts = [0.01, 2 * pulse_record("A", 4.0, 3.0)[1]]
    alphas, ps = np.array([0.16, 0.25, 0.1]), np.array([1.25, 2.0, 3.0])
    peaks = rocking_peaks_batch(records, dts, alphas, ps)
    assert peaks.theta_max_over_alpha.shape == (3, 2)
    for i in range(3):
        for j in range(2):
            single = rocking_response(records[j], dts[j], alphas[i], ps[i])
            assert peaks.theta_max_over_alpha[i, j] == single.theta_max_over_alpha
            assert peaks.overturned[i, j] == single.overturned and peaks.impacts[i, j] == single.impacts
            assert peaks.uplift[i, j] == single.uplift
            np.testing.assert_equal(peaks.overturn_time_s[i, j], single.overturn_time_s)
    assert peaks.overturned.any() and not peaks.overturned.all()


def test_invalid_input_is_rejected():
    with pytest.raises(ValueError):
        rocking_response([0.0, np.nan], 0.01, ALPHA, P)
    with pytest.raises(ValueError):
        rocking_response([0.0, 0.1], 0.01, 2.0, P)
    with pytest.raises(ValueError):
        rocking_response([0.0, 0.1], -0.01, ALPHA, P)
    with pytest.raises(ValueError):
        rocking_response([0.0, 0.1], 0.01, ALPHA, P, restitution=1.5)


# ------------------------------------------------------------------ overturning spectrum (paper Fig. 6)
OMEGA_RATIOS = (1.0, 2.0, 3.0, 4.0, 6.0, 8.0, 10.0, 12.0)
AMPLITUDE_GRID = np.round(np.arange(1.0, 40.0, 0.1), 10)  # ap/(αg)


def overturning_scan(omega_ratio):
    """Overturned flags of the block under Type-A pulses of every amplitude of the grid."""
    records, dts = zip(*(pulse_record("A", omega_ratio, a) for a in AMPLITUDE_GRID))
    return rocking_peaks_batch(list(records), list(dts), ALPHA, P).overturned[0]


def minimum_overturning(omega_ratio, overturned):
    """Smallest ap/(αg) that overturns, bisected to 1e-4 inside the first grid bracket."""
    first = int(np.argmax(overturned))
    assert overturned[first] and first > 0
    low, high = AMPLITUDE_GRID[first - 1], AMPLITUDE_GRID[first]
    while high - low > 1e-4:
        middle = 0.5 * (low + high)
        if rocking_response(*pulse_record("A", omega_ratio, middle), ALPHA, P).overturned:
            high = middle
        else:
            low = middle
    return high


@pytest.fixture(scope="module")
def spectrum():
    scans = {w: overturning_scan(w) for w in OMEGA_RATIOS}
    return scans, {w: minimum_overturning(w, scans[w]) for w in OMEGA_RATIOS}


def test_minimum_overturning_acceleration_rises_with_pulse_frequency(spectrum):
    _, minimum = spectrum
    values = np.array([minimum[w] for w in OMEGA_RATIOS])
    print("ap/(alpha g) minimum overturning:", dict(zip(OMEGA_RATIOS, np.round(values, 3))))
    assert np.all(np.diff(values) > 0.0)
    assert np.all(values > np.tan(ALPHA) / ALPHA)  # a pulse below g tan α cannot even uplift


def test_overturning_spectrum_is_multivalued(spectrum):
    scans, minimum = spectrum
    multivalued = [w for w in OMEGA_RATIOS if not scans[w][AMPLITUDE_GRID > minimum[w]].all()]
    assert multivalued, "no safe region above the minimum overturning acceleration"
    omega_ratio = 6.0
    assert omega_ratio in multivalued
    over = scans[omega_ratio]
    ap1 = AMPLITUDE_GRID[np.argmax(over)]
    ap2 = AMPLITUDE_GRID[(AMPLITUDE_GRID > ap1) & ~over][0]  # survives a larger pulse
    print(f"omega_p/p = {omega_ratio}: overturns at ap/(alpha g) = {ap1:.1f}, survives {ap2:.1f}")
    for amplitude, overturns in ((ap1, True), (ap2, False)):
        accel, dt = pulse_record("A", omega_ratio, amplitude)
        assert rocking_response(accel, dt, ALPHA, P).overturned is overturns
        assert reference_rocking(accel, dt, ALPHA, P, E)["overturned"] is overturns


@pytest.mark.parametrize("omega_ratio", [2.0, 6.0, 10.0])
def test_minimum_overturning_matches_reference(spectrum, omega_ratio):
    _, minimum = spectrum
    for factor, overturns in ((0.99, False), (1.01, True)):
        accel, dt = pulse_record("A", omega_ratio, factor * minimum[omega_ratio])
        assert rocking_response(accel, dt, ALPHA, P).overturned is overturns
        assert reference_rocking(accel, dt, ALPHA, P, E)["overturned"] is overturns


# ------------------------------------------------------------------ pivot forces (validity of pure rocking)
def test_pivot_forces_match_newton_on_the_computed_motion():
    """|F|/N and N/(mg) reported by the kernel equal m·(CM acceleration) by finite differences.

    The centre of mass of a block pivoting on corner s sits at
    (−s b cos θ + h sin θ, s b sin θ + h cos θ) from the pivot; differentiating
    the kernel's θ history twice (before the first impact, where θ is smooth)
    gives F = m(ẍ + ü_g) and N = m(ÿ + g) without the kernel's force formula.
    """
    from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2 as g
    alpha, p = 0.2, 2.0
    radius = 3 * g / (4 * p**2)
    b, h = radius * np.sin(alpha), radius * np.cos(alpha)
    dt = 2e-4
    time_s = np.arange(0.0, 1.2, dt)
    accel = pulse_acceleration("A", 0.45, 1.0, time_s)
    full = rocking_response(accel, dt, alpha, p, return_history=True)
    assert full.impacts > 0
    n_cut = int(full.impact_time_s[0] / dt) - 2
    cut = rocking_response(accel[:n_cut], dt, alpha, p, return_history=True)
    theta = cut.theta_rad
    side = np.sign(theta[np.argmax(np.abs(theta))])
    x_cm = -side * b * np.cos(theta) + h * np.sin(theta)
    y_cm = side * b * np.sin(theta) + h * np.cos(theta)
    xdd = np.gradient(np.gradient(x_cm, dt), dt)[3:-3]
    ydd = np.gradient(np.gradient(y_cm, dt), dt)[3:-3]
    lifted = np.abs(theta[3:-3]) > 1e-6
    friction = xdd / g + accel[:n_cut][3:-3]
    normal = 1.0 + ydd / g
    demand = np.abs(friction[lifted]) / normal[lifted]
    assert cut.uplift and not cut.overturned
    assert cut.friction_demand_max == pytest.approx(demand.max(), rel=2e-3)
    assert cut.normal_force_min_over_weight == pytest.approx(normal[lifted].min(), rel=2e-3)


def test_friction_demand_at_onset_is_shenton_requirement():
    """Just after uplift under a constant floor acceleration A the pivot needs μ_req(A) (Shenton 1996, eq. 14)."""
    from assess.mechanics.modes import friction_required_to_rock
    alpha, p, accel_g = 0.25, 2.0, 0.4
    result = rocking_response([accel_g, accel_g], 1e-6, alpha, p)
    shenton = (accel_g * (4 * np.tan(alpha)**2 + 1) + 3 * np.tan(alpha)) / (
        np.tan(alpha)**2 + 4 + 3 * accel_g * np.tan(alpha))
    assert result.uplift
    assert result.friction_demand_max == pytest.approx(shenton, rel=1e-4)
    assert result.friction_demand_max == pytest.approx(friction_required_to_rock(accel_g, np.tan(alpha)), rel=1e-4)


def test_stopping_when_pure_rocking_fails_keeps_the_held_runs_and_the_verdict():
    """``rocking_case_peaks(mu_static=)`` stops a run once |F|/N > μs or N ≤ 0: the runs that held
    are those of the full kernel, bit for bit, and every stopped run is one the full run rejects
    (μs from 0.2 to 1.2 under synthetic records of 0.25, 0.4 and 0.7 g)."""
    from assess.mechanics.rocking import rocking_case_peaks

    records = [synthetic_record(seed, pga) for seed, pga in ((1, 0.25), (2, 0.4), (3, 0.7))]
    mu_static = np.repeat(np.linspace(0.2, 1.2, 11), len(records))
    index = np.tile(np.arange(len(records)), 11)
    full = rocking_case_peaks(records, 0.01, index, ALPHA, P, tail_s=5.0)
    stopped = rocking_case_peaks(records, 0.01, index, ALPHA, P, tail_s=5.0, mu_static=mu_static)
    held_full = (full.friction_demand_max <= mu_static) & (full.normal_force_min_over_weight > 0.0)
    held_stopped = (stopped.friction_demand_max <= mu_static) & (stopped.normal_force_min_over_weight > 0.0)
    assert held_full.any() and (~held_full).any()
    np.testing.assert_array_equal(held_stopped, held_full)
    for field in ("theta_max_over_alpha", "uplift", "overturned", "impacts", "friction_demand_max"):
        np.testing.assert_array_equal(getattr(stopped, field)[held_full], getattr(full, field)[held_full])
    # and the case kernel is the block-by-record kernel, case by case
    batch = rocking_peaks_batch(records, 0.01, ALPHA, P, tail_s=5.0)
    np.testing.assert_array_equal(full.theta_max_over_alpha[:3], batch.theta_max_over_alpha[0])
