"""``mu`` optional (docs/workbook.md, "Default range of mu"): an item without it is assessed over a
default range chosen by its base and floor finish, through the μ-range machinery; anchored items never
need it; what cannot be read is refused at its cell.

The steel-feet range is checked against the paper's Table 3 as transcribed in assess/data
(km2010_table3.csv: best fit to slow pull), the documented table against the code, and the run's
range and nominal μ against the documented numbers, never against the tool's own output.
"""
from __future__ import annotations

import re
from pathlib import Path

import pandas as pd
import pytest

from assess import cli
from assessed import run_assessment
from assess.errors import InputError
from assess.inventory import read_workbook
from assess.inventory.friction import WIDE_RANGE, default_range
from assess.report.sentences import default_mu_text

DOCS = Path(__file__).resolve().parents[2] / "docs"
TABLE3 = Path(__file__).resolve().parents[2] / "assess" / "data" / "km2010_table3.csv"


def _item(item_id, **extra):
    row = {"id": item_id, "name": f"item {item_id}", "floor": 0, "height_cm": 180, "width_cm": 70,
           "depth_cm": 80, "mass_kg": 200, "clearance_cm": 10}
    row.update(extra)
    return row


PULSE = [{"level": "DE", "motion": "pulse", "floor": "all", "pta_g": 0.5, "tp_s": 0.6, "vp_cm_s": 40, "pulse": "B"}]


def test_the_steel_feet_range_is_the_papers_best_fit_to_slow_pull():
    table = pd.read_csv(TABLE3, comment="#")
    chosen = default_range("steel feet", "sealed concrete")
    assert (chosen.mu_low, chosen.mu_high) == (table["mu_best_fit"].min(), table["mu_slow_pull"].max())
    assert "Table 3" in chosen.why and chosen.mu == pytest.approx((0.13 + 0.31) / 2)


@pytest.mark.parametrize("base, finish, casters, expected", [
    ("rubber feet", "epoxy", False, (0.45, 0.85)),
    ("Wood base", "", False, (0.3, 0.7)),
    ("steel feet", "carpet", False, WIDE_RANGE),  # no published value on carpet
    ("", "vinyl/VCT", True, WIDE_RANGE),          # casters
    ("", "", False, WIDE_RANGE),
])
def test_default_ranges(base, finish, casters, expected):
    chosen = default_range(base, finish, casters)
    assert (chosen.mu_low, chosen.mu_high) == pytest.approx(expected)
    assert chosen.mu_low < chosen.mu < chosen.mu_high and chosen.why.startswith("default")


def test_the_documented_table_is_the_codes():
    text = (DOCS / "workbook.md").read_text(encoding="utf-8")
    section = text[text.index("#### Default range of mu"):]
    section = section[:section.index("\n#", 5)]
    ranges = re.findall(r"^\| ([^|]+) \| ([^|]+) \| (\d\.\d+)–(\d\.\d+)", section, flags=re.M)
    assert len(ranges) == 4
    first_base = {"steel or levelling feet, metal base": "steel feet", "rubber feet or pads": "rubber feet",
                  "wood or plastic base": "wood base"}
    for base, _, low, high in ranges:
        chosen = default_range(first_base.get(base.strip(), ""), "")
        assert (chosen.mu_low, chosen.mu_high) == pytest.approx((float(low), float(high))), base


def test_anchored_items_need_no_mu_and_freestanding_ones_take_a_default(make_workbook):
    equipment = [_item(f"A-{k}", anchored="yes") for k in range(21)] + [
        _item("F-1", base="steel feet", floor_finish="VCT"), _item("F-2"), _item("F-3", mu=0.3),
        _item("F-4", mu_low=0.2, mu_high=0.3)]
    inventory = read_workbook(make_workbook({"equipment": equipment, "hazard": PULSE}, record=False))
    items = inventory.equipment.set_index("id")
    assert items.loc["A-0", "mu_source"] == "" and pd.isna(items.loc["A-0", "mu"])
    assert items.loc["F-1", ["mu_low", "mu", "mu_high"]].tolist() == pytest.approx([0.13, 0.22, 0.31])
    assert items.loc["F-2", ["mu_low", "mu", "mu_high"]].tolist() == pytest.approx([0.2, 0.4, 0.6])
    assert items.loc["F-3", "mu_source"] == "workbook" and pd.isna(items.loc["F-3", "mu_low"])
    assert items.loc["F-4", "mu"] == pytest.approx(0.25) and "middle" in items.loc["F-4", "mu_source"]
    assert items.loc["F-2", "mu_static"] == pytest.approx(0.4)  # mu_static = mu, scaled with it at each node


def test_a_default_range_runs_as_a_range_and_the_report_says_why(make_workbook):
    equipment = [_item("F-1", base="rubber feet", floor_finish="sealed concrete"), _item("F-2", mu=0.3),
                 _item("A-1", anchored="yes")]
    result = run_assessment(read_workbook(make_workbook({"equipment": equipment, "hazard": PULSE},
                                                        record=False)), "DE")
    summary = result.summary.set_index("id")
    assert summary.loc["F-1", ["mu_low", "mu", "mu_high"]].tolist() == pytest.approx([0.45, 0.65, 0.85])
    assert summary.loc["F-1", "risk_mu_low"] in ("low", "moderate", "high")  # the range machinery ran
    assert summary.loc["F-2", "mu_source"] == "workbook" and pd.isna(summary.loc["F-2", "mu_low"])
    note = default_mu_text(result.summary)
    assert note.startswith("No μ in the workbook for 1 item:") and "F-1: 0.45–0.85" in note
    assert "F-2" not in note and "A-1" not in note
    from assess.report import render_html
    assert "F-1: 0.45–0.85" in render_html(result)


@pytest.mark.parametrize("extra, cell, words", [
    ({"base": "granite blocks"}, "base", "not one the default friction table knows"),
    ({"floor_finish": "vinly"}, "floor_finish", "did you mean 'vinyl'"),
    ({"mu_static": 0.4}, "mu_static", "without mu"),
    ({"mu_low": 0.5, "mu_high": 0.3}, "mu_low", "above mu_high"),
])
def test_what_cannot_be_read_is_refused_at_its_cell(make_workbook, extra, cell, words):
    with pytest.raises(InputError) as error:
        read_workbook(make_workbook({"equipment": [_item("F-1", **extra)], "hazard": PULSE}, record=False))
    (problem,) = error.value.problems
    assert problem.sheet == "equipment" and problem.row == 2 and problem.column == cell, str(problem)
    assert words in problem.message and problem.fix


def test_a_workbook_of_anchored_items_without_mu_runs(make_workbook, tmp_path, capsys):
    equipment = [_item(f"A-{k}", anchored="yes") for k in range(3)] + [_item("F-1")]
    path = make_workbook({"equipment": equipment, "hazard": PULSE}, record=False)
    out = tmp_path / "out"
    assert cli.main([str(path), "--hazard", "DE", "--out", str(out), "--format", "html", "--quiet"]) == 0
    summary = pd.read_csv(out / "summary.csv")
    assert list(summary["mu_source"].fillna(""))[:3] == ["", "", ""]
    assert summary.loc[summary["id"] == "F-1", "mu_source"].item().startswith("default, no base")
