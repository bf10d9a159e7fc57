"""The workbook's ``site`` and ``building`` sheets (docs/workbook.md): read, converted, refused at their cell."""
from __future__ import annotations

import pytest

from assess.errors import InputError
from assess.inventory import read_workbook
from assess.inventory.site_building import parse_storey_profile
from workbooks import good_sheets


def _sheets(site=None, building=None, hazard=True):
    sheets = good_sheets()
    if not hazard:
        del sheets["hazard"]
    if site is not None:
        sheets["site"] = [["key", "value"]] + [list(pair) for pair in site]
    if building is not None:
        sheets["building"] = [["key", "value"]] + [list(pair) for pair in building]
    return sheets


def _problems(make_workbook, **kwargs) -> list:
    with pytest.raises(InputError) as error:
        read_workbook(make_workbook(_sheets(**kwargs)))
    return error.value.problems


def test_site_with_design_values_and_no_hazard_sheet(make_workbook):
    inventory = read_workbook(make_workbook(_sheets(
        site=[("code", "ASCE 7-22"), ("sds_g", 1.0), ("sd1_g", 0.6), ("site_class", "D"),
              ("risk_category", "iv")], hazard=False)))
    site = inventory.site  # the site class beside design values is kept (it says what they stand on)
    assert (site.code, site.sds_g, site.sd1_g, site.site_class, site.risk_category) == (
        "ASCE 7-22", 1.0, 0.6, "D", "IV")
    assert site.tl_s is None and site.suite_size is None and site.ss_g is None  # the route's default
    assert inventory.hazard.empty and inventory.building is None


def test_site_mapped_values_with_7_16_and_numbers_for_categories(make_workbook):
    site = read_workbook(make_workbook(_sheets(site=[
        ("code", "asce7-16"), ("SS_g", 1.5), ("s1_g", 0.6), ("site_class", "d"), ("risk_category", 3),
        ("tl_s", 12), ("suite_size", 7)]))).site
    assert (site.code, site.ss_g, site.s1_g, site.site_class, site.risk_category) == (
        "ASCE 7-16", 1.5, 0.6, "D", "III")
    assert (site.tl_s, site.suite_size) == (12.0, 7)


def test_building_in_feet_is_converted_once(make_workbook):
    building = read_workbook(make_workbook(_sheets(building=[
        ("storeys", 4), ("storey_height_ft", 13), ("system", "Concrete moment frame"), ("period_s", 0.6),
        ("damping", 0.03)]))).building
    assert building.storeys == 4 and building.roof_floor == 4
    assert building.height_m == pytest.approx(4 * 13 * 0.3048, rel=1e-12)
    assert (building.system, building.period_s, building.damping) == ("concrete moment frame", 0.6, 0.03)


def test_building_defaults(make_workbook):
    building = read_workbook(make_workbook(_sheets(building=[("storeys", 3), ("height_m", 12)]))).building
    assert (building.system, building.period_s, building.damping) == ("other", None, 0.05)


def _located(problems, sheet, cell):
    return [p for p in problems if p.sheet == sheet and p.cell == cell]


def test_refusals_name_the_cell(make_workbook):
    problems = _problems(make_workbook, site=[("sds_g", 1.0), ("sd1_g", 0.6), ("ss_g", 1.5)],
                         building=[("storeys", 3), ("height_cm", 1200), ("system", "steel momentframe")])
    # both sets of site values: located at the first mapped key
    assert _located(problems, "site", "A4") and "both design values" in _located(problems, "site", "A4")[0].message
    # a storey of 4 cm: the unit slip is caught at its value cell
    # (height_cm 1200 = 12 m passes; the misspelt system is refused with a suggestion)
    system = _located(problems, "building", "B4")
    assert system and "did you mean 'steel moment frame'" in system[0].message


