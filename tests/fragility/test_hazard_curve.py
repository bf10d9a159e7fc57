"""Risk over the whole hazard curve: fragilities over stripes from the engine, integrated over an
OpenQuake curve (assess.fragility.stripes), end to end through the pipeline and the command.

Expected values come from outside the code under test: the closed-form sliding of a rigid block
under a rectangular pulse, a numerical quadrature of the fragility over the curve, the curve's
own numbers, and pelicun reading the exported files.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from scipy import integrate, stats

from assessed import run_assessment
from assess.hazard.openquake import read_openquake_hazard
from assess.hazard.risk_integral import annual_rates_of_curve
from assess.inventory import read_workbook
from assess.mechanics.runner import LocalRunner

import commands
from declared import check_file
from workbooks import write_workbook

REPO = Path(__file__).resolve().parents[2]
CURVE = REPO / "inventories" / "lab-hazard-curve.csv"
G = 9.80665
PULSE_S = 0.5
DT_S = 0.001


def _rect_record(duration_s=PULSE_S, amplitude_g=0.5, total_s=4.0) -> str:
    time_s = np.arange(0.0, total_s, DT_S)
    accel = np.where(time_s < duration_s - 1e-12, amplitude_g, 0.0)
    return "time_s,accel_g\n" + "\n".join(f"{t:.4f},{a:.6f}" for t, a in zip(time_s, accel)) + "\n"


def rect_threshold_g(mu, clearance_m, duration_s=PULSE_S):
    """Peak floor acceleration A [g] at which a rigid block on Coulomb friction μ slides exactly
    ``clearance_m`` under a rectangular pulse A for ``duration_s`` (floor at rest after).

    During the pulse the block lags with relative acceleration (A − μ)g: u = (A − μ)g T²/2,
    v = (A − μ)g T; after it, friction stops it within v²/(2μg). The peak sliding
    (A − μ)A g T²/(2μ) = c is a quadratic in A.
    """
    k = clearance_m * 2.0 * mu / (G * duration_s**2)  # (A − μ) A = k
    return 0.5 * (mu + math.sqrt(mu * mu + 4.0 * k))


def _workbook(tmp_path, equipment, motions, files):
    return write_workbook(tmp_path / "w.xlsx", {
        "equipment": equipment,
        "hazard": motions,
        "settings": [{"key": "synthetic_realizations", "value": 3}],
    }, files=files)


SQUAT = dict(height_cm=100, width_cm=100, depth_cm=100, mass_kg=100)  # b/h = 1: it cannot uplift


@pytest.fixture(scope="module")
def rect_run(tmp_path_factory):
    """Two sliding blocks and one anchored, under one rectangular-pulse record, with the lab curve."""
    tmp_path = tmp_path_factory.mktemp("rect")
    path = _workbook(tmp_path, [
        {"id": "S1", "name": "low friction", "floor": 0, "mu": 0.15, "clearance_cm": 10, **SQUAT},
        {"id": "S2", "name": "more friction", "floor": 0, "mu": 0.30, "clearance_cm": 25, **SQUAT},
        {"id": "A1", "name": "anchored", "floor": 0, "mu": 0.30, "clearance_cm": 5, "anchored": "yes", **SQUAT},
    ], [{"level": "2in50", "motion": "rect", "floor": 0, "record": "records/rect.csv"}],
        {"records/rect.csv": _rect_record()})
    hazard = read_openquake_hazard(CURVE)
    runner = LocalRunner()
    result = run_assessment(read_workbook(path), "2in50", hazard_curve=hazard, runner=runner)
    return result, hazard, runner


def _curve_rate(hazard, pga_g):
    """The curve's annual rate of exceeding ``pga_g``, log-log between its levels (its own numbers)."""
    rates = annual_rates_of_curve(hazard.poes[0], hazard.investigation_time_yr)
    return float(np.exp(np.interp(np.log(pga_g), np.log(hazard.levels_g), np.log(rates))))


