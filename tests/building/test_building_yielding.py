"""The yielding stick (assess.building.nonlinear, hysteresis, design) against closed forms and the elastic route.

* Elastoplastic SDOF under a suddenly applied constant ground acceleration (a step force
  p_0 = m a_0), undamped: energy conservation at the peak (velocity 0) gives
  u_max = 2 p_0/k while 2 p_0 ≤ F_y, and for F_y/2 < p_0 < F_y (b = 0)
  p_0 u_m = F_y²/(2k) + F_y (u_m - u_y), i.e. μ = 1/(2(1 - p_0/F_y)) (Chopra 2012 §7.5 gives the same for
  the elastoplastic system under a step force).
* Free vibration of the elastic SDOF after a short ground pulse: period T and the logarithmic
  decrement ln(u_i/u_{i+1}) = 2πζ/√(1-ζ²) of stiffness-proportional damping ζ at ω.
* Energy balance of a yielding, undamped SDOF: the work of the ground, -∫m ü_g du, equals the
  kinetic energy plus the spring's work ∫f du (from the stored histories, trapezoids at 1 ms).
* The hysteresis laws' rules on a prescribed drift path: the bilinear law's yield and
  kinematic hardening lines; the pinching law's envelope, its degraded unloading stiffness
  k_0 (d_max/d_y)^-β (Takeda et al. 1970), its reloading to the largest drift reached.
* The elastic limit: strengths far above the demand give the elastic modal route's floor
  histories (assess.building.response.floor_accelerations, exact for piecewise-linear input)
  with each mode's Rayleigh damping ratio, within 1 % RMS (what remains is Newmark's Δt² error).
* ASCE 7-22 §12.8 numbers worked by hand.
"""
import numpy as np
import pytest

from assess.building.design import (IMPORTANCE_BY_RISK_CATEGORY, design_strength, distribution_exponent,
                                    seismic_response_coefficient, storey_shear_ratios, upper_limit_coefficient)
from assess.building.hysteresis import spring_forces
from assess.building.modes import building_modes
from assess.building.nonlinear import (GRAVITY_M_S2, YieldingStick, elastic_periods, p_delta_stiffness,
                                       rayleigh_modal_damping, yielding_response, yielding_stick)
from assess.building.response import floor_accelerations


def _sdof(period_s, yield_force_n, hardening=0.0, rayleigh=(0.0, 0.0), law="bilinear", mass_kg=1.0):
    k = mass_kg * (2 * np.pi / period_s) ** 2
    return YieldingStick(np.array([mass_kg]), np.array([3.0]), np.array([k]), np.array([float(yield_force_n)]),
                         np.array([hardening]), law, np.zeros((1, 1)), rayleigh)


@pytest.mark.parametrize("load_over_yield", [0.3, 0.45, 0.6, 0.75, 0.9])
def test_step_load_peak_against_energy_closed_form(load_over_yield):
    period, fy = 0.5, 1.0
    stick = _sdof(period, fy)
    k = stick.stiffness_n_m[0]
    a0_g = load_over_yield * fy / GRAVITY_M_S2  # p0 = m a0, m = 1 kg
    ground = np.full(int(3.0 / 0.001) + 1, -a0_g)
    response = yielding_response(stick, ground, 0.001)
    peak = np.abs(response.drift_m).max()
    p0 = load_over_yield * fy
    expected = 2 * p0 / k if 2 * p0 <= fy else (fy / k) / (2 * (1 - load_over_yield))
    assert response.unconverged_steps == 0
    assert peak == pytest.approx(expected, rel=2e-4), (peak, expected)


def test_free_vibration_period_and_decrement():
    period, zeta = 0.4, 0.05
    omega = 2 * np.pi / period
    stick = _sdof(period, 1e9, rayleigh=(0.0, 2 * zeta / omega))
    dt = 0.0005
    ground = np.zeros(int(6.0 / dt) + 1)
    ground[1:21] = 0.3  # a 10 ms pulse, then free vibration
    drift = yielding_response(stick, ground, dt, substeps=1).drift_m[0]
    tail = drift[200:]
    peaks = np.flatnonzero((tail[1:-1] > tail[:-2]) & (tail[1:-1] >= tail[2:])) + 1
    times = peaks * dt
    assert np.diff(times).mean() == pytest.approx(period * 1 / np.sqrt(1 - zeta ** 2), rel=2e-3)
    decrement = np.log(tail[peaks[:-1]] / tail[peaks[1:]]).mean()
    assert decrement == pytest.approx(2 * np.pi * zeta / np.sqrt(1 - zeta ** 2), rel=1e-2)


