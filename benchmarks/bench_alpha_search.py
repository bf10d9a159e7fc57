"""What finding α from a pushover's slope costs a run: the tool's pushover of its stick over the search's α.

Run: python benchmarks/bench_alpha_search.py [--storeys 12] [--system "steel moment frame"] [--slope 0.07]
     [--alpha-range-ends] (time it as a whole process, against the same command with --no-search, which imports
     as much and reads the sheet but finds no α; with --alpha-range-ends, against the same command without it)

A building sheet with ``pushover_slope_ratio`` has its α found once per run (assess/assessment/floors.py
``pushover_alpha``, cached): the stick pushed over (assess/building/pushover.py, 200 steps to 2 % roof drift) at
the 17 α of the search's grid and at Brent's steps in each interval that passes the slope. Prints the α found,
the number of pushovers and the seconds in this process.

Measured (2026-11-30, each command timed as a whole process, 5 runs, medians, against ``--no-search``): 12 storeys
of a steel moment frame, 26 pushovers (24 since the search keeps each α's slope), 3.29 s against 2.58 s wall
(+0.7 s); 40 storeys of a braced frame, 3.78 s against 2.51 s wall (+1.3 s; +2.6 s CPU).
A run of the main job on such a building takes a minute or more.

``--alpha-range-ends`` also finds the ends ``--alpha-range`` runs at where α comes from the slope alone
(assess/assessment/alpha_range.py ``pushover_ends``: the search again with the storeys hardening at 2 % and at
5 %), two more searches: 75 pushovers where one search takes 24, 4.79 s against 3.32 s wall (medians of 5, 12
storeys; 2026-11-30), where ``--alpha-range`` runs the level twice more.
"""
from __future__ import annotations

import argparse
import time

from assess.assessment import floors
from assess.building import pushover
from assess.inventory.site_building import BuildingSheet


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--storeys", type=int, default=12)
    parser.add_argument("--system", default="steel moment frame")
    parser.add_argument("--slope", type=float, default=0.07)
    parser.add_argument("--no-search", action="store_true")
    parser.add_argument("--alpha-range-ends", action="store_true")
    args = parser.parse_args(argv)
    sheet = BuildingSheet(storeys=args.storeys, height_m=4.0 * args.storeys, system=args.system,
                          yield_base_shear_g=0.1, pushover_slope_ratio=args.slope)
    if args.no_search:
        print(f"{args.storeys} storeys, {args.system}: no search")
        return
    calls = [0]
    original = pushover.stick_pushover

    def counted(*a, **k):
        calls[0] += 1
        return original(*a, **k)

    pushover.stick_pushover = counted
    start = time.perf_counter()
    found = floors.pushover_alpha(sheet)
    ends = ""
    if args.alpha_range_ends:
        from assess.assessment.alpha_range import pushover_ends
        ends = "; --alpha-range ends {:.4g} and {:.4g}".format(*pushover_ends(sheet))
    print(f"{args.storeys} storeys, {args.system}, slope {args.slope:g}: α {found.alpha:.4g}{ends} after {calls[0]} "
          f"pushovers, {time.perf_counter() - start:.2f} s")


if __name__ == "__main__":
    main()
