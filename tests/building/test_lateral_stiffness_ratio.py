"""The building sheet's ``lateral_stiffness_ratio`` (docs/workbook.md, sheet ``building``): Miranda & Taghavi's α.

α = H √(GA/EI) sets how the building's flexure (its columns' or wall's bending) shares the storeys' shear
(Miranda & Taghavi 2005): the engineer who knows the building's gives it, else the system's typical value
answers. Checked here: it is read and refused at its cell as the other keys are; it reaches both building
models in its defining relation (the stick's column EI = GA H²/α², so two α give EI in the inverse ratio of
their squares); a column stiffer against the storeys (a smaller α) ratios the drift more evenly over the
height, as a flexural beam does; ``floors.csv`` and the report's note say which α ran and whose it is. What
α moves in the equipment's demand is measured against OpenSees buildings of α 5 and 20 in
``tests/verification/test_yielding_equipment.py`` (``benchmarks/bench_yielding_equipment.py --truth-alphas``).
"""
from __future__ import annotations

import numpy as np
import pytest

from assess.assessment.floors import building_model_of, building_modes_of, building_note
from assess.building import ALPHA_BY_SYSTEM
from assess.errors import InputError
from assess.inventory import read_workbook
from assess.inventory.site_building import LATERAL_STIFFNESS_RATIO_RANGE, BuildingSheet, SiteSheet
from tests.project.test_docs import section, table_rows
from workbooks import good_sheets

SITE = SiteSheet(sds_g=1.0, sd1_g=0.6)


def _sheets(building):
    sheets = good_sheets()
    sheets["building"] = [["key", "value"]] + [list(pair) for pair in building]
    return sheets


def test_it_is_read_where_given_and_none_where_not(make_workbook):
    given = read_workbook(make_workbook(_sheets([("storeys", 4), ("height_m", 16), ("system", "steel moment frame"),
                                                 ("lateral_stiffness_ratio", 6.5)]))).building
    assert given.lateral_stiffness_ratio == 6.5
    assert given.rows["lateral_stiffness_ratio"] == 5
    absent = read_workbook(make_workbook(_sheets([("storeys", 4), ("height_m", 16)]))).building
    assert absent.lateral_stiffness_ratio is None


@pytest.mark.parametrize("value", [0, 0.05, 31, 1000, -5, "stiff"])
def test_a_value_outside_its_range_is_refused_at_its_cell(make_workbook, value):
    with pytest.raises(InputError) as error:
        read_workbook(make_workbook(_sheets([("storeys", 4), ("height_m", 16), ("lateral_stiffness_ratio", value)])))
    cells = [(p.sheet, p.cell) for p in error.value.problems]
    assert cells == [("building", "B4")], [(p.cell, p.message) for p in error.value.problems]
    assert "lateral_stiffness_ratio" in error.value.problems[0].message


