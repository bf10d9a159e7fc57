"""The motions of a hazard level that act on each floor."""
from __future__ import annotations

import numpy as np
import pandas as pd

from assess.errors import Problem, raise_if_any
from assess.hazard.levels import HazardLevel, parse_level
from assess.hazard.records import MAX_PLAUSIBLE_PGA_G
from assess.quantity_text import floor_text


def select_level(hazard: pd.DataFrame, level_text: str, workbook_name: str) -> tuple[HazardLevel, pd.DataFrame]:
    """Rows of the ``hazard`` table for the level ``level_text`` names.

    Any spelling of the same probability matches (``2475yr`` finds ``2in50``);
    a label matches the same text, ignoring case (``de`` finds ``DE``).
    Raises :class:`~assess.errors.InputError` listing the workbook's levels
    when it has none that matches.
    """
    try:
        wanted = parse_level(level_text)
    except ValueError as error:
        raise_if_any([Problem(file="--hazard", message=str(error) + ".",
                              fix="give the level as the workbook's hazard sheet names it, e.g. --hazard 2in50")])
    labels = hazard.drop_duplicates("level_label")["level_label"]
    matching = [label for label in labels if parse_level(label).same_as(wanted)]
    if matching:
        chosen = hazard[hazard["level_label"].isin(matching)].reset_index(drop=True)
        return parse_level(chosen["level_label"].iloc[0]), chosen
    listed = list(labels)
    have = ", ".join(f"'{label}'" for label in listed[:20]) or "none"
    if len(listed) > 20:
        have += f" and {len(listed) - 20} more"
    raise_if_any([Problem(
        file=workbook_name, sheet="hazard", column="level",
        message=f"the workbook has no motions for hazard level '{wanted.label or level_text}' "
                f"({wanted.description}); it has: {have}.",
        fix="run with one of those levels, or add rows for this level to the hazard sheet.")])
    raise AssertionError("unreachable")


def require_probability(level: HazardLevel, level_label: str, workbook_name: str, needed_by: str) -> None:
    """Raise :class:`~assess.errors.InputError` when ``level`` is a label, which ``needed_by``
    (e.g. ``--oq-hazard``) cannot use: it reads the hazard at a probability of exceedance."""
    if level.has_probability:
        return
    raise_if_any([Problem(
        file=workbook_name, sheet="hazard", column="level",
        message=f"{needed_by} reads the site's hazard at the level's probability of exceedance, but "
                f"the level '{level_label}' is a label with no probability.",
        fix=f"name the level by its probability in the hazard sheet and in --hazard (e.g. 2in50, "
            f"10%/50yr or 2475yr), or run without {needed_by}.")])


def motions_by_item(equipment: pd.DataFrame, level_motions: pd.DataFrame, level_label: str,
                    workbook_name: str) -> pd.DataFrame:
    """Pair every item with every motion of the level acting on its floor.

    Returns one row per (item, motion) with the item's ``id`` and the motion's
    columns. A floor with no motion is an error (by default no floor motion is
    derived from another floor's).
    """
    specific = level_motions[~level_motions["all_floors"]]
    everywhere = level_motions[level_motions["all_floors"]]
    pairs = []
    problems = []
    for item in equipment.itertuples(index=False):
        acting = pd.concat([specific[specific["floor"] == item.floor], everywhere])
        if acting.empty:
            floors = sorted({int(f) for f in specific["floor"].dropna()})
            problems.append(Problem(
                file=workbook_name, sheet="equipment", row=item.row, column="floor",
                message=f"item '{item.id}' is on floor {item.floor}, but hazard level '{level_label}' "
                        f"has no motion for that floor (it has floors {floors or 'none'}).",
                fix=f"add hazard rows for floor {item.floor} (or a row with floor 'all'), correct the "
                    "item's floor, or run with --derive-floors ROOF_FLOOR to derive the floor's motion "
                    "from the ground motions (ASCE 7-16 eq. 13.3-1; the item is flagged)."))
            continue
        pairs.append(acting.assign(id=item.id))
    raise_if_any(problems)
    return pd.concat(pairs, ignore_index=True)


