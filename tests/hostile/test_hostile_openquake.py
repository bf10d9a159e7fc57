"""Hostile and edited OpenQuake files given to ``--oq-hazard`` (and to ``batch`` through a portfolio).

Each ends in exit 2 with a message naming the file and what is expected, or in
numbers: never a traceback (ValueError, OverflowError) and never the contents
of a file that is not a curve (/etc/passwd, /proc/self/environ).
"""
from __future__ import annotations

import math
import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from assess.errors import InputError
from assess.hazard.levels import HazardLevel
from assess.hazard.openquake import (MAX_PLAUSIBLE_PGA_G, MIN_PLAUSIBLE_PGA_G, pga_at_level,
                                     read_openquake_hazard)
from assess.hazard.risk_integral import cornell_failure_rate, openquake_failure_rate, segment_failure_rate
from workbooks import good_sheets, write_workbook

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "data" / "openquake"
CURVE_ONE_SITE = DATA / "case_23-hazard_curve-mean-PGA_953.csv"  # 1 site, 1 yr, 0.005 .. 2.13 g
LAST_POE = "1.514692E-06"  # the poe of its last level, 2.13 g
SECRET = "hunter2-SECRET-TOKEN"
#: A 10 s record peaking at 0.3 g.
_T = np.arange(0.0, 10.0, 0.01)
RECORD = "time_s,accel_g\n" + "".join(f"{t:.2f},{a:.6f}\n" for t, a in
                                      zip(_T, 0.3 * np.sin(2 * np.pi * _T) * np.exp(-0.3 * _T)))


def cli_env(**extra) -> dict:
    return {**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]), **extra}


def run(*args, cwd, env=None, timeout=600):
    started = time.monotonic()
    done = subprocess.run([sys.executable, "-m", "assess", *map(str, args)], cwd=cwd, capture_output=True,
                          text=True, timeout=timeout, env=env or cli_env())
    done.seconds = time.monotonic() - started
    return done


def assert_refused(done, *expected):
    assert done.returncode == 2, done.stderr
    assert "Traceback" not in done.stderr and "internal error" not in done.stderr, done.stderr
    for text in expected:
        assert text in done.stderr, done.stderr


def curve_with(tmp_path, old, new, name="hazard_curve-mean-PGA_1.csv") -> Path:
    text = CURVE_ONE_SITE.read_text()
    assert old in text
    path = tmp_path / name
    path.write_text(text.replace(old, new, 1))
    return path


def one_record_workbook(folder: Path) -> Path:
    sheets = good_sheets()
    sheets["hazard"] = [{"level": "2in50", "motion": "M1", "floor": "all", "record": "m1.csv"}]
    folder.mkdir(parents=True, exist_ok=True)
    return write_workbook(folder / "wb.xlsx", sheets, files={"m1.csv": RECORD})


# ------------------------------------------------------------------ levels and probabilities

@pytest.mark.parametrize("column", ["poe-1e400", "poe-1e-298", "poe-50.0"])
def test_a_level_outside_the_plausible_range_is_refused_at_its_column(tmp_path, column):
    path = curve_with(tmp_path, "poe-2.1300000", column)
    with pytest.raises(InputError) as caught:
        read_openquake_hazard(path)
    (problem,) = caught.value.problems
    assert problem.column == column and problem.row == 2
    assert f"outside {MIN_PLAUSIBLE_PGA_G:g} to {MAX_PLAUSIBLE_PGA_G:g} g" in problem.message


def test_a_pga_of_1e_298_g_is_refused_not_read_as_a_low_hazard(tmp_path):
    path = curve_with(tmp_path, "poe-0.0050000", "poe-1e-298")
    with pytest.raises(InputError) as caught:
        read_openquake_hazard(path)
    assert "1e-298 g, outside 1e-05 to 10 g" in str(caught.value)


def test_a_map_value_of_1e_298_g_is_refused(tmp_path):
    path = tmp_path / "hazard_map-mean_1.csv"
    path.write_text("#,,\"kind='mean', investigation_time=50.0\"\nlon,lat,PGA-0.02\n0.0,0.0,1e-298\n")
    hazard = read_openquake_hazard(path)
    with pytest.raises(InputError) as caught:
        pga_at_level(hazard, HazardLevel(0.02, 50.0))
    assert "outside 1e-05 to 10 g" in str(caught.value)


@pytest.mark.parametrize("poe", ["5E-324", "1E-300", "1E-100"])
def test_a_tiny_last_poe_gives_a_finite_rate_not_overflow(tmp_path, poe):
    """It raised OverflowError (e^{k²β²/2} of a steep last segment); the rate is now that of a curve ending there."""
    original = openquake_failure_rate(read_openquake_hazard(CURVE_ONE_SITE), 0.3, 0.5)
    edited = openquake_failure_rate(read_openquake_hazard(curve_with(tmp_path, LAST_POE, poe)), 0.3, 0.5)
    assert math.isfinite(edited.annual_rate)
    # less hazard at the top level: less failure, by at most what the original had above 1.55 g
    assert edited.annual_rate <= original.annual_rate
    assert edited.annual_rate >= original.rate_within_curve * 0.5


