"""The risk report: HTML from a jinja2 template, PDF from that HTML with WeasyPrint (:mod:`assess.report.pdf`).

Nothing the report shows is fetched: the stylesheet is inlined, the figures
are SVG, inline or embedded as ``data:`` URIs, and :func:`render_pdf` renders with a URL
fetcher that refuses every URL that is not a ``data:`` URI. Text from the
workbook (names, rooms, ids, motions, actions) is escaped by jinja2's
autoescape. The report carries no timestamp, so the same result gives the
same HTML byte for byte.
"""
from __future__ import annotations

import base64
import dataclasses
import functools
import math
from collections.abc import Callable
from importlib import resources
from pathlib import Path

import jinja2
import numpy as np
import pandas as pd
from markupsafe import Markup

import assess
from assess.anchorage.method import anchorage_method
from assess.report.advice import anchorage_sentence, brief_action, decision_head, with_words, work_order_sentences
from assess.report.anchorage_table import anchorage_context
from assess.decision.risk_classes import rule_text
from assess.quantity_text import floor_numbering_of, length_unit, length_value, system_of
from assess.report import figures
from assess.report.building import building_context
from assess.report.costs import costs_context
from assess.report.curve import curve_context
from assess.report.items_table import action_note, demand_from, regression_words, table_action
from assess.report.method import floor_motion_route
from assess.report.pdf import (  # noqa: F401
    RefusedURLError, data_only_url_fetcher, decode_data_uri, render_pdf, report_pdf)
from assess.report.references import reference_rows
from assess.report.sentences import (
    DASH, action_groups, after_text, case_outcomes, changes, class_rule_paragraph, cm_interval_text, finite,
    flag_groups, floor_text, format_cm, format_length, format_percent, format_significant, given_by_parameters,
    hazard_limit_text, history_phrases, integer_text, interval_text, level_text, list_text, method_notes,
    regression_items, rest_sentence, risk_units, slides_in_both, source_definitions, suite_text, text,
    total_units, what_happens, worst_run_text,
)
from assess.report.title import title_block

TEMPLATE_NAME = "report.html.j2"
STYLESHEET_NAME = "report.css"

RISK_ORDER = {"high": 0, "moderate": 1, "low": 2, "anchored": 3}

#: What each mode of response means, in plain words.
MODE_TEXT = {
    "rest": "stays put",
    "slide": "slides",
    "rock": "rocks",
    "slide-rock": "slides and rocks",
}



# --------------------------------------------------------------------------- templates
def template_text(name: str) -> str:
    """The text of a packaged template or stylesheet.

    Reads it from the package ``assess.templates`` (how an installed wheel
    ships ``templates/``); in a source checkout, where that package does not
    exist, from the repository's ``templates/`` folder.
    """
    try:
        return resources.files("assess.templates").joinpath(name).read_text(encoding="utf-8")
    except (ModuleNotFoundError, FileNotFoundError, NotADirectoryError):
        return (Path(__file__).parents[2] / "templates" / name).read_text(encoding="utf-8")


def _template_or_none(name: str) -> str | None:
    """The text of a packaged template, or None where there is none (jinja2's "not found": an
    ``{% include ... ignore missing %}`` of a block another part of the tool adds is then skipped)."""
    try:
        return template_text(name)
    except (OSError, ValueError):
        return None


def make_environment() -> jinja2.Environment:
    """A jinja2 environment that autoescapes everything and fails on undefined names."""
    environment = jinja2.Environment(
        loader=jinja2.FunctionLoader(_template_or_none),
        autoescape=True,
        undefined=jinja2.StrictUndefined,
        trim_blocks=True,
        lstrip_blocks=True,
        keep_trailing_newline=True,
    )
    environment.filters["sig"] = format_significant
    environment.filters["cm"] = format_cm
    environment.filters["percent"] = format_percent
    return environment


@functools.cache
def report_template() -> jinja2.Template:
    """The report's template, compiled once per process (:func:`make_environment`)."""
    return make_environment().get_template(TEMPLATE_NAME)


# --------------------------------------------------------------------------- context
#: How :func:`_sorted_summary` orders the items, as the all-items table's lead says it: by the pipeline's
#: ``priority`` where there is one, else by risk.
ORDER_SENTENCE = {
    "priority": "In order of priority: what a failure of the item costs (life-safety, hazardous, critical, "
                "valuable, ordinary) times its chance of overturning, of sliding past its room (counted half) or "
                "of rocking that harms it (a quarter, where that counts), so a moderate item may come before a "
                "high one; the items that need no action and the anchored ones last, by id.",
    "risk": "Sorted by risk, then by the chance of overturning, items that rock before those that only slide, "
            "then by the chance of sliding beyond the clearance.",
}


