"""Build the second sample workbook ``inventories/pharmacy.xlsx``: a 3-storey hospital pharmacy, in US units.

Written from the README alone, as a new user would: inches and pounds
(``height_in``, ``mass_lb``, ``clearance_in``), a hazard level named by a
label (``DE``, the design earthquake), motions given by PTA, Tp and vp per
floor, some pulse-like and some not, a ``consequence`` for every item, and
``sds_g``/``roof_floor`` so that the items to anchor get their design force.
Every item and number is invented but typical; do not use it for a real
building. Deterministic (same bytes each run), like build_lab.py.

    python inventories/build_pharmacy.py
    assess inventories/pharmacy.xlsx --hazard DE --units us
"""
from __future__ import annotations

from pathlib import Path

from openpyxl import Workbook

from build_lab import deterministic_bytes, write_replacing, write_sheet

OUT = Path(__file__).resolve().parent / "pharmacy.xlsx"


def item(id, name, room, floor, h_in, w_in, d_in, lb, mu, clearance_in, consequence, notes, cg_in=None,
         anchored=False, qty=1, casters=False, contents=None):
    row = dict(id=id, name=name, room=room, floor=floor, height_in=h_in, width_in=w_in, depth_in=d_in,
               mass_lb=lb, mu=mu, clearance_in=clearance_in, cg_height_in=cg_in,
               anchored="yes" if anchored else "no", casters="yes" if casters else "no", quantity=qty,
               consequence=consequence, notes=notes)
    if contents is not None:  # what its contents can do (movable, fixed, none): only where the row says
        row["contents"] = contents
    return row


EQUIPMENT = [
    # ground floor: receiving and bulk storage
    item("RX-0-01", "Bulk IV-fluid storage rack, 5 shelves, loaded", "0-110 bulk store", 0, 84, 48, 24, 1400,
         0.35, 12, "life-safety", "rack in the aisle to the fire exit; heavy cases on the upper shelves", cg_in=48,
         contents="movable"),
    item("RX-0-02", "Oxygen cylinder cart, 6 E-cylinders", "0-115 medical gases", 0, 40, 18, 12, 120, 0.45, 6,
         "hazardous", "cart on casters, brakes on; compressed oxygen", casters=True),
    item("RX-0-03", "Pharmacy refrigerator, double door", "0-120 cold room anteroom", 0, 80, 52, 32, 650, 0.25, 8,
         "critical", "vaccines and insulin; 8 in to the wall behind"),
    item("RX-0-04", "Flammable liquids cabinet, 45 gal", "0-125 hazardous store", 0, 65, 43, 18, 420, 0.30, 4,
         "hazardous", "alcohols and solvents", contents="movable"),
    item("RX-0-05", "Carton flow rack", "0-110 bulk store", 0, 72, 60, 30, 900, 0.30, 10, "ordinary",
         "anchored to the wall", anchored=True),
    # floor 1: dispensing
    item("RX-1-01", "Automated dispensing cabinet, tower", "1-210 dispensing", 1, 78, 36, 30, 1100, 0.30, 6,
         "critical", "the unit the nurses draw every dose from"),
    item("RX-1-02", "Medication shelving, 6 shelves, stock loaded", "1-210 dispensing", 1, 84, 36, 18, 450, 0.35, 18,
         "life-safety", "open shelving beside the staff workstation", cg_in=46, contents="movable"),
    item("RX-1-03", "Controlled-substance safe", "1-215 vault", 1, 42, 24, 22, 900, 0.40, 3, "valuable",
         "heavy, short"),
    item("RX-1-04", "Hazardous-drug storage cabinet (chemotherapy)", "1-220 hazardous drugs", 1, 72, 36, 24, 380, 0.30,
         5, "hazardous", "negative-pressure room; spills are a hazmat event"),
    # floor 2: compounding
    item("RX-2-01", "Compounding aseptic isolator", "2-310 clean room", 2, 80, 60, 32, 1200, 0.25, 10, "critical",
         "sterile compounding stops without it", cg_in=44),
    item("RX-2-02", "Biological safety cabinet, class II, on stand", "2-320 hazardous compounding", 2, 90, 52, 31, 850,
         0.30, 8, "hazardous", "chemotherapy compounding", cg_in=55),
    item("RX-2-03", "Vaccine freezer, upright, -20 °C", "2-330 cold storage", 2, 76, 28, 30, 330, 0.25, 4, "critical",
         "single unit, narrow"),
    item("RX-2-04", "Supply cart, stainless, 3 shelves", "2-310 clean room", 2, 38, 48, 24, 150, 0.60, 24, "ordinary",
         "on locked casters", casters=True),
]

# The design earthquake (DE) per floor: three motions a floor, PTA, Tp and vp; the pulse share
# 2π|vp|/(Tp·PTA·g) of 0.55-0.70 makes the first two near-fault pulses and ~0.2 the third a motion with no
# strong pulse, so that the report shows both paths (the regression and synthetic histories).
HAZARD = [
    dict(level="DE", motion=f"{name}, floor {floor}", floor=floor, pta_g=round(pta * amp, 3), tp_s=tp,
         vp_cm_s=round(vp * amp, 1), source=source)
    for floor, amp in ((0, 1.0), (1, 1.33), (2, 1.67))
    for name, pta, tp, vp, source in (
        ("Near-fault pulse A", 0.40, 1.0, 40.0, "invented: pulse share 0.65"),
        ("Near-fault pulse B", 0.45, 1.6, 70.0, "invented: pulse share 0.62"),
        ("Distant event C", 0.35, 0.9, 10.0, "invented: pulse share 0.20 (no strong pulse)"),
    )
]

SETTINGS = [
    ("facility", "Sample hospital pharmacy (3 storeys)"),
    ("site", "Sample site (invented)"),
    ("sds_g", 1.0), ("roof_floor", 3),
]


def build() -> bytes:
    workbook = Workbook()
    write_sheet(workbook.active, list(EQUIPMENT[0]), EQUIPMENT)
    workbook.active.title = "equipment"
    write_sheet(workbook.create_sheet("hazard"), list(HAZARD[0]), HAZARD)
    write_sheet(workbook.create_sheet("settings"), ["key", "value"], SETTINGS)
    return deterministic_bytes(workbook, "inventories/build_pharmacy.py")


if __name__ == "__main__":
    write_replacing(OUT, build())
    print(f"wrote {OUT} ({len(EQUIPMENT)} items)")
