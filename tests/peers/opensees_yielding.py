"""OpenSeesPy models of yielding shear buildings: the test-only peer of :mod:`assess.building.nonlinear`.

A chain of ``zeroLength`` storey springs (``-doRayleigh 1``) whose material is ``Steel01``
(F_y, k_0, b; no isotropic hardening) for the bilinear law or ``Hysteretic`` (a bilinear
backbone F_y at F_y/k_0, then slope b k_0 to 100 yield drifts; pinchX, pinchY, no damage,
β) for the pinching law; Rayleigh damping a_0 M + a_1 K on the committed tangent
(``rayleigh(a0, 0, 0, a1)``: betaKcomm); with the stick's EI, an elastic column
(``elasticBeamColumn``, axially rigid) beside the springs, tied at the floors; Newmark average acceleration with Newton
iterations (``NormDispIncr`` 1e-12) at the substep given.
"""
from __future__ import annotations

import numpy as np

from peers.opensees_shear import GRAVITY_M_S2, load_opensees


def shear_chain(ops, storeys, storey_height_m, bending_rigidity_n_m2=None):
    """The floors' nodes: a 1-D chain, or (with ``bending_rigidity_n_m2``) an axially rigid elastic column on
    nodes 0..n, each spring running from node 1000 + i (tied to floor i - 1) to floor i. Returns whether the
    column is there."""
    column = bending_rigidity_n_m2 is not None
    if column:
        ops.model("basic", "-ndm", 2, "-ndf", 3)
        for i in range(storeys + 1):
            ops.node(i, 0.0, i * storey_height_m)
        ops.fix(0, 1, 1, 1)
        ops.geomTransf("Linear", 1)
        for i in range(1, storeys + 1):
            ops.fix(i, 0, 1, 0)
            ops.element("elasticBeamColumn", 2000 + i, i - 1, i, 1e12, 1.0, float(bending_rigidity_n_m2), 1)
            ops.node(1000 + i, 0.0, i * storey_height_m)
            ops.fix(1000 + i, 0, 1, 1)
            ops.equalDOF(i - 1, 1000 + i, 1)
    else:
        ops.model("basic", "-ndm", 1, "-ndf", 1)
        for i in range(storeys + 1):
            ops.node(i, 0.0)
        ops.fix(0, 1)
    return column


#: A buckling brace (:func:`buckling_brace_pair`): its compression strength over its tension yield, the share of it
#: left after buckling, the brace's deformation at which that share is reached over its buckling deformation, and
#: the Hysteretic pinching (pinchX, pinchY) of a buckled brace pulled straight again.
BRACE_BUCKLING_RATIO = 0.5
BRACE_POST_BUCKLING_RATIO = 0.3
BRACE_POST_BUCKLING_DEFORMATION_RATIO = 5.0
BRACE_PINCH = (0.4, 0.2)


def buckling_brace_pair(ops, tag, k0, fy, hardening):
    """A storey's two braces, one pulled while the other is pushed, as the material ``tag`` (``Parallel`` of two
    mirrored ``Hysteretic`` braces, ``tag + 1`` and ``tag + 2``): each brace of stiffness k0/2 yields in tension at
    F_y (its drift 2 F_y/k0) and hardens at ``hardening`` of its stiffness; it buckles in compression at
    :data:`BRACE_BUCKLING_RATIO` F_y (drift F_y/k0, where the storey's force is F_y: the storey's first
    nonlinearity at the storey's yield drift and strength), its strength then falling to
    :data:`BRACE_POST_BUCKLING_RATIO` of that at :data:`BRACE_POST_BUCKLING_DEFORMATION_RATIO` times its buckling
    drift and staying there; pinched loops (:data:`BRACE_PINCH`), no cyclic damage. The storey's backbone, pushed one
    way: F_y at F_y/k0, 1.41 F_y at 2 F_y/k0 (the pulled brace yielding, the pushed one at 0.41 F_y), then falling
    as the pushed brace loses its strength."""
    kb, dy = k0 / 2.0, fy / k0
    tension = [(fy, 2.0 * dy)] + [(fy + hardening * kb * (d - 2.0 * dy), d) for d in (51.0 * dy, 100.0 * dy)]
    buckling = BRACE_BUCKLING_RATIO * fy
    after = BRACE_POST_BUCKLING_RATIO * buckling
    compression = [(buckling, dy), (after, BRACE_POST_BUCKLING_DEFORMATION_RATIO * dy), (after, 100.0 * dy)]
    pinch_x, pinch_y = BRACE_PINCH
    pulled = [v for f, d in tension for v in (f, d)] + [-v for f, d in compression for v in (f, d)]
    pushed = [v for f, d in compression for v in (f, d)] + [-v for f, d in tension for v in (f, d)]
    ops.uniaxialMaterial("Hysteretic", tag + 1, *pulled, pinch_x, pinch_y, 0.0, 0.0, 0.0)
    ops.uniaxialMaterial("Hysteretic", tag + 2, *pushed, pinch_x, pinch_y, 0.0, 0.0, 0.0)
    ops.uniaxialMaterial("Parallel", tag, tag + 1, tag + 2)


