"""US units and floor numbering (docs/commands.md --units, docs/workbook.md settings units and floor_numbering).

A report in US units says inches, pounds and kips in its advice, tables and figures, is laid out on
letter paper, and summary.csv keeps its SI columns with inch and kip columns beside them. The
conversions are the exact ones (1 in = 2.54 cm by definition, 1 lbf = 4.4482216152605 N), written
here by hand, not taken from assess. Also the small refusals that come with the output folder and
--oq-site.
"""
from __future__ import annotations

import dataclasses
import io
import math
import re

import pandas as pd
import pypdf
import pytest

from assess import cli
from assess.command import job
from assess.inventory.settings import Settings
from assess.report import advice
from assess.errors import InputError
from assess.inventory import read_workbook
from assess.report import render_html
from assess.report.sentences import floor_text
from commands import assert_refused, run
from tests.report.test_report import make_result
from workbooks import job_sheets, rename_column, write_workbook

CM_PER_IN = 2.54  # by definition (1959)
LETTER_PT, A4_PT = (612, 792), (595, 842)  # 8.5 x 11 in and 210 x 297 mm, in points (1/72 in)


def _inch_sheets() -> dict:
    """The small job workbook with every length of its equipment sheet in inches (values converted by hand)."""
    sheets = job_sheets()
    for row in sheets["equipment"]:
        for column, factor in (("width_cm", 1 / CM_PER_IN), ("depth_mm", 0.1 / CM_PER_IN),
                               ("clearance_cm", 1 / CM_PER_IN), ("cg_height_cm", 1 / CM_PER_IN)):
            if row.get(column) is not None:
                row[column] = round(float(row[column]) * factor, 3)
    for old, new in (("width_cm", "width_in"), ("depth_mm", "depth_in"), ("clearance_cm", "clearance_in"),
                     ("cg_height_cm", "cg_height_in")):
        rename_column(sheets["equipment"], old, new)
    return sheets


def _media_boxes(pdf: bytes) -> set[tuple[int, int]]:
    """The page sizes [pt] of a PDF, rounded, as pypdf reads them."""
    return {(round(float(page.mediabox.width)), round(float(page.mediabox.height)))
            for page in pypdf.PdfReader(io.BytesIO(pdf)).pages}


@pytest.fixture(scope="module")
def unit_runs(tmp_path_factory):
    """The small job workbook in inches, run as it is (US from its headers), and with --units si."""
    scratch = tmp_path_factory.mktemp("units")
    workbook = write_workbook(scratch / "inches.xlsx", _inch_sheets())
    runs = {}
    for name, extra in (("us", ()), ("si", ("--units", "si"))):
        out = scratch / name
        done = run(workbook, "--hazard", "2in50", "--out", out, "--quiet", *extra, cwd=scratch)
        assert done.returncode == 0, done.stderr[-3000:]
        runs[name] = out
    return runs


def test_an_inch_workbook_gives_a_us_report_on_letter_paper(unit_runs):
    us, si = unit_runs["us"], unit_runs["si"]
    assert _media_boxes((us / "report.pdf").read_bytes()) <= {LETTER_PT, LETTER_PT[::-1]}
    assert _media_boxes((si / "report.pdf").read_bytes()) <= {A4_PT, A4_PT[::-1]}
    html = (us / "report.html").read_text()
    assert "[in]" in html and "[cm]" not in html
    text = re.sub(r"<[^>]+>", " ", html)
    assert not re.findall(r"\d\s*cm\b(?!/s)", text), "a length in cm in a US report"
    assert not re.findall(r"\d\s*kN", text), "a force in kN in a US report"
    assert "[cm]" in (si / "report.html").read_text()


def test_a_us_report_advises_in_inches_and_rounds_as_its_tables(unit_runs):
    summary = pd.read_csv(unit_runs["us"] / "summary.csv")
    advice = " ".join(summary["action"].fillna("").astype(str)) + " " + " ".join(summary["what_if"].fillna("").astype(str))
    assert " cm" not in advice and " kN" not in advice
    room = summary[summary["action"].str.contains("needs", na=False)]
    assert len(room), "no item with a room to give: the workbook no longer exercises the advice"
    for _, row in room.iterrows():
        needs_in = math.ceil(row["demand_room_cm"] / CM_PER_IN - 1e-9)
        has_in = math.floor(row["clearance_cm"] / CM_PER_IN + 1e-9)
        assert f"needs {needs_in} in" in row["action"] and f"has {has_in} in" in row["action"], row["action"]


