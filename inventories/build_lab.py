"""Build the sample inventory workbook ``inventories/lab.xlsx`` (format: docs/workbook.md).

A sample research-laboratory building with floors 0 (ground) to 6, modelled on
the "UC Science Building" of Konstantinidis & Makris (2010), Bull. Earthquake
Eng. 8:1457-1477 (below "K&M 2010"). The building, its rooms and its
inventory are invented; see inventories/README.md for where every number
came from. Deterministic: no randomness, fixed document dates and fixed zip
timestamps, so re-running it rewrites the same bytes.

    python inventories/build_lab.py
"""
from __future__ import annotations

import datetime
import os
from decimal import ROUND_HALF_UP, Decimal
from fractions import Fraction
from pathlib import Path

from openpyxl import Workbook
from openpyxl.utils import get_column_letter

from assess.report import spreadsheet

OUT = Path(__file__).resolve().parent / "lab.xlsx"
FIXED_DATE = datetime.datetime(2024, 1, 1, 0, 0, 0)

K10 = "Konstantinidis & Makris (2010)"
T1 = f"{K10} Table 1 p.1460"
T3 = f"{K10} Table 3 p.1467"
CAT = "dimensions and mass: typical manufacturer-catalogue values for this class of equipment, not measured"
PCAT = "depth and mass: typical manufacturer-catalogue values for this class of equipment, not measured"
STEEL = ("mu: assumed for steel levelling feet/steel base on vinyl tile or sealed concrete, in the range of "
         f"the equipment-floor values of {T3} (best fit 0.13-0.20, slow pull 0.23-0.31), up to 0.35 for pads")
RUBBER = ("mu: assumed for rubber/elastomer levelling pads on vinyl tile or concrete "
          "(dry rubber typically 0.5-0.8; wooden blocks on concrete 0.68 in K&M 2010 p.1460)")
CASTER = "mu: assumed for equipment standing on locked casters (lower than steel feet)"
CG_LOW = "cg_height: assumed below mid-height (compressor/batteries/drive in the base, contents loaded low)"
CG_HIGH = "cg_height: assumed above mid-height (heavy part carried high on a light stand or top shelves loaded)"


#: What a failure costs, by the kind of item (the id's prefix): gases, cryogens, solvents and biohazards are
#: hazardous; loaded shelving and racks can fall on people or block an exit (life-safety); freezers,
#: incubators and servers hold the samples and data the labs run on (critical); the rest is valuable or ordinary.
CONSEQUENCE_BY_PREFIX = {"GAS": "hazardous", "LN2": "hazardous", "CAB": "hazardous", "BSC": "hazardous",
                         "FLM": "hazardous", "SHF": "life-safety", "ULT": "critical", "FRZ": "critical",
                         "INC": "critical", "SRV": "critical", "REF": "valuable", "CEN": "valuable",
                         "ACL": "valuable", "SHK": "ordinary"}


def item(id, name, room, floor, h, w, d, kg, mu, clearance, notes, source,
         mu_static=None, cg=None, anchored=False, qty=1, mu_range=(None, None), casters=False):
    """One row of the `equipment` sheet, in cm and kg (docs/workbook.md)."""
    return dict(id=id, name=name, room=room, floor=floor, height_cm=h, width_cm=w,
                depth_cm=d, mass_kg=kg, mu=mu, mu_static=mu_static, mu_low=mu_range[0], mu_high=mu_range[1],
                clearance_cm=clearance, cg_height_cm=cg,
                anchored="yes" if anchored else "no", casters="yes" if casters else "no", quantity=qty,
                consequence=CONSEQUENCE_BY_PREFIX.get(id.split("-")[0], "ordinary"),
                notes=notes, source=source)


# The paper's three prototypes, Table 1 height and width exactly, best-fit mu of
# Table 3 (left column). Depth > width so that the Table 1 width governs. mu_low
# to mu_high: the best-fit to the slow-pull value of Table 3 (the two values the
# paper gives for each prototype; the shake table matched the lower).
def forma(id, room, floor, clearance, notes, qty=1):
    return item(id, "FORMA CO2 incubator, stacked pair (K&M prototype)", room, floor,
                228.6, 62.2, 84.0, 330, 0.13, clearance, notes,
                f"height, width: {T1}; mu 0.13: best fit, {T3}; mu_low-mu_high 0.13-0.23: best fit to slow pull, "
                f"{T3}; {PCAT} (stacked water-jacketed CO2 incubators on stand)", qty=qty, mu_range=(0.13, 0.23))


