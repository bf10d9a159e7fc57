"""The yielding building in the product (docs/workbook.md, sheet ``building``; docs/outputs.md, ``floors.csv``).

Checked against what the route does not compute itself: the elastic route's histories from the building
sheet's numbers (``building_modes`` + ``floor_records``, the modal route of today) byte for byte where the
building must stay elastic; the yielding stick's own response history (``yielding_response`` of
assess/building/nonlinear.py, verified against OpenSees in tests/verification/) built here from the sheet's
numbers and ASCE 7-22 §12.8 by hand; the drift ratios against the stick's drifts over the storey height; the
documented columns of docs/outputs.md against the file; the report's words against the rules of the issue
(the drift beyond the trusted limit is warned, the collapse is said not to be assessed).
"""
from __future__ import annotations

import numpy as np
import pytest

from assess.assessment.motions import level_motions, simulated_motions
from assess.assessment.pipeline import run_assessment
from assess.building import building_modes, floor_records
from assess.building.design import OVERSTRENGTH_BY_SYSTEM
from assess.building import yielding as yielding_module
from assess.building.nonlinear import yielding_response, yielding_stick
from assess.inventory import read_workbook
from assess.report.render import render_html
from tests.assessment.test_floor_motions import EQUIPMENT, SITE
from tests.project.test_docs import compare, section, table_names

#: 2 storeys of 4 m, T1 0.3 s, "other" (pinching springs, an equivalent shear stick): docs/workbook.md.
BUILDING = [["key", "value"], ["storeys", 2], ["storey_height_m", 4.0], ["period_s", 0.3]]


def _sheets(*rows):
    return {"equipment": [dict(item) for item in EQUIPMENT], "site": SITE,
            "building": BUILDING + [list(r) for r in rows]}


def _floor_histories(path):
    """Every floor motion's history (by motion name) and the level's ground histories, as the route makes them."""
    inventory = read_workbook(path)
    level = level_motions(inventory, "DE", lambda m: None, seed=3)
    simulated = simulated_motions(level, path.name, inventory.settings, 3, lambda m: None)
    table = level.table.set_index("motion_key")
    out = {table.at[k, "motion"]: [r.accel_g for r, _ in h] for k, h in simulated.histories.items()}
    ground = [level.records[key] for key in level.table.loc[level.table["floor"] == 0, "record_path"]]
    return out, ground, level, simulated


def _elastic_expected(ground):
    modes = building_modes(2, 4.0, system="other", period_s=0.3, damping=0.05)
    return floor_records(modes, ground, floors=[1, 2])


@pytest.mark.parametrize("rows", [[("response", "elastic")],
                                  [("response", "yielding"), ("yield_base_shear_g", 3.0)]])
def test_elastic_or_strong_enough_gives_todays_elastic_floor_motions_byte_for_byte(make_workbook, rows):
    """``response: elastic``, or a yield base shear above the demand (3 W: no storey yields), gives the floor
    histories of the elastic modes built here from the sheet's numbers, to the last bit."""
    yielding_module.forget()
    histories, ground, level, simulated = _floor_histories(make_workbook(_sheets(*rows), record=False))
    expected = _elastic_expected(ground)
    for m, motion in enumerate(ground):
        for floor in (1, 2):
            (got,) = histories[f"{motion.name} @ floor {floor}"]
            assert got.tobytes() == expected[floor][m].accel_g.tobytes()
    if rows[0][1] == "yielding":  # and floors.csv says no motion yielded a storey
        assert (simulated.floors["motions_yielded"] == 0).all()
        assert simulated.floors["ductility_max"].max() < 1.0


