"""The engine on a Dask cluster against this machine's threads at equal cores: throughput, CPU, memory, same numbers.

Run: python benchmarks/bench_distributed.py [--items 1000] [--workers 2] [--repeat 5] [--scheduler ADDRESS]
                                            [--tasks-per-thread N] [--cold-cache]

The cases are those of ``bench_assessment.py`` (N items x pyslammer's 18
records x 2 directions). They run on this machine with as many numba threads
as there are workers (``assess.mechanics.engine.simulate_cases``), and
through :class:`assess.mechanics.distributed.DaskRunner` on a loopback
cluster of ``--workers`` worker processes (one thread and one numba thread
each) started here, or on the cluster at ``--scheduler``. Each is run once to
warm up (the first run on the cluster includes the workers' loading, with
``--cold-cache`` compiling, of the numba kernels), then ``--repeat`` times,
the two alternating so that a change in the machine's load falls on both;
the median and the fastest run are reported. Prints cases per second, the
CPU seconds spent in the workers, in this process (the client; a loopback
scheduler runs in it too) and in the scheduler, each worker's peak resident
memory, the load average before and after, and whether every number of every
case is identical. Not a test.
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


def load():
    """The 1, 5 and 15 minute load averages, as text."""
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def main():
    import numba
    import numpy as np

    from assess.mechanics.distributed import TASKS_PER_THREAD, DaskRunner
    from assess.mechanics.engine import simulate_cases

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--items", type=int, default=1000)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--repeat", type=int, default=5, help="timed runs of each, after one warm-up run")
    parser.add_argument("--scheduler", metavar="ADDRESS", help="an existing cluster (default: a loopback one)")
    parser.add_argument("--tasks-per-thread", type=int, default=TASKS_PER_THREAD)
    parser.add_argument("--cold-cache", action="store_true",
                        help="the loopback workers compile the kernels into an empty numba cache")
    args = parser.parse_args()
    print(f"load average before: {load()} ({os.cpu_count()} cores)")
    blocks, records, dts, index = cases(args.items)
    n = len(blocks)
    print(f"{args.items} items x {len(records)} records x 2 directions = {n} cases")

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
    runner = DaskRunner.connect(address, tasks_per_thread=args.tasks_per_thread)
    try:
        client = runner.client
        workers = client.nthreads()
        threads = sum(workers.values())
        numba.set_num_threads(min(threads, numba.config.NUMBA_NUM_THREADS))
        local_label = f"this machine ({numba.get_num_threads()} numba threads)"
        cluster_label = f"Dask ({len(workers)} workers, {threads} threads)"
        print("numba in the workers (threads, cache folder or '' beside the package):",
              ", ".join(map(str, set(client.run(numba_config).values()))))
        scheduler_pid = client.run_on_scheduler(os.getpid)
        scheduler_here = scheduler_pid == os.getpid()
        before_memory = client.run(peak_rss_mb)

        def local_run():
            return simulate_cases(blocks, records, dts, index)

        def cluster_run():
            return runner.simulate_cases(blocks, records, dts, index)

        clock = {"local": [], "cluster": []}
        cpu = {"local": 0.0, "workers": 0.0, "here": 0.0, "scheduler": 0.0}
        for attempt in range(args.repeat + 1):
            start, start_here = time.perf_counter(), cpu_s()
            serial = local_run()
            wall = time.perf_counter() - start
            if attempt:
                clock["local"].append(wall)
                cpu["local"] += cpu_s() - start_here
            else:
                print(f"{local_label}: warm-up run {wall:.2f} s")
            tasks_before = runner.tasks_run
            workers_cpu = sum(client.run(cpu_s).values())
            scheduler_cpu = client.run_on_scheduler(cpu_s)
            start, start_here = time.perf_counter(), cpu_s()
            remote = cluster_run()
            wall = time.perf_counter() - start
            here = cpu_s() - start_here
            tasks = runner.tasks_run - tasks_before
            if attempt:
                clock["cluster"].append(wall)
                cpu["here"] += here
                cpu["workers"] += sum(client.run(cpu_s).values()) - workers_cpu
                cpu["scheduler"] += client.run_on_scheduler(cpu_s) - scheduler_cpu
            else:
                print(f"{cluster_label}: warm-up run {wall:.2f} s (the workers load the kernels), {tasks} tasks")
        after_memory = client.run(peak_rss_mb)
    finally:
        runner.close()
        if cluster is not None:
            cluster.close()

    repeat = max(1, args.repeat)
    median = {k: float(np.median(v)) for k, v in clock.items()}
    fastest = {k: min(v) for k, v in clock.items()}
    print(f"{local_label}: median {median['local']:.2f} s, fastest {fastest['local']:.2f} s of {repeat} runs; "
          f"{cpu['local'] / repeat:.2f} CPU s a run")
    where = ("client and scheduler: one process here" if scheduler_here else "client")
    print(f"{cluster_label}: median {median['cluster']:.2f} s, fastest {fastest['cluster']:.2f} s of {repeat} runs; "
          f"{cpu['workers'] / repeat:.2f} CPU s a run in the workers, {cpu['here'] / repeat:.2f} here ({where})"
          + ("" if scheduler_here else f", {cpu['scheduler'] / repeat:.2f} in the scheduler")
          + f"; {tasks} tasks a run")
    local_rate, cluster_rate = n / median["local"], n / median["cluster"]
    print(f"throughput (medians): this machine {local_rate:,.0f} cases/s, Dask {cluster_rate:,.0f} cases/s: "
          f"the cluster at {100 * cluster_rate / local_rate:.0f} % of the threads "
          f"(fastest runs: {100 * fastest['local'] / fastest['cluster']:.0f} %)")
    spent = cpu["workers"] + cpu["here"] + (0.0 if scheduler_here else cpu["scheduler"])
    print(f"work per CPU second (a measure the machine's other load does not change much): this machine "
          f"{n * repeat / cpu['local']:,.0f} cases per CPU s, Dask {n * repeat / spent:,.0f} "
          f"(workers, client and scheduler): {100 * cpu['local'] / spent:.0f} %")
    for worker in sorted(after_memory):
        print(f"  worker {worker}: peak resident memory {after_memory[worker]:.0f} MB "
              f"(after start-up {before_memory[worker]:.0f} MB)")
    print(f"this process: peak resident memory {peak_rss_mb():.0f} MB")
    same = all(np.array_equal(getattr(serial, f), getattr(remote, f)) for f in FIELDS)
    print(f"identical numbers (every field of all {n} cases): {'yes' if same else 'NO'}")
    print(f"load average after: {load()}")
    os._exit(0 if same else 1)  # the cluster's threads need not be waited for


if __name__ == "__main__":
    main()
