"""A CSV as written, read back with pandas (not with the writer's code), against the declared table of output
columns (``assess/data/columns.csv``): :func:`check_file`.

Used by the tests of every writer of a CSV (tests/command/test_output_columns.py for the assessment's files,
the fragility, calibration and portfolio tests for theirs), so that each file of a real run is checked where
that run is made.
"""
from __future__ import annotations

import io
import re

import numpy as np
import pandas as pd

from assess.data import output_columns


def declared(file: str) -> pd.DataFrame:
    """The rows of ``assess/data/columns.csv`` for ``file``, in order."""
    table = output_columns()
    return table[table["file"] == file].reset_index(drop=True)


def _pattern(name: str) -> re.Pattern:
    return re.compile(re.escape(name).replace(re.escape("<T>"), r"[0-9.eE+-]+"))


def read_back_matches(dtype: str, column: pd.Series) -> bool:
    """What pandas reads back from a column of the declared dtype (empty cells aside): numbers for float64
    (whole ones read as int64), whole numbers for int64, True/False for bool, anything for str (a text
    column of numbers, such as a floor label, reads back as numbers)."""
    values = column.dropna()
    if not len(values) or dtype == "str":
        return True
    if dtype == "bool":
        return set(values.astype(str)) <= {"True", "False"}
    if not pd.api.types.is_numeric_dtype(values) or pd.api.types.is_bool_dtype(values):
        return False
    return dtype == "float64" or bool(np.all(np.mod(values.to_numpy(dtype=float), 1.0) == 0.0))


def check_file(source, file: str) -> list[str]:
    """Every column of the CSV ``source`` (a path, or the file's bytes) declared for ``file``, in the declared
    order, of its dtype, and every column declared as always written there; returns the columns written."""
    written = pd.read_csv(io.BytesIO(source) if isinstance(source, bytes) else source, keep_default_na=True)
    table = declared(file)
    assert len(table), f"{file} is not a file of assess/data/columns.csv"
    patterns = [_pattern(name) for name in table["column"]]
    positions = []
    for column in written.columns:
        matches = [k for k, pattern in enumerate(patterns) if pattern.fullmatch(column)]
        assert matches, f"{file}: {column} is not declared in assess/data/columns.csv"
        positions.append(matches[0])
        dtype = table.loc[matches[0], "dtype"]
        assert read_back_matches(dtype, written[column]), (
            f"{file}: {column} is declared {dtype}, read {written[column].dtype}")
    assert positions == sorted(positions), f"{file}: the columns are not in the declared order"
    always = table[(table["when"] == "") & (table["stage"] != "report units")]
    assert set(always["column"]) <= set(written.columns), f"{file}: a column written always is missing"
    return list(written.columns)
