"""The ``assess`` command (assess/__main__.py, assess/startup.py): its exit code is cli.main's, and a first
run after install compiles the general solver on a second core while the core imports."""
from __future__ import annotations

import subprocess
import sys

import pytest

from assess import startup
from assess.mechanics import warmup
from tests.commands import child_env


@pytest.mark.parametrize("argv, code", [(["--version"], 0), (["no-such-workbook.xlsx", "--hazard", "2in50"], 2)])
def test_the_command_exits_with_mains_code_and_no_traceback(tmp_path, argv, code):
    done = subprocess.run([sys.executable, "-m", "assess", *argv], cwd=tmp_path, capture_output=True, text=True,
                          env=child_env(), timeout=300)
    assert done.returncode == code, done.stderr
    assert "Traceback" not in done.stderr


def test_nothing_is_compiled_here_for_a_cluster(monkeypatch):
    started = []
    monkeypatch.setattr(warmup, "start", lambda threads=None: started.append(threads))
    startup.warm_up("tcp://127.0.0.1:8786", 2)
    assert started == []
    startup.warm_up(None, 2)
    assert started == [2]