def test_unit_slip_in_height_is_refused(make_workbook):
    problems = _problems(make_workbook, building=[("storeys", 12), ("height_m", 48 * 12)])
    bad = _located(problems, "building", "B3")
    assert bad and "48 m a storey" in bad[0].message and "height_ft" in bad[0].fix


@pytest.mark.parametrize("pairs, cell, words", [
    ([("sds_g", 1.0)], "A2", "without sd1_g"),
    ([("ss_g", 1.0), ("s1_g", 0.4)], "A2", "without site_class"),
    ([("ss_g", 1.0), ("site_class", "C")], "A2", "without s1"),
    ([("sds_g", 1.0), ("sd1_g", 0.6), ("code", "ASCE 7-10")], "B4", "not an edition"),
    ([("ss_g", 1.0), ("s1_g", 0.4), ("site_class", "F")], "B4", "site response analysis"),
    ([("ss_g", 1.0), ("s1_g", 0.4), ("site_class", "CD"), ("code", "ASCE 7-16")], "B4", "not one of ASCE 7-16's"),
    ([("sds_g", 1.0), ("sd1_g", 0.6), ("risk_category", "V")], "B4", "risk category"),
    ([("sds_g", 9.0), ("sd1_g", 0.6)], "B2", "not plausible"),
    ([("sds_g", 5.0), ("sd1_g", 0.01)], "B3", "T_s = S_D1/S_DS at 0.002 s, outside 0.05 to 5 s"),
    ([("sd1_g", 1.2), ("sds_g", 0.2)], "B2", "T_s = S_D1/S_DS at 6 s, outside 0.05 to 5 s"),
    ([("sds_g", 1.0), ("sd1_g", 0.6), ("records", "../elsewhere")], "B4", "outside the workbook's folder"),
    ([("sds_g", 1.0), ("sd1_g", 0.6), ("records", "missing")], "B4", "is not a folder"),
    ([("sds_g", 1.0), ("sd1_g", 0.6), ("sds", 1.1)], "A4", "given twice"),
    ([("sds_g", 1.0), ("sd1_g", 0.6), ("pga", 0.4)], "A4", "unknown key"),
    ([("sds_g", 1.0), ("sd1_g", 0.6), ("suite_size", 2)], "B4", "not plausible"),
    ([("sds_g", 1.0), ("sd1_g", 0.6), ("records_scaling", "matched")], "B4", "names no records folder"),
    ([("sds_g", 1.0), ("sd1_g", 0.6), ("records_scaling", "spectral")], "B4", "is not amplitude or matched"),
])
def test_site_refusals(make_workbook, pairs, cell, words):
    problems = _problems(make_workbook, site=pairs)
    located = _located(problems, "site", cell)
    assert located, [str(p) for p in problems]
    assert words in located[0].message, str(located[0])


def test_records_scaling_is_read_any_case_and_amplitude_by_default(make_workbook, tmp_path):
    (tmp_path / "recs").mkdir()
    given = read_workbook(make_workbook(_sheets(site=[("sds_g", 1.0), ("sd1_g", 0.6), ("records", "recs"),
                                                      ("records_scaling", " Matched ")], hazard=False))).site
    assert given.records_scaling == "matched"
    plain = read_workbook(make_workbook(_sheets(site=[("sds_g", 1.0), ("sd1_g", 0.6)], hazard=False))).site
    assert plain.records_scaling == "amplitude"


