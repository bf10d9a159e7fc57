"""Calibration (docs/calibration.md): recover an undeclared effect from synthetic measurements, and read MEASURED.xlsx.

The generator plays the engine with ONE effect switched on that the workbook
does not declare, and measures like a shake table would: peak sliding with
lognormal noise (σ = 0.1, seeded), θmax/α with N(0, 0.02) noise (lost when the
item overturns), overturning exactly. Four items (two incubator/fridge-like
blocks that slide, two slender cabinets that rock and some overturn) under
eight Type-B pulses: 32 tests.
"""
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import openpyxl
import pandas as pd
import pytest

from assess.calibration import EFFECTS, build_cases, read_measured, run_calibration
from assess.calibration.effects import available_effects
from assess.calibration.fit import predict_cases, select_effect
from assess.calibration.measured import test_motion
from assess.inventory.settings import Settings
from assess.errors import InputError
from assess.inventory import Inventory

SEEDS = (1, 2)


def item(item_id, height_m, width_m, mu, depth_m=0.8, anchored=False, row=2):
    return {"id": item_id, "name": item_id, "room": "lab", "floor": 0, "height_m": height_m,
            "width_m": width_m, "depth_m": depth_m, "mass_kg": 200.0, "mu": mu, "mu_static": mu,
            "clearance_m": 0.3, "cg_height_m": height_m / 2, "anchored": anchored, "quantity": 1, "row": row}


ITEMS = [item("INCUBATOR", 2.286, 0.622, 0.20), item("FRIDGE", 2.134, 0.66, 0.17, row=3),
         item("CABINET", 2.0, 0.40, 0.5, row=4), item("SHELF", 1.8, 0.5, 0.6, row=5),
         item("BOLTED", 1.8, 0.5, 0.6, anchored=True, row=6)]
PULSES = [(0.25, 1.0), (0.35, 0.5), (0.45, 1.5), (0.5, 0.8), (0.6, 0.4), (0.7, 1.2), (0.8, 0.6), (0.4, 2.0)]


def pulse_name(pta_g, tp_s):
    return f"B {pta_g}g {tp_s}s"


def make_inventory():
    motions = [{"level": "test", "level_label": "test", "motion": pulse_name(a, t), "all_floors": True,
                "floor": None, "pta_g": a, "tp_s": t, "vp_m_s": np.nan, "pulse": "B" if k % 2 else "",
                "record_path": "", "scale": 1.0, "row": k + 2} for k, (a, t) in enumerate(PULSES)]
    hazard = pd.DataFrame(motions)
    hazard["floor"] = hazard["floor"].astype("Int64")
    return Inventory(path=Path("WORKBOOK.xlsx"), equipment=pd.DataFrame(ITEMS), hazard=hazard,
                     settings=Settings())


@pytest.fixture(scope="module")
def lab():
    inventory = make_inventory()
    tests = pd.DataFrame([dict(specimen=i["id"], motion=pulse_name(*p), direction=1, sliding_m=np.nan,
                               theta_max_over_alpha=np.nan, overturned=None, row=0)
                          for i in ITEMS[:4] for p in PULSES])
    cache = {}  # predictions depend on the tests, not on the measured values: shared by every test here
    return SimpleNamespace(inventory=inventory, tests=tests, cases=build_cases(inventory, tests), cache=cache)


def measured_with(lab, effect, parameters, seed, sliding_sigma=0.1, theta_sigma=0.02):
    """What the table would measure if the item behaved as the engine with ``effect`` on."""
    truth = predict_cases(EFFECTS[effect], lab.cases, parameters, lab.cache)
    rng = np.random.default_rng(seed)
    measured = lab.tests.copy()
    measured["sliding_m"] = truth.sliding_m * np.exp(sliding_sigma * rng.standard_normal(len(measured)))
    theta = np.maximum(truth.theta_max_over_alpha + theta_sigma * rng.standard_normal(len(measured)), 0.0)
    measured["theta_max_over_alpha"] = np.where(truth.overturned, np.nan, theta)
    measured["overturned"] = [bool(v) for v in truth.overturned]
    return measured


