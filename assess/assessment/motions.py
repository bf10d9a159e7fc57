"""Stage 2 of the assessment: the motions of the level, per floor, and the histories to simulate.

:func:`level_motions` selects the hazard level's rows, fills what a record
leaves empty (PTA, Tp, vp), scales them to an OpenQuake PGA or by a
calibration's ``input_scale``, and derives the floors that have no motion;
:func:`simulated_motions` turns every motion into the accelerations the engine
runs (its record, synthetic near-fault histories or its pulse) and pairs the
two components of a motion with ``record_2``. The hazard sheet's columns are
described in docs/workbook.md.
"""
from __future__ import annotations

import functools
import warnings
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Callable

import numba
import numpy as np
import pandas as pd

from assess.assessment import floors as site_and_building
from assess.building.yielding import pass_progress, through_building
from assess.calibration.apply import scaled_motions
from assess.errors import InputError, Problem
from assess.fragility.governing import PULSE, RECORD, SYNTHETIC
from assess.hazard.levels import HazardLevel
from assess.hazard.levels import parse_level
from assess.hazard.motions import derive_floor_motions, require_probability, scale_to_pga, select_level
from assess.hazard.openquake import pga_at_level
from assess.hazard.pulse_identification import identify_pulse
from assess.hazard.record_pairs import item_axes_pair
from assess.hazard.records import MIN_DURATION_S, Record, pulse_record, read_record
from assess.hazard.synthesis import synthesize_motion
from assess.inventory.settings import Settings
from assess.quantity_text import floor_numbering_of, floor_text, floors_text, sentence_start

Progress = Callable[[str], None]
#: ``pulse_source`` of a motion with no pulse to identify (synthetic, or through the building): its Tp and vp are
#: empty and the paper's regression does not apply to it.
NO_PULSE = "no pulse: a synthetic or floor motion (the regression does not apply)"
#: Pulse simulated for a motion given by PTA and Tp without a pulse type.
DEFAULT_PULSE = "B"


@dataclass
class LevelMotions:
    """The motions of one hazard level, one row per motion and floor (``motion_key`` numbers them).

    ``table`` has the hazard sheet's columns (SI) with PTA, Tp and vp filled, ``pulse_source`` and, with
    derived floors, ``derived``; ``notes`` say how the motions differ from the workbook's (for the report).
    """

    level: HazardLevel
    level_label: str
    table: pd.DataFrame
    notes: list[str] = field(default_factory=list)
    #: Histories made in memory (the site's ground suite), by the key their rows give as ``record_path``.
    records: dict[str, Record] = field(default_factory=dict)
    #: The level's ground suite from the site sheet (``ground_motions.csv``, ``spectrum.csv``), or None.
    site: site_and_building.SiteSuite | None = None
    #: The building, where a building sheet passes the ground motions to floors without motions: its elastic
    #: modes or its yielding stick (:func:`assess.assessment.floors.building_model_of`).
    building: object | None = None
    #: How floors are labelled in motion names and notes (settings ``floor_numbering``).
    numbering: str = "ground_0"
    #: A calibration's ``input_scale`` s (1: none), by which ``table``'s motions are already multiplied: the
    #: building takes the ground motions at the level's own amplitude and its floors' histories are then
    #: multiplied by s, so that every item's floor shakes s times what it would (a yielding building's floors do
    #: not scale with its ground).
    input_scale: float = 1.0


@dataclass
class SimulatedMotions:
    """What the engine runs per motion (``motion_key``).

    ``histories``: the floor accelerations, each with how it was obtained; ``kinds``: ``record``,
    ``synthetic`` or ``pulse``; ``record_pairs``: for a motion with ``record_2``, its accelerations along
    the items' width and depth (``histories`` then holds the width one).
    """

    histories: dict[int, list[tuple[Record, str]]]
    kinds: dict[int, str]
    record_pairs: dict[int, tuple[Record, Record]]
    #: ``floors.csv``: the building's modes and each floor's PFA over the ground suite (None: no building).
    floors: pd.DataFrame | None = None