def test_a_steep_segment_against_the_closed_form():
    """A power law λ = c a^-k with k = 300: the whole-line integral is Cornell's closed form, in logs."""
    k, beta, median, anchor_rate = 300.0, 0.05, 1.0, 1e-4
    rate = segment_failure_rate(0.0, math.inf, 1.0, anchor_rate, k, median, beta)
    expected = cornell_failure_rate(anchor_rate, k, median, beta)  # 1e-4 · e^{k²β²/2} = 1e-4 · e^{112.5}
    assert math.isclose(rate, expected, rel_tol=1e-9)
    # steeper still, k β = 60: e^{k²β²/2} = e^{1800} overflows a float, the rate does not. With θ = e^6 g,
    # λ_f = c θ^-k e^{k²β²/2} = 1e-4 · e^{-1800} · e^{1800} = 1e-4 (Cornell's form, exponents added by hand)
    rate = segment_failure_rate(0.0, math.inf, 1.0, anchor_rate, 300.0, math.exp(6.0), 0.2)
    assert math.isclose(rate, 1e-4, rel_tol=1e-9)


def test_a_curve_with_poe_1e400_through_the_cli_exits_2(tmp_path):
    book = one_record_workbook(tmp_path / "site")
    curve = curve_with(tmp_path / "site", "poe-2.1300000", "poe-1e400")
    done = run(book, "--hazard", "2in50", "--oq-hazard", curve, "--out", tmp_path / "out", "--format", "xlsx",
               cwd=tmp_path)
    assert_refused(done, curve.name, "'poe-1e400'", "outside 1e-05 to 10 g")
    assert not (tmp_path / "out").exists()


# ------------------------------------------------------------------ files that are not curves

def test_etc_passwd_is_refused_without_quoting_it(tmp_path):
    fake = tmp_path / "passwd"
    fake.write_text(f"root:x:0:0:{SECRET}:/root:/bin/bash\ndaemon:x:1:1::/:/usr/sbin/nologin\n")
    for path in (fake, Path("/etc/passwd")):
        if not path.is_file():
            continue
        with pytest.raises(InputError) as caught:
            read_openquake_hazard(path)
        text = str(caught.value)
        assert "not an OpenQuake hazard curve or map" in text and "'poe-<PGA level>'" in text
        assert "root:" not in text and SECRET not in text and "/bin/" not in text


@pytest.mark.skipif(not Path("/proc/self/environ").exists(), reason="no /proc/self/environ here")
def test_proc_self_environ_through_the_cli_is_never_printed(tmp_path):
    book = one_record_workbook(tmp_path / "site")
    done = run(book, "--hazard", "2in50", "--oq-hazard", "/proc/self/environ", "--out", tmp_path / "out",
               cwd=tmp_path, env=cli_env(ASSESS_TEST_SECRET=SECRET))
    assert_refused(done, "/proc/self/environ", "not an OpenQuake hazard curve or map")
    assert SECRET not in done.stderr and "PYTHONPATH" not in done.stderr


def test_a_cell_or_column_of_text_is_not_quoted(tmp_path):
    path = tmp_path / "hazard_curve-mean-PGA_1.csv"
    path.write_text(f"#,,\"kind='mean', investigation_time=1.0, imt='PGA'\"\nlon,lat,poe-0.1,poe-0.2\n"
                    f"0.0,0.0,{SECRET}:x:0,0.01\n")
    with pytest.raises(InputError) as caught:
        read_openquake_hazard(path)
    assert SECRET not in str(caught.value) and "not shown" in str(caught.value)
    path.write_text(f"#,,\"kind='mean', investigation_time=1.0\"\nlon,lat,{SECRET}:x\n0.0,0.0,0.1\n")
    with pytest.raises(InputError) as caught:
        read_openquake_hazard(path)
    assert SECRET not in str(caught.value)


def test_batch_with_files_outside_does_not_quote_a_file_that_is_not_a_curve(tmp_path):
    secret = tmp_path / "elsewhere" / "passwd"
    secret.parent.mkdir()
    secret.write_text(f"root:x:0:0:{SECRET}:/root:/bin/bash\n")
    folder = tmp_path / "portfolio"
    one_record_workbook(folder)
    portfolio = write_workbook(folder / "portfolio.xlsx", {"buildings": [
        {"building": "lab", "workbook": "wb.xlsx", "oq_hazard": str(secret)}]})
    done = run("batch", portfolio, "--allow-files-outside", "--out", tmp_path / "out", cwd=tmp_path)
    assert_refused(done, "passwd", "not an OpenQuake hazard curve or map")
    assert SECRET not in done.stderr and "root:" not in done.stderr


# ------------------------------------------------------------------ a record pushed past 5 g by the curve

def test_a_record_pushed_over_5_g_by_the_curve_names_the_curve_not_a_scale_cell(tmp_path):
    """The curve gives about 6 g at 2 % in 50 years; the record peaks at 0.3 g: a factor of about 20."""
    book = one_record_workbook(tmp_path / "site")
    curve = tmp_path / "site" / "hazard_curve-mean-PGA_7.csv"
    curve.write_text("#,,,,,,\"kind='mean', investigation_time=50.0, imt='PGA'\"\n"
                     "lon,lat,poe-0.1000000,poe-1.0000000,poe-3.0000000,poe-6.0000000,poe-8.0000000\n"
                     "0.0,0.0,0.9,0.5,0.1,0.02,0.005\n")
    done = run(book, "--hazard", "2in50", "--oq-hazard", curve, "--out", tmp_path / "out", "--format", "xlsx",
               cwd=tmp_path)
    assert_refused(done, curve.name, "the curve gives PGA 6 g at this level", "motion 'M1'",
                   "wb.xlsx, sheet 'hazard', row 2", "more than 5 g")
    assert "check the scale" not in done.stderr
