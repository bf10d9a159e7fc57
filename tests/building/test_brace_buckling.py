"""A braced frame whose braces buckle: the ``buckling`` law and the building sheet's ``brace_buckling``.

Each storey is its two braces, one pulled and one pushed (:func:`assess.building.hysteresis.brace_backbones`).
Checked here against the backbone and its unloading worked by hand and the sheet's contract; against OpenSees'
own brace pair (two mirrored ``Hysteretic`` braces in ``Parallel``) in
``tests/verification/test_yielding_buckling.py`` and ``tests/verification/test_building_yielding_opensees.py``.
"""
from __future__ import annotations

import numpy as np
import pytest

from assess.assessment.floors import building_model_of, building_note
from assess.building.hysteresis import (BRACE_BUCKLING_RATIO, BRACE_POST_BUCKLING_DRIFT_RATIO,
                                        BRACE_POST_BUCKLING_RATIO, spring_forces)
from assess.building.nonlinear import yielding_response
from assess.inventory import read_workbook
from assess.inventory.site_building import BuildingSheet
from tests.building.test_pushover_alpha import _sheets, assert_refused_at

K0, FY, B = 1000.0, 10.0, 0.02
DY = FY / K0


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_a_storey_of_buckling_braces_follows_its_backbone_worked_by_hand(sign):
    """k_0 1000 N/m, F_y 10 N, b 0.02 (d_y 0.01 m), each brace k_0/2, either way:

    * at 0.5 d_y, elastic: 0.5 F_y;
    * at d_y the pushed brace buckles at 0.5 F_y, the pulled one carries k_0/2 d_y = 0.5 F_y: F_y;
    * at 2 d_y the pulled one yields (F_y) and the pushed one has fallen a quarter of the way from 0.5 F_y to
      0.3 × 0.5 F_y = 0.15 F_y, which it reaches at 5 d_y: 0.5 - 0.35/4 = 0.4125 F_y; 1.4125 F_y;
    * at 5 d_y: F_y + 0.02 (k_0/2)(3 d_y) = 1.03 F_y and 0.15 F_y: 1.18 F_y; at 8 d_y 1.06 + 0.15 = 1.21 F_y.
    """
    assert (BRACE_BUCKLING_RATIO, BRACE_POST_BUCKLING_RATIO, BRACE_POST_BUCKLING_DRIFT_RATIO) == (0.5, 0.3, 5.0)
    path = sign * DY * np.linspace(0.0, 8.0, 1601)[1:]
    forces = sign * spring_forces(path, "buckling", K0, FY, hardening=B) / FY
    at = {d: forces[int(round(d * 200)) - 1] for d in (0.5, 1.0, 2.0, 5.0, 8.0)}
    assert at == pytest.approx({0.5: 0.5, 1.0: 1.0, 2.0: 1.4125, 5.0: 1.18, 8.0: 1.21}, rel=1e-9)


def test_unloading_after_buckling_is_elastic_on_both_braces_then_the_buckled_brace_is_pinched():
    """From 2 d_y (pulled brace yielded at F_y, pushed one at 0.4125 F_y), back by 0.1 d_y: each brace unloads at
    its stiffness k_0/2 (no degradation, β 0), 1.4125 − 2 × 0.05 = 1.3125 F_y; at 1.2 d_y, 1.0 − 0.4 = 0.6 and
    0.4125 − 0.4 = 0.0125: 0.6125 F_y. The buckled brace's force reaches zero at 2 − 0.825 = 1.175 d_y; pulled
    on, it reloads towards its tension yield (F_y at −2 d_y in its own sense) through the pinching point
    (Hysteretic's rules: pinch_x 0.4, pinch_y 0.2): 0.2 F_y at 1.175 + 0.4 (−0.4 − 1.175) = 0.545 d_y, the
    target point −2 d_y + 0.8 × 2 d_y = −0.4 d_y. At 1.0 d_y it carries −0.2 × 0.175/0.63 F_y, the pulled one
    0.5 F_y: 0.4444 F_y, where an elastic storey carries F_y."""
    path = DY * np.concatenate([np.linspace(0.0, 2.0, 401)[1:], [1.9, 1.2, 1.0]])
    forces = spring_forces(path, "buckling", K0, FY, hardening=B) / FY
    assert forces[-4:] == pytest.approx([1.4125, 1.3125, 0.6125, 0.5 - 0.2 * 0.175 / 0.63], rel=1e-9)


