"""Warnings (not errors) for equipment whose size or density no freestanding equipment has.

The reader's ranges (:mod:`assess.inventory.schema`) refuse what cannot be an
item at all (a height of 20 m). Inside them a value can still be a slip: a
rack typed in centimetres under a ``height_in`` header reads as 213 in, a
17.7-ft rack, and its density drops sixteen-fold; an inch value under a ``_cm``
header makes it sixteen times denser. Such an item is assessed as written, but
the run says where the cell is and why it looks wrong (docs/workbook.md,
*Plausibility warnings*).

Bounds, with why:

* **height above 4 m**: the tallest freestanding equipment of labs,
  hospitals and data centres — upright freezers, 48U racks, tall shelving —
  stands 2.0 to 2.5 m; a storey's clear height is about 2.7 to 3.5 m. 4 m
  leaves room for high-bay storage and stays below the 5.4 m a 213-cm rack
  becomes when read in inches.
* **width or depth above 3 m**: a freestanding unit that long (a bench, a
  row of cabinets bolted together) is unusual; a double-door cold room or a
  row of racks is built in or anchored. The same slip turns a 120-cm bench
  into 3.05 m.
* **density** (mass over the bounding box h × w × d) **below 20 kg/m³ or
  above 3000 kg/m³**: the lightest freestanding equipment for its box is empty
  chrome-wire shelving (a 1.22 × 0.46 × 1.83 m unit of about 23 kg: 22 kg/m³);
  an empty steel wardrobe cabinet (about 50 kg in 1.95 × 0.9 × 0.45 m) is
  63 kg/m³, an empty 42U rack (about 130 kg in 2.0 × 0.6 × 1.07 m) 100 kg/m³.
  A loaded battery cabinet or a safe (1500 to 2000 kg/m³) lies near the top;
  steel itself is 7850 kg/m³, but an item's box holds air: 30 g/cm³
  (30 000 kg/m³) is a slip. The sample workbooks span 84 to 1123 kg/m³.
  Centimetres typed under ``_in`` headers divide a density by 16.4 (a
  400 kg/m³ freezer reads 24 kg/m³: the height check catches it first), inches
  under ``_cm`` headers multiply it by 16.4.
"""
from __future__ import annotations

from dataclasses import dataclass

from assess.errors import Problem
from assess.inventory.units import M_PER_FT
from assess.inventory.schema import quote

#: Taller than this [m]: a warning.
MAX_HEIGHT_M = 4.0
#: Wider or deeper than this [m]: a warning.
MAX_PLAN_M = 3.0
#: Mass over bounding-box volume outside this range [kg/m³]: a warning.
DENSITY_RANGE_KG_M3 = (20.0, 3000.0)
#: The code of the flag an item with a warning carries (summary.csv ``flags``).
FLAG_CODE = "implausible_input"



@dataclass(frozen=True)
class Implausible:
    """One warning: the item it concerns and the located problem (file, sheet, row, cell, column)."""

    item_id: str
    problem: Problem

    def __str__(self) -> str:
        return f"item '{self.item_id}': {self.problem}"


def bounding_box_density_kg_m3(mass_kg, height_m, width_m, depth_m):
    """Mass over the item's bounding box [kg/m³].

    >>> round(bounding_box_density_kg_m3(300.0, 2.0, 0.6, 1.0))
    250
    """
    return mass_kg / (height_m * width_m * depth_m)


def _length_text(value_m: float) -> str:
    return f"{value_m:.2f} m ({value_m / M_PER_FT:.1f} ft)"


def _unit_hint(header) -> str:
    """What a slip of unit between this header and centimetres or inches would look like."""
    if header.suffix in ("in", "ft"):
        return (f" If the values are centimetres, rename the header {header.column.name}_cm "
                f"(a `_{header.suffix}` header reads {'inches' if header.suffix == 'in' else 'feet'}).")
    return " Check the unit in the header: values typed in inches belong under a `_in` header."


def item_warnings(values: dict, raw: dict, headers: dict, row: int, file: str, sheet: str) -> list[Implausible]:
    """The warnings of one equipment row (``values``: canonical SI values by column name, ``raw``: the cells
    as written, ``headers``: the recognised headers by column name)."""
    item_id = str(values["id"])
    found = []

    def warn(column: str, message: str, fix: str) -> None:
        header = headers[column]
        found.append(Implausible(item_id, Problem(file, message, fix, sheet=sheet, row=row, column=header.text,
                                                  cell=f"{header.letter}{row}")))

    for column, limit in (("height", MAX_HEIGHT_M), ("width", MAX_PLAN_M), ("depth", MAX_PLAN_M)):
        value = values[column]
        if value > limit:
            header = headers[column]
            word = "tall" if column == "height" else ("wide" if column == "width" else "deep")
            warn(column, f"{header.text} {quote(raw[column])} is {_length_text(value)}: freestanding equipment is "
                         f"rarely more than {limit:g} m {word}; the item is assessed as written.",
                 "check the value and its unit." + _unit_hint(header))
    density = bounding_box_density_kg_m3(values["mass"], values["height"], values["width"], values["depth"])
    low, high = DENSITY_RANGE_KG_M3
    if not low <= density <= high:
        size = " × ".join(f"{headers[c].text} {quote(raw[c])}" for c in ("height", "width", "depth"))
        side = "below" if density < low else "above"
        density_text = f"{density:.0f}" if density >= 100.0 else f"{density:.3g}"
        warn("mass", f"{headers['mass'].text} {quote(raw['mass'])} in a box of {size} is {density_text} kg/m³ "
                     f"({density / 1000.0:.3g} g/cm³), {side} what equipment weighs for its size "
                     f"({low:g} to {high:g} kg/m³: empty wire shelving to a battery cabinet or a safe); the item "
                     "is assessed as written.",
             "check the mass, the three dimensions and the units in their headers (centimetres typed under "
             "`_in` headers make an item 16 times larger and lighter for its size; inches under `_cm` "
             "headers, 16 times denser).")
    return found


def equipment_warnings(rows, headers: dict, file: str, sheet: str) -> list[Implausible]:
    """Every warning of the equipment sheet's rows (each :class:`assess.inventory.workbook.Row` read
    without a problem), in row order."""
    found = []
    for row in rows:
        needed = ("id", "height", "width", "depth", "mass")
        if row.ok(*needed) and all(row.values.get(name) is not None for name in needed):
            found.extend(item_warnings(row.values, row.raw, headers, row.number, file, sheet))
    return found