@pytest.mark.parametrize("law", ["bilinear", "pinching"])
def test_energy_balance_of_a_yielding_oscillator(law):
    period, dt = 0.5, 0.001
    rng = np.random.default_rng(3)
    coarse = rng.normal(scale=0.3, size=801)  # 8 s of noise at 10 ms, linear between samples
    ground = np.interp(np.arange(0, 8.0 + dt / 2, dt), np.arange(801) * 0.01, coarse)
    stick = _sdof(period, 1.0, hardening=0.02, law=law)
    response = yielding_response(stick, ground, dt, substeps=1)
    u = response.drift_m[0]
    absolute = response.floor_accel_g[1] * GRAVITY_M_S2
    force = -absolute  # undamped: m ü_abs + f_s = 0 (m = 1 kg)
    assert response.ductility[0] > 3
    relative_accel = absolute - ground * GRAVITY_M_S2
    velocity = np.concatenate([[0.0], np.cumsum((relative_accel[1:] + relative_accel[:-1]) / 2 * dt)])
    du = np.diff(u)
    ground_work = np.sum(-(ground[1:] + ground[:-1]) / 2 * GRAVITY_M_S2 * du)
    spring_work = np.sum((force[1:] + force[:-1]) / 2 * du)
    kinetic = velocity[-1] ** 2 / 2
    assert spring_work + kinetic == pytest.approx(ground_work, rel=1e-3)


def test_bilinear_law_yield_and_kinematic_hardening():
    k0, fy, b = 200.0, 10.0, 0.05  # d_y = 0.05 m
    path = np.array([0.02, 0.05, 0.15, 0.05, -0.05, -0.15, 0.0])
    forces = spring_forces(path, "bilinear", k0, fy, hardening=b)
    top = fy + b * k0 * 0.10  # 11.0 N at 0.15 m
    expected = [4.0, 10.0, top, top - k0 * 0.10,
                # unloading at k0 until the lower hardening line b k0 d - (1-b) fy
                b * k0 * -0.05 - (1 - b) * fy, b * k0 * -0.15 - (1 - b) * fy,
                (1 - b) * fy]  # back to 0: -11 + 200 × 0.15 = 19 passes the upper line b k0 d + (1 - b) F_y = 9.5
    np.testing.assert_allclose(forces, expected, atol=1e-9)


def test_pinching_law_envelope_unloading_and_reloading():
    k0, fy, b, beta = 100.0, 1.0, 0.03, 0.4
    dy = fy / k0
    path = np.concatenate([np.linspace(0, 3 * dy, 31), np.linspace(3 * dy, 2 * dy, 11)[1:],
                           np.linspace(2 * dy, -3 * dy, 51)[1:], np.linspace(-3 * dy, 3 * dy, 61)[1:]])
    forces = spring_forces(path, "pinching", k0, fy, hardening=b, pinch_x=0.8, pinch_y=0.4, beta=beta)
    envelope = fy + b * k0 * 2 * dy
    assert forces[30] == pytest.approx(envelope)                           # on the backbone at 3 d_y
    slope = (forces[30] - forces[40]) / dy
    assert slope == pytest.approx(k0 * 3.0 ** -beta, rel=1e-9)           # Takeda's degraded unloading
    assert forces[90] == pytest.approx(-envelope)                          # the backbone the other way
    assert forces[-1] == pytest.approx(envelope, rel=1e-9)                 # reloads to the largest drift
    # pinched: on the way back up, at zero drift the force is below the bilinear law's
    bilinear = spring_forces(path, "bilinear", k0, fy, hardening=b)
    zero = 90 + 30
    assert abs(forces[zero]) < abs(bilinear[zero])