def test_a_yielding_building_gives_the_sticks_floor_motions(make_workbook):
    """With the code's design (no yield_base_shear_g): the storeys' strength by hand from ASCE 7-22 §12.8 —
    'other' takes R 3 (Table 12.2-1, H.), risk category IV I_e 1.5, S_DS 1.0, S_D1 0.6, T 0.3 s ≤ C_u T_a:
    C_s = min(1.0/(3/1.5), 0.6/(0.3 · 3/1.5)) = 0.5, times the overstrength 1.2 given here = 0.6 W; with
    k = 1 (T ≤ 0.5 s), C_v = (4, 8)/12, so storey 2 carries 2/3 of it (and the storey whose share asks more of
    its spring yields at its share, the other at the same drift ratio). Under a motion that yields a storey
    the floors' histories are the stick's response itself."""
    yielding_module.forget()
    path = make_workbook(_sheets(("response", "yielding"), ("overstrength", 1.2)), record=False)
    histories, ground, level, simulated = _floor_histories(path)
    ratios = np.array([0.6, 0.6 * 2.0 / 3.0])
    stick = yielding_stick(2, 4.0, ratios, system="other", period_s=0.3, damping=0.05)
    floors = simulated.floors.set_index("floor")
    assert floors.loc[1, "yield_base_shear_g"] == pytest.approx(0.6, rel=1e-12)
    # both springs at one yield drift ratio (a shear stick: each spring carries its storey's whole shear), the least
    # that leaves neither below its share: the storey whose share asks most of its spring yields at its share
    springs = stick.stiffness_n_m
    assert np.all(stick.linear_stiffness_n_m == 0.0)
    expected = springs * np.max(ratios / springs)
    assert floors.loc[[1, 2], "storey_yield_ratio"].to_numpy() == pytest.approx(expected, rel=1e-12)
    assert np.min(expected / ratios) == pytest.approx(1.0, rel=1e-12) and np.all(expected >= ratios)
    assert (floors["yielding_model"] == "storey springs").all()  # the stick of storey springs built above
    elastic = _elastic_expected(ground)
    yielded = 0
    drifts = []
    for m, motion in enumerate(ground):
        response = yielding_response(stick, motion.accel_g, motion.dt_s)
        drifts.append(np.abs(response.drift_m).max(axis=1) / 4.0)
        for floor in (1, 2):
            (got,) = histories[f"{motion.name} @ floor {floor}"]
            if response.ductility.max() >= 1.0:
                np.testing.assert_array_equal(got, response.floor_accel_g[floor])
            else:
                np.testing.assert_array_equal(got, elastic[floor][m].accel_g)
        yielded += response.ductility.max() >= 1.0
    assert yielded >= 1, "the design level must yield this building for the test to mean anything"
    assert floors.loc[1, "motions_yielded"] == yielded
    drifts = np.array(drifts)
    for storey in (1, 2):
        assert floors.loc[storey, "drift_ratio_median"] == pytest.approx(np.median(drifts[:, storey - 1]), rel=1e-12)
        assert floors.loc[storey, "drift_ratio_max"] == pytest.approx(drifts[:, storey - 1].max(), rel=1e-12)
    # the roof shakes less than the elastic building's where the building yields
    roof_pfa = [np.abs(histories[f"{g.name} @ floor 2"][0]).max() for g in ground]
    elastic_pfa = [np.abs(e.accel_g).max() for e in elastic[2]]
    assert np.median(roof_pfa) < np.median(elastic_pfa)


def test_the_same_ground_history_gives_the_same_floor_history_bit_for_bit():
    """What lets the case cache find a yielding floor's cases again (a curve update simulates nothing twice):
    the stick's history depends on the stick and the ground history only, memory or not."""
    modes = building_modes(4, 3.5, system="steel moment frame", period_s=0.6)
    building = yielding_module.yielding_building(modes, "steel moment frame", sds_g=1.0, sd1_g=0.6)
    t = np.arange(0.0, 12.0, 0.01)
    from assess.hazard.records import Record
    ground = [Record(0.6 * np.sin(2 * np.pi * t / 0.7) * np.exp(-((t - 4.0) / 2.0) ** 2), 0.01, "g")]
    yielding_module.forget()
    first = yielding_module.through_building(building, ground)[0]
    yielding_module.forget()
    again = yielding_module.through_building(building, ground)[0]
    remembered = yielding_module.through_building(building, ground)[0]
    for k in range(5):
        assert first[k][0].accel_g.tobytes() == again[k][0].accel_g.tobytes() == remembered[k][0].accel_g.tobytes()


def test_floors_csv_columns_are_documented(make_workbook):
    path = make_workbook(_sheets(("response", "yielding")), record=False)
    _, _, _, simulated = _floor_histories(path)
    documented = table_names(section("outputs.md", "With a `building` sheet: `floors.csv`"))
    compare(documented, list(simulated.floors.columns), "docs/outputs.md, floors.csv")


