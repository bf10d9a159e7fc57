"""Three yielding OpenSeesPy buildings of our own: the truth the equipment checks measure the tool against.

Not built from the tool's stick (:mod:`assess.building.nonlinear`) but from numbers of their own, as a
structural engineer's model of a designed building would be: shear buildings of ``zeroLength`` storey
springs (``-doRayleigh 1``), equal floor masses, each storey's stiffness tapering up the height (scaled so
that T_1 is the building's), each storey's strength its ASCE 7-22 §12.8 design shear (computed here by
hand, the numbers in :data:`BUILDINGS`) times an overstrength that grows up the height (upper storeys
sized for drift, gravity and least member sizes are stronger than their design shear asks), Rayleigh
damping 5 % at modes 1 and 2 on the committed tangent stiffness, Newmark average acceleration with
Newton iterations at 1 ms substeps.

* ``smf4``: steel special moment frame, 4 storeys of 4 m, T_1 0.6 s; ``Steel01`` (b 0.02). Design at
  S_DS 1.0, S_D1 0.6 g, Risk Category II: R 8, C_s = min(1.0/8, 0.6/(0.6·8)) = 0.125, k = 1.05.
* ``smf8``: the same system, 8 storeys of 4 m, T_1 1.2 s: C_s = min(0.125, 0.6/(1.2·8)) = 0.0625,
  k = 1.35.
* ``wall6``: reinforced-concrete special shear wall, 6 storeys of 3.5 m, T_1 0.5 s; ``Hysteretic``
  with pinching (pinchX 0.7, pinchY 0.3, β 0.3: more pinched than the tool's 0.8/0.4/0.4) on a bilinear
  backbone (b 0.02); R 5: C_s = min(1.0/5, 0.6/(0.5·5)) = 0.2, k = 1.

``yield_base_shear_g`` of each is its first storey's yield shear over the weight: what a pushover
gives as the base shear at yield, the number an engineer would write in the building sheet.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from peers.opensees_shear import GRAVITY_M_S2, load_opensees

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
    law: str             # "steel01" or "hysteretic"
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

    def stiffness_n_m(self) -> np.ndarray:
        """Storey stiffnesses with the building's profile, scaled so that T_1 is ``period_s``."""
        k = np.asarray(self.stiffness_profile, dtype=float)
        omega2 = np.linalg.eigvalsh(_chain(k) / FLOOR_MASS_KG)
        return k * (2.0 * np.pi / self.period_s) ** 2 / omega2[0]


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


BUILDINGS = {
    "smf4": TruthBuilding("smf4", "steel moment frame", 4, 4.0, 0.6, 0.125, 1.05,
                          (1.0, 0.9, 0.78, 0.62), (2.2, 2.4, 2.7, 3.0), "steel01"),
    "smf8": TruthBuilding("smf8", "steel moment frame", 8, 4.0, 1.2, 0.0625, 1.35,
                          (1.0, 0.95, 0.9, 0.82, 0.74, 0.66, 0.58, 0.5),
                          (2.0, 2.1, 2.2, 2.4, 2.6, 2.8, 3.0, 3.2), "steel01"),
    "wall6": TruthBuilding("wall6", "shear wall", 6, 3.5, 0.5, 0.2, 1.0,
                           (1.0, 0.85, 0.72, 0.6, 0.5, 0.42), (1.8, 2.0, 2.2, 2.5, 2.8, 3.0), "hysteretic"),
}


def truth_response(building: TruthBuilding, ground_accel_g, dt_s):
    """(absolute floor accelerations [g] (n + 1, samples), storey drifts [m] (n, samples), yield drifts [m])."""
    ops, why = load_opensees()
    if ops is None:
        raise RuntimeError(why)
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    n = building.storeys
    k0 = building.stiffness_n_m()
    weight = n * FLOOR_MASS_KG * GRAVITY_M_S2
    fy = building.yield_ratios() * weight
    for i in range(n + 1):
        ops.node(i, 0.0)
    ops.fix(0, 1)
    for i in range(1, n + 1):
        ops.mass(i, FLOOR_MASS_KG)
        k, f, b = float(k0[i - 1]), float(fy[i - 1]), building.hardening
        if building.law == "steel01":
            ops.uniaxialMaterial("Steel01", i, f, k, b)
        else:
            dy = f / k
            d3 = 100.0 * dy
            f3 = f + b * k * (d3 - dy)
            ops.uniaxialMaterial("Hysteretic", i, f, dy, f3, d3, -f, -dy, -f3, -d3, building.pinch_x,
                                 building.pinch_y, 0.0, 0.0, building.beta)
        ops.element("zeroLength", i, i - 1, i, "-mat", i, "-dir", 1, "-doRayleigh", 1)
    omega = np.sqrt(np.linalg.eigvalsh(_chain(k0) / FLOOR_MASS_KG))[:2]
    if omega.size == 1:
        a0, a1 = 0.0, 2.0 * 0.05 / omega[0]
    else:
        a0, a1 = 0.05 * 2.0 * omega[0] * omega[1] / (omega[0] + omega[1]), 0.05 * 2.0 / (omega[0] + omega[1])
    ops.rayleigh(float(a0), 0.0, 0.0, float(a1))
    ground = np.asarray(ground_accel_g, dtype=float)
    ops.timeSeries("Path", 1, "-dt", float(dt_s), "-values", *(ground * GRAVITY_M_S2).tolist())
    ops.pattern("UniformExcitation", 1, 1, "-accel", 1)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormDispIncr", 1e-10, 50)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    substeps = max(1, int(np.ceil(float(dt_s) / SUBSTEP_S - 1e-9)))
    accel = np.zeros((n + 1, ground.size))
    drift = np.zeros((n, ground.size))
    accel[0] = ground
    for step in range(1, ground.size):
        if ops.analyze(substeps, float(dt_s) / substeps) != 0:
            raise RuntimeError(f"OpenSees failed at step {step} of {building.name}")
        below = 0.0
        for k in range(1, n + 1):
            accel[k, step] = ground[step] + ops.nodeAccel(k, 1) / GRAVITY_M_S2
            u = ops.nodeDisp(k, 1)
            drift[k - 1, step] = u - below
            below = u
    ops.wipe()
    return accel, drift, fy / k0
