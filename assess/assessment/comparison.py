"""Reassessment: what changed between a previous run's summary and this one's.

After a hazard update the same workbook is run again; a facility manager wants
to know which items changed risk class and why. :func:`compare_summaries`
matches the two ``summary.csv`` tables by item id and names, for every item,
the quantities that moved (governing PTA, mode, Pf, 84th-percentile sliding,
overturning share).
"""
from __future__ import annotations

import math
import re
import stat
from pathlib import Path

import pandas as pd

from assess.errors import InputError, Problem
from assess.quantity_text import length_text, percent_text

RISK_ORDER = {"anchored": -1, "low": 0, "moderate": 1, "high": 2}
#: Columns compared, with how each is written in the explanation.
#: The governing demand's columns (what the risk class rests on), after PTA and mode.
COMPARED = (("pta_g", "PTA", "{:.2f} g"), ("mode", "mode", "{}"), ("demand_source", "demand from", "{}"),
            ("p_beyond_clearance", "chance of sliding past the clearance", "{:.0%}"),
            ("demand_p84_cm", "84th-percentile sliding", "{:.0f} cm"),
            ("p_overturn", "chance of overturning", "{:.0%}"),
            ("p_rocking_harm", "chance of rocking that harms it", "{:.0%}"))
COMPARISON_COLUMNS = ["id", "name", "risk_before", "risk_after", "change", "why"] + [
    f"{column}_{when}" for column, _, _ in COMPARED for when in ("before", "after")]


#: The largest previous summary read [bytes] and its most rows: a summary of this tool is about 1 kB an item,
#: and a portfolio's building has at most tens of thousands of items.
MAX_PREVIOUS_BYTES = 64 * 1024 * 1024
MAX_PREVIOUS_ROWS = 100_000
_FIX = "give the summary.csv of an earlier assess run."


def read_previous_summary(path) -> pd.DataFrame:
    """A previous run's ``summary.csv``; it must have ``id`` and ``risk`` columns, a known class in every row.

    Only a regular file is opened (a pipe would block the run and a device never end), of at most
    :data:`MAX_PREVIOUS_BYTES` and :data:`MAX_PREVIOUS_ROWS` rows; a file that is not such a table is refused
    by line, never quoting its contents.
    """
    path = Path(path)
    try:
        status = path.stat()
    except OSError:
        raise InputError([Problem(file=str(path), message="the previous summary does not exist.", fix=_FIX)]) from None
    if not stat.S_ISREG(status.st_mode):
        raise InputError([Problem(file=str(path), message="the previous summary is not a regular file (a folder, "
                                  "a pipe or a device): it is not read.", fix=_FIX)])
    if status.st_size > MAX_PREVIOUS_BYTES:
        raise InputError([Problem(file=str(path), message=f"the previous summary is larger than "
                                  f"{MAX_PREVIOUS_BYTES // 2**20} MB: it is not read.", fix=_FIX)])
    try:
        table = pd.read_csv(path, dtype={"id": str}, nrows=MAX_PREVIOUS_ROWS + 1)
    except (OSError, ValueError, pd.errors.ParserError) as error:
        line = re.search(r"line (\d+)", str(error))
        where = f" (line {line.group(1)})" if line else ""
        raise InputError([Problem(file=str(path), message=f"the previous summary is not a CSV table{where}.",
                                  fix=_FIX)]) from None
    if len(table) > MAX_PREVIOUS_ROWS:
        raise InputError([Problem(file=str(path), message=f"the previous summary has more than "
                                  f"{MAX_PREVIOUS_ROWS:,} rows.", fix=_FIX)])
    missing = [c for c in ("id", "risk") if c not in table]
    if missing:
        raise InputError([Problem(file=str(path), message=f"the previous summary has no {missing} column(s).",
                                  fix=_FIX)])
    unknown = ~table["risk"].isin(list(RISK_ORDER))
    if unknown.any():
        row = int(unknown.to_numpy().argmax()) + 2  # the header is line 1
        raise InputError([Problem(file=str(path), message=f"line {row}: the risk class is not one of "
                                  f"{', '.join(RISK_ORDER)}.", fix=_FIX, row=row, column="risk")])
    return table


