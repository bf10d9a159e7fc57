"""Sliding in the plane under two floor components (assess.mechanics.sliding_2d), checked five ways.

(a) Floor motion along one axis: the one-way exact kernel (assess.mechanics.sliding).
(b) Floor motion along a diagonal: the one-way answer under the resultant.
(c) Circular floor motion: the closed-form steady circle (derived in the test's docstring).
(d) MuJoCo (test-only, skipped when absent): a box on a plane, first against Newmark's
    rectangular pulse (tests/data/newmark/), then on two pairs of real records.
(e) An independent time stepping written here: Moreau's implicit (projection) step of
    Coulomb friction on substeps of dt/200, no event location.

Every figure quoted in a docstring was measured with the command
``python -m pytest -q tests/verification/test_sliding_2d.py`` from the repository root (records:
pyslammer's 18 sample ground motions, accel [g], dt [s]).
"""
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from numba import get_num_threads

from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2 as G
from assess.mechanics.sliding import sliding_response
from assess.mechanics.sliding_2d import Sliding2DResult, sliding_2d_peaks_batch, sliding_response_2d
from peers.moreau import moreau_reference

NEWMARK = Path(__file__).resolve().parents[1] / "data" / "newmark" / "rectangular_pulse.csv"
MUS = (0.05, 0.1, 0.2)

#: The two real record pairs of the MuJoCo comparison (x component, y component).
MUJOCO_PAIRS = (("Duzce_1999_375-090", "Kobe_1995_TAK-090"),
                ("Northridge_1994_PAC-175", "Cape_Mendocino_1992_PET-090"))


# ----------------------------------------------------------------------------- helpers
@pytest.fixture(scope="module")
def records():
    pyslammer = pytest.importorskip("pyslammer")
    motions = pyslammer.sample_ground_motions()  # pyslammer's own loader (accel in g, dt in s)
    assert len(motions) >= 18
    return {name: (np.asarray(m.accel, dtype=float), float(m.dt)) for name, m in sorted(motions.items())}


def record_pair(first, second):
    """(x, y, dt): ``second`` resampled linearly onto ``first``'s steps, both cut to the shorter."""
    (ax, dt), (b, dt_b) = first, second
    t_b = np.arange(b.size) * dt_b
    t = np.arange(0.0, min(ax.size * dt, t_b[-1]), dt)
    n = min(t.size, ax.size)
    return ax[:n], np.interp(t[:n], t_b, b), dt


def pairs(records):
    """Each record with the next one in name order (the last with the first): 18 pairs."""
    names = list(records)
    return [(a, b) for a, b in zip(names, names[1:] + names[:1])]


# ----------------------------------------------------------------------------- (a), (b)
@pytest.mark.parametrize("mu", MUS)
@pytest.mark.parametrize("axis", ["x", "y"])
def test_one_axis_reproduces_exact_1d_kernel(records, axis, mu):
    """(a) Floor motion along x (or y) only: peak and residual equal the one-way exact kernel.

    Measured on all 18 records × μ 0.05/0.1/0.2: largest relative difference of the peak
    3.8e-15 (round-off); the path never leaves the axis (the other component stays 0).
    """
    for name, (accel, dt) in records.items():
        zero = np.zeros_like(accel)
        one_way = sliding_response(accel, dt, mu)
        pair = (accel, zero) if axis == "x" else (zero, accel)
        plane = sliding_response_2d(*pair, dt, mu)
        along, across = ((plane.sliding_residual_x_m, plane.sliding_residual_y_m) if axis == "x"
                         else (plane.sliding_residual_y_m, plane.sliding_residual_x_m))
        assert plane.sliding_max_m == pytest.approx(one_way.sliding_max_m, rel=1e-12, abs=1e-15), name
        assert along == pytest.approx(one_way.sliding_residual_m, rel=1e-12, abs=1e-15), name
        assert across == 0.0, name
        assert plane.slide_time_s == pytest.approx(one_way.slide_time_s, rel=1e-12, abs=1e-15), name


