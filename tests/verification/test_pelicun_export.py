"""The pelicun export (assess/fragility/pelicun_export.py) against the real library files and pelicun.

* the columns are those of the FEMA P-58 ``fragility.csv`` of NHERI SimCenter's
  Damage and Loss Model Library (tests/data/pelicun, verbatim excerpt), and the
  values and the metadata obey the library's own format rules and JSON schema
  (transcribed from its tests/test_data_format.py), which also accept the real
  excerpt here;
* pelicun itself (when installed: it is in the ``test`` extra) loads the
  exported file into a damage model and computes, at given peak floor
  accelerations, damage-state probabilities equal to the lognormal
  fragilities: P(DS2) = Φ(ln(a/θ₂)/β₂) and P(DS ≥ 1) = max(P₁, P₂) (its limit
  states are exceeded in order, with fully correlated capacities);
* each item stands at the story pelicun counts (Location = assess floor + 1, pelicun reading PFA-(story - 1))
  and, in pelicun's damage model with a different PFA at every level (tests/peers/pelicun_dl.py), its damage
  probability is its fragility at the PFA of its own floor, from hand-made items and from an assessment's
  export.
"""
from __future__ import annotations

import csv
import json
import re
from dataclasses import replace
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from scipy import stats

from assess.fragility.msa import fit_lognormal_fragility
from assess.fragility.pelicun_export import (
    COLUMNS, ItemFragilities, LimitStateFragility, component_table, fragility_metadata, fragility_table,
    pelicun_component_id, write_pelicun_fragility,
)

DATA = Path(__file__).resolve().parents[1] / "data" / "pelicun"
REAL_CSV = DATA / "fema_p58_fragility_excerpt.csv"
REAL_JSON = DATA / "fema_p58_fragility_excerpt.json"

NAN = float("nan")
ITEMS = [
    # sliding first, overturning later with the same β: nested limit states
    ItemFragilities("freezer_F12", "Upright freezer F-12, lab 2.14",
                    LimitStateFragility(0.35, 0.4, "fitted"), LimitStateFragility(0.8, 0.4)),
    # a slender cabinet that tips before it slides that far: the fragilities cross
    ItemFragilities("cabinet_C3", "Gas-bottle cabinet C-3",
                    LimitStateFragility(0.6, 0.3), LimitStateFragility(0.45, 0.5)),
    # squat item never overturned in the simulations: LS1 only
    ItemFragilities("incubator_7", "Incubator 7",
                    LimitStateFragility(0.5, 0.45), LimitStateFragility(NAN, NAN, "no overturn")),
]


def _phi(a_g, median_g, beta):
    return stats.norm.cdf(np.log(a_g / median_g) / beta)


# ----------------------------------------------------------- the library's format


def test_columns_are_the_library_columns():
    with REAL_CSV.open(newline="", encoding="utf-8") as handle:
        real_header = next(csv.reader(handle))
    assert list(COLUMNS) == real_header[:len(COLUMNS)]  # the library goes on to LS4
    ours = fragility_table(ITEMS).columns.tolist()
    assert ours == real_header[:14]


def test_rows_read_back_like_the_library_rows(tmp_path):
    csv_path, _ = write_pelicun_fragility(tmp_path, ITEMS)
    ours = pd.read_csv(csv_path, index_col=0)
    real = pd.read_csv(REAL_CSV, index_col=0)
    for column in ours.columns:  # same parsed types column by column (int flags, str, float)
        assert ours[column].dtype.kind == real[column].dtype.kind or ours[column].isna().all(), \
            column
    pfa_contents = real.loc["E.20.22.001"]
    for column in ("Demand-Type", "Demand-Unit", "Demand-Offset", "LS1-Family"):
        assert ours.loc["freezer_F12", column] == pfa_contents[column], column
    assert ours.loc["freezer_F12", "LS1-Theta_0"] == 0.35
    assert ours.loc["cabinet_C3", "LS2-Theta_1"] == 0.5
    assert ours.loc["incubator_7", ["LS2-Family", "LS2-Theta_0"]].isna().all()


