"""The workbook's columns as a table, and the parsing of headers and cells.

Each sheet is described by a :class:`SheetSpec`, a tuple of :class:`Column`
entries (docs/workbook.md). Validation is driven by that table: a column's ``kind``
picks its cell parser, its ``dimension`` the unit suffixes it accepts (see
:mod:`assess.inventory.units`), its range the plausibility check. Nothing here
raises to the user: a bad cell raises :class:`CellError`, which the reader
turns into a located :class:`~assess.errors.Problem`.
"""
from __future__ import annotations

import difflib
import math
import numbers
import re
from dataclasses import dataclass
from typing import Callable

from assess.hazard.levels import HazardLevel, parse_level as parse_hazard_level
from assess.inventory import units
from assess.inventory.units import ACCELERATION, LENGTH, MASS, PERIOD, VELOCITY, Dimension
from assess.inventory.xlsx import EXCEL_ERRORS
from openpyxl.utils import get_column_letter

#: Columns of free text, allowed in every sheet and ignored.
FREE_TEXT_COLUMNS = ("notes", "note", "source", "comment")

_TRUE = {"yes", "y", "true", "1"}
_FALSE = {"no", "n", "false", "0"}
_MONEY_HINT = ("an amount per unit in the settings' currency, 0 or more, as a plain number (12000, not "
               "'$12,000'); leave it empty where not known")
_FLOOR_HINT = "floors are numbered 0 (ground), 1, 2, ... and -1, -2, ... below ground"
_MU_HINT = ("a friction coefficient is a plain number, typically 0.2 to 0.7 "
            "(write 0.3, not 30 %); measure it with a slow pull test if unsure")


class _Unusable:
    """A cell already reported (a formula without a computed value)."""

    def __repr__(self) -> str:
        return "<unusable cell>"


#: Stands for a cell whose problem is already reported; skipped by every check.
UNUSABLE = _Unusable()


class CellError(Exception):
    """A cell that cannot be used: what is wrong and how to fix it."""

    def __init__(self, message: str, fix: str = "") -> None:
        super().__init__(message)
        self.message = message
        self.fix = fix


@dataclass(frozen=True)
class Column:
    """One column of a sheet.

    ``name`` is the header without its unit suffix; ``kind`` selects the cell
    parser (see :data:`PARSERS`); ``dimension`` is set for quantities whose
    header must carry a unit suffix; ``spec_suffix`` is the suffix docs/workbook.md
    documents. ``low``/``high`` bound the plausible value in canonical units
    (``positive``: must be > 0; ``signed``: the bound applies to the magnitude).
    ``unless_record``: required on a row that gives no ``record``.
    ``max_chars``: the longest text a text column takes (an id, a name, a path).
    """

    name: str
    kind: str
    required: bool = False
    dimension: Dimension | None = None
    spec_suffix: str = ""
    default: object = None
    low: float | None = None
    high: float | None = None
    positive: bool = False
    signed: bool = False
    unless_record: bool = False
    hint: str = ""
    max_chars: int | None = None

    def header(self, suffix: str | None = None) -> str:
        """The header for this column with ``suffix`` (default: the documented one)."""
        if self.dimension is None:
            return self.name
        return f"{self.name}_{suffix or self.spec_suffix}"

    def accepted_headers(self) -> list[str]:
        if self.dimension is None:
            return [self.name]
        suffixes = [self.spec_suffix] + [s for s in self.dimension.units if s != self.spec_suffix]
        return [self.header(s) for s in suffixes]

    @property
    def output(self) -> str:
        """Name of the canonical (SI) output column, e.g. ``height_m``."""
        if self.dimension is None:
            return self.name
        return f"{self.name}_{self.dimension.canonical}"


@dataclass(frozen=True)
class SheetSpec:
    """A sheet: its name, columns, and what one of its rows describes."""

    name: str
    columns: tuple[Column, ...]
    subject: str
    extra_required_headers: tuple[str, ...] = ()

    def column(self, name: str) -> Column:
        return next(c for c in self.columns if c.name == name)

    def accepted_headers(self) -> list[str]:
        return [h for c in self.columns for h in c.accepted_headers()]


