"""``--alpha-range``: the level again at both ends of the building's lateral stiffness ratio α.

The ends' columns are checked against the same workbook run with α written in its building sheet (the
route a user without the option takes), not against the option's own output; the ground floor's item,
which α cannot move, gets none.
"""
from __future__ import annotations

import pytest

from assess.assessment.alpha_range import ALPHA_RANGE_COLUMNS, alpha_ends, items_through_building
from assess.assessment.pipeline import run_assessment
from assess.building import ALPHA_BY_SYSTEM, ALPHA_RANGE_BY_SYSTEM
from assess.building.modes import ALPHA_RANGE_SOURCE
from assess.inventory import read_workbook
from tests.assessment.test_floor_motions import SITE

#: An incubator on the ground floor, and low-friction ones on floors 1 to 3 with 1 to 12 cm of room: some slide
#: past it at one end of α and not at the other.
EQUIPMENT = [{"id": "G-1", "name": "incubator", "floor": 0, "height_cm": 180, "width_cm": 70, "depth_cm": 80,
              "mass_kg": 200, "mu": 0.3, "clearance_cm": 10}] + [
    {"id": f"S-{k}", "name": "incubator", "floor": floor, "height_cm": 120, "width_cm": 80, "depth_cm": 80,
     "mass_kg": 200, "mu": 0.15, "clearance_cm": room}
    for k, (floor, room) in enumerate([(3, 1), (3, 3), (3, 6), (3, 12), (2, 2), (2, 5), (1, 2)])]
UPPER = [f"S-{k}" for k in range(7)]
#: A 3-storey steel moment frame that yields at 0.08 W (so that α moves its floors' motions most), the site's
#: 3 motions (tests/assessment/test_floor_motions.py).
BUILDING = [["key", "value"], ["storeys", 3], ["storey_height_m", 4.0], ["period_s", 0.6],
            ["system", "steel moment frame"], ["response", "yielding"], ["yield_base_shear_g", 0.08]]
ENDS = (5.0, 20.0)


def _path(make_workbook, name, alpha=None):
    building = BUILDING + ([["lateral_stiffness_ratio", alpha]] if alpha is not None else [])
    return make_workbook({"equipment": [dict(item) for item in EQUIPMENT], "site": SITE, "building": building},
                         name=name, record=False)


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """The level with --alpha-range 5,20 (and what it said on the way), and the same workbook with α 5 and with α 20
    written in its sheet."""
    from workbooks import write_workbook

    folder = tmp_path_factory.mktemp("alpha")

    def make(sheets, name, record=False):
        return write_workbook(folder / name, sheets)

    said = []
    bracketed = run_assessment(read_workbook(_path(make, "bracket.xlsx")), "DE", seed=3, alpha_range=ENDS,
                               progress=said.append)
    given = {alpha: run_assessment(read_workbook(_path(make, f"alpha{alpha:g}.xlsx", alpha)), "DE", seed=3)
             for alpha in ENDS}
    return bracketed, given, said


def test_each_end_is_the_level_with_that_alpha_given(runs):
    """risk_alpha_low and the chances there are those of the workbook with α 5 given; _high those of α 20."""
    bracketed, given, _ = runs
    summary = bracketed.summary.set_index("id")
    for alpha, side in zip(ENDS, ("low", "high")):
        other = given[alpha].summary.set_index("id")
        for item in UPPER:
            assert summary.at[item, f"risk_alpha_{side}"] == other.at[item, "risk"], (item, side)
            for column in ("p_beyond_clearance", "p_overturn"):
                assert summary.at[item, f"{column}_alpha_{side}"] == pytest.approx(other.at[item, column], abs=0), (
                    item, column, side)


def test_alpha_moves_the_upper_floors_and_not_the_ground_floor(runs):
    """The two ends differ on the upper floors (else the check above could not fail), never on the ground."""
    _, given, _ = runs
    low, high = (given[alpha].summary.set_index("id") for alpha in ENDS)
    assert (low.loc[UPPER, "pta_g"] != high.loc[UPPER, "pta_g"]).all()
    assert (low.loc[UPPER, "p_beyond_clearance"] != high.loc[UPPER, "p_beyond_clearance"]).any()
    assert low.at["G-1", "pta_g"] == high.at["G-1", "pta_g"]


