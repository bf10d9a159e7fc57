"""assess batch: a portfolio of buildings, what it re-runs, what it writes, and what it refuses.

Counts are checked against what the test computes from its own workbooks
(items x motions x directions), and a building's folder against the main
command run on the same workbook without any cache.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from assess import cli
from assess.portfolio import report as portfolio_report
from assess.portfolio.batch import PORTFOLIO_FILES
from declared import check_file
from workbooks import write_workbook

#: A 4 s record: 2 s of a 1.5 Hz sine of 0.6 g, then rest (every item below slides).
RECORD = "time_s,accel_g\n" + "".join(
    f"{k * 0.01:.2f},{0.6 * math.sin(2 * math.pi * 1.5 * k * 0.01) if k <= 200 else 0.0:.6f}\n" for k in range(401))
#: Items by building: id, height, width, depth (cm; never a square base, so no two directions are alike), mu, clearance.
ITEMS = {
    "alpha": [("A-1", 200, 60, 80, 0.20, 10), ("A-2", 90, 120, 60, 0.45, 5), ("A-3", 180, 70, 90, 0.30, 20)],
    "beta": [("B-1", 150, 50, 70, 0.25, 15), ("B-2", 100, 80, 60, 0.35, 8)],
}
DIRECTIONS = 2
LEVEL = "2in50"


def _sheets(items, level=LEVEL, extra_level=False):
    equipment = [{"id": i, "name": f"item {i}", "floor": 0, "height_cm": h, "width_cm": w, "depth_cm": d,
                  "mass_kg": 200, "mu": mu, "clearance_cm": c, "quantity": 2 if i.endswith("1") else 1}
                 for i, h, w, d, mu, c in items]
    hazard = [{"level": level, "motion": "M1", "floor": "all", "record": "records/m1.csv"}]
    if extra_level:
        hazard.append({"level": "10in50", "motion": "M1", "floor": "all", "record": "records/m1.csv", "scale": 0.5})
    return {"equipment": equipment, "hazard": hazard}


def _write_building(folder: Path, name: str, items, **options) -> Path:
    return write_workbook(folder / f"{name}.xlsx", _sheets(items, **options), files={"records/m1.csv": RECORD})


def _portfolio(folder: Path, rows=None) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    for name, items in ITEMS.items():
        _write_building(folder, name, items)
    rows = rows if rows is not None else [{"building": name, "workbook": f"{name}.xlsx", "level": LEVEL}
                                          for name in ITEMS]
    return write_workbook(folder / "portfolio.xlsx", {"buildings": rows})


def _batch(*args) -> int:
    return cli.main(["batch", *map(str, args), "--format", "xlsx", "--quiet"])


def _csv(path: Path) -> pd.DataFrame:
    return pd.read_csv(path, dtype=str, keep_default_na=False)


@pytest.fixture
def first_run(tmp_path):
    portfolio = _portfolio(tmp_path / "site")
    out = tmp_path / "out"
    assert _batch(portfolio, "--out", out) == 0
    return portfolio, out


def test_first_run_writes_each_building_and_counts_its_cases(first_run):
    portfolio, out = first_run
    table = pd.read_csv(out / "portfolio.csv")
    assert list(table["building"]) == list(ITEMS)
    for row in table.to_dict("records"):
        items = ITEMS[row["building"]]
        # one motion with one history: every item x direction simulated once, none reused
        assert row["cases_simulated"] == len(items) * DIRECTIONS and row["cases_reused"] == 0
        summary = pd.read_csv(out / row["building"] / "summary.csv")
        assert sorted(summary["id"]) == sorted(i[0] for i in items)
        for risk in portfolio_report.RISKS:
            assert row[f"risk_{risk}"] == int((summary["risk"] == risk).sum())
        for kind in portfolio_report.ACTIONS:
            assert row[f"action_{kind}"] == int((summary["action_kind"] == kind).sum())
        assert row["units"] == sum(2 if i[0].endswith("1") else 1 for i in items)
    changes = _csv(out / "changes.csv")
    assert sorted(changes["change"]) == ["building added"] * len(ITEMS)
    for name in [name for name in PORTFOLIO_FILES if name.endswith(".csv")]:
        check_file(out / name, name)  # declared in assess/data/columns.csv, in order, of its dtype
    html = (out / "portfolio.html").read_text()
    assert "No previous run" in html and "alpha/report.html" in html
    assert not list(out.parent.glob(".out-*"))  # no staging folder left


def test_a_buildings_folder_is_what_the_main_command_writes_without_a_cache(first_run, tmp_path):
    portfolio, out = first_run
    alone = tmp_path / "alone"
    assert cli.main([str(portfolio.parent / "alpha.xlsx"), "--hazard", LEVEL, "--out", str(alone),
                     "--format", "xlsx", "--quiet"]) == 0
    for name in ("summary.csv", "motions.csv"):
        assert (out / "alpha" / name).read_bytes() == (alone / name).read_bytes()


def test_a_rerun_with_nothing_changed_simulates_nothing_and_reports_no_change(first_run):
    portfolio, out = first_run
    before = {p.relative_to(out): p.read_bytes() for p in out.glob("*/summary.csv") if p.parent.name in ITEMS}
    assert _batch(portfolio, "--out", out) == 0
    table = pd.read_csv(out / "portfolio.csv")
    assert list(table["cases_simulated"]) == [0, 0]
    assert list(table["cases_reused"]) == [len(ITEMS[b]) * DIRECTIONS for b in table["building"]]
    assert _csv(out / "changes.csv").empty
    assert {p: (out / p).read_bytes() for p in before} == before
    assert (out / "previous" / "alpha" / "summary.csv").read_bytes() == before[Path("alpha/summary.csv")]
    assert "Nothing changed" in (out / "portfolio.html").read_text()


def test_an_edited_item_reruns_only_its_cases_and_the_change_report_names_it(first_run, tmp_path):
    portfolio, out = first_run
    old = _csv(out / "alpha" / "summary.csv").set_index("id")
    items = [list(i) for i in ITEMS["alpha"]]
    items[1][4] = 0.25  # mu 0.45 -> 0.25
    _write_building(portfolio.parent, "alpha", [tuple(i) for i in items])
    assert _batch(portfolio, "--out", out) == 0
    table = pd.read_csv(out / "portfolio.csv").set_index("building")
    assert table.at["alpha", "cases_simulated"] == DIRECTIONS  # A-2 in its two directions, nothing else
    assert table.at["alpha", "cases_reused"] == (len(items) - 1) * DIRECTIONS
    assert table.at["beta", "cases_simulated"] == 0
    new = _csv(out / "alpha" / "summary.csv").set_index("id")
    # the change report holds exactly the differences between the two summaries, in the fields it follows
    expected = {(i, f, old.at[i, f], new.at[i, f]) for i in new.index for f in portfolio_report.CHANGE_FIELDS
                if old.at[i, f] != new.at[i, f]}
    changes = _csv(out / "changes.csv")
    got = {(r["id"], r["field"], r["old"], r["new"]) for r in changes.to_dict("records")}
    assert got == expected and any(i == "A-2" for i, *_ in got)
    assert set(changes["building"]) == {"alpha"}
    # the same numbers as an uncached run of the edited workbook
    alone = tmp_path / "alone"
    assert cli.main([str(portfolio.parent / "alpha.xlsx"), "--hazard", LEVEL, "--out", str(alone),
                     "--format", "xlsx", "--quiet"]) == 0
    assert (out / "alpha" / "summary.csv").read_bytes() == (alone / "summary.csv").read_bytes()


def test_a_clearance_change_reassesses_without_simulating(first_run):
    portfolio, out = first_run
    items = [list(i) for i in ITEMS["beta"]]
    items[0][5] = 40  # B-1: clearance 15 -> 40 cm; the motion of the block does not depend on it
    _write_building(portfolio.parent, "beta", [tuple(i) for i in items])
    assert _batch(portfolio, "--out", out) == 0
    table = pd.read_csv(out / "portfolio.csv").set_index("building")
    assert table.at["beta", "cases_simulated"] == 0
    assert table.at["beta", "cases_reused"] == len(items) * DIRECTIONS
    assert pd.read_csv(out / "beta" / "summary.csv").set_index("id").at["B-1", "clearance_cm"] == 40


def test_added_and_removed_buildings_and_items(first_run):
    portfolio, out = first_run
    _write_building(portfolio.parent, "gamma", [("G-1", 120, 60, 70, 0.3, 10)])
    _write_building(portfolio.parent, "alpha", ITEMS["alpha"][:2] + [("A-4", 160, 60, 70, 0.3, 10)])
    write_workbook(portfolio, {"buildings": [{"building": "alpha", "workbook": "alpha.xlsx", "level": LEVEL},
                                             {"building": "gamma", "workbook": "gamma.xlsx", "level": LEVEL}]})
    assert _batch(portfolio, "--out", out) == 0
    changes = _csv(out / "changes.csv")
    rows = {(r["building"], r["id"], r["change"]) for r in changes.to_dict("records") if r["change"] != "changed"}
    assert rows == {("alpha", "A-4", "item added"), ("alpha", "A-3", "item removed"),
                    ("beta", "", "building removed"), ("gamma", "", "building added")}
    assert not (out / "beta").exists() and (out / "gamma" / "summary.csv").is_file()


def test_a_folder_portfolio_takes_each_workbooks_only_level(tmp_path):
    folder = tmp_path / "site"
    folder.mkdir()
    _write_building(folder, "alpha", ITEMS["alpha"])
    _write_building(folder, "beta", ITEMS["beta"], level="DE")
    (folder / "~$alpha.xlsx").write_bytes(b"an Excel lock file")
    out = tmp_path / "out"
    assert _batch(folder, "--out", out) == 0
    table = pd.read_csv(out / "portfolio.csv")
    assert list(zip(table["building"], table["level"])) == [("alpha", LEVEL), ("beta", "DE")]


def test_a_workbook_with_several_levels_needs_one_named(tmp_path, capsys):
    folder = tmp_path / "site"
    folder.mkdir()
    _write_building(folder, "alpha", ITEMS["alpha"], extra_level=True)
    out = tmp_path / "out"
    assert _batch(folder, "--out", out) == 2
    err = capsys.readouterr().err
    assert "alpha" in err and "--hazard" in err and "Traceback" not in err
    assert not out.exists()
    assert _batch(folder, "--out", out, "--hazard", "10in50") == 0
    assert pd.read_csv(out / "portfolio.csv")["level"].tolist() == ["10in50"]


@pytest.mark.parametrize("row, where, what", [
    ({"building": "gamma", "workbook": "missing.xlsx"}, "cell B3", "was not found"),
    ({"building": "gamma", "workbook": "../elsewhere/alpha.xlsx"}, "cell B3", "outside the portfolio's folder"),
    ({"building": "gamma", "workbook": "records/m1.csv"}, "cell B3", "not an Excel workbook"),
    ({"building": "a/b", "workbook": "beta.xlsx"}, "cell A3", "cannot name a folder"),
    ({"building": "ALPHA", "workbook": "beta.xlsx"}, "cell A3", "already in row 2"),
    ({"building": "previous", "workbook": "beta.xlsx"}, "cell A3", "the portfolio writes itself"),
    ({"building": "beta", "workbook": "beta.xlsx", "level": "2in"}, "row 3, column 'level'", "no motions for hazard level '2in'"),
    ({"building": "beta", "workbook": "beta.xlsx", "oq_hazard": "none.csv"}, "cell D3", "was not found"),
])
def test_bad_portfolio_rows_exit_2_naming_the_cell_and_nothing_is_written(tmp_path, capsys, row, where, what):
    site = tmp_path / "site"
    _portfolio(site)
    (tmp_path / "elsewhere").mkdir()
    _write_building(tmp_path / "elsewhere", "alpha", ITEMS["alpha"])
    columns = ["building", "workbook", "level", "oq_hazard"]
    rows = [["building", "workbook", "level", "oq_hazard"], ["alpha", "alpha.xlsx", LEVEL, None],
            [row.get(c) for c in columns]]
    portfolio = write_workbook(site / "portfolio.xlsx", {"buildings": rows})
    out = tmp_path / "out"
    assert _batch(portfolio, "--out", out) == 2
    err = capsys.readouterr().err
    assert "sheet 'buildings'" in err and where in err and what in err and "Traceback" not in err
    assert not out.exists()


def test_files_outside_the_portfolio_are_read_only_when_allowed(tmp_path):
    site = tmp_path / "site"
    _portfolio(site)
    (tmp_path / "elsewhere").mkdir()
    _write_building(tmp_path / "elsewhere", "far", ITEMS["beta"])
    portfolio = write_workbook(site / "portfolio.xlsx", {"buildings": [
        {"building": "far", "workbook": "../elsewhere/far.xlsx", "level": LEVEL}]})
    assert _batch(portfolio, "--out", tmp_path / "out") == 2
    assert _batch(portfolio, "--out", tmp_path / "out", "--allow-files-outside") == 0


def test_a_portfolio_without_the_buildings_sheet_is_refused(tmp_path, capsys):
    site = tmp_path / "site"
    site.mkdir()
    portfolio = write_workbook(site / "portfolio.xlsx", {"sites": [["building"], ["x"]]})
    assert _batch(portfolio, "--out", tmp_path / "out") == 2
    assert "no sheet 'buildings'" in capsys.readouterr().err


def test_an_output_folder_holding_other_files_is_refused_before_running(tmp_path, capsys):
    portfolio = _portfolio(tmp_path / "site")
    out = tmp_path / "out"
    out.mkdir()
    (out / "my notes.docx").write_text("mine")
    assert _batch(portfolio, "--out", out) == 2
    assert "my notes.docx" in capsys.readouterr().err
    assert sorted(p.name for p in out.iterdir()) == ["my notes.docx"]


def test_a_failure_leaves_the_previous_output_and_keeps_what_was_simulated(first_run, monkeypatch, capsys):
    portfolio, out = first_run
    before = {p: p.read_bytes() for p in out.rglob("*") if p.is_file() and ".cache" not in p.parts}
    _write_building(portfolio.parent, "alpha", [(i, h, w, d, mu + 0.01, c) for i, h, w, d, mu, c in ITEMS["alpha"]])
    _write_building(portfolio.parent, "beta", [(i, h, w, d, mu + 0.01, c) for i, h, w, d, mu, c in ITEMS["beta"]])
    import assess.command.output
    real = assess.command.output.render_outputs
    calls = []

    def failing(result, *args, **kwargs):
        calls.append(result)
        if len(calls) == 2:
            raise RuntimeError("disk on fire")
        return real(result, *args, **kwargs)

    monkeypatch.setattr(assess.command.output, "render_outputs", failing)
    assert _batch(portfolio, "--out", out) == 1
    assert "disk on fire" in capsys.readouterr().err
    after = {p: p.read_bytes() for p in out.rglob("*") if p.is_file() and ".cache" not in p.parts}
    assert after == before
    assert not [p for p in out.parent.iterdir() if p.name.startswith(".out-")]
    monkeypatch.setattr(assess.command.output, "render_outputs", real)
    # both buildings were simulated before beta's report failed: the cache kept their cases
    assert _batch(portfolio, "--out", out) == 0
    table = pd.read_csv(out / "portfolio.csv").set_index("building")
    assert list(table["cases_simulated"]) == [0, 0]
    assert table.at["beta", "cases_reused"] == len(ITEMS["beta"]) * DIRECTIONS


def test_the_hazard_curve_reaches_the_assessment_and_its_rates_the_portfolio(tmp_path, monkeypatch):
    """With an assessment that takes ``hazard_curve`` (the rates over the curve), each building gets its
    row's curve or --oq-hazard's, and portfolio.csv sums the units' annual rates; the curve does not scale
    the motions (``oq_hazard`` is not passed)."""
    import assess.assessment.pipeline
    site = tmp_path / "site"
    _portfolio(site)
    curves = Path(__file__).resolve().parents[1] / "data" / "openquake"
    (site / "curve.csv").write_bytes((curves / "case_23-hazard_curve-mean-PGA_953.csv").read_bytes())
    portfolio = write_workbook(site / "portfolio.xlsx", {"buildings": [
        {"building": "alpha", "workbook": "alpha.xlsx", "level": LEVEL, "oq_hazard": "curve.csv"},
        {"building": "beta", "workbook": "beta.xlsx", "level": LEVEL}]})
    real = assess.assessment.pipeline.run_assessment
    seen = {}

    def with_curve(inventory, level_text, seed=0, progress=lambda m: None, oq_hazard=None,
                   derive_floors_roof=None, calibration=None, runner=None, hazard_curve=None,
                   allow_records_outside=False):
        seen[inventory.path.name] = (hazard_curve, oq_hazard)
        result = real(inventory, level_text, seed=seed, progress=progress, runner=runner)
        rate = np.arange(1, len(result.summary) + 1) * 1e-4
        summary = result.summary.assign(annual_rate_overturn=rate, p50yr_overturn=1 - np.exp(-50 * rate))
        return type(result)(**{**result.__dict__, "summary": summary})

    monkeypatch.setattr(assess.assessment.pipeline, "run_assessment", with_curve)
    other = tmp_path / "other-curve.csv"
    other.write_bytes((curves / "case_13-hazard_curve-mean-PGA.csv").read_bytes())
    out = tmp_path / "out"
    assert cli.main(["batch", str(portfolio), "--out", str(out), "--format", "xlsx", "--quiet",
                     "--oq-hazard", str(curves / "case_23-hazard_curve-mean-PGA_953.csv")]) == 0
    assert Path(seen["alpha.xlsx"][0].path).name == "curve.csv" and seen["alpha.xlsx"][1] is None
    assert Path(seen["beta.xlsx"][0].path).name == "case_23-hazard_curve-mean-PGA_953.csv"
    table = pd.read_csv(out / "portfolio.csv").set_index("building")
    summary = pd.read_csv(out / "alpha" / "summary.csv")
    assert table.at["alpha", "annual_rate_overturn_units_total"] == pytest.approx(
        (summary["quantity"] * summary["annual_rate_overturn"]).sum(), rel=1e-5)
    assert table.at["alpha", "p50yr_overturn_max"] == pytest.approx(summary["p50yr_overturn"].max(), rel=1e-5)


def test_changes_between_follows_the_curve_columns():
    old = b"id,name,risk,priority,annual_rate_overturn\nX,fridge,low,2,1e-05\nY,rack,high,1,0.002\n"
    new = b"id,name,risk,priority,annual_rate_overturn\nX,fridge,low,2,2e-05\nZ,shelf,moderate,1,0\n"
    table = portfolio_report.changes_between({"b": old}, {"b": new}, {"b": "B"})
    rows = {tuple(r.values()) for r in table.to_dict("records")}
    assert rows == {("B", "X", "fridge", "changed", "annual_rate_overturn", "1e-05", "2e-05"),
                    ("B", "Z", "shelf", "item added", "", "", ""),
                    ("B", "Y", "rack", "item removed", "", "", "")}


def test_batch_help_describes_the_portfolio():
    text = cli.build_batch_parser().format_help()
    for option in ("--out", "--hazard", "--oq-hazard", "--scheduler", "--allow-files-outside", "buildings"):
        assert option in text


def test_ctrl_c_exits_130_and_leaves_the_previous_output(first_run, monkeypatch, capsys):
    portfolio, out = first_run
    before = {p: p.read_bytes() for p in out.rglob("*") if p.is_file() and ".cache" not in p.parts}
    _write_building(portfolio.parent, "beta", [(i, h, w, d, mu + 0.01, c) for i, h, w, d, mu, c in ITEMS["beta"]])
    import assess.assessment.pipeline
    real = assess.assessment.pipeline.run_assessment
    calls = []

    def interrupted(*args, **kwargs):
        calls.append(1)
        if len(calls) == 1:
            raise KeyboardInterrupt
        return real(*args, **kwargs)

    monkeypatch.setattr(assess.assessment.pipeline, "run_assessment", interrupted)
    assert _batch(portfolio, "--out", out) == 130
    assert "interrupted; nothing was written" in capsys.readouterr().err
    assert {p: p.read_bytes() for p in out.rglob("*") if p.is_file() and ".cache" not in p.parts} == before
    assert not [p for p in out.parent.iterdir() if p.name.startswith(".out-")]


def _curve_portfolio(tmp_path):
    """alpha with the sample portfolio's site curve (a power law in OpenQuake's format), beta without."""
    site = tmp_path / "site"
    _portfolio(site)
    sample = Path(__file__).resolve().parents[2] / "inventories" / "portfolio" / "site-hazard.csv"
    (site / "curve.csv").write_bytes(sample.read_bytes())
    return write_workbook(site / "portfolio.xlsx", {"buildings": [
        {"building": "alpha", "workbook": "alpha.xlsx", "level": LEVEL, "oq_hazard": "curve.csv"},
        {"building": "beta", "workbook": "beta.xlsx", "level": LEVEL}]})


def test_a_buildings_curve_gives_annual_rates_and_an_unchanged_rerun_keeps_its_fragilities(tmp_path):
    portfolio = _curve_portfolio(tmp_path)
    out = tmp_path / "out"
    assert _batch(portfolio, "--out", out) == 0
    summary = pd.read_csv(out / "alpha" / "summary.csv")
    assert {"annual_rate_beyond_clearance", "p50yr_overturn"} <= set(summary.columns)
    assert "annual_rate_overturn" not in pd.read_csv(out / "beta" / "summary.csv").columns  # no curve, no rates
    table = pd.read_csv(out / "portfolio.csv").set_index("building")
    total = (summary["quantity"] * summary["annual_rate_beyond_clearance"]).sum(min_count=1)
    assert table.at["alpha", "annual_rate_beyond_clearance_units_total"] == pytest.approx(total, rel=1e-5)
    assert table.at["alpha", "hazard_curve"] == "curve.csv"
    # the stripes went through the cache too: more cases than the level's own
    assert table.at["alpha", "cases_simulated"] + table.at["alpha", "cases_reused"] > len(ITEMS["alpha"]) * DIRECTIONS
    before = {p: p.read_bytes() for p in (out / "alpha").rglob("*") if p.is_file()}
    assert any(p.parent.name == "fragility" for p in before)
    assert _batch(portfolio, "--out", out) == 0
    assert pd.read_csv(out / "portfolio.csv")["cases_simulated"].sum() == 0
    assert {p: p.read_bytes() for p in (out / "alpha").rglob("*") if p.is_file()} == before


def test_a_curve_update_reintegrates_without_simulating(tmp_path):
    portfolio = _curve_portfolio(tmp_path)
    out = tmp_path / "out"
    assert _batch(portfolio, "--out", out) == 0
    site = portfolio.parent
    text = (site / "curve.csv").read_text().splitlines()
    # the same site's curve, every poe 20 % higher (a hazard model update)
    values = text[2].split(",")
    text[2] = ",".join(values[:3] + [f"{min(1.0, float(v) * 1.2):.6E}" for v in values[3:]])
    (site / "curve.csv").write_text("\n".join(text) + "\n")
    assert _batch(portfolio, "--out", out) == 0
    table = pd.read_csv(out / "portfolio.csv").set_index("building")
    assert table.at["alpha", "cases_simulated"] == 0
    assert (_csv(out / "changes.csv")["field"] == "annual_rate_beyond_clearance").any()
    assert "annual_rate_beyond_clearance_units_total" in check_file(out / "portfolio.csv", "portfolio.csv")
    check_file(out / "changes.csv", "changes.csv")


def test_an_edited_record_reassesses_its_building(first_run):
    portfolio, out = first_run
    record = portfolio.parent / "records" / "m1.csv"
    lines = record.read_text().splitlines()
    lines[20] = lines[20].split(",")[0] + ",0.65"  # one sample of the record
    record.write_text("\n".join(lines) + "\n")
    import assess.assessment.motions
    assess.assessment.motions.read_scaled.cache_clear()  # it keeps a record by path for the process's life
    assert _batch(portfolio, "--out", out) == 0
    table = pd.read_csv(out / "portfolio.csv").set_index("building")
    # both buildings read this record: every case of each runs again
    assert table.at["alpha", "cases_simulated"] == len(ITEMS["alpha"]) * DIRECTIONS
    assert table.at["beta", "cases_simulated"] == len(ITEMS["beta"]) * DIRECTIONS


def test_a_missing_oq_hazard_file_is_refused_once(tmp_path, capsys):
    portfolio = _portfolio(tmp_path / "site")
    assert _batch(portfolio, "--out", tmp_path / "out", "--oq-hazard", tmp_path / "nothere.csv") == 2
    err = capsys.readouterr().err
    assert err.count("nothere.csv") == 1 and "1 problem" in err


def test_every_buildings_pdf_is_the_one_the_main_command_writes_for_it_alone(tmp_path):
    portfolio = _portfolio(tmp_path / "site")
    out = tmp_path / "out"
    assert cli.main(["batch", str(portfolio), "--out", str(out), "--format", "pdf", "--quiet"]) == 0
    alone = tmp_path / "alone"
    assert cli.main([str(portfolio.parent / "alpha.xlsx"), "--hazard", LEVEL, "--out", str(alone),
                     "--format", "pdf", "--quiet"]) == 0
    assert (out / "alpha" / "report.pdf").read_bytes() == (alone / "report.pdf").read_bytes()


# ---------------------------------------------------------------- buildings with site and building sheets

#: A site sheet and a 2-storey building, no hazard sheet: the ground suite and the floors' motions are made.
SITE_SHEET = [["key", "value"], ["sds_g", 1.0], ["sd1_g", 0.6], ["suite_size", 3], ["risk_category", "IV"]]
BUILDING_SHEET = [["key", "value"], ["storeys", 2], ["storey_height_m", 4.0], ["period_s", 0.3]]


def _site_building(folder: Path, name: str = "clinic") -> Path:
    equipment = [{"id": i, "name": f"item {i}", "floor": floor, "height_cm": h, "width_cm": w, "depth_cm": d,
                  "mass_kg": 200, "mu": mu, "clearance_cm": c}
                 for i, floor, (_, h, w, d, mu, c) in zip(("C-0", "C-2"), (0, 2), ITEMS["alpha"])]
    folder.mkdir(parents=True, exist_ok=True)
    return write_workbook(folder / f"{name}.xlsx", {"equipment": equipment, "site": SITE_SHEET,
                                                     "building": BUILDING_SHEET})


def test_a_building_with_site_and_building_sheets_gives_what_the_main_command_gives(tmp_path):
    """The portfolio's building folder holds the same numbers as ``assess WORKBOOK --hazard DE --seed 3``:
    the same ground suite (ground_motions.csv), floor motions (floors.csv, motions.csv) and results."""
    site = tmp_path / "site"
    workbook = _site_building(site)
    portfolio = write_workbook(site / "portfolio.xlsx", {"buildings": [
        {"building": "clinic", "workbook": workbook.name, "level": "DE"}]})
    out, alone = tmp_path / "out", tmp_path / "alone"
    assert _batch(portfolio, "--out", out, "--seed", 3) == 0
    assert cli.main([str(workbook), "--hazard", "DE", "--out", str(alone), "--seed", "3", "--format", "xlsx",
                     "--quiet"]) == 0
    for name in ("summary.csv", "motions.csv", "ground_motions.csv", "floors.csv", "work_orders.csv"):
        assert (out / "clinic" / name).read_bytes() == (alone / name).read_bytes(), name
    floors = pd.read_csv(out / "clinic" / "floors.csv")
    # a yielding building (the default where the site sheet gives design values): a row for every floor
    assert sorted(set(floors["floor"])) == [0, 1, 2] and set(floors["response"]) == {"yielding"}
    motions = pd.read_csv(out / "clinic" / "motions.csv")
    assert len(set(motions.loc[motions["id"] == "C-2", "motion"])) == 3  # one per ground motion of the suite


def test_a_site_workbook_without_a_level_is_refused_at_the_row_and_a_level_the_site_cannot_give_too(
        tmp_path, capsys):
    site = tmp_path / "site"
    workbook = _site_building(site)
    portfolio = write_workbook(site / "portfolio.xlsx", {"buildings": [
        ["building", "workbook", "level"], ["clinic", workbook.name, None], ["annex", workbook.name, "2in50"]]})
    out = tmp_path / "out"
    assert _batch(portfolio, "--out", out) == 2
    err = capsys.readouterr().err
    assert "row 2, column 'level'" in err and "has a site sheet" in err and "--hazard" in err
    assert "row 3, column 'level'" in err and "'uhs'" in err  # 2in50 needs the site's OpenQuake spectrum
    assert "Traceback" not in err and not out.exists()
