"""Plausibility warnings (assess/inventory/plausibility.py): sizes and densities no equipment has are
warned at their cell, on stderr and in the result's flags and report, and the run goes on.

Expected values are worked by hand from the cells: 213 in = 5.41 m; a 300 kg rack in a 213 × 60 × 107 in
box (22.4 m³) is 13.4 kg/m³; 600 kg in 50 × 20 × 20 cm is 30 000 kg/m³ (30 g/cm³).
"""
from __future__ import annotations

from pathlib import Path

import pandas as pd
import pytest

import commands
from assess.inventory import read_workbook
from assess.inventory.plausibility import DENSITY_RANGE_KG_M3, MAX_HEIGHT_M, MAX_PLAN_M
from workbooks import job_sheets, write_workbook

ROOT = Path(__file__).resolve().parents[2]

# a 42U rack measured in centimetres (213 x 60 x 107 cm, 300 kg) typed under inch headers
RACK = {"id": "RACK-1", "name": "server rack", "room": "DC", "floor": 0, "height_in": 213, "width_in": 60,
        "depth_in": 107, "mass_kg": 300, "mu": 0.3, "clearance_cm": 10}
NORMAL = {"id": "FRZ-1", "name": "upright freezer", "room": "B1", "floor": 0, "height_in": 78,
          "width_in": 31, "depth_in": 34, "mass_kg": 350, "mu": 0.3, "clearance_cm": 10}


def _book(tmp_path, rows) -> Path:
    sheets = job_sheets()
    sheets["equipment"] = rows
    return write_workbook(tmp_path / "w.xlsx", sheets)


def test_a_rack_in_centimetres_under_inch_headers_is_warned_at_its_cells(tmp_path):
    inventory = read_workbook(_book(tmp_path, [NORMAL, RACK]))
    assert inventory.equipment["height_m"].tolist() == pytest.approx([78 * 0.0254, 213 * 0.0254])  # as written
    by_column = {w.problem.column: w for w in inventory.warnings}
    assert set(by_column) == {"height_in", "mass_kg"}  # the height, and the density (at the mass cell)
    height = by_column["height_in"]
    assert height.item_id == "RACK-1"
    assert (height.problem.sheet, height.problem.row, height.problem.cell) == ("equipment", 3, "E3")
    assert "5.41 m (17.7 ft)" in height.problem.message and "rename the header height_cm" in height.problem.fix
    assert 213 * 0.0254 > MAX_HEIGHT_M and 60 * 0.0254 < MAX_PLAN_M and 107 * 0.0254 < MAX_PLAN_M
    density = by_column["mass_kg"]
    assert density.problem.cell == "H3"
    assert "13.4 kg/m³" in density.problem.message  # 300 / (5.4102 x 1.524 x 2.7178)
    assert "w.xlsx, sheet 'equipment', cell E3, column 'height_in'" in str(height)


def test_thirty_grams_per_cubic_centimetre_is_warned(tmp_path):
    dense = {**NORMAL, "id": "BOX-1"}
    sheets_rows = [{k: v for k, v in dense.items() if not k.endswith("_in")} | {
        "height_cm": 50, "width_cm": 20, "depth_cm": 20, "mass_kg": 600}]
    inventory = read_workbook(_book(tmp_path, sheets_rows))
    assert [w.problem.column for w in inventory.warnings] == ["mass_kg"]
    message = inventory.warnings[0].problem.message
    assert "30000 kg/m³ (30 g/cm³)" in message and "above" in message
    assert 30000 > DENSITY_RANGE_KG_M3[1]


@pytest.mark.parametrize("name", ["lab.xlsx", "pharmacy.xlsx", "hospital.xlsx"])
def test_the_sample_workbooks_give_no_warning(name):
    path = ROOT / "inventories" / name
    if not path.is_file():
        pytest.skip(f"{name} is not in this checkout")
    assert read_workbook(path).warnings == ()


def test_the_run_goes_on_and_says_it_on_stderr_in_the_flags_and_in_the_report(tmp_path):
    path = _book(tmp_path, [NORMAL, RACK])
    done = commands.run(path, "--hazard", "2in50", "--out", tmp_path / "out", "--format", "html", "--quiet",
                        cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    # warnings are not progress: shown with --quiet too, located
    lines = [line for line in done.stderr.splitlines() if "warning" in line]
    assert len(lines) == 2 and all("item 'RACK-1'" in line for line in lines)
    assert any("sheet 'equipment', cell E3, column 'height_in'" in line for line in lines)
    summary = pd.read_csv(tmp_path / "out" / "summary.csv").set_index("id")
    assert "implausible_input" in summary.loc["RACK-1", "flags"]
    assert "implausible_input" not in str(summary.loc["FRZ-1", "flags"])
    html = (tmp_path / "out" / "report.html").read_text(encoding="utf-8")
    assert "Size or density no equipment has" in html and "cell E3" in html
