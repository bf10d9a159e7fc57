"""The yielding stick's strength over the height (issue 29): the code's share, raised where the design makes a
storey stronger (assess.building.nonlinear.STRENGTH_BY_SYSTEM; docs/workbook.md).

Checked against closed forms computed here, not against the functions' own output:

* frames: a storey as strong as it is stiff. In a pure shear stick (no column) each spring's drift at yield is
  F_y/k_0 whatever the load pattern, so every storey yields at one drift ratio, the least that leaves none
  below its code share: the storey whose share asks most of its stiffness yields at its share;
* walls: capacity design. Under the code's forces scaled up, the base yields first and every storey yields
  where the moment of those forces at its base reaches a straight line from the base's moment to zero at
  the top (the linear moment envelope), the moments summed here by hand;
* the elastic column and the code's share: with the ``"code"`` profile the springs carry the code's shares
  as before.
"""
from __future__ import annotations

import numpy as np
import pytest

from assess.building.design import storey_shear_ratios
from assess.building.modes import building_modes
from assess.building.nonlinear import GRAVITY_M_S2, STRENGTH_BY_SYSTEM, yielding_stick
from assess.building.yielding import yielding_building

TAPER = np.array([1.0, 0.95, 0.9, 0.8, 0.7, 0.6, 0.5, 0.4])
HEIGHT_M = 4.0


def _code_shares(storeys, period_s):
    return storey_shear_ratios(np.ones(storeys), HEIGHT_M * np.arange(1, storeys + 1), period_s)


@pytest.mark.parametrize("storeys, period_s", [(4, 0.6), (8, 1.2)])
def test_frame_storeys_yield_at_one_drift_ratio_the_first_to_yield_at_its_code_share(storeys, period_s):
    """A pure shear stick (no column), tapering storeys: every spring yields at one drift ratio θ_y, the least that
    leaves no storey below its code share, so the storey whose share asks most of its stiffness yields at its share
    and every other above it (θ_y worked out here from the shares and the taper: max_j share_j / k_j)."""
    shares = _code_shares(storeys, period_s)
    stick = yielding_stick(storeys, HEIGHT_M, 0.2 * shares, system="steel moment frame", period_s=period_s,
                           alpha=np.inf, storey_stiffness=TAPER[:storeys])
    assert np.all(stick.linear_stiffness_n_m == 0.0)  # a pure shear stick: springs carry the storey shear
    yield_drift_ratio = stick.yield_force_n / stick.stiffness_n_m / HEIGHT_M
    np.testing.assert_allclose(yield_drift_ratio, yield_drift_ratio[0], rtol=1e-12)
    weight = storeys * 1.0e5 * GRAVITY_M_S2
    relative_stiffness = TAPER[:storeys] / TAPER[0]
    first = int(np.argmax(shares / relative_stiffness))  # the storey whose share asks most of its stiffness
    expected = 0.2 * weight * relative_stiffness * float(np.max(shares / relative_stiffness))
    np.testing.assert_allclose(stick.yield_force_n, expected, rtol=1e-12)
    assert stick.yield_force_n[first] == pytest.approx(0.2 * shares[first] * weight, rel=1e-12)
    assert np.all(stick.yield_force_n >= 0.2 * shares * weight * (1 - 1e-12))
    if storeys == 8:  # the taper outruns the upper shares: a storey above the first yields first
        assert first > 0 and stick.yield_force_n[0] > 0.2 * weight * (1 + 1e-3)


def test_uniform_storeys_of_a_frame_are_all_as_strong_as_the_first():
    stick = yielding_stick(6, HEIGHT_M, 0.3 * _code_shares(6, 0.9), system="steel moment frame", period_s=0.9,
                           alpha=np.inf)
    np.testing.assert_allclose(stick.yield_force_n, stick.yield_force_n[0], rtol=1e-12)


@pytest.mark.parametrize("storeys, period_s", [(6, 0.5), (10, 1.0)])
def test_a_capacity_designed_wall_yields_first_at_its_base_and_above_on_a_linear_moment_envelope(storeys,
                                                                                               period_s):
    heights = HEIGHT_M * np.arange(1, storeys + 1)
    k = np.clip(1.0 + (period_s - 0.5) / 2.0, 1.0, 2.0)            # ASCE 7-22 §12.8.3, by hand
    forces = heights ** k / np.sum(heights ** k)
    shears = np.cumsum(forces[::-1])[::-1]
    # the equivalent shear stick's springs (a wall's default is its base hinge, test_wall_hinge.py)
    stick = yielding_stick(storeys, HEIGHT_M, 0.4 * shears, system="shear wall", period_s=period_s,
                           flexure="equivalent shear")
    weight = storeys * 1.0e5 * GRAVITY_M_S2
    load_factor = stick.yield_force_n / (shears * weight)  # storey i yields under λ_i × the code's forces
    assert np.all(load_factor[1:] > load_factor[0])               # the base yields first
    base = HEIGHT_M * np.arange(storeys)
    moment = np.array([sum(forces[j] * (heights[j] - base[i]) for j in range(i, storeys)) for i in range(storeys)])
    strength_moment = load_factor * moment                        # the wall's strength at each storey's base
    line = strength_moment[0] * (1.0 - base / heights[-1])
    assert np.all(line >= 0.4 * moment * (1 - 1e-12))  # the envelope lies above the code's moments
    np.testing.assert_allclose(strength_moment, line, rtol=1e-12)


def test_the_code_profile_keeps_the_code_shares():
    shares = _code_shares(4, 0.6)
    stick = yielding_stick(4, HEIGHT_M, 0.2 * shares, system="steel moment frame", period_s=0.6, alpha=np.inf,
                           strength_profile="code")
    np.testing.assert_allclose(stick.yield_force_n, 0.2 * shares * 4 * 1.0e5 * GRAVITY_M_S2, rtol=1e-12)
    with pytest.raises(ValueError, match="strength_profile"):
        yielding_stick(4, HEIGHT_M, shares, system="other", period_s=0.6, strength_profile="uniform")


@pytest.mark.parametrize("system", sorted(STRENGTH_BY_SYSTEM))
def test_the_reported_storey_strength_is_the_sticks(system):
    """floors.csv's storey_yield_ratio, each storey's spring as the base shear under the code's forces at which it
    yields: the first to yield does so at the given strength (a pushover's first yield, whichever storey), no
    storey below the code's share; a wall on its base hinge yields at its base at the given strength."""
    modes = building_modes(5, 3.5, system=system, period_s=0.7)
    building = yielding_building(modes, system, yield_base_shear_g=0.3)
    ratios = building.strength.storey_yield_ratio
    code = 0.3 * storey_shear_ratios(np.ones(5), 3.5 * np.arange(1, 6), 0.7)
    if system == "shear wall":  # its base hinge: the storeys above do not yield, no strength to report
        assert ratios[0] == pytest.approx(0.3, rel=1e-12)
        assert np.all(np.isnan(ratios[1:]))
        return
    assert np.min(ratios / code) == pytest.approx(1.0, rel=1e-12)
    assert np.all(ratios >= code * (1 - 1e-12))
    if system in ("steel moment frame", "concrete moment frame"):
        # the top storey raised above its share (in a braced frame, α 4, the column already leaves the top
        # storey's springs more than their share of the code's forces)
        assert ratios[-1] > code[-1] * 1.2, (system, ratios, code)
