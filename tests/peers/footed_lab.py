"""A shake-table data set of boxes on inset feet, made with the independent peer (tests only).

Four slender specimens whose feet stand at 0.7·b from the centre line (inset
d = 0.3) are played six of pyslammer's real records at two amplitudes each
(48 tests). The table "measures" the peak rotation over α of the box as the
workbook declares it, atan(b/h), with 5 % multiplicative noise (N(0, 0.05),
seeded), and whether the specimen overturned (exactly; its rotation is then
not read). The responses come from :mod:`peers.footed_rocking`, which shares
nothing with ``assess.mechanics``.

:func:`write_lab` writes what a user would hand ``assess calibrate``: the
workbook (equipment, hazard rows naming the record files and their scale),
the record files next to it (pyslammer's CSVs, copied), and ``measured.xlsx``.
"""
from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import openpyxl

from peers.footed_rocking import FootedBox, footed_rocking

#: (id, height cm, width cm): slender boxes (b/h 0.20 to 0.23); μ 0.8, so they rock without sliding.
SPECIMENS = [("CAB-A", 180.0, 40.0), ("CAB-B", 200.0, 45.0), ("CAB-C", 150.0, 30.0), ("CAB-D", 220.0, 50.0)]
MU = 0.8
#: pyslammer's records and the two peak accelerations [g] each was played at.
RECORDS = ["Northridge_1994_PAC-175", "Cape_Mendocino_1992_PET-090", "Duzce_1999_375-090",
           "Imperial_Valley_1979_BCR-230", "N_Palm_Springs_1986_WWT-180", "Coalinga_1983_PVB-045"]
PGAS_G = (0.22, 0.32)
INSET = 0.3
NOISE = 0.05


def pyslammer_records() -> dict:
    """{name: (path of pyslammer's CSV, accel [g], dt [s])} of :data:`RECORDS`."""
    import pyslammer

    motions = pyslammer.sample_ground_motions()
    folder = Path(pyslammer.__file__).parent / "sample_ground_motions"
    return {name: (folder / f"{name}.csv", np.asarray(motions[name].accel, float), float(motions[name].dt))
            for name in RECORDS}


def motion_name(record: str, pga_g: float) -> str:
    return f"{record} @ {pga_g:g} g"


def true_responses(inset=INSET, records=None, amplitude_jitter=0.0, seed=0) -> list[dict]:
    """Every test's noise-free response by the peer: specimen, motion, record, scale, θ/α declared, overturned.

    ``amplitude_jitter`` > 0: the table plays each test at its nominal amplitude × (1 + jitter·N(0, 1))
    (seeded), as a real table does not reproduce the commanded amplitude exactly; ``scale`` stays the
    nominal one (what the workbook says).
    """
    records = pyslammer_records() if records is None else records
    rng = np.random.default_rng(seed)
    rows = []
    for specimen, height_cm, width_cm in SPECIMENS:
        box = FootedBox(half_width_m=width_cm / 200.0, height_m=height_cm / 100.0, inset_fraction=inset)
        for name, (_, accel_g, dt_s) in records.items():
            for pga in PGAS_G:
                scale = pga / float(np.max(np.abs(accel_g)))
                played = scale * (1.0 + amplitude_jitter * rng.standard_normal()) if amplitude_jitter else scale
                response = footed_rocking(box, accel_g * played, dt_s)
                rows.append(dict(specimen=specimen, motion=motion_name(name, pga), record=name, scale=scale,
                                 played=played, theta=response.theta_over_declared_alpha(box),
                                 overturned=response.overturned))
    return rows


def measured_rows(truth: list[dict], seed: int, noise=NOISE) -> list[dict]:
    """The table's readings: θ/α × (1 + noise·N(0,1)) where it stood, overturned exactly."""
    rng = np.random.default_rng(seed)
    out = []
    for row in truth:
        factor = 1.0 + noise * rng.standard_normal()
        theta = None if row["overturned"] else max(row["theta"] * factor, 0.0)
        out.append(dict(specimen=row["specimen"], motion=row["motion"], theta_max_over_alpha=theta,
                        overturned="yes" if row["overturned"] else "no"))
    return out


def write_lab(folder: Path, truth: list[dict], seed: int, noise=NOISE) -> tuple[Path, Path]:
    """Write ``folder/footed.xlsx``, its records and ``folder/measured.xlsx``; return both paths."""
    from workbooks import write_workbook

    folder = Path(folder)
    (folder / "records").mkdir(parents=True, exist_ok=True)
    sources = pyslammer_records()
    for name, (path, _, _) in sources.items():
        shutil.copyfile(path, folder / "records" / f"{name}.csv")
    equipment = [{"id": i, "name": f"{i} on feet", "floor": 0, "height_cm": h, "width_cm": w, "depth_cm": 60,
                  "mass_kg": 150, "mu": MU, "clearance_cm": 20} for i, h, w in SPECIMENS]
    motions = {}
    for row in truth:
        motions.setdefault(row["motion"], row)
    hazard = [{"level": "table", "motion": m, "floor": "all", "record": f"records/{r['record']}.csv",
               "scale": r["scale"]} for m, r in motions.items()]
    workbook = write_workbook(folder / "footed.xlsx", {"equipment": equipment, "hazard": hazard})
    book = openpyxl.Workbook()
    sheet = book.active
    sheet.title = "tests"
    rows = measured_rows(truth, seed, noise)
    header = list(rows[0])
    sheet.append(header)
    for row in rows:
        sheet.append([row[k] for k in header])
    measured = folder / "measured.xlsx"
    book.save(measured)
    return workbook, measured


#: The peer's noise-free responses, stored (``python tests/peers/footed_lab.py`` writes them again):
#: the table playing each record exactly as commanded, and playing it × (1 + 0.01·N(0, 1)) (seed 11).
TRUTH_CSV = Path(__file__).resolve().parents[1] / "data" / "footed_lab" / "truth.csv"
TRUTH_JITTER_CSV = TRUTH_CSV.with_name("truth_jitter.csv")
JITTER, JITTER_SEED = 0.01, 11
_COLUMNS = ["specimen", "motion", "record", "scale", "played", "theta", "overturned"]


def read_truth(path=TRUTH_CSV) -> list[dict]:
    """The stored noise-free responses (columns of :func:`true_responses`)."""
    import csv

    with open(path, newline="") as handle:
        return [dict(specimen=r["specimen"], motion=r["motion"], record=r["record"], scale=float(r["scale"]),
                     played=float(r["played"]), theta=float(r["theta"]), overturned=r["overturned"] == "True")
                for r in csv.DictReader(handle)]


def write_truth(rows: list[dict], path=TRUTH_CSV) -> None:
    import csv

    Path(path).parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as handle:
        writer = csv.DictWriter(handle, _COLUMNS)
        writer.writeheader()
        for row in rows:
            writer.writerow({**{k: row[k] for k in _COLUMNS}, "scale": repr(float(row["scale"])),
                             "played": repr(float(row["played"])), "theta": repr(float(row["theta"])),
                             "overturned": str(bool(row["overturned"]))})


if __name__ == "__main__":  # about 10 minutes: every test of the lab by the peer, twice
    import sys

    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
    write_truth(true_responses())
    write_truth(true_responses(amplitude_jitter=JITTER, seed=JITTER_SEED), TRUTH_JITTER_CSV)
    print(TRUTH_CSV, TRUTH_JITTER_CSV)
