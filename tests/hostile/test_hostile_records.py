"""Hostile and odd record files, as a user (or a workbook from someone else) hands them to the CLI.

Each case must end in exit 2 with a message that names the file and what is
wrong, or exit 0; never a traceback, never the contents of a file that is not
a record, and never unbounded time or memory. The CLI runs in a scratch folder, in this process
(tests/commands.py) unless the process is what is looked at (its environment, a hang).
"""
from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

from assess.errors import InputError
from assess.hazard.pulse_identification import identify_pulse
from assess.hazard.pulses import pulse_acceleration
from assess.hazard.records import (MAX_RECORD_BYTES, MAX_STEP_S, MIN_STEP_S, check_record_location,
                                   read_record, record_file_problem)
from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2 as G
from commands import child_env, location, run, run_in_child
from workbooks import good_sheets, write_workbook

#: Text that must never appear in a message: it stands for a secret in a file that is no record.
SECRET = "hunter2-SECRET-TOKEN"
#: A valid record: 10 s of a decaying 1 Hz sine at 0.01 s, 0.3 g.
_T = np.arange(0.0, 10.0, 0.01)
GOOD_RECORD = "time_s,accel_g\n" + "".join(f"{t:.2f},{a:.6f}\n" for t, a in
                                           zip(_T, 0.3 * np.sin(2 * np.pi * _T) * np.exp(-0.3 * _T)))
SIMULATE = ["simulate", "--height-cm", "200", "--width-cm", "80", "--mu", "0.3"]
#: The checkout under test.
ROOT = Path(__file__).resolve().parents[2]


def workbook_naming(folder: Path, record: str, scale=None, files=None) -> Path:
    """A workbook in ``folder`` whose one hazard row (level 2in50, all floors) names ``record``, no tp_s."""
    sheets = good_sheets()
    sheets["hazard"] = [{"level": "2in50", "motion": "M1", "floor": "all", "record": record, "scale": scale}]
    folder.mkdir(parents=True, exist_ok=True)
    return write_workbook(folder / "wb.xlsx", sheets, files=files)


def assert_refused(done, *expected, places=()):
    """Exit 2, no traceback, a short message holding every text and naming every place (file, sheet,
    cell or row, as ``assess.errors.Problem.location`` writes it)."""
    assert done.returncode == 2, done.stderr
    assert "Traceback" not in done.stderr and "internal error" not in done.stderr
    for text in (*places, *expected):
        assert text in done.stderr, done.stderr
    assert len(done.stderr) < 3000


# ------------------------------------------------------------------ records outside the workbook's folder

def test_a_record_outside_the_workbooks_folder_is_refused_and_never_read(tmp_path):
    secret = tmp_path / "secret.txt"
    secret.write_text(f"{SECRET}:x:0:0\n")
    book = workbook_naming(tmp_path / "site", "../secret.txt")
    done = run(book, "--hazard", "2in50", "--out", tmp_path / "out", cwd=tmp_path)
    assert_refused(done, "wb.xlsx, sheet 'hazard', row 2, column 'record'", "outside the workbook's folder",
                   "--allow-records-outside")
    assert SECRET not in done.stderr and not (tmp_path / "out").exists()
    # opted in, the file is read as a record: refused as one, still without quoting it
    done = run(book, "--hazard", "2in50", "--out", tmp_path / "out", "--allow-records-outside", cwd=tmp_path)
    assert_refused(done, "secret.txt", "does not name the acceleration with its unit",
                   places=["secret.txt, row 1: the record of motion 'M1' (wb.xlsx, sheet 'hazard', row 2)"])
    assert SECRET not in done.stderr


