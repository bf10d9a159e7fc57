"""The risk report (docs/outputs.md: report.html and report.pdf).

The result is built here from the dataclass, not by the pipeline, so the
report is tested on its own: one item rocks (high), one slides far beyond its
clearance (high), one is moderate, one low and one anchored; one name carries
markup that must come out escaped.
"""
from __future__ import annotations

import base64
import io
import math
import re
import urllib.request
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from scipy.stats import norm

from assess.assessment.result import MOTION_COLUMNS, SUMMARY_COLUMNS, AssessmentResult, RegressionRecord
from assess.decision.flags import Flag
from assess.hazard.levels import HazardLevel
from assess.inventory.settings import Settings
from assess.report import figures, render_html, render_pdf
from assess.report.render import (
    RefusedURLError,
    data_only_url_fetcher,
    format_cm,
    format_percent,
    format_significant,
    template_text,
)

G = 9.80665
ZETA, ETA, SIGMA = 0.370, 0.953, 0.445
NASTY_NAME = '<script>alert(1)</script> & "quotes"'
NOT_SIMULATED = ("Overturning was not assessed by time-history simulation in this version: "
                 "rocking items are flagged, and sliding comes from the paper's regression.")
NOT_SIMULATED_HTML = NOT_SIMULATED.replace("'", "&#39;")  # either spelling is acceptable


def _regression_numbers(pta_g, tp_s, mu, clearance_cm):
    """IM, median EDP, median/p84 sliding [cm], capacity and Pf from eqs. 7-20."""
    im = pta_g / mu - 1
    omega_p = 2 * math.pi / tp_s
    edp = ZETA * im ** ETA
    median_cm = 100 * edp * pta_g * G / omega_p ** 2
    capacity = clearance_cm / 100 * omega_p ** 2 / (pta_g * G)
    pf = 1 - norm.cdf(math.log(capacity / edp) / SIGMA)
    return im, edp, median_cm, median_cm * math.exp(SIGMA), capacity, pf


def _item(item_id, name, room, floor, mode, b_over_h, mu, motion, pta_g, tp_s, clearance_cm,
          risk, action, sliding=True):
    if sliding:
        im, edp, median, p84, capacity, pf = _regression_numbers(pta_g, tp_s, mu, clearance_cm)
    else:
        im, edp, median, p84, capacity, pf = pta_g / mu - 1, math.nan, math.nan, math.nan, \
            math.nan, math.nan
    alpha = math.atan(b_over_h)
    summary = {
        "id": item_id, "name": name, "room": room, "floor": floor, "quantity": 1,
        "alpha_rad": alpha, "p_rad_s": 1.2, "b_over_h": b_over_h, "governing_direction": 1,
        "mu": mu, "mode": mode, "governing_motion": motion, "pta_g": pta_g, "tp_s": tp_s,
        "im": im, "edp_median": edp, "sliding_median_cm": median, "sliding_p84_cm": p84,
        "clearance_cm": clearance_cm, "pf_sliding": pf, "overturn_fraction": math.nan,
        "theta_max_over_alpha": math.nan, "risk": risk, "action": action, "flags": "",
        "regression_applies": sliding, "regression_note": "" if sliding else "not applicable: the item uplifts",
    }
    motion_row = {
        "id": item_id, "motion": motion, "direction": 1, "pta_g": pta_g, "tp_s": tp_s,
        "im": im, "edp_median": edp, "sliding_median_cm": median, "pf_sliding": pf,
        "sim_sliding_max_cm": math.nan, "sim_theta_max_over_alpha": math.nan,
        "sim_overturned": math.nan, "floor": floor, "vp_cm_s": math.nan,
        "b_over_h": b_over_h, "alpha_rad": alpha, "mode": mode, "sliding_p84_cm": p84,
        "capacity_edp": capacity, "flags": "",
    }
    return summary, motion_row