@pytest.mark.parametrize("storeys, period_s", [(3, 0.35), (6, 0.70), (12, 1.40)])
@pytest.mark.parametrize("flexure, alpha", [("equivalent shear", np.inf), ("elastic column", 12.0),
                                            ("elastic column", 1.0)])
def test_elastic_limit_is_the_modal_route(storeys, period_s, flexure, alpha):
    rng = np.random.default_rng(storeys)
    dt = 0.01
    ground = np.convolve(rng.normal(scale=0.2, size=1500), np.ones(5) / 5, mode="same")
    stick = yielding_stick(storeys, 3.5, np.full(storeys, 100.0), system="steel moment frame", period_s=period_s,
                           alpha=alpha, flexure=flexure)
    periods = elastic_periods(stick)
    modes = building_modes(storeys, 3.5, period_s=period_s, alpha=alpha, n_modes=storeys,
                           damping=rayleigh_modal_damping(periods, *stick.rayleigh))
    np.testing.assert_allclose(modes.periods_s, periods, rtol=1e-9)
    ours = yielding_response(stick, ground, dt)
    assert ours.ductility.max() < 0.1
    theirs = floor_accelerations(modes, ground, dt)
    error = np.sqrt(np.mean((ours.floor_accel_g - theirs) ** 2, axis=1)[1:] / np.mean(theirs ** 2, axis=1)[1:])
    assert error.max() <= 0.01, error


def test_equivalent_shear_stick_keeps_the_period_and_the_code_drift_profile():
    stick = yielding_stick(6, 3.5, np.full(6, 1.0), system="shear wall", period_s=0.5, flexure="equivalent shear")
    assert elastic_periods(stick)[0] == pytest.approx(0.5, rel=1e-12)
    assert np.all(stick.linear_stiffness_n_m == 0.0)


def test_p_delta_lowers_the_period_as_the_geometric_stiffness_says():
    # one storey: k_eff = k - P/h, so T grows by sqrt(k/(k - W/h))
    stick = yielding_stick(1, 3.0, [1.0], system="steel moment frame", period_s=1.0, alpha=np.inf, p_delta=True)
    k = stick.stiffness_n_m[0]
    expected = 1.0 * np.sqrt(k / (k - stick.floor_masses_kg[0] * GRAVITY_M_S2 / 3.0))
    assert elastic_periods(stick)[0] == pytest.approx(expected, rel=1e-12)
    assert p_delta_stiffness([2.0], [GRAVITY_M_S2])[0, 0] == pytest.approx(-2.0)


def test_seismic_response_coefficient_and_its_bounds():
    # Eq. 12.8-2: 1.1 / (5 / 1.5) = 0.33
    assert seismic_response_coefficient(1.1, 0.6, 0.3, 5.0, 1.5) == pytest.approx(0.33)
    # Eq. 12.8-3: 0.6 / (1.2 × 8) = 0.0625
    assert seismic_response_coefficient(1.0, 0.6, 1.2, 8.0) == pytest.approx(0.0625)
    # Eq. 12.8-4: 0.6 × 4 / (6² × 8) = 0.008333, then Eq. 12.8-5: 0.044 × 1.0 = 0.044
    assert seismic_response_coefficient(1.0, 0.6, 6.0, 8.0, tl_s=4.0) == pytest.approx(0.044)
    assert seismic_response_coefficient(0.2, 0.1, 6.0, 8.0, tl_s=4.0) == pytest.approx(0.01)
    # Eq. 12.8-6: S1 0.8: 0.5 × 0.8 / 8 = 0.05 above 0.6/(3 × 8) = 0.025
    assert seismic_response_coefficient(1.0, 0.6, 3.0, 8.0, s1_g=0.8) == pytest.approx(0.05)
    assert IMPORTANCE_BY_RISK_CATEGORY == {"I": 1.0, "II": 1.0, "III": 1.25, "IV": 1.5}
    assert upper_limit_coefficient(0.05) == 1.7 and upper_limit_coefficient(0.175) == pytest.approx(1.55)
    assert distribution_exponent(0.5) == 1.0 and distribution_exponent(2.5) == 2.0


