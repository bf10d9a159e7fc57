"""Shared timing helper of the benchmarks (run them as scripts from the repo root)."""
from __future__ import annotations

import time


def best_of(repeat: int, function):
    """(best wall time [s] over ``repeat`` calls, the last call's return value)."""
    times, value = [], None
    for _ in range(repeat):
        start = time.perf_counter()
        value = function()
        times.append(time.perf_counter() - start)
    return min(times), value
