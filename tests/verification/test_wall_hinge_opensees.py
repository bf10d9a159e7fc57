"""The wall on a base hinge (assess.building.wall_hinge) against OpenSeesPy with the same model.

Shear walls of 3, 6 and 12 storeys of 3.5 m (T_1 0.25, 0.50, 1.00 s; equal floor masses; the tool's
shear-flexural elastic model, α 1, on its base hinge, :func:`~assess.building.nonlinear.yielding_stick`'s
``"base hinge"``), strength from ASCE 7-22 §12.8 at S_DS 1.0 g, S_D1 0.6 g, Risk Category II, overstrength 2
(:func:`~assess.building.design.design_strength`); the hinge pinching (OpenSees ``Hysteretic``, pinchX 0.8,
pinchY 0.4, β 0.4, no damage) and, for the 6-storey wall, bilinear (``Steel01``). The OpenSees model
(tests/peers/opensees_wall_hinge.py) is built element by element from the tool's numbers: a flexural
column and a chain of storey shear beams that turn with the hinge, on a ``zeroLength`` hinge without
damping; Rayleigh damping a_0 M + a_1 (n + 1)/n on the elastic elements. Records: pyslammer's
Northridge Pacoima Dam (PAC-175, 20 s) and Kobe Takatori (TAK-090, first 20 s), scaled so that their 5 %
S_a(T_1) is the design spectrum's (DE) and 1.5 times it (MCE_R): every wall yields. Both step Newmark's
average acceleration with Newton iterations at the same substep: floor histories RMS(ours −
OpenSees)/RMS(OpenSees) ≤ 1 % on every floor, the wall's rotation ductility within 2 %; the periods of the
elastic assembly against OpenSees' eigenvalues.

Skipped, with the reason, where openseespy is not importable.
"""
import numpy as np
import pytest

from assess.building.design import design_strength
from assess.building.nonlinear import substeps_for, yielding_stick
from assess.building.wall_hinge import hinged_periods, hinged_wall_response
from peers.opensees_shear import load_opensees
from peers.opensees_wall_hinge import hinge_floor_histories, hinge_periods
from verification.test_building_yielding_opensees import (LEVELS, RECORDS, SD1_G, SDS_G, pyslammer_record,
                                                          scaled_to_design)

OPS, WHY = load_opensees()
pytestmark = pytest.mark.skipif(OPS is None, reason=str(WHY))

WALLS = [(3, 0.25), (6, 0.50), (12, 1.00)]


def wall(storeys, period_s, law=None):
    heights = 3.5 * np.arange(1, storeys + 1)
    strength = design_strength("shear wall", np.ones(storeys), heights, period_s, sds_g=SDS_G, sd1_g=SD1_G,
                               risk_category="II", overstrength=2.0)
    return yielding_stick(storeys, 3.5, strength.storey_yield_ratio, system="shear wall", period_s=period_s,
                          flexure="base hinge", law=law)


@pytest.mark.parametrize("storeys, period_s", WALLS)
def test_elastic_periods_against_opensees(storeys, period_s):
    model = wall(storeys, period_s)
    ours = hinged_periods(model)[:3]
    theirs = hinge_periods(model, 1.0)
    assert ours[0] == pytest.approx(period_s, rel=1e-9)
    np.testing.assert_allclose(ours, theirs, rtol=1e-6)


@pytest.mark.parametrize("storeys, period_s, law", [(3, 0.25, None), (6, 0.50, None), (6, 0.50, "bilinear"),
                                                    (12, 1.00, None)])
@pytest.mark.parametrize("level", list(LEVELS))
def test_hinged_wall_floor_histories_against_opensees(storeys, period_s, law, level):
    model = wall(storeys, period_s, law)
    for name, first_s in RECORDS:
        raw, dt = pyslammer_record(name, first_s)
        ground = scaled_to_design(raw, dt, period_s, LEVELS[level])
        substeps = substeps_for(dt, min(0.001, hinged_periods(model)[-1] / 40))
        ours = hinged_wall_response(model, ground, dt, substeps=substeps)
        theirs, drift, peak_rotation = hinge_floor_histories(model, 1.0, ground, dt, substeps)
        error = np.sqrt(np.mean((ours.floor_accel_g - theirs) ** 2, axis=1)[1:] / np.mean(theirs ** 2, axis=1)[1:])
        hinge_yield = model.yield_moment_n_m / model.hinge_stiffness_n_m_rad
        their_ductility = 1.0 + (peak_rotation - hinge_yield) / model.yield_rotation_rad
        drift_error = np.abs(np.abs(ours.drift_m).max(axis=1) / np.abs(drift).max(axis=1) - 1.0)
        print(f"\n| {storeys} | {model.law} | {name} | {level} | {error.max():.2e} | {ours.ductility[0]:.3f} | "
              f"{their_ductility:.3f} | {drift_error.max():.1e} |")
        assert ours.unconverged_steps == 0
        assert ours.ductility[0] > 1.2, "the wall must yield for the comparison to mean something"
        assert np.all(np.isnan(ours.ductility[1:]))
        assert error.max() <= 0.01, (name, error)
        assert ours.ductility[0] == pytest.approx(their_ductility, rel=0.02)
        assert drift_error.max() <= 0.02, (name, drift_error)
