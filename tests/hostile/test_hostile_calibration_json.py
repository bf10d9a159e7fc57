"""A hostile or re-saved calibration.json given to ``--calibration``.

Nothing read from the file reaches the terminal raw: control characters (ANSI
escape sequences) in the effect name or the values are escaped or replaced,
and a UTF-8 byte order mark (added by Windows editors) is not content.
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from assess.calibration.apply import read_calibration
from assess.errors import InputError, Problem

ROOT = Path(__file__).resolve().parents[2]
LAB = ROOT / "inventories" / "lab.xlsx"
ANSI = "\x1b[2J\x1b[31mPWNED\x1b[0m\x07"


def write(path: Path, content, *, bom=False) -> Path:
    text = json.dumps(content)
    path.write_bytes((b"\xef\xbb\xbf" if bom else b"") + text.encode("utf-8"))
    return path


def good() -> dict:
    return {"selected": {"effect": "friction_scale", "parameters": {"k": 0.7}}, "applies_to": "all"}


def test_a_byte_order_mark_is_read_as_the_same_file(tmp_path):
    plain = read_calibration(write(tmp_path / "plain.json", good()))
    marked = read_calibration(write(tmp_path / "marked.json", good(), bom=True))
    assert (marked.effect, marked.parameters, marked.applies_to) == ("friction_scale", {"k": 0.7}, None)
    assert (plain.effect, plain.parameters) == (marked.effect, marked.parameters)


@pytest.mark.parametrize("content", [
    {"selected": {"effect": "friction" + ANSI, "parameters": {}}},
    {"selected": {"effect": "friction_scale", "parameters": {"k": "0.7" + ANSI}}},
    {"selected": {"effect": "friction_scale", "parameters": {"k": 0.7}}, "applies_to": ["A" + ANSI]},
], ids=["effect", "value", "applies_to"])
def test_control_characters_from_the_file_never_reach_the_message(tmp_path, content):
    with pytest.raises(InputError) as caught:
        read_calibration(write(tmp_path / "calibration.json", content))
    text = str(caught.value)
    assert "\x1b" not in text and "\x07" not in text


def test_every_problem_escapes_control_characters():
    text = str(InputError([Problem(file="a\x1b[2Jb.csv", message="cell 'x\x1b[31my'", fix="z\x07")]))
    assert "\x1b" not in text and "\x07" not in text
    assert "a\\x1b[2Jb.csv" in text and "x\\x1b[31my" in text


def test_through_the_cli_the_terminal_gets_no_escape_sequence(tmp_path):
    calibration = write(tmp_path / "calibration.json", {"selected": {"effect": ANSI, "parameters": {}}})
    done = subprocess.run([sys.executable, "-m", "assess", str(LAB), "--hazard", "2in50", "--calibration",
                           str(calibration), "--out", str(tmp_path / "out")], capture_output=True, text=True,
                          timeout=300, cwd=tmp_path,
                          env={**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")])})
    assert done.returncode == 2, done.stderr
    assert "calibration.json" in done.stderr and "is not one of" in done.stderr
    assert "\x1b" not in done.stderr + done.stdout and "\x07" not in done.stderr + done.stdout
    assert "Traceback" not in done.stderr
