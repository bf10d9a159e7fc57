"""Boxes on inset feet: the tool's rocking physics against an independent derivation and MuJoCo,
and ``assess calibrate`` on a shake-table data set made by the independent code.

The peer (:mod:`peers.footed_rocking`) derives everything from the box: the
pivot at the foot c = (1 − d)·b, the whole box's inertia moved to the foot by
the parallel-axis theorem, Housner's impact as angular momentum about the
striking foot (computed from vectors), the rotation read over the declared α.
MuJoCo (a box carrying two line feet on a plane, high friction) checks the
pivot and inertia part: the time a tilted box takes to fall back onto its
other foot, and the floor acceleration at which it lifts off.

The data set (:mod:`peers.footed_lab`): four slender specimens on feet at
0.7 b, six of pyslammer's records at two amplitudes (48 tests), θ/α of the
declared box with 5 % multiplicative noise, overturning exact. The peer's
noise-free responses are stored in ``tests/data/footed_lab/truth.csv``
(5 minutes to make); two of them are made again here.
"""
from __future__ import annotations

import json
import tempfile
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from assess.calibration import fit as fit_module
from assess.calibration import run_calibration
from assess.calibration.effects import declared_alpha_rad, item_block, theta_over_declared_alpha
from assess.calibration.measured import read_measured
from assess.hazard.records import pulse_record
from assess.inventory import read_workbook
from assess.mechanics.block import Block
from assess.mechanics.engine import simulate
from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2
from assess.mechanics.rocking import rocking_response

from peers.footed_lab import INSET, NOISE, TRUTH_JITTER_CSV, measured_rows, read_truth, write_lab
from peers.footed_rocking import FootedBox, footed_rocking
from peers.mujoco_box import box_model

#: (b, H, d): slender and squat boxes, on their edges and on feet.
BOXES = [(0.2, 1.6, 0.0), (0.2, 1.6, 0.3), (0.4, 1.2, 0.5), (0.311, 2.286, 0.15)]


def tool_block(b, H, d, mu=0.8):
    return Block(half_width_m=b, cg_height_m=H / 2, height_m=H, mu=mu, foot_inset_m=d * b)


@pytest.mark.parametrize("b, H, d", BOXES)
def test_every_term_is_the_derived_one(b, H, d):
    """Uplift threshold c/h, p² = m g R/I_f, Housner's e about the other foot: the tool's Block and the
    peer's derivation, to rounding."""
    box, block = FootedBox(b, H, d), tool_block(b, H, d)
    assert block.b_over_h == pytest.approx(box.uplift_accel_m_s2() / STANDARD_GRAVITY_M_S2, rel=1e-12)
    radius = np.hypot(box.c, box.h)
    assert block.p_rad_s == pytest.approx(np.sqrt(STANDARD_GRAVITY_M_S2 * radius / box.inertia_foot_per_mass),
                                          rel=1e-12)
    # returning onto the other foot: ω⁻ < 0 on the +c foot, ω⁻ > 0 on the −c foot; ω⁺ = e ω⁻
    assert block.restitution_effective == pytest.approx(box.omega_after_impact(-1.0, 1.0) / -1.0, rel=1e-12)
    assert block.restitution_effective == pytest.approx(box.omega_after_impact(2.0, -1.0) / 2.0, rel=1e-12)
    # the equation's coefficient: θ̈ at θ = 0 under a floor at rest, tool (p² sin α) and peer
    assert block.p_rad_s**2 * np.sin(block.alpha_rad) == pytest.approx(-box.theta_ddot(0.0, 0.0, 1.0), rel=1e-12)
    # what is reported: θ over α of the declared box, atan(b/h)
    assert declared_alpha_rad(block) == pytest.approx(box.declared_alpha, rel=1e-15)


