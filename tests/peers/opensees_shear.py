"""OpenSeesPy models of linear buildings: the test-only peer of :mod:`assess.building`.

Two models, both with the mass lumped at the floors and the base fixed:

* :func:`shear_building_floor_accelerations`: a chain of storey springs (``zeroLength``
  elements with an elastic material, one per storey), under a ground acceleration
  record (``UniformExcitation``), stepped by Newmark's average-acceleration method at a
  fraction of the record's step. Damping: OpenSees' own ``modalDamping`` (the same ζ
  for every mode), or Rayleigh damping on two modes. ``zeroLength`` elements ignore
  Rayleigh damping unless built with ``-doRayleigh 1``: without it the floor
  histories were 20-80 % off.
* :func:`shear_flexural_periods`: an Euler-Bernoulli column (``elasticBeamColumn``)
  and storey springs in parallel, tied at the floors, for the periods of the
  shear-flexural model.

On this machine ``openseespy`` imports only after the libraries bundled in its
``openseespylinux`` wheel (``lib/``: libquadmath, libgfortran, libgomp, libblas,
liblapack) are loaded globally (:func:`load_opensees`); with the system's BLAS/LAPACK
installed it imports directly.
"""
from __future__ import annotations

import ctypes
import importlib.util
import os

import numpy as np

GRAVITY_M_S2 = 9.80665
_BUNDLED = ("libquadmath.so.0", "libgfortran.so.4", "libgomp.so.1", "libblas.so.3", "liblapack.so.3")
_STATE = {}


def load_opensees():
    """``(openseespy.opensees, None)`` or ``(None, why not)``."""
    if "ops" in _STATE:
        return _STATE["ops"], _STATE["why"]
    ops, why = None, None
    try:
        spec = importlib.util.find_spec("openseespylinux")
        if spec is not None and spec.submodule_search_locations:
            folder = os.path.join(list(spec.submodule_search_locations)[0], "lib")
            for name in _BUNDLED:
                path = os.path.join(folder, name)
                if os.path.exists(path):
                    ctypes.CDLL(path, mode=ctypes.RTLD_GLOBAL)
        import openseespy.opensees as ops  # noqa: F811
    except Exception as error:  # ImportError, RuntimeError('Failed to import openseespy on Linux.')
        ops, why = None, f"openseespy is not importable here ({type(error).__name__}: {error})"
    _STATE["ops"], _STATE["why"] = ops, why
    return ops, why


def _storey_chain(ops, storey_stiffness, floor_masses):
    """Nodes 0 (base, fixed) .. n, all at the origin, springs between consecutive ones (ndm 1)."""
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    n = len(storey_stiffness)
    for i in range(n + 1):
        ops.node(i, 0.0)
    ops.fix(0, 1)
    for i in range(1, n + 1):
        ops.mass(i, float(floor_masses[i - 1]))
        ops.uniaxialMaterial("Elastic", i, float(storey_stiffness[i - 1]))
        ops.element("zeroLength", i, i - 1, i, "-mat", i, "-dir", 1, "-doRayleigh", 1)
    return n


def shear_building_periods(storey_stiffness, floor_masses):
    """Periods [s] of the storey chain (OpenSees ``eigen``, full generalised LAPACK solver)."""
    ops, why = load_opensees()
    if ops is None:
        raise RuntimeError(why)
    n = _storey_chain(ops, storey_stiffness, floor_masses)
    eigenvalues = ops.eigen("-fullGenLapack", n)
    return 2 * np.pi / np.sqrt(np.array(eigenvalues))


def _stick(ops, storey_stiffness, floor_masses, storey_height_m, bending_rigidity_n_m2):
    """The column (EI) and the storey springs in parallel (see :func:`shear_flexural_periods`), ndm 2."""
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    n = len(storey_stiffness)
    for i in range(n + 1):
        ops.node(i, 0.0, i * storey_height_m)
    ops.fix(0, 1, 1, 1)
    ops.geomTransf("Linear", 1)
    for i in range(1, n + 1):
        ops.fix(i, 0, 1, 0)
        ops.mass(i, float(floor_masses[i - 1]), 0.0, 0.0)
        ops.element("elasticBeamColumn", i, i - 1, i, 1e12, 1.0, float(bending_rigidity_n_m2), 1)
        aux = 1000 + i
        ops.node(aux, 0.0, i * storey_height_m)
        ops.fix(aux, 0, 1, 1)
        ops.equalDOF(i - 1, aux, 1)
        ops.uniaxialMaterial("Elastic", i, float(storey_stiffness[i - 1]))
        ops.element("zeroLength", 1000 + i, aux, i, "-mat", i, "-dir", 1, "-doRayleigh", 1)
    return n