@pytest.fixture(scope="module")
def weak(tmp_path_factory):
    """A weak building (yield at 0.05 W) at DE: its storeys pass the 2 % drift 'other' is trusted to."""
    from workbooks import write_workbook
    path = write_workbook(tmp_path_factory.mktemp("weak") / "h.xlsx",
                          _sheets(("response", "yielding"), ("yield_base_shear_g", 0.05)))
    return run_assessment(read_workbook(path), "DE", seed=3)


def test_the_report_warns_beyond_the_trusted_drift_and_says_collapse_is_not_assessed(weak):
    floors = weak.floors.set_index("floor")
    assert floors.loc[1:, "drift_ratio_max"].max() > 0.02 and floors.loc[1, "drift_limit"] == 0.02
    beyond = floors.loc[1:, "motions_beyond_drift_limit"]
    assert beyond.max() >= 1
    # a storey counts motions beyond the limit exactly where its largest drift passed it
    assert ((beyond > 0) == (floors.loc[1:, "drift_ratio_max"] > 0.02)).all()
    html = render_html(weak)
    assert "The building: what its storeys did" in html
    assert "Beyond what the model can be trusted for" in html and "FEMA 356" in html
    first_page = html[:html.index("Act first")]  # and said on the first page, before the items
    assert "passed the storey drift it is trusted to" in first_page
    assert any(f"The building{quote}s own collapse is not assessed" in html for quote in ("&#39;", "'"))
    assert "a model of the building that yields" in html


def test_an_elastic_building_has_no_building_section(make_workbook):
    path = make_workbook(_sheets(("response", "elastic")), record=False)
    result = run_assessment(read_workbook(path), "DE", seed=3)
    assert "response" not in result.floors
    html = render_html(result)
    assert "The building: what its storeys did" not in html
    assert "through the building&#39;s elastic modes" in html or "through the building's elastic modes" in html


def test_p_delta_adds_the_gravity_loads_geometric_stiffness():
    """``p_delta: yes``: the stick's linear part gains -P_i/h_i per storey, P_i the weight above storey i
    (two floors of equal mass m, storeys of 4 m: -(2 m g + m g)/4 on floor 1, -m g/4 on the roof), and
    nothing else changes."""
    from assess.assessment.floors import building_model_of
    from assess.inventory.site_building import BuildingSheet, SiteSheet
    site = SiteSheet(sds_g=1.0, sd1_g=0.6)
    plain = building_model_of(BuildingSheet(storeys=2, height_m=8.0, period_s=0.3), site)
    with_p_delta = building_model_of(BuildingSheet(storeys=2, height_m=8.0, period_s=0.3, p_delta=True), site)
    weight = plain.stick.floor_masses_kg[0] * 9.80665
    expected = -np.array([[2 * weight / 4 + weight / 4, -weight / 4], [-weight / 4, weight / 4]])
    np.testing.assert_allclose(with_p_delta.stick.linear_stiffness_n_m - plain.stick.linear_stiffness_n_m, expected,
                               rtol=1e-12)
    np.testing.assert_array_equal(with_p_delta.stick.yield_force_n, plain.stick.yield_force_n)
    assert with_p_delta.p_delta and not plain.p_delta


def test_the_storey_table_gives_every_yield_shear_to_one_precision(weak):
    """The storeys' yield shears down the column, and the lead's base shear, are printed to the same three
    decimals (a general format dropped trailing zeros: 0.66 above 0.678)."""
    import re

    from assess.report.building import building_context

    section = building_context(weak)
    ratios = weak.floors.set_index("floor").loc[1:, "storey_yield_ratio"].to_numpy()
    assert [row["yield_ratio"] for row in section["rows"]] == [f"{r:.3f}" for r in ratios]
    assert all(re.fullmatch(r"\d\.\d{3}", row["yield_ratio"]) for row in section["rows"])
    assert "a base shear of 0.050 times its weight" in section["lead"]


