"""Packaged data: default settings and the paper's tables."""
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


def km2010_table3() -> pd.DataFrame:
    """Table 3 of Konstantinidis & Makris (2010), p. 1467, as transcribed.

    Columns: ``equipment``, ``mu_slow_pull``, ``mu_best_fit``, ``motion``,
    ``tp_s``, ``vp_cm_s``, ``pta_g``, ``umax_cm``, ``im``, ``edp``.
    """
    with resources.files(__package__).joinpath("km2010_table3.csv").open("r") as handle:
        return pd.read_csv(handle, comment="#")
