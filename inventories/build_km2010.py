"""Build the paper's own calibration loop as an example: ``km2010-prototypes.xlsx`` and ``km2010-measured.xlsx``.

Konstantinidis & Makris (2010), Bull. Earthquake Eng. 8:1457-1477, section 5
and Table 3 (p. 1467): the three full-scale prototypes (FORMA incubator,
KELVINATOR and ASP refrigerators; heights and widths of Table 1, p. 1460)
with the friction coefficients measured by slow pull (0.23, 0.28, 0.31), under
the nine Loma Prieta motions of Table 3 (PTA, Tp, vp as printed; each a
Type-B pulse, p. 1470), and the peak sliding Umax of Table 3 as the "measured"
response. Umax of Table 3 is the authors' Working Model sliding with their
best-fit μ, which they chose so that the model reproduced the sliding observed
on the shake table (section 5): it stands here for the observation, one step
removed. The paper found that the slow-pull μ overstated the friction the
equipment showed in shaking and fitted 0.13, 0.17 and 0.20 (0.57, 0.61 and
0.65 of the slow-pull values); ``assess calibrate`` should find what is
missing on its own:

    python inventories/build_km2010.py
    assess calibrate inventories/km2010-prototypes.xlsx --measured inventories/km2010-measured.xlsx

Deterministic (fixed dates), like build_lab.py. Depth and mass are not in the
paper and do not enter the results (direction 1, mass-free rigid block).
"""
from __future__ import annotations

import csv
from pathlib import Path

from openpyxl import Workbook

from build_lab import deterministic_bytes, write_replacing, write_sheet

HERE = Path(__file__).resolve().parent
TABLE3 = HERE.parent / "assess" / "data" / "km2010_table3.csv"
K10 = "Konstantinidis & Makris (2010)"
#: Table 1 p.1460 heights and widths [cm]; depth and mass: the sample lab's catalogue values.
PROTOTYPES = {"FORMA": (228.6, 62.2, 84.0, 330), "KELVINATOR": (213.4, 66.0, 81.0, 230),
              "ASP": (180.3, 58.4, 74.0, 140)}


def table3_rows():
    with TABLE3.open(newline="") as handle:
        return list(csv.DictReader(line for line in handle if not line.startswith("#")))


def motion_names(rows):
    """Table 3 lists the same nine runs for each prototype: name them run by run."""
    first = [r for r in rows if r["equipment"] == "FORMA"]
    names, counts = [], {}
    for r in first:
        counts[r["motion"]] = counts.get(r["motion"], 0) + 1
        names.append(f"{r['motion']}, run {counts[r['motion']]} ({float(r['pta_g']):.2f} g)")
    return first, names


def workbook_bytes(rows) -> bytes:
    first, names = motion_names(rows)
    wb = Workbook()
    equipment = []
    for name, (h, w, d, kg) in PROTOTYPES.items():
        slow_pull = next(float(r["mu_slow_pull"]) for r in rows if r["equipment"] == name)
        equipment.append({"id": name, "name": f"{name} prototype", "floor": 0, "height_cm": h, "width_cm": w,
                          "depth_cm": d, "mass_kg": kg, "mu": slow_pull, "clearance_cm": 100,
                          "source": f"height, width: {K10} Table 1 p.1460; mu: slow pull, Table 3 p.1467"})
    write_sheet(wb.active, list(equipment[0]), equipment)
    wb.active.title = "equipment"
    hazard = [{"level": "2in50", "motion": n, "floor": "all", "pta_g": float(r["pta_g"]), "tp_s": float(r["tp_s"]),
               "vp_cm_s": float(r["vp_cm_s"]), "pulse": "B",
               "source": f"{K10} Table 3 p.1467 (PTA, Tp, vp as printed); Type-B pulse p.1470"}
              for r, n in zip(first, names)]
    write_sheet(wb.create_sheet("hazard"), list(hazard[0]), hazard)
    write_sheet(wb.create_sheet("settings"), ["key", "value"],
                [{"key": "facility", "value": f"{K10}: full-scale prototypes, shake-table motions"},
                 {"key": "simulate_motions", "value": "pulse"}])
    return deterministic_bytes(wb, "inventories/build_km2010.py")


def measured_bytes(rows) -> bytes:
    _, names = motion_names(rows)
    tests = []
    for name in PROTOTYPES:
        own = [r for r in rows if r["equipment"] == name]
        for r, motion in zip(own, names):
            assert abs(float(r["pta_g"]) - float(motion.split("(")[-1].split(" g")[0])) < 1e-9, (r, motion)
            tests.append({"specimen": name, "motion": motion, "sliding_cm": float(r["umax_cm"]),
                          "source": f"Umax, {K10} Table 3 p.1467"})
    wb = Workbook()
    write_sheet(wb.active, list(tests[0]), tests)
    wb.active.title = "tests"
    return deterministic_bytes(wb, "inventories/build_km2010.py")


if __name__ == "__main__":
    rows = table3_rows()
    for filename, content in (("km2010-prototypes.xlsx", workbook_bytes(rows)),
                              ("km2010-measured.xlsx", measured_bytes(rows))):
        write_replacing(HERE / filename, content)
        print(f"wrote {HERE / filename}")