def test_a_shear_wall_yields_at_its_base_hinge(make_workbook):
    """A shear wall (2 storeys of 4 m, T1 0.3 s, yield at 0.2 W given): its floors' histories are its elastic
    model's on a base hinge (``hinged_wall_response`` of assess/building/wall_hinge.py, verified against
    OpenSees in tests/verification/), storey 1 carries the wall's ductility at its base and the given
    strength, storey 2 neither (it does not yield); the report's table says so with dashes, its words with
    the base."""
    from assess.building.wall_hinge import hinged_wall_response
    from assess.report.building import building_context

    yielding_module.forget()
    path = make_workbook(_sheets(("system", "shear wall"), ("response", "yielding"), ("yield_base_shear_g", 0.2)),
                         record=False)
    histories, ground, level, simulated = _floor_histories(path)
    wall = yielding_stick(2, 4.0, np.array([0.2, 0.1]), system="shear wall", period_s=0.3, damping=0.05)
    floors = simulated.floors.set_index("floor")
    assert floors.loc[1, "storey_yield_ratio"] == pytest.approx(0.2, rel=1e-12)
    assert np.isnan(floors.loc[2, "storey_yield_ratio"]) and np.isnan(floors.loc[2, "ductility_median"])
    assert (floors["yielding_model"] == "base hinge").all()
    ductility = []
    for motion in ground:
        response = hinged_wall_response(wall, motion.accel_g, motion.dt_s)
        if response.ductility[0] >= 1.0:
            for floor in (1, 2):
                (got,) = histories[f"{motion.name} @ floor {floor}"]
                # the same model to rounding (the product's T_1 comes back from the modes' eigenvalues)
                np.testing.assert_allclose(got, response.floor_accel_g[floor], rtol=0, atol=1e-9)
        ductility.append(response.ductility[0])
    assert max(ductility) >= 1.0, "the design level must yield this wall for the test to mean anything"
    assert floors.loc[1, "ductility_median"] == pytest.approx(np.median(ductility), rel=1e-9)
    assert floors.loc[1, "motions_yielded"] == sum(d >= 1.0 for d in ductility)
    result = run_assessment(read_workbook(path), "DE", seed=3)
    section = building_context(result)
    assert [row["yield_ratio"] for row in section["rows"]] == ["0.200", "–"]
    assert section["rows"][1]["ductility"] == "–" and section["rows"][1]["ductility_range"] == ""
    assert "yields in bending at its base only" in section["lead"]
    html = render_html(result)
    assert "plastic hinge at the base" in html and "<td class=\"num\">– </td>" not in html


def test_a_steel_moment_frame_yields_in_storey_springs(make_workbook):
    """floors.csv names the model that ran: a steel moment frame's storey springs, with a yield ratio in every
    storey (a wall's base hinge: tests above)."""
    path = make_workbook(_sheets(("system", "steel moment frame"), ("response", "yielding"),
                                 ("yield_base_shear_g", 0.2)), record=False)
    result = run_assessment(read_workbook(path), "DE", seed=3)
    assert (result.floors["yielding_model"] == "storey springs").all()
    assert result.floors.loc[result.floors["floor"] > 0, "storey_yield_ratio"].notna().all()


def test_the_reports_wording_follows_the_model_that_ran_not_the_empty_cells(weak):
    """The storey table's lead reads ``yielding_model``: the same storeys (every storey with a yield ratio) get
    the base hinge's words where the field says ``base hinge``, and a wall's table (storey 2 empty) gets the
    storeys' words where it says ``storey springs`` (what the report once guessed from the empty cells, and
    could not for a one-storey wall)."""
    import dataclasses

    from assess.report.building import building_context

    springs = building_context(weak)["lead"]
    assert "the first of its storeys to yield does so at a base shear of" in springs
    assert "yielded at least one storey" in springs
    assert "at its base only" not in springs
    hinge_floors = weak.floors.assign(yielding_model="base hinge")
    hinged = building_context(dataclasses.replace(weak, floors=hinge_floors))["lead"]
    assert "a wall that yields in bending at its base only, at a base shear of 0.050" in hinged
    assert "yielded it" in hinged and "the ductility, in storey 1's row, is the wall's at its base" in hinged
    wall_floors = weak.floors.copy()
    wall_floors.loc[wall_floors["floor"] > 1, ["storey_yield_ratio", "ductility_median", "ductility_min",
                                               "ductility_max"]] = np.nan
    walled = building_context(dataclasses.replace(weak, floors=wall_floors))["lead"]
    assert "the first of its storeys to yield" in walled
    assert "at its base only" in building_context(dataclasses.replace(
        weak, floors=wall_floors.assign(yielding_model="base hinge")))["lead"]
    # a one-storey wall has no empty storey to guess from: the field still gives the hinge's words
    one_storey = weak.floors[weak.floors["floor"] <= 1].assign(yielding_model="base hinge")
    assert "at its base only" in building_context(dataclasses.replace(weak, floors=one_storey))["lead"]


