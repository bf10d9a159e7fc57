"""Build ``inventories/advice-hospital.xlsx``: the Seattle shear-wall hospital of build_seattle_hospital.py with
the columns that decide its advice filled in as a facilities engineer would (issue 30).

Its ``component_type`` names what each item is (``gas water heater``, ``cylinder rack``, ``crash cart``,
``shelving``, ``server rack``, ``refrigerator``; assess/data/code_governed.csv prescribes the restraint of the
first five whatever the analysis says) and its ``contents`` what they can do (``fixed`` for the MRI gradient
cabinet's electronics, ``movable`` for loaded shelving, ``none`` for a water heater). Beside them: two reagent
refrigerators on glides (μ 0.18-0.40) 3 in from a bench that slide as far as each other (the slender one may
rock at the high end of its μ, the other cannot), values and action costs for six items (USD, for the
benefit-cost ratios with a hazard curve), low shelving with heavy stock up high (lower_contents), and a linen cart on casters. Every item and number
is invented but typical; do not use it for a real building. Deterministic (same bytes each run).

    python inventories/build_advice_hospital.py
    assess inventories/advice-hospital.xlsx --hazard DE,MCE_R
"""
from __future__ import annotations

from pathlib import Path

from build_hospital import site_and_building_workbook
from build_lab import write_replacing
from build_pharmacy import item  # an item in inches and pounds
from build_seattle_hospital import BUILDING, SITE

OUT = Path(__file__).resolve().parent / "advice-hospital.xlsx"


def typed(row: dict, component_type: str = "", contents: str = "", mu_range=(None, None),
          value=None, mitigation_cost=None) -> dict:
    """``row`` (:func:`build_pharmacy.item`) with its component type, contents, range of μ, value and the cost of
    its action in USD (empty: the defaults, no cost)."""
    return {**row, "component_type": component_type, "contents": contents, "mu_low": mu_range[0],
            "mu_high": mu_range[1], "value": value, "mitigation_cost": mitigation_cost}


EQUIPMENT = [
    # floor 0 (the ground floor, "1" in the US): emergency department, central supply, medical gases
    typed(item("ED-0-01", "Crash cart, 5 drawers", "0-105 resuscitation", 0, 44, 30, 22, 210, 0.45, 12, "critical",
               "on casters, brakes on", casters=True), "crash cart"),
    typed(item("ED-0-02", "Supply shelving, 6 shelves, loaded", "0-140 central supply", 0, 86, 48, 24, 900, 0.35, 10,
               "life-safety", "wire shelving beside the exit corridor", cg_in=46), "shelving", "movable",
          value=8000, mitigation_cost=600),
    typed(item("ED-0-03", "Supply shelving, 4 shelves, heavy stock on top", "0-140 central supply", 0, 60, 36, 18,
               300, 0.45, 10, "ordinary", "low wire shelving, cases of saline on the top shelf", cg_in=40),
          "shelving", "movable"),
    typed(item("ED-0-04", "Oxygen cylinder rack, 12 cylinders", "0-150 medical gases", 0, 60, 30, 16, 800, 0.40, 4,
               "hazardous", "freestanding rack"), "cylinder rack", "fixed", value=20000, mitigation_cost=300),
    # floor 1: laboratory
    typed(item("LB-1-01", "Ultra-low freezer, -80 C, upright", "1-210 core lab", 1, 78, 34, 35, 750, 0.25, 4,
               "critical", "patient specimens"), "freezer"),
    typed(item("LB-1-03", "Reagent refrigerator, glass door", "1-210 core lab", 1, 78, 22, 30, 320, 0.25, 3,
               "valuable", "reagents; on its glides, 3 in to the bench beside it"), "refrigerator",
          mu_range=(0.18, 0.40)),
    typed(item("LB-1-04", "Reagent refrigerator, solid door", "1-210 core lab", 1, 72, 30, 30, 380, 0.25, 3,
               "valuable", "reagents, beside LB-1-03"), "refrigerator", mu_range=(0.18, 0.40)),
    typed(item("LB-1-06", "Reagent refrigerator, glass door, wide", "1-210 core lab", 1, 78, 28, 30, 340, 0.25, 3,
               "valuable", "reagents, beside LB-1-04"), "refrigerator", mu_range=(0.18, 0.40), value=12000,
          mitigation_cost=200),
    typed(item("LB-1-05", "Linen cart, covered", "1-240 clean linen", 1, 66, 50, 26, 260, 0.50, 20, "ordinary",
               "on casters, brakes on", casters=True)),
    # floor 2: imaging
    typed(item("IM-2-01", "MRI gradient cabinet", "2-305 MRI equipment room", 2, 79, 22, 39, 1650, 0.35, 8,
               "critical", "electronics, no loose contents, heavy amplifiers up high", cg_in=46),
          "electrical cabinet", "fixed", value=250000, mitigation_cost=2500),
    typed(item("RX-2-03", "Medication shelving, 6 shelves", "2-310 pharmacy", 2, 84, 36, 18, 450, 0.35, 18,
               "life-safety", "open shelving", cg_in=46), "shelving", "movable"),
    # floor 3: IT closet
    typed(item("IT-3-01", "Server rack, 42U, loaded", "3-405 IT closet", 3, 80, 24, 42, 1400, 0.30, 14, "critical",
               "nurse call and network", cg_in=36), "server rack", value=80000, mitigation_cost=1500),
    # floor 5: the roof's mechanical penthouse
    typed(item("MP-5-01", "Gas water heater, 100 gal", "5-610 penthouse", 5, 72, 30, 30, 1300, 0.40, 6, "hazardous",
               "gas line"), "gas water heater", "none", value=15000, mitigation_cost=400),
    typed(item("MP-5-02", "Spare-parts shelving", "5-610 penthouse", 5, 84, 48, 24, 800, 0.35, 12, "ordinary",
               "motors and filters", cg_in=44), "shelving", "movable"),
]

SETTINGS = [("facility", "Seattle shear-wall hospital, advice check (invented)"), ("site", "Seattle, WA (invented)"),
            ("floor_numbering", "ground_1"), ("currency", "USD")]


def build() -> bytes:
    return site_and_building_workbook(EQUIPMENT, SITE, BUILDING, SETTINGS, "inventories/build_advice_hospital.py")


if __name__ == "__main__":
    write_replacing(OUT, build())
    print(f"wrote {OUT} ({len(EQUIPMENT)} items)")
