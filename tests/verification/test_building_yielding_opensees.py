"""The yielding stick (assess.building.nonlinear) against OpenSeesPy with the same springs.

Shear buildings of 3, 6 and 12 storeys (T_1 0.35, 0.70, 1.40 s; equal floor masses; the stick of
:func:`~assess.building.nonlinear.yielding_stick` with its frames' elastic column (α 12,
OpenSees ``elasticBeamColumn`` beside the springs) and as an equivalent shear stick),
strengths from ASCE 7-22 §12.8 at S_DS 1.0 g, S_D1 0.6 g, Risk Category II, overstrength 2
(:func:`~assess.building.design.design_strength`): steel special moment frames with the
bilinear law (OpenSees ``Steel01``) and concrete special moment frames with the pinching,
degrading law (OpenSees ``Hysteretic``, pinchX 0.8, pinchY 0.4, β 0.4, no damage), and special concentrically
braced frames with the buckling braces' law (two mirrored OpenSees ``Hysteretic`` braces in ``Parallel``,
:func:`peers.opensees_yielding.buckling_brace_pair`); Rayleigh
5 % at modes 1 and 3 on the committed tangent stiffness. Records: pyslammer's Northridge
Pacoima Dam (PAC-175, 20 s) and Kobe Takatori (TAK-090, first 20 s), scaled so that their
5 %-damped S_a(T_1) is the design spectrum's (DE) and 1.5 times it (MCE_R): every building
yields (its most ductile storey 2.2-27, the first storey 0.5-14: each storey as strong as it is stiff at
one yield drift ratio, the first to yield not always the first storey). Both step Newmark's average acceleration with
Newton iterations at the same substep, so that what is compared is the model, not the
discretisation: floor histories RMS(ours - OpenSees)/RMS(OpenSees) ≤ 1 % on every floor,
storey ductilities within 2 %.

Skipped, with the reason, where openseespy is not importable.
"""
import os

import numpy as np
import pytest

from assess.building.design import design_strength
from assess.building.nonlinear import elastic_periods, substeps_for, yielding_response, yielding_stick
from assess.hazard.records import read_record
from assess.site.asce7 import design_spectral_acceleration_g
from assess.site.spectrum import pseudo_acceleration_spectrum
from peers.opensees_shear import load_opensees
from peers.opensees_yielding import yielding_floor_accelerations

OPS, WHY = load_opensees()
pytestmark = pytest.mark.skipif(OPS is None, reason=str(WHY))

BUILDINGS = [(3, 0.35), (6, 0.70), (12, 1.40)]
RECORDS = [("Northridge_1994_PAC-175", None), ("Kobe_1995_TAK-090", 20.0)]
LEVELS = {"DE": 1.0, "MCE_R": 1.5}
SYSTEMS = {"bilinear": "steel moment frame", "pinching": "concrete moment frame", "buckling": "braced frame"}
SDS_G, SD1_G = 1.0, 0.6


def pyslammer_record(name, first_s=None):
    pyslammer = pytest.importorskip("pyslammer")
    folder = os.path.join(os.path.dirname(pyslammer.__file__), "sample_ground_motions")
    record = read_record(os.path.join(folder, name + ".csv"))
    accel = record.accel_g if first_s is None else record.accel_g[:int(round(first_s / record.dt_s)) + 1]
    return np.asarray(accel, dtype=float), record.dt_s


def scaled_to_design(accel, dt, period_s, level_factor):
    """The record scaled so that its 5 % S_a(T_1) is ``level_factor`` times the design spectrum's."""
    target = level_factor * float(design_spectral_acceleration_g(period_s, SDS_G, SD1_G))
    have = float(np.atleast_1d(pseudo_acceleration_spectrum(accel, dt, [period_s]))[0])
    return accel * (target / have)


def building(storeys, period_s, law, flexure):
    system = SYSTEMS[law]
    heights = 3.5 * np.arange(1, storeys + 1)
    strength = design_strength(system, np.ones(storeys), heights, period_s, sds_g=SDS_G, sd1_g=SD1_G,
                               risk_category="II")
    return yielding_stick(storeys, 3.5, strength.storey_yield_ratio, system=system, period_s=period_s,
                          flexure=flexure, law=law)


@pytest.mark.parametrize("flexure", ["elastic column", "equivalent shear"])
@pytest.mark.parametrize("law", list(SYSTEMS))
@pytest.mark.parametrize("storeys, period_s", BUILDINGS)
@pytest.mark.parametrize("level", list(LEVELS))
def test_yielding_floor_histories_against_opensees(storeys, period_s, law, level, flexure):
    stick = building(storeys, period_s, law, flexure)
    for name, first_s in RECORDS:
        raw, dt = pyslammer_record(name, first_s)
        ground = scaled_to_design(raw, dt, period_s, LEVELS[level])
        substeps = substeps_for(dt, min(0.001, elastic_periods(stick)[-1] / 40))
        ours = yielding_response(stick, ground, dt, substeps=substeps)
        theirs, drift = yielding_floor_accelerations(stick, ground, dt, substeps)
        error = np.sqrt(np.mean((ours.floor_accel_g - theirs) ** 2, axis=1)[1:] / np.mean(theirs ** 2, axis=1)[1:])
        their_ductility = np.abs(drift).max(axis=1) / stick.yield_drift_m
        difference = np.abs(ours.ductility / their_ductility - 1.0)
        print(f"\n| {storeys} | {law}, {flexure} | {name} | {level} | {error.max():.2e} | {ours.ductility[0]:.2f} | "
              f"{ours.ductility.max():.2f} | {difference.max():.2e} |")
        assert ours.unconverged_steps == 0
        # the building must yield for the comparison to mean something: its first storey to yield, whichever (each
        # storey as strong as it is stiff at one yield drift ratio, assess.building.nonlinear.stiffness_strength)
        assert ours.ductility.max() > 1.5, "the building must yield for the comparison to mean something"
        assert error.max() <= 0.01, (name, error)
        assert difference.max() <= 0.02, (name, difference)