def _multiindex(frame: pd.DataFrame) -> pd.DataFrame:
    """'LS1-Theta_0' -> ('LS1', 'Theta_0'); 'Incomplete' -> ('Incomplete', ''), as dlml and pelicun read."""
    frame = frame.copy()
    frame.columns = pd.MultiIndex.from_tuples(
        [tuple(c.split("-", 1)) if "-" in c else (c, "") for c in frame.columns])
    return frame


def _library_rule_violations(frame: pd.DataFrame) -> list:
    """The fragility rules of the library's tests/test_data_format.py (closed-world columns,
    binary flags, whole offsets, θ0 > 0, θ1 > 0, complete unless Incomplete)."""
    bad = []
    fixed = {"Demand": {"Directional", "Offset", "Type", "Unit"}, "Incomplete": {""}}
    numbered = {"Family", "Theta_0", "Theta_1", "DamageStateWeights"}
    for top, sub in frame.columns:
        ok = (sub in fixed[top]) if top in fixed else (
            re.fullmatch(r"LS\d+", top) is not None and sub in numbered)
        if not ok:
            bad.append(("column", top, sub))
    for (top, sub), flag in (((("Demand", "Directional")), "binary"),
                             (("Incomplete", ""), "binary"), (("Demand", "Offset"), "whole")):
        for key, value in frame[(top, sub)].dropna().items():
            if (flag == "binary" and float(value) not in (0.0, 1.0)) or (
                    flag == "whole" and not float(value).is_integer()):
                bad.append((key, top, sub, value))
    incomplete = frame[("Incomplete", "")] == 1
    for top in {t for t, _ in frame.columns if t.startswith("LS")}:
        for key, value in frame[(top, "Theta_1")].dropna().items():
            if not float(value) > 0.0:
                bad.append((key, top, "Theta_1", value))
        for key, value in frame[(top, "Theta_0")].dropna().items():
            if not float(value) > 0.0:
                bad.append((key, top, "Theta_0", value))
        active = frame[(top, "Family")].notna() & ~incomplete
        for key in frame.index[active & (frame[(top, "Theta_0")].isna()
                                         | frame[(top, "Theta_1")].isna())]:
            bad.append((key, top, "under-specified"))
    return bad


def test_values_obey_the_library_rules(tmp_path):
    real = _multiindex(pd.read_csv(REAL_CSV, index_col=0))
    assert _library_rule_violations(real) == []  # the transcription accepts the real file
    csv_path, _ = write_pelicun_fragility(tmp_path, ITEMS)
    ours = _multiindex(pd.read_csv(csv_path, index_col=0))
    assert _library_rule_violations(ours) == []
    # and a rule that bites: a zero dispersion would be refused
    broken = ours.copy()
    broken.loc["freezer_F12", ("LS1", "Theta_1")] = 0.0
    assert _library_rule_violations(broken)


# The metadata schema of the library's tests/test_data_format.py (fragility collection).
_REPAIR_STATE = {"type": "object", "required": ["Description"], "additionalProperties": False,
                 "properties": {"Description": {"type": "string"},
                                "RepairAction": {"type": "string"}}}
_LIMIT_STATES = {"type": "object", "additionalProperties": False, "patternProperties": {
    r"^LS\d+$": {"type": "object", "additionalProperties": False,
                 "patternProperties": {r"^DS\d+$": _REPAIR_STATE}}}}
_GENERAL_INFORMATION = {
    "type": "object", "required": ["ShortName", "Description", "Version", "ComponentGroups"],
    "additionalProperties": False,
    "properties": {"ShortName": {"type": "string"}, "Description": {"type": "string"},
                   "Version": {"type": "string"},
                   "ComponentGroups": {"type": ["object", "array"]},
                   "DecisionVariables": {"type": "object"}}}