def scale_to_pga(level_motions: pd.DataFrame, pga_g: float, workbook_name: str,
                 source: str, program: str = "OpenQuake",
                 through_building: bool = False) -> tuple[pd.DataFrame, float, str]:
    """Scale every motion of a level so that its ground motions match a hazard PGA.

    The factor is PGA / (geometric mean of the PTA of the level's ground-floor
    motions, floor 0 or ``all``); it multiplies every motion of the level —
    PTA, vp and the record scale — so the suite keeps its spread and each
    floor the workbook gives its amplification over the ground (a linear building). Tp is kept.
    ``source`` names the hazard file, ``program`` what wrote it (``OpenQuake``,
    ``USGS nshmp-haz``), for the note. ``through_building``: floors without motions of their own
    take the scaled ground motions through the building sheet's model (which may yield, so their
    motions are not the factor times anything), as the note then says.

    Returns ``(scaled motions, factor, a sentence for the report)``; raises
    :class:`~assess.errors.InputError` when the level has no ground motion.

    >>> motions = pd.DataFrame({"motion": ["a", "b", "roof"], "floor": [0, 0, 6], "all_floors": False,
    ...                         "pta_g": [0.4, 0.9, 1.2], "vp_m_s": [-0.5, -0.8, -1.0], "scale": 1.0})
    >>> scaled, factor, _ = scale_to_pga(motions, 0.3, "lab.xlsx", "oq.csv")
    >>> round(factor, 6), scaled["pta_g"].round(6).tolist()
    (0.5, [0.2, 0.45, 0.6])
    >>> _, _, note = scale_to_pga(motions[motions["floor"] == 0], 0.3, "lab.xlsx", "oq.csv", through_building=True)
    >>> note.split("; ")[-1]
    'the floors without motions of their own take the scaled ground motions through the building.'
    """
    ground = level_motions[level_motions["all_floors"] | (level_motions["floor"] == 0)]
    ground_pta = pd.to_numeric(ground["pta_g"], errors="coerce").dropna()
    if ground_pta.empty:
        raise_if_any([Problem(
            file=workbook_name, sheet="hazard", column="floor",
            message="--oq-hazard scales the level's motions to the site's PGA, but the level has no "
                    "ground motion (floor 0 or 'all') with a pta_g to scale from.",
            fix="add the level's ground motions (floor 0) with their pta_g, or run without --oq-hazard.")])
    reference_g = float(np.exp(np.log(ground_pta.to_numpy(dtype=float)).mean()))
    factor = pga_g / reference_g
    scaled = level_motions.copy()
    for column in ("pta_g", "vp_m_s", "scale"):
        if column in scaled:
            scaled[column] = scaled[column] * factor
    raise_if_any(_records_past_plausible(scaled, factor, pga_g, workbook_name, source))
    floors = []
    if ((~level_motions["all_floors"]) & (level_motions["floor"] != 0)).any():
        floors.append("the workbook's floor motions by the same factor")
    if through_building:
        floors.append("the floors without motions of their own take the scaled ground motions through the building")
    note = (f"Motions scaled by {factor:.3f} so that the geometric mean PTA of the level's "
            f"{len(ground_pta)} ground motion{'s' if len(ground_pta) != 1 else ''} "
            f"({reference_g:.3f} g in the workbook) equals the PGA {pga_g:.3f} g of the {program} "
            f"hazard in {source} at this level" + "".join(f"; {clause}" for clause in floors) + ".")
    return scaled, factor, note


