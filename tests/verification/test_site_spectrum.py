"""Response spectra (assess/site/spectrum.py) against closed forms and an independent integrator.

Closed forms (Chopra, Dynamics of Structures, §3.1-3.2, §4.3-4.4): a step and a ramp of
ground acceleration from rest, the harmonic steady state. Independent integration:
scipy.signal.lsim of the oscillator's state-space model with the input linear between
samples, on pyslammer's recorded ground motions.
"""
from importlib import resources

import numpy as np
import pytest
from scipy import signal

from assess.hazard.records import read_record
from assess.site.spectrum import (geometric_mean_spectrum, oscillator_displacements,
                                  pseudo_acceleration_spectrum, rotd_spectrum)

PYSLAMMER_RECORDS = sorted(p for p in (resources.files("pyslammer") / "sample_ground_motions").iterdir()
                           if p.name.endswith(".csv"))


def _step_response(t, a0, omega, zeta):
    """u(t) under a ground acceleration a0 from t = 0 (load −a0), from rest (Chopra eq. 4.3.x)."""
    wd = omega * np.sqrt(1 - zeta ** 2)
    return -a0 / omega ** 2 * (1 - np.exp(-zeta * omega * t) * (np.cos(wd * t)
                                                               + zeta / np.sqrt(1 - zeta ** 2) * np.sin(wd * t)))


def _ramp_response(t, rate, omega, zeta):
    """u(t) under a ground acceleration rate·t (load −rate·t), from rest (Chopra eq. 4.4.x)."""
    wd = omega * np.sqrt(1 - zeta ** 2)
    return -rate / omega ** 2 * (t - 2 * zeta / omega + np.exp(-zeta * omega * t) * (
        2 * zeta / omega * np.cos(wd * t) - (1 - 2 * zeta ** 2) / wd * np.sin(wd * t)))


@pytest.mark.parametrize("zeta", [0.0, 0.02, 0.05, 0.2])
@pytest.mark.parametrize("period", [0.05, 0.3, 2.0])
def test_step_and_ramp_are_exact(zeta, period):
    dt = 0.01
    t = np.arange(0, 5.0, dt)
    omega = 2 * np.pi / period
    u_step = oscillator_displacements(np.full(t.size, 0.3), dt, [period], zeta)[0]
    # the record's first sample is already 0.3: the recursion sees a ramp 0 -> 0.3 only if it starts at 0;
    # it starts from rest at the first sample with the load at its value, which is the step at t = 0
    np.testing.assert_allclose(u_step, _step_response(t, 0.3, omega, zeta), atol=1e-12 * 0.3 / omega ** 2 + 1e-15)
    u_ramp = oscillator_displacements(0.7 * t, dt, [period], zeta)[0]
    expected = _ramp_response(t, 0.7, omega, zeta)
    np.testing.assert_allclose(u_ramp, expected, atol=1e-10 * np.max(np.abs(expected)))


@pytest.mark.parametrize("ratio", [0.5, 0.9, 1.3, 3.0])
def test_harmonic_steady_state(ratio):
    """After the transient dies out, |u| = (a/ω²)/√((1−r²)² + (2ζr)²) (Chopra eq. 3.2.x)."""
    period, zeta, dt = 0.5, 0.05, 0.002
    omega = 2 * np.pi / period
    t = np.arange(0, 60.0, dt)
    a = 0.2 * np.sin(ratio * omega * t)
    u = oscillator_displacements(a, dt, [period], zeta)[0]
    steady = 0.2 / omega ** 2 / np.sqrt((1 - ratio ** 2) ** 2 + (2 * zeta * ratio) ** 2)
    late = t > 45.0  # e^(-ζω·45) < 1e-12
    # tolerance: the peak falls between samples (1 − cos(π dt / T_forcing) ≤ 7e-4 at r = 3) and the
    # sine is taken as linear between samples
    assert np.max(np.abs(u[late])) == pytest.approx(steady, rel=1e-3)


