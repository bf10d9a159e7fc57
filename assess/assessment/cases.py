"""Stage 3 of the assessment: the cases, one per freestanding item x motion x direction (x μ node).

Each case carries the block's geometry in its direction (b/h, α, p, the
inertia ratio) and the motion's numbers; an item with a range of friction has
its cases repeated at its μ nodes (:func:`assess.fragility.friction_range.expand_cases`).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import pandas as pd

from assess.fragility.friction_range import expand_cases
from assess.hazard.motions import motions_by_item
from assess.mechanics.geometry import frequency_parameter, inertia_ratio, slenderness

#: Base directions: 1 along the width, 2 along the depth.
DIRECTIONS = {1: "width_m", 2: "depth_m"}


@dataclass
class Cases:
    """The freestanding items (``items``) and their cases (``table``, one row per item x motion x
    direction x μ node; ``mu_nominal`` marks the cases at the workbook's μ)."""

    items: pd.DataFrame
    table: pd.DataFrame


def build_cases(equipment: pd.DataFrame, motions, workbook_name: str, progress: Callable[[str], None]) -> Cases:
    """The cases of every freestanding item of ``equipment`` under the motions of its floor
    (``motions``: :class:`assess.assessment.motions.LevelMotions`)."""
    freestanding = equipment[~equipment["anchored"]]
    pairs = motions_by_item(freestanding, motions.table, motions.level_label, workbook_name)
    items = f"{len(freestanding)} freestanding item{'' if len(freestanding) == 1 else 's'}"
    progress(f"{items}, {len(motions.table)} motions at level "
             f"{motions.level_label}: {len(pairs) * len(DIRECTIONS)} item x motion x direction cases")
    return Cases(freestanding, item_motion_direction_cases(freestanding, pairs))


def item_motion_direction_cases(items: pd.DataFrame, pairs: pd.DataFrame) -> pd.DataFrame:
    """One row per item x motion x direction with the block's geometry in that direction."""
    item_columns = ["id", "floor", "height_m", "width_m", "depth_m", "cg_height_m", "mu",
                    "mu_static", "clearance_m"] + [c for c in ("mu_low", "mu_high") if c in items]
    motion_columns = ["id", "motion", "motion_key", "pta_g", "tp_s", "vp_m_s", "pulse_source"] + [
        column for column in ("derived", "beyond_drift") if column in pairs]
    base = pairs[motion_columns].assign(pair_index=range(len(pairs))) \
        .merge(items[item_columns], on="id", validate="many_to_one")
    frames = []
    for direction, dimension in DIRECTIONS.items():
        frame = base.assign(direction=direction, half_width_m=base[dimension] / 2.0)
        frames.append(frame)
    cases = pd.concat(frames, ignore_index=True)
    cases["b_over_h"] = cases["half_width_m"] / cases["cg_height_m"]
    cases["alpha_rad"] = slenderness(cases["half_width_m"], cases["cg_height_m"])
    cases["p_rad_s"] = frequency_parameter(cases["half_width_m"], cases["cg_height_m"], cases["height_m"])
    cases["inertia_ratio"] = inertia_ratio(cases["half_width_m"], cases["cg_height_m"], cases["height_m"])
    return expand_cases(cases)  # an item with a μ range: its cases at its μ values (friction_range)


def with_centre_of_mass_at(cases: pd.DataFrame, ids, fraction: float) -> pd.DataFrame:
    """The cases of the items ``ids`` with their centre of mass at ``fraction`` of their height (heavy
    contents moved low: the what-if of :func:`assess.assessment.run.lowered_contents`), b/h, α, p and
    the inertia ratio recomputed for it. The block keeps its box's moment of inertia about the centre
    of mass (:mod:`assess.mechanics.block`), so only the centre's height changes."""
    chosen = cases[cases["id"].isin(list(ids))].reset_index(drop=True)
    chosen = chosen.assign(cg_height_m=float(fraction) * chosen["height_m"])
    chosen["b_over_h"] = chosen["half_width_m"] / chosen["cg_height_m"]
    chosen["alpha_rad"] = slenderness(chosen["half_width_m"], chosen["cg_height_m"])
    chosen["p_rad_s"] = frequency_parameter(chosen["half_width_m"], chosen["cg_height_m"], chosen["height_m"])
    chosen["inertia_ratio"] = inertia_ratio(chosen["half_width_m"], chosen["cg_height_m"], chosen["height_m"])
    return chosen
