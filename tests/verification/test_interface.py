"""Sliding on richer interfaces (assess.mechanics.interface), checked against independent results.

Velocity-dependent friction (Constantinou et al. 1990):
  * μmin = μmax is Coulomb: equals the exact kernel ``sliding_response`` and
    Newmark's rectangular-pulse closed form, on pulses and on pyslammer's records;
  * rate → ∞ with μs = μmax tends to Coulomb μmax (records);
  * a rectangular pulse with μ(v) against scipy ``solve_ivp`` (events on u̇ = 0),
    and its run-out time against the closed form of ∫ dv/μ(v);
  * one-way pulses: μmin Coulomb ≥ μ(v) ≥ μmax Coulomb.
Elastic-perfectly-plastic interface ("elastic legs", paper §5):
  * below yield it is a linear oscillator: closed form (undamped sine from rest)
    and ``solve_ivp`` (damped, same piecewise-linear input);
  * u_y → 0 tends to ``sliding_response`` (rectangular pulse and records, 1 %);
  * rectangular pulse: the excess over Newmark's Umax follows the asymptotic
    closed form derived in ``epp_pulse_excess`` (∝ √u_y, not ∝ u_y).
"""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2 as G
from assess.mechanics.interface import elastic_interface_response, velocity_friction_response
from assess.mechanics.sliding import SlidingResult, sliding_response

RECORDS = ("Nahanni_1985_NS1-280", "Coalinga_1983_PVB-045")


def newmark_umax(ap_g, tp_s, mu):
    """Newmark (1965) rectangular pulse: Umax = ½ g Tp² (ap - μ) ap / μ [m]."""
    return 0.5 * G * tp_s ** 2 * (ap_g - mu) * ap_g / mu


@pytest.fixture(scope="module")
def records():
    pyslammer = pytest.importorskip("pyslammer")
    motions = pyslammer.sample_ground_motions()  # test-only peer data: accel in g, dt in s
    return {name: (np.asarray(motions[name].accel, dtype=float), float(motions[name].dt)) for name in RECORDS}


# ----------------------------------------------------------------------------- velocity-dependent friction
def test_returns_sliding_result_with_history():
    accel = 0.3 * np.sin(np.linspace(0.0, 2 * np.pi, 201))
    for result in (velocity_friction_response(accel, 0.01, 0.1, 0.2, 30.0, return_history=True),
                   elastic_interface_response(accel, 0.01, 0.1, 0.002, return_history=True)):
        assert isinstance(result, SlidingResult)
        assert result.sliding_m.shape == result.time_s.shape == (201,)
        assert result.sliding_max_m == pytest.approx(max(result.sliding_max_positive_m,
                                                         result.sliding_max_negative_m))


@pytest.mark.parametrize("ap_g, tp_s, mu, samples", [(0.5, 1.0, 0.25, 1), (0.4, 0.3, 0.1, 7), (1.0, 0.2, 0.3, 50)])
def test_constant_friction_is_newmark(ap_g, tp_s, mu, samples):
    result = velocity_friction_response(np.full(samples + 1, ap_g), tp_s / samples, mu, mu, 30.0)
    assert result.sliding_max_m == pytest.approx(newmark_umax(ap_g, tp_s, mu), rel=1e-9)
    assert result.sliding_residual_m == pytest.approx(-newmark_umax(ap_g, tp_s, mu), rel=1e-9)
    assert result.slide_time_s == pytest.approx(tp_s * ap_g / mu, rel=1e-9)


@pytest.mark.parametrize("name", RECORDS)
@pytest.mark.parametrize("mu, mu_static", [(0.1, None), (0.05, 0.08)])
def test_constant_friction_equals_coulomb_kernel_on_records(records, name, mu, mu_static):
    accel, dt = records[name]
    expected = sliding_response(accel, dt, mu, mu_static, return_history=True)
    result = velocity_friction_response(accel, dt, mu, mu, 25.0, mu_static, return_history=True)
    assert expected.sliding_max_m > 0.005
    for field in ("sliding_max_m", "sliding_residual_m", "sliding_max_positive_m",
                  "sliding_max_negative_m", "slide_time_s"):
        assert getattr(result, field) == pytest.approx(getattr(expected, field), rel=1e-3, abs=1e-6), field
    np.testing.assert_allclose(result.sliding_m, expected.sliding_m, atol=1e-3 * expected.sliding_max_m)


