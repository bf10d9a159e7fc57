"""Stage 2a of the assessment: from the site and the building to every floor's motion.

With a ``site`` sheet, a level that the ``hazard`` sheet gives no ground motion for gets its ground
suite from the site: the level's target spectrum (``DE``, ``MCE_R``: ASCE 7; a probability: the
site's OpenQuake uniform-hazard spectrum) and records selected and scaled to it from the site's
``records`` folder, or spectrum-compatible synthetic motions (:mod:`assess.site`). With a
``building`` sheet, every floor that has no ``hazard`` rows at the level gets its motions by passing
each ground motion through the building (:mod:`assess.building`): its elastic modes, or, with
``response: yielding``, a stick of yielding storey springs (:mod:`assess.building.yielding`); the
floor's absolute acceleration in time. A floor with its own ``hazard`` rows keeps them: a structural
engineer's floor motions govern. The sheets are described in docs/workbook.md.

The functions here build those motions; :mod:`assess.assessment.motions` places them among the
level's motions.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from assess.building import BuildingModes, building_modes
from assess.anchorage.equations import height_factor
from assess.anchorage.item import system_ductility_reduction
from assess.building.design import OVERSTRENGTH_SOURCE_BY_SYSTEM, design_storey_stiffness
from assess.building.floors import floors_table
from assess.building.hysteresis import BRACE_BUCKLING_RATIO, BRACE_POST_BUCKLING_RATIO
from assess.building.nonlinear import STRENGTH_BY_SYSTEM
from assess.building.modes import ALPHA_BY_SYSTEM
from assess.building.period import approximate_period
from assess.building.pushover import (SLOPE_ROOF_DRIFT_RATIO, AlphaFromPushover, alpha_from_pushover,
                                      pushover_slope_ratio)
from assess.building.response import floor_records
from assess.building.yielding import (BASE_HINGE, STABILITY_COEFFICIENT_MAX, YieldingBuilding, storey_table,
                                      yielding_building, yielding_histories)
from assess.errors import InputError, Problem
from assess.hazard.levels import HazardLevel
from assess.hazard.openquake import SiteChoiceError, parse_site_choice
from assess.hazard.records import Record
from assess.inventory.site_building import MAX_YIELDING_STOREYS, BuildingSheet, SiteSheet
from assess.quantity_text import floor_text, floors_text, sentence_start
from assess.site.asce7 import MCE_R_OVER_DESIGN, DesignSpectrum, from_design_values, from_mapped_values
from assess.site.suite import MEAN_RATIO_MIN, GroundSuite, ground_suite
from assess.site.target import asce7_level, level_target

#: Shortest and longest period of an item's rocking 2π/p that the suite's period range follows [s].
#: Below 0.05 s a target spectrum is PGA; beyond 4 s a block is so large that it does not rock.
ITEM_PERIOD_RANGE_S = (0.05, 4.0)


@dataclass(frozen=True)
class SiteSuite:
    """A level's ground suite from the site, and the building's modes it passes through (if any).

    Attributes
    ----------
    suite : GroundSuite
        The motions against their target (``ground_motions.csv``, ``spectrum.csv``).
    design : DesignSpectrum or None
        The site's ASCE 7 spectrum, where the site sheet gives one.
    periods_s : ndarray
        The periods that matter, which set the suite's period range [s].
    spectrum : str or None
        Which ASCE 7 spectrum the level's target is (:func:`assess.site.target.asce7_level`: ``design`` or
        ``MCE_R``, 1.5 times it); None for a uniform-hazard spectrum.
    """

    suite: GroundSuite
    design: DesignSpectrum | None
    periods_s: np.ndarray
    spectrum: str | None = None


def storey_stiffness_of(building: BuildingSheet) -> np.ndarray:
    """The storeys' relative stiffnesses, the first storey to the roof: the sheet's ``storey_stiffness``, else
    the system's design profile (:func:`assess.building.design.design_storey_stiffness`, equal floor weights,
    at T_1: given, or ASCE 7 Table 12.8-2's estimate)."""
    if building.storey_stiffness is not None:
        return np.asarray(building.storey_stiffness, dtype=float)
    heights = building.height_m / building.storeys * np.arange(1, building.storeys + 1)
    period_s = building.period_s if building.period_s is not None else approximate_period(heights[-1],
                                                                                           building.system)
    return design_storey_stiffness(building.system, np.ones(building.storeys), heights, period_s)


