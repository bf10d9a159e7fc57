"""Anchorage design forces of nonstructural components: ASCE 7-16 and ASCE 7-22 Chapter 13.

- :mod:`assess.anchorage.equations`: the cited equations, one small function per term.
- :mod:`assess.anchorage.coefficients`: the component table (``assess/data/components.csv``).
- :mod:`assess.anchorage.design`: :func:`design_force`, one call with every term kept, and US units.

- :mod:`assess.anchorage.item`: an item of the workbook (its component type, I_p, floor) in its site and
  building (:class:`AnchorageSite`): the anchorage columns of ``summary.csv`` (:func:`item_anchorage`).
"""
from assess.anchorage.coefficients import (
    DEFAULT_COMPONENT_TYPE, EDITIONS, ComponentCoefficients, canonical_edition, component_coefficients,
    component_types,
)
from assess.anchorage.design import AnchorageForces, design_force, in_us_units
from assess.anchorage.equations import component_importance_factor
from assess.anchorage.item import AnchorageSite, ItemAnchorage, anchorage_site, item_anchorage

__all__ = ["AnchorageForces", "AnchorageSite", "ComponentCoefficients", "ItemAnchorage", "anchorage_site",
           "item_anchorage", "DEFAULT_COMPONENT_TYPE", "EDITIONS", "canonical_edition",
           "component_coefficients", "component_importance_factor", "component_types", "design_force",
           "in_us_units"]
