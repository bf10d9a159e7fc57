"""Quantities as a reader sees them, in the unit system of the report (``'si'`` or ``'us'``).

Every length, force and moment a sentence, table or plot shows goes through these functions, so that
a report asked for in US units (``--units us``, or a workbook written in inches) says inches, pounds
and kips everywhere, and one in SI centimetres and kilonewtons. Values are always held in SI (the
result object); only their text changes. Exact conversions: 1 in = 2.54 cm (by definition),
1 lbf = 4.4482216152605 N (g = 9.80665 m/s²), 1 kip = 1000 lbf.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

from assess.inventory.units import CM_PER_IN, KG_PER_LB, M_PER_FT, N_PER_LBF  # noqa: F401 (the report's conversions)

if TYPE_CHECKING:  # the annotations only
    from assess.inventory.settings import Settings

#: The unit systems a report can be written in.
SYSTEMS = ("si", "us")


def system_of(settings_or_system) -> str:
    """``'si'`` or ``'us'`` from the settings (:class:`assess.inventory.settings.Settings`, its ``units``) or a
    system name; ``'si'`` by default."""
    if not isinstance(settings_or_system, str) and settings_or_system is not None:
        settings_or_system = settings_or_system.units
    system = str(settings_or_system or "si").strip().lower()
    return system if system in SYSTEMS else "si"


#: Relative slack before rounding up or down, so that a length typed as 8 in and held as 0.2032 m
#: (8.000000000000002 or 7.999999999999999 in back) stays 8 in.
ROUNDING_SLACK = 1e-9


def _rounded(value: float, rounding: str) -> float:
    """``value`` rounded to a whole number: ``'up'``, ``'down'`` or to the nearest; a value within
    :data:`ROUNDING_SLACK` of a whole number is that number.

    >>> _rounded(0.2032 * 100 / 2.54, "down"), _rounded(8.1, "down"), _rounded(8.1, "up")
    (8, 8, 9)
    """
    slack = ROUNDING_SLACK * max(1.0, abs(value))
    if rounding == "up":
        return math.ceil(value - slack)
    if rounding == "down":
        return math.floor(value + slack)
    return round(value)


def length_value(value_cm: float, system="si") -> float:
    """A length given in cm, in the system's unit (cm or in)."""
    return float(value_cm) / CM_PER_IN if system_of(system) == "us" else float(value_cm)


def length_unit(system="si") -> str:
    """``'cm'`` or ``'in'``."""
    return "in" if system_of(system) == "us" else "cm"


def rounded_length(value_cm: float, system="si", rounding: str = "nearest") -> int:
    """A length given in cm as a whole number of the system's unit (cm or in), rounded as
    :func:`length_text` rounds it (a table's cell and the sentence beside it then read alike).

    >>> rounded_length(20.0, "us", "down"), rounded_length(20.32, "us", "down"), rounded_length(54.2, "si", "up")
    (7, 8, 55)
    """
    return int(_rounded(length_value(value_cm, system), rounding))


def length_text(value_cm: float, system="si", rounding: str = "nearest") -> str:
    """A length (given in cm) as ``'55 cm'`` or ``'22 in'``, rounded to a whole unit (``rounding``:
    ``'nearest'``, ``'up'`` for a room to give, ``'down'`` for a room the item has).

    >>> length_text(54.2, "si", "up"), length_text(54.2, "us", "up"), length_text(20.0, "us", "down")
    ('55 cm', '22 in', '7 in')
    """
    if value_cm is None or not math.isfinite(float(value_cm)):
        return "-"
    return f"{rounded_length(value_cm, system, rounding)} {length_unit(system)}"


def force_text(value_kn: float, system="si") -> str:
    """A force (given in kN) as ``'3.4 kN'``, or in US units ``'760 lb'`` below 1 kip and ``'2.3 kip'`` above.

    >>> force_text(3.4, "si"), force_text(3.4, "us"), force_text(12.0, "us")
    ('3.4 kN', '764 lb', '2.70 kip')
    """
    if value_kn is None or not math.isfinite(float(value_kn)):
        return "-"
    if system_of(system) != "us":
        return f"{float(value_kn):.3g} kN" if abs(value_kn) < 100 else f"{float(value_kn):.0f} kN"
    pounds = float(value_kn) * 1000.0 / N_PER_LBF
    return f"{pounds:.0f} lb" if abs(pounds) < 1000.0 else f"{pounds / 1000.0:.2f} kip"


def moment_text(value_knm: float, system="si") -> str:
    """A moment (given in kN·m) as ``'1.2 kN·m'`` or ``'0.89 kip·ft'``.

    >>> moment_text(1.2, "si"), moment_text(1.2, "us")
    ('1.2 kN·m', '0.885 kip·ft')
    """
    if value_knm is None or not math.isfinite(float(value_knm)):
        return "-"
    if system_of(system) != "us":
        return f"{float(value_knm):.3g} kN·m"
    kip_ft = float(value_knm) * 1000.0 / N_PER_LBF / 1000.0 / M_PER_FT
    return f"{kip_ft:.3g} kip·ft"


def mass_text(value_kg: float, system="si") -> str:
    """A mass (given in kg) as ``'250 kg'`` or ``'551 lb'``.

    >>> mass_text(250, "si"), mass_text(250, "us")
    ('250 kg', '551 lb')
    """
    if value_kg is None or not math.isfinite(float(value_kg)):
        return "-"
    if system_of(system) != "us":
        return f"{float(value_kg):.0f} kg"
    return f"{float(value_kg) / KG_PER_LB:.0f} lb"


#: The smallest magnitude a plain number is written out to (3 decimals): a smaller one, often a float's noise
#: about zero (a rotation of 9.6e-20 of an item that only slid), reads "< 0.001" instead of a long decimal.
SMALLEST_SHOWN = 0.001


