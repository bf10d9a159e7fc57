"""The calibrated model in the assessment (``assess WORKBOOK --hazard LEVEL --calibration calibration.json``).

End to end on a synthetic shake-table lab whose friction is 0.7 times what
its workbook declares: the measured sliding is made here with the engine on
blocks of μ × 0.7 (not through the calibration's code path), with lognormal
noise (σ = 0.1, seeded). ``assess calibrate`` must name ``friction_scale``,
and the main job with ``--calibration`` must then simulate each specimen
under each tested motion as the calibration predicted: its RMS of
ln(simulated/measured) peak sliding equals calibrate's ``error_after``, and
without the calibration it equals ``error_before``. Both computed here from
motions.csv and the measured sheet, not read from the tool.
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import openpyxl
import pandas as pd
import pytest

from assess.calibration.apply import AppliedCalibration, case_block, read_calibration
from assess.calibration.effects import EFFECTS, calibrated_block, item_block
from assess.errors import InputError
from assess.hazard.records import pulse_record
from assess.mechanics.block import Block
from assess.mechanics.engine import simulate

import commands
from workbooks import write_workbook

TRUE_K = 0.7
LEVEL = "2in50"
#: (id, height cm, width cm, μ declared): they slide without uplifting (μ < b/h), or rock (SHELF).
ITEMS = [("INCUBATOR", 228.6, 62.2, 0.20), ("FRIDGE", 213.4, 66.0, 0.25), ("CART", 100.0, 80.0, 0.30),
         ("SHELF", 180.0, 50.0, 0.60)]
#: Type-B pulses (PTA g, Tp s) the table played.
PULSES = [(0.35, 0.6), (0.45, 1.0), (0.55, 1.5), (0.5, 0.8), (0.6, 2.0), (0.3, 1.2)]


def pulse_name(pta_g, tp_s):
    return f"table B {pta_g} g {tp_s} s"


def measured_sliding_m(height_cm, width_cm, mu, pta_g, tp_s, rng):
    """The table's measured peak sliding: the engine on the block of μ × 0.7, with noise."""
    block = Block(half_width_m=width_cm / 200, cg_height_m=height_cm / 200, height_m=height_cm / 100, mu=TRUE_K * mu)
    motion = pulse_record("B", pta_g, tp_s)
    return simulate(block, motion.accel_g, motion.dt_s).sliding_max_m * np.exp(0.1 * rng.standard_normal())


@pytest.fixture(scope="module")
def lab(tmp_path_factory):
    folder = tmp_path_factory.mktemp("lab")
    equipment = [{"id": i, "name": f"{i} on the table", "floor": 0, "height_cm": h, "width_cm": w, "depth_cm": 90,
                  "mass_kg": 200, "mu": mu, "clearance_cm": 15} for i, h, w, mu in ITEMS]
    hazard = [{"level": LEVEL, "motion": pulse_name(a, t), "floor": "all", "pta_g": a, "tp_s": t, "pulse": "B"}
              for a, t in PULSES]
    settings = [{"key": "simulate_motions", "value": "pulse"}]
    write_workbook(folder / "table.xlsx", {"equipment": equipment, "hazard": hazard, "settings": settings})
    rng = np.random.default_rng(7)
    tests = [[i, pulse_name(a, t), 100 * measured_sliding_m(h, w, mu, a, t, rng)]
             for i, h, w, mu in ITEMS for a, t in PULSES]
    book = openpyxl.Workbook()
    book.active.title = "tests"
    book.active.append(["specimen", "motion", "sliding_cm"])
    for row in tests:
        book.active.append(row)
    book.save(folder / "measured.xlsx")
    run(folder, "calibrate", "table.xlsx", "--measured", "measured.xlsx", "--out", "cal", "--format", "html")
    run(folder, "table.xlsx", "--hazard", LEVEL, "--out", "declared", "--format", "html")
    run(folder, "table.xlsx", "--hazard", LEVEL, "--calibration", "cal/calibration.json", "--out", "calibrated",
        "--format", "html")
    measured = pd.DataFrame(tests, columns=["id", "motion", "sliding_cm"])
    return folder, measured, json.loads((folder / "cal" / "calibration.json").read_text())


def run(folder: Path, *args):
    """``assess ARGS --quiet`` run from ``folder`` (in this process, tests/commands.py), which must succeed."""
    done = commands.run(*args, "--quiet", cwd=folder)
    assert done.returncode == 0, done.stderr[-3000:]
    return done