@pytest.mark.parametrize("angle_rad", [0.6, 2.3, -1.1])
@pytest.mark.parametrize("mu", MUS)
def test_diagonal_motion_is_1d_under_the_resultant(records, angle_rad, mu):
    """(b) Both components a(t)·cos θ, a(t)·sin θ: the one-way answer under a(t), along θ.

    Measured on all 18 records × μ 0.05/0.1/0.2 × θ 0.6, 2.3, -1.1 rad: largest relative
    difference of the peak 6.7e-15. (A first version, which held the direction of the
    velocity at the start of each substep, drifted off the line by up to 0.5 %: the
    explicit direction is unstable at low speed; the held direction is now implicit.)
    """
    c, s = np.cos(angle_rad), np.sin(angle_rad)
    for name, (accel, dt) in records.items():
        one_way = sliding_response(accel, dt, mu)
        plane = sliding_response_2d(accel * c, accel * s, dt, mu)
        assert plane.sliding_max_m == pytest.approx(one_way.sliding_max_m, rel=1e-10, abs=1e-14), name
        assert plane.sliding_residual_x_m == pytest.approx(one_way.sliding_residual_m * c, rel=1e-10, abs=1e-14)
        assert plane.sliding_residual_y_m == pytest.approx(one_way.sliding_residual_m * s, rel=1e-10, abs=1e-14)


# ----------------------------------------------------------------------------- (c)
@pytest.mark.parametrize("amplitude_g, mu, frequency_hz", [(0.5, 0.2, 1.0), (0.3, 0.25, 2.0), (1.0, 0.1, 0.5)])
def test_circular_floor_motion_steady_circle(amplitude_g, mu, frequency_hz):
    """(c) Floor acceleration A(cos ωt, sin ωt), A > μg: steady circle of radius √(A² − μ²g²)/ω².

    Derivation. Try u = R r̂(ψ), ψ = ωt + φ, with r̂(ψ) = (cos ψ, sin ψ) and
    t̂(ψ) = (−sin ψ, cos ψ): the relative velocity Rω t̂(ψ) has constant magnitude, so
    friction is −μg t̂(ψ) throughout (the block never stops), and ü = −Rω² r̂(ψ).
    With r̂(ωt) = r̂(ψ − φ) = cos φ r̂(ψ) − sin φ t̂(ψ), the equation
    ü = −A r̂(ωt) − μg t̂(ψ) splits into
    radial: Rω² = A cos φ; tangential: A sin φ = μg. Hence sin φ = μg/A and

        R = √(A² − μ²g²)/ω²,   |u̇| = Rω,   u leads the floor acceleration by φ = asin(μg/A).

    R is the radius of the **relative** displacement (block minus floor), the quantity
    the kernel returns and the one compared with a clearance: the floor's own circle
    has radius A/ω², the block's absolute circle μg/ω² (friction is its only horizontal
    force), and the relative one is their difference, at right angles:
    R² = (A/ω²)² − (μg/ω²)². The circle's centre is set by the start-up transient, so R
    is measured about the centre of the path over the last three cycles (40 cycles run,
    1000 samples a cycle; the piecewise-linear sampling lowers the fundamental by
    sinc²(ωdt/2) = 1 − 3.3e-6).

    Measured: |R/R_exact − 1| ≤ 4.2e-6 (0.5 g, μ 0.2, 1 Hz), 1.5e-5 (0.3 g, μ 0.25, 2 Hz),
    3.6e-5 (1 g, μ 0.1, 0.5 Hz; its transient is the slowest to die out); the issue asks
    0.5 %. |speed/(Rω) − 1| ≤ 1.5e-5; the lead within 4.9e-5 rad of asin(μg/A).
    """
    omega = 2.0 * np.pi * frequency_hz
    dt = 1e-3 / frequency_hz  # 1000 samples a cycle
    duration_s = 40.0 / frequency_hz
    t = np.arange(0.0, duration_s + dt / 2, dt)
    result = sliding_response_2d(amplitude_g * np.cos(omega * t), amplitude_g * np.sin(omega * t), dt, mu,
                                 return_history=True)
    radius_exact_m = np.sqrt((amplitude_g * G) ** 2 - (mu * G) ** 2) / omega ** 2
    last = t > duration_s - 3.0 / frequency_hz
    path = result.sliding_m[last]
    centre = 0.5 * (path.max(axis=0) + path.min(axis=0))
    radius_m = np.hypot(*(path - centre).T)
    speed_m_s = np.hypot(*result.sliding_velocity_m_s[last].T)
    lead_rad = np.angle(np.exp(1j * (np.arctan2(path[:, 1] - centre[1], path[:, 0] - centre[0]) - omega * t[last])))
    assert np.abs(radius_m / radius_exact_m - 1.0).max() < 5e-3  # the tolerance
    assert np.abs(radius_m / radius_exact_m - 1.0).max() < 5e-5  # what the kernel achieves
    assert np.abs(speed_m_s / (omega * radius_exact_m) - 1.0).max() < 5e-5
    assert np.abs(lead_rad - np.arcsin(mu / amplitude_g)).max() < 1e-4
    # the floor's and the block's absolute circles: R² = (A/ω²)² − (μg/ω²)² (a restatement)
    assert radius_exact_m ** 2 == pytest.approx((amplitude_g * G / omega ** 2) ** 2 - (mu * G / omega ** 2) ** 2)


