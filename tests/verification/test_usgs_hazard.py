"""USGS nshmp-haz hazard curves (``assess/hazard/usgs.py``): read to the same annual rates as OpenQuake's.

Expected values come from outside the reader: the numbers a test writes into both formats (one set of
annual rates; OpenQuake's probabilities from them by P = 1 - exp(-λ T)), the real nshmp-haz example
outputs in ``tests/data/usgs/`` (numbers copied from the file by hand), and the log-log interpolation
written out here.
"""
from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np
import pytest

from assess.errors import InputError
from assess.hazard.levels import HazardLevel
from assess.hazard.openquake import pga_at_level
from assess.hazard.risk_integral import curve_annual_rates, openquake_failure_rate
from assess.hazard.usgs import (MAX_HAZARD_FILE_BYTES, SOURCE, bounded_text, imt_of_path, is_nshmp_header,
                                read_hazard_curve_file, read_nshmp_curve)

import commands

DATA = Path(__file__).resolve().parents[1] / "data" / "usgs"
SITES = DATA / "3-sites-file" / "curves" / "PGA" / "total.csv"  # 7 named sites, 0.005 .. 3.3 g
GRID = DATA / "4-hazard-map" / "curves" / "PGA" / "total.csv"  # unnamed sites (lon,lat,...), 0.001 .. 1 g
SECRET = "hunter2-SECRET-TOKEN"
TEN_IN_50 = HazardLevel(0.10, 50.0)
TWO_IN_50 = HazardLevel(0.02, 50.0)

#: One curve, two formats: 20 levels [g] OpenQuake can write exactly (%.7f) and their annual rates from
#: the second-order form ln λ = ln λ0 - k1 x - k2 x², x = ln(a / 0.5 g) (Vamvatsikos 2013; falling over the
#: levels, k1 + 2 k2 x > 0), about 0.08 per year at 0.005 g, the top level at rate 0.
LEVELS_G = np.round(np.geomspace(0.005, 3.0, 20), 4)
_X = np.log(LEVELS_G[:-1] / 0.5)
RATES = np.append(np.exp(math.log(2.0e-4) - 2.0 * _X - 0.15 * _X**2), 0.0)


def write_nshmp(folder: Path, levels_g, rates, name="Test Site", lon=-122.3, lat=47.6, imt="PGA") -> Path:
    """A curve in nshmp-haz's layout (``<IMT>/curves.csv``), the values as Python writes them in full."""
    path = folder / imt / "curves.csv"
    path.parent.mkdir(parents=True, exist_ok=True)
    header = ["name", "lon", "lat"] + [repr(float(x)) for x in levels_g]
    row = [name, f"{lon:.5f}", f"{lat:.5f}"] + [repr(float(r)) for r in rates]
    path.write_text(",".join(header) + "\n" + ",".join(row) + "\n")
    return path


def write_openquake(folder: Path, levels_g, rates, investigation_time_yr) -> Path:
    """The same curve in OpenQuake's layout: probabilities in the investigation time, P = 1 - exp(-λ T)."""
    path = folder / "hazard_curve-mean-PGA_1.csv"
    folder.mkdir(parents=True, exist_ok=True)
    poes = -np.expm1(-np.asarray(rates) * investigation_time_yr)
    header = ["lon", "lat", "depth"] + [f"poe-{x:.7f}" for x in levels_g]
    comment = "#" + "," * (len(header) - 1) + (f"\"kind='mean', investigation_time={investigation_time_yr!r}, "
                                                "imt='PGA'\"")
    row = ["-122.30000", "47.60000", "0.00000"] + [repr(float(p)) for p in poes]
    path.write_text("\n".join([comment, ",".join(header), ",".join(row)]) + "\n")
    return path


# ------------------------------------------------------------------ one curve, two formats


