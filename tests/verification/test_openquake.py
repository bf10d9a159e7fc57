"""OpenQuake hazard curves and maps -> PGA at a hazard level (``assess/hazard/openquake.py``).

The CSVs in ``tests/data/openquake/`` are the OpenQuake engine's own QA expected
outputs, copied verbatim (see the README there). Expected PGAs are worked out
here by hand from the numbers in those files, with the log–log interpolation
and the Poisson conversion written out, never taken from the module's output.
"""
from __future__ import annotations

import math
from pathlib import Path

import pytest

from assess.errors import InputError
from assess.hazard.levels import HazardLevel, parse_level
from assess.hazard.openquake import (
    OpenQuakeHazard,
    parse_openquake_comment,
    pga_at_level,
    poe_in_investigation_time,
    read_openquake_hazard,
)

DATA = Path(__file__).resolve().parents[1] / "data" / "openquake"
CURVE_50YR = DATA / "case_14-hazard_curve-rlz-000_PGA.csv"  # 10 sites, investigation_time=50.0
CURVE_1YR = DATA / "case_13-hazard_curve-mean-PGA.csv"  # 3 sites, investigation_time=1.0
CURVE_ONE_SITE = DATA / "case_23-hazard_curve-mean-PGA_953.csv"  # 1 site, 1 yr
MAP_1YR = DATA / "case_18-hazard_map-mean.csv"  # PGA-0.002105 + 2 SA columns, 3 sites
MAP_CUSTOM_ID = DATA / "case_26-hazard_map-mean.csv"  # custom_site_id, secondary perils
MAP_OLD_50YR = DATA / "case_13-hazard_map-mean.csv"  # "# mean, investigation_time=50.0", depth

TWO_IN_50 = HazardLevel(0.02, 50.0)
TEN_IN_50 = HazardLevel(0.10, 50.0)


def loglog(x0, p0, x1, p1, p):
    """ln x linear in ln p between (x0, p0) and (x1, p1): written out independently."""
    return math.exp(math.log(x0) + (math.log(p) - math.log(p0))
                    * (math.log(x1) - math.log(x0)) / (math.log(p1) - math.log(p0)))


def only_problem(excinfo):
    problems = excinfo.value.problems
    assert len(problems) == 1, problems
    return problems[0]


def variant(tmp_path, source, old, new, name=None):
    """A copy of a real file with one text replaced (for the error cases)."""
    text = source.read_text()
    assert old in text, old
    out = tmp_path / (name or source.name)
    out.write_text(text.replace(old, new, 1))
    return out


# --------------------------------------------------------------------------- hazard curves


def test_curve_50yr_is_read_with_its_metadata():
    hazard = read_openquake_hazard(CURVE_50YR, site=0)
    assert isinstance(hazard, OpenQuakeHazard)
    assert hazard.kind == "curve" and hazard.imt == "PGA"
    assert hazard.investigation_time_yr == 50.0
    assert hazard.statistic == "rlz-000"
    assert any("rlz-000" in note for note in hazard.notes)  # not the mean: said so
    assert hazard.metadata["generated_by"] == "OpenQuake engine 3.7.0-git5e91b20b88"
    assert hazard.metadata["checksum"] == "2580379596"
    assert len(hazard.sites) == 10
    assert (hazard.site.lon, hazard.site.lat, hazard.site.depth_km) == (-122.5, 38.1, 0.0)
    assert hazard.site.line == 3  # comment line 1, header line 2
    assert hazard.levels_g[0] == 0.005 and hazard.levels_g[-1] == 0.284
    assert hazard.poes.shape == (10, 13)
    assert hazard.poes[0, 9] == 2.703533e-02