def test_the_design_spectrums_corner_is_checked_against_real_sites(make_workbook):
    """Sites read from engineers' own calculation packages (tests/data/asce7/worked_examples.csv, T_s 0.54 s) and
    two sites near the ends of what ASCE 7-16's site coefficients give (Tables 11.4-1 and 11.4-2: rock, site class B,
    under S_S 1.5 and S_1 0.6: S_DS 2/3 x 1.5 x 0.9 = 0.9, S_D1 2/3 x 0.6 x 0.8 = 0.32, T_s 0.36 s; a soft soil, class E,
    S_S 0.1 and S_1 0.04: S_DS 2/3 x 0.1 x 2.4 = 0.16, S_D1 2/3 x 0.04 x 4.2 = 0.112, T_s 0.7 s) pass the corner
    check; an S_D1 a thirtieth of a high S_DS (2.0 and 0.06 g, T_s 0.03 s) does not. A tenfold slip in the first
    site's S_D1 (T_s 0.054 s) is within the bounds: the check catches values from different lookups, not every
    slip."""
    for sds, sd1 in ((1.060, 0.575), (0.9, 0.32), (0.16, 0.112), (1.060, 0.0575), (2.0, 0.06)):
        if not 0.05 <= sd1 / sds <= 5.0:
            problems = _problems(make_workbook, site=[("sds_g", sds), ("sd1_g", sd1)])
            assert ["T_s = S_D1/S_DS" in p.message for p in problems] == [True], [str(p) for p in problems]
        else:
            assert read_workbook(make_workbook(_sheets(site=[("sds_g", sds), ("sd1_g", sd1)]))).site.sd1_g == sd1


def test_no_hazard_anywhere_is_refused(make_workbook):
    problems = _problems(make_workbook, hazard=False)
    assert any("'hazard' is missing" in p.message and "'site' sheet" in p.fix for p in problems)


def test_a_site_sheet_without_any_hazard_is_refused(make_workbook):
    problems = _problems(make_workbook, site=[("risk_category", "IV")])
    assert any(p.sheet == "site" and p.row == 1 and "gives no hazard" in p.message for p in problems)


def test_building_needs_storeys_and_one_height(make_workbook):
    problems = _problems(make_workbook, building=[("height_m", 12), ("storey_height_m", 4)])
    messages = [p.message for p in problems if p.sheet == "building"]
    assert any("no 'storeys'" in m for m in messages) and any("both height" in m for m in messages)


@pytest.mark.parametrize("bad", ["one point one", float("nan"), float("inf"), 0])
def test_an_invalid_sds_is_named_once_not_called_missing(make_workbook, bad):
    """Hostile-input campaign: an invalid sds_g (text, NaN, inf, 0) was followed by "the site sheet gives sd1_g
    without sds_g", though the row exists. Its own cell says what is wrong; nothing is called missing."""
    problems = _problems(make_workbook, site=[("sds_g", bad), ("sd1_g", 0.6)])
    site = [p for p in problems if p.sheet == "site"]
    assert _located(problems, "site", "B2"), [str(p) for p in problems]
    assert not any("without" in p.message or "gives no hazard" in p.message for p in site), [str(p) for p in site]


# ---------------------------------------------------------------- the yielding building's keys

DESIGN_SITE = [("sds_g", 1.1), ("sd1_g", 0.6), ("risk_category", "IV")]


def test_yielding_keys_are_read(make_workbook):
    building = read_workbook(make_workbook(_sheets(site=DESIGN_SITE, building=[
        ("storeys", 5), ("height_m", 20), ("system", "shear wall"), ("response", " Yielding"),
        ("yield_base_shear_g", 0.45), ("p_delta", "YES")]))).building
    assert (building.response, building.yield_base_shear_g, building.overstrength, building.p_delta) == (
        "yielding", 0.45, None, True)


@pytest.mark.parametrize("site, building, expected", [
    (DESIGN_SITE, [], "yielding"),                              # the site's design values give the strength
    (None, [], "elastic"),                                      # nothing gives it
    (None, [("yield_base_shear_g", 0.3)], "yielding"),          # the engineer's
    (DESIGN_SITE, [("response", "elastic")], "elastic"),        # the sheet says so
])
def test_the_default_response_is_yielding_where_the_strength_is_known(make_workbook, site, building, expected):
    inventory = read_workbook(make_workbook(_sheets(site=site, building=[("storeys", 3), ("height_m", 12)]
                                                    + building)))
    assert inventory.building.response_with(inventory.site) == expected


