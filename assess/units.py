"""The project's one pint unit registry (pint asks for one per application: quantities of two registries do not
mix, and each registry parses pint's definitions again, about 0.2 s).

:func:`conversion_factor` is what the workbook's unit suffixes (:mod:`assess.inventory.units`) and the
anchorage's US units (:func:`assess.anchorage.design.in_us_units`) convert with.
"""
from __future__ import annotations

from functools import lru_cache

import pint


@lru_cache(maxsize=1)
def registry() -> pint.UnitRegistry:
    """The unit registry, made on first use."""
    return pint.UnitRegistry()


@lru_cache(maxsize=None)
def conversion_factor(source_unit: str, target_unit: str) -> float:
    """Multiplier taking a value in ``source_unit`` to ``target_unit`` (pint expressions).

    >>> conversion_factor("inch", "meter")
    0.0254
    """
    return float(registry().Quantity(1.0, source_unit).to(target_unit).magnitude)
