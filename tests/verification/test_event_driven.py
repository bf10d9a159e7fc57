"""Event-driven general solver (assess.mechanics.event_driven), each figure against an outside reference.

1. Pure sliding (μs < b/h): Newmark's rectangular pulse in closed form (paper eq. 6,
   tests/data/newmark/) and the exact sliding kernel on pyslammer's real records.
2. Pure rocking (μ = 2): Housner's free rocking (quarter period by quadrature, decay by
   the restitution, Housner's or the override) and the rocking kernel under pulses and
   a record.
3. Mode initiation from rest: Shenton's (1996) criteria, ``modes.initial_mode``.
4. Slide-rock and flight: the energy balance over whole runs and the impulse laws of
   every impact, computed here from the solver's trace of states and contact forces.
5. Froude similitude; 6. overturning, and surviving θ > α, as the rocking kernel.
"""
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from scipy import integrate

from assess.hazard.pulses import pulse_acceleration
from assess.mechanics.block import Block, corner_positions
from assess.mechanics.event_driven import _simulate, simulate_event_driven
from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2 as G
from assess.mechanics.geometry import housner_restitution
from assess.mechanics.modes import initial_mode
from assess.mechanics.rocking import rocking_response
from assess.mechanics.sliding import sliding_response

NEWMARK = Path(__file__).resolve().parents[1] / "data" / "newmark" / "rectangular_pulse.csv"
ALPHA, P = 0.16, 1.25  # the block of the paper's section 3.2 (Figs. 5, 6)
ROCKER = Block.uniform(ALPHA, P, mu=2.0)


@pytest.fixture(scope="module")
def records():
    pyslammer = pytest.importorskip("pyslammer")
    motions = pyslammer.sample_ground_motions()  # pyslammer's own loader (accel in g, dt in s)
    return {name: (np.asarray(m.accel, dtype=float), float(m.dt)) for name, m in motions.items()}


def rocking_pulse(pulse, omega_ratio, ap_over_alpha_g, free_s=12.0):
    """Pulse of frequency ωp = omega_ratio·p, amplitude (ap/αg)·α g, then free rocking [g], dt."""
    tp_s = 2 * np.pi / (omega_ratio * P)
    dt_s = min(tp_s / 200.0, 0.01)
    time_s = np.arange(0.0, tp_s + free_s / P, dt_s)
    return pulse_acceleration(pulse, ap_over_alpha_g * ALPHA, tp_s, time_s), dt_s


# ----------------------------------------------------------------------------- 1. pure sliding
def test_newmark_rectangular_pulse_closed_form():
    """Π1 = Umax ωp²/ap = 2π²(1/Π2 − 1) (paper eq. 6), rectangle [ap, ap] at dt = Tp, to 0.5 %."""
    rows = pd.read_csv(NEWMARK, comment="#")
    worst = 0.0
    for row in rows.itertuples():
        mu = row.in_pi2 * row.in_ap_g
        block = Block(half_width_m=1.0, cg_height_m=0.5, height_m=1.0, mu=mu)  # b/h = 2 > μs
        run_out_s = row.in_tp_s / row.in_pi2  # the block stops at ap Tp/(μg)
        result = simulate_event_driven(block, [row.in_ap_g, row.in_ap_g], row.in_tp_s, tail_s=2 * run_out_s)
        pi1 = result.sliding_max_m * (2 * np.pi / row.in_tp_s) ** 2 / (row.in_ap_g * G)
        worst = max(worst, abs(pi1 / row.exp_pi1 - 1.0))
        assert abs(pi1 / row.exp_pi1 - 1.0) <= 0.005, row
        assert result.sliding_residual_m == pytest.approx(-result.sliding_max_m, rel=1e-9)
        assert result.mode == "slide" and not result.uplift and result.theta_max_over_alpha == 0.0
        # slides from t = 0 until ap Tp/(μg) after the start, then rests
        assert [m for _, m in result.mode_sequence] == ["rest", "slide", "rest"]
        assert result.mode_sequence[2][0] == pytest.approx(row.in_tp_s / row.in_pi2, rel=1e-9)
    print(f"Newmark rectangle: worst relative error of Pi1 {worst:.2e}")


