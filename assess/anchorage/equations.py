"""The horizontal design force of a nonstructural component, ASCE 7-16 and ASCE 7-22 §13.3.1, and its terms.

ASCE 7-16 [1]_ (eqs. 13.3-1 to 13.3-3):

.. math::

    F_p = \\frac{0.4\\,a_p\\,S_{DS}\\,W_p}{R_p / I_p}\\left(1 + 2\\frac{z}{h}\\right)

ASCE 7-22 [2]_ (eqs. 13.3-1 to 13.3-3 of that edition; the provisions of FEMA P-2082 [3]_, Part 1, Ch. 13):

.. math::

    F_p = 0.4\\,S_{DS}\\,I_p\\,W_p\\,\\frac{H_f}{R_\\mu}\\,\\frac{C_{AR}}{R_{po}}

with, in both editions, :math:`0.3\\,S_{DS}\\,I_p\\,W_p \\le F_p \\le 1.6\\,S_{DS}\\,I_p\\,W_p`;

.. math::

    H_f = 1 + a_1\\frac{z}{h} + a_2\\left(\\frac{z}{h}\\right)^{10},\\quad
    a_1 = \\min(1/T_a,\\ 2.5),\\quad a_2 = \\max\\left(1 - (0.4/T_a)^2,\\ 0\\right)

(eq. 13.3-4) where the building's period T_a is known, :math:`H_f = 1 + 2.5\\,z/h` (eq. 13.3-5) where it
is not; and

.. math::  R_\\mu = \\max\\left(\\sqrt{1.1\\,R / (I_e\\,\\Omega_0)},\\ 1.3\\right)

(eq. 13.3-6), 1.3 where the structure's R is not known.

Verification of the forms: the same equations, term by term, are implemented by the public FpCalc
calculator (``fpcalc.py``: ``calculate_hf``, ``calculate_rmu``, ``calculate_fp_coeff_16``,
``calculate_fp_coeff_22``) and the 7-16 form by EZAnchor (Wang et al. 2024, ``Equipment.calculate_fp``);
the 7-16 form reproduces two published worked examples to their printed precision
(``tests/data/anchorage/published_7_16.csv``).

Not confirmed from the standard's text: R_μ = 1.0 for a component supported at or below grade (z = 0).
It is how we read ASCE 7-22 §13.3.1 (the ductility of the structure does not reduce the ground's
motion) and how one public 7-22 calculator treats grade (its ``calculateRmu`` takes the height, and its
hand-worked chiller case takes R_μ = 1.0 at grade, ``tests/data/anchorage/published_7_22.csv``); it is
a keyword (``at_or_below_grade_unreduced``) so the lead can switch it off if the text says otherwise.

References
----------
.. [1] ASCE/SEI 7-16 (2017). Minimum Design Loads and Associated Criteria for Buildings and Other
   Structures. §13.1.3, §13.3.1, §13.4.2, Tables 13.5-1, 13.6-1; §2.3.6, §12.4.2.2.
.. [2] ASCE/SEI 7-22 (2022). Same title. §13.1.3, §13.3.1, §13.4.2, Tables 13.5-1, 13.6-1.
.. [3] FEMA P-2082-1 (2020). NEHRP Recommended Seismic Provisions for New Buildings and Other
   Structures, Volume I, Part 1, Chapter 13 (the basis of ASCE 7-22 Chapter 13).
"""
from __future__ import annotations

import numpy as np

#: Consequences (the workbook's ``consequence``) that make I_p = 1.5 in any building (§13.1.3 items 1, 2:
#: needed for life safety after an earthquake; hazardous contents).
LIFE_SAFETY_OR_HAZARDOUS = ("life-safety", "hazardous")
#: Consequences that make I_p = 1.5 in a Risk Category IV structure (§13.1.3 item 3: needed for the
#: continued operation of the facility, or its failure could impair it).
NEEDED_FOR_OPERATION = ("critical",)
#: Lower bound of R_μ (ASCE 7-22 eq. 13.3-6) and its value where the structure's R is not known.
MINIMUM_DUCTILITY_REDUCTION = 1.3
#: Upper bound of a_1 in H_f (ASCE 7-22 eq. 13.3-4) and the slope of H_f where T_a is not known (eq. 13.3-5).
MAXIMUM_HEIGHT_SLOPE = 2.5


def component_importance_factor(consequence="ordinary", risk_category=None, ip=None) -> float:
    """I_p of ASCE 7-16 / 7-22 §13.1.3: 1.5 or 1.0.

    1.5 for a component needed for life safety after an earthquake or holding hazardous contents
    (``consequence`` ``life-safety`` or ``hazardous``), and, in a Risk Category IV structure, for one
    needed for the continued operation of the facility (``critical``); 1.0 otherwise. A given ``ip``
    overrides and must be 1.0 or 1.5 (the only values §13.1.3 assigns); None, NaN or a blank string (an
    empty workbook cell) does not.

    >>> component_importance_factor("critical", "IV"), component_importance_factor("critical", "II")
    (1.5, 1.0)
    >>> component_importance_factor("hazardous"), component_importance_factor("ordinary", "IV", ip=1.5)
    (1.5, 1.5)
    """
    blank = ip is None or (isinstance(ip, float) and np.isnan(ip)) or (isinstance(ip, str) and not ip.strip())
    if not blank:
        value = float(ip)
        if value not in (1.0, 1.5):
            raise ValueError(f"ip {ip!r}: ASCE 7 §13.1.3 assigns I_p = 1.0 or 1.5 only")
        return value
    text = str(consequence).strip().lower()
    if text in LIFE_SAFETY_OR_HAZARDOUS:
        return 1.5
    if text in NEEDED_FOR_OPERATION and str(risk_category).strip().upper() == "IV":
        return 1.5
    return 1.0