@pytest.mark.parametrize("investigation_time_yr", [1.0, 50.0])
def test_an_nshmp_curve_reads_to_the_annual_rates_of_the_same_openquake_curve(tmp_path, investigation_time_yr):
    usgs = read_hazard_curve_file(write_nshmp(tmp_path / "usgs", LEVELS_G, RATES))
    oq = read_hazard_curve_file(write_openquake(tmp_path / "oq", LEVELS_G, RATES, investigation_time_yr))
    assert usgs.source == SOURCE and oq.source == "OpenQuake" and usgs.kind == oq.kind == "curve"
    np.testing.assert_array_equal(usgs.levels_g, oq.levels_g)
    usgs_rates, oq_rates = curve_annual_rates(usgs), curve_annual_rates(oq)
    # the rates written, and OpenQuake's -ln(1 - P)/T of its probabilities, agree to 1e-9
    np.testing.assert_allclose(usgs_rates, RATES, rtol=1e-12, atol=0.0)
    np.testing.assert_allclose(oq_rates, RATES, rtol=1e-9, atol=0.0)
    np.testing.assert_allclose(usgs_rates, oq_rates, rtol=1e-9, atol=0.0)
    assert usgs_rates[-1] == oq_rates[-1] == 0.0
    # so does every risk integral over them (a fragility in PGA, and one moved by a floor's ratio)
    for median_g, beta, ratio in ((0.3, 0.5, 1.0), (1.2, 0.35, 1.8)):
        a = openquake_failure_rate(usgs, median_g, beta, pfa_per_pga=ratio).annual_rate
        b = openquake_failure_rate(oq, median_g, beta, pfa_per_pga=ratio).annual_rate
        assert a == pytest.approx(b, rel=1e-9)


def test_a_level_is_read_from_an_nshmp_curve_as_from_the_openquake_one_year_curve(tmp_path):
    """A level's PGA: log-log in the one-year probability 1 - exp(-λ), as OpenQuake's one-year curve gives it."""
    usgs = read_hazard_curve_file(write_nshmp(tmp_path / "usgs", LEVELS_G, RATES))
    oq = read_hazard_curve_file(write_openquake(tmp_path / "oq", LEVELS_G, RATES, 1.0))
    for level in (TEN_IN_50, TWO_IN_50):
        assert pga_at_level(usgs, level) == pytest.approx(pga_at_level(oq, level), rel=1e-12)
        # written out: the two levels around the level's one-year probability, ln a linear in ln P
        p = -math.expm1(-1.0 / level.return_period_yr)
        poes = -np.expm1(-RATES)
        j = int(np.flatnonzero(poes >= p)[-1])
        expected = math.exp(math.log(LEVELS_G[j]) + (math.log(p) - math.log(poes[j])) * (
            math.log(LEVELS_G[j + 1]) - math.log(LEVELS_G[j])) / (math.log(poes[j + 1]) - math.log(poes[j])))
        assert pga_at_level(usgs, level) == pytest.approx(expected, rel=1e-12)


def test_rates_above_one_per_year_are_kept_as_written(tmp_path):
    """A one-year probability rounds to 1 from about 37 per year; the file's rates are used, not through it."""
    rates = [40.0, 5.0, 0.5, 1e-3, 1e-6]
    hazard = read_hazard_curve_file(write_nshmp(tmp_path, [0.001, 0.01, 0.1, 0.5, 2.0], rates))
    np.testing.assert_array_equal(curve_annual_rates(hazard), rates)


# ------------------------------------------------------------------ the engine's own files