def test_the_step_of_a_rectangular_pulse_lies_where_the_closed_form_puts_it(rect_run):
    result, hazard, _ = rect_run
    curve = result.curve_risk
    for item_id, mu, clearance_m in (("S1", 0.15, 0.10), ("S2", 0.30, 0.25)):
        threshold_g = rect_threshold_g(mu, clearance_m)
        fit = curve.fits[(item_id, "beyond_clearance")]
        # one history: the outcomes are a step, bracketed by the stripes on either side of it
        assert fit.status == "separated", fit.message
        survived_g, failed_g = fit.separation_g
        assert survived_g < threshold_g <= failed_g, (item_id, survived_g, threshold_g, failed_g)
        row = result.summary.set_index("id").loc[item_id]
        # the rate of a step at the threshold is the curve's rate there: inside the reported interval
        exact = _curve_rate(hazard, threshold_g)
        assert row["annual_rate_beyond_clearance_low"] <= exact <= row["annual_rate_beyond_clearance_high"]
        assert row["p50yr_beyond_clearance"] == pytest.approx(-math.expm1(-50 * row["annual_rate_beyond_clearance"]))
        assert math.isnan(row["annual_rate_overturn"])  # it cannot uplift: never overturns
        assert row["annual_rate_overturn_high"] > 0.0


def test_anchored_items_have_no_fragility_and_the_export_says_why(rect_run, tmp_path):
    result, _, _ = rect_run
    row = result.summary.set_index("id").loc["A1"]
    assert math.isnan(row["annual_rate_beyond_clearance"]) and math.isnan(row["annual_rate_overturn"])
    from assess.fragility.stripes import fragility_files
    files = fragility_files(result.curve_risk, result.summary)
    table = pd.read_csv(pd.io.common.BytesIO(files["fragility/fragility.csv"]))
    assert list(table["ID"]) == ["S1", "S2"]  # the anchored item is no freestanding component
    assert (table["Incomplete"] == 1).all()  # a step has no lognormal: no numbers invented
    stripes = pd.read_csv(pd.io.common.BytesIO(files["fragility/stripes.csv"]))
    assert set(stripes["mode"]) == {"beyond_clearance", "overturn"}
    csv_files = [name for name in files if name.endswith(".csv")]
    assert len(csv_files) == 3  # stripes, fragility, cmp_marginals: each declared, in order, of its dtype
    for name in csv_files:
        check_file(files[name], name)
    assert "pfa_g" in stripes.columns  # stripes of floor acceleration


@pytest.fixture(scope="module")
def two_pulse_run(tmp_path_factory):
    """Two rectangular pulses of different lengths: the thresholds differ, the outcomes overlap, a
    lognormal fragility is fitted."""
    tmp_path = tmp_path_factory.mktemp("two")
    path = _workbook(tmp_path, [
        {"id": "S1", "name": "low friction", "floor": 0, "mu": 0.15, "clearance_cm": 10, **SQUAT},
    ], [{"level": "2in50", "motion": "short", "floor": 0, "record": "records/short.csv"},
        {"level": "2in50", "motion": "long", "floor": 0, "record": "records/long.csv"},
        {"level": "2in50", "motion": "mid", "floor": 0, "record": "records/mid.csv"}],
        {"records/short.csv": _rect_record(0.25), "records/long.csv": _rect_record(1.0),
         "records/mid.csv": _rect_record(0.5)})
    hazard = read_openquake_hazard(CURVE)
    return run_assessment(read_workbook(path), "2in50", hazard_curve=hazard), hazard


def test_the_fitted_rate_equals_a_quadrature_of_the_fragility_over_the_curve(two_pulse_run):
    result, hazard = two_pulse_run
    fit = result.curve_risk.fits[("S1", "beyond_clearance")]
    assert fit.status == "fitted", fit.message
    # each pulse's failures begin at its own closed-form threshold: P rises in three steps of 1/3
    thresholds = sorted(rect_threshold_g(0.15, 0.10, d) for d in (0.25, 0.5, 1.0))
    assert thresholds[0] < fit.median_g < thresholds[-1]
    # λ = ∫ P(fail | a) |dλ(a)|, by quadrature in ln a over the curve interpolated log-log
    # (power law beyond its ends), independent of the closed-form segments of the code
    levels = np.log(hazard.levels_g)
    log_rates = np.log(annual_rates_of_curve(hazard.poes[0], hazard.investigation_time_yr))
    slope = np.diff(log_rates) / np.diff(levels)

    def minus_dlambda_dlna(y):
        k = np.clip(np.searchsorted(levels, y) - 1, 0, levels.size - 2)
        rate = np.exp(log_rates[k] + slope[k] * (y - levels[k]))
        return -slope[k] * rate

    def integrand(y):
        return stats.norm.cdf((y - math.log(fit.median_g)) / fit.beta) * minus_dlambda_dlna(y)

    lo, hi = math.log(fit.median_g) - 8 * fit.beta, math.log(fit.median_g) + 8 * fit.beta
    quadrature, _ = integrate.quad(integrand, lo, hi, points=list(levels[(levels > lo) & (levels < hi)]),
                                   limit=200)
    below = math.exp(np.interp(lo, levels, log_rates)) * stats.norm.cdf(-8)  # all of λ below lo, times P(lo)
    rate = result.summary.set_index("id").loc["S1", "annual_rate_beyond_clearance"]
    assert rate == pytest.approx(quadrature + below, rel=0.01)
    row = result.summary.set_index("id").loc["S1"]
    assert row["annual_rate_beyond_clearance_low"] < rate < row["annual_rate_beyond_clearance_high"]


