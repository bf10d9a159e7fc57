"""Tables as the files show them: CSV text, protected from spreadsheet formulas, with the columns declared.

Used by every writer of a table (:mod:`assess.command.output`, :mod:`assess.report.spreadsheet`,
:mod:`assess.portfolio.batch`), so that it depends on nothing but pandas and the packaged data. The columns of
the tables a run writes are declared in one table, ``assess/data/columns.csv``
(:func:`assess.data.output_columns`: name, unit, dtype, meaning, owning stage); :func:`as_declared` puts a
table's columns in its order and refuses, as a bug, a column it does not declare or values of another kind.
"""
from __future__ import annotations

import functools
import numbers
import re

import numpy as np
import pandas as pd

from assess.data import output_columns

#: First characters that make a spreadsheet read a cell as a formula (OWASP, "CSV Injection"):
#: = + - @, tab and carriage return; and the quote itself, so that the prefix can be undone exactly.
_FORMULA_START = ("=", "+", "-", "@", "\t", "\r", "'")
#: Text that is a plain number (e.g. an id "-5") is no formula and is left as it is.
_PLAIN_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def neutralise_formulas(table: pd.DataFrame) -> pd.DataFrame:
    """``table`` with every text cell that a spreadsheet would run as a formula made inert.

    A cell written from user text (an item's name ``=HYPERLINK(...)``, a
    motion ``-M1``) that starts with ``=``, ``+``, ``-``, ``@``, a tab or a
    carriage return gets a single quote in front, as the OWASP "CSV
    Injection" page recommends; a spreadsheet then shows it as text. A text
    starting with a quote gets one more, so that :func:`restore_text` gives
    back exactly what was written. Only text cells change: numbers (negative
    ones included) and text that is a plain number (an id ``-5``) are left as
    they are.

    >>> table = pd.DataFrame({"name": ["=1+2", "-80 freezer", "fridge", "-5"], "x": [-1.5, 2.0, 3.0, 4.0]})
    >>> neutralise_formulas(table).to_dict("list")
    {'name': ["'=1+2", "'-80 freezer", 'fridge', '-5'], 'x': [-1.5, 2.0, 3.0, 4.0]}
    """
    out = table.copy()
    for column in out.columns:
        if _is_text(out[column]):
            out[column] = out[column].map(_neutralised)
    return out


def _is_text(column: pd.Series) -> bool:
    """Whether a column may hold text (object or string dtype); numeric columns never change."""
    return column.dtype == object or pd.api.types.is_string_dtype(column.dtype)


def _neutralised(value):
    if isinstance(value, str) and value.startswith(_FORMULA_START) and not _PLAIN_NUMBER.fullmatch(value):
        return "'" + value
    return value


def restore_text(table: pd.DataFrame) -> pd.DataFrame:
    """The text cells of a CSV written through :func:`neutralise_formulas`, as they were."""
    out = table.copy()
    for column in out.columns:
        if _is_text(out[column]):
            out[column] = out[column].map(
                lambda v: v[1:] if isinstance(v, str) and v.startswith("'") and v[1:].startswith(_FORMULA_START)
                else v)
    return out


#: Columns of the summary that hold a list (a tuple per item), and how summary.csv and summary.xlsx join it.
SUMMARY_LISTS = {"flags": "; ", "demand_source": " + "}


def summary_text(summary: pd.DataFrame) -> pd.DataFrame:
    """The summary as its files show it: each list column (:data:`SUMMARY_LISTS`) joined into one text.

    >>> summary_text(pd.DataFrame({"flags": [("uplift", "im_outside_fit"), ()], "x": [1, 2]}))["flags"].tolist()
    ['uplift; im_outside_fit', '']
    """
    out = summary.copy()
    for column, separator in SUMMARY_LISTS.items():
        if column in out:
            out[column] = out[column].map(lambda v, s=separator: s.join(v) if isinstance(v, tuple) else v)
    return out


def csv_text(table: pd.DataFrame) -> str:
    """A table as CSV text: formulas neutralised, fixed float format so that reruns compare byte for byte."""
    return neutralise_formulas(table).to_csv(index=False, float_format="%.6g", lineterminator="\n")


