"""Floor accelerations of the modal response history, against closed forms and scipy.

* The oscillator step: scipy.signal.lsim with first-order hold (its own exact
  discretisation of a linear system under piecewise-linear input).
* Harmonic ground motion, each mode from rest: the closed-form solution of a damped
  oscillator under p(t) = p0 sin ω̄t from rest (Chopra 2012 §3.2); at resonance
  (ω̄ = ω_n) u(t) = (u_st/2ζ)[e^{-ζω t}(cos ω_D t + ζ/√(1-ζ²) sin ω_D t) - cos ω t], whose
  steady-state relative acceleration has amplitude a0/(2ζ) and whose envelope builds up as
  (1 - e^{-ζωt})/(2ζ) for light damping (Chopra 2012 §3.2). The sine is sampled at T/400
  and read as piecewise linear: tolerance 2e-4 of the peak.
"""
import time

import numpy as np
import pytest
import scipy.signal

from assess.building.modes import building_modes
from assess.building.response import floor_accelerations, floor_records, modal_relative_accelerations
from assess.site.spectrum import nigam_jennings_coefficients
from assess.hazard.records import Record


def test_recursion_against_scipy_first_order_hold():
    rng = np.random.default_rng(7)
    ground = rng.normal(size=3000)
    dt = 0.01
    periods, zeta = np.array([0.05, 0.3, 1.4, 4.0]), np.array([0.0, 0.05, 0.02, 0.2])
    ours = modal_relative_accelerations(ground, dt, periods, zeta)
    time_s = np.arange(ground.size) * dt
    for j, (period, z) in enumerate(zip(periods, zeta)):
        w = 2 * np.pi / period
        system = scipy.signal.lti([[0, 1], [-w * w, -2 * z * w]], [[0], [1]], [[-w * w, -2 * z * w]], [[1]])
        _, relative_accel, _ = scipy.signal.lsim(system, -ground, time_s, interp=True)
        np.testing.assert_allclose(ours[:, j], relative_accel, atol=1e-9 * np.abs(relative_accel).max())


def _harmonic_from_rest(a0, forcing_rad_s, period_s, zeta, time_s):
    """u, u̇ of ü + 2ζωu̇ + ω²u = -a0 sin(ω̄t), u(0) = u̇(0) = 0 (Chopra 2012 §3.2)."""
    w = 2 * np.pi / period_s
    wd = w * np.sqrt(1 - zeta ** 2)
    r = forcing_rad_s / w
    ust = -a0 / w ** 2
    den = (1 - r ** 2) ** 2 + (2 * zeta * r) ** 2
    c, d = ust * (1 - r ** 2) / den, ust * (-2 * zeta * r) / den
    a = -d
    b = (zeta * w * a - c * forcing_rad_s) / wd
    e = np.exp(-zeta * w * time_s)
    u = c * np.sin(forcing_rad_s * time_s) + d * np.cos(forcing_rad_s * time_s) + \
        e * (a * np.cos(wd * time_s) + b * np.sin(wd * time_s))
    v = forcing_rad_s * (c * np.cos(forcing_rad_s * time_s) - d * np.sin(forcing_rad_s * time_s)) + \
        e * (-zeta * w * (a * np.cos(wd * time_s) + b * np.sin(wd * time_s))
             + wd * (-a * np.sin(wd * time_s) + b * np.cos(wd * time_s)))
    return u, v


def test_single_mode_at_resonance_closed_form_and_build_up():
    period, zeta, a0 = 0.5, 0.05, 0.3
    w = 2 * np.pi / period
    dt = period / 400
    time_s = np.arange(0, 60 * period, dt)
    ground = a0 * np.sin(w * time_s)
    relative = modal_relative_accelerations(ground, dt, [period], [zeta])[:, 0]
    # Chopra's resonance solution, written out
    wd = w * np.sqrt(1 - zeta ** 2)
    u = (-a0 / w ** 2) / (2 * zeta) * (np.exp(-zeta * w * time_s) * (
        np.cos(wd * time_s) + zeta / np.sqrt(1 - zeta ** 2) * np.sin(wd * time_s)) - np.cos(w * time_s))
    u_general, v = _harmonic_from_rest(a0, w, period, zeta, time_s)
    np.testing.assert_allclose(u_general, u, atol=1e-12)
    closed = -ground - 2 * zeta * w * v - w ** 2 * u
    np.testing.assert_allclose(relative, closed, atol=2e-4 * np.abs(closed).max())
    # steady state: amplitude a0/(2ζ) = 3.0 g; build-up (1 - e^{-ζωt})/(2ζ) cycle by cycle
    last_cycle = time_s > 55 * period
    assert np.abs(relative[last_cycle]).max() == pytest.approx(a0 / (2 * zeta), rel=2e-3)
    for cycle in (1, 3, 6, 12, 25):
        window = (time_s >= (cycle - 1) * period) & (time_s < cycle * period)
        envelope = a0 / (2 * zeta) * (1 - np.exp(-zeta * w * cycle * period))
        assert np.abs(relative[window]).max() == pytest.approx(envelope, rel=0.06, abs=0.03 * a0)