#: The α a pushover's slope is looked for between (:func:`pushover_alpha`): from columns so stiff that the storeys
#: barely yield to storeys that shear as a shear building's.
PUSHOVER_ALPHA_BOUNDS = (0.5, 30.0)


@functools.lru_cache(maxsize=16)
def pushover_alpha(building: BuildingSheet) -> AlphaFromPushover | None:
    """The α whose yielding stick, pushed over under the code's lateral forces, has the sheet's
    ``pushover_slope_ratio`` (:func:`assess.building.pushover.alpha_from_pushover`); None without it.

    The stick is the one the yielding route runs (the sheet's T_1, storey stiffnesses, ``yield_base_shear_g`` and
    ``p_delta``) at each α tried; the sheet's checks made sure the system is a frame or a braced frame and the
    strength is given."""
    if building.pushover_slope_ratio is None:
        return None

    def slope_at(alpha: float) -> float:
        modes = building_modes_of(building, alpha)
        model = yielding_building(modes, building.system, **_stick_arguments(building))
        return pushover_slope_ratio(model.stick, float(modes.periods_s[0]))

    return alpha_from_pushover(float(building.pushover_slope_ratio), slope_at, PUSHOVER_ALPHA_BOUNDS,
                               prefer=ALPHA_BY_SYSTEM[building.system])


def alpha_of(building: BuildingSheet) -> float:
    """The lateral stiffness ratio α the building is modelled with: the sheet's ``lateral_stiffness_ratio``, else the
    one its ``pushover_slope_ratio`` gives (:func:`pushover_alpha`), else the system's typical one."""
    if building.lateral_stiffness_ratio is not None:
        return float(building.lateral_stiffness_ratio)
    found = pushover_alpha(building)
    return found.alpha if found is not None else ALPHA_BY_SYSTEM[building.system]


def alpha_source_of(building: BuildingSheet, short: bool = False) -> str:
    """Where :func:`alpha_of`'s α comes from, in words for the notes (``short``: in a few)."""
    if building.alpha_source:
        return building.alpha_source
    if building.lateral_stiffness_ratio is not None:
        return "given"
    found = pushover_alpha(building)
    if found is None:
        return "the system's typical one"
    if short:
        return "from the pushover's slope after yield"
    said, drift = f"from pushover_slope_ratio {found.slope_ratio:g}", f"{SLOPE_ROOF_DRIFT_RATIO:.0%} roof drift"
    if not found.matched:
        low, high = found.slope_ratio_range
        return (f"{said}, which the yielding stick's pushover has at no α from {found.bounds[0]:g} to "
                f"{found.bounds[1]:g} (its slope at {drift} over the initial one lies between {low:.3g} and "
                f"{high:.3g} there): the α whose slope, {found.stick_slope_ratio:.3g}, comes nearest; check the slope "
                f"is read at {drift} and the strength is the pushover's")
    if len(found.roots) > 1:
        others = ", ".join(f"{a:.3g}" for a in found.roots if a != found.alpha)
        return (f"{said}: the yielding stick's pushover has that slope at {drift} at this α and at {others}, and "
                "this one is nearer the system's typical α")
    return f"{said}: the yielding stick's pushover has that slope at {drift} at this α"


def building_modes_of(building: BuildingSheet, alpha: float | None = None) -> BuildingModes:
    """The building sheet's modes (:func:`assess.building.building_modes`), every mode kept, with the storeys'
    stiffness profile of :func:`storey_stiffness_of` and the α of :func:`alpha_of` (or ``alpha``)."""
    return building_modes(building.storeys, building.height_m / building.storeys, system=building.system,
                          period_s=building.period_s, damping=building.damping,
                          alpha=alpha_of(building) if alpha is None else alpha,
                          storey_stiffness=storey_stiffness_of(building))


def _stick_arguments(building: BuildingSheet) -> dict:
    """What the building sheet gives :func:`assess.building.yielding.yielding_building` beside the modes, the
    system and the site's design values: the yielding route's stick and :func:`pushover_alpha`'s are the same."""
    return dict(damping=building.damping, overstrength=building.overstrength,
                yield_base_shear_g=building.yield_base_shear_g, p_delta=building.p_delta,
                hardening=building.storey_hardening_ratio, law="buckling" if building.brace_buckling else None,
                storey_strength=building.storey_strength)


