"""The storeys' strengths from the engineer's model: the building sheet's ``storey_strength``.

Without it each storey's strength follows the system's rule (a frame storey as strong as it is stiff at one yield
drift ratio, a capacity-designed wall yielding at its base only). With it the storeys are as strong against each
other as the model says, the first to yield doing so at ``yield_base_shear_g`` (or the design's strength), and a
shear wall yields storey by storey. Checked here against a stick worked by hand, the tool's own static pushover (a
Newton solve that shares nothing with the rule but the stick) and the sheet's contract; against OpenSees buildings,
with the items on their floors, in ``tests/verification/test_yielding_storey_strength.py``.
"""
from __future__ import annotations

import numpy as np
import pytest

from assess.assessment.floors import building_model_of, building_note
from assess.building.nonlinear import GRAVITY_M_S2, YieldingStick
from assess.building.pushover import stick_pushover
from assess.building.yielding import BASE_HINGE, STOREY_SPRINGS, storey_table, yielding_histories
from assess.hazard.records import Record
from assess.inventory import read_workbook
from assess.inventory.site_building import BuildingSheet, SiteSheet
from tests.building.test_pushover_alpha import _sheets, assert_refused_at


def _weight_n(stick) -> float:
    return float(stick.floor_masses_kg.sum()) * GRAVITY_M_S2


def test_a_two_storey_shear_stick_takes_the_strengths_given_worked_by_hand():
    """Two storeys of 4 m, T_1 0.5 s (k = 1): the code's forces at floors 4 and 8 m are 1/3 and 2/3 of the base
    shear, so storey 2 carries 2/3 of it. A shear stick (``other``) whose storeys are as strong as 1 and 0.5:
    storey 1's share asks 1 of its strength, storey 2's (2/3)/0.5 = 4/3, so storey 2 yields first, at the given
    0.2 W, and is 2/3 × 0.2 = 0.1333 W strong; storey 1 is twice that, 0.2667 W, and yields later."""
    sheet = BuildingSheet(storeys=2, height_m=8.0, system="other", period_s=0.5, yield_base_shear_g=0.2,
                          response="yielding", storey_strength=(1.0, 0.5))
    model = building_model_of(sheet, None)
    assert model.stick.yield_force_n / _weight_n(model.stick) == pytest.approx([0.8 / 3, 0.4 / 3], rel=1e-12)
    assert stick_pushover(model.stick, 0.5).first_yield_g == pytest.approx(0.2, rel=1e-9)
    uniform = building_model_of(BuildingSheet(storeys=2, height_m=8.0, system="other", period_s=0.5,
                                              yield_base_shear_g=0.2, response="yielding",
                                              storey_strength=(1.0, 1.0)), None)
    # as strong as each other: storey 1's share asks most, both 0.2 W
    assert uniform.stick.yield_force_n / _weight_n(uniform.stick) == pytest.approx([0.2, 0.2], rel=1e-12)


@pytest.mark.parametrize("system,storeys", [("steel moment frame", 8), ("concrete moment frame", 5),
                                            ("braced frame", 6), ("shear wall", 6)])
def test_the_storeys_are_as_strong_as_given_and_the_first_yields_at_the_given_base_shear(system, storeys):
    """Any profile: the springs' strengths are in its ratios, and the stick's own pushover under the code's forces
    (a Newton solve of the stick, column included) first yields at ``yield_base_shear_g``."""
    profile = tuple(np.round(np.linspace(1.0, 0.3, storeys) ** 0.7, 4))
    sheet = BuildingSheet(storeys=storeys, height_m=3.5 * storeys, system=system, period_s=0.1 * storeys,
                          yield_base_shear_g=0.25, response="yielding", storey_strength=profile)
    model = building_model_of(sheet, None)
    assert isinstance(model.stick, YieldingStick) and model.yielding_model == STOREY_SPRINGS
    ratios = model.stick.yield_force_n / np.asarray(profile)
    assert ratios == pytest.approx(np.full(storeys, ratios[0]), rel=1e-12)
    assert stick_pushover(model.stick, 0.1 * storeys).first_yield_g == pytest.approx(0.25, rel=1e-9)


