"""Build the sample workbook ``inventories/hospital.xlsx``: a 4-storey hospital, in inches, with no motion typed in.

Written as a hospital's facility engineer would fill it in: the site's hazard as a hazard lookup gives
it (``site`` sheet: ASCE 7-22, S_DS, S_D1, site class D, risk category IV), the building as the
drawings give it (``building`` sheet: 4 storeys of 14 ft, a steel moment frame), and equipment on
every floor in inches and pounds. There is no ``hazard`` sheet: every level's ground suite comes from
the site's spectrum and every floor's motion from the building (docs/workbook.md, sheets ``site`` and
``building``). Every item and number is invented but typical; do not use it for a real building.
Deterministic (same bytes each run), like build_lab.py.

The site's uniform-hazard spectra at 10 % and 2 % in 50 years, for levels named by a probability, are
``hospital-uhs.csv`` in OpenQuake's export layout (``hazard_uhs-mean_*.csv``). They are illustrative,
NOT an OpenQuake run: ASCE 7's two-period shape (S_a = 2.5 PGA on the plateau, T_S = 0.55 s) anchored
at the PGAs of ``lab-hazard-curve.csv`` (0.40 g at 10 % and 0.62 g at 2 % in 50 years), so that the
curve and the spectra agree.

    python inventories/build_hospital.py
    assess inventories/hospital.xlsx --hazard DE
    assess inventories/hospital.xlsx --hazard 2in50,10in50 --oq-hazard inventories/lab-hazard-curve.csv
"""
from __future__ import annotations

from pathlib import Path

from openpyxl import Workbook

from build_lab import deterministic_bytes, write_replacing, write_sheet
from build_pharmacy import item  # an item in inches and pounds, as the pharmacy writes them

OUT = Path(__file__).resolve().parent / "hospital.xlsx"
UHS = OUT.with_name("hospital-uhs.csv")
#: PGA [g] at each probability of exceedance in 50 years: the anchors of lab-hazard-curve.csv.
UHS_PGA_G = {0.1: 0.40, 0.02: 0.62}
UHS_PERIODS_S = (0.05, 0.1, 0.2, 0.3, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0)
#: Plateau over PGA and the corner period T_S of the illustrative spectra (ASCE 7 two-period shape).
PLATEAU_OVER_PGA, CORNER_S = 2.5, 0.55  # S_a(0) = 0.4 S_DS = PGA


EQUIPMENT = [
    # floor 0: emergency department and central supply
    item("ED-0-01", "Crash cart, 5 drawers", "0-105 resuscitation", 0, 44, 30, 22, 210, 0.45, 12, "critical",
         "on casters, brakes on; the code team's cart", casters=True),
    item("ED-0-02", "Supply shelving, 6 shelves, loaded", "0-140 central supply", 0, 86, 48, 24, 900, 0.35, 10,
         "life-safety", "wire shelving beside the corridor to the exit", cg_in=46),
    item("ED-0-03", "Blanket and fluid warmer cabinet", "0-110 ED core", 0, 74, 24, 25, 360, 0.30, 6, "ordinary",
         "two doors, glass"),
    item("ED-0-04", "Liquid-nitrogen dewar, 230 L, on roller base", "0-150 lab receiving", 0, 62, 26, 26, 620, 0.40,
         8, "hazardous", "pressurised LN2 on a roller base", casters=True),
    # floor 1: laboratory
    item("LB-1-01", "Ultra-low freezer, -80 °C, upright", "1-210 core lab", 1, 78, 34, 35, 750, 0.25, 4, "critical",
         "patient specimens and reagents"),
    item("LB-1-02", "Blood bank refrigerator, 2 doors", "1-220 blood bank", 1, 80, 52, 32, 680, 0.25, 6, "critical",
         "the hospital's blood supply"),
    item("LB-1-03", "Chemistry analyser", "1-210 core lab", 1, 50, 70, 34, 1500, 0.35, 12, "valuable",
         "on levelling feet"),
    item("LB-1-04", "Solvent cabinet, 30 gal", "1-230 histology", 1, 44, 43, 18, 300, 0.30, 3, "hazardous",
         "xylene and alcohols"),
    # floor 2: inpatient pharmacy
    item("RX-2-01", "Automated dispensing cabinet, tower", "2-310 pharmacy", 2, 78, 36, 30, 1100, 0.30, 6,
         "critical", "the unit the nurses draw every dose from"),
    item("RX-2-02", "Medication shelving, 6 shelves", "2-310 pharmacy", 2, 84, 36, 18, 450, 0.35, 18, "life-safety",
         "open shelving by the staff workstation", cg_in=46),
    item("RX-2-03", "Pharmacy refrigerator, single door", "2-320 cold storage", 2, 72, 28, 30, 280, 0.25, 8,
         "critical", "vaccines and insulin"),
    # floor 3: patient floor and IT closet
    item("IT-3-01", "Server rack, 42U, loaded", "3-405 IT closet", 3, 80, 24, 42, 1400, 0.30, 14, "critical",
         "nurse-call and the floor's network", cg_in=36),
    item("IT-3-02", "UPS cabinet", "3-405 IT closet", 3, 60, 20, 32, 1100, 0.30, 6, "critical",
         "batteries low in the cabinet", cg_in=24),
    item("PT-3-03", "Linen cart, stainless, covered", "3-420 clean linen", 3, 66, 50, 26, 260, 0.50, 20,
         "ordinary", "on casters, brakes on", casters=True),
    # floor 4: the roof's mechanical penthouse
    item("MP-4-01", "Medical-gas manifold cabinet", "4-510 penthouse", 4, 72, 48, 18, 650, 0.35, 6, "hazardous",
         "oxygen manifold controls"),
    item("MP-4-02", "Spare-parts shelving, 5 shelves", "4-510 penthouse", 4, 84, 48, 24, 800, 0.35, 12,
         "ordinary", "motors and filters on every shelf", cg_in=44),
    item("MP-4-03", "Water-treatment skid", "4-520 penthouse", 4, 70, 60, 36, 2200, 0.40, 0, "critical",
         "bolted to its housekeeping pad", anchored=True),
]

