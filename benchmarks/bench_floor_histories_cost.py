"""Cost of the building's floor histories: 11 ground motions through a 12-storey building, every floor.

Run: python benchmarks/bench_floor_histories_cost.py   (needs pyslammer for its records)

The first 11 of pyslammer's sample records (in name order) through a 12-storey concrete moment frame
(T_1 1.4 s, all 12 modes, 5 % damping): every floor's absolute acceleration history as records, the
best of 5 runs after the compiled kernels are loaded.
"""
import os
import time

import pyslammer

from assess.building import building_modes, floor_records
from assess.hazard.records import read_record


def main():
    folder = os.path.join(os.path.dirname(pyslammer.__file__), "sample_ground_motions")
    suite = [read_record(os.path.join(folder, name)) for name in sorted(os.listdir(folder))[:11]]
    modes = building_modes(12, 3.5, system="concrete moment frame", period_s=1.4)
    floor_records(modes, suite[:1])  # compile, or load numba's cache
    times = []
    for _ in range(5):
        start = time.perf_counter()
        floor_records(modes, suite)
        times.append(time.perf_counter() - start)
    samples = sum(record.accel_g.size for record in suite)
    print(f"{len(suite)} motions ({samples} samples) x {modes.storeys} floors, {modes.n_modes} modes: "
          f"best of 5 {min(times) * 1000:.1f} ms, worst {max(times) * 1000:.1f} ms")


if __name__ == "__main__":
    main()