def test_free_vibration_after_the_record_counts():
    """A short half-sine pulse: the peak comes after it ends, in free vibration."""
    dt, period = 0.005, 2.0
    t = np.arange(0, 0.2 + dt / 2, dt)
    a = np.sin(np.pi * t / 0.2)
    with_tail = pseudo_acceleration_spectrum(a, dt, [period])[0]
    without = pseudo_acceleration_spectrum(a, dt, [period], free_vibration_s=0.0)[0]
    assert with_tail > 2.0 * without
    # impulse limit: velocity kick I = ∫a = 0.4/π, peak ≈ I/ω (light damping, short pulse)
    omega = 2 * np.pi / period
    assert with_tail / omega ** 2 == pytest.approx(0.4 / np.pi / omega * np.exp(-0.05 * np.pi / 2), rel=0.02)


def _lsim_spectrum(accel, dt, periods, zeta=0.05):
    out = []
    accel = np.concatenate([accel, np.zeros(int(np.ceil(max(periods) / dt)))])
    t = np.arange(accel.size) * dt
    for period in periods:
        w = 2 * np.pi / period
        system = signal.StateSpace([[0, 1], [-w * w, -2 * zeta * w]], [[0], [-1]], [[1, 0]], [[0]])
        _, u, _ = signal.lsim(system, accel, t, interp=True)
        out.append(w * w * np.max(np.abs(u)))
    return np.array(out)


@pytest.mark.parametrize("path", PYSLAMMER_RECORDS[::4], ids=lambda p: p.name)
def test_against_lsim_on_recorded_motions(path):
    record = read_record(path)
    periods = np.array([0.02, 0.05, 0.1, 0.2, 0.3, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0, 4.0])
    ours = pseudo_acceleration_spectrum(record.accel_g, record.dt_s, periods)
    peer = _lsim_spectrum(record.accel_g, record.dt_s, periods)
    np.testing.assert_allclose(ours, peer, rtol=1e-6)
    # the short-period end tends to PGA
    assert pseudo_acceleration_spectrum(record.accel_g, record.dt_s, [0.0, 0.01])[0] == pytest.approx(record.pta_g)


def test_rotd_of_one_component():
    """Motion along axis 1 only: RotD100 = its spectrum, RotD50 = cos 45° of it (median of |cos θ|)."""
    record = read_record(PYSLAMMER_RECORDS[0])
    periods = [0.1, 0.5, 1.0]
    one = pseudo_acceleration_spectrum(record.accel_g, record.dt_s, periods)
    rot = rotd_spectrum(record.accel_g, np.zeros(record.accel_g.size), record.dt_s, periods)
    np.testing.assert_allclose(rot[100.0], one, rtol=1e-12)
    np.testing.assert_allclose(rot[50.0], np.cos(np.pi / 4) * one, rtol=0.01)


def test_rotd_is_orientation_independent_and_bounds_geometric_mean():
    a = read_record(PYSLAMMER_RECORDS[1])
    b = read_record(PYSLAMMER_RECORDS[2])
    n = min(a.accel_g.size, b.accel_g.size)
    x, y = a.accel_g[:n], b.accel_g[:n] * (a.dt_s == b.dt_s)
    periods = [0.2, 1.0]
    rot = rotd_spectrum(x, y, a.dt_s, periods)
    c, s = np.cos(0.6), np.sin(0.6)
    turned = rotd_spectrum(c * x + s * y, -s * x + c * y, a.dt_s, periods)
    np.testing.assert_allclose(turned[100.0], rot[100.0], rtol=1e-9)
    np.testing.assert_allclose(turned[50.0], rot[50.0], rtol=0.02)  # 1° grid
    gm = geometric_mean_spectrum(x, y, a.dt_s, periods)
    assert np.all(gm <= rot[100.0] * (1 + 1e-12))