def _ordering(summary: pd.DataFrame) -> str:
    """How :func:`_sorted_summary` orders ``summary``'s items: ``priority`` where the pipeline gave one, else
    ``risk``."""
    return "priority" if "priority" in summary else "risk"


def order_sentence(summary: pd.DataFrame) -> str:
    """The sentence saying how :func:`_sorted_summary` orders ``summary``'s items (:data:`ORDER_SENTENCE`)."""
    return ORDER_SENTENCE[_ordering(summary)]


def _sorted_summary(summary: pd.DataFrame) -> pd.DataFrame:
    """Items by urgency: the pipeline's ``priority`` where there is one (what the failure costs times its
    chance); otherwise risk class, then the chance of overturning, then rocking before sliding, then the
    chance of sliding past the clearance, high to low, then id (all from the governing demand)."""
    keys = pd.DataFrame({
        "risk": summary["risk"].astype(str).map(RISK_ORDER).fillna(len(RISK_ORDER)),
        "overturn": -pd.to_numeric(summary["p_overturn"], errors="coerce").fillna(-1.0),
        "rocks": ~summary["mode"].astype(str).isin(["rock", "slide-rock"]),
        "pf": -pd.to_numeric(summary["p_beyond_clearance"], errors="coerce").fillna(-1.0),
        "id": summary["id"].astype(str),
    }, index=summary.index)
    if _ordering(summary) == "priority":  # the pipeline's order of action: consequence × chance (1 = act first)
        keys["priority"] = pd.to_numeric(summary["priority"], errors="coerce").fillna(len(summary) + 1)
        order = keys.sort_values(["priority", "risk", "id"], kind="mergesort").index
        return summary.loc[order]
    order = keys.sort_values(["risk", "overturn", "rocks", "pf", "id"], kind="mergesort").index
    return summary.loc[order]


def _item_row(row: pd.Series, system: str = "si", numbering: str = "ground_0") -> dict:
    """One item's cells, formatted: lengths in the report's unit (``system``, :mod:`assess.quantity_text`;
    the room an item has rounded down, as its advice rounds it), forces with their unit, the floor as
    ``numbering`` labels it (:func:`~assess.report.sentences.floor_text`)."""
    direction = finite(row.get("governing_direction"))
    motion = text(row.get("governing_motion"))
    quantity = finite(row.get("quantity"))
    return {
        "id": text(row.get("id")),
        "name": text(row.get("name")),
        "quantity": int(quantity) if quantity is not None and quantity > 1 else None,
        "room": text(row.get("room")),
        "floor": floor_text(row.get("floor"), numbering),
        "mode": text(row.get("mode")) or DASH,
        "what_happens": what_happens(row),
        "b_over_h": format_significant(row.get("b_over_h"), 2),
        "mu": format_significant(row.get("mu"), 2),
        "motion": motion or DASH,
        "direction": f"{direction:.0f}" if direction is not None and motion else "",  # no motion, no direction
        "pta": format_significant(row.get("pta_g"), 2),
        "tp": format_significant(row.get("tp_s"), 2),
        "im": format_significant(row.get("im"), 3),
        "median": format_length(row.get("sliding_median_cm"), system),
        "p84": format_length(row.get("sliding_p84_cm"), system),
        "clearance": format_length(row.get("clearance_cm"), system, "down"),
        "pf": format_percent(row.get("pf_sliding")),
        "overturn": format_percent(row.get("overturn_fraction")),
        "sim_sliding": format_length(row.get("sim_sliding_max_cm"), system),
        "theta": format_significant(row.get("theta_max_over_alpha"), 2),
        "risk": text(row.get("risk")),
        "risk_range": text(row.get("risk_range")),
        "action_kind": text(row.get("action_kind")),
        "action_reference": text(row.get("action_reference")),
        "type_source": text(row.get("type_source")),
        "consequence": text(row.get("consequence")),
        "anchor_sentence": anchorage_sentence(row, system),
        "anchor_basis": text(row.get("anchor_basis")),
        "what_if": text(row.get("what_if")),
        "after": after_text(row),
        "priority": integer_text(row.get("priority")),
        "action": text(row.get("action")) or DASH,
        "action_brief": brief_action(text(row.get("action")), text(row.get("type_source"))) or DASH,
        "source": list_text(row.get("demand_source"), " + ") or DASH,
        "source_note": text(row.get("demand_note")),
        "demand_median": format_length(row.get("demand_median_cm"), system),
        "demand_p84": format_length(row.get("demand_p84_cm"), system),
        "p_beyond": format_percent(row.get("p_beyond_clearance")),
        "p_beyond_interval": interval_text(row.get("p_beyond_clearance_low"), row.get("p_beyond_clearance_high")),
        "demand_interval": cm_interval_text(row, "median", system) + " / " + cm_interval_text(row, "p84", system),
        "p_overturn": format_percent(row.get("p_overturn")),
        "p_overturn_interval": interval_text(row.get("p_overturn_low"), row.get("p_overturn_high")),
        "p_rocking_harm": format_percent(row.get("p_rocking_harm")),
        "p_rocking_harm_interval": interval_text(row.get("p_rocking_harm_low"), row.get("p_rocking_harm_high")),
        "risk_reason": text(row.get("risk_reason")),
        "regression_applies": isinstance(row.get("regression_applies"), (bool, np.bool_))
        and bool(row.get("regression_applies")),
        "regression_note": text(row.get("regression_note")),
        "suite": suite_text(row),
    }


