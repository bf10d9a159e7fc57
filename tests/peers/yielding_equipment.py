"""Equipment on the floors of yielding buildings: the harness of the tool-against-OpenSees equipment checks.

Used by tests/verification/test_yielding_equipment.py and benchmarks/bench_yielding_equipment.py (its
docstring says what is measured). The truth is :mod:`peers.opensees_buildings`; every route runs the
product itself (``run_assessment`` on a workbook whose hazard sheet gives the scaled ground records at
floor 0, a ``site`` sheet with the design values, Risk Category II, and a ``building`` sheet with the
building's storeys, height, system and T_1), so that only the floor histories differ: for the truth, the
yielding route's stick is swapped for the OpenSees building (:func:`opensees_floors`).
"""
from __future__ import annotations

import dataclasses
import hashlib
import os
from contextlib import contextmanager
from pathlib import Path

import numpy as np
import pandas as pd

from assess.assessment.pipeline import run_assessment
from assess.building import ALPHA_RANGE_BY_SYSTEM
from assess.building import yielding as yielding_module
from assess.decision.risk_classes import Chances, classify_risk
from assess.hazard.records import read_record
from assess.inventory import read_workbook
from assess.inventory.settings import Settings
from assess.site.asce7 import design_spectral_acceleration_g
from assess.site.spectrum import pseudo_acceleration_spectrum
from peers.opensees_buildings import (FlexuralWall, pushover_slope_ratio, pushover_yield_base_shear_g, truth_response,
                                     wall_history)
from workbooks import write_workbook

SDS_G, SD1_G = 1.0, 0.6
LEVELS = {"DE": 1.0, "MCE_R": 1.5}
WINDOW_S = 30.0
#: pyslammer's records used, in this order: all 18 of its sample records (the longest, Chi-Chi's, Kocaeli and
#: Nisqually, late; the three last were added once the first 15 had been measured, so that ``--motions 15``
#: and the tests' first 11 keep their motions).
RECORDS = ("Cape_Mendocino_1992_PET-090", "Coalinga_1983_PVB-045", "Duzce_1999_375-090",
           "Imperial_Valley_1979_BCR-230", "Kobe_1995_TAK-090", "Landers_1992_LCN-345",
           "Loma_Prieta_1989_HSP-000", "Morgan_Hill_1984_CYC-285", "N_Palm_Springs_1986_WWT-180",
           "Northridge_1994_PAC-175", "Northridge_1994_VSP-360", "Nahanni_1985_NS1-280",
           "Coyote_Lake_1979_G02-050", "Mammoth_Lakes-1_1980_CVK-090", "Chi-Chi_1999_TCU068-090",
           "Kocaeli_1999_ATS-090", "Mammoth_Lakes-2_1980_CVK-090", "Nisqually_2001_UNR-058")
#: The items (SI): id, height, width, depth [m], mass [kg], μ, clearance [m].
ITEMS = (("FORMA", 2.286, 0.622, 0.84, 330.0, 0.23, 0.15),
         ("KELVINATOR", 2.134, 0.66, 0.81, 230.0, 0.28, 0.15),
         ("ASP", 1.803, 0.584, 0.74, 140.0, 0.31, 0.15),
         ("RACK", 2.032, 0.6096, 1.0668, 635.0, 0.30, 0.3556),
         ("SHELVING", 2.1844, 1.2192, 0.6096, 408.0, 0.35, 0.254),
         ("CHEST", 0.91, 1.60, 0.75, 150.0, 0.30, 0.10))
def narrow_box(name: str) -> dict:
    """The item ``name`` of :data:`ITEMS` rocking about its narrow side (its depth): ``half_width_m``, ``height_m``
    and ``mu``, as :func:`peers.mujoco_box.box_model` takes them."""
    (height, depth, mu), = [(h, d, mu) for item, h, _, d, _, mu, _ in ITEMS if item == name]
    return {"half_width_m": depth / 2, "height_m": height, "mu": mu}


def stronger(truth, factor: float):
    """The OpenSees building ``truth`` with every storey's strength (a wall's hinge's) times ``factor``."""
    if hasattr(truth, "overstrength_profile"):
        return dataclasses.replace(truth, overstrength_profile=tuple(factor * np.asarray(truth.overstrength_profile)))
    return dataclasses.replace(truth, yield_base_shear_g=factor * truth.yield_base_shear_g)