def test_the_engines_sites_file_output_by_name_index_and_coordinates():
    oakland = read_hazard_curve_file(SITES, site="Oakland CA")
    assert oakland.site.index == 1 and oakland.site.line == 3
    assert read_hazard_curve_file(SITES, site=1).site == oakland.site
    assert read_hazard_curve_file(SITES, site=(-122.25, 37.8)).site == oakland.site
    assert oakland.levels_g[0] == 0.005 and oakland.levels_g[-1] == 3.3 and oakland.levels_g.size == 20
    rates = curve_annual_rates(oakland)
    # copied from the file: 0.103 g at 1.28698458e-03 per year, 0.397 g at 9.57533360e-07, 0.556 g at 0.0
    assert rates[9] == 1.28698458e-03 and rates[13] == 9.57533360e-07 and rates[14] == 0.0
    # 10 % in 50 years: λ = -ln(0.9)/50 = 2.107e-3 per year, between 0.0527 g (2.56390943e-03) and 0.0738 g
    # (2.04401519e-03); one-year probabilities, ln a linear in ln P
    p = -math.expm1(-1.0 / TEN_IN_50.return_period_yr)
    p0, p1 = -math.expm1(-2.56390943e-03), -math.expm1(-2.04401519e-03)
    expected = math.exp(math.log(0.0527) + (math.log(p) - math.log(p0)) * (math.log(0.0738) - math.log(0.0527))
                        / (math.log(p1) - math.log(p0)))
    assert pga_at_level(oakland, TEN_IN_50) == pytest.approx(expected, rel=1e-12)


def test_several_sites_and_none_chosen_lists_them_by_name():
    with pytest.raises(InputError) as caught:
        read_hazard_curve_file(SITES)
    (problem,) = caught.value.problems
    assert "holds 7 sites" in problem.message and "'San Francisco CA'" in problem.message
    assert "its name" in problem.fix and "custom_site_id" not in problem.fix
    with pytest.raises(InputError) as caught:
        read_hazard_curve_file(SITES, site="Seattle WA")
    assert "no site has name 'Seattle WA'" in str(caught.value)


def test_the_engines_unnamed_grid_output():
    hazard = read_hazard_curve_file(GRID, site=(-122.3, 37.5))
    assert hazard.site.index == 4 and hazard.site.custom_site_id is None
    np.testing.assert_array_equal(curve_annual_rates(hazard)[:5],
                                  [2.85280770e-03, 2.84160070e-03, 6.92379552e-04, 4.25381097e-05, 2.18789296e-07])


def test_the_header_tells_the_formats_apart():
    assert is_nshmp_header(["name", "lon", "lat", "0.005", "1.0E-4"])
    assert is_nshmp_header(["lon", "lat", "0.001"])
    for header in (["lon", "lat", "depth", "poe-0.1"], ["lon", "lat", "PGA-0.002105"], ["name", "lon", "lat"],
                   ["root:x:0:0:root:/root:/bin/bash"], []):
        assert not is_nshmp_header(header)
    assert imt_of_path("hazout/PGA/curves.csv") == "PGA" and imt_of_path("curves/PGA.csv") == "PGA"
    assert imt_of_path("out/SA0P2/curves.csv") == "SA0P2" and imt_of_path("site-curve.csv") is None


def test_curves_truncated_gets_a_note(tmp_path):
    path = write_nshmp(tmp_path, LEVELS_G, RATES)
    truncated = path.with_name("curves-truncated.csv")
    path.rename(truncated)
    assert "curves-truncated.csv" in read_nshmp_curve(truncated).notes[0]


# ------------------------------------------------------------------ refusals


def _edited(tmp_path, header=None, row=None, imt="PGA") -> Path:
    path = write_nshmp(tmp_path, [0.01, 0.1, 1.0], [1e-2, 1e-3, 1e-5], imt=imt)
    lines = path.read_text().splitlines()
    path.write_text("\n".join([header or lines[0], row or lines[1]]) + "\n")
    return path


def _refusal(path, **kwargs):
    with pytest.raises(InputError) as caught:
        read_hazard_curve_file(path, **kwargs)
    return caught.value.problems


@pytest.mark.parametrize("level", ["1e400", "1e-298", "50.0", "-0.1"])
def test_an_implausible_level_is_refused_at_its_column(tmp_path, level):
    (problem,) = _refusal(_edited(tmp_path, header=f"name,lon,lat,0.01,0.1,{level}"))
    assert problem.row == 1 and problem.column == level and "outside 1e-05 to 10 g" in problem.message


def test_levels_that_do_not_increase_are_refused(tmp_path):
    (problem,) = _refusal(_edited(tmp_path, header="name,lon,lat,0.01,0.1,0.1"))
    assert problem.row == 1 and "must increase" in problem.message