def kelvinator(id, room, floor, clearance, notes):
    return item(id, "KELVINATOR refrigerator (K&M prototype)", room, floor,
                213.4, 66.0, 81.0, 230, 0.17, clearance, notes,
                f"height, width: {T1}; mu 0.17: best fit, {T3}; mu_low-mu_high 0.17-0.28: best fit to slow pull, "
                f"{T3}; {PCAT} (upright laboratory refrigerator, loaded)", mu_range=(0.17, 0.28))


def asp(id, room, floor, clearance, notes):
    return item(id, "ASP refrigerator (K&M prototype)", room, floor,
                180.3, 58.4, 74.0, 140, 0.20, clearance, notes,
                f"height, width: {T1}; mu 0.20: best fit, {T3}; mu_low-mu_high 0.20-0.31: best fit to slow pull, "
                f"{T3}; {PCAT} (upright laboratory refrigerator, loaded)", mu_range=(0.20, 0.31))


ULT = "−80 °C upright ultra-low freezer, loaded"
ULT_SRC = f"{CAT} (upright −80 °C freezer ~86 × 90 cm base, ~300 kg loaded); {CG_LOW}"

EQUIPMENT = [
    # --- Floor 0 (ground): the paper's prototypes under the paper's ground motions
    forma("INC-G-01", "G-120 cell culture", 0, 25, "clearance to the biosafety cabinet beside it"),
    kelvinator("REF-G-01", "G-140 reagent storage", 0, 30, "clearance to the swing of the room's door"),
    asp("REF-G-02", "G-140 reagent storage", 0, 20, "clearance to the KELVINATOR beside it"),
    # --- Floor 0: building services (server room, gas store, LN2 fill station)
    item("SRV-G-01", "Server rack, 42U, UPS batteries in base", "G-050 server room", 0,
         200, 60, 107, 450, 0.35, 15, "racks in a row, not bolted; clearance to the cable-ladder posts",
         f"{CAT}; {STEEL} (steel levelling feet, upper end); {CG_LOW}", cg=85, qty=4),
    item("GAS-G-01", "Gas-cylinder rack, 4 cylinders, freestanding", "G-010 gas cylinder store", 0,
         150, 90, 35, 300, 0.55, 10, "cylinders chained to the rack, rack not bolted; clearance to the wall behind",
         f"dimensions, mass: typical catalogue rack + 4 × ~70 kg cylinders, not measured; {RUBBER}; "
         "cg_height: mid-height of the cylinders", cg=75),
    item("GAS-G-02", "Gas-cylinder rack, 4 cylinders, wall-bolted", "G-010 gas cylinder store", 0,
         150, 90, 35, 300, 0.55, 5, "bolted to the wall: listed, not analysed",
         "as GAS-G-01; anchorage assumed", cg=75, anchored=True, qty=2),
    item("LN2-G-01", "Liquid-nitrogen supply dewar, 180 L, on caster base", "G-015 LN2 fill station", 0,
         160, 51, 51, 250, 0.15, 40, "casters locked; clearance = slack in its transfer hose",
         f"dimensions, mass (full): typical catalogue values for a 180 L liquid cylinder, not measured; "
         f"{CASTER}; cg_height: assumed below mid-height (liquid in the lower vessel)", cg=65, casters=True),
    item("LN2-G-02", "Liquid-nitrogen storage freezer (vapour phase)", "G-015 LN2 fill station", 0,
         105, 80, 80, 380, 0.30, 60, "clearance to the opposite wall",
         f"dimensions, mass (filled): typical catalogue values, not measured; {STEEL}"),
    # --- Floor 1: sample storage, tissue culture, synthesis
    item("ULT-1-01", ULT, "1-110 sample storage", 1, 198, 86, 90, 300, 0.25, 10,
         "freezers side by side; clearance to the neighbouring freezer",
         f"{ULT_SRC}; {STEEL}", cg=85, qty=3),
    item("FRZ-1-01", "−20 °C chest freezer", "1-110 sample storage", 1, 90, 140, 70, 120, 0.70, 10,
         "clearance to the ULT freezer row", f"{CAT}; {RUBBER}", mu_static=0.75),
    item("CEN-1-01", "High-speed centrifuge, floor-standing", "1-130 instrument room", 1,
         90, 70, 90, 390, 0.70, 20, "clearance to the bench",
         f"{CAT}; {RUBBER}; cg_height: assumed low (drive and rotor chamber)", mu_static=0.80, cg=40),
    item("BSC-1-01", "Class II biosafety cabinet, 4 ft, on stand", "1-120 tissue culture", 1,
         230, 135, 80, 350, 0.28, 15, "depth governs; clearance to the wall behind (exhaust duct)",
         f"{CAT}; {STEEL} (stand feet); {CG_HIGH}", cg=140),
    item("CAB-1-01", "Fume-hood base cabinet (solvents), freestanding", "1-140 synthesis lab", 1,
         89, 120, 56, 150, 0.35, 3, "under a 6 ft fume hood; clearance to the hood's side panel",
         f"{CAT} (loaded); {STEEL}", qty=2),
    item("CAB-1-02", "Fume-hood base cabinet (acids), bolted as hood support", "1-140 synthesis lab", 1,
         89, 120, 56, 150, 0.35, 3, "bolted to the floor: listed, not analysed",
         "as CAB-1-01; anchorage assumed", anchored=True, qty=2),
    # --- Floor 2: cell culture, media preparation, stores
    item("INC-2-01", "CO2 incubator, stacked pair on stand", "2-210 cell culture", 2,
         200, 64, 80, 230, 0.25, 15, "clearance to the biosafety cabinet beside it",
         f"{CAT}; {STEEL}", qty=2),
    item("CEN-2-01", "Refrigerated centrifuge, floor-standing", "2-210 cell culture", 2,
         85, 70, 75, 300, 0.75, 15, "clearance to the incubators",
         f"{CAT}; {RUBBER}; cg_height: assumed low (compressor and drive)", mu_static=0.80, cg=38),
    item("REF-2-01", "Chromatography refrigerator, 2 glass doors", "2-220 protein lab", 2,
         200, 132, 80, 230, 0.20, 20, "depth governs; clearance to the wall behind",
         f"{CAT}; {STEEL} (lower end)"),
    item("ACL-2-01", "Benchtop autoclave on mobile steel stand", "2-230 media prep", 2,
         140, 60, 70, 130, 0.45, 30, "casters retracted, rubber-capped feet; clearance to the sink",
         f"{CAT}; {RUBBER} (lower end); {CG_HIGH}", cg=100, casters=True),
    item("SHF-2-01", "Steel wire shelving, 5 shelves, top shelves loaded", "2-240 consumables store", 2,
         188, 122, 46, 120, 0.45, 5, "clearance to the wall behind",
         f"{CAT} (188 × 122 × 46 cm unit, loaded); mu: assumed for plastic/rubber-capped feet on vinyl; {CG_HIGH}",
         cg=110, qty=3),
    # --- Floor 3: freezer corridor, cold room, virology, microbiology
    item("ULT-3-01", ULT + ", on locked casters", "3-310 freezer corridor", 3, 198, 86, 90, 300, 0.15, 8,
         "clearance to the neighbouring freezer", f"{ULT_SRC}; {CASTER}", cg=85, qty=4, casters=True),
    item("SHF-3-01", "Stainless wire shelving, uniformly loaded", "3-214 cold room", 3,
         183, 152, 61, 200, 0.30, 10, "clearance to the cold-room wall",
         f"{CAT}; {STEEL} (steel feet on epoxy floor)", qty=2),
    item("BSC-3-01", "Class II biosafety cabinet, 6 ft, on stand", "3-320 virology", 3,
         230, 195, 80, 450, 0.25, 20, "depth governs; clearance to the bench opposite",
         f"{CAT}; {STEEL} (stand feet); {CG_HIGH}", cg=140),
    item("SHK-3-01", "Incubator shakers, 2 stacked on stand", "3-330 microbiology", 3,
         185, 90, 70, 500, 0.50, 25, "clearance to the doorway",
         f"{CAT}; {RUBBER} (lower end); cg_height: assumed just above mid-height (upper shaker)", cg=95),
    # --- Floor 4: anchored freezers, small dewar, incubator, refrigerators
    item("ULT-4-01", ULT + ", seismic restraint kit", "4-410 sample storage", 4, 198, 86, 90, 300, 0.25, 5,
         "restrained to the wall: listed, not analysed", f"{ULT_SRC}; anchorage assumed",
         cg=85, anchored=True, qty=2),
    item("LN2-4-01", "Liquid-nitrogen dewar, 50 L, on roller base", "4-420 imaging lab", 4,
         80, 50, 50, 85, 0.15, 30, "casters locked; clearance to the microscope table",
         f"dimensions, mass (full): typical catalogue values, not measured; {CASTER}", casters=True),
    item("FLM-4-01", "Flammable-liquids cabinet, 45 gal, wall-bolted", "4-430 chemistry lab", 4,
         165, 109, 46, 250, 0.35, 5, "bolted to the wall: listed, not analysed",
         f"{CAT}; anchorage assumed", anchored=True),
    item("INC-4-01", "CO2 incubator, single, on low stand", "4-430 chemistry lab", 4,
         125, 64, 80, 130, 0.30, 40, "clearance to the bench",
         f"{CAT}; {STEEL}"),
    item("REF-4-01", "Laboratory refrigerator, single glass door", "4-440 genomics", 4,
         200, 71, 80, 160, 0.22, 12, "clearance to the neighbouring refrigerator",
         f"{CAT}; {STEEL}", qty=2),
    # --- Floor 5: freezers, under-counter units, network closet, glassware store
    item("FRZ-5-01", "−20 °C upright laboratory freezer", "5-510 biochemistry", 5,
         190, 76, 80, 180, 0.22, 25, "clearance to the corridor door",
         f"{CAT}; {STEEL}; {CG_LOW}", cg=80),
    item("REF-5-01", "Under-counter refrigerator", "5-520 biochemistry", 5,
         85, 60, 60, 50, 0.40, 3, "under a bench top; clearance to the bench legs",
         f"{CAT}; mu: assumed for plastic feet on vinyl"),
    item("SRV-5-01", "Network rack, 24U, floor-bolted", "5-030 network closet", 5,
         120, 60, 80, 150, 0.30, 5, "bolted to the floor: listed, not analysed",
         f"{CAT}; anchorage assumed", anchored=True),
    item("SHF-5-01", "Steel shelving, glassware, uniformly loaded", "5-530 glassware store", 5,
         213, 91, 61, 150, 0.25, 15, "clearance to the wall behind",
         f"{CAT}; {STEEL}"),
    # --- Floor 6: the paper's prototypes under the 6th-floor motion
    forma("INC-6-01", "6-620 cell culture", 6, 30, "clearance to the neighbouring incubator", qty=2),
    kelvinator("REF-6-01", "6-640 cold storage", 6, 45, "clearance to the opposite refrigerator row"),
    asp("REF-6-02", "6-640 cold storage", 6, 25, "clearance to the KELVINATOR beside it"),
    item("LN2-6-01", "Liquid-nitrogen dewar, 50 L, on roller base", "6-630 structural biology", 6,
         80, 50, 50, 85, 0.12, 50, "casters locked; clearance to the cryo-EM room door",
         f"dimensions, mass (full): typical catalogue values, not measured; {CASTER} (worn wheel locks)",
         casters=True),
    item("ULT-6-01", ULT, "6-610 freezer room", 6, 198, 86, 90, 300, 0.25, 60,
         "clearance to the opposite wall", f"{ULT_SRC}; {STEEL}", cg=85, qty=2),
    item("CEN-6-01", "Ultracentrifuge, floor-standing", "6-630 structural biology", 6,
         95, 80, 70, 450, 0.60, 20, "clearance to the bench",
         f"{CAT}; {RUBBER}; cg_height: assumed low (drive, armour ring)", cg=45),
]