def test_sliding_matches_exact_kernel_on_records(records):
    """Every pyslammer record, μ = 0.1 (μs = 0.1, 0.15): peak and residual as the exact kernel.

    The brief's bar is 1e-3; both solve the same piecewise-linear problem, one in closed
    form, so they agree to the integration tolerance (found: 4e-13 relative).
    """
    worst = 0.0
    for name, (accel, dt) in sorted(records.items()):
        for mu_static in (None, 0.15):
            block = Block(half_width_m=0.4, cg_height_m=1.0, height_m=2.0, mu=0.1, mu_static=mu_static)
            result = simulate_event_driven(block, accel, dt, return_history=True)
            exact = sliding_response(accel, dt, 0.1, mu_static, return_history=True)
            scale = exact.sliding_max_m
            assert result.sliding_max_m == pytest.approx(scale, rel=1e-3), name
            assert result.sliding_residual_m == pytest.approx(exact.sliding_residual_m, abs=1e-3 * scale), name
            worst = max(worst, abs(result.sliding_max_m - scale) / scale,
                        np.abs(result.sliding_m[:accel.size] - exact.sliding_m).max() / scale)
            assert result.mode == ("slide" if scale > 0 else "rest") and not result.uplift
            assert {m for _, m in result.mode_sequence} <= {"rest", "slide"}
            assert np.all(result.theta_rad == 0.0)
    print(f"sliding on records: worst relative difference from the exact kernel {worst:.1e}")
    assert worst < 1e-8


# ----------------------------------------------------------------------------- 2. pure rocking
def quarter_period(theta0, alpha, p):
    """Release at θ0 to θ = 0 in free rocking [s], by quadrature of the energy integral.

    ½θ̇² = p²[cos(α − θ) − cos(α − θ0)]; the inverse square root at θ0 is taken by QAWS.
    """
    def smooth(theta):  # the integrand times sqrt(θ0 − θ)
        return 1.0 / np.sqrt(2.0 * np.sin((2 * alpha - theta - theta0) / 2)
                             * np.sinc((theta0 - theta) / (2 * np.pi)))
    value, _ = integrate.quad(smooth, 0.0, theta0, weight="alg", wvar=(0.0, -0.5), epsabs=1e-14, epsrel=1e-13)
    return value / p


def peak_after_first_impact(theta0, alpha, p, e):
    """|θ| of the first peak after the first impact of free rocking from θ0, restitution e [rad]."""
    omega_1 = p * np.sqrt(2.0 * (np.cos(alpha - theta0) - np.cos(alpha)))  # energy
    return alpha - np.arccos(np.cos(alpha) + 0.5 * (e * omega_1 / p) ** 2)


def test_free_rocking_quarter_period():
    """From θ0 = α/2: first impact at 1.0544 s (to 0.1 %), and at the quadrature's time."""
    dt = 0.001
    result = simulate_event_driven(ROCKER, np.zeros(1201), dt, tail_s=0.0, initial_theta_rad=ALPHA / 2,
                                   return_history=True)
    theta, time_s = result.theta_rad, result.time_s
    k = np.flatnonzero(theta <= 0.0)[0]  # first sample past the impact
    t_impact = time_s[k - 1] + theta[k - 1] / (theta[k - 1] - theta[k]) * dt
    exact = quarter_period(ALPHA / 2, ALPHA, P)
    assert abs(t_impact / 1.0544 - 1.0) < 1e-3
    assert t_impact == pytest.approx(exact, abs=1e-5)
    assert result.mode_sequence[0] == (0.0, "rock") and result.sliding_max_m < 1e-12


@pytest.mark.parametrize("restitution", [None, 0.8])
def test_free_rocking_decay_follows_restitution(restitution):
    """First peak after an impact from the energy with e: Housner's (2/κ form) or the override."""
    dt = 0.001
    for block in (Block.uniform(ALPHA, P, mu=2.0, restitution=restitution),
                  Block(half_width_m=0.15, cg_height_m=0.6, height_m=1.5, mu=2.0, restitution=restitution)):
        alpha, p = block.alpha_rad, block.p_rad_s
        e = housner_restitution(alpha, block.inertia_ratio) if restitution is None else restitution
        n = int(4.5 * quarter_period(alpha / 2, alpha, p) / dt)
        result = simulate_event_driven(block, np.zeros(n), dt, tail_s=0.0, initial_theta_rad=alpha / 2,
                                       return_history=True)
        peak = -result.theta_rad.min()  # the first swing after the impact is to θ < 0
        assert peak == pytest.approx(peak_after_first_impact(alpha / 2, alpha, p, e), rel=1e-5)
        other = 0.9 if restitution is None else float(housner_restitution(alpha, block.inertia_ratio))
        assert abs(peak - peak_after_first_impact(alpha / 2, alpha, p, other)) > 1e-3 * peak