def test_circular_floor_motion_inside_the_static_cone_never_slides():
    """|a_g| = A constant: below μs the block never starts, however long the motion (0.0 m)."""
    t = np.arange(0.0, 10.0, 1e-3)
    result = sliding_response_2d(0.3 * np.cos(6 * t), 0.3 * np.sin(6 * t), 1e-3, 0.25, mu_static=0.31)
    assert result.sliding_max_m == 0.0 and result.slide_time_s == 0.0


# ----------------------------------------------------------------------------- (e) independent stepping
@pytest.mark.parametrize("mu", [0.1, 0.2])
def test_record_pairs_against_moreau_time_stepping(records, mu):
    """(e) Real record pairs (each record with the next, 6 of the 18 pairs) against Moreau stepping.

    The reference (``moreau_reference``, tests/peers/moreau.py) shares nothing with the kernel but
    the equation: implicit projection step on substeps of dt/200, no events, first order.
    Measured: largest relative difference of the peak 7.5e-4 (μ 0.1) and 1.5e-3 (μ 0.2)
    (8.8e-4 and 1.7e-3 with the reference on dt/100); residuals within 4.0e-3 of the peak.
    (Moreau, J. J. (1988). Unilateral contact and dry friction in finite freedom
    dynamics. CISM Courses and Lectures 302, Springer, 1-82.)
    """
    for first, second in pairs(records)[::3]:
        ax, ay, dt = record_pair(records[first], records[second])
        plane = sliding_response_2d(ax, ay, dt, mu)
        peak_ref, res_x, res_y = moreau_reference(ax, ay, dt, mu, 200)
        assert plane.sliding_max_m == pytest.approx(peak_ref, rel=5e-3, abs=1e-5), (first, second)
        assert np.hypot(plane.sliding_residual_x_m - res_x,
                        plane.sliding_residual_y_m - res_y) < 1e-2 * peak_ref + 1e-5, (first, second)


def test_default_substep_against_16_times_finer(records):
    """Accuracy of the default 1 ms substep on real pairs: against the same kernel at 1/16 of it.

    Measured on 6 pairs × μ 0.05/0.1/0.2: largest relative difference of the peak 1.3e-3
    (median 6e-5; on all 18 pairs 1.5e-3, median 5e-5); on smooth two-component input the difference falls about 4x per halving
    of the substep (second order), on records less regularly (first order near stops).
    """
    worst = 0.0
    for first, second in pairs(records)[::3]:
        ax, ay, dt = record_pair(records[first], records[second])
        for mu in MUS:
            default = sliding_response_2d(ax, ay, dt, mu).sliding_max_m
            fine = sliding_response_2d(ax, ay, dt, mu, max_substep_s=1e-3 / 16).sliding_max_m
            worst = max(worst, abs(default / fine - 1.0))
    assert worst < 3e-3


