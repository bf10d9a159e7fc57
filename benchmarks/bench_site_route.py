"""The site-and-building route on buildings of every kind the docs accept: does every run end well?

Builds workbooks for three lateral systems (shear wall, braced frame, steel moment frame) of 1, 5 and 20
storeys (4 m each), with and without ``period_s``, each with a cabinet on the ground and on the roof, on the
site of inventories/seattle-hospital.xlsx (ASCE 7-22, S_DS 1.1 g, S_D1 0.6 g, site class D), runs
``assess WORKBOOK --hazard DE,MCE_R --seed S --format xlsx`` for each seed, and prints every run's exit
status, the worst motion's largest deviation from its target (ground_motions.csv ``max_deviation``) and the
suite means' lowest ratio to the target (spectrum.csv, in the range).

    python benchmarks/bench_site_route.py --seeds 0-9 --suite-size 11

Nothing is asserted: it prints what the issue's note quotes.
"""
from __future__ import annotations

import argparse
import itertools
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pandas as pd
from openpyxl import Workbook

SYSTEMS = ("shear wall", "braced frame", "steel moment frame")
STOREYS = (1, 5, 20)
#: period_s given where the case asks for one [s], by storeys (a stiff low building, a mid-rise, a tall one).
PERIODS_S = {1: 0.15, 5: 0.6, 20: 2.5}


def workbook(path: Path, system: str, storeys: int, period_s: float | None, suite_size: int | None) -> None:
    book = Workbook()
    sheet = book.active
    sheet.title = "equipment"
    header = ["id", "name", "floor", "height_m", "width_m", "depth_m", "mass_kg", "mu", "clearance_cm", "anchored"]
    sheet.append(header)
    sheet.append(["C-0", "cabinet, ground", 0, 1.8, 0.9, 0.45, 200, 0.35, 10, "no"])
    sheet.append(["C-R", "cabinet, roof", storeys, 1.8, 0.9, 0.45, 200, 0.35, 10, "no"])
    site = book.create_sheet("site")
    site.append(["key", "value"])
    for row in (("code", "ASCE 7-22"), ("sds_g", 1.1), ("sd1_g", 0.6), ("site_class", "D"), ("risk_category", "IV")):
        site.append(list(row))
    if suite_size:
        site.append(["suite_size", suite_size])
    building = book.create_sheet("building")
    building.append(["key", "value"])
    for row in (("storeys", storeys), ("storey_height_m", 4.0), ("system", system)):
        building.append(list(row))
    if period_s:
        building.append(["period_s", period_s])
    book.save(path)


def seeds(text: str) -> list[int]:
    low, _, high = text.partition("-")
    return list(range(int(low), int(high or low) + 1))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", default="0-9")
    parser.add_argument("--suite-size", type=int, default=None, help="default: the route's own")
    parser.add_argument("--levels", default="DE,MCE_R")
    parser.add_argument("--only", default="", help="run only the workbooks whose name holds this text")
    args = parser.parse_args(argv)
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for system, storeys, with_period in itertools.product(SYSTEMS, STOREYS, (False, True)):
            path = Path(folder) / f"{system.replace(' ', '-')}-{storeys}-{'T' if with_period else 'noT'}.xlsx"
            if args.only not in path.stem:
                continue
            workbook(path, system, storeys, PERIODS_S[storeys] if with_period else None, args.suite_size)
            for seed in seeds(args.seeds):
                out = Path(folder) / f"{path.stem}-{seed}"
                tick = time.perf_counter()
                run = subprocess.run([sys.executable, "-m", "assess", str(path), "--hazard", args.levels, "--seed",
                                      str(seed), "--format", "xlsx", "--out", str(out), "--quiet"],
                                     capture_output=True, text=True)
                worst, mean_min = float("nan"), float("nan")
                if run.returncode == 0:
                    ground = pd.concat(pd.read_csv(p) for p in out.glob("*/ground_motions.csv"))
                    spectrum = pd.concat(pd.read_csv(p) for p in out.glob("*/spectrum.csv"))
                    worst = ground["max_deviation"].max()
                    mean_min = spectrum.loc[spectrum["in_range"], "ratio"].min()
                rows.append(dict(system=system, storeys=storeys, period_s=with_period, seed=seed,
                                 exit=run.returncode, worst_deviation=worst, mean_ratio_min=mean_min,
                                 seconds=time.perf_counter() - tick,
                                 error=run.stderr.strip().splitlines()[-1][:120] if run.returncode else ""))
                print(f"{path.stem:32s} seed {seed}: exit {run.returncode}, worst deviation {worst:.3f}, "
                      f"suite mean >= {mean_min:.3f} of the target, {rows[-1]['seconds']:.1f} s {rows[-1]['error']}",
                      flush=True)
    table = pd.DataFrame(rows)
    print(f"\n{len(table)} runs: exit 0 for {(table['exit'] == 0).sum()}; worst deviation "
          f"{table['worst_deviation'].max():.3f}; lowest suite-mean ratio {table['mean_ratio_min'].min():.3f}")


if __name__ == "__main__":
    main()