def test_curve_50yr_pga_at_2_and_10_percent_in_50_years():
    """investigation_time = exposure time = 50 yr: the level's poe is used as is."""
    hazard = read_openquake_hazard(CURVE_50YR, site=0)  # lon -122.5, lat 38.1
    # 2 %: poe 0.02 lies between 0.103 g (2.703533E-02) and 0.145 g (5.818043E-03)
    expected_2 = loglog(0.1030, 2.703533e-02, 0.1450, 5.818043e-03, 0.02)
    # 10 %: poe 0.1 lies between 0.0527 g (1.891050E-01) and 0.0738 g (8.157492E-02)
    expected_10 = loglog(0.0527, 1.891050e-01, 0.0738, 8.157492e-02, 0.10)
    assert pga_at_level(hazard, TWO_IN_50) == pytest.approx(expected_2, rel=1e-12)
    assert pga_at_level(hazard, TEN_IN_50) == pytest.approx(expected_10, rel=1e-12)
    # by hand (calculator): 0.103 * exp(ln(0.02/0.02703533) * ln(0.145/0.103)
    #                        / ln(0.005818043/0.02703533)) = 0.11015 g
    assert pga_at_level(hazard, TWO_IN_50) == pytest.approx(0.11015, abs=1e-5)
    assert pga_at_level(hazard, TEN_IN_50) == pytest.approx(0.06802, abs=1e-5)


def test_curve_1yr_converts_the_level_with_poisson():
    """investigation_time = 1 yr: P_1 = 1 - exp(-1/T_R) = 1 - (1 - P_50)^(1/50)."""
    hazard = read_openquake_hazard(CURVE_1YR, site=(-65.0, 0.0))
    assert hazard.investigation_time_yr == 1.0 and hazard.site_index == 0
    p2 = 1.0 - 0.98 ** (1.0 / 50.0)  # 4.0397e-4, not 0.02/50 = 4.0e-4
    p10 = 1.0 - 0.90 ** (1.0 / 50.0)  # 2.1050e-3
    # p2 between 0.4641589 g (7.837311E-04) and 1.0 g (1.016227E-04)
    expected_2 = loglog(0.4641589, 7.837311e-04, 1.0, 1.016227e-04, p2)
    # p10 between 0.2154435 g (3.026459E-03) and 0.4641589 g (7.837311E-04)
    expected_10 = loglog(0.2154435, 3.026459e-03, 0.4641589, 7.837311e-04, p10)
    assert pga_at_level(hazard, TWO_IN_50) == pytest.approx(expected_2, rel=1e-12)
    assert pga_at_level(hazard, TEN_IN_50) == pytest.approx(expected_10, rel=1e-12)
    assert pga_at_level(hazard, TWO_IN_50) == pytest.approx(0.5954, abs=1e-4)
    assert pga_at_level(hazard, TEN_IN_50) == pytest.approx(0.2648, abs=1e-4)
    # any spelling of the same level gives the same PGA
    assert pga_at_level(hazard, parse_level("2475yr")) == pytest.approx(expected_2, rel=1e-4)


def test_poisson_conversion_between_investigation_times():
    assert poe_in_investigation_time(TWO_IN_50, 50.0) == pytest.approx(0.02, rel=1e-12)
    assert poe_in_investigation_time(TWO_IN_50, 1.0) == pytest.approx(1 - 0.98 ** (1 / 50), rel=1e-12)
    assert poe_in_investigation_time(TEN_IN_50, 1.0) == pytest.approx(1 - 0.90 ** (1 / 50), rel=1e-12)
    assert poe_in_investigation_time(TWO_IN_50, 100.0) == pytest.approx(1 - 0.98 ** 2, rel=1e-12)


