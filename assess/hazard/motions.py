"""The motions of a hazard level that act on each floor."""
from __future__ import annotations

import pandas as pd

from assess.errors import Problem, raise_if_any
from assess.hazard.levels import HazardLevel, parse_level


def select_level(hazard: pd.DataFrame, level_text: str, workbook_name: str) -> tuple[HazardLevel, pd.DataFrame]:
    """Rows of the ``hazard`` table for the level ``level_text`` names.

    Any spelling of the same level matches (``2475yr`` finds ``2in50``).
    Raises :class:`~assess.errors.InputError` listing the workbook's levels
    when it has none that matches.
    """
    try:
        wanted = parse_level(level_text)
    except ValueError as error:
        raise_if_any([Problem(file="--hazard", message=str(error),
                              fix="give the level as the workbook's hazard sheet names it, e.g. --hazard 2in50")])
    labels = hazard.drop_duplicates("level")[["level", "level_label"]]
    for level, label in labels.itertuples(index=False):
        if parse_level(level).same_as(wanted):
            return parse_level(level), hazard[hazard["level"] == level].reset_index(drop=True)
    have = ", ".join(f"'{label}'" for label in labels["level_label"]) or "none"
    raise_if_any([Problem(
        file=workbook_name, sheet="hazard", column="level",
        message=f"the workbook has no motions for hazard level '{level_text}' ({wanted.description}); "
                f"it has: {have}.",
        fix="run with one of those levels, or add rows for this level to the hazard sheet.")])
    raise AssertionError("unreachable")


def motions_by_item(equipment: pd.DataFrame, level_motions: pd.DataFrame, level_label: str,
                    workbook_name: str) -> pd.DataFrame:
    """Pair every item with every motion of the level acting on its floor.

    Returns one row per (item, motion) with the item's ``id`` and the motion's
    columns. A floor with no motion is an error (by default no floor motion is
    derived from another floor's).
    """
    specific = level_motions[~level_motions["all_floors"]]
    everywhere = level_motions[level_motions["all_floors"]]
    pairs = []
    problems = []
    for item in equipment.itertuples(index=False):
        acting = pd.concat([specific[specific["floor"] == item.floor], everywhere])
        if acting.empty:
            floors = sorted({int(f) for f in specific["floor"].dropna()})
            problems.append(Problem(
                file=workbook_name, sheet="equipment", row=item.row, column="floor",
                message=f"item '{item.id}' is on floor {item.floor}, but hazard level '{level_label}' "
                        f"has no motion for that floor (it has floors {floors or 'none'}).",
                fix=f"add hazard rows for floor {item.floor} (or a row with floor 'all'), "
                    "or correct the item's floor."))
            continue
        pairs.append(acting.assign(id=item.id))
    raise_if_any(problems)
    return pd.concat(pairs, ignore_index=True)