def building_model_of(building: BuildingSheet, site: SiteSheet | None, modes: BuildingModes | None = None,
                      workbook_name: str = ""):
    """How the floor route models the building: its elastic modes, or, where the sheet's response is
    ``yielding`` (:meth:`~assess.inventory.site_building.BuildingSheet.response_with`), its yielding stick
    (:func:`assess.building.yielding.yielding_building`) with the site's design values and risk category."""
    modes = building_modes_of(building) if modes is None else modes
    if building.response_with(site) != "yielding":
        return modes
    design = {}
    if building.yield_base_shear_g is None:  # the code's design (the workbook check made sure the site gives it)
        spectrum = design_spectrum_of(site, workbook_name)
        design = dict(sds_g=spectrum.sds_g, sd1_g=spectrum.sd1_g, tl_s=site.tl_s, s1_g=site.s1_g,
                      risk_category=site.risk_category)
    elif site is not None:
        design = dict(risk_category=site.risk_category)
    if site is not None:
        design["code"] = site.code
    model = yielding_building(modes, building.system, **_stick_arguments(building), **design)
    theta = model.stability_coefficient
    if theta > STABILITY_COEFFICIENT_MAX:
        approximate = float(approximate_period(building.height_m, building.system))
        raise InputError([Problem(
            workbook_name, f"with p_delta the gravity loads make this building unstable or nearly so: its first "
            f"mode's stability coefficient θ is {theta:.2g} (1 − (T1/T1 with P-Delta)², "
            f"T1 {modes.periods_s[0]:.3g} s), "
            f"above the {STABILITY_COEFFICIENT_MAX:g} that ASCE 7-22 §12.8.7 allows a building; a building that "
            "flexible under its own weight would collapse in the model, not shake its floors.",
            f"check period_s (T1 {modes.periods_s[0]:.3g} s is {modes.periods_s[0] / approximate:.2g} times ASCE 7's "
            f"approximate period T_a {approximate:.2g} s for this height and system), or write no in p_delta.",
            sheet=building.sheet, row=building.rows.get("p_delta"))])
    return model


def design_spectrum_of(site: SiteSheet, workbook_name: str) -> DesignSpectrum | None:
    """The site's ASCE 7 spectrum from SDS/SD1 or SS/S1/site class; None when the sheet gives neither.

    Raises :class:`~assess.errors.InputError` at the site sheet's cells where the code cannot give
    the spectrum from what is given (e.g. ASCE 7-22's site classes BC, CD and DE from SS and S1).
    """
    try:
        if site.sds_g is not None:
            return from_design_values(site.sds_g, site.sd1_g, site.tl_s, code=site.code)
        if site.ss_g is not None:
            return from_mapped_values(site.ss_g, site.s1_g, site.site_class, site.tl_s, code=site.code)
    except ValueError as error:
        row = site.rows.get("site_class", site.rows.get("ss", site.rows.get("sds")))
        raise InputError([Problem(workbook_name, f"{error}.", "give sds_g and sd1_g from the site's hazard "
                                  "lookup (the USGS service gives them for every site class).",
                                  sheet=site.sheet, row=row)]) from None
    return None


def site_level_target(site: SiteSheet, level: HazardLevel, workbook_name: str, design: DesignSpectrum | None):
    """The site sheet's target spectrum of ``level`` (:func:`assess.site.target.level_target`), ``design`` the
    site's ASCE 7 spectrum (:func:`design_spectrum_of`).

    Raises :class:`~assess.errors.InputError`; where ``oq_site`` names no site of the ``uhs`` file, at the
    site sheet's ``oq_site`` cell as well as the file.
    """
    try:
        return level_target(level, design=design, uhs_path=site.uhs_path or None,
                            oq_site=parse_site_choice(site.oq_site) if site.oq_site else None,
                            workbook=workbook_name, sheet=site.sheet)
    except SiteChoiceError as error:
        file = Path(error.problems[0].file).name
        raise InputError([Problem(workbook_name, f"oq_site names no site of {file}: {error.problems[0].message}",
                                  error.problems[0].fix, sheet=site.sheet,
                                  row=site.rows.get("oq_site", site.rows.get("uhs")), column="value")]) from None


