"""The anchorage table an engineer checks: one row per item whose action holds it in place (anchor, tether,
strap, chain, restrain) or that is anchored, with the design force's inputs, F_p and its governing bound,
and the shear and tension its anchors carry with and without Ω0, in the report's units.

Every number is a field of the item's :class:`~assess.anchorage.design.AnchorageForces` (the result's
decisions): nothing is computed here but the unit of each force (pint's factors, :mod:`assess.units`) and
F_p/W_p. The same table is the report's section and ``summary.xlsx``'s sheet ``anchorage``.

References: ASCE 7-22 eqs. 13.3-1 to 13.3-6 (ASCE 7-16 eqs. 13.3-1 to 13.3-3), §13.4.2 (Ω0 for anchors in
concrete or masonry).
"""
from __future__ import annotations

import math

import pandas as pd

from assess.quantity_text import floor_numbering_of, floor_text, system_of
from assess.units import conversion_factor

#: The force unit of each system, as pint names it and as a column shows it.
FORCE_UNITS = {"si": ("kilonewton", "kN"), "us": ("kip", "kip")}


def _force(value_n: float, system: str) -> float:
    unit = FORCE_UNITS[system][0]
    return float(value_n) * conversion_factor("newton", unit) if math.isfinite(float(value_n)) else math.nan


def anchorage_rows(result) -> pd.DataFrame:
    """The anchorage table of ``result`` (its ``decisions``): one row per item with a design force, in its
    summary's order, forces in the units of its settings (kN or kip per unit of the item).

    Columns (``assess/data/columns.csv``, file ``summary.xlsx anchorage``): ``id``, ``name``, ``floor``,
    ``action``, ``connections`` (its lines: ``gas, fluid``, ``none``), ``component type``, ``edition``, ``W_p``,
    ``z/h``, ``H_f``, ``R_mu``, ``C_AR``, ``R_po`` (ASCE 7-22; ``a_p``, ``R_p`` under 7-16), ``I_p``, ``F_p``,
    ``F_p/W_p``, ``governs`` (eq. 13.3-1, or its minimum or maximum), ``V`` (the shear at the base, F_p),
    ``T`` (the tension of the anchor line on the far edge of its narrower base, 0.9D − 1.0E), ``Omega_0``,
    ``V with Omega_0``, ``T with Omega_0``, ``table row`` and ``confirmed`` (whether the coefficients were
    read in the standard: ``yes``, ``partly``, ``no``).
    """
    system = system_of(result.settings)
    unit = FORCE_UNITS[system][1]
    listed = result.summary.set_index("id")
    rows = []
    for item_id in result.summary["id"]:
        decision = (result.decisions or {}).get(item_id)
        forces = None if decision is None else decision.anchorage.forces
        if forces is None:
            continue
        omega = forces.overstrength if forces.overstrength_applied else 1.0
        seven_16 = forces.edition == "ASCE 7-16"
        rows.append({
            "id": item_id, "name": listed.at[item_id, "name"], "floor": int(listed.at[item_id, "floor"]),
            "action": decision.action.kind.value, "connections": ", ".join(decision.action.connections) or "none",
            "component type": forces.component_type,
            "edition": forces.edition, f"W_p ({unit})": _force(forces.weight_n, system), "z/h": forces.z_over_h,
            "H_f": math.nan if seven_16 else forces.height_factor,
            "R_mu": math.nan if seven_16 else forces.ductility_reduction,
            "C_AR": math.nan if seven_16 else forces.resonance, "R_po": math.nan if seven_16 else forces.strength,
            "a_p": forces.amplification if seven_16 else math.nan,
            "R_p": forces.response_modification if seven_16 else math.nan,
            "I_p": forces.importance, f"F_p ({unit})": _force(forces.force_n, system),
            "F_p/W_p": forces.force_n / forces.weight_n, "governs": forces.governs,
            f"V ({unit})": _force(forces.shear_n, system), f"T ({unit})": _force(forces.tension_n, system),
            "Omega_0": omega, f"V with Omega_0 ({unit})": _force(forces.anchor_shear_n, system),
            f"T with Omega_0 ({unit})": _force(forces.anchor_tension_n, system),
            "table row": forces.row, "confirmed": forces.coefficients_confirmed,
        })
    table = pd.DataFrame(rows)
    if len(table):
        if not any(decision.anchorage.forces.edition == "ASCE 7-16" for decision in result.decisions.values()
                   if decision.anchorage.forces is not None):
            table = table.drop(columns=["a_p", "R_p"])
    return table


#: Shorter headers on the page (summary.xlsx keeps the plain-text ones).
PAGE_HEADERS = {"component type": "type", "Omega_0": "Ω0", "V with Omega_0": "V·Ω0", "T with Omega_0": "T·Ω0",
                "R_mu": "Rμ", "confirmed": "checked"}
#: The columns summary.xlsx has that the report's page leaves out (they are in its method's table of types).
PAGE_LEAVES_OUT = ("name", "edition", "table row", "connections")


def anchorage_context(result) -> dict | None:
    """The report's anchorage table: its ``columns`` and ``rows`` as text (three significant digits for the
    forces, two decimals for the factors, floors labelled as the report labels them), without
    :data:`PAGE_LEAVES_OUT` so that it fits a page's width; ``edition``; None where no item has a design
    force."""
    table = anchorage_rows(result)
    if not len(table):
        return None
    editions = ", ".join(sorted(set(table["edition"])))
    table = table.drop(columns=[column for column in PAGE_LEAVES_OUT if column in table])
    numbering = floor_numbering_of(result.settings)
    table["floor"] = [floor_text(floor, numbering) for floor in table["floor"]]  # labelled as the report's floors
    def cell(column, value):
        if isinstance(value, float):
            if not math.isfinite(value):
                return "–"
            if column.startswith(("W_p", "F_p (", "V ", "T ", "V with", "T with")):
                return f"{value:.3g}" if abs(value) < 1000 else f"{value:,.0f}"
            return f"{value:.2f}" if column != "F_p/W_p" else f"{value:.3f}"
        return str(value)
    headers = [PAGE_HEADERS.get(column.split(" (")[0], column.split(" (")[0]) + (
        f" ({column.split(' (')[1]}" if " (" in column else "") for column in table.columns]
    return {"edition": editions, "columns": headers,
            "rows": [[cell(column, value) for column, value in zip(table.columns, row)]
                     for row in table.itertuples(index=False)]}