def test_a_map_of_return_periods_is_told_from_a_curve(tmp_path):
    (problem,) = _refusal(_edited(tmp_path, header="name,lon,lat,475,975,2475"))
    assert "return periods" in problem.message and "map.csv" in problem.fix


@pytest.mark.parametrize("value, why", [("nan", "is not an annual rate"), ("inf", "is not an annual rate"),
                                        ("-1e-3", "is not an annual rate"), ("1e5", "is not an annual rate"),
                                        (f"{SECRET}:x", "not shown")])
def test_a_rate_that_is_no_rate_is_refused_at_its_cell_without_quoting_text(tmp_path, value, why):
    (problem,) = _refusal(_edited(tmp_path, row=f"Test Site,-122.3,47.6,1e-2,{value},1e-5"))
    assert problem.row == 2 and problem.column == "0.1" and why in problem.message
    assert SECRET not in str(problem)


def test_a_curve_rising_with_the_level_is_refused(tmp_path):
    (problem,) = _refusal(_edited(tmp_path, row="Test Site,-122.3,47.6,1e-3,1e-2,1e-5"))
    assert problem.row == 2 and problem.column == "0.1" and "not monotone" in problem.message


@pytest.mark.parametrize("row, text", [("Test Site,-122.3,47.6,1e-2,1e-3", "fields"),
                                       ("Test Site,-422.3,47.6,1e-2,1e-3,1e-5", "not a longitude"),
                                       ("Test Site,-122.3,97.6,1e-2,1e-3,1e-5", "not a latitude")])
def test_a_bad_site_row_is_refused(tmp_path, row, text):
    (problem,) = _refusal(_edited(tmp_path, row=row))
    assert problem.row == 2 and text in problem.message


def test_a_curve_of_another_intensity_measure_is_refused(tmp_path):
    (problem,) = _refusal(_edited(tmp_path, imt="SA0P2"))
    assert "for SA0P2, not PGA" in problem.message and "PGA/curves.csv" in problem.fix


def test_a_curve_whose_path_names_no_intensity_measure_is_refused(tmp_path):
    path = _edited(tmp_path).rename(tmp_path / "site-curve.csv")
    (problem,) = _refusal(path)
    assert "does not say its intensity measure" in problem.message


def test_a_file_too_large_is_refused_unread(tmp_path):
    path = tmp_path / "PGA" / "curves.csv"
    path.parent.mkdir()
    with path.open("wb") as stream:  # sparse: no disk written
        stream.truncate(MAX_HAZARD_FILE_BYTES + 1)
    (problem,) = _refusal(path)
    assert "larger than 32 MiB" in problem.message and "read no further" in problem.message
    with pytest.raises(InputError):
        bounded_text(_edited(tmp_path / "small"), max_bytes=10)


def test_a_file_of_neither_format_names_both(tmp_path):
    fake = tmp_path / "passwd"
    fake.write_text(f"root:x:0:0:{SECRET}:/root:/bin/bash\n")
    (problem,) = _refusal(fake)
    assert "not an OpenQuake hazard curve or map" in problem.message and "USGS nshmp-haz" in problem.fix
    assert SECRET not in str(problem) and "root:" not in str(problem)


@pytest.mark.parametrize("text", ["name,lon,lat,0.1,0.2\n" + "x" * 200_000 + ",1,2,0.1,0.01\n",
                                  "a" * 200_000 + "\n1,2\n",
                                  "#,,\"kind='mean', investigation_time=1.0\"\nlon,lat,poe-0.1\n" + "y" * 200_000])
def test_a_field_beyond_the_csv_limit_is_refused_not_a_crash(tmp_path, text):
    path = tmp_path / "PGA" / "curves.csv"
    path.parent.mkdir()
    path.write_text(text)
    (problem,) = _refusal(path)
    assert "field larger than field limit" in problem.message and "x" * 50 not in str(problem)


def test_a_folder_or_a_missing_file_is_refused(tmp_path):
    (problem,) = _refusal(tmp_path)
    assert "is not a file" in problem.message
    (problem,) = _refusal(tmp_path / "PGA" / "curves.csv")
    assert "does not exist" in problem.message and "--oq-hazard" in problem.fix


