"""The advice as a reader sees it: each item's action, what-if, why it is in its class, its anchorage's basis
and US forces, its cost note, and the work orders, in the report's units.

The decisions stage (:mod:`assess.decision`) gives numbers and kinds in SI
(:class:`~assess.decision.decisions.ItemDecision`, the cost stage's
:class:`~assess.decision.costs.CostNote`); every sentence of the advice is made here from them, lengths,
forces and moments through :mod:`assess.quantity_text` (pint's conversions), so that the same numbers give
the same words in ``summary.csv``, ``summary.xlsx`` and the report. :func:`with_words` adds the summary's
columns that are words (:data:`WORD_COLUMNS`) to a result; the command applies it to every result it writes.
"""
from __future__ import annotations

import dataclasses
import math

import pandas as pd

from assess.anchorage.design import in_us_units
from assess.assessment.result import SUMMARY_COLUMNS, WORD_COLUMNS, AssessmentResult
from assess.decision.actions import ActionKind, LoweredDemand, room_to_gain_cm
from assess.decision.costs import CostNote  # noqa: F401 (the doctests)
from assess.decision.risk_classes import CLASS_ORDER, MODE_WORDS, Chances, mode_classes, rocking_harm_counts
from assess.inventory.settings import Settings
from assess.quantity_text import force_text, length_text, moment_text, percent_text, system_of

#: What a work order asks for, by action kind (work_orders.csv and the report's work orders).
WORK_ORDER_TEXT = {
    "anchor": "anchor to the floor or wall",
    "tether": "tether or strap to the wall (on casters)",
    "strap": "strap to the wall (top and bottom thirds)",
    "chain": "chain each cylinder to the wall or a fastened rack",
    "lower_contents": "move heavy contents to the lowest shelves or drawers",
    "restrain": "restrain (edge stops, bumpers or straps)",
    "lock_casters": "lock or chock the casters and keep room clear (each item's in its details)",
    "room": "give room (each item's in its details)",
    "relocate": "relocate",
    "none": "no restraint needed, only the lines",  # an order for the flexible connections alone
    "anchored": "already anchored, only the lines",
}
#: What an anchored item's words say (it is not analysed as freestanding).
ANCHORED_WORDS = {"action": "None: anchored (not analysed as freestanding)",
                  "risk_reason": "anchored: not analysed as freestanding", "what_if": math.nan}


def _plural(count: int, word: str) -> str:
    return f"{count} {word}{'' if count == 1 else 's'}"


def suite_share_text(probability: float, row) -> str:
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


# ---------------------------------------------------------------- the action and its what-if

def _rocking_text(row: dict) -> str:
    return (f"it uplifts and rocks (peak rotation {float(row['theta_max_over_alpha']):.2f} of its overturning "
            f"angle alpha) but did not overturn under its {_plural(int(row['suite_motions']), 'motion')}")


def _why_overturn_or_rock(row: dict) -> str:
    if float(row["p_overturn"]) > 0.0:
        return f"it overturns under {suite_share_text(float(row['p_overturn']), row)}"
    return _rocking_text(row)


def _why(row, mode: str, system: str, settings: Settings) -> str:
    """Why an item is held: it overturns or rocks (``mode`` overturn or rocking_harm), or it slides farther
    than a room can spare."""
    if mode in ("overturn", "rocking_harm"):
        return _why_overturn_or_rock(row)
    return f"{_room_numbers(row, system)}: {_more_than_spare(row, system, settings)}"


#: Why moving the contents low is not offered, by ``contents``.
_NOT_LOWERED = {"fixed": "its contents are fixed", "none": "it has no contents to move"}


def _lowering_clause(row, lowered: LoweredDemand | None, contents: str, system: str) -> str:
    """Why moving its contents low is not the action: its contents cannot move, or the engine's what-if."""
    if contents in _NOT_LOWERED:
        return f" Moving its contents low is not offered: {_NOT_LOWERED[contents]}."
    if lowered is not None:
        return f" Lowering its contents alone is not enough. {_lowered_text(row, lowered, system)}."
    return ""


