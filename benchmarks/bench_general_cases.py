"""The general solver alone, on the cases the engine hands it in the assessment benchmark.

Run: python benchmarks/bench_general_cases.py [--items 2000] [--every 1] [--repeat 2]

The items of ``bench_assessment.py`` (same seed) under pyslammer's 18 records x 2 directions go through
``simulate_cases``; the cases it answers with the general solver are then run again by
``time_stepping_case_peaks`` alone (every ``--every``-th of them), ``--repeat`` times, and the best CPU
time (all threads) is printed, with cases per CPU second. CPU seconds, not wall seconds: on a shared
machine they move less with the load. Run it with ``NUMBA_NUM_THREADS=1`` to compare code versions
per case. Not a test.
"""
from __future__ import annotations

import argparse
import time

import numba
import numpy as np

from assess.mechanics.block import Block
from assess.mechanics.engine import GENERAL, simulate_cases
from assess.mechanics.timestepping import time_stepping_case_peaks
from bench_assessment import draw_items, load_records


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--items", type=int, default=2000)
    parser.add_argument("--every", type=int, default=1)
    parser.add_argument("--repeat", type=int, default=2)
    args = parser.parse_args()
    _, records, dts = load_records()
    height, width, depth, mu = draw_items(args.items)
    blocks, index = [], []
    for j in range(len(records)):
        for i in range(args.items):
            for base in (width[i], depth[i]):
                blocks.append(Block(half_width_m=base / 2, cg_height_m=height[i] / 2, height_m=height[i], mu=mu[i]))
                index.append(j)
    index = np.asarray(index)
    solver = simulate_cases(blocks, records, dts, index).solver
    cases = np.flatnonzero(solver == GENERAL)[::args.every]
    general = [blocks[i] for i in cases]
    best = np.inf
    for _ in range(args.repeat):
        start = time.process_time()
        time_stepping_case_peaks(general, records, dts, index[cases])
        best = min(best, time.process_time() - start)
    print(f"{cases.size} general cases of {len(blocks)} ({args.items} items), {numba.get_num_threads()} threads: "
          f"best of {args.repeat} {best:.2f} CPU s, {cases.size / best:,.0f} cases per CPU s")


if __name__ == "__main__":
    main()
