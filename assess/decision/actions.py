"""What to do about each freestanding item, what that would change, and the work orders by floor and room.

The actions part of the decisions stage (:mod:`assess.decision.decisions` calls
:func:`decide_action` for every freestanding item). The failure that makes the item's class decides the
action (:func:`choose_action`; the mode is :func:`assess.decision.risk_classes.deciding_mode`):

* where overturning or rocking that harms it is not low, the item is anchored, or tethered when it
  stands on casters (mobile by design), unless moving its heavy contents low stops it rocking (the engine
  says so: the what-if run of :func:`assess.assessment.run.lowered_contents`), which is offered only where
  its ``contents`` are movable and never where it raises a chance;
* where only sliding past its room makes it moderate or high, it gets room where the room it needs to
  gain is one a room can spare (``room_max_cm``), a restraint against sliding otherwise; on casters, its
  casters locked or chocked and that room kept clear where a room can spare it, a tether otherwise.

Each action carries the item's chances if it is taken
(:func:`residual_chances`): ``p_overturn_after`` and
``p_beyond_clearance_after``, from the engine for ``lower_contents``, from
the sliding demand for ``room`` and ``lock_casters`` (the room is the sliding
exceeded with probability ``risk_pf_moderate``; for an item on casters the
workbook's μ is taken as that of its casters locked), 0 for a restraint that
holds (an assumption, stated in the what-if sentence: anchor and tether hold it against both, a restraint
against sliding only, its overturning left as it is), unchanged for ``none``.

Everything here is a number or a kind (:class:`ActionKind`, :class:`ActionDecision`), in SI; the
sentences a reader sees are made from them by :mod:`assess.report.advice`, in the report's units.
"""
from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum

import numpy as np
import pandas as pd

from assess.quantity_text import floor_text
from assess.decision.code_governed import CodeRule, code_rule, connection_rules
from assess.decision.risk_classes import Chances, deciding_mode, mode_classes
from assess.inventory.units import CM_PER_M  # noqa: F401 (the decisions' too)
from assess.inventory.settings import Settings


class ActionKind(StrEnum):
    """The action kinds, in the order a facility takes them (``action_kind`` of summary.csv)."""

    ANCHOR = "anchor"
    TETHER = "tether"
    STRAP = "strap"
    CHAIN = "chain"
    LOWER_CONTENTS = "lower_contents"
    RESTRAIN = "restrain"
    LOCK_CASTERS = "lock_casters"
    ROOM = "room"
    RELOCATE = "relocate"
    NONE = "none"
    ANCHORED = "anchored"


#: The action kinds, in the order a facility takes them (``action_kind`` of summary.csv).
ACTION_KINDS = tuple(kind.value for kind in ActionKind)
#: The kinds that hold the item against sliding and overturning (its residual chances 0, assuming it holds).
HELD_KINDS = (ActionKind.ANCHOR, ActionKind.TETHER, ActionKind.STRAP, ActionKind.CHAIN)
#: What an item's contents can do where the workbook says nothing (``contents``).
DEFAULT_CONTENTS = "none"


@dataclass(frozen=True)
class LoweredDemand:
    """An item's demand in the what-if run with its heavy contents low (:func:`lowered_rows`): its chances,
    whether it still rocks, its peak rotation over α, and where its centre of mass is then (a share of its
    height and a height [cm])."""

    p_overturn: float
    p_beyond_clearance: float
    uplift: bool
    theta_max_over_alpha: float
    cg_fraction: float
    cg_height_cm: float


