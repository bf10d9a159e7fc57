"""Sliding in the plane under both horizontal components, for the items that cannot uplift.

Where a motion gives both horizontal components (``record`` and ``record_2``,
:mod:`assess.hazard.record_pairs`) and an item cannot uplift in either base
direction (μs < b/h both ways, :func:`~assess.mechanics.gateway.pure_sliding_proved`),
the block slides on the floor under the two components at once, with the
friction force μmg opposing its velocity vector (the engine's ``planar`` runs,
:meth:`assess.mechanics.gateway.Cases.planar`). Its sliding
demand under that motion is then the **peak distance from rest** of that
path, compared with its clearance, and it replaces the larger of the two
one-way answers (each base direction under its component alone, friction
μmg per axis): that is the physical answer where it applies; the one-way
answers are kept in ``motions.csv``. On pyslammer's records paired (18 pairs,
PGA 0.4 and 0.7 g, μ 0.1-0.3; ``benchmarks/bench_sliding_2d.py``) the 2-D
peak is 0.74 to 1.87 times the larger one-way peak (median 1.02) where that
is at least 1 cm.

An item that can uplift keeps the one-way rocking/sliding engine in each
direction: no 2-D rocking model is verified here.
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from assess.hazard.records import Record
from assess.inventory.units import CM_PER_M
from assess.mechanics.gateway import Cases, pure_sliding_proved

#: Columns of :func:`planar_runs`.
PLANAR_COLUMNS = ["id", "motion_key", "mu_node", "realization", "sliding_cm", "residual_cm"]


def planar_cases(cases: pd.DataFrame, pairs: dict) -> pd.DataFrame:
    """One row per item × paired motion × μ node that slides in the plane: ``id``, ``motion_key``,
    ``mu_node``, ``mu``, ``mu_static``, ``case`` (its direction-1 row in ``cases``), and ``block`` (that
    row's block) where ``cases`` has one."""
    if not pairs or cases.empty:
        return pd.DataFrame(columns=["id", "motion_key", "mu_node", "mu", "mu_static", "case"])
    node = cases["mu_node"] if "mu_node" in cases else pd.Series(0, index=cases.index)
    table = cases.assign(mu_node=node, case=np.arange(len(cases)))
    table = table[table["motion_key"].isin(list(pairs))]
    slender = table.groupby(["id", "motion_key", "mu_node"])["b_over_h"].transform("min")
    sliding = pure_sliding_proved(table["mu_static"].to_numpy(), slender.to_numpy())
    chosen = table[sliding & (table["direction"] == 1)]
    columns = ["id", "motion_key", "mu_node", "mu", "mu_static", "case"] + (["block"] if "block" in chosen else [])
    return chosen[columns].reset_index(drop=True)


def planar_runs(cases: pd.DataFrame, pairs: dict[int, tuple[Record, Record]], runner) -> pd.DataFrame:
    """The 2-D peak distance from rest [cm] of every item that cannot uplift under every paired motion.

    ``cases`` carry their ``block``; ``pairs`` maps a ``motion_key`` to its
    accelerations along the items' width and depth
    (:func:`assess.hazard.record_pairs.item_axes_pair`); ``runner`` runs the
    engine's cases (:mod:`assess.mechanics.gateway`). Returns
    :data:`PLANAR_COLUMNS` (``realization`` 0: a record is one history).
    """
    chosen = planar_cases(cases, pairs)
    if chosen.empty:
        return pd.DataFrame(columns=PLANAR_COLUMNS)
    chosen = chosen.sort_values("motion_key", kind="stable").reset_index(drop=True)
    keys = sorted(set(chosen["motion_key"]))
    slot = {key: 2 * j for j, key in enumerate(keys)}
    records = [component for key in keys for component in pairs[key]]
    first = chosen["motion_key"].map(slot).to_numpy(dtype=np.int64)
    peaks = runner.run(Cases.planar(chosen["block"].tolist(), [r.accel_g for r in records],
                                    [r.dt_s for r in records], first, first + 1))
    return chosen[["id", "motion_key", "mu_node"]].assign(
        realization=0, sliding_cm=peaks.sliding_max_m * CM_PER_M,
        residual_cm=peaks.sliding_residual_m * CM_PER_M)[PLANAR_COLUMNS]


def planar_note(motions: int, total: int) -> str:
    """The demand note's sentence for an item that slid in the plane under ``motions`` of its ``total``.

    >>> planar_note(2, 3)  # doctest: +NORMALIZE_WHITESPACE
    'Under 2 of its 3 motions (both horizontal components given) it cannot uplift and slides in the plane: its sliding
    there is the peak distance from rest under both components at once, not the larger of the one-way answers.'
    """
    which = f"all {total} motions" if motions == total and total > 1 else (
        "its one motion" if total == 1 else f"{motions} of its {total} motions")
    return (f"Under {which} (both horizontal components given) it cannot uplift and slides in the plane: its "
            "sliding there is the peak distance from rest under both components at once, not the larger of "
            "the one-way answers.")


def with_planar_peaks(cases: pd.DataFrame, planar: pd.DataFrame) -> pd.DataFrame:
    """``cases`` with ``planar_sliding_cm``: the 2-D peak distance from rest of its item under its motion
    (both directions' rows; NaN where the item did not slide in the plane under it)."""
    keys = ["id", "motion_key", "mu_node"]
    node = cases["mu_node"] if "mu_node" in cases else pd.Series(0, index=cases.index)
    if planar is None or planar.empty:
        return cases.assign(planar_sliding_cm=np.nan)
    peaks = planar[planar["realization"] == 0][keys + ["sliding_cm"]]
    found = cases.assign(mu_node=node)[keys].merge(peaks, on=keys, how="left")["sliding_cm"]
    return cases.assign(planar_sliding_cm=found.to_numpy(dtype=float))


def method_text(summary: pd.DataFrame) -> str:
    """The report's method paragraph on sliding in the plane ("" when no item's demand used it)."""
    if "demand_planar" not in summary:
        return ""
    planar = summary["demand_planar"].eq(True)
    if not planar.any():
        return ""
    ids = summary.loc[planar, "id"].astype(str).tolist()
    return (f"Where a motion gives both horizontal components (record and record_2), an item that cannot uplift "
            f"(mu_s < b/h in both directions) slides on the floor under both at once, friction mu m g opposing "
            f"its velocity (isotropic Coulomb friction); its sliding under that motion is the largest distance "
            f"from where it stood, compared with its clearance, in place of the larger of the two one-way "
            f"answers (each direction under its component alone, still listed per direction in motions.csv). "
            f"This applies to {len(ids)} item{'s' if len(ids) != 1 else ''} ({', '.join(ids)}). Items that "
            f"can uplift run each direction under its own component.")
