"""The command as a user runs it, in a scratch folder.

The sample lab is run end to end once per set of formats and its outputs shared: every format
(``lab_run``, tests/conftest.py), HTML alone (``lab_html``), and a rerun with an OpenQuake curve
into a copy of the first (``lab_rerun``). What a command does with its options, its refusals and
its output folder is checked on small workbooks (tests/workbooks.py). The commands run in this
process (tests/commands.py) except where the test is about the process: Ctrl-C, a closed pipe,
the installed wheel.
"""
import json
import os
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from assess import cli
from commands import LAB, ROOT, assert_refused, child_env, location, run
from conftest import RECORD_TEXT
from declared import check_file
from workbooks import RECORD_FILE, job_sheets, write_workbook

CURVE = ROOT / "tests" / "data" / "openquake" / "case_14-hazard_curve-rlz-000_PGA.csv"
#: An OpenQuake hazard map of one site (the layout of tests/data/openquake/case_13-hazard_map-mean.csv):
#: PGA 0.11 g at 2 % in 50 years, the PGA the curve above gives there. A map scales the motions without
#: the curve's stripes.
MAP_2IN50 = "# mean, investigation_time=50.0\nlon,lat,depth,PGA-0.02\n-122.50000,38.10000,0.00000,1.100000E-01\n"
SPEC_SUMMARY = ["id", "name", "floor", "alpha_rad", "p_rad_s", "b_over_h", "mu", "mode", "pta_g", "im",
                "sliding_median_cm", "sliding_p84_cm", "clearance_cm", "pf_sliding", "overturn_fraction",
                "theta_max_over_alpha", "risk"]
SPEC_MOTIONS = ["id", "motion", "direction", "pta_g", "tp_s", "im", "edp_median", "sliding_median_cm",
                "pf_sliding", "sim_sliding_max_cm", "sim_theta_max_over_alpha", "sim_overturned"]


@pytest.fixture(scope="module")
def lab_html(tmp_path_factory):
    """The lab again, at 2475yr (the same level as 2in50), HTML only, quiet, in a fresh folder."""
    scratch = tmp_path_factory.mktemp("lab-html")
    return scratch / "o", run(LAB, "--hazard", "2475yr", "--format", "html", "--out", scratch / "o", "--quiet",
                              cwd=scratch)


@pytest.fixture(scope="module")
def lab_rerun(lab_run, tmp_path_factory):
    """The lab's first run (every format) copied to a fresh folder, then the lab rerun into it as HTML,
    the motions scaled down to an OpenQuake PGA: ``(the first run's folder, the folder rerun into, what
    the rerun returned)``."""
    scratch, done = lab_run
    assert done.returncode == 0, done.stderr
    first = scratch / "reports" / "lab-2in50"
    out = tmp_path_factory.mktemp("lab-rerun") / "lab"
    shutil.copytree(first, out)
    hazard_map = tmp_path_factory.mktemp("map") / "hazard_map-mean.csv"
    hazard_map.write_text(MAP_2IN50)
    done = run(LAB, "--hazard", "2in50", "--oq-hazard", hazard_map, "--oq-site", "0", "--out", out, "--format", "html",
               cwd=out.parent)
    return first, out, done


def job_workbook(folder: Path, sheets=None) -> Path:
    """A small workbook the main job runs in seconds (``workbooks.job_sheets``), with its record file."""
    folder.mkdir(parents=True, exist_ok=True)
    return write_workbook(folder / "wb.xlsx", job_sheets() if sheets is None else sheets,
                          files={RECORD_FILE: RECORD_TEXT})