@dataclass(frozen=True)
class ActionDecision:
    """The action chosen for one item (:func:`decide_action`) and what it leaves: numbers and kinds only.

    ``kind``: :class:`ActionKind`; ``p_overturn_after``, ``p_beyond_clearance_after``: its chances if the
    action is taken (:func:`residual_chances`); ``uplift``: whether it rocks as it stands; ``casters``:
    whether it stands on casters; ``lowered``: the engine's what-if with its heavy contents low (None where
    it was not run); ``room_to_gain_cm``: :func:`room_to_gain_cm`; ``mode``: the failure that decided it
    (``overturn``, ``beyond_clearance``, ``rocking_harm``; "" for none); ``contents``: what its contents can
    do (``movable``, ``fixed``, ``none``); ``code``: the rule of :mod:`assess.decision.code_governed` that
    prescribes ``kind`` whatever the analysis says (None: the analysis chose it); ``analysis_kind``: the
    action the analysis alone chooses (:func:`choose_action`); ``type_source``: where the item's type comes from
    (``typed``, ``name``, ``default``: the report asks to confirm a type read from the name);
    ``connections``: its lines (``gas``, ``fluid``), each taking a flexible connection beside the action
    (:func:`assess.decision.code_governed.connection_rules`); ``connections_assumed``: they were not written
    but follow from its type (the report says so).
    """

    kind: ActionKind
    p_overturn_after: float
    p_beyond_clearance_after: float
    uplift: bool = False
    casters: bool = False
    lowered: LoweredDemand | None = None
    room_to_gain_cm: float = float("nan")
    mode: str = ""
    contents: str = DEFAULT_CONTENTS
    code: CodeRule | None = None
    analysis_kind: ActionKind | None = None
    type_source: str = "default"
    connections: tuple[str, ...] = ()
    connections_assumed: bool = False

    def connection_rules(self) -> tuple:
        """The flexible connections its lines take (:class:`~assess.decision.code_governed.ConnectionRule` s)."""
        rules = connection_rules()
        return tuple(rules[line] for line in self.connections if line in rules)

    def columns(self) -> dict:
        """Its columns of summary.csv that are numbers and kinds (and the code's detail and reference, and its
        lines' flexible connections)."""
        code = self.code
        lines = self.connection_rules()
        return {"action_kind": self.kind.value, "p_overturn_after": self.p_overturn_after,
                "p_beyond_clearance_after": self.p_beyond_clearance_after, "action_mode": self.mode,
                "action_analysis": (self.analysis_kind or self.kind).value,
                "action_detail": code.detail if code else "", "action_reference": code.reference if code else "",
                "connection_detail": "; ".join(f"{rule.connection}: {rule.detail}" for rule in lines),
                "connection_reference": "; ".join(dict.fromkeys(rule.reference for rule in lines))}


def item_connections(item) -> tuple[str, ...]:
    """The lines of ``item`` (its ``connections``: ``"gas, fluid"``, ``"none"`` or empty) as a tuple."""
    text = getattr(item, "connections", "") or ""
    text = text if isinstance(text, str) else ""
    return tuple(line for line in (part.strip() for part in text.split(",")) if line and line != "none")


def room_to_gain_cm(row: dict) -> float:
    """The room [cm] the item must gain to be low risk on sliding: ``demand_room_cm`` rounded up less
    ``clearance_cm`` rounded down (the two numbers its sentence shows), at least 0."""
    return max(float(np.ceil(float(row["demand_room_cm"]))) - float(np.floor(float(row["clearance_cm"]))), 0.0)


def room_is_realistic(row: dict, settings: Settings) -> bool:
    """Whether the room the item must gain (:func:`room_to_gain_cm`) is one a room can spare: at most
    ``room_max_cm``, what an aisle can give up when the item is moved out into it.

    >>> settings = Settings(room_max_cm=30)
    >>> room_is_realistic({"demand_room_cm": 39.6, "clearance_cm": 35.6}, settings), room_is_realistic(
    ...     {"demand_room_cm": 191.0, "clearance_cm": 30.0}, settings)
    (True, False)
    """
    return room_to_gain_cm(row) <= settings.room_max_cm


def lowering_suffices(row: dict, lowered: LoweredDemand | None, settings: Settings) -> bool:
    """Whether moving the heavy contents low is enough on its own: with the lowered centre of mass the
    engine finds no overturning and no rocking under any history of the item's suite, and sliding past
    its room below ``risk_pf_moderate`` and no more likely than as loaded (lowering never offered where it
    raises a chance; ``lowered``: the item's demand in the what-if run; None where it was not run)."""
    if lowered is None:
        return False
    return (lowered.p_overturn == 0.0 and not lowered.uplift
            and lowered.p_beyond_clearance < settings.risk_pf_moderate
            and lowered.p_beyond_clearance <= float(row["p_beyond_clearance"]))