def test_the_lead_says_the_yield_shear_holds_the_columns_share_where_the_springs_own_differ(weak):
    """Where a frame's columns stand apart from its springs, the table's yield shear (the storey's, columns
    included) does not keep the springs' ratios, which ``storey_strength`` gives: the lead names the column that
    does (``storey_spring_yield_ratio``); where the two agree it says nothing of it."""
    import dataclasses

    from assess.report.building import building_context

    clause = "the springs' own are floors.csv's storey_spring_yield_ratio"
    same = weak.floors.assign(storey_spring_yield_ratio=weak.floors["storey_yield_ratio"])
    assert clause not in building_context(dataclasses.replace(weak, floors=same))["lead"]
    apart = weak.floors.assign(storey_spring_yield_ratio=0.8 * weak.floors["storey_yield_ratio"])
    assert clause in building_context(dataclasses.replace(weak, floors=apart))["lead"]


@pytest.mark.parametrize("system, rows, said", [
    ("steel moment frame", [], "The overstrength is the literature's typical one, Elkady & Lignos' (2015) for steel "
                               "moment frames with their gravity framing and slabs, not this building's"),
    ("concrete moment frame", [], "The overstrength is a judgement, not this building's"),
    ("steel moment frame", [("overstrength", 2.0)], None),
    ("steel moment frame", [("yield_base_shear_g", 0.5)], None)])
def test_the_note_says_where_an_assumed_overstrength_comes_from_and_what_to_give(make_workbook, system, rows, said):
    """Only the design data (no ``yield_base_shear_g``, no ``overstrength``): the run's building note says where
    the assumed overstrength comes from (the literature's for a steel moment frame, a judgement for the systems
    without a source), that it moves the answer most, and names the two cells that replace it; where the
    engineer gave either, it says none of this."""
    path = make_workbook(_sheets(("system", system), ("response", "yielding"), *rows), record=False)
    result = run_assessment(read_workbook(path), "DE", seed=3)
    note = next(n for n in result.hazard_notes if "modelled as yielding" in n)
    assert ("The overstrength is" in note) == (said is not None), note
    if said is not None:
        assert said in note, note
        default = OVERSTRENGTH_BY_SYSTEM[system]
        assert f"times an assumed overstrength {default:g};" in note
        assert "give yield_base_shear_g (from a pushover or an evaluation) or overstrength where known." in note


@pytest.mark.parametrize("code", ["ASCE 7-22", "ASCE 7-16"])
@pytest.mark.parametrize("system, given, expected", [
    ("steel moment frame", None, "{code} §12.8 design (C.1 steel special moment frames"),
    ("steel moment frame", 0.3, "base shear at yield 0.3 W as given, spread over the storeys as {code} §12.8.3 does"),
    ("shear wall", 0.3, "base shear at yield 0.3 W as given; the wall yields in flexure at its base only, its "
                        "plastic hinge carrying the moment of {code} §12.8.3's lateral forces"),
])
def test_the_strengths_words_name_the_sites_edition(code, system, given, expected):
    """The design strength's words name the edition of the site sheet's ``code`` (page 1 names it too), not
    always ASCE 7-22: a 7-16 site read "ASCE 7-22 §12.8" in its building note."""
    from assess.assessment.floors import building_model_of
    from assess.inventory.site_building import BuildingSheet, SiteSheet
    site = SiteSheet(code=code, sds_g=1.0, sd1_g=0.6)
    model = building_model_of(BuildingSheet(storeys=3, height_m=12.0, period_s=0.4, system=system,
                                            response="yielding", yield_base_shear_g=given), site)
    other = "ASCE 7-16" if code == "ASCE 7-22" else "ASCE 7-22"
    assert expected.format(code=code) in model.strength.source
    assert other not in model.strength.source


