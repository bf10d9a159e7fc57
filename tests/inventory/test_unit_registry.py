"""The project's one pint registry (assess/units.py), against pint itself and the units' exact definitions.

The definitions are exact by law, not computed here: the international inch is 0.0254 m and the foot 12 inches
(1959 agreement), the avoirdupois pound 0.45359237 kg, the pound-force that pound under standard gravity
9.80665 m/s² (so 4.4482216152605 N) and the kip 1000 pounds-force (NIST SP 811, Appendix B).
"""
import pint
import pytest

from assess.units import conversion_factor, registry


def test_one_registry_for_the_whole_application():
    assert registry() is registry()
    assert isinstance(registry(), pint.UnitRegistry)


def test_quantities_of_another_registry_do_not_mix():
    """Why there is one registry: pint refuses arithmetic across two of them."""
    ours, other = registry().Quantity(1.0, "meter"), pint.UnitRegistry().Quantity(1.0, "meter")
    with pytest.raises(ValueError):
        ours + other


@pytest.mark.parametrize("source, target, exact", [
    ("inch", "meter", 0.0254),
    ("foot", "meter", 0.3048),
    ("pound", "kilogram", 0.45359237),
    ("force_pound", "newton", 0.45359237 * 9.80665),
    ("kip", "newton", 1000 * 0.45359237 * 9.80665),
    ("meter", "inch", 1 / 0.0254),
    ("inch", "centimeter", 2.54),
])
def test_conversion_factors_are_the_exact_definitions(source, target, exact):
    assert conversion_factor(source, target) == pytest.approx(exact, rel=1e-15)


def test_an_unknown_unit_is_pints_own_error():
    with pytest.raises(pint.errors.UndefinedUnitError):
        conversion_factor("furlongish", "meter")
