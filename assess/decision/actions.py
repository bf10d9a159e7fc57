"""What to do about each freestanding item, what that would change, and the work orders by floor and room.

The actions part of the decisions stage (:mod:`assess.decision.decisions` calls
:func:`decide_action` for every freestanding item). An action fits the item
(:func:`choose_action`): an item that overturns or rocks is anchored, or
tethered when it stands on casters (mobile by design), unless moving its
heavy contents low stops it rocking (the engine says so: the what-if run of
:func:`assess.assessment.run.lowered_contents`); an item that only slides
past its room gets room where the room it needs to gain is one a room can
spare (``room_max_cm``), a restraint otherwise; an item on casters that slides gets
its casters locked or chocked and that room kept clear where a room can spare
it, a tether otherwise.

Each action carries the item's chances if it is taken
(:func:`residual_chances`): ``p_overturn_after`` and
``p_beyond_clearance_after``, from the engine for ``lower_contents``, from
the sliding demand for ``room`` and ``lock_casters`` (the room is the sliding
exceeded with probability ``risk_pf_moderate``; for an item on casters the
workbook's μ is taken as that of its casters locked), 0 for a restraint that
holds (anchor, tether, restraint: an assumption, stated in the what-if
sentence), unchanged for ``none``.

Every sentence is built here from the item's own numbers; lengths go through
:func:`assess.quantity_text.length_text`.
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from assess.quantity_text import floor_text, length_text, percent_text, system_of
from assess.inventory.settings import Settings  # noqa: F401 (the doctests)

#: The action kinds, in the order a facility takes them (``action_kind`` of summary.csv).
ACTION_KINDS = ("anchor", "tether", "lower_contents", "restrain", "lock_casters", "room", "relocate", "none",
                "anchored")
#: The kinds whose residual chances are 0 on the assumption that the restraint holds.
HELD_KINDS = ("anchor", "tether", "restrain")
#: What a work order asks for, by action kind (work_orders.csv and the report's work orders).
WORK_ORDER_TEXT = {
    "anchor": "anchor to the floor or wall",
    "tether": "tether or strap to the wall (on casters)",
    "lower_contents": "move heavy contents to the lowest shelves",
    "restrain": "restrain (edge stops, bumpers or straps)",
    "lock_casters": "lock or chock the casters and keep room clear (each item's in its details)",
    "room": "give room (each item's in its details)",
    "relocate": "relocate",
}


def _plural(count: int, word: str) -> str:
    return f"{count} {word}{'' if count == 1 else 's'}"


def suite_share_text(probability: float, row: dict) -> str:
    """"2 of its 3 motions" for records, "12% of its 30 simulated histories" otherwise (never "0%" for a
    probability above 0: :func:`~assess.quantity_text.percent_text`).

    >>> suite_share_text(0.002, {"suite_motions": 3, "suite_histories": 30})
    '<1% of its 30 simulated histories (3 motions)'
    """
    motions, histories = int(row["suite_motions"]), int(row["suite_histories"])
    if histories == motions:
        count = probability * motions
        if abs(count - round(count)) > 1e-9:  # runs weighted over a range of mu
            return f"a weighted {percent_text(probability)} of its {_plural(motions, 'motion')} over its range of mu"
        return f"{int(round(count))} of its {_plural(motions, 'motion')}"
    return f"{percent_text(probability)} of its {histories} simulated histories ({_plural(motions, 'motion')})"


def room_to_gain_cm(row: dict) -> float:
    """The room [cm] the item must gain to be low risk on sliding: ``demand_room_cm`` rounded up less
    ``clearance_cm`` rounded down (the two numbers its sentence shows), at least 0."""
    return max(float(np.ceil(float(row["demand_room_cm"]))) - float(np.floor(float(row["clearance_cm"]))), 0.0)


def room_is_realistic(row: dict, settings: dict) -> bool:
    """Whether the room the item must gain (:func:`room_to_gain_cm`) is one a room can spare: at most
    ``room_max_cm``, what an aisle can give up when the item is moved out into it.

    >>> settings = Settings(room_max_cm=30)
    >>> room_is_realistic({"demand_room_cm": 39.6, "clearance_cm": 35.6}, settings), room_is_realistic(
    ...     {"demand_room_cm": 191.0, "clearance_cm": 30.0}, settings)
    (True, False)
    """
    return room_to_gain_cm(row) <= settings.room_max_cm


def lowering_suffices(row: dict, lowered: dict | None, settings: dict) -> bool:
    """Whether moving the heavy contents low is enough on its own: with the lowered centre of mass the
    engine finds no overturning and no rocking under any history of the item's suite, and sliding past
    its room below ``risk_pf_moderate`` (``lowered``: the item's demand in the what-if run; None where
    it was not run)."""
    if lowered is None:
        return False
    return (float(lowered["p_overturn"]) == 0.0 and not bool(lowered["uplift"])
            and float(lowered["p_beyond_clearance"]) < settings.risk_pf_moderate)


def choose_action(row: dict, uplift: bool, casters: bool, lowered: dict | None, settings: dict) -> str:
    """The action kind that fits the item (module docstring).

    ``row``: its governing demand with ``risk``; ``uplift``: whether it rocks under any motion;
    ``casters``: whether it stands on casters; ``lowered``: its demand with its heavy contents low
    (:func:`lowering_suffices`), or None.

    >>> settings = Settings(risk_pf_moderate=0.1, room_max_cm=30)
    >>> row = {"p_overturn": 0.0, "p_beyond_clearance": 0.6, "demand_room_cm": 191.0, "risk": "high",
    ...        "clearance_cm": 30.0}
    >>> choose_action(row, False, False, None, settings), choose_action(row, False, True, None, settings)
    ('restrain', 'tether')
    >>> choose_action({**row, "demand_room_cm": 25.0}, False, True, None, settings)
    'lock_casters'
    >>> choose_action({**row, "p_overturn": 0.3}, True, True, None, settings)
    'tether'
    """
    if row.get("risk") == "low":  # the class says it needs nothing: the action never says otherwise
        return "none"
    overturns = float(row["p_overturn"]) > 0.0
    if overturns or uplift:
        if lowering_suffices(row, lowered, settings):
            return "lower_contents"
        return "tether" if casters else "anchor"
    if float(row["p_beyond_clearance"]) < settings.risk_pf_moderate and row.get("risk") != "high":
        return "none"
    if room_is_realistic(row, settings):
        return "lock_casters" if casters else "room"
    return "tether" if casters else "restrain"


def residual_chances(kind: str, row: dict, lowered: dict | None, settings: dict) -> tuple[float, float]:
    """(``p_overturn_after``, ``p_beyond_clearance_after``): the item's chances if the action is taken.

    ``lower_contents``: the engine's, with the lowered centre of mass; ``room`` and ``lock_casters``: its
    chance of overturning (0: an item that overturns is not given room) and ``risk_pf_moderate``, the
    chance that the sliding exceeds ``demand_room_cm``; a restraint (:data:`HELD_KINDS`): 0 and 0, assuming it holds;
    ``none``: unchanged.

    >>> residual_chances("room", {"p_overturn": 0.0, "p_beyond_clearance": 0.4}, None, Settings(risk_pf_moderate=0.1))
    (0.0, 0.1)
    """
    if kind == "lower_contents":
        return float(lowered["p_overturn"]), float(lowered["p_beyond_clearance"])
    if kind in ("room", "lock_casters"):
        return float(row["p_overturn"]), min(settings.risk_pf_moderate, float(row["p_beyond_clearance"]))
    if kind in HELD_KINDS:
        return 0.0, 0.0
    return float(row["p_overturn"]), float(row["p_beyond_clearance"])


def _rocking_text(row: dict) -> str:
    return (f"it uplifts and rocks (peak rotation {float(row['theta_max_over_alpha']):.2f} of its overturning "
            f"angle alpha) but did not overturn under its {_plural(int(row['suite_motions']), 'motion')}")


def _why_overturn_or_rock(row: dict) -> str:
    if float(row["p_overturn"]) > 0.0:
        return f"it overturns under {suite_share_text(float(row['p_overturn']), row)}"
    return _rocking_text(row)


def _why(row: dict, uplift: bool, system: str, settings: dict) -> str:
    """Why an item is held: it overturns or rocks, or it slides farther than a room can spare."""
    if float(row["p_overturn"]) > 0.0 or uplift:
        return _why_overturn_or_rock(row)
    return f"{_room_numbers(row, system)}: {_more_than_spare(row, system, settings)}"


def _more_than_spare(row: dict, system: str, settings: dict) -> str:
    return (f"{length_text(room_to_gain_cm(row), system, 'up')} more, beyond the "
            f"{length_text(settings.room_max_cm, system)} a room can spare")


def _room_numbers(row: dict, system: str) -> str:
    return (f"it needs {length_text(row['demand_room_cm'], system, 'up')} to be low risk and has "
            f"{length_text(row['clearance_cm'], system, 'down')} ({percent_text(row['p_beyond_clearance'])} chance "
            "of sliding past it)")


def _lowered_text(row: dict, lowered: dict, system: str) -> str:
    """What the engine gives with the heavy contents low, in one clause."""
    rocks = "it still rocks" if lowered["uplift"] else "it no longer rocks"
    return (f"With its heavy contents moved low (centre of mass at {float(lowered['cg_fraction']):.0%} of its "
            f"height, {length_text(lowered['cg_height_cm'], system)} instead of "
            f"{length_text(row['cg_height_cm'], system)}) the engine gives overturning "
            f"{percent_text(lowered['p_overturn'])} (as loaded {percent_text(row['p_overturn'])}) and sliding past "
            f"its room {percent_text(lowered['p_beyond_clearance'])} (as loaded "
            f"{percent_text(row['p_beyond_clearance'])}), and {rocks}, under the same motions")


def action_sentence(kind: str, row: dict, uplift: bool, lowered: dict | None, settings: dict) -> str:
    """A plain sentence a facility manager can act on, for the action ``kind`` (:func:`choose_action`)."""
    system = system_of(settings)
    if kind == "anchor":
        return f"Anchor it to the floor or wall: {_why_overturn_or_rock(row)}"
    if kind == "tether":
        return f"Tether or strap it to the wall (it stands on casters): {_why(row, uplift, system, settings)}"
    if kind == "lower_contents":
        return (f"Move its heavy contents to the lowest shelves: as loaded {_why_overturn_or_rock(row)}; with its "
                f"centre of mass at {float(lowered['cg_fraction']):.0%} of its height the engine finds it still "
                "under the same motions")
    if kind == "lock_casters":
        return (f"Lock or chock its casters and keep {length_text(row['demand_room_cm'], system, 'up')} clear "
                f"around it: {_room_numbers(row, system)}")
    if kind == "room":
        return f"Give it room: {_room_numbers(row, system)}"
    if kind == "restrain":
        return (f"Restrain it (edge stops, bumpers or straps): {_room_numbers(row, system)}: "
                f"{_more_than_spare(row, system, settings)}")
    return "No action needed"


def what_if_sentence(kind: str, row: dict, lowered: dict | None, settings: dict) -> str:
    """The item's risk if the action is taken, from its own numbers or the engine's what-if run."""
    system = system_of(settings)
    engine = ""
    if lowered is not None and kind != "lower_contents":
        engine = f" Lowering its contents alone is not enough. {_lowered_text(row, lowered, system)}."
    if kind == "anchor":
        return ("Anchored (assumed to hold), it would neither slide nor overturn: "
                "0% for both. Giving it room does not help: it overturns or rocks where it stands." + engine)
    if kind == "tether":
        return ("Tethered to the structure (assumed to hold), it would neither roll away nor overturn: "
                "0% for both." + engine)
    if kind == "lower_contents":
        return (f"{_lowered_text(row, lowered, system)}. Anchoring it would also do, at 0% for both "
                "(assumed to hold).")
    if kind == "restrain":
        return ("Restrained (assumed to hold), it would not slide past its room: 0%. Room would not do: it needs "
                f"{_more_than_spare(row, system, settings)} (setting room_max_cm).")
    if kind == "room" or kind == "lock_casters":
        locked = (" Its sliding was computed with the workbook's mu, taken as that of its casters locked: if they "
                  "are not, tether it." if kind == "lock_casters" else "")
        return (f"Given {length_text(row['demand_room_cm'], system, 'up')} of room (it has "
                f"{length_text(row['clearance_cm'], system, 'down')}), its chance of sliding past it would be "
                f"{percent_text(settings.risk_pf_moderate)}: low risk.{locked}")
    return ""


def decide_action(item, row: dict, uplift: bool, lowered: dict | None, settings: dict) -> dict:
    """The action columns of one freestanding item: ``action_kind``, ``action``, ``what_if``,
    ``p_overturn_after`` and ``p_beyond_clearance_after`` (``row``: its governing demand with ``risk``,
    ``clearance_cm`` and ``cg_height_cm``; ``lowered``: its demand in the lowered-contents run, or None)."""
    casters = bool(getattr(item, "casters", False))
    kind = choose_action(row, uplift, casters, lowered, settings)
    p_overturn_after, p_beyond_after = residual_chances(kind, row, lowered, settings)
    return {"action_kind": kind, "action": action_sentence(kind, row, uplift, lowered, settings),
            "what_if": what_if_sentence(kind, row, lowered, settings),
            "p_overturn_after": p_overturn_after, "p_beyond_clearance_after": p_beyond_after}


# ---------------------------------------------------------------- the what-if run: heavy contents low

def lowered_contents_items(equipment: pd.DataFrame, rows: dict, uplift: dict, settings: dict) -> list:
    """The items whose heavy contents the what-if moves low: freestanding items that overturn or rock
    (``rows``: id -> governing demand; ``uplift``: id -> whether it rocks) and whose centre of mass is
    above ``lower_contents_cg_fraction`` of their height (by more than 1 cm), in item order."""
    fraction = settings.lower_contents_cg_fraction
    chosen = []
    for item in equipment[~equipment["anchored"]].itertuples(index=False):
        if item.id not in rows:
            continue
        moves = float(rows[item.id]["p_overturn"]) > 0.0 or bool(uplift[item.id])
        if moves and float(item.cg_height_m) > fraction * float(item.height_m) + 0.01:
            chosen.append(item.id)
    return chosen


def lowered_rows(equipment: pd.DataFrame, rows: dict, uplift: dict, settings: dict) -> dict:
    """id -> what :func:`decide_action` reads of the lowered-contents run (``rows``/``uplift`` of that run,
    :class:`assess.assessment.demand.ItemDemand`): ``p_overturn``, ``p_beyond_clearance``, ``uplift``,
    ``theta_max_over_alpha``, ``cg_fraction`` and ``cg_height_cm``."""
    fraction = settings.lower_contents_cg_fraction
    heights = equipment.set_index("id")["height_m"]
    return {item_id: {"p_overturn": float(row["p_overturn"]), "p_beyond_clearance": float(row["p_beyond_clearance"]),
                      "uplift": bool(uplift[item_id]), "theta_max_over_alpha": float(row["theta_max_over_alpha"]),
                      "cg_fraction": fraction, "cg_height_cm": fraction * float(heights[item_id]) * 100.0}
            for item_id, row in rows.items()}


# ---------------------------------------------------------------- work orders

#: Columns of work_orders.csv (docs/outputs.md).
WORK_ORDER_COLUMNS = ["floor", "floor_label", "room", "action", "items", "count"]


def work_orders(summary: pd.DataFrame, numbering: str = "ground_0") -> pd.DataFrame:
    """One row per floor, room and action (:data:`WORK_ORDER_COLUMNS`): ``floor`` the workbook's number,
    ``floor_label`` as the report labels it (``numbering``: :func:`assess.quantity_text.floor_text`),
    ``items`` the ids (in id order), ``count`` the units (``quantity`` summed); items that need no action
    and anchored items are left out (and a row without a known action kind). Ordered by floor, room, then
    :data:`ACTION_KINDS`."""
    kinds = summary["action_kind"] if "action_kind" in summary else pd.Series("", index=summary.index)
    acts = summary[kinds.isin([k for k in ACTION_KINDS if k not in ("none", "anchored")])]
    if not len(acts):
        return pd.DataFrame(columns=WORK_ORDER_COLUMNS)
    acts = acts.assign(room=acts["room"].fillna("").astype(str), _order=acts["action_kind"].map(ACTION_KINDS.index),
                       id=acts["id"].astype(str))
    grouped = acts.sort_values("id", kind="stable").groupby(["floor", "room", "_order", "action_kind"], sort=True)
    table = grouped.agg(items=("id", lambda ids: ", ".join(ids)), count=("quantity", "sum")).reset_index()
    table = table.rename(columns={"action_kind": "action"})
    table["floor"] = table["floor"].astype(int)
    table["count"] = table["count"].astype(int)
    table["floor_label"] = [floor_text(f, numbering) for f in table["floor"]]
    return table[WORK_ORDER_COLUMNS].reset_index(drop=True)


def work_order_sentences(table: pd.DataFrame) -> list[dict]:
    """The report's work orders: per floor, its rooms, each with one sentence per action
    ("anchor to the floor or wall: GAS-G-01 (1 unit)")."""
    floors = []
    for floor, on_floor in table.groupby("floor", sort=True):
        rooms = []
        for room, in_room in on_floor.groupby("room", sort=False):
            orders = [f"{WORK_ORDER_TEXT.get(r.action, r.action)}: {r.items} ({_plural(int(r.count), 'unit')})"
                      for r in in_room.itertuples(index=False)]
            rooms.append({"room": room or "(no room given)", "orders": orders})
        floors.append({"floor": int(floor), "units": int(on_floor["count"].sum()), "rooms": rooms})
    return floors
