"""The floors table: the modes used and each floor's peak acceleration over the suite (``floors.csv``).

Its check columns beside PFA/PGA, the code's floor acceleration (ASCE 7-22 §13.3.1's H_f, and H_f/R_μ
for a building that yields), are added where the code's provisions live
(:func:`assess.assessment.floors.with_code_check`).
"""
from __future__ import annotations

from typing import Mapping, Sequence

import numpy as np
import pandas as pd

from assess.hazard.records import Record

from .modes import BuildingModes

#: Modes whose period and Γφ the table shows in columns of their own (all are used).
MODES_SHOWN = 3


def floors_table(modes: BuildingModes, floors: Mapping[int, Sequence[Record]], level: str = "") -> pd.DataFrame:
    """One row per floor: the modes used and the peak floor acceleration over the level's suite.

    Parameters
    ----------
    modes : BuildingModes
        The modes the floor histories were computed with.
    floors : mapping of int to sequence of Record
        ``floors[k][m]``: floor k under ground motion m (:func:`~assess.building.response.floor_records`);
        it must hold floor 0 (the ground motions, for PGA); the table has a row per floor it holds.
    level : str
        The hazard level the suite belongs to.

    Returns
    -------
    DataFrame
        Columns ``level, floor, height_m, z_over_h``; the building's ``period_1_s`` ..
        ``period_3_s``, ``modes_used``, ``mass_used`` (share of the mass in the modes used),
        ``alpha``, ``damping``, ``period_source``, ``storey_stiffness`` (the storey below the floor's
        stiffness over the first storey's, empty at the ground); the floor's ``gamma_phi_1`` .. ``gamma_phi_3``
        (Γ_j φ_j at the floor); over the suite, ``motions``, ``pfa_median_g``, ``pfa_min_g``,
        ``pfa_max_g``, ``pfa_over_pga_median``, ``pfa_over_pga_min``, ``pfa_over_pga_max``
        (each motion's PFA over its own PGA) and ``pfa_over_pga_mean``.
    """
    heights = modes.floor_heights_m
    if 0 not in floors or any(not 0 <= int(k) < heights.size for k in floors):
        raise ValueError("floors must hold the ground (floor 0) and floors of the building only")
    pga = np.array([record.pta_g for record in floors[0]])
    contributions = modes.floor_participation()
    rows = []
    for k, suite in sorted(floors.items()):
        pfa = np.array([record.pta_g for record in suite])
        ratio = pfa / pga
        row = {"level": level, "floor": k, "height_m": heights[k], "z_over_h": heights[k] / heights[-1]}
        for j in range(MODES_SHOWN):
            row[f"period_{j + 1}_s"] = modes.periods_s[j] if j < modes.n_modes else np.nan
        row.update(modes_used=modes.n_modes, mass_used=float(modes.effective_mass_ratio.sum()),
                   alpha=modes.alpha, damping=float(modes.damping[0]), period_source=modes.period_source,
                   storey_stiffness=float(modes.storey_stiffness[k - 1]) if k > 0 else np.nan)
        for j in range(MODES_SHOWN):
            row[f"gamma_phi_{j + 1}"] = contributions[k, j] if j < modes.n_modes else np.nan
        row.update(motions=pfa.size, pfa_median_g=float(np.median(pfa)), pfa_min_g=float(pfa.min()),
                   pfa_max_g=float(pfa.max()), pfa_over_pga_median=float(np.median(ratio)),
                   pfa_over_pga_min=float(ratio.min()), pfa_over_pga_max=float(ratio.max()),
                   pfa_over_pga_mean=float(ratio.mean()))
        rows.append(row)
    return pd.DataFrame(rows)