def level_motions(inventory, level_text: str, progress: Progress, oq_hazard=None,
                  derive_floors_roof: int | None = None, calibration=None, seed: int = 0) -> LevelMotions:
    """The motions of level ``level_text`` at every floor that has freestanding items (module docstring).

    With a ``site`` sheet and no ground motion for the level in the ``hazard`` sheet, the level's
    ground suite comes from the site; with a ``building`` sheet, every floor without motions gets the
    ground motions through the building (:mod:`assess.assessment.floors`), and ``--derive-floors``
    gives way to it.
    """
    workbook_name = inventory.path.name
    numbering = floor_numbering_of(inventory.settings)
    level, motions = _level_rows(inventory, level_text, workbook_name)
    level_label = str(motions["level_label"].iloc[0]) if len(motions) else (level.label or level.name)
    freestanding = inventory.equipment[~inventory.equipment["anchored"]]
    modes = site_and_building.building_modes_of(inventory.building) if inventory.building is not None else None
    building = (site_and_building.building_model_of(inventory.building, inventory.site, modes, workbook_name)
                if modes is not None else None)  # its elastic modes or its yielding stick
    records, site, notes = {}, None, []
    if inventory.site is not None and not _has_ground_motions(motions):
        progress(f"making the ground suite of level {level_label} from the site sheet")
        site = site_and_building.site_suite(inventory.site, level, modes, workbook_name, inventory.path.parent,
                                           seed)
        rows, records = _site_rows(site, level, level_label)
        motions = pd.concat([motions, rows], ignore_index=True) if len(motions) else rows
        notes.append(site_and_building.site_note(site, inventory.site))
    motions, measured = _measure_pulse_parameters(motions, workbook_name, records)
    notes += measured
    for note in notes:
        progress(note)
    # the floors the building gives their motions (the notes on scaling say how those scale)
    missing = _floors_without_motions(motions, freestanding, modes.storeys) if modes is not None else []
    if oq_hazard is not None:
        require_probability(level, level_label, workbook_name, "--oq-hazard")
        pga_g = pga_at_level(oq_hazard, level)
        motions, _, note = scale_to_pga(motions, pga_g, workbook_name, Path(oq_hazard.path).name,
                                        oq_hazard.source, through_building=bool(missing))
        notes.append(note)
        progress(note)
    input_scale = 1.0
    if calibration is not None:  # input_scale: the motions (assess.calibration.apply)
        motions, note = scaled_motions(motions, calibration, through_building=bool(missing))
        if note:
            notes.append(note)
            input_scale = float(calibration.motion_scale)
    if modes is not None:
        motions = motions.reset_index(drop=True).assign(motion_key=lambda m: np.arange(len(m)))
        motions = _with_building_rows(motions, missing, workbook_name, numbering)
        building_notes = []
        if missing:
            building_notes.append(site_and_building.building_note(building, inventory.building, missing,
                                                                  derive_floors_roof, numbering))
        elif (freestanding["floor"] > 0).any():
            building_notes.append("The building sheet gives no floor its motion: every floor with freestanding "
                                  "items has its own rows in the hazard sheet at this level, or rows for all "
                                  "floors (a structural engineer's floor motions govern).")
        roof = site_and_building.roof_note(freestanding, inventory.building, numbering)
        building_notes += [roof] if roof else []
        for note in building_notes:
            notes.append(note)
            progress(note)
    elif derive_floors_roof is not None:
        motions = derive_floor_motions(motions, freestanding["floor"].unique(), derive_floors_roof, workbook_name,
                                       numbering)
        if motions["derived"].any():
            floors = sorted(set(int(f) for f in motions.loc[motions["derived"], "floor"]))
            have, their = ("have", "their") if len(floors) > 1 else ("has", "its")
            note = (f"{sentence_start(floors_text(floors, numbering))} {have} no motion in the workbook: {their} "
                    "motions are the ground motions amplified by 1 + 2z/h (ASCE 7-16 eq. 13.3-1, roof = floor "
                    f"{floor_text(derive_floors_roof, numbering)}), with the ground's pulse period.")
            notes.append(note)
            progress(note)
    # one key per motion row: a motion named on several floors is a different motion on each
    motions = motions.reset_index(drop=True).assign(motion_key=lambda m: np.arange(len(m)))
    return LevelMotions(level, level_label, motions, notes, records, site, building, numbering, input_scale)


