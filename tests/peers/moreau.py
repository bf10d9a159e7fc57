"""Two-way Coulomb sliding by Moreau's implicit step: the reference the 2-D sliding checks take (tests only).

Written here, sharing nothing with ``assess.mechanics.sliding_2d`` but the gravity constant; used by
tests/verification/test_sliding_2d.py and tests/fragility/test_friction_range.py. It lives in the peers'
package so that both import it by one name: its compiled cache records the module it was compiled in.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2 as G


@njit(cache=True)
def moreau_reference(ax_g, ay_g, dt, mu, substeps):
    """Peak |u| and residual (x, y) [m] by Moreau's implicit step of Coulomb friction.

    On each substep h the velocity without friction is ``w = v - g a h`` (a at the
    substep's midpoint); friction removes at most μ g h from it, opposite to it:
    ``v' = 0`` if ``|w| ≤ μ g h``, else ``w (1 - μ g h/|w|)`` (the exact projection onto
    the friction cone of an implicit Euler step; first order in h, no event location).
    The floor is at rest after the record and a sliding block is stepped on until it stops.
    """
    h = dt / substeps
    ux = uy = vx = vy = peak2 = 0.0
    n = ax_g.shape[0]
    k = 0
    while True:
        for j in range(substeps):
            if k < n - 1:
                frac = (j + 0.5) / substeps
                ax = ax_g[k] + (ax_g[k + 1] - ax_g[k]) * frac
                ay = ay_g[k] + (ay_g[k + 1] - ay_g[k]) * frac
            else:
                ax = ay = 0.0
            wx = vx - G * ax * h
            wy = vy - G * ay * h
            w = np.sqrt(wx * wx + wy * wy)
            if w <= mu * G * h:
                nx = ny = 0.0
            else:
                nx = wx * (1.0 - mu * G * h / w)
                ny = wy * (1.0 - mu * G * h / w)
            ux += 0.5 * (vx + nx) * h
            uy += 0.5 * (vy + ny) * h
            vx, vy = nx, ny
            peak2 = max(peak2, ux * ux + uy * uy)
        k += 1
        if k >= n - 1 and vx == 0.0 and vy == 0.0:
            break
    return np.sqrt(peak2), ux, uy