def test_the_curve_leaves_the_level_answer_alone(two_pulse_run, tmp_path):
    result, _ = two_pulse_run
    path = Path(result.workbook)
    plain = run_assessment(read_workbook(path), "2in50")
    columns = [c for c in plain.summary.columns]
    pd.testing.assert_frame_equal(result.summary[columns], plain.summary)
    assert "annual_rate_overturn" not in plain.summary


def test_stripes_run_through_the_runner(rect_run):
    result, _, runner = rect_run
    from assess.fragility.stripes import N_STRIPES, REFINE_STRIPES
    # the level: 2 freestanding items x 2 directions x 1 history; the stripes: as many x N stripes,
    # and each item's step (one history: its outcomes are a step) looked into with REFINE_STRIPES more
    assert runner.cases_simulated - result.curve_risk.runs == 2 * 2 * 1
    assert result.curve_risk.runs == 2 * 2 * N_STRIPES + 2 * 2 * REFINE_STRIPES


def _cli(args, cwd):
    """``assess ARGS`` from ``cwd``, in this process (tests/commands.py)."""
    return commands.run(*args, cwd=cwd)


def test_several_levels_in_one_run_write_one_folder_each(tmp_path):
    path = _workbook(tmp_path, [
        {"id": "S1", "name": "low friction", "floor": 0, "mu": 0.15, "clearance_cm": 10, **SQUAT},
    ], [{"level": "2in50", "motion": "p2", "floor": 0, "pta_g": 0.6, "tp_s": 0.5, "pulse": "A"},
        {"level": "10in50", "motion": "p10", "floor": 0, "pta_g": 0.35, "tp_s": 0.5, "pulse": "A"}], {})
    done = _cli([str(path), "--hazard", "2in50,10%/50yr", "--out", str(tmp_path / "out"), "--format", "xlsx"],
                tmp_path)
    assert done.returncode == 0, done.stderr
    two = pd.read_csv(tmp_path / "out" / "2in50" / "summary.csv")
    ten = pd.read_csv(tmp_path / "out" / "10in50" / "summary.csv")
    assert two.loc[0, "pta_g"] == pytest.approx(0.6) and ten.loc[0, "pta_g"] == pytest.approx(0.35)
    import openpyxl
    book = openpyxl.load_workbook(tmp_path / "out" / "10in50" / "summary.xlsx", read_only=True)
    assert book.sheetnames[:2] == ["10in50", "2in50"]  # its own level first, then the others
    again = _cli([str(path), "--hazard", "2in50,2%/50yr", "--out", str(tmp_path / "again")], tmp_path)
    assert again.returncode == 2 and "again" in again.stderr and "Traceback" not in again.stderr
    commands.assert_refused(again, "Fix: give each level once.",
                            places=["--hazard: '2%/50yr' is the level '2in50' again"])
    assert not (tmp_path / "again").exists()


