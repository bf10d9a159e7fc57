"""The files of real runs against the declared table of output columns (``assess/data/columns.csv``).

Each CSV a run writes is read back with pandas, not with the writer's code: every column it has is declared
for it, in the declared order, and its values are of the declared dtype. The runs: the sample lab as a user
runs it (SI), and a small site-and-building workbook in US units against a previous summary, which writes
every other file the table declares (US columns, comparison, ground motions, spectrum, floors). The writer
refuses, as a bug, a column the table does not declare or values of another kind.
"""
from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest

from assess.data import output_columns
from assess.report.tables import UndeclaredColumn, as_declared, declared_csv_text
from commands import run
from workbooks import write_workbook

EQUIPMENT = [
    {"id": "G-1", "name": "incubator", "floor": 0, "height_in": 70, "width_in": 28, "depth_in": 32,
     "mass_kg": 200, "mu": 0.3, "clearance_in": 4},
    {"id": "R-2", "name": "rack", "floor": 2, "height_in": 80, "width_in": 24, "depth_in": 40,
     "mass_kg": 400, "mu": 0.35, "clearance_in": 2, "anchored": "no"},
    {"id": "A-1", "name": "cabinet", "floor": 1, "height_in": 72, "width_in": 36, "depth_in": 18,
     "mass_kg": 150, "mu": 0.4, "clearance_in": 2, "anchored": "yes"},
]
SITE = [["key", "value"], ["sds_g", 1.0], ["sd1_g", 0.6], ["suite_size", 3], ["risk_category", "IV"]]
BUILDING = [["key", "value"], ["storeys", 2], ["storey_height_m", 4.0], ["period_s", 0.3]]


def _declared(file: str) -> pd.DataFrame:
    table = output_columns()
    return table[table["file"] == file].reset_index(drop=True)


def _pattern(name: str) -> re.Pattern:
    return re.compile(re.escape(name).replace(re.escape("<T>"), r"[0-9.eE+-]+"))


def _read_back_matches(dtype: str, column: pd.Series) -> bool:
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


def check_file(path, file: str) -> list[str]:
    """Every column of the CSV at ``path`` declared for ``file``, in the declared order, of its dtype."""
    written = pd.read_csv(path, keep_default_na=True)
    declared = _declared(file)
    patterns = [_pattern(name) for name in declared["column"]]
    positions = []
    for column in written.columns:
        matches = [k for k, pattern in enumerate(patterns) if pattern.fullmatch(column)]
        assert matches, f"{file}: {column} is not declared in assess/data/columns.csv"
        positions.append(matches[0])
        dtype = declared.loc[matches[0], "dtype"]
        assert _read_back_matches(dtype, written[column]), (
            f"{file}: {column} is declared {dtype}, read {written[column].dtype}")
    assert positions == sorted(positions), f"{file}: the columns are not in the declared order"
    always = declared[(declared["when"] == "") & (declared["stage"] != "report units")]
    assert set(always["column"]) <= set(written.columns), f"{file}: a column written always is missing"
    return list(written.columns)


def test_the_lab_s_files_have_the_declared_columns(lab_run):
    scratch, done = lab_run
    assert done.returncode == 0, done.stderr
    out = scratch / "reports" / "lab-2in50"
    for file in ("summary.csv", "motions.csv", "work_orders.csv"):
        check_file(out / file, file)
    assert not any(column.endswith("_in") for column in pd.read_csv(out / "summary.csv").columns)  # SI


@pytest.fixture(scope="module")
def us_site_run(tmp_path_factory, lab_run):
    """A site-and-building workbook in inches, against the lab's summary (every item new or removed)."""
    scratch = tmp_path_factory.mktemp("columns")
    path = write_workbook(scratch / "h.xlsx", {"equipment": [dict(item) for item in EQUIPMENT], "site": SITE,
                                               "building": BUILDING})
    previous = lab_run[0] / "reports" / "lab-2in50" / "summary.csv"
    done = run(path, "--hazard", "DE", "--format", "xlsx", "--seed", "3", "--compare-with", previous,
               "--out", scratch / "out", "--quiet", cwd=scratch)
    assert done.returncode == 0, done.stderr
    return scratch / "out"


@pytest.mark.parametrize("file", ["summary.csv", "motions.csv", "work_orders.csv", "comparison.csv",
                                  "ground_motions.csv", "spectrum.csv", "floors.csv"])
def test_a_us_site_and_building_run_has_the_declared_columns(us_site_run, file):
    columns = check_file(us_site_run / file, file)
    if file == "summary.csv":  # the US columns, each after its SI column
        assert columns[columns.index("clearance_cm") + 1] == "clearance_in"
        assert columns[columns.index("demand_room_cm") + 1] == "demand_room_in"
    if file == "ground_motions.csv":
        assert sum(column.startswith("sa_") for column in columns) >= 10


def test_the_writer_refuses_an_undeclared_column_or_values_of_another_kind():
    table = pd.DataFrame({"level": ["DE"], "floor": [0], "motions": [3]})
    assert declared_csv_text("floors.csv", table).splitlines()[0] == "level,floor,motions"
    with pytest.raises(UndeclaredColumn, match="'surprise'"):
        as_declared("floors.csv", table.assign(surprise=1.0))
    with pytest.raises(UndeclaredColumn, match="'floor' is declared int64"):
        as_declared("floors.csv", table.assign(floor=[0.5]))
    with pytest.raises(UndeclaredColumn, match="'level' is declared str"):
        as_declared("floors.csv", table.assign(level=[1.0]))
    with pytest.raises(UndeclaredColumn):
        as_declared("no-such.csv", table)


def test_the_writer_puts_the_columns_in_the_declared_order():
    table = pd.DataFrame({"motions": [3], "floor": [1], "level": ["DE"]})
    assert list(as_declared("floors.csv", table).columns) == ["level", "floor", "motions"]
    spectra = pd.DataFrame({"sa_0.1s_g": [0.5], "level": ["DE"], "sa_1s_g": [0.2]})
    assert list(as_declared("ground_motions.csv", spectra).columns) == ["level", "sa_0.1s_g", "sa_1s_g"]


def test_the_anchorage_sheet_of_summary_xlsx_has_the_declared_columns(us_site_run):
    """summary.xlsx's `anchorage DE` sheet, read back with pandas (openpyxl): every column declared for
    `summary.xlsx anchorage` (`<unit>` the report's force unit: kip in this US run), in the declared order."""
    sheet = pd.read_excel(us_site_run / "summary.xlsx", sheet_name="anchorage DE")
    declared = _declared("summary.xlsx anchorage")
    names = [name.replace("<unit>", "kip") for name in declared["column"]]
    assert [column for column in names if column in sheet.columns] == list(sheet.columns)
    assert {"W_p (kip)", "F_p (kip)", "T with Omega_0 (kip)", "connections"} <= set(sheet.columns)
    assert set(sheet["connections"]) == {"none"}