def _more_than_spare(row: dict, system: str, settings: Settings) -> str:
    return (f"{length_text(room_to_gain_cm(row), system, 'up')} more, beyond the "
            f"{length_text(settings.room_max_cm, system)} a room can spare")


def _room_numbers(row: dict, system: str) -> str:
    return (f"it needs {length_text(row['demand_room_cm'], system, 'up')} to be low risk and has "
            f"{length_text(row['clearance_cm'], system, 'down')} ({percent_text(row['p_beyond_clearance'])} chance "
            "of sliding past it)")


def _lowered_text(row, lowered: LoweredDemand, system: str) -> str:
    """What the engine gives with the heavy contents low, in one clause."""
    rocks = "it still rocks" if lowered.uplift else "it no longer rocks"
    return (f"With its heavy contents moved low (centre of mass at {float(lowered.cg_fraction):.0%} of its "
            f"height, {length_text(lowered.cg_height_cm, system)} instead of "
            f"{length_text(row['cg_height_cm'], system)}) the engine gives overturning "
            f"{percent_text(lowered.p_overturn)} (as loaded {percent_text(row['p_overturn'])}) and sliding past "
            f"its room {percent_text(lowered.p_beyond_clearance)} (as loaded "
            f"{percent_text(row['p_beyond_clearance'])}), and {rocks}, under the same motions")


#: The head of an action's sentence (:func:`action_sentence`), by kind, before why and its numbers; a table
#: of many items shows the head alone, with the room the item needs where sliding decided it (:func:`action_head`).
ACTION_HEADS = {
    "anchor": "Anchor it to the floor or wall",
    "tether": "Tether or strap it to the wall (it stands on casters)",
    "lower_contents": "Move its heavy contents to the lowest shelves or drawers",
    "restrain": "Restrain it against sliding (edge stops, bumpers or cable restraints)",
    "room": "Give it room",
}


def _lock_casters_head(row, system: str) -> str:
    return f"Lock or chock its casters and keep {length_text(row['demand_room_cm'], system, 'up')} clear around it"


def _decided_by(row, mode: str, uplift: bool = False) -> str:
    """The failure that decided an action: ``mode`` where given (:func:`assess.decision.actions.action_mode`),
    else overturning where the item overturns (or ``uplift``: it rocks), else sliding past its room."""
    return mode or ("overturn" if float(row["p_overturn"]) > 0.0 or uplift else "beyond_clearance")


def action_head(kind: str, row, settings: Settings, mode: str = "", uplift: bool = False) -> str:
    """The head of the action's sentence (:func:`action_sentence`, of which it is the start), and where sliding
    past its room decided the action (``mode`` ``beyond_clearance``; room and a restraint always) the room the item
    needs; "" for a kind with no sentence of its own (anchored, a code's; "No action needed" for none).

    >>> row = {"demand_room_cm": 107.2, "clearance_cm": 25.0, "p_beyond_clearance": 0.98, "p_overturn": 0.0}
    >>> action_head("restrain", row, Settings(), "beyond_clearance")
    'Restrain it against sliding (edge stops, bumpers or cable restraints): it needs 108 cm'
    >>> action_head("anchor", row, Settings(), "overturn"), action_head("none", row, Settings())
    ('Anchor it to the floor or wall', 'No action needed')
    """
    system = system_of(settings)
    mode = _decided_by(row, mode, uplift)
    if kind == "lock_casters":
        return _lock_casters_head(row, system)
    if kind == "none":
        return "No action needed"
    head = ACTION_HEADS.get(kind, "")
    if kind in ("room", "restrain") or (kind == "tether" and mode == "beyond_clearance"):
        return f"{head}: it needs {length_text(row['demand_room_cm'], system, 'up')}"
    return head


def decision_head(decision, settings: Settings) -> str:
    """:func:`action_head` of one item's :class:`~assess.decision.decisions.ItemDecision` ("" where a code
    prescribes its action or it is anchored: their sentences have heads of their own)."""
    action = decision.action
    if action.kind == ActionKind.ANCHORED or action.code is not None:
        return ""
    return action_head(action.kind, decision.demand, settings, action.mode, action.uplift)