def check_level(inventory, level_text: str) -> None:
    """Refuse, before anything runs, a level the workbook cannot give motions for: one the hazard sheet
    does not name (without a site sheet), or, with a site sheet and no ground motion for the level in
    the hazard sheet, one the site sheet gives no target spectrum for
    (:func:`assess.site.target.level_target`). Raises :class:`~assess.errors.InputError`."""
    workbook_name = inventory.path.name
    level, motions = _level_rows(inventory, level_text, workbook_name)
    if inventory.site is not None and not _has_ground_motions(motions):
        site = inventory.site
        site_and_building.site_level_target(site, level, workbook_name,
                                            site_and_building.design_spectrum_of(site, workbook_name))


def _level_rows(inventory, level_text: str, workbook_name: str) -> tuple[HazardLevel, pd.DataFrame]:
    """The hazard sheet's rows of the level; with a site sheet, none is no error (the site gives them)."""
    if inventory.site is None or (len(inventory.hazard) and _names_level(inventory.hazard, level_text)):
        return select_level(inventory.hazard, level_text, workbook_name)
    try:
        level = parse_level(level_text)
    except ValueError:
        return select_level(inventory.hazard, level_text, workbook_name)  # its message names the level
    return level, inventory.hazard.iloc[0:0].copy()


def _names_level(hazard: pd.DataFrame, level_text: str) -> bool:
    try:
        wanted = parse_level(level_text)
    except ValueError:
        return True
    return any(parse_level(label).same_as(wanted) for label in hazard["level_label"].unique())


def _has_ground_motions(motions: pd.DataFrame) -> bool:
    return bool(len(motions)) and bool((motions["all_floors"] | (motions["floor"] == 0)).any())


#: Prefix of the key a row gives as ``record_path`` for a history made in memory (never a file's path:
#: a workbook's record paths are absolute).
MEMORY = "memory:"


def _site_rows(site, level: HazardLevel, level_label: str) -> tuple[pd.DataFrame, dict[str, Record]]:
    """The ground suite as hazard rows at floor 0, each naming its history by a :data:`MEMORY` key."""
    records, rows = {}, []
    synthetic = site.suite.method == "synthetic"
    for k, motion in enumerate(site.suite.motions):
        key = f"{MEMORY}{level_label}/{k + 1}"
        records[key] = motion.first
        second = ""
        if motion.second is not None:
            second = f"{key}/2"
            records[second] = motion.second
        rows.append({"level": level.name, "level_label": level_label, "motion": motion.name, "all_floors": False,
                     "floor": 0, "pta_g": motion.first.pta_g if synthetic else np.nan, "tp_s": np.nan,
                     "vp_m_s": np.nan, "pulse": "", "record_path": key, "scale": 1.0, "record_2_path": second,
                     "azimuth_deg": 0.0, "row": 0, "no_pulse": synthetic})
    table = pd.DataFrame(rows)
    table["floor"] = table["floor"].astype("Int64")
    return table, records


def _floors_without_motions(motions: pd.DataFrame, freestanding: pd.DataFrame, storeys: int) -> list[int]:
    """Floors above the ground with freestanding items and no motion of the level (the building gives theirs)."""
    if motions["all_floors"].any():
        return []
    have = set(int(f) for f in motions["floor"].dropna())
    return sorted(f for f in set(int(f) for f in freestanding["floor"]) if 0 < f <= storeys and f not in have)