FRAGILITY_METADATA_SCHEMA = {
    "type": "object", "required": ["_GeneralInformation"],
    "properties": {"_GeneralInformation": _GENERAL_INFORMATION,
                   "References": {"type": "object", "additionalProperties": {"type": "string"}}},
    "additionalProperties": {
        "type": "object", "additionalProperties": False,
        "required": ["Description", "SuggestedComponentBlockSize", "RoundUpToIntegerQuantity",
                     "LimitStates"],
        "properties": {"Description": {"type": "string"},
                       "SuggestedComponentBlockSize": {"type": "string"},
                       "RoundUpToIntegerQuantity": {"enum": ["True", "False"]},
                       "Comments": {"type": "string"},
                       "Reference": {"type": "array", "items": {"type": "string"}},
                       "LimitStates": _LIMIT_STATES}},
}


def _states_in_csv(frame: pd.DataFrame) -> dict:
    """Each model's LS<n> groups with any non-empty cell (the library's metadata/CSV check)."""
    states: dict = {}
    for top, sub in frame.columns:
        if re.fullmatch(r"LS\d+", top):
            for model in frame.index[frame[(top, sub)].notna().to_numpy()]:
                states.setdefault(model, set()).add(top)
    return states


def test_metadata_obeys_the_library_schema_and_matches_the_table(tmp_path):
    jsonschema = pytest.importorskip("jsonschema", reason="jsonschema (a pelicun dependency) "
                                     "validates the metadata against the library's schema")
    validator = jsonschema.Draft7Validator(FRAGILITY_METADATA_SCHEMA)
    real = json.loads(REAL_JSON.read_text(encoding="utf-8"))
    assert list(validator.iter_errors(real)) == []  # the transcription accepts the real file
    csv_path, json_path = write_pelicun_fragility(tmp_path, ITEMS)
    ours = json.loads(json_path.read_text(encoding="utf-8"))
    errors = [f"{e.json_path}: {e.message}" for e in validator.iter_errors(ours)]
    assert errors == []
    table = _multiindex(pd.read_csv(csv_path, index_col=0))
    assert set(ours) - {"_GeneralInformation"} == set(table.index)
    in_csv = _states_in_csv(table)
    for model, entry in ours.items():
        if model != "_GeneralInformation":
            assert set(entry["LimitStates"]) == in_csv[model], model
    assert set(ours["incubator_7"]["LimitStates"]) == {"LS1"}
    assert "max(P(LS1), P(LS2))" in ours["cabinet_C3"]["Comments"]


def test_missing_fits_are_never_invented():
    no_slide = ItemFragilities("heavy_safe", "Safe", LimitStateFragility(NAN, NAN, "none"),
                               LimitStateFragility(1.2, 0.3))
    row = fragility_table([no_slide]).iloc[0]
    assert row["Incomplete"] == 1 and row["LS1-Family"] == "lognormal"
    assert pd.isna(row["LS1-Theta_0"]) and row["LS2-Theta_0"] == 1.2
    # from real fits: outcomes with no overturn give no LS2
    x = [0.2, 0.4, 0.8]
    sliding = fit_lognormal_fragility(x, [20, 20, 20], [2, 9, 17])
    overturn = fit_lognormal_fragility(x, [20, 20, 20], [0, 0, 0])
    item = ItemFragilities("bench_1", "Bench", LimitStateFragility.from_fit(sliding),
                           LimitStateFragility.from_fit(overturn))
    meta = fragility_metadata([item])
    assert set(meta["bench_1"]["LimitStates"]) == {"LS1"}
    assert "no failure in 60 simulations up to 0.8 g" in meta["bench_1"]["Comments"]
    assert fragility_table([item]).iloc[0]["LS1-Theta_0"] == pytest.approx(sliding.median_g,
                                                                           rel=1e-3)


def test_component_ids():
    assert pelicun_component_id(" Fume hood - FH-2 ") == "Fume_hood_FH_2"
    with pytest.raises(ValueError):
        fragility_table([ItemFragilities("bad-id", "x", ITEMS[0].beyond_clearance,
                                         ITEMS[0].overturn)])
    with pytest.raises(ValueError):
        fragility_table([ITEMS[0], ITEMS[0]])