def given_strength(truth) -> list:
    """The building sheet's rows of the route ``given``: ``response`` yielding and ``yield_base_shear_g`` the truth
    building's own pushover gives (:func:`peers.opensees_buildings.pushover_yield_base_shear_g`), written to six
    decimals as an engineer would copy it."""
    return [["response", "yielding"], ["yield_base_shear_g", round(pushover_yield_base_shear_g(truth), 6)]]


#: The route of an engineer who reads the pushover's slope after yield as well as its strength (:func:`given_pushover`).
PUSHOVER_ROUTE = "given + pushover slope"


def given_pushover(truth) -> list:
    """The building sheet's rows of the route ``given + pushover slope``: :func:`given_strength` and the slope of the
    same pushover at 2 % roof drift over its initial slope (:func:`peers.opensees_buildings.pushover_slope_ratio`),
    to four significant figures, in ``pushover_slope_ratio``: the α the tool then finds is its own."""
    return given_strength(truth) + [["pushover_slope_ratio", float(f"{pushover_slope_ratio(truth):.4g}")]]


#: What a route adds where the engineer also writes the model's storey hardening (:func:`own_hardening`).
OWN_HARDENING = " + own hardening"


def own_hardening(truth) -> list:
    """The building sheet's row an engineer with the truth building's own model would add: its springs' (a wall's:
    its own) stiffness after yield over their stiffness before, in ``storey_hardening_ratio``."""
    return [["storey_hardening_ratio", float(truth.hardening)]]


#: The route of an engineer who reads the pushover's slope after yield and writes the model's storey hardening beside
#: it (:func:`given_pushover_hardening`), and the same with the model's storey stiffnesses: its whole model but α.
PUSHOVER_HARDENING = PUSHOVER_ROUTE + OWN_HARDENING
PUSHOVER_MODEL = PUSHOVER_HARDENING + " + own stiffness"


def given_pushover_hardening(truth) -> list:
    """The building sheet's rows of :data:`PUSHOVER_HARDENING`: :func:`given_pushover` and :func:`own_hardening`."""
    return given_pushover(truth) + own_hardening(truth)


def given_pushover_model(truth) -> list:
    """The building sheet's rows of :data:`PUSHOVER_MODEL`: :func:`given_pushover_hardening` and the truth's storey
    stiffnesses (:func:`own_stiffness`)."""
    return given_pushover_hardening(truth) + [["storey_stiffness", own_stiffness(truth)]]


def own_alpha(truth) -> float:
    """The lateral stiffness ratio α an engineer with the truth building's own model would write in the building
    sheet's ``lateral_stiffness_ratio``: the frames' column's α; the shear building (``wall6``, no column, α ∞) the
    sheet's highest, the flexural wall (``wallf6``, a cantilever, α 0) its lowest
    (:data:`assess.inventory.site_building.LATERAL_STIFFNESS_RATIO_RANGE`)."""
    from assess.inventory.site_building import LATERAL_STIFFNESS_RATIO_RANGE
    if isinstance(truth, FlexuralWall):
        return LATERAL_STIFFNESS_RATIO_RANGE[0]
    return float(min(truth.column_alpha, LATERAL_STIFFNESS_RATIO_RANGE[1]))


def own_stiffness(truth) -> str | None:
    """The relative storey stiffnesses an engineer with the truth building's own model would write in the building
    sheet's ``storey_stiffness``: its profile (first storey 1), as the sheet takes it; None for the flexural wall,
    a cantilever with no storeys of its own (``lateral_stiffness_ratio`` says what it is)."""
    profile = getattr(truth, "stiffness_profile", None)
    return None if profile is None else ", ".join(f"{k:g}" for k in profile)


def own_strength(truth) -> str | None:
    """The relative storey strengths an engineer with the truth building's own model would write in the building
    sheet's ``storey_strength``: its storey springs' yield shears (first storey 1, four significant figures); None
    for the flexural wall, which yields at its base hinge only."""
    if not hasattr(truth, "yield_ratios"):
        return None
    ratios = truth.yield_ratios() / truth.yield_ratios()[0]
    return ", ".join(f"{r:.4g}" for r in ratios)


#: The route of an engineer who knows the building's strength whole: the pushover's base shear and each storey's
#: share of it (an evaluation's storey capacities), nothing of its stiffness (:func:`given_strengths`).
GIVEN_STRENGTHS = "given + own strength"


