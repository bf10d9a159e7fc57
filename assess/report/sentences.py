"""What the report says, built from the result: numbers as text, sentences, and the counts a page shows.

The templates only lay these out (:mod:`assess.report.render`). Sentences
that the decisions make for an item (its action, what-if, demand note) are
fields of the result (:mod:`assess.decision.decisions`); what is here turns the result's
fields into the report's words and counts, so that a count a page shows adds up
in a test and is never re-derived in a template.
"""
from __future__ import annotations

import math

import pandas as pd

from assess.assessment.result import RISK_CLASSES, AssessmentResult
from assess.fragility import friction_range, planar
from assess.inventory.settings import Settings
from assess.quantity_text import (  # noqa: F401 (floor labels)
    floor_text, floors_text, length_text, percent_text, rounded_length, significant_text,
)

DASH = "–"

#: Headings for the flag codes the pipeline is known to emit; others get their code.
FLAG_TITLES = {
    "im_outside_fit": "Outside the range the regression was fitted on",
    "uplift": "Uplifts and rocks: the simulation answers",
    "calibrated": "Changed by the calibration",
    "alpha_range": "Risk class moves over the range of the building's α",
    "cg_not_mid_height": "Centre of mass not at mid-height",
    "derived_floor_motion": "Floor motion derived from the ground motion",
    "building_beyond_drift": "Floor motions from the building's model beyond the drift it is trusted to",
    "implausible_input": "Size or density no equipment has: check the workbook cell",
}


def finite(value) -> float | None:
    try:
        number = float(value)
    except (TypeError, ValueError):
        return None
    return number if math.isfinite(number) else None


def format_significant(value, digits: int = 2) -> str:
    """``value`` to ``digits`` significant digits (0.30, 3.38, 12000), never in exponent form nor as a long
    decimal (a float's noise about zero reads "< 0.001"): :func:`assess.quantity_text.significant_text`."""
    return significant_text(value, digits)


def format_cm(value) -> str:
    """A length in cm as an integer; NaN as "–"."""
    number = finite(value)
    if number is None:
        return DASH
    return f"{round(number):d}".replace("-", "−")


def format_length(value_cm, system="si", rounding: str = "nearest") -> str:
    """A length given in cm as a whole number of the report's unit (cm, or in for ``system`` ``'us'``),
    rounded as the advice rounds it (:func:`assess.quantity_text.rounded_length`: ``'down'`` for the
    room an item has, ``'up'`` for the room it needs); NaN as "–".

    >>> format_length(20.0, "us", "down"), format_length(20.0, "si", "down"), format_length(float("nan"))
    ('7', '20', '–')
    """
    number = finite(value_cm)
    if number is None:
        return DASH
    return f"{rounded_length(number, system, rounding):d}".replace("-", "−")


def format_percent(value) -> str:
    """A probability as a whole percentage: :func:`assess.quantity_text.percent_text`, the one formatting
    of a chance in tables and sentences alike."""
    return percent_text(value)


def text(value) -> str:
    """Workbook text as a plain string ("" for missing)."""
    if value is None:
        return ""
    if isinstance(value, float) and math.isnan(value):
        return ""
    if value is pd.NA or value is pd.NaT:
        return ""
    return str(value)


def list_text(value, separator: str) -> str:
    """A list field of the result (a tuple, e.g. an item's demand sources) as one text ("" for missing).

    >>> list_text(("records", "regression"), " + "), list_text(float("nan"), " + ")
    ('records + regression', '')
    """
    if isinstance(value, (tuple, list)):
        return separator.join(str(part) for part in value)
    return text(value)


def integer_text(value) -> str:
    number = finite(value)
    if number is None:
        return text(value) or DASH
    return f"{number:.0f}" if number == int(number) else f"{number:g}"


def risk_units(summary: pd.DataFrame) -> dict[str, int]:
    """Units (``quantity``, 1 where not given) in each risk class; the classes of :data:`RISK_CLASSES`."""
    quantity = pd.to_numeric(summary["quantity"], errors="coerce").fillna(1) if "quantity" in summary \
        else pd.Series(1, index=summary.index)
    return {risk: int(quantity[summary["risk"].astype(str) == risk].sum()) for risk in RISK_CLASSES}


