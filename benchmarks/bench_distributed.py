"""The engine on a Dask cluster against this machine: throughput, memory per worker, same numbers.

Run: python benchmarks/bench_distributed.py [--items 1000] [--workers 2] [--scheduler ADDRESS]
                                            [--cases-per-task N] [--cold-cache]

The cases are those of ``bench_assessment.py`` (N items x pyslammer's 18
records x 2 directions). They run once serially on this machine
(``assess.mechanics.engine.simulate_cases``, all numba threads) and once
through :class:`assess.mechanics.distributed.DaskRunner` on a loopback
cluster of ``--workers`` worker processes (one thread and one numba thread
each) started here, or on the cluster at ``--scheduler``. Each is run twice
and the second (warm) run is reported; the first run on the cluster includes
the workers' loading (``--cold-cache``: compiling) of the numba kernels.
Prints cases per second, each worker's peak resident memory and whether
every number of every case is identical. Not a test.
"""
from __future__ import annotations

import argparse
import os
import resource
import sys
import tempfile
import time
from pathlib import Path

# numba, numpy and assess are imported inside the functions: the loopback workers start by importing
# this module (multiprocessing's spawn), and numba must first see the environment they are given


FIELDS = ("sliding_max_m", "sliding_residual_m", "theta_max_over_alpha", "uplift", "overturned", "mode", "solver")


def cases(n_items):
    import numpy as np

    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from bench_assessment import draw_items, load_records

    from assess.mechanics.block import Block

    names, records, dts = load_records()
    height, width, depth, mu = draw_items(n_items)
    blocks, index = [], []
    for j in range(len(records)):
        for i in range(n_items):
            for base in (width[i], depth[i]):
                blocks.append(Block(half_width_m=base / 2, cg_height_m=height[i] / 2, height_m=height[i], mu=mu[i]))
                index.append(j)
    return blocks, records, dts, np.asarray(index)


def peak_rss_mb():
    """Peak resident memory of the calling process [MB]: VmHWM of /proc/self/status (Linux).

    Not ru_maxrss: Linux carries it over an exec, so a spawned worker would start with its parent's.
    """
    try:
        with open("/proc/self/status") as status:
            for line in status:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) / 1024.0
    except OSError:
        pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def numba_config():
    import numba
    return numba.config.NUMBA_NUM_THREADS, numba.config.CACHE_DIR


def cpu_s():
    """CPU time of the calling process so far [s], all its threads."""
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


def timed(run, label, cpu=None):
    """(peaks, wall seconds, CPU seconds) of the second of two runs; ``cpu()`` reads the workers' CPU clock."""
    seconds = []
    for attempt in range(2):
        start, start_cpu, start_here = time.perf_counter(), cpu() if cpu else 0.0, cpu_s()
        peaks = run()
        seconds.append(time.perf_counter() - start)
    here = cpu_s() - start_here
    used = (cpu() - start_cpu) if cpu else here
    where = f"{used:.1f} CPU s in the workers, {here:.1f} CPU s here (client and scheduler)" if cpu \
        else f"{used:.1f} CPU s"
    print(f"{label}: first run {seconds[0]:.1f} s, second run {seconds[1]:.1f} s ({where})")
    return peaks, seconds[1], used


def main():
    import numba
    import numpy as np

    from assess.mechanics.distributed import DaskRunner
    from assess.mechanics.engine import simulate_cases

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--items", type=int, default=1000)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--scheduler", metavar="ADDRESS", help="an existing cluster (default: a loopback one)")
    parser.add_argument("--cases-per-task", type=int, help="default: DaskRunner's")
    parser.add_argument("--cold-cache", action="store_true",
                        help="the loopback workers compile the kernels into an empty numba cache")
    args = parser.parse_args()
    blocks, records, dts, index = cases(args.items)
    n = len(blocks)
    print(f"{args.items} items x {len(records)} records x 2 directions = {n} cases")

    serial, serial_s, _ = timed(lambda: simulate_cases(blocks, records, dts, index),
                             f"this machine ({numba.config.NUMBA_NUM_THREADS} numba threads)")

    cluster = None
    address = args.scheduler
    if address is None:
        from distributed import LocalCluster
        env = {"NUMBA_NUM_THREADS": "1"}
        if args.cold_cache:
            env["NUMBA_CACHE_DIR"] = tempfile.mkdtemp(prefix="numba-cold-")
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                               dashboard_address=None, env=env, silence_logs=40)
        address = cluster.scheduler_address
    runner = DaskRunner.connect(address) if args.cases_per_task is None else DaskRunner.connect(
        address, cases_per_task=args.cases_per_task)
    try:
        workers = runner.client.scheduler_info()["workers"]
        numba_setup = set(runner.client.run(numba_config).values())
        print("numba in the workers (threads, cache folder or '' beside the package):",
              ", ".join(map(str, numba_setup)))
        threads = sum(w["nthreads"] for w in workers.values())
        before = runner.client.run(peak_rss_mb)
        remote, remote_s, _ = timed(lambda: runner.simulate_cases(blocks, records, dts, index),
                                    f"Dask at {address} ({len(workers)} workers, {threads} threads)",
                                    cpu=lambda: sum(runner.client.run(cpu_s).values()))
        after = runner.client.run(peak_rss_mb)
    finally:
        runner.close()
        if cluster is not None:
            cluster.close()

    print(f"throughput: this machine {n / serial_s:,.0f} cases/s, Dask {n / remote_s:,.0f} cases/s "
          f"(tasks of {runner.cases_per_task} cases, {runner.tasks_run // 2} per run)")
    for worker in sorted(after):
        print(f"  worker {worker}: peak resident memory {after[worker]:.0f} MB "
              f"(after start-up {before[worker]:.0f} MB)")
    print(f"this process: peak resident memory {peak_rss_mb():.0f} MB")
    same = all(np.array_equal(getattr(serial, f), getattr(remote, f)) for f in FIELDS)
    print(f"identical numbers (every field of all {n} cases): {'yes' if same else 'NO'}")
    os._exit(0 if same else 1)  # the cluster's threads need not be waited for


if __name__ == "__main__":
    main()