def test_the_level_s_answer_is_unchanged_and_governs(runs, make_workbook):
    """The bracketed run's own columns are those of the run without the option; the ground floor's item has
    no ends (α cannot move it) and only the upper floors' items were run again."""
    bracketed, _, _ = runs
    plain = run_assessment(read_workbook(_path(make_workbook, "plain.xlsx")), "DE", seed=3).summary
    summary = bracketed.summary
    columns = [c for c in plain.columns if c != "flags"]
    assert summary[columns].equals(plain[columns])
    # in the declared order, which summary.csv takes and summary.xlsx keeps as the result gives it
    assert [column for column in summary.columns if column in ALPHA_RANGE_COLUMNS] == ALPHA_RANGE_COLUMNS
    assert summary.set_index("id").loc["G-1", ALPHA_RANGE_COLUMNS].isna().all()
    assert items_through_building(bracketed) == UPPER


def test_an_item_whose_class_moves_is_flagged_and_the_note_counts_it(runs):
    bracketed, _, _ = runs
    summary = bracketed.summary.set_index("id")
    moved = [item for item in UPPER
             if len({summary.at[item, "risk"], summary.at[item, "risk_alpha_low"],
                     summary.at[item, "risk_alpha_high"]}) > 1]
    flagged = sorted(flag.item_id for flag in bracketed.flags if flag.code == "alpha_range")
    assert moved and flagged == sorted(moved)
    assert all(("alpha_range" in summary.at[item, "flags"]) == (item in moved) for item in UPPER)
    note = next(note for note in bracketed.hazard_notes if note.startswith("The building's lateral stiffness"))
    assert "α 5 and 20 (Miranda & Taghavi's (2005) range for moment frames)" in note
    assert (f"for the 7 freestanding items on floors 1 to 3. {len(moved)} items are in another risk class at one "
            "end or both than at the building's α") in note
    assert f"at α {ALPHA_BY_SYSTEM['steel moment frame']:g} (the system's typical one), governs" in note


def test_the_ends_say_their_alpha_is_an_end_not_the_building_s(runs):
    """Each end's building note (on the console, after "α 5: ") names its α as an end of the option, not as the
    sheet's: the workbook gives none."""
    *_, said = runs
    for alpha in ENDS:
        notes = [m for m in said if m.startswith(f"α {alpha:g}: ") and "lateral stiffness ratio" in m]
        assert notes, said
        assert all(f"α {alpha:g} (an end of --alpha-range, not the building's)" in m for m in notes), notes
    level = [m for m in said if not m.startswith("α ") and "lateral stiffness ratio" in m]
    assert level and all(f"α {ALPHA_BY_SYSTEM['steel moment frame']:g} (the system's typical one)" in m
                         for m in level), level


def test_every_system_has_a_range_around_its_typical_alpha():
    """Miranda & Taghavi's ranges hold each system's typical α, and the sheet's bounds hold the ranges."""
    from assess.inventory.site_building import LATERAL_STIFFNESS_RATIO_RANGE

    assert set(ALPHA_RANGE_BY_SYSTEM) == set(ALPHA_BY_SYSTEM) == set(ALPHA_RANGE_SOURCE)
    for system, (low, high) in ALPHA_RANGE_BY_SYSTEM.items():
        assert LATERAL_STIFFNESS_RATIO_RANGE[0] <= low < ALPHA_BY_SYSTEM[system] < high \
            <= LATERAL_STIFFNESS_RATIO_RANGE[1], system
    assert alpha_ends(type("Sheet", (), {"system": "braced frame"})(), (2.0, 3.0)) == (2.0, 3.0)


def test_the_report_says_the_cause_once_and_each_item_s_three_classes(runs):
    """The flags' section names the cause once and, beside each item whose class moves, its class at the low end,
    at the building's α and at the high end, read from the summary; the note is among the level's notes."""
    from assess.report import advice
    from assess.report.render import render_html

    bracketed, _, _ = runs
    html = render_html(advice.with_words(bracketed))
    section = html[html.index('<h2 id="flags">'):]
    assert section.count("(--alpha-range)") == 1
    summary = bracketed.summary.set_index("id")
    for flag in (f for f in bracketed.flags if f.code == "alpha_range"):
        row = summary.loc[flag.item_id]
        assert (f"{row['risk_alpha_low']} at α 5, {row['risk']} at α 12, {row['risk_alpha_high']} at α 20"
                in section), flag.item_id
    assert "The building&#39;s lateral stiffness ratio α: the level ran again at α 5 and 20" in html