def total_units(summary: pd.DataFrame) -> int:
    """Units of every item (``quantity``, 1 where not given)."""
    quantity = pd.to_numeric(summary["quantity"], errors="coerce").fillna(1) if "quantity" in summary \
        else pd.Series(1, index=summary.index)
    return int(quantity.sum())


def what_happens(row: pd.Series) -> str:
    """What the item does in its governing case, in two or three words."""
    mode = text(row.get("mode"))
    return {
        "rock": "Rocks; may overturn",
        "slide-rock": "Slides and rocks; may overturn",
        "slide": "Slides",
        "rest": "Stays put",
    }.get(mode, mode.capitalize() or DASH)


#: Page 1's groups of actions, in the order a manager takes them.
ACTION_GROUPS = (
    ("code", "Restrain as the codes require", "a code or FEMA E-74 prescribes their restraint whatever the analysis "
     "says: each item's detail and reference are in the work orders and Appendix A"),
    ("anchor", "Anchor", "they overturn or rock in this earthquake; moving them away from walls does not help"),
    ("tether", "Tether or strap", "they stand on casters and overturn, rock, or roll farther than a room can "
     "spare in this earthquake"),
    ("lower_contents", "Move heavy contents low", "they rock or overturn as loaded, and with their heavy contents "
     "on the lowest shelves the engine finds them still"),
    ("restrain", "Restrain", "they are likely to slide past their room and need more room than a room can spare"),
    ("lock_casters", "Lock or chock the casters", "they stand on casters and may roll past their room"),
    ("room", "Give room", "they may slide past their room, and the room they need is one a room can spare"),
    ("none", "No action", "they stay within their room"),
)


def rest_sentence(rows: list[dict], counts: dict) -> str:
    """The sentence under page 2's lists: the low-risk and anchored items that need no action, and apart from
    them the low-risk items a code still asks to restrain (``action_reference``), named, so that it counts what
    page 1's "No action" counts.

    >>> rest_sentence([{"id": "R", "risk": "low", "action_reference": "NFPA 99"}, {"id": "F", "risk": "low"}],
    ...               {"low": 2, "anchored": 0})  # doctest: +NORMALIZE_WHITESPACE
    '1 item at low risk and 0 anchored items need no action from this assessment; 1 more at low risk, R, is to be
    restrained as the codes require (page 1 and the work orders).'
    """
    coded = [r["id"] for r in rows if r.get("risk") == "low" and r.get("action_reference")]
    free = counts.get("low", 0) - len(coded)
    anchored = counts.get("anchored", 0)
    sentence = (f"{free} item{'s' if free != 1 else ''} at low risk and {anchored} anchored "
                f"item{'s' if anchored != 1 else ''} need no action from this assessment")
    if coded:
        named = ", ".join(coded[:5]) + (f" and {len(coded) - 5} more" if len(coded) > 5 else "")
        sentence += (f"; {len(coded)} more at low risk, {named}, {'is' if len(coded) == 1 else 'are'} to be "
                     "restrained as the codes require (page 1 and the work orders)")
    return sentence + "."


def after_text(row) -> str:
    """"If done: overturning 0%, past its room 10%" from ``p_overturn_after`` and ``p_beyond_clearance_after``
    ("" for an item that needs no action or is anchored)."""
    if text(row.get("action_kind")) in ("", "none", "anchored"):
        return ""
    return (f"If done: overturning {format_percent(row.get('p_overturn_after'))}, past its room "
            f"{format_percent(row.get('p_beyond_clearance_after'))}")


def action_groups(rows: list[dict]) -> list[dict]:
    """The items of each action kind (``action_kind`` of the summary), in the page's order; the items whose
    action a code prescribes (``action_reference``) in a group of their own, first, saying how many of them
    had their kind read from their name (``type_source``)."""
    groups = []
    for kind, title, why in ACTION_GROUPS:
        members = [r for r in rows if (r.get("action_kind") == kind and not r.get("action_reference"))
                   or (kind == "code" and r.get("action_reference"))]
        if members:
            named = [r for r in members if kind == "code" and r.get("type_source") == "name"]
            if named:
                whose = "its name" if len(named) == 1 else "their names"
                why += (f"; the kind of {len(named)} of them was read from {whose}: confirm it, or write "
                        "component_type in the workbook")
            groups.append({"kind": kind, "title": title, "why": why, "rows": members})
    return groups


