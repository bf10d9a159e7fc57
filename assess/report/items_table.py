"""The all-items table's shared words: what every row would repeat, said once above the table.

A building report's items take their demand from the same few suites (one per floor: the ground suite on
the ground floor, passed through the building above it), and the paper's regression applies to none of
them for the same reason (a floor motion has no clear pulse). Said in every row, these words filled the
narrow "Demand from", "Regression" and "Action" columns many lines deep, three to five items to a page.
Here they are said once, from the result's own fields:

* :func:`demand_from`: where every item's demand comes from, once (for every item, or by floor where each
  floor has one source), and the column kept only for what differs item by item;
* :func:`regression_words`: why the regression does not apply, in short words explained once, the reason
  every item shares said in the note instead of in each row;
* :func:`table_action`: a code-prescribed action's head, its two standard remarks as short tags explained
  in the column note (:data:`ACTION_TAGS`).

Nothing here computes a number: the words come from the summary's ``demand_source``, ``suite_motions``,
``suite_histories``, ``floor``, ``regression_note``, ``action`` and ``type_source``.
"""
from __future__ import annotations

import pandas as pd
from markupsafe import Markup

from assess.fragility.governing import NO_PULSE_WORDS, OUTSIDE_WORDS, UPLIFT_WORDS
from assess.fragility.suite import PULSE_SHARE_MIN
from assess.quantity_text import floor_text, floors_text
from assess.report.advice import CODE_REQUIRED
from assess.report.sentences import DASH, finite, list_text, suite_text, text

#: The short word of each reason why the regression does not apply, by the words of the item's
#: ``regression_note`` (:func:`assess.fragility.governing.regression_note`) that give it, and what it means.
REGRESSION_SHORT = (
    (NO_PULSE_WORDS, "no pulse", "its governing motion has no clear pulse, none carrying at least "
                                 f"{PULSE_SHARE_MIN * 100:g} % of PTA"),
    (OUTSIDE_WORDS, "IM", "its IM is outside the range the regression was fitted on, {im_min}–{im_max}"),
    (UPLIFT_WORDS, "uplift", "it uplifts"),
)

#: The tags under a code-prescribed action in the table, and what the column's note says of each.
ACTION_TAGS = {
    "code": "a code requires the action whatever the analysis says; its detail and reference are in the work "
            "orders and Appendix A",
    "kind from name": "its kind was read from its name; confirm it, or give its component_type in the workbook",
}


def _analysed(summary: pd.DataFrame) -> pd.Series:
    """Which items the table shows numbers for: every item but the anchored ones."""
    return summary["risk"].astype(str) != "anchored"


def demand_from(summary: pd.DataFrame, numbering: str = "ground_0") -> dict:
    """Where the items' demand comes from, said once where the rows would all repeat it.

    Returns ``sentence`` (for the table's lead) and ``column``: ``None`` where the sentence says it all (one
    source and suite for every analysed item, or one per floor: the Floor column then tells each item's),
    ``"suite"`` where every item has the same source but not the same motions (the column keeps those),
    ``"full"`` otherwise (the column as it is: the source and the motions of each item).

    >>> one = pd.DataFrame({"risk": ["high", "low", "anchored"], "floor": [1, 2, 2],
    ...                     "demand_source": [("records",), ("records",), ()], "suite_motions": [7, 7, None]})
    >>> demand_from(one)
    {'sentence': 'Where it comes from, for every item: records (7 motions).', 'column': None}
    >>> by_floor = one.assign(demand_source=[("records",), ("records through the building",), ()])
    >>> demand_from(by_floor)["sentence"]  # doctest: +NORMALIZE_WHITESPACE
    'Where it comes from, by floor: records (7 motions) on floor 1; records through the building (7 motions)
    on floor 2.'
    >>> demand_from(one.assign(floor=[2, 2, 2], suite_motions=[7, 5, None]))  # doctest: +NORMALIZE_WHITESPACE
    {'sentence': 'Where it comes from, for every item: records; “Demand from” gives its motions and histories.',
    'column': 'suite'}
    >>> demand_from(one.assign(floor=[2, 2, 2], demand_source=[("records",), ("regression",), ()]))["column"]
    'full'
    """
    free = summary[_analysed(summary)]
    sources = [list_text(value, " + ") for value in free.get("demand_source", pd.Series(dtype=object))]
    suites = [suite_text(row) for _, row in free.iterrows()]
    floors = [finite(value) for value in free.get("floor", pd.Series([None] * len(free), dtype=object))]
    full = {"sentence": "“Demand from” says which model gives it and for how many motions and histories.",
            "column": "full"}
    if not sources or any(not source for source in sources):
        return full
    groups: dict[tuple[str, str], set] = {}
    for source, suite, floor in zip(sources, suites, floors):
        groups.setdefault((source, suite), set()).add(floor)
    groups = dict(sorted(groups.items(), key=lambda group: min((f for f in group[1] if f is not None),
                                                                default=float("inf"))))  # lowest floor first
    said = [f"{source} ({suite})" if suite else source for source, suite in groups]
    if len(groups) == 1:
        return {"sentence": f"Where it comes from, for every item: {said[0]}.", "column": None}
    every_floor = [floor for members in groups.values() for floor in members]
    if None not in every_floor and len(every_floor) == len(set(every_floor)):  # each floor has one source
        by_floor = "; ".join(f"{words} on {floors_text(members, numbering)}"
                             for words, members in zip(said, groups.values()))
        return {"sentence": f"Where it comes from, by floor: {by_floor}.", "column": None}
    if len(set(sources)) == 1:
        return {"sentence": f"Where it comes from, for every item: {sources[0]}; “Demand from” gives its motions "
                            "and histories.", "column": "suite"}
    return full


