"""OpenQuake target spectra (assess/site/uhs.py) on the engine's own export files (tests/data/openquake/README.md)."""
import shutil
from pathlib import Path

import numpy as np
import pytest

from assess.errors import InputError
from assess.hazard.levels import parse_level
from assess.hazard.openquake import parse_site_choice
from assess.site.uhs import read_target_spectrum

DATA = Path(__file__).resolve().parents[1] / "data" / "openquake"
TEN_IN_50 = parse_level("10in50")  # 1 - exp(-1/474.56) = 0.002105 in 1 yr: case_18's poe


def test_user_guide_uhs_at_its_own_poe():
    uhs = read_target_spectrum(DATA / "userguide-hazard_uhs-rlz-001.csv", TEN_IN_50, site=1)
    assert uhs.source == "uhs" and uhs.statistic == "rlz-001" and uhs.investigation_time_yr == 1.0
    np.testing.assert_array_equal(uhs.period_s, [0.0, 0.2, 1.0])
    np.testing.assert_allclose(uhs.sa_g, [2.603451e-03, 1.105909e-02, 1.208975e-02], rtol=1e-12)
    assert uhs.site.lat == pytest.approx(49.26162)


def test_old_uhs_columns_and_comment():
    uhs = read_target_spectrum(DATA / "case_18-hazard_uhs-mean-old.csv", TEN_IN_50, site=(-123.2048, 49.26786))
    np.testing.assert_allclose(uhs.sa_g, [5.964043e-02, 1.325416e-01, 4.454478e-02], rtol=1e-12)


def test_multi_imt_map_is_a_spectrum():
    uhs = read_target_spectrum(DATA / "case_18-hazard_map-mean.csv", TEN_IN_50, site=0)
    assert uhs.source == "map"
    np.testing.assert_allclose(uhs.sa_g, [3.023842e-03, 1.227869e-02, 1.304541e-02], rtol=1e-12)


def test_curves_interpolated_as_openquake_builds_its_map():
    """The per-IMT curves of case_18 (engine 3.15), log-log at 0.002105 in 1 yr, against the engine's
    own hazard map of the same case (3.20): within 0.2 % (engine versions differ; the curve's levels
    are a decade apart at PGA, where OpenQuake interpolates the same way)."""
    uhs = read_target_spectrum(DATA / "case_18-curves" / "hazard_curve-mean_SA(0.2).csv", TEN_IN_50, site=0)
    assert uhs.source == "curves" and len(uhs.files) == 2
    np.testing.assert_array_equal(uhs.period_s, [0.0, 0.2])
    np.testing.assert_allclose(uhs.sa_g, [3.023842e-03, 1.227869e-02], rtol=0.002)
    # the 3.9-era SA(1.0) curve against the UHS the engine exported for that model: 4.460330E-02
    older = read_target_spectrum(DATA / "case_18-curves-3.9" / "hazard_curve-mean_SA(1.0).csv", TEN_IN_50, site=0)
    assert float(older.sa_g[0]) == pytest.approx(4.460330e-02, rel=0.002)


def test_interpolation_between_poes_is_exact_for_a_power_law():
    """P = k0 x^-2.5 (constructed file): x at 2 % in 50 yr = (0.02/k0)^(-1/2.5), for the site chosen by id."""
    uhs = read_target_spectrum(DATA / "constructed-hazard_uhs-mean_1.csv", parse_level("2in50"), site="LAB")
    k0 = np.array([0.004, 0.009, 0.006, 0.0008])
    np.testing.assert_allclose(uhs.sa_g, 1.5 * (0.02 / k0) ** (-1 / 2.5), rtol=1e-6)
    # between the periods: log-log; PGA to the first SA period: linear
    assert float(uhs.target_g(0.05)) == pytest.approx(0.5 * (uhs.sa_g[0] + uhs.sa_g[1]))
    assert float(uhs.target_g(1.0)) == pytest.approx(np.sqrt(uhs.sa_g[2] * uhs.sa_g[3]))
    with pytest.raises(ValueError):
        uhs.target_g(3.0)


