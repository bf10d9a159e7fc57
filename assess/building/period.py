"""The building's approximate fundamental period from its height and lateral system (ASCE 7 §12.8.2.1).

.. math::  T_a = C_t\\,h_n^{\\,x}

with h_n the structural height and C_t, x from Table 12.8-2 of ASCE 7-16 [1]_
and ASCE 7-22 [2]_ (the two editions print the same table). The table gives
C_t for h_n in feet and, in parentheses, for h_n in metres; this module uses
the metre values, :data:`PERIOD_COEFFICIENTS`. The four rows of the table are

=================================================  ==========  =============  ======
structure type                                      C_t (ft)    C_t (m)        x
=================================================  ==========  =============  ======
steel moment-resisting frames                       0.028       0.0724         0.8
concrete moment-resisting frames                    0.016       0.0466         0.9
steel eccentrically braced frames (and BRBF)        0.03        0.0731         0.75
all other structural systems                        0.02        0.0488         0.75
=================================================  ==========  =============  ======

A concentrically braced frame, a shear wall and any other system are "all other
structural systems": that is the code's own rule for them, not a choice made
here. (For masonry or concrete shear walls §12.8.2.1 also permits
T_a = 0.0019 h_n / √C_w (ft), which needs the walls' areas and lengths; and for
moment frames of at most 12 storeys, each at least 3 m high, T_a = 0.1 N. Neither
is used here.)

T_a is the code's estimate for sizing the base shear, a deliberately short
period (measured periods of real buildings are mostly longer, which is why
§12.8.2 caps an analysis period at C_u T_a). Where the building's period is known,
from its structural engineer's model or from measurements, it should be given
instead.

References
----------
.. [1] ASCE/SEI 7-16 (2017). Minimum Design Loads and Associated Criteria for
   Buildings and Other Structures. §12.8.2.1, Eq. 12.8-7, Table 12.8-2.
.. [2] ASCE/SEI 7-22 (2022). Minimum Design Loads and Associated Criteria for
   Buildings and Other Structures. §12.8.2.1, Eq. 12.8-7, Table 12.8-2.
"""
from __future__ import annotations

import numpy as np

#: The lateral systems a ``building`` sheet may name (``system``).
SYSTEMS = ("steel moment frame", "concrete moment frame", "eccentrically braced frame",
           "braced frame", "shear wall", "other")

#: (C_t [s/m^x], x) of ASCE 7-16/7-22 Table 12.8-2, metre values, per system. A concentrically
#: braced frame, a shear wall and "other" fall under the table's "all other structural systems".
PERIOD_COEFFICIENTS = {
    "steel moment frame": (0.0724, 0.8),
    "concrete moment frame": (0.0466, 0.9),
    "eccentrically braced frame": (0.0731, 0.75),
    "braced frame": (0.0488, 0.75),
    "shear wall": (0.0488, 0.75),
    "other": (0.0488, 0.75),
}

#: The same table's C_t for h_n in feet (the x are those above), kept to check the metre values.
PERIOD_COEFFICIENTS_FT = {
    "steel moment frame": 0.028,
    "concrete moment frame": 0.016,
    "eccentrically braced frame": 0.03,
    "braced frame": 0.02,
    "shear wall": 0.02,
    "other": 0.02,
}


def approximate_period(height_m, system="other"):
    """Approximate fundamental period T_a [s] of ASCE 7-16/7-22 Eq. 12.8-7.

    .. math::  T_a = C_t\\,h_n^{\\,x}

    Parameters
    ----------
    height_m : float or array-like
        Structural height h_n [m]: from the base to the roof.
    system : str
        One of :data:`SYSTEMS`; sets C_t and x (Table 12.8-2, metre values).

    Returns
    -------
    float or ndarray
        T_a [s], of the shape of ``height_m``.

    References
    ----------
    ASCE/SEI 7-22 (2022), §12.8.2.1, Eq. 12.8-7, Table 12.8-2 (same in ASCE/SEI 7-16).

    Examples
    --------
    A 6-storey steel moment frame 22 m high: 0.0724 × 22^0.8 = 0.0724 × 11.856 = 0.858 s
    (in feet: 0.028 × 72.18^0.8 = 0.028 × 30.66 = 0.858 s):

    >>> round(float(approximate_period(22.0, "steel moment frame")), 3)
    0.858
    >>> round(float(approximate_period(22.0, "shear wall")), 3)   # 0.0488 × 22^0.75 = 0.0488 × 10.158
    0.496
    """
    if system not in PERIOD_COEFFICIENTS:
        raise ValueError(f"system must be one of {', '.join(SYSTEMS)}, not {system!r}")
    height = np.asarray(height_m, dtype=float)
    if np.any(~np.isfinite(height)) or np.any(height <= 0.0):
        raise ValueError("height_m must be positive")
    coefficient, exponent = PERIOD_COEFFICIENTS[system]
    period = coefficient * height ** exponent
    return float(period) if period.ndim == 0 else period