def _with_building_rows(motions: pd.DataFrame, floors: list[int], workbook_name: str,
                        numbering: str = "ground_0") -> pd.DataFrame:
    """``motions`` and, for every floor in ``floors``, one row per ground motion (floor 0) whose history the
    building gives (``from_ground``: the ground row's ``motion_key``; PTA, Tp and vp are measured later),
    named ``<ground motion> @ floor <label>`` (the floor labelled by ``numbering``: :func:`floor_text`)."""
    motions = motions.assign(from_ground=-1)
    if not floors:
        return motions
    ground = motions[(~motions["all_floors"]) & (motions["floor"] == 0)]
    if ground.empty:
        raise InputError([Problem(workbook_name, f"floors {floors} have no motion, and the level has no ground "
                                  "motion (floor 0) to pass through the building.",
                                  "add the level's ground motions (floor 0) to the hazard sheet, or a site sheet "
                                  "with the site's hazard.", sheet="hazard", column="floor")])
    rows = []
    for floor in floors:
        derived = ground.assign(floor=floor, from_ground=ground["motion_key"], record_path="", record_2_path="",
                                scale=1.0, pta_g=np.nan, tp_s=np.nan, vp_m_s=np.nan, pulse="",
                                pulse_source=NO_PULSE)
        derived["motion"] = [f"{name} @ floor {floor_text(floor, numbering)}" for name in ground["motion"]]
        rows.append(derived)
    out = pd.concat([motions, *rows], ignore_index=True)
    out["floor"] = out["floor"].astype("Int64")
    return out.drop(columns="motion_key")


def simulated_motions(motions: LevelMotions, workbook_name: str, settings: Settings, seed: int,
                      progress: Progress) -> SimulatedMotions:
    """The accelerations the engine runs for every motion of the level (:class:`SimulatedMotions`);
    notes on turning a pair of records to the items' axes are added to ``motions.notes``."""
    progress("preparing the motions to simulate")
    histories, kinds = _simulated_motions(motions.table, workbook_name, settings, seed, motions.records)
    pairs = _record_pairs(motions.table, histories, workbook_name, motions.notes, progress, motions.records)
    floors = None
    if motions.building is not None and "from_ground" in motions.table and (motions.table["from_ground"] >= 0).any():
        progress("passing the ground motions through the building")
        floors = _through_building(motions, histories, kinds, pairs, progress)
    return SimulatedMotions(histories, kinds, pairs, floors)


def _through_building(motions: LevelMotions, histories: dict, kinds: dict, pairs: dict,
                      progress: Progress) -> pd.DataFrame:
    """Every floor row's histories (``from_ground`` >= 0): its ground motion's through the building; the
    row's PTA, Tp and vp measured from its first history (``motions.table`` is updated). Returns floors.csv."""
    table, modes = motions.table, motions.building
    derived = table[table["from_ground"] >= 0]
    grounds = sorted(int(key) for key in derived["from_ground"].unique())
    floors = sorted(int(f) for f in derived["floor"].unique())
    # every ground history (and each pair's second) through the building in one pass, side by side; a
    # calibration's input_scale s multiplies the floors' histories, not the ground's before the building
    s = motions.input_scale
    widths = [record for key in grounds for record, _ in histories[key]]
    depths = [pairs[key][1] for key in grounds if key in pairs]
    earthquake = [record.scaled(1.0 / s) for record in widths + depths] if s != 1.0 else widths + depths
    through, beyond = through_building(modes, earthquake, floors, progress=pass_progress(progress))
    if s != 1.0:
        through = {floor: [record.scaled(s) for record in records] for floor, records in through.items()}
    counts = [len(histories[key]) for key in grounds]
    first = dict(zip(grounds, np.cumsum([0] + counts[:-1]).tolist()))  # where each ground's histories start
    depth_of = {key: len(widths) + j for j, key in enumerate(key for key in grounds if key in pairs)}
    table["beyond_drift"] = False  # whether the building's model passed its trusted drift under the motion
    for index, row in derived.iterrows():
        ground_key, k, floor = int(row["from_ground"]), int(row["motion_key"]), int(row["floor"])
        start, stop = first[ground_key], first[ground_key] + len(histories[ground_key])
        width = through[floor][start:stop]
        table.loc[index, "beyond_drift"] = any(beyond[start:stop]) or (
            ground_key in pairs and beyond[depth_of[ground_key]])
        histories[k] = [(record, f"{label} @ floor {floor_text(floor, motions.numbering)}, through the building")
                        for record, (_, label) in zip(width, histories[ground_key])]
        kinds[k] = RECORD  # the engine under the floor's history governs (no pulse regression for it)
        if ground_key in pairs:
            pairs[k] = (width[0], through[floor][depth_of[ground_key]])
        # a floor's motion is the building's filtered response, no pulse: the paper's regression (Tp, vp)
        # does not apply to it, and the engine under the history governs
        table.loc[index, ["pta_g", "tp_s", "vp_m_s", "pulse_source"]] = [width[0].pta_g, np.nan, np.nan, NO_PULSE]
    ground = [earthquake[first[key]] for key in grounds]  # what the building took (floors.csv: what it did)
    return site_and_building.floors_csv(modes, ground, floors, motions.level_label)


