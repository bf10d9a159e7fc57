"""A shear wall in the yielding building: its base hinge by default, what its storeys report, and the equivalent
shear stick still there (the hinge's own physics: tests/verification/test_wall_hinge_closed_forms.py and
test_wall_hinge_opensees.py)."""
import numpy as np
import pytest

from assess.building.modes import building_modes
from assess.building.nonlinear import yielding_stick
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


def test_equivalent_shear_stays_available_for_walls():
    stick = _wall(6, 0.5, flexure="equivalent shear")
    assert np.all(stick.linear_stiffness_n_m == 0.0)
    with pytest.raises(ValueError, match="Rayleigh"):
        _wall(6, 0.5, damping_model="modal")