def make_result(simulated: bool = False) -> AssessmentResult:
    rows = [
        _item("F-01", "FORMA incubator", "B-214", 2, "slide", 0.42, 0.13, "Los Gatos PC",
              0.57, 2.10, 20, "high", "Give room or restrain: needs 115 cm, has 20 cm"),
        _item("K-02", NASTY_NAME, "B-214", 2, "rock", 0.18, 0.35, "Corralitos", 0.84, 0.60,
              25, "high", "Anchor: it rocks under the design motion", sliding=False),
        _item("M-05", "Biosafety cabinet", "B-220", 2, "slide", 0.45, 0.20, "Gilroy Hist. Bldg.",
              0.59, 1.50, 30, "moderate", "Give room or restrain: needs 46 cm, has 30 cm"),
        _item("A-03", "ASP cabinet", "Lab 1", 0, "slide", 0.50, 0.30, "Gilroy Hist. Bldg.",
              0.59, 1.50, 60, "low", "No action needed"),
    ]
    summary = pd.DataFrame([s for s, _ in rows])
    motions = pd.DataFrame([m for _, m in rows], columns=MOTION_COLUMNS)
    anchored = {column: math.nan for column in SUMMARY_COLUMNS}
    anchored.update({"id": "R-04", "name": "Wire rack", "room": "Store", "floor": 1,
                     "quantity": 3, "mode": "", "governing_motion": "", "risk": "anchored",
                     "action": "Anchored: check the anchorage", "clearance_cm": 5.0,
                     "flags": "", "regression_applies": None})  # None, not NaN: pandas 2 would make the column float
    summary = pd.concat([summary, pd.DataFrame([anchored])], ignore_index=True)
    summary = summary[SUMMARY_COLUMNS]
    return AssessmentResult(
        workbook=Path("/somewhere/inventory.xlsx"),
        facility="Life Sciences Building",
        site="Berkeley, CA",
        level=HazardLevel(0.02, 50.0),
        level_label="2in50",
        summary=summary,
        motions=motions,
        flags=[
            Flag("K-02", "rocks", "Rocks from rest: μ = 0.35 > b/h = 0.18 and PTA = 0.84 g "
                 "> g·b/h; the sliding regression does not apply."),
            Flag("A-03", "im_extrapolated", "IM = 0.97 is below the fitted range 1.71–6.40: "
                 "the sliding estimate is extrapolated."),
            Flag("K-02", "not_simulated", "Overturning not simulated."),
        ],
        regression=RegressionRecord(ZETA, ETA, SIGMA, 1.71, 6.40, "Konstantinidis & Makris (2010), Table 3"),
        settings=Settings(risk_pf_high=0.5, risk_pf_moderate=0.1),
        simulated=simulated,
        seed=1,
    )


@pytest.fixture(scope="module")
def result() -> AssessmentResult:
    return make_result()


@pytest.fixture(scope="module")
def html(result) -> str:
    return render_html(result)


@pytest.fixture(scope="module")
def pdf(html) -> bytes:
    return render_pdf(html)


def _first_section(html: str) -> str:
    match = re.search(r'<section id="summary".*?</section>', html, re.S)
    assert match, "no first section"
    return match.group(0)


def _data_uris(html: str) -> list[str]:
    return re.findall(r'src="(data:image/svg\+xml;base64,[A-Za-z0-9+/=]+)"', html)


def _page_count(pdf: bytes) -> int:
    import pypdf

    return len(pypdf.PdfReader(io.BytesIO(pdf)).pages)


# --------------------------------------------------------------------------- HTML
def test_workbook_text_is_escaped(html):
    assert "&lt;script&gt;alert(1)&lt;/script&gt; &amp; &#34;quotes&#34;" in html
    assert html.count("<script") == 1  # our own inline sort-and-filter script, and nothing from the workbook
    assert "alert(1)</script>" not in html


def test_every_link_on_page_1_lands_on_its_item_details(html, result):
    first = _first_section(html)
    targets = set(re.findall(r'href="#(item-[^"]+)"', first))
    assert targets
    for target in targets:
        block = re.search(rf'<div class="item-detail" id="{re.escape(target)}">\s*<h3>(?:<span class="muted small">[^<]*</span> )?<span class="id">([^<]+)</span>',
                          html)
        assert block and f"item-{block.group(1)}" == target, target
    freestanding = result.summary[result.summary["risk"] != "anchored"]
    assert html.count('<div class="item-detail"') == len(freestanding)


def test_counts_are_shown(html, result):
    counts = result.risk_counts()
    assert counts == {"high": 2, "moderate": 1, "low": 1, "anchored": 1}
    for risk, count in counts.items():
        match = re.search(rf'class="count risk-{risk}">\s*<span class="number">(\d+)</span>', html)
        assert match, risk
        assert int(match.group(1)) == count


def test_first_section_lists_every_high_item_and_its_action(html, result):
    first = _first_section(html)
    high = result.summary[result.summary["risk"] == "high"]
    for _, row in high.iterrows():
        assert f'<a class="id" href="#item-{row["id"]}">{row["id"]}</a>' in first
        assert str(row["action"]) in first
    assert "Life Sciences Building" in first and "Berkeley, CA" in first
    assert "2% in 50 years (return period 2475 years)" in first
    assert "M-05" in first  # moderate, briefly
    assert "A-03" not in first  # low: only in the full table


def test_not_simulated_sentence(result):
    first = _first_section(render_html(result))
    assert NOT_SIMULATED in first or NOT_SIMULATED_HTML in first
    simulated = make_result(simulated=True)
    simulated.summary["overturn_fraction"] = [0.0, 0.5, 0.0, 0.0, math.nan]
    text = render_html(simulated)
    assert NOT_SIMULATED not in text and NOT_SIMULATED_HTML not in text
    assert "Over&shy;turns" in text  # the simulated column appears