@pytest.mark.parametrize("name", RECORDS)
def test_infinite_rate_tends_to_coulomb_mu_max(records, name):
    """μ(v) = μmax for any v > 0 as the rate grows; with μs = μmax this is Coulomb μmax.

    Measured relative error of the peak: 2 % / 1 % at a = 1e3 s/m, 0.4 % / 0.2 % at
    1e4, 0.06 % / 0.03 % at 1e5 (Nahanni / Coalinga).
    """
    accel, dt = records[name]
    expected = sliding_response(accel, dt, 0.15)
    result = velocity_friction_response(accel, dt, 0.05, 0.15, 1e5, mu_static=0.15)
    assert result.sliding_max_m == pytest.approx(expected.sliding_max_m, rel=1e-3)
    assert result.sliding_residual_m == pytest.approx(expected.sliding_residual_m, rel=2e-3)


def ivp_rectangular_pulse(ap_g, tp_s, mu_min, mu_max, rate):
    """Peak |u| [m] and slide time [s] of a rectangular pulse with μ(v), by solve_ivp.

    The block slides backwards (u̇ < 0) from t = 0 (ap > μmin = μs) through the
    pulse, then runs out on a floor at rest until u̇ = 0.
    """
    def friction(speed):
        return mu_max - (mu_max - mu_min) * np.exp(-rate * speed)

    opts = dict(rtol=1e-11, atol=1e-13, method="DOP853")
    pulse = solve_ivp(lambda t, y: [y[1], -G * (ap_g - friction(-y[1]))], (0.0, tp_s), [0.0, 0.0], **opts)
    stop = lambda t, y: y[1]
    stop.terminal, stop.direction = True, 1.0
    runout = solve_ivp(lambda t, y: [y[1], G * friction(-y[1])], (tp_s, tp_s + 100.0), pulse.y[:, -1],
                       events=stop, **opts)
    return -runout.y[0, -1], runout.t[-1], -pulse.y[1, -1]


@pytest.mark.parametrize("ap_g, tp_s, mu_min, mu_max, rate", [(0.5, 1.0, 0.1, 0.25, 30.0),
                                                              (0.3, 0.5, 0.05, 0.2, 5.0),
                                                              (0.8, 0.25, 0.1, 0.3, 100.0)])
def test_rectangular_pulse_against_solve_ivp(ap_g, tp_s, mu_min, mu_max, rate):
    peak, slide_time, speed = ivp_rectangular_pulse(ap_g, tp_s, mu_min, mu_max, rate)
    result = velocity_friction_response([ap_g, ap_g], tp_s, mu_min, mu_max, rate)
    assert result.sliding_max_m == pytest.approx(peak, rel=1e-6)
    assert result.sliding_residual_m == pytest.approx(-peak, rel=1e-6)
    assert result.slide_time_s == pytest.approx(slide_time, rel=1e-6)
    # run-out time in closed form: (1/g)∫0^v dw/μ(w) = v/(g μmax) + ln(μ(v)/μmin)/(g μmax a)
    mu_v = mu_max - (mu_max - mu_min) * np.exp(-rate * speed)
    runout = speed / (G * mu_max) + np.log(mu_v / mu_min) / (G * mu_max * rate)
    assert result.slide_time_s - tp_s == pytest.approx(runout, rel=1e-6)