def test_proc_self_environ_is_refused_and_the_environment_never_printed(tmp_path):
    book = workbook_naming(tmp_path, "/proc/self/environ")
    env = child_env(ASSESS_TEST_SECRET=SECRET)  # in a child: /proc/self/environ is the one it started with
    done = run_in_child(book, "--hazard", "2in50", "--quiet", cwd=tmp_path, env=env)
    assert_refused(done, "outside the workbook's folder", places=["wb.xlsx, sheet 'hazard', row 2, column 'record'"])
    assert SECRET not in done.stderr
    done = run_in_child(book, "--hazard", "2in50", "--quiet", "--allow-records-outside", cwd=tmp_path, env=env)
    assert_refused(done, "binary data (a NUL byte on line 1)",
                   places=["/environ, row 1: the record of motion 'M1' (wb.xlsx, sheet 'hazard', row 2)"])
    assert SECRET not in done.stderr


def test_a_link_in_the_folder_that_points_outside_is_outside(tmp_path):
    (tmp_path / "elsewhere.csv").write_text(GOOD_RECORD)
    (tmp_path / "site").mkdir()
    (tmp_path / "site" / "records").mkdir()
    (tmp_path / "site" / "records" / "lg.csv").symlink_to(tmp_path / "elsewhere.csv")
    assert check_record_location(tmp_path / "site" / "records" / "lg.csv", tmp_path / "site") is not None
    (tmp_path / "site" / "records" / "own.csv").write_text(GOOD_RECORD)
    assert check_record_location(tmp_path / "site" / "records" / "own.csv", tmp_path / "site") is None
    assert check_record_location(tmp_path / "site" / "records" / ".." / ".." / "elsewhere.csv",
                                 tmp_path / "site") is not None
    assert check_record_location(tmp_path / "sitex" / "a.csv", tmp_path / "site") is not None  # not a prefix test


def test_help_and_readme_document_the_opt_in():
    done = run("--help", cwd=Path.cwd())
    assert "--allow-records-outside" in done.stdout
    readme = (Path(__file__).resolve().parents[2] / "README.md").read_text(encoding="utf-8")
    assert "--allow-records-outside" in readme


# ------------------------------------------------------------------ files that are not records

def test_symlink_loop(tmp_path):
    (tmp_path / "a.csv").symlink_to(tmp_path / "b.csv")
    (tmp_path / "b.csv").symlink_to(tmp_path / "a.csv")
    done = run(*SIMULATE, "--record", tmp_path / "a.csv", cwd=tmp_path)
    assert_refused(done, "a.csv: the path is a loop of symbolic links")
    book = workbook_naming(tmp_path, "a.csv")
    assert_refused(run(book, "--hazard", "2in50", cwd=tmp_path), "wb.xlsx", "'a.csv' cannot be followed",
                   "a link that leads back to itself", places=[location("wb.xlsx", "hazard", "D2")])


def test_a_200_mb_file_of_nul_bytes_gets_a_short_message(tmp_path):
    huge = tmp_path / "nul.csv"
    with open(huge, "wb") as stream:
        stream.truncate(200 * 2**20)  # sparse: costs no disk
    done = run(*SIMULATE, "--record", huge, cwd=tmp_path)
    assert_refused(done, "nul.csv", f"larger than {MAX_RECORD_BYTES // 2**20} MB", places=[f"{huge}: the file"])
    small = tmp_path / "small.csv"
    small.write_bytes(b"time_s,accel_g\n0,0.1\n" + b"\x00" * 1000)
    assert_refused(run(*SIMULATE, "--record", small, cwd=tmp_path), "binary data (a NUL byte on line 3)",
                   places=[f"{small}, row 3: "])


def test_a_fifo_does_not_hang_the_run(tmp_path):
    fifo = tmp_path / "fifo.csv"
    os.mkfifo(fifo)
    done = run_in_child(*SIMULATE, "--record", fifo, cwd=tmp_path, timeout=120)  # a hang fails, not waits
    assert_refused(done, "not a regular file", places=[f"{fifo}: this is"])
    assert_refused(run(*SIMULATE, "--record", tmp_path, cwd=tmp_path), "a folder, not a record file",
                   places=[f"{tmp_path}: this is"])


