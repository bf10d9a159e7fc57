"""The all-items table of a building report: what every row shared is said once, and nothing is lost
(assess/report/items_table.py, templates/report.html.j2).

A building report's items take their demand from one suite per floor, the paper's regression applies to
none of them (no clear pulse), and code-prescribed actions carried the same two remarks: said in every row,
these filled the table three to five items a page. Each test rebuilds what a row means from the summary
itself (its source, its regression note, its action) and checks that the table and the words said once
over it give back the same, and that the rows fit more to a page than with those words in every row.
"""
from __future__ import annotations

import html as html_module
import re

import pandas as pd
import pytest

from assess.fragility.governing import regression_note
from assess.fragility.regression import RegressionConstants
from assess.report import render_html
from assess.report.pdf import data_only_url_fetcher, split_appendix
from tests.report.test_report import make_result

GROUND, THROUGH = "synthetic ground motions", "synthetic ground motions through the building"
CONSTANTS = RegressionConstants(zeta=0.37, eta=0.953, sigma=0.445, im_min=1.71, im_max=6.4)
#: The short words the table uses for each reason of a regression note, written out here, not read from
#: the module: the reason's words in the note -> the cell's word.
SHORT = {"no clear pulse": "no pulse", "outside": "IM", "uplifts": "uplift"}
CODE_ACTION = ("Anchor it (tall shelving: required whatever the analysis says): bolted at the top to the wall. "
               "Reference: ASCE 7-22 13.5. Its kind (tall shelving) was read from its name: confirm it, or write "
               "its component_type in the workbook.")


def _building_result(copies: int = 1):
    """The test report's items as a building report has them: the ground suite on floor 0, passed through
    the building above it, 120 motions; the regression applying to none (no clear pulse, some outside its
    IM range or uplifting); the high items' actions prescribed by a code, their kind read from the name.
    ``copies``: how many times each item is listed (with its own id), to fill pages."""
    result = make_result(simulated=True)
    summary = pd.concat([result.summary.assign(id=result.summary["id"] + f"-{n}") for n in range(copies)],
                        ignore_index=True)
    summary["demand_source"] = summary["demand_source"].astype(object)
    summary["regression_note"] = summary["regression_note"].astype(object)
    for index, row in summary.iterrows():
        anchored = row["risk"] == "anchored"
        summary.at[index, "demand_source"] = () if anchored else ((GROUND,) if row["floor"] == 0 else (THROUGH,))
        summary.at[index, "regression_note"] = "" if anchored else regression_note(
            0.05, 9.0 if index % 3 == 0 else 3.0, index % 2 == 0, CONSTANTS)
    free = summary["risk"] != "anchored"
    summary.loc[free, "suite_motions"] = 120.0
    summary.loc[free, "suite_histories"] = 120.0
    summary.loc[free, "regression_applies"] = False
    summary["type_source"] = "typed"
    high = summary["risk"] == "high"
    summary.loc[high, "action"] = CODE_ACTION
    summary.loc[high & (summary.index % 2 == 0), "type_source"] = "name"
    result.summary = summary
    return result


def _all_items(html: str) -> str:
    return re.search(r'<section id="all-items".*?</section>', html, re.S).group(0)


def _plain(fragment: str) -> str:
    return html_module.unescape(re.sub(r"<[^>]+>", "", fragment))


def _rows(section: str) -> dict[str, str]:
    """Each item's row of the table, by id."""
    return {re.search(r'<td class="c-id id">(?:<a[^>]*>)?([^<]+)', row).group(1): row
            for row in re.findall(r"<tr class=\"row-.*?</tr>", section, re.S)}


def _cell(row: str, column: str) -> str:
    return _plain(re.search(rf'<td class="[^"]*\b{column}\b[^"]*">(.*?)</td>', row, re.S).group(1))


def _floors(words: str) -> set[int]:
    """'floors 1 to 3 and 6' -> {1, 2, 3, 6}, written out here as the lead writes it."""
    floors = set()
    for part in re.split(r", | and ", re.sub(r"^floors? ", "", words)):
        low, _, high = part.partition(" to ")
        floors |= set(range(int(low), int(high or low) + 1))
    return floors


@pytest.fixture(scope="module")
def building_html() -> str:
    return render_html(_building_result())