def action_sentence(kind: str, row, uplift: bool, lowered: LoweredDemand | None, settings: Settings,
                    mode: str = "") -> str:
    """A plain sentence a facility manager can act on, for the action ``kind``
    (:func:`assess.decision.actions.choose_action`) and the failure that decided it (``mode``:
    :func:`assess.decision.actions.action_mode`; "" read as overturning where it overturns or rocks)."""
    system = system_of(settings)
    mode = _decided_by(row, mode, uplift)
    if kind == "anchor":
        return f"{ACTION_HEADS['anchor']}: {_why_overturn_or_rock(row)}"
    if kind == "tether":
        return f"{ACTION_HEADS['tether']}: {_why(row, mode, system, settings)}"
    if kind == "lower_contents":
        return (f"{ACTION_HEADS['lower_contents']}: as loaded {_why_overturn_or_rock(row)}; with its "
                f"centre of mass at {float(lowered.cg_fraction):.0%} of its height the engine finds it still "
                "under the same motions")
    if kind == "lock_casters":
        return f"{_lock_casters_head(row, system)}: {_room_numbers(row, system)}"
    if kind == "room":
        return f"{ACTION_HEADS['room']}: {_room_numbers(row, system)}"
    if kind == "restrain":
        return (f"{ACTION_HEADS['restrain']}: {_room_numbers(row, system)}: "
                f"{_more_than_spare(row, system, settings)}")
    return "No action needed"


def _overturn_stays(row) -> str:
    return (f"its chance of overturning stays {percent_text(float(row['p_overturn']))}, low on its own, "
            "so anchoring is not needed")


def what_if_sentence(kind: str, row, lowered: LoweredDemand | None, settings: Settings, mode: str = "",
                     contents: str = "movable") -> str:
    """The item's risk if the action is taken, from its own numbers or the engine's what-if run, and why
    not the next action (``mode``: the failure that decided it; ``contents``: what its contents can do)."""
    system = system_of(settings)
    mode = _decided_by(row, mode)
    lowering = "" if kind == "lower_contents" else _lowering_clause(row, lowered, contents, system)
    if kind == "anchor":
        return ("Anchored (assumed to hold), it would neither slide nor overturn: 0% for both. Room or a "
                "restraint against sliding would not do: it overturns or rocks where it stands." + lowering)
    if kind == "tether":
        if mode == "beyond_clearance":
            return ("Tethered to the structure (assumed to hold), it would neither roll away nor overturn: "
                    f"0% for both. Locking its casters would not do: it needs "
                    f"{_more_than_spare(row, system, settings)} (setting room_max_cm).")
        return ("Tethered to the structure (assumed to hold), it would neither roll away nor overturn: "
                "0% for both." + lowering)
    if kind == "lower_contents":
        return (f"{_lowered_text(row, lowered, system)}. Anchoring it would also do, at 0% for both "
                "(assumed to hold).")
    if kind == "restrain":
        return ("Restrained against sliding (assumed to hold), it would not slide past its room: 0%; "
                f"{_overturn_stays(row)}. Room would not do: it needs "
                f"{_more_than_spare(row, system, settings)} (setting room_max_cm).")
    if kind == "room" or kind == "lock_casters":
        locked = (" Its sliding was computed with the workbook's mu, taken as that of its casters locked: if they "
                  "are not, tether it." if kind == "lock_casters" else "")
        return (f"Given {length_text(row['demand_room_cm'], system, 'up')} of room (it has "
                f"{length_text(row['clearance_cm'], system, 'down')}), its chance of sliding past it would be "
                f"{percent_text(settings.risk_pf_moderate)}: low risk; {_overturn_stays(row)}.{locked}")
    return ""


#: What a code-prescribed action is called at the head of its sentence, by kind.
CODE_VERBS = {"strap": "Strap it", "chain": "Chain it", "anchor": "Anchor it", "tether": "Tether it",
              "restrain": "Restrain it"}
