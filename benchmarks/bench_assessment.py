"""A full engine assessment: N items x the 18 records x 2 directions, as the main job runs it.

Run: python benchmarks/bench_assessment.py [--items 1000] [--threads N] [--baseline-blocks 2000] [--building STOREYS]
     [--yielding]

Items are drawn from a seeded generator spanning a laboratory inventory:
height 0.8-2.4 m, width and depth 0.4-1.2 m, centre of mass at mid-height,
μ_s uniform in [0.10, 0.70] and μ = μ_s (so some items slide, some rock and
some slide-rock). Records: pyslammer's 18 sample records (test/benchmark-only
dependency), used as floor motions. Every case goes through
``assess.mechanics.engine.simulate_cases``, which picks the solver per case;
the run is done twice and the second (compiled, cached) time is reported:

* seconds, and cases per second;
* cases per solver, the seconds spent in each solver and their share (the
  rocking kernel's include the runs it hands on to the general solver);
* block-steps per second (a block-step: one block over one sample interval of
  its record; the run-out after the record is not counted), overall and per
  solver, against a plain compiled loop (numba, one explicit stick-slip update
  per sample per block, threads over blocks; ``bench_sliding.py``): the
  baseline of what the hardware does with the simplest possible kernel;
* the engine against the compiled-loop limit of the physics each case needs: the
  same cases, each by the simplest compiled loop of its physics, threads over
  cases. A case the sliding kernel ran: the plain stick-slip loop. A case the
  rocking kernel or the general solver ran: the plain rocking loop of
  ``bench_rocking.py`` (fixed Runge-Kutta steps, impacts at the step where θ
  changes sign, not located, no rest logic, stopped at overturning), at p·h ≤ 0.01
  (the step at which bench_rocking compares it with the kernel) and at p·h ≤ 0.1
  (the kernel's own largest step: the stricter limit, as no loop without event
  location is that accurate at that step). A slide-rock case has the rocking loop
  as its limit, though it also slides: a limit lower than its physics.

With ``--building STOREYS`` the items stand on the floors of a building of that many storeys (3.6 m
each, a steel moment frame, T1 from ASCE 7 Table 12.8-2, 5 % damping: :mod:`assess.building`), item i
on floor i mod (STOREYS + 1), and run under the 18 records passed through the building to their floor
(the time to make the floor histories is printed apart). With ``--yielding`` as well, the building
yields: the records go through its yielding stick (:func:`assess.building.yielding.yielding_building`,
strength from the ASCE 7-22 §12.8 design at S_DS 1.0 g, S_D1 0.6 g, Risk Category II, a steel moment frame's
default overstrength 2.5;
the records as recorded, unscaled), and the floor histories' time, the motions that yielded the building
and the largest storey ductility are printed.

Not a test.
"""
from __future__ import annotations

import argparse
import time
from collections import Counter

import numba
import numpy as np

from bench_rocking import plain_one_at

from assess.mechanics.block import Block
from assess.mechanics.engine import GENERAL, ROCKING_KERNEL, SLIDING_KERNEL, simulate_cases
from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2


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


def plain_loop_block_steps_per_s(records, dts, n_blocks, repeat=3):
    """Block-steps per second of the plain compiled stick-slip loop on ``n_blocks`` blocks x the records."""
    from bench_sliding import plain_loop_parallel

    lengths = np.array([r.size for r in records], dtype=np.int64)
    accel_2d = np.zeros((len(records), lengths.max()))
    for j, record in enumerate(records):
        accel_2d[j, :record.size] = record
    mu = np.random.default_rng(1).uniform(0.10, 0.70, n_blocks)
    dt = np.asarray(dts, dtype=float)
    plain_loop_parallel(accel_2d, lengths, dt, mu, STANDARD_GRAVITY_M_S2)  # compile or load
    best = np.inf
    for _ in range(repeat):
        start = time.perf_counter()
        plain_loop_parallel(accel_2d, lengths, dt, mu, STANDARD_GRAVITY_M_S2)
        best = min(best, time.perf_counter() - start)
    return n_blocks * int(lengths.sum()) / best