def interval_text(low, high) -> str:
    """"10–60%" for a probability's interval; "" where it is exact (a model's, not a sample's)."""
    low, high = finite(low), finite(high)
    if low is None or high is None or high - low < 0.005:
        return ""
    return f"{format_percent(low)}–{format_percent(high)}"


def cm_interval_text(row: pd.Series, quantile: str, system: str = "si") -> str:
    """"12–30" for the 90 % interval of the demand's median or 84th percentile [cm, or in for ``system``
    ``'us'``]; "∞" where the suite cannot bound it; "–" where the quantile is the regression's own (no
    interval)."""
    low, high = finite(row.get(f"demand_{quantile}_low_cm")), row.get(f"demand_{quantile}_high_cm")
    value = finite(row.get(f"demand_{quantile}_cm"))
    try:
        high = float(high)
    except (TypeError, ValueError):
        return DASH
    if low is None or value is None or (math.isclose(low, value) and math.isclose(high, value)):
        return DASH
    return f"{format_length(low, system)}–{'∞' if math.isinf(high) else format_length(high, system)}"


def suite_text(row: pd.Series) -> str:
    """"3 motions, 15 simulated histories": what the item's governing demand is made of."""
    motions, histories = finite(row.get("suite_motions")), finite(row.get("suite_histories"))
    if motions is None:
        return ""
    text = f"{motions:.0f} motion{'s' if motions != 1 else ''}"
    if histories and histories != motions:
        text += f", {histories:.0f} simulated histories"
    return text


#: The causes of a flag that concern a model's limit rather than a cell to check: the report says each once,
#: with the items it concerns (and what is each one's own, :attr:`assess.decision.flags.Flag.detail`), not once per
#: item. ``{im_min}`` and ``{im_max}`` are the regression's fitted range.
FLAG_CAUSES = {
    "alpha_range": "With the building's lateral stiffness ratio α at either end of its range (--alpha-range), the "
                   "level puts these items in another class than at the building's α, which governs (beside each: "
                   "its class at the low end, at the building's α and at the high end; summary.csv gives their "
                   "chances at both ends): their class rests on α, which lateral_stiffness_ratio from the building's "
                   "model would settle (or, for a frame, the pushover's slope after yield in pushover_slope_ratio, "
                   "with the model's storey_hardening_ratio).",
    "uplift": "They uplift and rock in the simulation (their mode and peak θ/α are in the tables). The paper's "
              "sliding regression assumes no uplift: the simulation answers for them.",
    "derived_floor_motion": "Their floors have no motion in the workbook: they were assessed under the ground "
                            "motions amplified by ASCE 7-16 eq. 13.3-1 (--derive-floors), an envelope rule, not "
                            "a floor response analysis. Floor motions from a structural engineer would replace it.",
    "building_beyond_drift": "Under some of their motions (beside each) the building's model passed the storey "
                             "drift it is trusted to (the building page says which storeys): the floor motions "
                             "under those, and these items' results under them, are outside what the model stands "
                             "for; their classes still count every motion.",
    "cg_not_mid_height": "The workbook puts their centre of mass off mid-height (at the height beside each): "
                         "α and b/h use it; the rocking frequency p assumes the mass spread over the whole box.",
    "im_outside_fit": "At these items' IM (beside each) the paper's regression, fitted on IM {im_min}–{im_max}, "
                      "would extrapolate: its numbers are marked n/a and their demand does not use them. A note on "
                      "the model, nothing to act on.",
}
#: The order of the flag groups: a cell to check first, then what changed an item's result, then the model's
#: limits; codes not named here follow, in the order the result gives them.
FLAG_ORDER = ("implausible_input", "calibrated", "alpha_range", "uplift", "derived_floor_motion",
              "building_beyond_drift", "cg_not_mid_height", "im_outside_fit")


def flag_text(text: str, flag, system: str = "si") -> str:
    """A flag's ``message`` or ``detail`` (``text``) with its length (:attr:`~assess.decision.flags.Flag.length_cm`)
    in the report's units.

    >>> from assess.decision.flags import Flag
    >>> flag_text("{length}", Flag("A", "cg_not_mid_height", "", "{length}", 116.84), "us")
    '46 in'
    """
    if flag.length_cm is None:
        return text
    return text.replace("{length}", length_text(flag.length_cm, system))