def test_free_rocking_settles_after_the_zeno_sequence():
    """Rest at the K-th impact, the first leaving |θ̇| < 1e-5·pα; at the sum of the swing times.

    Free rocking: |θ̇| before impact k is e^(k-1) ω1 (energy between impacts), so K is known
    in advance, and the time of rest is T/4(θ0) + Σ 2·T/4(θ_k), θ_k the amplitude after impact k.
    """
    e = housner_restitution(ALPHA)
    omega_1 = P * np.sqrt(2.0 * (np.cos(ALPHA / 2 - ALPHA) - np.cos(ALPHA)))
    impacts = int(np.ceil(np.log(1e-5 * P * ALPHA / omega_1) / np.log(e)))
    omega = omega_1 * e ** np.arange(1, impacts)
    amplitudes = ALPHA - np.arccos(np.cos(ALPHA) + 0.5 * (omega / P) ** 2)
    rest_time = quarter_period(ALPHA / 2, ALPHA, P) + sum(2 * quarter_period(a, ALPHA, P) for a in amplitudes)
    result, run = _simulate(ROCKER, np.zeros(2), 0.01, tail_s=60.0, initial_theta_rad=ALPHA / 2)
    assert run.log == {"impacts": impacts, "settlings": 1}
    assert [m for _, m in result.mode_sequence] == ["rock", "rest"]
    assert result.mode_sequence[-1][0] == pytest.approx(rest_time, rel=1e-6)
    assert result.sliding_residual_m == pytest.approx(0.0, abs=1e-12)


def test_impact_angular_velocity_ratio_is_housner():
    """θ̇ after/before a rocking impact (trace of states) = 1 − (2/κ) sin²α, for two inertia ratios."""
    for block in (ROCKER, Block(half_width_m=0.15, cg_height_m=0.6, height_m=1.5, mu=2.0)):
        _, run = _simulate(block, np.zeros(301), 0.01, tail_s=0.0, initial_theta_rad=0.5 * block.alpha_rad,
                           keep_trace=True)
        _, before, after = run.impacts[0]
        expected = housner_restitution(block.alpha_rad, block.inertia_ratio)
        assert after[5] / before[5] == pytest.approx(expected, rel=1e-9)


@pytest.mark.parametrize("pulse, omega_ratio, amplitude", [("A", 2.0, 1.2), ("B", 2.0, 1.2), ("A", 6.0, 9.5)])
def test_rocking_matches_kernel_under_pulses(pulse, omega_ratio, amplitude):
    """θmax/α to 0.5 % of the rocking kernel, no slip; ("A", 6, 9.5) passes θ > α and survives."""
    accel, dt = rocking_pulse(pulse, omega_ratio, amplitude)
    result = simulate_event_driven(ROCKER, accel, dt, tail_s=0.0)
    kernel = rocking_response(accel, dt, ALPHA, P)
    assert result.overturned is kernel.overturned is False
    assert result.theta_max_over_alpha == pytest.approx(kernel.theta_max_over_alpha, rel=0.005)
    assert result.mode == "rock" and result.sliding_max_m < 1e-9
    if amplitude > 9:
        assert result.theta_max_over_alpha > 1.2  # like the FORMA incubator of the paper's Fig. 7


def test_rocking_matches_kernel_on_record(records):
    accel, dt = records["Kobe_1995_TAK-090"]
    result = simulate_event_driven(ROCKER, accel, dt, tail_s=0.0)
    kernel = rocking_response(accel, dt, ALPHA, P)
    assert kernel.uplift and not kernel.overturned and not result.overturned
    assert result.theta_max_over_alpha == pytest.approx(kernel.theta_max_over_alpha, rel=0.005)
    assert result.mode == "rock" and result.sliding_max_m < 1e-9


@pytest.mark.parametrize("omega_ratio, amplitude", [(2.0, 3.0), (4.0, 3.0)])
def test_overturning_under_strong_pulse_as_kernel(omega_ratio, amplitude):
    """Overturns as the kernel, within 10 ms; slip starts only in the final fall (|θ| > 2α)."""
    accel, dt = rocking_pulse("A", omega_ratio, amplitude)
    result = simulate_event_driven(ROCKER, accel, dt, tail_s=0.0, return_history=True)
    kernel = rocking_response(accel, dt, ALPHA, P)
    assert result.overturned and kernel.overturned
    assert result.overturn_time_s == pytest.approx(kernel.overturn_time_s, abs=0.01)
    assert result.theta_max_over_alpha == pytest.approx(np.pi / 2 / ALPHA)
    for start, mode in result.mode_sequence:
        if mode == "slide-rock":
            assert abs(np.interp(start, result.time_s, result.theta_rad)) > 2 * ALPHA
    assert np.isnan(result.theta_rad[-1])


