"""What ``assess batch`` reports across buildings: portfolio.csv's rows, changes.csv, portfolio.html.

Computed from each building's summary (the assessment's table, or the
summary.csv a kept folder holds); the page only lays the numbers out.
"""
from __future__ import annotations

import html
import io

import pandas as pd

from assess.decision.actions import ACTION_KINDS
from assess.inventory import schema

#: Columns of summary.csv the change report follows, besides the hazard-curve ones.
CHANGE_FIELDS = ("risk", "action_kind", "action", "priority", "p_beyond_clearance", "p_overturn")
#: The hazard-curve columns of summary.csv (docs/outputs.md), followed when present (their intervals are not).
CURVE_FIELDS = ("annual_rate_beyond_clearance", "annual_rate_overturn", "p50yr_beyond_clearance", "p50yr_overturn")
CHANGE_COLUMNS = ["building", "id", "name", "change", "field", "old", "new"]
RISKS = ("high", "moderate", "low", "anchored")
ACTIONS = ACTION_KINDS  # every action kind (assess.decision.actions)


def read_summary_csv(data: bytes) -> pd.DataFrame:
    """A summary.csv as written, every cell as its text ("" when empty)."""
    return pd.read_csv(io.BytesIO(data), dtype=str, keep_default_na=False)


def _curve_columns(summary: pd.DataFrame) -> list[str]:
    return [c for c in CURVE_FIELDS if c in summary.columns]


def building_row(building: str, workbook: str, level_label: str, curve: str, summary: pd.DataFrame,
                 simulated: int, reused: int) -> dict:
    """One row of portfolio.csv: the building's items by risk class and by action kind, and its cases."""
    row = {"building": building, "workbook": workbook, "level": level_label, "hazard_curve": curve,
           "items": len(summary), "units": int(summary["quantity"].sum())}
    risks = summary["risk"].value_counts()
    row.update({f"risk_{risk}": int(risks.get(risk, 0)) for risk in RISKS})
    actions = summary["action_kind"].value_counts()
    row.update({f"action_{kind}": int(actions.get(kind, 0)) for kind in ACTIONS})
    for column in _curve_columns(summary):
        values = pd.to_numeric(summary[column], errors="coerce")
        if column.startswith("annual_rate_"):  # expected number of units failing so, per year
            row[f"{column}_units_total"] = float((values * summary["quantity"]).sum(min_count=1))
        else:
            row[f"{column}_max"] = float(values.max()) if values.notna().any() else float("nan")
    row.update({"cases_simulated": simulated, "cases_reused": reused})
    return row


def changes_between(previous: dict[str, bytes], current: dict[str, bytes], names: dict[str, str]) -> pd.DataFrame:
    """What changed from the previous run's summaries to this run's, building by building.

    ``previous`` and ``current`` map a building (lower-case name) to its
    summary.csv bytes; ``names`` gives each its name as written. Values are
    compared as summary.csv writes them (6 significant digits), so a change
    is one a reader of the two files would see. Rows: ``building added`` /
    ``building removed`` (one row each), ``item added`` / ``item removed``,
    and ``changed`` with the ``field`` (:data:`CHANGE_FIELDS` and the
    hazard-curve columns) and its ``old`` and ``new`` values.
    """
    rows = []
    for key in sorted(set(previous) | set(current), key=lambda k: names.get(k, k)):
        building = names.get(key, key)
        if key not in previous:
            rows.append(dict(building=building, change="building added"))
            continue
        if key not in current:
            rows.append(dict(building=building, change="building removed"))
            continue
        old, new = read_summary_csv(previous[key]), read_summary_csv(current[key])
        if "id" not in old or "id" not in new:
            rows.append(dict(building=building, change="not compared",
                             old="the previous summary.csv has no id column"))
            continue
        old, new = old.drop_duplicates("id").set_index("id"), new.drop_duplicates("id").set_index("id")
        fields = list(CHANGE_FIELDS) + [c for c in dict.fromkeys(_curve_columns(old) + _curve_columns(new))]
        for item_id in new.index:
            name = new.at[item_id, "name"] if "name" in new else ""
            if item_id not in old.index:
                rows.append(dict(building=building, id=item_id, name=name, change="item added"))
                continue
            for column in fields:
                before = old.at[item_id, column] if column in old else ""
                after = new.at[item_id, column] if column in new else ""
                if before != after:
                    rows.append(dict(building=building, id=item_id, name=name, change="changed", field=column,
                                     old=before, new=after))
        for item_id in old.index.difference(new.index, sort=False):
            rows.append(dict(building=building, id=item_id, name=old.at[item_id, "name"] if "name" in old else "",
                             change="item removed"))
    return pd.DataFrame([{**dict.fromkeys(CHANGE_COLUMNS, ""), **row} for row in rows], columns=CHANGE_COLUMNS)