def _number(value):
    try:
        number = float(value)
    except (TypeError, ValueError):
        return None
    return number if math.isfinite(number) else None


def _moved(before, after, label, fmt) -> str | None:
    """'label a -> b' when the value changed (numbers by more than 0.5 % or 0.005), else None."""
    b, a = _number(before), _number(after)
    if b is not None or a is not None:
        if b is not None and a is not None and abs(a - b) <= max(0.005, 0.005 * abs(b)):
            return None
        text = [("–" if v is None else fmt(v) if callable(fmt)
                 else percent_text(v) if fmt == "{:.0%}" else fmt.format(v))
                for v in (b, a)]
        return f"{label} {text[0]} -> {text[1]}"
    sb, sa = ("" if pd.isna(v) else str(v) for v in (before, after))
    return None if sb == sa else f"{label} {sb or '–'} -> {sa or '–'}"


def compare_summaries(previous: pd.DataFrame, current: pd.DataFrame, system: str = "si") -> pd.DataFrame:
    """One row per item of either run: risk before and after, the change, and why.

    ``change`` is ``up`` / ``down`` (risk class), ``same``, ``new`` (only now)
    or ``removed`` (only before); ``why`` lists the compared quantities that
    moved, lengths in the report's unit (``system``, :mod:`assess.quantity_text`). Rows are ordered: up,
    down, new, removed, same.

    >>> before = pd.DataFrame({"id": ["A"], "name": ["fridge"], "risk": ["moderate"], "pta_g": [0.54],
    ...                        "mode": ["slide"], "p_beyond_clearance": [0.2]})
    >>> after = before.assign(risk="high", pta_g=0.71, p_beyond_clearance=0.62)
    >>> row = compare_summaries(before, after).iloc[0]
    >>> row["change"], row["why"]
    ('up', 'PTA 0.54 g -> 0.71 g; chance of sliding past the clearance 20% -> 62%')
    """
    merged = previous.add_suffix("_before").merge(
        current.add_suffix("_after"), left_on="id_before", right_on="id_after", how="outer", sort=False)
    rows = []
    for record in merged.to_dict("records"):
        item_id = record["id_after"] if isinstance(record.get("id_after"), str) else record["id_before"]
        risk_b, risk_a = record.get("risk_before"), record.get("risk_after")
        if pd.isna(risk_b):
            change = "new"
        elif pd.isna(risk_a):
            change = "removed"
        else:
            delta = RISK_ORDER.get(str(risk_a), 0) - RISK_ORDER.get(str(risk_b), 0)
            change = "up" if delta > 0 else "down" if delta < 0 else "same"
        reasons = [_moved(record.get(f"{column}_before"), record.get(f"{column}_after"), label,
                          (lambda value: length_text(value, system)) if column.endswith("_cm") else fmt)
                   for column, label, fmt in COMPARED if column in previous and column in current]
        name = record.get("name_after")
        row = {"id": item_id, "name": name if isinstance(name, str) else record.get("name_before"),
               "risk_before": "" if pd.isna(risk_b) else risk_b, "risk_after": "" if pd.isna(risk_a) else risk_a,
               "change": change, "why": "; ".join(r for r in reasons if r)}
        if change in ("up", "down") and not row["why"]:
            # same numbers, another class: the class rule or its thresholds changed since the previous run
            now = record.get("risk_reason_after")
            row["why"] = "the same chances under another class rule or thresholds" + (
                f" (now {now})" if isinstance(now, str) and now else "")
        for column, _, _ in COMPARED:
            for when in ("before", "after"):
                row[f"{column}_{when}"] = record.get(f"{column}_{when}")
        rows.append(row)
    order = {"up": 0, "down": 1, "new": 2, "removed": 3, "same": 4}
    table = pd.DataFrame(rows, columns=COMPARISON_COLUMNS)
    return table.sort_values("change", key=lambda s: s.map(order), kind="stable").reset_index(drop=True)
