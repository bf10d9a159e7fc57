"""An item of the workbook in its building: the anchorage columns of ``summary.csv`` (:func:`item_anchorage`).

What the design force of ASCE 7 Chapter 13 (:func:`assess.anchorage.design_force`) needs from the workbook,
and where each comes from (:func:`anchorage_site` says it in ``AnchorageSite.basis``):

- the edition: the ``site`` sheet's ``code`` (ASCE 7-22 when it has none, or there is no site sheet);
- S_DS: the site sheet (``sds_g``, or from ``ss_g``, ``s1_g`` and ``site_class``), else the settings' ``sds_g``;
- the Risk Category: the site sheet's ``risk_category`` (II when not given);
- z/h: the item's floor over the building sheet's ``storeys`` (the roof is floor ``storeys``), else over the
  settings' ``roof_floor``; neither: z/h = 1 (the roof's force, an upper bound);
- T_a for H_f (ASCE 7-22 eq. 13.3-4): the building's approximate period C_t h_n^x (§12.8.2.1, eq. 12.8-7,
  :func:`assess.building.period.approximate_period`), as §13.3.1.1 asks ("the lowest approximate fundamental
  period"), from the building sheet's ``height`` and ``system``; without a building sheet H_f = 1 + 2.5 z/h
  (eq. 13.3-5);
- R_μ (ASCE 7-22 eq. 13.3-6): sqrt(1.1 R/(I_e Ω0)), not less than 1.3, from the building sheet's ``system``
  (Table 12.2-1's R and Ω0, :data:`assess.building.design.SYSTEM_FACTORS`; ``other`` when not given, whose R 3
  and Ω0 3 give the least value) and the Risk Category's I_e (Table 1.5-2); without a building sheet 1.3, the
  largest force the equation allows; R_μ = 1.0 at grade.

Per item: ``component_type`` (a row of Table 13.5-1 / 13.6-1, or an alias; empty: laboratory equipment,
:data:`~assess.anchorage.coefficients.DEFAULT_COMPONENT_TYPE`), ``ip`` (1.0 or 1.5; empty: from the
``consequence`` and the Risk Category, §13.1.3), W_p its mass times g (one unit), and the base about its
narrower side for the anchors' tension. Ω0 is applied to the anchors' shear and tension (anchors in
concrete, §13.4.2), in their own columns beside those without it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from assess.anchorage.coefficients import DEFAULT_COMPONENT_TYPE, canonical_edition, component_coefficients
from assess.building.design import SYSTEM_FACTORS, importance_factor
from assess.building.period import approximate_period
from assess.anchorage.design import AnchorageForces, design_force
from assess.anchorage.equations import component_importance_factor, ductility_reduction
from assess.site.asce7 import from_mapped_values
from assess.units import conversion_factor

#: ``g`` [m/s²] (the one in assess.mechanics.geometry; repeated so this package stays free of the engine's).
STANDARD_GRAVITY_M_S2 = 9.80665
#: Edition when the workbook names none (the current edition).
DEFAULT_EDITION = "ASCE 7-22"
DEFAULT_RISK_CATEGORY = "II"
#: Action kinds (``action_kind``) whose item gets the design force: it is anchored, restrained or tethered
#: (its restraint carries the force; a code's strap or chain too), or already anchored (its anchorage to be checked
#: against it).
ANCHORAGE_KINDS = ("anchor", "restrain", "tether", "strap", "chain", "anchored")

#: The anchorage columns of ``summary.csv`` (docs/outputs.md), in order; the ``*_kip`` ones and ``anchor_basis``
#: are the report's (:func:`assess.report.advice.anchorage_columns`), the others :meth:`ItemAnchorage.columns`.
COLUMNS = ("component_type", "ip", "anchor_force_kn", "anchor_force_kip", "anchor_moment_knm", "anchor_moment_kip_ft",
           "anchor_tension_kn", "anchor_tension_kip", "anchor_omega0", "anchor_shear_omega_kn",
           "anchor_shear_omega_kip", "anchor_tension_omega_kn", "anchor_tension_omega_kip", "anchor_basis")
#: Newtons per kilonewton (pint).
N_PER_KN = conversion_factor("kilonewton", "newton")


@dataclass(frozen=True)
class AnchorageSite:
    """What the design force takes from the site, the building and the settings, and where it came from.

    ``sds_g`` is NaN when nothing gives it; ``storeys`` is the roof's floor number (NaN: z/h = 1);
    ``period_s`` T_a [s] for H_f (None: eq. 13.3-5); ``building_r``, ``building_omega0``, ``building_ie`` the
    building's R, Ω0 and I_e for R_μ (None: R_μ 1.3). ``basis`` says where each came from, in words.
    """

    edition: str = DEFAULT_EDITION
    risk_category: str = DEFAULT_RISK_CATEGORY
    sds_g: float = math.nan
    storeys: float = math.nan
    period_s: float | None = None
    building_r: float | None = None
    building_omega0: float | None = None
    building_ie: float = 1.0
    basis: str = ""

    def z_over_h(self, floor) -> float:
        """z/h of an item on ``floor``: floor / roof floor within 0..1; 1 where the roof floor is not known."""
        if not self.storeys > 0.0:
            return 1.0
        return min(max(float(floor) / float(self.storeys), 0.0), 1.0)


def _sds_from_site(site) -> tuple[float, str]:
    if site is None:
        return math.nan, ""
    if site.sds_g is not None:
        return float(site.sds_g), "the site sheet's sds_g"
    if site.ss_g is not None:
        try:
            spectrum = from_mapped_values(site.ss_g, site.s1_g, site.site_class, site.tl_s, code=site.code)
        except ValueError:
            return math.nan, ""
        return float(spectrum.sds_g), "the site sheet's ss_g, s1_g and site class"
    return math.nan, ""


def anchorage_site(site=None, building=None, settings=None) -> AnchorageSite:
    """The :class:`AnchorageSite` of a workbook from its ``site`` and ``building`` sheets
    (:class:`~assess.inventory.site_building.SiteSheet`, :class:`~assess.inventory.site_building.BuildingSheet`,
    None where absent) and its settings (:class:`assess.inventory.settings.Settings`: ``sds_g``, ``roof_floor``
    where the sheets do not give them; None: neither given).

    >>> from assess.inventory.settings import Settings
    >>> s = anchorage_site(None, None, Settings(sds_g=1.0, roof_floor=4))
    >>> s.edition, s.risk_category, s.sds_g, s.z_over_h(2), s.period_s
    ('ASCE 7-22', 'II', 1.0, 0.5, None)
    """
    notes = []
    edition = canonical_edition(site.code) if site is not None else DEFAULT_EDITION
    risk = str(site.risk_category) if site is not None else DEFAULT_RISK_CATEGORY
    notes.append(f"{edition} from the site sheet" if site is not None else f"{edition} (no site sheet)")
    notes.append(f"Risk Category {risk}" + ("" if site is not None else " (no site sheet)"))
    sds_g, source = _sds_from_site(site)
    if not math.isfinite(sds_g):
        given = settings.sds_g if settings is not None else 0.0
        sds_g, source = (given, "the settings' sds_g") if given > 0.0 else (math.nan, "")
    if source:
        notes.append(f"S_DS {sds_g:g} g from {source}")
    period_s = building_r = building_omega0 = None
    building_ie = importance_factor(risk)
    if building is not None:
        storeys = float(building.storeys)
        period_s = float(approximate_period(building.height_m, building.system))
        notes.append(f"z/h = storeys from the ground floor to the item's / {building.storeys} storeys; "
                     f"T_a = {period_s:.3f} s (eq. 12.8-7, {building.system}, h_n {building.height_m:.1f} m)")
        building_r, building_omega0, row = SYSTEM_FACTORS[building.system]
    else:
        roof = settings.roof_floor if settings is not None else 0.0
        storeys = roof if roof > 0.0 else math.nan
        notes.append(f"z/h = the workbook's floor / roof_floor {roof:g}" if roof > 0.0
                     else "z/h = 1 (no building sheet or roof_floor: the roof's force)")
        if edition == "ASCE 7-22":
            notes.append("H_f = 1 + 2.5 z/h (eq. 13.3-5: no building period)")
    if edition == "ASCE 7-22" and building_r is not None:
        r_mu = ductility_reduction(building_r, building_ie, building_omega0)  # Table 12.2-1's row, read above
        notes.append(f"R_mu {r_mu:.3f} (eq. 13.3-6: R {building_r:g} and Omega0 {building_omega0:g} of Table 12.2-1's "
                     f"{row}, I_e {building_ie:g}; 1.0 at grade)")
    elif edition == "ASCE 7-22":
        notes.append("R_mu 1.3 (eq. 13.3-6, the building's R not given; 1.0 at grade)")
    return AnchorageSite(edition=edition, risk_category=risk, sds_g=sds_g, storeys=storeys, period_s=period_s,
                         building_r=building_r, building_omega0=building_omega0, building_ie=building_ie,
                         basis="; ".join(notes))


def system_ductility_reduction(system: str, importance: float) -> float:
    """R_μ of ASCE 7-22 eq. 13.3-6 for a building of lateral ``system``: its R and Ω0 of Table 12.2-1
    (:data:`assess.building.design.SYSTEM_FACTORS`) and its I_e ``importance`` [-]; the anchorage forces and
    ``floors.csv``'s H_f/R_μ both take it from here.

    >>> round(system_ductility_reduction("steel moment frame", 1.5), 4), system_ductility_reduction("other", 1.0)
    (1.3984, 1.3)
    """
    r_factor, omega0, _ = SYSTEM_FACTORS[system]
    return ductility_reduction(r_factor, importance, omega0)


def _type_name(item) -> str:
    name = getattr(item, "component_type", None)
    if name is None or (isinstance(name, float) and name != name) or not str(name).strip():
        return DEFAULT_COMPONENT_TYPE
    return str(name)


def item_forces(item, consequence: str, site: AnchorageSite) -> AnchorageForces:
    """The design forces of one workbook item (``item``: a row of the equipment table, with ``floor``,
    ``mass_kg``, ``width_m``, ``depth_m``, ``cg_height_m`` and, where given, ``component_type``, ``ip``)."""
    return design_force(
        site.edition, _type_name(item), float(item.mass_kg) * STANDARD_GRAVITY_M_S2, site.sds_g,
        site.z_over_h(item.floor), ip=getattr(item, "ip", None), period_s=site.period_s, building_r=site.building_r,
        building_omega0=site.building_omega0, building_ie=site.building_ie, consequence=consequence,
        risk_category=site.risk_category, cg_height_m=float(item.cg_height_m),
        half_width_m=min(float(item.width_m), float(item.depth_m)) / 2.0)


@dataclass(frozen=True)
class ItemAnchorage:
    """What one item's anchorage must resist (:func:`item_anchorage`), in SI: its component type and I_p;
    ``forces`` (:class:`~assess.anchorage.design.AnchorageForces`, newtons) where its action holds it in place
    and S_DS is known, None otherwise; ``wanted``: whether its action asks for the force
    (:data:`ANCHORAGE_KINDS`); ``site``: where the force's terms come from."""

    component_type: str
    importance: float
    forces: AnchorageForces | None
    wanted: bool
    site: AnchorageSite

    @property
    def missing_sds(self) -> bool:
        """The force is wanted but S_DS is not known."""
        return self.wanted and self.forces is None

    def columns(self) -> dict:
        """Its columns of summary.csv in SI (kN, kN·m; NaN without a force); ``ip`` and ``component_type``
        always."""
        out = {column: math.nan for column in COLUMNS if not column.endswith(("_kip", "_kip_ft", "_basis"))}
        out.update({"component_type": self.component_type, "ip": self.importance})
        forces = self.forces
        if forces is None:
            return out
        out.update({
            "anchor_force_kn": forces.force_n / N_PER_KN, "anchor_moment_knm": forces.overturning_moment_nm / N_PER_KN,
            "anchor_tension_kn": forces.tension_n / N_PER_KN,
            "anchor_omega0": forces.overstrength if forces.overstrength_applied else 1.0,
            "anchor_shear_omega_kn": forces.anchor_shear_n / N_PER_KN,
            "anchor_tension_omega_kn": forces.anchor_tension_n / N_PER_KN,
        })
        return out


def item_anchorage(item, consequence: str, action_kind: str, site: AnchorageSite) -> ItemAnchorage:
    """The anchorage of one item (:class:`ItemAnchorage`): its component type and I_p always; for an item
    whose ``action_kind`` is one of :data:`ANCHORAGE_KINDS`, the design forces per unit (F_p and what it does
    at the base, without and with Ω0) where S_DS is known."""
    wanted = action_kind in ANCHORAGE_KINDS
    if not wanted or not site.sds_g > 0.0:
        return ItemAnchorage(component_coefficients(site.edition, _type_name(item)).component_type,
                             component_importance_factor(consequence, site.risk_category, getattr(item, "ip", None)),
                             None, wanted, site)
    forces = item_forces(item, consequence, site)
    return ItemAnchorage(forces.component_type, forces.importance, forces, True, site)
