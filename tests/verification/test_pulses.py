"""Acceleration pulses: shapes and the Type-C1 closure, checked by numerical integration."""
import numpy as np
import pytest
from scipy import integrate

from assess.hazard.pulses import pulse_acceleration, pulse_duration, type_c_phase


@pytest.mark.parametrize("pulse", ["A", "B", "C"])
def test_trigonometric_pulses_velocity_amplitude_and_closure(pulse):
    ap_g, tp_s = 0.6, 1.5
    t = np.linspace(0.0, pulse_duration(pulse, tp_s), 200_001)
    accel = pulse_acceleration(pulse, ap_g, tp_s, t) * 9.80665
    velocity = integrate.cumulative_trapezoid(accel, t, initial=0.0)
    displacement = integrate.cumulative_trapezoid(velocity, t, initial=0.0)
    vp = ap_g * 9.80665 * tp_s / (2 * np.pi)
    assert abs(velocity[-1]) < 1e-6 * vp  # every pulse ends at rest
    if pulse == "A":  # u = (ap/wp)(t - sin(wp t)/wp): forward displacement (ap/wp)*Tp at the end
        assert displacement[-1] == pytest.approx(vp * tp_s, rel=1e-6)
        assert np.max(velocity) == pytest.approx(2 * vp, rel=1e-6)
    else:  # B: forward and back; C1: back to where it started
        assert abs(displacement[-1]) < 1e-6 * vp * tp_s
        assert np.max(np.abs(velocity)) == pytest.approx(vp * (1 + (pulse == "C") * np.sin(type_c_phase())),
                                                         rel=1e-4)


def test_zero_outside_and_rect():
    assert list(pulse_acceleration("rect", 0.3, 1.0, [-0.1, 0.0, 0.5, 1.0, 1.1])) == [0.0, 0.3, 0.3, 0.3, 0.0]
    with pytest.raises(ValueError, match="unknown pulse"):
        pulse_acceleration("D", 0.3, 1.0, [0.0])