def item_anchors(ids) -> list[str]:
    """HTML anchors ``item-<id>`` for the items, made of letters, digits, ``-`` and ``_`` only, unique.

    >>> item_anchors(["FRZ-1", "a b", "a_b"])
    ['item-FRZ-1', 'item-a_b', 'item-a_b-2']
    """
    anchors, seen = [], set()
    for item_id in ids:
        anchor = "item-" + "".join(c if c.isascii() and (c.isalnum() or c in "-_") else "_" for c in str(item_id))
        candidate, k = anchor, 1
        while candidate in seen:
            k += 1
            candidate = f"{anchor}-{k}"
        seen.add(candidate)
        anchors.append(candidate)
    return anchors


#: How many of the worst items' histories are drawn full size (Fig. 7 of the paper).
HISTORY_FIGURES = 3
#: Size of an item's small history plot [px] (the text width of a portrait page), the most points it draws
#: per curve, and its margins [px]: left and right for the two vertical axes' numbers (and the time axis'
#: title, right of its end), top for their titles, bottom for the time axis' numbers.
SPARK_WIDTH, SPARK_HEIGHT, SPARK_POINTS = 660, 70, 280
SPARK_LEFT, SPARK_RIGHT, SPARK_TOP, SPARK_BOTTOM = 46, 46, 11, 15
#: Size of an item's suite strip [px]: width, left margin for the motion names, height of a one-line row,
#: font size of a name, and the widest name on one line [characters] (longer ones wrap on two lines).
STRIP_WIDTH, STRIP_LEFT, STRIP_ROW, STRIP_FONT_PX, STRIP_LABEL_CHARS = 660, 250, 13, 8, 52
#: The words of an item's strip and history plot (the motions' names, the axes' titles and numbers) are HTML laid
#: over their SVG, at the SVG's own coordinates [px], not SVG text: the PDF's renderer lays SVG text out letter
#: by letter, each word not left-aligned a PDF group of its own (a third of the appendix's PDF, which the merge
#: then reads and writes again). A line of words is WORD_LINE_PX high (a name on two lines: one under the other,
#: as the SVG's 9 px); DejaVu Sans' ascent and descent [em] (its hhea table, 1901 and 483 of 2048 units) put its
#: baseline where the SVG text's was; a centred word (an axis' number) is centred in a box WORD_MIDDLE_PX wide, a
#: word that ends at its x (a motion's name) ends a box WORD_END_PX wide (wider than any name's line, so that a
#: long one runs out to the left, never over the dots).
WORD_LINE_PX, FONT_ASCENT_EM, FONT_DESCENT_EM, WORD_MIDDLE_PX, WORD_END_PX = 9.0, 1901 / 2048, 483 / 2048, 80.0, 400.0


