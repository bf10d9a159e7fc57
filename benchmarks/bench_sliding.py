"""Speed of the exact two-way sliding kernel on pyslammer's 18 sample records.

Run: python benchmarks/bench_sliding.py [--blocks 1 100 10000] [--repeat 3]

Prints, for 1, 100 and 10,000 blocks (μ drawn uniformly in [0.05, 0.30], seeded)
× the 18 records (peaks only, ``sliding_peaks_batch``):

* block-steps per second of the exact event-driven kernel (assess.mechanics.sliding;
  serial for 1 block, threads over blocks from 2 x threads up);
* the same for a plain compiled loop (numba, one explicit step per sample, no event
  location, same parallel layout): how far the kernel is from the simplest loop;
* seconds per analysis (one block, one record) of pyslammer's one-way rigid
  analysis on the same records in the same run, and the speed-up per analysis;
* peak memory of the 10,000-block run (process peak RSS growth, and the Python-side
  allocations traced by tracemalloc).

pyslammer (GPL) is only called, as a peer; it is a test dependency. Not a test.
"""
from __future__ import annotations

import argparse
import os
import resource
import tracemalloc

import numpy as np
from numba import njit, prange, get_num_threads

from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2
from assess.mechanics.sliding import sliding_peaks_batch
from timing import best_of


@njit(cache=True)
def plain_loop_block(accel_2d, lengths, dt, mu, gravity, peak, i):
    """Simplest compiled stick-slip loop: one explicit step per sample, no event location."""
    for r in range(accel_2d.shape[0]):
        u = v = top = 0.0
        h = dt[r]
        for k in range(lengths[r]):
            a = accel_2d[r, k]
            if v == 0.0:
                if abs(a) <= mu[i]:
                    continue
                direction = -1.0 if a > 0.0 else 1.0
            else:
                direction = 1.0 if v > 0.0 else -1.0
            v_new = v - gravity * (a + direction * mu[i]) * h
            if v_new * direction < 0.0:
                v_new = 0.0
            u += 0.5 * (v + v_new) * h
            v = v_new
            top = max(top, abs(u))
        peak[i, r] = top


@njit(cache=True, parallel=True)
def plain_loop_parallel(accel_2d, lengths, dt, mu, gravity):
    peak = np.empty((mu.shape[0], accel_2d.shape[0]))
    for i in prange(mu.shape[0]):
        plain_loop_block(accel_2d, lengths, dt, mu, gravity, peak, i)
    return peak


@njit(cache=True)
def plain_loop_serial(accel_2d, lengths, dt, mu, gravity):
    peak = np.empty((mu.shape[0], accel_2d.shape[0]))
    for i in range(mu.shape[0]):
        plain_loop_block(accel_2d, lengths, dt, mu, gravity, peak, i)
    return peak


def plain_loop_batch(accel_2d, lengths, dt, mu, gravity):
    """Same dispatch as sliding_peaks_batch: serial below twice the thread count."""
    kernel = plain_loop_parallel if mu.shape[0] >= 2 * get_num_threads() else plain_loop_serial
    return kernel(accel_2d, lengths, dt, mu, gravity)


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--blocks", type=int, nargs="+", default=[1, 100, 10_000])
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()

    import pyslammer

    motions = [m for _, m in sorted(pyslammer.sample_ground_motions().items())]
    records = [np.asarray(m.accel, dtype=float) for m in motions]
    lengths = np.array([r.size for r in records], dtype=np.int64)
    accel_2d = np.zeros((len(records), lengths.max()))
    for i, r in enumerate(records):
        accel_2d[i, :r.size] = r
    dt = np.array([m.dt for m in motions])
    steps_per_block = int((lengths - 1).sum())
    rng = np.random.default_rng(2010)
    print(f"{len(records)} records, {steps_per_block} steps per block, {get_num_threads()} numba threads, "
          f"load average {os.getloadavg()[0]:.2f} at start (other work on the cores slows the threaded rows)")

    # compile (or load the cache) outside the timings
    sliding_peaks_batch(accel_2d, dt, [0.1], record_lengths=lengths)
    sliding_peaks_batch(accel_2d, dt, np.full(8, 0.1), record_lengths=lengths)
    plain_loop_batch(accel_2d, lengths, dt, np.array([0.1]), STANDARD_GRAVITY_M_S2)
    plain_loop_batch(accel_2d, lengths, dt, np.full(8, 0.1), STANDARD_GRAVITY_M_S2)

    print(f"{'blocks':>7} {'exact kernel':>22} {'plain loop':>22} {'exact/plain':>11} {'s/analysis':>11}")
    per_analysis = {}
    for n_blocks in args.blocks:
        mu = rng.uniform(0.05, 0.30, n_blocks)
        repeat = args.repeat if n_blocks <= 1000 else 1
        if n_blocks == max(args.blocks):
            rss_before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
            tracemalloc.start()
        t_exact, (peak, _) = best_of(repeat, lambda: sliding_peaks_batch(accel_2d, dt, mu, record_lengths=lengths))
        if n_blocks == max(args.blocks):
            _, traced_peak = tracemalloc.get_traced_memory()
            tracemalloc.stop()
            rss_growth = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - rss_before
            memory = (n_blocks, traced_peak, rss_growth, peak.nbytes)
        t_plain, plain = best_of(repeat, lambda: plain_loop_batch(accel_2d, lengths, dt, mu, STANDARD_GRAVITY_M_S2))
        block_steps = n_blocks * steps_per_block
        per_analysis[n_blocks] = t_exact / (n_blocks * len(records))
        print(f"{n_blocks:>7} {block_steps / t_exact:>16.3e} st/s {block_steps / t_plain:>16.3e} st/s "
              f"{t_plain / t_exact:>11.2f} {per_analysis[n_blocks]:>11.2e}")
        if n_blocks >= 100:
            gap = np.abs(plain - peak)
            print(f"{'':>7} plain loop vs exact peaks: median |diff| {np.median(gap) * 1e3:.3f} mm, "
                  f"max {gap.max() * 1e3:.2f} mm")

    # pyslammer's one-way rigid analysis, one analysis per record, same records
    mu_py = 0.1
    t_py, _ = best_of(args.repeat, lambda: [pyslammer.RigidAnalysis(mu_py, m).max_sliding_disp for m in motions])
    py_per_analysis = t_py / len(motions)
    print(f"\npyslammer RigidAnalysis (one-way, mu={mu_py}): {py_per_analysis:.2e} s/analysis, "
          f"{steps_per_block / t_py:.3e} steps/s")
    for n_blocks, seconds in per_analysis.items():
        print(f"  speed-up per analysis of the exact kernel with {n_blocks:>6} blocks: {py_per_analysis / seconds:8.1f}x"
              f"  (two-way, exact, vs one-way time-stepping)")
    n_blocks, traced_peak, rss_growth, result_bytes = memory
    print(f"\nmemory of the {n_blocks}-block run: peak RSS growth {rss_growth / 1024:.1f} MiB "
          f"(ru_maxrss, includes first-touch of numba's result arrays), Python-side tracemalloc peak "
          f"{traced_peak / 2**20:.2f} MiB; each result array {result_bytes / 2**20:.2f} MiB; "
          f"the records themselves {accel_2d.nbytes / 2**20:.2f} MiB")


if __name__ == "__main__":
    main()