def flag_groups(flags, im_range: tuple[float, float] = (1.71, 6.40), system: str = "si") -> list[dict]:
    """The result's flags, one group per cause (code), each titled (:data:`FLAG_TITLES`) and in the order of
    :data:`FLAG_ORDER`. A cause of :data:`FLAG_CAUSES` is said once (``cause``), with its items and what is
    each one's own (``items``: ``id`` and ``detail``); any other (a cell to check, a calibration's change)
    keeps each item's own message (``entries``). ``im_range`` is the regression's fitted IM range.

    >>> from assess.decision.flags import Flag
    >>> groups = flag_groups([Flag("A", "cg_not_mid_height", "…", "46 in"), Flag("B", "implausible_input", "b"),
    ...                       Flag("C", "cg_not_mid_height", "…", "40 in")])
    >>> [(g["code"], [i["id"] for i in g["items"]], len(g["entries"])) for g in groups]
    [('implausible_input', ['B'], 1), ('cg_not_mid_height', ['A', 'C'], 0)]
    """
    by_code: dict[str, list] = {}
    for flag in flags:
        by_code.setdefault(flag.code, []).append(flag)
    rank = {code: k for k, code in enumerate(FLAG_ORDER)}
    codes = sorted(by_code, key=lambda code: rank.get(code, len(rank)))  # stable: others as the result gives
    groups = []
    for code in codes:
        members = by_code[code]
        items = list({flag.item_id: {"id": flag.item_id, "detail": flag_text(flag.detail, flag, system)}
                      for flag in members}.values())
        cause = FLAG_CAUSES.get(code)
        groups.append({
            "code": code,
            "title": FLAG_TITLES.get(code, code.replace("_", " ").capitalize()),
            "cause": cause.format(im_min=f"{im_range[0]:g}", im_max=f"{im_range[1]:g}") if cause else "",
            "items": items,
            "entries": [] if cause else [{"item_id": flag.item_id, "message": flag_text(flag.message, flag, system)}
                                         for flag in members],
        })
    return groups


def method_notes(summary: pd.DataFrame) -> list[str]:
    """The method section's paragraphs on sliding in the plane, on μ ranges and on default μ ranges, where
    they apply."""
    return [note for note in (planar.method_text(summary), friction_range.method_text(summary),
                              default_mu_text(summary)) if note]


def default_mu_text(summary: pd.DataFrame) -> str:
    """Which items the workbook gave no μ and what range each took instead, and why (``mu_source``), in a
    paragraph; "" when every freestanding item has its own μ.

    >>> rows = pd.DataFrame({"id": ["A", "B", "C"], "mu_source": ["workbook", "default, no base given (0.2-0.6)",
    ...                      "default, no base given (0.2-0.6)"], "mu_low": [None, 0.2, 0.2],
    ...                      "mu_high": [None, 0.6, 0.6]})
    >>> default_mu_text(rows)  # doctest: +NORMALIZE_WHITESPACE
    'No μ in the workbook for 2 items: each was assessed over a range of μ instead (a triangular distribution with its
    mode, the μ shown, at the middle; the risk at either end is in the table). B, C: 0.2–0.6, default, no base given
    (0.2-0.6). Measured values for the item on its floor narrow it (mu in the equipment sheet).'
    """
    if "mu_source" not in summary:
        return ""
    sources = summary["mu_source"].map(lambda value: value if isinstance(value, str) else "")
    chosen = summary[(sources != "") & (sources != "workbook")]
    if chosen.empty:
        return ""
    groups = []
    for source, rows in chosen.groupby(sources[chosen.index], sort=False):
        low, high = float(rows["mu_low"].iloc[0]), float(rows["mu_high"].iloc[0])
        groups.append(f"{', '.join(str(i) for i in rows['id'])}: {low:g}–{high:g}, {source}.")
    count = len(chosen)
    return (f"No μ in the workbook for {count} item{'s' if count != 1 else ''}: "
            f"{'each was' if count != 1 else 'it was'} assessed over a range of μ instead (a triangular "
            "distribution with its mode, the μ shown, at the middle; the risk at either end is in the table). "
            + " ".join(groups) + " Measured values for the item on its floor narrow it (mu in the equipment sheet).")