def test_nan_shows_as_dash_and_numbers_are_rounded(html):
    all_items = re.search(r'<section id="all-items".*?</section>', html, re.S).group(0)
    rock_row = re.search(r'<tr class="row-high">\s*<td class="c-id id"><a class="id" href="#item-K-02">K-02</a></td>.*?</tr>',
                         all_items, re.S).group(0)
    # the regression does not apply to an item that uplifts: not shown, "n/a" and why (issue 19)
    assert '<td class="num c-sl"><span class="muted">n/a</span><br><span class="muted small">uplift</span></td>' in rock_row
    assert '<td class="num c-pfa">–</td>' in rock_row
    forma = re.search(r'<td class="c-id id"><a class="id" href="#item-F-01">F-01</a></td>.*?</tr>', all_items, re.S).group(0)
    assert '<td class="num c-sl">74 / 115<span class="unit">Pf ' in forma
    assert '<td class="num c-im">3.38</td>' in forma
    assert not re.search(r"\b(nan|NaN|None|<NA>)\b", html)


def test_formatting_helpers():
    assert format_significant(float("nan")) == "–"
    assert format_significant(0.4234) == "0.42"
    assert format_significant(3.3846, 3) == "3.38"
    assert format_significant(12345.0) == "12000"
    assert format_cm(73.6) == "74" and format_cm(None) == "–"
    assert format_percent(0.2849) == "28%" and format_percent(0.9999) == ">99%"
    assert format_percent(1e-5) == "<1%" and format_percent(0.0) == "0%"


def test_three_figures_embedded_and_nothing_external(html):
    uris = _data_uris(html)
    assert len(uris) == 3
    for uri in uris:
        svg = base64.b64decode(uri.split(",", 1)[1]).decode("utf-8")
        assert "<svg" in svg
        assert not re.search(r'href="(?!#)', svg), "an SVG refers to something outside itself"
    for forbidden in ("http://", "https://", "file:"):
        assert forbidden not in html
    assert not re.search(r'(src|href)="(?!data:|#)', html)
    assert "@import" not in html and "url(" not in html


def test_html_is_reproducible(result, html):
    assert render_html(result) == html
    assert render_html(make_result()) == html


def test_rendering_does_not_mutate_the_result(result, html):
    assert list(result.summary["id"]) == ["F-01", "K-02", "M-05", "A-03", "R-04"]


def test_templates_load_from_the_package_or_the_checkout():
    assert "{% for r in rows %}" in template_text("report.html.j2")
    assert "@page" in template_text("report.css")


# --------------------------------------------------------------------------- figures
def test_fragility_curve_agrees_with_scipy():
    im = np.array([0.5, 1.71, 2.0, 3.4, 5.0, 6.4])
    for capacity in (0.2, 0.4, 0.6, 0.8, 1.37):
        expected = 1 - norm.cdf(np.log(capacity / (ZETA * im ** ETA)) / SIGMA)
        got = figures.fragility_curve(im, capacity, ZETA, ETA, SIGMA)
        np.testing.assert_allclose(got, expected, rtol=1e-9, atol=1e-12)
    # hand-checked example of the docstring
    assert figures.fragility_curve(3.0, 0.4, ZETA, ETA, SIGMA) == pytest.approx(0.9853, abs=1e-4)


def test_fragility_curve_is_zero_without_sliding_and_keeps_the_input_kind():
    assert figures.fragility_curve(0.0, 0.4, ZETA, ETA, SIGMA) == 0.0
    assert isinstance(figures.fragility_curve(-0.5, 0.4, ZETA, ETA, SIGMA), float)
    np.testing.assert_array_equal(
        figures.fragility_curve(np.array([-1.0, 0.0]), 0.4, ZETA, ETA, SIGMA), [0.0, 0.0])
    series = pd.Series([0.0, 2.0, np.nan], index=["a", "b", "c"])
    out = figures.fragility_curve(series, 0.4, ZETA, ETA, SIGMA)
    assert isinstance(out, pd.Series) and list(out.index) == ["a", "b", "c"]
    assert out["a"] == 0.0 and math.isnan(out["c"])
    assert out["b"] == pytest.approx(1 - norm.cdf(math.log(0.4 / (ZETA * 2 ** ETA)) / SIGMA))