#: The row of ASCE 7 Table 13.5-1 / 13.6-1 each item's anchorage is designed to (the ``component_type`` column,
#: names or aliases of assess/data/components.csv); the others are left empty: laboratory equipment.
COMPONENT_TYPES = {
    "ED-0-02": "storage shelving", "LB-1-01": "freezer", "LB-1-02": "refrigerator", "LB-1-03": "laboratory equipment",
    "RX-2-01": "medical equipment", "RX-2-02": "storage shelving", "RX-2-03": "refrigerator", "IT-3-01": "server rack",
    "IT-3-02": "UPS", "MP-4-01": "mechanical equipment", "MP-4-02": "storage shelving",
    "MP-4-03": "mechanical equipment",
}
for _row in EQUIPMENT:  # after consequence, before notes
    _notes = _row.pop("notes")
    _row["component_type"] = COMPONENT_TYPES.get(_row["id"])
    _row["notes"] = _notes

#: What each item's failure costs per unit (replacement, contents, downtime) and, for some, what its action costs
#: per unit, in US dollars: our estimates for the example, not quotes (the settings give the other actions' costs).
COSTS = {
    "ED-0-01": (25_000, None), "ED-0-02": (15_000, None), "ED-0-03": (8_000, None), "ED-0-04": (20_000, None),
    "LB-1-01": (150_000, 1_200), "LB-1-02": (120_000, None), "LB-1-03": (250_000, 2_500), "LB-1-04": (10_000, None),
    "RX-2-01": (60_000, None), "RX-2-02": (40_000, None), "RX-2-03": (30_000, None),
    "IT-3-01": (200_000, 3_000), "IT-3-02": (50_000, None), "PT-3-03": (2_000, None),
    "MP-4-01": (40_000, None), "MP-4-02": (15_000, None), "MP-4-03": (80_000, None),
}
for row in EQUIPMENT:
    row["value"], row["mitigation_cost"] = COSTS[row["id"]]

#: The site as a hazard lookup gives it (invented values typical of a coastal California site).
SITE = [
    ("code", "ASCE 7-22"), ("sds_g", 1.2), ("sd1_g", 0.7), ("tl_s", 8), ("site_class", "D"),
    ("risk_category", "IV"), ("uhs", UHS.name),
]
#: The building as its drawings give it.
BUILDING = [
    ("storeys", 4), ("storey_height_ft", 14), ("system", "steel moment frame"), ("damping", 0.05),
]
SETTINGS = [
    ("facility", "Sample community hospital (4 storeys)"),
    ("site", "Sample site (invented)"),
    # costs per unit of each kind of action where an item gives none (our estimates, in US dollars)
    ("currency", "USD"),
    ("mitigation_cost_anchor", 1_500), ("mitigation_cost_restrain", 800), ("mitigation_cost_tether", 300),
    ("mitigation_cost_lock_casters", 150), ("mitigation_cost_room", 500), ("mitigation_cost_lower_contents", 200),
    ("mitigation_cost_relocate", 2_000),
]


def spectral_acceleration_g(pga_g: float, period_s: float) -> float:
    """The illustrative spectrum: ASCE 7's two-period shape through ``pga_g`` at T = 0 (S_DS = 2.5 PGA)."""
    sds = PLATEAU_OVER_PGA * pga_g
    t0 = 0.2 * CORNER_S
    if period_s < t0:
        return sds * (0.4 + 0.6 * period_s / t0)
    return sds if period_s <= CORNER_S else sds * CORNER_S / period_s


def uhs_text() -> str:
    """hospital-uhs.csv in the layout of OpenQuake's ``hazard_uhs-mean_*.csv`` export."""
    columns = [f"{poe}~{imt}" for poe in UHS_PGA_G for imt in ["PGA"] + [f"SA({t})" for t in UHS_PERIODS_S]]
    values = [spectral_acceleration_g(pga, period) for pga in UHS_PGA_G.values()
              for period in (0.0,) + UHS_PERIODS_S]
    meta = ("\"generated_by='assess inventories/build_hospital.py (illustrative, not an OpenQuake run)', "
            "kind='mean', investigation_time=50.0\"")
    return "\n".join(["#," + "," * (len(columns) + 1) + meta, "custom_site_id,lon,lat," + ",".join(columns),
                      "HOSP,-121.89000,37.34000," + ",".join(f"{v:.6E}" for v in values)]) + "\n"


def site_and_building_workbook(equipment, site, building, settings, creator: str) -> bytes:
    """A workbook of an equipment sheet and key/value site, building and settings sheets (no hazard sheet)."""
    workbook = Workbook()
    write_sheet(workbook.active, list(equipment[0]), equipment)
    workbook.active.title = "equipment"
    write_sheet(workbook.create_sheet("site"), ["key", "value"], site)
    write_sheet(workbook.create_sheet("building"), ["key", "value"], building)
    write_sheet(workbook.create_sheet("settings"), ["key", "value"], settings)
    return deterministic_bytes(workbook, creator)


def build() -> bytes:
    return site_and_building_workbook(EQUIPMENT, SITE, BUILDING, SETTINGS, "inventories/build_hospital.py")


if __name__ == "__main__":
    write_replacing(OUT, build())
    UHS.write_text(uhs_text())
    print(f"wrote {OUT} ({len(EQUIPMENT)} items)")