#: Most rows of the report's table of changes (comparison.csv holds them all): a previous summary of another
#: building would otherwise lay out every item it had as "removed".
MAX_CHANGE_ROWS = 200


def changes(comparison) -> dict | None:
    """The rows of a comparison with a previous run whose risk class changed, for the report."""
    if comparison is None:
        return None
    changed = comparison[comparison["change"] != "same"]
    return {"total": len(comparison), "same": int((comparison["change"] == "same").sum()), "changed": len(changed),
            "rows": [{"id": text(r["id"]), "name": text(r["name"]), "before": text(r["risk_before"]) or DASH,
                      "after": text(r["risk_after"]) or DASH, "change": text(r["change"]),
                      "why": text(r["why"]) or DASH} for _, r in changed.head(MAX_CHANGE_ROWS).iterrows()]}


def slides_in_both(motions: pd.DataFrame) -> pd.Series:
    """Which cases (rows of ``result.motions``) slide in the simulation and in the paper's regression alike:
    a simulated peak sliding and a regression median both above zero (the cases the report's figure of
    one against the other shows, :func:`assess.report.figures.simulation_vs_regression_figure`)."""
    simulated = pd.to_numeric(motions["sim_sliding_max_cm"], errors="coerce")
    regression = pd.to_numeric(motions["sliding_median_cm"], errors="coerce")
    return (simulated > 0) & (regression > 0)


def case_outcomes(result: AssessmentResult) -> dict:
    """How the simulated cases ended, in classes that add up, and how many runs each solver answered.

    A case (item × motion × direction) counts once, by the worst of its runs:
    ``overturned`` if any run overturns, else ``uplift`` if any uplifts, else
    ``slid`` if it slides, else ``rest``; the four add up to ``cases``.
    Solvers are counted per run (a case of several histories may use several).
    ``both``: the cases that slide in the simulation and in the regression (:func:`slides_in_both`), and
    ``no_comparison``: the sentence the report gives instead of their figure where there is none.
    """
    motions = result.motions
    if not result.simulated or "sim_solver" not in motions:
        return {}
    overturned = motions["sim_overturn_share"].fillna(0.0).astype(float) > 0.0 if "sim_overturn_share" in motions \
        else motions["sim_overturned"].astype(bool)
    uplift = motions["sim_uplift"].astype(bool) & ~overturned
    slid = (pd.to_numeric(motions["sim_sliding_max_cm"], errors="coerce") > 0) & ~overturned & ~uplift
    rest = ~(overturned | uplift | slid)
    solvers = result.solver_runs
    if solvers is None:  # a result built without the pipeline: one run per case
        solvers = motions["sim_solver"].astype(object).where(motions["sim_solver"].notna(), "").astype(str) \
            .value_counts().to_dict()
    return {"cases": len(motions), "runs": int(sum(solvers.values())),
            "solvers": sorted(solvers.items(), key=lambda kv: -kv[1]),
            "overturned": int(overturned.sum()), "uplift": int(uplift.sum()), "slid": int(slid.sum()),
            "rest": int(rest.sum()), "both": (both := int(slides_in_both(motions).sum())),
            "no_comparison": "" if both else (
                "No case slides both in the simulation and by the paper's regression (where the regression "
                "does not apply to a case, it gives no sliding), so there is no figure of the one against the "
                "other.")}


# --------------------------------------------------------------------------- where the numbers come from
#: What each model of an item's demand (``demand_source``, :mod:`assess.fragility.governing`) is, for the
#: report's "How to read this"; the words of the time histories' origins are added from
#: :data:`assess.assessment.summary.HISTORY_ORIGINS`.
MODEL_DEFINITIONS = {
    "regression": "the paper's formula, used only for near-fault pulses like the paper's",
    "synthetic": "simulated under near-fault histories made to match the workbook's PTA, Tp and vp",
    "pulse": "simulated under the motion's pulse alone",
}


