"""The building's modes against closed forms.

* Continuous shear beam (α → ∞): ω_i ∝ 2i - 1, period ratios 1 : 1/3 : 1/5 (the continuous shear beam, e.g. Chopra 2012 chapter 16).
* Flexural cantilever (α = 0): β_iL = 1.8751, 4.6941, 7.8548, 10.9955, T_1/T_i = 1 : 6.267 : 17.547 :
  34.39 (roots of cos βL cosh βL = -1, the Euler-Bernoulli cantilever).
* Uniform shear building of n storeys: ω_j = 2√(k/m) sin((2j-1)π/(2(2n+1))),
  φ_j(i) = sin((2j-1) i π/(2n+1)) (the free-fixed chain's exact eigenvalues and vectors).
* Euler-Bernoulli cantilever flexibility: deflection at x from a unit load at b ≥ x is
  x²(3b - x)/(6EI) (any strength-of-materials text), exact for the cubic elements.
* Intermediate α: the lumped stick model with many storeys against the continuum's
  characteristic equation (Miranda & Taghavi 2005), two independent computations of one
  problem; the OpenSees peer (tests/verification/test_building_opensees.py) checks the stick model
  itself with OpenSees' own beam and spring elements.
"""
import numpy as np
import pytest

from assess.building.modes import (ALPHA_BY_SYSTEM, building_modes, continuum_eigenvalues,
                                   continuum_mode_shape, continuum_period_ratios,
                                   flexural_stiffness_matrix, lumped_modes, modes_for_mass,
                                   shear_building_frequency_ratios, stiffness_matrix)
from assess.building.period import SYSTEMS, approximate_period


def test_flexural_cantilever_eigenvalues_and_period_ratios():
    np.testing.assert_allclose(continuum_eigenvalues(0.0, 4), [1.8751, 4.6941, 7.8548, 10.9955], atol=1e-4)
    np.testing.assert_allclose(1 / continuum_period_ratios(0.0, 4), [1.0, 6.267, 17.547, 34.39], rtol=1e-3)


def test_shear_beam_limit_period_ratios():
    np.testing.assert_allclose(1 / continuum_period_ratios(2000.0, 4), [1, 3, 5, 7], rtol=2e-3)


@pytest.mark.parametrize("alpha", [0.0, 1.0, 5.0, 12.0, 30.0])
def test_continuum_mode_shape_meets_the_boundary_conditions(alpha):
    """φ(0) = φ'(0) = 0 at the base, φ''(1) = 0 and φ'''(1) - α²φ'(1) = 0 at the free top
    (no moment, no shear), by finite differences of the closed-form shape."""
    for gamma in continuum_eigenvalues(alpha, 3):
        h = 1e-3
        phi = lambda x: continuum_mode_shape(x, gamma, alpha)
        scale = np.max(np.abs(phi(np.linspace(0, 1, 101))))
        assert abs(phi(0.0)) < 1e-12 * scale
        assert abs((phi(1e-5) - phi(-1e-5)) / 2e-5) < 1e-6 * scale
        top = [phi(1 - k * h) for k in range(5)]  # backward differences at ξ = 1
        second = (2 * top[0] - 5 * top[1] + 4 * top[2] - top[3]) / h ** 2
        assert abs(second) < 1e-3 * scale * gamma ** 2
        x = np.linspace(0.0, 1.0, 4001)
        d1, d3 = np.gradient(phi(x), x), np.gradient(np.gradient(np.gradient(phi(x), x), x), x)
        assert abs(d3[-8] - alpha ** 2 * d1[-8]) < 0.02 * scale * (gamma ** 3 + alpha ** 2 * gamma)


@pytest.mark.parametrize("storeys", [1, 2, 3, 6, 12])
def test_uniform_shear_building_against_the_closed_form(storeys):
    periods, shapes, gamma, mass = lumped_modes(stiffness_matrix(storeys, 3.0, np.inf), np.ones(storeys))
    np.testing.assert_allclose(periods[0] / periods, shear_building_frequency_ratios(storeys), rtol=1e-10)
    i = np.arange(1, storeys + 1)
    for j in range(1, storeys + 1):
        closed = np.sin((2 * j - 1) * i * np.pi / (2 * storeys + 1))
        np.testing.assert_allclose(shapes[1:, j - 1], closed / closed[-1], atol=1e-9)
    # absolute frequency, k = m = 1: ω_1 = 2 sin(π/(2(2n+1)))
    assert 2 * np.pi / periods[0] == pytest.approx(2 * np.sin(np.pi / (2 * (2 * storeys + 1))), rel=1e-12)
    assert mass.sum() == pytest.approx(1.0, abs=1e-12)
    np.testing.assert_allclose(shapes[1:] @ gamma, 1.0, atol=1e-10)  # Σ Γ_j φ_j = 1 at every floor


