"""Which mode a block at rest enters when the floor accelerates.

With :math:`A` = PTA/g and :math:`t = b/h`, a block at rest on a floor with
friction coefficient μ ([1], section 3; [2]):

* stays at rest while :math:`A \\le \\mu` and :math:`A \\le t`;
* slides when :math:`\\mu < t` and :math:`A > \\mu` (friction gives way before
  the overturning moment can lift the heel);
* rocks when :math:`\\mu \\ge t` and :math:`A > t`, provided friction can hold
  the pivot; otherwise it slides and rocks at once (slide-rock). The friction
  needed at the pivot at the onset of rocking, from the block's equations of
  motion about the corner with :math:`\\kappa = I_O/(mR^2)`, is

  .. math::

      \\mu_{req}(A) = \\frac{A[\\kappa(1+t^2) - 1] + t}{\\kappa(1+t^2) + A t - t^2}

  which for a uniform block (κ = 4/3) is
  :math:`\\mu_{req} = [A(4t^2+1)+3t]/[t^2+4+3At]` ([2], eq. 14) and equals
  :math:`t` at :math:`A = t`.

References
----------
.. [1] Konstantinidis & Makris (2010), Bull. Earthquake Eng. 8:1457-1477,
   doi:10.1007/s10518-010-9192-8.
.. [2] Shenton, H. W. (1996). Criteria for initiation of slide, rock, and
   slide-rock rigid-body modes. J. Eng. Mech. 122(7):690-693,
   doi:10.1061/(ASCE)0733-9399(1996)122:7(690).
"""
from __future__ import annotations

import numpy as np

REST, SLIDE, ROCK, SLIDE_ROCK = "rest", "slide", "rock", "slide-rock"

#: Severity order used to pick the worst mode of an item over several motions.
MODE_SEVERITY = {REST: 0, SLIDE: 1, SLIDE_ROCK: 2, ROCK: 3}


def friction_required_to_rock(peak_accel_g, b_over_h, inertia_ratio_value=4.0 / 3.0):
    """Friction coefficient μ_req the pivot needs at the onset of rocking [-].

    See the module docstring for the equation. Below μ_req the block slides
    as it rocks (slide-rock).

    Examples
    --------
    At the threshold of uplift, A = t, the requirement is t itself:

    >>> round(float(friction_required_to_rock(0.3, 0.3)), 12)
    0.3
    """
    accel = np.asarray(peak_accel_g, dtype=float)
    t = np.asarray(b_over_h, dtype=float)
    kappa = np.asarray(inertia_ratio_value, dtype=float)
    numerator = accel * (kappa * (1.0 + t**2) - 1.0) + t
    denominator = kappa * (1.0 + t**2) + accel * t - t**2
    result = numerator / denominator
    return result if result.ndim else float(result)


def initial_mode(peak_accel_g, mu, b_over_h, inertia_ratio_value=4.0 / 3.0):
    """Mode entered from rest: ``"rest"``, ``"slide"``, ``"rock"`` or ``"slide-rock"``.

    Parameters
    ----------
    peak_accel_g : float or array-like
        Peak floor acceleration A [g].
    mu : float or array-like
        Friction coefficient (static, the one that holds the block at rest) [-].
    b_over_h : float or array-like
        Half base width over centre-of-mass height, t = tan α [-].
    inertia_ratio_value : float or array-like
        κ = I_O/(mR²), 4/3 for a uniform block.

    Returns
    -------
    str or ndarray of str (same shape as the broadcast inputs)

    Examples
    --------
    FORMA incubator (b/h = 0.272) with its best-fit μ = 0.13 and with the
    wooden model's μ = 0.68 under PTA = 0.54 g ([1], section 4):

    >>> initial_mode(0.54, 0.13, 0.272), initial_mode(0.54, 0.68, 0.272)
    ('slide', 'rock')
    """
    accel, friction, t, kappa = np.broadcast_arrays(
        np.asarray(peak_accel_g, dtype=float), np.asarray(mu, dtype=float),
        np.asarray(b_over_h, dtype=float), np.asarray(inertia_ratio_value, dtype=float))
    slides_first = friction < t
    required = friction_required_to_rock(accel, t, kappa)
    mode = np.where(
        slides_first,
        np.where(accel > friction, SLIDE, REST),
        np.where(accel > t, np.where(friction < required, SLIDE_ROCK, ROCK), REST),
    )
    return mode if mode.ndim else str(mode)