EQUIPMENT = SheetSpec("equipment", (
    Column("id", "text", required=True, max_chars=100),
    Column("name", "text", required=True, max_chars=200),
    Column("room", "text", default="", max_chars=200),
    Column("floor", "integer", required=True, low=-5, high=200, hint=_FLOOR_HINT),
    Column("height", "number", required=True, dimension=LENGTH, spec_suffix="cm",
           low=0.05, high=6.0, positive=True),
    Column("width", "number", required=True, dimension=LENGTH, spec_suffix="cm",
           low=0.02, high=6.0, positive=True),
    Column("depth", "number", required=True, dimension=LENGTH, spec_suffix="cm",
           low=0.02, high=6.0, positive=True),
    Column("mass", "number", required=True, dimension=MASS, spec_suffix="kg",
           low=0.1, high=50000.0, positive=True),
    # empty: a default range from base and floor_finish (assess/inventory/friction.py); anchored items need none
    Column("mu", "number", low=0.01, high=1.5, positive=True, hint=_MU_HINT),
    Column("mu_static", "number", low=0.01, high=1.5, positive=True, hint=_MU_HINT),
    Column("clearance", "number", required=True, dimension=LENGTH, spec_suffix="cm",
           low=0.0, high=100.0),
    # 1 cm to 6 m, like the height: below, b/h of any base is unbounded (no real item)
    Column("cg_height", "number", dimension=LENGTH, spec_suffix="cm",
           low=0.01, high=6.0, positive=True),
    Column("anchored", "boolean", default=False),
    # on casters or a roller base: mobile by design, so tethered or its casters locked, never bolted down
    Column("casters", "boolean", default=False),
    # identical items in one row: a million is beyond any building (a large data centre
    # holds some 10^4 racks) and keeps every count exact in 64-bit integers and floats
    Column("quantity", "integer", default=1, low=1, high=1_000_000),
    Column("consequence", "consequence", default="ordinary"),
    # what its contents can do: movable (they can be moved to low shelves), fixed (built in), none; empty:
    # movable for shelving and cabinets (component type storage shelving), none otherwise
    Column("contents", "contents", default=""),
    # the lines it has: gas, fluid (both: "gas, fluid"), none; empty: from its type (a water heater: fluid)
    Column("connections", "connections", default=""),
    # the row of ASCE 7 Table 13.5-1 / 13.6-1 for the anchorage force (empty: laboratory equipment)
    Column("component_type", "component_type", default=""),
    # I_p of ASCE 7 section 13.1.3, 1.0 or 1.5 (empty: from the consequence and the Risk Category)
    Column("ip", "importance", default=math.nan),
    # the range mu may take (e.g. the paper's best-fit and slow-pull values); both or neither
    Column("mu_low", "number", low=0.01, high=1.5, positive=True, hint=_MU_HINT),
    Column("mu_high", "number", low=0.01, high=1.5, positive=True, hint=_MU_HINT),
    # what the item stands on and the floor's finish: they choose the default μ range of a row without mu
    Column("base", "text", default="", max_chars=60),
    Column("floor_finish", "text", default="", max_chars=60),
    # what the item's failure costs and what its recommended action costs, per unit, in the settings'
    # currency (assess/decision/costs.py); empty: no cost for that item
    Column("value", "number", default=math.nan, low=0.0, hint=_MONEY_HINT),
    Column("mitigation_cost", "number", default=math.nan, low=0.0, hint=_MONEY_HINT),
), subject="a piece of equipment")

HAZARD = SheetSpec("hazard", (
    Column("level", "level", required=True),
    Column("motion", "text", required=True, max_chars=200),
    Column("floor", "floor_or_all", required=True, low=-5, high=200, hint=_FLOOR_HINT),
    Column("pta", "number", dimension=ACCELERATION, spec_suffix="g", unless_record=True,
           default=math.nan, high=5.0, positive=True),
    Column("tp", "number", dimension=PERIOD, spec_suffix="s", unless_record=True,
           default=math.nan, low=0.05, high=20.0, positive=True),
    # a pulse of PTA > 0 moves the floor: |vp| = 0 has no pulse (1 mm/s is below any record's)
    Column("vp", "number", dimension=VELOCITY, spec_suffix="cm_s", default=math.nan,
           low=0.001, high=5.0, signed=True,
           hint="correct it, or leave vp empty when the pulse's velocity is not known"),
    Column("pulse", "pulse", default=""),
    Column("record", "path", default="", max_chars=255),
    # a factor beyond 100 or below 1/10,000 (a record in cm/s² read as g is 1/981) is a unit
    # mistake, not a scaling of the motion: convert the record instead
    Column("scale", "number", default=1.0, low=1e-4, high=100.0, positive=True),
    # the second horizontal component of the same motion, along the items' depth (record: their width)
    Column("record_2", "path", default="", max_chars=255),
    # the angle from the items' width axis to the component in `record`, counter-clockwise seen
    # from above (towards their depth axis); the pair is rotated by it onto the items' axes
    Column("azimuth_deg", "number", default=0.0, high=360.0, signed=True,
           hint="an angle in degrees, -360 to 360; leave it empty when the records are along the items' axes"),
), subject="a floor motion")