def test_main_job_writes_the_five_files(lab_run):
    scratch, completed = lab_run
    assert completed.returncode == 0, completed.stderr
    out = scratch / "reports" / "lab-2in50"
    assert sorted(p.name for p in out.iterdir()) == ["motions.csv", "report.html", "report.pdf", "summary.csv",
                                                     "summary.xlsx", "work_orders.csv"]
    # the work orders hold every unit that needs an action, once
    orders = pd.read_csv(out / "work_orders.csv")
    acting = pd.read_csv(out / "summary.csv").query("action_kind not in ['none', 'anchored']")
    assert orders["count"].sum() == acting["quantity"].sum()
    assert sorted(i for items in orders["items"] for i in items.split(", ")) == sorted(acting["id"])
    summary = pd.read_csv(out / "summary.csv")
    motions = pd.read_csv(out / "motions.csv")
    assert set(SPEC_SUMMARY) <= set(summary.columns)
    assert set(SPEC_MOTIONS) <= set(motions.columns)
    assert summary["id"].is_unique and len(summary) >= 25
    assert set(summary["mode"].dropna()) <= {"rest", "slide", "rock", "slide-rock"}
    assert set(summary["risk"]) <= {"low", "moderate", "high", "anchored"}
    assert (out / "report.pdf").read_bytes().startswith(b"%PDF")
    assert "progress" not in completed.stdout and "items" in completed.stderr  # progress goes to stderr


def test_lab_prototypes_on_the_ground_reproduce_table3_im(lab_run):
    """The sample building holds the paper's FORMA on floor 0 under its Table 3 motions."""
    scratch, _ = lab_run
    out = scratch / "reports" / "lab-2in50"
    motions = pd.read_csv(out / "motions.csv")
    summary = pd.read_csv(out / "summary.csv")
    forma_ids = summary.loc[summary["name"].str.contains("FORMA") & (summary["floor"] == 0), "id"]
    assert len(forma_ids) == 1
    forma = motions[motions["id"].isin(forma_ids)]
    corralitos = forma[forma["motion"].str.contains("Corralitos") & (forma["pta_g"] == 0.84)]
    assert len(corralitos) > 0
    assert corralitos["im"].iloc[0] == pytest.approx(5.45, abs=0.005 / 0.13 + 0.005)


def test_summary_xlsx_has_the_rows_of_summary_csv(lab_run):
    """summary.xlsx read back with openpyxl: the same header and the same values as summary.csv, a frozen
    header, and every text cell plain text (no formula)."""
    import openpyxl

    from assess.command.output import restore_text

    scratch, _ = lab_run
    out = scratch / "reports" / "lab-2in50"
    csv = restore_text(pd.read_csv(out / "summary.csv", dtype={"id": str}, keep_default_na=False, na_values=[""]))
    book = openpyxl.load_workbook(out / "summary.xlsx", read_only=False)
    assert book.sheetnames == ["2in50", "anchorage 2in50"]  # the level, then its anchorage table
    sheet = book["2in50"]
    assert sheet.freeze_panes == "C2"
    rows = list(sheet.iter_rows(values_only=True))
    assert list(rows[0]) == list(csv.columns)
    assert len(rows) - 1 == len(csv)
    for values, (_, expected) in zip(rows[1:], csv.iterrows()):
        for value, column in zip(values, csv.columns):
            want = expected[column]
            if isinstance(want, str):
                text = value[1:] if isinstance(value, str) and value.startswith("'") else value
                assert text == want, (expected["id"], column)
            elif pd.isna(want):
                assert value is None, (expected["id"], column)
            elif np.isinf(want):
                assert value == "unbounded", (expected["id"], column)
            else:
                assert value == pytest.approx(float(want), rel=1e-5, abs=1e-9), (expected["id"], column)
    assert all(cell.data_type != "f" for row in sheet.iter_rows() for cell in row)
    anchorage = list(book["anchorage 2in50"].iter_rows(values_only=True))  # the items with a design force
    assert anchorage[0][0] == "id"
    assert [row[0] for row in anchorage[1:]] == list(csv.loc[csv["anchor_force_kn"].notna(), "id"])


