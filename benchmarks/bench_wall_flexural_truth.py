"""The tool's shear-wall stick against a FLEXURAL OpenSees wall: does the wall's excess sliding come from its truth?

Run: python benchmarks/bench_wall_flexural_truth.py [--levels DE,MCE_R] [--hinge 10]
     (needs openseespy and pyslammer; about a minute a level)

The project's truth wall (tests/peers/opensees_buildings.py ``wall6``) is a shear building of pinching storey
springs, its storeys 42 % as stiff at the top as at the base, with T_2/T_1 0.38. A slender wall bends: here
the same 6 storeys of 3.5 m, floor masses and T_1 0.5 s as an elastic Euler-Bernoulli cantilever
(``elasticBeamColumn``, EI scaled to T_1) on a base hinge (``zeroLength`` rotational ``Hysteretic`` with wall6's
pinching, b 0.02), capacity-designed to stay elastic above it (Paulay & Priestley 1992, ch. 5): T_2/T_1 0.15
to 0.16. Its yield moment is 0.36 W times the ELF moment arm, so that its pushover base shear at yield is
wall6's 0.36 W, and the tool is given that (``given``); also ``design x 2`` and ``elastic``. The hinge's
elastic rotational stiffness ``--hinge`` × EI/H is not known from the literature used here, and it moves the
answer: with 10, sliding gm 1.33 (σ ln 0.56) at DE and 1.25 (0.42) at MCE_R, the roof's PFA 1.01 and 0.94
of the truth's; with 100 (a nearly rigid-plastic hinge), 0.99 (0.50) and 0.99 (0.40), the roof's PFA 0.93
and 0.72. So this is an exploration, not a check: against a bending wall the tool's wall stick is within
the issue's [0.8, 1.25] or just above it, depending on the hinge. The flexural wall's roof PFA/PGA at DE,
2.2 to 2.9, brackets ASCE 7-22's H_f/R_μ (2.27); wall6's is 1.86. Same records, items and measures as benchmarks/bench_yielding_equipment.py.
"""
from __future__ import annotations

import argparse
import sys
import tempfile
from contextlib import contextmanager
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(REPO / "tests")]

from assess.building import yielding as yielding_module  # noqa: E402
from peers.opensees_buildings import BUILDINGS, FLOOR_MASS_KG, elf_pattern  # noqa: E402
from peers.opensees_shear import GRAVITY_M_S2, load_opensees  # noqa: E402
from peers.opensees_yielding import floor_histories  # noqa: E402
from peers.yielding_equipment import LEVELS, _key, assess, compare, ground_suite, workbook  # noqa: E402

WALL = BUILDINGS["wall6"]
YIELD_BASE_SHEAR_G = 0.36  # wall6's pushover base shear at yield
HARDENING = 0.02