def force_bounds(weight_n, sds_g, importance):
    """(minimum, maximum) of F_p [N]: 0.3 S_DS I_p W_p and 1.6 S_DS I_p W_p (7-16 eqs. 13.3-2, 13.3-3;
    7-22 eqs. 13.3-2, 13.3-3).

    >>> [round(float(x)) for x in force_bounds(1000.0, 1.0, 1.5)]
    [450, 2400]
    """
    weight_n = np.asarray(weight_n, dtype=float)
    return 0.3 * sds_g * importance * weight_n, 1.6 * sds_g * importance * weight_n


def force_asce7_16(weight_n, sds_g, z_over_h, importance, amplification, response_modification):
    """F_p of ASCE 7-16 eq. 13.3-1 [N], before its bounds.

    Parameters: W_p [N], S_DS [g], z/h [-] (clipped to 0..1), I_p, a_p, R_p.

    >>> round(float(force_asce7_16(2000.0, 1.0, 0.5, 1.0, 1.0, 2.5)))  # 0.4·2000/2.5·2
    640
    """
    z_over_h = np.clip(np.asarray(z_over_h, dtype=float), 0.0, 1.0)
    return (0.4 * amplification * sds_g * np.asarray(weight_n, dtype=float) / (response_modification / importance)
            * (1.0 + 2.0 * z_over_h))


def height_factor(z_over_h, period_s=None):
    """H_f of ASCE 7-22 eqs. 13.3-4 (T_a known) and 13.3-5 (not known) [-].

    >>> round(float(height_factor(1.0, 0.5)), 4), round(float(height_factor(0.75)), 4)
    (3.36, 2.875)
    """
    z_over_h = np.clip(np.asarray(z_over_h, dtype=float), 0.0, 1.0)
    if period_s is None or not np.isfinite(period_s) or period_s <= 0.0:
        return 1.0 + MAXIMUM_HEIGHT_SLOPE * z_over_h
    a1 = min(1.0 / period_s, MAXIMUM_HEIGHT_SLOPE)
    a2 = max(1.0 - (0.4 / period_s) ** 2, 0.0)
    return 1.0 + a1 * z_over_h + a2 * z_over_h ** 10


def ductility_reduction(building_r=None, building_ie=1.0, building_omega0=None):
    """R_μ of ASCE 7-22 eq. 13.3-6 [-]: sqrt(1.1 R / (I_e Ω0)), not less than 1.3; 1.3 without R or Ω0.

    >>> round(ductility_reduction(8.0, 1.5, 3.0), 4), ductility_reduction()
    (1.3984, 1.3)
    """
    if building_r is None or building_omega0 is None or not building_r > 0.0 or not building_omega0 > 0.0:
        return MINIMUM_DUCTILITY_REDUCTION
    return max(float(np.sqrt(1.1 * building_r / (building_ie * building_omega0))), MINIMUM_DUCTILITY_REDUCTION)


def force_asce7_22(weight_n, sds_g, importance, height, ductility, resonance, strength):
    """F_p of ASCE 7-22 eq. 13.3-1 [N], before its bounds: 0.4 S_DS I_p W_p (H_f/R_μ)(C_AR/R_po).

    >>> round(float(force_asce7_22(1000.0, 1.0, 1.0, 3.5, 1.3, 2.2, 1.3)), 1)  # 400·(3.5/1.3)·(2.2/1.3)
    1822.5
    """
    return 0.4 * sds_g * importance * np.asarray(weight_n, dtype=float) * (height / ductility) * (resonance / strength)


def govern(force_n, minimum_n, maximum_n):
    """F_p within its bounds [N] and which governs: ``'equation'``, ``'minimum'`` or ``'maximum'`` (scalars).

    >>> govern(500.0, 600.0, 3200.0)
    (600.0, 'minimum')
    """
    force_n, minimum_n, maximum_n = float(force_n), float(minimum_n), float(maximum_n)
    if force_n < minimum_n:
        return minimum_n, "minimum"
    if force_n > maximum_n:
        return maximum_n, "maximum"
    return force_n, "equation"


def base_tension(horizontal_n, cg_height_m, weight_n, half_width_m, sds_g):
    """Overturning moment [N·m] of a horizontal force about the base edge and the anchors' tension [N].

    Strength combination 7 of §2.3.6 (0.9D − 1.0E, E_v = 0.2 S_DS D, §12.4.2.2):
    T = max(0, (F h_cg − (0.9 − 0.2 S_DS) W_p b) / (2b)), 2b the base dimension, for one edition or the
    other (the combination is the same in 7-16 and 7-22).

    >>> [round(float(x)) for x in base_tension(1413.0, 0.9, 2943.0, 0.3, 1.0)]
    [1272, 1089]
    """
    moment = np.asarray(horizontal_n, dtype=float) * np.asarray(cg_height_m, dtype=float)
    resisting = (0.9 - 0.2 * sds_g) * np.asarray(weight_n, dtype=float) * np.asarray(half_width_m, dtype=float)
    tension = np.maximum(0.0, (moment - resisting) / (2.0 * np.asarray(half_width_m, dtype=float)))
    return moment, tension