# --- Hazard, level 2in50 only.
def half_up(x: Fraction, step: str) -> float:
    """x rounded half up to a multiple of `step` ("0.01", "1"), exactly."""
    return float((Decimal(x.numerator) / Decimal(x.denominator)).quantize(Decimal(step), ROUND_HALF_UP))


GROUND = [  # (motion as in Table 2/3, PTA g, Tp s, vp cm/s), one row per distinct motion and PTA
    ("Los Gatos PC, ground", "0.54", "2.10", -75),
    ("Los Gatos PC, ground", "0.60", "2.10", -75),
    ("Los Gatos PC FP, ground", "0.57", "2.10", -75),
    ("Corralitos, ground", "0.84", "0.60", -61),
    ("Corralitos, ground", "0.83", "0.60", -61),
    ("Gilroy Hist. Bldg., ground", "0.59", "1.50", -84),
    ("Gilroy Hist. Bldg., ground", "0.58", "1.50", -84),
]
G0 = (Fraction("0.59") + Fraction("0.58") + Fraction("0.59")) / 3, Fraction("1.50"), Fraction(-84)
G6 = Fraction("0.96"), Fraction("1.60"), Fraction(-120)
TOP = 6


def hazard_rows():
    rows = []
    for motion, pta, tp, vp in GROUND:
        rows.append(dict(level="2in50", motion=f"{motion} ({pta} g)", floor=0, pta_g=float(pta),
                         tp_s=float(tp), vp_cm_s=vp, pulse="B",
                         source=f"{T3} (PTA, Tp, vp as printed; Type-B pulse, p.1470); "
                                f"motion name as in {K10} Table 2 p.1461"))
    for f in range(1, TOP):
        pta, tp, vp = (a + (b - a) * Fraction(f, TOP) for a, b in zip(G0, G6))
        rows.append(dict(
            level="2in50", motion=f"Gilroy Hist. Bldg., floor {f} (interpolated)", floor=f,
            pta_g=half_up(pta, "0.01"), tp_s=half_up(tp, "0.01"), vp_cm_s=int(half_up(vp, "1")), pulse="B",
            source=("not in the paper: linear interpolation in floor number between the Gilroy Hist. Bldg. "
                    f"ground motion (mean PTA of the three runs 0.587 g, Tp 1.50 s, vp -84 cm/s; {T3}) and the "
                    f"Gilroy Hist. Bldg. 6th-floor motion (0.96 g, 1.60 s, -120 cm/s; {T3}), value = ground + "
                    f"(6th floor - ground) × {f}/6, i.e. the linear-with-height floor acceleration of ASCE 7-16 "
                    "eq. 13.3-1 (1 + 2z/h) anchored at the paper's two motions instead of the code's factor 3 "
                    "at the roof; rounded to 0.01 g, 0.01 s, 1 cm/s (half up)")))
    rows.append(dict(level="2in50", motion="Gilroy Hist. Bldg., 6th floor (0.96 g)", floor=TOP, pta_g=0.96,
                     tp_s=1.60, vp_cm_s=-120, pulse="B",
                     source=f"{T3} (simulated floor motion of Lee & Mosalam 2005, {K10} p.1461)"))
    return rows