@pytest.mark.parametrize("shape", ["rectangular", "half-sine"])
@pytest.mark.parametrize("rate", [3.0, 30.0, 300.0])
def test_velocity_friction_bounded_by_coulomb(shape, rate):
    """One-way pulses: the slip is monotone in μ, so μmin ≤ μ(v) ≤ μmax brackets it.

    (On two-way records the bracket need not hold, and does not always: the peak of
    two-way sliding is not monotone in μ; e.g. Coalinga, μ 0.05-0.15, a = 30 s/m:
    0.065 m against 0.072 m for Coulomb μmax, since the block starts to slide at
    μs = μmin = 0.05 in both directions.)
    """
    time = np.linspace(0.0, 0.8, 401)
    accel = np.full_like(time, 0.6) if shape == "rectangular" else 0.6 * np.sin(np.pi * time / 0.8)
    dt = time[1]
    low = sliding_response(accel, dt, 0.1).sliding_max_m
    high = sliding_response(accel, dt, 0.3).sliding_max_m
    result = velocity_friction_response(accel, dt, 0.1, 0.3, rate).sliding_max_m
    assert high < result < low


def test_velocity_friction_rejects_bad_input():
    with pytest.raises(ValueError):
        velocity_friction_response([0.5, 0.5], 1.0, 0.2, 0.1, 30.0)  # μmax < μmin
    with pytest.raises(ValueError):
        velocity_friction_response([0.5, 0.5], 1.0, 0.1, 0.2, 30.0, mu_static=0.05)
    with pytest.raises(ValueError):
        velocity_friction_response([0.5, np.nan], 1.0, 0.1, 0.2, 30.0)


# ----------------------------------------------------------------------------- elastic-perfectly-plastic interface
def test_below_yield_is_undamped_oscillator_closed_form():
    """a_g = A sin Ωt from rest, ζ = 0: u = -gA/(ω² - Ω²) (sin Ωt - (Ω/ω) sin ωt)."""
    mu, u_y, amplitude_g, big_omega = 0.2, 0.002, 0.05, 2 * np.pi * 1.5
    omega = np.sqrt(mu * G / u_y)
    dt = 5e-4
    time = np.arange(0.0, 4.0 + dt / 2, dt)
    accel = amplitude_g * np.sin(big_omega * time)
    result = elastic_interface_response(accel, dt, mu, u_y, return_history=True, damping_ratio=0.0)
    exact = -G * amplitude_g / (omega ** 2 - big_omega ** 2) * (
        np.sin(big_omega * time) - big_omega / omega * np.sin(omega * time))
    scale = np.abs(exact).max()
    assert scale < 0.6 * u_y  # stays elastic
    np.testing.assert_allclose(result.sliding_m, exact, atol=1e-4 * scale)
    assert result.sliding_max_m == pytest.approx(scale, rel=1e-3)
    assert result.sliding_residual_m == 0.0 and result.slide_time_s == 0.0


def test_below_yield_damped_oscillator_against_solve_ivp():
    mu, u_y, zeta = 0.3, 0.005, 0.05
    omega = np.sqrt(mu * G / u_y)
    rng = np.random.default_rng(7)
    dt = 0.01
    accel = np.convolve(rng.normal(0.0, 0.05, 400), np.ones(5) / 5, mode="same")  # |a| well below μ
    result = elastic_interface_response(accel, dt, mu, u_y, return_history=True, damping_ratio=zeta)
    time = np.arange(accel.size) * dt
    sol = solve_ivp(lambda t, y: [y[1], -G * np.interp(t, time, accel) - omega ** 2 * y[0] - 2 * zeta * omega * y[1]],
                    (0.0, time[-1]), [0.0, 0.0], t_eval=time, rtol=1e-10, atol=1e-13, method="DOP853",
                    max_step=dt / 4)
    assert np.abs(sol.y[0]).max() < 0.8 * u_y
    np.testing.assert_allclose(result.sliding_m, sol.y[0], atol=1e-4 * np.abs(sol.y[0]).max())
    assert result.slide_time_s == 0.0


