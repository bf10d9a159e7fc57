"""The unit constants the summary and the report convert with agree with pint's definitions
(NIST SP 811 / the 1959 international yard and pound: 1 in = 2.54 cm, 1 lb = 0.45359237 kg, 1 lbf = 1 lb x g_n)."""
import pytest

from assess.inventory import units
from assess.units import conversion_factor


def test_the_lengths_are_pints_to_the_bit():
    assert units.CM_PER_M == 100.0 and units.CM_PER_IN == 2.54
    assert units.CM_PER_M == conversion_factor("meter", "centimeter")
    assert units.CM_PER_IN == conversion_factor("inch", "centimeter")


def test_the_pound_and_the_pound_force_are_their_definitions():
    assert units.KG_PER_LB == pytest.approx(conversion_factor("pound", "kilogram"), rel=1e-15)
    assert units.N_PER_LBF == pytest.approx(0.45359237 * 9.80665, rel=1e-15)
    assert units.N_PER_LBF == pytest.approx(conversion_factor("lbf", "newton"), rel=1e-15)