def _chances(row) -> Chances:
    return Chances(float(row["p_overturn"]), float(row["p_beyond_clearance"]),
                   float(row.get("p_rocking_harm", 0.0) or 0.0))


def topples(row, settings: Settings) -> bool:
    """Whether overturning or rocking that harms the item is not low on its own
    (:func:`assess.decision.risk_classes.mode_classes`): room or a restraint against sliding would leave it."""
    classes = mode_classes(_chances(row), str(row.get("consequence", "ordinary")), settings)
    return classes["overturn"] != "low" or classes["rocking_harm"] != "low"


def action_mode(row, settings: Settings) -> str:
    """The failure that decides the action of a moderate or high item: ``overturn`` or ``rocking_harm`` where
    either is not low (:func:`topples`; the larger chance of the two at the higher class), else
    ``beyond_clearance``; "" for a low item."""
    if row.get("risk") == "low":
        return ""
    chances, consequence = _chances(row), str(row.get("consequence", "ordinary"))
    if not topples(row, settings):
        return "beyond_clearance"
    mode = deciding_mode(Chances(chances.overturn, 0.0, chances.rocking_harm), consequence, settings)
    return mode if mode != "beyond_clearance" else "overturn"


def choose_action(row: dict, uplift: bool, casters: bool, lowered: LoweredDemand | None,
                  settings: Settings, contents: str = DEFAULT_CONTENTS) -> ActionKind:
    """The action kind that fits the item, from the failure that decides it (module docstring).

    ``row``: its governing demand with ``risk`` (and ``consequence``, ``p_rocking_harm`` where known);
    ``uplift``: whether it rocks under any motion; ``casters``: whether it stands on casters; ``lowered``:
    its demand with its heavy contents low (:func:`lowering_suffices`), or None; ``contents``: what its
    contents can do (lowering is offered only where they are ``movable``).

    >>> settings = Settings(risk_pf_moderate=0.1, room_max_cm=30, risk_overturn_moderate=0.025,
    ...                     risk_overturn_high=0.1, risk_pf_high=0.5, risk_rocking_moderate=0.1)
    >>> row = {"p_overturn": 0.0, "p_beyond_clearance": 0.6, "demand_room_cm": 191.0, "risk": "high",
    ...        "clearance_cm": 30.0}
    >>> str(choose_action(row, False, False, None, settings)), str(choose_action(row, False, True, None, settings))
    ('restrain', 'tether')
    >>> str(choose_action({**row, "demand_room_cm": 25.0}, False, True, None, settings))
    'lock_casters'
    >>> str(choose_action({**row, "p_overturn": 0.3}, True, True, None, settings))
    'tether'
    >>> str(choose_action({**row, "p_overturn": 0.004}, True, False, None, settings))  # <1%: the sliding decides
    'restrain'
    """
    if row.get("risk") == "low":  # the class says it needs nothing: the action never says otherwise
        return ActionKind.NONE
    if topples(row, settings):
        if contents == "movable" and lowering_suffices(row, lowered, settings):
            return ActionKind.LOWER_CONTENTS
        return ActionKind.TETHER if casters else ActionKind.ANCHOR
    if room_is_realistic(row, settings):
        return ActionKind.LOCK_CASTERS if casters else ActionKind.ROOM
    return ActionKind.TETHER if casters else ActionKind.RESTRAIN