# ----------------------------------------------------------------------------- 3. initiation
def test_mode_entered_from_rest_follows_shenton():
    """Rectangular pulse A from rest over a grid of μ = μs, b/h, A and two inertia ratios."""
    count = {}
    for h_over_height in (0.5, 0.35):
        for b_over_h in (0.15, 0.25, 0.4, 0.7, 1.0):
            block0 = Block(half_width_m=b_over_h, cg_height_m=1.0, height_m=1.0 / h_over_height, mu=0.1)
            kappa = block0.inertia_ratio
            for mu in (0.1, 0.2, 0.3, 0.45, 0.6, 0.9, 1.2):
                block = Block(block0.half_width_m, block0.cg_height_m, block0.height_m, mu=mu)
                for amplitude in (0.05, 0.12, 0.22, 0.35, 0.5, 0.8, 1.2, 2.0):
                    result = simulate_event_driven(block, [amplitude, amplitude], 0.01, tail_s=0.0)
                    entered = result.mode_sequence[1][1] if len(result.mode_sequence) > 1 else "rest"
                    expected = initial_mode(amplitude, mu, b_over_h, kappa)
                    assert entered == expected, (h_over_height, b_over_h, mu, amplitude)
                    count[expected] = count.get(expected, 0) + 1
    assert set(count) == {"rest", "slide", "rock", "slide-rock"} and min(count.values()) >= 30, count


# ----------------------------------------------------------------------------- 4. slide-rock, flight
def kinetic_energy(state, block):
    """Kinetic energy per unit mass [J/kg] of (x, y, θ, ẋ, ẏ, θ̇)."""
    return 0.5 * (state[3] ** 2 + state[4] ** 2 + block.inertia_cm_over_mass_m2 * state[5] ** 2)


def corner_velocity(state, sign, block):
    """(Ẋ, Ẏ) of base corner ``sign`` (±1) [m/s], differentiating block.py's map of body points.

    X = x + ξ cos θ + η sin θ, Y = y − ξ sin θ + η cos θ with ξ = ±b, η = −h.
    """
    xi, eta = sign * block.half_width_m, -block.cg_height_m
    theta, theta_dot = state[2], state[5]
    return (state[3] + theta_dot * (-xi * np.sin(theta) + eta * np.cos(theta)),
            state[4] + theta_dot * (-xi * np.cos(theta) - eta * np.sin(theta)))


def energy_balance(block, accel, dt, run):
    """Terms of W_floor = ΔE + W_friction + E_impacts per unit mass [J/kg], from the trace.

    The trace holds (t, mode, x, y, θ, ẋ, ẏ, θ̇, N₋, N₊, F₋, F₊) at every sample and on both
    sides of every event; each term is a trapezoid over it (zero-width steps at events).
    """
    time_s = dt * np.arange(accel.size)
    t = np.array([row[0] for row in run.trace])
    state = np.array([row[2:8] for row in run.trace]).T
    forces = np.array([row[8:12] for row in run.trace]).T
    mid = 0.5 * (t[1:] + t[:-1])
    a_mid = np.interp(mid, time_s, accel, right=0.0)  # linear input: its exact mean over each step
    w_floor = np.sum(-G * a_mid * 0.5 * (state[3][1:] + state[3][:-1]) * np.diff(t))
    power = forces[2] * corner_velocity(state, -1, block)[0] + forces[3] * corner_velocity(state, 1, block)[0]
    w_friction = -np.sum(0.5 * (power[1:] + power[:-1]) * np.diff(t))
    energy = kinetic_energy(state, block) + G * state[1]
    e_impacts = sum(kinetic_energy(before, block) - kinetic_energy(after, block)
                    for _, before, after in run.impacts)
    return w_floor, energy[-1] - energy[0], w_friction, e_impacts, forces