def rms_log_sliding(motions_csv: Path, measured: pd.DataFrame) -> float:
    """RMS of ln(max(simulated, 1 mm)/max(measured, 1 mm)) over the tests, direction 1 (the width)."""
    motions = pd.read_csv(motions_csv, dtype={"id": str})
    along_width = motions[motions["direction"] == 1][["id", "motion", "sim_sliding_max_cm"]]
    joined = measured.merge(along_width, on=["id", "motion"], validate="one_to_one")
    assert len(joined) == len(measured)
    ratio = np.log(np.maximum(joined["sim_sliding_max_cm"], 0.1) / np.maximum(joined["sliding_cm"], 0.1))
    return float(np.sqrt(np.mean(ratio**2)))


def test_calibrate_names_the_friction_the_table_showed(lab):
    _, _, calibration = lab
    assert calibration["selected"]["effect"] == "friction_scale", calibration["selected"]
    assert calibration["selected"]["parameters"]["k"] == pytest.approx(TRUE_K, rel=0.05)
    assert calibration["applies_to"] == sorted(i for i, *_ in ITEMS)


def test_main_job_matches_the_measured_sliding_as_calibrate_said(lab):
    folder, measured, calibration = lab
    declared = rms_log_sliding(folder / "declared" / "motions.csv", measured)
    calibrated = rms_log_sliding(folder / "calibrated" / "motions.csv", measured)
    # motions.csv holds 6 significant digits: ln ratios to 1e-6, their RMS to 2e-5
    assert declared == pytest.approx(calibration["error_before"]["sliding_rms_log"], abs=2e-5)
    assert calibrated == pytest.approx(calibration["error_after"]["sliding_rms_log"], abs=2e-5)
    assert calibrated < 0.2 < 0.5 < declared  # noise is 0.1; the declared friction is 1/0.7 too high


def test_report_shows_each_affected_items_risk_with_and_without(lab):
    folder, _, _ = lab
    summary = pd.read_csv(folder / "calibrated" / "summary.csv", dtype={"id": str}).set_index("id")
    declared = pd.read_csv(folder / "declared" / "summary.csv", dtype={"id": str}).set_index("id")
    html = (folder / "calibrated" / "report.html").read_text()
    assert "Calibration calibration.json applied: friction_scale (factor k on μ and μ_s = 0.7" in html
    for item_id, *_ in ITEMS:
        assert "calibrated" in summary.loc[item_id, "flags"]
        assert f"as declared: risk {declared.loc[item_id, 'risk']} (mode " in html
        assert "with the calibration (friction_scale" in html
    # the declared run carries no such flag
    assert not declared["flags"].fillna("").str.contains("calibrated").any()


def test_case_block_is_the_calibrations_block():
    """The main job's block of a case is the one the calibration predicted with, for every effect."""
    item = {"height_m": 2.0, "cg_height_m": 1.0, "width_m": 0.6, "mu": 0.2, "mu_static": 0.25}
    block = Block(half_width_m=0.3, cg_height_m=1.0, height_m=2.0, mu=0.2, mu_static=0.25)
    for name, effect in EFFECTS.items():
        parameters = {p.name: (p.lower + p.upper) / 2 for p in effect.parameters}
        applied = AppliedCalibration(name, parameters, ("A",), "calibration.json")
        assert case_block(block, "A", applied) == calibrated_block(item_block(item, 0.3), name, parameters)
        assert case_block(block, "B", applied) == block


@pytest.mark.parametrize("content, phrase", [
    ("not json", "is not JSON"),
    ('{"selected": {"effect": "gravity_scale", "parameters": {}}}', "not one of"),
    ('{"selected": {"effect": "friction_scale", "parameters": {"k": 7}}}', "not a number from 0.3 to 1.5"),
    ('{"selected": {"effect": "friction_scale", "parameters": {}}}', "parameter k of friction_scale"),
    ('{"selected": {"effect": "friction_scale", "parameters": {"k": 0.7}}, "applies_to": 3}', "applies_to"),
    ('[1, 2]', 'has no "selected"'),
])
def test_a_wrong_calibration_file_is_refused(tmp_path, content, phrase):
    path = tmp_path / "calibration.json"
    path.write_text(content)
    with pytest.raises(InputError, match=phrase) as caught:
        read_calibration(path)
    assert all(p.file == "calibration.json" and p.fix for p in caught.value.problems)