def test_substep_convergence_on_smooth_input():
    """Second order on smooth input: the error at h/2 is at most 1/3 of the error at h.

    Floor (0.5 cos 2πt ramped in over 3 s, 0.3 sin 2.6πt) g, μ 0.2, dt 2 ms: peak errors
    against h = 1/64 ms measured 1.3e-5, 2.8e-6, 7.6e-7 at h = 1, 0.5, 0.25 ms.
    """
    dt = 2e-3
    t = np.arange(0.0, 10.0, dt)
    ax = 0.5 * np.cos(2 * np.pi * t) * np.minimum(1.0, t / 3.0)
    ay = 0.3 * np.sin(2.6 * np.pi * t)
    ref = sliding_response_2d(ax, ay, dt, 0.2, max_substep_s=1e-3 / 64).sliding_max_m
    errors = [abs(sliding_response_2d(ax, ay, dt, 0.2, max_substep_s=h).sliding_max_m / ref - 1.0)
              for h in (1e-3, 5e-4, 2.5e-4)]
    assert errors[1] < errors[0] / 3.0 and errors[2] < errors[1] / 3.0
    assert errors[0] < 1e-4


# ----------------------------------------------------------------------------- (d) MuJoCo
def mujoco_box(mu, timestep_s=1e-3):
    """A 0.6 x 0.6 x 0.1 m box of 100 kg on a plane, isotropic friction μ, MuJoCo settings.

    Elliptic friction cone (isotropic Coulomb; the default pyramid is not), sliding
    friction only (condim 3), a stiff contact (solref 0.002 s = 2 time steps, solimp
    0.99-0.999: the default 0.02 s contact creeps and slipped 1 % off Newmark's exact
    answer on records), 1 ms steps. The box translates on three slide joints, as the
    model it is compared with: it can neither rock nor twist (a free box, tried with the
    default contact on the two pairs below, twisted by less than 0.001 rad).
    """
    mujoco = pytest.importorskip("mujoco", reason="MuJoCo is an optional test dependency "
                                 "(pip install mujoco); the 3-D engine comparison is skipped")
    xml = f"""<mujoco>
  <option timestep="{timestep_s}" cone="elliptic" gravity="0 0 -{G}"/>
  <default><geom condim="3" friction="{mu} 0 0" solref="0.002 1" solimp="0.99 0.999 0.001"/></default>
  <worldbody>
    <geom name="floor" type="plane" size="100 100 0.1"/>
    <body name="box" pos="0 0 0.05">
      <joint type="slide" axis="1 0 0"/><joint type="slide" axis="0 1 0"/><joint type="slide" axis="0 0 1"/>
      <geom type="box" size="0.3 0.3 0.05" mass="100"/>
    </body>
  </worldbody>
</mujoco>"""
    return mujoco, mujoco.MjModel.from_xml_string(xml)


def mujoco_peak_distance(mu, ax_g, ay_g, dt, tail_s=3.0):
    """(peak distance from rest [m], residual (x, y) [m]) of the MuJoCo box.

    The floor is the box's frame: the floor motion enters as the inertial force −m ü_g,
    applied through the gravity vector (−g a_x, −g a_y, −g) set at each step from the
    record (linear between samples, evaluated at the step's midpoint; zero after the
    record, followed for ``tail_s``). The box first settles for 0.2 s.
    """
    mujoco, model = mujoco_box(mu)
    data = mujoco.MjData(model)
    for _ in range(200):
        mujoco.mj_step(model, data)
    data.qvel[:] = 0.0
    box = model.body("box").id
    start = data.xpos[box][:2].copy()
    h = model.opt.timestep
    end_s = (len(ax_g) - 1) * dt
    t = (np.arange(int(round((end_s + tail_s) / h))) + 0.5) * h
    gx = np.where(t <= end_s, np.interp(t, np.arange(len(ax_g)) * dt, ax_g), 0.0)
    gy = np.where(t <= end_s, np.interp(t, np.arange(len(ay_g)) * dt, ay_g), 0.0)
    peak = 0.0
    for k in range(t.size):
        model.opt.gravity[0] = -G * gx[k]
        model.opt.gravity[1] = -G * gy[k]
        mujoco.mj_step(model, data)
        peak = max(peak, float(np.hypot(*(data.xpos[box][:2] - start))))
    return peak, data.xpos[box][:2] - start


