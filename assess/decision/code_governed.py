"""Equipment whose restraint a code or FEMA E-74 prescribes whatever the analysis says.

The table is data (``assess/data/code_governed.csv``): for each kind of equipment (water heaters, gas
cylinders, tall shelving, computer racks, medical carts) the workbook's ``component_type`` values that
select it, the action kind, the detail a crew installs and the reference it comes from. An item it
selects (:func:`code_rule`) gets that action (:func:`assess.decision.actions.decide_action`); the analysis
still gives its numbers and its class, and the action the analysis alone would choose.

References
----------
FEMA E-74 (2012), Reducing the Risks of Nonstructural Earthquake Damage - A Practical Guide, chapter 6.
IAPMO, Uniform Plumbing Code, §507.2 (water heaters: seismic provisions).
NFPA 99 (2021), Health Care Facilities Code, chapter 11 (cylinder storage).
ASCE 7-22, §13.5 and Table 13.5-1 (storage cabinets and shelving more than 6 ft tall).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

import pandas as pd

from assess.inventory.units import CM_PER_M

#: The table's file in the package data.
TABLE = "code_governed.csv"


@dataclass(frozen=True)
class CodeRule:
    """One row of the table: ``equipment`` (its name), ``action`` (an action kind), ``detail`` (what the crew
    installs) and ``reference`` (where the detail comes from); ``min_height_cm``: it applies only from that
    height (NaN: any)."""

    equipment: str
    action: str
    detail: str
    reference: str
    min_height_cm: float = math.nan


def _key(name) -> str:
    return " ".join(str(name).strip().lower().replace("_", " ").replace("-", " ").split())


@lru_cache(maxsize=1)
def code_rules() -> tuple[tuple[tuple[str, ...], CodeRule], ...]:
    """The table as (matched component types, :class:`CodeRule`) pairs, in its order."""
    with resources.files("assess.data").joinpath(TABLE).open("r", encoding="utf-8") as handle:
        table = pd.read_csv(handle, comment="#", dtype=str, keep_default_na=False)
    rules = []
    for row in table.itertuples(index=False):
        height = float(row.min_height_cm) if row.min_height_cm.strip() else math.nan
        rules.append((tuple(_key(name) for name in row.matches.split(";")),
                      CodeRule(row.equipment, row.action, row.detail, row.reference, height)))
    return tuple(rules)


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
        if names.intersection(matches) and not height_cm < rule.min_height_cm:
            return rule
    return None