SETTINGS = [
    ("facility", f"Sample research laboratory building (after the UC Science Building, {K10})"),
    ("site", "Berkeley, California (sample)"),
    ("zeta", 0.370), ("eta", 0.953), ("sigma", 0.445),
    ("sds_g", 1.2), ("roof_floor", 7),
]

SOURCES = [
    ("settings: sds_g, roof_floor", "S_DS 1.2 g: a typical ASCE 7-16 value for a Berkeley site of class D (an "
                                    "assumption for the sample, not a site-specific value); the roof is above "
                                    "floor 6, so roof_floor = 7 for z/h in ASCE 7-16 eq. 13.3-1."),
    ("disclaimer", "A SAMPLE building. Rooms, items, depths, masses, clearances and most friction coefficients are "
                   "invented but typical; only the numbers attributed to the paper below are from it."),
    ("paper", f"{K10}, Experimental and analytical studies on the response of 1/4-scale models of freestanding "
              "laboratory equipment subjected to strong earthquake shaking, Bull. Earthquake Eng. 8:1457-1477."),
    ("equipment: prototypes", f"FORMA 228.6 × 62.2 cm, KELVINATOR 213.4 × 66.0 cm, ASP 180.3 × 58.4 cm "
                              f"(height × width): {T1}. mu 0.13 / 0.17 / 0.20: best-fit values, {T3} left "
                              "column; mu_low-mu_high from that best-fit value to the slow-pull value 0.23 / 0.28 / 0.31 of the same table. Depth and "
                              "mass: typical catalogue values, not measured; depth > width so that the Table 1 "
                              "width governs. Placed on floor 0 and floor 6, where the paper's motions act."),
    ("equipment: other items", "height, width, depth, mass: typical manufacturer-catalogue values for the class, "
                               "not measured. Each row's `source` says which."),
    ("equipment: mu", f"steel feet/bases 0.20-0.35, bracketed by {T3} (best fit 0.13-0.20, slow pull 0.23-0.31); "
                      "rubber/elastomer pads 0.45-0.75 (assumed; wooden blocks on concrete 0.68, K&M 2010 p.1460); "
                      "locked casters 0.12-0.15 (assumed). mu_static only where a pad's static value is assumed higher."),
    ("equipment: cg_height_cm", "blank = height/2. Given where the mass is clearly low (compressor, batteries, "
                                "drive, liquid) or high (heavy unit on a light stand, loaded top shelves): assumed."),
    ("equipment: clearance_cm", "assumed; the obstacle (wall, neighbour, doorway, utility line) is in `notes`."),
    ("equipment: anchored", "anchored = yes items are assumed restrained; they are listed, not analysed."),
    ("hazard: floor 0", f"{T3} ground motions, one row per distinct motion and PTA; Tp, vp of the Type-B pulse as "
                        "printed (vp negative); 'Los Gatos PC FP' for the 0.57 g run as named in Table 2 p.1461."),
    ("hazard: floor 6", f"Gilroy Hist. Bldg., 6th floor: 0.96 g, Tp 1.60 s, vp -120 cm/s, {T3}."),
    ("hazard: floors 1-5", "not in the paper: linear interpolation in floor number between the Gilroy ground motion "
                           "(mean of its three runs, 0.587 g; 1.50 s; -84 cm/s) and the Gilroy 6th-floor motion "
                           "(0.96 g; 1.60 s; -120 cm/s): ASCE 7-16 eq. 13.3-1 linear shape (1 + 2z/h) anchored at "
                           "the paper's two motions; rounded to 0.01 g, 0.01 s, 1 cm/s."),
    ("settings", f"zeta 0.370, eta 0.953, sigma 0.445: {K10} eqs. (11) and (21), pp.1472-1475."),
]


