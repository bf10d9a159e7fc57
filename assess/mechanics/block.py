"""The rigid block on a moving floor: the model every general solver integrates.

A rectangular block of base width 2b and height H, with its centre of mass
(CM) on the vertical axis of symmetry at height h above the base, stands on a
rigid floor that moves horizontally with acceleration :math:`a_g(t)\\,g`. The
block touches the floor, if at all, with its two base corners. Each corner
takes a normal force N ≥ 0 (unilateral contact) and a friction force F with
Coulomb's law: :math:`|F| \\le \\mu_s N` while the corner sticks,
:math:`F = -\\mu N\\,\\mathrm{sign}(v_t)` while it slips with tangential
velocity :math:`v_t`. An impact (a corner arriving on the floor) is perfectly
inelastic at that corner in the normal direction, with Coulomb friction on the
impulse; for a corner that does not slip this is Housner's impact, whose
angular velocity ratio is :math:`e = 1 - (2/\\kappa)\\sin^2\\alpha`
(:func:`assess.mechanics.geometry.housner_restitution`; [1], [2]).

**Coordinates** (floor frame, which is non-inertial: the body feels the
force :math:`-m a_g g` along x):

* x [m]: horizontal displacement of the CM from where it stands at rest;
* y [m]: height of the CM above the floor (h at rest);
* θ [rad]: rotation, **positive when the top moves towards +x** (the block
  then pivots on its +x corner). A body point (ξ, η) relative to the CM
  (ξ along the base towards +x, η upwards) is at

  .. math:: X = x + \\xi\\cos\\theta + \\eta\\sin\\theta, \\qquad
            Y = y - \\xi\\sin\\theta + \\eta\\cos\\theta

  so the corners are at ξ = ±b, η = −h.

The equations of motion are

.. math::

    m\\ddot x = -m a_g g + \\sum F_c, \\qquad
    m\\ddot y = -m g + \\sum N_c, \\qquad
    I_{cm}\\ddot\\theta = -\\sum (r_{x,c} N_c - r_{y,c} F_c)

with :math:`(r_{x,c}, r_{y,c})` the corner's offset from the CM and
:math:`I_{cm} = m(4b^2 + H^2)/12` (:func:`assess.mechanics.geometry.inertia_ratio`).
The sign conventions are those of the specialised kernels: a positive floor
acceleration drives negative sliding (:mod:`assess.mechanics.sliding`) and a
negative rotation (:mod:`assess.mechanics.rocking`).

**Sliding** u [m] is the horizontal displacement of the lower base corner
(the pivot; the base itself when θ = 0) from where it stood at rest:

.. math:: u = x - h\\sin\\theta - b\\,\\mathrm{sgn}(\\theta)(1 - \\cos\\theta)

It is continuous through θ = 0, zero throughout pure rocking, equal to x in
pure sliding, and it grows only by slip while that corner is on the floor.

**Modes** (:data:`MODES`): ``rest`` (both corners on the floor, sticking),
``slide`` (both on the floor, slipping), ``rock`` (one corner, sticking),
``slide-rock`` (one corner, slipping), ``flight`` (no contact).

References
----------
.. [1] Housner, G. W. (1963). The behavior of inverted pendulum structures
   during earthquakes. Bull. Seismol. Soc. Am. 53(2):403-417.
.. [2] Shenton, H. W., Jones, N. P. (1991). Base excitation of rigid bodies.
   I: Formulation. J. Eng. Mech. 117(10):2286-2306.
   doi:10.1061/(ASCE)0733-9399(1991)117:10(2286)
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from .geometry import (frequency_parameter, housner_restitution, inertia_ratio, size,
                       slenderness)
from .modes import REST, ROCK, SLIDE, SLIDE_ROCK

FLIGHT = "flight"
#: Every mode a general solver reports, in the order of :mod:`assess.mechanics.modes`.
MODES = (REST, SLIDE, ROCK, SLIDE_ROCK, FLIGHT)


@dataclass(frozen=True)
class Block:
    """A rigid rectangular block in one base direction.

    Parameters
    ----------
    half_width_m : float
        b, half the base dimension in the direction of motion [m].
    cg_height_m : float
        h, height of the centre of mass above the base [m].
    height_m : float
        H, overall height [m] (≥ h; 2h for a uniform block).
    mu : float
        Kinetic friction coefficient [-].
    mu_static : float, optional
        Static friction coefficient [-] (≥ ``mu``); defaults to ``mu``.
    restitution : float, optional
        Coefficient of restitution of angular velocity at a rocking impact
        [-], in [0, 1]; defaults to Housner's value for this block.
    foot_inset_m : float
        How far the item's feet stand in from the edges of its box [m]
        (default 0: it stands on its edges). The block then touches the floor
        at ±(b − inset) (``contact_half_width_m``): α, b/h, R, κ and p are
        those of rocking about a foot, while the moment of inertia remains
        that of the whole box.

    Examples
    --------
    FORMA incubator prototype of Table 1 (2h = 228.6 cm, 2b = 62.2 cm):

    >>> forma = Block(half_width_m=0.311, cg_height_m=1.143, height_m=2.286, mu=0.13)
    >>> round(forma.alpha_rad, 3), round(forma.p_rad_s, 2), forma.mu_static
    (0.266, 2.49, 0.13)
    """

    half_width_m: float
    cg_height_m: float
    height_m: float
    mu: float
    mu_static: Optional[float] = None
    restitution: Optional[float] = None
    foot_inset_m: float = 0.0

    def __post_init__(self):
        if self.mu_static is None:
            object.__setattr__(self, "mu_static", self.mu)
        for name in ("half_width_m", "cg_height_m", "height_m"):
            value = getattr(self, name)
            if not np.isfinite(value) or value <= 0.0:
                raise ValueError(f"{name} must be a positive finite length, got {value!r}")
        if self.cg_height_m > self.height_m:
            raise ValueError(f"cg_height_m {self.cg_height_m} is above the top of the block "
                             f"(height_m {self.height_m})")
        if not (np.isfinite(self.mu) and self.mu >= 0.0):
            raise ValueError(f"mu must be a finite coefficient >= 0, got {self.mu!r}")
        if not (np.isfinite(self.mu_static) and self.mu_static >= self.mu):
            raise ValueError(f"mu_static must be >= mu ({self.mu}), got {self.mu_static!r}")
        if self.restitution is not None and not 0.0 <= self.restitution <= 1.0:
            raise ValueError(f"restitution must lie in [0, 1], got {self.restitution!r}")
        if not (np.isfinite(self.foot_inset_m) and 0.0 <= self.foot_inset_m < self.half_width_m):
            raise ValueError(f"foot_inset_m must lie in [0, half_width_m), got {self.foot_inset_m!r}")

    @classmethod
    def uniform(cls, alpha_rad, p_rad_s, mu, mu_static=None, restitution=None):
        """The uniform block (h = H/2) of slenderness α and frequency parameter p.

        From :math:`p = \\sqrt{3g/(4R)}`, :math:`R = 3g/(4p^2)`,
        :math:`b = R\\sin\\alpha`, :math:`h = R\\cos\\alpha`.

        >>> block = Block.uniform(0.16, 1.25, mu=0.7)
        >>> round(block.alpha_rad, 12), round(block.p_rad_s, 12)
        (0.16, 1.25)
        """
        from .geometry import STANDARD_GRAVITY_M_S2
        radius_m = 3.0 * STANDARD_GRAVITY_M_S2 / (4.0 * p_rad_s**2)
        cg_height_m = radius_m * np.cos(alpha_rad)
        return cls(half_width_m=radius_m * np.sin(alpha_rad), cg_height_m=cg_height_m,
                   height_m=2.0 * cg_height_m, mu=mu, mu_static=mu_static, restitution=restitution)

    @property
    def contact_half_width_m(self) -> float:
        """b_c = b − foot inset: half the distance between the points it stands on [m]."""
        return self.half_width_m - self.foot_inset_m

    @property
    def alpha_rad(self) -> float:
        """Slenderness α = atan(b_c/h) [rad] (b_c = b without feet)."""
        return float(slenderness(self.contact_half_width_m, self.cg_height_m))

    @property
    def b_over_h(self) -> float:
        """tan α = b_c/h [-]."""
        return self.contact_half_width_m / self.cg_height_m

    @property
    def size_m(self) -> float:
        """R, pivot (corner or foot) to centre of mass [m]."""
        return float(size(self.contact_half_width_m, self.cg_height_m))

    @property
    def inertia_cm_over_mass_m2(self) -> float:
        """I_cm/m = (4b² + H²)/12 [m²], of the whole box."""
        return (4.0 * self.half_width_m**2 + self.height_m**2) / 12.0

    @property
    def inertia_ratio(self) -> float:
        """κ = I_O/(mR²) about the pivot, I_O = I_cm + mR² [-] (4/3 for a uniform block on its edges)."""
        if self.foot_inset_m == 0.0:
            return float(inertia_ratio(self.half_width_m, self.cg_height_m, self.height_m))
        return (self.inertia_cm_over_mass_m2 + self.size_m**2) / self.size_m**2

    @property
    def p_rad_s(self) -> float:
        """Frequency parameter p = √(g/(κR)) [rad/s]."""
        if self.foot_inset_m == 0.0:
            return float(frequency_parameter(self.half_width_m, self.cg_height_m, self.height_m))
        from .geometry import STANDARD_GRAVITY_M_S2
        return float(np.sqrt(STANDARD_GRAVITY_M_S2 / (self.inertia_ratio * self.size_m)))

    @property
    def restitution_effective(self) -> float:
        """The restitution in use: the override, or Housner's e for this block [-].

        Housner's e is negative for squat blocks (sin²α > κ/2, e.g. b/h = 2):
        the impact then leaves no rocking motion, and 0 is used.
        """
        if self.restitution is not None:
            return float(self.restitution)
        return max(0.0, float(housner_restitution(self.alpha_rad, self.inertia_ratio)))

    def scaled(self, length_factor):
        """The same block with every length multiplied by ``length_factor`` (Froude model)."""
        return Block(self.half_width_m * length_factor, self.cg_height_m * length_factor,
                     self.height_m * length_factor, self.mu, self.mu_static, self.restitution,
                     self.foot_inset_m * length_factor)


def corner_positions(x_m, y_m, theta_rad, half_width_m, cg_height_m):
    """Floor-frame positions of the −x and +x base corners [m].

    Returns ``(x_minus, y_minus, x_plus, y_plus)``; see the module docstring
    for the map from body to floor frame.

    >>> [round(float(v), 12) for v in corner_positions(0.0, 1.0, 0.0, 0.3, 1.0)]
    [-0.3, 0.0, 0.3, 0.0]
    """
    cos_t, sin_t = np.cos(theta_rad), np.sin(theta_rad)
    x_minus = x_m - half_width_m * cos_t - cg_height_m * sin_t
    y_minus = y_m + half_width_m * sin_t - cg_height_m * cos_t
    x_plus = x_m + half_width_m * cos_t - cg_height_m * sin_t
    y_plus = y_m - half_width_m * sin_t - cg_height_m * cos_t
    return x_minus, y_minus, x_plus, y_plus


def sliding_displacement(x_m, theta_rad, half_width_m, cg_height_m):
    """Sliding u of the lower base corner from its position at rest [m].

    .. math:: u = x - h\\sin\\theta - b\\,\\mathrm{sgn}(\\theta)(1 - \\cos\\theta)

    Pure rocking about a fixed corner (x = h sin θ + b sgn θ (1 − cos θ)) gives
    u = 0:

    >>> theta = 0.2
    >>> x = 1.0 * np.sin(theta) + 0.3 * (1 - np.cos(theta))
    >>> abs(float(sliding_displacement(x, theta, 0.3, 1.0))) < 1e-15
    True
    """
    return (x_m - cg_height_m * np.sin(theta_rad)
            - half_width_m * np.sign(theta_rad) * (1.0 - np.cos(theta_rad)))


def summary_mode(modes_visited):
    """One of ``rest``, ``slide``, ``rock``, ``slide-rock`` for a whole run.

    ``rock`` if the block uplifted (rock or flight) and never slipped,
    ``slide`` if it slipped and never uplifted, ``slide-rock`` if it did both
    (at once or in turn), ``rest`` if neither.

    >>> summary_mode(["rest", "slide", "rest"]), summary_mode(["rest", "rock", "slide"])
    ('slide', 'slide-rock')
    """
    visited = set(modes_visited)
    unknown = visited - set(MODES)
    if unknown:
        raise ValueError(f"unknown modes {sorted(unknown)}; expected some of {MODES}")
    slipped = bool(visited & {SLIDE, SLIDE_ROCK})
    uplifted = bool(visited & {ROCK, SLIDE_ROCK, FLIGHT})
    if slipped and uplifted:
        return SLIDE_ROCK
    if uplifted:
        return ROCK
    if slipped:
        return SLIDE
    return REST


@dataclass(frozen=True)
class BlockResponse:
    """Response of a block to one floor motion, as every solver reports it.

    Attributes
    ----------
    sliding_max_m : float
        Peak |u| [m] over the motion and the run-out after it.
    sliding_residual_m : float
        u where the block comes to rest after the motion [m] (signed).
    theta_max_over_alpha : float
        Peak |θ|/α [-]; (π/2)/α or more if the block overturned.
    uplift : bool
        Whether a base corner left the floor at any time.
    overturned : bool
        Whether |θ| reached π/2.
    overturn_time_s : float
        When |θ| reached π/2 [s]; NaN if it did not.
    mode_sequence : tuple of (float, str)
        (start time [s], mode) of each mode the block went through, in order,
        starting with ``(0.0, "rest")`` for a block starting at rest.
    time_s, sliding_m, theta_rad : ndarray or None
        Histories at the samples of the record (and of the run-out), on request.
    solver : str
        Which solver produced the response (set by :mod:`assess.mechanics.engine`).
    """

    sliding_max_m: float
    sliding_residual_m: float
    theta_max_over_alpha: float
    uplift: bool
    overturned: bool
    overturn_time_s: float
    mode_sequence: tuple = field(default_factory=tuple)
    time_s: Optional[np.ndarray] = None
    sliding_m: Optional[np.ndarray] = None
    theta_rad: Optional[np.ndarray] = None
    solver: str = ""

    @property
    def mode(self) -> str:
        """The run's mode in the four-word vocabulary of the report (:func:`summary_mode`)."""
        return summary_mode(mode for _, mode in self.mode_sequence)
