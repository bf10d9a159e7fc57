"""The floors table: the modes used and each floor's peak acceleration over the suite (``floors.csv``).

Beside the measured PFA/PGA each row shows the code's height factor H_f of ASCE 7-22
§13.3.1.1 [1]_ for the building's T_1, as a sanity check (not a target: H_f is a
design envelope fitted to instrumented buildings' records, the floors here are
an elastic model's answer to this suite):

.. math::  H_f = 1 + a_1\\frac{z}{h} + a_2\\left(\\frac{z}{h}\\right)^{10},\\qquad
           a_1 = \\frac{1}{T_a} \\le 2.5,\\qquad a_2 = 1 - \\left(\\frac{0.4}{T_a}\\right)^2 \\ge 0

References
----------
.. [1] ASCE/SEI 7-22 (2022). Minimum Design Loads and Associated Criteria for
   Buildings and Other Structures. §13.3.1.1, Eqs. 13.3-4 and 13.3-5.
"""
from __future__ import annotations

from typing import Mapping, Sequence

import numpy as np
import pandas as pd

from assess.hazard.records import Record

from .modes import BuildingModes

#: Modes whose period and Γφ the table shows in columns of their own (all are used).
MODES_SHOWN = 3


def height_factor(height_ratio, period_s=None):
    """ASCE 7-22 floor amplification H_f (Eq. 13.3-4; Eq. 13.3-5 without a period) [-].

    Parameters
    ----------
    height_ratio : float or array-like
        z/h, the floor's height over the roof's (0 at the ground, 1 at the roof).
    period_s : float, optional
        T_a [s], the building's fundamental period (§13.3.1.1 takes the approximate
        period of §12.8.2.1); without it H_f = 1 + 2.5 z/h (Eq. 13.3-5).

    Examples
    --------
    T_a = 1.0 s at the roof: a1 = 1, a2 = 1 - 0.16 = 0.84, H_f = 2.84; T_a = 0.35 s:
    a1 = 2.5 (2.857 capped), a2 = 0 (negative), H_f = 3.5:

    >>> float(height_factor(1.0, 1.0)), float(height_factor(1.0, 0.35)), float(height_factor(0.5))
    (2.84, 3.5, 2.25)
    """
    ratio = np.asarray(height_ratio, dtype=float)
    if period_s is None:
        return 1.0 + 2.5 * ratio
    a1 = min(1.0 / float(period_s), 2.5)
    a2 = max(1.0 - (0.4 / float(period_s)) ** 2, 0.0)
    return 1.0 + a1 * ratio + a2 * ratio ** 10


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
        (each motion's PFA over its own PGA), ``pfa_over_pga_mean``; and ``hf_asce7_22``,
        the code's H_f at the floor for T_1.
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
                   pfa_over_pga_mean=float(ratio.mean()),
                   hf_asce7_22=float(height_factor(heights[k] / heights[-1], modes.periods_s[0])))
        rows.append(row)
    return pd.DataFrame(rows)