def _item_details(rows: list[dict], summary: pd.DataFrame, runs: pd.DataFrame | None,
                  histories: dict | None = None, system: str = "si",
                  run_text: Callable[[dict], str] | None = None) -> list[dict]:
    """One block per freestanding item: its numbers, and its suite drawn as a strip (every motion a line,
    every history a dot at its sliding, overturned ones as crosses, the clearance a bar); its worst run's
    motion named by ``run_text(history)`` (:func:`~assess.report.sentences.worst_run_text`; the engine's
    description where not given)."""
    by_id = summary.set_index(summary["id"].astype(str))
    details = []
    for row in rows:
        if row["risk"] == "anchored":
            continue
        number = len(details) + 1  # the blocks are numbered 1, 2, 3 …: anchored items have none
        item = by_id.loc[row["id"]]
        item = item.iloc[0] if isinstance(item, pd.DataFrame) else item
        strip = None
        if runs is not None and len(runs):
            strip = _suite_strip(runs[runs["id"].astype(str) == row["id"]], finite(item.get("clearance_cm")), system)
        history = (histories or {}).get(row["id"])
        spark = _history_spark(history, system) if history else None
        if spark is not None and run_text is not None:
            spark["motion"] = run_text(history)
        details.append({**row, "number": number, "strip": strip, "spark": spark,
                        "theta": format_significant(item.get("theta_max_over_alpha"), 2),
                        "alpha": format_significant(item.get("alpha_rad"), 2)})
    return details


def figure_word(lines, x: float, baseline_y: float, anchor: str = "start", size_px: float = 8.0,
                colour: str = "black", width_px: float = STRIP_WIDTH) -> dict:
    """A word (or a name on two lines) to lay over an SVG ``width_px`` wide, as SVG text at ``x``, ``baseline_y``
    [px] with ``text-anchor`` ``anchor`` ('start', 'middle', 'end') would be: its lines and its CSS position, in a
    box of a given width (ending at ``x`` for 'end', from ``x`` to the SVG's right edge for 'start'), which the
    renderer need not measure its words to size.

    >>> figure_word("0", 100.0, 20.0, "middle", 7.5)["style"]
    'left: 60.0px; width: 80px; text-align: center; top: 12.90px; font-size: 7.5px; color: black'
    >>> figure_word(["a", "b"], 244, 18.0, "end")["style"]
    'left: -156px; width: 400px; text-align: right; top: 10.73px; font-size: 8px; color: black'
    """
    lines = [lines] if isinstance(lines, str) else list(lines)
    ascent, height = FONT_ASCENT_EM * size_px, (FONT_ASCENT_EM + FONT_DESCENT_EM) * size_px
    top = baseline_y - ((WORD_LINE_PX - height) / 2.0 + ascent)
    if anchor == "end":
        where = f"left: {x - WORD_END_PX:g}px; width: {WORD_END_PX:g}px; text-align: right"
    elif anchor == "middle":
        where = f"left: {x - WORD_MIDDLE_PX / 2.0:.1f}px; width: {WORD_MIDDLE_PX:g}px; text-align: center"
    else:
        where = f"left: {x:g}px; width: {width_px - x:g}px"
    return {"lines": lines, "style": f"{where}; top: {top:.2f}px; font-size: {size_px:g}px; color: {colour}"}


