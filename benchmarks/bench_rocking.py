"""Throughput of the pure-rocking kernel: block-steps per second, peaks only.

Run: python benchmarks/bench_rocking.py [--blocks 1 100 10000]
Beside it, a plain compiled loop (fixed RK4 steps, impacts not located, no
rest logic, same threads) shows how close the kernel is to the simplest loop.
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


@numba.njit(cache=True)
def _plain_one(accel, dt, alpha, p, e):
    """The simplest compiled rocking loop: fixed RK4 steps (p h <= 0.01), impacts at the
    step where theta changes sign (not located), no rest logic. Peak |theta|/alpha."""
    return plain_one_at(accel, dt, alpha, p, e, 0.01)


@numba.njit(cache=True)
def plain_one_at(accel, dt, alpha, p, e, step):
    """:func:`_plain_one` with fixed RK4 steps of p h <= ``step``."""
    n_sub = max(1, int(np.ceil(p * dt / step)))
    h = p * dt / n_sub
    theta, w, side, peak = 0.0, 0.0, 1.0, 0.0
    for k in range(accel.size - 1):
        for m in range(n_sub):
            a = accel[k] + (accel[k + 1] - accel[k]) * m / n_sub
            if theta == 0.0 and w == 0.0:
                if abs(a) <= np.tan(alpha):
                    continue
                side = -1.0 if a > 0.0 else 1.0
            k1 = -(np.sin(alpha * side - theta) + a * np.cos(alpha * side - theta))
            th2 = theta + 0.5 * h * w
            k2 = -(np.sin(alpha * side - th2) + a * np.cos(alpha * side - th2))
            th3 = theta + 0.5 * h * (w + 0.5 * h * k1)
            k3 = -(np.sin(alpha * side - th3) + a * np.cos(alpha * side - th3))
            th4 = theta + h * (w + 0.5 * h * k2)
            k4 = -(np.sin(alpha * side - th4) + a * np.cos(alpha * side - th4))
            theta_new = theta + h * w + h * h / 6.0 * (k1 + k2 + k3)
            w = w + h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)
            if theta_new * side < 0.0:
                theta_new, w, side = 0.0, e * w, -side
            theta = theta_new
            peak = max(peak, abs(theta))
            if peak >= 0.5 * np.pi:
                return peak / alpha
    return peak / alpha


@numba.njit(cache=True, parallel=True)
def plain_loop(accel_flat, offsets, dts, alpha, p, e):
    out = np.empty((alpha.size, dts.size))
    for job in numba.prange(alpha.size * dts.size):
        j, i = job // alpha.size, job % alpha.size
        out[i, j] = _plain_one(accel_flat[offsets[j]:offsets[j + 1]], dts[j], alpha[i], p[i], e[i])
    return out


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
    flat = np.concatenate(records)
    offsets = np.concatenate(([0], np.cumsum([r.size for r in records]))).astype(np.int64)
    dts_array = np.asarray(dts, dtype=float)
    plain_loop(flat, offsets, dts_array, alpha, p, 1.0 - 1.5 * np.sin(alpha) ** 2)
    for n in args.blocks:
        alpha, p = blocks(n, rng)
        tracemalloc.start()
        start = time.perf_counter()
        peaks = rocking_peaks_batch(records, dts, alpha, p)
        seconds = time.perf_counter() - start
        _, traced_peak = tracemalloc.get_traced_memory()
        tracemalloc.stop()
        steps = n * intervals
        start = time.perf_counter()
        plain = plain_loop(flat, offsets, dts_array, alpha, p, 1.0 - 1.5 * np.sin(alpha) ** 2)
        plain_seconds = time.perf_counter() - start
        print(f"{n:6d} blocks x {len(records)} records: {seconds:8.2f} s, {steps / seconds / 1e6:7.2f} M block-steps/s, "
              f"overturned {peaks.overturned.mean():.1%}, uplift {peaks.uplift.mean():.1%}, "
              f"peak traced memory {traced_peak / 2**20:.1f} MiB; plain compiled loop {plain_seconds:.2f} s "
              f"({steps / plain_seconds / 1e6:.2f} M block-steps/s, kernel/plain time {seconds / plain_seconds:.2f}; "
              f"plain-loop peaks differ from the kernel's by a median "
              f"{np.median(np.abs(plain - peaks.theta_max_over_alpha)):.3f} alpha)")
    try:
        import pyslammer
        motions = [m for _, m in sorted(pyslammer.sample_ground_motions().items())]
        start = time.perf_counter()
        for motion in motions:
            pyslammer.RigidAnalysis(0.2, motion).max_sliding_disp
        per_py = (time.perf_counter() - start) / len(motions)
        print(f"pyslammer RigidAnalysis (one-way sliding, a different problem, for scale): "
              f"{per_py * 1e3:.2f} ms/analysis; rocking kernel with {n} blocks: "
              f"{seconds / (n * len(records)) * 1e3:.3f} ms/analysis ({per_py / (seconds / (n * len(records))):.0f}x)")
    except ImportError:
        pass
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"process peak RSS {rss:.0f} MiB")


if __name__ == "__main__":
    main()