def significant_text(value, digits: int = 2) -> str:
    """``value`` to ``digits`` significant digits (0.30, 3.38, 12000), never in exponent form nor as a long
    decimal: a magnitude below :data:`SMALLEST_SHOWN` reads "< 0.001" ("> −0.001" when negative), exact zero
    "0"; "–" for a missing value.

    >>> [significant_text(v) for v in (0.4234, 12345.0, 0.996, 0.0012, 9.6e-20, -3e-7, 0.0, float("nan"))]
    ['0.42', '12000', '1.0', '0.0012', '< 0.001', '> −0.001', '0', '–']
    """
    try:
        number = float(value)
    except (TypeError, ValueError):
        return "–"
    if not math.isfinite(number):
        return "–"
    if number == 0:
        return "0"
    if abs(number) < SMALLEST_SHOWN:
        return f"< {SMALLEST_SHOWN:g}" if number > 0 else f"> −{SMALLEST_SHOWN:g}"
    decimals = digits - 1 - math.floor(math.log10(abs(number)))
    rounded = round(number, decimals)
    if rounded != 0:  # rounding may carry into the next decade (0.996 -> 1.0)
        decimals = digits - 1 - math.floor(math.log10(abs(rounded)))
        rounded = round(number, decimals)
    return f"{rounded:.{max(decimals, 0)}f}".replace("-", "−")


def percent_text(probability) -> str:
    """A probability as a whole percentage, the one way every table and sentence writes a chance:
    "<1%" and ">99%" at the ends (a chance that rounds to 0 or 100 but is not), "0%" and "100%" only when
    exact; "–" for a missing value.

    >>> [percent_text(p) for p in (0.0, 0.004, 0.39, 0.996, 1.0, float("nan"))]
    ['0%', '<1%', '39%', '>99%', '100%', '–']
    """
    try:
        number = float(probability)
    except (TypeError, ValueError):
        return "–"
    if not math.isfinite(number):
        return "–"
    if number <= 0:
        return "0%"
    if number < 0.005:
        return "<1%"
    if number >= 1:
        return "100%"
    if number > 0.995:
        return ">99%"
    return f"{100 * number:.0f}%"


#: How the report labels floors (settings ``floor_numbering``, docs/workbook.md).
FLOOR_NUMBERINGS = ("ground_0", "ground_1")


def floor_numbering_of(settings: Settings | None) -> str:
    """``'ground_0'`` or ``'ground_1'`` from the settings (:class:`assess.inventory.settings.Settings`, its
    ``floor_numbering``); ``'ground_0'`` by default (no settings)."""
    numbering = str((settings.floor_numbering if settings is not None else "") or "ground_0").strip().lower()
    return numbering if numbering in FLOOR_NUMBERINGS else "ground_0"


def floor_text(value, numbering: str = "ground_0") -> str:
    """A floor number of the workbook (0 = the ground floor) as the report labels it: as it is, or with
    ``numbering`` ``'ground_1'`` (US) counted from 1 at the ground floor, floors below ground unchanged
    (-1 is the first basement, B1, in both). The one formatter of a floor label: motion names, notes,
    work orders, sentences and figures all use it.

    >>> floor_text(0), floor_text(0, "ground_1"), floor_text(3, "ground_1"), floor_text(-1, "ground_1")
    ('0', '1', '4', '−1')
    """
    try:
        number = float(value)
    except (TypeError, ValueError):
        return "–" if value is None or str(value) in ("", "nan", "<NA>") else str(value)
    if not math.isfinite(number):
        return "–"
    if number != int(number):
        return f"{number:g}"
    shown = int(number) + 1 if numbering == "ground_1" and number >= 0 else int(number)
    return f"{shown:d}".replace("-", "−")


def runs_text(numbers, noun: str, label=str) -> str:
    """Numbers after their noun (its plural with an "s" for two or more), each as ``label`` writes it, runs of
    three or more written as a range.

    >>> runs_text([4], "storey"), runs_text(range(4, 41), "storey"), runs_text([0, 2, 3, 4, 7], "floor",
    ...                                                                        lambda f: str(f + 1))
    ('storey 4', 'storeys 4 to 40', 'floors 1, 3 to 5 and 8')
    """
    ordered = sorted({int(n) for n in numbers})
    runs: list[list[int]] = []
    for number in ordered:
        if runs and number == runs[-1][-1] + 1:
            runs[-1].append(number)
        else:
            runs.append([number])
    parts: list[str] = []
    for run in runs:
        labels = [label(n) for n in run]
        parts += [f"{labels[0]} to {labels[-1]}"] if len(run) >= 3 else labels
    words = parts[0] if len(parts) == 1 else ", ".join(parts[:-1]) + " and " + parts[-1]
    return f"{noun}{'s' if len(ordered) > 1 else ''} {words}"


def floors_text(floors, numbering: str = "ground_0") -> str:
    """Floor numbers of the workbook after "floor" or "floors", each as :func:`floor_text` labels it, runs of
    three or more written as a range (:func:`runs_text`): the one way notes, tables and pages name floors.

    >>> floors_text([0]), floors_text([3, 1, 2, 4]), floors_text([0, 2]), floors_text([0, 1, 2, 5], "ground_1")
    ('floor 0', 'floors 1 to 4', 'floors 0 and 2', 'floors 1 to 3 and 6')
    """
    return runs_text(floors, "floor", lambda f: floor_text(f, numbering))


def sentence_start(words: str) -> str:
    """``words`` with its first letter a capital, the rest as written (floor labels such as B1 kept).

    >>> sentence_start("floors 2 to 6")
    'Floors 2 to 6'
    """
    return words[:1].upper() + words[1:]
