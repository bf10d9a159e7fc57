"""The yielding stick's static pushover, and the lateral stiffness ratio α a pushover's slope after yield gives.

A frame's pushover (base shear against roof displacement under the code's lateral forces) rises at its initial
stiffness until its first storey yields, then far less steeply: what stiffness is left is the continuous
column's (its bending, which α measures against the storeys' shear stiffness, Miranda & Taghavi [1]_), the
springs' own hardening, less the gravity loads' P-Delta. The first yield alone (``yield_base_shear_g``) does not
tell α apart (on OpenSees frames of 8 and 12 storeys rebuilt at α 5 to 20 it moved 0.082-0.090 W), the slope
after yield does (0.171 / 0.065 / 0.051 / 0.032 of the initial slope at 2 % roof drift on the 12-storey one:
``benchmarks/bench_pushover_alpha.py``). So a building sheet that gives ``pushover_slope_ratio`` beside
``yield_base_shear_g`` (both from the engineer's pushover) has its α found: the α whose stick
(:func:`~assess.building.yielding.yielding_building`) pushed over the same way has that slope
(:func:`alpha_from_pushover`).

The pushover (:func:`stick_pushover`) is the stick of :mod:`assess.building.nonlinear` loaded by ASCE 7-22
§12.8.3's lateral forces at its T_1 (:func:`~assess.building.design.vertical_distribution`, the pattern the
stick's strength is distributed by), its roof displacement raised step by step (displacement control, FEMA 440
[2]_ §2.2: the pushover of a multi-storey model), with Newton's iterations on the tangent stiffness at each
step. Loading only increases every storey's drift here, so each spring follows its backbone, which both laws
share (:mod:`assess.building.hysteresis`): k_0 to F_y, then b k_0. Its slope ratio (:attr:`Pushover.slope_ratio`)
is the slope of base shear against roof drift at :data:`SLOPE_ROOF_DRIFT_RATIO` over the slope before yield, as an
engineer reads it off the curve (the tangent there over the initial one). Once every storey has yielded it is
what the column and the springs' hardening leave (b k_0 each, :data:`~assess.building.nonlinear.DEFAULT_HARDENING`),
and it falls as α rises. Where a storey has not yet yielded at that drift it keeps the slope up, and the slope
may then rise again with α over part of the range (an 8-storey frame of uniform storeys, each as strong as
stiff, at α 13 to 16, whose top storeys yield later the weaker the column): two α can give one slope, and
:func:`alpha_from_pushover` says so. The mean slope from the first yield to 2 % falls steadily with α on every
frame tried, but it also measures how the storeys' yielding spreads, which their strength profile sets (the
tool's and a building's differ): against the OpenSees frames of ``tests/peers/opensees_buildings.py`` rebuilt
with the stick's hardening, the slope at 2 % gave their α back (5, 10 and 20 on frames of 4 to 12 storeys) where
the mean slope gave 3.7 to 30.

Only a stick whose flexure is an elastic column beside its springs (frames and braced frames,
:data:`~assess.building.nonlinear.FLEXURE_BY_SYSTEM`) has an α that the slope after yield tells: a wall yields at
its base hinge (its slope is the hinge's hardening), an equivalent shear stick has no column.

References
----------
.. [1] Miranda, E. and Taghavi, S. (2005). Approximate floor acceleration demands in multistory buildings. I:
   Formulation. J. Struct. Eng. 131(2):203-211. doi:10.1061/(ASCE)0733-9445(2005)131:2(203)
.. [2] FEMA 440 (2005). Improvement of Nonlinear Static Seismic Analysis Procedures. Federal Emergency
   Management Agency. Ch. 2 (the pushover of multi-degree-of-freedom models).
"""
from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Callable

import numpy as np
from scipy.optimize import brentq

from .design import vertical_distribution
from .nonlinear import GRAVITY_M_S2, YieldingStick, shear_chain_matrix

#: The roof drift ratio at which the pushover's slope after yield is read [-]: well past a frame's first yield
#: (0.3-0.5 % of the height on the OpenSees frames) and within its design drifts.
SLOPE_ROOF_DRIFT_RATIO = 0.02
#: Steps of roof displacement up to :data:`SLOPE_ROOF_DRIFT_RATIO`, and Newton's iterations allowed in each.
STEPS = 200
MAX_ITERATIONS = 50
#: Residual force below which a step has converged, over the building's weight [-].
TOLERANCE = 1.0e-10