SETTINGS = SheetSpec("settings", (
    Column("key", "text", required=True, max_chars=100),
    Column("value", "raw"),
), subject="a setting", extra_required_headers=("value",))
#: The site's hazard and the building, key/value sheets like settings (assess/inventory/site_building.py).
SITE = SheetSpec("site", SETTINGS.columns, subject="a site value", extra_required_headers=("value",))
BUILDING = SheetSpec("building", SETTINGS.columns, subject="a building value",
                     extra_required_headers=("value",))


# ---------------------------------------------------------------- formatting

def number_text(value: float) -> str:
    """A number as a person would type it (``2286``, ``0.3``)."""
    return f"{value:.10g}"


#: Longest cell text quoted in a message; longer text is cut with an ellipsis.
QUOTE_MAX_CHARS = 80


def clip(text: str, limit: int = QUOTE_MAX_CHARS) -> str:
    """``text`` on one line, at most ``limit`` characters (cut with an ellipsis)."""
    text = re.sub(r"\s+", " ", str(text)).strip()
    text = "".join(c if c.isprintable() else "\ufffd" for c in text)
    return text if len(text) <= limit else text[:limit - 1] + "…"


def quote(value: object) -> str:
    """The offending cell value, quoted, as the user sees it; never more than
    :data:`QUOTE_MAX_CHARS` characters of it."""
    if isinstance(value, float):
        return f"'{number_text(value)}'"
    if isinstance(value, int) and not isinstance(value, bool) and abs(value) >= 10**15:
        digits = len(str(abs(value)))
        return f"'{str(value)[:12]}…' (a {digits}-digit number)"
    return f"'{clip(value)}'"


#: Words a header may use for a column's name, by the name: ``weight_lb`` is ``mass_lb`` (a pound of mass
#: is what scales weigh in; the engine takes the mass).
HEADER_WORDS = {"weight": "mass"}


def suggest(name: str, choices: list[str]) -> str | None:
    """The closest of ``choices`` to ``name``: ``name`` with a word of :data:`HEADER_WORDS` replaced, where
    that is one of them, else difflib's closest, or None.

    >>> suggest("weight_lb", ["height_m", "mass_kg", "mass_lb"])
    'mass_lb'
    """
    word, underscore, rest = name.partition("_")
    if word in HEADER_WORDS and HEADER_WORDS[word] + underscore + rest in choices:
        return HEADER_WORDS[word] + underscore + rest
    close = difflib.get_close_matches(name, choices, n=1, cutoff=0.6)
    return close[0] if close else None


# ---------------------------------------------------------------- headers

@dataclass(frozen=True)
class Header:
    """A recognised header: the column it fills and where it is."""

    column: Column
    index: int  # column number, 1-based as in Excel
    text: str  # as the user wrote it (stripped)
    letter: str  # Excel column letter
    suffix: str | None  # unit suffix for quantities


Report = Callable[..., None]  # report(message, fix, *, row, column, cell)