def test_the_pass_through_a_yielding_building_shows_progress(make_workbook, monkeypatch):
    """The ground histories go through the yielding stick in one pass, which says how far it has got (here at
    every history: this pass is quicker than the lines' interval), counting up to all of them."""
    import re

    monkeypatch.setattr(yielding_module, "PROGRESS_EVERY_S", 0.0)
    path = make_workbook(_sheets(("system", "steel moment frame"), ("response", "yielding")), record=False)
    said = []
    run_assessment(read_workbook(path), "DE", seed=3, progress=said.append)
    counts = [tuple(map(int, m.groups())) for line in said
              if (m := re.fullmatch(r"through the building: (\d+) of (\d+) ground histories", line))]
    assert counts and counts[-1][0] == counts[-1][1] == 3, said  # the site sheet's suite_size
    assert [done for done, _ in counts] == sorted(done for done, _ in counts)


def test_a_pass_speaks_every_interval_and_at_its_end_and_a_quick_one_not_at_all(monkeypatch):
    """:func:`pass_progress` on a clock that advances 2 s a motion, lines every 5 s: it speaks at the third
    motion (6 s), the sixth (12 s) and the end (the seventh); on a clock that stands still, never."""
    from assess.building.yielding import pass_progress
    clock = iter(range(0, 100, 2))
    monkeypatch.setattr(yielding_module.time, "monotonic", lambda: next(clock))
    said = []
    report = pass_progress(said.append, "stripe 0.1 g: ")
    for done in range(1, 8):
        report(done, 7)
    assert said == [f"stripe 0.1 g: through the building: {k} of 7 ground histories" for k in (3, 6, 7)]
    monkeypatch.setattr(yielding_module.time, "monotonic", lambda: 0.0)
    quiet = []
    report = pass_progress(quiet.append)
    for done in range(1, 8):
        report(done, 7)
    assert quiet == []


def test_the_note_says_why_a_tall_building_is_elastic():
    """Above the storeys the yielding model takes, a building whose strength is known is modelled elastic by
    default; the note says why (and says nothing of it where the sheet asked for elastic)."""
    from assess.assessment.floors import building_model_of, building_note
    from assess.inventory.site_building import MAX_YIELDING_STOREYS, BuildingSheet, SiteSheet
    site = SiteSheet(sds_g=1.0, sd1_g=0.6)
    n = MAX_YIELDING_STOREYS + 1
    for response, said in ((None, True), ("elastic", False)):
        sheet = BuildingSheet(storeys=n, height_m=4.0 * n, system="steel moment frame", response=response)
        note = building_note(building_model_of(sheet, site), sheet, [n], None)
        assert ("The yielding model takes at most 40 storeys" in note) == said, note
        assert "through the building's elastic modes" in note


@pytest.mark.parametrize("period_s, refused", [(1.0, False), (2.0, True)])
def test_p_delta_beyond_the_codes_stability_coefficient_is_refused(period_s, refused):
    """One storey of 3 m: k = m (2π/T)², P = m g, so θ = P/(k h) = g T²/(4π² h) exactly (0.0828 at 1 s, 0.331 at
    2 s); above ASCE 7-22 §12.8.7's 0.25 the building would collapse in the model under its own weight, so the
    run stops at the p_delta row (exit 2) rather than shake floors with a collapsing stick."""
    from assess.assessment.floors import building_model_of
    from assess.errors import InputError
    from assess.inventory.site_building import BuildingSheet, SiteSheet
    site = SiteSheet(sds_g=1.0, sd1_g=0.6)
    sheet = BuildingSheet(storeys=1, height_m=3.0, period_s=period_s, p_delta=True, rows={"p_delta": 5})
    theta = 9.80665 * period_s ** 2 / (4 * np.pi ** 2 * 3.0)
    if not refused:
        assert building_model_of(sheet, site).stability_coefficient == pytest.approx(theta, rel=1e-9)
        return
    with pytest.raises(InputError) as error:
        building_model_of(sheet, site, workbook_name="b.xlsx")
    (problem,) = error.value.problems
    assert (problem.sheet, problem.row) == ("building", 5)
    assert f"stability coefficient θ is {theta:.2g}" in problem.message and "p_delta" in problem.fix