@pytest.mark.parametrize("rows, cell, words, fix", [
    ([("response", "plastic")], "B4", "is not elastic or yielding", "write yielding"),
    ([("response", "yeilding")], "B4", "did you mean 'yielding'", "write yielding"),
    ([("p_delta", "maybe")], "B4", "not yes or no", "write yes"),
    ([("yield_base_shear_g", 7.0)], "B4", "not plausible", ""),
    ([("overstrength", 0.5)], "B4", "not plausible", ""),
    ([("response", "elastic"), ("overstrength", 2.5)], "A5", "response is elastic", "delete the overstrength row"),
    ([("yield_base_shear_g", 0.3), ("overstrength", 2.5)], "A5", "both yield_base_shear_g and overstrength",
     "keep yield_base_shear_g"),
])
def test_yielding_refusals_name_the_cell(make_workbook, rows, cell, words, fix):
    problems = _problems(make_workbook, site=DESIGN_SITE, building=[("storeys", 3), ("height_m", 12)] + rows)
    located = _located(problems, "building", cell)
    assert located and words in located[0].message, [(p.cell, p.message) for p in problems]
    assert fix in located[0].fix and located[0].fix


@pytest.mark.parametrize("storeys, building, expected", [
    (40, [], "yielding"),                                       # the most the yielding model takes
    (41, [], "elastic"),                                        # beyond it, the elastic modes answer
    (41, [("p_delta", "no")], "elastic"),                       # a p_delta that asks nothing is no request
    (200, [("response", "elastic")], "elastic"),
])
def test_above_the_yielding_models_storeys_the_default_is_elastic(make_workbook, storeys, building, expected):
    inventory = read_workbook(make_workbook(_sheets(site=DESIGN_SITE, building=[
        ("storeys", storeys), ("height_m", 4 * storeys)] + building)))
    assert inventory.building.response_with(inventory.site) == expected


@pytest.mark.parametrize("rows, cell, header", [
    ([("response", "yielding")], "B4", "value"),
    ([("yield_base_shear_g", 0.2)], "A4", "key"),
    ([("overstrength", 2.5)], "A4", "key"),
    ([("p_delta", "yes")], "A4", "key"),
])
def test_asking_for_yielding_above_its_storeys_is_refused_at_the_cell(make_workbook, rows, cell, header):
    """A 41-storey building: one ground motion through the yielding stick costs about the cube of the storeys,
    so what asks for it is refused, at its cell, with the elastic modes as the fix (or the row deleted)."""
    problems = _problems(make_workbook, site=DESIGN_SITE, building=[("storeys", 41), ("height_m", 164)] + rows)
    located = _located(problems, "building", cell)
    assert located, [(p.cell, p.message) for p in problems]
    assert "the building has 41 storeys: the yielding model takes at most 40" in located[0].message
    assert ("write elastic in response" if header == "value" else "delete the") in located[0].fix


@pytest.mark.parametrize("system, period, refused", [
    ("shear wall", 0.04, True),            # T_a = 0.0488 × 20^0.75 = 0.46 s: a tenth of it
    ("shear wall", 0.12, False),           # a quarter of it and more
    ("steel moment frame", 0.17, True),    # T_a = 0.0724 × 20^0.8 = 0.79 s
    ("steel moment frame", 0.2, False),
])
def test_a_period_far_below_the_approximate_one_is_refused_at_its_cell(make_workbook, system, period, refused):
    """A T1 under a quarter of ASCE 7's T_a (Eq. 12.8-7) is a unit slip, and would make the yielding model's
    steps as short: refused at the period cell."""
    building = [("storeys", 5), ("height_m", 20), ("system", system), ("period_s", period)]
    if not refused:
        assert read_workbook(make_workbook(_sheets(site=DESIGN_SITE, building=building))).building.period_s == period
        return
    located = _located(_problems(make_workbook, site=DESIGN_SITE, building=building), "building", "B5")
    assert located and "below 1/4 of ASCE 7's approximate period T_a" in located[0].message
    assert "in seconds" in located[0].fix