def test_same_hazard_in_1yr_and_50yr_files_gives_the_same_pga(tmp_path):
    """The one-site 1-yr curve rewritten for 50 yr (P50 = 1 - (1 - P1)^50, Poisson).

    Tolerance 1e-3: log–log interpolation is not exactly invariant under that
    transform (nearly a power law for these small poes: ~1e-4 apart) and the
    rewritten poes are rounded to 7 digits like OpenQuake's.
    """
    lines = CURVE_ONE_SITE.read_text().splitlines()
    comment = lines[0].replace("investigation_time=1.0", "investigation_time=50.0")
    cells = lines[2].split(",")
    poes_50 = ["%.6E" % (1.0 - (1.0 - float(c)) ** 50) for c in cells[3:]]
    out = tmp_path / "hazard_curve-mean-PGA_50yr.csv"
    out.write_text("\n".join([comment, lines[1], ",".join(cells[:3] + poes_50)]) + "\n")
    one_year = read_openquake_hazard(CURVE_ONE_SITE)
    fifty_years = read_openquake_hazard(out)
    assert fifty_years.investigation_time_yr == 50.0
    for level in (TWO_IN_50, parse_level("3in50")):
        assert pga_at_level(fifty_years, level) == pytest.approx(
            pga_at_level(one_year, level), rel=1e-3)


def test_one_site_file_needs_no_site_and_its_real_export_name_is_read():
    hazard = read_openquake_hazard(CURVE_ONE_SITE)
    assert hazard.site_index == 0 and len(hazard.sites) == 1
    p2 = 1.0 - 0.98 ** (1.0 / 50.0)  # 4.0397e-4: between 0.0465264 g (4.460811E-04)
    expected = loglog(0.0465264, 4.460811e-04, 0.0639867, 3.517737e-04, p2)  # and 0.0639867 g
    assert pga_at_level(hazard, TWO_IN_50) == pytest.approx(expected, rel=1e-12)


def test_windows_line_ends_and_byte_order_mark_are_read(tmp_path):
    """OpenQuake's csv.writer ends lines with \\r\\n; Excel may add a BOM."""
    out = tmp_path / "crlf.csv"
    out.write_bytes(b"\xef\xbb\xbf" + CURVE_ONE_SITE.read_text().replace("\n", "\r\n").encode())
    assert pga_at_level(read_openquake_hazard(out), TWO_IN_50) == pytest.approx(
        pga_at_level(read_openquake_hazard(CURVE_ONE_SITE), TWO_IN_50), rel=1e-15)


# --------------------------------------------------------------------------- hazard maps


def test_map_1yr_picks_the_column_of_the_level():
    """PGA-0.002105 per year is 10 % in 50 years: rates 0.0021072 vs -ln(0.9)/50."""
    assert -math.log(1 - 0.002105) / 1.0 == pytest.approx(-math.log(0.9) / 50.0, rel=0.01)
    hazard = read_openquake_hazard(MAP_1YR, site=0)
    assert hazard.kind == "map" and hazard.investigation_time_yr == 1.0
    assert list(hazard.map_poes) == [0.002105]
    assert any("SA(0.2)" in note and "SA(1.0)" in note for note in hazard.notes)
    assert pga_at_level(hazard, TEN_IN_50) == 3.023842e-03
    assert pga_at_level(read_openquake_hazard(MAP_1YR, site=2), TEN_IN_50) == 2.971275e-03


def test_map_older_comment_style_with_depth_column():
    hazard = read_openquake_hazard(MAP_OLD_50YR, site=(-121.19, 36.73))
    assert hazard.investigation_time_yr == 50.0 and hazard.statistic == "mean"
    assert hazard.site.depth_km == 0.0 and hazard.site_index == 4
    assert pga_at_level(hazard, TEN_IN_50) == 2.219182e-01
    assert pga_at_level(hazard, parse_level("475yr")) == 2.219182e-01


def test_map_with_custom_site_ids_and_secondary_perils():
    hazard = read_openquake_hazard(MAP_CUSTOM_ID, site="d29egh4g")
    assert hazard.site_index == 4 and hazard.site.custom_site_id == "d29egh4g"
    assert any("HazusLiquefaction_LiqProb" in note for note in hazard.notes)
    assert pga_at_level(hazard, HazardLevel(0.01, 1.0)) == 1.334583e-01  # 1 % per year