def test_refusals_name_the_file_and_never_echo_it(tmp_path):
    constructed = DATA / "constructed-hazard_uhs-mean_1.csv"
    with pytest.raises(InputError, match="2 sites"):
        read_target_spectrum(constructed, parse_level("2in50"))
    with pytest.raises(InputError, match="not extrapolated"):
        read_target_spectrum(constructed, parse_level("10000yr"), site="HOSP")  # 0.005 in 50 yr, below 0.01
    with pytest.raises(InputError, match="not a probability"):
        read_target_spectrum(constructed, parse_level("DE"), site="HOSP")
    broken = tmp_path / "hazard_uhs-mean_2.csv"
    lines = constructed.read_text().splitlines()
    lines[2] = lines[2].replace("2.759459E-01", "SECRET-TEXT")
    broken.write_text("\n".join(lines) + "\n")
    with pytest.raises(InputError) as error:
        read_target_spectrum(broken, parse_level("2in50"), site="HOSP")
    text = str(error.value)
    problem = error.value.problems[0]
    assert problem.file == str(broken) and problem.row == 3 and problem.column == "4"
    assert "SECRET" not in text
    no_time = tmp_path / "hazard_uhs-mean_3.csv"
    no_time.write_text("\n".join(["# mean"] + lines[1:]) + "\n")
    with pytest.raises(InputError, match="investigation_time"):
        read_target_spectrum(no_time, parse_level("2in50"), site="HOSP")
    with pytest.raises(InputError, match="does not exist"):
        read_target_spectrum(tmp_path / "missing.csv", parse_level("2in50"))


def test_curve_outside_its_range_is_refused(tmp_path):
    folder = tmp_path / "export"
    shutil.copytree(DATA / "case_18-curves", folder)
    with pytest.raises(InputError, match="not extrapolated"):
        read_target_spectrum(folder / "hazard_curve-mean_PGA.csv", parse_level("50in50"), site=0)


def test_site_choice_text():
    assert parse_site_choice("0") == 0
    assert parse_site_choice(" -122.3 , 37.9 ") == (-122.3, 37.9)
    assert parse_site_choice(None) is None


@pytest.mark.parametrize("text", ["-122.25,37.87", "(-122.25, 37.87)", "[-122.25, 37.87]", "-122.25 37.87", " 0 ",
                                  "HOSP"])
def test_a_site_written_any_of_the_ways_the_fix_names_is_the_same_site(text):
    """The site sheet's ``oq_site`` and ``--oq-site`` read the same (one parser): a new user who followed the old
    fix text, "(lon, lat)", was told no site had that id. Each form picks the file's first site, HOSP."""
    from assess.command.job import oq_site

    path = DATA / "constructed-hazard_uhs-mean_1.csv"
    for site in (parse_site_choice(text), oq_site(text)):
        uhs = read_target_spectrum(path, parse_level("10in50"), site=site)
        assert uhs.site.custom_site_id == "HOSP", text


def test_a_wrong_oq_site_in_the_site_sheet_names_its_cell_and_the_files_sites(tmp_path):
    from assess.assessment.motions import check_level
    from assess.inventory import read_workbook
    from tests.assessment.test_floor_motions import BUILDING, EQUIPMENT
    from workbooks import write_workbook

    site = [["key", "value"], ["uhs", "oq/uhs.csv"], ["oq_site", "HOSPX"], ["suite_size", 3]]
    path = write_workbook(tmp_path / "w.xlsx", {"equipment": [dict(item) for item in EQUIPMENT], "site": site,
                                                "building": BUILDING},
                          files={"oq/uhs.csv": (DATA / "constructed-hazard_uhs-mean_1.csv").read_text()})
    with pytest.raises(InputError) as raised:
        check_level(read_workbook(path), "10in50")
    text = str(raised.value)
    assert "w.xlsx, sheet 'site', row 3, column 'value'" in text and "oq_site names no site of uhs.csv" in text
    assert "'HOSP'" in text and "'LAB'" in text and "lon,lat in degrees" in text


