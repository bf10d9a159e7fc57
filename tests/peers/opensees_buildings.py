"""Six yielding OpenSeesPy buildings of our own: the truth the equipment checks measure the tool against.

Not built from the tool's stick (:mod:`assess.building.nonlinear`) but from numbers of their own, as a
structural engineer's model of a code-designed building would be: shear buildings of ``zeroLength``
storey springs (``-doRayleigh 1``), equal floor masses, Rayleigh damping 5 % at modes 1 and 2 on the
committed tangent stiffness, Newmark average acceleration with Newton iterations at 1 ms substeps.

**Design** (ASCE 7-22 §12.8 ELF at issue 29's S_DS 1.0 g, S_D1 0.6 g, Risk Category II; C_s and k worked
by hand below, the numbers in :data:`BUILDINGS`): each storey's design shear V_x = C_s W Σ_{i≥x} C_vi.

**Stiffness**: each storey's stiffness tapers up the height (members lighter up the building, sections
changing every storey or two), scaled so that T_1 is the building's.

**Strength**: each storey's yield shear is its design shear times an overstrength that grows up the
height. At the base 2.2 (``smf4``), 2.0 (``smf8``), 1.8 (``wall6``): within the 1.5-3.5 of the pushover
overstrength of code-designed archetypes that FEMA P-695 [1]_ and NIST GCR 10-917-8 [2]_ report (as
recalled; their tables were not read here). Up the height the overstrength grows because the upper
members are not sized by their design shear: in drift-controlled frames the storey stiffness is set by
the drift limit and least member sizes, and a frame storey's yield drift is fixed by its geometry and the
steel's yield strain, not by its strength (θ_y ≈ 0.65 ε_y L_b/h_b for steel frames, Priestley, Calvi &
Kowalsky [3]_; "strength and stiffness are not independent", Priestley [4]_), so a storey is about as
strong as it is stiff. For ``smf4`` that uniform-yield-drift argument gives, from the stiffness profile
and the ELF shears, overstrengths 2.2, 2.18, 2.42, 3.35 up the height; the profile used, 2.2, 2.4, 2.7,
3.0, was set by the first pass before this argument and is within 10 % of it, so it is kept rather than
moved toward the tool. For the wall, capacity design keeps the plastic hinge at the base and makes the
wall above stronger than its design actions ([5]_: the upper wall designed to a linear moment envelope
from the base's overstrength moment, which lies above the ELF moment diagram), hence 1.8 at the base to
3.0 at the top; that is less than a full linear envelope gives in a shear stick (1.8 × 2.53 = 4.5 at the
top storey, the tool's rule, :func:`assess.building.nonlinear.capacity_design_strength`): a wall whose
upper reinforcement is curtailed nearer its demand. Kept as the first pass set it.

**Continuous column** (frames): the columns of a strong-column weak-beam moment frame stay elastic and
continuous over the height; they tie the storeys together and spread the drift that a chain of
independent storey springs would concentrate in one storey (MacRae, Kimura & Roeder [6]_). The frames
carry it as an elastic Euler-Bernoulli column (OpenSees ``elasticBeamColumn``, axially rigid, fixed at
the base) beside the springs, tied at the floors, with EI = GA H²/α², GA = k_1 h, α = 10: within the
5-20 Miranda & Taghavi [7]_ give for moment frames (the tool takes 12). Without it, the 8-storey frame's
first storey reached ductility 27 at MCE_R (≈ 10 % drift, a collapse-level concentration), which code
frames do not show at MCE_R; with it, 2. The column is elastic at its base too (a simplification: a real
column base hinges).

* ``smf4``: steel special moment frame, 4 storeys of 4 m, T_1 0.6 s; ``Steel01`` (b 0.02). Design at
  S_DS 1.0, S_D1 0.6 g, Risk Category II: R 8, C_s = min(1.0/8, 0.6/(0.6·8)) = 0.125, k = 1.05.
* ``smf8``: the same system, 8 storeys of 4 m, T_1 1.2 s: C_s = min(0.125, 0.6/(1.2·8)) = 0.0625,
  k = 1.35.
* ``wall6``: reinforced-concrete special shear wall, 6 storeys of 3.5 m, T_1 0.5 s; ``Hysteretic``
  with pinching (pinchX 0.7, pinchY 0.3, β 0.3: more pinched than the tool's 0.8/0.4/0.4) on a bilinear
  backbone (b 0.02); R 5: C_s = min(1.0/5, 0.6/(0.5·5)) = 0.2, k = 1. No column: a wall is its own
  flexural member, here idealised as a SHEAR building (storey springs, no bending), which a slender wall
  is not; kept, and its results reported, beside ``wallf6``.
* ``rcf5``: reinforced-concrete special moment frame, 5 storeys of 3.5 m, T_1 0.8 s (cracked sections: longer
  than T_a = 0.016 h_n^0.9 = 0.61 s, within C_u T_a = 0.86 s); ``Hysteretic`` with pinching on a bilinear backbone
  (b 0.02) and the frames' continuous column (α 10). A frame of flexural beam hinges pinches less than a wall
  (pinchX 0.85, pinchY 0.5, β 0.25: less pinched than the tool's 0.8/0.4/0.4, where ``wall6`` is more); R 8:
  C_s = min(1.0/8, 0.6/(0.8·8)) = 0.0938, k = 1 + (0.8 − 0.5)/2 = 1.15. Its stiffness tapers and its
  overstrength grows up the height as the steel frames' do (2.0 at the base to 3.0 at the roof), set before
  the tool was run on it: the concrete system and height the other truths leave out.
* ``wallf6``: the same wall as it bends (:class:`FlexuralWall`): ``wall6``'s storeys, masses, T_1, pinching
  and pushover base shear at yield (0.36 W), as an elastic cantilever on a concentrated plastic hinge at
  its base, the hinge's elastic stiffness and the damping set as concentrated-plasticity models set them
  (Ibarra & Krawinkler [8]_ App. B's n = 10, Zareian & Medina [9]_, as OpenSees' examples do [10]_; the
  class text says how): T_2/T_1 0.157, where ``wall6``'s is 0.38.

Beside these five, a sixth system checked on its own (:data:`BRACED`, tests/verification/test_yielding_braced.py):

* ``bf6``: steel special concentrically braced frame (chevron braces), 6 storeys of 4 m, T_1 0.6 s (T_a =
  0.02 h_n^0.75 = 0.02 · 78.7^0.75 = 0.53 s, "all other structural systems"; C_u T_a = 0.74 s); R 6: C_s =
  min(1.0/6, 0.6/(0.6·6)) = 0.167, k = 1.05; design storey shears 1, 0.956, 0.864, 0.723, 0.532, 0.292 of the
  base's. Braces sized for their storey's shear, one section over two storeys: stiffnesses 1, 1, 0.86, 0.86,
  0.55, 0.55; each storey as strong as its braces are stiff, 1.6 times its design shear at the base (within
  the archetypes' 1.5-3.5 above) and 1.6 times its stiffness over its shear's share above (1.6, 1.67, 1.59,
  1.9, 1.65, 3.02). ``Steel01`` (b 0.02), as the frames: the braces' buckling, which pinches a storey's
  loops and loses strength cycle by cycle, is in neither this truth nor the tool's bilinear springs. Its column
  is the braced bay bending as a truss, the columns' axial strain its flexure: for a 9 m bay with HSS 8×8×½
  braces (A 8.7e-3 m², 6.0 m long, cos θ 0.75) and W14×82 columns (A 1.55e-2 m²), GA = 2 E A cos²θ h/L_br =
  1.29e9 N and EI = E · 2 A_c (L/2)² = 1.25e11 N m², α = H √(GA/EI) = 24 · 0.102 = **2.4** (heavier columns,
  W14×132, give 1.9; the tool takes 4 for braced frames where no α is given).
* ``bf6b`` (:data:`BUCKLING`): ``bf6`` whose braces buckle. An SCBF dissipates "primarily through brace buckling and
  yielding of the brace in tension" (AISC 341-16 §F2.1 as ideCAD's help page on §F2 paraphrases it,
  help.idecad.com/ideCAD/f2-special-concentrically-braced-frames-scbf). Each storey is its two braces, one pulled
  and one pushed (:func:`peers.opensees_yielding.buckling_brace_pair`: two mirrored ``Hysteretic`` braces in
  ``Parallel``), on ``bf6``'s stiffnesses and strengths: a brace's compression strength half its tension yield
  (AISC 360-16 eq. E3-2, F_cr = 0.658^(F_y/F_e) F_y, at KL/r 90 and F_y 345 MPa: F_e = π² 200,000/90² = 244 MPa,
  F_cr = 0.658^1.42 F_y = 0.55 F_y), so the pushed brace buckles at the storey's yield drift F_y/k_0 with the
  storey at F_y, and the pulled one yields at twice that; after buckling the brace keeps 0.3 of its compression
  strength (AISC 341-16 §F2.3's post-buckling strength for the analysis of SCBF, as recalled: not read here),
  reached at five times its buckling drift; loops pinched (pinchX 0.4, pinchY 0.2, a judgement: a buckled brace
  carries little until pulled straight), no cyclic damage. Pushed one way the storey carries F_y at F_y/k_0,
  1.41 F_y at twice that, then less as the pushed brace weakens: past their yield drift the truth's storeys gain
  strength until the pulled brace yields and then lose it, where ``bf6``'s harden at 2 %; neither the tool's
  bilinear springs nor ``bf6`` do this.

And a taller one checked on its own (:data:`TALL`), where the higher modes carry more of the floors' motion:

* ``smf12``: steel special moment frame, 12 storeys of 4 m, T_1 2.0 s (T_a = 0.0724 · 48^0.8 = 1.60 s; within
  C_u T_a = 2.24 s, as a model of a frame with its panel zones and gravity framing gives a long period). R 8:
  C_s = max(min(1.0/8, 0.6/(2.0·8)), 0.044 · 1.0) = 0.044 (ASCE 7-22 eq. 12.8-5's least governs: 0.6/16 is
  0.0375), k = 1 + (2.0 − 0.5)/2 = 1.75. Members change every two storeys: stiffnesses 1, 1, 0.92, 0.92, 0.8,
  0.8, 0.66, 0.66, 0.5, 0.5, 0.36, 0.36 (the roof pair at about a third of the base, as beams falling from
  W36 to W24 sections give in a frame of this height; as recalled, no design read here); the overstrength
  grows up the height as ``smf8``'s does, 2.0 at the base to 3.2 at the roof; the frames' column (α 10) and
  ``Steel01`` (b 0.02). Set before the tool was run on it.

``yield_base_shear_g``, what the engineer writes in the building sheet, is what a static pushover of the
building itself gives (:func:`pushover_yield_base_shear_g`): the base shear, every part of the lateral
system included, when any storey first yields, over the weight (first yield, not an idealised bilinear
"effective" yield as ASCE 41 §7.4.3.2.5 fits, which would be higher). The load pattern is ASCE 7-22 §12.8.3's
(the ELF forces with the building's k): the tool reads ``yield_base_shear_g`` as the base shear at which
its first storey yields under those same forces (:func:`assess.building.nonlinear.yielding_stick` gives the
first spring its share of that shear), so the number means the same on both sides; FEMA P-695 [1]_
pushes with the first mode's shape, which differs from the ELF pattern by a few per cent for these
buildings. In the frames the first to yield is not the first storey but storey 2 (``smf4``, at 0.305 W;
its first storey would yield at 0.408 W) and storey 3 (``smf8``, at 0.144 W; its first at 0.278 W): the
continuous column carries a third to a half of the lower storeys' shear, more than their overstrength
falls short of the upper storeys'. So the base shear at first yield is above the first storey spring's
yield shear (0.305 against 0.275, 0.144 against 0.125); for the wall, a shear stick, it is that spring's
(0.36); for the flexural wall, a determinate cantilever, the base shear at which the ELF forces' base moment
reaches the hinge's yield moment (0.36 by construction, :func:`wall_pushover_yield_base_shear_g`).

References
----------
.. [1] FEMA P-695 (2009). Quantification of Building Seismic Performance Factors. Ch. 9, App. F.
.. [2] NIST GCR 10-917-8 (2010). Evaluation of the FEMA P-695 Methodology for Quantification of
   Building Seismic Performance Factors.
.. [3] Priestley, M. J. N., Calvi, G. M. and Kowalsky, M. J. (2007). Displacement-Based Seismic Design
   of Structures. IUSS Press, Pavia (yield drift of frames).
.. [4] Priestley, M. J. N. (2003). Myths and Fallacies in Earthquake Engineering, Revisited. The Mallet
   Milne Lecture. IUSS Press, Pavia.
.. [5] Paulay, T. and Priestley, M. J. N. (1992). Seismic Design of Reinforced Concrete and Masonry
   Buildings. Wiley. Ch. 5 (capacity design of cantilever walls); also EN 1998-1 §5.5.2.4.1.
.. [6] MacRae, G. A., Kimura, Y. and Roeder, C. (2004). Effect of column stiffness on braced frame
   seismic behavior. J. Struct. Eng. 130(3):381-391.
.. [7] Miranda, E. and Taghavi, S. (2005). Approximate floor acceleration demands in multistory
   buildings. I: Formulation. J. Struct. Eng. 131(2):203-211.
.. [8] Ibarra, L. F. and Krawinkler, H. (2005). Global collapse of frame structures under seismic
   excitations. Report 152, John A. Blume Earthquake Engineering Center, Stanford. App. B (stiffness
   modification of the elastic element and its end springs, n = 10). Not read here: its rule as the
   OpenSees examples [10]_ state and apply it.
.. [9] Zareian, F. and Medina, R. A. (2010). A practical method for proper modeling of structural damping
   in inelastic plane structural systems. Computers & Structures 88(1-2):45-53. Abstract read: each
   element as an elastic element with stiffness-proportional damping and end springs with none.
.. [10] Eads, L. (2010-2012). OpenSees examples "Pushover Analysis of 2-Story Moment Frame" ("Stiffness
   Modifications to Elastic Frame Elements": springs n times the element's rotational stiffness, the element
   (n + 1)/n, the springs' hardening α_mem/(1 + n(1 − α_mem)), "a corrected version of Equation B.5"), "Pushover
   and Dynamic Analyses of 2-Story Moment Frame with Panel Zones and RBS" (Tcl: n = 10, K_s = n·6EI_mod/L,
   a1_mod = a1 (1 + n)/n on the modified elements, "See Zareian & Medina 2010", mass-proportional on the
   nodes, none on the springs); OpenSees' ModElasticBeam2d manual page (the same element-and-springs
   damping split). https://opensees.berkeley.edu/wiki (as mirrored in github.com/STAIRlab/opensees-gallery,
   examples/mrf_pushover and mrf_panelzone).
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from peers.opensees_shear import GRAVITY_M_S2, load_opensees
from peers.opensees_yielding import floor_histories, shear_chain, storey_spring

FLOOR_MASS_KG = 1.0e5
SUBSTEP_S = 0.001


@dataclass(frozen=True)
class TruthBuilding:
    name: str
    system: str          # the building sheet's system
    storeys: int
    storey_height_m: float
    period_s: float
    design_cs: float     # C_s of the design (hand-computed, module text)
    exponent_k: float    # ASCE 7-22 §12.8.3's k at T_1
    stiffness_profile: tuple
    overstrength_profile: tuple
    law: str             # "steel01", "hysteretic" or "buckling" (peers.opensees_yielding.buckling_brace_pair)
    column_alpha: float = np.inf  # α = H √(GA/EI) of the continuous elastic column (∞: none)
    hardening: float = 0.02
    pinch_x: float = 0.7
    pinch_y: float = 0.3
    beta: float = 0.3

    def storey_shear_ratios(self) -> np.ndarray:
        """V_x/W of the design: C_s times the share of the ELF forces above storey x (equal floor weights)."""
        heights = self.storey_height_m * np.arange(1, self.storeys + 1)
        forces = heights ** self.exponent_k / np.sum(heights ** self.exponent_k)
        return self.design_cs * np.cumsum(forces[::-1])[::-1]

    def yield_ratios(self) -> np.ndarray:
        """Each storey's yield shear over the weight: design shear times its overstrength."""
        return self.storey_shear_ratios() * np.asarray(self.overstrength_profile, dtype=float)

    @property
    def yield_base_shear_g(self) -> float:
        return float(self.yield_ratios()[0])

    def _scale(self) -> float:
        k = np.asarray(self.stiffness_profile, dtype=float)
        omega2 = np.linalg.eigvalsh((_chain(k) + _column(self, k)) / FLOOR_MASS_KG)
        return (2.0 * np.pi / self.period_s) ** 2 / omega2[0]

    def stiffness_n_m(self) -> np.ndarray:
        """Storey stiffnesses with the building's profile, scaled so that T_1 (column included) is ``period_s``."""
        return np.asarray(self.stiffness_profile, dtype=float) * self._scale()

    def bending_rigidity_n_m2(self) -> float:
        """EI of the continuous column: GA H²/α², GA = k_1 h the first storey's (scaled) shear rigidity."""
        if not np.isfinite(self.column_alpha):
            return 0.0
        height = self.storeys * self.storey_height_m
        return float(self.stiffness_n_m()[0] * self.storey_height_m * height ** 2 / self.column_alpha ** 2)


