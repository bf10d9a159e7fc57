"""The files of real runs against the declared table of output columns (``assess/data/columns.csv``).

Each CSV a run writes is read back with pandas, not with the writer's code: every column it has is declared
for it, in the declared order, and its values are of the declared dtype. The runs: the sample lab as a user
runs it (SI), and a small site-and-building workbook in US units against a previous summary, which writes
every other file of an assessment (US columns, comparison, ground motions, spectrum, floors); the files of
the fragility folder, the calibration and ``assess batch`` are checked the same way (tests/declared.py) where
the tests of those commands make them. The writer refuses, as a bug, a column the table does not declare or
values of another kind.
"""
from __future__ import annotations

import pandas as pd
import pytest

from assess.data import UndeclaredColumn, as_declared, output_columns
from assess.report.tables import declared_csv_text
from commands import run
from declared import check_file
from declared import declared as declared_table
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


@pytest.mark.parametrize("scaling", ["amplitude", "matched"])
def test_a_records_route_run_has_the_declared_columns(tmp_path, scaling):
    """A site sheet whose ground suite is selected from a records folder, beside a hazard sheet that holds its
    headers only (the site gives the hazard): the run writes every file, and ground_motions.csv names each record
    with an empty seed (a seed is a synthetic motion's). Both were refused or failed before: the empty hazard
    sheet at its row 2 (exit 2), the seed column as a bug (exit 1). The records scaled, or each matched to the
    target (``records_scaling``), which the item's demand_source says."""
    from importlib import resources
    folder = tmp_path / "records"
    folder.mkdir()
    source = resources.files("pyslammer") / "sample_ground_motions"
    for name in ("Kobe_1995_TAK-090", "Landers_1992_LCN-345", "Northridge_1994_PAC-175", "Loma_Prieta_1989_HSP-000"):
        (folder / f"{name}.csv").write_text((source / f"{name}.csv").read_text())
    site = [["key", "value"], ["sds_g", 1.0], ["sd1_g", 0.6], ["records", "records"], ["suite_size", 3],
            ["records_scaling", scaling]]
    path = write_workbook(tmp_path / "r.xlsx", {"equipment": [dict(EQUIPMENT[0])], "site": site,
                                                "hazard": [["level", "motion", "floor", "pta_g", "tp_s"]]})
    done = run(path, "--hazard", "DE", "--format", "xlsx", "--out", tmp_path / "out", "--quiet", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    check_file(tmp_path / "out" / "ground_motions.csv", "ground_motions.csv")
    ground = pd.read_csv(tmp_path / "out" / "ground_motions.csv")
    assert len(ground) == 3 and ground["seed"].isna().all() and (ground["record"] != "synthetic").all()
    assert set(ground["motion"]) < {"Kobe_1995_TAK-090", "Landers_1992_LCN-345", "Northridge_1994_PAC-175",
                                    "Loma_Prieta_1989_HSP-000"}
    summary = pd.read_csv(tmp_path / "out" / "summary.csv")
    word = "matched records" if scaling == "matched" else "scaled records"
    assert summary["demand_source"].str.contains(word).all(), summary["demand_source"].tolist()
    assert ((ground["scale_factor"] == 1.0).all()) == (scaling == "matched")


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


def test_every_csv_a_run_writes_is_declared_and_every_declared_file_is_one():
    """The CSVs the code names as its outputs (the output folder's, ``assess batch``'s, the fragility folder's)
    are the files of assess/data/columns.csv: a new file is declared, and a declared file is still written."""
    from assess.command.folders import OUTPUT_NAMES
    from assess.fragility import pelicun_export
    from assess.portfolio.batch import PORTFOLIO_FILES

    written = {name for name in OUTPUT_NAMES | set(PORTFOLIO_FILES) if name.endswith(".csv")}
    written |= {f"fragility/{pelicun_export.CSV_NAME}", f"fragility/{pelicun_export.COMPONENTS_NAME}",
                "fragility/stripes.csv"}
    assert written == {file for file in output_columns()["file"] if file.endswith(".csv")}


def test_the_fragility_writers_refuse_an_undeclared_column():
    """The fragility folder's files go through the same check (pelicun's columns are declared as pelicun
    names them)."""
    stripes = pd.DataFrame({"id": ["S1"], "mode": ["overturn"], "pfa_g": [0.3], "trials": [10], "failures": [2]})
    assert list(as_declared("fragility/stripes.csv", stripes.iloc[:, ::-1]).columns) == list(stripes.columns)
    with pytest.raises(UndeclaredColumn, match="'pfa_ms2'"):
        as_declared("fragility/stripes.csv", stripes.rename(columns={"pfa_g": "pfa_ms2"}))
    with pytest.raises(UndeclaredColumn, match="'Theta_0' is declared int64"):
        as_declared("fragility/cmp_marginals.csv", pd.DataFrame({"ID": ["S1"], "Theta_0": [1.5]}))


def test_the_anchorage_sheet_of_summary_xlsx_has_the_declared_columns(us_site_run):
    """summary.xlsx's `anchorage DE` sheet, read back with pandas (openpyxl): every column declared for
    `summary.xlsx anchorage` (`<unit>` the report's force unit: kip in this US run), in the declared order."""
    sheet = pd.read_excel(us_site_run / "summary.xlsx", sheet_name="anchorage DE")
    declared = declared_table("summary.xlsx anchorage")
    names = [name.replace("<unit>", "kip") for name in declared["column"]]
    assert [column for column in names if column in sheet.columns] == list(sheet.columns)
    assert {"W_p (kip)", "F_p (kip)", "T with Omega_0 (kip)", "connections"} <= set(sheet.columns)
    assert set(sheet["connections"]) == {"none"}