@numba.njit(cache=True)
def _plain_sliding_one(accel, dt, mu, gravity):
    """bench_sliding's plain stick-slip loop for one block under one record: peak |u|."""
    u = v = top = 0.0
    for k in range(accel.size):
        a = accel[k]
        if v == 0.0:
            if abs(a) <= mu:
                continue
            direction = -1.0 if a > 0.0 else 1.0
        else:
            direction = 1.0 if v > 0.0 else -1.0
        v_new = v - gravity * (a + direction * mu) * dt
        if v_new * direction < 0.0:
            v_new = 0.0
        u += 0.5 * (v + v_new) * dt
        v = v_new
        top = max(top, abs(u))
    return top


@numba.njit(cache=True, parallel=True)
def _plain_cases(accel_flat, offsets, dts, record, rocks, mu, alpha, p, e, step, gravity):
    """Each case by the plain loop of its physics (``rocks``: the rocking loop, else the sliding one)."""
    out = np.empty(record.size)
    for c in numba.prange(record.size):
        j = record[c]
        accel = accel_flat[offsets[j]:offsets[j + 1]]
        if rocks[c]:
            out[c] = plain_one_at(accel, dts[j], alpha[c], p[c], e[c], step)
        else:
            out[c] = _plain_sliding_one(accel, dts[j], mu[c], gravity)
    return out


def physics_limit_seconds(blocks, records, dts, index, solver, step, repeat=2):
    """Seconds the plain loops of each case's physics take for all the cases (best of ``repeat``)."""
    flat = np.concatenate([np.asarray(r, dtype=float) for r in records])
    offsets = np.concatenate(([0], np.cumsum([r.size for r in records]))).astype(np.int64)
    dts = np.asarray(dts, dtype=float)
    rocks = solver != SLIDING_KERNEL
    mu = np.array([b.mu for b in blocks])
    alpha = np.array([b.alpha_rad for b in blocks])
    p = np.array([b.p_rad_s for b in blocks])
    e = np.array([b.restitution_effective for b in blocks])
    args = (flat, offsets, dts, np.asarray(index, dtype=np.int64), rocks, mu, alpha, p, e, step,
            STANDARD_GRAVITY_M_S2)
    _plain_cases(*args)  # compile or load
    best = np.inf
    for _ in range(repeat):
        start = time.perf_counter()
        _plain_cases(*args)
        best = min(best, time.perf_counter() - start)
    return best


