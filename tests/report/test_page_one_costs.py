"""Page 1 holds the costs and the benefit-cost ratio's sensitivity to the discount rate and the remaining
life (issue 30 §6: "shown on page 1"), in a US run over a USGS curve with more actions than page 1 can list.

Before this check the cost table listed every action, with or without a value, and pushed the sensitivity
table onto page 2 in the sample US run (advice-hospital.xlsx at MCE_R over the sample USGS curve: 14 rows,
7 of them dashes). The page's text is read from the PDF (pypdf), not from the HTML the report was made of.
"""
from __future__ import annotations

import io
from pathlib import Path

import numpy as np
import pytest

from assessed import run_assessment
from assess.hazard.usgs import read_hazard_curve_file
from assess.inventory import read_workbook
from assess.report import advice, costs
from assess.report.pdf import render_part, split_appendix
from assess.report.render import render_html
from workbooks import write_workbook

pypdf = pytest.importorskip("pypdf")

USGS_CURVE = Path(__file__).resolve().parents[2] / "inventories" / "lab-hazard-usgs" / "PGA" / "curves.csv"


def _record(duration_s=0.5, amplitude_g=0.5, total_s=3.0, dt_s=0.001) -> str:
    time_s = np.arange(0.0, total_s, dt_s)
    accel = np.where(time_s < duration_s - 1e-12, amplitude_g, 0.0)
    return "time_s,accel_g\n" + "\n".join(f"{t:.4f},{a:.6f}" for t, a in zip(time_s, accel)) + "\n"


@pytest.fixture(scope="module")
def us_curve_result(tmp_path_factory):
    """28 blocks that slide past their room under a rectangular pulse, 24 with a value and a cost, 4 without,
    over the sample USGS curve, in US units."""
    tmp_path = tmp_path_factory.mktemp("page1")
    items = []
    for k in range(28):
        row = {"id": f"IT-{k:02d}", "name": f"Cabinet number {k}, steel, loaded", "room": f"room {k}", "floor": 0,
               "height_cm": 100, "width_cm": 100, "depth_cm": 100, "mass_kg": 200, "mu": 0.15 + 0.003 * k,
               "clearance_cm": 2 + k % 8}
        if k < 24:
            row.update(value=10_000 + 1_000 * k, mitigation_cost=300 + 50 * k)
        items.append(row)
    path = write_workbook(tmp_path / "w.xlsx", {
        "equipment": items,
        "hazard": [{"level": "2in50", "motion": "rect", "floor": 0, "record": "records/rect.csv"}],
        "settings": [{"key": "units", "value": "us"}, {"key": "currency", "value": "USD"}],
    }, files={"records/rect.csv": _record()})
    result = run_assessment(read_workbook(path), "2in50", hazard_curve=read_hazard_curve_file(USGS_CURVE))
    return advice.with_words(result)


def _page_one(result) -> str:
    """The text of page 1 of the report's PDF: the body's first page (the body is laid out alone, as
    :func:`assess.report.pdf.render_pdf` lays it out before it adds the appendix's pages after it)."""
    body, _ = split_appendix(render_html(result))
    return " ".join(pypdf.PdfReader(io.BytesIO(render_part(body))).pages[0].extract_text().split())


def test_page_one_holds_the_costs_and_the_sensitivity_table(us_curve_result):
    context = costs.costs_context(us_curve_result)
    assert context["has_curve"] and context["sensitivity"] is not None
    assert len(context["rows"]) == costs.MAX_COST_ROWS < 24  # 24 with a value: 16 more in summary.csv
    assert "16 more actions ranked in summary.csv" in context["left_out"]
    assert "Not ranked, without a value: IT-24, IT-25, IT-26, IT-27" in context["left_out"]
    page = _page_one(us_curve_result)
    assert "Where money avoids most loss" in page
    assert "at other discount rates and remaining lives" in page
    sensitivity = context["sensitivity"]
    for row in sensitivity["rows"]:
        assert row["rate"] in page
    assert all(f"{life} years" in page for life in sensitivity["lives"])
    assert all(value in page for value in sensitivity["rows"][-1]["ratios"])  # its last row, not cut off


def test_the_sensitivity_stands_before_the_ranked_actions_so_page_one_keeps_it_however_many_there_are(
        us_curve_result, monkeypatch):
    """With every action listed (no cap) the sensitivity table is still on page 1: it stands beside the lead
    sentence, before the ranked actions, which may run on to page 2 (before this check it came after them and
    a long table pushed it off page 1)."""
    monkeypatch.setattr(costs, "MAX_COST_ROWS", 100)
    page = _page_one(us_curve_result)
    assert "Where money avoids most loss" in page and "Discount rate" in page
    assert page.index("Discount rate") < page.index("Benefit / cost", page.index("Where money avoids most loss") + 30)