def test_summary_csv_keeps_its_si_columns_and_adds_inches_and_kips_in_us_units(unit_runs):
    us = pd.read_csv(unit_runs["us"] / "summary.csv")
    si = pd.read_csv(unit_runs["si"] / "summary.csv")
    added = [c for c in us.columns if c not in si.columns]
    assert added and all(c.endswith(("_in", "_kip", "_kip_ft")) for c in added)
    assert [c for c in us.columns if c in si.columns] == list(si.columns)  # the SI table, in its order
    assert not [c for c in si.columns if c.endswith("_in")]  # inches only in US units (kip: the anchorage's own)
    pd.testing.assert_series_equal(us["clearance_in"], us["clearance_cm"] / CM_PER_IN, check_names=False,
                                   rtol=1e-5)
    assert list(us.columns).index("clearance_in") == list(us.columns).index("clearance_cm") + 1
    forces = us["anchor_force_kn"].notna()
    pd.testing.assert_series_equal(us.loc[forces, "anchor_force_kip"],
                                   us.loc[forces, "anchor_force_kn"] * 1000 / 4.4482216152605 / 1000,
                                   check_names=False, rtol=1e-5)


def test_the_room_an_item_has_reads_alike_in_its_advice_and_its_table():
    """Clearance 20 cm = 7.87 in: the advice says it has 7 in, and so does the table (not 8)."""
    row = {"p_overturn": 0.0, "risk": "moderate", "demand_room_cm": 54.2, "clearance_cm": 20.0,
           "p_beyond_clearance": 0.3, "theta_max_over_alpha": 0.0, "suite_motions": 3}
    us = advice.action_sentence("room", row, False, None, Settings(units="us"))
    si = advice.action_sentence("room", row, False, None, Settings(units="si"))
    assert "needs 22 in" in us and "has 7 in" in us  # 54.2 / 2.54 = 21.3 up; 20 / 2.54 = 7.87 down
    assert "needs 55 cm" in si and "has 20 cm" in si
    result = make_result()
    result = dataclasses.replace(result, settings=dataclasses.replace(result.settings, units="us"))
    html = render_html(result)
    # F-01 has 20 cm of clearance: its room in the item's detail
    detail = html[html.index('id="item-F-01"'):]
    assert re.search(r"<th>Room</th><td>7 in</td>", detail), detail[:2000]


# --------------------------------------------------------------------------- floor numbering

def test_floor_labels_under_us_floor_numbering():
    assert [floor_text(f, "ground_1") for f in (0, 1, 5, -1)] == ["1", "2", "6", "−1"]
    assert [floor_text(f) for f in (0, 1, -1)] == ["0", "1", "−1"]
    result = make_result()  # F-01 on floor 2, A-03 on floor 0, R-04 on floor 1
    us = render_html(dataclasses.replace(result, settings=dataclasses.replace(result.settings, floor_numbering="ground_1")))
    si = render_html(result)
    assert "ground floor = 1" in us and "ground floor = 1" not in si
    assert "the ground floor 1 (the workbook&#39;s floor 0)" in us

    def floors(html):
        table = html[html.index('id="all-items-table"'):]
        return dict(re.findall(r'<a class="id" href="#item-[^"]+">([^<]+)</a></td>.*?<td class="num c-floor">([^<]+)</td>',
                                table, re.S))

    assert floors(si)["F-01"] == "2" and floors(us)["F-01"] == "3"
    assert floors(si)["A-03"] == "0" and floors(us)["A-03"] == "1"


def test_floor_numbering_does_not_change_how_the_workbook_is_read(make_workbook):
    sheets = job_sheets()
    plain = read_workbook(make_workbook(sheets, name="plain.xlsx"))
    sheets["settings"].append({"key": "floor_numbering", "value": "ground_1"})
    us = read_workbook(make_workbook(sheets, name="us.xlsx"))
    assert us.settings.floor_numbering == "ground_1" and plain.settings.floor_numbering == "ground_0"
    assert us.equipment["floor"].tolist() == plain.equipment["floor"].tolist()