def test_a_parameter_not_determined_takes_the_declared_value(tmp_path):
    path = tmp_path / "calibration.json"
    path.write_text('{"selected": {"effect": "restitution", "parameters": {"e": null}}, "applies_to": "all"}')
    applied = read_calibration(path)
    assert applied.parameters == {"e": None} and applied.neutral_used == ("e",) and applied.applies_to is None
    block = Block(half_width_m=0.3, cg_height_m=1.0, height_m=2.0, mu=0.7)
    assert case_block(block, "X", applied).restitution_effective == block.restitution_effective
    assert "not determined by the tests" in applied.describe()


def test_cli_exits_2_on_a_calibration_naming_no_item_of_the_workbook(lab, tmp_path):
    folder, _, _ = lab
    other = tmp_path / "calibration.json"
    other.write_text('{"selected": {"effect": "friction_scale", "parameters": {"k": 0.7}}, "applies_to": ["X9"]}')
    done = commands.run(folder / "table.xlsx", "--hazard", LEVEL, "--calibration", other, "--out", tmp_path / "out",
                        "--quiet", cwd=tmp_path)
    assert done.returncode == 2, done.stderr
    commands.assert_refused(done, "none of which is in this workbook", "Nothing was written.",
                            places=["calibration.json: the calibration applies to the items X9"])
    assert "calibration.json" in done.stderr and '"applies_to": "all"' in done.stderr
    assert "Traceback" not in done.stderr and not (tmp_path / "out").exists()


def test_a_calibration_that_selected_none_leaves_the_declared_model(lab, tmp_path):
    folder, _, _ = lab
    none = tmp_path / "calibration.json"
    none.write_text('{"selected": {"effect": "none", "parameters": {}}, "applies_to": ["INCUBATOR"]}')
    run(folder, "table.xlsx", "--hazard", LEVEL, "--calibration", str(none), "--out", str(tmp_path / "out"),
        "--format", "html")
    summary = pd.read_csv(tmp_path / "out" / "summary.csv", dtype={"id": str})
    declared = pd.read_csv(folder / "declared" / "summary.csv", dtype={"id": str})
    pd.testing.assert_frame_equal(summary, declared)
    assert "the tests selected no effect (none)" in (tmp_path / "out" / "report.html").read_text()


def test_feet_in_the_main_job_rotate_against_the_declared_alpha(lab, tmp_path):
    """foot_inset d = 0.3 applied to SHELF: motions.csv's θmax/α is the event-driven solver's peak
    rotation of the footed box over α of the declared box (computed here by hand), within 1 %."""
    from assess.mechanics.event_driven import simulate_event_driven

    folder, _, _ = lab
    feet = tmp_path / "calibration.json"
    feet.write_text('{"selected": {"effect": "foot_inset", "parameters": {"d": 0.3}}, "applies_to": ["SHELF"]}')
    run(folder, "table.xlsx", "--hazard", LEVEL, "--calibration", str(feet), "--out", str(tmp_path / "out"),
        "--format", "html")
    motions = pd.read_csv(tmp_path / "out" / "motions.csv", dtype={"id": str})
    _, height_cm, width_cm, mu = ITEMS[3]
    b, h = width_cm / 200, height_cm / 200
    checked = 0
    for pta_g, tp_s in PULSES:
        footed = Block(half_width_m=b, cg_height_m=h, height_m=2 * h, mu=mu, foot_inset_m=0.3 * b)
        motion = pulse_record("B", pta_g, tp_s)
        reference = simulate_event_driven(footed, motion.accel_g, motion.dt_s)
        row = motions[(motions["id"] == "SHELF") & (motions["motion"] == pulse_name(pta_g, tp_s))
                      & (motions["direction"] == 1)].iloc[0]
        assert bool(row["sim_overturned"]) == reference.overturned, (pta_g, tp_s)
        if not reference.overturned:
            theta_rad = reference.theta_max_over_alpha * np.arctan(0.7 * b / h)
            assert row["sim_theta_max_over_alpha"] == pytest.approx(theta_rad / np.arctan(b / h), rel=0.01, abs=1e-3)
            checked += 1
    assert checked >= 1  # the others overturn, in both