# ------------------------------------------------------------------ through the command


def test_the_command_refuses_a_damaged_nshmp_curve_and_writes_nothing(tmp_path):
    curve = _edited(tmp_path / "hazout", row="Test Site,-122.3,47.6,1e-2,nan,1e-5")
    done = commands.run(commands.LAB, "--hazard", "2in50", "--oq-hazard", curve, "--out", tmp_path / "out",
                        "--format", "xlsx", cwd=tmp_path)
    commands.assert_refused(done, "is not an annual rate", places=[f"{curve}, row 2, column '0.1'"])
    assert not (tmp_path / "out").exists()


@pytest.mark.skipif(not Path("/proc/self/environ").exists(), reason="no /proc/self/environ here")
def test_proc_self_environ_is_never_printed(tmp_path):
    done = commands.run(commands.LAB, "--hazard", "2in50", "--oq-hazard", "/proc/self/environ", "--out",
                        tmp_path / "out", cwd=tmp_path)
    commands.assert_refused(done, "not an OpenQuake hazard curve or map", "USGS nshmp-haz")
    assert os.environ.get("PATH", "PATH=") not in done.stderr


# ------------------------------------------------------------------ end to end: the same numbers


def test_an_assessment_over_an_nshmp_curve_matches_the_openquake_one_it_copies(tmp_path):
    """The lab's one-year OpenQuake curve and an nshmp-haz file of its rates (-ln(1 - P), written in full):
    the level's PGA, the motions' scaling, the fragilities' annual rates, expected annual losses and
    benefit-cost ratios agree to 1e-9."""
    from assess.assessment.pipeline import run_assessment
    from assess.inventory import read_workbook
    from tests.fragility.test_hazard_curve import SQUAT, _rect_record
    from workbooks import write_workbook

    oq_path = Path(__file__).resolve().parents[2] / "inventories" / "lab-hazard-curve.csv"
    lines = oq_path.read_text().splitlines()
    assert "investigation_time=1.0" in lines[0]
    header, row = lines[1].split(","), lines[2].split(",")
    levels = [float(name[len("poe-"):]) for name in header[3:]]
    usgs_path = write_nshmp(tmp_path / "hazout", levels, [-math.log1p(-float(p)) for p in row[3:]])
    book = write_workbook(tmp_path / "w.xlsx", {
        "equipment": [
            {"id": "S1", "name": "low friction", "floor": 0, "mu": 0.15, "clearance_cm": 10, "value": 40_000,
             "mitigation_cost": 1_500, **SQUAT},
            {"id": "S2", "name": "more friction", "floor": 0, "mu": 0.30, "clearance_cm": 25, "value": 9_000,
             "mitigation_cost": 800, **SQUAT}],
        "hazard": [{"level": "2in50", "motion": "rect", "floor": 0, "record": "records/rect.csv"}],
    }, files={"records/rect.csv": _rect_record()})
    runs = [run_assessment(read_workbook(book), "2in50", oq_hazard=hazard, hazard_curve=hazard)
            for hazard in (read_hazard_curve_file(oq_path), read_hazard_curve_file(usgs_path))]
    assert runs[0].curve_risk.curve.startswith("lab-hazard-curve.csv, site #0")
    assert runs[1].curve_risk.curve.startswith("PGA/curves.csv (USGS nshmp-haz), site #0")
    oq, usgs = (run.summary.set_index("id") for run in runs)
    columns = ["pta_g", "annual_rate_beyond_clearance", "annual_rate_beyond_clearance_low",
               "annual_rate_beyond_clearance_high", "p50yr_beyond_clearance", "expected_annual_loss",
               "expected_annual_loss_after", "benefit_cost_ratio"]
    assert oq[columns].notna().all().all(), oq[columns]
    np.testing.assert_allclose(usgs[columns].to_numpy(float), oq[columns].to_numpy(float), rtol=1e-9)


