"""Tables as the files show them: CSV text, protected from spreadsheet formulas, with the columns declared.

Used by every writer of a table (:mod:`assess.command.output`, :mod:`assess.report.spreadsheet`,
:mod:`assess.portfolio.batch`), so that it depends on nothing but pandas and the packaged data. The columns of
the tables a run writes are declared in one table, ``assess/data/columns.csv``
(:func:`assess.data.output_columns`: name, unit, dtype, meaning, owning stage); :func:`assess.data.as_declared`
puts a table's columns in its order and refuses, as a bug, a column it does not declare or values of another
kind (it lives in :mod:`assess.data`, below every package, so that ``fragility/`` can check its files too).
"""
from __future__ import annotations

import re

import pandas as pd

from assess.data import as_declared

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


def declared_csv_text(file: str, table: pd.DataFrame) -> str:
    """:func:`csv_text` of ``table`` with its columns as declared for ``file`` (:func:`as_declared`)."""
    return csv_text(as_declared(file, table))