def _chain(k) -> np.ndarray:
    """Stiffness matrix of a chain of storey springs k (floor 1 to the roof)."""
    n = len(k)
    matrix = np.zeros((n, n))
    for i in range(n):
        matrix[i, i] += k[i]
        if i + 1 < n:
            matrix[i, i] += k[i + 1]
            matrix[i, i + 1] -= k[i + 1]
            matrix[i + 1, i] -= k[i + 1]
    return matrix


def _column(building, k) -> np.ndarray:
    """Lateral stiffness at the floors of the continuous column (Euler-Bernoulli elements between the floors,
    fixed at the base, rotations condensed out), with the unscaled storey stiffnesses ``k``."""
    n = building.storeys
    if not np.isfinite(building.column_alpha):
        return np.zeros((n, n))
    h = building.storey_height_m
    ei = float(k[0]) * h * (n * h) ** 2 / building.column_alpha ** 2
    element = ei / h ** 3 * np.array([[12.0, 6 * h, -12.0, 6 * h], [6 * h, 4 * h * h, -6 * h, 2 * h * h],
                                      [-12.0, -6 * h, 12.0, -6 * h], [6 * h, 2 * h * h, -6 * h, 4 * h * h]])
    full = np.zeros((2 * (n + 1), 2 * (n + 1)))  # (u_0, θ_0, u_1, θ_1, ...)
    for e in range(n):
        full[2 * e:2 * e + 4, 2 * e:2 * e + 4] += element
    free = full[2:, 2:]
    u, t = np.arange(0, 2 * n, 2), np.arange(1, 2 * n, 2)
    return free[np.ix_(u, u)] - free[np.ix_(u, t)] @ np.linalg.solve(free[np.ix_(t, t)], free[np.ix_(t, u)])