def test_record_text_is_never_quoted_in_messages(tmp_path):
    cases = {
        "h.csv": f"{SECRET},{SECRET}\n0,1\n",                       # header naming nothing
        "d.csv": f"time_s,accel_g\n0,0.1\n0.01,{SECRET}\n",          # a data line
        "n.csv": f"time_s,accel_g\n0,0.1\n{SECRET}\n",               # a line of text
        "t.csv": f"time_{SECRET}:x,accel_g\n0,0.1\n",                # a time column in another unit
        "x.AT2": f"PEER\nx\nACCELERATION IN UNITS OF G\n{SECRET}\n 0.1 0.2\n",
        "y.AT2": f"PEER\nx\nACCELERATION IN UNITS OF G\nNPTS= 2, DT= .01 SEC\n 0.1 {SECRET}\n",
        "v.AT2": f"PEER\nx\nVELOCITY {SECRET}\nNPTS= 2, DT= .01 SEC\n 0.1 0.2\n",
    }
    for name, text in cases.items():
        (tmp_path / name).write_text(text)
        with pytest.raises(InputError) as error:
            read_record(tmp_path / name)
        assert SECRET not in str(error.value), name
        assert error.value.problems[0].row is not None, name


# ------------------------------------------------------------------ records pulse identification cannot fit

@pytest.mark.parametrize("files, scale, expected", [
    ({"r.csv": "time_s,accel_g\n" + "".join(f"{k * 0.5},0.1\n" for k in range(5))}, None,
     ["r.csv, row 3", "the time step is 0.5 s", f"between {MIN_STEP_S:g} s and {MAX_STEP_S:g} s"]),
    ({"r.csv": "time_s,accel_g\n" + "".join(f"{k * 0.01:.2f},0\n" for k in range(1000))}, None,
     ["r.csv", "the acceleration is zero at every one of the 1000 samples"]),
    # an absurd scale is refused where it is written, before the record is read
    ({"r.csv": GOOD_RECORD}, 5e-324, ["cell E2, column 'scale'", "expected 0.0001 to 100"]),
    ({"r.csv": GOOD_RECORD}, 1e300, ["cell E2, column 'scale'", "expected 0.0001 to 100"]),
    ({"r.AT2": "PEER\nx\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS= 10, DT= 1E300 SEC\n"
               + " 0.1" * 10 + "\n"}, None, ["r.AT2, row 4", "the time step is 1e+300 s (DT on line 4)"]),
])
def test_records_without_tp_that_cannot_be_fitted_exit_2_located(tmp_path, files, scale, expected):
    book = workbook_naming(tmp_path, next(iter(files)), scale=scale, files=files)
    done = run(book, "--hazard", "2in50", "--out", tmp_path / "out", cwd=tmp_path)
    assert_refused(done, "wb.xlsx", "sheet 'hazard'", *expected)
    assert "row 2" in done.stderr or "cell E2" in done.stderr
    assert ("(wb.xlsx, sheet 'hazard', row 2)" in done.stderr  # the record's own place, and the row naming it
            or location("wb.xlsx", "hazard", "E2") in done.stderr), done.stderr
    assert not (tmp_path / "out").exists()


def test_pulse_identification_does_not_depend_on_the_scale_of_the_record():
    """A Type-B pulse (Tp 1.5 s, vp -0.84 m/s, the docstring's Gilroy case) scaled by 1e-300 keeps its Tp."""
    t = np.arange(0.0, 12.0, 0.01)
    vp, tp = -0.84, 1.5
    accel = pulse_acceleration("B", vp * 2 * np.pi / tp / G, tp, t - 2.0)
    for factor in (1.0, 1e-300, 2.0**-1070):
        fit = identify_pulse(accel * factor, 0.01, models=("B",))
        assert fit.tp_s == pytest.approx(tp, rel=0.01)
        assert fit.vp_m_s == pytest.approx(vp * factor, rel=0.02)
    with pytest.raises(ValueError, match="cannot hold a pulse"):
        identify_pulse(np.full(10, 0.1), 1e300)


# ------------------------------------------------------------------ synthetic motions