def test_a_portfolio_row_naming_an_nshmp_curve_gets_the_rates_of_the_openquake_one(tmp_path):
    """Two copies of one building in a portfolio, one with the lab's OpenQuake curve, one with its nshmp-haz
    copy (in the portfolio's folder, as a row names it): the same annual rates, item by item and in total."""
    import pandas as pd

    from assess import cli
    from tests.portfolio.test_batch import ITEMS, _write_building
    from workbooks import write_workbook

    site = tmp_path / "site"
    site.mkdir()
    oq_text = (Path(__file__).resolve().parents[2] / "inventories" / "lab-hazard-curve.csv").read_text()
    (site / "lab-curve.csv").write_text(oq_text)
    header, row = (line.split(",") for line in oq_text.splitlines()[1:3])
    write_nshmp(site / "hazout", [float(name[len("poe-"):]) for name in header[3:]],
                [-math.log1p(-float(p)) for p in row[3:]])
    for name in ("oq", "usgs"):
        _write_building(site, name, ITEMS["alpha"])
    portfolio = write_workbook(site / "portfolio.xlsx", {"buildings": [
        {"building": "oq", "workbook": "oq.xlsx", "level": "2in50", "oq_hazard": "lab-curve.csv"},
        {"building": "usgs", "workbook": "usgs.xlsx", "level": "2in50", "oq_hazard": "hazout/PGA/curves.csv"}]})
    out = tmp_path / "out"
    assert cli.main(["batch", str(portfolio), "--out", str(out), "--format", "xlsx", "--quiet"]) == 0
    oq, usgs = (pd.read_csv(out / name / "summary.csv").set_index("id") for name in ("oq", "usgs"))
    columns = [c for c in oq.columns if c.startswith(("annual_rate_", "p50yr_"))]
    assert oq["annual_rate_beyond_clearance"].notna().any()
    pd.testing.assert_frame_equal(usgs[columns], oq[columns])
    table = pd.read_csv(out / "portfolio.csv").set_index("building")
    assert table.at["usgs", "hazard_curve"] == "curves.csv"
    assert table.at["usgs", "annual_rate_beyond_clearance_units_total"] == \
        table.at["oq", "annual_rate_beyond_clearance_units_total"]


def _label_workbook(folder: Path, level: str) -> Path:
    from workbooks import job_sheets, write_workbook

    sheets = job_sheets()
    sheets["hazard"][0]["level"] = level
    folder.mkdir(parents=True, exist_ok=True)
    return write_workbook(folder / "wb.xlsx", sheets)


def test_a_level_named_by_a_label_keeps_its_motions_and_the_curve_gives_the_rates(tmp_path):
    """DE (a code level, no probability): nothing to read the curve at, so the motions stay the workbook's
    (PTA 0.5 g, as without a curve) and the curve gives the annual rates; a map, which only scales, is refused."""
    import pandas as pd

    book = _label_workbook(tmp_path / "site", "DE")
    curve = write_nshmp(tmp_path / "hazout", LEVELS_G, RATES)
    done = commands.run(book, "--hazard", "DE", "--oq-hazard", curve, "--out", tmp_path / "out", "--format", "xlsx",
                        cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert "level DE is a label, not a probability: its motions are kept" in done.stdout + done.stderr
    motions = pd.read_csv(tmp_path / "out" / "motions.csv")
    assert set(motions["pta_g"].round(12)) == {0.5}
    summary = pd.read_csv(tmp_path / "out" / "summary.csv")
    assert summary["annual_rate_beyond_clearance"].notna().any() or summary["annual_rate_overturn"].notna().any()
    hazard_map = Path(__file__).resolve().parents[1] / "data" / "openquake" / "case_18-hazard_map-mean.csv"
    done = commands.run(book, "--hazard", "DE", "--oq-hazard", hazard_map, "--oq-site", "0", "--out",
                        tmp_path / "map", "--format", "xlsx", cwd=tmp_path)
    commands.assert_refused(done, "the level 'DE' is a label with no probability")
    assert not (tmp_path / "map").exists()