def periods_that_matter_s(modes: BuildingModes | None) -> tuple[np.ndarray, float | None]:
    """The periods a level's ground suite is matched over, and the shortest 90 %-mass mode's [s].

    The building's modes that carry 90 % of its mass (ASCE 7-22 §16.2.3.1) and the band of rocking
    periods 2π/p an item may have (Housner 1963; p the frequency parameter), :data:`ITEM_PERIOD_RANGE_S`,
    whatever the workbook's items: the suite is the site's and the building's, so that editing an item
    never changes the motions every other item is assessed under.

    >>> periods, mass_period = periods_that_matter_s(None)
    >>> [float(t) for t in periods], mass_period
    ([0.05, 4.0], None)
    """
    periods = [np.array(ITEM_PERIOD_RANGE_S, dtype=float)]
    mass_period = None
    if modes is not None:
        cumulative = np.cumsum(modes.effective_mass_ratio)
        n90 = int(np.searchsorted(cumulative, 0.9 - 1e-12) + 1)
        periods.insert(0, modes.periods_s[:n90])
        mass_period = float(modes.periods_s[min(n90, modes.n_modes) - 1])
    return np.concatenate(periods), mass_period


def site_suite(site: SiteSheet, level: HazardLevel, modes: BuildingModes | None, workbook_name: str,
               workbook_folder, seed: int, *, suite_size: int | None = None, progress=None) -> SiteSuite:
    """A level's ground suite from the site sheet (module docstring).

    Raises :class:`~assess.errors.InputError` naming the site sheet where the level names no target
    the sheet can give, or the suite cannot be made from the records folder.
    """
    design = design_spectrum_of(site, workbook_name)
    target = site_level_target(site, level, workbook_name, design)
    periods, mass_period = periods_that_matter_s(modes)
    name = level.label or level.name
    try:
        suite = ground_suite(target, periods, level=name, records_folder=site.records_folder or None,
                             workbook_folder=workbook_folder, suite_size=suite_size or site.suite_size,
                             base_seed=seed, mass_period_s=mass_period, progress=progress,
                             records_scaling=site.records_scaling)
    except ValueError as error:
        # the cause's own cell: the records folder (too few records), else the uhs file (a target that ends
        # below the range); a synthetic suite from an ASCE 7 spectrum is never refused
        if site.records_folder:
            key, fix = "records", "add records to the records folder, or give the level's motions in the hazard sheet."
        else:
            key, fix = "uhs", ("give a uniform-hazard spectrum that reaches the building's periods, or run the level "
                               "DE or MCE_R.")
        raise InputError([Problem(workbook_name, f"the ground suite of level '{name}' cannot be made: {error}.",
                                  fix, sheet=site.sheet, row=site.rows.get(key))]) from None
    return SiteSuite(suite, design, periods, asce7_level(level))


def floors_csv(building, ground: list[Record], floors, level_label: str) -> pd.DataFrame:
    """``floors.csv`` of a level: the modes used and PFA, PFA/PGA per floor over the ground suite; a yielding
    building has a row for every floor, with what each storey did
    (:func:`assess.building.yielding.storey_table`)."""
    if isinstance(building, YieldingBuilding):
        wanted = list(range(building.storeys + 1))
        records, histories = yielding_histories(building, ground, floors=wanted)
        table = with_code_check(floors_table(building.modes, records, level=level_label), building)
        return pd.concat([table, storey_table(building, histories, wanted)], axis=1)
    wanted = sorted({0, *(int(f) for f in floors)})
    return with_code_check(floors_table(building, floor_records(building, ground, floors=wanted), level=level_label),
                           building)


def ductility_reduction_of(building: YieldingBuilding) -> float:
    """R_μ of ASCE 7-22 eq. 13.3-6 for a yielding building, as its items' anchorage takes it
    (:func:`assess.anchorage.item.system_ductility_reduction`) [-]."""
    return system_ductility_reduction(building.system, building.importance)