def test_zero_vp_with_synthetic_motions_is_refused_located(tmp_path):
    sheets = good_sheets()
    sheets["hazard"] = [{"level": "2in50", "motion": "M1", "floor": "all", "pta_g": 0.5, "tp_s": 1.0,
                         "vp_cm_s": 0}]
    book = write_workbook(tmp_path / "wb.xlsx", sheets)
    done = run(book, "--hazard", "2in50", "--out", tmp_path / "out", cwd=tmp_path)
    assert_refused(done, "wb.xlsx, sheet 'hazard', cell F2, column 'vp_cm_s'", "vp 0 cm/s",
                   "leave vp empty")


# ------------------------------------------------------------------ how much of the input a message may echo

def test_messages_are_bounded_whatever_the_input():
    """A 40,000-character cell and a sheet of 100,000 wrong rows give messages of a few kB."""
    from assess.errors import MAX_PROBLEMS_SHOWN, Problem
    long = Problem(file="x" * 40_000, message="m" * 40_000, fix="f" * 40_000, sheet="hazard", row=2)
    assert len(str(long)) < 2_000 and "more characters" in str(long)
    many = InputError([Problem(file="wb.xlsx", message=f"row {k} is wrong.", row=k) for k in range(100_000)])
    text = str(many)
    assert text.startswith("100000 problems in the input:")
    assert len(text.splitlines()) == 1 + MAX_PROBLEMS_SHOWN + 1 and "99950 more" in text


@pytest.mark.parametrize("dt_s, accepted", [(MIN_STEP_S, True), (MIN_STEP_S / 10, False), (MAX_STEP_S, True),
                                            (0.2, False), (5.0, False)])
def test_time_step_bounds(tmp_path, dt_s, accepted):
    count = int(round(2.5 / dt_s)) + 1  # 2.5 s of samples
    path = tmp_path / "r.csv"
    path.write_text(f"accel_g,dt_s={dt_s!r}\n" + "0.1\n-0.1\n" * (count // 2 + 1))
    if accepted:
        assert read_record(path).dt_s == dt_s
    else:
        with pytest.raises(InputError, match=f"the time step is {dt_s:g} s .dt_s in the header, line 1."):
            read_record(path)


# ------------------------------------------------------------------ user text in figures

@pytest.mark.parametrize("name", [r"Freezer $\foo$", r"a\$b$c$", "$5 and $6", "x_1^2 $"])
def test_figures_draw_user_text_as_text(name):
    """Matplotlib parses text between two $ as mathtext (``$\\foo$`` fails when drawn); escaped, it is drawn
    as written. The check uses matplotlib's own reading of a text (math or not, and what it shows)."""
    import io

    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    from assess.report.figures import plain_text
    figure = Figure()
    FigureCanvasAgg(figure)
    axes = figure.add_subplot()
    title = axes.set_title(plain_text(name))
    axes.set_yticks([0], [plain_text(name)])
    figure.savefig(io.BytesIO(), format="svg")
    assert title._preprocess_math(title.get_text()) == (name, False)
    if name == r"Freezer $\foo$":  # unescaped, the same name cannot be drawn
        axes.set_title(name)
        with pytest.raises(ValueError):
            figure.savefig(io.BytesIO(), format="svg")


def test_what_is_wrong_with_a_record_path_is_said_without_raising(tmp_path):
    (tmp_path / "a.csv").symlink_to(tmp_path / "b.csv")
    (tmp_path / "b.csv").symlink_to(tmp_path / "a.csv")
    os.mkfifo(tmp_path / "fifo.csv")
    (tmp_path / "good.csv").write_text(GOOD_RECORD)
    assert "loop of symbolic links" in record_file_problem(tmp_path / "a.csv")
    assert "too long" in record_file_problem(tmp_path / ("x" * 300 + ".csv"))
    assert record_file_problem(tmp_path / "none.csv") == "the record file does not exist."
    assert "not a regular file" in record_file_problem(tmp_path / "fifo.csv")
    assert "folder" in record_file_problem(tmp_path)
    assert record_file_problem(tmp_path / "good.csv") is None
    for path in (tmp_path / ("x" * 300 + ".csv"), "a\0b.csv"):
        with pytest.raises(InputError):
            read_record(path)