def _motion_record(record_path: str, scale: float, motion: str, row: int, workbook_name: str,
                   memory: dict | None = None) -> Record:
    """The record of a hazard row, read (once per file and scale) and scaled; errors name the row.
    A :data:`MEMORY` key names a history made in memory (``memory``)."""
    if record_path.startswith(MEMORY):
        record = memory[record_path]
        return record if float(scale) == 1.0 else record.scaled(float(scale))
    try:
        return read_scaled(record_path, float(scale))
    except InputError as error:
        raise InputError([replace(problem, message=f"the record of motion '{motion}' "
                                  f"({workbook_name}, sheet 'hazard', row {int(row)}): "
                                  f"{problem.message}") for problem in error.problems]) from None


@functools.lru_cache(maxsize=64)
def read_scaled(path: str, scale: float) -> Record:
    return read_record(path, min_duration_s=MIN_DURATION_S, scale=scale)


def _measure_pulse_parameters(level_motions: pd.DataFrame, workbook_name: str,
                              memory: dict | None = None) -> tuple[pd.DataFrame, list[str]]:
    """Fill PTA, Tp and vp that a motion with a record leaves empty, from the record.

    PTA is the record's peak absolute acceleration (after ``scale``); Tp and
    vp come from a Type-B pulse fitted to its velocity
    (:func:`assess.hazard.pulse_identification.identify_pulse`; the paper's
    regression was fitted with Type-B periods). ``pulse_source`` says, per
    motion, where its numbers came from; the notes go to the report.
    """
    motions = level_motions.assign(pulse_source="workbook")
    notes = []
    for index, row in motions.iterrows():
        # a synthetic motion: stationary filtered noise, no pulse to fit
        if row.get("no_pulse") == True:  # noqa: E712 (NaN where the row has none)
            motions.at[index, "pulse_source"] = NO_PULSE
            continue
        missing = [c for c in ("pta_g", "tp_s", "vp_m_s") if not np.isfinite(row[c])]
        if not row["record_path"] or not missing:
            continue
        record = _motion_record(row["record_path"], row["scale"], row["motion"], row["row"], workbook_name, memory)
        measured = []
        if "pta_g" in missing:
            motions.at[index, "pta_g"] = record.pta_g
            measured.append(f"PTA {record.pta_g:.3f} g")
        if {"tp_s", "vp_m_s"} & set(missing):
            fit = identify_pulse(record.accel_g, record.dt_s, models=("B",))
            if "tp_s" in missing:
                motions.at[index, "tp_s"] = fit.tp_s
                measured.append(f"Tp {fit.tp_s:.2f} s")
            if "vp_m_s" in missing:
                motions.at[index, "vp_m_s"] = fit.vp_m_s
                measured.append(f"vp {fit.vp_m_s * 100:.0f} cm/s")
            clarity = "a clear pulse" if fit.is_pulse_like else "no clear pulse: Tp is only the best single pulse"
            source = f"measured from the record (Type-B fit explains {fit.fit_r2:.0%} of the velocity; {clarity})"
        else:
            source = "PTA measured from the record"
        motions.at[index, "pulse_source"] = source
        if not row["record_path"].startswith(MEMORY):  # the site's motions are said once (floors.site_note)
            notes.append(f"Motion '{row['motion']}': {', '.join(measured)} {source}.")
    return motions, notes