def test_hand_checked_box_on_feet():
    """b = 0.4, H = 1.2, feet at 0.2 (d = 0.5): I_cm/m = (0.8² + 1.2²)/12 = 0.17333 m², I_f/m = 0.17333 +
    0.2² + 0.6² = 0.57333 m²; e = (0.17333 + 0.36 − 0.04)/0.57333 = 0.86047; threshold 0.2/0.6 = 1/3 g."""
    box, block = FootedBox(0.4, 1.2, 0.5), tool_block(0.4, 1.2, 0.5)
    assert box.inertia_foot_per_mass == pytest.approx(0.573333333, rel=1e-8)
    assert box.omega_after_impact(1.0, 1.0) == pytest.approx(0.860465116, rel=1e-8)
    assert block.restitution_effective == pytest.approx(0.860465116, rel=1e-8)
    assert block.b_over_h == pytest.approx(1 / 3, rel=1e-12)


def _mujoco_box(mujoco, b, H, c, gravity_x=0.0, foot_radius_m=0.001, step_s=1e-4):
    """A 100 kg box of half-width b and height H (no collision of its own) carrying two line feet
    (capsules of 1 mm radius across its depth) at x = ±c, on a plane; μ = 2, stiff contact
    (peers.mujoco_box.box_model)."""
    return box_model(mujoco, b, H, 2.0, foot_half_span_m=c, mass_kg=100.0, step_s=step_s, gravity_x_m_s2=gravity_x,
                     foot_radius_m=foot_radius_m)


def _tilt(data):
    """Rotation about +y [rad] (top towards +x positive) of the free body."""
    return 2.0 * np.arctan2(data.qpos[5], data.qpos[3])


def mujoco_fall_back_s(b, H, c, theta0, foot_radius_m=0.001, step_s=1e-4):
    """Time [s] a box released at rest, tilted θ0 onto its +x foot, takes to reach θ = 0 in MuJoCo."""
    mujoco = pytest.importorskip("mujoco")
    model = _mujoco_box(mujoco, b, H, c, foot_radius_m=foot_radius_m, step_s=step_s)
    data = mujoco.MjData(model)
    rotation = np.array([[np.cos(theta0), 0, np.sin(theta0)], [0, 1, 0], [-np.sin(theta0), 0, np.cos(theta0)]])
    foot = np.array([c, 0.0, foot_radius_m])
    data.qpos[:3] = foot + rotation @ np.array([-c, 0.0, H / 2 - foot_radius_m])
    data.qpos[3:7] = [np.cos(theta0 / 2), 0.0, np.sin(theta0 / 2), 0.0]
    mujoco.mj_forward(model, data)
    previous = _tilt(data)
    while data.time < 5.0:
        mujoco.mj_step(model, data)
        theta = _tilt(data)
        if theta <= 0.0 < previous:
            return data.time - step_s * theta / (theta - previous)
        previous = theta
    return np.nan


def mujoco_tilt_after(b, H, c, accel_over_g, seconds=1.0):
    """|rotation| [rad] after ``seconds`` under a constant floor acceleration (as a sideways gravity)."""
    mujoco = pytest.importorskip("mujoco")
    model = _mujoco_box(mujoco, b, H, c, gravity_x=accel_over_g * STANDARD_GRAVITY_M_S2)
    data = mujoco.MjData(model)
    data.qpos[:3], data.qpos[3:7] = [0.0, 0.0, H / 2], [1.0, 0.0, 0.0, 0.0]
    mujoco.mj_forward(model, data)
    while data.time < seconds:
        mujoco.mj_step(model, data)
    return abs(_tilt(data))


def tool_fall_back_s(block, theta0):
    """The rocking kernel's time to the first impact of a box released at rest, tilted θ0."""
    result = rocking_response(np.zeros(301), 0.01, block.alpha_rad, block.p_rad_s, return_history=True,
                              initial_theta_rad=theta0, inertia_ratio_value=block.inertia_ratio)
    return float(result.impact_time_s[0])