def write_sheet(ws, header, rows):
    ws.append(header)
    for row in rows:
        ws.append([row.get(h) if isinstance(row, dict) else row[i] for i, h in enumerate(header)])
    ws.freeze_panes = "A2"
    for i, h in enumerate(header, start=1):
        longest = max(len(str(c.value or "")) for c in ws[get_column_letter(i)])
        ws.column_dimensions[get_column_letter(i)].width = min(max(len(h), longest) + 2, 60)


def deterministic_bytes(wb: Workbook, creator: str) -> bytes:
    """The .xlsx bytes of ``wb`` with fixed document dates and zip timestamps (as assess writes summary.xlsx)."""
    return spreadsheet.deterministic_bytes(wb, creator, FIXED_DATE)


def write_replacing(path: Path, content: bytes) -> None:
    """Write ``content`` to ``path`` through a temporary file renamed over it: no half-written workbook if
    anything fails."""
    tmp = path.with_suffix(path.suffix + ".tmp")
    tmp.write_bytes(content)
    os.replace(tmp, path)


def build() -> bytes:
    wb = Workbook()
    write_sheet(wb.active, list(EQUIPMENT[0]), EQUIPMENT)
    wb.active.title = "equipment"
    write_sheet(wb.create_sheet("hazard"), ["level", "motion", "floor", "pta_g", "tp_s", "vp_cm_s", "pulse",
                                            "source"], hazard_rows())
    write_sheet(wb.create_sheet("settings"), ["key", "value"], SETTINGS)
    write_sheet(wb.create_sheet("sources"), ["subject", "source"], SOURCES)
    return deterministic_bytes(wb, "inventories/build_lab.py")


if __name__ == "__main__":
    ids = [row["id"] for row in EQUIPMENT]
    assert len(ids) == len(set(ids)), "duplicate equipment id"
    write_replacing(OUT, build())
    print(f"wrote {OUT} ({len(EQUIPMENT)} items)")