def map_headers(spec: SheetSpec, header_row: dict[int, object],
                rows: list[tuple[int, dict[int, object]]], report: Report) -> dict[str, Header]:
    """Recognise the header row (``header_row``: cells of row 1 by 1-based column) of a sheet.

    ``rows`` are the data rows ``(row number, cells by column)``. Returns the
    recognised headers by column name. Unknown, unit-less, badly-suffixed and
    duplicated headers, values under no header and missing required columns
    are reported through ``report``.
    """
    found: dict[str, Header] = {}
    flawed: set[str] = set()  # columns whose header was reported as wrong
    for column_number in sorted(header_row):
        raw = header_row[column_number]
        letter = get_column_letter(column_number)
        if is_empty(raw) or raw is UNUSABLE:
            continue
        text = str(raw).strip()
        cell = f"{letter}1"
        key = text.lower()
        if key in FREE_TEXT_COLUMNS:
            continue
        column, suffix, problem = _classify(spec, key, text)
        if problem is not None:
            report(problem[0], problem[1], row=1, column=clip(text), cell=cell)
            if column is not None:
                flawed.add(column.name)
            continue
        if column.name in found:
            first = found[column.name]
            report(f"columns '{first.text}' ({first.letter}1) and '{text}' ({cell}) both give "
                   f"{column.name}.", "keep one of the two columns and delete the other.",
                   row=1, column=text, cell=cell)
            continue
        found[column.name] = Header(column, column_number, text, letter, suffix)
    _check_headerless_data(header_row, rows, report)
    _report_missing(spec, found, flawed, report)
    return found


def _check_headerless_data(header_row: dict[int, object], rows: list[tuple[int, dict]],
                           report: Report) -> None:
    """Columns holding values below an empty header, each reported once at its first value."""
    first_value: dict[int, int] = {}
    for number, cells in rows:
        for column_number, value in cells.items():
            if column_number not in first_value and is_empty(header_row.get(column_number)) \
                    and not is_empty(value):
                first_value[column_number] = number
    for column_number in sorted(first_value):
        letter = get_column_letter(column_number)
        report(f"column {letter} holds values (e.g. {letter}{first_value[column_number]}) but has "
               "no header.",
               f"write the column's name in {letter}1, "
               "or delete the values if they are not needed.",
               row=1, cell=f"{letter}1")


def _classify(spec: SheetSpec, key: str, text: str):
    """``(column, suffix, None)`` for a known header.

    Otherwise ``(column meant or None, None, (message, fix))``.
    """
    for column in spec.columns:
        if column.dimension is None and key == column.name:
            return column, None, None
    quantities = sorted((c for c in spec.columns if c.dimension is not None),
                        key=lambda c: len(c.name), reverse=True)
    for column in quantities:
        if key == column.name:
            return column, None, (
                f"the column '{text}' does not say its unit.",
                f"name it with its unit suffix: {or_list(column.accepted_headers())}.")
        if key.startswith(column.name + "_"):
            suffix = key[len(column.name) + 1:]
            if suffix in column.dimension.units:
                return column, suffix, None
            return column, None, (
                f"'{clip(suffix, 40)}' is not an accepted unit for {column.name}.",
                f"convert the values to one of the accepted units and name the column "
                f"{or_list(column.accepted_headers())}.")
    close = suggest(key, spec.accepted_headers())
    message = f"unknown column '{clip(text, 60)}'" + (f"; did you mean '{close}'?" if close else ".")
    elsewhere = [other.name for other in (EQUIPMENT, HAZARD, SETTINGS)
                 if other is not spec and key in other.accepted_headers()]
    if elsewhere:
        message = f"unknown column '{clip(text, 60)}' (a column of sheet '{elsewhere[0]}', not of this one)."
    fix = (f"rename it to '{close}' if that is what it holds" if close else
           f"use the columns of sheet '{spec.name}': {_column_list(spec)}")
    fix += f"; a column of remarks may be named {or_list(list(FREE_TEXT_COLUMNS))}."
    # the suggested column counts as flawed, not missing: one problem, one fix
    meant = next((c for c in spec.columns if close in c.accepted_headers()), None)
    return meant, None, (message, fix)


def _report_missing(spec: SheetSpec, found: dict, flawed: set, report: Report) -> None:
    for column in spec.columns:
        if column.name in found or column.name in flawed:
            continue
        if column.required or column.name in spec.extra_required_headers:
            report(f"the required column '{column.header()}' is missing.",
                   f"add a column headed {or_list(column.accepted_headers())} in row 1.",
                   row=1, column=column.header())
        elif column.unless_record and "record" not in found:
            report(f"the column '{column.header()}' is missing, and there is no 'record' column.",
                   f"add a column headed {or_list(column.accepted_headers())} in row 1, "
                   f"or a 'record' column naming each motion's acceleration record.",
                   row=1, column=column.header())


