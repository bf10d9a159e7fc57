"""The building's modes: periods, shapes at the floors, participation factors, effective masses.

The building is a vertical cantilever with its mass lumped at the floors, one
horizontal degree of freedom per floor, resisting lateral load as a **shear beam
and a flexural beam in parallel**, tied at every floor (the model of Miranda [1]_
and Miranda & Taghavi [2]_, discretised to the floors). One number sets the
mix, the lateral stiffness ratio

.. math::  \\alpha = H\\sqrt{\\frac{GA}{EI}}

(H the height, GA the shear beam's shear rigidity, EI the flexural beam's
bending rigidity): α = 0 is a flexural cantilever (a shear-wall building), α → ∞
a shear beam (a moment frame whose floors stay horizontal). Miranda & Taghavi [2]_
give α between 0 and 2 for shear-wall buildings, 1.5 to 6 for dual (wall-frame)
systems and 5 to 20 for moment-resisting frames; :data:`ALPHA_BY_SYSTEM` takes
one value in each range per lateral system. Where the storeys' stiffnesses are
known (``storey_stiffness``), they replace the uniform shear beam.

Discretised (:func:`stiffness_matrix`): storey i is a spring k_i between floors
i-1 and i (k_i = GA/h for the shear beam), the flexural beam is a chain of
Euler-Bernoulli elements between the floors whose rotations are condensed out.
The modes solve :math:`K\\phi = \\omega^2 M\\phi`; the stiffness is then scaled
so that T_1 is the building's period (given, or ASCE 7's T_a; the ratios
T_i/T_1 and the shapes do not depend on that scale).

The continuous beam's own eigenvalue problem (:func:`continuum_eigenvalues`,
:func:`continuum_period_ratios`, :func:`continuum_mode_shape`) is the limit of
many storeys; with α → ∞ its period ratios tend to 1 : 1/3 : 1/5 (shear beam), with
α = 0 to 1 : 1/6.27 : 1/17.55 (flexural cantilever). The floors' modes are taken
from the discretised model rather than from the continuum's shapes sampled at the
floors, because a low building is far from that limit: a uniform 3-storey shear
building has T_1/T_2 = 2.80 and T_1/T_3 = 4.05 (:func:`shear_building_frequency_ratios`,
exact for its three masses), the continuum 3 and 5; at 12 storeys 2.98 and 4.92.
The discrete model also keeps the modes orthogonal in the floors' masses, so that
the Γ_j φ_j of all modes sum to 1 on every floor.

References
----------
.. [1] Miranda, E. (1999). Approximate seismic lateral deformation demands in
   multistory buildings. J. Struct. Eng. 125(4):417-425.
   doi:10.1061/(ASCE)0733-9445(1999)125:4(417)
.. [2] Miranda, E., Taghavi, S. (2005). Approximate floor acceleration demands
   in multistory buildings. I: Formulation. J. Struct. Eng. 131(2):203-211.
   doi:10.1061/(ASCE)0733-9445(2005)131:2(203)
.. [3] Chopra, A. K. (2012). Dynamics of Structures, 4th ed. Pearson: modal
   participation factors and effective modal masses (chapter 13), distributed-mass
   systems (chapter 16), finite-element beam stiffness (chapter 17).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.linalg import eigh
from scipy.optimize import brentq

from .period import SYSTEMS, approximate_period

#: Lateral stiffness ratio α per lateral system, one value inside each range Miranda & Taghavi
#: (2005) [2] give: moment frames 5 to 20 (12, mid-range); dual systems 1.5 to 6 (4), taken also for
#: braced frames, whose columns stretch and shorten as a wall's chords do, so that they deform in
#: flexure as well as in shear; shear walls 0 to 2 (1); "other" systems as the dual ones.
ALPHA_BY_SYSTEM = {
    "steel moment frame": 12.0,
    "concrete moment frame": 12.0,
    "eccentrically braced frame": 4.0,
    "braced frame": 4.0,
    "shear wall": 1.0,
    "other": 4.0,
}
#: The range α may take for each lateral system, whose ends ``assess --alpha-range`` runs the level at where the
#: building's own α is not known: Miranda & Taghavi's (2005) [2] ranges (moment frames 5 to 20, dual systems and,
#: as in :data:`ALPHA_BY_SYSTEM`, braced frames 1.5 to 6, shear walls 0 to 2, whose 0 is the building sheet's
#: least α, 0.1); "other" systems from the dual systems' least to the moment frames' most.
ALPHA_RANGE_BY_SYSTEM = {
    "steel moment frame": (5.0, 20.0),
    "concrete moment frame": (5.0, 20.0),
    "eccentrically braced frame": (1.5, 6.0),
    "braced frame": (1.5, 6.0),
    "shear wall": (0.1, 2.0),
    "other": (1.5, 20.0),
}
#: Where each system's range in :data:`ALPHA_RANGE_BY_SYSTEM` comes from, in words for the report.
ALPHA_RANGE_SOURCE = {
    "steel moment frame": "Miranda & Taghavi's (2005) range for moment frames",
    "concrete moment frame": "Miranda & Taghavi's (2005) range for moment frames",
    "eccentrically braced frame": "Miranda & Taghavi's (2005) range for dual systems, taken for braced frames",
    "braced frame": "Miranda & Taghavi's (2005) range for dual systems, taken for braced frames",
    "shear wall": "Miranda & Taghavi's (2005) range for shear-wall buildings, its 0 taken as 0.1",
    "other": "from Miranda & Taghavi's (2005) least for dual systems to their most for moment frames",
}
#: Share of the mass ASCE 7-16 §12.9.1.1 asks the modes of a response-spectrum analysis to reach.
#: Not the default here: that rule is for base shear and storey forces. A floor's acceleration
#: carries the higher modes, which are not rigid under earthquake ground motion (a 12-storey shear
#: building's 4th to 12th modes have periods of 0.09 to 0.25 s): with the 3 modes that reach 90 % of
#: its mass, floor 1's history was 32 % (RMS) off OpenSees' (tests/verification/test_building_opensees.py). Every
#: mode is kept by default; one per storey costs little (11 motions x 12 floors: 40 ms).
DEFAULT_MASS_FRACTION = 0.9
#: Modal damping ratio by default.
DEFAULT_DAMPING = 0.05


def continuum_characteristic(gamma, alpha):
    """Characteristic function of the shear-flexural cantilever's modes; zero at its eigenvalues γ_i.

    .. math::

        2 + \\left(2 + \\frac{\\alpha^4}{\\gamma^2\\beta^2}\\right)\\cos\\gamma\\cosh\\beta
          + \\frac{\\alpha^2}{\\gamma\\beta}\\sin\\gamma\\sinh\\beta = 0,
        \\qquad \\beta^2 = \\gamma^2 + \\alpha^2

    (the characteristic equation of Miranda & Taghavi 2005 [2]_), here divided by cosh β so that it stays finite.

    Parameters
    ----------
    gamma : float or ndarray
        Eigenvalue candidate γ > 0 [-].
    alpha : float
        Lateral stiffness ratio α ≥ 0 [-].

    Examples
    --------
    The flexural cantilever (α = 0): cos γ cosh γ = -1, first root 1.8751:

    >>> bool(abs(continuum_characteristic(1.87510407, 0.0)) < 1e-7)
    True
    """
    gamma = np.asarray(gamma, dtype=float)
    beta = np.sqrt(gamma ** 2 + alpha ** 2)
    two_over_cosh = 4.0 * np.exp(-beta) / (1.0 + np.exp(-2.0 * beta))  # 2/cosh β, no overflow
    return (two_over_cosh + (2.0 + alpha ** 4 / (gamma ** 2 * beta ** 2)) * np.cos(gamma)
            + alpha ** 2 / (gamma * beta) * np.sin(gamma) * np.tanh(beta))


def continuum_eigenvalues(alpha, n_modes):
    """The first ``n_modes`` eigenvalues γ_i of the shear-flexural cantilever [-].

    Roots of :func:`continuum_characteristic`; γ_i lies between (i-1)π and iπ,
    tending to (2i-1)π/2 as α → ∞ (shear beam).

    Examples
    --------
    >>> np.round(continuum_eigenvalues(0.0, 3), 4)   # flexural cantilever: 1.8751, 4.6941, 7.8548
    array([1.8751, 4.6941, 7.8548])
    """
    if not alpha >= 0.0:
        raise ValueError("alpha must be zero or positive")
    roots = []
    grid = np.linspace(1e-3, (n_modes + 1) * np.pi, 400 * (n_modes + 1))
    values = continuum_characteristic(grid, alpha)
    for i in np.flatnonzero(np.sign(values[:-1]) != np.sign(values[1:])):
        roots.append(brentq(continuum_characteristic, grid[i], grid[i + 1], args=(alpha,), xtol=1e-13))
        if len(roots) == n_modes:
            break
    return np.array(roots)


def continuum_period_ratios(alpha, n_modes):
    """Period ratios T_i/T_1 of the shear-flexural cantilever (Miranda & Taghavi 2005 [2]_).

    .. math::

        \\frac{T_i}{T_1} = \\frac{\\gamma_1}{\\gamma_i}\\sqrt{\\frac{\\gamma_1^2 + \\alpha^2}{\\gamma_i^2 + \\alpha^2}}

    Examples
    --------
    Flexural cantilever: roots of cos γ cosh γ = -1, T_1/T_2 = 6.27, T_1/T_3 = 17.55:

    >>> np.round(1.0 / continuum_period_ratios(0.0, 3), 2)
    array([ 1.  ,  6.27, 17.55])
    """
    gamma = continuum_eigenvalues(alpha, n_modes)
    return gamma[0] / gamma * np.sqrt((gamma[0] ** 2 + alpha ** 2) / (gamma ** 2 + alpha ** 2))


def continuum_mode_shape(height_ratio, gamma, alpha):
    """Mode shape φ(ξ) of the shear-flexural cantilever at ξ = z/H (Miranda & Taghavi 2005 [2]_).

    .. math::

        \\phi(\\xi) = \\sin\\gamma\\xi - \\frac{\\gamma}{\\beta}\\sinh\\beta\\xi
                     + \\eta\\left(\\cosh\\beta\\xi - \\cos\\gamma\\xi\\right),\\qquad
        \\eta = \\frac{\\gamma^2\\sin\\gamma + \\gamma\\beta\\sinh\\beta}{\\gamma^2\\cos\\gamma + \\beta^2\\cosh\\beta}

    Unnormalised. Examples: the flexural cantilever's first mode is 0 at the base,
    and its curvature vanishes at the top.

    >>> round(float(continuum_mode_shape(0.0, 1.87510407, 0.0)), 12)
    0.0
    """
    xi = np.asarray(height_ratio, dtype=float)
    beta = np.sqrt(gamma ** 2 + alpha ** 2)
    # the hyperbolic terms are evaluated scaled by exp(-β), so that a large α (β up to 10⁴) neither
    # overflows nor cancels: -(γ/β) sinh βξ + η cosh βξ
    #   = [-(γ³/β) cos γ sinh βξ + γ² sin γ cosh βξ + γβ sinh β(1-ξ)] / (γ² cos γ + β² cosh β)
    e = np.exp(-beta)
    denominator = gamma ** 2 * np.cos(gamma) * e + beta ** 2 * (1.0 + e * e) / 2.0
    eta = (gamma ** 2 * np.sin(gamma) * e + gamma * beta * (1.0 - e * e) / 2.0) / denominator
    sinh_x = (np.exp(beta * (xi - 1.0)) - np.exp(-beta * (xi + 1.0))) / 2.0
    cosh_x = (np.exp(beta * (xi - 1.0)) + np.exp(-beta * (xi + 1.0))) / 2.0
    sinh_rest = (np.exp(-beta * xi) - np.exp(beta * (xi - 2.0))) / 2.0
    hyperbolic = (-(gamma ** 3 / beta) * np.cos(gamma) * sinh_x + gamma ** 2 * np.sin(gamma) * cosh_x
                  + gamma * beta * sinh_rest) / denominator
    return np.sin(gamma * xi) + hyperbolic - eta * np.cos(gamma * xi)


def shear_building_frequency_ratios(storeys):
    """ω_j/ω_1 of a uniform shear building (equal floor masses, equal storey stiffnesses).

    .. math::  \\omega_j = 2\\sqrt{k/m}\\,\\sin\\frac{(2j-1)\\pi}{2(2n+1)},\\qquad
               \\phi_j(i) = \\sin\\frac{(2j-1)\\,i\\,\\pi}{2n+1}

    (n storeys, floor i = 1..n, the roof carrying a full floor's mass: the eigenvalues of
    K/k = tridiag(-1, 2, -1) with 1 in its last diagonal cell, 4 sin²(θ_j/2), θ_j = (2j-1)π/(2n+1),
    as substituting φ_j(i) = sin(iθ_j) shows; its free end needs sin(nθ_j) = sin((n+1)θ_j)).

    Examples
    --------
    Three storeys: sin(π/14) : sin(3π/14) : sin(5π/14) = 0.2225 : 0.6235 : 0.9010,
    so T_1/T_2 = 2.80 and T_1/T_3 = 4.05:

    >>> np.round(shear_building_frequency_ratios(3), 3)
    array([1.   , 2.802, 4.049])
    """
    j = np.arange(1, storeys + 1)
    values = np.sin((2 * j - 1) * np.pi / (2 * (2 * storeys + 1)))
    return values / values[0]


def shear_stiffness_matrix(storey_stiffness):
    """Lateral stiffness matrix [N/m] of a chain of storey springs k_1..k_n (floor 1 to the roof).

    K[i,i] = k_i + k_{i+1}, K[i,i+1] = K[i+1,i] = -k_{i+1} (k_{n+1} = 0).

    >>> shear_stiffness_matrix([2.0, 1.0]).tolist()
    [[3.0, -1.0], [-1.0, 1.0]]
    """
    k = np.asarray(storey_stiffness, dtype=float)
    n = k.size
    below = k
    above = np.append(k[1:], 0.0)
    matrix = np.diag(below + above)
    matrix[np.arange(n - 1), np.arange(1, n)] = -k[1:]
    matrix[np.arange(1, n), np.arange(n - 1)] = -k[1:]
    return matrix


def flexural_stiffness_matrix(storeys, storey_height_m, bending_rigidity_n_m2):
    """Lateral stiffness matrix [N/m] of a uniform Euler-Bernoulli cantilever, translations at the floors.

    Beam elements between the floors (the cubic Hermitian element, Chopra [3]_ chapter 17,
    translation and rotation at each end), the base fixed, the rotations
    condensed out (static condensation, no rotational inertia).

    Examples
    --------
    One storey: the cantilever tip stiffness 3EI/h³:

    >>> float(flexural_stiffness_matrix(1, 2.0, 8.0)[0, 0])
    3.0
    """
    n = int(storeys)
    h = float(storey_height_m)
    element = bending_rigidity_n_m2 / h ** 3 * np.array([
        [12.0, 6 * h, -12.0, 6 * h],
        [6 * h, 4 * h * h, -6 * h, 2 * h * h],
        [-12.0, -6 * h, 12.0, -6 * h],
        [6 * h, 2 * h * h, -6 * h, 4 * h * h]])
    full = np.zeros((2 * (n + 1), 2 * (n + 1)))
    for e in range(n):
        dofs = [2 * e, 2 * e + 1, 2 * e + 2, 2 * e + 3]
        full[np.ix_(dofs, dofs)] += element
    free = full[2:, 2:]  # node 0 (u, θ) fixed
    u = np.arange(0, 2 * n, 2)
    r = np.arange(1, 2 * n, 2)
    return free[np.ix_(u, u)] - free[np.ix_(u, r)] @ np.linalg.solve(free[np.ix_(r, r)], free[np.ix_(r, u)])


def stiffness_matrix(storeys, storey_height_m, alpha, storey_stiffness=None):
    """Lateral stiffness matrix of the shear-flexural model, floors 1..n, to a common scale.

    The shear beam's storey springs are ``storey_stiffness`` (uniform 1 N/m by
    default); the flexural beam's EI follows from α with GA = k_1 h:
    EI = k_1 h H²/α² (α = ∞: shear only; α = 0: flexure only, EI = 1 N m²).

    Examples
    --------
    >>> stiffness_matrix(2, 3.0, np.inf).tolist()
    [[2.0, -1.0], [-1.0, 1.0]]
    """
    n = int(storeys)
    if storey_stiffness is None:
        storey_stiffness = np.ones(n)
    storey_stiffness = np.asarray(storey_stiffness, dtype=float)
    if storey_stiffness.shape != (n,) or np.any(storey_stiffness <= 0.0):
        raise ValueError("storey_stiffness must give one positive stiffness per storey")
    if np.isinf(alpha):
        return shear_stiffness_matrix(storey_stiffness)
    if alpha == 0.0:
        return flexural_stiffness_matrix(n, storey_height_m, 1.0)
    height = n * storey_height_m
    bending = storey_stiffness[0] * storey_height_m * height ** 2 / alpha ** 2
    return shear_stiffness_matrix(storey_stiffness) + flexural_stiffness_matrix(n, storey_height_m, bending)


@dataclass(frozen=True)
class BuildingModes:
    """The building's modes as the floor response uses them.

    Attributes
    ----------
    floor_heights_m : ndarray, (storeys + 1,)
        Height of each floor above the ground floor [m]; floor 0 is the ground.
    periods_s : ndarray, (n_modes,)
        T_j [s], longest first.
    shapes : ndarray, (storeys + 1, n_modes)
        φ_j at each floor, 0 at the ground, 1 at the roof.
    participation : ndarray, (n_modes,)
        Γ_j = φ_jᵀ M 1 / φ_jᵀ M φ_j (for the shapes as normalised) [-].
    effective_mass_ratio : ndarray, (n_modes,)
        M_j* / M of each mode [-]; summed over all the building's modes, 1.
    damping : ndarray, (n_modes,)
        ζ_j of each mode [-].
    alpha : float
        Lateral stiffness ratio of the model (inf: shear building).
    period_source : str
        Where T_1 came from (``given`` or the code's estimate).
    storey_stiffness : ndarray, (storeys,)
        The shear beam's storey stiffnesses relative to the first storey's, floor 1 to the roof
        (all 1: uniform); the yielding stick starts from the same profile.
    """

    floor_heights_m: np.ndarray
    periods_s: np.ndarray
    shapes: np.ndarray
    participation: np.ndarray
    effective_mass_ratio: np.ndarray
    damping: np.ndarray
    alpha: float
    period_source: str
    storey_stiffness: np.ndarray = None

    def __post_init__(self):
        if self.storey_stiffness is None:
            object.__setattr__(self, "storey_stiffness", np.ones(self.floor_heights_m.size - 1))

    @property
    def storeys(self) -> int:
        return self.floor_heights_m.size - 1

    @property
    def n_modes(self) -> int:
        return self.periods_s.size

    def floor_participation(self) -> np.ndarray:
        """Γ_j φ_j at each floor, shape (storeys + 1, n_modes): the modal contributions per unit SDOF response."""
        return self.shapes * self.participation

    def truncated(self, n_modes: int) -> "BuildingModes":
        """The first ``n_modes`` modes only."""
        keep = slice(0, int(n_modes))
        return BuildingModes(self.floor_heights_m, self.periods_s[keep], self.shapes[:, keep],
                             self.participation[keep], self.effective_mass_ratio[keep],
                             self.damping[keep], self.alpha, self.period_source, self.storey_stiffness)


def modes_for_mass(effective_mass_ratio, mass_fraction=DEFAULT_MASS_FRACTION) -> int:
    """Fewest modes, longest first, whose effective masses reach ``mass_fraction`` of the total.

    >>> modes_for_mass([0.8, 0.15, 0.05], 0.9)
    2
    """
    cumulative = np.cumsum(effective_mass_ratio)
    return int(min(np.searchsorted(cumulative, mass_fraction - 1e-12) + 1, len(cumulative)))


def lumped_modes(stiffness, floor_masses, period_s=None):
    """Modes of a lumped-mass model: periods [s] (scaled to T_1 = ``period_s`` if given), shapes, Γ, M*/M.

    Solves K φ = ω² M φ (scipy.linalg.eigh); shapes normalised to 1 at the roof
    (the last degree of freedom), a ground row of zeros added on top.
    Γ_j = φ_jᵀ M 1 / φ_jᵀ M φ_j, M_j* = (φ_jᵀ M 1)² / φ_jᵀ M φ_j (Chopra [3]_ chapter 13).

    Examples
    --------
    Two storeys, k = m = 1: ω² = (3 ∓ √5)/2, T_1/T_2 = 2.618:

    >>> periods, shapes, gamma, mass = lumped_modes(shear_stiffness_matrix([1, 1]), [1, 1])
    >>> round(float(periods[0] / periods[1]), 3), round(float(mass.sum()), 12)
    (2.618, 1.0)
    """
    masses = np.asarray(floor_masses, dtype=float)
    omega2, vectors = eigh(stiffness, np.diag(masses))
    if np.any(omega2 <= 0.0):
        raise ValueError("the stiffness matrix must be positive definite")
    periods = 2.0 * np.pi / np.sqrt(omega2)
    if period_s is not None:
        periods = periods * (float(period_s) / periods[0])
    vectors = vectors / vectors[-1, :]  # roof = 1 (a mode with a node at the roof would divide by 0)
    generalised = np.einsum("ij,i,ij->j", vectors, masses, vectors)
    loading = vectors.T @ masses
    participation = loading / generalised
    effective = loading ** 2 / generalised / masses.sum()
    shapes = np.vstack([np.zeros(vectors.shape[1]), vectors])
    return periods, shapes, participation, effective


def building_modes(storeys, storey_height_m, *, system="other", period_s=None, damping=DEFAULT_DAMPING,
                   alpha=None, storey_stiffness=None, floor_masses=None, n_modes=None,
                   mass_fraction=None) -> BuildingModes:
    """The modes a building's floor response uses.

    Parameters
    ----------
    storeys : int
        Storeys above ground; floors 0 (ground) to ``storeys`` (roof).
    storey_height_m : float or array-like
        Height of each storey [m] (one value: uniform). The flexural beam takes their mean.
    system : str
        Lateral system (:data:`~assess.building.period.SYSTEMS`): sets α
        (:data:`ALPHA_BY_SYSTEM`) and, without ``period_s``, T_1 = T_a of ASCE 7
        Table 12.8-2 (:func:`~assess.building.period.approximate_period`).
    period_s : float, optional
        T_1 [s] where known; the stiffness is scaled to it.
    damping : float or array-like
        Modal damping ratio ζ (one for all modes, or one per mode kept).
    alpha : float, optional
        Lateral stiffness ratio replacing the system's; ``np.inf`` is a shear building.
    storey_stiffness : array-like, optional
        Relative storey stiffnesses of the shear beam, floor 1 to the roof (uniform by default).
    floor_masses : array-like, optional
        Relative floor masses, floor 1 to the roof (equal by default).
    n_modes : int, optional
        Modes kept (the others move with the ground); by default all of them, one per
        storey (see :data:`DEFAULT_MASS_FRACTION` for why).
    mass_fraction : float, optional
        Instead of ``n_modes``: the fewest modes reaching this share of the mass (at
        least min(3, storeys)), e.g. :data:`DEFAULT_MASS_FRACTION`.

    Returns
    -------
    BuildingModes

    Examples
    --------
    A 3-storey shear building with T_1 = 0.35 s: T_2 = 0.35/2.802 = 0.125 s,
    T_3 = 0.35/4.049 = 0.086 s; the first mode carries 91.4 % of the mass:

    >>> modes = building_modes(3, 3.5, period_s=0.35, alpha=np.inf)
    >>> np.round(modes.periods_s, 3), round(float(modes.effective_mass_ratio[0]), 3)
    (array([0.35 , 0.125, 0.086]), 0.914)
    """
    n = int(storeys)
    if n < 1:
        raise ValueError("storeys must be at least 1")
    if system not in ALPHA_BY_SYSTEM:
        raise ValueError(f"system must be one of {', '.join(SYSTEMS)}, not {system!r}")
    heights = np.broadcast_to(np.asarray(storey_height_m, dtype=float), (n,))
    if np.any(~np.isfinite(heights)) or np.any(heights <= 0.0):
        raise ValueError("storey heights must be positive")
    floor_heights = np.concatenate([[0.0], np.cumsum(heights)])
    if period_s is None:
        period_s = approximate_period(floor_heights[-1], system)
        source = f"ASCE 7 Table 12.8-2 ({system})"
    else:
        if not float(period_s) > 0.0:
            raise ValueError("period_s must be positive")
        source = "given"
    alpha = ALPHA_BY_SYSTEM[system] if alpha is None else float(alpha)
    masses = np.ones(n) if floor_masses is None else np.asarray(floor_masses, dtype=float)
    relative = np.ones(n) if storey_stiffness is None else np.asarray(storey_stiffness, dtype=float)
    stiffness = stiffness_matrix(n, float(np.mean(heights)), alpha, relative)
    periods, shapes, participation, effective = lumped_modes(stiffness, masses, period_s)
    if n_modes is None:
        n_modes = n if mass_fraction is None else max(modes_for_mass(effective, mass_fraction), min(3, n))
    n_modes = int(min(n_modes, n))
    zeta = np.broadcast_to(np.asarray(damping, dtype=float), (n_modes,)).copy() if np.ndim(damping) == 0 \
        else np.asarray(damping, dtype=float)[:n_modes]
    if zeta.shape != (n_modes,) or np.any(zeta < 0.0) or np.any(zeta >= 1.0):
        raise ValueError("damping must be between 0 and 1, one value or one per mode kept")
    return BuildingModes(floor_heights_m=floor_heights, periods_s=periods[:n_modes], shapes=shapes[:, :n_modes],
                         participation=participation[:n_modes], effective_mass_ratio=effective[:n_modes],
                         damping=zeta, alpha=alpha, period_source=source,
                         storey_stiffness=relative / relative[0])