def test_same_inputs_give_the_same_files(lab_run, lab_html, odd_names_run, tmp_path):
    """The lab at 2475yr gives the bytes of its run at 2in50 (the report's PDF: on the small workbook of
    odd names, run again in every format)."""
    scratch, _ = lab_run
    again, completed = lab_html
    assert completed.returncode == 0, completed.stderr
    for name in ("summary.csv", "motions.csv", "report.html"):
        assert (again / name).read_bytes() == (scratch / "reports" / "lab-2in50" / name).read_bytes()
    book, first = odd_names_run
    completed = run(book, "--hazard", "2475yr", "--out", tmp_path / "again", "--quiet", cwd=tmp_path)
    assert completed.returncode == 0, completed.stderr
    for name in ("summary.csv", "motions.csv", "report.html", "report.pdf"):
        assert (tmp_path / "again" / name).read_bytes() == (first / name).read_bytes(), name


def test_bad_workbook_exit_2_no_traceback_nothing_written(tmp_path):
    bad = tmp_path / "bad.xlsx"
    bad.write_text("this is not a workbook")
    completed = run(bad, "--hazard", "2in50", "--out", tmp_path / "out", cwd=tmp_path)
    assert completed.returncode == 2
    assert "bad.xlsx" in completed.stderr and "Traceback" not in completed.stderr
    assert_refused(completed, f"{bad}: the file is not a valid .xlsx workbook", "Nothing was written.")
    assert not (tmp_path / "out").exists()


def test_unknown_level_lists_the_levels(tmp_path):
    completed = run(LAB, "--hazard", "10in50", "--out", tmp_path / "out", cwd=tmp_path)
    assert completed.returncode == 2
    assert "'2in50'" in completed.stderr and "sheet 'hazard'" in completed.stderr
    assert_refused(completed, "no motions for hazard level '10in50'", "it has: '2in50'",
                   places=["lab.xlsx, sheet 'hazard', column 'level'"])
    assert "Traceback" not in completed.stderr and not (tmp_path / "out").exists()


def test_a_second_level_the_workbook_lacks_is_refused_before_the_first_runs(tmp_path):
    """--hazard 2in50,10in50: 2in50 is there, 10in50 is not; nothing is simulated before the refusal."""
    completed = run(LAB, "--hazard", "2in50,10in50", "--out", tmp_path / "out", cwd=tmp_path)
    assert_refused(completed, "no motions for hazard level '10in50'",
                   places=["lab.xlsx, sheet 'hazard', column 'level'"])
    assert "simulated" not in completed.stderr and "preparing the motions" not in completed.stderr
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("args, place", [
    (["--hazard", "sometimes"], "lab.xlsx, sheet 'hazard', column 'level'"),
    (["--hazard", "2in50", "--format", "docx"], "argument --format: 'docx'"),
    (["--hazard", "2in50", "--jobs", "0"], "argument --jobs: '0'"),
    (["--hazard", "2in50", "--alpha-range", "20,5"], "argument --alpha-range: '20,5'"),
    (["--hazard", "2in50", "--alpha-range", "5"], "argument --alpha-range: '5'"),
    (["--hazard", "2in50", "--alpha-range", "0.01,5"], "argument --alpha-range: '0.01,5'"),
    (["--hazard", "2in50", "--alpha-range"], "lab.xlsx, sheet 'building'"),
])
def test_wrong_option_values_exit_2(tmp_path, args, place):
    """Each wrong value is refused naming where it is: the option, or the sheet column it is looked for in."""
    completed = run(LAB, *args, cwd=tmp_path)
    assert completed.returncode == 2, args
    assert "Traceback" not in completed.stderr
    assert_refused(completed, places=[place])
    assert list(tmp_path.iterdir()) == []


def test_html_only_format(lab_html):
    out, completed = lab_html
    assert completed.returncode == 0, completed.stderr
    assert sorted(p.name for p in out.iterdir()) == ["motions.csv", "report.html", "summary.csv", "work_orders.csv"]
    assert completed.stderr == ""


