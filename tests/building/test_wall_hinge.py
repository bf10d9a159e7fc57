"""A shear wall in the yielding building: its base hinge by default, what its storeys report, and the equivalent
shear stick still there (the hinge's own physics: tests/verification/test_wall_hinge_closed_forms.py and
test_wall_hinge_opensees.py)."""
import numpy as np
import pytest

from assess.building.modes import building_modes
from assess.building.nonlinear import YieldingStick, yielding_stick
from assess.building.wall_hinge import HingedWall
from assess.building.yielding import stick_history, storey_table, yielding_building

HEIGHT_M = 3.5


def _wall(storeys, period_s, alpha=1.0, ratio=0.3, **kwargs):
    return yielding_stick(storeys, HEIGHT_M, np.full(storeys, ratio), system="shear wall", period_s=period_s,
                          alpha=alpha, **kwargs)


def test_a_shear_wall_yields_at_its_base_and_reports_no_upper_storey_strength():
    modes = building_modes(6, HEIGHT_M, system="shear wall", period_s=0.5)
    building = yielding_building(modes, "shear wall", yield_base_shear_g=0.3)
    assert building.stick.yield_moment_n_m > 0.0
    ratios = building.strength.storey_yield_ratio
    assert ratios[0] == pytest.approx(0.3) and np.all(np.isnan(ratios[1:]))
    assert "at its base only" in building.strength.source
    # the design's "spread over the storeys" is taken out of the note by its wording: a rewording must be seen here
    assert "spread over the storeys" not in building.strength.source
    assert building.strength.source.startswith("base shear at yield 0.3 W as given;")
    t = np.arange(0.0, 10.0, 0.01)
    strong = stick_history(building, 1.0 * np.sin(2 * np.pi * t / 0.5) * (t < 4.0), 0.01)
    weak = stick_history(building, 0.02 * np.sin(2 * np.pi * t / 0.5) * (t < 4.0), 0.01)
    assert not strong.elastic and strong.ductility[0] > 1.0 and np.all(np.isnan(strong.ductility[1:]))
    assert weak.elastic  # the elastic route's histories then
    table = storey_table(building, [strong, weak], range(7))
    assert table["ductility_median"].iloc[1] == pytest.approx(np.median([strong.ductility[0],
                                                                          weak.ductility[0]]))
    assert table["ductility_median"].iloc[2:].isna().all()
    assert table["storey_yield_ratio"].iloc[2:].isna().all()
    assert (table["drift_ratio_median"].iloc[1:] > 0).all()
    # the model that ran, on every row: the stick is a HingedWall
    assert isinstance(building.stick, HingedWall)
    assert (table["yielding_model"] == "base hinge").all()


@pytest.mark.parametrize("system", ["steel moment frame", "concrete moment frame", "braced frame", "other"])
def test_other_systems_yield_in_storey_springs(system):
    """Every system but a shear wall yields in its storey springs (a YieldingStick), and floors.csv says so."""
    modes = building_modes(4, HEIGHT_M, system=system, period_s=0.6)
    building = yielding_building(modes, system, yield_base_shear_g=0.3)
    assert isinstance(building.stick, YieldingStick) and not isinstance(building.stick, HingedWall)
    t = np.arange(0.0, 6.0, 0.01)
    history = stick_history(building, 1.0 * np.sin(2 * np.pi * t / 0.6) * (t < 3.0), 0.01)
    table = storey_table(building, [history], range(5))
    assert (table["yielding_model"] == "storey springs").all()
    assert table["storey_yield_ratio"].iloc[1:].notna().all()


def test_equivalent_shear_stays_available_for_walls():
    stick = _wall(6, 0.5, flexure="equivalent shear")
    assert np.all(stick.linear_stiffness_n_m == 0.0)
    with pytest.raises(ValueError, match="Rayleigh"):
        _wall(6, 0.5, damping_model="modal")
