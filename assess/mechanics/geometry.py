"""Geometry of a rigid rectangular block standing on its base.

A block of height 2h_full and base width 2b rocks about a base corner. With
its centre of mass at height h above the base (h = h_full/2 for a uniform
block):

.. math::

    \\alpha = \\arctan(b/h), \\qquad R = \\sqrt{b^2 + h^2}, \\qquad
    p = \\sqrt{\\frac{m g R}{I_O}}

where :math:`I_O` is the moment of inertia about the pivot. For a uniform block
:math:`I_O = \\tfrac{4}{3} m R^2` and :math:`p = \\sqrt{3g/(4R)}`.

References
----------
.. [1] Konstantinidis, D., Makris, N. (2010). Experimental and analytical
   studies on the response of 1/4-scale models of freestanding laboratory
   equipment subjected to strong earthquake shaking. Bull. Earthquake Eng.
   8:1457-1477, Table 1 and Fig. 6. doi:10.1007/s10518-010-9192-8
.. [2] Housner, G. W. (1963). The behavior of inverted pendulum structures
   during earthquakes. Bull. Seismol. Soc. Am. 53(2):403-417.
"""
from __future__ import annotations

import numpy as np

#: Standard gravity [m/s²] (CGPM 1901), used wherever an acceleration in g is converted.
STANDARD_GRAVITY_M_S2 = 9.80665


def slenderness(half_width_m, cg_height_m):
    """Slenderness angle α [rad] of a block rocking about a base corner.

    .. math:: \\alpha = \\arctan(b / h)

    Parameters
    ----------
    half_width_m : float or array-like
        Half the base dimension in the direction of motion, b [m].
    cg_height_m : float or array-like
        Height of the centre of mass above the base, h [m].

    Returns
    -------
    alpha_rad : float or ndarray [rad]

    Examples
    --------
    FORMA incubator, Table 1 of [1]: 2h = 228.6 cm, 2b = 62.2 cm.

    >>> round(float(slenderness(0.311, 1.143)), 3)
    0.266
    """
    return np.arctan2(half_width_m, cg_height_m)


def size(half_width_m, cg_height_m):
    """Distance R [m] from a base corner to the centre of mass, :math:`\\sqrt{b^2+h^2}`.

    >>> round(float(size(0.3, 0.4)), 6)
    0.5
    """
    return np.hypot(half_width_m, cg_height_m)


def inertia_ratio(half_width_m, cg_height_m, height_m):
    """:math:`\\kappa = I_O / (m R^2)` of a block about a base corner [-].

    The mass is taken as spread over the full box (width 2b, height H) as in a
    uniform block, so the moment of inertia about the centre of mass is
    :math:`I_{cm} = m(4b^2 + H^2)/12` wherever the centre of mass is; then
    :math:`I_O = I_{cm} + m R^2` (parallel axes). For a uniform block
    (h = H/2) this gives exactly 4/3. Where the workbook gives a centre of mass
    below mid-height (heavy compressor at the bottom), this is an assumption:
    the true I_cm of such an item is not known from its dimensions.

    >>> round(float(inertia_ratio(0.3, 1.0, 2.0)), 12)
    1.333333333333
    """
    half_width_m = np.asarray(half_width_m, dtype=float)
    cg_height_m = np.asarray(cg_height_m, dtype=float)
    height_m = np.asarray(height_m, dtype=float)
    radius_sq = half_width_m**2 + cg_height_m**2
    inertia_cm_over_m = (4.0 * half_width_m**2 + height_m**2) / 12.0
    result = (inertia_cm_over_m + radius_sq) / radius_sq
    return result if result.ndim else float(result)


def frequency_parameter(half_width_m, cg_height_m, height_m=None):
    """Frequency parameter p [rad/s] of a rocking block.

    .. math:: p = \\sqrt{\\frac{m g R}{I_O}} = \\sqrt{\\frac{g}{\\kappa R}}

    For a uniform block (``height_m`` None or equal to ``2 * cg_height_m``)
    :math:`\\kappa = 4/3` and :math:`p = \\sqrt{3g/(4R)}` ([1], Fig. 6; [2]).

    Parameters
    ----------
    half_width_m, cg_height_m : float or array-like
        b and h [m].
    height_m : float or array-like, optional
        Overall height [m]; defaults to ``2 * cg_height_m`` (uniform block).

    Examples
    --------
    FORMA incubator prototype, Table 1 of [1] prints p = 2.49 rad/s:

    >>> round(float(frequency_parameter(0.311, 1.143)), 2)
    2.49
    """
    if height_m is None:
        height_m = 2.0 * np.asarray(cg_height_m, dtype=float)
    kappa = inertia_ratio(half_width_m, cg_height_m, height_m)
    return np.sqrt(STANDARD_GRAVITY_M_S2 / (kappa * size(half_width_m, cg_height_m)))


def housner_restitution(alpha_rad, inertia_ratio_value=4.0 / 3.0):
    """Housner's coefficient of restitution of angular velocity at impact [-].

    Conservation of angular momentum about the new pivot ([2], eq. 11):

    .. math:: e = 1 - \\frac{2}{\\kappa} \\sin^2\\alpha

    with :math:`\\kappa = I_O/(mR^2)`; for a uniform block
    :math:`e = 1 - 1.5 \\sin^2\\alpha`.

    >>> round(float(housner_restitution(0.16)), 4)
    0.9619
    """
    return 1.0 - (2.0 / np.asarray(inertia_ratio_value, dtype=float)) * np.sin(alpha_rad) ** 2