def test_a_shear_wall_with_its_storeys_strengths_yields_storey_by_storey_and_the_note_says_so():
    wall = dict(storeys=6, height_m=21.0, system="shear wall", period_s=0.5, yield_base_shear_g=0.36,
                response="yielding")
    hinged, storeys = (building_model_of(BuildingSheet(**wall, **extra), None)
                       for extra in ({}, {"storey_strength": (1.0, 0.95, 0.9, 0.8, 0.65, 0.45)}))
    assert hinged.yielding_model == BASE_HINGE and storeys.yielding_model == STOREY_SPRINGS
    note = building_note(storeys, BuildingSheet(**wall, storey_strength=(1.0,) * 6), [3, 6], None)
    assert "so the wall yields storey by storey" in note
    assert "the storeys as strong against each other as storey_strength gives" in note
    assert "yields storey by storey" not in building_note(hinged, BuildingSheet(**wall), [3, 6], None)


def test_a_frame_s_note_no_longer_asks_for_the_stiffnesses_to_set_the_strengths():
    frame = dict(storeys=4, height_m=16.0, system="steel moment frame", period_s=0.6, yield_base_shear_g=0.3,
                 response="yielding")
    asks = "give storey_stiffness from the building's model where known"
    without = BuildingSheet(**frame)
    assert asks in building_note(building_model_of(without, None), without, [2, 4], None)
    given = BuildingSheet(**frame, storey_strength=(1.0, 0.9, 0.8, 0.6))
    assert asks not in building_note(building_model_of(given, None), given, [2, 4], None)


def test_the_note_cautions_strengths_given_without_the_stiffnesses_that_go_with_them():
    """Measured on the OpenSees buildings (benchmarks/bench_yielding_equipment.py's ``given + own strength``): the
    storeys' strengths over the system's stiffness profile did no better than the strength alone."""
    frame = dict(storeys=4, height_m=16.0, system="steel moment frame", period_s=0.6, yield_base_shear_g=0.3,
                 response="yielding", storey_strength=(1.0, 0.9, 0.8, 0.6))
    caution = "give storey_stiffness and lateral_stiffness_ratio from the same model"
    apart = BuildingSheet(**frame)
    assert caution in building_note(building_model_of(apart, None), apart, [2, 4], None)
    both = BuildingSheet(**frame, storey_stiffness=(1.0, 0.9, 0.75, 0.6))
    assert caution not in building_note(building_model_of(both, None), both, [2, 4], None)


@pytest.mark.parametrize("system, alpha, apart", [("steel moment frame", 8.0, True), ("shear wall", 30.0, False)])
def test_floors_csv_gives_the_springs_strengths_back_in_the_ratios_given(system, alpha, apart):
    """``storey_spring_yield_ratio`` is the springs' own yield shears over the weight, in ``storey_strength``'s
    ratios; ``storey_yield_ratio`` is the storey's shear when its spring yields under the code's forces, the
    columns' share included: the two part where a frame's continuous column stands apart from its springs (most in
    storey 1, on the column's fixed base), and agree for a wall on storey springs, which has none."""
    given = (1.0, 0.97, 0.93, 0.88, 0.8, 0.7)
    sheet = BuildingSheet(storeys=6, height_m=21.0, system=system, period_s=0.8, yield_base_shear_g=0.25,
                          response="yielding", lateral_stiffness_ratio=alpha, storey_strength=given)
    model = building_model_of(sheet, None)
    time_s = np.arange(0.0, 4.0, 0.005)
    ground = Record(0.4 * np.sin(2.0 * np.pi * time_s / 0.8) * np.minimum(time_s, 1.0), 0.005, "pulse")
    _, histories = yielding_histories(model, [ground])
    table = storey_table(model, histories, range(7)).iloc[1:]
    springs, storeys = table["storey_spring_yield_ratio"].to_numpy(), table["storey_yield_ratio"].to_numpy()
    assert springs / springs[0] == pytest.approx(np.array(given), rel=1e-12)
    assert springs == pytest.approx(model.stick.yield_force_n / _weight_n(model.stick), rel=1e-12)
    if apart:
        assert storeys[0] / springs[0] > 1.05 * (storeys[1:] / springs[1:]).max(), (storeys, springs)
    else:
        assert storeys == pytest.approx(springs, rel=1e-9)