#: The analysis's own action in a few words, by kind, for a code-prescribed item's what-if.
ANALYSIS_WORDS = {"anchor": "anchor it", "tether": "tether it", "lower_contents": "move its heavy contents low",
                  "restrain": "restrain it against sliding", "lock_casters": "lock its casters and keep room clear",
                  "room": "give it room", "none": "no action", "relocate": "relocate it"}


#: What closes the head of a code-prescribed action's sentence, before its detail (:func:`brief_action`).
CODE_REQUIRED = ": required whatever the analysis says)"


def brief_action(action: str, type_source: str = "") -> str:
    """An item's action for the tables that list many items (what to do first, all items): a code-prescribed
    action's head, the detail and its reference left to the work orders and Appendix A (they fill a narrow
    column many lines deep), its kind read from the name said; any other action whole.

    >>> brief_action("Chain it (gas cylinders: required whatever the analysis says): each cylinder chained. "
    ...              "Reference: NFPA 99 (2021) ch. 11. Its kind (gas cylinders) was read ...",
    ...              "name")  # doctest: +NORMALIZE_WHITESPACE
    'Chain it (gas cylinders: required whatever the analysis says): the detail and its reference are in the work orders
    and Appendix A; its kind was read from its name: confirm it.'
    >>> brief_action("Give it room: it needs 18 cm.")
    'Give it room: it needs 18 cm.'
    """
    head, required, _ = action.partition(CODE_REQUIRED)
    if not required:
        return action
    read = "; its kind was read from its name: confirm it" if type_source == "name" else ""
    return f"{head}{required}: the detail and its reference are in the work orders and Appendix A{read}."


def code_sentences(action, row, settings: Settings) -> tuple[str, str]:
    """The action and what-if of an item whose action a code prescribes (``action.code``:
    :class:`~assess.decision.code_governed.CodeRule`): the detail with its reference, and what the analysis
    alone finds and would do (its own numbers are the item's as ever)."""
    code = action.code
    action_text = (f"{CODE_VERBS.get(action.kind.value, action.kind.value.capitalize())} ({code.equipment}"
                   f"{CODE_REQUIRED}: {code.detail}. Reference: {code.reference}")
    analysis = ANALYSIS_WORDS.get(action.analysis_kind.value, action.analysis_kind.value)
    if action.analysis_kind.value == "none":
        alone = "the analysis alone asks for no action (it is low risk in this earthquake)"
    else:
        sentence = action_sentence(action.analysis_kind.value, row, action.uplift, action.lowered, settings,
                                   action.mode)
        alone = f"the analysis alone would {analysis}: {sentence.split(': ', 1)[-1]}"
    if action.type_source == "name":
        action_text += (f". Its kind ({code.equipment}) was read from its name: confirm it, or write its "
                        "component_type in the workbook.")
    what_if = (f"Restrained as the code asks (assumed to hold), it would neither slide nor overturn: 0% for both; "
               f"{alone}.")
    return action_text, what_if


#: A line in words, by connection (assess/data/connections.csv).
LINE_WORDS = {"gas": "gas line", "fluid": "water or fluid lines"}


def connection_sentence(action) -> str:
    """What the item's lines take beside its action (``action``:
    :class:`~assess.decision.actions.ActionDecision`): each line's flexible connection and its reference, and
    where the lines were not written, that they follow from its kind (read from its name where it was); ""
    without lines.

    >>> from assess.decision.actions import ActionDecision, ActionKind
    >>> connection_sentence(ActionDecision(ActionKind.NONE, 0.0, 0.0, connections=("gas",))).split(" between")[0]
    'Its gas line: a flexible connector (braided or corrugated)'
    """
    rules = action.connection_rules()
    if not rules:
        return ""
    references = "; ".join(dict.fromkeys(rule.reference for rule in rules))
    text = " ".join(f"Its {LINE_WORDS.get(rule.connection, rule.connection)}: {rule.detail}." for rule in rules)
    text = f"{text[:-1]} (Reference: {references})."
    if action.connections_assumed:
        read = " (read from its name)" if action.type_source == "name" else ""
        text += (f" Its {' and '.join(LINE_WORDS.get(r.connection, r.connection) for r in rules)} are assumed from "
                 f"its kind{read}: write connections in the workbook if it has other lines or none.")
    return text