def storey_spring(ops, i, mass_kg, k0, fy, hardening, bilinear, pinch=(0.0, 0.0, 0.0), column=False,
                  buckling=False):
    """Floor i's mass and the spring of storey i: ``Steel01`` (bilinear), ``Hysteretic`` with a bilinear
    backbone to 100 yield drifts and ``pinch`` = (pinchX, pinchY, β), or (``buckling``) a pair of buckling braces
    (:func:`buckling_brace_pair`)."""
    ops.mass(i, *([mass_kg] + ([0.0, 0.0] if column else [])))
    if buckling:
        buckling_brace_pair(ops, 100 * i, k0, fy, hardening)
        ops.element("zeroLength", i, 1000 + i if column else i - 1, i, "-mat", 100 * i, "-dir", 1, "-doRayleigh", 1)
        return
    if bilinear:
        ops.uniaxialMaterial("Steel01", i, fy, k0, hardening)
    else:
        dy = fy / k0
        d3 = 100.0 * dy
        f3 = fy + hardening * k0 * (d3 - dy)
        pinch_x, pinch_y, beta = pinch
        ops.uniaxialMaterial("Hysteretic", i, fy, dy, f3, d3, -fy, -dy, -f3, -d3, pinch_x, pinch_y, 0.0, 0.0,
                             beta)
    ops.element("zeroLength", i, 1000 + i if column else i - 1, i, "-mat", i, "-dir", 1, "-doRayleigh", 1)


def floor_histories(ops, storeys, ground_accel_g, dt_s, substeps, tolerance_m, column, name="", each_sample=None):
    """Newmark average acceleration with Newton iterations under the ground motion, ``substeps`` a sample;
    (absolute floor accelerations [g] (n + 1, samples), storey drifts [m] (n, samples)). ``each_sample(ops)``,
    where given, is called after every sample (to read more of the model). Wipes the model."""
    ground = np.asarray(ground_accel_g, dtype=float)
    ops.timeSeries("Path", 1, "-dt", float(dt_s), "-values", *(ground * GRAVITY_M_S2).tolist())
    ops.pattern("UniformExcitation", 1, 1, "-accel", 1)
    ops.constraints("Transformation" if column else "Plain")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormDispIncr", tolerance_m, 50)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    accel = np.zeros((storeys + 1, ground.size))
    drift = np.zeros((storeys, ground.size))
    accel[0] = ground
    step = float(dt_s) / substeps
    for i in range(1, ground.size):
        if ops.analyze(substeps, step) != 0:
            raise RuntimeError(f"OpenSees failed at step {i}" + (f" of {name}" if name else ""))
        below = 0.0
        for k in range(1, storeys + 1):
            accel[k, i] = ops.nodeAccel(k, 1) / GRAVITY_M_S2 + ground[i]
            u = ops.nodeDisp(k, 1)
            drift[k - 1, i] = u - below
            below = u
        if each_sample is not None:
            each_sample(ops)
    ops.wipe()
    return accel, drift


def yielding_floor_accelerations(stick, ground_accel_g, dt_s, substeps):
    """(absolute floor accelerations [g] (n + 1, samples), storey drifts [m] (n, samples)) from OpenSees."""
    ops, why = load_opensees()
    if ops is None:
        raise RuntimeError(why)
    ops.wipe()
    n = stick.storeys
    column = shear_chain(ops, n, float(np.mean(stick.storey_heights_m)), stick.bending_rigidity_n_m2)
    for i in range(1, n + 1):
        storey_spring(ops, i, float(stick.floor_masses_kg[i - 1]), float(stick.stiffness_n_m[i - 1]),
                      float(stick.yield_force_n[i - 1]), float(np.broadcast_to(stick.hardening, (n,))[i - 1]),
                      stick.law == "bilinear",
                      (float(stick.pinch_x), float(stick.pinch_y), float(stick.unloading_beta)), column,
                      buckling=stick.law == "buckling")
    a0, a1 = stick.rayleigh
    if stick.damping_stiffness == "initial":
        ops.rayleigh(float(a0), 0.0, float(a1), 0.0)
    else:
        ops.rayleigh(float(a0), 0.0, 0.0, float(a1))
    return floor_histories(ops, n, ground_accel_g, dt_s, substeps, 1e-12, column)