def test_the_lead_gives_each_floor_the_source_its_items_have(building_html):
    """No "Demand from" column: the lead says each floor's source and suite, and every item's floor (its
    own cell) finds there the source and motions the summary gives it."""
    result = _building_result()
    section = _all_items(building_html)
    assert 'class="c-src"' not in section and "no-source" in section
    lead = _plain(re.search(r'<p class="lead">(.*?)</p>', section, re.S).group(1))
    said = re.search(r"Where it comes from, by floor: (.*?)\. The small", lead).group(1)
    by_floor = {}
    for source, motions, floors in re.findall(r"(.+?) \((\d+) motions\) on (floors? [^;]+)(?:; |$)", said):
        for floor in _floors(floors):
            assert floor not in by_floor, f"floor {floor} given two sources"
            by_floor[floor] = (source, int(motions))
    rows = _rows(section)
    for _, item in result.summary[result.summary["risk"] != "anchored"].iterrows():
        floor = int(_cell(rows[item["id"]], "c-floor"))
        assert by_floor[floor] == (item["demand_source"][0], int(item["suite_motions"])), item["id"]


def test_a_floor_with_two_sources_keeps_the_column():
    """Two sources on one floor (the regression for one item, the engine for another): each row says its own."""
    result = _building_result()
    summary = result.summary
    summary.at[summary.index[summary["id"] == "F-01-0"][0], "demand_source"] = ("regression",)
    section = _all_items(render_html(result))
    assert '<th class="c-src">Demand from</th>' in section and "no-source" not in section
    assert "“Demand from” says which model gives it" in _plain(section)
    rows = _rows(section)
    for _, item in summary[summary["risk"] != "anchored"].iterrows():
        assert _cell(rows[item["id"]], "c-src").startswith(item["demand_source"][0]), item["id"]
        assert "120 motions" in _cell(rows[item["id"]], "c-src")


def test_one_source_with_different_motions_keeps_only_the_motions_in_the_column():
    """Every item from the same source, two items of one floor from different suites: the lead names the
    source once and each row says its own motions."""
    result = _building_result()
    summary = result.summary
    summary.loc[summary["risk"] != "anchored", "demand_source"] = pd.Series(
        [(THROUGH,)] * int((summary["risk"] != "anchored").sum()), index=summary.index[summary["risk"] != "anchored"])
    summary.loc[summary["id"] == "F-01-0", ["suite_motions", "suite_histories"]] = [7.0, 70.0]
    section = _all_items(render_html(result))
    assert f"Where it comes from, for every item: {THROUGH};" in _plain(section)
    rows = _rows(section)
    assert _cell(rows["F-01-0"], "c-src") == "7 motions, 70 simulated histories"
    assert _cell(rows["M-05-0"], "c-src") == "120 motions" and _cell(rows["R-04-0"], "c-src") == "–"


def test_every_reason_the_regression_does_not_apply_is_in_the_row_or_said_once_for_all(building_html):
    result = _building_result()
    section = _all_items(building_html)
    note = _plain(re.search(r'<p class="note">(.*?)</p>', section, re.S).group(1))
    assert "for every freestanding item here its governing motion has no clear pulse" in note  # all four freestanding items: no pulse
    rows = _rows(section)
    for _, item in result.summary[result.summary["risk"] != "anchored"].iterrows():
        expected = {short for words, short in SHORT.items() if words in item["regression_note"]}
        cell = _cell(rows[item["id"]], "c-sl")
        assert cell.startswith("n/a")
        shown = {word for word in cell.removeprefix("n/a").split(", ") if word}
        assert shown | {"no pulse"} == expected and "no pulse" not in shown, item["id"]
        for word in shown:  # each short word the cells use is explained in the note
            assert f"{word}: " in note


def test_one_item_without_the_regression_keeps_its_reason_in_its_row():
    """Among items the regression applies to, the one it does not apply to says why in its own row."""
    section = _all_items(render_html(make_result()))
    assert '<span class="muted">n/a</span><br><span class="muted small">uplift</span>' in _rows(section)["K-02"]
    assert "every item" not in _plain(re.search(r'<p class="note">(.*?)</p>', section, re.S).group(1))