def with_code_check(table: pd.DataFrame, building) -> pd.DataFrame:
    """``floors.csv``'s check beside each floor's PFA/PGA (not a target): ASCE 7-22's H_f at the floor for the
    building's T_1 (eq. 13.3-4, ``hf_asce7_22``); for a building that yields, also its R_μ (eq. 13.3-6,
    ``rmu_asce7_22``) and H_f/R_μ (``hf_over_rmu_asce7_22``, empty at the ground), the floor acceleration over the
    ground's that §13.3.1 takes for a building yielding as its design assumes. ``building`` as
    :func:`building_model_of` gives it."""
    modes = building.modes if isinstance(building, YieldingBuilding) else building
    table = table.assign(hf_asce7_22=height_factor(table["z_over_h"].to_numpy(dtype=float), modes.periods_s[0]))
    if isinstance(building, YieldingBuilding):
        r_mu = ductility_reduction_of(building)
        table = table.assign(rmu_asce7_22=r_mu, hf_over_rmu_asce7_22=np.where(
            table["floor"].to_numpy() > 0, table["hf_asce7_22"].to_numpy() / r_mu, np.nan))
    return table


def site_note(site: SiteSuite, sheet: SiteSheet) -> str:
    """Where the level's ground motions come from, in a sentence for the report."""
    suite = site.suite
    if site.design is not None and site.spectrum is not None:
        # MCE_R's target is 1.5 times the design spectrum whose S_DS and S_D1 the sentence quotes (ASCE 7 §11.4.7)
        times = f"{MCE_R_OVER_DESIGN:g} times " if site.spectrum == "MCE_R" else ""
        where = (f"{times}the {sheet.code} design spectrum (S_DS {site.design.sds_g:.3g} g, S_D1 "
                 f"{site.design.sd1_g:.3g} g" + (f", site class {sheet.site_class}" if sheet.site_class else "") + ")")
    else:  # a level named by a probability: the uhs file's spectrum, whatever design values the sheet also gives
        where = "the site's uniform-hazard spectrum" + (f" ({Path(sheet.uhs_path).name})" if sheet.uhs_path else "")
    how = {"records": "records selected from the records folder and scaled to",
           "matched records": "records selected from the records folder and each matched to"}.get(
        suite.method, "spectrum-compatible synthetic ground motions matched to")
    cautions = "".join(f" {caution[0].upper()}{caution[1:]}." for caution in suite.cautions)
    # a mean below what §16.2.3 asks is said by its caution, once
    mean = (f"the suite's mean is at least {suite.min_mean_ratio:.0%} of the target there; "
            if suite.min_mean_ratio >= MEAN_RATIO_MIN - 1e-9 else "")
    return (f"Ground floor: {len(suite.motions)} {how} {where} at level {suite.level}, over periods "
            f"{suite.lower_s:.3g} to {suite.upper_s:.3g} s ({mean}ground_motions.csv and spectrum.csv).{cautions}")


#: The least α at which a shear wall given its storeys' strengths, modelled as a stick of shear storeys, is not
#: cautioned in the building's note: Miranda & Taghavi's (2005) walls bend at 0 to 2, moment frames 5 to 20. Before
#: it yields, a 6-storey wall's stick shakes its roof 0.59-1.58 times as hard as its elastic modes at α 1, 0.79-1.25
#: at 10, 0.99-1.10 at 20 and 30 (the peak roof acceleration, 11 of pyslammer's records scaled at T_1 0.5 s).
SHEAR_WALL_ALPHA_MIN = 20.0
#: A storey of buckling braces in the building's note (:func:`assess.building.hysteresis.brace_backbones`).
BRACES = (f"storeys of two braces each, one pulled and one pushed (brace_buckling): the pushed one buckles at the "
          f"storey's first yield, at {BRACE_BUCKLING_RATIO:g} of the pulled one's tension strength, and keeps "
          f"{BRACE_POST_BUCKLING_RATIO:g} of that once buckled; the pulled one yields,")