def test_failure_while_rendering_leaves_old_outputs_untouched(tmp_path, monkeypatch, capsys):
    out = tmp_path / "out"
    out.mkdir()
    (out / "summary.csv").write_text("previous run\n")

    def broken(result, **_):
        raise RuntimeError("renderer crashed")

    import assess.report

    monkeypatch.setattr(assess.report, "report_files", broken)
    code = cli.main([str(job_workbook(tmp_path / "in")), "--hazard", "2in50", "--out", str(out), "--quiet"])
    assert code == 1
    assert "internal error" in capsys.readouterr().err
    assert (out / "summary.csv").read_text() == "previous run\n"
    assert sorted(p.name for p in out.iterdir()) == ["summary.csv"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in", "out"]  # no staging folder left behind


def test_help_describes_every_option(tmp_path):
    completed = run("--help", cwd=tmp_path)
    assert completed.returncode == 0
    for option in ("--hazard", "--out", "--format", "--jobs", "--seed"):
        assert option in completed.stdout


def test_installed_wheel_finds_its_templates(tmp_path):
    """Build the wheel, check it carries the templates, and render from it outside the checkout."""
    built = subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "-q", "-w", str(tmp_path), str(ROOT)],
                           capture_output=True, text=True)
    assert built.returncode == 0, built.stderr
    wheel = next(tmp_path.glob("assess-*.whl"))
    names = zipfile.ZipFile(wheel).namelist()
    assert "assess/templates/report.html.j2" in names and "assess/templates/report.css" in names
    assert "assess/templates/calibration.html.j2" in names
    packages = {str(p.relative_to(ROOT)) for p in (ROOT / "assess").rglob("__init__.py")}
    assert packages <= set(names), f"packages missing from the wheel: {sorted(packages - set(names))}"
    unpacked = tmp_path / "site"
    zipfile.ZipFile(wheel).extractall(unpacked)
    probe = ("import assess.report.render as r; from pathlib import Path; "
             "t = r.template_text('report.html.j2'); print(len(t) > 100)")
    env = {**os.environ, "PYTHONPATH": str(unpacked)}
    completed = subprocess.run([sys.executable, "-c", probe], cwd=tmp_path, env=env, capture_output=True, text=True)
    assert completed.returncode == 0, completed.stderr
    assert completed.stdout.strip() == "True"