def test_level_names_its_target():
    from assess.site.asce7 import from_design_values
    from assess.site.target import level_target
    design = from_design_values(1.0, 0.6, 8.0)
    assert float(level_target(parse_level("DE"), design=design)(1.0)) == pytest.approx(0.6)
    assert float(level_target(parse_level("mce_r"), design=design)(1.0)) == pytest.approx(0.9)
    uhs = level_target(parse_level("2in50"), uhs_path=DATA / "constructed-hazard_uhs-mean_1.csv", oq_site="HOSP")
    assert uhs.max_period_s == 2.0
    with pytest.raises(InputError, match="sds_g"):
        level_target(parse_level("DE"), workbook="h.xlsx")
    with pytest.raises(InputError, match="uhs"):
        level_target(parse_level("2in50"), design=design, workbook="h.xlsx")
    with pytest.raises(InputError, match="no target"):
        level_target(parse_level("SLE"), design=design, workbook="h.xlsx")


def _curves_copy(tmp_path):
    folder = tmp_path / "site" / "oq"
    folder.mkdir(parents=True)
    for path in sorted((DATA / "case_18-curves").iterdir()):
        (folder / path.name).write_bytes(path.read_bytes())
    return folder


def test_a_curve_file_linked_out_of_the_export_folder_is_not_read(tmp_path):
    """A third hostile-input campaign's finding: a sibling of the named curve file that links to a file outside
    the folder was read, its site ids quoted in the error, its numbers taken as the target when it parsed. The
    outside file here is a valid curve of another site, so that reading it would succeed: it must be refused
    unread, the message naming the link and never the outside file's contents."""
    folder = _curves_copy(tmp_path)
    outside = tmp_path / "secret"
    outside.mkdir()
    sibling = folder / "hazard_curve-mean_PGA.csv"
    target = outside / sibling.name
    target.write_text(sibling.read_text().replace(",0.", ",0.9"))  # parsable, other numbers
    sibling.unlink()
    sibling.symlink_to(target)
    with pytest.raises(InputError) as error:
        read_target_spectrum(folder / "hazard_curve-mean_SA(0.2).csv", TEN_IN_50, site=0)
    text = str(error.value)
    assert sibling.name in text and "not read" in text and "0.9" not in text


def test_a_curve_file_linked_to_proc_is_refused_not_a_traceback(tmp_path):
    folder = _curves_copy(tmp_path)
    sibling = folder / "hazard_curve-mean_PGA.csv"
    sibling.unlink()
    sibling.symlink_to("/proc/self/status")
    with pytest.raises(InputError, match="not a plain file in the export's folder"):
        read_target_spectrum(folder / "hazard_curve-mean_SA(0.2).csv", TEN_IN_50, site=0)


def test_a_uhs_column_with_a_probability_above_one_is_refused_at_its_column(tmp_path):
    """Hostile-input campaign: a column '1.5~SA(0.2)' was accepted with a numpy warning on stderr."""
    source = (DATA / "constructed-hazard_uhs-mean_1.csv").read_text().splitlines()
    header = source[1].split(",")
    column = next(i for i, name in enumerate(header) if "~SA(" in name)
    header[column] = "1.5~" + header[column].split("~", 1)[1]
    path = tmp_path / "hazard_uhs-mean_1.csv"
    path.write_text("\n".join([source[0], ",".join(header)] + source[2:]) + "\n")
    with pytest.raises(InputError) as error:
        read_target_spectrum(path, parse_level("2in50"), site="HOSP")
    problem = error.value.problems[0]
    assert "not between 0 and 1" in problem.message and problem.column == f"{column + 1}"