def _column_list(spec: SheetSpec) -> str:
    """``id, name, ..., height_cm (or _m, _mm, _in, _ft), ...``"""
    names = []
    for column in spec.columns:
        others = [s for s in (column.dimension.units if column.dimension else ())
                  if s != column.spec_suffix]
        alternatives = f" (or {', '.join('_' + s for s in others)})" if others else ""
        names.append(column.header() + alternatives)
    return ", ".join(names)


def or_list(items: list[str]) -> str:
    if len(items) == 1:
        return items[0]
    return ", ".join(items[:-1]) + " or " + items[-1]


# ---------------------------------------------------------------- cells

def is_empty(value: object) -> bool:
    return value is None or (isinstance(value, str) and value.strip() == "")


def parse_text(value: object, column: Column) -> str:
    if isinstance(value, float) and value.is_integer() and abs(value) < 2**53:
        text = str(int(value))
    else:
        text = str(value).strip()
    if text in EXCEL_ERRORS:
        raise CellError(f"the cell shows the Excel error {text}.",
                        "correct the formula so that it gives a value, or type the value.")
    if column.max_chars is not None and len(text) > column.max_chars:
        raise CellError(f"the text is {len(text):,} characters long ({quote(text)}); "
                        f"{column.name} takes at most {column.max_chars}.",
                        "shorten it (put remarks in a 'notes' column).")
    return text


def parse_path(value: object, column: Column) -> str:
    """A file path: text, never a number (a number cell is a value typed in the wrong column)."""
    if isinstance(value, numbers.Number):
        raise CellError(f"{quote(value)} is a number, not the path of a record file.",
                        "write the record file's name (e.g. records/lg.csv, relative to the "
                        "workbook's folder), or leave the cell empty.")
    text = str(value).strip()
    if len(text) > column.max_chars:
        raise CellError(f"the record path is {len(text):,} characters long ({quote(text)}); a "
                        f"path is read up to {column.max_chars}.",
                        "move the record file nearer the workbook (e.g. into a folder 'records' "
                        "beside it) and give its path relative to the workbook's folder.")
    text = parse_text(text, column)
    if any(not c.isprintable() for c in text):
        raise CellError("the record path holds control characters (line breaks, tabs).",
                        "write the record file's name on one line.")
    return text


def parse_number(value: object, column: Column) -> float:
    if isinstance(value, bool):
        raise CellError(f"{quote(value)} is not a number.", "type a number.")
    if isinstance(value, numbers.Real):
        try:
            number = float(value)
        except OverflowError:  # an integer of hundreds of digits
            number = math.inf
    elif isinstance(value, str) and value.strip() in EXCEL_ERRORS:
        raise CellError(f"the cell shows the Excel error {quote(value.strip())}.",
                        "correct the formula so that it gives a number, or type the value.")
    elif isinstance(value, str):
        try:
            number = float(value.strip())
        except ValueError:
            raise CellError(f"{quote(value)} is not a number.", _number_fix(column)) from None
    else:  # dates, times
        kind = type(value).__name__
        raise CellError(f"{quote(value)} is not a number (the cell holds a {kind}).",
                        _number_fix(column))
    if not math.isfinite(number):
        raise CellError(f"{quote(value)} is not a finite number (it is beyond what a computer "
                        "represents, about 1.8e308).", _number_fix(column))
    return number


def _number_fix(column: Column) -> str:
    if column.dimension is not None:
        return ("type the number alone; the unit is given by the column header "
                f"(e.g. {column.header()}).")
    return "type a plain number."


def parse_integer(value: object, column: Column) -> int:
    number = parse_number(value, column)
    if not number.is_integer():
        raise CellError(f"{quote(value)} is not a whole number.",
                        "type a whole number" + (f"; {column.hint}." if column.hint else "."))
    return int(number)


def parse_boolean(value: object, column: Column) -> bool:
    if isinstance(value, bool):
        return value
    text = parse_text(value, column).lower()
    if text in _TRUE:
        return True
    if text in _FALSE:
        return False
    raise CellError(f"{quote(value)} is not yes or no.",
                    "write yes or no (y/n, true/false and 1/0 are also accepted), "
                    "or leave the cell empty for no.")