class FlexuralWall:
    """The cantilever on its base hinge; ``hinge`` is the hinge's elastic rotational stiffness over EI/H."""

    def __init__(self, ops, hinge):
        self.ops, self.hinge = ops, float(hinge)
        n, h = WALL.storeys, WALL.storey_height_m
        heights = h * np.arange(1, n + 1)
        weight = n * FLOOR_MASS_KG * GRAVITY_M_S2
        self.yield_moment = YIELD_BASE_SHEAR_G * weight * float(np.sum(elf_pattern(WALL) * heights))
        self.bending_rigidity = 1e10
        period = self.periods()[0]
        self.bending_rigidity *= (period / WALL.period_s) ** 2  # T scales as 1/sqrt(EI), the hinge with it

    def build(self):
        """The OpenSees model; returns the hinge's yield rotation."""
        ops, n, h = self.ops, WALL.storeys, WALL.storey_height_m
        ops.wipe()
        ops.model("basic", "-ndm", 2, "-ndf", 3)
        ops.node(0, 0.0, 0.0)
        ops.fix(0, 1, 1, 1)
        ops.node(100, 0.0, 0.0)
        ops.fix(100, 1, 1, 0)
        k_theta = self.hinge * self.bending_rigidity / (n * h)
        yield_rotation = self.yield_moment / k_theta
        m3, r3 = self.yield_moment + HARDENING * k_theta * 99 * yield_rotation, 100 * yield_rotation
        ops.uniaxialMaterial("Hysteretic", 1, self.yield_moment, yield_rotation, m3, r3, -self.yield_moment,
                             -yield_rotation, -m3, -r3, WALL.pinch_x, WALL.pinch_y, 0.0, 0.0, WALL.beta)
        ops.element("zeroLength", 1, 0, 100, "-mat", 1, "-dir", 6, "-doRayleigh", 1)
        ops.geomTransf("Linear", 1)
        below = 100
        for i in range(1, n + 1):
            ops.node(i, 0.0, i * h)
            ops.fix(i, 0, 1, 0)
            ops.mass(i, FLOOR_MASS_KG, 0.0, 0.0)
            ops.element("elasticBeamColumn", 10 + i, below, i, 1e12, 1.0, self.bending_rigidity, 1)
            below = i
        return yield_rotation

    def periods(self):
        self.build()
        return 2.0 * np.pi / np.sqrt(np.array(self.ops.eigen("-fullGenLapack", 2)))

    def history(self, accel_g, dt_s):
        """The floors' absolute accelerations as the yielding route's StickHistory (ductility: the hinge's)."""
        ops, n, h = self.ops, WALL.storeys, WALL.storey_height_m
        yield_rotation = self.build()
        omega = np.sqrt(np.array(ops.eigen("-fullGenLapack", 2)))
        ops.rayleigh(float(0.05 * 2 * omega[0] * omega[1] / (omega[0] + omega[1])), 0.0, 0.0,
                     float(0.05 * 2 / (omega[0] + omega[1])))
        rotation = [0.0]  # the hinge's, after every sample
        substeps = max(1, int(np.ceil(dt_s / 0.001 - 1e-9)))
        accel, drift = floor_histories(ops, n, accel_g, dt_s, substeps, 1e-10, True,
                                       each_sample=lambda ops: rotation.append(ops.nodeDisp(100, 3)))
        ductility = np.full(n, np.nan)
        ductility[0] = np.abs(rotation).max() / yield_rotation
        return yielding_module.StickHistory(accel, np.abs(drift).max(axis=1) / h, ductility, False)


@contextmanager
def flexural_floors(wall, suite):
    """The yielding route's stick swapped for the flexural wall under each ground history of ``suite``."""
    answers = {_key(accel): wall.history(accel, dt) for _, accel, dt in suite}
    original = yielding_module.stick_history
    yielding_module.stick_history = lambda building, ground_accel_g, dt_s: answers[_key(ground_accel_g)]
    try:
        yield answers
    finally:
        yielding_module.stick_history = original


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--levels", default="DE")
    parser.add_argument("--hinge", type=float, default=10.0, help="the hinge's elastic rotational stiffness / (EI/H)")
    args = parser.parse_args(argv)
    ops, why = load_opensees()
    if ops is None:
        sys.exit(why)
    wall = FlexuralWall(ops, args.hinge)
    print("T1, T2 [s]:", np.round(wall.periods(), 4))
    routes = {"given": [["response", "yielding"], ["yield_base_shear_g", YIELD_BASE_SHEAR_G]],
              "design x 2": [["response", "yielding"], ["overstrength", 2.0]],
              "elastic": [["response", "elastic"]]}
    for level in args.levels.split(","):
        suite = ground_suite(11, WALL.period_s, LEVELS[level])
        with tempfile.TemporaryDirectory() as tmp:
            folder = Path(tmp)
            with flexural_floors(wall, suite) as answers:
                reference = assess(workbook(folder, WALL, suite, level, [["response", "yielding"]]), level)
            hinge = np.median([a.ductility[0] for a in answers.values()])
            print(f"{level}: the hinge's rotation ductility, median {hinge:.1f}")
            for route, rows in routes.items():
                c = compare(assess(workbook(folder, WALL, suite, level, rows), level), reference)
                print(f"{level} {route:10s} gm {c['gm']:.3f} sigma_ln {c['sigma_ln']:.3f} PFA tool/truth mid "
                      f"{c['pfa_mid']:.3f} roof {c['pfa_roof']:.3f} overturn verdicts {c['overturn_agree']:.2f} "
                      f"({c['n_overturn']}) risk class {c['class_agree']:.2f}", flush=True)
            floors = reference[0].floors.set_index("floor")["pfa_over_pga_median"]
            print(f"{level} the flexural wall's PFA/PGA by floor:", floors.round(3).tolist())


if __name__ == "__main__":
    main()
