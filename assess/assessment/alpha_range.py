"""What the building's lateral stiffness ratio α moves: the level again at the ends of its range.

α (Miranda & Taghavi 2005; :mod:`assess.building.modes`) sets how the building's columns or walls spread the
storeys' drift over its height, and with it how the upper floors shake, most of all once the building yields.
A building sheet without ``lateral_stiffness_ratio`` takes the system's typical α
(:data:`~assess.building.modes.ALPHA_BY_SYSTEM`), and no record of a level can tell what the building's own is.
On yielding OpenSees frames whose own α was 5 to 20, the system's α slid their upper floors' items 0.44 to
1.78 times as far as their own did (``benchmarks/bench_yielding_equipment.py --truth-alphas 5,20``).

``assess --alpha-range`` runs the level again at the two ends of the system's range
(:data:`~assess.building.modes.ALPHA_RANGE_BY_SYSTEM`, or the ends the engineer gives; for a frame whose α comes
from its pushover's slope without the model's storey hardening, the α that slope gives at the ends of the hardening's
range, :func:`pushover_ends`), with the same ground
motions and seed, for the items on the floors whose motions come through the building
(:func:`items_through_building`); :func:`with_alpha_range` puts each one's risk class and chances at both
ends beside the level's answer, flags the items whose class moves and says so in a note. The level's answer,
at the building sheet's α, governs: the ends say how far it would move, not where the building is. Nor do they
bound what lies between them where an item's class does not move one way with α: on an OpenSees braced frame
(tests/verification/test_yielding_braced.py) one item kept one class at α 1.5, 4 and 6 and had another at the
frame's own 2.4.
"""
from __future__ import annotations

from dataclasses import replace

import pandas as pd

from assess.assessment.result import AssessmentResult
from assess.assessment.summary import THROUGH_BUILDING
from assess.assessment.floors import alpha_of, alpha_source_of, pushover_alpha
from assess.building.modes import ALPHA_RANGE_BY_SYSTEM, ALPHA_RANGE_SOURCE
from assess.decision.flags import Flag, result_state
from assess.inventory import Inventory
from assess.inventory.site_building import BuildingSheet
from assess.quantity_text import floor_numbering_of, floors_text, sentence_start, system_of

#: The summary's columns of the two ends, in the order of ``assess/data/columns.csv``: empty for an item the
#: building's motions do not reach (and for anchored items).
ALPHA_RANGE_COLUMNS = ["risk_alpha_low", "risk_alpha_high", "p_beyond_clearance_alpha_low",
                       "p_beyond_clearance_alpha_high", "p_overturn_alpha_low", "p_overturn_alpha_high"]
#: The flag of an item whose risk class is not the same at both ends and at the sheet's α.
FLAG_CODE = "alpha_range"
#: The most items the note names (the flags name them all).
MAX_NAMED = 8


#: The storeys' stiffness after yield over their stiffness before that bounds the α a pushover's slope gives where
#: the sheet does not give the model's (``storey_hardening_ratio``): the 2 to 5 % of code-designed frames' storey
#: pushover curves that :data:`~assess.building.nonlinear.DEFAULT_HARDENING` (3 %) is taken from.
PUSHOVER_HARDENING_RANGE = (0.02, 0.05)


def pushover_ends(sheet: BuildingSheet) -> tuple[float, float] | None:
    """The α the sheet's ``pushover_slope_ratio`` gives with the storeys hardening at either end of
    :data:`PUSHOVER_HARDENING_RANGE` (:func:`assess.assessment.floors.pushover_alpha`), low to high: where the
    hardening is not the model's, the building's α lies between them as its hardening lies between those (a storey
    that hardens more leaves less of the slope to the columns, so they are weaker: a larger α). None where the sheet
    gives α, or the model's hardening, or no slope, and where both ends give the same α (both beyond the search)."""
    hardening = _pushover_end_hardening(sheet)
    return None if hardening is None else tuple(hardening)