def residual_chances(kind: str, row: dict, lowered: LoweredDemand | None, settings: Settings) -> tuple[float, float]:
    """(``p_overturn_after``, ``p_beyond_clearance_after``): the item's chances if the action is taken.

    ``lower_contents``: the engine's, with the lowered centre of mass; ``room`` and ``lock_casters``: its
    chance of overturning (low: an item whose overturning is not low is not given room) and
    ``risk_pf_moderate``, the chance that the sliding exceeds ``demand_room_cm``; ``restrain``: its chance of
    overturning and 0 (held against sliding, assuming it holds); anchor and tether (:data:`HELD_KINDS`): 0 and
    0, assuming they hold; ``none``: unchanged.

    >>> residual_chances("room", {"p_overturn": 0.0, "p_beyond_clearance": 0.4}, None, Settings(risk_pf_moderate=0.1))
    (0.0, 0.1)
    """
    if kind == "lower_contents":
        return lowered.p_overturn, lowered.p_beyond_clearance
    if kind in ("room", "lock_casters"):
        return float(row["p_overturn"]), min(settings.risk_pf_moderate, float(row["p_beyond_clearance"]))
    if kind in HELD_KINDS:
        return 0.0, 0.0
    if kind == "restrain":
        return float(row["p_overturn"]), 0.0
    return float(row["p_overturn"]), float(row["p_beyond_clearance"])


def decide_action(item, row: dict, uplift: bool, lowered: LoweredDemand | None, settings: Settings) -> ActionDecision:
    """The action of one freestanding item (:class:`ActionDecision`; ``row``: its governing demand with
    ``risk`` and ``clearance_cm``; ``lowered``: its demand in the lowered-contents run, or None): the one a
    code prescribes for its kind of equipment (:func:`assess.decision.code_governed.code_rule`) where one
    does, else the analysis's (:func:`choose_action`)."""
    casters = bool(getattr(item, "casters", False))
    contents = str(getattr(item, "contents", "") or DEFAULT_CONTENTS)
    analysis = choose_action(row, uplift, casters, lowered, settings, contents)
    code = code_rule(item)
    kind = ActionKind(code.action) if code is not None else analysis
    p_overturn_after, p_beyond_after = residual_chances(kind, row, lowered, settings)
    return ActionDecision(kind, p_overturn_after, p_beyond_after, uplift=bool(uplift), casters=casters,
                          lowered=lowered, room_to_gain_cm=room_to_gain_cm(row), mode=action_mode(row, settings),
                          contents=contents, code=code, analysis_kind=analysis,
                          type_source=str(getattr(item, "type_source", "") or "default"),
                          connections=item_connections(item),
                          connections_assumed=bool(getattr(item, "connections_assumed", False)))


# ---------------------------------------------------------------- the what-if run: heavy contents low

def lowered_contents_items(equipment: pd.DataFrame, rows: dict, uplift: dict, settings: Settings) -> list:
    """The items whose heavy contents the what-if moves low: freestanding items whose ``contents`` are
    movable, that overturn or rock (``rows``: id -> governing demand; ``uplift``: id -> whether it rocks) and
    whose centre of mass is above ``lower_contents_cg_fraction`` of their height (by more than 1 cm), in item
    order."""
    fraction = settings.lower_contents_cg_fraction
    chosen = []
    for item in equipment[~equipment["anchored"]].itertuples(index=False):
        if item.id not in rows or str(getattr(item, "contents", "") or DEFAULT_CONTENTS) != "movable":
            continue
        moves = float(rows[item.id]["p_overturn"]) > 0.0 or bool(uplift[item.id])
        if moves and float(item.cg_height_m) > fraction * float(item.height_m) + 0.01:
            chosen.append(item.id)
    return chosen


def lowered_rows(equipment: pd.DataFrame, rows: dict, uplift: dict, settings: Settings) -> dict:
    """id -> :class:`LoweredDemand`, what :func:`decide_action` reads of the lowered-contents run
    (``rows``/``uplift`` of that run, :class:`assess.assessment.demand.ItemDemand`)."""
    fraction = settings.lower_contents_cg_fraction
    heights = equipment.set_index("id")["height_m"]
    return {item_id: LoweredDemand(float(row["p_overturn"]), float(row["p_beyond_clearance"]), bool(uplift[item_id]),
                                   float(row["theta_max_over_alpha"]), fraction,
                                   fraction * float(heights[item_id]) * CM_PER_M)
            for item_id, row in rows.items()}


# ---------------------------------------------------------------- work orders

