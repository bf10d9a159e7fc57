"""The stochastic residual's filter sums (:func:`assess.hazard.synthesis._filtered_noise_sums`) against the
sums written out from the impulse response of Rezaeian & Der Kiureghian (2008), and against the same terms
added source by source, in the order the kernel promises (so synthetic motions are the same to the last bit
whichever way the loop runs)."""
import numba
import numpy as np
import pytest

from assess.hazard.synthesis import _FILTER_MEMORY_DECAY_TIMES, _filtered_noise_sums


def _case(n, seed, zeta):
    rng = np.random.default_rng(seed)
    dt_s = 0.01
    time_s = np.arange(n) * dt_s
    omega = 2.0 * np.pi * np.clip(8.0 - 0.9 * time_s, 1.5, None)  # a filter frequency falling in time
    return omega, rng.standard_normal(n), zeta, dt_s


def _written_out(omega, noise, zeta, dt_s, decay_times):
    """Σ_i h(t_j − t_i; t_i) u_i and Σ_i h², h = ω/√(1−ζ²) e^{−ζω(t−τ)} sin(ω√(1−ζ²)(t−τ)), each
    response kept for ``decay_times`` decay times 1/(ζω) of its own frequency (as the kernel cuts it)."""
    n = omega.size
    root = np.sqrt(1.0 - zeta ** 2)
    numerator, energy = np.zeros(n), np.zeros(n)
    for i in range(n):
        lags = min(n - i, int(np.ceil(decay_times / (zeta * omega[i] * dt_s))) + 1)
        lag_s = np.arange(1, lags) * dt_s
        h = omega[i] / root * np.exp(-zeta * omega[i] * lag_s) * np.sin(omega[i] * root * lag_s)
        numerator[i + 1:i + lags] += h * noise[i]
        energy[i + 1:i + lags] += h * h
    return numerator, energy


@numba.njit(cache=False)
def _source_by_source(omega, noise, zeta, dt_s, decay_times):
    """The same terms, each source followed to its end by repeated rotation before the next source
    (compiled as the kernel is, so that both take their sines and exponentials from the same library)."""
    n = omega.size
    root = np.sqrt(1.0 - zeta * zeta)
    numerator, energy = np.zeros(n), np.zeros(n)
    for i in range(n):
        w = omega[i]
        lags = min(n - i, int(np.ceil(decay_times / (zeta * w * dt_s))) + 1)
        decay = np.exp(-zeta * w * dt_s)
        c_re, c_im = decay * np.cos(w * root * dt_s), decay * np.sin(w * root * dt_s)
        z_re, z_im, gain = 1.0, 0.0, w / root
        for lag in range(1, lags):
            z_re, z_im = z_re * c_re - z_im * c_im, z_re * c_im + z_im * c_re
            h = gain * z_im
            numerator[i + lag] += h * noise[i]
            energy[i + lag] += h * h
    return numerator, energy


@pytest.mark.parametrize("zeta", [0.2, 0.45])
def test_the_sums_are_the_impulse_responses_written_out(zeta):
    case = _case(600, 3, zeta)
    numerator, energy = _filtered_noise_sums(*case, _FILTER_MEMORY_DECAY_TIMES)
    expected_numerator, expected_energy = _written_out(*case, _FILTER_MEMORY_DECAY_TIMES)
    scale = np.sqrt(expected_energy.max())
    assert np.max(np.abs(numerator - expected_numerator)) < 1e-10 * scale
    assert np.allclose(energy, expected_energy, rtol=1e-10, atol=0.0)


@pytest.mark.parametrize("seed", [1, 2])
def test_gathered_sample_by_sample_they_are_the_source_by_source_sums_to_the_last_bit(seed):
    case = _case(500, seed, 0.3)
    numerator, energy = _filtered_noise_sums(*case, _FILTER_MEMORY_DECAY_TIMES)
    expected_numerator, expected_energy = _source_by_source(*case, _FILTER_MEMORY_DECAY_TIMES)
    assert np.array_equal(numerator, expected_numerator)
    assert np.array_equal(energy, expected_energy)