def _with_lines(text: str, action) -> str:
    """``text`` (an action sentence) with its lines' flexible connections after it (:func:`connection_sentence`)."""
    lines = connection_sentence(action)
    if not lines:
        return text
    return f"{str(text).rstrip('.')}. {lines}"


# ---------------------------------------------------------------- why the item is in its class

def _threshold_text(mode: str, risk: str, settings: Settings) -> str:
    key = {"overturn": "risk_overturn", "beyond_clearance": "risk_pf", "rocking_harm": "risk_rocking"}[mode]
    return f"{100.0 * getattr(settings, f'{key}_{risk}'):g}%"  # a threshold as given: 2.5%, not rounded


def risk_reason(chances: Chances, consequence: str, settings: Settings) -> str:
    """Why the item is in its class (:func:`assess.decision.risk_classes.classify_risk`), in one sentence from
    its chances and the thresholds.

    >>> s = Settings(risk_overturn_high=0.1, risk_overturn_moderate=0.025, risk_pf_high=0.5,
    ...              risk_pf_moderate=0.1, risk_rocking_moderate=0.1)
    >>> risk_reason(Chances(0.39, 0.0, 0.2), "hazardous", s)
    'high: 39% chance of overturning (high from 10%)'
    >>> risk_reason(Chances(0.0, 0.03, 0.6), "ordinary", s)  # doctest: +NORMALIZE_WHITESPACE
    'low: 0% chance of overturning, 3% of sliding past its room, each below its threshold (moderate from 2.5% and 10%);
    rocking that harms it (60%) does not count for an ordinary item'
    """
    classes = mode_classes(chances, consequence, settings)
    risk = max(classes.values(), key=CLASS_ORDER.index)
    values = {"overturn": chances.overturn, "beyond_clearance": chances.beyond_clearance,
              "rocking_harm": chances.rocking_harm}
    if risk != "low":
        parts = [f"{percent_text(values[mode])} chance of {MODE_WORDS[mode]} ({risk} from "
                 f"{_threshold_text(mode, risk, settings)})" for mode in MODE_WORDS if classes[mode] == risk]
        return f"{risk}: " + "; ".join(parts)
    counted = [mode for mode in MODE_WORDS if mode != "rocking_harm" or rocking_harm_counts(consequence)]
    listed = ", ".join(f"{percent_text(values[mode])}{' chance' if k == 0 else ''} of {MODE_WORDS[mode]}"
                       for k, mode in enumerate(counted))
    thresholds = " and ".join(_threshold_text(mode, "moderate", settings) for mode in counted)
    text = f"low: {listed}, each below its threshold (moderate from {thresholds})"
    if not rocking_harm_counts(consequence):
        text += (f"; rocking that harms it ({percent_text(chances.rocking_harm)}) does not count for an "
                 "ordinary item")
    return text


# ---------------------------------------------------------------- the anchorage in words and US units

def anchorage_sentence(row, system="si") -> str:
    """What the report says about an item's anchorage, from its summary row (``row``: a mapping with the
    :data:`COLUMNS`), forces in SI or US units (:mod:`assess.quantity_text`); "" without a force.

    >>> anchorage_sentence({"anchor_force_kn": 4.0, "anchor_moment_knm": 4.8, "anchor_tension_kn": 1.2,
    ...                     "anchor_omega0": 2.0, "anchor_shear_omega_kn": 8.0,
    ...                     "anchor_tension_omega_kn": 5.2})  # doctest: +NORMALIZE_WHITESPACE
    'design force F_p 4 kN per unit at its centre of mass; overturning moment 4.8 kN·m and uplift (tension) 1.2 kN on
    the far edge of its narrower base; anchors in concrete, with Omega_0 2: shear 8 kN, tension 5.2 kN'
    """
    force = row.get("anchor_force_kn")
    if force is None or not math.isfinite(float(force)):
        return ""
    text = (f"design force F_p {force_text(force, system)} per unit at its centre of mass; overturning moment "
            f"{moment_text(row.get('anchor_moment_knm'), system)} and uplift (tension) "
            f"{force_text(row.get('anchor_tension_kn'), system)} on the far edge of its narrower base")
    omega = row.get("anchor_omega0")
    if omega is not None and math.isfinite(float(omega)) and float(omega) > 1.0:
        text += (f"; anchors in concrete, with Omega_0 {float(omega):g}: shear "
                 f"{force_text(row.get('anchor_shear_omega_kn'), system)}, tension "
                 f"{force_text(row.get('anchor_tension_omega_kn'), system)}")
    return text


