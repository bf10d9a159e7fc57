"""A report an engineer can sign: the title block, the same bytes for the same inputs, every figure's axes
labelled with units, and the item-by-item layout (numbering, motion names, the time axis).

The references are tested in tests/report/test_report_references.py.
"""
from __future__ import annotations

import dataclasses
import datetime
import re
import types

import matplotlib
import numpy as np
import pandas as pd
import pytest

from assess.inventory.workbook import read_workbook
from assess.report import figures, render_html, render_pdf
from assess.report.render import strip_label_lines
from tests.report.test_report import make_result
from tests.workbooks import job_sheets, write_workbook

try:  # the anchorage's own record of what it applied, where the tool has one
    from assess.anchorage.item import AnchorageSite
    ANCHORAGE_7_22 = AnchorageSite(edition="ASCE 7-22")
except ImportError:
    ANCHORAGE_7_22 = types.SimpleNamespace(edition="ASCE 7-22")

SIGNED = {"prepared_by": "A. Engineer, PE", "checked_by": "B. Checker, SE", "report_date": "2026-11-26",
          "revision": "B"}


def _signed(result, **settings):
    return dataclasses.replace(result, settings=dataclasses.replace(result.settings, **settings),
                               anchorage=ANCHORAGE_7_22)


def _title_block(html: str) -> str | None:
    match = re.search(r'<table class="title-block">.*?</table>', html, re.S)
    return match.group(0) if match else None


# --------------------------------------------------------------------------- title block
def test_the_title_block_shows_each_setting_given_under_its_label_and_the_code_edition():
    html = render_html(_signed(make_result(), **SIGNED))
    block = _title_block(html)
    assert block is not None
    headings = re.findall(r"<th>(.*?)</th>", block)
    values = re.findall(r"<td>(.*?)</td>", block)
    assert headings == ["Code edition", "Prepared by", "Checked by", "Date", "Revision"]
    assert values == ["ASCE 7-22", "A. Engineer, PE", "B. Checker, SE", "2026-11-26", "B"]
    # the running header of every page repeats the revision and the date; the PDF's author is the preparer
    assert re.search(r'<p class="report-id">[^<]*· rev\. B · 2026-11-26</p>', html)
    assert '<meta name="author" content="A. Engineer, PE">' in html


def test_only_what_is_given_is_shown_and_nothing_when_nothing_is():
    partial = render_html(_signed(make_result(), revision="3"))
    assert re.findall(r"<th>(.*?)</th>", _title_block(partial)) == ["Code edition", "Revision"]
    assert "Prepared by" not in partial and "Checked by" not in partial
    bare = render_html(make_result())  # no settings, no anchorage: no block, no date, no author
    assert _title_block(bare) is None
    for label in ("Prepared by", "Checked by", "Revision", "Code edition", 'name="author"', "rev."):
        assert label not in bare
    assert not re.search(r"\b20\d\d-\d\d-\d\d\b", bare), "a date the inputs do not give"


def test_workbook_text_in_the_title_block_is_escaped():
    html = render_html(_signed(make_result(), prepared_by="<script>x</script> & Co"))
    assert "&lt;script&gt;x&lt;/script&gt; &amp; Co" in _title_block(html)


@pytest.mark.parametrize("settings", [SIGNED, {}], ids=["signed", "unsigned"])
def test_the_same_inputs_give_the_same_bytes(settings):
    result = _signed(make_result(), **settings) if settings else make_result()
    first, second = render_html(result), render_html(dataclasses.replace(result))
    assert first == second
    assert render_pdf(first) == render_pdf(second)


def test_a_date_cell_is_read_as_its_date_and_a_number_as_text(tmp_path):
    sheets = job_sheets()
    sheets["settings"] += [{"key": "report_date", "value": datetime.datetime(2026, 11, 26)},
                           {"key": "revision", "value": 2}, {"key": "prepared_by", "value": "A. Engineer"}]
    inventory = read_workbook(write_workbook(tmp_path / "w.xlsx", sheets))
    assert inventory.settings.report_date == "2026-11-26"
    assert inventory.settings.revision == "2"
    assert inventory.settings.prepared_by == "A. Engineer" and inventory.settings.checked_by == ""


