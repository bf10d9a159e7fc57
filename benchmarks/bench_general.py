"""Throughput of the general solver (Moreau-Jean time stepping) on pyslammer's 18 records.

Run: python benchmarks/bench_general.py [--blocks 1 100 10000]

Blocks are drawn from a seeded generator in the slide-rock region, where the
general solver is the one the engine uses: height 1-2.4 m, b/h 0.15-0.45,
μ = μ_s between b/h and 1.6 b/h (they uplift, and many slip at the pivot).
Peaks only (``time_stepping_peaks_batch``, threads over block x record pairs).
A block-step is one *sample interval* of one record for one block (the solver
takes at least 4 steps per interval, more for small blocks; the run-out of
10 s after each record is included in the time but not in the count).
Also prints pyslammer's one-way rigid analysis per analysis on the same
records in the same run, and the peak memory of the largest run. Not a test.
"""
from __future__ import annotations

import argparse
import resource
import time
import tracemalloc

import numba
import numpy as np

from assess.mechanics.block import Block
from assess.mechanics.timestepping import time_stepping_peaks_batch
from timing import best_of


def draw_blocks(n, rng):
    height = rng.uniform(1.0, 2.4, n)
    b_over_h = rng.uniform(0.15, 0.45, n)
    mu = b_over_h * rng.uniform(1.0, 1.6, n)
    return [Block(half_width_m=t * h / 2, cg_height_m=h / 2, height_m=h, mu=m)
            for h, t, m in zip(height, b_over_h, mu)]


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--blocks", type=int, nargs="+", default=[1, 100, 10_000])
    args = parser.parse_args()
    import pyslammer
    motions = [m for _, m in sorted(pyslammer.sample_ground_motions().items())]
    records = [np.asarray(m.accel, dtype=float) for m in motions]
    dts = [float(m.dt) for m in motions]
    intervals = sum(r.size - 1 for r in records)
    print(f"{len(records)} pyslammer records, {intervals} sample intervals in all; "
          f"numba threads: {numba.get_num_threads()}")
    rng = np.random.default_rng(11)
    time_stepping_peaks_batch(draw_blocks(2, rng), records[:1], dts[:1])  # compile or load from cache
    per_analysis = None
    for n in args.blocks:
        blocks = draw_blocks(n, rng)
        tracemalloc.start()
        start = time.perf_counter()
        peaks = time_stepping_peaks_batch(blocks, records, dts)
        seconds = time.perf_counter() - start
        _, traced = tracemalloc.get_traced_memory()
        tracemalloc.stop()
        per_analysis = seconds / (n * len(records))
        modes = {m: float(np.mean(peaks.mode == m)) for m in ("slide", "rock", "slide-rock", "rest")}
        print(f"{n:6d} blocks x {len(records)} records: {seconds:8.2f} s, "
              f"{n * intervals / seconds / 1e6:6.2f} M block-steps/s, {per_analysis * 1e3:.2f} ms/analysis, "
              f"overturned {peaks.overturned.mean():.0%}, modes "
              + ", ".join(f"{k} {v:.0%}" for k, v in modes.items())
              + f"; traced peak {traced / 2**20:.1f} MiB")
    t_py, _ = best_of(1, lambda: [pyslammer.RigidAnalysis(0.2, m).max_sliding_disp for m in motions])
    py_per = t_py / len(motions)
    print(f"pyslammer RigidAnalysis (one-way sliding only): {py_per * 1e3:.2f} ms/analysis; "
          f"general solver / pyslammer per analysis: {per_analysis / py_per:.2f}")
    print(f"process peak RSS {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024:.0f} MiB")


if __name__ == "__main__":
    main()