def _reasons(note) -> list[str]:
    """The short words of why the regression does not apply to an item, from its ``regression_note``."""
    note = text(note)
    return [short for words, short, _ in REGRESSION_SHORT if words in note]


def regression_words(summary: pd.DataFrame, im_range: tuple) -> dict:
    """Why the paper's regression does not apply, in short words: ``reasons`` per item (in the summary's
    order; a reason that every item it does not apply to shares, where there are two or more, left out) and ``note``,
    the sentence of the column's note that explains the words and says the shared reasons once.

    >>> table = pd.DataFrame({"risk": ["high", "low", "anchored"], "regression_note": [
    ...     "not applicable: pulse share 0.02 < 0.38 (no clear pulse), IM 9 outside 1.71-6.4, the item uplifts",
    ...     "not applicable: pulse share 0.1 < 0.38 (no clear pulse)", ""]})
    >>> words = regression_words(table, (1.71, 6.4))
    >>> words["reasons"]
    ['IM, uplift', '', '']
    >>> words["note"]  # doctest: +NORMALIZE_WHITESPACE
    Markup('“n/a” where it does not: for every freestanding item here its governing motion has no clear pulse, none
    carrying at least 38 % of PTA; <i>IM</i>: its IM is outside the range the regression was fitted on, 1.71–6.4;
    <i>uplift</i>: it uplifts.')
    """
    free = _analysed(summary)
    reasons = [_reasons(note) for note in summary.get("regression_note", pd.Series([""] * len(summary)))]
    unapplied = [r for r, is_free in zip(reasons, free) if is_free and r]
    shared = [short for _, short, _ in REGRESSION_SHORT  # said once where two or more rows would repeat it
              if len(unapplied) >= 2 and all(short in r for r in unapplied)]
    shown = {short for r in unapplied for short in r if short not in shared}
    im_min, im_max = (f"{value:g}" for value in im_range)
    meaning = {short: words.format(im_min=im_min, im_max=im_max) for _, short, words in REGRESSION_SHORT}
    every = "every freestanding item here" if len(unapplied) == int(free.sum()) else "every item marked n/a here"
    parts = [f"for {every} {meaning[short]}" for short in shared]
    parts += [_term(short, meaning[short]) for _, short, _ in REGRESSION_SHORT if short in shown]
    note = Markup("“n/a” where it does not") + (Markup(": ") + Markup("; ").join(parts) if parts else "") + "."
    return {"reasons": [", ".join(short for short in r if short not in shared) for r in reasons], "note": note}


def table_action(action: str, type_source: str = "", head: str = "") -> dict:
    """An item's action as the table shows it: ``head`` and ``tags`` (:data:`ACTION_TAGS`) for a
    code-prescribed action, whose detail and reference the work orders and Appendix A give; the analysis's
    action by its sentence's ``head`` where one is given (:func:`assess.report.advice.decision_head`: what
    to do, and the room it needs where sliding decided it; ``short`` where that leaves words out); else the
    action whole, with no tags.

    >>> table_action("Chain it (gas cylinders: required whatever the analysis says): each cylinder chained. "
    ...              "Reference: NFPA 99 (2021) ch. 11.", "name")
    {'head': 'Chain it (gas cylinders)', 'tags': 'code, kind from name', 'short': False}
    >>> table_action("Give it room: it needs 18 cm to be low risk and has 10 cm.", head="Give it room: it needs 18 cm")
    {'head': 'Give it room: it needs 18 cm', 'tags': '', 'short': True}
    >>> table_action("Give it room: it needs 18 cm.")
    {'head': 'Give it room: it needs 18 cm.', 'tags': '', 'short': False}
    """
    start, required, _ = action.partition(CODE_REQUIRED)
    if not required:
        if head and action.startswith(head):  # the sentence's own start: the table never says other words
            return {"head": head, "tags": "", "short": head != action}
        return {"head": action or DASH, "tags": "", "short": False}
    tags = ["code"] + (["kind from name"] if type_source == "name" else [])
    return {"head": f"{start})", "tags": ", ".join(tags), "short": False}


#: The column note's sentence where the table shows an analysis's action by its head (``short``).
SHORT_ACTIONS = ("Action: what to do, with the room the item needs where sliding decided it; why, with its "
                 "numbers, is in the work orders and Appendix A.")


def action_note(actions: list[dict]) -> str:
    """The column note's sentences on the table's actions: that an action shown by its head is whole in the
    work orders and Appendix A (where one is, :data:`SHORT_ACTIONS`), and the tags they carry ("" where
    neither).

    >>> action_note([{"tags": "code", "short": False}, {"tags": "", "short": False}])  # doctest: +NORMALIZE_WHITESPACE
    Markup('Action, under it: <i>code</i>: a code requires the action whatever the analysis says; its detail and
    reference are in the work orders and Appendix A.')
    >>> action_note([{"tags": "", "short": True}])  # doctest: +NORMALIZE_WHITESPACE
    Markup('Action: what to do, with the room the item needs where sliding decided it; why, with its numbers, is in the
    work orders and Appendix A.')
    """
    used = {tag for action in actions for tag in action["tags"].split(", ") if tag}
    said = [_term(tag, meaning) for tag, meaning in ACTION_TAGS.items() if tag in used]
    short = Markup(SHORT_ACTIONS) if any(action.get("short") for action in actions) else Markup("")
    tags = Markup("Action, under it: ") + Markup("; ").join(said) + "." if said else Markup("")
    return Markup(" ").join(part for part in (short, tags) if part)


def _term(word: str, meaning: str) -> Markup:
    """A short word of the table in italics, and what it means (both escaped)."""
    return Markup("<i>{}</i>: {}").format(word, meaning)
