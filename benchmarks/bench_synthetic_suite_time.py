"""Time a synthetic ground suite of 11 motions (assess.site.suite.synthetic_suite) and check it.

Run: python benchmarks/bench_synthetic_suite_time.py [--repeat 1]

For the ASCE 7 design spectrum SDS 1.0 g, SD1 0.6 g, TL 8 s (level DE) and the periods that matter
0.35, 0.7 and 1.4 s (range 0.07-2.8 s): the wall time of one suite of 11 (after a warm-up of the
compiled spectrum loop), then per motion the attempts, the smallest and largest Sa/target on 1500
log-spaced periods (the tests' dense check), the end velocity and displacement, and a SHA-256 of
the suite's bytes (the same on every rerun and machine). Not a test.

Measured on the shared 2-core machine (2026-11-26): 31.2 s before the spectrum loop ran all periods
together and the matching stopped at its acceptance (commit e15ef4b, sha256 69b0f44e5c75f3a0), 2.54 s
after (2.54, 2.56, 2.54 s over three suites; sha256 11e7153ceccc9fc2).
"""
from __future__ import annotations

import argparse
import hashlib
import time

import numpy as np

from assess.site import asce7, suite
from assess.site.spectrum import pseudo_acceleration_spectrum

PERIODS_THAT_MATTER_S = [0.35, 0.7, 1.4]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=1)
    args = parser.parse_args()
    target = asce7.from_design_values(1.0, 0.6, 8.0)
    pseudo_acceleration_spectrum(np.zeros(10), 0.01, [0.1, 0.2])  # compile / load the cached loop
    times = []
    for _ in range(args.repeat):
        tick = time.perf_counter()
        built = suite.synthetic_suite(target.design_g, PERIODS_THAT_MATTER_S, level="DE")
        times.append(time.perf_counter() - tick)
    print(f"suite of {len(built.motions)} synthetic motions: {' '.join(f'{t:.2f}' for t in times)} s")
    grid = np.geomspace(built.lower_s, built.upper_s, 1500)
    digest = hashlib.sha256()
    for motion in built.motions:
        record = motion.first
        digest.update(record.accel_g.tobytes())
        ratio = pseudo_acceleration_spectrum(record.accel_g, record.dt_s, grid) / target.design_g(grid)
        v = np.concatenate([[0], np.cumsum(0.5 * (record.accel_g[1:] + record.accel_g[:-1]) * record.dt_s)])
        d = np.concatenate([[0], np.cumsum(0.5 * (v[1:] + v[:-1]) * record.dt_s)])
        print(f"  {motion.name}: {record.accel_g.size} samples, Sa/target {ratio.min():.3f}-{ratio.max():.3f}, "
              f"PGA {record.pta_g:.3f} g, end v {v[-1]:.1e} d {d[-1]:.1e} g s^n")
    print(f"sha256 of the suite: {digest.hexdigest()[:16]}")


if __name__ == "__main__":
    main()