@pytest.mark.parametrize("day_zero", [datetime.datetime(1899, 12, 30), datetime.time(0, 0)])
def test_a_date_cell_holding_excels_day_zero_is_refused_at_its_cell(tmp_path, day_zero):
    """Hostile-input campaign: a report_date of 1899-12-30 (a date cell holding 0) printed "00:00:00"."""
    from assess.errors import InputError
    sheets = job_sheets()
    sheets["settings"] += [{"key": "report_date", "value": day_zero}]
    with pytest.raises(InputError) as error:
        read_workbook(write_workbook(tmp_path / "w.xlsx", sheets))
    assert any("no date" in p.message and p.sheet == "settings" for p in error.value.problems)


# --------------------------------------------------------------------------- axes
def _is_number(text: str) -> bool:
    try:
        float(text.replace("\N{MINUS SIGN}", "-"))
    except ValueError:
        return False
    return True


def _axis_problems(figure) -> list[str]:
    """Every axis that shows numbers has a label with its unit in brackets ([cm], [s], [g], [–] for a ratio);
    an axis of names (items) has a label; an axis that shows no tick labels (the upper panels of a shared
    time axis) is labelled by the panel that shows them."""
    figure.canvas.draw()
    problems = []
    for k, axes in enumerate(figure.axes):
        if not axes.get_visible() or not axes.axison:
            continue
        for name, axis in (("x", axes.xaxis), ("y", axes.yaxis)):
            shown = [t.get_text() for t in axis.get_ticklabels() if t.get_visible() and t.get_text()]
            if not shown:
                continue
            label = axis.get_label_text()
            numeric = all(_is_number(text) for text in shown)
            if not label:
                problems.append(f"axes {k} ({axes.get_title()!r}): {name} axis has no label")
            elif numeric and not re.search(r"\[[^\]]+\]", label):
                problems.append(f"axes {k}: {name} label {label!r} gives no unit in brackets")
    return problems


@pytest.fixture
def checked_figures(monkeypatch):
    """figures._to_svg, checking every Axes of the figure before it is saved; the problems found."""
    found, drawn = [], []
    to_svg = figures._to_svg

    def checking(figure):
        drawn.append(figure)
        found.extend(_axis_problems(figure))
        return to_svg(figure)

    monkeypatch.setattr(figures, "_to_svg", checking)
    return found, drawn


def _history():
    time_s = np.linspace(0.0, 12.0, 601)
    return {"id": "F-01", "name": "FORMA incubator", "mode": "slide", "overturned": False, "time_s": time_s,
            "sliding_cm": 3 * np.sin(time_s), "theta_over_alpha": 0.1 * np.sin(2 * time_s),
            "floor_accel_g": 0.5 * np.sin(5 * time_s), "clearance_cm": 20.0, "sim_motion": "synthetic 1/10",
            "direction": 1, "motion": "Los Gatos PC", "solver": "sliding kernel"}


def test_every_figure_of_the_report_labels_its_axes_with_units(checked_figures):
    found, drawn = checked_figures
    result = make_result(simulated=True)
    result = dataclasses.replace(result, motions=result.motions.assign(sim_sliding_max_cm=[50.0, 0.0, 10.0, 1.0]))
    figures.fragility_figure(result)
    figures.regression_figure(result)
    figures.sliding_demand_figures(result)
    figures.simulation_vs_regression_figure(result)
    figures.history_figure(_history())
    assert len(drawn) == 5
    assert found == []


def test_the_check_finds_an_axis_without_a_unit(checked_figures):
    """The axis check can fail: a figure whose y label has no unit is caught."""
    found, _ = checked_figures
    with matplotlib.rc_context(figures._RC):
        figure = figures._new_figure(2.0)
        axes = figure.add_subplot()
        axes.plot([0, 1], [0, 2])
        axes.set_xlabel("time [s]")
        axes.set_ylabel("sliding")
        figures._to_svg(figure)
    assert found == ["axes 0: y label 'sliding' gives no unit in brackets"]


