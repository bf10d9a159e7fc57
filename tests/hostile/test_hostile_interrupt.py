"""Ctrl-C while batch draws its reports: exit 130 in one line, no "Exception ignored in ..." on stderr.

Drawing (matplotlib, WeasyPrint) runs weakref callbacks and ``__del__``
methods; a SIGINT that arrives while Python runs one raises KeyboardInterrupt
where Python can only print it ("Exception ignored in: <function
WeakKeyDictionary.__init__.<locals>.remove ...>"). The run has recorded the
interrupt and stops at its next check, so the printout is noise. The test
makes the interrupt arrive inside a ``__del__`` during drawing, deterministically,
in a child process.
"""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from tests.portfolio.test_batch import ITEMS, _write_building
from workbooks import write_workbook

ROOT = Path(__file__).resolve().parents[2]

#: Runs the CLI with every report drawn right after an object whose __del__ receives Ctrl-C.
_INTERRUPTED_WHILE_DRAWING = """
import signal, sys
import assess.command.output as output
from assess import cli

class Dropped:
    def __del__(self):
        signal.raise_signal(signal.SIGINT)
        sum(range(1000))  # the handler runs here, inside __del__

real = output.render_outputs

def drawing(*args, **kwargs):
    Dropped()  # collected at once: Ctrl-C arrives while Python runs its __del__
    return real(*args, **kwargs)

output.render_outputs = drawing
sys.exit(cli.main(sys.argv[1:]))
"""


def test_ctrl_c_inside_a_del_while_batch_draws_exits_130_cleanly(tmp_path):
    folder = tmp_path / "portfolio"
    folder.mkdir()
    _write_building(folder, "alpha", ITEMS["alpha"])
    portfolio = write_workbook(folder / "portfolio.xlsx", {"buildings": [
        {"building": "alpha", "workbook": "alpha.xlsx", "level": "2in50"}]})
    done = subprocess.run([sys.executable, "-c", _INTERRUPTED_WHILE_DRAWING, "batch", str(portfolio), "--out",
                           str(tmp_path / "out"), "--format", "html"], capture_output=True, text=True, timeout=300,
                          env={**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")])})
    assert done.returncode == 130, done.stderr
    assert "Exception ignored" not in done.stderr and "KeyboardInterrupt" not in done.stderr, done.stderr
    assert "Traceback" not in done.stderr
    assert done.stderr.strip().splitlines()[-1] == "assess: interrupted; nothing was written."
    out = tmp_path / "out"
    assert not out.exists() or [p.name for p in out.iterdir()] == [".cache"]  # only the simulations' cache
