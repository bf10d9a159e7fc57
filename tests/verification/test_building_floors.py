"""The floors table and ASCE 7-22's H_f (Eqs. 13.3-4, 13.3-5), by hand."""
import numpy as np
import pytest

from assess.anchorage.equations import height_factor
from assess.assessment.floors import with_code_check
from assess.building import building_modes, floor_records, floors_table
from assess.hazard.records import Record


@pytest.mark.parametrize("z_over_h, period_s, expected", [
    (1.0, 1.0, 2.84),            # a1 = 1, a2 = 1 - 0.4² = 0.84
    (0.5, 1.0, 1.5008203125),    # 1 + 0.5 + 0.84 × 0.5^10
    (1.0, 0.35, 3.5),            # a1 = 1/0.35 = 2.86 → 2.5, a2 = 1 - 1.306 < 0 → 0
    (1.0, 0.4, 3.5),             # a1 = 2.5, a2 = 0
    (1.0, 2.0, 1.5 + 0.96),      # a1 = 0.5, a2 = 1 - 0.04
    (0.0, 2.0, 1.0),
    (1.0, None, 3.5),            # Eq. 13.3-5: 1 + 2.5 z/h
])
def test_height_factor_by_hand(z_over_h, period_s, expected):
    assert float(height_factor(z_over_h, period_s)) == pytest.approx(expected, rel=1e-12)


def test_floors_table_rows_and_statistics():
    modes = building_modes(3, 3.5, period_s=0.35, system="steel moment frame")
    rng = np.random.default_rng(5)
    suite = [Record(rng.normal(size=1500) * s, 0.01, f"m{i}") for i, s in enumerate((0.1, 0.2, 0.3))]
    floors = floor_records(modes, suite)
    table = with_code_check(floors_table(modes, floors, level="DE"), modes)
    assert list(table["floor"]) == [0, 1, 2, 3]
    assert (table["level"] == "DE").all() and (table["motions"] == 3).all()
    np.testing.assert_allclose(table["height_m"], [0, 3.5, 7.0, 10.5])
    np.testing.assert_allclose(table.loc[0, ["pfa_over_pga_min", "pfa_over_pga_median", "pfa_over_pga_max"]]
                               .astype(float), 1.0)  # a row of mixed columns is an object Series under pandas 2
    roof = np.array([r.pta_g for r in floors[3]])
    ratios = roof / np.array([r.pta_g for r in suite])
    assert table.loc[3, "pfa_median_g"] == pytest.approx(np.median(roof))
    assert table.loc[3, "pfa_over_pga_max"] == pytest.approx(ratios.max())
    assert table.loc[3, "period_1_s"] == pytest.approx(0.35)
    assert table.loc[3, "modes_used"] == 3 and table.loc[3, "mass_used"] == pytest.approx(1.0)
    assert table.loc[3, "gamma_phi_1"] == pytest.approx(modes.participation[0])  # φ = 1 at the roof
    assert table.loc[3, "hf_asce7_22"] == pytest.approx(3.5)
    assert table.loc[0, "gamma_phi_2"] == 0.0
    with pytest.raises(ValueError):
        floors_table(modes, {3: floors[3]})
    some = floors_table(modes, floor_records(modes, suite, floors=[0, 2]))
    assert list(some["floor"]) == [0, 2]
    assert some.loc[1, "pfa_median_g"] == pytest.approx(table.loc[2, "pfa_median_g"])
