"""The building sheet's values: good ones give the modes, bad ones one InputError naming every problem."""
import pytest

from assess.building.modes import ALPHA_BY_SYSTEM
from assess.building.period import approximate_period
from assess.building.sheet import modes_from_sheet
from assess.errors import InputError


def test_good_sheets():
    modes = modes_from_sheet({"Storeys": 6, "storey_height_m": 3.5, "system": "Steel Moment Frame",
                              "period_s": 0.7, "damping": 0.03}, file="b.xlsx")
    assert modes.storeys == 6 and modes.periods_s[0] == pytest.approx(0.7) and modes.period_source == "given"
    assert modes.alpha == ALPHA_BY_SYSTEM["steel moment frame"] and (modes.damping == 0.03).all()
    modes = modes_from_sheet({"storeys": 4, "height_m": 16.0, "period_s": None, "damping": ""}, file="b.xlsx")
    assert modes.periods_s[0] == pytest.approx(approximate_period(16.0, "other"))
    assert (modes.damping == 0.05).all()
    assert modes.floor_heights_m[-1] == pytest.approx(16.0)


def test_every_problem_reported_with_its_row_and_no_cell_text():
    secret = "=HYPERLINK(\"file:///etc/passwd\")"
    with pytest.raises(InputError) as caught:
        modes_from_sheet({"storeys": 2.5, "height_m": 7, "storey_height_m": 3.5, "system": secret,
                          "period_s": -1, "damping": 5, "colour": "red"}, file="b.xlsx",
                         rows={"storeys": 2, "system": 5, "period_s": 6, "damping": 7, "colour": 8})
    problems = caught.value.problems
    text = str(caught.value)
    assert len(problems) == 6
    assert all(p.sheet == "building" for p in problems)
    assert {p.row for p in problems} >= {2, 5, 6, 7, 8}
    assert "passwd" not in text and "red" not in text.replace("reduce", "")
    for word in ("storeys", "height_m", "system", "period_s", "damping", "does not know"):
        assert word in text


def test_storey_heights_in_feet_are_refused():
    with pytest.raises(InputError, match="metres"):
        modes_from_sheet({"storeys": 4, "height_m": 52.0}, file="b.xlsx")  # 13 m storeys: feet?