def building_note(building, sheet: BuildingSheet, floors, derive_floors_roof, numbering: str = "ground_0") -> str:
    """Where the upper floors' motions come from, in a sentence for the report (floors labelled by
    ``numbering``: :func:`assess.quantity_text.floor_text`); ``building`` as :func:`building_model_of` gives it."""
    modes = building.modes if isinstance(building, YieldingBuilding) else building
    source = "given" if sheet.period_s is not None else "ASCE 7 Table 12.8-2's estimate"
    which = sentence_start(floors_text(floors, numbering))
    stiffness = stiffness_note(modes, sheet)
    ratio = f"lateral stiffness ratio α {modes.alpha:.3g} ({alpha_source_of(sheet)})"
    if isinstance(building, YieldingBuilding):
        strength = building.strength
        hinged = building.yielding_model == BASE_HINGE
        springs = (f"its elastic model on a {building.stick.law} plastic hinge at the base" if hinged
                   else BRACES if building.stick.law == "buckling" else f"{building.stick.law} storey springs")
        one = hinged or building.stick.law == "buckling"
        springs += (f" hardening at {100 * building.hardening:.3g}% of {'its' if one else 'their'} "
                    "stiffness after yield ("
                    + ("by default" if sheet.storey_hardening_ratio is None
                       else sheet.hardening_source or "storey_hardening_ratio") + ")")
        text = (f"{which}: each ground motion through the building, modelled as yielding ({sheet.storeys} storeys, "
                f"{sheet.system}, T1 {modes.periods_s[0]:.2f} s ({source}), {stiffness}, {ratio}, "
                f"{sheet.damping:.0%} Rayleigh damping; {springs}"
                + (", with P-Delta" if building.p_delta else "") + "): the floor's absolute acceleration in time "
                "(floors.csv). " + ("It yields" if hinged else "The first of its storeys to yield does so")
                + " at a base shear of "
                f"{strength.yield_base_shear_g:.3g} W: {strength.source}. Under a motion that "
                f"{'does not yield it' if hinged else 'yields no storey'} the floors' motions are the elastic modes' "
                "ones. The "
                "building's own collapse is not assessed.")
        if strength.overstrength_assumed:
            basis = OVERSTRENGTH_SOURCE_BY_SYSTEM.get(sheet.system)
            said = f"the literature's typical one, {basis}" if basis else "a judgement"
            text += (f" The overstrength is {said}, "
                     "not this building's, and the strength moves the floors' motions most: give yield_base_shear_g "
                     "(from a pushover or an evaluation) or overstrength where known.")
        if sheet.lateral_stiffness_ratio is None and sheet.pushover_slope_ratio is None and not hinged:
            text += (" The lateral stiffness ratio α, the system's typical value and not this building's, moves the "
                     "floors' motions nearly as much as the strength does (it sets how the columns spread the "
                     "storeys' drift over the height; on OpenSees frames of 4 to 12 storeys whose own α was 5 to 20, "
                     "the system's α slid their upper floors' items 0.44 to 1.78 times as far as theirs did, and 0.66 "
                     "times on the 12-storey one whose α was 10): give lateral_stiffness_ratio where the building's "
                     "own is known; --alpha-range shows which items it moves here.")
        if (sheet.lateral_stiffness_ratio is None and sheet.pushover_slope_ratio is not None
                and sheet.storey_hardening_ratio is None):
            text += (f" The α found from the pushover rests on the storeys hardening at "
                     f"{building.hardening:.0%} of their stiffness after they yield, as the stick's "
                     "do: where the building's own harden less, its columns are stiffer than this α says (on OpenSees "
                     "frames of α 10 whose storeys harden at 2%, the α found was 11.1 to 12.5, and 9.6 to 10.5 "
                     "with their 2% written): give the model's in storey_hardening_ratio.")
        if sheet.system == "braced frame" and building.stick.law != "buckling":
            text += (" Its storeys yield without the braces' buckling (bilinear springs, as a buckling-restrained "
                     "brace's): where the braces buckle, as a special concentrically braced frame's do, write yes "
                     "in brace_buckling.")
        if sheet.system == "shear wall" and not hinged:
            text += (" Its storeys' strengths are given (storey_strength), so the wall yields storey by storey, as "
                     "storey springs, where without them it yields at a plastic hinge at its base and stays elastic "
                     "above (a capacity-designed wall).")
            if modes.alpha < SHEAR_WALL_ALPHA_MIN:
                text += (f" Its α {modes.alpha:.3g} is a wall's that bends, which a stick of shear storeys is not: "
                         "before it yields such a stick shakes the roof otherwise than the wall's elastic modes do "
                         "(a 6-storey wall of α 1: 0.59 to 1.58 times their roof PFA under 11 records; of α 20 "
                         "or more, 0.99 to 1.10). Give lateral_stiffness_ratio where the wall's storeys shear, or "
                         "delete storey_strength for a wall that yields at its base.")
        if sheet.storey_strength is not None and sheet.storey_stiffness is None:
            text += (" Its storeys' strengths are given (storey_strength) but not their stiffnesses, which are the "
                     "system's default profile: a storey's strength and stiffness come from the same members, and "
                     "given apart they put the yielding where the building's model does not (on OpenSees buildings "
                     "of 4 to 8 storeys, given their storeys' strengths but not their stiffnesses or α, the items' "
                     "sliding met the checks on 15 and their risk class on 13 of 26 building-and-earthquake pairs; "
                     "with both, on all 26): give storey_stiffness and lateral_stiffness_ratio from the same model.")
        if (sheet.storey_stiffness is None and sheet.storey_strength is None and not hinged
                and STRENGTH_BY_SYSTEM[sheet.system] == "stiffness"):
            text += (" The storeys' stiffnesses, which set their strengths, are the system's default profile, not "
                     "this building's: give storey_stiffness from the building's model where known.")
    else:
        text = (f"{which}: each ground motion through the building's elastic modes "
                f"({sheet.storeys} storeys, {sheet.system}, T1 {modes.periods_s[0]:.2f} s ({source}), {stiffness}, "
                f"{ratio}, "
                f"{sheet.damping:.0%} damping, {modes.n_modes} modes): the floor's absolute acceleration in time "
                "(floors.csv). The building is taken as elastic: a building that yields has lower peak floor "
                "accelerations than these, at longer periods; floor motions a structural engineer gives in the "
                "hazard sheet govern.")
        if sheet.response is None and sheet.too_tall_to_yield:
            text += (f" The yielding model takes at most {MAX_YIELDING_STOREYS} storeys (its cost grows with the "
                     "cube of the storeys), so it did not run.")
    if derive_floors_roof is not None:
        text += " --derive-floors gives way to the building sheet."
    return text


