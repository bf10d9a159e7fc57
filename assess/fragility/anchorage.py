"""The force an engineer sizes an item's anchorage for: ASCE 7-16 §13.3.1, and what it does at the base.

For an item to anchor or restrain, the horizontal design force at its centre
of mass (ASCE 7-16 [1]_, eqs. 13.3-1 to 13.3-3):

.. math::

    F_p = \\frac{0.4\\,a_p\\,S_{DS}\\,W_p}{R_p / I_p}\\left(1 + 2\\frac{z}{h}\\right), \\qquad
    0.3\\,S_{DS}\\,I_p\\,W_p \\le F_p \\le 1.6\\,S_{DS}\\,I_p\\,W_p

with the component factors of Table 13.5-1 for laboratory equipment and
floor-supported storage cabinets (a_p = 1.0, R_p = 2.5,
:data:`COMPONENT_AMPLIFICATION`, :data:`COMPONENT_RESPONSE_MODIFICATION`),
I_p = 1.5 for a component that holds hazardous contents or is needed for life
safety and 1.0 otherwise (§13.1.3, :func:`importance_factor`), and z/h the
height of its floor over the building's (the roof at z/h = 1).

At the base, about the edge it would tip over, F_p at the centre-of-mass
height h_cg overturns it and its weight, reduced by the vertical earthquake
effect, holds it (strength load combination 7 of §2.3.6 with
E_v = 0.2 S_DS D, §12.4.2.2): the tension the anchors on the far side carry is

.. math::  T = \\max\\left(0,\\ \\frac{F_p\\,h_{cg} - (0.9 - 0.2\\,S_{DS})\\,W_p\\,b}{2b}\\right)

with 2b the base dimension in the direction considered, and the shear is F_p.
Anchors in concrete are designed with the overstrength factor Ω0 (§13.4.2),
which these functions do not apply: the engineer sizing them does.

Both editions (ASCE 7-16 and 7-22), component types, I_p from the Risk Category, Ω0 and US units are in
:mod:`assess.anchorage` (:func:`assess.anchorage.design_force`), which gives these functions' numbers for
the ASCE 7-16 laboratory-equipment case.

References
----------
.. [1] ASCE/SEI 7-16 (2017). Minimum Design Loads and Associated Criteria for
   Buildings and Other Structures. American Society of Civil Engineers.
   §2.3.6, §12.4.2.2, §13.1.3, §13.3.1 (eqs. 13.3-1 to 13.3-3), Table 13.5-1.
"""
from __future__ import annotations

import numpy as np

from assess.anchorage.equations import base_tension

#: a_p of ASCE 7-16 Table 13.5-1, laboratory equipment and floor-supported storage cabinets.
COMPONENT_AMPLIFICATION = 1.0
#: R_p of the same rows.
COMPONENT_RESPONSE_MODIFICATION = 2.5
#: Consequences (the workbook's ``consequence``) that make I_p = 1.5 (§13.1.3).
IMPORTANT_CONSEQUENCES = ("life-safety", "hazardous")


def importance_factor(consequence) -> float:
    """I_p of ASCE 7-16 §13.1.3: 1.5 for life-safety or hazardous contents, else 1.0.

    >>> importance_factor("hazardous"), importance_factor("ordinary")
    (1.5, 1.0)
    """
    return 1.5 if str(consequence).strip().lower() in IMPORTANT_CONSEQUENCES else 1.0


def component_design_force(weight_n, sds_g, z_over_h, importance=1.0, amplification=COMPONENT_AMPLIFICATION,
                           response_modification=COMPONENT_RESPONSE_MODIFICATION):
    """Horizontal seismic design force F_p [N] of ASCE 7-16 eqs. 13.3-1 to 13.3-3.

    Parameters
    ----------
    weight_n : float or array
        Operating weight W_p [N].
    sds_g : float
        Design spectral acceleration at short periods S_DS [g].
    z_over_h : float or array
        Height of the item's floor over the building's height [-], 0 at grade, 1 at the roof.
    importance, amplification, response_modification : float
        I_p, a_p, R_p.

    Examples
    --------
    A 300 kg freezer on the roof, S_DS = 1.0 g, I_p = 1.0: 0.4·1·1·2942/2.5·3 = 1412 N,
    between 0.3·2942 = 883 N and 1.6·2942 = 4707 N:

    >>> round(float(component_design_force(300 * 9.80665, 1.0, 1.0)))
    1412
    >>> round(float(component_design_force(300 * 9.80665, 1.0, 0.0)))  # at grade: 471 N < 883 N
    883
    """
    weight_n, z_over_h = np.asarray(weight_n, dtype=float), np.clip(np.asarray(z_over_h, dtype=float), 0.0, 1.0)
    force = 0.4 * amplification * sds_g * weight_n / (response_modification / importance) * (1.0 + 2.0 * z_over_h)
    return np.clip(force, 0.3 * sds_g * importance * weight_n, 1.6 * sds_g * importance * weight_n)


def base_overturning(force_n, cg_height_m, weight_n, half_width_m, sds_g):
    """Overturning moment [N·m] of F_p about the base edge and the anchors' tension [N] on the far side.

    See the module docstring for the equation (strength combination 7 of
    ASCE 7-16 §2.3.6, E_v = 0.2 S_DS D).

    Examples
    --------
    F_p = 1413 N at h_cg = 0.9 m, W_p = 2943 N, base 0.6 m (b = 0.3 m), S_DS = 1.0 g:
    M = 1271.7 N·m, resisting (0.9 − 0.2)·2943·0.3 = 618.0 N·m, T = (1271.7 − 618.0)/0.6 = 1089 N:

    >>> [round(float(x)) for x in base_overturning(1413.0, 0.9, 2943.0, 0.3, 1.0)]
    [1272, 1089]
    """
    return base_tension(force_n, cg_height_m, weight_n, half_width_m, sds_g)
