"""Record readers (docs/workbook.md): every format, robustness to how files are saved, and wrong records.

Every wrong record must raise :class:`InputError` whose problem names the file,
the line (``Problem.row``), says what is wrong and how to fix it.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from assess.errors import InputError
from assess.hazard.records import (MAX_PLAUSIBLE_PGA_G, MIN_DURATION_S, Record, pulse_record,
                                   read_record)
from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2 as G
from commands import run

ACCEL_G = np.array([0.0, 0.1, -0.25, 0.05, 0.0])


def write(tmp_path, text, name="record.csv", encoding="utf-8", newline="\n"):
    path = tmp_path / name
    path.write_bytes(text.replace("\n", newline).encode(encoding))
    return path


def refused(path, **options):
    """The single problem of the InputError that reading ``path`` raises."""
    with pytest.raises(InputError) as error:
        read_record(path, **options)
    problems = error.value.problems
    assert len(problems) == 1
    problem = problems[0]
    assert problem.file == str(path) and problem.fix, problem
    return problem


def two_columns(values, dt=0.01, unit="g"):
    rows = "".join(f"{k * dt:.4f},{float(v)!r}\n" for k, v in enumerate(values))
    return f"time_s,accel_{unit}\n{rows}"


# ------------------------------------------------------------------ formats

@pytest.mark.parametrize("unit, per_g", [("g", 1.0), ("m_s2", G), ("cm_s2", 100 * G), ("gal", 100 * G)])
def test_csv_time_and_acceleration_in_each_declared_unit(tmp_path, unit, per_g):
    record = read_record(write(tmp_path, two_columns(list(ACCEL_G * per_g), unit=unit)))
    np.testing.assert_allclose(record.accel_g, ACCEL_G, rtol=1e-12, atol=1e-15)
    assert record.dt_s == 0.01 and record.name == "record.csv"
    assert record.duration_s == pytest.approx(0.04) and record.pta_g == pytest.approx(0.25)
    np.testing.assert_allclose(record.time_s, [0.0, 0.01, 0.02, 0.03, 0.04])


def test_csv_header_is_case_insensitive_and_extra_columns_are_ignored(tmp_path):
    text = "Time_s, Accel_G ,velocity_m_s\n" + "".join(
        f"{k * 0.02},{v},{9.9}\n" for k, v in enumerate(ACCEL_G))
    record = read_record(write(tmp_path, text))
    np.testing.assert_array_equal(record.accel_g, ACCEL_G)
    assert record.dt_s == 0.02


def test_single_column_with_the_step_in_the_header(tmp_path):
    text = "accel_g, dt_s = 0.005\n" + "".join(f"{v}\n" for v in ACCEL_G)
    record = read_record(write(tmp_path, text))
    np.testing.assert_array_equal(record.accel_g, ACCEL_G)
    assert record.dt_s == 0.005


def test_time_column_and_matching_step_in_the_header(tmp_path):
    text = two_columns(ACCEL_G).replace("time_s,accel_g", "time_s,accel_g,dt_s=0.01")
    assert read_record(write(tmp_path, text)).dt_s == 0.01


AT2_HEAD = "PEER NGA STRONG MOTION DATABASE RECORD\nLOMA PRIETA 10/18/89 00:05, LOS GATOS, 000\n" \
           "ACCELERATION TIME SERIES IN UNITS OF G\n"


@pytest.mark.parametrize("line4", ["NPTS=    5, DT=   .0050 SEC", "NPTS=5,DT=0.005",
                                   "    5   .0050   NPTS, DT", "5 0.005 NPTS, DT, SEC"])
def test_peer_at2_new_and_old_header(tmp_path, line4):
    text = AT2_HEAD + line4 + "\n  .0000000E+00  .1000000E+00 -.2500000E+00\n  .5000000E-01  .0000000E+00\n"
    record = read_record(write(tmp_path, text, name="LGP000.AT2"))
    np.testing.assert_allclose(record.accel_g, ACCEL_G, rtol=1e-12)
    assert record.dt_s == 0.005 and record.name == "LGP000.AT2"


def test_peer_at2_with_numbers_run_together(tmp_path):
    """Fortran E-format leaves no space between a value and a following negative one."""
    text = AT2_HEAD + "NPTS= 5, DT= .0100 SEC\n .0000000E+00 .1000000E+00-.2500000E+00\n .5000000E-01 .0000000E+00\n"
    np.testing.assert_allclose(read_record(write(tmp_path, text, name="x.at2")).accel_g, ACCEL_G)


# ------------------------------------------------------------------ how files are saved

@pytest.mark.parametrize("encoding, newline, bom", [
    ("utf-8", "\n", ""), ("utf-8", "\r\n", "\ufeff"), ("utf-8", "\r", ""), ("utf-8", "\r\n", ""),
    ("utf-16", "\r\n", ""),  # Excel's "Unicode text": UTF-16 with its byte-order mark
])
def test_bom_line_ends_comments_and_blank_lines_do_not_change_the_record(tmp_path, encoding, newline, bom):
    text = (f"{bom}# Loma Prieta 1989, Los Gatos\n#\n\ntime_s,accel_g,\n0.00,0.0,\n0.01,0.1\n"
            "# a comment between samples\n0.02,-0.25\n\n0.03,0.05\n0.04,0.0\n\n")
    record = read_record(write(tmp_path, text, encoding=encoding, newline=newline))
    np.testing.assert_array_equal(record.accel_g, ACCEL_G)
    assert record.dt_s == 0.01


def test_pyslammer_comment_header_is_read_as_time_and_g(tmp_path):
    text = "\ufeff# Time Series: Northridge 1994 - VSP-360,\r\n# Time (s),Acceleration (g's)\r\n" + \
           "".join(f"{k * 0.005},{v}\r\n" for k, v in enumerate(ACCEL_G))
    record = read_record(write(tmp_path, text))
    np.testing.assert_array_equal(record.accel_g, ACCEL_G)
    assert record.dt_s == 0.005


def test_the_18_pyslammer_records_read_as_pyslammer_reads_them():
    """Same accelerations bit for bit and the same step, with the strict checks on (2 s, 5 g)."""
    pyslammer = pytest.importorskip("pyslammer")
    folder = Path(pyslammer.__file__).parent / "sample_ground_motions"
    theirs = pyslammer.sample_ground_motions()
    assert len(theirs) == 18
    for name, motion in theirs.items():
        ours = read_record(folder / f"{name}.csv", min_duration_s=MIN_DURATION_S)
        np.testing.assert_array_equal(ours.accel_g, np.asarray(motion.accel, dtype=float), err_msg=name)
        assert ours.dt_s == pytest.approx(float(motion.dt), rel=1e-9), name
        assert ours.name == f"{name}.csv"


def test_pulse_record_is_unchanged():
    record = pulse_record("B", 0.54, 2.1)
    assert isinstance(record, Record)
    assert record.dt_s == 0.005 and record.accel_g.size == 421 and record.pta_g == pytest.approx(0.54)


# ------------------------------------------------------------------ wrong records

@pytest.mark.parametrize("text, line, expected", [
    ("time_s,accel_g\n0,0.1\n0.01,0.2\n0.02,0.1\n0.04,0.1\n0.05,0.1\n", 5,
     "time step is not constant: 0.02 s between lines 4 and 5 (times 0.02 and 0.04 s), "
     "where the usual step is 0.01 s"),
    ("time_s,accel_g\n0,0.1\n0.01,abc\n", 3, "line 3 is not a row of numbers (it holds other text)."),
    ("time_s,accel_g\n0,0.1\nend of record\n", 3, "line 3 is not a row of numbers"),
    ("time_s,accel_g\n0,0.1\n0.01,nan\n0.02,0.1\n", 3,
     "NaN or infinite accelerations (1 value(s), the first on line 3)"),
    ("time_s,accel_g\n0,0.1\n0.02,0.2\n0.01,0.1\n", 4,
     "the time does not increase at line 4: 0.01 s after 0.02 s on line 3"),
    ("time_s,accel_g\n0,0.1\n0.01,0.2\n0.01,0.2\n", 4, "the time does not increase at line 4: 0.01 s after 0.01 s"),
    ("time_s,accel_g\n0,0.1\n0.01,0.2\ntime_s,accel_g\n0,0.1\n", 4, "line 4 repeats the header of line 1"),
    ("time_s,accel_g,accel_m_s2\n0,0.1,1\n", 1, "names the acceleration 2 times (accel_g, accel_m_s2)"),
    ("time_s,time_s,accel_g\n0,0,0.1\n", 1, "names the time 2 times"),
    ("time_s,accel\n0,0.1\n", 1, "does not name the acceleration with its unit ('accel')"),
    ("time_ms,accel_g\n0,0.1\n", 1, "names the time 'time_ms'; only seconds are read"),
    ("accel_g\n0.1\n0.2\n", 1, "neither a time_s column nor dt_s="),
    ("accel_g,dt_s=0\n0.1\n0.2\n", 1, "the header gives dt_s=0"),
    ("time_s,accel_g,dt_s=0.02\n0,0.1\n0.01,0.2\n", 2,
     "the header says dt_s=0.02 but the time column steps by 0.01 s"),
    ("0.00,0.1\n0.01,0.2\n", 1, "line 1 holds numbers where the header should be"),
    ("time_s;accel_g\n0;0.1\n", 1, "has no commas; columns must be separated by commas"),
    ("time_s\taccel_g\n0\t0.1\n", 1, "has no commas"),
    ("time_s,accel_g\n0,0.1,7\n", 2, "line 2 has 3 value(s) where the header (line 1) names 2 column(s)"),
    ("time_s,accel_g\n", 1, "the file has a header (line 1) but no samples"),
    ("time_s,accel_g\n0,0.1\n", None, "the record has 1 sample(s)"),
])
def test_wrong_csv_records_are_refused_naming_file_and_line(tmp_path, text, line, expected):
    path = write(tmp_path, text)
    problem = refused(path)
    assert expected in problem.message
    assert problem.row == line
    if line is not None:
        assert f"{path}, row {line}:" in str(problem)


@pytest.mark.parametrize("text", ["", "\n  \n\r\n", "\ufeff"])
def test_empty_file(tmp_path, text):
    assert refused(write(tmp_path, text)).message == "the file is empty."


def test_file_of_comments_only(tmp_path):
    assert "only comments" in refused(write(tmp_path, "# nothing here\n# yet\n")).message


def test_missing_file(tmp_path):
    problem = refused(tmp_path / "nowhere.csv")
    assert problem.message == "the record file does not exist."
    assert "start from its folder" in problem.fix and "--record from the current folder" in problem.fix


@pytest.mark.parametrize("unit, values, suggested", [
    ("g", [0.0, 6.0, -3.0], "accel_m_s2"),        # m/s² written under accel_g: 6 "g"
    ("g", [0.0, 350.0, -120.0], "accel_cm_s2"),   # gal written under accel_g
    ("m_s2", [0.0, 350.0, -120.0], "accel_cm_s2"),
])
def test_peak_over_5_g_is_called_a_unit_mistake_with_the_suffix_to_use(tmp_path, unit, values, suggested):
    problem = refused(write(tmp_path, two_columns(values, unit=unit)))
    assert "probably a unit mistake" in problem.message and f"more than {MAX_PLAUSIBLE_PGA_G:g} g" in problem.message
    assert problem.row == 3 and f"(line 3, value {values[1]:g} read as" in problem.message
    assert f"head the column {suggested}" in problem.fix


def test_peak_limit_can_be_raised_for_a_genuinely_strong_record(tmp_path):
    assert read_record(write(tmp_path, two_columns([0.0, 6.0, -3.0])), max_pga_g=10.0).pta_g == 6.0


def test_record_shorter_than_2_s_is_refused_when_asked(tmp_path):
    path = write(tmp_path, two_columns(np.full(150, 0.01)))  # 149 steps of 0.01 s = 1.49 s
    problem = refused(path, min_duration_s=MIN_DURATION_S)
    assert problem.message == "the record lasts 1.49 s (150 samples at 0.01 s), less than 2 s."
    assert problem.row == 151 and "in seconds" in problem.fix
    assert read_record(path).duration_s == pytest.approx(1.49)  # no duration check by default
    assert read_record(write(tmp_path, two_columns(np.full(201, 0.01)), "long.csv"),
                       min_duration_s=MIN_DURATION_S).duration_s == pytest.approx(2.0)


@pytest.mark.parametrize("line4, data, expected, line", [
    ("NPTS=    6, DT=   .0050 SEC", " .1 .2 .3\n .4 .5\n",
     "line 4 says NPTS=6 but 5 values follow (lines 5 to 6)", 4),
    ("NPTS=    4, DT=   .0050 SEC", " .1 .2 .3\n .4 .5\n", "line 4 says NPTS=4 but 5 values follow", 4),
    ("NPTS=    0, DT=   .0050 SEC", "", "the record has 0 sample(s)", None),
    ("Number of points 5, step .005", " .1 .2 .3\n .4 .5\n", "line 4 should give NPTS= and DT=", 4),
    ("NPTS=    5, DT=   0 SEC", " .1 .2 .3\n .4 .5\n", "line 4 gives the step DT=0", 4),
    ("NPTS=    5, DT=   .0050 SEC", " .1 .2 .3\n .4 x5\n", "line 6 is not a row of numbers (it holds other text)", 6),
])
def test_wrong_at2_files(tmp_path, line4, data, expected, line):
    problem = refused(write(tmp_path, AT2_HEAD + line4 + "\n" + data, name="bad.AT2"))
    assert expected in problem.message and problem.row == line


def test_at2_of_velocity_or_in_other_units_is_refused(tmp_path):
    velocity = AT2_HEAD.replace("ACCELERATION TIME SERIES IN UNITS OF G", "VELOCITY TIME SERIES IN UNITS OF CM/SEC")
    problem = refused(write(tmp_path, velocity + "NPTS= 2, DT= .01 SEC\n 1. 2.\n", name="LGP000.VT2.AT2"))
    assert "velocity history" in problem.message and ".AT2" in problem.fix and problem.row == 3
    gal = AT2_HEAD.replace("UNITS OF G", "UNITS OF CM/S/S")
    problem = refused(write(tmp_path, gal + "NPTS= 2, DT= .01 SEC\n 1. 2.\n", name="gal.AT2"))
    assert "gives the units as CM/S/S" in problem.message and "accel_cm_s2" in problem.fix


def test_at2_in_gal_by_mistake_gets_the_unit_advice(tmp_path):
    problem = refused(write(tmp_path, AT2_HEAD + "NPTS= 3, DT= .01 SEC\n 0. 350. -100.\n", name="gal.AT2"))
    assert "PEER .AT2 files are in g" in problem.fix and "time_s,accel_cm_s2" in problem.fix


def test_short_at2(tmp_path):
    problem = refused(write(tmp_path, "PEER\nx\n", name="short.AT2"))
    assert "four header lines" in problem.message


def test_a_unit_mistake_reaches_the_user_through_the_cli_without_traceback(tmp_path):
    path = write(tmp_path, two_columns(list(np.linspace(0.0, 30.0, 300)), unit="g"))
    done = run("simulate", "--height-cm", "200", "--width-cm", "80", "--mu", "0.3", "--record", path, cwd=tmp_path)
    assert done.returncode == 2 and "Traceback" not in done.stderr
    assert f"  - {path}" in done.stderr, done.stderr  # the record file is where the problem is
    assert "probably a unit mistake" in done.stderr and "accel_m_s2" in done.stderr
