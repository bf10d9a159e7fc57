"""Packaged data: default settings, the paper's tables and the declared output columns."""
from __future__ import annotations

import sys
from importlib import resources

import pandas as pd

if sys.version_info >= (3, 11):
    import tomllib
else:  # Python 3.10: tomli is the package tomllib was made from (same API), a dependency there only
    import tomli as tomllib


def default_settings() -> dict:
    """The default ``settings`` (regression constants, risk thresholds), a fresh dict."""
    with resources.files(__package__).joinpath("defaults.toml").open("rb") as handle:
        return tomllib.load(handle)


def output_columns() -> pd.DataFrame:
    """Every column of the tables a run writes (``columns.csv``), one row each, in the order the files show them.

    Columns (all text): ``file`` (``summary.csv``, ``motions.csv``, ...), ``column`` (its name; ``<T>`` stands for
    a number, as in ``sa_<T>s_g``, and ``<unit>`` for the report's force unit, ``kN`` or ``kip``), ``unit`` (SI, ``–`` for a pure number, ``text``, ```True`/`False```;
    "(per report units)" where the column is converted when the file is written), ``dtype`` (``str``,
    ``float64``, ``int64`` or ``bool``: the kind of its values, empty cells aside), ``stage`` (the stage whose
    output it is: ``inventory``, ``demand``, ``decision``, ``anchorage``, ``costs``, ``curve``, ``report``
    (the advice's words and kips, :mod:`assess.report.advice`), ...), ``when``
    (empty: always written; else when: ``us units``, ``hazard curve``, ``a site sheet``, ...) and ``meaning``
    (as ``docs/outputs.md`` gives it; tests/project/test_docs.py checks that page against this table).
    """
    with resources.files(__package__).joinpath("columns.csv").open("r", encoding="utf-8") as handle:
        return pd.read_csv(handle, dtype=str, keep_default_na=False)


def km2010_table3() -> pd.DataFrame:
    """Table 3 of Konstantinidis & Makris (2010), p. 1467, as transcribed.

    Columns: ``equipment``, ``mu_slow_pull``, ``mu_best_fit``, ``motion``,
    ``tp_s``, ``vp_cm_s``, ``pta_g``, ``umax_cm``, ``im``, ``edp``.
    """
    with resources.files(__package__).joinpath("km2010_table3.csv").open("r") as handle:
        return pd.read_csv(handle, comment="#")
