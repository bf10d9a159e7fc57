"""Block geometry and the mode a block enters from rest."""
import itertools

import numpy as np
import pytest

from assess.mechanics.geometry import (
    frequency_parameter, housner_restitution, inertia_ratio, size, slenderness,
)
from assess.mechanics.modes import friction_required_to_rock, initial_mode


def test_uniform_block_p_is_sqrt_3g_over_4r():
    b, h = np.array([0.2, 0.3, 0.5]), np.array([1.0, 0.8, 0.5])
    expected = np.sqrt(3 * 9.80665 / (4 * np.hypot(b, h)))
    np.testing.assert_allclose(frequency_parameter(b, h), expected, rtol=1e-12)


def test_housner_figure5_block():
    """Fig. 5/6 block: alpha = 0.16 rad, p = 1.25 rad/s means R = 3g/(4p²) = 4.707 m."""
    radius = 3 * 9.80665 / (4 * 1.25**2)
    b, h = radius * np.sin(0.16), radius * np.cos(0.16)
    assert float(size(b, h)) == pytest.approx(radius)
    assert float(slenderness(b, h)) == pytest.approx(0.16)
    assert float(frequency_parameter(b, h)) == pytest.approx(1.25)
    assert float(housner_restitution(0.16)) == pytest.approx(1 - 1.5 * np.sin(0.16) ** 2)


def test_low_centre_of_mass_is_stockier_and_restitution_general_form():
    b, height = 0.4, 1.8
    uniform_alpha = float(slenderness(b, height / 2))
    low_alpha = float(slenderness(b, 0.7))
    assert low_alpha > uniform_alpha
    kappa = inertia_ratio(b, 0.7, height)
    # I_O = I_cm + m R²: I_cm/m = (4b² + H²)/12 for the whole box
    assert kappa == pytest.approx(((4 * b**2 + height**2) / 12 + b**2 + 0.7**2) / (b**2 + 0.7**2))
    assert float(housner_restitution(low_alpha, kappa)) == pytest.approx(1 - 2 / kappa * np.sin(low_alpha) ** 2)


def _shenton_uniform(accel, t):
    """The uniform-block form as the issue writes it: [A(4t²+1)+3t]/[t²+4+3At]."""
    return (accel * (4 * t**2 + 1) + 3 * t) / (t**2 + 4 + 3 * accel * t)


@pytest.mark.parametrize("accel,t", list(itertools.product([0.1, 0.3, 0.6, 1.0, 2.0], [0.1, 0.27, 0.5, 1.0])))
def test_required_friction_uniform_form(accel, t):
    assert friction_required_to_rock(accel, t) == pytest.approx(_shenton_uniform(accel, t), rel=1e-12)


def test_required_friction_equals_b_over_h_at_uplift_and_grows():
    t = np.linspace(0.05, 1.0, 20)
    np.testing.assert_allclose(friction_required_to_rock(t, t), t, rtol=1e-12)
    assert np.all(np.diff(friction_required_to_rock(np.linspace(0.3, 3, 30), 0.3)) > 0)


GRID_MU = [0.05, 0.13, 0.2, 0.3, 0.45, 0.68, 1.0]
GRID_T = [0.1, 0.2, 0.27, 0.35, 0.5, 0.8]
GRID_A = [0.04, 0.1, 0.25, 0.3, 0.5, 0.96, 1.5, 3.0]


def _expected_mode(accel, mu, t):
    """The criteria of the main-job issue, written out case by case."""
    if mu < t:
        return "slide" if accel > mu else "rest"
    if accel <= t:
        return "rest"
    return "slide-rock" if mu < _shenton_uniform(accel, t) else "rock"


def test_initial_mode_over_a_grid():
    cases = list(itertools.product(GRID_A, GRID_MU, GRID_T))
    accel, mu, t = (np.array(column) for column in zip(*cases))
    got = initial_mode(accel, mu, t)
    expected = [_expected_mode(*case) for case in cases]
    mismatched = [(case, g, e) for case, g, e in zip(cases, got, expected) if g != e]
    assert not mismatched, mismatched[:5]
    assert set(expected) == {"rest", "slide", "rock", "slide-rock"}  # the grid reaches every mode


def test_paper_prototypes_slide_with_best_fit_mu_and_rock_with_wood_mu():
    """Section 4-5: with best-fit mu the prototypes slide; with mu = 0.68 they rock."""
    for height_cm, width_cm, mu_best in [(228.6, 62.2, 0.13), (213.4, 66.0, 0.17), (180.3, 58.4, 0.20)]:
        t = width_cm / height_cm
        for pta in (0.54, 0.60, 0.84, 0.96):
            assert initial_mode(pta, mu_best, t) == "slide"
            assert initial_mode(pta, 0.68, t) in ("rock", "slide-rock")
        assert initial_mode(0.54, 0.68, t) == "rock"


def test_scalar_in_scalar_out_and_arrays_keep_shape():
    assert isinstance(initial_mode(0.5, 0.2, 0.3), str)
    assert initial_mode(np.full((2, 3), 0.5), 0.2, 0.3).shape == (2, 3)
    assert isinstance(friction_required_to_rock(0.5, 0.3), float)