#: The summary's US force columns and the field of :func:`assess.anchorage.design.in_us_units` each takes.
US_FORCE_COLUMNS = {"anchor_force_kip": "force_kip", "anchor_tension_kip": "tension_kip",
                    "anchor_shear_omega_kip": "anchor_shear_kip", "anchor_tension_omega_kip": "anchor_tension_kip"}


def anchorage_columns(anchorage, system: str = "si") -> dict:
    """The anchorage columns an item's :class:`~assess.anchorage.ItemAnchorage` gives in words and US units:
    the forces in kip and the moment in kip·ft (pint, :func:`assess.anchorage.design.in_us_units`; NaN
    without a force) and ``anchor_basis``: the factors used with the forces in ``system``'s units, or what
    to add where S_DS is not known ("" where no force is wanted)."""
    out = {column: math.nan for column in (*US_FORCE_COLUMNS, "anchor_moment_kip_ft")}
    out["anchor_basis"] = ""
    if anchorage.missing_sds:
        out["anchor_basis"] = ("add sds_g to the site sheet (or the settings) for the ASCE 7 design force of its "
                               "anchorage")
    forces = anchorage.forces
    if forces is None:
        return out
    us = in_us_units(forces)
    out.update({column: us[name] for column, name in US_FORCE_COLUMNS.items()})
    out["anchor_moment_kip_ft"] = us["overturning_moment_lbf_ft"] / 1000.0
    out["anchor_basis"] = f"{forces.basis(system)}; forces per unit; {anchorage.site.basis}"
    return out


# ---------------------------------------------------------------- what the costs rest on

def cost_note_text(notes, kind: str = "") -> str:
    """The ``cost_note`` of an item: its :class:`~assess.decision.costs.CostNote` s in words, joined by "; "
    (``kind``: its action kind).

    >>> cost_note_text((CostNote("no_cost"), CostNote("no_curve")), "anchor")[:60]
    "no cost for 'anchor': give mitigation_cost or the setting mi"
    """
    if isinstance(notes, str):
        return notes
    if not isinstance(notes, tuple):
        return ""
    words = {
        "no_value": "no value given",
        "anchored": "anchored: not analysed, no loss computed",
        "no_action": "no action recommended",
        "unknown_after": f"what '{kind}' leaves is not known: no loss after it",
        "no_cost": f"no cost for '{kind}': give mitigation_cost or the setting mitigation_cost_{kind}",
        "free": f"'{kind}' costs nothing as given: no ratio",
        "scaled_after": f"annual loss after '{kind}' scaled by the share of the level's loss it leaves",
        "no_curve": "no benefit-cost ratio without a hazard curve (--oq-hazard): the level is one earthquake, "
                    "not how often it happens",
    }
    texts = []
    for note in notes:
        if note.code == "curve_rates":
            texts.append("annual loss from the curve's rates of overturning and sliding past the room"
                         + (f" ({' and '.join(note.bounds)} where the stripes give no central rate)"
                            if note.bounds else "") + ", without rocking harm")
        else:
            texts.append(words[note.code])
    return "; ".join(texts)


# ---------------------------------------------------------------- the summary's words