@pytest.mark.parametrize("fraction_of_alpha", [0.5, 0.8])
def test_free_rocking_on_feet_against_mujoco(fraction_of_alpha):
    """The squat box on feet at 0.5 b (where the inertia about the foot matters most): the time to
    fall back onto the other foot, MuJoCo vs the rocking kernel within 0.5 %; the model of a narrower
    box (the inertia of a box of half-width c) is 3.5 % off, so the comparison can tell them apart."""
    b, H, d = 0.4, 1.2, 0.5
    block = tool_block(b, H, d)
    theta0 = fraction_of_alpha * block.alpha_rad
    reference = mujoco_fall_back_s(b, H, block.contact_half_width_m, theta0)
    assert tool_fall_back_s(block, theta0) == pytest.approx(reference, rel=0.005)
    assert footed_rocking(FootedBox(b, H, d), np.zeros(201), 0.01, theta0=theta0).first_impact_s == pytest.approx(
        reference, rel=0.005)
    narrower = tool_block(block.contact_half_width_m, H, 0.0)
    assert abs(tool_fall_back_s(narrower, theta0) / reference - 1.0) > 0.02


def test_uplift_threshold_against_mujoco():
    """A box on feet at 0.5 b stays put at 0.97 of the tool's b/h (of the feet) and lifts at 1.03."""
    b, H, d = 0.4, 1.2, 0.5
    block = tool_block(b, H, d)
    assert mujoco_tilt_after(b, H, block.contact_half_width_m, 0.97 * block.b_over_h) < 1e-4
    assert mujoco_tilt_after(b, H, block.contact_half_width_m, 1.03 * block.b_over_h) > 0.05


def _records():
    pyslammer = pytest.importorskip("pyslammer")
    return pyslammer.sample_ground_motions()


@pytest.mark.parametrize("b, H, d, motion, level", [
    (0.2, 1.6, 0.3, "pulse B 0.3 g 1.0 s", 0.0),
    (0.3, 1.8, 0.3, "pulse A 0.45 g 0.8 s", 0.0),
    (0.2, 1.6, 0.3, "Northridge_1994_PAC-175", 0.25),
    (0.225, 2.0, 0.3, "Northridge_1994_PAC-175", 0.32),
])
def test_tool_rotations_on_feet_match_the_peer(b, H, d, motion, level):
    """θmax over the declared α, tool (engine on the footed block) and peer, under pulses and real records."""
    if motion.startswith("pulse"):
        _, kind, amplitude, _, period, _ = motion.split()
        record = pulse_record(kind, float(amplitude), float(period))
        accel, dt = record.accel_g, record.dt_s
    else:
        source = _records()[motion]
        accel = np.asarray(source.accel, float)
        accel, dt = accel * level / np.max(np.abs(accel)), float(source.dt)
    box, block = FootedBox(b, H, d), tool_block(b, H, d)
    peer = footed_rocking(box, accel, dt)
    tool = simulate(block, accel, dt)
    assert tool.overturned == peer.overturned
    assert peer.theta_over_declared_alpha(box) > 0.05
    assert theta_over_declared_alpha(tool.theta_max_over_alpha, block) == pytest.approx(
        peer.theta_over_declared_alpha(box), abs=2e-3)


# ------------------------------------------------------------------ the data set and assess calibrate
@pytest.fixture(scope="module")
def truth():
    return read_truth()


@pytest.fixture(scope="module")
def truth_jitter():
    return read_truth(TRUTH_JITTER_CSV)