# (effect, true parameters, relative tolerance on the recovered parameters or None when not identifiable)
CASES = [
    ("friction_scale", {"k": 0.65}, 0.05),  # the paper's best-fit / slow-pull ratio, Table 3
    ("friction_scale", {"k": 1.3}, 0.05),
    ("static_friction", {"r": 1.3}, 0.05),
    ("static_friction", {"r": 2.0}, 0.05),
    ("restitution", {"e": 0.5}, 0.05),
    ("restitution", {"e": 0.75}, 0.05),
    ("input_scale", {"s": 0.7}, 0.05),
    ("input_scale", {"s": 1.4}, 0.05),
    ("foot_inset", {"d": 0.2}, 0.05),
    ("foot_inset", {"d": 0.4}, 0.05),
    ("velocity_friction", {"f": 0.5, "rate_s_m": 10.0}, None),  # f and rate trade off on peaks alone
    ("interface_elasticity", {"yield_displacement_m": 0.005}, 0.1),
    ("interface_elasticity", {"yield_displacement_m": 0.02}, 0.1),
]


@pytest.mark.parametrize("effect, parameters, tolerance", CASES,
                         ids=[f"{e}-{'-'.join(f'{v:g}' for v in p.values())}" for e, p, _ in CASES])
def test_recovers_the_undeclared_effect(lab, effect, parameters, tolerance):
    if EFFECTS[effect].requires:
        pytest.importorskip(EFFECTS[effect].requires)
    for seed in SEEDS:
        result = run_calibration(lab.inventory, measured_with(lab, effect, parameters, seed), cache=lab.cache)
        scores = {f.effect.name: round(f.score, 4) for f in result.fits}
        context = f"seed {seed}: selected {result.selected} {result.parameters}, scores {scores}"
        assert result.selected == effect or effect in result.indistinguishable_from, context
        assert result.error_after["objective"] < 0.5 * result.error_before["objective"], context
        if result.selected == effect and tolerance is not None:
            for name, value in parameters.items():
                assert result.parameters[name] == pytest.approx(value, rel=tolerance), context
        assert result.error_after["overturn_misclassified"] <= result.error_before["overturn_misclassified"]


def test_noise_only_selects_none(lab):
    for seed in (0, 1, 2):
        result = run_calibration(lab.inventory, measured_with(lab, "none", {}, seed), cache=lab.cache)
        assert result.selected == "none", {f.effect.name: f.score for f in result.fits}
        assert result.parameters == {} and result.error_after == result.error_before
        # effects that can do no worse than the declared model are said to be indistinguishable from it
        assert "none" not in result.indistinguishable_from


def test_json_structure_and_tables(lab):
    result = run_calibration(lab.inventory, measured_with(lab, "friction_scale", {"k": 0.65}, 3),
                             effects=["friction_scale", "input_scale"], cache=lab.cache)
    out = result.as_json()
    assert list(out) == ["error_before", "error_after", "residual_correlation_before", "selected",
                         "indistinguishable_from", "applies_to", "candidates"]
    assert out["applies_to"] == ["CABINET", "FRIDGE", "INCUBATOR", "SHELF"]
    assert set(out["residual_correlation_before"]) == {"im", "omega_p_over_p", "pgv_m_s", "mu", "b_over_h",
                                                       "pressure_kpa"}
    assert set(out["selected"]) == {"effect", "parameters", "standard_error", "not_determined"}
    assert out["selected"]["effect"] == "friction_scale"
    # the jackknife standard error of k is small against k's offset from 1 (the declared model)
    assert 0.0 <= out["selected"]["standard_error"]["k"] < 0.1 * abs(out["selected"]["parameters"]["k"] - 1.0)
    assert [c["effect"] for c in out["candidates"]] == ["none", "friction_scale", "input_scale"]
    for candidate in out["candidates"]:
        assert set(candidate) == {"effect", "parameters", "standard_error", "not_determined", "error", "score"}
        assert {"sliding_rms_log", "overturn_misclassified", "theta_rms"} <= set(candidate["error"])
    import json
    json.dumps(out)  # plain JSON types throughout
    assert len(result.residuals_before) == len(result.residuals_after) == len(lab.tests)
    assert result.residuals_after["loss"].sum() < result.residuals_before["loss"].sum()
    diagnosis = result.diagnosis.set_index(["specimen", "motion"])
    row = diagnosis.loc[("INCUBATOR", pulse_name(0.45, 1.5))]
    assert row["im"] == pytest.approx(0.45 / 0.20 - 1.0)
    assert row["b_over_h"] == pytest.approx(0.311 / 1.143) and row["mode"] == "slide"
    assert diagnosis.loc[("CABINET", pulse_name(0.25, 1.0)), "mode"] == "rock"