def test_storey_shears_with_k_two():
    # k = 2 (T 2.5 s), equal weights at 1, 2, 3: w h² = 1, 4, 9 of 14; storey shears 14/14, 13/14, 9/14
    np.testing.assert_allclose(storey_shear_ratios([1, 1, 1], [1.0, 2.0, 3.0], 2.5), [1.0, 13 / 14, 9 / 14])


def test_design_strength_seattle_hospital_and_given_yield():
    # 5-storey RC shear wall, 4.5 m storeys, RC IV, S_DS 1.1, S_D1 0.6, T_1 0.6 s (below C_u T_a = 1.4 ×
    # 0.0488 × 22.5^0.75 = 0.70 s): C_s = min(1.1 / (5/1.5), 0.6 / (0.6 × 5/1.5)) = min(0.33, 0.30) = 0.30,
    # yield 2 × 0.30 = 0.60 W
    strength = design_strength("shear wall", np.ones(5), 4.5 * np.arange(1, 6), 0.6, sds_g=1.1, sd1_g=0.6,
                               risk_category="IV")
    assert strength.design_period_s == 0.6  # below C_u T_a = 1.4 × 0.4998 = 0.70 s
    assert strength.seismic_response_coefficient == pytest.approx(0.30)
    assert strength.yield_base_shear_g == pytest.approx(0.60)
    assert strength.storey_yield_ratio[0] == pytest.approx(0.60)
    short = design_strength("shear wall", np.ones(5), 4.5 * np.arange(1, 6), 0.3, sds_g=1.1, sd1_g=0.6,
                            risk_category="IV")
    assert short.seismic_response_coefficient == pytest.approx(0.33)  # Eq. 12.8-2 governs at 0.3 s
    given = design_strength("shear wall", np.ones(5), 4.5 * np.arange(1, 6), 0.6, yield_base_shear_g=0.4)
    assert given.yield_base_shear_g == 0.4 and given.seismic_response_coefficient is None
    with pytest.raises(ValueError, match="S_DS"):
        design_strength("shear wall", np.ones(5), 4.5 * np.arange(1, 6), 0.6)


@pytest.mark.parametrize("storeys, period_s, system", [(3, 0.35, "steel moment frame"), (6, 0.70, "braced frame"),
                                                       (12, 1.40, "concrete moment frame")])
def test_modal_damping_elastic_limit_is_todays_route(storeys, period_s, system):
    """With ζ in every mode (the elastic route's default damping) and the frames' elastic column, a stick
    that stays elastic gives the elastic route's own floor histories (building_modes as it is called today)."""
    rng = np.random.default_rng(11)
    ground = np.convolve(rng.normal(scale=0.2, size=1500), np.ones(5) / 5, mode="same")
    stick = yielding_stick(storeys, 3.5, np.full(storeys, 100.0), system=system, period_s=period_s,
                           damping_model="modal")
    assert stick.rayleigh == (0.0, 0.0)
    ours = yielding_response(stick, ground, 0.01)
    theirs = floor_accelerations(building_modes(storeys, 3.5, system=system, period_s=period_s), ground, 0.01)
    error = np.sqrt(np.mean((ours.floor_accel_g - theirs) ** 2, axis=1)[1:] / np.mean(theirs ** 2, axis=1)[1:])
    assert error.max() <= 0.01, error


def test_modal_damping_matrix_gives_the_ratio_in_every_mode():
    from assess.building.modes import shear_stiffness_matrix
    from assess.building.nonlinear import modal_damping_matrix
    from scipy.linalg import eigh
    stiffness, masses = shear_stiffness_matrix([3.0, 2.0, 1.0]), np.array([1.0, 2.0, 1.5])
    damping = modal_damping_matrix(stiffness, masses, 0.07)
    omega2, shapes = eigh(stiffness, np.diag(masses))
    modal = shapes.T @ damping @ shapes  # Φᵀ C Φ = diag(2 ζ ω) for mass-normalised shapes
    np.testing.assert_allclose(modal, np.diag(2 * 0.07 * np.sqrt(omega2)), atol=1e-12)
