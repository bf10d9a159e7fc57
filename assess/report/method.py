"""What the method section says about where this report's floor motions come from.

The floor motions reach an item by one of four routes (docs/workbook.md): given per floor in the
``hazard`` sheet; derived from the ground motion with ``--derive-floors``; a ``site`` sheet's ground
suite (records scaled, or synthetic motions matched, to the site's spectrum) acting on the ground floor;
and that suite through the ``building`` sheet's elastic modes to the upper floors. The method section
gives the equations of every route and says which this report took, from the result alone.
"""
from __future__ import annotations

from assess.assessment.result import AssessmentResult
from assess.building.nonlinear import DEFAULT_HARDENING


def floor_motion_route(result: AssessmentResult) -> dict:
    """Which routes gave this report's floor motions: ``given`` (the hazard sheet's floor motions, unless a
    site sheet gives the level), ``derived`` (``--derive-floors``: floors without one derived from the
    ground's), ``site`` (a site sheet's ground suite) and ``building`` (that suite through the building's
    modes to the upper floors), ``yielding`` (through its yielding stick instead) and its storeys' ``hardening``
    (floors.csv's ``storey_hardening_ratio``; None without one) beside ``default_hardening``; and ``ground``, how the
    site made its ground suite (``records``, ``matched records`` or ``synthetic``, the result's ``ground_method``; ""
    without one)."""
    site = result.ground_motions is not None
    building = result.floors is not None
    yielding = building and "response" in result.floors  # floors.csv of a yielding building says so
    derived = any(flag.code == "derived_floor_motion" for flag in result.flags)
    hardening = float(result.floors["storey_hardening_ratio"].iloc[0]) if yielding else None
    return {"site": site, "building": building, "yielding": bool(yielding), "hardening": hardening,
            "default_hardening": DEFAULT_HARDENING, "derived": derived,
            "given": not (site or building),
            "ground": str(getattr(result, "ground_method", "") or "") if site else ""}