def given_strengths(truth) -> list | None:
    """The building sheet's rows of :data:`GIVEN_STRENGTHS`: :func:`given_strength` and the storeys' strengths
    (:func:`own_strength`) in ``storey_strength``; None for the flexural wall, which yields at its base only."""
    if own_strength(truth) is None:
        return None
    return given_strength(truth) + [["storey_strength", own_strength(truth)]]


#: The route of an engineer with the building's own model: its pushover strength, α and storey stiffnesses.
OWN_MODEL = "given + own α + own stiffness"
#: The same with the model's storey strengths and hardening as well: the whole model (:func:`whole_model`).
WHOLE_MODEL = OWN_MODEL + " + own strength" + OWN_HARDENING


def whole_model(truth) -> list:
    """The building sheet's rows of :data:`WHOLE_MODEL`: the pushover's strength (:func:`given_strength`), α
    (:func:`own_alpha`), the storeys' stiffnesses (:func:`own_stiffness`) and strengths (:func:`own_strength`) and
    the springs' hardening (:func:`own_hardening`); None for the flexural wall."""
    if own_strength(truth) is None:
        return None
    return (given_strength(truth) + [["lateral_stiffness_ratio", own_alpha(truth)],
                                     ["storey_stiffness", own_stiffness(truth)],
                                     ["storey_strength", own_strength(truth)]] + own_hardening(truth))


def given_routes(truth) -> dict:
    """The building sheet's rows of the routes of what the engineer knows: ``given`` (:func:`given_strength`),
    ``given + own α`` (that and :func:`own_alpha` in ``lateral_stiffness_ratio``) and, where the building has
    storeys of its own, :data:`OWN_MODEL` (those and :func:`own_stiffness` in ``storey_stiffness``)."""
    strength = given_strength(truth)
    routes = {"given": strength, "given + own α": strength + [["lateral_stiffness_ratio", own_alpha(truth)]]}
    if own_stiffness(truth) is not None:
        routes[OWN_MODEL] = routes["given + own α"] + [["storey_stiffness", own_stiffness(truth)]]
    return routes


#: Issue 29's targets with the strength given: sliding gm within these, σ of ln at most this; the share of items
#: whose risk class agrees, and of the cases where either overturns that agree, at least these.
TARGET_GM = (0.8, 1.25)
TARGET_SIGMA_LN = 0.45
TARGET_CLASS_AGREE = 0.8
TARGET_OVERTURN_AGREE = 0.75


def meets_sliding_targets(numbers: dict) -> bool:
    """Whether a route's :func:`compare` numbers meet the sliding targets (gm and σ ln)."""
    return TARGET_GM[0] <= numbers["gm"] <= TARGET_GM[1] and numbers["sigma_ln"] <= TARGET_SIGMA_LN


def meets_class_target(numbers: dict) -> bool:
    """Whether a route's :func:`compare` numbers meet the risk-class target."""
    return numbers["class_agree"] >= TARGET_CLASS_AGREE


#: (R, Ω_0) of ASCE 7-22 Table 12.2-1 for the systems (I_e 1), for R_μ.
SYSTEM_R = {"steel moment frame": (8.0, 3.0), "concrete moment frame": (8.0, 3.0), "shear wall": (5.0, 2.5),
            "braced frame": (6.0, 2.0)}


def windowed(record):
    """A 30 s window of the record from 1 s before 5 % of its Arias intensity."""
    accel = np.asarray(record.accel_g, dtype=float)
    arias = np.cumsum(accel ** 2)
    start = max(0, int(np.searchsorted(arias, 0.05 * arias[-1])) - int(round(1.0 / record.dt_s)))
    return accel[start:start + int(round(WINDOW_S / record.dt_s)) + 1]


def ground_suite(count, period_s, factor, skip=()):
    """The first ``count`` of :data:`RECORDS` but those named in ``skip``, each windowed (:func:`windowed`) and
    scaled so that its 5 %-damped S_a(``period_s``) is ``factor`` times the design spectrum's: (name, accel_g,
    dt_s) each."""
    import pyslammer
    folder = os.path.join(os.path.dirname(pyslammer.__file__), "sample_ground_motions")
    target = factor * float(design_spectral_acceleration_g(period_s, SDS_G, SD1_G))
    out = []
    for name in [name for name in RECORDS if name not in skip][:count]:
        record = read_record(os.path.join(folder, name + ".csv"))
        accel = windowed(record)
        have = float(np.atleast_1d(pseudo_acceleration_spectrum(accel, record.dt_s, [period_s]))[0])
        scaled = np.array([float(f"{a:.10g}") for a in accel * (target / have)])  # as the record file holds it
        out.append((name, scaled, record.dt_s))
    return out