def newmark_rows():
    table = pd.read_csv(NEWMARK, comment="#")
    return table[table.in_pi2.isin([0.1, 0.3, 0.5, 0.8])].head(4)


@pytest.mark.parametrize("angle_rad", [0.0, 0.9])
def test_mujoco_box_against_newmark_rectangular_pulse(angle_rad):
    """MuJoCo's box under Newmark's rectangular pulse (tests/data/newmark/, closed form eq. 1/6).

    Shows the engine's settings fit before it judges the kernel: pulse ap = 0.5 g,
    Tp scaled to 0.25 s (Π1 does not depend on Tp), μ = Π2·ap, along x and along a
    diagonal (θ = 0.9 rad). Measured: largest |Π1/Π1_exact − 1| 6.8e-5 (Π2 0.8; 1.5e-7 to
    4.0e-6 for Π2 0.1, 0.3, 0.5), the same along x and along the diagonal.
    """
    c, s = np.cos(angle_rad), np.sin(angle_rad)
    for row in newmark_rows().itertuples():
        tp_s = 0.25
        mu = row.in_pi2 * row.in_ap_g
        peak, _ = mujoco_peak_distance(mu, [row.in_ap_g * c] * 2, [row.in_ap_g * s] * 2, tp_s,
                                       tail_s=tp_s * row.in_ap_g / mu + 0.5)
        pi1 = peak * (2 * np.pi / tp_s) ** 2 / (row.in_ap_g * G)
        assert pi1 == pytest.approx(row.exp_pi1, rel=5e-4), row


@pytest.fixture(scope="module")
def mujoco_pairs(records):
    pytest.importorskip("mujoco", reason="MuJoCo is an optional test dependency (pip install mujoco)")
    return [(first, second, *record_pair(records[first], records[second])) for first, second in MUJOCO_PAIRS]


@pytest.mark.parametrize("mu", [0.1, 0.2])
def test_mujoco_box_on_single_components_against_exact_1d(mujoco_pairs, mu):
    """The engine's own accuracy on real records: one component at a time vs the exact kernel.

    Measured (4 records × μ 0.1/0.2): largest |peak_MuJoCo/peak_exact − 1| 4.2e-3
    (Kobe, μ 0.1; Duzce 4.0e-3; the others 3e-6 to 1.3e-3). This is the scale at which the two-component comparison can agree.
    """
    for first, second, ax, ay, dt in mujoco_pairs:
        for name, accel in ((first, ax), (second, ay)):
            exact = sliding_response(accel, dt, mu).sliding_max_m
            peak, _ = mujoco_peak_distance(mu, accel, np.zeros_like(accel), dt)
            assert peak == pytest.approx(exact, rel=1e-2), name


@pytest.mark.parametrize("mu", [0.1, 0.2])
def test_mujoco_box_on_two_component_records(mujoco_pairs, mu):
    """(d) Two real record pairs, both components at once: kernel vs MuJoCo's box.

    Pairs: Duzce 375-090 (x) with Kobe TAK-090 (y), 30 s; Northridge PAC-175 (x) with
    Cape Mendocino PET-090 (y), 20 s. Measured |peak_MuJoCo/peak_kernel − 1|:
    5.5e-3 and 1.3e-3 (Duzce/Kobe, μ 0.1 and 0.2), 2.1e-4 and 2.5e-5 (Northridge/Cape),
    the same scale as the engine's own one-component error above; residuals agree within
    0.73 % of the peak.
    """
    for first, second, ax, ay, dt in mujoco_pairs:
        kernel = sliding_response_2d(ax, ay, dt, mu)
        peak, residual = mujoco_peak_distance(mu, ax, ay, dt)
        assert peak == pytest.approx(kernel.sliding_max_m, rel=1e-2), (first, second)
        assert np.hypot(residual[0] - kernel.sliding_residual_x_m,
                        residual[1] - kernel.sliding_residual_y_m) < 2e-2 * kernel.sliding_max_m


