"""What kind of equipment an item is: its code table row by its written type or by its name, and its lines.

The table is data (``assess/data/code_governed.csv``): for each kind of equipment a code or FEMA E-74 governs
(water heaters, gas cylinders, tall shelving, computer racks, medical carts) the workbook's
``component_type`` values that select it, the phrases that select it in the item's name where the workbook
gives no type (:func:`kind_from_name`), the component type, contents and lines such an item has, and the
action, detail and reference :mod:`assess.decision.code_governed` applies. The lines an item may have
(``connections``: gas, fluid) and the flexible connection each takes are ``assess/data/connections.csv``
(:func:`connection_rules`). The workbook reader resolves each item's type here (:func:`item_type`).

References
----------
FEMA E-74 (2012), Reducing the Risks of Nonstructural Earthquake Damage - A Practical Guide, chapter 6;
§6.4.1.3, p. 6-182: flexible connections for fuel lines and piping.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

import pandas as pd

#: The code table's file in the package data.
TABLE = "code_governed.csv"
#: The lines an item may have, and what they take (``connections`` of the workbook).
CONNECTIONS_TABLE = "connections.csv"


@dataclass(frozen=True)
class CodeRule:
    """One row of the table: ``equipment`` (its name), ``action`` (an action kind), ``detail`` (what the crew
    installs) and ``reference`` (where the detail comes from); ``min_height_cm``: it applies only from that
    height (NaN: any); ``name_phrases``: the phrases that select it in an item's name (:func:`kind_from_name`);
    ``component_type``, ``contents``: what an item of its kind takes where the workbook does not say;
    ``connections``: the lines such an item always has; ``named_connections``: the lines read from its name."""

    equipment: str
    action: str
    detail: str
    reference: str
    min_height_cm: float = math.nan
    name_phrases: tuple[str, ...] = ()
    component_type: str = ""
    contents: str = ""
    connections: tuple[str, ...] = ()
    named_connections: tuple[str, ...] = ()


@dataclass(frozen=True)
class ConnectionRule:
    """One row of ``assess/data/connections.csv``: the ``connection`` (``gas``, ``fluid``), what it stands for
    (``meaning``), what the crew installs (``detail``) and where that comes from (``reference``)."""

    connection: str
    meaning: str
    detail: str
    reference: str


def _key(name) -> str:
    return " ".join(str(name).strip().lower().replace("_", " ").replace("-", " ").split())


def _listed(text: str) -> tuple[str, ...]:
    return tuple(_key(part) for part in str(text).split(";") if part.strip())


def _text_table(name: str) -> pd.DataFrame:
    """A CSV of the package data (``#`` lines are its notes), every cell as text ("" where empty)."""
    with resources.files("assess.data").joinpath(name).open("r", encoding="utf-8") as handle:
        return pd.read_csv(handle, comment="#", dtype=str, keep_default_na=False)


@lru_cache(maxsize=1)
def code_rules() -> tuple[tuple[tuple[str, ...], CodeRule], ...]:
    """The table as (matched component types, :class:`CodeRule`) pairs, in its order."""
    table = _text_table(TABLE)
    rules = []
    for row in table.itertuples(index=False):
        height = float(row.min_height_cm) if row.min_height_cm.strip() else math.nan
        rules.append((_listed(row.matches),
                      CodeRule(row.equipment, row.action, row.detail, row.reference, height,
                               name_phrases=_listed(row.name_phrases), component_type=row.component_type.strip(),
                               contents=row.contents.strip(), connections=_listed(row.connections),
                               named_connections=_listed(row.named_connections))))
    return tuple(rules)


@lru_cache(maxsize=1)
def _phrase_patterns() -> tuple[tuple[re.Pattern, CodeRule], ...]:
    """Each rule's name phrases as whole-word patterns (a plural s or es allowed), in the table's order."""
    return tuple((re.compile(r"\b(?:" + "|".join(re.escape(phrase) for phrase in rule.name_phrases) + r")(?:e?s)?\b"),
                  rule) for _, rule in code_rules() if rule.name_phrases)


def kind_from_name(name) -> CodeRule | None:
    """The rule whose ``name_phrases`` stand in ``name`` as whole words (any case, hyphens and underscores as
    spaces), the first in the table's order; None where none does. Only for items whose workbook gives no
    ``component_type``: the report says the type was read from the name and asks to confirm it.

    >>> kind_from_name("Gas-cylinder rack, 4 cylinders").equipment, kind_from_name("Oxygen cylinder cart").equipment
    ('gas cylinders', 'gas cylinder cart')
    >>> kind_from_name("Linen cart, covered") is None, kind_from_name("Dry heater block") is None
    (True, True)
    """
    text = _key(name or "")
    for pattern, rule in _phrase_patterns():
        if pattern.search(text):
            return rule
    return None


def kind_rule(written) -> CodeRule | None:
    """The rule a written ``component_type`` (as written, or as the components table names it) selects,
    whatever the item's height (for its defaults: contents and lines); None where none does."""
    key = _key(written or "")
    for matches, rule in code_rules():
        if key and (key in matches or key == _key(rule.equipment)):
            return rule
    return None


@lru_cache(maxsize=1)
def connection_rules() -> dict[str, ConnectionRule]:
    """``assess/data/connections.csv`` by connection (``gas``, ``fluid``), in its order."""
    table = _text_table(CONNECTIONS_TABLE)
    return {row.connection: ConnectionRule(row.connection, row.meaning, row.detail, row.reference)
            for row in table.itertuples(index=False)}


def default_connections(rule: CodeRule | None, *texts) -> tuple[str, ...]:
    """The lines an item of ``rule``'s kind has where the workbook does not say: the rule's ``connections``
    and those of its ``named_connections`` that stand as whole words in one of ``texts`` (its name, its
    written component type), in :func:`connection_rules`' order; () without a rule.

    >>> default_connections(kind_from_name("Gas water heater, 100 gal"), "Gas water heater, 100 gal")
    ('gas', 'fluid')
    >>> default_connections(kind_from_name("Gas-cylinder rack"), "Gas-cylinder rack")
    ()
    """
    if rule is None:
        return ()
    words = set(" ".join(_key(text or "") for text in texts).split())
    found = set(rule.connections) | {line for line in rule.named_connections if line in words}
    return tuple(line for line in connection_rules() if line in found)


#: Component types whose contents are movable where the workbook does not say (shelving and cabinets).
MOVABLE_CONTENTS_TYPES = ("storage shelving",)


def equipment_kind(written) -> str:
    """The workbook's ``component_type`` as written (an alias such as ``water heater`` names more than the
    table's type), in lower case with single spaces; "" where empty. :mod:`assess.decision.code_governed`
    reads it.

    >>> equipment_kind(" Gas_Water  Heater "), equipment_kind(None)
    ('gas water heater', '')
    """
    if written is None or (isinstance(written, float) and written != written):
        return ""
    return _key(written)


def default_contents(contents, component_type, kind_contents: str = "") -> str:
    """An item's ``contents`` as written, else those of its kind of equipment (``kind_contents``: the code
    table's, e.g. ``none`` for gas cylinders), else ``movable`` for shelving and cabinets
    (:data:`MOVABLE_CONTENTS_TYPES`) and ``none`` otherwise.

    >>> default_contents("", "storage shelving"), default_contents(None, ""), default_contents("fixed",
    ...                                                                                        "storage shelving")
    ('movable', 'none', 'fixed')
    >>> default_contents("", "storage shelving", "none")
    'none'
    """
    if contents:
        return str(contents)
    if kind_contents:
        return kind_contents
    return "movable" if component_type in MOVABLE_CONTENTS_TYPES else "none"


#: Where an item's type comes from (``type_source``): the workbook's ``component_type``, its name, neither.
TYPE_SOURCES = ("typed", "name", "default")


def item_type(values: dict, raw: dict) -> dict:
    """An item's type and what follows from it, from its row's parsed ``values`` and ``raw`` cells:
    ``component_type`` (the workbook's; else the type its name selects in the code table,
    :func:`assess.inventory.kinds.kind_from_name`; else ""), ``equipment_kind`` (the component type as
    written, or the code table's kind its name selects), ``type_source`` (:data:`TYPE_SOURCES`), ``contents``
    (:func:`default_contents`), ``connections`` (as written, else the lines of its kind:
    :func:`assess.inventory.kinds.default_connections`; ``"none"`` for none) and
    ``connections_assumed`` (True where they were not written and are not none).

    >>> t = item_type({"name": "Gas water heater, 100 gal", "component_type": "", "contents": ""}, {})
    >>> t["component_type"], t["equipment_kind"], t["type_source"], t["contents"], t["connections"]
    ('mechanical equipment', 'water heater', 'name', 'none', 'gas, fluid')
    >>> item_type({"name": "Linen cart", "component_type": ""}, {})["type_source"]
    'default'
    """
    typed = values.get("component_type") or ""
    written = equipment_kind(raw.get("component_type"))
    name = str(values.get("name") or "")
    if typed:
        rule, kind, source = kind_rule(written) or kind_rule(typed), written, "typed"
    else:
        rule = kind_from_name(name)
        kind, source = (rule.equipment, "name") if rule is not None else ("", "default")
        typed = rule.component_type if rule is not None else ""
    connections = values.get("connections") or ""
    assumed = not connections
    if assumed:
        connections = ", ".join(default_connections(rule, name, written)) or "none"
    return {"component_type": typed, "equipment_kind": kind, "type_source": source,
            "contents": default_contents(values.get("contents"), typed, rule.contents if rule is not None else ""),
            "connections": connections, "connections_assumed": assumed and connections != "none"}
