"""The command as a user runs it, in a scratch folder: in this process, or in a child process.

:func:`run` calls ``assess.cli.main(argv)`` here. The modules are imported and the
numba kernels compiled once for the whole session, so a run costs what the job costs,
not a Python start-up and a compilation. It returns what a child process would have
given: the exit code (argparse's ``SystemExit`` included), stdout and stderr (the
warnings a run shows included), and it leaves the working folder and numba's thread
count as they were.

:func:`run_in_child` runs ``python -m assess``: for what only a process shows
(signals, a closed pipe, the environment, everything written to the terminal).

Both return a :class:`subprocess.CompletedProcess`; a test reads ``returncode``,
``stdout`` and ``stderr`` alike from either. :func:`assert_refused` checks a refusal.
"""
from __future__ import annotations

import contextlib
import io
import os
import subprocess
import sys
import warnings
from pathlib import Path

import numba

from assess import cli

#: The checkout under test, first on the path of a child process (not an installed copy).
ROOT = Path(__file__).resolve().parents[1]
LAB = ROOT / "inventories" / "lab.xlsx"


def run(*args, cwd) -> subprocess.CompletedProcess:
    """``assess ARGS`` run from the folder ``cwd`` in this process."""
    argv = [str(arg) for arg in args]
    out, err = io.StringIO(), io.StringIO()
    threads, folder = numba.get_num_threads(), os.getcwd()

    def show(message, category, filename, lineno, file=None, line=None):
        err.write(warnings.formatwarning(message, category, filename, lineno, line))

    os.chdir(cwd)
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err), warnings.catch_warnings():
            warnings.resetwarnings()  # the filters a fresh interpreter starts with, not pytest's
            for category in (DeprecationWarning, PendingDeprecationWarning, ImportWarning, ResourceWarning):
                warnings.simplefilter("ignore", category)
            warnings.showwarning = show
            try:
                code = cli.main(argv)
            except SystemExit as stop:  # argparse: --help (0), a wrong option (2)
                code = stop.code if isinstance(stop.code, int) else (0 if stop.code is None else 1)
    finally:
        os.chdir(folder)
        numba.set_num_threads(threads)  # --jobs N sets them for the process
    return subprocess.CompletedProcess(["assess", *argv], code, out.getvalue(), err.getvalue())


def child_env(**extra) -> dict:
    """The environment of a child process: this checkout first on the path."""
    return {**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]), **extra}


def run_in_child(*args, cwd, env=None, timeout=600) -> subprocess.CompletedProcess:
    """``python -m assess ARGS`` in a child process started in ``cwd``."""
    return subprocess.run([sys.executable, "-m", "assess", *map(str, args)], cwd=cwd, capture_output=True,
                          text=True, timeout=timeout, env=child_env() if env is None else env)


def assert_refused(done, *fragments, places=(), max_chars=6000):
    """Exit 2, no traceback, a short message holding every fragment and every located place.

    A place is written as the message locates a problem (``assess.errors.Problem.location``):
    ``"wb.xlsx, sheet 'hazard', cell F2"``, ``"sheet 'equipment', row 3"``; a place given as a
    tuple ``(file, sheet, cell or row)`` is spelt that way here.
    """
    err = done.stderr
    assert done.returncode == 2, err[-3000:]
    assert "Traceback" not in err and "internal error" not in err, err[-3000:]
    assert len(err) < max_chars, f"{len(err)} characters of message"
    for place in places:
        text = place if isinstance(place, str) else location(*place)
        assert text in err, f"{text!r} not in {err!r}"
    for fragment in fragments:
        assert fragment in err, f"{fragment!r} not in {err!r}"


def location(file, sheet, where) -> str:
    """A problem's place as the message writes it: ``location("wb.xlsx", "hazard", "F2")`` is
    ``"wb.xlsx, sheet 'hazard', cell F2"``; ``where`` a whole number is a row."""
    spot = f"row {where}" if isinstance(where, int) else f"cell {where}"
    return f"{file}, sheet '{sheet}', {spot}"