def test_selection_rule():
    def fit(name, score, size=1):
        return SimpleNamespace(effect=SimpleNamespace(name=name, parameters=(None,) * size), score=score)
    # beats none by more than 10 %: selected; another within 10 % of it: indistinguishable
    assert select_effect([fit("none", 1.0, 0), fit("a", 0.5), fit("b", 0.53), fit("c", 0.9)]) == ("a", ["b"])
    # within 10 % of the best, the effect with fewer parameters wins
    assert select_effect([fit("none", 1.0, 0), fit("two", 0.50, 2), fit("one", 0.52, 1)]) == ("one", ["two"])
    # 5 % better than none does not earn a parameter
    assert select_effect([fit("none", 1.0, 0), fit("a", 0.95), fit("b", 1.5)]) == ("none", ["a"])


def test_missing_interface_module_skips_its_effects(monkeypatch):
    import importlib
    real = importlib.import_module

    def without_interface(name, *args):
        if name == "assess.mechanics.interface":
            raise ImportError(name)
        return real(name, *args)
    monkeypatch.setattr(importlib, "import_module", without_interface)
    names = [e.name for e in available_effects()]
    assert "velocity_friction" not in names and "interface_elasticity" not in names
    assert names[0] == "none" and "friction_scale" in names


def test_motion_of_a_test_is_its_pulse():
    inventory = make_inventory()
    default = test_motion(inventory, pulse_name(*PULSES[0]))  # no pulse type given: Type-B
    assert default.pta_g == pytest.approx(0.25) and "Type-B" in default.name
    given = test_motion(inventory, pulse_name(*PULSES[1]))
    assert given.pta_g == pytest.approx(0.35)


def write_tests(path, rows, sheet="tests"):
    book = openpyxl.Workbook()
    book.active.title = sheet
    for row in rows:
        book.active.append(row)
    book.save(path)
    return path


def test_read_measured_good(tmp_path):
    inventory = make_inventory()
    path = write_tests(tmp_path / "MEASURED.xlsx", [
        ["Specimen", "motion", "sliding_cm", "theta_max_over_alpha", "overturned", "direction"],
        ["INCUBATOR", pulse_name(0.45, 1.5), 21.5, None, "no", None],
        ["CABINET", pulse_name(0.25, 1.0), 0, 0.33, "No", 2],
        [None, None, None, None, None, None],
        ["SHELF", pulse_name(0.5, 0.8), None, None, "yes", 1]])
    table = read_measured(path, inventory)
    assert table["sliding_m"].tolist()[0] == pytest.approx(0.215) and np.isnan(table["sliding_m"][2])
    assert table["overturned"].tolist() == [False, False, True]
    assert table["direction"].tolist() == [1, 2, 1] and table["row"].tolist() == [2, 3, 5]


def test_read_measured_reports_every_problem(tmp_path):
    inventory = make_inventory()
    path = write_tests(tmp_path / "MEASURED.xlsx", [
        ["specimen", "motion", "sliding_cm", "overturned", "direction"],
        ["INCUBATR", pulse_name(0.45, 1.5), 3.0, "no", 1],
        ["FRIDGE", "Northridge", -2, "maybe", 3],
        ["BOLTED", pulse_name(0.45, 1.5), 1.0, None, None],
        ["FRIDGE", pulse_name(0.45, 1.5), None, None, None]])
    with pytest.raises(InputError) as caught:
        read_measured(path, inventory)
    problems = caught.value.problems
    text = str(caught.value)
    assert all(p.file == "MEASURED.xlsx" and p.sheet == "tests" and p.fix for p in problems)
    located = {(p.row, p.column) for p in problems}
    assert {(2, "specimen"), (3, "motion"), (3, "sliding_cm"), (3, "overturned"), (3, "direction"),
            (4, "specimen"), (5, None)} <= located
    assert "did you mean 'INCUBATOR'" in text and "cell A2" in text and "anchored" in text