def epp_pulse_excess(ap_g, tp_s, mu, u_y):
    """Leading term of (peak |u| of the EPP interface - Newmark Umax) for a rectangular pulse, ζ = 0.

    Derived for this test: under the step ap the spring loads as e = -r u_y (1 - cos ωt),
    r = ap/μ, and yields at θ = ωt_y = arccos(1 - 1/r) with speed r u_y ω sin θ, while the
    Coulomb block has reached (r - 1) u_y ω θ. The excess speed δv = u_y ω (r sin θ - (r - 1)θ)
    persists through the pulse (δv Tp) and lengthens the run-out by δv·v1/(μg) = δv Tp (r - 1):
    δU ≈ r Tp δv ∝ √u_y (ω u_y = √(μ g u_y)); the remainder is O(u_y).
    """
    r = ap_g / mu
    theta = np.arccos(1.0 - 1.0 / r)
    omega = np.sqrt(mu * G / u_y)
    return r * tp_s * u_y * omega * (r * np.sin(theta) - (r - 1.0) * theta)


@pytest.mark.parametrize("ap_g, tp_s, mu", [(0.5, 1.0, 0.25), (0.6, 0.5, 0.1)])
@pytest.mark.parametrize("u_y", [1e-6, 1e-4, 1e-3])
def test_rectangular_pulse_excess_over_newmark(ap_g, tp_s, mu, u_y):
    """Peak |u| = Umax + δU(√u_y) + O(u_y): the legs add slip ∝ √u_y, not ∝ u_y.

    Measured (0.5 g, 1 s, μ 0.25): δU/√u_y = 2.14 m^½ for u_y = 1e-7 ... 1e-3 m
    (6.8e-4 m at 1e-7, 0.068 m at 1e-3); slower growth at large u_y (0.95 m at 0.2 m).
    """
    result = elastic_interface_response([ap_g, ap_g], tp_s, mu, u_y, damping_ratio=0.0)
    umax = newmark_umax(ap_g, tp_s, mu)
    excess = epp_pulse_excess(ap_g, tp_s, mu, u_y)
    assert result.sliding_max_m - umax == pytest.approx(excess, abs=0.1 * u_y)  # measured: -0.03 u_y
    # the peak is at the end of the slip, legs bent by u_y; then they relax to the slip z
    assert result.sliding_max_m == pytest.approx(-result.sliding_residual_m + u_y, rel=1e-9)


@pytest.mark.parametrize("damping_ratio", [0.0, 0.05])
def test_small_yield_displacement_tends_to_newmark(damping_ratio):
    """u_y = 1e-7 m: within 0.03 % of Umax (the excess decays as √u_y)."""
    result = elastic_interface_response([0.5, 0.5], 1.0, 0.25, 1e-7, damping_ratio=damping_ratio)
    assert result.sliding_max_m == pytest.approx(newmark_umax(0.5, 1.0, 0.25), rel=1e-3)
    assert result.slide_time_s == pytest.approx(2.0, rel=1e-3)


@pytest.mark.parametrize("name", RECORDS)
def test_small_yield_displacement_tends_to_coulomb_on_records(records, name):
    """Relative error of the peak (Nahanni / Coalinga, μ = 0.1, ζ = 0.05):
    u_y = 1e-4: 9 % / 4.5 %; 1e-5: 6 % / 3 %; 1e-6: 2 % / 1 %; 1e-7: 0.7 % / 0.3 %.

    The convergence is slow (≈ √u_y): after each stop the bent legs throw the block
    back with a speed ~ √(μ g u_y) and it can slip again where Coulomb would stick.
    """
    accel, dt = records[name]
    expected = sliding_response(accel, dt, 0.1)
    result = elastic_interface_response(accel, dt, 0.1, 1e-7)
    assert result.sliding_max_m == pytest.approx(expected.sliding_max_m, rel=0.01)
    assert result.sliding_residual_m == pytest.approx(expected.sliding_residual_m, rel=0.02)


def test_elastic_interface_rejects_bad_input():
    with pytest.raises(ValueError):
        elastic_interface_response([0.5, 0.5], 1.0, 0.25, 0.0)
    with pytest.raises(ValueError):
        elastic_interface_response([0.5, 0.5], 1.0, 0.25, 1e-3, damping_ratio=-0.1)