def test_the_command_writes_the_fragility_folder_with_a_curve(tmp_path):
    path = _workbook(tmp_path, [
        {"id": "S1", "name": "low friction", "floor": 0, "mu": 0.15, "clearance_cm": 10, **SQUAT},
    ], [{"level": "2in50", "motion": "short", "floor": 0, "record": "records/short.csv"},
        {"level": "2in50", "motion": "long", "floor": 0, "record": "records/long.csv"}],
        {"records/short.csv": _rect_record(0.25), "records/long.csv": _rect_record(1.0)})
    done = _cli([str(path), "--hazard", "2in50", "--oq-hazard", str(CURVE), "--out", str(tmp_path / "out"),
                 "--format", "html"], tmp_path)
    assert done.returncode == 0, done.stderr
    summary = pd.read_csv(tmp_path / "out" / "summary.csv")
    for column in ("annual_rate_beyond_clearance", "annual_rate_overturn", "p50yr_beyond_clearance",
                   "p50yr_overturn"):
        assert column in summary
    assert (tmp_path / "out" / "fragility" / "fragility.json").is_file()
    html = (tmp_path / "out" / "report.html").read_text()
    assert "Over the building&#39;s life" in html or "Over the building's life" in html
    assert "in 50 years" in html


def test_pelicun_loads_the_exported_fragility_of_a_run_into_its_damage_model(two_pulse_run, tmp_path):
    """The fragility an assessment exports, read by pelicun (a test-only peer) into a damage model:
    its damage-state probabilities at given floor accelerations are the fitted lognormal's."""
    pelicun_assessment = pytest.importorskip(
        "pelicun.assessment", reason="pelicun is not installed (pip install -e '.[test,pelicun]' adds it)")
    from assess.fragility.stripes import fragility_files

    result, _ = two_pulse_run
    folder = tmp_path / "fragility"
    folder.mkdir()
    for name, content in fragility_files(result.curve_risk, result.summary).items():
        (tmp_path / name).write_bytes(content)
    fit = result.curve_risk.fits[("S1", "beyond_clearance")]
    pfa_g = np.array([0.5 * fit.median_g, fit.median_g, 1.5 * fit.median_g])
    repeats = 4000
    sample = np.tile(pfa_g, repeats)
    demand_csv = tmp_path / "demand.csv"
    with demand_csv.open("w", encoding="utf-8") as handle:
        handle.write(",1-PFA-0-1,1-PFA-1-1\nUnits,g,g\n")
        for i, a in enumerate(sample):
            handle.write(f"{i},{a},{a}\n")
    asmnt = pelicun_assessment.Assessment({"PrintLog": False, "Seed": 3})
    asmnt.stories = 1
    asmnt.demand.load_sample(str(demand_csv))
    marginals = pd.DataFrame({"Units": "ea", "Location": "1", "Direction": "1", "Theta_0": 1.0, "Blocks": 1},
                             index=["S1"])
    asmnt.asset.load_cmp_model({"marginals": marginals})
    asmnt.asset.generate_cmp_sample(len(sample))
    asmnt.damage.load_model_parameters([str(folder / "fragility.csv")], {"S1"})
    asmnt.damage.calculate()
    assert asmnt.damage.missing_components == []
    states = asmnt.damage.ds_model.sample.xs("S1", axis=1, level="cmp").T.groupby(level="ds").sum().T
    damaged = states.drop(columns="0", errors="ignore").sum(axis=1).to_numpy()
    observed = np.array([damaged[sample == a].mean() for a in pfa_g])
    expected = stats.norm.cdf(np.log(pfa_g / fit.median_g) / fit.beta)
    print("pelicun P(DS>=1)", observed.round(4), "fitted lognormal", expected.round(4))
    np.testing.assert_allclose(observed, expected, atol=0.03)  # > 4 sampling sd of 4000 draws


def test_a_curve_with_nothing_to_integrate_exits_2_naming_it(tmp_path):
    path = _workbook(tmp_path, [
        {"id": "S1", "name": "low friction", "floor": 0, "mu": 0.15, "clearance_cm": 10, **SQUAT},
    ], [{"level": "2in50", "motion": "p2", "floor": 0, "pta_g": 0.6, "tp_s": 0.5, "pulse": "A"}], {})
    flat = tmp_path / "hazard_curve-mean-PGA_1.csv"
    flat.write_text("#,,,,\"kind='mean', investigation_time=50.0, imt='PGA'\"\n"
                    "lon,lat,depth,poe-0.1000000,poe-0.2000000\n0.0,0.0,0.0,1.000000E+00,1.000000E+00\n")
    done = _cli([str(path), "--hazard", "2in50", "--oq-hazard", str(flat), "--out", str(tmp_path / "out")], tmp_path)
    assert done.returncode == 2, done.stderr
    assert "hazard_curve-mean-PGA_1.csv" in done.stderr and "Traceback" not in done.stderr
    commands.assert_refused(done, "lies above the curve's range", places=[f"{flat}, row 3: site #0"])
    assert not (tmp_path / "out").exists()