@pytest.mark.parametrize("rows, sheet, phrase", [
    ([], "tests", "the sheet is empty"),
    ([["specimen", "motion", "sliding_cm"]], "tests", "no test"),
    ([["specimen", "sliding_cm"]], "tests", "'motion' is missing"),
    ([["specimen", "motion", "notes"]], "tests", "no measure column"),
    ([["specimen", "motion", "sliding_cm"]], "Sheet1", "no sheet 'tests'"),
])
def test_read_measured_sheet_problems(tmp_path, rows, sheet, phrase):
    path = write_tests(tmp_path / "MEASURED.xlsx", rows, sheet=sheet)
    with pytest.raises(InputError, match=phrase):
        read_measured(path, make_inventory())


def test_read_measured_missing_file(tmp_path):
    with pytest.raises(InputError, match="does not exist"):
        read_measured(tmp_path / "MEASURED.xlsx", make_inventory())


def test_residual_correlation_points_to_the_quantity_the_residual_follows():
    """Residuals made to grow with bearing pressure (as pressure-dependent friction would) are
    reported as correlated with pressure and not with b/h (independent here)."""
    from assess.calibration import residual_correlations

    rng = np.random.default_rng(3)
    pressure = rng.uniform(2.0, 12.0, 20)
    diagnosis = pd.DataFrame({"im": rng.uniform(1, 5, 20), "omega_p_over_p": rng.uniform(0.5, 4, 20),
                              "pgv_m_s": rng.uniform(0.2, 1, 20), "mu": rng.uniform(0.1, 0.3, 20),
                              "b_over_h": rng.uniform(0.2, 0.5, 20), "pressure_kpa": pressure})
    residuals = pd.DataFrame({"sliding_log_ratio": 0.1 * pressure + rng.normal(0, 0.05, 20)})
    rho = residual_correlations(residuals, diagnosis)
    assert rho["pressure_kpa"] > 0.9
    assert abs(rho["b_over_h"]) < 0.6


def test_a_parameter_the_tests_cannot_fix_is_not_determined(lab):
    """Only specimens that slide (μ < b/h: they cannot uplift): the restitution of rocking impacts
    changes no prediction, so it is 'not determined by these tests', null in calibration.json with a
    reason, and a sentence in the report, never 'e = 0 ± 0.00144'."""
    import json

    from assess.report.calibration import calibration_context

    sliding_only = lab.tests["specimen"].isin(["INCUBATOR", "FRIDGE"]).to_numpy()
    measured = measured_with(lab, "friction_scale", {"k": 0.8}, 4)[sliding_only].reset_index(drop=True)
    result = run_calibration(lab.inventory, measured, effects=["friction_scale", "restitution"], cache=lab.cache)
    out = json.loads(json.dumps(result.as_json()))
    restitution = next(c for c in out["candidates"] if c["effect"] == "restitution")
    assert restitution["parameters"] == {"e": None} and restitution["standard_error"] == {"e": None}
    assert "rocking impacts" in restitution["not_determined"]["e"]
    friction = next(c for c in out["candidates"] if c["effect"] == "friction_scale")
    assert friction["not_determined"] == {} and friction["parameters"]["k"] == pytest.approx(0.8, rel=0.05)
    assert out["selected"]["effect"] == "friction_scale" and out["selected"]["not_determined"] == {}
    context = calibration_context(result, "WORKBOOK.xlsx", "MEASURED.xlsx")
    rows = {c["effect"]: c["parameters"] for c in context["candidates"]}
    assert rows["restitution"].startswith("restitution e at a rocking impact: not determined by these tests (")
    assert "±" not in rows["restitution"]
    assert rows["friction_scale"].startswith("factor k on μ and μ_s = 0.")
    # the error rows are sentences, not keys
    names = [e["name"] for e in context["errors"]]
    assert "RMS of ln(predicted/measured) peak sliding" in names
    assert not any("_" in name for name in names), names