#: Columns of work_orders.csv (docs/outputs.md).
WORK_ORDER_COLUMNS = ["floor", "floor_label", "room", "action", "items", "names", "count", "detail", "reference",
                      "connection_detail", "connection_reference", "force_kn", "unit_cost", "total_cost"]


def _joined(values) -> str:
    """The distinct non-empty texts of ``values``, in order, joined by "; "."""
    seen = []
    for value in values:
        if isinstance(value, str) and value and value not in seen:
            seen.append(value)
    return "; ".join(seen)


def work_orders(summary: pd.DataFrame, numbering: str = "ground_0") -> pd.DataFrame:
    """One row per floor, room, action and detail (:data:`WORK_ORDER_COLUMNS`): ``floor`` the workbook's
    number, ``floor_label`` as the report labels it (``numbering``: :func:`assess.quantity_text.floor_text`),
    ``items`` the ids and ``names`` their names (in id order), ``count`` the units (``quantity`` summed),
    ``detail`` and ``reference`` what a code prescribes (``action_detail``, ``action_reference``; empty where
    the analysis chose the action), ``connection_detail`` and ``connection_reference`` the flexible
    connections of their gas or fluid lines (empty without), ``force_kn`` the largest design force F_p per unit among
    them (the force the anchor, tether, strap, chain or restraint resists; ``anchor_force_kn``), ``total_cost`` Σ
    ``mitigation_cost`` × ``quantity`` (empty where an item has no cost) and ``unit_cost`` that over
    ``count``. Items that need no action and anchored items are left out unless their gas or fluid lines need
    flexible connections (their order's ``action`` is then ``none`` or ``anchored``: the connections are the
    work), and so is a row without a known action kind. Ordered by floor, room, then :data:`ACTION_KINDS`."""
    kinds = summary["action_kind"] if "action_kind" in summary else pd.Series("", index=summary.index)
    lines = (summary["connection_detail"] if "connection_detail" in summary
             else pd.Series("", index=summary.index)).map(
        lambda value: bool(value) if isinstance(value, str) else False)
    acts = summary[kinds.isin([k for k in ACTION_KINDS if k not in ("none", "anchored")])
                   | (kinds.isin(["none", "anchored"]) & lines)]  # their lines' flexible connections, at least
    if not len(acts):
        return pd.DataFrame(columns=WORK_ORDER_COLUMNS)
    def column(name, default):
        return acts[name] if name in acts else pd.Series(default, index=acts.index)

    def text(name):
        return column(name, "").map(lambda value: value if isinstance(value, str) else "")
    cost = pd.to_numeric(column("mitigation_cost", np.nan), errors="coerce") * acts["quantity"]
    acts = acts.assign(room=acts["room"].fillna("").astype(str), _order=acts["action_kind"].map(ACTION_KINDS.index),
                       id=acts["id"].astype(str), _detail=text("action_detail"),
                       _reference=text("action_reference"), _lines=text("connection_detail"),
                       _lines_reference=text("connection_reference"), _cost=cost,
                       _force=pd.to_numeric(column("anchor_force_kn", np.nan), errors="coerce"),
                       _name=text("name"))
    grouped = acts.sort_values("id", kind="stable").groupby(
        ["floor", "room", "_order", "action_kind", "_detail", "_lines"], sort=True)
    table = grouped.agg(items=("id", lambda ids: ", ".join(ids)),
                        names=("_name", lambda names: "; ".join(name for name in names if name)),
                        count=("quantity", "sum"), reference=("_reference", _joined),
                        connection_reference=("_lines_reference", _joined),
                        force_kn=("_force", "max"),
                        total_cost=("_cost", lambda costs: costs.sum() if costs.notna().all() else np.nan)
                        ).reset_index()
    table = table.rename(columns={"action_kind": "action", "_detail": "detail", "_lines": "connection_detail"})
    table["floor"] = table["floor"].astype(int)
    table["count"] = table["count"].astype(int)
    table["unit_cost"] = table["total_cost"] / table["count"]
    table["floor_label"] = [floor_text(f, numbering) for f in table["floor"]]
    return table[WORK_ORDER_COLUMNS].reset_index(drop=True)
