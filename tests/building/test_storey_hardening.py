"""The building sheet's ``storey_hardening_ratio``: the model's storeys' stiffness after yield, given.

The yielding stick's springs harden at :data:`~assess.building.nonlinear.DEFAULT_HARDENING` unless the engineer
writes the model's own. Checked here against closed forms (a storey's slope after yield is its hardening; a wall's
hinge gives the assembly the hardening asked for) and the sheet's contract; against OpenSees frames whose springs
harden at 2 % in ``tests/verification/test_truth_pushover.py``.
"""
from __future__ import annotations

import numpy as np
import pytest

from assess.assessment.floors import building_model_of, building_note, pushover_alpha, storey_stiffness_of
from assess.building.modes import building_modes
from assess.building.nonlinear import DEFAULT_HARDENING
from assess.building.pushover import stick_pushover
from assess.building.wall_hinge import STIFFNESS_RATIO_N
from assess.building.yielding import yielding_building
from assess.errors import InputError
from assess.inventory import read_workbook
from assess.inventory.site_building import BuildingSheet
from tests.building.test_pushover_alpha import BASE, _sheets, assert_refused_at  # an 8-storey frame's sheet


def _sheet(storeys=8, system="steel moment frame", **extra):
    return BuildingSheet(storeys=storeys, height_m=4.0 * storeys, system=system, period_s=0.15 * storeys,
                         yield_base_shear_g=0.15, response="yielding", **extra)


def test_a_single_storey_s_slope_after_yield_is_the_hardening_given():
    """One shear storey (``other``: an equivalent shear stick, no column): once it yields, the base shear rises by
    b k0 per metre of drift, so the pushover's slope at 2 % drift over its first slope is b itself."""
    for hardening in (0.005, 0.015, 0.1):
        stick = building_model_of(_sheet(1, "other", storey_hardening_ratio=hardening), None).stick
        assert np.all(stick.hardening == hardening)
        assert stick_pushover(stick, 0.15).slope_ratio == pytest.approx(hardening, abs=1e-9)


def test_without_it_the_storeys_harden_as_before():
    stick = building_model_of(_sheet(), None).stick
    assert np.all(stick.hardening == DEFAULT_HARDENING)


def test_a_wall_s_hinge_gives_the_wall_the_hardening_given():
    """A shear wall yields at its base hinge, in series with the elastic wall: the hinge hardens at
    b/(1 + n(1 − b)) so that the assembly hardens at b (Ibarra & Krawinkler's stiffness modification, the module
    :mod:`assess.building.wall_hinge`)."""
    wall = building_model_of(_sheet(6, "shear wall", storey_hardening_ratio=0.02), None).stick
    n = STIFFNESS_RATIO_N
    assert wall.hardening == 0.02
    assert wall.hinge_hardening == pytest.approx(0.02 / (1.0 + n * (1.0 - 0.02)), rel=1e-12)


def _slope_at(sheet: BuildingSheet, alpha: float, hardening: float) -> float:
    modes = building_modes(sheet.storeys, sheet.height_m / sheet.storeys, system=sheet.system,
                           period_s=sheet.period_s, alpha=alpha, storey_stiffness=storey_stiffness_of(sheet))
    model = yielding_building(modes, sheet.system, yield_base_shear_g=0.15, hardening=hardening)
    return stick_pushover(model.stick, sheet.period_s).slope_ratio


@pytest.mark.parametrize("alpha, hardening", [(7.0, 0.015), (20.0, 0.02), (5.0, 0.05)])
def test_the_pushover_s_alpha_is_found_with_the_hardening_given(alpha, hardening):
    """The slope of a stick at α whose storeys harden at b: with b given the α found is α; with the stick's own
    3 % it is another (above α where b is less: stiffer springs after yield leave less to the column)."""
    slope = _slope_at(_sheet(), alpha, hardening)
    found = pushover_alpha(_sheet(pushover_slope_ratio=slope, storey_hardening_ratio=hardening))
    assert found.matched and found.alpha == pytest.approx(alpha, rel=1e-5)
    default = pushover_alpha(_sheet(pushover_slope_ratio=slope))
    assert (default.alpha > alpha) == (hardening < DEFAULT_HARDENING)
    assert abs(np.log(default.alpha / alpha)) > 0.04  # 5 % at α 5, where the column carries most of the slope


