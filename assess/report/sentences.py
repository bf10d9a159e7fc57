"""What the report says, built from the result: numbers as text, sentences, and the counts a page shows.

The templates only lay these out (:mod:`assess.report.render`). Sentences
that the decisions make for an item (its action, what-if, demand note) are
fields of the result (:mod:`assess.decisions`); what is here turns the result's
fields into the report's words and counts, so that a count a page shows adds up
in a test and is never re-derived in a template.
"""
from __future__ import annotations

import math

import pandas as pd

from assess.fragility import friction_range, planar
from assess.quantity_text import floor_text, floors_text, percent_text, rounded_length  # noqa: F401 (floor labels)
from assess.result import RISK_CLASSES, AssessmentResult

DASH = "–"

#: Headings for the flag codes the pipeline is known to emit; others get their code.
FLAG_TITLES = {
    "im_outside_fit": "Outside the range the regression was fitted on",
    "uplift": "Uplifts and rocks",
    "cg_not_mid_height": "Centre of mass not at mid-height",
    "derived_floor_motion": "Floor motion derived from the ground motion",
    "implausible_input": "Size or density no equipment has: check the workbook cell",
}


def finite(value) -> float | None:
    try:
        number = float(value)
    except (TypeError, ValueError):
        return None
    return number if math.isfinite(number) else None


def format_significant(value, digits: int = 2) -> str:
    """``value`` to ``digits`` significant digits (0.30, 3.38, 12000), never in exponent form; NaN as "–"."""
    number = finite(value)
    if number is None:
        return DASH
    if number == 0:
        return "0"
    decimals = digits - 1 - math.floor(math.log10(abs(number)))
    rounded = round(number, decimals)
    if rounded != 0:  # rounding may carry into the next decade (0.996 -> 1.0)
        decimals = digits - 1 - math.floor(math.log10(abs(rounded)))
        rounded = round(number, decimals)
    return f"{rounded:.{max(decimals, 0)}f}".replace("-", "−")


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
    ("anchor", "Anchor", "they overturn or rock in the design earthquake; moving them away from walls does not help"),
    ("tether", "Tether or strap", "they stand on casters and overturn, rock, or roll farther than a room can "
     "spare in the design earthquake"),
    ("lower_contents", "Move heavy contents low", "they rock or overturn as loaded, and with their heavy contents "
     "on the lowest shelves the engine finds them still"),
    ("restrain", "Restrain", "they are likely to slide past their room and need more room than a room can spare"),
    ("lock_casters", "Lock or chock the casters", "they stand on casters and may roll past their room"),
    ("room", "Give room", "they may slide past their room, and the room they need is one a room can spare"),
    ("none", "No action", "they stay within their room"),
)


def after_text(row) -> str:
    """"If done: overturning 0%, past its room 10%" from ``p_overturn_after`` and ``p_beyond_clearance_after``
    ("" for an item that needs no action or is anchored)."""
    if text(row.get("action_kind")) in ("", "none", "anchored"):
        return ""
    return (f"If done: overturning {format_percent(row.get('p_overturn_after'))}, past its room "
            f"{format_percent(row.get('p_beyond_clearance_after'))}")


def action_groups(rows: list[dict]) -> list[dict]:
    """The items of each action kind (``action_kind`` of the summary), in the page's order."""
    groups = []
    for kind, title, why in ACTION_GROUPS:
        members = [r for r in rows if r.get("action_kind") == kind]
        if members:
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


def flag_groups(flags) -> list[dict]:
    """The result's flags grouped by code, each group titled (:data:`FLAG_TITLES`)."""
    groups: dict[str, list[dict]] = {}
    for flag in flags:
        groups.setdefault(flag.code, []).append({"item_id": flag.item_id,
                                                 "message": flag.message})
    return [{"code": code,
             "title": FLAG_TITLES.get(code, code.replace("_", " ").capitalize()),
             "entries": entries}
            for code, entries in groups.items()]


def method_notes(summary: pd.DataFrame) -> list[str]:
    """The method section's paragraphs on sliding in the plane, on μ ranges and on default μ ranges, where
    they apply."""
    return [note for note in (planar.method_text(summary), friction_range.method_text(summary),
                              default_mu_text(summary)) if note]


def default_mu_text(summary: pd.DataFrame) -> str:
    """Which items the workbook gave no μ and what range each took instead, and why (``mu_source``), in a
    paragraph; "" when every freestanding item has its own μ.

    >>> rows = pd.DataFrame({"id": ["A", "B", "C"], "mu_source": ["workbook", "default, no base given (0.2-0.6)",
    ...                      "default, no base given (0.2-0.6)"], "mu_low": [None, 0.2, 0.2], "mu_high": [None, 0.6, 0.6]})
    >>> default_mu_text(rows)
    'No μ in the workbook for 2 items: each was assessed over a range of μ instead (a triangular distribution with its mode, the μ shown, at the middle; the risk at either end is in the table). B, C: 0.2–0.6, default, no base given (0.2-0.6). Measured values for the item on its floor narrow it (mu in the equipment sheet).'
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


def changes(comparison) -> dict | None:
    """The rows of a comparison with a previous run whose risk class changed, for the report."""
    if comparison is None:
        return None
    changed = comparison[comparison["change"] != "same"]
    return {"total": len(comparison), "same": int((comparison["change"] == "same").sum()),
            "rows": [{"id": text(r["id"]), "name": text(r["name"]), "before": text(r["risk_before"]) or DASH,
                      "after": text(r["risk_after"]) or DASH, "change": text(r["change"]),
                      "why": text(r["why"]) or DASH} for _, r in changed.iterrows()]}


def case_outcomes(result: AssessmentResult) -> dict:
    """How the simulated cases ended, in classes that add up, and how many runs each solver answered.

    A case (item × motion × direction) counts once, by the worst of its runs:
    ``overturned`` if any run overturns, else ``uplift`` if any uplifts, else
    ``slid`` if it slides, else ``rest``; the four add up to ``cases``.
    Solvers are counted per run (a case of several histories may use several).
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
            "rest": int(rest.sum())}
