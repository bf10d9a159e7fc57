"""The ``building`` sheet's key/value rows, checked, into the building's modes.

Keys (docs/workbook.md, sheet ``building``): ``storeys``; ``height_m`` (roof above the
ground floor) or ``storey_height_m`` (uniform storeys), not both; ``system`` (one of
:data:`~assess.building.period.SYSTEMS`, any case); ``period_s`` (T_1 where known,
overriding ASCE 7's T_a); ``damping`` (modal damping ratio, default 0.05). Every problem
is collected and raised as one :class:`~assess.errors.InputError` naming the sheet, the
key's row, what is wrong and how to fix it; the cell's text is never echoed.
"""
from __future__ import annotations

import math
from typing import Mapping, Optional

from assess.errors import InputError, Problem

from .modes import DEFAULT_DAMPING, BuildingModes, building_modes
from .period import SYSTEMS

SHEET = "building"
KEYS = ("storeys", "height_m", "storey_height_m", "system", "period_s", "damping")
#: Plausible bounds: a storey 2-10 m high, up to 200 storeys, T_1 0.02-15 s, damping below 30 %.
STOREYS_MAX = 200
STOREY_HEIGHT_RANGE_M = (2.0, 10.0)
PERIOD_RANGE_S = (0.02, 15.0)
DAMPING_RANGE = (0.0, 0.3)


def _number(value) -> Optional[float]:
    if isinstance(value, bool):
        return None
    try:
        number = float(value)
    except (TypeError, ValueError):
        return None
    return number if math.isfinite(number) else None


def modes_from_sheet(values: Mapping[str, object], *, file: str,
                     rows: Optional[Mapping[str, int]] = None) -> BuildingModes:
    """The building's modes from the ``building`` sheet's values, or an InputError listing every problem.

    Parameters
    ----------
    values : mapping
        Key (as written in the sheet, any case) to its cell's value; empty cells may be
        None or absent.
    file : str
        The workbook, for the messages.
    rows : mapping, optional
        Key to its row in the sheet, for the messages.

    Examples
    --------
    >>> modes = modes_from_sheet({"storeys": 4, "height_m": 16, "system": "Shear wall"}, file="h.xlsx")
    >>> modes.storeys, round(float(modes.periods_s[0]), 3), modes.period_source  # 0.0488 × 16^0.75 = 0.0488 × 8
    (4, 0.39, 'ASCE 7 Table 12.8-2 (shear wall)')
    """
    values = {str(k).strip().lower(): v for k, v in values.items() if v is not None and str(v).strip() != ""}
    rows = {str(k).strip().lower(): r for k, r in (rows or {}).items()}
    problems = []

    def problem(key, message, fix):
        problems.append(Problem(file=file, sheet=SHEET, row=rows.get(key), column="value",
                                message=f"'{key}': {message}", fix=fix))

    for key in values:
        if key not in KEYS:
            problems.append(Problem(file=file, sheet=SHEET, row=rows.get(key), column="key",
                                    message="a key this sheet does not know",
                                    fix=f"use the keys {', '.join(KEYS)}, or delete the row."))
    storeys = _number(values.get("storeys"))
    if storeys is None or storeys != int(storeys) or not 1 <= storeys <= STOREYS_MAX:
        problem("storeys", "needs a whole number of storeys above ground" if "storeys" in values
                else "is missing", f"give the storeys above ground, 1 to {STOREYS_MAX} (the roof is floor 'storeys').")
        storeys = None
    storey_height = None
    if ("height_m" in values) == ("storey_height_m" in values):
        problem("height_m", "give the roof's height or the storey height" if "height_m" not in values
                else "both height_m and storey_height_m are given",
                "give height_m (roof above the ground floor) or storey_height_m (uniform storeys), one of them.")
    elif storeys is not None:
        key = "height_m" if "height_m" in values else "storey_height_m"
        number = _number(values[key])
        storey_height = None if number is None else (number / storeys if key == "height_m" else number)
        low, high = STOREY_HEIGHT_RANGE_M
        if storey_height is None or not low <= storey_height <= high:
            problem(key, "is not a height in metres giving storeys of 2 to 10 m",
                    "give the height in metres (a workbook in feet: height_ft is not read here; convert it).")
            storey_height = None
    system = str(values.get("system", "other")).strip().lower()
    if system not in SYSTEMS:
        problem("system", "is not a lateral system this sheet knows", f"use one of: {', '.join(SYSTEMS)}.")
    period = None
    if "period_s" in values:
        period = _number(values["period_s"])
        if period is None or not PERIOD_RANGE_S[0] <= period <= PERIOD_RANGE_S[1]:
            problem("period_s", "is not a period in seconds between 0.02 and 15",
                    "give the building's fundamental period T1 in seconds, or leave it empty for ASCE 7's estimate.")
            period = None
    damping = DEFAULT_DAMPING
    if "damping" in values:
        damping = _number(values["damping"])
        if damping is None or not DAMPING_RANGE[0] <= damping < DAMPING_RANGE[1]:
            problem("damping", "is not a damping ratio between 0 and 0.3",
                    "give the modal damping as a ratio (0.05 for 5 %), or leave it empty for 0.05.")
    if problems:
        raise InputError(problems)
    return building_modes(int(storeys), storey_height, system=system, period_s=period, damping=damping)