def history_phrases(summary: pd.DataFrame) -> list[str]:
    """Where the time histories the engine ran come from, one phrase per origin the summary's
    ``demand_source`` names (:func:`assess.assessment.summary.origin_words`), in the order they first appear.

    >>> history_phrases(pd.DataFrame({"demand_source": [("scaled records", "regression"), ("records",)]}))
    ["records selected from the site's records folder and scaled to the site's spectrum", "the workbook's records"]
    """
    from assess.assessment.summary import HISTORY_ORIGINS, THROUGH_BUILDING, origin_words
    phrases = dict(origin_words(which) for origin in HISTORY_ORIGINS for which in (origin, origin + THROUGH_BUILDING))
    shown = []
    for sources in summary.get("demand_source", pd.Series(dtype=object)):
        for word in (sources if isinstance(sources, (tuple, list)) else ()):
            if word in phrases and phrases[word] not in shown:
                shown.append(phrases[word])
    return shown


def source_definitions(summary: pd.DataFrame) -> list[tuple[str, str]]:
    """Each word of the summary's ``demand_source`` that this report shows, with what it means: the models
    (:data:`MODEL_DEFINITIONS`) and the time histories by their origin
    (:func:`assess.assessment.summary.origin_words`), in the order they first appear.

    >>> source_definitions(pd.DataFrame({"demand_source": [("synthetic ground motions through the building",),
    ...                                                  ("records", "regression")]}))[0][1]
    "simulated under synthetic ground motions matched to the site's spectrum, passed through the building"
    """
    from assess.assessment.summary import HISTORY_ORIGINS, THROUGH_BUILDING, origin_words
    meanings = {}
    for origin in HISTORY_ORIGINS:
        for which in (origin, origin + THROUGH_BUILDING):
            word, phrase = origin_words(which)
            meanings[word] = f"simulated under {phrase}"
    meanings.update(MODEL_DEFINITIONS)
    shown = []
    for sources in summary.get("demand_source", pd.Series(dtype=object)):
        for word in (sources if isinstance(sources, (tuple, list)) else ()):
            if word in meanings and word not in [w for w, _ in shown]:
                shown.append((word, meanings[word]))
    return shown


def history_origin_phrase(result: AssessmentResult, item_id) -> str:
    """Where the time histories of an item's floor come from, as a phrase ("" where the item's floor's
    motions are the workbook's own): from the result's ``floor_origins``."""
    from assess.assessment.summary import origin_words
    origins = result.floor_origins or {}
    floors = result.summary.loc[result.summary["id"].astype(str) == str(item_id), "floor"]
    floor = finite(floors.iloc[0]) if len(floors) else None
    origin = origins.get(int(floor) if floor is not None else None, origins.get(None, ""))
    return "" if origin in ("", "workbook") else origin_words(origin)[1]


def worst_run_text(history: dict, result: AssessmentResult) -> str:
    """The motion of an item's worst run as the report names it: its name and, where it is not the workbook's
    own record, where its history comes from (the engine's own description otherwise).

    >>> from types import SimpleNamespace
    >>> r = SimpleNamespace(floor_origins={0: "site synthetic"}, summary=pd.DataFrame({"id": ["A"], "floor": [0]}))
    >>> worst_run_text({"id": "A", "motion": "DE synthetic 5", "sim_motion": "record DE synthetic 5 x 1"}, r)
    "DE synthetic 5, one of the synthetic ground motions matched to the site's spectrum"
    """
    phrase = history_origin_phrase(result, history.get("id"))
    if not phrase:
        return text(history.get("sim_motion")) or text(history.get("motion"))
    return f"{text(history.get('motion'))}, one of the {phrase}"


