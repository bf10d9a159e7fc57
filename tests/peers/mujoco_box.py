"""MuJoCo's rigid box under a floor acceleration history: does it overturn? (a test-only peer)

A box of the item's half-width and height (408 kg by default, no collision of its own) carrying two line feet at its
edges (capsules of 1 mm radius across its depth) on a plane, the item's μ, stiff critically damped contact
(``solref`` four steps, damping ratio 1: an impact that does not bounce, as Housner's), MuJoCo's
``implicitfast`` integrator at 0.2 ms steps, elliptic friction cone. The floor's acceleration a(t) (linear
between the record's samples, then at rest for ``tail_s``) enters as a sideways gravity −a(t)·g in the
floor's frame, as in tests/verification/test_foot_inset.py. Overturned: the box's tilt passes 1 rad (3.7 α for
the loaded shelving, far past where it could come back under these floors), checked every 10 ms.

Nothing is shared with the tool's engines: MuJoCo solves contact and impact by its own soft-constraint
model (Todorov, Erez & Tassa 2012, "MuJoCo: A physics engine for model-based control", IROS), not by
Housner's angular-momentum rule.
"""
from __future__ import annotations

import numpy as np

from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2

STEP_S = 2e-4
FOOT_RADIUS_M = 0.001
OVERTURNED_RAD = 1.0


def box_model(mujoco, half_width_m, height_m, mu, *, foot_half_span_m=None, mass_kg=408.0, step_s=STEP_S,
              gravity_x_m_s2=0.0, foot_radius_m=FOOT_RADIUS_M):
    """The MuJoCo model of the box on its two line feet (module text): at its edges, or at ±``foot_half_span_m``
    (a box on inset feet, tests/verification/test_foot_inset.py); a constant sideways gravity where given."""
    h, c = height_m / 2, half_width_m if foot_half_span_m is None else foot_half_span_m
    contact = f'friction="{mu} 0.005 0.0001" solref="{4 * step_s} 1"'
    feet = "".join(f'<geom type="capsule" fromto="{x} -0.3 {-h + foot_radius_m} {x} 0.3 {-h + foot_radius_m}" '
                   f'size="{foot_radius_m}" density="0" {contact}/>' for x in (c, -c))
    xml = (f'<mujoco><option timestep="{step_s}" gravity="{gravity_x_m_s2} 0 {-STANDARD_GRAVITY_M_S2}" '
           f'integrator="implicitfast" cone="elliptic" impratio="10"/><worldbody>'
           f'<geom type="plane" size="50 5 0.1" {contact}/><body><freejoint/>'
           f'<geom type="box" size="{half_width_m} 0.3 {h}" contype="0" conaffinity="0" mass="{mass_kg}"/>{feet}'
           f'</body></worldbody></mujoco>')
    return mujoco.MjModel.from_xml_string(xml)


def overturns(mujoco, model, floor_accel_g, dt_s, height_m, tail_s=5.0) -> bool:
    """Whether the box of ``model`` (standing at rest) overturns under ``floor_accel_g`` sampled at ``dt_s``."""
    data = mujoco.MjData(model)
    data.qpos[:3], data.qpos[3:7] = [0.0, 0.0, height_m / 2], [1.0, 0.0, 0.0, 0.0]
    mujoco.mj_forward(model, data)
    accel = np.asarray(floor_accel_g, dtype=float)
    steps = int((accel.size * dt_s + tail_s) / STEP_S)
    floor = np.interp(np.arange(steps) * STEP_S, np.arange(accel.size) * dt_s, accel, right=0.0)
    check_every = int(round(0.01 / STEP_S))
    for k in range(steps):
        model.opt.gravity[0] = -floor[k] * STANDARD_GRAVITY_M_S2
        mujoco.mj_step(model, data)
        if k % check_every == 0 and abs(2.0 * np.arctan2(data.qpos[5], data.qpos[3])) > OVERTURNED_RAD:
            return True
    return False
