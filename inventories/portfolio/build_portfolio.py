"""Build the sample portfolio ``inventories/portfolio/`` (format: docs/workbook.md).

Three small buildings made from the sample laboratory (``inventories/lab.xlsx``,
built by ``inventories/build_lab.py``; its README says where every number came
from), each with other floors, clearances and items, so that a portfolio runs
in a minute:

* ``north-lab.xlsx``: the lab's floors 0 and 1, three of its seven ground motions;
* ``south-lab.xlsx``: the lab's floors 4 and 6, every clearance halved (tighter rooms);
* ``annex.xlsx``: a two-storey annex holding the paper's three prototypes on
  rubber pads (mu 0.5) with other clearances, and the lab's shelving and
  autoclave on its upper floor;

``portfolio.xlsx`` (sheet ``buildings``) lists them at level 2in50 with the
sample site's hazard curve ``site-hazard.csv``: an OpenQuake-format curve of
PGA made from a power law, lambda(a) = 4.04e-4 (a / 0.9 g)^-2.5 per year (so
0.9 g at 2 % in 50 years), invented for the sample, not a site's hazard.
``site-hazard-updated.csv`` is the same curve 20 % higher in rate (a hazard
model update). Deterministic: re-running it writes the same bytes.

    python inventories/portfolio/build_portfolio.py
"""
from __future__ import annotations

import math
import os
import sys
from pathlib import Path

from openpyxl import Workbook

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
import build_lab as lab  # noqa: E402 - the sample lab's items, motions and deterministic writer

#: Ground motions kept (one per record family of K&M 2010 Table 3): the motion ids of lab.xlsx.
GROUND_KEPT = ("Los Gatos PC, ground (0.54 g)", "Corralitos, ground (0.84 g)", "Gilroy Hist. Bldg., ground (0.59 g)")
#: Sample site curve: lambda(a) = RATE_AT_REF (a / REF_G)^-SLOPE [1/yr] (invented; 2 % in 50 yr at REF_G).
REF_G, RATE_AT_REF, SLOPE = 0.9, 1.0 / 2475.0, 2.5
CURVE_LEVELS_G = [0.005 * (3.0 / 0.005) ** (k / 19) for k in range(20)]


def _items(ids, **changes):
    """The lab's rows ``ids``, with ``changes`` (a value, or a function of the row) applied."""
    by_id = {row["id"]: row for row in lab.EQUIPMENT}
    rows = []
    for item_id in ids:
        row = dict(by_id[item_id])
        for key, value in changes.items():
            row[key] = value(row) if callable(value) else value
        rows.append(row)
    return rows


def _hazard(floors, ground=GROUND_KEPT):
    return [row for row in lab.hazard_rows()
            if (row["floor"] == 0 and row["motion"] in ground) or (row["floor"] != 0 and row["floor"] in floors)]


def north_lab():
    equipment = _items(["INC-G-01", "REF-G-01", "REF-G-02", "LN2-G-01", "GAS-G-02", "ULT-1-01", "FRZ-1-01",
                        "CAB-1-01"])
    return equipment, _hazard({1}), "North lab (sample: floors 0-1 of the sample laboratory)"


def south_lab():
    equipment = _items(["INC-4-01", "REF-4-01", "LN2-4-01", "FLM-4-01", "INC-6-01", "REF-6-01", "REF-6-02",
                        "LN2-6-01"], clearance_cm=lambda row: row["clearance_cm"] / 2,
                       notes=lambda row: f"{row['notes']} (clearance halved from the sample lab's)")
    return equipment, _hazard({4, 6}, ground=()), "South lab (sample: floors 4 and 6, tighter rooms)"


def annex():
    pads = dict(mu=0.5, source=lambda row: row["source"] + "; mu 0.5: assumed rubber pads (annex variant)")
    equipment = (
        _items(["INC-G-01"], clearance_cm=10, **pads) + _items(["REF-G-01"], clearance_cm=15, **pads)
        + _items(["REF-G-02"], clearance_cm=40, **pads)
        + _items(["SHF-2-01", "ACL-2-01"], floor=1,
                 room=lambda row: "A-1 " + row["room"].split(" ", 1)[1]))
    for row in equipment:
        row["id"] = "AX-" + row["id"]
    return equipment, _hazard({1}), "Annex (sample: two storeys, prototypes on rubber pads)"


BUILDINGS = {"north-lab": north_lab, "south-lab": south_lab, "annex": annex}


def workbook_bytes(equipment, hazard, facility) -> bytes:
    wb = Workbook()
    lab.write_sheet(wb.active, list(lab.EQUIPMENT[0]), equipment)
    wb.active.title = "equipment"
    lab.write_sheet(wb.create_sheet("hazard"), ["level", "motion", "floor", "pta_g", "tp_s", "vp_cm_s", "pulse",
                                                "source"], hazard)
    settings = [(key, facility if key == "facility" else value) for key, value in lab.SETTINGS]
    lab.write_sheet(wb.create_sheet("settings"), ["key", "value"], settings)
    return lab.deterministic_bytes(wb, "inventories/portfolio/build_portfolio.py")


def portfolio_bytes() -> bytes:
    wb = Workbook()
    rows = [dict(building=name, workbook=f"{name}.xlsx", level="2in50", oq_hazard="site-hazard.csv",
                 notes="sample building made from inventories/lab.xlsx") for name in BUILDINGS]
    lab.write_sheet(wb.active, ["building", "workbook", "level", "oq_hazard", "notes"], rows)
    wb.active.title = "buildings"
    return lab.deterministic_bytes(wb, "inventories/portfolio/build_portfolio.py")


def curve_csv(rate_factor: float = 1.0) -> str:
    """The sample site's PGA hazard curve in OpenQuake's CSV format (one site, 1-year poes)."""
    poes = [1.0 - math.exp(-rate_factor * RATE_AT_REF * (a / REF_G) ** -SLOPE) for a in CURVE_LEVELS_G]
    header = ["lon", "lat", "depth"] + [f"poe-{a:.7f}" for a in CURVE_LEVELS_G]
    comment = ["#"] + [""] * (len(header) - 2) + [
        "\"generated_by='inventories/portfolio/build_portfolio.py (sample power law, not an OpenQuake run)', "
        "kind='mean', investigation_time=1.0, imt='PGA'\""]
    values = ["-122.25900", "37.87200", "0.00000"] + [f"{p:.6E}" for p in poes]
    return "\n".join([",".join(comment), ",".join(header), ",".join(values)]) + "\n"


def _write(path: Path, data: bytes) -> None:
    temporary = path.with_name(path.name + ".tmp")
    temporary.write_bytes(data)
    os.replace(temporary, path)  # no half-written file if anything fails


if __name__ == "__main__":
    for name, make in BUILDINGS.items():
        equipment, hazard, facility = make()
        ids = [row["id"] for row in equipment]
        assert len(ids) == len(set(ids)), "duplicate equipment id"
        _write(HERE / f"{name}.xlsx", workbook_bytes(equipment, hazard, facility))
        print(f"wrote {HERE / f'{name}.xlsx'} ({len(equipment)} items, {len(hazard)} motions)")
    _write(HERE / "portfolio.xlsx", portfolio_bytes())
    _write(HERE / "site-hazard.csv", curve_csv().encode())
    _write(HERE / "site-hazard-updated.csv", curve_csv(1.2).encode())
    print(f"wrote {HERE / 'portfolio.xlsx'}, site-hazard.csv, site-hazard-updated.csv")