def _key(accel) -> str:
    return hashlib.blake2b(np.ascontiguousarray(accel, dtype=float).tobytes(), digest_size=16).hexdigest()


def workbook(folder: Path, truth, suite, level, building_rows) -> Path:
    floors = (truth.storeys // 2, truth.storeys)
    equipment = [{"id": f"{item}-{floor}", "name": item.lower(), "floor": floor, "height_m": h, "width_m": w,
                  "depth_m": d, "mass_kg": m, "mu": mu, "clearance_m": c}
                 for floor in floors for item, h, w, d, m, mu, c in ITEMS]
    files, hazard = {}, []
    for name, accel, dt in suite:
        path = f"records/{name}.csv"
        files[path] = "time_s,accel_g\n" + "".join(f"{k * dt:.6f},{a:.10g}\n" for k, a in enumerate(accel))
        hazard.append({"level": level, "motion": name, "floor": 0, "record": path, "scale": 1.0})
    site = [["key", "value"], ["sds_g", SDS_G], ["sd1_g", SD1_G], ["risk_category", "II"]]
    building = [["key", "value"], ["storeys", truth.storeys], ["storey_height_m", truth.storey_height_m],
                ["system", truth.system], ["period_s", truth.period_s], ["damping", 0.05]] + building_rows
    return write_workbook(folder / "building.xlsx", {"equipment": equipment, "hazard": hazard, "site": site,
                                                     "building": building}, files=files)


@contextmanager
def opensees_floors(truth, suite, floor_scale=1.0):
    """The yielding route's stick swapped for the OpenSees building under each ground history of ``suite``;
    every floor's acceleration above the ground times ``floor_scale`` (1: as OpenSees gives it)."""
    answers = {}
    for _, accel, dt in suite:
        if isinstance(truth, FlexuralWall):  # the storeys have no yield drift: the hinge's ductility on storey 1
            floor_accel, drift, hinge_ductility = wall_history(truth, accel, dt)
            ductility = np.full(truth.storeys, np.nan)
            ductility[0] = hinge_ductility
        else:
            floor_accel, drift, yield_drift = truth_response(truth, accel, dt)
            ductility = np.abs(drift).max(axis=1) / yield_drift
        peak = np.abs(drift).max(axis=1)
        floor_accel = np.vstack([floor_accel[:1], floor_scale * floor_accel[1:]])
        answers[_key(accel)] = yielding_module.StickHistory(floor_accel, peak / truth.storey_height_m, ductility,
                                                            False)
    original = yielding_module.stick_history

    def stick_history(building, ground_accel_g, dt_s):
        return answers[_key(ground_accel_g)]

    yielding_module.stick_history = stick_history
    try:
        yield
    finally:
        yielding_module.stick_history = original


def assess(path, level, alpha_range=None):
    """The product's result on the workbook at ``path`` (with ``alpha_range``: ``--alpha-range``'s ends), and its
    motions table indexed by (item, ground record, direction)."""
    result = run_assessment(read_workbook(path), level, seed=0, alpha_range=alpha_range)
    motions = result.motions.copy()
    motions["ground"] = motions["motion"].str.split(" @ ").str[0]
    return result, motions.set_index(["id", "ground", "direction"]).sort_index()


def truth_result(truth, suite, level, folder: Path, floor_scale=1.0):
    """The product's answer on the OpenSees building ``truth``'s floor histories under ``suite`` at ``level``
    (as :func:`assess` gives it): the reference every route is compared with; with ``floor_scale``, on those
    histories times it (no model error, only the floors' amplitude off by a known factor)."""
    with opensees_floors(truth, suite, floor_scale):
        return assess(workbook(folder, truth, suite, level, [["response", "yielding"]]), level)


def compared(truth, suite, level, folder: Path, routes: dict, bracket=None) -> dict:
    """Each route's :func:`compare` numbers against the truth's, ``routes`` the building sheet's rows by route; with
    ``bracket`` (low, high), the route ``given`` runs with ``--alpha-range`` there (its own answer is the same) and
    adds :func:`bracket_held`'s."""
    reference = truth_result(truth, suite, level, folder)
    numbers = {}
    for route, rows in routes.items():
        tool = assess(workbook(folder, truth, suite, level, rows), level, bracket if route == "given" else None)
        numbers[route] = {**compare(tool, reference), **bracket_held(tool, reference)}
    return numbers


def compared_on_its_own(truth, folder: Path, motions: int = 11) -> dict:
    """:func:`compared` at DE over the first ``motions`` records for a building checked on its own (the braced frame,
    the 12-storey frame): the routes of what the engineer knows (:func:`given_routes`; ``given`` with
    ``--alpha-range`` at the system's ends, :func:`bracket_held`), with the pushover's slope (:data:`PUSHOVER_ROUTE`,
    :func:`given_pushover`), and with the model's hardening beside it (:data:`PUSHOVER_HARDENING`, and with the
    model's storey stiffnesses as well, :data:`PUSHOVER_MODEL`), the whole model (:data:`WHOLE_MODEL`, where the
    building has storeys of its own), the design data alone (``design``) and the elastic
    modes (``elastic``)."""
    routes = {**given_routes(truth), PUSHOVER_ROUTE: given_pushover(truth),
              PUSHOVER_HARDENING: given_pushover_hardening(truth)}
    if own_stiffness(truth) is not None:
        routes[PUSHOVER_MODEL] = given_pushover_model(truth)
    whole = whole_model(truth)
    if whole is not None:
        routes[WHOLE_MODEL] = whole
    routes.update({"design": [["response", "yielding"]], "elastic": [["response", "elastic"]]})
    return compared(truth, ground_suite(motions, truth.period_s, 1.0), "DE", folder, routes,
                    bracket=ALPHA_RANGE_BY_SYSTEM[truth.system])


def bracket_held(tool, truth) -> dict:
    """Where the tool ran with ``--alpha-range``: the share of the items whose truth lies within what the tool
    gives at the two ends of α and at the system's α (the least to the most of the three): the risk class
    (``bracket_class_held``), the chance of sliding past the room and of overturning (``bracket_p_held``, both);
    the share whose class the ends left where the system's α put it (``bracket_class_fixed``), and of the items
    whose class the system's α gets wrong (``n_class_missed``), the share the ends flag (``class_missed_flagged``:
    their class moves between the ends). {} without."""
    summary = tool[0].summary.set_index("id")
    if "risk_alpha_low" not in summary:
        return {}
    truth_rows = truth[0].summary.set_index("id").loc[summary.index]
    rank = {"low": 0, "moderate": 1, "high": 2}
    classes = summary[["risk_alpha_low", "risk", "risk_alpha_high"]].apply(lambda column: column.map(rank))
    truth_class = truth_rows["risk"].map(rank)
    held = (classes.min(axis=1) <= truth_class) & (truth_class <= classes.max(axis=1))
    within = []
    for column in ("p_beyond_clearance", "p_overturn"):
        values = summary[[f"{column}_alpha_low", column, f"{column}_alpha_high"]].astype(float)
        within.append((values.min(axis=1) - 1e-9 <= truth_rows[column])
                      & (truth_rows[column] <= values.max(axis=1) + 1e-9))
    fixed = classes.min(axis=1) == classes.max(axis=1)
    missed = classes["risk"] != truth_class
    return {"bracket_class_held": float(held.mean()), "bracket_p_held": float((within[0] & within[1]).mean()),
            "bracket_class_fixed": float(fixed.mean()), "n_class_missed": int(missed.sum()),
            "class_missed_flagged": float((~fixed[missed]).mean()) if missed.any() else np.nan}


def overturn_class(p_overturn):
    """Each item's overturning verdict as the summary's risk takes it from ``p_overturn`` alone: ``high`` from
    ``risk_overturn_high``, ``moderate`` from ``risk_overturn_moderate`` (the defaults), else ``low``."""
    settings = Settings()
    p = np.asarray(p_overturn, dtype=float)
    verdict = np.where(p >= settings.risk_overturn_high, "high",
                       np.where(p >= settings.risk_overturn_moderate, "moderate", "low"))
    return pd.Series(verdict, index=getattr(p_overturn, "index", None))


#: Resamples of the ground motions behind :func:`motion_bootstrap`'s intervals, and their seed.
BOOTSTRAP_RESAMPLES, BOOTSTRAP_SEED = 2000, 29


def motion_bootstrap(ratio: pd.Series, level=0.90) -> dict:
    """90 % intervals of the sliding gm and σ ln over the suite's motions: the ground motions resampled with
    replacement (Efron & Tibshirani 1993, the percentile interval), each motion's cases kept together (an item's
    cases under one motion are not independent of each other), ``ratio`` ln(tool/truth) indexed by ``ground``.

    How finely 11-15 motions fix σ ln: a σ ln of 0.45 and one of 0.48 cannot be told apart when both intervals
    span 0.38-0.55."""
    groups = [values.to_numpy() for _, values in ratio.groupby(level="ground")]
    rng = np.random.default_rng(BOOTSTRAP_SEED)
    gm, sigma = [], []
    for _ in range(BOOTSTRAP_RESAMPLES):
        sample = np.concatenate([groups[k] for k in rng.integers(0, len(groups), len(groups))])
        gm.append(np.exp(sample.mean()))
        sigma.append(sample.std(ddof=1) if sample.size > 1 else np.nan)
    tails = [50 * (1 - level), 50 * (1 + level)]
    (gm_low, gm_high), (sigma_low, sigma_high) = np.nanpercentile(gm, tails), np.nanpercentile(sigma, tails)
    return {"gm_low": float(gm_low), "gm_high": float(gm_high), "sigma_ln_low": float(sigma_low),
            "sigma_ln_high": float(sigma_high)}


def one_motion_away(tool_row, truth_class: str, settings: Settings) -> bool:
    """Whether one motion's verdict on one failure mode, moved (its chance up or down by one motion's share of the
    suite, ``suite_motions``), gives the tool's summary row ``tool_row`` the truth's risk class: a class miss at the
    resolution of a suite of that many motions, where the truth's own class moves as far for one motion."""
    step = 1.0 / float(tool_row["suite_motions"])
    chances = Chances.of(tool_row)
    for mode in ("overturn", "beyond_clearance", "rocking_harm"):
        for sign in (-1.0, 1.0):
            moved = min(max(getattr(chances, mode) + sign * step, 0.0), 1.0)
            if classify_risk(dataclasses.replace(chances, **{mode: moved}), tool_row["consequence"],
                             settings) == truth_class:
                return True
    return False


def compare(tool, truth):
    """The route's numbers against the truth's (module text)."""
    (_, t), (_, r) = tool, truth
    t, r = t.align(r, join="inner", axis=0)
    over_t, over_r = t["sim_overturned"].astype(bool), r["sim_overturned"].astype(bool)
    slides = (r["sim_sliding_max_cm"] >= 1.0) & ~over_t & ~over_r
    ratio = np.log(np.maximum(t.loc[slides, "sim_sliding_max_cm"], 0.1) / r.loc[slides, "sim_sliding_max_cm"])
    either = over_t | over_r
    tool_rows = tool[0].summary.set_index("id")
    classes = tool_rows["risk"].align(truth[0].summary.set_index("id")["risk"], join="inner")
    missed = classes[0].index[classes[0] != classes[1]]
    one_motion = [one_motion_away(tool_rows.loc[item], classes[1][item], Settings()) for item in missed]
    overturn_classes = [overturn_class(result[0].summary.set_index("id")["p_overturn"]) for result in (tool, truth)]
    overturn_classes = overturn_classes[0].align(overturn_classes[1], join="inner")
    pfa = {}
    for where in ("mid", "roof"):
        floor_of = t.reset_index().groupby("id")["floor"].first()
        floor = floor_of.max() if where == "roof" else floor_of.min()
        tp = t[t["floor"] == floor].groupby(level="ground")["pta_g"].first()
        rp = r[r["floor"] == floor].groupby(level="ground")["pta_g"].first()
        pfa[where] = float(np.median(tp / rp))
    return {"pfa_mid": pfa["mid"], "pfa_roof": pfa["roof"], "n_sliding": int(slides.sum()),
            "gm": float(np.exp(ratio.mean())) if len(ratio) else np.nan,
            "sigma_ln": float(ratio.std(ddof=1)) if len(ratio) > 1 else np.nan,
            **(motion_bootstrap(ratio) if len(ratio) > 1 else {}),
            "n_overturn": int(either.sum()),
            "overturn_tool_only": int((over_t & ~over_r).sum()), "overturn_truth_only": int((~over_t & over_r).sum()),
            "overturn_agree": float((over_t[either] == over_r[either]).mean()) if either.any() else np.nan,
            "overturn_agree_all": float((over_t == over_r).mean()),
            "overturn_class_agree": float((overturn_classes[0] == overturn_classes[1]).mean()),
            "class_agree": float((classes[0] == classes[1]).mean()), "n_items": len(classes[0]),
            "n_class_missed": len(missed),
            "class_missed_one_motion": int(sum(one_motion))}
