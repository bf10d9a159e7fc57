"""ASCE 7 Table 12.8-2 approximate period, against the table's own numbers.

Expected values: T_a = C_t h_n^x with the table's *feet* coefficients (0.028/0.8,
0.016/0.9, 0.03/0.75, 0.02/0.75) and h_n converted to feet (1 ft = 0.3048 m);
the module uses the table's *metre* coefficients, so the check is the table's two
columns against each other. The table prints C_t (m) to three significant digits:
tolerance 0.2 %.
"""
import numpy as np
import pytest

from assess.building.period import (PERIOD_COEFFICIENTS, PERIOD_COEFFICIENTS_FT, SYSTEMS,
                                    approximate_period)

# h_n [m], system, T_a [s] from the feet column (worked with a calculator: h_n/0.3048 ft)
TABLE = [
    (10.0, "steel moment frame", 0.4570),      # 0.028 × 32.81^0.8
    (30.0, "steel moment frame", 1.1006),      # 0.028 × 98.43^0.8
    (60.0, "steel moment frame", 1.9163),
    (10.0, "concrete moment frame", 0.3703),   # 0.016 × 32.81^0.9
    (30.0, "concrete moment frame", 0.9952),
    (60.0, "concrete moment frame", 1.8571),
    (10.0, "eccentrically braced frame", 0.4113),  # 0.03 × 32.81^0.75
    (30.0, "eccentrically braced frame", 0.9375),
    (10.0, "braced frame", 0.2742),            # all other structural systems: 0.02 × 32.81^0.75
    (30.0, "shear wall", 0.6250),
    (60.0, "other", 1.0511),
]


@pytest.mark.parametrize("height_m, system, expected_s", TABLE)
def test_period_against_the_tables_feet_column(height_m, system, expected_s):
    assert approximate_period(height_m, system) == pytest.approx(expected_s, rel=2e-3), (height_m, system)


def test_metre_and_feet_coefficients_agree():
    """C_t(m) = C_t(ft) × (1/0.3048)^x for every row, to the table's rounding."""
    for system in SYSTEMS:
        ct_m, x = PERIOD_COEFFICIENTS[system]
        assert ct_m == pytest.approx(PERIOD_COEFFICIENTS_FT[system] * (1 / 0.3048) ** x, rel=2e-3), system


def test_braced_frames_shear_walls_and_other_are_all_other_systems():
    assert PERIOD_COEFFICIENTS["braced frame"] == PERIOD_COEFFICIENTS["shear wall"] == \
        PERIOD_COEFFICIENTS["other"] == (0.0488, 0.75)


def test_arrays_and_bad_input():
    np.testing.assert_allclose(approximate_period([10.0, 30.0], "other"), [0.2742, 0.6250], rtol=2e-3)
    with pytest.raises(ValueError):
        approximate_period(10.0, "timber")
    with pytest.raises(ValueError):
        approximate_period(0.0, "other")