# --------------------------------------------------------------------------- item by item
def _with_runs_and_history(result, motion_name):
    runs = pd.DataFrame({"id": ["F-01"] * 3, "motion_key": [0, 0, 1], "motion": [motion_name, motion_name, "Short"],
                         "sliding_cm": [5.0, 12.0, 30.0], "overturned": [False, False, True]})
    return dataclasses.replace(result, suite_runs=runs, histories=[_history()])


def test_a_long_motion_name_is_shown_whole_in_the_strip_and_the_history_has_a_time_axis():
    long_name = "Gilroy Historic Building, floor 2 (interpolated between floors 1 and 3) at 0.71 g"
    html = render_html(_with_runs_and_history(make_result(simulated=True), long_name))
    detail = html.split('<div class="item-detail" id="item-F-01">')[1].split('<div class="item-detail"')[0]
    strip = re.search(r'<svg class="strip".*?</svg>.*?</div>', detail, re.S).group(0)  # the SVG, then its words
    names = [name.split("<br>") for name in re.findall(r'<span class="figure-word" [^>]*>(.*?)</span>', strip)]
    assert long_name in [" ".join(lines) for lines in names]
    assert all(len(line) <= 52 for lines in names for line in lines)
    assert "[cm]</span>" in strip
    spark = re.search(r'<svg class="spark".*?</svg>.*?</div>', detail, re.S).group(0)
    for title in ("time [s]", "sliding [cm]", "θ/α [–]"):
        assert f">{title}</span>" in spark
    ticks = [float(t) for t in re.findall(r'text-align: center[^>]*font-size: 7.5px[^>]*>([0-9.]+)</span>', spark)]
    assert ticks[0] == 0 and ticks[-1] <= 12.0 < ticks[-1] + (ticks[1] - ticks[0])


def test_strip_label_lines_break_at_a_space_and_shorten_only_beyond_two_lines():
    assert strip_label_lines("a" * 10, 10) == ["a" * 10]
    assert strip_label_lines("abc defgh ijk", 9) == ["abc defgh", "ijk"]
    assert strip_label_lines("abcd efgh ijkl mnop", 9) == ["abcd efgh", "ijkl mnop"]
    assert strip_label_lines("abcd efgh ijkl mnop qrst", 9) == ["abcd efgh", "ijkl mno…"]


def test_item_blocks_are_numbered_one_by_one_though_an_anchored_item_has_a_priority_between():
    result = make_result()
    summary = result.summary.assign(priority=[1, 2, 4, 5, 3])  # R-04, anchored, is third in priority
    html = render_html(dataclasses.replace(result, summary=summary))
    numbers = re.findall(r'<div class="item-detail" id="[^"]+">\s*<h3><span class="muted small">#(\d+)</span>', html)
    assert numbers == ["1", "2", "3", "4"]
    assert 'id="item-R-04"' not in html.split('<section id="details">')[1].split("</section>")[0]


def test_the_anchorage_equations_are_in_the_method_where_their_block_exists(monkeypatch):
    """templates/_anchorage_method.html.j2 (the anchorage's own block) is included in the method when the
    package has it, and its absence is no error."""
    from assess.report import render

    result = make_result()
    without = render_html(result)
    assert "ANCHORAGE-BLOCK" not in without and '<section id="method">' in without
    text_of = render.template_text

    def with_block(name):
        if name == "_anchorage_method.html.j2":
            return "<h3>ANCHORAGE-BLOCK</h3>\n"
        return text_of(name)

    monkeypatch.setattr(render, "template_text", with_block)
    render.report_template.cache_clear()  # compiled once per process: again, with the block
    try:
        html = render_html(result)
    finally:
        render.report_template.cache_clear()  # not kept for the other tests
    method = html.split('<section id="method">')[1].split("</section>")[0]
    assert "<h3>ANCHORAGE-BLOCK</h3>" in method