def impulse_laws(block, run):
    """Check the impulse laws at every single-corner impact of the trace; returns how many slipped."""
    slipped = 0
    j = block.inertia_cm_over_mass_m2
    for _, before, after in run.impacts:
        if after[5] == 0.0 and after[4] == 0.0:
            continue  # landed flat (both corners) or settled: not a single-corner impact
        sign = min((-1, 1), key=lambda s: corner_velocity(before, s, block)[1])  # arriving corner
        x, y, theta = before[:3]
        corners = corner_positions(x, y, theta, block.half_width_m, block.cg_height_m)
        r_x, r_y = corners[1 + sign] - x, corners[2 + sign] - y
        v_after = corner_velocity(after, sign, block)
        p_t, p_n = after[3] - before[3], after[4] - before[4]
        # impulses are differences of velocities: round-off relative to the block's speed
        tolerance = 1e-9 * (abs(before[3]) + abs(before[4]) + block.size_m * abs(before[5]))
        assert p_n > 0.0
        assert abs(p_t) <= block.mu_static * p_n + tolerance
        # angular momentum about the contact point, I ω_z + m (ρ × v)_z with ω_z = −θ̇, ρ = −r
        momentum = [-j * s[5] - r_x * s[4] + r_y * s[3] for s in (before, after)]
        assert momentum[1] == pytest.approx(momentum[0], abs=tolerance * block.size_m)
        assert abs(v_after[1]) < tolerance  # perfectly inelastic
        if abs(p_t) < block.mu_static * p_n - tolerance:
            assert abs(v_after[0]) < tolerance  # sticks
        else:
            slipped += 1
            assert abs(p_t) == pytest.approx(block.mu * p_n, abs=tolerance)
            assert v_after[0] * p_t <= 0.0  # still slipping against the friction impulse
        assert kinetic_energy(after, block) <= kinetic_energy(before, block) * (1 + 1e-12)
    return slipped


SLIDE_ROCK_CASES = [  # (b, mu, pulse, ap_g, tp_s): rest -> rock/slide-rock ... -> rest
    (0.3, 0.32, "A", 0.6, 0.5), (0.3, 0.33, "B", 1.5, 0.4), (0.2, 0.204, "B", 1.5, 0.2)]
#: cases whose slide-rock ends in an impact on a slipping corner (the impulse at μ P_N)
SLIPPING_IMPACT = {(0.2, 0.204, "B", 1.5, 0.2)}


@pytest.mark.parametrize("b, mu, pulse, ap_g, tp_s", SLIDE_ROCK_CASES)
def test_slide_rock_energy_balance_and_impulses(b, mu, pulse, ap_g, tp_s):
    """Work of the floor's inertial force = ΔE + friction work + impact losses, to 1e-5."""
    block = Block(half_width_m=b, cg_height_m=1.0, height_m=2.0, mu=mu)
    dt = 1e-3
    accel = pulse_acceleration(pulse, ap_g, tp_s, np.arange(0.0, tp_s + dt / 2, dt))
    result, run = _simulate(block, accel, dt, tail_s=8.0, keep_trace=True)
    modes = [m for _, m in result.mode_sequence]
    assert "slide-rock" in modes and modes[-1] == "rest" and not result.overturned
    w_floor, d_energy, w_friction, e_impacts, forces = energy_balance(block, accel, dt, run)
    assert w_friction > 0.0 and e_impacts > 0.0 and d_energy == pytest.approx(0.0, abs=1e-12)
    assert w_floor == pytest.approx(d_energy + w_friction + e_impacts, rel=1e-5)
    # Coulomb's law and unilateral contact all along
    assert np.all(forces[:2] >= -1e-9 * G)
    assert np.all(np.abs(forces[2:]) <= block.mu_static * forces[:2] * (1 + 1e-9) + 1e-12)
    slipped = impulse_laws(block, run)
    assert (slipped > 0) is ((b, mu, pulse, ap_g, tp_s) in SLIPPING_IMPACT)
    assert result.sliding_max_m > 1e-3 and result.uplift and result.mode == "slide-rock"


def test_flight_and_landing_keep_energy_and_impulse_laws():
    """A violent pulse (8 g) throws a block with μ = 2 off its pivot; it lands on a corner, survives."""
    block = Block.uniform(0.3, 2.0, mu=2.0)
    dt = 1e-3
    accel = pulse_acceleration("B", 8.0, 0.5, np.arange(0.0, 0.5 + dt / 2, dt))
    result, run = _simulate(block, accel, dt, tail_s=5.0, keep_trace=True)
    modes = [m for _, m in result.mode_sequence]
    assert "flight" in modes and modes[-1] == "rest"
    w_floor, d_energy, w_friction, e_impacts, _ = energy_balance(block, accel, dt, run)
    assert w_floor == pytest.approx(d_energy + w_friction + e_impacts, rel=1e-5)
    impulse_laws(block, run)
    landing = [t for t, before, _ in run.impacts if abs(before[2]) > 1e-3]
    assert landing, "no landing on a corner at theta != 0"


