"""The yielding stick's pushover, and the building sheet's ``pushover_slope_ratio`` that finds α from it.

An engineer with a pushover of the building has its base shear at first yield (``yield_base_shear_g``) and, from
the same curve, how steeply it rises after yield: its slope at 2 % roof drift over its initial slope. That slope
is what α (the columns' bending against the storeys' shear) sets once the storeys yield, so the sheet's
``pushover_slope_ratio`` gives the α whose stick has it (assess/building/pushover.py). Checked here: the pushover
against closed forms (a shear stick's storeys in equilibrium with the lateral forces at every step, its slope
after yield its springs' hardening); the α found is the one that made the slope; the sheet refuses the value at
its cell where it cannot give α; the found α reaches the model, ``floors.csv`` and the notes. Against OpenSees
frames' own pushovers: tests/verification/test_truth_pushover.py.
"""
from __future__ import annotations

import numpy as np
import pytest

from assess.assessment.floors import (PUSHOVER_ALPHA_BOUNDS, alpha_of, building_model_of, building_modes_of,
                                      building_note, pushover_alpha, storey_stiffness_of)
from assess.building.design import vertical_distribution
from assess.building.modes import building_modes
from assess.building.nonlinear import GRAVITY_M_S2, YieldingStick
from assess.building.pushover import alpha_from_pushover, stick_pushover
from assess.building.yielding import yielding_building
from assess.errors import InputError
from assess.inventory import read_workbook
from assess.inventory.site_building import BuildingSheet, SiteSheet
from workbooks import good_sheets

SITE = SiteSheet(sds_g=1.0, sd1_g=0.6)


def _shear_stick(hardening=0.03):
    """Three storeys of 3.5 m, no column, stiffness 60, 50, 40 W/m, yielding at 0.20, 0.16, 0.10 W."""
    masses = np.full(3, 1.0e5)
    weight = masses.sum() * GRAVITY_M_S2
    return YieldingStick(masses, np.full(3, 3.5), np.array([60.0, 50.0, 40.0]) * weight,
                         np.array([0.20, 0.16, 0.10]) * weight, np.full(3, hardening), "bilinear", np.zeros((3, 3)),
                         (0.0, 0.0)), weight


def _backbone_drift(shear, k0, fy, b):
    """A bilinear spring's drift at a force ``shear`` on its backbone (inverse of k_0 d, F_y + b k_0 (d − d_y))."""
    return np.where(shear <= fy, shear / k0, fy / k0 + (shear - fy) / (b * k0))


