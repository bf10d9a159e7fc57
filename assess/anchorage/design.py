"""One call for an item's anchorage design forces, either edition, every term kept (:func:`design_force`).

The result, :class:`AnchorageForces`, holds every term of the equation (:mod:`assess.anchorage.equations`),
the component row used (:mod:`assess.anchorage.coefficients`), the force at the centre of mass (the shear
at the base) and the anchors' tension, without and with the overstrength factor Ω0 that ASCE 7-16 and
7-22 §13.4.2 apply to anchors in concrete or masonry (their design to ACI 318 Chapter 17 takes E as
Ω0·E for tension and shear, ACI 318-14 §17.2.3.4.3(d), §17.2.3.5.3(c); ACI 318-19 §17.10.5.3(d),
§17.10.6.3(c)). The exceptions of those clauses — the anchor's ductile steel governs its tension, the
attachment yields first, or the anchors are designed for the largest force the attachment can transfer —
are the engineer's to claim: ``ductile_anchorage=True`` drops Ω0 and the result says so.

Forces are in newtons; :func:`in_us_units` gives the same numbers in lbf, kip and lbf·ft (pint).
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass

from assess.anchorage.coefficients import canonical_edition, component_coefficients
from assess.anchorage.equations import (
    MINIMUM_DUCTILITY_REDUCTION, base_tension, component_importance_factor, ductility_reduction,
    force_asce7_16, force_asce7_22, force_bounds, govern, height_factor,
)
from assess.quantity_text import force_text
from assess.units import conversion_factor


@dataclass(frozen=True)
class AnchorageForces:
    """An item's anchorage design forces and every term behind them (SI: N, N·m, m).

    ``force_n`` is F_p within its bounds (the shear at the base), ``force_equation_n`` eq. 13.3-1 before
    them, ``governs`` which of ``equation``, ``minimum``, ``maximum`` gave F_p. Terms of the other
    edition are NaN (a_p and R_p under 7-22; H_f, R_μ, C_AR, R_po under 7-16). ``tension_n`` is the
    anchors' tension from F_p (0.9D − 1.0E, E_v = 0.2 S_DS D), ``anchor_shear_n`` and
    ``anchor_tension_n`` the same with Ω0·F_p where ``overstrength_applied`` (NaN tensions without the
    base geometry). ``coefficients_confirmed`` is the table row's ``confirmed`` (``yes``, ``partly``,
    ``no``): the report must say which numbers an engineer must check against the standard.
    """

    edition: str
    component_type: str
    row: str
    coefficients_confirmed: str
    coefficient_source: str
    weight_n: float
    sds_g: float
    z_over_h: float
    above_grade: bool
    importance: float
    amplification: float
    response_modification: float
    height_factor: float
    ductility_reduction: float
    resonance: float
    strength: float
    force_equation_n: float
    force_minimum_n: float
    force_maximum_n: float
    force_n: float
    governs: str
    overstrength: float
    overstrength_applied: bool
    cg_height_m: float
    half_width_m: float
    overturning_moment_nm: float
    tension_n: float
    anchor_shear_n: float
    anchor_tension_n: float

    @property
    def shear_n(self) -> float:
        """The shear at the base [N]: F_p."""
        return self.force_n

    def basis(self, system: str = "si") -> str:
        """The factors used, in words (for the report's method or an item's note); forces in ``system``'s
        units (``'si'`` or ``'us'``, :func:`assess.quantity_text.force_text`)."""
        if self.edition == "ASCE 7-16":
            terms = f"a_p {self.amplification:g}, R_p {self.response_modification:g}"
            equation = "ASCE 7-16 eqs. 13.3-1 to 13.3-3"
        else:
            terms = (f"H_f {self.height_factor:.3f}, R_mu {self.ductility_reduction:.3f}, C_AR {self.resonance:g} "
                     f"({'above' if self.above_grade else 'at or below'} grade), R_po {self.strength:g}")
            equation = "ASCE 7-22 eqs. 13.3-1 to 13.3-6"
        omega = (f"anchors in concrete with Omega_0 {self.overstrength:g} (section 13.4.2)" if self.overstrength_applied
                 else "without Omega_0 (ductile anchorage claimed, or not anchored in concrete)")
        checked = {"yes": "",
                   "partly": "; coefficients from public transcriptions of the table, to be checked against the "
                             "standard",
                   "no": "; coefficients not confirmed, to be checked against the standard",
                   }[self.coefficients_confirmed]
        return (f"{equation}: {self.component_type} ({self.row}): {terms}, I_p {self.importance:g}, "
                f"S_DS {self.sds_g:g} g, z/h {self.z_over_h:.2f}; F_p {force_text(self.force_n / 1000.0, system)} "
                f"({self.governs} governs) for W_p {force_text(self.weight_n / 1000.0, system)}; {omega}{checked}")


def design_force(edition, component_type, weight_n, sds_g, z_over_h, ip=None, period_s=None, building_r=None,
                 building_omega0=None, building_ie=1.0, *, consequence="ordinary", risk_category=None,
                 cg_height_m=math.nan, half_width_m=math.nan, anchors_in_concrete=True, ductile_anchorage=False,
                 at_or_below_grade_unreduced=True) -> AnchorageForces:
    """The anchorage design forces of one item under ``edition`` (``ASCE 7-16`` or ``ASCE 7-22``).

    Parameters
    ----------
    edition : str
        The ``site`` sheet's ``code``.
    component_type : str or None
        A type or alias of ``components.csv`` (any case); None: laboratory equipment.
    weight_n : float
        Operating weight W_p [N] of one unit.
    sds_g : float
        S_DS [g].
    z_over_h : float
        Height of the item's floor over the building's [-]: 0 at grade, 1 on the roof (clipped to 0..1).
        Above 0 the item is "supported above grade" (7-22 C_AR).
    ip : float, optional
        I_p; None: from ``consequence`` and ``risk_category`` (§13.1.3,
        :func:`~assess.anchorage.equations.component_importance_factor`).
    period_s : float, optional
        The building's T_a [s] for H_f (7-22); None: eq. 13.3-5.
    building_r, building_omega0, building_ie : float, optional
        R, Ω0 and I_e of the building's seismic force-resisting system for R_μ (7-22); None: R_μ = 1.3.
    cg_height_m, half_width_m : float
        Centre-of-mass height and half the base dimension b [m] for the tension (NaN: no tension).
    anchors_in_concrete, ductile_anchorage : bool
        Ω0 applies to anchors in concrete or masonry unless the ductile exceptions are claimed.
    at_or_below_grade_unreduced : bool
        R_μ = 1.0 at grade (z/h = 0) under 7-22 (see :mod:`assess.anchorage.equations`).

    Examples
    --------
    ASCE 7-16, laboratory equipment (a_p 1, R_p 2.5): a 300 kg freezer on the roof, S_DS 1.0 g:
    0.4·1·1·2942/2.5·3 = 1412 N:

    >>> round(design_force("ASCE 7-16", None, 300 * 9.80665, 1.0, 1.0).force_n)
    1412
    """
    edition = canonical_edition(edition)
    row = component_coefficients(edition, component_type)
    z = min(max(float(z_over_h), 0.0), 1.0)
    importance = component_importance_factor(consequence, risk_category, ip)
    minimum, maximum = (float(x) for x in force_bounds(weight_n, sds_g, importance))
    nan = math.nan
    if edition == "ASCE 7-16":
        equation = float(force_asce7_16(weight_n, sds_g, z, importance, row.amplification, row.response_modification))
        height = ductility = resonance = strength = nan
    else:
        height = float(height_factor(z, period_s))
        ductility = (1.0 if (at_or_below_grade_unreduced and z == 0.0)
                     else ductility_reduction(building_r, building_ie, building_omega0))
        resonance = row.resonance_above_grade if z > 0.0 else row.resonance_at_or_below_grade
        strength = row.strength
        equation = float(force_asce7_22(weight_n, sds_g, importance, height, ductility, resonance, strength))
    force, governs = govern(equation, minimum, maximum)
    applied = bool(anchors_in_concrete and not ductile_anchorage)
    omega = row.overstrength if applied else 1.0
    if math.isfinite(cg_height_m) and math.isfinite(half_width_m) and half_width_m > 0.0:
        moment, tension = (float(x) for x in base_tension(force, cg_height_m, weight_n, half_width_m, sds_g))
        anchor_tension = float(base_tension(omega * force, cg_height_m, weight_n, half_width_m, sds_g)[1])
    else:
        moment = tension = anchor_tension = nan
    return AnchorageForces(
        edition=edition, component_type=row.component_type, row=row.row, coefficients_confirmed=row.confirmed,
        coefficient_source=row.source, weight_n=float(weight_n), sds_g=float(sds_g), z_over_h=z, above_grade=z > 0.0,
        importance=importance,
        amplification=row.amplification if edition == "ASCE 7-16" else nan,
        response_modification=row.response_modification if edition == "ASCE 7-16" else nan,
        height_factor=height, ductility_reduction=ductility, resonance=resonance, strength=strength,
        force_equation_n=equation, force_minimum_n=minimum, force_maximum_n=maximum, force_n=force, governs=governs,
        overstrength=row.overstrength, overstrength_applied=applied, cg_height_m=float(cg_height_m),
        half_width_m=float(half_width_m), overturning_moment_nm=moment, tension_n=tension,
        anchor_shear_n=omega * force, anchor_tension_n=anchor_tension)


#: The force fields of :class:`AnchorageForces` converted by :func:`in_us_units`.
FORCE_FIELDS = ("weight_n", "force_equation_n", "force_minimum_n", "force_maximum_n", "force_n", "tension_n",
                "anchor_shear_n", "anchor_tension_n")


def in_us_units(forces: AnchorageForces) -> dict:
    """The forces of ``forces`` in US units: ``<name>_lbf`` and ``<name>_kip`` for each force field
    (``force_n`` → ``force_lbf``, ``force_kip``), ``overturning_moment_lbf_ft``; conversions by pint
    (1 lbf = 4.4482216152605 N).

    >>> round(in_us_units(design_force("7-16", None, 4448.2216152605, 1.0, 1.0))["weight_lbf"], 6)
    1000.0
    """
    out = {}
    lbf, kip = conversion_factor("newton", "lbf"), conversion_factor("newton", "kip")
    values = asdict(forces)
    for name in FORCE_FIELDS:
        stem = name[:-2]
        out[f"{stem}_lbf"] = values[name] * lbf
        out[f"{stem}_kip"] = values[name] * kip
    out["overturning_moment_lbf_ft"] = (values["overturning_moment_nm"]
                                        * conversion_factor("newton * meter", "lbf * foot"))
    return out


__all__ = ["AnchorageForces", "design_force", "in_us_units", "FORCE_FIELDS", "MINIMUM_DUCTILITY_REDUCTION"]
