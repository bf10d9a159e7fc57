"""Cost of the fragilities over a hazard curve through a yielding building: the stick's runs and the seconds.

Run: python benchmarks/bench_curve_yielding.py [WORKBOOK] [--level DE] [--curve CSV]

By default the sample hospital (inventories/hospital.xlsx: 4 storeys, a steel moment frame yielding at its
code design) at level DE with the sample curve (inventories/lab-hazard-curve.csv), assessed twice in one
process after the level alone has loaded the kernels, each from an empty memory of the stick
(``assess.building.yielding.forget``) and without the case cache: with the bound switched off (the stick
run on every copy), then as the command does it (the stripes strongest first, a ground history's copies
weaker than one that yielded no storey taken from the elastic route without running the stick:
``assess.building.yielding.ElasticBound``). Prints, for each, the stick's runs, the ground histories
passed through the building (copies included), the seconds of the whole assessment, and whether the two
give the same stripes' outcomes.

Measured (2 cores, 2026-11-29): the stick run 3600 times without the bound, 2766 with it (the same 524
stripes' rows, 62,880 trials); 103.8 s and 85.4 s, one run each. The command as a whole (a new user's
8-storey frame, ``--oq-hazard`` with the same curve; the stripes' runs also gathered without pandas'
row-by-row reading): 224 s before, 173 s after (median of 2 whole-process runs each, in turn; ratio
0.77, 0.72-0.82), the same files.
"""
import argparse
import time
from pathlib import Path

import numpy as np

from assess.assessment.pipeline import run_assessment
from assess.building import yielding
from assess.hazard.openquake import read_openquake_hazard
from assess.inventory import read_workbook

REPO = Path(__file__).resolve().parents[1]


def assess_counting(path: Path, level: str, curve, bounded: bool):
    """The assessment, the stick's runs and the histories passed, with the bound on or off."""
    counts = {"stick": 0, "passed": 0}
    kernels = {name: getattr(yielding, name) for name in ("yielding_response", "hinged_wall_response")}
    below = yielding.ElasticBound.below

    def counted(kernel):
        def run(*args, **kwargs):
            counts["stick"] += 1
            return kernel(*args, **kwargs)
        return run

    weaker = yielding.weaker_elastic_history

    def weaker_counted(*args, **kwargs):
        counts["passed"] += 1
        return weaker(*args, **kwargs)

    try:
        for name, kernel in kernels.items():
            setattr(yielding, name, counted(kernel))
        yielding.weaker_elastic_history = weaker_counted
        if not bounded:
            yielding.ElasticBound.below = lambda self, ground, factor: None
        yielding.forget()
        start = time.perf_counter()
        result = run_assessment(read_workbook(path), level, hazard_curve=curve)
        seconds = time.perf_counter() - start
    finally:
        for name, kernel in kernels.items():
            setattr(yielding, name, kernel)
        yielding.weaker_elastic_history = weaker
        yielding.ElasticBound.below = below
    counts["passed"] += counts["stick"]
    return result, counts, seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("workbook", nargs="?", default=str(REPO / "inventories" / "hospital.xlsx"))
    parser.add_argument("--level", default="DE")
    parser.add_argument("--curve", default=str(REPO / "inventories" / "lab-hazard-curve.csv"))
    args = parser.parse_args()
    curve = read_openquake_hazard(args.curve)
    run_assessment(read_workbook(Path(args.workbook)), args.level)  # compiles, or loads, the kernels first
    outcomes = {}
    for bounded in (False, True):
        result, counts, seconds = assess_counting(Path(args.workbook), args.level, curve, bounded)
        stripes = result.curve_risk.stripes
        outcomes[bounded] = stripes
        print(f"{'bound on ' if bounded else 'bound off'}: the stick run {counts['stick']} times for "
              f"{counts['passed']} ground histories through the building; {seconds:.1f} s for the assessment")
    same = outcomes[True].reset_index(drop=True).equals(outcomes[False].reset_index(drop=True))
    print(f"the stripes' outcomes {'the same' if same else 'DIFFER'} "
          f"({len(outcomes[True])} rows, {int(np.sum(outcomes[True]['trials']))} trials)")


if __name__ == "__main__":
    main()