def _pushover_end_hardening(sheet: BuildingSheet) -> dict[float, float] | None:
    """:func:`pushover_ends`' two α, low to high, each with the storeys' hardening that gives it."""
    if (sheet.pushover_slope_ratio is None or sheet.storey_hardening_ratio is not None
            or sheet.lateral_stiffness_ratio is not None):
        return None
    found = sorted((pushover_alpha(replace(sheet, storey_hardening_ratio=b)).alpha, b)
                   for b in PUSHOVER_HARDENING_RANGE)
    return dict(found) if found[1][0] > found[0][0] else None


def alpha_ends(sheet: BuildingSheet, given: tuple[float, float] | None = None) -> tuple[float, float]:
    """The two α the level runs again at: ``given`` (low, high) where the engineer names them, else
    :func:`pushover_ends` where α comes from the pushover's slope alone, else the ends of the sheet's system's range
    (:data:`~assess.building.modes.ALPHA_RANGE_BY_SYSTEM`).

    >>> alpha_ends(BuildingSheet(storeys=12, height_m=48.0, system="steel moment frame"))
    (5.0, 20.0)
    >>> alpha_ends(BuildingSheet(storeys=6, height_m=21.0, system="shear wall"), (0.5, 3.0))
    (0.5, 3.0)
    """
    if given:
        return float(given[0]), float(given[1])
    return pushover_ends(sheet) or ALPHA_RANGE_BY_SYSTEM[sheet.system]


def alpha_ends_source(sheet: BuildingSheet, ends: tuple[float, float]) -> str:
    """Where :func:`alpha_ends`'s ``ends`` come from, in words for the note."""
    if ends == pushover_ends(sheet):
        low, high = PUSHOVER_HARDENING_RANGE
        return (f"the α the pushover's slope gives with the storeys hardening at {low:.0%} and at {high:.0%} of "
                "their stiffness after yield, the range of code-designed frames, where the building's own is not "
                "given in storey_hardening_ratio")
    if ends == ALPHA_RANGE_BY_SYSTEM[sheet.system]:
        return ALPHA_RANGE_SOURCE[sheet.system]
    return "the ends given to --alpha-range"


def items_through_building(result: AssessmentResult) -> list[str]:
    """The ids of the freestanding items on floors whose motions come through the building
    (:func:`assess.assessment.summary.floor_origins`), in the summary's order: those α can move."""
    floors = [floor for floor, origin in result.floor_origins.items()
              if floor is not None and origin.endswith(THROUGH_BUILDING)]
    summary = result.summary
    reached = summary["floor"].isin(floors) & (summary["risk"] != "anchored")
    return [str(item_id) for item_id in summary.loc[reached, "id"]]


def at_alpha(inventory: Inventory, ids: list[str], alpha: float) -> Inventory:
    """``inventory`` with only the items ``ids`` (and their workbook warnings) and the building's α ``alpha``; at an
    end of :func:`pushover_ends`, with the storeys hardening as that end takes them (the building that slope
    describes if its storeys harden so)."""
    keep = inventory.equipment["id"].astype(str).isin(ids)
    sheet, source = inventory.building, "an end of --alpha-range, not the building's"
    hardening, whence = sheet.storey_hardening_ratio, sheet.hardening_source
    ends = _pushover_end_hardening(sheet)
    if ends is not None and alpha in ends:
        hardening, whence = ends[alpha], "this end of --alpha-range's"
        source = f"an end of --alpha-range, with the storeys hardening at {hardening:.0%}, not the building's"
    return replace(inventory, equipment=inventory.equipment[keep].reset_index(drop=True),
                   building=replace(sheet, lateral_stiffness_ratio=float(alpha), pushover_slope_ratio=None,
                                    storey_hardening_ratio=hardening, alpha_source=source, hardening_source=whence),
                   warnings=tuple(w for w in inventory.warnings if str(w.item_id) in ids))