BUILDINGS = {
    "smf4": TruthBuilding("smf4", "steel moment frame", 4, 4.0, 0.6, 0.125, 1.05,
                          (1.0, 0.9, 0.78, 0.62), (2.2, 2.4, 2.7, 3.0), "steel01", 10.0),
    "smf8": TruthBuilding("smf8", "steel moment frame", 8, 4.0, 1.2, 0.0625, 1.35,
                          (1.0, 0.95, 0.9, 0.82, 0.74, 0.66, 0.58, 0.5),
                          (2.0, 2.1, 2.2, 2.4, 2.6, 2.8, 3.0, 3.2), "steel01", 10.0),
    "wall6": TruthBuilding("wall6", "shear wall", 6, 3.5, 0.5, 0.2, 1.0,
                           (1.0, 0.85, 0.72, 0.6, 0.5, 0.42), (1.8, 2.0, 2.2, 2.5, 2.8, 3.0), "hysteretic"),
    "rcf5": TruthBuilding("rcf5", "concrete moment frame", 5, 3.5, 0.8, 0.09375, 1.15,
                          (1.0, 0.92, 0.82, 0.7, 0.55), (2.0, 2.2, 2.4, 2.7, 3.0), "hysteretic", 10.0,
                          pinch_x=0.85, pinch_y=0.5, beta=0.25),
}


