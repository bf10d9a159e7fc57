"""assess batch on the sample portfolio: what a first run, an unchanged re-run, an edited item and a
hazard-curve update cost, and how many simulations each one ran.

Run: python benchmarks/bench_batch.py [--format html,pdf,xlsx] [--keep DIR]

Copies inventories/portfolio/ into a scratch folder and runs, each as a user
would (``python -m assess batch portfolio.xlsx --out out``):

1. the first run (nothing cached);
2. the same again, nothing changed;
3. one item edited in one workbook (north-lab.xlsx, REF-G-02: mu 0.20 -> 0.25);
4. the hazard curve updated (every building's oq_hazard -> site-hazard-updated.csv).

For each: wall-clock seconds, cases simulated and reused (portfolio.csv), rows
of changes.csv. Wall-clock time depends on the machine and its load; the case
counts do not. ``--overhead`` instead times the cache itself on the issue's
large assessment (10,000 items x 18 records x 2 directions = 360,000 cases;
the engine replaced by a runner that returns zeros): keying, looking up and
storing every case, all misses then all hits. Not a test.
"""
from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import openpyxl
import pandas as pd

ROOT = Path(__file__).resolve().parents[1]
SAMPLE = ROOT / "inventories" / "portfolio"


def run_batch(folder: Path, formats: str) -> tuple[float, list[str]]:
    command = [sys.executable, "-m", "assess", "batch", "portfolio.xlsx", "--out", "out", "--format", formats]
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")])}
    started = time.perf_counter()
    completed = subprocess.run(command, cwd=folder, capture_output=True, text=True, env=env)
    seconds = time.perf_counter() - started
    if completed.returncode != 0:
        raise SystemExit(f"{' '.join(command)} exited {completed.returncode}:\n{completed.stderr}")
    return seconds, command


def set_cell(path: Path, sheet: str, match: tuple[str, str], column: str, value) -> None:
    """Set ``column`` of the rows whose ``match[0]`` column holds ``match[1]`` (every row when match is None)."""
    book = openpyxl.load_workbook(path)
    rows = book[sheet]
    header = [cell.value for cell in rows[1]]
    for row in rows.iter_rows(min_row=2):
        if match is None or row[header.index(match[0])].value == match[1]:
            row[header.index(column)].value = value
    book.save(path)


def report(step: str, seconds: float, folder: Path) -> dict:
    table = pd.read_csv(folder / "out" / "portfolio.csv")
    changes = pd.read_csv(folder / "out" / "changes.csv", dtype=str, keep_default_na=False)
    row = dict(step=step, seconds=round(seconds, 1), simulated=int(table["cases_simulated"].sum()),
               reused=int(table["cases_reused"].sum()),
               per_building=" ".join(f"{b}:{s}/{s + r}" for b, s, r in
                                     zip(table["building"], table["cases_simulated"], table["cases_reused"])),
               changes=len(changes))
    print(f"{step:<28} {row['seconds']:>6.1f} s  simulated {row['simulated']:>4}  reused {row['reused']:>4}  "
          f"[{row['per_building']}]  changes.csv rows {row['changes']}", flush=True)
    return row


def cache_overhead(n_items: int = 10_000, n_records: int = 18, samples: int = 4000) -> None:
    import numpy as np

    from assess.mechanics.block import Block
    from assess.command.cache import CachingRunner
    from assess.mechanics.engine import CasePeaks

    class Zeros:  # no engine: what is timed is the cache alone
        def simulate_cases(self, blocks, records_g, dt_s, record_index, *, tail_s, progress=None):
            n = len(blocks)
            return CasePeaks(np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n, bool), np.zeros(n, bool),
                             np.full(n, "slide"), np.full(n, "sliding kernel"))

    rng = np.random.default_rng(2010)
    blocks = [Block(half_width_m=rng.uniform(0.2, 0.6), cg_height_m=1.0, height_m=2.0, mu=rng.uniform(0.1, 0.7))
              for _ in range(2 * n_items)]  # an item in each of its two directions
    records = [rng.normal(size=samples) * 0.1 for _ in range(n_records)]
    cases = [b for _ in records for b in blocks]
    index = np.repeat(np.arange(n_records), len(blocks))
    with tempfile.TemporaryDirectory() as folder:
        for label in ("all misses", "all hits"):
            runner = CachingRunner(Zeros(), folder)
            started = time.perf_counter()
            runner.simulate_cases(cases, records, [0.01] * n_records, index, tail_s=10.0)
            print(f"{label}: {len(cases):,} cases in {time.perf_counter() - started:.2f} s "
                  f"(simulated {runner.cases_simulated:,}, reused {runner.cases_reused:,})")
        size = sum(p.stat().st_size for p in Path(folder).glob("*.npz"))
        print(f"cache folder: {size / 1e6:.1f} MB")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--format", default="html,pdf,xlsx")
    parser.add_argument("--keep", type=Path, help="keep the scratch folder here")
    parser.add_argument("--overhead", action="store_true", help="time the cache alone on 360,000 cases")
    args = parser.parse_args()
    if args.overhead:
        cache_overhead()
        return
    scratch = Path(tempfile.mkdtemp(prefix="bench-batch-"))
    folder = scratch / "portfolio"
    shutil.copytree(SAMPLE, folder, ignore=shutil.ignore_patterns("build_portfolio.py"))
    print(f"in {folder}: python -m assess batch portfolio.xlsx --out out --format {args.format}")
    rows = []
    seconds, _ = run_batch(folder, args.format)
    rows.append(report("1 first run", seconds, folder))
    seconds, _ = run_batch(folder, args.format)
    rows.append(report("2 nothing changed", seconds, folder))
    set_cell(folder / "north-lab.xlsx", "equipment", ("id", "REF-G-02"), "mu", 0.25)
    seconds, _ = run_batch(folder, args.format)
    rows.append(report("3 one item edited", seconds, folder))
    print((folder / "out" / "changes.csv").read_text())
    set_cell(folder / "portfolio.xlsx", "buildings", None, "oq_hazard", "site-hazard-updated.csv")
    seconds, _ = run_batch(folder, args.format)
    rows.append(report("4 hazard curve updated", seconds, folder))
    print((folder / "out" / "changes.csv").read_text())
    if args.keep:
        shutil.rmtree(args.keep, ignore_errors=True)
        shutil.copytree(folder, args.keep)
    shutil.rmtree(scratch, ignore_errors=True)


if __name__ == "__main__":
    main()
