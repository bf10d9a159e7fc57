"""Spectral matching of a recorded pair (assess/site/matching.py::match_pair): the pair's maximum-direction
spectrum against the target on a grid finer than the matching's own, recomputed with RotD100 as Boore (2010)
defines it (the largest of the rotated oscillator's peaks, here over 1° steps, not the code's sqrt(u1² + u2²)),
the components' shape kept, and the motion back at rest."""
from importlib import resources

import numpy as np
import pytest

from assess.hazard.records import read_record
from assess.site import asce7
from assess.site.matching import match_pair, match_spectrum
from assess.site.spectrum import oscillator_displacements

RECORDS = resources.files("pyslammer") / "sample_ground_motions"
DE = asce7.from_design_values(1.0, 0.6, 8.0)


def _rotd100_on_angles(a1, a2, dt_s, periods_s):
    """max over θ in 1° steps of ω² max_t |u1 cos θ + u2 sin θ|, with the oscillators vibrating freely after."""
    tail = int(np.ceil(max(periods_s) / dt_s))
    a1, a2 = (np.concatenate([a, np.zeros(tail)]) for a in (a1, a2))
    out = []
    for period in periods_s:
        u1, u2 = (oscillator_displacements(a, dt_s, [period])[0] for a in (a1, a2))
        theta = np.deg2rad(np.arange(0.0, 180.0, 1.0))[:, None]
        out.append((2 * np.pi / period) ** 2 * np.max(np.abs(np.cos(theta) * u1 + np.sin(theta) * u2)))
    return np.array(out)


def test_a_recorded_pair_is_matched_by_its_rotd100_keeping_its_shape():
    first = read_record(str(RECORDS / "Landers_1992_LCN-345.csv"))
    second = read_record(str(RECORDS / "Loma_Prieta_1989_HSP-000.csv"))  # the same step, 0.005 s
    assert first.dt_s == second.dt_s
    (m1, m2), error = match_pair(first.accel_g, second.accel_g, first.dt_s, DE.design_g, 0.1, 2.0, tolerance=0.1,
                                 max_iterations=40)
    assert m1.size == m2.size == max(first.accel_g.size, second.accel_g.size)
    grid = np.geomspace(0.1, 2.0, 60)
    rotd = _rotd100_on_angles(m1, m2, first.dt_s, grid)
    # 1° steps find the largest direction within cos(0.5°): the dense check's error, to that
    assert np.max(np.abs(rotd / DE.design_g(grid) - 1.0)) <= error + 0.01
    assert error <= 0.15
    for original, matched in ((first.accel_g, m1), (second.accel_g, m2)):
        o = np.concatenate([original, np.zeros(matched.size - original.size)])
        assert np.corrcoef(o, matched)[0, 1] > 0.7  # the record's own history, reshaped, not another one
        v = np.concatenate([[0.0], np.cumsum(0.5 * (matched[1:] + matched[:-1]) * first.dt_s)])
        assert abs(v[-1]) < 1e-9 * np.max(np.abs(v))  # at rest at its end (trapezoidal, as corrected)


def test_a_pair_with_a_silent_second_component_is_its_first_matched_alone():
    """RotD100 of (a, 0) is a's own spectrum: the pair's matching is the one component's, to rounding."""
    record = read_record(str(RECORDS / "Landers_1992_LCN-345.csv"))
    one, error = match_spectrum(record.accel_g, record.dt_s, DE.design_g, 0.1, 2.0, tolerance=0.1)
    (first, silent), pair_error = match_pair(record.accel_g, np.zeros(record.accel_g.size), record.dt_s,
                                             DE.design_g, 0.1, 2.0, tolerance=0.1)
    assert not silent.any()
    np.testing.assert_allclose(first, one, rtol=0, atol=1e-9 * np.max(np.abs(one)))
    assert pair_error == pytest.approx(error, abs=1e-9)