#: The sixth system, checked on its own (module text): not in :data:`BUILDINGS`, whose five the documented ranges
#: of the equipment checks are measured on.
BRACED = {
    "bf6": TruthBuilding("bf6", "braced frame", 6, 4.0, 0.6, 1.0 / 6.0, 1.05, (1.0, 1.0, 0.86, 0.86, 0.55, 0.55),
                         (1.6, 1.67, 1.59, 1.9, 1.65, 3.02), "steel01", 2.4),
}

#: The braced frame with braces that buckle, checked on its own beside ``bf6`` (module text).
BUCKLING = {"bf6b": dataclasses.replace(BRACED["bf6"], name="bf6b", law="buckling")}

#: The taller frame, checked on its own (module text).
TALL = {
    "smf12": TruthBuilding("smf12", "steel moment frame", 12, 4.0, 2.0, 0.044, 1.75,
                           (1.0, 1.0, 0.92, 0.92, 0.8, 0.8, 0.66, 0.66, 0.5, 0.5, 0.36, 0.36),
                           (2.0, 2.0, 2.1, 2.1, 2.2, 2.3, 2.4, 2.5, 2.6, 2.8, 3.0, 3.2), "steel01", 10.0),
}


def _build(ops, building: TruthBuilding):
    """The OpenSees model of ``building`` (wiped first): (whether it has the column, k_0 [N/m], F_y [N])."""
    ops.wipe()
    n = building.storeys
    k0 = building.stiffness_n_m()
    weight = n * FLOOR_MASS_KG * GRAVITY_M_S2
    fy = building.yield_ratios() * weight
    column = shear_chain(ops, n, building.storey_height_m,
                         building.bending_rigidity_n_m2() if np.isfinite(building.column_alpha) else None)
    for i in range(1, n + 1):
        storey_spring(ops, i, FLOOR_MASS_KG, float(k0[i - 1]), float(fy[i - 1]), building.hardening,
                      building.law == "steel01", (building.pinch_x, building.pinch_y, building.beta), column,
                      buckling=building.law == "buckling")
    return column, k0, fy