def _simulated_motions(level_motions: pd.DataFrame, workbook_name: str, settings: Settings, seed: int,
                       memory: dict | None = None) -> tuple[dict[int, list[tuple[Record, str]]], dict[int, str]]:
    """Per motion (``motion_key``): the floor accelerations the engine simulates, each with how it
    was obtained; and how each motion was simulated (``record``, ``synthetic`` or ``pulse``).

    A motion with a record is simulated under the record (times ``scale``).
    One given by PTA, Tp and vp is simulated under ``synthetic_realizations``
    near-fault histories synthesised to match them
    (:func:`assess.hazard.synthesis.synthesize_motion`, seeded by ``seed`` and
    the motion's place in the sheet) when ``simulate_motions`` is
    ``synthetic``, or under its pulse (:data:`DEFAULT_PULSE` where the workbook
    names none) when it is ``pulse`` or vp is not given.
    """
    synthetic = settings.simulate_motions.strip().lower() == "synthetic"
    count = settings.synthetic_realizations
    motions, kinds, to_synthesize = {}, {}, {}
    for row in level_motions.itertuples(index=False):
        k = int(row.motion_key)
        if getattr(row, "from_ground", -1) >= 0:
            continue  # a floor's motion through the building (:func:`_through_building`)
        if row.record_path:
            record = _motion_record(row.record_path, row.scale, row.motion, row.row, workbook_name, memory)
            motions[k], kinds[k] = [(record, f"record {record.name} x {float(row.scale):g}")], RECORD
            continue
        pta, tp, vp = float(row.pta_g), float(row.tp_s), float(row.vp_m_s)
        if synthetic and np.isfinite(vp):
            to_synthesize[k], kinds[k] = (pta, tp, vp), SYNTHETIC
            continue
        pulse = row.pulse or DEFAULT_PULSE
        record = pulse_record(pulse, pta, tp)
        note = f"Type-{pulse} pulse" if row.pulse else f"Type-{pulse} pulse (assumed: no pulse type given)"
        if synthetic:
            note += " (no vp given to synthesise from)"
        motions[k], kinds[k] = [(record, f"{note}, {pta:g} g, Tp {tp:g} s")], PULSE

    def synthesized(k):
        pta, tp, vp = to_synthesize[k]
        return synthesize_motion(pta, tp, vp, n_realizations=count, seed=np.random.default_rng([seed, k]))

    # each motion from its own seed, so the threads change when, not what (the filter kernel releases the GIL)
    with warnings.catch_warnings(), ThreadPoolExecutor(max(1, numba.get_num_threads())) as pool:
        warnings.simplefilter("ignore")  # a pulse above PTA is said in the record's name
        for k, records in zip(to_synthesize, pool.map(synthesized, to_synthesize)):
            motions[k] = [(r, r.name) for r in records]
    return {k: motions[k] for k in kinds}, kinds  # in the sheet's order


def _record_pairs(level_motions: pd.DataFrame, motions: dict, workbook_name: str, notes: list,
                  progress: Progress, memory: dict | None = None) -> dict[int, tuple[Record, Record]]:
    """Per motion with ``record_2``: its accelerations along the items' width and depth
    (:func:`assess.hazard.record_pairs.item_axes_pair`); ``motions`` then holds the width one."""
    pairs, uneven = {}, []
    for row in level_motions.itertuples(index=False):
        second_path = str(getattr(row, "record_2_path", "") or "")
        if not second_path or not row.record_path:
            continue
        k = int(row.motion_key)
        first = _motion_record(row.record_path, row.scale, row.motion, row.row, workbook_name, memory)
        try:
            second = _motion_record(second_path, row.scale, row.motion, row.row, workbook_name, memory)
        except InputError as error:  # say which of the two components it is
            raise InputError([replace(problem, message=f"record_2: {problem.message}")
                              for problem in error.problems]) from None
        width, depth, note = item_axes_pair(first, second, float(row.azimuth_deg), row.motion, row.row,
                                            workbook_name)
        if note:
            uneven.append(f"'{row.motion}' ({note})")
        pairs[k] = (width, depth)
        motions[k] = [(width, f"records {first.name} + {second.name} x {float(row.scale):g}"
                       + (f", turned {float(row.azimuth_deg):g} deg" if float(row.azimuth_deg) else ""))]
    if uneven:  # one note for all: a suite of pairs may hold many
        one = len(uneven) == 1
        note = (f"{'Motion' if one else f'{len(uneven)} motions'} {'; '.join(uneven)}: "
                f"{'its' if one else 'each'} shorter component is taken as zero (the floor at rest along its axis) "
                "after its last sample.")
        notes.append(note)
        progress(note)
    return pairs