def test_fragility_figure_plots_the_papers_curves(result, monkeypatch):
    calls = []
    real = figures.fragility_curve

    def spy(im, capacity_edp, zeta, eta, sigma):
        values = real(im, capacity_edp, zeta, eta, sigma)
        calls.append((np.array(im, dtype=float), capacity_edp, zeta, eta, sigma, values))
        return values

    monkeypatch.setattr(figures, "fragility_curve", spy)
    figures.fragility_figure(result)
    assert sorted(call[1] for call in calls) == [0.2, 0.4, 0.6, 0.8]
    for im, capacity, zeta, eta, sigma, values in calls:
        assert (zeta, eta, sigma) == (ZETA, ETA, SIGMA)
        assert im.min() <= 0 and im.max() >= 7
        positive = im > 0
        expected = 1 - norm.cdf(np.log(capacity / (ZETA * im[positive] ** ETA)) / SIGMA)
        np.testing.assert_allclose(values[positive], expected, rtol=1e-9, atol=1e-12)
        assert np.all(values[~positive] == 0)


def test_figures_are_byte_identical(result):
    assert figures.fragility_figure(result) == figures.fragility_figure(result)
    assert figures.regression_figure(result) == figures.regression_figure(result)
    assert figures.sliding_demand_figures(result) == figures.sliding_demand_figures(result)


def test_long_inventories_split_the_demand_figure(result):
    many = make_result()
    many.summary = pd.concat([result.summary] * 20, ignore_index=True)
    many.summary["id"] = [f"X-{i:03d}" for i in range(len(many.summary))]
    svgs = figures.sliding_demand_figures(many, per_figure=30)
    freestanding = int((many.summary["risk"] != "anchored").sum())
    assert len(svgs) == math.ceil(freestanding / 30)


# --------------------------------------------------------------------------- PDF
def test_pdf_renders_several_pages(pdf):
    assert isinstance(pdf, bytes)
    assert pdf.startswith(b"%PDF")
    assert _page_count(pdf) > 1


@pytest.mark.parametrize("url", ["http://example.com/x.png", "file:///etc/passwd",
                                 "https://example.com/a.css", "/etc/passwd"])
def test_fetcher_refuses_everything_but_data_uris(url):
    fetcher = data_only_url_fetcher()
    with pytest.raises(RefusedURLError, match=re.escape(url)):
        fetcher(url)
    assert fetcher.refused == [url]


def test_fetcher_serves_data_uris():
    fetcher = data_only_url_fetcher()
    response = fetcher("data:image/svg+xml;base64," + base64.b64encode(b"<svg/>").decode())
    assert response.read() == b"<svg/>"
    assert response.content_type == "image/svg+xml"
    assert fetcher("data:text/plain,a%20b").read() == b"a b"


def test_pdf_fetches_nothing(monkeypatch):
    def no_network(*args, **kwargs):
        raise AssertionError("urllib was asked to open a URL")

    monkeypatch.setattr(urllib.request.OpenerDirector, "open", no_network)
    monkeypatch.setattr(urllib.request, "urlopen", no_network)
    html = ('<html><head><link rel="stylesheet" href="https://example.com/a.css"></head><body>'
            '<p>before</p><img src="http://example.com/x.png"><img src="file:///etc/passwd">'
            '<p>after</p></body></html>')
    fetcher = data_only_url_fetcher()
    pdf = render_pdf(html, url_fetcher=fetcher)
    assert pdf.startswith(b"%PDF")
    assert set(fetcher.refused) == {"http://example.com/x.png", "file:///etc/passwd",
                                    "https://example.com/a.css"}


def _history_of(item_id: str) -> dict:
    """A simulated time history of one item, as ``result.histories`` holds them (Fig. 7 of the paper)."""
    time_s = np.linspace(0.0, 12.0, 601)
    return {"id": item_id, "name": "FORMA incubator", "mode": "slide", "overturned": False, "time_s": time_s,
            "sliding_cm": 3 * np.sin(time_s), "theta_over_alpha": 0.1 * np.sin(2 * time_s),
            "floor_accel_g": 0.5 * np.sin(5 * time_s), "clearance_cm": 20.0, "sim_motion": "synthetic 1/10",
            "direction": 1, "motion": "Los Gatos PC", "solver": "sliding kernel"}


@pytest.mark.parametrize("simulated_sliding_cm, figure_4, history_figure", [(0.0, False, 4), (50.0, True, 5)])
def test_the_figure_of_simulation_against_regression_only_where_a_case_slides_in_both(
        simulated_sliding_cm, figure_4, history_figure):
    """Where no case slides both in the simulation and by the regression, a sentence stands where the empty
    figure of one against the other was, and the time histories' figures are numbered on from Figure 3."""
    import dataclasses

    result = make_result(simulated=True)
    result = dataclasses.replace(result, motions=result.motions.assign(sim_sliding_max_cm=simulated_sliding_cm),
                                 histories=[_history_of("F-01")])
    section = re.search(r'<section id="simulation">.*?</section>', render_html(result), re.S).group(0)
    assert ("<b>Figure 4.</b> Regression and simulation side by side" in section) is figure_4
    assert ("No case slides both in the simulation and by the paper&#39;s regression" in section) is not figure_4
    assert f"<b>Figure {history_figure}.</b> F-01 FORMA incubator" in section