def _history_spark(history: dict, system: str = "si") -> dict:
    """The item's worst run as two small polylines on one time axis: sliding [cm, or in for ``system``
    ``'us'``] against the left axis (with the clearance dashed) and θ/α [–] against the right one (its own
    scale), the time [s] below."""
    per_cm = length_value(1.0, system)
    time_s = np.asarray(history["time_s"], dtype=float)
    step = max(1, int(np.ceil(time_s.size / SPARK_POINTS)))
    time_s = time_s[::step]
    sliding = np.asarray(history["sliding_cm"], dtype=float)[::step] * per_cm
    theta = np.clip(np.asarray(history["theta_over_alpha"], dtype=float)[::step], -3.0, 3.0)
    span = max(float(time_s[-1]), 1e-9)
    x0, x1 = SPARK_LEFT, SPARK_WIDTH - SPARK_RIGHT
    top, bottom = SPARK_TOP, SPARK_HEIGHT - SPARK_BOTTOM
    middle, half = (top + bottom) / 2.0, (bottom - top) / 2.0

    def x_of(t):
        return x0 + (x1 - x0) * np.asarray(t, dtype=float) / span

    def y_of(values, limit):
        return middle - half * np.clip(np.asarray(values, dtype=float) / max(limit, 1e-9), -1.0, 1.0)

    def points(values, limit):
        xs, ys = x_of(time_s), y_of(values, limit)
        finite = np.isfinite(xs) & np.isfinite(ys)  # the run stops where the item overturns
        return " ".join(f"{x:.1f},{y:.1f}" for x, y in zip(xs[finite], ys[finite]))

    clearance = float(history.get("clearance_cm", np.nan)) * per_cm
    sliding_limit = max(float(np.nanmax(np.abs(sliding))) if np.isfinite(sliding).any() else 0.0,
                        clearance if np.isfinite(clearance) else 0.0, 0.1)
    theta_limit = max(float(np.nanmax(np.abs(theta))) if np.isfinite(theta).any() else 0.0, 1.0)
    sliding_text, theta_text = format_significant(sliding_limit, 2), format_significant(theta_limit, 2)
    sliding_ticks = [("+" + sliding_text, top), ("0", middle), ("−" + sliding_text, bottom)]
    theta_ticks = [("+" + theta_text, top), ("0", middle), ("−" + theta_text, bottom)]
    time_ticks = [{"x": float(x_of(t)), "label": f"{t:g}"} for t in _nice_ticks(span * 1.0001)]
    blue, red, grey = "#2c3e50", "#c0392b", "#5d6d7e"
    words = [figure_word(f"sliding [{length_unit(system)}]", x0, top - 4, colour=blue, width_px=SPARK_WIDTH),
             figure_word("θ/α [–]", x1, top - 4, "end", colour=red, width_px=SPARK_WIDTH)]
    words += [figure_word(label, x0 - 3, y + 3, "end", 7.5, blue, SPARK_WIDTH) for label, y in sliding_ticks]
    words += [figure_word(label, x1 + 3, y + 3, "start", 7.5, red, SPARK_WIDTH) for label, y in theta_ticks]
    words += [figure_word(t["label"], t["x"], bottom + 12, "middle", 7.5, width_px=SPARK_WIDTH) for t in time_ticks]
    words.append(figure_word("time [s]", x1 + 4, bottom + 12, colour=grey, width_px=SPARK_WIDTH))
    return {"width": SPARK_WIDTH, "height": SPARK_HEIGHT, "x0": x0, "x1": x1, "top": top, "bottom": bottom,
            "middle": middle, "sliding": points(sliding, sliding_limit), "theta": points(theta, theta_limit),
            "sliding_limit": sliding_text, "theta_limit": theta_text, "duration": f"{span:.0f}",
            "time_ticks": time_ticks, "words": words,
            "clearance_y": float(y_of(clearance, sliding_limit)) if np.isfinite(clearance) else None,
            "motion": text(history.get("sim_motion")), "overturned": bool(history.get("overturned")),
            "direction": history.get("direction")}


def strip_label_lines(label: str, limit: int = STRIP_LABEL_CHARS) -> list[str]:
    """A motion's name on one line, or on two broken at a space, each at most ``limit`` characters; only a
    name longer than two lines is shortened (with "…"), so that no name runs under the strip's dots.

    >>> strip_label_lines("Los Gatos PC, ground (0.54 g)")
    ['Los Gatos PC, ground (0.54 g)']
    >>> strip_label_lines("Gilroy Hist. Bldg., floor 2 (interpolated) (0.71 g)", 30)
    ['Gilroy Hist. Bldg., floor 2', '(interpolated) (0.71 g)']
    """
    label = " ".join(label.split())
    if len(label) <= limit:
        return [label]
    cut = label.rfind(" ", 0, limit + 1)
    cut = cut if cut > 0 else limit
    first, rest = label[:cut].rstrip(), label[cut:].lstrip()
    return [first, rest if len(rest) <= limit else rest[: limit - 1] + "…"]


#: Most lines of an item's strip, one per motion; a larger suite is drawn as one line of all its histories.
STRIP_MAX_LINES = 24