def parse_floor_or_all(value: object, column: Column) -> int | str:
    if isinstance(value, str) and value.strip().lower() == "all":
        return "all"
    try:
        return parse_integer(value, column)
    except CellError:
        raise CellError(f"{quote(value)} is neither a floor number nor 'all'.",
                        f"write the floor as a whole number ({_FLOOR_HINT}), "
                        "or 'all' for a motion that acts on every floor.") from None


def parse_pulse(value: object, column: Column) -> str:
    text = parse_text(value, column).upper()
    if text not in ("A", "B", "C"):
        raise CellError(f"{quote(value)} is not a pulse type.",
                        "write A, B or C (the Makris pulse types), or leave the cell empty.")
    return text


#: What an item's failure may cost (docs/workbook.md, ``consequence``), most severe first.
CONSEQUENCES = ("life-safety", "hazardous", "critical", "valuable", "ordinary")


def parse_consequence(value: object, column: Column) -> str:
    """One of :data:`CONSEQUENCES`, written in any case, with a space or an underscore for the hyphen.

    >>> parse_consequence(" Life Safety ", None), parse_consequence("HAZARDOUS", None)
    ('life-safety', 'hazardous')
    """
    text = str(value).strip().lower().replace("_", "-").replace(" ", "-")
    if text not in CONSEQUENCES:
        raise CellError(f"{quote(value)} is not a consequence.",
                        "write one of " + ", ".join(CONSEQUENCES) + " (what a failure of the item costs), "
                        "or leave the cell empty for ordinary.")
    return text


#: What an item's contents can do (docs/workbook.md, ``contents``).
CONTENTS = ("movable", "fixed", "none")


def parse_contents(value: object, column: Column) -> str:
    """One of :data:`CONTENTS`, in any case.

    >>> parse_contents(" Fixed ", None), parse_contents("NONE", None)
    ('fixed', 'none')
    """
    text = str(value).strip().lower()
    if text not in CONTENTS:
        raise CellError(f"{quote(value)} is not a kind of contents.",
                        "write movable (contents that can be moved to the lowest shelves), fixed (built in or "
                        "fastened) or none, or leave the cell empty: from the item's type (movable for shelving "
                        "and storage cabinets, none otherwise).")
    return text


#: The lines an item may have (docs/workbook.md, ``connections``; assess/data/connections.csv), and ``none``.
CONNECTIONS = ("gas", "fluid")


def parse_connections(value: object, column: Column) -> str:
    """The lines an item has: words of :data:`CONNECTIONS` separated by commas or semicolons, in any case and
    order, as ``"gas, fluid"`` (in that order); ``"none"`` for none.

    >>> parse_connections(" Fluid; GAS ", None), parse_connections("none", None)
    ('gas, fluid', 'none')
    """
    words = [word.strip().lower() for word in re.split(r"[,;]", str(value)) if word.strip()]
    unknown = [word for word in words if word not in (*CONNECTIONS, "none")]
    if unknown or not words or ("none" in words and len(words) > 1):
        raise CellError(f"{quote(value)} is not a list of connections.",
                        "write gas (a fuel or medical gas line), fluid (water, drain or other liquid lines), "
                        "both as 'gas, fluid', or none; or leave the cell empty: from the item's type (a water "
                        "heater has fluid lines, and a gas line where its name says gas).")
    return ", ".join(line for line in CONNECTIONS if line in words) or "none"


def parse_component_type(value: object, column: Column) -> str:
    """A component type of ASCE 7 Tables 13.5-1 / 13.6-1 (``assess/data/components.csv``), by its name or an
    alias in any case, as the table names it.

    >>> parse_component_type(" UPS ", None), parse_component_type("Server_Rack", None)
    ('battery rack', 'computer rack')
    """
    from assess.anchorage.coefficients import component_coefficients, component_types
    try:
        return component_coefficients("ASCE 7-22", str(value)).component_type
    except ValueError:
        raise CellError(f"{quote(value)} is not a component type.",
                        "write one of " + ", ".join(component_types()) + " (or an alias such as freezer, UPS, "
                        "server rack, switchgear), or leave the cell empty for laboratory equipment.") from None