def level_text(result: AssessmentResult) -> str:
    """The level the report assesses, named as the code names it where it is an ASCE 7 level of the site's
    spectrum (from the result's ``design_spectrum``); the level's own description otherwise.

    >>> from types import SimpleNamespace
    >>> from assess.hazard.levels import parse_level
    >>> from assess.site.asce7 import from_design_values
    >>> r = SimpleNamespace(level=parse_level("DE"), site_class="D",
    ...                     design_spectrum=from_design_values(1.1, 0.6, 8.0, code="ASCE 7-22"))
    >>> level_text(r)
    'DE: the ASCE 7-22 design earthquake, 2/3 of MCE_R (S_DS 1.1 g, S_D1 0.6 g, site class D)'
    >>> level_text(SimpleNamespace(level=parse_level("MCE_R"), site_class="", design_spectrum=r.design_spectrum))
    'MCE_R: the ASCE 7-22 risk-targeted maximum considered earthquake (S_MS 1.65 g, S_M1 0.9 g)'
    """
    from fractions import Fraction

    from assess.site.asce7 import MCE_R_OVER_DESIGN
    from assess.site.target import asce7_level
    design, level = getattr(result, "design_spectrum", None), result.level
    kind = asce7_level(level)
    if design is None or kind is None:
        return level.description
    site_class = text(getattr(result, "site_class", "")) or text(getattr(design, "site_class", ""))
    where = f", site class {site_class}" if site_class else ""
    if kind == "design":
        share = Fraction(1.0 / MCE_R_OVER_DESIGN).limit_denominator(12)
        return (f"{level.label or level.name}: the {design.code} design earthquake, {share} of MCE_R "
                f"(S_DS {design.sds_g:.3g} g, S_D1 {design.sd1_g:.3g} g{where})")
    return (f"{level.label or level.name}: the {design.code} risk-targeted maximum considered earthquake "
            f"(S_MS {design.sms_g:.3g} g, S_M1 {design.sm1_g:.3g} g{where})")


def class_rule_paragraph(settings: Settings) -> str:
    """The method's paragraph on the risk classes: the rule that decides them
    (:func:`assess.decision.risk_classes.rule_text`, from the run's thresholds), the intervals, the room advised
    (the sliding exceeded with the moderate threshold's chance) and the anchored items."""
    from assess.decision.risk_classes import rule_text
    moderate = 100.0 * settings.risk_pf_moderate
    return (f"Risk class, from the governing demand. {rule_text(settings)} Where a chance's 90 % interval spans "
            "other classes, the tables say which. The room an item is advised to have is the sliding it exceeds "
            f"with a {moderate:g}% chance: with that room it would be low risk on sliding past it. Anchored items "
            "are listed and not analysed.")


def hazard_limit_text(result: AssessmentResult) -> str:
    """The report's limit on its motions: where they come from, from the result (the site's ground suite,
    the building's elastic model, the hazard sheet's motions and how they were changed)."""
    parts = []
    if result.ground_motions is not None:
        from assess.assessment.summary import HISTORY_ORIGINS  # the suite's origin in the items' own words
        _, how = HISTORY_ORIGINS.get(f"site {text(result.ground_method)}",
                                     ("", "motions matched to the site's spectrum"))
        parts.append(f"The ground motions are {how} ({len(result.ground_motions)} motions)")
    if result.floors is not None and "response" in result.floors:  # a yielding building (floors.csv says so)
        parts.append("the upper floors' motions are the ground motions through a model of the building that "
                     "yields, trusted up to the storey drift its section gives; the building's own collapse is "
                     "not assessed")
    elif result.floors is not None:
        parts.append("the upper floors' motions are the ground motions through the building's elastic modes, "
                     "which a yielding building would lower")
    if parts:
        return "; ".join(parts) + " (as stated at the top of this report)."
    if result.hazard_notes:
        return "The hazard motions are the workbook's, changed as stated at the top of this report."
    return ("The hazard motions (peak floor acceleration and pulse period for each floor) are taken as given in "
            "the workbook; this report does not derive them.")


def given_by_parameters(result: AssessmentResult) -> bool:
    """Whether any motion was given by PTA, Tp and vp (simulated under synthetic near-fault histories or its
    pulse, not under a history of its own: ``sim_motion`` not ``record …``)."""
    motions = result.motions
    if "sim_motion" not in motions:
        return False
    described = motions["sim_motion"].astype(object).where(motions["sim_motion"].notna(), "").astype(str)
    return bool((~described.str.startswith("record ") & (described != "")).any())


def regression_items(summary: pd.DataFrame) -> dict:
    """How many freestanding items the figures of the paper's regression mark (``shown``: those whose
    governing case it applies to, with its Pf) of how many (``of``).

    >>> nan = float("nan")
    >>> regression_items(pd.DataFrame({"risk": ["low", "high", "anchored"], "pf_sliding": [0.2, nan, nan]}))
    {'shown': 1, 'of': 2}
    """
    free = summary[summary["risk"].astype(str) != "anchored"]
    if "pf_sliding" not in free:
        return {"shown": 0, "of": len(free)}
    return {"shown": int(pd.to_numeric(free["pf_sliding"], errors="coerce").notna().sum()), "of": len(free)}