def _suite_strip(runs: pd.DataFrame, clearance_cm: float | None, system: str = "si") -> dict | None:
    """An item's suite as a strip, one line per motion (all on one line beyond :data:`STRIP_MAX_LINES`
    motions); lengths in cm, or in inches for ``system`` ``'us'``."""
    if runs.empty:
        return None
    per_cm = length_value(1.0, system)
    sliding = pd.to_numeric(runs["sliding_cm"], errors="coerce").fillna(0.0) * per_cm
    clearance = None if clearance_cm is None else clearance_cm * per_cm  # in the report's unit
    top = max(float(sliding.max()), clearance or 0.0, 1.0) * 1.08
    scale = (STRIP_WIDTH - STRIP_LEFT - 10) / top
    motions = list(dict.fromkeys(runs["motion_key"]))
    groups = [(key, runs[runs["motion_key"] == key], None) for key in motions]
    if len(motions) > STRIP_MAX_LINES:  # a large suite: every history on one line, its density in the dots
        groups = [(None, runs, f"all {len(motions)} motions ({len(runs)} histories)")]
    lines, y = [], 15.0  # below the axis titles
    words = [figure_word("motion", STRIP_LEFT - 6, 7, "end", colour="#5d6d7e")]
    for key, mine, name in groups:
        label = strip_label_lines(name or text(mine["motion"].iloc[0]))
        extra = (len(label) - 1) * (STRIP_FONT_PX + 1)
        y += extra / 2.0  # a name on two lines starts as low as one on one line: never up against the title
        line_y = y + extra / 2.0
        sliding_of_run = pd.to_numeric(mine["sliding_cm"], errors="coerce").fillna(0.0).to_numpy(float) * per_cm
        xs = STRIP_LEFT + sliding_of_run * scale
        overturned = mine["overturned"].to_numpy(bool)
        words.append(figure_word(label, STRIP_LEFT - 6, y - extra / 2.0 + 3, "end", STRIP_FONT_PX))
        lines.append({"y": line_y,
                      "dots": strip_dot_paths(xs[~overturned], line_y),
                      "crosses": strip_crosses_path(xs[overturned], line_y)})
        y += STRIP_ROW + extra / 2.0
    axis_y = y - STRIP_ROW / 2.0 + 4
    height = axis_y + 12
    words += [figure_word(f"{t:g}", STRIP_LEFT + t * scale, axis_y + 11, "middle") for t in _nice_ticks(top)]
    words.append(figure_word(f"peak sliding of a history [{length_unit(system)}]", STRIP_LEFT - 10, axis_y + 11,
                             "end", colour="#5d6d7e"))
    return {"width": STRIP_WIDTH, "height": height, "left": STRIP_LEFT, "lines": lines, "axis_y": axis_y,
            "words": words,
            "clearance_x": None if clearance is None else STRIP_LEFT + clearance * scale}


#: A cross of the strip (an overturned history): the "×" of DejaVu Sans at 9 px, drawn as two strokes
#: [px]: half its width and height, its centre below the line's y, the width of its strokes (the glyph's
#: outline, glyph "multiply" in font units of 2048 per em: arms' ends 1376.5 - 858.5 = 518 from the centre,
#: 170 thick, centre 642 above the baseline at y + 3).
CROSS_HALF_PX, CROSS_DROP_PX, CROSS_STROKE_PX = 2.28, 0.18, 0.75


def strip_crosses_path(xs, y: float) -> str:
    """The crosses of one strip line, one at each x [px], as the ``d`` of one SVG path ("" for none): one
    path node to draw instead of one text node (laid out letter by letter by the PDF's renderer) each.

    >>> strip_crosses_path([100.0], 15.0)
    'M97.7 12.9l4.56 4.56m0-4.56l-4.56 4.56'
    """
    side = f"{2 * CROSS_HALF_PX:.2f}"
    top = y + CROSS_DROP_PX - CROSS_HALF_PX
    return "".join(f"M{x - CROSS_HALF_PX:.1f} {top:.1f}l{side} {side}m0-{side}l-{side} {side}" for x in xs)


#: Radius of a dot of the strip (a history that did not overturn) [px]; a quarter circle as a cubic Bézier curve
#: has its control points this fraction of the radius from its ends (4/3·(√2 − 1), the usual circle).
DOT_RADIUS_PX, CIRCLE_KAPPA = 2.2, 4.0 / 3.0 * (math.sqrt(2.0) - 1.0)


def strip_dot_paths(xs, y: float, radius: float = DOT_RADIUS_PX) -> list[str]:
    """The dots of one strip line, one at each x [px], as the ``d`` of a few SVG paths: each path holds dots
    that do not touch one another, so that drawn half-opaque, one path after another, dots that overlap darken
    where they overlap as separate circles do (the same colour and opacity: the order does not matter), with a
    node per path instead of per dot.

    >>> [layer.count("M") for layer in strip_dot_paths([10.0, 12.0, 20.0], 5.0)]  # 10 and 12 overlap
    [2, 1]
    >>> strip_dot_paths([10.0], 5.0)[0]  # from (12.2, 5) round through (10, 7.2), (7.8, 5), (10, 2.8)
    'M12.2 5.0c0 1.22 -0.98 2.20 -2.20 2.20s-2.20 -0.98 -2.20 -2.20s0.98 -2.20 2.20 -2.20s2.20 0.98 2.20 2.20z'
    """
    layers: list[list[float]] = []  # each layer's x, rounded as drawn, in the order given
    for x in (round(float(x), 1) for x in xs):
        for layer in layers:
            if all(abs(x - other) >= 2 * radius for other in layer):
                layer.append(x)
                break
        else:
            layers.append([x])
    r, k = radius, radius * (1.0 - CIRCLE_KAPPA)
    circle = (f"c0 {r - k:.2f} {-k:.2f} {r:.2f} {-r:.2f} {r:.2f}s{-r:.2f} {-k:.2f} {-r:.2f} {-r:.2f}"
              f"s{k:.2f} {-r:.2f} {r:.2f} {-r:.2f}s{r:.2f} {k:.2f} {r:.2f} {r:.2f}z")
    return ["".join(f"M{x + radius:.1f} {y:.1f}{circle}" for x in layer) for layer in layers]