def with_alpha_range(result: AssessmentResult, sheet: BuildingSheet, ends: tuple[float, float],
                     at_ends: dict[float, AssessmentResult]) -> AssessmentResult:
    """``result`` (the level at the sheet's α) with each reached item's risk class and chances at the two ``ends``
    of α (``at_ends``: the level's result for those items at each end, :func:`at_alpha`) in the summary
    (:data:`ALPHA_RANGE_COLUMNS`), a :data:`FLAG_CODE` flag on each item whose class is not the same at the
    ends and at the sheet's α, and a note saying what was run and what moved."""
    low, high = ends
    summary = result.summary.copy()
    ids = summary["id"].astype(str)
    at = {side: _rows_of(at_ends.get(end), ids) for end, side in ((low, "low"), (high, "high"))}
    for column in ALPHA_RANGE_COLUMNS:  # empty where the building's motions do not reach the item
        taken, side = column.rsplit("_alpha_", 1)
        summary[column] = at[side][taken].to_numpy()
    alpha, whose = alpha_of(sheet), alpha_source_of(sheet, short=True)
    if not at_ends:
        note = (f"--alpha-range: no freestanding item is on a floor whose motions come through the building, so "
                f"the building's α ({alpha:.3g}, {whose}) moves no item's result and the level did not run again.")
        return replace(result, summary=summary, hazard_notes=list(result.hazard_notes) + [note])
    system = system_of(result.settings)
    flags = list(result.flags)
    codes = list(summary["flags"])
    moved, held = [], []
    for k, item_id in enumerate(ids):
        row = summary.iloc[k]
        if not isinstance(row["risk_alpha_low"], str):  # not reached
            continue
        if len({row["risk_alpha_low"], row["risk"], row["risk_alpha_high"]}) == 1:
            held.append(item_id)
            continue
        moved.append(item_id)
        flags.append(Flag(item_id, FLAG_CODE, (
            f"at α {low:.3g}: {result_state(at['low'].loc[item_id], system)}; at α {high:.3g}: "
            f"{result_state(at['high'].loc[item_id], system)}; at the building's α {alpha:.3g} ({whose}, which "
            f"governs): {result_state(row, system)}."), detail=(
            f"{row['risk_alpha_low']} at α {low:.3g}, {row['risk']} at α {alpha:.3g}, {row['risk_alpha_high']} at "
            f"α {high:.3g}")))
        codes[k] = tuple(codes[k]) + (FLAG_CODE,)
    summary["flags"] = codes
    note = alpha_range_note(sheet, ends, alpha, whose, result, moved, held)
    return replace(result, summary=summary, flags=flags, hazard_notes=list(result.hazard_notes) + [note])


def _rows_of(end_result: AssessmentResult | None, ids):
    """The summary rows of one end's result by item id, in the order of ``ids`` (empty rows where it has none)."""
    if end_result is None:
        return pd.DataFrame(index=ids, columns=["risk", "p_beyond_clearance", "p_overturn"], dtype=object)
    rows = end_result.summary
    return rows.set_index(rows["id"].astype(str)).reindex(ids)


def alpha_range_note(sheet, ends, alpha, whose, result, moved, held) -> str:
    """What ``--alpha-range`` ran and what it moved, in sentences for the report (from the summary's columns)."""
    low, high = ends
    source = alpha_ends_source(sheet, ends)
    summary = result.summary
    floors = sorted(set(summary.loc[summary["id"].astype(str).isin(moved + held), "floor"].astype(int)))
    count = len(moved) + len(held)
    text = (f"The building's lateral stiffness ratio α: the level ran again at α {low:.3g} and {high:.3g} "
            f"({source}), "
            f"with the same ground motions, for the {count} freestanding "
            f"{'item' if count == 1 else 'items'} on "
            f"{floors_text(floors, floor_numbering_of(result.settings))}. ")
    if moved:
        named = ", ".join(moved[:MAX_NAMED]) + (f" and {len(moved) - MAX_NAMED} more" if len(moved) > MAX_NAMED else "")
        text += (f"{sentence_start(_count(moved))} {'is' if len(moved) == 1 else 'are'} in another risk class at "
                 f"one end or both than at the building's α ({named}: under Flags); ")
        text += (f"{'the other' if len(held) == 1 else 'the other ' + str(len(held))} "
                 f"{'keeps its' if len(held) == 1 else 'keep their'} class at both ends. " if held
                 else "no item keeps its class at both ends. ")
    else:
        text += "Every one is in the same class at both ends as at the building's α. "
    return text + (f"The level's answer, at α {alpha:.3g} ({whose}), governs; summary.csv gives each item's class and "
                   "chances at both ends (risk_alpha_low, risk_alpha_high, ...).")


def _count(ids) -> str:
    return f"{len(ids)} {'item' if len(ids) == 1 else 'items'}"
