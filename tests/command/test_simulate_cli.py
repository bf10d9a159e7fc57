"""``assess simulate`` (docs/commands.md) as a user runs it, and the record reader it uses."""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from assess.errors import InputError
from assess.hazard.records import read_record
from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2 as G
from commands import run

SPEC_KEYS = {"alpha_rad", "p_rad_s", "mode", "sliding_max_cm", "sliding_residual_cm",
             "theta_max_over_alpha", "uplift", "overturned"}




def simulate(*args, cwd=None):
    """``assess simulate ARGS`` run from ``cwd`` (default: this folder), in this process (tests/commands.py)."""
    return run("simulate", *args, cwd=Path.cwd() if cwd is None else cwd)


def test_rectangular_pulse_gives_newmark_closed_form():
    """Newmark (1965): Umax = ½ g Tp² (ap − μ) ap/μ for a rectangular pulse (here 245.17 cm)."""
    done = simulate("--height-cm", 200, "--width-cm", 100, "--mu", 0.25, "--pulse", "rect",
                    "--ap-g", 0.5, "--tp-s", 1.0, "--json")
    assert done.returncode == 0, done.stderr
    out = json.loads(done.stdout)
    assert SPEC_KEYS <= set(out)
    newmark_cm = 0.5 * G * 1.0**2 * (0.5 - 0.25) * 0.5 / 0.25 * 100
    assert out["sliding_max_cm"] == pytest.approx(newmark_cm, rel=1e-9)
    assert out["sliding_residual_cm"] == pytest.approx(-newmark_cm, rel=1e-9)  # +a drives −u
    assert out["mode"] == "slide" and out["uplift"] is False and out["overturned"] is False
    assert out["alpha_rad"] == pytest.approx(np.arctan(0.5), rel=1e-12)
    assert out["p_rad_s"] == pytest.approx(np.sqrt(3 * G / (4 * np.hypot(0.5, 1.0))), rel=1e-12)
    assert out["solver"] == "sliding kernel"


def test_pulse_prints_regression_beside_simulation():
    done = simulate("--height-cm", 228.6, "--width-cm", 62.2, "--mu", 0.13, "--pulse", "B",
                    "--ap-g", 0.54, "--tp-s", 2.1)
    assert done.returncode == 0, done.stderr
    assert "mode: slide" in done.stdout and "regression (eq. 21): IM 3.154" in done.stdout


def test_rocking_item_under_a_pulse():
    done = simulate("--height-cm", 228.6, "--width-cm", 62.2, "--mu", 0.68, "--pulse", "B",
                    "--ap-g", 0.30, "--tp-s", 2.1, "--json")
    out = json.loads(done.stdout)
    assert out["mode"] == "rock" and out["uplift"] is True and out["sliding_max_cm"] == 0.0
    assert 0.0 < out["theta_max_over_alpha"] < 1.0


def test_record_and_history(tmp_path):
    record = tmp_path / "floor.csv"
    time_s = np.arange(0, 4.0, 0.01)
    accel = 0.4 * np.sin(2 * np.pi * time_s) * (time_s < 2.0)
    pd.DataFrame({"time_s": time_s, "accel_g": accel}).to_csv(record, index=False)
    history = tmp_path / "out" / "history.csv"
    done = simulate("--height-cm", 180, "--width-cm", 60, "--mu", 0.2, "--record", record,
                    "--scale", 2.0, "--history", history, "--json", "--tail-s", 1.0)
    assert done.returncode == 0, done.stderr
    out = json.loads(done.stdout)
    assert out["motion"]["pta_g"] == pytest.approx(0.8, rel=1e-3)
    table = pd.read_csv(history)
    assert list(table.columns) == ["time_s", "floor_accel_g", "sliding_cm", "theta_over_alpha"]
    assert len(table) == time_s.size + 100
    assert table["sliding_cm"].abs().max() == pytest.approx(out["sliding_max_cm"], rel=0.02)


