"""A motion given by its two horizontal components (``record`` and ``record_2``), on the items' axes.

The hazard sheet (docs/workbook.md) may give a motion both horizontal components of one
recording: ``record`` and ``record_2``, and ``azimuth_deg``, the angle from the
items' width axis (direction 1) to the axis of the component in ``record``,
counted positive towards the items' depth axis (direction 2); the axis of
``record_2`` lies 90° further on, the same way. With ``azimuth_deg`` = 0 (the
default), ``record`` is along the items' width and ``record_2`` along their
depth. The floor acceleration along the items' axes is then

.. math::

    a_1 = r_1\\cos\\theta - r_2\\sin\\theta,\\qquad a_2 = r_1\\sin\\theta + r_2\\cos\\theta

(a rotation of the pair by θ = ``azimuth_deg``; its magnitude
:math:`\\sqrt{a_1^2 + a_2^2} = \\sqrt{r_1^2 + r_2^2}` at every instant, so the
sliding in the plane, :mod:`assess.mechanics.sliding_2d`, does not depend on
θ for an isotropic friction; the one-way answers of each base direction do).

The two components must share their time step (they are one recording): a
pair whose steps differ by more than :data:`~assess.hazard.records.DT_TOLERANCE`
is refused with the hazard row named (resampling either onto the other's
step would move the samples the model joins by straight lines). Where one
component is longer, the shorter is taken as zero after its last sample (the
floor at rest along that axis, the convention of the engines at the end of
any record), and the note says by how much.
"""
from __future__ import annotations

import numpy as np

from assess.errors import InputError, Problem
from assess.hazard.records import DT_TOLERANCE, Record


def rotate_to_item_axes(accel_1_g, accel_2_g, azimuth_deg: float):
    """The pair (``record``, ``record_2``) turned by ``azimuth_deg`` onto the items' width and depth axes [g].

    >>> a1, a2 = rotate_to_item_axes([1.0], [0.0], 90.0)  # record along the depth axis
    >>> round(float(a1[0]), 12), round(float(a2[0]), 12)
    (0.0, 1.0)
    >>> a1, a2 = rotate_to_item_axes([0.3], [0.4], 30.0)
    >>> round(float(np.hypot(a1[0], a2[0])), 12)  # the magnitude is kept
    0.5
    """
    theta = np.deg2rad(float(azimuth_deg))
    r1, r2 = np.asarray(accel_1_g, dtype=float), np.asarray(accel_2_g, dtype=float)
    return r1 * np.cos(theta) - r2 * np.sin(theta), r1 * np.sin(theta) + r2 * np.cos(theta)


def item_axes_pair(first: Record, second: Record, azimuth_deg: float, motion: str, row: int,
                   workbook_name: str) -> tuple[Record, Record, str]:
    """The motion's accelerations along the items' width and depth, and what to say of them: "" when nothing,
    else which component ends how long before the other (``STA1_H2.csv ends 26.58 s before STA1_H1.csv``), the
    shorter being taken as zero after its last sample.

    Raises :class:`~assess.errors.InputError` naming the hazard row when the two steps differ.
    """
    if abs(first.dt_s - second.dt_s) > DT_TOLERANCE * first.dt_s:
        raise InputError([Problem(
            file=workbook_name, sheet="hazard", row=int(row), column="record_2",
            message=f"the two components of motion '{motion}' have different time steps: record "
                    f"{first.dt_s:g} s, record_2 {second.dt_s:g} s; they must be one recording's two components.",
            fix="give both components of one recording (same time step), or resample one onto the "
                "other's step before naming it here.")])
    n = max(first.accel_g.size, second.accel_g.size)
    r1, r2 = np.zeros(n), np.zeros(n)
    r1[:first.accel_g.size], r2[:second.accel_g.size] = first.accel_g, second.accel_g
    note = ""
    if first.accel_g.size != second.accel_g.size:
        shorter, longer = (first, second) if first.accel_g.size < second.accel_g.size else (second, first)
        extra_s = abs(first.accel_g.size - second.accel_g.size) * first.dt_s
        note = f"{shorter.name} ends {extra_s:.2f} s before {longer.name}"
    a1, a2 = rotate_to_item_axes(r1, r2, azimuth_deg)
    turned = f", turned by {float(azimuth_deg):g} deg" if float(azimuth_deg) else ""
    return (Record(a1, first.dt_s, f"{first.name} (+ {second.name}{turned}, along width)"),
            Record(a2, first.dt_s, f"{second.name} (+ {first.name}{turned}, along depth)"), note)