def test_a_suite_of_two_kinds_of_motion_is_no_lognormal_and_its_rate_comes_from_the_outcomes(tmp_path):
    """Three short and three long rectangular pulses: half the suite needs far more acceleration than
    the other half, so the fragility rises in two groups of steps with a plateau between, which no
    lognormal describes. Its rate has a closed form, the mean over the motions of λ(a*) at each one's
    closed-form threshold."""
    durations = (0.06, 0.07, 0.08, 1.6, 1.8, 2.0)
    path = _workbook(tmp_path, [
        {"id": "S1", "name": "low friction", "floor": 0, "mu": 0.15, "clearance_cm": 10, **SQUAT},
    ], [{"level": "2in50", "motion": f"rect {d} s", "floor": 0, "record": f"records/r{k}.csv"}
        for k, d in enumerate(durations)],
        {f"records/r{k}.csv": _rect_record(d) for k, d in enumerate(durations)})
    hazard = read_openquake_hazard(CURVE)
    result = run_assessment(read_workbook(path), "2in50", hazard_curve=hazard)
    row = result.summary.set_index("id").loc["S1"]
    thresholds = [rect_threshold_g(0.15, 0.10, d) for d in durations]
    exact = float(np.mean([_curve_rate(hazard, a) for a in thresholds]))
    fit = result.curve_risk.fits[("S1", "beyond_clearance")]
    from assess.hazard.risk_integral import openquake_failure_rate
    lognormal = openquake_failure_rate(hazard, fit.median_g, fit.beta).annual_rate
    print("thresholds", np.round(thresholds, 3), "exact", exact, "reported", row["annual_rate_beyond_clearance"],
          row["annual_rate_beyond_clearance_low"], row["annual_rate_beyond_clearance_high"], "lognormal", lognormal)
    # the steep rises were refined, and the fitted lognormal's rate, with its interval, holds the closed form
    assert len(result.curve_risk.stripes.query("id == 'S1' and mode == 'beyond_clearance'")) > 10
    assert row["annual_rate_beyond_clearance_low"] <= exact <= row["annual_rate_beyond_clearance_high"]
    assert row["annual_rate_beyond_clearance"] == pytest.approx(exact, rel=0.25)


def test_where_no_lognormal_fits_the_rate_is_the_outcomes_own():
    """Many trials on a fine grid of stripes, half the histories failing from a1 and half from a2:
    the deviance rejects the lognormal, and the rate integrated from the outcomes is the closed form
    of the two steps, ½ λ(a1) + ½ λ(a2); the lognormal's is not."""
    from assess.fragility.msa import fit_lognormal_fragility
    from assess.fragility.stripes import curve_rates_per_yr, item_rates

    hazard = read_openquake_hazard(CURVE)
    levels_g, rates = curve_rates_per_yr(hazard)
    x = np.geomspace(0.05, 2.0, 60)
    a1, a2 = x[15], x[45]  # on stripes, so the steps are seen exactly
    n = np.full(x.size, 200)
    z = (100 * (x >= a1) + 100 * (x >= a2)).astype(int)
    fit = fit_lognormal_fragility(x, n, z)
    assert fit.status == "fitted"
    outcomes = pd.DataFrame({"pfa_g": x, "trials": n, "failures": z})
    rates_out = item_rates(fit, "beyond_clearance", hazard, levels_g, rates, 1.0, x, outcomes, onset_g=0.0)
    exact = 0.5 * _curve_rate(hazard, a1) + 0.5 * _curve_rate(hazard, a2)
    from assess.hazard.risk_integral import openquake_failure_rate
    lognormal = openquake_failure_rate(hazard, fit.median_g, fit.beta).annual_rate
    print("exact", exact, "outcomes", rates_out["annual_rate_beyond_clearance"], "lognormal", lognormal)
    assert "does not fit the outcomes" in rates_out["note"]
    # a step seen at one stripe is spread over the gap below it (linear in ln a): within 25 %
    assert rates_out["annual_rate_beyond_clearance"] == pytest.approx(exact, rel=0.25)
    assert abs(math.log(rates_out["annual_rate_beyond_clearance"] / exact)) < abs(math.log(lognormal / exact))


