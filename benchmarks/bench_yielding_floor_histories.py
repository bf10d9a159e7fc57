"""Cost of the yielding building's floor histories: 11 ground motions through a 12-storey stick, every floor.

Run: python benchmarks/bench_yielding_floor_histories.py [--storeys 12,24,48,96]   (needs pyslammer for its records)

The first 11 of pyslammer's sample records (in name order), each scaled so that its 5 % S_a(T_1) is the
design spectrum's (S_DS 1.0 g, S_D1 0.6 g) at T_1 1.4 s, through a 12-storey stick designed by ASCE 7-22
§12.8 (Risk Category II, the system's default overstrength: 2.5 for steel moment frames, 2 for the
others): a steel special moment frame (bilinear springs) and a concrete
special moment frame (pinching springs), Rayleigh 5 % on the tangent stiffness, and a concrete shear
wall (its elastic model on a pinching base hinge, assess/building/wall_hinge.py; the ductility then the
wall's at its base), Newmark/Newton at substeps of at most 1 ms (shorter where the stick's shortest period
asks). Prints the compile-or-load time, the best and worst of 3 runs, the
median first-storey ductility, and the elastic modal route's time on the same suite for scale.

With ``--storeys``: how the cost grows with the height, the reason for the most storeys the yielding model
takes (``MAX_YIELDING_STOREYS`` of assess/inventory/site_building.py): for each number of storeys (4 m
storeys, T_1 ASCE 7-22's T_a of the system, the same design), the seconds one ground motion (the first
record, at the design spectrum at that T_1) takes per 30 s of shaking, best of 2, each system.
Measured (2 cores, 2026-11-29): per 30 s of shaking at 12 / 24 / 40 / 48 storeys, steel moment frames 0.07 /
0.50 / 3.1 / 6.1 s, concrete moment frames 0.14 / 0.74 / 3.6 / 6.5 s, braced frames 0.29 / 2.3 / 14 / 28 s,
eccentrically braced 0.19 / 1.5 / 9.6 / 18 s, shear walls 0.25 / 1.2 / 4.8 / 8.0 s, ``other`` 0.09 / 0.26 / 0.69 /
1.0 s.
"""
import argparse
import os
import time

import numpy as np
import pyslammer

from assess.building import building_modes, floor_records
from assess.building.design import design_strength
from assess.building.nonlinear import yielding_response, yielding_stick
from assess.building.wall_hinge import HingedWall, hinged_wall_response
from assess.hazard.records import read_record
from assess.site.asce7 import design_spectral_acceleration_g
from assess.site.spectrum import pseudo_acceleration_spectrum

STOREYS, PERIOD_S = 12, 1.4


def suite_at_design(period_s):
    folder = os.path.join(os.path.dirname(pyslammer.__file__), "sample_ground_motions")
    out = []
    target = float(design_spectral_acceleration_g(period_s, 1.0, 0.6))
    for name in sorted(os.listdir(folder))[:11]:
        record = read_record(os.path.join(folder, name))
        have = float(np.atleast_1d(pseudo_acceleration_spectrum(record.accel_g, record.dt_s, [period_s]))[0])
        out.append((np.asarray(record.accel_g) * target / have, record.dt_s))
    return out


def height_sweep(storey_counts):
    """Seconds per 30 s of shaking of one ground motion through the yielding stick, by storeys and system."""
    from assess.building.period import approximate_period
    for storeys in storey_counts:
        heights = 4.0 * np.arange(1, storeys + 1)
        for system in ("steel moment frame", "concrete moment frame", "braced frame", "eccentrically braced frame",
                       "shear wall", "other"):
            period_s = float(approximate_period(heights[-1], system))
            accel, dt = suite_at_design(period_s)[0]
            strength = design_strength(system, np.ones(storeys), heights, period_s, sds_g=1.0, sd1_g=0.6)
            stick = yielding_stick(storeys, 4.0, strength.storey_yield_ratio, system=system, period_s=period_s)
            respond = hinged_wall_response if isinstance(stick, HingedWall) else yielding_response
            respond(stick, accel[:10], dt)  # compile or load
            times = []
            for _ in range(2):
                start = time.perf_counter()
                respond(stick, accel, dt)
                times.append(time.perf_counter() - start)
            per_30_s = min(times) * 30.0 / (accel.size * dt)
            print(f"{storeys} storeys, {system} (T_1 {period_s:.2f} s): {per_30_s:.2f} s per 30 s of shaking",
                  flush=True)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--storeys", default="", help="comma-separated storey counts: the height sweep instead")
    args = parser.parse_args(argv)
    if args.storeys:
        height_sweep([int(n) for n in args.storeys.split(",")])
        return
    suite = suite_at_design(PERIOD_S)
    samples = sum(accel.size for accel, _ in suite)
    duration = sum(accel.size * dt for accel, dt in suite)
    heights = 3.5 * np.arange(1, STOREYS + 1)
    for system in ("steel moment frame", "concrete moment frame", "shear wall"):
        strength = design_strength(system, np.ones(STOREYS), heights, PERIOD_S, sds_g=1.0, sd1_g=0.6)
        stick = yielding_stick(STOREYS, 3.5, strength.storey_yield_ratio, system=system, period_s=PERIOD_S)
        respond = hinged_wall_response if isinstance(stick, HingedWall) else yielding_response
        start = time.perf_counter()
        respond(stick, suite[0][0][:10], suite[0][1])
        compile_s = time.perf_counter() - start
        times = []
        for _ in range(3):
            start = time.perf_counter()
            results = [respond(stick, accel, dt) for accel, dt in suite]
            times.append(time.perf_counter() - start)
        ductility = np.median([r.ductility[0] for r in results])
        unconverged = sum(r.unconverged_steps for r in results)
        print(f"{system} ({stick.law}): {len(suite)} motions ({samples} samples, {duration:.0f} s of shaking) x "
              f"{STOREYS} storeys: best of 3 {min(times):.2f} s, worst {max(times):.2f} s "
              f"(compile or cache load {compile_s:.1f} s); median first-storey ductility {ductility:.1f}; "
              f"unconverged substeps {unconverged}")
    modes = building_modes(STOREYS, 3.5, system="concrete moment frame", period_s=PERIOD_S)
    from assess.hazard.records import Record
    records = [Record(accel, dt, f"m{i}") for i, (accel, dt) in enumerate(suite)]
    floor_records(modes, records[:1])
    start = time.perf_counter()
    floor_records(modes, records)
    print(f"elastic modal route, same suite: {(time.perf_counter() - start) * 1000:.0f} ms")


if __name__ == "__main__":
    main()
