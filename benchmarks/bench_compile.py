"""What a first run after install spends compiling: the main job on inventories/lab.xlsx with an empty numba cache.

Run: python benchmarks/bench_compile.py [--hazard 2in50] [--no-warmup]

In a fresh process with NUMBA_CACHE_DIR set to an empty folder, reads the
workbook and runs the assessment (no report), listening to numba's compile
events; prints the seconds of every outermost compile (what a kernel costs,
its callees included), their sum, and the assessment's wall time. Then runs
the same again on the filled cache (a later run). ``--no-warmup`` keeps the
general solver from compiling in a second process (assess.mechanics.warmup),
to see what that saves. Not a test.
"""
from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import textwrap
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

PROBE = textwrap.dedent("""
    import sys, time
    from numba.core import event
    compiles, depth = [], [0]

    class Listener(event.Listener):
        def on_start(self, ev):
            depth[0] += 1
            ev.data["started"] = time.perf_counter()

        def on_end(self, ev):
            depth[0] -= 1
            if depth[0] == 0:
                func = ev.data["dispatcher"].py_func
                compiles.append((time.perf_counter() - ev.data["started"], f"{func.__module__}.{func.__qualname__}"))

    event.register("numba:compile", Listener())
    start = time.perf_counter()
    from assess.assessment.pipeline import run_assessment
    from assess.command.job import open_runner
    from assess.inventory import read_workbook
    if sys.argv[3] == "no-warmup":
        from assess.mechanics import warmup
        warmup.start = lambda: None
    imported = time.perf_counter()
    with open_runner(None, lambda message: None) as runner:
        run_assessment(read_workbook(sys.argv[1]), sys.argv[2], runner=runner)
    done = time.perf_counter()
    for seconds, name in sorted(compiles, reverse=True):
        print(f"  compile {seconds:6.2f} s  {name}")
    print(f"  compiling, outermost calls summed {sum(s for s, _ in compiles):6.2f} s")
    print(f"  imports {imported - start:6.2f} s, read + assess {done - imported:6.2f} s")
""")


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--hazard", default="2in50")
    parser.add_argument("--no-warmup", action="store_true")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as cache:
        env = dict(os.environ, NUMBA_CACHE_DIR=cache)
        for run in ("first run (empty cache)", "later run (filled cache)"):
            print(run)
            subprocess.run([sys.executable, "-c", PROBE, str(ROOT / "inventories" / "lab.xlsx"), args.hazard,
                            "no-warmup" if args.no_warmup else "warmup"], env=env, check=True)


if __name__ == "__main__":
    main()
