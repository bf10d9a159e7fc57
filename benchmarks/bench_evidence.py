"""How much evidence a synthetic suite gives an item's class, and whether its intervals are honest.

For a workbook with a ``site`` sheet (default: inventories/seattle-hospital.xlsx), assesses every item at a
level with suites of several sizes (the same realisations: motion k is the same in every suite, so a suite
of 120 is the first 120 of the largest), and prints

* per size: the share of assessed items whose 90 % intervals span more than one class (``risk_range``), and
  the run's time;
* coverage: for each smaller suite, the share of (item, failure mode) intervals that hold the probability the
  largest suite gives (its point estimate, from ``--reference`` motions: 10 times the default by default).

    python benchmarks/bench_evidence.py --level MCE_R --sizes 11,120 --reference 1200

Nothing here is asserted: it prints what docs/guide.md (the `site` sheet's suite size) and the issue's note quote.
"""
from __future__ import annotations

import argparse
import dataclasses
import time
from pathlib import Path

import numpy as np

from assess.assessment.pipeline import run_assessment
from assess.inventory.workbook import read_workbook

MODES = ("p_overturn", "p_beyond_clearance", "p_rocking_harm")


def assess(inventory, level: str, size: int, seed: int):
    inventory = dataclasses.replace(inventory, site=dataclasses.replace(inventory.site, suite_size=size))
    tick = time.perf_counter()
    result = run_assessment(inventory, level, seed=seed)
    summary = result.summary
    return summary[summary["risk"] != "anchored"].set_index("id"), time.perf_counter() - tick


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--workbook", default=str(Path(__file__).resolve().parents[1] / "inventories" /
                                                  "seattle-hospital.xlsx"))
    parser.add_argument("--level", default="MCE_R")
    parser.add_argument("--sizes", default="11,120")
    parser.add_argument("--reference", type=int, default=1200)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args(argv)
    inventory = read_workbook(args.workbook)
    sizes = [int(s) for s in args.sizes.split(",")]
    results = {}
    for size in sizes + [args.reference]:
        summary, seconds = assess(inventory, args.level, size, args.seed)
        results[size] = summary
        spans = summary["risk_range"].fillna("").astype(str).str.contains(" to ")
        print(f"{size:5d} motions: {spans.sum()} of {len(summary)} assessed items span classes "
              f"({spans.mean():.0%}); classes {summary['risk'].value_counts().to_dict()}; {seconds:.1f} s")
    reference = results[args.reference]
    for size in sizes:
        summary = results[size]
        held, total, misses = 0, 0, []
        for mode in MODES:
            truth = reference[mode]
            low, high = summary[f"{mode}_low"], summary[f"{mode}_high"]
            ok = (low <= truth + 1e-12) & (truth <= high + 1e-12)
            held += int(ok.sum())
            total += int(ok.size)
            misses += [f"{item} {mode} {truth[item]:.3f} outside {low[item]:.3f}-{high[item]:.3f}"
                       for item in ok.index[~ok]]
        print(f"{size:5d} motions: {held} of {total} intervals (90 %) hold the {args.reference}-motion estimate "
              f"({held / total:.0%})" + "".join(f"\n      {m}" for m in misses))
        changed = (summary["risk"] != reference["risk"]).sum()
        print(f"      class differs from the {args.reference}-motion class for {changed} of {len(summary)} items")


if __name__ == "__main__":
    main()
