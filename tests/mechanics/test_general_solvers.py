"""The two general solvers check each other where no closed form exists: slide-rock.

The event-driven solver (assess.mechanics.event_driven: one set of equations
per mode, transitions located by scipy's DOP853 events, impacts by impulse
laws written out) and the Moreau–Jean time-stepping solver
(assess.mechanics.timestepping: no modes, an exact two-corner contact problem
at every step) share only the model of assess.mechanics.block. Agreement on
blocks that uplift *and* slip, under pulses and under a real record, is the
evidence that both integrate that model; each is also checked against closed
forms and the specialised kernels in its own test file.

Tolerances: the time-stepping scheme is first order at p·Δt = 2e-3 (its
module docstring), so peak rotation agrees to 1 %, sliding to 3 % (or 0.3 mm),
overturning times to 10 ms.
"""
from __future__ import annotations

import numpy as np
import pytest

from assess.hazard.records import pulse_record
from assess.mechanics.block import Block
from assess.mechanics.event_driven import simulate_event_driven
from assess.mechanics.timestepping import simulate_time_stepping

#: (b/h, μ/(b/h), pulse, ap [g], Tp [s]); a 1 m tall uniform block.
CASES = [
    (0.30, 1.05, "rect", 0.50, 0.30),   # slide-rock, survives
    (0.30, 1.05, "A", 0.45, 0.60),
    (0.30, 1.05, "B", 0.40, 0.50),
    (0.45, 1.05, "B", 0.60, 0.80),      # mostly rocks, slips a little
    (0.30, 1.30, "A", 0.45, 0.40),
    (0.20, 1.05, "B", 0.60, 0.80),      # overturns
    (0.30, 1.05, "A", 1.20, 0.50),      # overturns after sliding
    (0.45, 1.30, "A", 0.80, 1.00),
]


def block(b_over_h, mu_ratio, height_m=1.0):
    return Block(half_width_m=b_over_h * height_m / 2, cg_height_m=height_m / 2, height_m=height_m,
                 mu=b_over_h * mu_ratio)


def assert_agree(event, stepped, label):
    assert event.overturned == stepped.overturned, label
    if event.overturned:
        assert stepped.overturn_time_s == pytest.approx(event.overturn_time_s, abs=0.01), label
    else:
        assert stepped.theta_max_over_alpha == pytest.approx(event.theta_max_over_alpha, rel=0.01, abs=1e-3), label
        assert stepped.sliding_residual_m == pytest.approx(event.sliding_residual_m, rel=0.03, abs=3e-4), label
    assert stepped.sliding_max_m == pytest.approx(event.sliding_max_m, rel=0.03, abs=3e-4), label
    assert stepped.uplift == event.uplift, label
    assert stepped.mode == event.mode, label


@pytest.mark.parametrize("b_over_h, mu_ratio, pulse, ap_g, tp_s", CASES)
def test_solvers_agree_under_pulses(b_over_h, mu_ratio, pulse, ap_g, tp_s):
    motion = pulse_record(pulse, ap_g, tp_s)
    item = block(b_over_h, mu_ratio)
    event = simulate_event_driven(item, motion.accel_g, motion.dt_s, tail_s=5.0)
    stepped = simulate_time_stepping(item, motion.accel_g, motion.dt_s, tail_s=5.0)
    assert_agree(event, stepped, (b_over_h, mu_ratio, pulse, ap_g, tp_s))


def test_the_grid_reaches_slide_rock_survival_and_overturning():
    """The cases above are not all one kind: both solvers see slide-rock runs that survive and that overturn."""
    seen = set()
    for b_over_h, mu_ratio, pulse, ap_g, tp_s in CASES:
        motion = pulse_record(pulse, ap_g, tp_s)
        r = simulate_event_driven(block(b_over_h, mu_ratio), motion.accel_g, motion.dt_s, tail_s=5.0)
        seen.add((r.mode, r.overturned))
    assert ("slide-rock", False) in seen and ("slide-rock", True) in seen


def test_solvers_agree_on_a_real_record():
    """Kobe 1995 Takatori (pyslammer's record) x 0.8, its first 12 s, on slide-rock blocks of 1.8 m
    (one overturns, one survives)."""
    pyslammer = pytest.importorskip("pyslammer")
    motion = pyslammer.sample_ground_motions()["Kobe_1995_TAK-090"]
    accel, dt = np.asarray(motion.accel, dtype=float)[:1200] * 0.8, float(motion.dt)
    slid = 0
    for b_over_h in (0.30, 0.40):
        item = block(b_over_h, 1.05, height_m=1.8)
        event = simulate_event_driven(item, accel, dt, tail_s=5.0)
        stepped = simulate_time_stepping(item, accel, dt, tail_s=5.0)
        assert_agree(event, stepped, b_over_h)
        slid += event.mode == "slide-rock"
    assert slid == 2


def test_mode_sequences_visit_the_same_modes():
    motion = pulse_record("rect", 0.50, 0.30)
    item = block(0.30, 1.05)
    event = simulate_event_driven(item, motion.accel_g, motion.dt_s, tail_s=5.0)
    stepped = simulate_time_stepping(item, motion.accel_g, motion.dt_s, tail_s=5.0)
    first = [m for _, m in event.mode_sequence]
    assert first[:3] == ["rest", "rock", "slide-rock"] or first[:2] == ["rest", "slide-rock"]
    assert {m for _, m in event.mode_sequence} == {m for _, m in stepped.mode_sequence}
    # the first uplift happens at the same time in both (located by each)
    assert stepped.mode_sequence[1][0] == pytest.approx(event.mode_sequence[1][0], abs=2e-3)
