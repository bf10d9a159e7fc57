"""Throughput of the pure-rocking kernel: block-steps per second, peaks only.

Run: python benchmarks/bench_rocking.py [--blocks 1 100 10000]
Records: the 18 sample records shipped with pyslammer, read with pyslammer's own
loader (pyslammer is a test/benchmark-only dependency); without pyslammer,
18 seeded synthetic records of the same lengths class (said so in the output).
A block-step is one sample interval of one record for one block. Blocks are
drawn from a seeded generator: α in [0.1, 0.4] rad, p in [1, 5] rad/s. The peak
memory of the largest run is the tracemalloc peak of the Python-side arrays
(numpy reports its allocations to tracemalloc) and the process peak RSS. Not a test.
"""
from __future__ import annotations

import argparse
import resource
import time
import tracemalloc

import numba
import numpy as np

from assess.mechanics.rocking import rocking_peaks_batch


def load_records():
    try:
        import pyslammer
    except ImportError:
        rng = np.random.default_rng(2010)
        records, dts = [], []
        for _ in range(18):
            dt = 0.005
            n = int(rng.integers(2000, 12000))
            t = np.arange(n) * dt
            accel = np.zeros(n)
            for f, ph, a in zip(rng.uniform(0.3, 8, 20), rng.uniform(0, 2 * np.pi, 20), rng.uniform(0.1, 1, 20)):
                accel += a * np.sin(2 * np.pi * f * t + ph)
            accel *= np.minimum(1, t / 2) * np.exp(-np.maximum(t - 10, 0) / 4)
            records.append(rng.uniform(0.2, 1.0) * accel / np.abs(accel).max())
            dts.append(dt)
        return records, dts, "18 synthetic records (pyslammer not installed), seeded generator"
    motions = pyslammer.sample_ground_motions()
    names = sorted(motions)
    return ([np.asarray(motions[k].accel, dtype=float) for k in names], [motions[k].dt for k in names],
            f"{len(names)} pyslammer sample records (accelerations in g)")


def blocks(n, rng):
    return rng.uniform(0.1, 0.4, n), rng.uniform(1.0, 5.0, n)


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--blocks", type=int, nargs="+", default=[1, 100, 10_000])
    args = parser.parse_args()
    records, dts, source = load_records()
    intervals = sum(r.size - 1 for r in records)
    print(f"records: {source}; {intervals} sample intervals in all; numba threads: {numba.get_num_threads()}")
    rng = np.random.default_rng(7)
    alpha, p = blocks(2, rng)
    rocking_peaks_batch(records[:1], dts[:1], alpha, p)  # compile or load from cache
    for n in args.blocks:
        alpha, p = blocks(n, rng)
        tracemalloc.start()
        start = time.perf_counter()
        peaks = rocking_peaks_batch(records, dts, alpha, p)
        seconds = time.perf_counter() - start
        _, traced_peak = tracemalloc.get_traced_memory()
        tracemalloc.stop()
        steps = n * intervals
        print(f"{n:6d} blocks x {len(records)} records: {seconds:8.2f} s, {steps / seconds / 1e6:7.2f} M block-steps/s, "
              f"overturned {peaks.overturned.mean():.1%}, uplift {peaks.uplift.mean():.1%}, "
              f"peak traced memory {traced_peak / 2**20:.1f} MiB")
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"process peak RSS {rss:.0f} MiB")


if __name__ == "__main__":
    main()