def test_the_command_exits_2_on_a_bad_ratio_and_writes_nothing(make_workbook, tmp_path, capsys):
    from assess import cli
    sheets = _sheets([("storeys", 3), ("height_m", 12), ("lateral_stiffness_ratio", 0)])
    sheets["site"] = [["key", "value"], ["sds_g", 1.0], ["sd1_g", 0.6]]
    out = tmp_path / "out"
    assert cli.main([str(make_workbook(sheets)), "--hazard", "DE", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert "building" in err and "B4" in err and "lateral_stiffness_ratio" in err and "Traceback" not in err
    assert not out.exists() or not any(out.iterdir())


@pytest.mark.parametrize("system", ["steel moment frame", "braced frame", "concrete moment frame"])
def test_it_reaches_both_models_in_its_defining_relation(system):
    """α² = GA H²/EI: with T_1 and the storeys fixed, α 5 against α 20 leaves the storeys' GA alike and gives the
    yielding stick's column (20/5)² = 16 times the EI, and the elastic modes α itself."""
    sticks = {}
    for alpha in (5.0, 20.0):
        sheet = BuildingSheet(storeys=8, height_m=32.0, system=system, period_s=1.2, lateral_stiffness_ratio=alpha)
        assert building_modes_of(sheet).alpha == alpha
        sticks[alpha] = building_model_of(sheet, SITE).stick
    stiff, soft = sticks[5.0], sticks[20.0]
    ga_ratio = stiff.stiffness_n_m[0] / soft.stiffness_n_m[0]
    assert stiff.bending_rigidity_n_m2 / soft.bending_rigidity_n_m2 == pytest.approx(16.0 * ga_ratio, rel=1e-12)
    default = BuildingSheet(storeys=8, height_m=32.0, system=system, period_s=1.2)
    assert building_modes_of(default).alpha == ALPHA_BY_SYSTEM[system]


def test_the_drift_moves_up_the_height_as_alpha_falls():
    """Under the same lateral forces a shear building drifts most in its lowest storey, a flexural cantilever in its
    highest (Miranda 1999): the first storey's drift over the top storey's falls as α falls (the elastic stick under
    forces growing with height, uniform storeys)."""
    ratios = []
    for alpha in (20.0, 10.0, 5.0, 1.0):
        sheet = BuildingSheet(storeys=8, height_m=32.0, system="steel moment frame", period_s=1.2,
                              lateral_stiffness_ratio=alpha, storey_stiffness=(1.0,) * 8)
        stick = building_model_of(sheet, SITE).stick
        n = stick.storeys
        springs = np.zeros((n, n))
        for i, k in enumerate(stick.stiffness_n_m):
            springs[i, i] += k
            if i > 0:
                springs[i - 1, i - 1] += k
                springs[i - 1, i] -= k
                springs[i, i - 1] -= k
        displacement = np.linalg.solve(springs + stick.linear_stiffness_n_m, np.arange(1.0, n + 1.0))
        drifts = np.diff(np.concatenate([[0.0], displacement]))
        ratios.append(drifts[0] / drifts[-1])
    assert all(a > b for a, b in zip(ratios, ratios[1:])), ratios


def test_the_note_says_which_alpha_ran_and_whose():
    """(floors.csv's ``alpha`` is the modes', checked above.)"""
    given = BuildingSheet(storeys=4, height_m=16.0, system="steel moment frame", lateral_stiffness_ratio=6.5)
    assumed = BuildingSheet(storeys=4, height_m=16.0, system="steel moment frame")
    given_note = building_note(building_model_of(given, SITE), given, [4], None)
    assumed_note = building_note(building_model_of(assumed, SITE), assumed, [4], None)
    assert "lateral stiffness ratio α 6.5 (given)" in given_note
    assert "lateral stiffness ratio α 12 (the system's typical one)" in assumed_note
    assert "give lateral_stiffness_ratio" in assumed_note and "give lateral_stiffness_ratio" not in given_note
    assert "0.44 to 1.78 times as far" in assumed_note  # what it moved on the OpenSees frames (docs/workbook.md)
    elastic = BuildingSheet(storeys=4, height_m=16.0, system="steel moment frame", response="elastic",
                            lateral_stiffness_ratio=6.5)
    assert "lateral stiffness ratio α 6.5 (given)" in building_note(building_model_of(elastic, SITE), elastic, [4],
                                                                    None)
    wall = BuildingSheet(storeys=6, height_m=21.0, system="shear wall")
    assert "give lateral_stiffness_ratio" not in building_note(building_model_of(wall, SITE), wall, [6], None)


def test_the_note_asks_for_the_storey_stiffnesses_where_a_yielding_frames_strength_follows_them():
    """A yielding frame's storeys are as strong as they are stiff (assess.building.nonlinear.stiffness_strength):
    where the sheet gives no storey_stiffness the note says the profile is the system's and asks for the model's; not
    where it is given, nor for an elastic building or a wall on its base hinge (whose strength does not follow it)."""
    asked = "give storey_stiffness from the building's model"
    frame = BuildingSheet(storeys=4, height_m=16.0, system="steel moment frame")
    assert asked in building_note(building_model_of(frame, SITE), frame, [4], None)
    given = BuildingSheet(storeys=4, height_m=16.0, system="steel moment frame", storey_stiffness=(1.0, 0.9, 0.8, 0.6))
    elastic = BuildingSheet(storeys=4, height_m=16.0, system="steel moment frame", response="elastic")
    wall = BuildingSheet(storeys=6, height_m=21.0, system="shear wall")
    for sheet, floor in ((given, 4), (elastic, 4), (wall, 6)):
        assert asked not in building_note(building_model_of(sheet, SITE), sheet, [floor], None), sheet


def test_the_users_page_gives_the_key_its_range():
    rows = {row["key"].strip("`"): row for row in table_rows(section("workbook.md", "Sheet `building` (optional)"))
            if "key" in row}
    low, high = LATERAL_STIFFNESS_RATIO_RANGE
    assert rows["lateral_stiffness_ratio"]["accepted"] == f"{low:g} to {high:g}"
    assert "Miranda & Taghavi" in rows["lateral_stiffness_ratio"]["meaning"]