def elf_pattern(building: TruthBuilding) -> np.ndarray:
    """ASCE 7-22 §12.8.3's lateral forces over the base shear, floor 1 to the roof (equal floor weights)."""
    heights = building.storey_height_m * np.arange(1, building.storeys + 1)
    return heights ** building.exponent_k / np.sum(heights ** building.exponent_k)


def pushover(building: TruthBuilding, roof_drift_ratio=0.02, steps=400):
    """Static pushover of the OpenSees building under the ELF pattern, displacement-controlled at the roof.

    Returns (base shear over the weight (steps,), storey drifts [m] (steps, n)), from the same model
    (springs and column) as :func:`truth_response`, without damping."""
    ops, why = load_opensees()
    if ops is None:
        raise RuntimeError(why)
    column, _, _ = _build(ops, building)
    n = building.storeys
    weight = n * FLOOR_MASS_KG * GRAVITY_M_S2
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    for i, share in enumerate(elf_pattern(building), start=1):
        ops.load(i, *([float(share * weight)] + ([0.0, 0.0] if column else [])))
    ops.constraints("Transformation" if column else "Plain")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormDispIncr", 1e-10, 50)
    ops.algorithm("Newton")
    step_m = roof_drift_ratio * n * building.storey_height_m / steps
    ops.integrator("DisplacementControl", n, 1, step_m)
    ops.analysis("Static")
    shear, drifts = np.zeros(steps), np.zeros((steps, n))
    for s in range(steps):
        if ops.analyze(1) != 0:
            raise RuntimeError(f"the pushover of {building.name} failed at step {s}")
        shear[s] = ops.getLoadFactor(1)
        u = np.array([ops.nodeDisp(i, 1) for i in range(n + 1)])
        drifts[s] = np.diff(u)
    ops.wipe()
    return shear, drifts