def _nice_ticks(top: float) -> list[float]:
    """Round tick values from 0 to below ``top`` (about five)."""
    raw = top / 5.0
    magnitude = 10 ** math.floor(math.log10(raw))
    step = min((m * magnitude for m in (1, 2, 5, 10) if m * magnitude >= raw), default=magnitude * 10)
    return [k * step for k in range(int(top // step) + 1)]


def _data_uri(svg: str) -> str:
    return "data:image/svg+xml;base64," + base64.b64encode(svg.encode("utf-8")).decode("ascii")


def report_context(result, with_figures: bool = True) -> dict:
    """Everything the template shows, formatted (pure: no clock, no I/O); its ``figures``
    (:func:`report_figures`, the slow part) None where ``with_figures`` is false."""
    result = with_words(result)
    summary = _sorted_summary(result.summary)
    settings = result.settings
    system = system_of(settings)
    numbering = floor_numbering_of(settings)
    rows = [_item_row(row, system, numbering) for _, row in summary.iterrows()]
    for row, anchor in zip(rows, item_anchors([r["id"] for r in rows])):
        row["anchor"] = anchor
    counts = result.risk_counts()
    zeta, eta, sigma, im_min, im_max = figures.regression_constants(result)
    regression_short = regression_words(summary, (im_min, im_max))
    decisions = result.decisions or {}
    for row, reasons, item_id in zip(rows, regression_short["reasons"], summary["id"]):
        decision = decisions.get(item_id)
        head = decision_head(decision, settings) if decision is not None else ""
        row["table_action"] = table_action(row["action"], row["type_source"], head)
        row["regression_short"] = reasons
    return {
        "version": assess.__version__,
        "facility": text(result.facility),
        "site": text(result.site),
        "level_description": level_text(result),
        "level_label": text(result.level_label),
        "workbook": Path(result.workbook).name if result.workbook else "",
        "simulated": bool(result.simulated),
        "seed": result.seed,
        "counts": counts,
        "units": risk_units(summary),
        "total_items": len(rows),
        "total_units": total_units(summary),
        "action_groups": action_groups(rows),
        "rest_sentence": rest_sentence(rows, counts),
        "details": _item_details(rows, summary, result.suite_runs, {str(h["id"]): h for h in result.histories},
                                 system, lambda history: worst_run_text(history, result)),
        "u": report_units(system, numbering),
        "strip_max_lines": STRIP_MAX_LINES,
        "high": [r for r in rows if r["risk"] == "high"],
        "moderate": [r for r in rows if r["risk"] == "moderate"],
        "rows": rows,
        "all_items": {"order": order_sentence(summary), "demand": demand_from(summary, numbering),
                      "regression_note": regression_short["note"],
                      "action_note": action_note([r["table_action"] for r in rows])},  # said once, not per row
        "flag_groups": flag_groups(result.flags, (im_min, im_max), system),
        "flag_count": len(result.flags),
        "flag_items": len({flag.item_id for flag in result.flags}),
        "regression": {"zeta": zeta, "eta": eta, "sigma": sigma, "im_min": im_min,
                       "im_max": im_max,
                       "source": text(result.regression.source)
                       or "Konstantinidis & Makris (2010)"},
        "anchorage": anchorage_method(result.anchorage, summary),
        "class_rule": rule_text(settings),
        "class_paragraph": class_rule_paragraph(settings),
        "source_definitions": source_definitions(summary),
        "history_phrases": history_phrases(summary),
        "given_by_parameters": given_by_parameters(result),
        "regression_items": regression_items(summary),
        "hazard_limit": hazard_limit_text(result),
        "figures": report_figures(result) if with_figures else None,
        "simulation": case_outcomes(result),
        "hazard_notes": list(result.hazard_notes),
        "method_notes": method_notes(summary),
        "changes": changes(result.comparison),
        "work_orders": [{**floor, "floor": floor_text(floor["floor"], numbering)}  # labelled as every floor is
                        for floor in work_order_sentences(result.work_orders(), system,
                                                          settings.currency or "")],
        "anchorage_table": anchorage_context(result),
        "curve": curve_context(result, numbering),
        "costs": costs_context(result, {r["id"]: r["anchor"] for r in rows}),
        "title": title_block(settings, code_edition(result)),
        "route": floor_motion_route(result),
        "building": building_context(result),  # a yielding building's storeys (assess/report/building.py)
        "references": reference_rows(),
        "stylesheet": Markup(template_text(STYLESHEET_NAME)),  # our own file, not user text
    }


def report_figures(result) -> dict:
    """The report's figures (matplotlib, as SVG ``data:`` URIs), by the template's name for them, each drawn once."""
    system = system_of(result.settings)
    sorted_result = _with_summary(result, _sorted_summary(result.summary))
    drawn = {
        "demand": figures.sliding_demand_figures(sorted_result, system=system),
        "histories": [{"svg": figures.history_figure(h, system), "id": h["id"], "name": h["name"],
                       "motion": h["motion"], "sim_motion": worst_run_text(h, result), "solver": h["solver"],
                       "direction": h["direction"]}
                      for h in list(result.histories)[:HISTORY_FIGURES]],
        "fragility": figures.fragility_figure(sorted_result),
        "regression": figures.regression_figure(sorted_result),
        "simulation": (figures.simulation_vs_regression_figure(result, system)
                       if result.simulated and slides_in_both(result.motions).any() else None),
    }
    return {
        "demand": [_data_uri(svg) for svg in drawn["demand"]],
        "fragility": _data_uri(drawn["fragility"]),
        "regression": _data_uri(drawn["regression"]),
        "simulation": _data_uri(drawn["simulation"]) if drawn["simulation"] is not None else None,
        "histories": [{"uri": _data_uri(history.pop("svg")), **history} for history in drawn["histories"]],
    }


def report_units(system: str, numbering: str) -> dict:
    """The report's unit words for the template: ``length`` (cm or in), ``length_word`` (centimetres or
    inches), ``page`` (the CSS page size, A4 or letter: a US report is printed on letter paper) and
    ``floor_note`` and ``floor_sentence`` (how floors are counted, when the ground floor is labelled 1)."""
    us = system == "us"
    ground_1 = numbering == "ground_1"
    return {"length": length_unit(system), "length_word": "inches" if us else "centimetres",
            "page": "letter" if us else "A4",
            "floor_note": "ground floor = 1" if ground_1 else "",
            "floor_sentence": ("Floors are labelled as in the US, the ground floor 1 (the workbook's floor 0), "
                               "floors below ground as in the workbook (−1), in the tables, motion names, notes "
                               "and work orders alike; the CSV and summary.xlsx files' floor columns give the "
                               "workbook's numbers." if ground_1 else "")}
def code_edition(result) -> str:
    """The edition of ASCE 7 the anchorage applies ('' where the result has no anchorage)."""
    return "" if result.anchorage is None else text(result.anchorage.edition)


def _with_summary(result, summary: pd.DataFrame):
    """A copy of ``result`` whose summary is ``summary`` (the input is not mutated)."""
    return dataclasses.replace(result, summary=summary)


def render_html(result) -> str:
    """The risk report of ``result`` as one self-contained HTML document (its advice in words,
    :func:`assess.report.advice.with_words`)."""
    result = with_words(result)
    return report_template().render(report_context(result, with_figures=False), figures=report_figures(result))


def report_files(result, *, html: bool = True, pdf: bool = True, pdf_processes: int | None = None
                 ) -> dict[str, bytes]:
    """``report.html`` and/or ``report.pdf`` of ``result``, by name: the report's HTML
    (:func:`render_html`) and its PDF (:func:`assess.report.pdf.render_pdf`). ``pdf_processes``: as
    ``render_pdf`` takes its ``processes`` (1 on a cluster's worker, which may start no process).
    """
    if not (html or pdf):
        return {}
    if not pdf:
        return {"report.html": render_html(result).encode()}
    text, pdf_bytes = report_pdf(lambda: render_html(result), processes=pdf_processes)
    files = {"report.html": text.encode()} if html else {}
    files["report.pdf"] = pdf_bytes
    return files