def test_a_slope_below_the_stick_s_least_is_matched_with_the_model_s_hardening():
    """A frame of α 20 whose storeys harden at 2 %: its slope is below anything the stick's 3 % gives at α ≤ 30
    (the search takes 30 and says so); with the model's 2 % written, α 20 is found."""
    slope = _slope_at(_sheet(), 20.0, 0.02)
    assert not pushover_alpha(_sheet(pushover_slope_ratio=slope)).matched
    found = pushover_alpha(_sheet(pushover_slope_ratio=slope, storey_hardening_ratio=0.02))
    assert found.matched and found.alpha == pytest.approx(20.0, rel=1e-5)


def test_the_note_says_which_hardening_the_storeys_take():
    given = _sheet(pushover_slope_ratio=0.06, storey_hardening_ratio=0.02)
    note = building_note(building_model_of(given, None), given, [4, 8], None)
    assert "hardening at 2% of their stiffness after yield (storey_hardening_ratio)" in note
    assert "rests on the storeys hardening" not in note  # the caveat is for the stick's own 3 %
    default = _sheet(pushover_slope_ratio=0.06)
    note = building_note(building_model_of(default, None), default, [4, 8], None)
    assert "hardening at 3% of their stiffness after yield (by default)" in note
    assert "rests on the storeys hardening at 3%" in note


def test_it_is_read_where_given(make_workbook):
    sheet = read_workbook(make_workbook(_sheets(BASE + [("yield_base_shear_g", 0.15),
                                                        ("storey_hardening_ratio", 0.02)]))).building
    assert sheet.storey_hardening_ratio == 0.02 and sheet.rows["storey_hardening_ratio"] == 7


@pytest.mark.parametrize("rows,cell,words", [
    ([("storey_hardening_ratio", 0.25)], "B6", "storey_hardening_ratio"),
    ([("storey_hardening_ratio", -0.01)], "B6", "storey_hardening_ratio"),
    ([("response", "elastic"), ("storey_hardening_ratio", 0.02)], "A7", "response is elastic"),
])
def test_where_it_cannot_apply_it_is_refused_at_its_cell(make_workbook, rows, cell, words):
    assert_refused_at(make_workbook, rows, cell, words)


def test_a_building_too_tall_to_yield_refuses_it(make_workbook):
    rows = [("storeys", 41), ("height_m", 164), ("system", "steel moment frame"), ("storey_hardening_ratio", 0.02)]
    with pytest.raises(InputError) as error:
        read_workbook(make_workbook(_sheets(rows)))
    (problem,) = error.value.problems
    assert problem.cell == "A5" and "storey_hardening_ratio is given but the building has 41 storeys" in problem.message


@pytest.mark.parametrize("key, value", [("storey_hardening_ratio", 0.02), ("p_delta", "yes"), ("overstrength", 2.5)])
def test_a_key_of_the_yielding_stick_where_nothing_gives_the_strength_is_refused(make_workbook, key, value):
    """No response row, no yield_base_shear_g, no site sheet: the building answers through its elastic modes, and
    a key only the yielding stick uses would be ignored without a word; it is refused at its key cell."""
    with pytest.raises(InputError) as error:
        read_workbook(make_workbook(_sheets(BASE + [(key, value)])))
    (problem,) = error.value.problems
    assert problem.cell == "A6" and f"{key} is given but nothing gives the storeys' strength" in problem.message
    assert "yield_base_shear_g" in problem.fix
    if key != "overstrength":  # which multiplies the code's design, not a given strength
        assert read_workbook(make_workbook(_sheets(BASE + [("yield_base_shear_g", 0.15), (key, value)]))).building
