"""A full engine assessment: N items x the 18 records x 2 directions, as the main job runs it.

Run: python benchmarks/bench_assessment.py [--items 1000] [--threads N]

Items are drawn from a seeded generator spanning a laboratory inventory:
height 0.8-2.4 m, width and depth 0.4-1.2 m, centre of mass at mid-height,
μ_s uniform in [0.10, 0.70] and μ = μ_s (so some items slide, some rock and
some slide-rock). Records: pyslammer's 18 sample records (test/benchmark-only
dependency), used as floor motions. Every case goes through
``assess.mechanics.engine.simulate_cases``, which picks the solver per case;
the run is done twice and the second (compiled, cached) time is reported,
with the count of cases per solver and the seconds spent in each. Not a test.
"""
from __future__ import annotations

import argparse
import time
from collections import Counter

import numba
import numpy as np

from assess.mechanics.block import Block
from assess.mechanics.engine import simulate_cases


def load_records():
    import pyslammer
    motions = pyslammer.sample_ground_motions()
    names = sorted(motions)
    return names, [np.asarray(motions[n].accel, dtype=float) for n in names], [float(motions[n].dt) for n in names]


def draw_items(n, seed=2010):
    rng = np.random.default_rng(seed)
    height = rng.uniform(0.8, 2.4, n)
    width, depth = rng.uniform(0.4, 1.2, n), rng.uniform(0.4, 1.2, n)
    mu = rng.uniform(0.10, 0.70, n)
    return height, width, depth, mu


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--items", type=int, default=1000)
    parser.add_argument("--threads", type=int, default=numba.config.NUMBA_NUM_THREADS)
    args = parser.parse_args()
    numba.set_num_threads(args.threads)
    names, records, dts = load_records()
    height, width, depth, mu = draw_items(args.items)
    blocks, index = [], []
    for j in range(len(records)):
        for i in range(args.items):
            for base in (width[i], depth[i]):
                blocks.append(Block(half_width_m=base / 2, cg_height_m=height[i] / 2, height_m=height[i], mu=mu[i]))
                index.append(j)
    samples = sum(r.size for r in records)
    print(f"{args.items} items x {len(records)} records x 2 directions = {len(blocks)} cases; "
          f"{samples} record samples; {args.threads} threads")
    for attempt in ("first run (includes compilation or cache load)", "second run"):
        start = time.perf_counter()
        peaks = simulate_cases(blocks, records, dts, index)
        seconds = time.perf_counter() - start
        print(f"{attempt}: {seconds:.1f} s")
    counts = Counter(peaks.solver.tolist())
    modes = Counter(peaks.mode.tolist())
    print("cases per solver: " + ", ".join(f"{k} {v}" for k, v in sorted(counts.items())))
    print("modes: " + ", ".join(f"{k} {v}" for k, v in sorted(modes.items())))
    print(f"overturned: {int(peaks.overturned.sum())}")


if __name__ == "__main__":
    main()
