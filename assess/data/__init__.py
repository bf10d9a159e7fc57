"""Packaged data: default settings, the paper's tables and the declared output columns.

:func:`as_declared` checks a table about to be written against the declared columns; it lives here, below every
package, so that every writer of a CSV (``report/``, ``portfolio/``, ``fragility/``) can call it.
"""
from __future__ import annotations

import functools
import numbers
import re
import tomllib
from importlib import resources

import numpy as np
import pandas as pd


def default_settings() -> dict:
    """The default ``settings`` (regression constants, risk thresholds), a fresh dict."""
    with resources.files(__package__).joinpath("defaults.toml").open("rb") as handle:
        return tomllib.load(handle)


def output_columns() -> pd.DataFrame:
    """Every column of the tables a run writes (``columns.csv``), one row each, in the order the files show them.

    Columns (all text): ``file`` (``summary.csv``, ``motions.csv``, ...), ``column`` (its name; ``<T>`` stands for
    a number, as in ``sa_<T>s_g``, and ``<unit>`` for the report's force unit, ``kN`` or ``kip``), ``unit`` (SI, ``–``
    for a pure number, ``text``, ```True`/`False```; "(per report units)" where the column is converted when the file is
    written), ``dtype`` (``str``, ``float64``, ``int64`` or ``bool``: the kind of its values, empty cells aside),
    ``stage`` (the stage whose output it is: ``inventory``, ``demand``, ``decision``, ``anchorage``, ``costs``,
    ``curve``, ``report`` (the advice's words and kips, :mod:`assess.report.advice`), ...), ``when``
    (empty: always written; else when: ``us units``, ``hazard curve``, ``a site sheet``, ...) and ``meaning``
    (as ``docs/outputs.md`` gives it; tests/project/test_docs.py checks that page against this table).
    """
    with resources.files(__package__).joinpath("columns.csv").open("r", encoding="utf-8") as handle:
        return pd.read_csv(handle, dtype=str, keep_default_na=False)


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


def km2010_table3() -> pd.DataFrame:
    """Table 3 of Konstantinidis & Makris (2010), p. 1467, as transcribed.

    Columns: ``equipment``, ``mu_slow_pull``, ``mu_best_fit``, ``motion``,
    ``tp_s``, ``vp_cm_s``, ``pta_g``, ``umax_cm``, ``im``, ``edp``.
    """
    with resources.files(__package__).joinpath("km2010_table3.csv").open("r") as handle:
        return pd.read_csv(handle, comment="#")