def pushover_slope_ratio(building: TruthBuilding, roof_drift_ratio: float = 0.02) -> float:
    """The slope of :func:`pushover`'s base shear against roof drift at ``roof_drift_ratio`` over its slope before
    yield, as an engineer reads it off the curve: the central difference over ±0.1 % of roof drift about it (600
    steps to 3 %), over the secant of the first steps (elastic)."""
    shear, drifts = pushover(building, roof_drift_ratio=0.03, steps=600)
    roof = np.cumsum(drifts, axis=1)[:, -1] / (building.storeys * building.storey_height_m)
    at = int(np.searchsorted(roof, roof_drift_ratio))
    tangent = (shear[at + 20] - shear[at - 20]) / (roof[at + 20] - roof[at - 20])
    return float(tangent / (shear[5] / roof[5]))


def pushover_yield_base_shear_g(building: TruthBuilding) -> float:
    """The base shear over the weight when the first storey (any) yields in :func:`pushover`.

    Below first yield the pushover is linear, so the last step with every storey below its yield drift
    F_y/k_0 scales exactly to the step at which the first reaches it. For the flexural wall, the hinge's
    yield (:func:`wall_pushover_yield_base_shear_g`)."""
    if isinstance(building, FlexuralWall):
        return wall_pushover_yield_base_shear_g(building)
    shear, drifts = pushover(building)
    yield_drift = building.yield_ratios() / building.stiffness_n_m() * building.storeys * FLOOR_MASS_KG * GRAVITY_M_S2
    elastic = np.all(np.abs(drifts) < yield_drift, axis=1)
    last = int(np.flatnonzero(elastic)[-1])
    if last == elastic.size - 1:
        raise RuntimeError(f"{building.name} did not yield in the pushover")
    return float(shear[last] * np.min(yield_drift / np.abs(drifts[last])))


def truth_response(building: TruthBuilding, ground_accel_g, dt_s):
    """(absolute floor accelerations [g] (n + 1, samples), storey drifts [m] (n, samples), yield drifts [m])."""
    ops, why = load_opensees()
    if ops is None:
        raise RuntimeError(why)
    n = building.storeys
    column, k0, fy = _build(ops, building)
    omega = np.sqrt(np.linalg.eigvalsh((_chain(k0) + _column(building, k0)) / FLOOR_MASS_KG))[:2]
    if omega.size == 1:
        a0, a1 = 0.0, 2.0 * 0.05 / omega[0]
    else:
        a0, a1 = 0.05 * 2.0 * omega[0] * omega[1] / (omega[0] + omega[1]), 0.05 * 2.0 / (omega[0] + omega[1])
    ops.rayleigh(float(a0), 0.0, 0.0, float(a1))
    substeps = max(1, int(np.ceil(float(dt_s) / SUBSTEP_S - 1e-9)))
    accel, drift = floor_histories(ops, n, ground_accel_g, dt_s, substeps, 1e-10, column, building.name)
    return accel, drift, fy / k0