def test_a_shear_stick_is_in_equilibrium_with_the_lateral_forces_at_every_step():
    """Storey i of a shear stick carries the forces above it, λ Σ_{j ≥ i} f_j: its drift is its backbone's at that
    shear, and the roof's displacement their sum; the pushover's drifts and base shear must say the same."""
    stick, weight = _shear_stick()
    period_s = 0.5
    pushover = stick_pushover(stick, period_s)
    pattern = vertical_distribution(stick.floor_masses_kg, np.cumsum(stick.storey_heights_m), period_s)
    pattern = np.asarray(pattern) / np.sum(pattern)
    storey_share = np.cumsum(pattern[::-1])[::-1]
    for base_shear_g, drifts in zip(pushover.base_shear_g, pushover.storey_drift_m):
        expected = _backbone_drift(base_shear_g * weight * storey_share, stick.stiffness_n_m, stick.yield_force_n,
                                   stick.hardening)
        np.testing.assert_allclose(drifts, expected, rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(pushover.storey_drift_m.sum(axis=1), pushover.roof_drift_ratio * 10.5, rtol=1e-9)
    # every storey has yielded by 2 % roof drift: each spring at b k_0 in series, the slope is b of the initial
    assert np.all(pushover.storey_drift_m[-1] > stick.yield_force_n / stick.stiffness_n_m)
    assert pushover.slope_ratio == pytest.approx(0.03, rel=1e-9)


def test_a_column_beside_the_springs_adds_its_own_stiffness_after_yield():
    """One storey with a linear part beside its spring: after yield the slope is (b k_0 + k_lin)/(k_0 + k_lin)."""
    weight = 1.0e5 * GRAVITY_M_S2
    k0, k_lin = 100.0 * weight, 25.0 * weight
    stick = YieldingStick(np.array([1.0e5]), np.array([4.0]), np.array([k0]), np.array([0.1 * weight]),
                          np.array([0.02]), "pinching", np.array([[k_lin]]), (0.0, 0.0))
    assert stick_pushover(stick, 0.4).slope_ratio == pytest.approx((0.02 * k0 + k_lin) / (k0 + k_lin), rel=1e-9)


def _frame(storeys=8, system="steel moment frame", **extra):
    return BuildingSheet(storeys=storeys, height_m=4.0 * storeys, system=system, period_s=0.15 * storeys,
                         yield_base_shear_g=0.15, **extra)


def _slope_at(sheet: BuildingSheet, alpha: float) -> float:
    modes = building_modes(sheet.storeys, sheet.height_m / sheet.storeys, system=sheet.system,
                           period_s=sheet.period_s, alpha=alpha, storey_stiffness=storey_stiffness_of(sheet))
    return stick_pushover(yielding_building(modes, sheet.system, yield_base_shear_g=0.15,
                                            p_delta=sheet.p_delta).stick, sheet.period_s).slope_ratio


@pytest.mark.parametrize("storeys,system", [(4, "steel moment frame"), (8, "concrete moment frame"),
                                            (12, "steel moment frame"), (20, "steel moment frame"),
                                            (6, "braced frame")])
def test_the_slope_after_yield_falls_as_alpha_rises(storeys, system):
    """With the design's storey stiffnesses every storey has yielded by 2 % roof drift: a weaker column (a larger
    α) leaves less stiffness, and the slope falls with α over the whole search, down to what the springs'
    hardening leaves."""
    sheet = _frame(storeys, system)
    alphas = np.geomspace(*PUSHOVER_ALPHA_BOUNDS, 9)
    slopes = [_slope_at(sheet, a) for a in alphas]
    assert np.all(np.diff(slopes) < 0), slopes
    assert slopes[-1] > 0.03 and slopes[0] > 0.9  # the springs' own hardening beside a weak column; a stiff one


def test_where_two_alpha_give_the_slope_the_one_nearer_the_system_s_is_taken_and_the_note_names_the_other():
    """Uniform storeys, each as strong as it is stiff: the top storeys yield later the weaker the column, and
    between α 13 and 16 the slope at 2 % rises again (they have not yielded there): a slope within that rise
    has more than one α."""
    uniform = tuple(np.ones(8))
    sheet = _frame(8, storey_stiffness=uniform)
    slopes = {a: _slope_at(sheet, a) for a in (13.0, 15.6)}
    assert slopes[15.6] > slopes[13.0]  # the rise
    given = _frame(8, storey_stiffness=uniform, pushover_slope_ratio=float(np.mean(list(slopes.values()))))
    found = pushover_alpha(given)
    assert len(found.roots) >= 2 and found.matched
    assert found.alpha == min(found.roots, key=lambda a: abs(np.log(a / 12.0)))
    for alpha in found.roots:
        assert _slope_at(sheet, alpha) == pytest.approx(given.pushover_slope_ratio, rel=1e-5)
    note = building_note(building_model_of(given, SITE), given, [8], None)
    assert "nearer the system's typical α" in note


@pytest.mark.parametrize("alpha", [2.0, 7.0, 15.0])
def test_the_alpha_found_is_the_one_whose_stick_made_the_slope(alpha):
    """Write the slope of the stick at α in the sheet: the α found is that α (the search's own tolerance), and it
    is the one the modes and the yielding stick take."""
    sheet = _frame(8)
    slope = _slope_at(sheet, alpha)
    given = _frame(8, pushover_slope_ratio=slope)
    found = pushover_alpha(given)
    assert found.alpha == pytest.approx(alpha, rel=1e-5)
    assert found.roots == (found.alpha,)
    assert alpha_of(given) == found.alpha
    assert building_modes_of(given).alpha == found.alpha
    assert building_model_of(given, SITE).modes.alpha == found.alpha


def test_a_slope_no_alpha_gives_takes_the_nearest_and_says_so():
    flat = _frame(8, pushover_slope_ratio=0.005)  # below the springs' hardening: no column is that weak
    found = pushover_alpha(flat)
    assert not found.matched and found.alpha == PUSHOVER_ALPHA_BOUNDS[1]
    note = building_note(building_model_of(flat, SITE), flat, [8], None)
    assert "at no α from 0.5 to 30" in note and "comes nearest" in note


def test_a_building_that_has_not_yielded_by_then_keeps_the_system_s_alpha():
    """Strong enough not to yield by 2 % roof drift, the stick has the slope before yield at every α (1): no α gives
    a slope after yield, and of the α alike the system's typical one is kept."""
    strong = BuildingSheet(storeys=6, height_m=24.0, system="concrete moment frame", period_s=3.0,
                           yield_base_shear_g=3.0, pushover_slope_ratio=0.05)
    found = pushover_alpha(strong)
    assert not found.matched
    assert found.slope_ratio_range[0] == pytest.approx(1.0, rel=1e-9)
    assert found.alpha == 12.0


def test_alpha_from_pushover_on_a_known_curve():
    found = alpha_from_pushover(0.2, lambda a: 1.0 / (1.0 + a), (0.5, 30.0), prefer=12.0)
    assert found.alpha == pytest.approx(4.0, rel=1e-6)
    assert found.stick_slope_ratio == pytest.approx(0.2, rel=1e-6)


def _sheets(building):
    sheets = good_sheets()
    sheets["building"] = [["key", "value"]] + [list(pair) for pair in building]
    return sheets


BASE = [("storeys", 8), ("height_m", 32), ("system", "steel moment frame"), ("period_s", 1.2)]


def test_it_is_read_where_given(make_workbook):
    sheet = read_workbook(make_workbook(_sheets(BASE + [("yield_base_shear_g", 0.15),
                                                        ("pushover_slope_ratio", 0.06)]))).building
    assert sheet.pushover_slope_ratio == 0.06 and sheet.rows["pushover_slope_ratio"] == 7


@pytest.mark.parametrize("rows,cell,words", [
    ([("yield_base_shear_g", 0.15), ("pushover_slope_ratio", 0.06), ("lateral_stiffness_ratio", 10)], "A7",
     "both lateral_stiffness_ratio and pushover_slope_ratio"),
    ([("pushover_slope_ratio", 0.06)], "A6", "without yield_base_shear_g"),
    ([("yield_base_shear_g", 0.15), ("pushover_slope_ratio", 0)], "B7", "pushover_slope_ratio"),
    ([("yield_base_shear_g", 0.15), ("pushover_slope_ratio", 1.5)], "B7", "pushover_slope_ratio"),
    ([("response", "elastic"), ("pushover_slope_ratio", 0.06)], "A7", "response is elastic"),
])
def test_where_it_cannot_give_alpha_it_is_refused_at_its_cell(make_workbook, rows, cell, words):
    assert_refused_at(make_workbook, rows, cell, words)


def assert_refused_at(make_workbook, rows, cell, words, base=BASE):
    """The 8-storey frame's sheet (or ``base``) with ``rows`` added is refused with one problem, at the building
    sheet's ``cell``, whose message has ``words``."""
    with pytest.raises(InputError) as error:
        read_workbook(make_workbook(_sheets(base + rows)))
    problems = error.value.problems
    assert [(p.sheet, p.cell) for p in problems] == [("building", cell)], [(p.cell, p.message) for p in problems]
    assert words in problems[0].message


@pytest.mark.parametrize("system", ["shear wall", "other"])
def test_a_wall_or_a_shear_stick_is_refused(make_workbook, system):
    rows = [("storeys", 6), ("height_m", 24), ("system", system), ("yield_base_shear_g", 0.3),
            ("pushover_slope_ratio", 0.06)]
    with pytest.raises(InputError) as error:
        read_workbook(make_workbook(_sheets(rows)))
    (problem,) = error.value.problems
    assert problem.cell == "A6" and "frames and braced frames only" in problem.message
    assert "lateral_stiffness_ratio" in problem.fix


def test_the_note_and_floors_csv_say_which_alpha_ran_and_whence():
    sheet = _frame(8, pushover_slope_ratio=0.06)
    model = building_model_of(sheet, SITE)
    note = building_note(model, sheet, [4, 8], None)
    alpha = pushover_alpha(sheet).alpha
    assert f"α {alpha:.3g} (from pushover_slope_ratio 0.06: the yielding stick's pushover has that slope" in note
    assert "the system's typical value and not this building's" not in note  # no caution: α is the building's
