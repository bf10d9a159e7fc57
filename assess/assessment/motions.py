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
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Callable

import numpy as np
import pandas as pd

from assess.calibration.apply import scaled_motions
from assess.errors import InputError
from assess.fragility.governing import PULSE, RECORD, SYNTHETIC
from assess.hazard.levels import HazardLevel
from assess.hazard.motions import derive_floor_motions, require_probability, scale_to_pga, select_level
from assess.hazard.openquake import pga_at_level
from assess.hazard.pulse_identification import identify_pulse
from assess.hazard.record_pairs import item_axes_pair
from assess.hazard.records import MIN_DURATION_S, Record, pulse_record, read_record
from assess.hazard.synthesis import synthesize_motion

Progress = Callable[[str], None]
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


def level_motions(inventory, level_text: str, progress: Progress, oq_hazard=None,
                  derive_floors_roof: int | None = None, calibration=None) -> LevelMotions:
    """The motions of level ``level_text`` at every floor that has freestanding items (module docstring)."""
    workbook_name = inventory.path.name
    level, motions = select_level(inventory.hazard, level_text, workbook_name)
    level_label = str(motions["level_label"].iloc[0])
    motions, notes = _measure_pulse_parameters(motions, workbook_name)
    for note in notes:
        progress(note)
    if oq_hazard is not None:
        require_probability(level, level_label, workbook_name, "--oq-hazard")
        pga_g = pga_at_level(oq_hazard, level)
        motions, _, note = scale_to_pga(motions, pga_g, workbook_name, Path(oq_hazard.path).name)
        notes.append(note)
        progress(note)
    if calibration is not None:  # input_scale: the motions (assess.calibration.apply)
        motions, note = scaled_motions(motions, calibration)
        if note:
            notes.append(note)
    if derive_floors_roof is not None:
        equipment = inventory.equipment
        freestanding = equipment[~equipment["anchored"]]
        motions = derive_floor_motions(motions, freestanding["floor"].unique(), derive_floors_roof, workbook_name)
        if motions["derived"].any():
            floors = sorted(set(int(f) for f in motions.loc[motions["derived"], "floor"]))
            note = (f"Floors {floors} have no motion in the workbook: their motions are the ground motions "
                    f"amplified by 1 + 2z/h (ASCE 7-16 eq. 13.3-1, roof = floor {derive_floors_roof}), "
                    f"with the ground's pulse period.")
            notes.append(note)
            progress(note)
    # one key per motion row: a motion named on several floors is a different motion on each
    motions = motions.reset_index(drop=True).assign(motion_key=lambda m: np.arange(len(m)))
    return LevelMotions(level, level_label, motions, notes)


def simulated_motions(motions: LevelMotions, workbook_name: str, settings: dict, seed: int,
                      progress: Progress) -> SimulatedMotions:
    """The accelerations the engine runs for every motion of the level (:class:`SimulatedMotions`);
    notes on turning a pair of records to the items' axes are added to ``motions.notes``."""
    progress("preparing the motions to simulate")
    histories, kinds = _simulated_motions(motions.table, workbook_name, settings, seed)
    pairs = _record_pairs(motions.table, histories, workbook_name, motions.notes, progress)
    return SimulatedMotions(histories, kinds, pairs)


def _motion_record(record_path: str, scale: float, motion: str, row: int, workbook_name: str) -> Record:
    """The record of a hazard row, read (once per file and scale) and scaled; errors name the row."""
    try:
        return read_scaled(record_path, float(scale))
    except InputError as error:
        raise InputError([replace(problem, message=f"the record of motion '{motion}' "
                                  f"({workbook_name}, sheet 'hazard', row {int(row)}): "
                                  f"{problem.message}") for problem in error.problems]) from None


@functools.lru_cache(maxsize=64)
def read_scaled(path: str, scale: float) -> Record:
    return read_record(path, min_duration_s=MIN_DURATION_S, scale=scale)


def _measure_pulse_parameters(level_motions: pd.DataFrame, workbook_name: str) -> tuple[pd.DataFrame, list[str]]:
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
        missing = [c for c in ("pta_g", "tp_s", "vp_m_s") if not np.isfinite(row[c])]
        if not row["record_path"] or not missing:
            continue
        record = _motion_record(row["record_path"], row["scale"], row["motion"], row["row"], workbook_name)
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
        notes.append(f"Motion '{row['motion']}': {', '.join(measured)} {source}.")
    return motions, notes


def _simulated_motions(level_motions: pd.DataFrame, workbook_name: str, settings: dict,
                       seed: int) -> tuple[dict[int, list[tuple[Record, str]]], dict[int, str]]:
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
    synthetic = str(settings.get("simulate_motions", "synthetic")).strip().lower() == "synthetic"
    count = int(settings.get("synthetic_realizations", 5))
    motions, kinds = {}, {}
    for row in level_motions.itertuples(index=False):
        k = int(row.motion_key)
        if row.record_path:
            record = _motion_record(row.record_path, row.scale, row.motion, row.row, workbook_name)
            motions[k], kinds[k] = [(record, f"record {record.name} x {float(row.scale):g}")], RECORD
            continue
        pta, tp, vp = float(row.pta_g), float(row.tp_s), float(row.vp_m_s)
        if synthetic and np.isfinite(vp):
            with warnings.catch_warnings():  # a pulse above PTA is said in the record's name
                warnings.simplefilter("ignore")
                records = synthesize_motion(pta, tp, vp, n_realizations=count,
                                            seed=np.random.default_rng([seed, k]))
            motions[k], kinds[k] = [(r, r.name) for r in records], SYNTHETIC
            continue
        pulse = row.pulse or DEFAULT_PULSE
        record = pulse_record(pulse, pta, tp)
        note = f"Type-{pulse} pulse" if row.pulse else f"Type-{pulse} pulse (assumed: no pulse type given)"
        if synthetic:
            note += " (no vp given to synthesise from)"
        motions[k], kinds[k] = [(record, f"{note}, {pta:g} g, Tp {tp:g} s")], PULSE
    return motions, kinds


def _record_pairs(level_motions: pd.DataFrame, motions: dict, workbook_name: str, notes: list,
                  progress: Progress) -> dict[int, tuple[Record, Record]]:
    """Per motion with ``record_2``: its accelerations along the items' width and depth
    (:func:`assess.hazard.record_pairs.item_axes_pair`); ``motions`` then holds the width one."""
    pairs = {}
    for row in level_motions.itertuples(index=False):
        second_path = str(getattr(row, "record_2_path", "") or "")
        if not second_path or not row.record_path:
            continue
        k = int(row.motion_key)
        first = _motion_record(row.record_path, row.scale, row.motion, row.row, workbook_name)
        try:
            second = _motion_record(second_path, row.scale, row.motion, row.row, workbook_name)
        except InputError as error:  # say which of the two components it is
            raise InputError([replace(problem, message=f"record_2: {problem.message}")
                              for problem in error.problems]) from None
        width, depth, note = item_axes_pair(first, second, float(row.azimuth_deg), row.motion, row.row,
                                            workbook_name)
        if note:
            notes.append(note)
            progress(note)
        pairs[k] = (width, depth)
        motions[k] = [(width, f"records {first.name} + {second.name} x {float(row.scale):g}"
                       + (f", turned {float(row.azimuth_deg):g} deg" if float(row.azimuth_deg) else ""))]
    return pairs
