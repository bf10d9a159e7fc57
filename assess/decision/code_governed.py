"""Equipment whose restraint a code or FEMA E-74 prescribes whatever the analysis says.

The table is data (``assess/data/code_governed.csv``): for each kind of equipment (water heaters, gas
cylinders, tall shelving, computer racks, medical carts) the workbook's ``component_type`` values that
select it, the phrases that select it in the item's name where the workbook gives no type
(:func:`kind_from_name`), the component type, contents and lines such an item has, the action kind, the
detail a crew installs and the reference it comes from. An item it selects (:func:`code_rule`) gets that
action (:func:`assess.decision.actions.decide_action`); the analysis still gives its numbers and its class,
and the action the analysis alone would choose.

The lines an item has (``connections``: gas, fluid) take a flexible connection (``assess/data/connections.csv``,
:func:`connection_rules`) beside whatever action it gets.

References
----------
FEMA E-74 (2012), Reducing the Risks of Nonstructural Earthquake Damage - A Practical Guide, chapter 6.
IAPMO, Uniform Plumbing Code, §507.2 (water heaters: seismic provisions).
NFPA 99 (2021), Health Care Facilities Code, chapter 11 (cylinder storage).
ASCE 7-16 and 7-22, §13.5 and Table 13.5-1 (storage cabinets and shelving more than 6 ft tall: the same row in both).
FEMA E-74 (2012) §6.4.1.3, p. 6-182: flexible connections for fuel lines and piping.
"""
from __future__ import annotations

import math

from assess.inventory.kinds import (  # noqa: F401 (the table, read where the workbook is: re-exported)
    CodeRule, ConnectionRule, _key, code_rules, connection_rules, default_connections, kind_from_name, kind_rule,
)
from assess.inventory.units import CM_PER_M


def code_rule(item) -> CodeRule | None:
    """The rule of the table that selects ``item`` (a row of the equipment table: its ``equipment_kind``,
    the workbook's component type as written, or its ``component_type``, and its ``height_m``), the first
    that matches; None where none does.

    >>> from types import SimpleNamespace
    >>> code_rule(SimpleNamespace(equipment_kind="Gas water heater", component_type="mechanical equipment",
    ...                           height_m=1.8)).action
    'strap'
    >>> code_rule(SimpleNamespace(equipment_kind="shelving", component_type="storage shelving", height_m=1.5)) is None
    True
    """
    names = {_key(getattr(item, "equipment_kind", "") or ""), _key(getattr(item, "component_type", "") or "")}
    names.discard("")
    height_cm = float(getattr(item, "height_m", math.nan)) * CM_PER_M
    for matches, rule in code_rules():
        if names.intersection((*matches, _key(rule.equipment))) and not height_cm < rule.min_height_cm:
            return rule
    return None