def stiffness_note(modes: BuildingModes, sheet: BuildingSheet) -> str:
    """The storeys' stiffness profile the model used, in words for the report.

    >>> from assess.building import building_modes
    >>> sheet = BuildingSheet(storeys=2, height_m=8.0, system="steel moment frame")
    >>> stiffness_note(building_modes(2, 4.0, storey_stiffness=[1.0, 0.5]), sheet)
    "storey stiffness from the base to the roof falling with the design's storey shears to 0.5 of the first storey's"
    >>> stiffness_note(building_modes(2, 4.0), BuildingSheet(storeys=2, height_m=8.0, storey_stiffness=(1.0, 1.0)))
    'uniform storey stiffness (given)'
    """
    relative = modes.storey_stiffness
    given = " (given)" if sheet.storey_stiffness is not None else ""
    if np.allclose(relative, relative[0]):
        return f"uniform storey stiffness{given}"
    if given:
        return f"the storey stiffnesses given (the top storey {relative[-1]:.2g} of the first storey's)"
    return ("storey stiffness from the base to the roof falling with the design's storey shears to "
            f"{relative[-1]:.2g} of the first storey's")


def roof_note(freestanding: pd.DataFrame, building: BuildingSheet, numbering: str = "ground_0") -> str | None:
    """That the items on floor ``storeys`` stand on the roof, in a sentence for the report; None when none does.

    The workbook counts the ground floor 0 whatever ``floor_numbering`` says, so floor ``storeys`` is the
    roof (docs/workbook.md, sheet building); the report labels it by ``numbering``.

    >>> from assess.inventory.site_building import BuildingSheet
    >>> items = pd.DataFrame({"id": ["P-1", "G-1"], "floor": [5, 0]})
    >>> roof_note(items, BuildingSheet(storeys=5, height_m=20.0), "ground_1")  # doctest: +NORMALIZE_WHITESPACE
    "Floor 6 is the building's roof (5 storeys above the ground floor; the workbook's floor 5): P-1 stands on it, under
    the roof's motion."
    """
    on_roof = freestanding.loc[freestanding["floor"] == building.storeys, "id"]
    if on_roof.empty:
        return None
    shown = ", ".join(str(i) for i in on_roof[:10]) + (f" and {len(on_roof) - 10} more" if len(on_roof) > 10 else "")
    return (f"Floor {floor_text(building.storeys, numbering)} is the building's roof ({building.storeys} storeys "
            f"above the ground floor; the workbook's floor {building.storeys}): {shown} "
            f"{'stands' if len(on_roof) == 1 else 'stand'} on it, under the "
            "roof's motion.")