def test_items_under_motions_beyond_the_trusted_drift_are_flagged(weak):
    """An item on a floor whose motions come from the stick is flagged with how many of its motions the stick
    passed its trusted drift under. That is at least the most motions any one storey counted (floors.csv) and
    at most their sum over the storeys. The ground floor's item, whose motions no model touched, is not
    flagged."""
    floors = weak.floors.set_index("floor")
    beyond = floors.loc[1:, "motions_beyond_drift_limit"]
    flags = {flag.item_id: flag for flag in weak.flags if flag.code == "building_beyond_drift"}
    assert set(flags) == {"M-1", "R-2"}
    summary = weak.summary.set_index("id")
    for item_id, flag in flags.items():
        count, total = map(int, flag.detail.split(" motions")[0].split(" of "))
        assert total == 3 and beyond.max() <= count <= min(beyond.sum(), total)
        assert "building_beyond_drift" in summary.loc[item_id, "flags"]
    assert "building_beyond_drift" not in summary.loc["G-1", "flags"]
    html = render_html(weak).replace("&#39;", "'")
    assert "Floor motions from the building's model beyond the drift it is trusted to" in html


@pytest.mark.parametrize("system, risk_category, expected", [
    # ASCE 7-22 Table 12.2-1's R and Ω0, Table 1.5-2's I_e, eq. 13.3-6 by hand: sqrt(1.1 R / (I_e Ω0)) >= 1.3
    ("steel moment frame", "II", (1.1 * 8 / (1.0 * 3)) ** 0.5),  # C.1: R 8, Ω0 3 -> 1.713
    ("eccentrically braced frame", "IV", (1.1 * 8 / (1.5 * 2)) ** 0.5),  # B.1: R 8, Ω0 2 -> 1.713
    ("braced frame", "III", (1.1 * 6 / (1.25 * 2)) ** 0.5),  # B.2: R 6, Ω0 2 -> 1.625
    ("shear wall", "II", (1.1 * 5 / (1.0 * 2.5)) ** 0.5),  # A.1: R 5, Ω0 2.5 -> 1.483
    ("other", "IV", 1.3),  # H: R 3, Ω0 3 -> 0.856, the floor 1.3
])
def test_the_buildings_ductility_reduction_is_the_codes_for_its_system_and_risk_category(system, risk_category,
                                                                                        expected):
    from assess.assessment.floors import ductility_reduction_of
    from assess.building.yielding import yielding_building

    modes = building_modes(4, 4.0, system=system, period_s=0.5)
    building = yielding_building(modes, system, sds_g=1.0, sd1_g=0.6, risk_category=risk_category)
    assert ductility_reduction_of(building) == pytest.approx(expected, abs=1e-12)


def test_the_building_page_sets_pfa_over_pga_beside_hf_and_hf_over_rmu(weak):
    """floors.csv's H_f/R_μ is H_f over the building's R_μ ('other' in Risk Category IV: the floor, 1.3), empty at
    the ground; the report's building page prints both columns from it and names R_μ in its lead."""
    from assess.report.building import building_context

    floors = weak.floors.set_index("floor")
    assert (floors["rmu_asce7_22"] == 1.3).all() and np.isnan(floors.loc[0, "hf_over_rmu_asce7_22"])
    np.testing.assert_allclose(floors.loc[1:, "hf_over_rmu_asce7_22"], floors.loc[1:, "hf_asce7_22"] / 1.3)
    section = building_context(weak)
    expected = [f"{v:.2f}" for v in floors.loc[1:, "hf_over_rmu_asce7_22"]]
    assert [row["hf_over_rmu"] for row in section["rows"]] == expected
    assert "H_f/R_μ with R_μ 1.30 (eq. 13.3-6" in section["lead"]
    assert "H<sub>f</sub>/R<sub>μ</sub>" in render_html(weak)


def test_the_method_and_floors_csv_say_the_storeys_hardening_that_ran(weak, make_workbook):
    """floors.csv's storey_hardening_ratio and the method's (F5) give the hardening of the stick that ran: the
    default 3 %, or the building sheet's."""
    assert (weak.floors["storey_hardening_ratio"] == 0.03).all()
    assert "hardening after yield at 3 % of its stiffness" in render_html(weak)
    path = make_workbook(_sheets(("response", "yielding"), ("yield_base_shear_g", 0.05),
                                 ("storey_hardening_ratio", 0.015)), record=False)
    given = run_assessment(read_workbook(path), "DE", seed=3)
    assert (given.floors["storey_hardening_ratio"] == 0.015).all()
    assert "hardening after yield at 1.5 % of its stiffness (the building sheet" in render_html(given)