def test_below_the_buckling_drift_the_storey_is_the_elastic_spring():
    """Below d_y neither brace buckles nor yields: k_0 d, whatever the path."""
    rng = np.random.default_rng(29)
    path = 0.99 * DY * np.sin(np.cumsum(rng.uniform(0.0, 0.3, 500)))
    assert np.allclose(spring_forces(path, "buckling", K0, FY, hardening=B), K0 * path, rtol=1e-12, atol=1e-12)


def _braced(**extra):
    return BuildingSheet(storeys=6, height_m=24.0, system="braced frame", period_s=0.6, yield_base_shear_g=0.3,
                         response="yielding", **extra)


def test_a_braced_frame_with_brace_buckling_has_buckling_storeys_and_the_note_says_so():
    plain, buckled = building_model_of(_braced(), None), building_model_of(_braced(brace_buckling=True), None)
    assert plain.stick.law == "bilinear" and buckled.stick.law == "buckling"
    # the same elastic stick and first yield: only the springs' law differs
    assert np.allclose(plain.stick.stiffness_n_m, buckled.stick.stiffness_n_m)
    assert np.allclose(plain.stick.yield_force_n, buckled.stick.yield_force_n)
    assert plain.key != buckled.key  # the floors' cache tells them apart
    note = building_note(buckled, _braced(brace_buckling=True), [3, 6], None)
    assert "the pushed one buckles at the storey's first yield, at 0.5 of the pulled one's tension strength" in note
    assert "hardening at 3% of its stiffness after yield (by default)" in note
    assert "write yes in brace_buckling" not in note
    plain_note = building_note(plain, _braced(), [3, 6], None)
    assert "write yes in brace_buckling" in plain_note


def test_the_braces_buckling_changes_the_floors_once_a_storey_passes_its_first_yield():
    """Under a motion that leaves every storey elastic the two laws give the same floors; under one that yields
    them, not."""
    plain, buckled = building_model_of(_braced(), None), building_model_of(_braced(brace_buckling=True), None)
    t = np.arange(0.0, 10.0, 0.01)
    pulse = np.sin(2.0 * np.pi * t / 0.6) * np.exp(-((t - 3.0) / 1.5) ** 2)
    small = [yielding_response(m.stick, 0.05 * pulse, 0.01) for m in (plain, buckled)]
    assert small[0].ductility.max() < 1.0
    # the same to rounding: the braces' two halves of k_0 in the damping's tangent
    assert np.abs(small[0].floor_accel_g - small[1].floor_accel_g).max() < 1e-9 * np.abs(small[0].floor_accel_g).max()
    large = [yielding_response(m.stick, 1.5 * pulse, 0.01) for m in (plain, buckled)]
    assert large[1].ductility.max() > 2.0
    assert np.abs(large[0].floor_accel_g - large[1].floor_accel_g).max() > 0.05 * np.abs(large[0].floor_accel_g).max()


BRACED = [("storeys", 6), ("height_m", 24), ("system", "braced frame"), ("period_s", 0.6)]


def test_it_is_read_where_given(make_workbook):
    sheet = read_workbook(make_workbook(_sheets(BRACED + [("yield_base_shear_g", 0.3),
                                                          ("brace_buckling", "yes")]))).building
    assert sheet.brace_buckling and sheet.rows["brace_buckling"] == 7
    sheet = read_workbook(make_workbook(_sheets(BRACED + [("yield_base_shear_g", 0.3),
                                                          ("brace_buckling", "no")]))).building
    assert not sheet.brace_buckling


@pytest.mark.parametrize("rows,cell,words", [
    ([("system", "steel moment frame"), ("brace_buckling", "yes")], "A6", "but the system is steel moment frame"),
    ([("system", "braced frame"), ("brace_buckling", "sometimes")], "B6", "is not yes or no"),
])
def test_where_it_cannot_apply_it_is_refused_at_its_cell(make_workbook, rows, cell, words):
    assert_refused_at(make_workbook, rows, cell, words, base=[("storeys", 8), ("height_m", 32), ("period_s", 1.2)])


@pytest.mark.parametrize("rows,cell,words", [
    ([("yield_base_shear_g", 0.3), ("pushover_slope_ratio", 0.06), ("brace_buckling", "yes")], "A8",
     "buckling braces' storeys lose strength"),
    ([("response", "elastic"), ("brace_buckling", "yes")], "A7", "brace_buckling is given but response is elastic"),
])
def test_with_what_it_cannot_go_with_it_is_refused(make_workbook, rows, cell, words):
    assert_refused_at(make_workbook, rows, cell, words, base=BRACED)
