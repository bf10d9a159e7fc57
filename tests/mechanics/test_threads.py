"""Cases spread over threads (assess.mechanics.threads): every case once, any number of threads."""
import threading

import numba
import numpy as np
import pytest

from assess.mechanics.threads import case_ranges, run_case_ranges


@pytest.mark.parametrize("n_cases", [0, 1, 7, 31, 32, 33, 1000, 100_003])
@pytest.mark.parametrize("threads", [1, 2, 3, 8])
def test_ranges_cover_every_case_once_in_order(n_cases, threads):
    ranges = case_ranges(n_cases, threads)
    covered = [i for start, stop in ranges for i in range(start, stop)]
    assert covered == list(range(n_cases))
    assert all(stop > start for start, stop in ranges)


@numba.njit(nogil=True)
def _square_roots(start, stop, x, out):
    for i in range(start, stop):
        out[i] = np.sqrt(x[i])


def test_a_compiled_kernel_gives_the_same_answers_on_one_and_two_threads():
    x = np.random.default_rng(3).uniform(0.0, 9.0, 5000)
    default = numba.get_num_threads()
    answers = []
    for threads in (1, min(2, numba.config.NUMBA_NUM_THREADS)):
        numba.set_num_threads(threads)
        try:
            out = np.full_like(x, np.nan)
            run_case_ranges(_square_roots, x.size, x, out)
            answers.append(out)
        finally:
            numba.set_num_threads(default)
    assert np.array_equal(answers[0], np.sqrt(x)) and np.array_equal(answers[0], answers[-1])


def test_an_error_in_a_range_is_raised_and_the_ranges_not_started_are_dropped():
    if numba.config.NUMBA_NUM_THREADS < 2:
        pytest.skip("needs two numba threads")
    started, lock = [], threading.Lock()

    def kernel(start, stop):
        with lock:
            started.append(start)
        if start == 0:
            raise ValueError("bad case")

    default = numba.get_num_threads()
    numba.set_num_threads(2)
    try:
        with pytest.raises(ValueError, match="bad case"):
            run_case_ranges(kernel, 100_000)
    finally:
        numba.set_num_threads(default)
    assert len(started) < len(case_ranges(100_000, 2))