def test_a_code_prescribed_action_shows_its_head_and_tags_explained_once(building_html):
    result = _building_result()
    section = _all_items(building_html)
    note = _plain(re.search(r'<p class="note">(.*?)</p>', section, re.S).group(1))
    rows = _rows(section)
    for _, item in result.summary.iterrows():
        cell = re.search(r'<td class="c-act">(.*?)</td>', rows[item["id"]], re.S).group(1)
        if item["action"] != CODE_ACTION:
            assert _plain(cell) == item["action"]  # any other action whole
            continue
        head, _, tags = cell.partition("<br>")
        assert _plain(head) == "Anchor it (tall shelving)"
        assert _plain(tags).split(", ") == (["code", "kind from name"] if item["type_source"] == "name"
                                            else ["code"]), item["id"]
    assert "code: a code requires the action whatever the analysis says; its detail and reference are in the " \
           "work orders and Appendix A" in note
    assert "kind from name: its kind was read from its name" in note
    typed = _building_result()
    typed.summary["type_source"] = "typed"
    assert "kind from name" not in _all_items(render_html(typed))  # a tag no row carries is not explained


@pytest.mark.parametrize("html_of", [lambda: render_html(_building_result()), lambda: render_html(make_result()),
                                     lambda: render_html(make_result(simulated=True))])
def test_every_row_has_a_cell_under_each_heading(html_of):
    """The on-screen sort takes a heading's position as its cells' position: with or without the
    "Demand from" column, every row has as many cells as the table has headings, in their order."""
    section = _all_items(html_of())
    heading_classes = [c.split()[-1] for c in re.findall(r'<th class="([^"]+)"', section)]
    for row in _rows(section).values():
        cell_classes = [next(w for w in c.split() if w.startswith("c-"))
                        for c in re.findall(r'<td class="([^"]+)"', row)]
        assert cell_classes == heading_classes


# --------------------------------------------------------------------------- on paper
def _rows_per_page(html: str) -> list[int]:
    """How many of the all-items table's rows start on each of its pages, as WeasyPrint lays out the body."""
    weasyprint = pytest.importorskip("weasyprint")
    body, _ = split_appendix(html)
    document = weasyprint.HTML(string=body, url_fetcher=data_only_url_fetcher()).render()
    seen, counts = set(), []

    def walk(box, in_table, count):
        element = getattr(box, "element", None)
        tag = getattr(box, "element_tag", None)
        in_table = in_table or (tag == "table" and element is not None and element.get("id") == "all-items-table")
        if in_table and tag == "tr" and element is not None and element.get("class", "").startswith("row-"):
            if id(element) not in seen:
                seen.add(id(element))
                count[0] += 1
            return
        for child in getattr(box, "children", None) or ():
            walk(child, in_table, count)

    for page in document.pages:
        count = [0]
        walk(page._page_box, False, count)
        if count[0]:
            counts.append(count[0])
    return counts


def test_the_building_table_fits_twice_the_rows_it_did_with_its_shared_words_in_every_row(monkeypatch):
    """Twenty-four items of a building report: the table's first full page holds at least 10 rows. With the
    shared words back in every row (as the table had them: the source and its motions, "n/a" with every
    reason, the code action's standard remarks) the same page holds fewer than 6."""
    result = _building_result(copies=6)
    result.summary = result.summary[result.summary["risk"] != "anchored"].reset_index(drop=True)
    counts = _rows_per_page(render_html(result))
    assert sum(counts) == len(result.summary) and counts[1] >= 10, counts

    def every_row(summary, numbering="ground_0"):
        return {"sentence": "“Demand from” says which model gives it.", "column": "full"}

    def every_reason(summary, im_range):
        return {"reasons": ["no clear pulse, IM outside its range, uplifts"] * len(summary), "note": ""}

    def whole(action, type_source="", head=""):
        start, _, _ = action.partition(": required")
        return {"head": (start + ": required whatever the analysis says): the detail and its reference are in "
                         "the work orders and Appendix A; its kind was read from its name: confirm it.")
                if action == CODE_ACTION else action, "tags": "", "short": False}

    from assess.report import render as render_module
    monkeypatch.setattr(render_module, "demand_from", every_row)
    monkeypatch.setattr(render_module, "regression_words", every_reason)
    monkeypatch.setattr(render_module, "table_action", whole)
    assert _rows_per_page(render_html(result))[1] < 6