@pytest.mark.parametrize("args, expected, place", [
    (["--pulse", "B", "--ap-g", 0.5], "needs --ap-g and --tp-s", "command line: --pulse B"),
    ([], "either as --record FILE or as --pulse", "command line: give the motion"),
    (["--pulse", "B", "--ap-g", 0.5, "--tp-s", 1, "--record", "x.csv"], "exactly one", "command line: give the motion"),
    (["--record", "missing.csv"], "missing.csv: the record file does not exist", "  - missing.csv: "),
    (["--pulse", "B", "--ap-g", 0.5, "--tp-s", 1, "--mu-static", 0.1], "--mu-static 0.1 is below --mu",
     "command line: --mu-static 0.1"),
    (["--pulse", "B", "--ap-g", 0.5, "--tp-s", 1, "--cg-height-cm", 300], "above the top",
     "command line: --cg-height-cm 300"),
    (["--pulse", "B", "--ap-g", 0.5, "--tp-s", 1, "--history", "."], "--history names a folder", "  - .: --history"),
])
def test_wrong_input_exits_2_without_traceback(args, expected, place, tmp_path):
    """Exit 2, the problem located where the user wrote it (the command line's option, or the file named)."""
    done = simulate("--height-cm", 200, "--width-cm", 80, "--mu", 0.3, *args, cwd=tmp_path)
    assert done.returncode == 2
    assert expected in done.stderr and "Traceback" not in done.stderr
    assert place in done.stderr and "Nothing was written." in done.stderr, done.stderr


def test_bad_option_value_exits_2():
    done = simulate("--height-cm", -5, "--width-cm", 80, "--mu", 0.3, "--pulse", "A", "--ap-g", 1, "--tp-s", 1)
    assert done.returncode == 2 and "must be a positive number" in done.stderr
    assert "argument --height-cm: '-5'" in done.stderr


def test_help_describes_every_option():
    done = simulate("--help")
    for option in ("--height-cm", "--width-cm", "--cg-height-cm", "--mu", "--mu-static", "--record",
                   "--scale", "--pulse", "--ap-g", "--tp-s", "--json", "--solver", "--restitution"):
        assert option in done.stdout


# ------------------------------------------------------------------ record reader
def test_reader_agrees_with_pyslammer_loader_on_its_18_records():
    pyslammer = pytest.importorskip("pyslammer")
    from pathlib import Path
    folder = Path(pyslammer.__file__).parent / "sample_ground_motions"
    theirs = pyslammer.sample_ground_motions()
    assert len(theirs) >= 18
    for name, motion in theirs.items():
        ours = read_record(folder / f"{name}.csv")
        np.testing.assert_allclose(ours.accel_g, np.asarray(motion.accel, dtype=float), rtol=0, atol=0)
        assert ours.dt_s == pytest.approx(float(motion.dt), rel=1e-9)


@pytest.mark.parametrize("text, expected", [
    ("time_s,accel_g\n0,0.1\n0.01,0.2\n0.03,0.1\n", "time step is not constant"),
    ("time_s,accel_g\n0,0.1\n0.01,abc\n", "line 3 is not a row of numbers"),
    ("time_s,accel\n0,0.1\n0.01,0.2\n", "does not name the acceleration with its unit"),
    ("accel_g\n0.1\n0.2\n", "neither a time_s column nor dt_s="),
    ("time_s,accel_g\n0,nan\n0.01,0.2\n", "NaN"),
    ("time_s,accel_g\n0,0.1\n", "1 sample"),
])
def test_reader_refuses_wrong_records(tmp_path, text, expected):
    path = tmp_path / "record.csv"
    path.write_text(text)
    with pytest.raises(InputError, match=expected) as error:
        read_record(path)
    assert str(path) in str(error.value)


def test_reader_units_and_single_column(tmp_path):
    path = tmp_path / "one.csv"
    path.write_text("\ufeff# a comment\r\naccel_m_s2,dt_s=0.02\r\n9.80665\r\n-4.903325\r\n")
    record = read_record(path)
    assert record.dt_s == 0.02
    np.testing.assert_allclose(record.accel_g, [1.0, -0.5], rtol=1e-12)


def test_reader_peer_at2(tmp_path):
    path = tmp_path / "motion.AT2"
    path.write_text("PEER NGA STRONG MOTION DATABASE RECORD\nTest 1989\nACCELERATION TIME SERIES IN UNITS OF G\n"
                    "NPTS=    5, DT=   .0050 SEC\n  .1000E-01  .2000E-01 -.3000E-01\n  .4000E-01  .0000E+00\n")
    record = read_record(path)
    assert record.dt_s == 0.005
    np.testing.assert_allclose(record.accel_g, [0.01, 0.02, -0.03, 0.04, 0.0])