# ----------------------------------------------------------------------------- API
@pytest.mark.parametrize("n_blocks", [1, 2 * get_num_threads()])  # one range, then several over the threads
def test_batch_equals_single_runs(records, n_blocks):
    """sliding_2d_peaks_batch gives, per (block, pair), what sliding_response_2d gives."""
    chosen = pairs(records)[:3]
    xs, ys, dts = zip(*(record_pair(records[a], records[b]) for a, b in chosen))
    mus = np.linspace(0.05, 0.2, n_blocks)
    mus_static = mus * 1.2
    peak, residual = sliding_2d_peaks_batch(list(xs), list(ys), np.array(dts), mus, mus_static)
    assert peak.shape == residual.shape == (n_blocks, 3)
    for i, (mu, mu_s) in enumerate(zip(mus, mus_static)):
        for r in range(3):
            single = sliding_response_2d(xs[r], ys[r], dts[r], mu, mu_s)
            assert peak[i, r] == single.sliding_max_m
            assert residual[i, r] == pytest.approx(single.sliding_residual_m, rel=1e-14)


@pytest.mark.parametrize("angle_rad", [0.0, 2.3])
def test_static_friction_on_a_line_equals_1d_with_static_friction(records, angle_rad):
    """μs = 1.3 μ (starts later than it stops): on a line, still the one-way kernel (to 1e-10).

    Measured on the first 6 records × μ 0.1/0.2, θ 0 and 2.3 rad: largest relative difference 2.9e-15.
    """
    c, s = np.cos(angle_rad), np.sin(angle_rad)
    for name, (accel, dt) in list(records.items())[:6]:
        for mu in (0.1, 0.2):
            one_way = sliding_response(accel, dt, mu, 1.3 * mu)
            plane = sliding_response_2d(accel * c, accel * s, dt, mu, 1.3 * mu)
            assert plane.sliding_max_m == pytest.approx(one_way.sliding_max_m, rel=1e-10, abs=1e-14), name


def test_history_and_result_fields():
    result = sliding_response_2d([0.5, 0.5, 0.0], [0.0, 0.2, 0.0], 0.5, 0.2, return_history=True)
    assert isinstance(result, Sliding2DResult)
    assert result.time_s.shape == (3,) and result.sliding_m.shape == (3, 2)
    assert result.sliding_velocity_m_s.shape == (3, 2)
    assert result.sliding_residual_m == pytest.approx(np.hypot(result.sliding_residual_x_m,
                                                               result.sliding_residual_y_m))
    assert result.sliding_max_m >= result.sliding_residual_m > 0.0
    assert sliding_response_2d([0.5], [0.0], 0.5, 0.2).sliding_max_m == 0.0  # one sample: no step


@pytest.mark.parametrize("kwargs", [dict(mu=0.0), dict(mu=-0.1), dict(mu=0.2, mu_static=0.1),
                                    dict(mu=0.2, max_substep_s=0.0), dict(mu=np.nan)])
def test_bad_friction_or_substep_raises(kwargs):
    with pytest.raises(ValueError):
        sliding_response_2d([0.1, 0.2], [0.0, 0.1], 0.01, **kwargs)


def test_bad_records_raise():
    with pytest.raises(ValueError):
        sliding_response_2d([0.1, 0.2], [0.0], 0.01, 0.2)
    with pytest.raises(ValueError):
        sliding_response_2d([0.1, np.nan], [0.0, 0.0], 0.01, 0.2)
    with pytest.raises(ValueError):
        sliding_2d_peaks_batch([[0.1, 0.2]], [[0.1, 0.2, 0.3]], 0.01, [0.2])
