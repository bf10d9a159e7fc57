"""The storeys' stiffness profile (issue 29): the system's design profile by default, the engineer's where given,
taken by both the elastic modes and the yielding stick (docs/workbook.md, ``storey_stiffness``).

Checked against what the profile means, computed here:

* a frame's design profile is a *uniform drift* design: a shear building with those storey stiffnesses,
  loaded by ASCE 7-22 §12.8.3's forces (k worked by hand), drifts the same ratio in every storey; the storey
  shears are summed here from C_vx = h_x^k / Σ h_i^k (equal floor weights);
* a wall's and ``other``'s profile is uniform;
* the sheet's profile (given, or the default) reaches the modes (the stiffness matrix they solve is the
  chain of those springs plus the column, checked against a stiffness matrix assembled by hand for a shear
  building) and the stick (its springs in the same ratios), and floors.csv reports it.
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy.linalg import eigh

from assess.assessment.floors import building_model_of, building_modes_of
from assess.building.design import design_storey_stiffness
from assess.building.yielding import YieldingBuilding
from assess.inventory.site_building import BuildingSheet, SiteSheet

SITE = SiteSheet(sds_g=1.0, sd1_g=0.6)


def _hand_storey_shears(storeys, storey_height_m, exponent_k):
    heights = storey_height_m * np.arange(1, storeys + 1)
    forces = heights ** exponent_k / np.sum(heights ** exponent_k)
    return forces, np.array([forces[i:].sum() for i in range(storeys)])


def _shear_matrix(k):
    n = len(k)
    matrix = np.zeros((n, n))
    for i in range(n):
        matrix[i, i] = k[i] + (k[i + 1] if i + 1 < n else 0.0)
        if i + 1 < n:
            matrix[i, i + 1] = matrix[i + 1, i] = -k[i + 1]
    return matrix


@pytest.mark.parametrize("system", ["steel moment frame", "concrete moment frame", "braced frame",
                                    "eccentrically braced frame"])
@pytest.mark.parametrize("storeys, period_s, exponent_k", [(4, 0.6, 1.05), (8, 1.2, 1.35), (12, 2.5, 2.0),
                                                            (3, 0.4, 1.0)])
def test_a_frames_design_profile_drifts_every_storey_alike_under_the_codes_forces(system, storeys, period_s,
                                                                                  exponent_k):
    forces, shears = _hand_storey_shears(storeys, 3.5, exponent_k)
    profile = design_storey_stiffness(system, np.ones(storeys), 3.5 * np.arange(1, storeys + 1), period_s)
    np.testing.assert_allclose(profile, shears / shears[0], rtol=1e-12)
    displacement = np.linalg.solve(_shear_matrix(profile), forces)
    drifts = np.diff(np.concatenate([[0.0], displacement]))
    np.testing.assert_allclose(drifts, drifts[0], rtol=1e-10)


@pytest.mark.parametrize("system", ["shear wall", "other"])
def test_a_walls_and_others_design_profile_is_uniform(system):
    np.testing.assert_array_equal(design_storey_stiffness(system, np.ones(6), 3.5 * np.arange(1, 7), 0.5),
                                  np.ones(6))


def test_the_sheets_default_profile_reaches_the_modes_and_the_stick():
    """An 8-storey steel moment frame, T_1 1.2 s (k 1.35): the modes and the stick take the design profile."""
    sheet = BuildingSheet(storeys=8, height_m=32.0, system="steel moment frame", period_s=1.2)
    _, shears = _hand_storey_shears(8, 4.0, 1.35)
    modes = building_modes_of(sheet)
    np.testing.assert_allclose(modes.storey_stiffness, shears / shears[0], rtol=1e-12)
    building = building_model_of(sheet, SITE)
    assert isinstance(building, YieldingBuilding)
    springs = building.stick.stiffness_n_m
    np.testing.assert_allclose(springs / springs[0], shears / shears[0], rtol=1e-12)


def test_the_engineers_profile_replaces_the_default_in_the_modes_and_the_stick():
    given = (1.0, 0.9, 0.78, 0.62)
    sheet = BuildingSheet(storeys=4, height_m=16.0, system="steel moment frame", period_s=0.6,
                          storey_stiffness=tuple(10.0 * k for k in given))  # any unit: only the ratios count
    modes = building_modes_of(sheet)
    np.testing.assert_allclose(modes.storey_stiffness, given, rtol=1e-12)
    springs = building_model_of(sheet, SITE).stick.stiffness_n_m
    np.testing.assert_allclose(springs / springs[0], given, rtol=1e-12)


def test_a_shear_buildings_modes_are_those_of_the_springs_given():
    """With no flexural column (α given as ∞ is not a sheet key, so the modes are solved here for a shear
    building assembled by hand and compared with building_modes at α = ∞ and the same profile)."""
    from assess.building.modes import building_modes
    given = np.array([1.0, 0.7, 0.4])
    modes = building_modes(3, 3.0, alpha=np.inf, storey_stiffness=given, period_s=0.5)
    omega2 = eigh(_shear_matrix(given), np.eye(3), eigvals_only=True)
    np.testing.assert_allclose(modes.periods_s / modes.periods_s[0], np.sqrt(omega2[0] / omega2), rtol=1e-10)
    np.testing.assert_allclose(modes.storey_stiffness, given, rtol=1e-12)


def test_a_walls_default_modes_are_todays_uniform_ones():
    sheet = BuildingSheet(storeys=5, height_m=20.0, system="shear wall", period_s=0.5)
    from assess.building.modes import building_modes
    today = building_modes(5, 4.0, system="shear wall", period_s=0.5)
    modes = building_modes_of(sheet)
    np.testing.assert_array_equal(modes.periods_s, today.periods_s)
    np.testing.assert_array_equal(modes.shapes, today.shapes)


def test_floors_csv_reports_the_profile_used():
    from assess.building.floors import floors_table
    from assess.building.response import floor_records
    from assess.hazard.records import Record
    sheet = BuildingSheet(storeys=4, height_m=16.0, system="steel moment frame", period_s=0.6)
    modes = building_modes_of(sheet)
    ground = [Record(0.1 * np.sin(np.linspace(0.0, 20.0, 500)), 0.01, "g")]
    floors = {0: ground, **floor_records(modes, ground, floors=[1, 2, 3, 4])}
    table = floors_table(modes, floors, "DE").set_index("floor")
    _, shears = _hand_storey_shears(4, 4.0, 1.05)
    assert np.isnan(table.loc[0, "storey_stiffness"])
    np.testing.assert_allclose(table.loc[[1, 2, 3, 4], "storey_stiffness"], shears / shears[0], rtol=1e-12)