def test_map_at_2_and_10_percent_in_50_years(tmp_path):
    """A 50-yr map with both poes, as OpenQuake writes it (comment row padded to the
    header's width), holding what OpenQuake would compute from case 14's first curve."""
    pga_2 = loglog(0.1030, 2.703533e-02, 0.1450, 5.818043e-03, 0.02)
    pga_10 = loglog(0.0527, 1.891050e-01, 0.0738, 8.157492e-02, 0.10)
    out = tmp_path / "hazard_map-rlz-000_7.csv"
    out.write_text(
        "#,,,,,\"generated_by='OpenQuake engine 3.16.0', start_date='2023-05-02T10:00:00', "
        "checksum=2580379596, kind='rlz-000', investigation_time=50.0\"\n"
        "lon,lat,PGA-0.1,PGA-0.02,SA(0.2)-0.1,SA(0.2)-0.02\n"
        f"-122.50000,38.10000,{pga_10:.6E},{pga_2:.6E},2.0E-01,3.0E-01\n")
    hazard = read_openquake_hazard(out)
    assert list(hazard.map_poes) == [0.1, 0.02]
    assert pga_at_level(hazard, TWO_IN_50) == pytest.approx(pga_2, rel=1e-6)
    assert pga_at_level(hazard, TEN_IN_50) == pytest.approx(pga_10, rel=1e-6)
    # the curve of the same site gives the same numbers
    curve = read_openquake_hazard(CURVE_50YR, site=0)
    assert pga_at_level(curve, TWO_IN_50) == pytest.approx(pga_at_level(hazard, TWO_IN_50), rel=1e-6)


def test_map_poe_written_in_exponent_form(tmp_path):
    """'%s' % 1e-05 is '1e-05': the column is PGA-1e-05, return period 100000 yr."""
    out = tmp_path / "hazard_map-mean_9.csv"
    out.write_text("#,,\"kind='mean', investigation_time=1.0\"\nlon,lat,PGA-1e-05\n"
                   "0.00000,0.00000,1.234000E+00\n")
    hazard = read_openquake_hazard(out)
    assert list(hazard.map_poes) == [1e-05]
    assert pga_at_level(hazard, parse_level("100000yr")) == 1.234


def test_map_without_the_levels_column_lists_what_it_has():
    with pytest.raises(InputError) as excinfo:
        pga_at_level(read_openquake_hazard(MAP_1YR, site=0), TWO_IN_50)
    problem = only_problem(excinfo)
    assert problem.file.endswith("case_18-hazard_map-mean.csv")
    assert "2% in 50 years" in problem.message
    assert "PGA-0.002105 (return period 475 years)" in problem.message
    assert "poes" in problem.fix


def test_map_zero_is_refused(tmp_path):
    """OpenQuake writes 0 when the level lies below the curve's lowest level."""
    out = variant(tmp_path, MAP_1YR, "3.023842E-03", "0.000000E+00")
    with pytest.raises(InputError) as excinfo:
        pga_at_level(read_openquake_hazard(out, site=0), TEN_IN_50)
    problem = only_problem(excinfo)
    assert problem.row == 3 and problem.column == "PGA-0.002105"
    assert "writes 0" in problem.message


# --------------------------------------------------------------------------- sites


def test_several_sites_and_none_chosen_lists_them():
    with pytest.raises(InputError) as excinfo:
        read_openquake_hazard(CURVE_50YR)
    problem = only_problem(excinfo)
    assert "10 sites" in problem.message
    assert "lon -122.50000, lat 38.10000" in problem.message
    assert "lon -121.47000, lat 38.10000" in problem.message
    assert "lon,lat" in problem.fix and "--oq-site" in problem.fix