def test_without_items_on_the_building_s_floors_nothing_runs_again_and_the_note_says_why(make_workbook):
    sheets = {"equipment": [dict(EQUIPMENT[0])], "site": SITE, "building": BUILDING}
    said = []
    result = run_assessment(read_workbook(make_workbook(sheets, name="ground.xlsx", record=False)), "DE", seed=3,
                            alpha_range=ENDS, progress=said.append)
    assert not any(message.startswith("again at the building's α") for message in said)
    assert result.summary[ALPHA_RANGE_COLUMNS].isna().all().all()
    assert result.hazard_notes[-1].startswith("--alpha-range: no freestanding item is on a floor whose motions come "
                                              "through the building")


def _pushover_building(**extra):
    """An 8-storey steel moment frame whose α comes from its pushover's slope (0.06) alone."""
    from assess.inventory.site_building import BuildingSheet
    return BuildingSheet(storeys=8, height_m=32.0, system="steel moment frame", period_s=1.2, yield_base_shear_g=0.25,
                         response="yielding", pushover_slope_ratio=0.06, **extra)


def test_with_alpha_from_the_pushover_s_slope_alone_the_ends_are_its_alpha_at_the_hardening_s_ends():
    """Without the model's storey hardening, the building's α is what the slope gives at its hardening, which lies
    in the 2 to 5 % of code-designed frames: the ends are the α of those two (the run's 3 % between them); with the
    model's hardening or α given, the system's range."""
    from dataclasses import replace

    from assess.assessment.alpha_range import alpha_ends_source
    from assess.assessment.floors import alpha_of, pushover_alpha
    sheet = _pushover_building()
    low, high = alpha_ends(sheet)
    assert low == pushover_alpha(replace(sheet, storey_hardening_ratio=0.02)).alpha
    assert high == pushover_alpha(replace(sheet, storey_hardening_ratio=0.05)).alpha
    assert low < alpha_of(sheet) < high
    assert "hardening at 2% and at 5% of their stiffness" in alpha_ends_source(sheet, (low, high))
    assert alpha_ends(_pushover_building(storey_hardening_ratio=0.02)) == ENDS
    assert alpha_ends(replace(sheet, pushover_slope_ratio=None, lateral_stiffness_ratio=13.0)) == ENDS
    assert alpha_ends(sheet, (6.0, 9.0)) == (6.0, 9.0)


def test_each_pushover_end_is_a_building_with_the_pushover_s_slope(make_workbook):
    """An end runs with its α and the storeys' hardening that gives it: its stick pushed over has the sheet's slope
    at 2 % roof drift, as the building the engineer's pushover describes would if its storeys hardened so."""
    from assess.assessment.alpha_range import at_alpha
    from assess.assessment.floors import building_model_of, building_note
    from assess.building.pushover import stick_pushover
    building = [["key", "value"], ["storeys", 8], ["height_m", 32.0], ["period_s", 1.2],
                ["system", "steel moment frame"], ["response", "yielding"], ["yield_base_shear_g", 0.25],
                ["pushover_slope_ratio", 0.06]]
    inventory = read_workbook(make_workbook({"equipment": [dict(item) for item in EQUIPMENT], "site": SITE,
                                             "building": building}, name="pushover.xlsx", record=False))
    for alpha, hardening in zip(alpha_ends(inventory.building), (0.02, 0.05)):
        end = at_alpha(inventory, UPPER, alpha).building
        assert (end.lateral_stiffness_ratio, end.storey_hardening_ratio, end.pushover_slope_ratio) == (
            alpha, hardening, None)
        assert f"with the storeys hardening at {hardening:.0%}, not the building's" in end.alpha_source
        note = building_note(building_model_of(end, None), end, [8], None)
        assert f"hardening at {100 * hardening:g}% of their stiffness after yield (this end of --alpha-range's)" in note
        stick = building_model_of(end, None).stick
        assert stick_pushover(stick, 1.2).slope_ratio == pytest.approx(0.06, rel=1e-5)
