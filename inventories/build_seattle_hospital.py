"""Build ``inventories/seattle-hospital.xlsx``: a 5-storey concrete shear-wall hospital in Seattle, in inches and
pounds, with no motion typed in and no period known.

Written as a new user would fill it in, to check the site-and-building route end to end: the site as a hazard
lookup gives it (ASCE 7-22, S_DS 1.1 g, S_D1 0.6 g, site class D, Risk Category IV), the building as the drawings
give it (5 storeys of 13 ft, a reinforced-concrete shear wall, no ``period_s``), floors labelled as in the US
(``floor_numbering`` ``ground_1``: the workbook's own floor numbers still count the ground floor 0), and 21 items
on every floor, the roof's penthouse included. Every item and number is invented but typical; do not use it for a
real building. Deterministic (same bytes each run), like build_lab.py.

    python inventories/build_seattle_hospital.py
    assess inventories/seattle-hospital.xlsx --hazard DE,MCE_R
"""
from __future__ import annotations

from pathlib import Path

from build_hospital import site_and_building_workbook
from build_lab import write_replacing
from build_pharmacy import item  # an item in inches and pounds

OUT = Path(__file__).resolve().parent / "seattle-hospital.xlsx"

EQUIPMENT = [
    # floor 0 (the ground floor, "1" in the US): emergency department and receiving
    item("ED-0-01", "Crash cart, 5 drawers", "0-105 resuscitation", 0, 44, 30, 22, 210, 0.45, 12, "critical",
         "on casters, brakes on", casters=True),
    item("ED-0-02", "Supply shelving, 6 shelves, loaded", "0-140 central supply", 0, 86, 48, 24, 900, 0.35, 10,
         "life-safety", "wire shelving beside the exit corridor", cg_in=46),
    item("ED-0-03", "Blanket warmer cabinet", "0-110 ED core", 0, 74, 24, 25, 360, 0.30, 6, "ordinary", "glass doors"),
    item("ED-0-04", "Oxygen cylinder rack, 12 cylinders", "0-150 medical gases", 0, 60, 30, 16, 800, 0.40, 4,
         "hazardous", "freestanding rack"),
    # floor 1: laboratory and blood bank
    item("LB-1-01", "Ultra-low freezer, -80 C, upright", "1-210 core lab", 1, 78, 34, 35, 750, 0.25, 4, "critical",
         "patient specimens"),
    item("LB-1-02", "Blood bank refrigerator, 2 doors", "1-220 blood bank", 1, 80, 52, 32, 680, 0.25, 6, "critical",
         "the hospital's blood supply"),
    item("LB-1-03", "Chemistry analyser", "1-210 core lab", 1, 50, 70, 34, 1500, 0.35, 12, "valuable",
         "levelling feet"),
    item("LB-1-04", "Reagent refrigerator, glass door", "1-210 core lab", 1, 78, 28, 30, 320, 0.30, 6, "valuable",
         "reagents"),
    item("LB-1-05", "CO2 incubator, stacked pair", "1-230 microbiology", 1, 70, 27, 33, 520, 0.30, 3, "valuable",
         "two units on a stacking stand", cg_in=40),
    # floor 2: imaging and pharmacy
    item("IM-2-01", "MRI gradient cabinet", "2-305 MRI equipment room", 2, 79, 31, 39, 1650, 0.35, 8, "critical",
         "electronics, no loose contents", cg_in=36),
    item("RX-2-02", "Automated dispensing cabinet", "2-310 pharmacy", 2, 78, 36, 30, 1100, 0.30, 6, "critical",
         "every dose on the unit"),
    item("RX-2-03", "Medication shelving, 6 shelves", "2-310 pharmacy", 2, 84, 36, 18, 450, 0.35, 18, "life-safety",
         "open shelving", cg_in=46),
    item("RX-2-04", "Pharmacy refrigerator", "2-320 cold storage", 2, 72, 28, 30, 280, 0.25, 8, "critical",
         "vaccines and insulin"),
    # floor 3: patient floor and IT closet
    item("IT-3-01", "Server rack, 42U, loaded", "3-405 IT closet", 3, 80, 24, 42, 1400, 0.30, 14, "critical",
         "nurse call and network", cg_in=36),
    item("IT-3-02", "UPS cabinet", "3-405 IT closet", 3, 60, 20, 32, 1100, 0.30, 6, "critical", "batteries low",
         cg_in=24),
    item("PT-3-03", "Linen cart, covered", "3-420 clean linen", 3, 66, 50, 26, 260, 0.50, 20, "ordinary",
         "on casters, brakes on", casters=True),
    # floor 4: surgery
    item("OR-4-01", "Anesthesia supply cabinet", "4-505 OR core", 4, 76, 36, 20, 420, 0.30, 6, "critical",
         "drawers of supplies"),
    item("OR-4-02", "Sterile storage shelving, 5 shelves", "4-510 sterile core", 4, 84, 48, 24, 700, 0.35, 12,
         "life-safety", "wire shelving", cg_in=44),
    # floor 5: the roof's mechanical penthouse
    item("MP-5-01", "Gas water heater, 100 gal", "5-610 penthouse", 5, 72, 30, 30, 1300, 0.40, 6, "hazardous",
         "gas line"),
    item("MP-5-02", "Spare-parts shelving", "5-610 penthouse", 5, 84, 48, 24, 800, 0.35, 12, "ordinary",
         "motors and filters", cg_in=44),
    item("MP-5-03", "Water-treatment skid", "5-620 penthouse", 5, 70, 60, 36, 2200, 0.40, 0, "critical",
         "bolted to its pad", anchored=True),
]

SITE = [("code", "ASCE 7-22"), ("sds_g", 1.1), ("sd1_g", 0.6), ("site_class", "D"), ("risk_category", "IV")]
BUILDING = [("storeys", 5), ("storey_height_ft", 13), ("system", "shear wall")]
SETTINGS = [("facility", "Seattle shear-wall hospital (5 storeys, invented)"), ("site", "Seattle, WA (invented)"),
            ("floor_numbering", "ground_1")]


def build() -> bytes:
    return site_and_building_workbook(EQUIPMENT, SITE, BUILDING, SETTINGS, "inventories/build_seattle_hospital.py")


if __name__ == "__main__":
    write_replacing(OUT, build())
    print(f"wrote {OUT} ({len(EQUIPMENT)} items)")