def test_no_word_of_the_building_table_runs_past_its_cell(building_html):
    """The columns widened where "Demand from" is gone keep every word inside its cell."""
    from tests.report.test_report_layout import _cell_lines

    assert dict(_cell_lines(building_html))["past"] == []


def _table_ids(page: str) -> list[str]:
    """The ids of the all-items table's rows, in the order the report shows them."""
    table = page[page.index('id="all-items-table"'):]
    table = table[:table.index("</table>")]
    return re.findall(r'<td class="[^"]*c-id[^"]*"[^>]*>\s*(?:<[^>]+>)*\s*([^<\s]+)', table)


def test_the_table_is_in_the_order_its_lead_says():
    """With a ``priority`` (as every run's summary has) the rows follow it and the lead says so, fractions
    as the priority score weighs them; without one, the lead says risk and the rows follow risk."""
    from assess.decision.risk_classes import ROCKING_HARM_SEVERITY, SLIDING_SEVERITY

    result = make_result(simulated=True)
    summary = result.summary.copy()
    assert "priority" in summary
    summary["priority"] = list(range(len(summary), 0, -1))  # the reverse of the ids' order
    result.summary = summary
    page = render_html(result)
    lead = html_module.unescape(page[page.index('<section id="all-items"'):].split("</p>")[0])
    assert "In order of priority" in lead and "Sorted by risk" not in lead
    assert {0.5: "counted half", 0.25: "a quarter"}[SLIDING_SEVERITY] in lead
    assert {0.25: "(a quarter, where that counts)", 0.125: "an eighth"}[ROCKING_HARM_SEVERITY] in lead
    expected = summary.sort_values("priority")["id"].astype(str).tolist()
    assert _table_ids(page) == expected

    result.summary = summary.drop(columns=["priority"])
    page = render_html(result)
    lead = html_module.unescape(page[page.index('<section id="all-items"'):].split("</p>")[0])
    assert "Sorted by risk" in lead and "priority" not in lead
    assert "items that rock before those that only slide" in lead  # the sort's third key, said
    risks = {str(i): str(r) for i, r in zip(summary["id"], summary["risk"])}
    order = {"high": 0, "moderate": 1, "low": 2, "anchored": 3}
    shown = [order[risks[i]] for i in _table_ids(page)]
    assert shown == sorted(shown) and len(shown) == len(summary)


@pytest.mark.parametrize("kind, mode, needs", [
    ("anchor", "overturn", False), ("tether", "overturn", False), ("tether", "beyond_clearance", True),
    ("lower_contents", "overturn", False), ("restrain", "beyond_clearance", True), ("room", "beyond_clearance", True),
    ("lock_casters", "beyond_clearance", True), ("none", "", False)])
@pytest.mark.parametrize("units", ["si", "us"])
def test_an_analysis_action_in_the_table_is_the_start_of_its_sentence(kind, mode, needs, units):
    """The table shows the analysis's action by the start of the very sentence the work orders and Appendix A
    give (what to do), and where sliding decided it the room the item needs, rounded up as the sentence
    rounds it: 107.2 cm -> 108 cm, 42.2 in (107.2 cm) -> 43 in."""
    from assess.decision.actions import LoweredDemand
    from assess.inventory.model import Settings
    from assess.report.advice import action_head, action_sentence

    settings = Settings(units=units)
    row = {"demand_room_cm": 107.2, "clearance_cm": 25.0, "p_beyond_clearance": 0.98, "p_overturn": 0.4,
           "suite_motions": 7, "suite_histories": 70, "theta_max_over_alpha": 1.4, "cg_height_cm": 90.0}
    lowered = LoweredDemand(0.3, 0.5, True, 1.2, 0.35, 60.0)
    head = action_head(kind, row, settings, mode)
    sentence = action_sentence(kind, row, True, lowered, settings, mode)
    assert head and sentence.startswith(head), (head, sentence)
    needed = "108 cm" if units == "si" else "43 in"
    assert head.endswith(f"needs {needed}") == needs or (kind == "lock_casters" and f"keep {needed} clear" in head)
    assert (len(head) < len(sentence)) == (kind != "none")