def test_squat_block_lands_flat():
    """b/h = 2 (Housner's e < 0): the first impact would drive the other corner into the floor,
    so both land; the block rests, with the energy balance and the impulse cone kept."""
    block = Block(half_width_m=1.0, cg_height_m=0.5, height_m=1.0, mu=2.5)
    assert housner_restitution(block.alpha_rad, block.inertia_ratio) < 0.0
    accel, dt = np.full(301, 2.5), 0.001  # 2.5 g for 0.3 s, sampled finely for the quadratures
    result, run = _simulate(block, accel, dt, tail_s=3.0, keep_trace=True)
    assert [m for _, m in result.mode_sequence] == ["rest", "rock", "rest"] and len(run.impacts) == 1
    _, before, after = run.impacts[0]
    assert after[4] == after[5] == 0.0 and before[5] != 0.0  # flat: ẏ = θ̇ = 0
    p_t, p_n = after[3] - before[3], after[4] - before[4]
    assert p_n > 0.0 and abs(p_t) <= block.mu_static * p_n
    w_floor, d_energy, w_friction, e_impacts, _ = energy_balance(block, accel, dt, run)
    assert e_impacts > 0.0 and w_floor == pytest.approx(d_energy + w_friction + e_impacts, rel=1e-4)


# ----------------------------------------------------------------------------- 5. similitude
def test_froude_similitude(records):
    """Lengths × 1/4, same accelerations at twice the rate: same θ/α, 1/4 of the sliding."""
    accel, dt = records["Nahanni_1985_NS1-280"]
    block = Block(half_width_m=0.2, cg_height_m=0.8, height_m=1.6, mu=0.26, mu_static=0.3)
    full = simulate_event_driven(block, accel, dt, return_history=True)
    model = simulate_event_driven(block.scaled(0.25), accel, dt / 2, tail_s=5.0, return_history=True)
    assert full.mode == "slide-rock" and full.sliding_max_m > 1e-3
    assert model.theta_max_over_alpha == pytest.approx(full.theta_max_over_alpha, rel=1e-6)
    assert model.sliding_max_m == pytest.approx(full.sliding_max_m / 4, rel=1e-6)
    assert model.sliding_residual_m == pytest.approx(full.sliding_residual_m / 4, rel=1e-6)
    assert [m for _, m in model.mode_sequence] == [m for _, m in full.mode_sequence]
    np.testing.assert_allclose([t for t, _ in model.mode_sequence], [t / 2 for t, _ in full.mode_sequence],
                               rtol=1e-6, atol=1e-9)
    np.testing.assert_allclose(model.theta_rad, full.theta_rad, rtol=0, atol=1e-6 * block.alpha_rad)


# ----------------------------------------------------------------------------- API
def test_history_rest_and_run_out():
    """Histories cover the record and the tail; the block rests, then stays; NaN after overturning."""
    accel = [0.0, 0.5, 0.5, 0.0]
    block = Block(half_width_m=0.5, cg_height_m=0.5, height_m=1.0, mu=0.2)
    result = simulate_event_driven(block, accel, 0.1, tail_s=1.0, return_history=True)
    assert result.time_s.shape == result.sliding_m.shape == result.theta_rad.shape == (14,)
    assert result.sliding_m[-1] == result.sliding_residual_m
    assert result.sliding_max_m >= np.abs(result.sliding_m).max()
    assert simulate_event_driven(block, accel, 0.1).time_s is None
    # below every threshold nothing moves
    calm = simulate_event_driven(block, [0.0, 0.19, -0.19, 0.0], 0.1, return_history=True)
    assert calm.mode_sequence == ((0.0, "rest"),) and not calm.uplift and np.all(calm.sliding_m == 0.0)


@pytest.mark.parametrize("kwargs", [dict(dt_s=0.0), dict(floor_accel_g=[0.1, np.nan]), dict(floor_accel_g=[0.1]),
                                    dict(initial_theta_rad=2.0), dict(tail_s=-1.0)])
def test_bad_input_raises(kwargs):
    args = dict(floor_accel_g=[0.0, 0.1], dt_s=0.01) | kwargs
    with pytest.raises(ValueError):
        simulate_event_driven(ROCKER, args.pop("floor_accel_g"), args.pop("dt_s"), **args)