@pytest.mark.parametrize("storeys, period_s, alpha", [(3, 0.35, np.inf), (6, 0.70, 4.0), (12, 1.40, 1.0)])
def test_floor_accelerations_under_harmonic_ground_motion(storeys, period_s, alpha):
    """Every floor's absolute acceleration = ü_g + Σ_j Γ_jφ_j ü_j with each ü_j the closed form;
    the ground at the first mode's frequency (resonance) and at 1.7 times it."""
    modes = building_modes(storeys, 3.5, period_s=period_s, alpha=alpha, n_modes=storeys)
    for forcing in (2 * np.pi / period_s, 1.7 * 2 * np.pi / period_s):
        dt = modes.periods_s[-1] / 100
        time_s = np.arange(0, 20 * period_s, dt)
        ground = 0.25 * np.sin(forcing * time_s)
        ours = floor_accelerations(modes, ground, dt)
        closed = np.tile(ground, (storeys + 1, 1))
        for j in range(modes.n_modes):
            u, v = _harmonic_from_rest(0.25, forcing, modes.periods_s[j], modes.damping[j], time_s)
            w = 2 * np.pi / modes.periods_s[j]
            relative = -ground - 2 * modes.damping[j] * w * v - w ** 2 * u
            closed += np.outer(modes.shapes[:, j] * modes.participation[j], relative)
        np.testing.assert_allclose(ours, closed, atol=2e-4 * np.abs(closed).max())
        np.testing.assert_array_equal(ours[0], ground)


def test_all_modes_of_a_rigid_building_follow_the_ground():
    """A very stiff building (T_1 = 1 ms): every floor moves with the ground."""
    modes = building_modes(4, 3.0, period_s=0.001, alpha=np.inf, n_modes=4)
    ground = np.sin(np.linspace(0, 20, 2001))
    np.testing.assert_allclose(floor_accelerations(modes, ground, 0.01), np.tile(ground, (5, 1)), atol=1e-4)


def test_floor_records_shape_names_and_step():
    modes = building_modes(3, 3.5, period_s=0.35)
    rng = np.random.default_rng(1)
    suite = [Record(rng.normal(size=500) * 0.1, 0.01, "a"), Record(rng.normal(size=300) * 0.1, 0.02, "b")]
    floors = floor_records(modes, suite)
    assert sorted(floors) == [0, 1, 2, 3] and all(len(f) == 2 for f in floors.values())
    assert floors[0][1] is not suite[1] and np.array_equal(floors[0][1].accel_g, suite[1].accel_g)
    assert floors[3][1].dt_s == 0.02 and floors[3][1].accel_g.size == 300
    assert floors[2][0].name == "a @ floor 2"
    np.testing.assert_array_equal(floors[3][0].accel_g, floor_accelerations(modes, suite[0].accel_g, 0.01)[3])
    some = floor_records(modes, suite, floors=[3, 1])
    assert list(some) == [3, 1]
    np.testing.assert_array_equal(some[1][1].accel_g, floors[1][1].accel_g)
    with pytest.raises(ValueError):
        floor_records(modes, suite, floors=[4])


def test_eleven_motions_twelve_floors_well_under_a_second():
    """Cost: 11 ground motions of 40 s at 0.005 s through a 12-storey building (all 12 modes)."""
    modes = building_modes(12, 3.5, period_s=1.4, n_modes=12)
    rng = np.random.default_rng(3)
    suite = [Record(rng.normal(size=8001) * 0.1, 0.005, f"m{i}") for i in range(11)]
    floor_records(modes, suite[:1])  # compile
    start = time.perf_counter()
    floor_records(modes, suite)
    elapsed = time.perf_counter() - start
    print(f"11 motions x 12 floors x 8001 samples: {elapsed * 1000:.1f} ms")
    assert elapsed < 1.0


def test_coefficients_reduce_to_free_vibration():
    """No load: the step is the free vibration's transition matrix (det = e^{-2ζωΔt})."""
    c = nigam_jennings_coefficients([0.7], 0.01, [0.05])
    a, b, a1, b1 = c[0, 0], c[1, 0], c[4, 0], c[5, 0]
    w = 2 * np.pi / 0.7
    assert a * b1 - b * a1 == pytest.approx(np.exp(-2 * 0.05 * w * 0.01), rel=1e-12)
