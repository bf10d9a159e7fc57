"""Cases spread over threads: compiled kernels that release the GIL, run by a pool of Python threads.

Each solver's batch entry point is a compiled loop over a range of cases,
``kernel(start, stop, *arrays)``, compiled with ``nogil=True`` and writing
case i's answers at index i of its output arrays. :func:`run_case_ranges`
cuts the cases into short ranges and hands them to as many threads as numba
may use (``numba.get_num_threads()``, which ``--jobs`` sets), a range at a
time, so that long and short runs balance.

Why not numba's ``parallel=True`` and ``prange``: compiling a parallel region
costs about as much again as compiling the loop it runs (measured on the
engine's three kernels: 5.8 s of the 20 s a first run spends compiling,
``benchmarks/bench_compile.py``), and a parallel region cannot be interrupted:
Ctrl-C waits for the whole batch. Here a range takes milliseconds, the
remaining ranges are dropped on an exception, and the answers do not depend
on the number of threads (every case is computed alone, by the same code).
"""
from __future__ import annotations

import threading

import numba

#: Most cases in one range handed to a thread [-] (fewer when there are few cases per thread).
MAX_CASES_PER_RANGE = 32
#: Ranges per thread aimed at, at least, so that the last ones to finish are short [-].
RANGES_PER_THREAD = 16


def case_ranges(n_cases: int, threads: int) -> list[tuple[int, int]]:
    """Consecutive (start, stop) ranges covering ``range(n_cases)``, short enough to balance ``threads``.

    >>> case_ranges(10, 1)
    [(0, 10)]
    >>> case_ranges(10, 2)
    [(0, 1), (1, 2), (2, 3), (3, 4), (4, 5), (5, 6), (6, 7), (7, 8), (8, 9), (9, 10)]
    >>> len(case_ranges(100_000, 2)), case_ranges(100_000, 2)[-1]
    (3125, (99968, 100000))
    """
    if n_cases <= 0:
        return []
    if threads <= 1:
        return [(0, n_cases)]
    size = max(1, min(MAX_CASES_PER_RANGE, n_cases // (threads * RANGES_PER_THREAD)))
    return [(start, min(start + size, n_cases)) for start in range(0, n_cases, size)]


def run_case_ranges(kernel, n_cases: int, *args) -> None:
    """Run ``kernel(start, stop, *args)`` over every case, on ``numba.get_num_threads()`` threads.

    ``kernel`` must be compiled with ``nogil=True`` and write case i's answers
    at index i only, so that ranges never share an output element. The calling
    thread is one of the threads; each takes the next range not yet taken. An
    exception in a range, or a KeyboardInterrupt (it reaches the calling
    thread between two of its ranges), stops every thread before its next
    range and is raised once the running ranges have finished.
    """
    threads = numba.get_num_threads()
    ranges = case_ranges(n_cases, threads)
    if len(ranges) <= 1:  # one thread, or too few cases to share
        for start, stop in ranges:
            kernel(start, stop, *args)
        return
    pending, lock, errors = iter(ranges), threading.Lock(), []

    def work():
        try:
            while not errors:
                with lock:
                    taken = next(pending, None)
                if taken is None:
                    return
                kernel(taken[0], taken[1], *args)
        except BaseException as error:  # noqa: B902 — handed to the calling thread, which raises it
            errors.append(error)

    helpers = [threading.Thread(target=work, name=f"assess-cases-{k}", daemon=True) for k in range(threads - 1)]
    for helper in helpers:
        helper.start()
    work()
    try:
        for helper in helpers:
            helper.join()
    except BaseException as error:  # Ctrl-C while the last ranges run: the others take no new one
        errors.append(error)
        for helper in helpers:
            helper.join()
        raise
    if errors:
        raise errors[0]