def parse_importance(value: object, column: Column) -> float:
    """I_p of ASCE 7 section 13.1.3: 1.0 or 1.5, the only values it assigns.

    >>> parse_importance("1.5", None), parse_importance(1, None)
    (1.5, 1.0)
    """
    try:
        number = float(str(value).strip())
    except ValueError:
        number = math.nan
    if number not in (1.0, 1.5):
        raise CellError(f"{quote(value)} is not a component importance factor.",
                        "write 1.5 (needed for life safety, hazardous contents, or needed to operate a Risk "
                        "Category IV facility: ASCE 7 section 13.1.3) or 1.0, or leave the cell empty to have it "
                        "from the consequence and the site's risk category.")
    return number


def parse_level_cell(value: object, column: Column) -> HazardLevel:
    try:
        return parse_hazard_level(parse_text(value, column))
    except ValueError as error:
        raise CellError(str(error).rstrip(".") + ".",
                        "write a probability (2in50, 2%/50yr and 2475yr are the same level and "
                        "may be mixed) or a label such as DE, MCE_R or test.") from None


def parse_raw(value: object, column: Column) -> object:
    return value


PARSERS = {
    "text": parse_text,
    "path": parse_path,
    "number": parse_number,
    "integer": parse_integer,
    "boolean": parse_boolean,
    "floor_or_all": parse_floor_or_all,
    "pulse": parse_pulse,
    "consequence": parse_consequence,
    "component_type": parse_component_type,
    "contents": parse_contents,
    "connections": parse_connections,
    "importance": parse_importance,
    "level": parse_level_cell,
    "raw": parse_raw,
}


def parse_cell(value: object, column: Column, suffix: str | None, subject: str) -> object:
    """Parse a non-empty cell of ``column``: typed, converted to canonical units, range-checked.

    Raises :class:`CellError` when the cell cannot be used.
    """
    parsed = PARSERS[column.kind](value, column)
    if column.kind in ("number", "integer") or (column.kind == "floor_or_all" and parsed != "all"):
        check_range(parsed, column, suffix, subject)
        if column.dimension is not None:
            return units.to_canonical(parsed, column.dimension, suffix)
    return parsed


def check_range(value: float, column: Column, suffix: str | None, subject: str) -> None:
    """Raise :class:`CellError` when ``value`` (in ``suffix`` units) is not plausible."""
    dimension = column.dimension
    canonical = units.to_canonical(value, dimension, suffix) if dimension else float(value)
    given = f"{column.name} {number_text(value)}"
    if dimension is not None:
        given += f" {units.label(dimension, suffix)}"
        if suffix != dimension.canonical:
            given += f" = {canonical:.3g} {units.label(dimension, dimension.canonical)}"
    if column.positive and canonical <= 0:
        raise CellError(f"{given} must be greater than 0.", _range_fix(column, value, suffix))
    magnitude = abs(canonical) if column.signed else canonical
    too_low = column.low is not None and magnitude < column.low
    too_high = column.high is not None and magnitude > column.high
    if too_low or too_high:
        raise CellError(f"{given} is not plausible for {subject} (expected {_expected(column)}).",
                        _range_fix(column, value, suffix))


def _expected(column: Column) -> str:
    dimension = column.dimension
    unit = f" {units.label(dimension, dimension.canonical)}" if dimension else ""
    low, high = column.low, column.high
    if column.signed and low is not None:
        return f"a magnitude of {number_text(low)} to {number_text(high)}{unit}"
    if column.signed:
        return f"a magnitude of at most {number_text(high)}{unit}"
    if low is None and column.positive:
        return f"more than 0 and at most {number_text(high)}{unit}"
    if high is None:
        return f"at least {number_text(low)}{unit}"
    return f"{number_text(low)} to {number_text(high)}{unit}"


def _range_fix(column: Column, value: float, suffix: str | None) -> str:
    if column.dimension is None:
        return (column.hint + "." if column.hint else "correct the value.")
    low = column.low if column.low is not None else 0.0
    high = column.high if column.high is not None else math.inf
    others = units.alternative_suffixes(value, column.dimension, suffix, low, high,
                                        signed=column.signed)
    if column.positive:
        others = [s for s in others if units.to_canonical(value, column.dimension, s) > 0]
    if not others:
        return column.hint + "." if column.hint else "correct the value."
    label = units.label
    parts = [f"if the values are in {label(column.dimension, others[0])}, "
             f"name the column {column.header(others[0])}"]
    parts += [f"if in {label(column.dimension, s)}, {column.header(s)}" for s in others[1:]]
    return "; ".join(parts) + "; otherwise correct the value."