def test_yielding_without_a_strength_is_refused_at_the_response_cell(make_workbook):
    """No yield_base_shear_g and a site sheet without design values (here, none at all): exit 2 at response."""
    problems = _problems(make_workbook, building=[("storeys", 3), ("height_m", 12), ("response", "yielding")])
    (problem,) = problems
    assert (problem.sheet, problem.cell) == ("building", "B4")
    assert "nothing gives the storeys' strength" in problem.message and "yield_base_shear_g" in problem.fix


def test_the_command_exits_2_on_a_bad_response_and_writes_nothing(make_workbook, tmp_path, capsys):
    from assess import cli
    path = make_workbook(_sheets(site=DESIGN_SITE, building=[("storeys", 3), ("height_m", 12),
                                                             ("response", "nonlinear")]))
    out = tmp_path / "out"
    assert cli.main([str(path), "--hazard", "DE", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert "building" in err and "B4" in err and "Traceback" not in err
    assert not out.exists() or not any(out.iterdir())


# ---------------------------------------------------------------- the storeys' stiffness profile

def test_storey_stiffness_is_read_as_one_number_per_storey(make_workbook):
    building = read_workbook(make_workbook(_sheets(building=[
        ("storeys", 4), ("height_m", 16), ("storey_stiffness", "100; 90, 78 ,62")]))).building
    assert building.storey_stiffness == (100.0, 90.0, 78.0, 62.0)
    uniform = read_workbook(make_workbook(_sheets(building=[
        ("storeys", 3), ("height_m", 12), ("storey_stiffness", " Uniform")]))).building
    assert uniform.storey_stiffness == (1.0, 1.0, 1.0)
    assert parse_storey_profile(2.5, 1) == ((2.5,), None)   # a one-storey building's number cell
    assert read_workbook(make_workbook(_sheets(building=[("storeys", 3), ("height_m", 12)]))) \
        .building.storey_stiffness is None


@pytest.mark.parametrize("value, words", [
    ("1, 0.9", "gives 2 values for 3 storeys"),
    ("1, 0.9, 0.8, 0.7", "gives 4 values for 3 storeys"),
    ("1, stiff, 0.8", "'stiff' is not a number"),
    ("1, 0, 0.8", "not greater than 0"),
    ("1, -0.5, 0.8", "not greater than 0"),
    ("1, nan, 0.8", "not greater than 0"),
    ("1, 0.9, 0.01", "100 times the softest"),
    ("linear", "'linear' is not a number"),
])
def test_a_bad_storey_stiffness_is_refused_at_its_cell(make_workbook, value, words):
    problems = _problems(make_workbook, building=[("storeys", 3), ("height_m", 12), ("storey_stiffness", value)])
    located = _located(problems, "building", "B4")
    assert located and words in located[0].message, [(p.cell, p.message) for p in problems]
    assert "first storey to the roof" in located[0].fix or "soft storey" in located[0].fix


def test_the_command_exits_2_on_a_bad_storey_stiffness_and_writes_nothing(make_workbook, tmp_path, capsys):
    from assess import cli
    path = make_workbook(_sheets(site=DESIGN_SITE, building=[("storeys", 3), ("height_m", 12),
                                                             ("storey_stiffness", "1, 0.5")]))
    out = tmp_path / "out"
    assert cli.main([str(path), "--hazard", "DE", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert "building" in err and "B4" in err and "storey_stiffness" in err and "Traceback" not in err
    assert not out.exists() or not any(out.iterdir())


def test_a_refused_height_is_not_also_called_missing(make_workbook):
    """A storey height out of range is refused at its cell, once: the sheet is not also said to have no height."""
    problems = _problems(make_workbook, building=[("storeys", 3), ("storey_height_ft", 33)])
    assert [p.cell for p in problems] == ["B3"], [(p.cell, p.message) for p in problems]
    assert "storey_height 33 ft" in problems[0].message