def portfolio_html(staged, compared: bool) -> str:
    """A short page: the buildings' items by risk and action, the cases simulated and reused, the changes."""
    e = html.escape
    summary, changes = staged.summary, staged.changes
    head = ["building", "level", "items", *[f"risk_{r}" for r in RISKS], *[f"action_{a}" for a in ACTIONS],
            *[c for c in summary.columns if c.startswith(CURVE_FIELDS)], "cases_simulated", "cases_reused"]
    head = [c for c in head if c in summary.columns]
    lines = ["<!doctype html>", "<html lang='en'><head><meta charset='utf-8'><title>Portfolio</title>",
             "<style>body{font-family:sans-serif;margin:2em}table{border-collapse:collapse}"
             "td,th{border:1px solid #bbb;padding:3px 8px;text-align:right}td:first-child,th{text-align:left}"
             "</style></head><body>",
             f"<h1>Portfolio: {len(summary)} building{'s' if len(summary) != 1 else ''}</h1>",
             f"<p>{staged.cases_simulated:,} cases simulated, {staged.cases_reused:,} reused from earlier runs "
             "(a case is reused when its item, its motion and the engine are unchanged).</p>",
             "<h2>Items by risk and by action, per building</h2>", "<table><tr>"
             + "".join(f"<th>{e(c)}</th>" for c in head) + "</tr>"]
    for row in summary.to_dict("records"):
        cells = []
        for c in head:
            value = row[c]
            text = ("–" if value != value else f"{value:.3g}") if isinstance(value, float) else str(value)
            if c == "building":
                text = f"<a href='{e(str(value))}/report.html'>{e(str(value))}</a>"
            else:
                text = e(text)
            cells.append(f"<td>{text}</td>")
        lines.append("<tr>" + "".join(cells) + "</tr>")
    lines.append("</table>")
    for note in staged.notes:
        lines.append(f"<p>{e(note)}</p>")
    lines.append("<h2>Changes since the previous run</h2>")
    if not compared:
        lines.append("<p>No previous run in this folder: nothing to compare with.</p>")
    elif changes.empty:
        lines.append("<p>Nothing changed.</p>")
    else:
        kinds = changes["change"].value_counts()
        lines.append("<p>" + e(", ".join(f"{n} {kind}" for kind, n in kinds.items())) + ".</p>")
        lines.append("<table><tr>" + "".join(f"<th>{c}</th>" for c in CHANGE_COLUMNS) + "</tr>")
        for row in changes.head(500).to_dict("records"):
            lines.append("<tr>" + "".join(f"<td>{e(schema.clip(str(row[c]), 200))}</td>" for c in CHANGE_COLUMNS)
                         + "</tr>")
        lines.append("</table>")
        if len(changes) > 500:
            lines.append(f"<p>… and {len(changes) - 500} more rows in changes.csv.</p>")
    lines.append("</body></html>")
    return "\n".join(lines) + "\n"
