"""What sliding in the plane changes in the assessment: lab.xlsx's items under pyslammer's records in pairs.

Run: python benchmarks/bench_planar_demand.py [--pga 0.5]

Hazard: pyslammer's 18 sample records, each with the next one in name order
as its ``record_2`` (the last with the first; the second resampled linearly
onto the first's steps and both cut to the shorter), each pair scaled so
that the larger component PGA is ``--pga``: one suite of 18 motions on
every floor. Items: lab.xlsx's freestanding items, as they are.

The assessment runs twice: as the tool does (items that cannot uplift slide
in the plane; their demand is the 2-D peak distance from rest) and with the
2-D step switched off (their demand per motion is the larger of the two
one-way answers, direction 1 under ``record``, direction 2 under
``record_2``). Prints, for the items whose demand is 2-D, the median over
the suite of the two answers, the chance of sliding past the clearance both
ways, and the items whose risk class differs. Not a test: numbers for the docs.
"""
from __future__ import annotations

import argparse
import tempfile
from pathlib import Path
from unittest import mock

import numpy as np
import pandas as pd

from assess.assessment.pipeline import run_assessment
from assess.inventory import Inventory, read_workbook

LAB = Path(__file__).resolve().parent.parent / "inventories" / "lab.xlsx"


def pair_rows(folder: Path, pga_g: float) -> pd.DataFrame:
    import pyslammer

    motions = sorted(pyslammer.sample_ground_motions().items())
    rows = []
    for k, ((name_x, first), (name_y, second)) in enumerate(zip(motions, motions[1:] + motions[:1])):
        ax, dt = np.asarray(first.accel, dtype=float), float(first.dt)
        b = np.asarray(second.accel, dtype=float)
        t_b = np.arange(b.size) * float(second.dt)
        t = np.arange(0.0, min(ax.size * dt, t_b[-1]), dt)
        n = min(t.size, ax.size)
        ax, ay = ax[:n], np.interp(t[:n], t_b, b)
        factor = pga_g / max(np.abs(ax).max(), np.abs(ay).max())
        paths = []
        for name, accel in ((name_x, ax), (name_y, ay)):
            path = folder / f"{k:02d}-{name}.csv"
            pd.DataFrame({"time_s": np.arange(n) * dt, "accel_g": accel * factor}).to_csv(path, index=False)
            paths.append(str(path))
        rows.append({"level": "pairs", "level_label": "pairs", "motion": f"{name_x} + {name_y}",
                     "all_floors": True, "floor": pd.NA, "pta_g": np.nan, "tp_s": np.nan, "vp_m_s": np.nan,
                     "pulse": "", "record_path": paths[0], "scale": 1.0, "row": k + 2,
                     "record_2_path": paths[1], "azimuth_deg": 0.0})
    hazard = pd.DataFrame(rows)
    hazard["floor"] = hazard["floor"].astype("Int64")
    return hazard


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pga", type=float, default=0.5)
    args = parser.parse_args()
    lab = read_workbook(LAB)
    with tempfile.TemporaryDirectory() as folder:
        inventory = Inventory(path=Path(folder) / "pairs.xlsx", equipment=lab.equipment,
                              hazard=pair_rows(Path(folder), args.pga), settings=lab.settings)
        planar = run_assessment(inventory, "pairs").summary.set_index("id")
        with mock.patch("assess.assessment.pipeline.planar_runs", return_value=None):
            one_way = run_assessment(inventory, "pairs").summary.set_index("id")
    used = planar.index[planar["demand_planar"].eq(True)]
    ratio = planar.loc[used, "demand_median_cm"] / one_way.loc[used, "demand_median_cm"]
    print(f"18 pyslammer record pairs at PGA {args.pga} g (larger component), lab.xlsx's "
          f"{planar['risk'].ne('anchored').sum()} freestanding items; {len(used)} cannot uplift and slide in the plane")
    table = pd.DataFrame({
        "clearance_cm": planar.loc[used, "clearance_cm"],
        "median_1d_cm": one_way.loc[used, "demand_median_cm"], "median_2d_cm": planar.loc[used, "demand_median_cm"],
        "p84_1d_cm": one_way.loc[used, "demand_p84_cm"], "p84_2d_cm": planar.loc[used, "demand_p84_cm"],
        "p_beyond_1d": one_way.loc[used, "p_beyond_clearance"], "p_beyond_2d": planar.loc[used, "p_beyond_clearance"],
        "risk_1d": one_way.loc[used, "risk"], "risk_2d": planar.loc[used, "risk"]})
    print(table.round(3).to_string())
    print(f"\nmedian over the suite, 2-D / larger one-way: median {ratio.median():.3f}, range "
          f"{ratio.min():.3f}-{ratio.max():.3f}")
    changed = table[table["risk_1d"] != table["risk_2d"]]
    print(f"risk class differs for {len(changed)} item(s): "
          + (", ".join(f"{i} ({r.risk_1d} -> {r.risk_2d})" for i, r in changed.iterrows()) or "none"))


if __name__ == "__main__":
    main()