@pytest.mark.parametrize("key, value", [("units", "metric"), ("floor_numbering", "european")])
def test_a_wrong_units_or_floor_numbering_setting_is_refused_at_its_cell(make_workbook, key, value):
    sheets = job_sheets()
    sheets["settings"].append({"key": key, "value": value})
    with pytest.raises(InputError) as caught:
        read_workbook(make_workbook(sheets))
    message = str(caught.value)
    assert f"setting '{key}'" in message and value in message and "sheet 'settings'" in message


def test_units_follow_the_workbook_headers_unless_set(make_workbook):
    assert read_workbook(make_workbook(_inch_sheets(), name="in.xlsx")).settings.units == "us"
    assert read_workbook(make_workbook(job_sheets(), name="mixed.xlsx")).settings.units == "si"
    sheets = _inch_sheets()
    sheets["settings"].append({"key": "units", "value": "SI"})
    assert read_workbook(make_workbook(sheets, name="set.xlsx")).settings.units == "si"


# --------------------------------------------------------------------------- refusals

def test_an_output_folder_with_summary_xlsx_open_in_excel_says_close_it(tmp_path, make_workbook):
    workbook = make_workbook(job_sheets())
    out = tmp_path / "out"
    out.mkdir()
    (out / "summary.xlsx").write_bytes(b"")
    (out / "~$summary.xlsx").write_bytes(b"\0" * 165)  # Excel's lock file beside the workbook it has open
    done = run(workbook, "--hazard", "2in50", "--out", out, cwd=tmp_path)
    assert_refused(done, "close summary.xlsx in Excel", places=[f"{out}: summary.xlsx in the output folder is open"])
    assert "reading" not in done.stderr  # refused before anything ran
    assert sorted(p.name for p in out.iterdir()) == ["summary.xlsx", "~$summary.xlsx"]


@pytest.mark.parametrize("argv", [["--oq-site", "-0.2,-0.3"], ["--oq-site", "-0.2, -0.3"], ["--oq-site", "-0.2,", "-0.3"],
                                  ["--oq-site=-0.2, -0.3"], ["--oq-site", "-0.2 -0.3"]])
def test_oq_site_with_a_negative_longitude_or_a_space(argv):
    args = cli.build_parser().parse_args(cli.joined_oq_site(["w.xlsx", "--hazard", "2in50", *argv, "--quiet"]))
    assert job.oq_site(args.oq_site) == (-0.2, -0.3) and args.quiet


def test_oq_site_that_is_no_site_is_refused_with_the_form_to_use():
    with pytest.raises(InputError) as caught:
        job.oq_site("-0.2; -0.3")
    assert "lon,lat" in str(caught.value) and "--oq-site -122.5,38.1" in str(caught.value)
    assert job.oq_site("0") == 0 and job.oq_site("HOSP-1") == "HOSP-1"


def test_the_item_strips_draw_every_history_inside_the_strip_in_either_unit(unit_runs):
    """Each history's dot (or cross: it overturned) lies on the strip, between its left margin and its right
    end, in inches as in cm (a dot placed at its sliding times the pixel scale twice lies far off it)."""
    for name, out in unit_runs.items():
        html = (out / "report.html").read_text()
        strips = re.findall(r'<svg class="strip".*?</svg>', html, re.S)
        assert strips, "no item strip drawn"
        for strip in strips:
            width = float(re.search(r'width="(\d+)"', strip).group(1))
            marks = " ".join(re.findall(r'<path d="([^"]+)" fill="(?:#2c3e50|none)"', strip))  # dots, crosses
            xs = [float(x) for x in re.findall(r"M([\d.]+) [\d.]+", marks)]  # where each dot or cross begins
            assert xs and all(0 < x <= width for x in xs), (name, xs, width)


def test_work_orders_label_floors_as_the_report_does():
    """Under ground_1 the work orders' floor headings count the ground floor 1, as the tables do."""
    result = make_result()  # items on floors 0, 1 and 2
    result = dataclasses.replace(result, summary=result.summary.assign(action_kind="anchor"))

    def headings(html):
        section = html[html.index("Work orders by floor"):]
        return re.findall(r"<h3>Floor ([^<]+) <span", section)

    assert headings(render_html(result)) == ["0", "1", "2"]
    us = dataclasses.replace(result, settings=dataclasses.replace(result.settings, floor_numbering="ground_1"))
    assert headings(render_html(us)) == ["1", "2", "3"]