# --------------------------------------------------------------------------------------------------
# The flexural wall: an elastic cantilever on a concentrated plastic hinge at its base.
# --------------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class FlexuralWall:
    """A slender wall as it bends: ``wall6``'s storeys, floor masses, T_1 and pushover yield base shear, as an
    elastic Euler-Bernoulli cantilever (``elasticBeamColumn``) on a rotational plastic hinge at its base
    (``zeroLength``, ``Hysteretic`` with ``wall6``'s pinching), capacity-designed to stay elastic above it
    (Paulay & Priestley [5]_, ch. 5).

    The hinge's elastic stiffness and the damping follow the concentrated-plasticity practice of Ibarra &
    Krawinkler [8]_ (App. B) and Zareian & Medina [9]_, as OpenSees' examples apply them [10]_: the member (the
    wall) is an elastic element in series with a spring ``n`` times stiffer than the element's rotational
    stiffness (n = 10 there), the element's EI raised by (n + 1)/n so that the assembly is as stiff as the wall;
    the spring's hardening b_s = b/(1 + n(1 − b)) so that the assembly hardens as the wall does (b, the wall's,
    0.02 as ``wall6``'s storeys); stiffness-proportional Rayleigh damping on the elastic element only, its
    coefficient raised by (n + 1)/n, none on the spring, mass-proportional on the floors. The frames' "rotational
    stiffness of the element", 6EI/L, is a member's in double curvature, i.e. two cantilevers of L/2 (3EI/(L/2));
    the wall is one cantilever of height H, so here it is 3EI_el/H, and the hinge's k_θ = n·3EI_el/H =
    (n + 1)·3EI/H with EI the wall's own: the assembly then has the wall's stiffness exactly under a load at the
    roof (and within 1.5 % at the roof under the ELF pattern, n 10). EI is set so that the assembly's T_1 is
    ``period_s`` (T ∝ 1/√EI with the ratios fixed). The yield moment is ``yield_base_shear_g`` W times the ELF
    forces' moment arm Σ C_vx h_x, so that the pushover's base shear at the hinge's yield is that (statics: the
    cantilever is determinate)."""

    name: str
    system: str
    storeys: int
    storey_height_m: float
    period_s: float
    exponent_k: float
    yield_base_shear_g: float
    stiffness_ratio_n: float = 10.0  # the hinge's stiffness over the element's rotational stiffness
    hardening: float = 0.02          # the wall's post-yield stiffness ratio (member, moment vs chord rotation)
    pinch_x: float = 0.7
    pinch_y: float = 0.3
    beta: float = 0.3

    @property
    def height_m(self) -> float:
        return self.storeys * self.storey_height_m

    @property
    def weight_n(self) -> float:
        return self.storeys * FLOOR_MASS_KG * GRAVITY_M_S2

    def yield_moment_n_m(self) -> float:
        heights = self.storey_height_m * np.arange(1, self.storeys + 1)
        return self.yield_base_shear_g * self.weight_n * float(np.sum(elf_pattern(self) * heights))

    def hinge_hardening(self) -> float:
        """b_s = b/(1 + n(1 − b)): the spring's hardening that gives the assembly the wall's b ([10]_, the
        corrected eq. B.5 of [8]_)."""
        n, b = self.stiffness_ratio_n, self.hardening
        return b / (1.0 + n * (1.0 - b))

    def _flexibility(self, ei) -> np.ndarray:
        """Lateral flexibility at the floors [m/N] of the element (EI_el = EI (n+1)/n) on the hinge."""
        n = self.stiffness_ratio_n
        x = self.storey_height_m * np.arange(1, self.storeys + 1)
        lo, hi = np.minimum.outer(x, x), np.maximum.outer(x, x)
        element = lo ** 2 * (3.0 * hi - lo) / (6.0 * ei * (n + 1.0) / n)
        return element + np.outer(x, x) / self.hinge_stiffness_n_m(ei)

    def hinge_stiffness_n_m(self, ei=None) -> float:
        """k_θ = (n + 1) 3EI/H [N m/rad] (class text)."""
        ei = self.bending_rigidity_n_m2() if ei is None else ei
        return (self.stiffness_ratio_n + 1.0) * 3.0 * ei / self.height_m

    def bending_rigidity_n_m2(self) -> float:
        """The wall's EI: the assembly's T_1 (numpy's eigenvalues of its flexibility) is ``period_s``."""
        lam = np.linalg.eigvals(self._flexibility(1.0) * FLOOR_MASS_KG).real.max()  # 1/ω_1² at EI = 1
        return float(lam * (2.0 * np.pi / self.period_s) ** 2)

    def yield_rotation_rad(self) -> float:
        return self.yield_moment_n_m() / self.hinge_stiffness_n_m()


WALLF6 = FlexuralWall("wallf6", "shear wall", 6, 3.5, 0.5, 1.0, 0.36)
BUILDINGS["wallf6"] = WALLF6  # beside the shear buildings: the harness and the checks take every truth building


def _build_wall(ops, wall: FlexuralWall) -> None:
    """The OpenSees model of ``wall`` (wiped first): node 0 fixed, the hinge from 0 to 100, the element up
    through the floors 1..n (axially rigid, rotations free), floor masses."""
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(0, 0.0, 0.0)
    ops.fix(0, 1, 1, 1)
    ops.node(100, 0.0, 0.0)
    ops.fix(100, 1, 1, 0)
    ei = wall.bending_rigidity_n_m2()
    k_theta = wall.hinge_stiffness_n_m(ei)
    m_y, theta_y = wall.yield_moment_n_m(), wall.yield_rotation_rad()
    theta_3 = 100.0 * theta_y
    m_3 = m_y + wall.hinge_hardening() * k_theta * (theta_3 - theta_y)
    ops.uniaxialMaterial("Hysteretic", 1, m_y, theta_y, m_3, theta_3, -m_y, -theta_y, -m_3, -theta_3,
                         wall.pinch_x, wall.pinch_y, 0.0, 0.0, wall.beta)
    ops.element("zeroLength", 1, 0, 100, "-mat", 1, "-dir", 6)  # no -doRayleigh: no damping on the hinge
    ops.geomTransf("Linear", 1)
    n = wall.stiffness_ratio_n
    below = 100
    for i in range(1, wall.storeys + 1):
        ops.node(i, 0.0, i * wall.storey_height_m)
        ops.fix(i, 0, 1, 0)
        ops.mass(i, FLOOR_MASS_KG, 0.0, 0.0)
        ops.element("elasticBeamColumn", 10 + i, below, i, 1e12, 1.0, ei * (n + 1.0) / n, 1)
        below = i