def floor_histories(records, dts, storeys, yielding=False):
    """The records through a building of ``storeys`` storeys: one list of every floor's histories (floor-major)."""
    from assess.building import building_modes, floor_records
    from assess.building.yielding import yielding_building, yielding_histories
    from assess.hazard.records import Record

    modes = building_modes(storeys, 3.6, system="steel moment frame")
    ground = [Record(np.asarray(r, dtype=float), dt, f"record {k}") for k, (r, dt) in enumerate(zip(records, dts))]
    floor_records(modes, ground[:1], floors=[storeys])  # compile or load
    what = f"{modes.n_modes} modes"
    if yielding:
        building = yielding_building(modes, "steel moment frame", sds_g=1.0, sd1_g=0.6)
        yielding_histories(building, [Record(ground[0].accel_g[:10], ground[0].dt_s, "warm")])  # compile or load
        start = time.perf_counter()
        by_floor, histories = yielding_histories(building, ground)
        seconds = time.perf_counter() - start
        what = (f"yielding stick (V_y {building.strength.yield_base_shear_g:.3f} W): "
                f"{sum(not h.elastic for h in histories)} of {len(ground)} records yield it, largest storey "
                f"ductility {max(h.ductility.max() for h in histories):.1f}")
    else:
        start = time.perf_counter()
        by_floor = floor_records(modes, ground)
        seconds = time.perf_counter() - start
    print(f"building: {storeys} storeys, T1 {modes.periods_s[0]:.2f} s, {what}; floor histories of "
          f"{len(ground)} records x {storeys + 1} floors in {seconds:.3f} s")
    out = [record for floor in sorted(by_floor) for record in by_floor[floor]]
    return [r.accel_g for r in out], [r.dt_s for r in out], storeys + 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--items", type=int, default=1000)
    parser.add_argument("--threads", type=int, default=numba.config.NUMBA_NUM_THREADS)
    parser.add_argument("--baseline-blocks", type=int, default=2000,
                        help="blocks of the plain compiled loop (x the 18 records)")
    parser.add_argument("--building", type=int, metavar="STOREYS",
                        help="items on the floors of a building of STOREYS storeys, under the records through it")
    parser.add_argument("--yielding", action="store_true", help="with --building: the building yields")
    args = parser.parse_args()
    numba.set_num_threads(args.threads)
    names, records, dts = load_records()
    n_records = len(records)
    floors = 1
    if args.building:
        records, dts, floors = floor_histories(records, dts, args.building, args.yielding)
    height, width, depth, mu = draw_items(args.items)
    blocks, index = [], []
    for j in range(n_records):
        for i in range(args.items):
            for base in (width[i], depth[i]):
                blocks.append(Block(half_width_m=base / 2, cg_height_m=height[i] / 2, height_m=height[i], mu=mu[i]))
                index.append((i % floors) * n_records + j)
    index = np.asarray(index)
    samples = np.array([r.size for r in records])
    print(f"{args.items} items x {n_records} records x 2 directions = {len(blocks)} cases; "
          f"{samples.sum()} record samples; {args.threads} threads")
    for attempt in ("first run (includes compilation or cache load)", "second run"):
        by_solver = {}
        start, start_cpu = time.perf_counter(), time.process_time()
        peaks = simulate_cases(blocks, records, dts, index, seconds_by_solver=by_solver)
        seconds, cpu_s = time.perf_counter() - start, time.process_time() - start_cpu
        print(f"{attempt}: {seconds:.1f} s ({len(blocks) / seconds:,.0f} cases/s; {cpu_s:.1f} CPU s, "
              f"{cpu_s / seconds:.2f} cores busy)")
    counts = Counter(peaks.solver.tolist())
    steps_by_solver = {name: int(samples[index[peaks.solver == name]].sum()) for name in counts}
    print(f"{'solver':<24} {'cases':>7} {'share':>6} {'seconds':>8} {'share':>6} {'CPU s':>7} {'share':>6} "
          f"{'block-steps/s':>14}")
    for name in (SLIDING_KERNEL, ROCKING_KERNEL, GENERAL):
        solver_s, solver_cpu = by_solver.get(name, (0.0, 0.0))
        rate = steps_by_solver.get(name, 0) / solver_s if solver_s > 0 else float("nan")
        print(f"{name:<24} {counts.get(name, 0):>7} {counts.get(name, 0) / len(blocks):>6.1%} {solver_s:>8.2f} "
              f"{solver_s / seconds:>6.1%} {solver_cpu:>7.2f} {solver_cpu / cpu_s:>6.1%} {rate:>14.3e}")
    other = seconds - sum(w for w, _ in by_solver.values())
    other_cpu = cpu_s - sum(c for _, c in by_solver.values())
    print(f"{'(dispatch, outside them)':<24} {'':>7} {'':>6} {other:>8.2f} {other / seconds:>6.1%} "
          f"{other_cpu:>7.2f} {other_cpu / cpu_s:>6.1%}")
    engine_rate = int(samples[index].sum()) / seconds
    baseline = plain_loop_block_steps_per_s(records, dts, args.baseline_blocks)
    print(f"block-steps per second: engine {engine_rate:.3e} overall; plain compiled loop {baseline:.3e} "
          f"({args.baseline_blocks} blocks x {len(records)} records); the engine at {engine_rate / baseline:.1%} "
          "of the plain loop")
    for step in (0.01, 0.1):
        limit = physics_limit_seconds(blocks, records, dts, index, peaks.solver, step)
        print(f"the compiled-loop limit of each case's physics (rocking loop at p·h <= {step:g}): {limit:.2f} s; "
              f"the engine at {seconds / limit:.1f}x it")
    modes = Counter(peaks.mode.tolist())
    print("modes: " + ", ".join(f"{k} {v}" for k, v in sorted(modes.items())))
    print(f"overturned: {int(peaks.overturned.sum())}")


if __name__ == "__main__":
    main()