def test_oq_hazard_scales_the_level_to_the_site_pga(tmp_path):
    """An OpenQuake curve (gem/oq-engine qa case_14) gives PGA 0.11015 g at 2 % in 50 years.

    The ground motions' geometric-mean PTA becomes that PGA (log-log interpolation
    between the curve's points written out here); every motion is scaled alike.
    """
    curve = CURVE
    done = run(job_workbook(tmp_path), "--hazard", "2475yr", "--oq-hazard", curve, "--oq-site=-122.5,38.1",
               "--out", tmp_path / "oq", "--format", "html", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    # 2 % in 50 yr lies between (0.103 g, poe 2.703533e-2) and (0.145 g, 5.818043e-3) on the curve
    import math
    x0, y0, x1, y1 = math.log(2.703533e-2), math.log(0.103), math.log(5.818043e-3), math.log(0.145)
    pga = math.exp(y0 + (math.log(0.02) - x0) * (y1 - y0) / (x1 - x0))
    motions = pd.read_csv(tmp_path / "oq" / "motions.csv")
    ground = motions[motions["floor"] == 0].drop_duplicates("motion")["pta_g"]
    assert math.exp(np.log(ground).mean()) == pytest.approx(pga, rel=1e-5)  # 2475 yr is 2 % to 1e-5
    html = (tmp_path / "oq" / "report.html").read_text()
    assert "Motions scaled by" in html and curve.name in html


def test_oq_hazard_without_the_level_is_refused(tmp_path):
    """The map holds 10 % in 50 yr only: 2 % in 50 yr is refused naming the map and the levels it has
    (its site chosen: without --oq-site a map of 21 sites is refused for that first)."""
    hazard_map = ROOT / "tests" / "data" / "openquake" / "case_13-hazard_map-mean.csv"  # 10 % in 50 yr only
    done = run(job_workbook(tmp_path), "--hazard", "2in50", "--oq-hazard", hazard_map, "--oq-site", "0",
               "--out", tmp_path / "x", cwd=tmp_path)
    assert done.returncode == 2 and "Traceback" not in done.stderr
    assert hazard_map.name in done.stderr and not (tmp_path / "x").exists()
    assert_refused(done, "has no column for 2% in 50 years", "it has PGA-0.1 (return period 475 years)",
                   places=[f"{hazard_map}: the hazard map"])
    done = run(job_workbook(tmp_path), "--hazard", "2in50", "--oq-hazard", hazard_map, "--out", tmp_path / "x",
               cwd=tmp_path)
    assert_refused(done, "the file holds 21 sites", "--oq-site", places=[f"{hazard_map}: "])
    assert not (tmp_path / "x").exists()


def test_rerun_with_new_hazard_writes_a_comparison(lab_rerun):
    """Run, then rerun into the same folder with the motions scaled down (an OpenQuake PGA):
    comparison.csv lists the items whose risk class changed, with the PTA that moved."""
    first, out, second = lab_rerun
    assert not (first / "comparison.csv").exists()
    assert second.returncode == 0, second.stderr
    comparison = pd.read_csv(out / "comparison.csv")
    summary = pd.read_csv(out / "summary.csv")
    assert set(comparison["id"]) == set(summary["id"])
    down = comparison[comparison["change"] == "down"]
    assert len(down) > 0 and down["why"].str.contains("PTA").all()
    assert (comparison.loc[comparison["change"] == "same", "risk_before"]
            == comparison.loc[comparison["change"] == "same", "risk_after"]).all()
    html = (out / "report.html").read_text()
    assert "Changes since the previous run" in html and str(down["id"].iloc[0]) in html


KM2010 = ROOT / "inventories" / "km2010-prototypes.xlsx"
KM2010_MEASURED = ROOT / "inventories" / "km2010-measured.xlsx"


def test_calibrate_the_papers_loop_writes_spec_json(tmp_path):
    """The shipped example (slow-pull mu against Table 3's sliding): calibration.json has docs/outputs.md's keys,
    27 tests, every effect tried, a selection the file explains, and a report."""
    import json

    done = run("calibrate", KM2010, "--measured", KM2010_MEASURED, "--out", tmp_path / "cal", "--format", "html",
               cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    result = json.loads((tmp_path / "cal" / "calibration.json").read_text())
    assert {"error_before", "error_after", "selected", "candidates", "indistinguishable_from"} <= set(result)
    assert {"sliding_rms_log", "overturn_misclassified", "theta_rms"} <= set(result["error_before"])
    names = {c["effect"] for c in result["candidates"]}
    assert names == {"none", "friction_scale", "interface_elasticity", "static_friction", "velocity_friction",
                     "foot_inset", "restitution", "input_scale"}
    assert result["error_before"]["tests_sliding"] == 27
    assert result["selected"]["effect"] in names
    assert result["error_after"]["objective"] <= result["error_before"]["objective"] + 1e-12
    tests = pd.read_csv(tmp_path / "cal" / "calibration_tests.csv")
    assert len(tests) == 27 and {"im", "omega_p_over_p", "sliding_log_ratio_before"} <= set(tests.columns)
    check_file(tmp_path / "cal" / "calibration_tests.csv", "calibration_tests.csv")
    assert "Calibration against measured tests" in (tmp_path / "cal" / "report.html").read_text()


def test_calibrate_refuses_a_test_of_an_unknown_specimen(tmp_path):
    from openpyxl import Workbook

    measured = tmp_path / "measured.xlsx"
    book = Workbook()
    book.active.title = "tests"
    book.active.append(["specimen", "motion", "sliding_cm"])
    book.active.append(["FROMA", "Corralitos, ground, run 1 (0.84 g)", 20.0])
    book.save(measured)
    done = run("calibrate", KM2010, "--measured", measured, "--out", tmp_path / "cal", cwd=tmp_path)
    assert done.returncode == 2 and "Traceback" not in done.stderr
    assert "FROMA" in done.stderr and "cell A2" in done.stderr and not (tmp_path / "cal").exists()
    assert_refused(done, "FROMA", places=[location("measured.xlsx", "tests", "A2")])


# ------------------------------------------------------------------ writing the output folder

def test_a_later_run_leaves_no_stale_file_of_an_earlier_one(lab_rerun):
    """html,pdf then html into one folder: the folder holds this run's files only (no report.pdf)."""
    first, out, done = lab_rerun
    assert {"report.pdf", "summary.xlsx"} <= {p.name for p in first.iterdir()}
    assert done.returncode == 0, done.stderr
    assert sorted(p.name for p in out.iterdir()) == ["comparison.csv", "motions.csv", "report.html", "summary.csv",
                                                     "work_orders.csv"]
    assert [p.name for p in out.parent.iterdir()] == ["lab"]  # no temporary folder left beside it
    umask = os.umask(0)
    os.umask(umask)
    assert out.stat().st_mode & 0o777 == 0o777 & ~umask  # a folder as mkdir makes it, not mkdtemp's 0700


def test_an_output_folder_holding_other_files_is_refused_before_running(tmp_path):
    (tmp_path / "notes.txt").write_text("mine\n")
    done = run(LAB, "--hazard", "2in50", "--out", tmp_path, cwd=tmp_path)
    assert done.returncode == 2 and "Traceback" not in done.stderr
    assert "holds files assess did not write (notes.txt)" in done.stderr and "reading" not in done.stderr
    assert_refused(done, places=[f"{tmp_path}: the output folder holds files"])
    assert sorted(p.name for p in tmp_path.iterdir()) == ["notes.txt"]


def test_a_failed_swap_puts_the_previous_folder_back(tmp_path, monkeypatch):
    from assess.command import folders as output

    out = tmp_path / "out"
    out.mkdir()
    (out / "summary.csv").write_text("previous\n")
    (out / "report.pdf").write_text("previous pdf\n")
    real_replace, calls = os.replace, []

    def failing_second_rename(source, target):
        calls.append((source, target))
        if len(calls) == 2:
            raise OSError("disk gone")
        return real_replace(source, target)

    monkeypatch.setattr(output.os, "replace", failing_second_rename)
    with pytest.raises(OSError, match="disk gone"):
        output.write_atomically({"summary.csv": b"new\n"}, out)
    assert (out / "summary.csv").read_text() == "previous\n" and (out / "report.pdf").exists()
    assert [p.name for p in tmp_path.iterdir()] == ["out"]
    monkeypatch.setattr(output.os, "replace", real_replace)
    assert output.write_atomically({"summary.csv": b"new\n"}, out) == [out / "summary.csv"]
    assert sorted(p.name for p in out.iterdir()) == ["summary.csv"] and [p.name for p in tmp_path.iterdir()] == ["out"]


# ------------------------------------------------------------------ user text in CSV files and figures

@pytest.fixture(scope="module")
def odd_names_run(tmp_path_factory):
    """A small workbook of ids and names a spreadsheet would run as formulas or matplotlib as mathtext,
    run once in every format: ``(the workbook, its output folder)``."""
    import openpyxl

    from workbooks import good_sheets
    folder = tmp_path_factory.mktemp("odd-names")
    sheets = good_sheets()
    sheets["hazard"] = [{"level": "2in50", "motion": "M1", "floor": "all", "pta_g": 0.5, "tp_s": 1.0}]
    sheets["equipment"][3]["name"], sheets["equipment"][3]["mu"] = "X", 0.9  # BSC-3: im = 0.5/0.9 - 1 < 0
    book = write_workbook(folder / "wb.xlsx", sheets)
    workbook = openpyxl.load_workbook(book)
    texts = {("equipment", "A2"): "=1+1", ("equipment", "B2"): '=HYPERLINK("http://x.example","y")',
             ("equipment", "B3"): "@SUM(A1)", ("equipment", "B5"): r"Freezer $\foo$", ("hazard", "B2"): "+M1"}
    for (sheet, ref), text in texts.items():
        workbook[sheet][ref].value = text
        workbook[sheet][ref].data_type = "s"  # text that starts with '=', not a formula
    workbook.save(book)
    done = run(book, "--hazard", "2in50", "--out", folder / "out", "--quiet", cwd=folder)
    assert done.returncode == 0, done.stderr
    return book, folder / "out"


def test_formulas_are_neutralised_in_the_csv_files_and_mathtext_names_are_drawn(odd_names_run, tmp_path):
    """Names and ids a spreadsheet would run as formulas get a leading quote in summary.csv and
    motions.csv; numbers, negative ones included, do not; a rerun compares the items by their real ids.
    An item named with matplotlib mathtext is drawn as text (the run used to crash after simulating)."""
    import csv

    book, first = odd_names_run
    shutil.copytree(first, tmp_path / "out")
    with open(tmp_path / "out" / "summary.csv", newline="") as stream:
        summary = {row["id"]: row for row in csv.DictReader(stream)}
    assert set(summary) == {"'=1+1", "FRZ-2", "BSC-3"}
    assert summary["'=1+1"]["name"] == "'=HYPERLINK(\"http://x.example\",\"y\")"
    assert summary["FRZ-2"]["name"] == "'@SUM(A1)"
    assert summary["BSC-3"]["name"] == r"Freezer $\foo$"
    assert float(summary["BSC-3"]["im"]) == pytest.approx(0.5 / 0.9 - 1.0, abs=1e-5)  # written as -0.444444
    assert summary["BSC-3"]["im"].startswith("-0.444")
    with open(tmp_path / "out" / "motions.csv", newline="") as stream:
        assert {row["motion"] for row in csv.DictReader(stream)} == {"'+M1"}
    assert r"Freezer $\foo$" in (tmp_path / "out" / "report.html").read_text()
    assert (tmp_path / "out" / "report.pdf").read_bytes().startswith(b"%PDF")

    again = run(book, "--hazard", "2in50", "--out", tmp_path / "out", "--format", "html", "--quiet", cwd=tmp_path)
    assert again.returncode == 0, again.stderr
    with open(tmp_path / "out" / "comparison.csv", newline="") as stream:
        changes = {row["id"]: row["change"] for row in csv.DictReader(stream)}
    assert changes == {"'=1+1": "same", "FRZ-2": "same", "BSC-3": "same"}


# ------------------------------------------------------------------ Ctrl-C and a closed pipe

INTERRUPTED = "assess: interrupted; nothing was written."


@pytest.mark.parametrize("phase", ["reading", "preparing the motions", "simulated", "rendering"])
def test_ctrl_c_in_every_phase_exits_130_in_one_line(tmp_path, phase):
    """SIGINT when the run reports ``phase`` (the simulation runs in numba's threads; the PDF in
    WeasyPrint, whose cffi callbacks swallow exceptions): exit 130, one line, the folder untouched."""
    import signal

    out = tmp_path / "out"
    out.mkdir()
    (out / "summary.csv").write_text("previous\n")
    process = subprocess.Popen([sys.executable, "-m", "assess", str(LAB), "--hazard", "2in50", "--out", str(out)],
                               cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               env=child_env())
    after = []
    for line in process.stderr:
        if after or phase in line:
            if not after:
                process.send_signal(signal.SIGINT)
                after.append("")
                continue
            after.append(line.rstrip("\n"))
    process.wait(timeout=600)
    assert after, f"the run never reported '{phase}'"
    assert process.returncode == 130, after
    assert after[-1] == INTERRUPTED and after.count(INTERRUPTED) == 1, after
    assert all(line.startswith("assess: ") for line in after[1:]), after  # progress printed before it landed
    assert sorted(p.name for p in out.iterdir()) == ["summary.csv"] and (out / "summary.csv").read_text() == "previous\n"
    assert [p.name for p in tmp_path.iterdir()] == ["out"]


def test_an_interrupt_a_library_swallows_still_stops_the_run(tmp_path, monkeypatch, capsys):
    """WeasyPrint draws through cffi callbacks, which print and drop an exception raised in them."""
    import signal

    import assess.report

    def render_swallowing(result, **_):
        try:
            os.kill(os.getpid(), signal.SIGINT)
            for _ in range(10**6):
                pass
        except KeyboardInterrupt:
            pass  # what a cffi callback does with it
        return {"report.pdf": b"%PDF-1.7\n"}

    monkeypatch.setattr(assess.report, "report_files", render_swallowing)
    code = cli.main([str(job_workbook(tmp_path)), "--hazard", "2in50", "--out", str(tmp_path / "out"), "--quiet"])
    assert code == 130 and capsys.readouterr().err.splitlines() == [INTERRUPTED]
    assert not (tmp_path / "out").exists()


def test_an_interrupt_wrapped_in_a_system_error_exits_130(tmp_path, monkeypatch, capsys):
    """numba's threads may turn KeyboardInterrupt into 'SystemError: ... returned a result with an exception set'."""
    import assess.assessment.pipeline

    def wrapped(*args, **kwargs):
        try:
            raise KeyboardInterrupt
        except KeyboardInterrupt as interrupt:
            raise SystemError("<built-in function> returned a result with an exception set") from interrupt

    monkeypatch.setattr(assess.assessment.pipeline, "run_assessment", wrapped)
    code = cli.main([str(LAB), "--hazard", "2in50", "--out", str(tmp_path / "out"), "--quiet"])
    assert code == 130 and capsys.readouterr().err.splitlines() == [INTERRUPTED]


def test_a_closed_pipe_exits_quietly(tmp_path):
    """``assess simulate --json | head -c 10``: the reader has gone; no traceback, no 'internal error'."""
    read_end, write_end = os.pipe()
    os.close(read_end)  # the reader is gone before anything is written
    try:
        done = subprocess.run([sys.executable, "-m", "assess", "simulate", "--height-cm", "200", "--width-cm", "80",
                               "--mu", "0.3", "--pulse", "B", "--ap-g", "0.5", "--tp-s", "1", "--json"],
                              cwd=tmp_path, stdout=write_end, stderr=subprocess.PIPE, text=True, env=child_env())
    finally:
        os.close(write_end)
    assert done.returncode == 141 and done.stderr == ""
    shell = subprocess.run("set -o pipefail; " + " ".join([sys.executable, "-m", "assess", "simulate",
                           "--height-cm", "200", "--width-cm", "80", "--mu", "0.3", "--pulse", "B", "--ap-g", "0.5",
                           "--tp-s", "1", "--json"]) + " | head -c 10", shell=True, executable="/bin/bash",
                           cwd=tmp_path, capture_output=True, text=True, env=child_env())
    assert shell.stdout == '{\n  "alpha' and "Error" not in shell.stderr and "internal" not in shell.stderr
    assert shell.returncode in (0, 141)  # 0 when head read everything before closing


@pytest.mark.parametrize("argv, code", [
    (["simulate", "--height-cm", "200", "--width-cm", "80", "--mu", "0.3", "--pulse", "B", "--ap-g", "0.5",
      "--tp-s", "1", "--json"], 0),
    (["no-such-workbook.xlsx", "--hazard", "2in50", "--quiet"], 2),
])
def test_the_command_ends_at_once_after_its_exit_handlers(tmp_path, argv, code):
    """``assess.__main__.run`` (the ``assess`` command): the exit handlers run, after everything printed, and
    the exit code is main()'s."""
    script = ("import atexit, sys\nfrom assess.__main__ import run\n"
              "atexit.register(lambda: print('exit handler ran', flush=True))\n"
              f"sys.argv = ['assess'] + {argv!r}\nrun()\nprint('not reached')\n")
    done = subprocess.run([sys.executable, "-c", script], cwd=tmp_path, capture_output=True, text=True,
                          env=child_env(), timeout=300)
    assert done.returncode == code, done.stderr
    assert done.stdout.endswith("exit handler ran\n") and "not reached" not in done.stdout
    if code == 0:
        assert json.loads(done.stdout[:-len("exit handler ran\n")])["overturned"] in (True, False)
    else:
        assert "no-such-workbook.xlsx" in done.stderr and "Traceback" not in done.stderr