def wall_periods_s(wall: FlexuralWall, modes=2) -> np.ndarray:
    """The OpenSees model's periods."""
    ops, why = load_opensees()
    if ops is None:
        raise RuntimeError(why)
    _build_wall(ops, wall)
    periods = 2.0 * np.pi / np.sqrt(np.array(ops.eigen("-fullGenLapack", modes)))
    ops.wipe()
    return periods


def wall_pushover(wall: FlexuralWall, roof_drift_ratio=0.01, steps=400):
    """Static pushover of the flexural wall under the ELF pattern, displacement-controlled at the roof:
    (base shear over the weight (steps,), roof displacement [m] (steps,), hinge rotation [rad] (steps,))."""
    ops, why = load_opensees()
    if ops is None:
        raise RuntimeError(why)
    _build_wall(ops, wall)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    for i, share in enumerate(elf_pattern(wall), start=1):
        ops.load(i, float(share * wall.weight_n), 0.0, 0.0)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormDispIncr", 1e-12, 50)
    ops.algorithm("Newton")
    ops.integrator("DisplacementControl", wall.storeys, 1, roof_drift_ratio * wall.height_m / steps)
    ops.analysis("Static")
    shear, roof, rotation = np.zeros(steps), np.zeros(steps), np.zeros(steps)
    for s in range(steps):
        if ops.analyze(1) != 0:
            raise RuntimeError(f"the pushover of {wall.name} failed at step {s}")
        shear[s] = ops.getLoadFactor(1)
        roof[s] = ops.nodeDisp(wall.storeys, 1)
        rotation[s] = ops.nodeDisp(100, 3)
    ops.wipe()
    return shear, roof, rotation


def wall_pushover_yield_base_shear_g(wall: FlexuralWall) -> float:
    """The pushover's base shear over the weight when the hinge yields (scaled from the last elastic step)."""
    shear, _, rotation = wall_pushover(wall)
    theta_y = wall.yield_rotation_rad()
    elastic = np.abs(rotation) < theta_y
    last = int(np.flatnonzero(elastic)[-1])
    if last == elastic.size - 1:
        raise RuntimeError(f"{wall.name} did not yield in the pushover")
    return float(shear[last] * theta_y / abs(rotation[last]))


def wall_history(wall: FlexuralWall, ground_accel_g, dt_s):
    """(absolute floor accelerations [g] (n + 1, samples), storey drifts [m] (n, samples), the wall's rotation
    ductility) under the ground motion; damping as the class text says (modes 1 and 2, 5 %).

    The ductility is the wall's, not the hinge's (whose elastic rotation is the device's 1/(n + 1) of the
    wall's): 1 + θ_p/θ_y with θ_p the hinge's peak plastic rotation and θ_y = M_y H/(3EI) the wall's chord
    rotation at yield under a load at the roof (the cantilever's displacement ductility)."""
    ops, why = load_opensees()
    if ops is None:
        raise RuntimeError(why)
    _build_wall(ops, wall)
    omega = np.sqrt(np.array(ops.eigen("-fullGenLapack", 2)))
    a0 = 0.05 * 2.0 * omega[0] * omega[1] / (omega[0] + omega[1])
    a1 = 0.05 * 2.0 / (omega[0] + omega[1])
    n = wall.stiffness_ratio_n
    # mass-proportional on the floors; stiffness-proportional on the elastic elements only (the zeroLength
    # hinge has no -doRayleigh), raised by (n + 1)/n (Zareian & Medina 2010, as the OpenSees examples do)
    ops.rayleigh(float(a0), 0.0, 0.0, float(a1 * (n + 1.0) / n))
    rotation = [0.0]
    substeps = max(1, int(np.ceil(float(dt_s) / SUBSTEP_S - 1e-9)))
    accel, drift = floor_histories(ops, wall.storeys, ground_accel_g, dt_s, substeps, 1e-10, True, wall.name,
                                   each_sample=lambda o: rotation.append(o.nodeDisp(100, 3)))
    plastic = max(float(np.max(np.abs(rotation))) - wall.yield_rotation_rad(), 0.0)
    return accel, drift, 1.0 + plastic / ((n + 1.0) * wall.yield_rotation_rad())