def test_site_by_coordinates_index_and_missing_site():
    assert read_openquake_hazard(CURVE_50YR, site=(-122.39, 38.1)).site_index == 1
    assert read_openquake_hazard(CURVE_50YR, site=9).site.lon == -121.47
    with pytest.raises(InputError) as excinfo:
        read_openquake_hazard(CURVE_50YR, site=(-100.0, 30.0))
    assert "nearest" in only_problem(excinfo).message
    with pytest.raises(InputError) as excinfo:
        read_openquake_hazard(CURVE_50YR, site=10)
    assert "index 0 to 9" in only_problem(excinfo).message
    with pytest.raises(InputError) as excinfo:
        read_openquake_hazard(MAP_CUSTOM_ID, site="nope")
    assert "d29e420k" in only_problem(excinfo).message


# --------------------------------------------------------------------------- comment line


def test_comment_pairs_with_commas_inside_quotes_and_brackets():
    # from the OpenQuake manual (conditional spectrum export) and older engines
    pairs = parse_openquake_comment(
        "generated_by='OpenQuake engine 3.13.0-gitd78d717e66', start_date='2021-10-13T06:15:20', "
        "checksum=3067457643, imls=[0.99999, 0.61470], site_id=0, lon=0.0, lat=0.0")
    assert pairs["generated_by"] == "OpenQuake engine 3.13.0-gitd78d717e66"
    assert pairs["imls"] == "[0.99999, 0.61470]" and pairs["lat"] == "0.0"
    old = parse_openquake_comment("# source_model_tree_path=('b11',), gsim_tree_path=('b1',), "
                                  "investigation_time=1.0, imt=\"PGA\", checksum=141718627")
    assert old["source_model_tree_path"] == "('b11',)"
    assert old["investigation_time"] == "1.0" and old["imt"] == "PGA"
    assert parse_openquake_comment("description='a, b = c', kind='mean'") == {
        "description": "a, b = c", "kind": "mean"}
    assert parse_openquake_comment("# mean, investigation_time=50.0")["kind"] == "mean"


# --------------------------------------------------------------------------- errors


def test_missing_file(tmp_path):
    with pytest.raises(InputError) as excinfo:
        read_openquake_hazard(tmp_path / "hazard_curve-mean-PGA_1.csv")
    problem = only_problem(excinfo)
    assert problem.file.endswith("hazard_curve-mean-PGA_1.csv")
    assert "does not exist" in problem.message and problem.fix


@pytest.mark.parametrize("text, words", [
    ("time_s,accel_g\n0.00,0.0\n0.01,0.1\n", "lon and lat"),
    ("", "empty"),
    ("#,,,\"kind='mean', investigation_time=1.0\"\nlon,lat,0.002105~PGA,0.002105~SA(0.2)\n"
     "0.0,0.0,0.1,0.2\n", "uniform hazard spectrum"),
    ("#,,,\"kind='mean', investigation_time=1.0\"\nlon,lat,poe-0.1,PGA-0.1\n0.0,0.0,0.1,0.2\n",
     "neither"),
])
def test_not_an_openquake_curve_or_map(tmp_path, text, words):
    out = tmp_path / "hazard.csv"
    out.write_text(text)
    with pytest.raises(InputError) as excinfo:
        read_openquake_hazard(out)
    problem = only_problem(excinfo)
    assert words in problem.message and "--export-outputs" in problem.fix


def test_curve_for_another_imt_is_refused(tmp_path):
    out = variant(tmp_path, CURVE_ONE_SITE, "imt='PGA'", "imt='SA(0.5)'",
                  name="hazard_curve-mean-SA(0.5)_953.csv")
    with pytest.raises(InputError) as excinfo:
        read_openquake_hazard(out)
    problem = only_problem(excinfo)
    assert "SA(0.5), not PGA" in problem.message and problem.row == 1
    assert "hazard_curve-mean-PGA" in problem.fix


def test_map_without_pga_is_refused(tmp_path):
    text = MAP_1YR.read_text().replace("lon,lat,PGA-0.002105,", "lon,lat,")
    rows = text.splitlines()
    rows[2:] = [",".join(r.split(",")[:2] + r.split(",")[3:]) for r in rows[2:]]
    out = tmp_path / "hazard_map-mean_1.csv"
    out.write_text("\n".join(rows) + "\n")
    with pytest.raises(InputError) as excinfo:
        read_openquake_hazard(out)
    problem = only_problem(excinfo)
    assert "no PGA column" in problem.message and "SA(0.2), SA(1.0)" in problem.message