def shear_building_floor_accelerations(storey_stiffness, floor_masses, ground_accel_g, dt_s, *,
                                       damping=0.05, rayleigh_modes=None, substeps=None,
                                       bending_rigidity_n_m2=None, storey_height_m=3.5):
    """Absolute floor accelerations [g] of the storey chain under a ground record.

    Parameters
    ----------
    storey_stiffness : array-like, (n,)
        k_i [N/m], storey 1 (ground to floor 1) to the roof.
    floor_masses : array-like, (n,)
        m_i [kg], floor 1 to the roof.
    ground_accel_g : array-like
        Ground acceleration [g] at 0, dt, 2dt, ... (linear between samples: ``Path`` series).
    dt_s : float
        Record step [s].
    damping : float
        ζ: with ``rayleigh_modes=None`` OpenSees' ``modalDamping`` for every mode; otherwise
        Rayleigh damping with ζ at the two modes given (1-based, e.g. ``(1, 3)``).
    bending_rigidity_n_m2, storey_height_m : float, optional
        With EI given, a column of that rigidity stands beside the storey springs, tied at
        the floors (the shear-flexural stick of :func:`shear_flexural_periods`).
    substeps : int, optional
        Newmark steps per record step; by default enough for steps of at most 1 ms (Newmark's
        error is O(Δt²): at 5 ms steps the floors of a 3-storey building were 1.5 % RMS off
        the exact answer, at 1.25 ms 0.1 %).

    Returns
    -------
    (accel, periods_s, zeta) : ndarray (n + 1, n_samples), ndarray (n,), ndarray (n,)
        Row k is floor k (row 0 the ground); the model's periods and the damping ratio
        each mode has (with Rayleigh damping, a0/(2ω) + a1 ω/2).
    """
    ops, why = load_opensees()
    if ops is None:
        raise RuntimeError(why)
    if bending_rigidity_n_m2 is None:
        n = _storey_chain(ops, storey_stiffness, floor_masses)
    else:
        n = _stick(ops, storey_stiffness, floor_masses, storey_height_m, bending_rigidity_n_m2)
    omega = np.sqrt(np.array(ops.eigen("-fullGenLapack", n)))
    if rayleigh_modes is None:
        ops.modalDamping(float(damping))
        zeta = np.full(n, float(damping))
    else:
        wi, wj = omega[rayleigh_modes[0] - 1], omega[rayleigh_modes[1] - 1]
        a0 = damping * 2 * wi * wj / (wi + wj)
        a1 = damping * 2 / (wi + wj)
        ops.rayleigh(a0, 0.0, 0.0, a1)  # stiffness-proportional on the initial stiffness
        zeta = a0 / (2 * omega) + a1 * omega / 2
    ground = np.asarray(ground_accel_g, dtype=float)
    ops.timeSeries("Path", 1, "-dt", float(dt_s), "-values", *(ground * GRAVITY_M_S2).tolist())
    ops.pattern("UniformExcitation", 1, 1, "-accel", 1)
    ops.constraints("Plain" if bending_rigidity_n_m2 is None else "Transformation")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Linear")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    out = np.zeros((n + 1, ground.size))
    out[0] = ground
    if substeps is None:
        substeps = int(np.ceil(float(dt_s) / 0.001 - 1e-9))
    step = float(dt_s) / substeps
    for i in range(1, ground.size):
        if ops.analyze(substeps, step) != 0:
            raise RuntimeError(f"OpenSees failed at step {i}")
        for k in range(1, n + 1):
            out[k, i] = ops.nodeAccel(k, 1) / GRAVITY_M_S2 + ground[i]
    ops.wipe()
    return out, 2 * np.pi / omega, zeta


def shear_flexural_periods(storeys, storey_height_m, storey_stiffness_n_m, bending_rigidity_n_m2,
                           floor_mass_kg=1.0):
    """Periods [s] of a column (EI) and storey springs (k) in parallel, tied at every floor.

    The column is ``elasticBeamColumn`` elements (axially rigid, E = 1, I = EI) between
    nodes at the floors, rotations free, vertical displacements fixed; each storey spring
    is a ``zeroLength`` element from an auxiliary node carrying the floor below's
    horizontal displacement (``equalDOF``) to the floor's node.
    """
    ops, why = load_opensees()
    if ops is None:
        raise RuntimeError(why)
    n = _stick(ops, np.full(int(storeys), float(storey_stiffness_n_m)), np.full(int(storeys), float(floor_mass_kg)),
               storey_height_m, bending_rigidity_n_m2)
    ops.constraints("Transformation")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    eigenvalues = ops.eigen("-fullGenLapack", n)
    ops.wipe()
    return 2 * np.pi / np.sqrt(np.array(eigenvalues))