# ----------------------------------------------------------- pelicun itself

PFA_VALUES_G = np.array([0.2, 0.35, 0.5, 0.8, 1.2])
REPEATS = 8000  # rows per PFA value; a probability's sampling sd is at most 0.0056


def _pelicun_damage_probabilities(csv_path, component_ids, tmp_path):
    """Run pelicun's damage model on the exported file: P(DS = k) per component and PFA value."""
    pelicun_assessment = pytest.importorskip(
        "pelicun.assessment", reason="pelicun is not installed (pip install -e '.[test,pelicun]' adds it)")
    n = PFA_VALUES_G.size * REPEATS
    pfa = np.tile(PFA_VALUES_G, REPEATS)  # interleaved, so any ordering of the sample mixes them
    demand_csv = tmp_path / "demand_sample.csv"
    with demand_csv.open("w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(["", "1-PFA-0-1", "1-PFA-0-2", "1-PFA-1-1", "1-PFA-1-2"])
        writer.writerow(["Units", "g", "g", "g", "g"])
        for i, value in enumerate(pfa):
            writer.writerow([i, value, value, value, value])
    asmnt = pelicun_assessment.Assessment({"PrintLog": False, "Seed": 12})
    asmnt.stories = 1
    asmnt.demand.load_sample(str(demand_csv))
    marginals = pd.DataFrame({"Units": "ea", "Location": "1", "Direction": "1", "Theta_0": 1.0,
                              "Blocks": 1}, index=list(component_ids))
    asmnt.asset.load_cmp_model({"marginals": marginals})
    asmnt.asset.generate_cmp_sample(n)
    cmp_set = set(asmnt.asset.list_unique_component_ids())
    asmnt.damage.load_model_parameters([str(csv_path)], cmp_set)
    asmnt.damage.calculate()
    # rows: realisations in the demand's order; columns (cmp, loc, dir, uid, ds): the quantity
    # in each damage state, here 1 in the state reached and 0 elsewhere (one block of 1 ea)
    sample = asmnt.damage.ds_model.sample
    result = {}
    for cmp in component_ids:
        per_state = sample.xs(cmp, axis=1, level="cmp").T.groupby(level="ds").sum().T
        result[cmp] = {k: np.array([per_state[str(k)].to_numpy()[pfa == a].mean()
                                    if str(k) in per_state else 0.0 for a in PFA_VALUES_G])
                       for k in (0, 1, 2)}
    return result, asmnt.damage.missing_components


def test_pelicun_computes_the_exported_lognormals(tmp_path):
    csv_path, _ = write_pelicun_fragility(tmp_path / "fragility", ITEMS)
    ids = [item.component_id for item in ITEMS]
    probs, missing = _pelicun_damage_probabilities(csv_path, ids, tmp_path)
    assert missing == []
    tol = 0.025  # > 4 sampling sd of 8000 draws
    for item in ITEMS:
        p = probs[item.component_id]
        p1 = _phi(PFA_VALUES_G, item.beyond_clearance.median_g, item.beyond_clearance.beta)
        if item.overturn.defined:
            p2 = _phi(PFA_VALUES_G, item.overturn.median_g, item.overturn.beta)
            np.testing.assert_allclose(p[2], p2, atol=tol, err_msg=item.component_id)
            np.testing.assert_allclose(p[1] + p[2], np.maximum(p1, p2), atol=tol,
                                       err_msg=item.component_id)
        else:
            assert np.all(p[2] == 0.0)
            np.testing.assert_allclose(p[1], p1, atol=tol, err_msg=item.component_id)
        np.testing.assert_allclose(p[0] + p[1] + p[2], 1.0, atol=1e-12)
        print(item.component_id, "pelicun P(DS>=1)", np.round(p[1] + p[2], 4), "lognormal",
              np.round(p1 if not item.overturn.defined else np.maximum(p1, p2), 4))


def test_pelicun_drops_an_incomplete_component(tmp_path):
    pytest.importorskip("pelicun.assessment", reason="pelicun is not installed")
    items = [ITEMS[0], ItemFragilities("safe_S1", "Safe", LimitStateFragility(NAN, NAN, "none"),
                                       LimitStateFragility(1.2, 0.3))]
    csv_path, _ = write_pelicun_fragility(tmp_path / "fragility", items)
    from pelicun.assessment import Assessment

    asmnt = Assessment({"PrintLog": False, "Seed": 1})
    asmnt.stories = 1
    marginals = pd.DataFrame({"Units": "ea", "Location": "1", "Direction": "1", "Theta_0": 1.0,
                              "Blocks": 1}, index=["freezer_F12", "safe_S1"])
    asmnt.asset.load_cmp_model({"marginals": marginals})
    asmnt.asset.generate_cmp_sample(10)
    asmnt.damage.load_model_parameters([str(csv_path)], {"freezer_F12", "safe_S1"},
                                       warn_missing=True)
    assert asmnt.damage.missing_components == ["safe_S1"]


def test_the_same_harness_on_the_real_library_row(tmp_path):
    """The P-58 unanchored-contents row E.20.22.001 (θ 1.0 g, β 0.4, non-directional) through
    the same pelicun run: P(DS1) = Φ(ln(1.2·a/θ)/β), 1.2 being pelicun's multiplier on the
    larger direction of a non-directional demand. Checks the harness and the module's claim."""
    probs, _ = _pelicun_damage_probabilities(REAL_CSV, ["E.20.22.001"], tmp_path)
    np.testing.assert_allclose(probs["E.20.22.001"][1], _phi(1.2 * PFA_VALUES_G, 1.0, 0.4),
                               atol=0.025)


def test_loads_beside_the_installed_library_as_the_docstring_says(tmp_path):
    pytest.importorskip("pelicun.assessment", reason="pelicun is not installed")
    from pelicun.assessment import Assessment

    csv_path, _ = write_pelicun_fragility(tmp_path / "fragility", ITEMS)
    asmnt = Assessment({"PrintLog": False, "Seed": 1})
    asmnt.stories = 1
    marginals = pd.DataFrame({"Units": "ea", "Location": "1", "Direction": "1", "Theta_0": 1.0,
                              "Blocks": 1}, index=["freezer_F12", "E.20.22.001"])
    asmnt.asset.load_cmp_model({"marginals": marginals})
    asmnt.asset.generate_cmp_sample(10)
    asmnt.damage.load_model_parameters(
        [str(csv_path), "PelicunDefault/FEMA P-58/fragility.csv"],
        set(asmnt.asset.list_unique_component_ids()))
    params = asmnt.damage.ds_model.damage_params
    assert asmnt.damage.missing_components == []
    assert set(params.index) == {"freezer_F12", "E.20.22.001"}
    assert params.loc["freezer_F12", ("LS2", "Theta_1")] == 0.4


# ----------------------------------------------------------- each item on its own floor

def test_items_stand_at_the_story_pelicun_counts():
    """pelicun's Location is the story, 1 = the ground story (pelicun/model/pelicun_model.py,
    _get_locations: 'roof' is stories + 1), and a PFA component at story s reads PFA-(s - 1) (its default
    DemandOffset PFA -1): an item on assess floor f (0 = ground) is at story f + 1."""
    items = [replace(ITEMS[0], floor=0), replace(ITEMS[1], floor=2, quantity=3),
             replace(ITEMS[2], floor=-1)]
    table = component_table(items).set_index("ID")
    assert table["Location"].tolist() == [1, 3, 1]
    assert table.loc["cabinet_C3", ["Theta_0", "Blocks"]].tolist() == [3, 3]
    assert table.loc["freezer_F12", "Comment"] == "assess floor 0: pelicun story 1 (reads PFA-0)"
    assert "below ground" in table.loc["incubator_7", "Comment"]
    meta = fragility_metadata(items)
    assert "assess floor 2, pelicun story 3: PFA-2" in meta["cabinet_C3"]["Comments"]


PFA_BY_LEVEL_G = np.array([0.30, 0.45, 0.60, 0.75, 0.90, 1.05])  # levels 0 (ground) to 5: all different


def _own_floor_vs_pelicun(folder, tmp_path, repeats=3000):
    from peers.pelicun_dl import demand_levels, exported_probabilities, run_pelicun

    rows = demand_levels(PFA_BY_LEVEL_G)
    got = run_pelicun(folder, rows, repeats=repeats, work=tmp_path)
    own = exported_probabilities(folder, rows)
    below = exported_probabilities(folder, rows, floor_offset=-1)
    return got, own, below


def test_pelicun_reads_each_item_on_its_own_floor(tmp_path):
    """The exported asset model and fragilities, through pelicun's damage model with a different PFA at
    every level: each item's damage probability is its lognormal at the PFA of its own floor (and not at
    the floor below's, which the test could tell apart)."""
    pytest.importorskip("pelicun.assessment", reason="pelicun is not installed (pip install -e '.[test,pelicun]' "
                        "adds it)")
    items = [replace(ITEMS[0], floor=0), replace(ITEMS[1], floor=2), replace(ITEMS[2], floor=5)]
    folder = tmp_path / "fragility"
    write_pelicun_fragility(folder, items)
    got, own, below = _own_floor_vs_pelicun(folder, tmp_path)
    assert got.attrs["missing"] == []
    table = got.merge(own, on=["id", "row"], suffixes=("", "_own"))
    assert dict(zip(table["id"], table["location"])) == {"freezer_F12": 1, "cabinet_C3": 3, "incubator_7": 6}
    assert dict(zip(table["id"], table["floor_read"])) == {"freezer_F12": 0, "cabinet_C3": 2, "incubator_7": 5}
    tol = 0.03  # > 4 sampling sd of 3000 draws
    np.testing.assert_allclose(table["p_ds1_or_more"], table["p_ds1_or_more_own"], atol=tol)
    np.testing.assert_allclose(table["p_ds2"], table["p_ds2_own"], atol=tol)
    # the floor below would give other numbers: the comparison can tell the floors apart
    other = table.merge(below, on=["id", "row"], suffixes=("", "_below")).dropna(subset=["pfa_g_below"])
    assert (other["p_ds1_or_more_own"] - other["p_ds1_or_more_below"]).abs().max() > 5 * tol


def test_the_floor_as_assess_numbers_it_is_not_pelicuns_story(tmp_path):
    """What the earlier instructions gave (Location = the assess floor): pelicun refuses a ground-floor
    item (it would need PFA-(-1))."""
    pelicun_assessment = pytest.importorskip("pelicun.assessment", reason="pelicun is not installed")
    folder = tmp_path / "fragility"
    write_pelicun_fragility(folder, [replace(ITEMS[0], floor=0)])
    marginals = pd.read_csv(folder / "cmp_marginals.csv", index_col=0)
    marginals["Location"] = 0  # the assess floor
    asmnt = pelicun_assessment.Assessment({"PrintLog": False, "Seed": 1})
    asmnt.stories = 1
    demand_csv = tmp_path / "demand.csv"
    demand_csv.write_text(",1-PFA-0-1,1-PFA-1-1\nUnits,g,g\n0,0.3,0.4\n1,0.3,0.4\n", encoding="utf-8")
    asmnt.demand.load_sample(str(demand_csv))
    asmnt.asset.load_cmp_model({"marginals": marginals.drop(columns="Comment")})
    asmnt.asset.generate_cmp_sample(2)
    asmnt.damage.load_model_parameters([str(folder / "fragility.csv")], {"freezer_F12"})
    with pytest.raises(ValueError, match="Negative location"):
        asmnt.damage.calculate()


def test_a_pga_fragility_reads_the_ground_from_any_story(tmp_path):
    """Stripes of ground acceleration through the building: the fragility is in PGA at location 0; the
    row's Demand-Offset takes the item's story back to it."""
    pelicun_assessment = pytest.importorskip("pelicun.assessment", reason="pelicun is not installed")
    item = replace(ITEMS[2], floor=3)  # LS1 only: theta 0.5 g, beta 0.45
    folder = tmp_path / "fragility"
    write_pelicun_fragility(folder, [item], demand="PGA")
    table = pd.read_csv(folder / "fragility.csv")
    assert table.loc[0, "Demand-Offset"] == -4 and table.loc[0, "Demand-Type"] == "Peak Ground Acceleration"
    pga = np.tile([0.25, 0.5, 1.0], 3000)
    demand_csv = tmp_path / "demand.csv"
    with demand_csv.open("w", encoding="utf-8") as handle:
        handle.write(",1-PGA-0-1,1-PGA-0-2," + ",".join(f"1-PFA-{k}-{d}" for k in range(5) for d in (1, 2))
                     + "\nUnits," + ",".join(["g"] * 12) + "\n")
        for i, a in enumerate(pga):
            handle.write(f"{i},{a},{a}," + ",".join(["9.9"] * 10) + "\n")  # PFA: would fail every item
    asmnt = pelicun_assessment.Assessment({"PrintLog": False, "Seed": 2})
    asmnt.stories = 4
    asmnt.demand.load_sample(str(demand_csv))
    asmnt.asset.load_cmp_model({"marginals": str(folder / "cmp_marginals.csv")})
    asmnt.asset.generate_cmp_sample(pga.size)
    asmnt.damage.load_model_parameters([str(folder / "fragility.csv")], {"incubator_7"})
    asmnt.damage.calculate()
    states = asmnt.damage.ds_model.sample.xs("incubator_7", axis=1, level="cmp").T.groupby(level="ds").sum().T
    damaged = states.drop(columns="0", errors="ignore").sum(axis=1).to_numpy()
    observed = np.array([damaged[pga == a].mean() for a in (0.25, 0.5, 1.0)])
    np.testing.assert_allclose(observed, _phi(np.array([0.25, 0.5, 1.0]), 0.5, 0.45), atol=0.03)


G = 9.80665


def _rect_record(duration_s, amplitude_g=0.5, total_s=3.0, dt_s=0.001) -> str:
    time_s = np.arange(0.0, total_s, dt_s)
    accel = np.where(time_s < duration_s - 1e-12, amplitude_g, 0.0)
    return "time_s,accel_g\n" + "\n".join(f"{t:.4f},{a:.6f}" for t, a in zip(time_s, accel)) + "\n"


@pytest.fixture(scope="module")
def floors_run(tmp_path_factory):
    """Squat blocks on floors 0, 2 and 5 (b/h = 1: they slide, never uplift), each floor under three
    rectangular pulses of different lengths (thresholds apart: a lognormal is fitted), with the lab curve."""
    pytest.importorskip("pelicun.assessment", reason="pelicun is not installed (pip install -e '.[test,pelicun]' "
                        "adds it)")
    from assess.assessment.pipeline import run_assessment
    from assess.hazard.openquake import read_openquake_hazard
    from assess.inventory import read_workbook
    from workbooks import write_workbook

    tmp_path = tmp_path_factory.mktemp("floors")
    squat = dict(height_cm=100, width_cm=100, depth_cm=100, mass_kg=200)
    equipment = [{"id": f"S-{floor}", "name": f"block on floor {floor}", "floor": floor, "mu": mu,
                  "clearance_cm": clearance, **squat}
                 for floor, mu, clearance in ((0, 0.15, 10), (2, 0.25, 15), (5, 0.35, 20))]
    motions, files = [], {}
    for floor in (0, 2, 5):
        for name, duration_s in (("short", 0.25), ("mid", 0.5), ("long", 1.0)):
            path = f"records/{name}.csv"
            files[path] = _rect_record(duration_s)
            motions.append({"level": "2in50", "motion": name, "floor": floor, "record": path})
    workbook = write_workbook(tmp_path / "w.xlsx", {"equipment": equipment, "hazard": motions}, files=files)
    curve = Path(__file__).resolve().parents[2] / "inventories" / "lab-hazard-curve.csv"
    return run_assessment(read_workbook(workbook), "2in50", hazard_curve=read_openquake_hazard(curve))


def test_an_assessment_export_read_by_pelicun_reads_each_item_on_its_own_floor(floors_run, tmp_path):
    """End to end: an assessment's fragility/ folder as written, in pelicun with a PFA per level."""
    from assess.fragility.stripes import fragility_files

    for name, content in fragility_files(floors_run.curve_risk, floors_run.summary).items():
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_bytes(content)
    folder = tmp_path / "fragility"
    fragility = pd.read_csv(folder / "fragility.csv", index_col=0)
    assert (fragility["Incomplete"] == 0).all(), fragility  # every item fitted: pelicun drops none
    got, own, below = _own_floor_vs_pelicun(folder, tmp_path)
    table = got.merge(own, on=["id", "row"], suffixes=("", "_own"))
    assert dict(zip(table["id"], table["floor_read"])) == {"S_0": 0, "S_2": 2, "S_5": 5}
    for item_id, floor in (("S_0", 0), ("S_2", 2), ("S_5", 5)):  # the fit's own numbers, at its floor's PFA
        fit = floors_run.curve_risk.fits[(item_id.replace("_", "-"), "beyond_clearance")]
        rows = table[table["id"] == item_id].sort_values("row")
        expected = _phi(rows["pfa_g"].to_numpy(), fit.median_g, fit.beta)
        np.testing.assert_allclose(rows["p_ds1_or_more"], expected, atol=0.03, err_msg=item_id)
        np.testing.assert_allclose(rows["pfa_g"], PFA_BY_LEVEL_G[floor] * np.array([0.6, 1.0, 1.5]))
    other = table.merge(below, on=["id", "row"], suffixes=("", "_below")).dropna(subset=["pfa_g_below"])
    assert (other["p_ds1_or_more_own"] - other["p_ds1_or_more_below"]).abs().max() > 0.15


def test_an_incomplete_note_is_true_to_the_stripes():
    """The lab's ULT-1-01 (stripes.csv of `assess inventories/lab.xlsx --oq-hazard ...`): none of 10 failed up
    to 0.525 g, 3 of 10 at 0.582 g, all from 0.644 g. No finite fit (quasi-separation), so the row is
    Incomplete; its note must give those counts, not "every one from 0.582 g failed"."""
    from assess.fragility.stripes import fit_items

    levels = [0.0551, 0.083, 0.125, 0.188, 0.284, 0.428, 0.474, 0.525, 0.582, 0.644, 0.971, 1.46, 2.2]
    failures = [0, 0, 0, 0, 0, 0, 0, 0, 3, 10, 10, 10, 10]
    outcomes = pd.DataFrame([{"id": "ULT-1-01", "pfa_g": x, "history": h, "beyond_clearance": h < k,
                              "overturn": False} for x, k in zip(levels, failures) for h in range(10)])
    fits, stripes = fit_items(outcomes)
    fit = fits[("ULT-1-01", "beyond_clearance")]
    item = ItemFragilities("ULT_1_01", "freezer", LimitStateFragility.from_fit(fit),
                           LimitStateFragility.from_fit(fits[("ULT-1-01", "overturn")]), floor=1)
    assert fragility_table([item]).loc[0, "Incomplete"] == 1
    comments = fragility_metadata([item])["ULT_1_01"]["Comments"]
    assert "3 of 10 failed at 0.582 g" in comments
    assert "every one from 0.582 g failed" not in comments
    # every count the note states, read back from the stripes table
    table = stripes[stripes["mode"] == "beyond_clearance"].set_index("pfa_g")
    low_g, high_g = fit.separation_g
    assert f"Every simulation up to {low_g:.3g} g survived" in comments
    assert f"every one from {high_g:.3g} g failed" in comments
    assert (table.loc[table.index <= low_g, "failures"] == 0).all()
    assert (table.loc[table.index >= high_g, "failures"] == table.loc[table.index >= high_g, "trials"]).all()