def test_a_record_pair_runs_each_direction_under_its_own_component_in_the_stripes(tmp_path):
    """Direction 1 under the width component, direction 2 under the depth one: a pair whose depth
    component is the width one at a tenth scaled together moves the block in direction 2 by what the
    one-way kernel gives under that smaller component (Newmark closed form of a rectangle)."""
    path = _workbook(tmp_path, [
        {"id": "S1", "name": "low friction", "floor": 0, "mu": 0.15, "clearance_cm": 10, **SQUAT},
    ], [{"level": "2in50", "motion": "pair", "floor": 0, "record": "records/w.csv", "record_2": "records/d.csv"}],
        {"records/w.csv": _rect_record(0.5, 0.5), "records/d.csv": _rect_record(0.5, 0.05)})
    captured = []
    from assess.fragility import stripes as module

    original = module.stripe_runs

    def spy(*args, **kwargs):
        runs = original(*args, **kwargs)
        captured.append(runs)
        return runs

    module.stripe_runs = spy
    try:
        run_assessment(read_workbook(path), "2in50", hazard_curve=read_openquake_hazard(CURVE))
    finally:
        module.stripe_runs = original
    runs = captured[0]
    top = runs[runs["pfa_g"] == runs["pfa_g"].max()].set_index("direction")["sliding_max_cm"]
    a_g, mu, t = runs["pfa_g"].max(), 0.15, PULSE_S
    newmark_cm = lambda amp: 100 * max(amp - mu, 0.0) * amp * G * t * t / (2 * mu)  # noqa: E731
    assert top[1] == pytest.approx(newmark_cm(a_g), rel=0.01)
    assert top[2] == pytest.approx(newmark_cm(a_g / 10), rel=0.02)  # 0.2 g: it slides, much less


def test_the_fragility_at_the_level_beside_the_level_answer_and_which_governs(two_pulse_run):
    """Three rectangular pulses of 0.5 g: the level's answer counts the pulses whose closed-form threshold
    lies below 0.5 g; the fragility at the level is Φ(ln(0.5/θ)/β) (every motion at 0.5 g). The report
    says which governs, with the item named where the two lie 10 % or more apart."""
    from assess.fragility.agreement import APART, level_comparison_sentence
    from assess.report.curve import curve_context

    result, _ = two_pulse_run
    row = result.summary.set_index("id").loc["S1"]
    fit = result.curve_risk.fits[("S1", "beyond_clearance")]
    thresholds = [rect_threshold_g(0.15, 0.10, d) for d in (0.25, 0.5, 1.0)]
    assert row["p_beyond_clearance"] == pytest.approx(sum(t < 0.5 for t in thresholds) / 3)
    assert row["p_beyond_clearance_fragility"] == pytest.approx(
        stats.norm.cdf(math.log(0.5 / fit.median_g) / fit.beta), rel=1e-9)
    assert math.isnan(row["p_overturn_fragility"])  # never overturns: no fit, no number
    context = curve_context(result)
    assert "the level's answer governs" in context["governs"]
    # stripes of floor acceleration: the median the page's table heads is the floor's
    assert context["intensity"] == "PFA" and context["stripes"].startswith("its floor's motions scaled to 10 stripes")
    assert "of floor acceleration" in context["stripes"]
    apart = abs(row["p_beyond_clearance"] - row["p_beyond_clearance_fragility"]) >= APART
    assert bool(context["apart"]) == apart
    if apart:
        sentence = level_comparison_sentence({**row.to_dict(), "id": "S1"}, why=False)
        assert context["apart"] == [sentence] and "both from the simulations" in sentence


def test_a_level_given_twice_in_other_case_is_refused():
    """Hostile-input campaign: --hazard DE,de ran the level twice into DE/ and de/ (one folder on macOS and
    Windows, whose file systems ignore case); DE,DE was refused. Both are the same level."""
    from assess.errors import InputError
    from assess.command.job import parse_levels
    with pytest.raises(InputError, match="'de' is the level 'DE' again"):
        parse_levels("DE,de")
    assert [name for name, _ in parse_levels("DE,MCE_R")] == ["DE", "MCE_R"]