def test_stored_truth_is_the_peers(truth, truth_jitter):
    """Stored responses made again by the peer (the files are the peer's, not the tool's)."""
    records = _records()
    from peers.footed_lab import SPECIMENS
    sizes = {s: (w / 200.0, h / 100.0) for s, h, w in SPECIMENS}
    # CAB-A and CAB-D under Northridge (the cheapest record: 20 s at 0.02 s)
    for row in (truth[1], truth[37], truth_jitter[13]):
        source = records[row["record"]]
        b, H = sizes[row["specimen"]]
        box = FootedBox(b, H, INSET)
        response = footed_rocking(box, np.asarray(source.accel, float) * row["played"], float(source.dt))
        assert response.overturned == row["overturned"]
        # 1e-3: the peer integrates a rocking response (DOP853 at rtol 1e-9), which scipy 1.17 moves by up to 5e-5
        # from the stored file's scipy (chaotic impacts); below the 2e-3 the tool is held to against the peer
        assert response.theta_over_declared_alpha(box) == pytest.approx(row["theta"], abs=1e-3)


def _theta_rms(predicted, measured):
    predicted, measured = np.minimum(np.asarray(predicted, float), 1.0), np.minimum(np.asarray(measured, float), 1.0)
    stood = np.isfinite(measured)
    return float(np.sqrt(np.mean((predicted[stood] - measured[stood]) ** 2)))


#: Predictions of the lab's tests (they depend on the workbook, not on the measured values, so the
#: labs below, which share the workbook, share them).
CACHE: dict = {}


def calibrate_lab(folder, truth_rows, seed, **options):
    """What ``assess calibrate`` does with the lab written to ``folder``: read the workbook and the
    measured tests as the command reads them, fit, select (in-process, sharing :data:`CACHE`)."""
    workbook, measured_path = write_lab(Path(folder), truth_rows, seed=seed)
    inventory = read_workbook(workbook)
    measured = read_measured(measured_path, inventory)
    return inventory, measured, run_calibration(inventory, measured, cache=CACHE, **options)


@pytest.fixture(scope="module")
def calibrated(truth, tmp_path_factory):
    """The lab written with noise seed 1, calibrated; the result as calibration.json has it."""
    _, _, result = calibrate_lab(tmp_path_factory.mktemp("footed"), truth, seed=1)
    return json.loads(json.dumps(result.as_json()))


def test_calibrate_names_the_feet_and_their_inset(truth, calibrated):
    """foot_inset selected, d = 0.30, θ rms after at the noise's own RMS (measured minus the peer's truth)."""
    result = calibrated
    rows = measured_rows(truth, seed=1)
    measured = np.array([np.nan if r["theta_max_over_alpha"] is None else r["theta_max_over_alpha"] for r in rows])
    noise_rms = _theta_rms([t["theta"] for t in truth], measured)
    assert 0.01 < noise_rms < NOISE * 0.5  # 5 % of θ/α values mostly below 0.5
    candidates = {c["effect"]: c for c in result["candidates"]}
    assert result["selected"]["effect"] == "foot_inset", {k: c.get("score") for k, c in candidates.items()}
    assert result["selected"]["parameters"]["d"] == pytest.approx(INSET, abs=0.01)
    assert result["error_before"]["theta_rms"] > 0.15
    assert result["error_after"]["theta_rms"] < 1.2 * noise_rms
    assert result["error_after"]["overturn_misclassified"] <= 1


def _predictions_at_true_inset(truth, model):
    """θ/α of the declared box and overturning per test, by the engine on ``model(declared block)``."""
    from peers.footed_lab import SPECIMENS
    sizes = {s: (w / 200.0, h / 100.0) for s, h, w in SPECIMENS}
    records = _records()
    theta, overturned = [], []
    for row in truth:
        b, H = sizes[row["specimen"]]
        declared = item_block({"cg_height_m": H / 2, "height_m": H, "mu": 0.8}, b)
        block, reading = model(declared)
        source = records[row["record"]]
        response = simulate(block, np.asarray(source.accel, float) * row["scale"], float(source.dt))
        theta.append(response.theta_max_over_alpha * reading(block, declared))
        overturned.append(response.overturned)
    return np.array(theta), np.array(overturned)


def _footed(declared):
    return replace(declared, foot_inset_m=INSET * declared.half_width_m), \
        lambda block, declared: block.alpha_rad / declared_alpha_rad(declared)


