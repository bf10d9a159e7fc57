"""Anchorage design forces of nonstructural components: ASCE 7-16 and ASCE 7-22 Chapter 13.

- :mod:`assess.anchorage.equations`: the cited equations, one small function per term.
- :mod:`assess.anchorage.coefficients`: the component table (``assess/data/components.csv``).
- :mod:`assess.anchorage.design`: :func:`design_force`, one call with every term kept, and US units.

:mod:`assess.fragility.anchorage` keeps the functions the pipeline calls today (ASCE 7-16, laboratory
equipment); :func:`design_force` gives the same numbers for that case.
"""
from assess.anchorage.coefficients import (
    DEFAULT_COMPONENT_TYPE, EDITIONS, ComponentCoefficients, canonical_edition, component_coefficients,
    component_types,
)
from assess.anchorage.design import AnchorageForces, design_force, in_us_units
from assess.anchorage.equations import component_importance_factor

__all__ = ["AnchorageForces", "ComponentCoefficients", "DEFAULT_COMPONENT_TYPE", "EDITIONS", "canonical_edition",
           "component_coefficients", "component_importance_factor", "component_types", "design_force",
           "in_us_units"]