@pytest.mark.parametrize("old, new, words", [
    (", investigation_time=1.0", "", "gives no investigation_time"),
    ("investigation_time=1.0", "investigation_time=None", "not a positive number"),
])
def test_bad_or_missing_investigation_time(tmp_path, old, new, words):
    out = variant(tmp_path, CURVE_ONE_SITE, old, new)
    with pytest.raises(InputError) as excinfo:
        read_openquake_hazard(out)
    problem = only_problem(excinfo)
    assert words in problem.message and problem.row == 1


def test_comment_line_stripped_off(tmp_path):
    out = tmp_path / "hazard_curve-mean-PGA_953.csv"
    out.write_text("\n".join(CURVE_ONE_SITE.read_text().splitlines()[1:]) + "\n")
    with pytest.raises(InputError) as excinfo:
        read_openquake_hazard(out)
    assert "comment line OpenQuake writes first" in only_problem(excinfo).message


def test_non_monotone_curve_names_line_and_column(tmp_path):
    out = variant(tmp_path, CURVE_ONE_SITE, "8.897138E-04", "9.900000E-04")
    with pytest.raises(InputError) as excinfo:
        read_openquake_hazard(out)
    problem = only_problem(excinfo)
    assert problem.row == 3 and problem.column == "poe-0.0094569"
    assert "not monotone" in problem.message


def test_levels_not_increasing_in_the_header(tmp_path):
    out = variant(tmp_path, CURVE_ONE_SITE, "poe-0.0068764", "poe-0.0040000")
    with pytest.raises(InputError) as excinfo:
        read_openquake_hazard(out)
    problem = only_problem(excinfo)
    assert problem.row == 2 and problem.column == "poe-0.0040000"


def test_cell_that_is_not_a_number(tmp_path):
    out = variant(tmp_path, CURVE_50YR, "7.544442E-01", "n/a")
    with pytest.raises(InputError) as excinfo:
        read_openquake_hazard(out, site=0)
    problem = only_problem(excinfo)
    assert problem.row == 3 and problem.column == "poe-0.0137000"
    assert "'n/a' is not a number" in problem.message


def test_row_with_missing_fields(tmp_path):
    out = variant(tmp_path, MAP_1YR, ",1.210475E-02,1.294519E-02", "")
    with pytest.raises(InputError) as excinfo:
        read_openquake_hazard(out, site=0)
    problem = only_problem(excinfo)
    assert problem.row == 4 and "3 fields" in problem.message


def test_level_more_frequent_than_the_curve_covers():
    """10 % in 50 yr is 2.1e-3 per year; the curve's lowest level 0.005 g has only 9.6e-4."""
    with pytest.raises(InputError) as excinfo:
        pga_at_level(read_openquake_hazard(CURVE_ONE_SITE), TEN_IN_50)
    problem = only_problem(excinfo)
    assert "below the curve's lowest PGA level 0.005 g" in problem.message
    assert problem.row == 3 and "lower PGA levels" in problem.fix


def test_level_rarer_than_the_curve_covers():
    # 1e-6 per year: below the top level's 1.514692E-06
    with pytest.raises(InputError) as excinfo:
        pga_at_level(read_openquake_hazard(CURVE_ONE_SITE), parse_level("1000000yr"))
    assert "above the curve's range" in only_problem(excinfo).message
    # case 14, first site: poe 0 at 0.284 g, so the range ends at 0.203 g (4.242370E-04)
    with pytest.raises(InputError) as excinfo:
        pga_at_level(read_openquake_hazard(CURVE_50YR, site=0), HazardLevel(0.0001, 50.0))
    problem = only_problem(excinfo)
    assert "0.203 g" in problem.message and "higher PGA levels" in problem.fix