@dataclass(frozen=True)
class Pushover:
    """A stick's pushover: at each roof drift ratio, the base shear over the weight and the storeys' drifts; its
    slope before yield and the base shear at its first yield."""

    roof_drift_ratio: np.ndarray
    base_shear_g: np.ndarray
    storey_drift_m: np.ndarray
    #: The slope of base shear over the weight against the roof drift ratio before any storey yields [-].
    initial_slope_g: float
    #: The base shear over the weight at which the first storey, whichever, yields [-].
    first_yield_g: float
    #: The slope there at the last roof drift (a spring at its yield drift counted as yielded) [-].
    tangent_g: float

    @property
    def slope_ratio(self) -> float:
        """The slope at the last roof drift over the slope before yield [-] (the module text)."""
        return self.tangent_g / self.initial_slope_g


def _springs(stick: YieldingStick, drift_m: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Each spring's force [N] and tangent [N/m] on its backbone (k_0 to F_y, then b k_0), either way."""
    k0, fy, b = stick.stiffness_n_m, stick.yield_force_n, stick.hardening
    yield_drift = fy / k0
    beyond = np.abs(drift_m) > yield_drift
    force = np.where(beyond, np.sign(drift_m) * (fy + b * k0 * (np.abs(drift_m) - yield_drift)), k0 * drift_m)
    return force, np.where(beyond, b * k0, k0)


def stick_pushover(stick: YieldingStick, period_s: float, roof_drift_ratio: float = SLOPE_ROOF_DRIFT_RATIO,
                   steps: int = STEPS) -> Pushover:
    """The pushover of ``stick`` (T_1 ``period_s``, for the lateral forces' exponent k) to ``roof_drift_ratio``.

    Examples
    --------
    One storey of 4 m, stiffness 100 W/m, yielding at 0.1 W (1 mm), hardening 3 %: the slope after yield is the
    hardening, and at 2 % drift (80 mm) the base shear is 0.1 + 0.03 × 100 × (0.080 − 0.001) = 0.337 W:

    >>> weight_n = 1.0e5 * 9.80665
    >>> stick = YieldingStick(np.array([1.0e5]), np.array([4.0]), np.array([100.0 * weight_n]),
    ...                       np.array([0.1 * weight_n]), np.array([0.03]), "bilinear", np.zeros((1, 1)), (0.0, 0.0))
    >>> p = stick_pushover(stick, 0.5)
    >>> round(p.slope_ratio, 9), round(float(p.base_shear_g[-1]), 9), round(p.first_yield_g, 9)
    (0.03, 0.337, 0.1)
    """
    masses, heights = stick.floor_masses_kg, stick.storey_heights_m
    n = masses.size
    weight_n = float(masses.sum()) * GRAVITY_M_S2
    floor_heights = np.cumsum(heights)
    pattern = np.asarray(vertical_distribution(masses, floor_heights, period_s), dtype=float)
    pattern = pattern / pattern.sum() * weight_n  # the lateral forces at a base shear of one weight
    chain = np.eye(n) - np.eye(n, k=-1)  # storey drifts from floor displacements
    roof_m = float(floor_heights[-1])

    def forces(u):
        force, tangent = _springs(stick, chain @ u)
        return (stick.linear_stiffness_n_m @ u + chain.T @ force,
                stick.linear_stiffness_n_m + shear_chain_matrix(tangent))

    # before yield: linear, at the initial stiffness; the first spring to reach F_y sets the first yield
    elastic = np.linalg.solve(stick.linear_stiffness_n_m + shear_chain_matrix(stick.stiffness_n_m), pattern)
    first_yield_g = float(np.min(stick.yield_force_n / (stick.stiffness_n_m * np.abs(chain @ elastic))))
    initial_slope_g = roof_m / float(elastic[-1])
    u, factor = np.zeros(n), 0.0
    targets = np.linspace(0.0, roof_drift_ratio, steps + 1)[1:]
    shear, drifts = np.zeros(steps), np.zeros((steps, n))
    for s, target in enumerate(targets):
        for _ in range(MAX_ITERATIONS):
            resisting, stiffness = forces(u)
            unbalanced = factor * pattern - resisting
            short_m = target * roof_m - u[-1]  # how far the roof still is from this step's displacement
            if np.max(np.abs(unbalanced)) < TOLERANCE * weight_n and abs(short_m) <= TOLERANCE * roof_m:
                break
            # Newton's step with the roof held at its target: u += δ + Δλ a, K a = F, K δ = unbalanced
            along = np.linalg.solve(stiffness, pattern)
            correct = np.linalg.solve(stiffness, unbalanced)
            d_factor = (short_m - correct[-1]) / along[-1]
            u = u + correct + d_factor * along
            factor += d_factor
        else:
            raise RuntimeError(f"the pushover did not converge at roof drift ratio {target:.4g}")
        shear[s], drifts[s] = factor, chain @ u
    _, tangent = forces(u * (1.0 + 1e-9))
    return Pushover(targets, shear, drifts, initial_slope_g, first_yield_g,
                    roof_m / float(np.linalg.solve(tangent, pattern)[-1]))


def pushover_slope_ratio(stick: YieldingStick, period_s: float) -> float:
    """:attr:`Pushover.slope_ratio` of ``stick``'s pushover to :data:`SLOPE_ROOF_DRIFT_RATIO` [-]."""
    return stick_pushover(stick, period_s).slope_ratio


#: Points of the search's grid over log α (:func:`alpha_from_pushover`), where it looks for every α with the slope.
SEARCH_POINTS = 17
#: How near the slope asked for an α's must come to be one that gives it, relative [-]: the slope jumps where a
#: storey reaches its yield drift just at that roof drift, and a change of sign across such a jump is no root.
ROOT_TOLERANCE = 1.0e-6


@dataclass(frozen=True)
class AlphaFromPushover:
    """The α :func:`alpha_from_pushover` found, and what the search saw."""

    alpha: float
    #: The slope ratio asked for, and the stick's at the α found.
    slope_ratio: float
    stick_slope_ratio: float
    #: The search's bounds of α, and the least and most slope ratio the stick has within them.
    bounds: tuple[float, float]
    slope_ratio_range: tuple[float, float]
    #: Every α within the bounds whose stick has the slope asked for (none where no α gives it).
    roots: tuple[float, ...]

    @property
    def matched(self) -> bool:
        """Whether some α within the bounds gives the stick the slope asked for (else α is the nearest the grid
        came)."""
        return bool(self.roots)


def alpha_from_pushover(slope_ratio: float, slope_at: Callable[[float], float], bounds: tuple[float, float],
                        prefer: float) -> AlphaFromPushover:
    """The α within ``bounds`` whose stick's pushover slope ratio (``slope_at(α)``) is ``slope_ratio``.

    ``slope_at`` is taken at :data:`SEARCH_POINTS` α spaced evenly in log α and at ``prefer``; each interval over
    which it passes the slope asked for holds a root, found by Brent's method on log α, unless it is a jump
    (:data:`ROOT_TOLERANCE`).
    Where two or more α give it (module text), the one nearest ``prefer`` (in log α: the system's typical α) is
    taken; where none does, the grid's α whose slope comes nearest (of several alike, the one nearest ``prefer``).

    >>> found = alpha_from_pushover(0.1, lambda a: 1.0 / (1.0 + a), (0.5, 30.0), prefer=12.0)
    >>> round(found.alpha, 6), found.matched
    (9.0, True)

    A slope that falls and rises again: two α give 0.5, 4/e^0.5 and 4 e^0.5; the one nearer 12 is taken:

    >>> two = alpha_from_pushover(0.5, lambda a: abs(np.log(a / 4.0)), (0.5, 30.0), prefer=12.0)
    >>> [round(a, 6) for a in two.roots], round(two.alpha, 6)
    ([2.426123, 6.594885], 6.594885)
    """
    low, high = (float(b) for b in bounds)
    slope_at = functools.lru_cache(maxsize=None)(slope_at)  # a root is checked, then kept: one pushover each
    grid = np.unique(np.append(np.geomspace(low, high, SEARCH_POINTS), min(max(float(prefer), low), high)))
    slopes = np.array([slope_at(float(a)) for a in grid])
    off = slopes - slope_ratio
    roots = []
    for i in range(grid.size - 1):
        if off[i] == 0.0:
            roots.append(float(grid[i]))
        elif off[i] * off[i + 1] < 0.0:
            root = float(np.exp(brentq(lambda x: slope_at(float(np.exp(x))) - slope_ratio,
                                       np.log(grid[i]), np.log(grid[i + 1]), xtol=1e-9)))
            # a storey reaching its yield drift at that roof drift makes the slope jump: no root there
            if abs(slope_at(root) - slope_ratio) <= ROOT_TOLERANCE * slope_ratio:
                roots.append(root)
    if off[-1] == 0.0:
        roots.append(float(grid[-1]))
    if roots:
        alpha = min(roots, key=lambda a: abs(np.log(a / prefer)))
    else:  # the grid's nearest; of a tie (a stick that has not yielded by then has one slope at every α), ``prefer``'s
        miss = np.abs(off)
        nearest = grid[miss <= miss.min() * (1.0 + ROOT_TOLERANCE) + 1e-12]
        alpha = float(min(nearest, key=lambda a: abs(np.log(a / prefer))))
    return AlphaFromPushover(alpha, float(slope_ratio), float(slope_at(alpha)), (low, high),
                             (float(slopes.min()), float(slopes.max())), tuple(roots))