def item_words(decision, settings: Settings) -> dict:
    """The word and US-unit columns (:data:`WORD_COLUMNS` but ``cost_note``) of one item's
    :class:`~assess.decision.decisions.ItemDecision`, in the units of ``settings`` (``units``)."""
    system = system_of(settings)
    words = anchorage_columns(decision.anchorage, system)
    action = decision.action
    if action.kind == ActionKind.ANCHORED:
        return {**words, **ANCHORED_WORDS, "action": _with_lines(ANCHORED_WORDS["action"], action)}
    row = decision.demand
    if action.code is not None:
        action_text, what_if = code_sentences(action, row, settings)
        return {**words, "action": _with_lines(action_text, action), "what_if": what_if,
                "risk_reason": risk_reason(decision.chances, decision.consequence, settings)}
    return {**words, "action": _with_lines(action_sentence(action.kind, row, action.uplift, action.lowered,
                                                           settings, action.mode), action),
            "what_if": what_if_sentence(action.kind, row, action.lowered, settings, action.mode, action.contents),
            "risk_reason": risk_reason(decision.chances, decision.consequence, settings)}


def with_words(result: AssessmentResult) -> AssessmentResult:
    """``result`` (:class:`~assess.assessment.result.AssessmentResult`) with its summary's columns that are
    words or US forces (:data:`WORD_COLUMNS`) made from each item's decision (``result.decisions``) and cost
    notes, in the units of its settings (``units``), each at its place in
    :data:`~assess.assessment.result.SUMMARY_COLUMNS`; ``result`` itself where they are made already (or it
    holds no decisions)."""
    summary = result.summary
    if "action" in summary.columns or not result.decisions:
        return result
    rows = [item_words(result.decisions[item_id], result.settings) for item_id in summary["id"]]
    out = summary.copy()
    for column in WORD_COLUMNS:
        if column != "cost_note":
            out[column] = [row[column] for row in rows]
    if "cost_note" in out:
        out["cost_note"] = [cost_note_text(notes, kind) for notes, kind in zip(out["cost_note"], out["action_kind"])]
    declared = [column for column in SUMMARY_COLUMNS if column in out]
    out = out[declared + [column for column in out.columns if column not in declared]]
    return dataclasses.replace(result, summary=out)


# ---------------------------------------------------------------- the work orders in words

def _order_sentence(order, system: str, currency: str) -> str:
    """One work order in a sentence: what to do, the items and their names, the code's detail and reference,
    the force to resist and the cost (each where the order has it)."""
    names = f": {order.names}" if getattr(order, "names", "") else ""
    text = (f"{WORK_ORDER_TEXT.get(order.action, order.action)}: {order.items} "
            f"({_plural(int(order.count), 'unit')}{names})")
    if getattr(order, "detail", ""):
        text += f" — {order.detail} ({order.reference})"
    if getattr(order, "connection_detail", ""):
        text += f"; flexible connections — {order.connection_detail} ({order.connection_reference})"
    force = getattr(order, "force_kn", math.nan)
    if force is not None and math.isfinite(float(force)):
        text += f"; force to resist up to {force_text(force, system)} per unit"
    total = getattr(order, "total_cost", math.nan)
    if total is not None and math.isfinite(float(total)):
        unit = f"{currency} " if currency else ""
        text += f"; cost {unit}{float(order.unit_cost):,.0f} per unit, {unit}{float(total):,.0f} in all"
    return text


def work_order_sentences(table: pd.DataFrame, system: str = "si", currency: str = "") -> list[dict]:
    """The report's work orders: per floor, its rooms, each with one sentence per order
    ("anchor to the floor or wall: GAS-G-01 (1 unit: gas cylinder cabinet); force to resist up to 2.3 kN per
    unit"), forces in ``system``'s units and costs in ``currency`` (work_orders.csv, the same)."""
    floors = []
    for floor, on_floor in table.groupby("floor", sort=True):
        rooms = []
        for room, in_room in on_floor.groupby("room", sort=False):
            orders = [_order_sentence(r, system, currency) for r in in_room.itertuples(index=False)]
            rooms.append({"room": room or "(no room given)", "orders": orders})
        floors.append({"floor": int(floor), "units": int(on_floor["count"].sum()), "rooms": rooms})
    return floors