class UndeclaredColumn(RuntimeError):
    """A table about to be written has a column ``assess/data/columns.csv`` does not declare for its file, or
    values that are not of the column's declared dtype: a bug (declare the column, or fix the stage that made
    it), never the user's input."""


@functools.cache
def declared_columns(file: str) -> tuple[tuple[str, str], ...]:
    """``(column, dtype)`` of every column declared for ``file`` (e.g. ``summary.csv``), in order
    (:func:`assess.data.output_columns`); ``<T>`` in a name stands for a number."""
    table = output_columns()
    table = table[table["file"] == file]
    return tuple(zip(table["column"], table["dtype"]))


@functools.cache
def _patterns(file: str) -> tuple[tuple[re.Pattern, str], ...]:
    return tuple((re.compile(re.escape(name).replace(re.escape("<T>"), r"[0-9.eE+-]+")
                             .replace(re.escape("<unit>"), "(?:kN|kip)")), dtype)
                 for name, dtype in declared_columns(file))


def declared_index(file: str, column: str) -> int:
    """Where ``column`` stands among ``file``'s declared columns; :class:`UndeclaredColumn` when it is not one.

    >>> declared_index("summary.csv", "id"), declared_index("ground_motions.csv", "sa_0.061774s_g")
    (0, 8)
    """
    for index, (pattern, _) in enumerate(_patterns(file)):
        if pattern.fullmatch(column):
            return index
    raise UndeclaredColumn(f"{file} has a column {column!r} that assess/data/columns.csv does not declare: "
                           "declare it there (and in docs/outputs.md), or drop it.")


def values_are(dtype: str, column: pd.Series) -> bool:
    """Whether every value of ``column`` that is not empty is of the declared ``dtype`` (``str``, ``float64``,
    ``int64`` or ``bool``): a number (not a bool) for ``float64``, a whole number for ``int64`` (a float column
    too, where pandas holds integers beside empty cells as floats), True/False for ``bool``, text for ``str``.

    >>> values_are("int64", pd.Series([1.0, None])), values_are("int64", pd.Series([1.5]))
    (True, False)
    >>> values_are("bool", pd.Series([True, np.nan], dtype=object)), values_are("str", pd.Series([1.0]))
    (True, False)
    """
    values = column[column.notna()]
    if not len(values):
        return True
    if dtype == "bool":
        return pd.api.types.is_bool_dtype(values) or all(isinstance(v, (bool, np.bool_)) for v in values)
    if dtype == "str":
        return all(isinstance(v, str) for v in values)
    if pd.api.types.is_bool_dtype(values):
        return False
    numeric = pd.api.types.is_numeric_dtype(values) or all(
        isinstance(v, numbers.Real) and not isinstance(v, (bool, np.bool_)) for v in values)
    if dtype == "float64":
        return numeric
    if dtype == "int64":
        return numeric and bool(np.all(np.mod(values.to_numpy(dtype=float), 1.0) == 0.0))
    raise UndeclaredColumn(f"unknown dtype {dtype!r} in assess/data/columns.csv")


def as_declared(file: str, table: pd.DataFrame) -> pd.DataFrame:
    """``table`` with its columns in the order ``assess/data/columns.csv`` declares for ``file`` (its rows and
    values unchanged); :class:`UndeclaredColumn` for a column not declared for ``file`` or values not of its
    declared dtype."""
    positions = {}
    for column in table.columns:
        positions[column] = index = declared_index(file, str(column))
        dtype = _patterns(file)[index][1]
        if not values_are(dtype, table[column]):
            kinds = sorted({type(v).__name__ for v in table[column][table[column].notna()]})
            raise UndeclaredColumn(f"{file}: column {column!r} is declared {dtype} in assess/data/columns.csv but "
                                   f"holds {', '.join(kinds)} ({table[column].dtype}).")
    order = sorted(table.columns, key=positions.__getitem__)  # stable: a pattern's columns keep their order
    return table if order == list(table.columns) else table[order]


def declared_csv_text(file: str, table: pd.DataFrame) -> str:
    """:func:`csv_text` of ``table`` with its columns as declared for ``file`` (:func:`as_declared`)."""
    return csv_text(as_declared(file, table))