def test_from_the_design_data_the_design_s_strength_sets_the_scale():
    """No yield_base_shear_g: the code's design × overstrength is the base shear at first yield, as without."""
    frame = dict(storeys=4, height_m=16.0, system="steel moment frame", period_s=0.6, response="yielding")
    site = SiteSheet(sds_g=1.0, sd1_g=0.6)
    plain = building_model_of(BuildingSheet(**frame), site)
    given = building_model_of(BuildingSheet(**frame, storey_strength=(1.0, 0.9, 0.8, 0.6)), site)
    assert given.strength.yield_base_shear_g == pytest.approx(plain.strength.yield_base_shear_g, rel=1e-12)
    assert stick_pushover(given.stick, 0.6).first_yield_g == pytest.approx(given.strength.yield_base_shear_g,
                                                                          rel=1e-9)


FRAME = [("storeys", 4), ("height_m", 16), ("system", "steel moment frame"), ("period_s", 0.6)]


def test_it_is_read_where_given(make_workbook):
    sheet = read_workbook(make_workbook(_sheets(FRAME + [("yield_base_shear_g", 0.3),
                                                         ("storey_strength", "1, 0.9; 0.8, 0.6")]))).building
    assert sheet.storey_strength == (1.0, 0.9, 0.8, 0.6) and sheet.rows["storey_strength"] == 7
    sheet = read_workbook(make_workbook(_sheets(FRAME + [("yield_base_shear_g", 0.3),
                                                         ("storey_strength", "uniform")]))).building
    assert sheet.storey_strength == (1.0,) * 4


@pytest.mark.parametrize("rows,cell,words", [
    ([("yield_base_shear_g", 0.3), ("storey_strength", "1, 0.9, 0.8")], "B7", "gives 3 values for 4 storeys"),
    ([("yield_base_shear_g", 0.3), ("storey_strength", "1, 0.9, 0, 0.6")], "B7", "not greater than 0"),
    ([("yield_base_shear_g", 0.3), ("storey_strength", "1, 0.9, 0.8, 0.04")], "B7",
     "the strongest storey is 25 times the weakest"),
    ([("yield_base_shear_g", 0.3), ("storey_strength", "1, 0.9, lots, 0.6")], "B7", "'lots' is not a number"),
    ([("response", "elastic"), ("storey_strength", "1, 0.9, 0.8, 0.6")], "A7",
     "storey_strength is given but response is elastic"),
    ([("storey_strength", "1, 0.9, 0.8, 0.6")], "A6", "storey_strength is given but nothing gives the storeys' "
                                                      "strength"),
])
def test_where_it_cannot_apply_it_is_refused_at_its_cell(make_workbook, rows, cell, words):
    assert_refused_at(make_workbook, rows, cell, words, base=FRAME)


def test_above_the_yielding_model_s_storeys_it_is_refused(make_workbook):
    tall = [("storeys", 45), ("height_m", 180), ("system", "steel moment frame")]
    assert_refused_at(make_workbook, [("storey_strength", "uniform")], "A5", "storey_strength is given but the "
                      "building has 45 storeys", base=tall)


def test_a_bending_wall_given_its_storeys_strengths_is_cautioned_a_shearing_one_not():
    wall = dict(storeys=6, height_m=21.0, system="shear wall", period_s=0.5, yield_base_shear_g=0.36,
                response="yielding", storey_strength=(1.0,) * 6)
    words = "is a wall's that bends, which a stick of shear storeys is not"
    bending = BuildingSheet(**wall)  # the system's α 1
    assert words in building_note(building_model_of(bending, None), bending, [3, 6], None)
    shearing = BuildingSheet(**wall, lateral_stiffness_ratio=30.0)
    assert words not in building_note(building_model_of(shearing, None), shearing, [3, 6], None)