def test_flexural_matrix_is_the_cantilever_flexibility():
    storeys, h, ei = 5, 3.2, 7.0
    flexibility = np.linalg.inv(flexural_stiffness_matrix(storeys, h, ei))
    z = h * np.arange(1, storeys + 1)
    x, b = np.minimum.outer(z, z), np.maximum.outer(z, z)
    np.testing.assert_allclose(flexibility, x ** 2 * (3 * b - x) / (6 * ei), rtol=1e-10)


@pytest.mark.parametrize("alpha", [0.0, 1.0, 5.0, 12.0, 30.0, np.inf])
def test_many_storey_stick_tends_to_the_continuum(alpha):
    """200 storeys: periods ratios within 0.5 % of the continuum's (the lumped roof mass and the
    discretisation are O(1/n)); the first mode shape within 1 % of the roof value."""
    n = 200
    periods, shapes, _, _ = lumped_modes(stiffness_matrix(n, 1.0, alpha), np.ones(n))
    continuum = continuum_period_ratios(min(alpha, 1e4), 4)
    np.testing.assert_allclose(periods[:4] / periods[0], continuum, rtol=5e-3)
    gamma = continuum_eigenvalues(min(alpha, 1e4), 1)[0]
    xi = np.arange(n + 1) / n
    shape = continuum_mode_shape(xi, gamma, min(alpha, 1e4))
    np.testing.assert_allclose(shapes[:, 0], shape / shape[-1], atol=1e-2)


def test_intermediate_alpha_lies_between_the_limits():
    ratios = [1 / continuum_period_ratios(a, 3) for a in (0.0, 1.0, 4.0, 12.0, 30.0)]
    second = [r[1] for r in ratios]
    assert all(a > b for a, b in zip(second, second[1:]))  # 6.27 down towards 3
    assert 3.0 < second[-1] < second[0] < 6.3


def test_building_modes_period_given_or_from_the_code():
    modes = building_modes(6, 3.5, period_s=0.70, system="steel moment frame")
    assert modes.periods_s[0] == pytest.approx(0.70)
    assert modes.period_source == "given"
    assert modes.alpha == ALPHA_BY_SYSTEM["steel moment frame"]
    assert modes.effective_mass_ratio.sum() == pytest.approx(1.0)
    assert modes.shapes.shape == (7, 6)
    np.testing.assert_allclose(modes.shapes[-1], 1.0)
    np.testing.assert_allclose(modes.shapes[0], 0.0)
    for system in SYSTEMS:
        code = building_modes(6, 3.5, system=system)
        assert code.periods_s[0] == pytest.approx(approximate_period(21.0, system))
        assert "12.8-2" in code.period_source


def test_modes_kept_reach_ninety_percent_of_the_mass():
    for storeys in (1, 3, 6, 12, 30):
        for system in SYSTEMS:
            assert building_modes(storeys, 3.5, system=system).n_modes == storeys  # the default: all
            modes = building_modes(storeys, 3.5, system=system, mass_fraction=0.9)
            kept = modes.effective_mass_ratio.sum()
            assert kept >= 0.9 - 1e-12 or modes.n_modes == storeys
            if modes.n_modes > min(3, storeys):
                assert kept - modes.effective_mass_ratio[-1] < 0.9
    assert modes_for_mass([0.5, 0.3, 0.15, 0.05]) == 3


def test_walls_have_longer_higher_mode_periods_than_frames():
    """A flexural (wall) building's second mode is at T_1/~5, a frame's at T_1/~3."""
    wall = building_modes(12, 3.5, period_s=1.0, system="shear wall")
    frame = building_modes(12, 3.5, period_s=1.0, system="concrete moment frame")
    assert wall.periods_s[1] < frame.periods_s[1]
    assert 4.5 < 1 / wall.periods_s[1] < 6.3 and 2.8 < 1 / frame.periods_s[1] < 3.4


def test_bad_input():
    with pytest.raises(ValueError):
        building_modes(0, 3.0)
    with pytest.raises(ValueError):
        building_modes(3, 3.0, system="tent")
    with pytest.raises(ValueError):
        building_modes(3, -3.0)
    with pytest.raises(ValueError):
        building_modes(3, 3.0, period_s=0.0)
    with pytest.raises(ValueError):
        building_modes(3, 3.0, damping=1.5)
    with pytest.raises(ValueError):
        building_modes(3, 3.0, storey_stiffness=[1.0, 2.0])