def _narrower_box(declared):  # a box of half-width c: its inertia about the feet is too small
    return replace(declared, half_width_m=(1 - INSET) * declared.half_width_m), \
        lambda block, declared: block.alpha_rad / declared_alpha_rad(declared)


def _over_alpha_of_the_feet(declared):  # the rotation read over α of the feet, not of the box
    return replace(declared, foot_inset_m=INSET * declared.half_width_m), lambda block, declared: 1.0


def _restitution_of_the_edges(declared):  # Housner's e of the box on its edges, not on its feet
    footed = replace(declared, foot_inset_m=INSET * declared.half_width_m)
    return replace(footed, restitution=declared.restitution_effective), \
        lambda block, declared: block.alpha_rad / declared_alpha_rad(declared)


@pytest.mark.parametrize("model, right", [(_footed, True), (_narrower_box, False), (_over_alpha_of_the_feet, False),
                                          (_restitution_of_the_edges, False)],
                         ids=["feet", "narrower-box", "over-alpha-of-feet", "edges-restitution"])
def test_at_the_true_inset_only_the_right_foot_model_reproduces_the_peer(truth, model, right):
    """Noise-free, at d = 0.3: the tool's foot model is within 0.005 (θ/α RMS) of the peer on the 48 tests;
    each wrong model (narrower box, α of the feet, the edges' restitution) is 0.05 or more off."""
    theta, overturned = _predictions_at_true_inset(truth, model)
    truth_theta = np.array([np.nan if t["overturned"] else t["theta"] for t in truth])
    rms = _theta_rms(theta, truth_theta)
    mismatched = int(np.sum(overturned != np.array([t["overturned"] for t in truth])))
    if right:
        assert rms < 0.005 and mismatched <= 1, (rms, mismatched)
    else:
        assert rms > 0.05, rms


# ------------------------------------------------------------------ a table that does not play the amplitude exactly
def test_a_table_off_by_one_percent_still_names_the_feet(truth_jitter):
    """The same lab, the table playing each record × (1 + 0.01·N(0, 1)) of what the workbook says.

    Rocking under records is chaotic: at d = 0.3 the tool's θ/α moves by more than 0.05 for ±0.5 %
    of amplitude in 17 of the 48 tests (9 by more than 0.15), so the exact model at the true inset is
    0.12 off the table in θ/α RMS. Compared at the nominal amplitude only (AMPLITUDE_BAND = 0, the
    measure before), that chaos chose input_scale s = 1.41, a wrong effect; charged only for what no
    amplitude within ±1 % explains, the selection names the feet and the inset."""
    with tempfile.TemporaryDirectory() as folder:
        inventory, measured, result = calibrate_lab(folder, truth_jitter, seed=2)
        scores = {f.effect.name: round(f.score, 4) for f in result.fits}
        assert result.selected == "foot_inset", scores
        assert result.parameters["d"] == pytest.approx(INSET, abs=0.015), result.parameters
        assert scores["foot_inset"] < 0.3 * scores["input_scale"], scores
        rows = measured_rows(truth_jitter, seed=2)
        noise = _theta_rms([t["theta"] for t in truth_jitter],
                           [np.nan if r["theta_max_over_alpha"] is None else r["theta_max_over_alpha"] for r in rows])
        assert result.error_after["theta_rms_band"] < 2.0 * noise, (result.error_after, noise)
        # the measure before: the nominal amplitude only (the predictions are cached, so this is quick)
        original = fit_module.AMPLITUDE_BAND
        try:
            fit_module.AMPLITUDE_BAND = 0.0
            nominal = run_calibration(inventory, measured, effects=["input_scale", "foot_inset"], cache=CACHE)
        finally:
            fit_module.AMPLITUDE_BAND = original
        assert nominal.selected == "input_scale", {f.effect.name: f.score for f in nominal.fits}