def _records_past_plausible(scaled: pd.DataFrame, factor: float, pga_g: float, workbook_name: str,
                            source: str) -> list[Problem]:
    """A problem for each record that the hazard curve's scaling pushes past the plausible peak (5 g).

    The record itself and its ``scale`` cell are fine; the factor comes from
    the curve (``source``), so the message names the curve and the factor.
    """
    if "record_path" not in scaled:
        return []
    problems = []
    for _, row in scaled.iterrows():
        peak_g = pd.to_numeric(pd.Series([row.get("pta_g")]), errors="coerce").iloc[0]
        if not row.get("record_path") or not np.isfinite(peak_g) or peak_g <= MAX_PLAUSIBLE_PGA_G:
            continue
        where = f", row {int(row['row'])}" if np.isfinite(pd.to_numeric(row.get("row"), errors="coerce")) else ""
        problems.append(Problem(
            file=str(source),
            message=f"--oq-hazard: the curve gives PGA {pga_g:.3g} g at this level, so the level's motions are "
                    f"scaled by {factor:.3g}; that makes the record of motion '{row['motion']}' ({workbook_name}, "
                    f"sheet 'hazard'{where}) peak at {peak_g:.3g} g, more than {MAX_PLAUSIBLE_PGA_G:g} g.",
            fix="check the curve and its site (--oq-site) and the level; if the hazard is right, give the level "
                "records whose ground motions are nearer its PGA, so that the factor stays moderate."))
    return problems


#: Cap of the floor amplification 1 + 2 z/h (ASCE 7-16 eq. 13.3-1 at the roof).
FLOOR_AMPLIFICATION_MAX = 3.0


def floor_amplification(floor, roof_floor):
    """Peak floor over peak ground acceleration, 1 + 2 z/h (ASCE 7-16, eq. 13.3-1).

    .. math:: \\frac{PFA}{PGA} = 1 + 2\\frac{z}{h}

    with z/h taken as ``floor / roof_floor`` (storeys of equal height), at most
    3 (the roof). The rule is the code's envelope for the force on a
    non-structural component; it ignores the building's periods.

    >>> floor_amplification(0, 6), floor_amplification(3, 6), floor_amplification(6, 6)
    (1.0, 2.0, 3.0)
    """
    ratio = min(max(float(floor) / float(roof_floor), 0.0), 1.0)
    return min(1.0 + 2.0 * ratio, FLOOR_AMPLIFICATION_MAX)


def derive_floor_motions(level_motions: pd.DataFrame, floors, roof_floor: int, workbook_name: str,
                         numbering: str = "ground_0") -> pd.DataFrame:
    """Add motions for ``floors`` that have none, derived from the level's ground motions.

    Each ground motion (floor 0) is copied to the floor with its PTA, vp and
    record scale multiplied by :func:`floor_amplification` and its Tp kept
    (the floor's pulse period is taken as the ground's). The new rows carry
    ``derived = True`` and a motion name that says so (the floor labelled by
    ``numbering``: :func:`assess.quantity_text.floor_text`). Floors that have
    motions are left alone; a level without ground motions is an error.
    """
    motions = level_motions.assign(derived=False)
    have = set(int(f) for f in motions.loc[~motions["all_floors"], "floor"].dropna())
    missing = sorted(set(int(f) for f in floors) - have) if not motions["all_floors"].any() else []
    if not missing:
        return motions
    ground = motions[(~motions["all_floors"]) & (motions["floor"] == 0)]
    if ground.empty:
        raise_if_any([Problem(
            file=workbook_name, sheet="hazard", column="floor",
            message=f"floors {missing} have no motion, and there is no ground motion (floor 0) to derive "
                    "them from.", fix="add the level's ground motions (floor 0), or motions for those floors.")])
    derived = []
    for floor in missing:
        factor = floor_amplification(floor, roof_floor)
        rows = ground.copy()
        rows["floor"] = floor
        rows["motion"] = [f"{name} -> floor {floor_text(floor, numbering)} (derived, x{factor:.2f})"
                          for name in ground["motion"]]
        for column in ("pta_g", "vp_m_s", "scale"):
            rows[column] = rows[column] * factor
        rows["derived"] = True
        derived.append(rows)
    out = pd.concat([motions, *derived], ignore_index=True)
    out["floor"] = out["floor"].astype("Int64")
    return out
