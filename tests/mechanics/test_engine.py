"""The engine's dispatch (assess.mechanics.engine): each case answered by a solver proved right for it.

Checked against the specialised kernels run directly, against the general
solver forced on the same case, and against the paper's statements about its
three prototypes (Konstantinidis & Makris 2010, Table 1, Table 3, section 4).
"""
from __future__ import annotations

import numpy as np
import pytest

from assess.data import km2010_table3
from assess.hazard.records import pulse_record
from assess.mechanics.block import Block
from assess.mechanics.engine import (DEFAULT_TAIL_S, GENERAL, ROCKING_KERNEL, SLIDING_KERNEL, simulate,
                                     simulate_cases)
from assess.mechanics.rocking import rocking_response
from assess.mechanics.sliding import sliding_response

#: Table 1 prototypes: height 2h and width 2b [m].
PROTOTYPES = {"FORMA": (2.286, 0.622), "KELVINATOR": (2.134, 0.660), "ASP": (1.803, 0.584)}
BEST_FIT_MU = {"FORMA": 0.13, "KELVINATOR": 0.17, "ASP": 0.20}  # Table 3
MODEL_MU = 0.68  # the wooden models on the shake table, section 4


def prototype(name, mu):
    height, width = PROTOTYPES[name]
    return Block(half_width_m=width / 2, cg_height_m=height / 2, height_m=height, mu=mu)


def table3_motions():
    """The paper's Table 3 motions as Type-B pulses of the printed PTA and Tp (p. 1470)."""
    table = km2010_table3()
    return table.drop_duplicates(["motion", "pta_g"])[["motion", "pta_g", "tp_s"]].itertuples(index=False)


def test_uplift_impossible_goes_to_the_exact_sliding_kernel():
    block = prototype("FORMA", 0.13)
    motion = pulse_record("B", 0.54, 2.1)
    response = simulate(block, motion.accel_g, motion.dt_s)
    direct = sliding_response(motion.accel_g, motion.dt_s, 0.13)
    assert response.solver == SLIDING_KERNEL
    assert response.sliding_max_m == direct.sliding_max_m
    assert response.sliding_residual_m == direct.sliding_residual_m
    assert not response.uplift and response.theta_max_over_alpha == 0.0


def test_rocking_kept_where_the_pivot_holds():
    block = prototype("FORMA", MODEL_MU)
    motion = pulse_record("B", 0.30, 2.1)
    response = simulate(block, motion.accel_g, motion.dt_s)
    direct = rocking_response(motion.accel_g, motion.dt_s, block.alpha_rad, block.p_rad_s,
                              tail_s=DEFAULT_TAIL_S)
    assert response.solver == ROCKING_KERNEL
    assert direct.friction_demand_max <= MODEL_MU and direct.normal_force_min_over_weight > 0
    assert response.theta_max_over_alpha == direct.theta_max_over_alpha
    assert response.uplift and response.sliding_max_m == 0.0 and response.mode == "rock"


def test_rocking_handed_to_the_general_solver_where_the_pivot_would_slip():
    """μs just above b/h: the block uplifts from rest, then the pivot needs more friction than it has."""
    block = Block(half_width_m=0.3, cg_height_m=1.0, height_m=2.0, mu=0.31)
    motion = pulse_record("A", 0.6, 1.0)
    direct = rocking_response(motion.accel_g, motion.dt_s, block.alpha_rad, block.p_rad_s,
                              tail_s=DEFAULT_TAIL_S)
    assert direct.friction_demand_max > block.mu_static  # the premise of this test
    response = simulate(block, motion.accel_g, motion.dt_s)
    assert response.solver == GENERAL
    assert response.mode == "slide-rock" and response.sliding_max_m > 0.0


@pytest.mark.parametrize("name", sorted(PROTOTYPES))
def test_prototypes_with_best_fit_mu_slide_without_uplift(name):
    """Section 4: with their best-fit μ the full-scale items slide and do not rock, under every Table 3 motion."""
    block = prototype(name, BEST_FIT_MU[name])
    for motion in table3_motions():
        record = pulse_record("B", motion.pta_g, motion.tp_s)
        response = simulate(block, record.accel_g, record.dt_s)
        assert response.mode == "slide", motion
        assert not response.uplift and response.sliding_max_m > 0.0


@pytest.mark.parametrize("name", sorted(PROTOTYPES))
def test_prototypes_with_model_mu_rock(name):
    """Section 4: with μ = 0.68 (wood on steel) the same geometry uplifts instead of sliding off from rest."""
    block = prototype(name, MODEL_MU)
    for motion in table3_motions():
        record = pulse_record("B", motion.pta_g, motion.tp_s)
        response = simulate(block, record.accel_g, record.dt_s)
        assert response.uplift, motion
        assert response.mode_sequence[1][1] == "rock", motion  # the first motion from rest is rocking


def test_cases_equal_single_runs():
    blocks = [prototype("FORMA", 0.13), prototype("ASP", MODEL_MU), prototype("KELVINATOR", 0.17),
              Block(half_width_m=0.3, cg_height_m=1.0, height_m=2.0, mu=0.31),
              prototype("FORMA", MODEL_MU)]
    motions = [pulse_record("B", 0.30, 2.1), pulse_record("A", 0.6, 1.0)]
    index = [0, 0, 1, 1, 1]
    calls = []
    peaks = simulate_cases(blocks, [m.accel_g for m in motions], [m.dt_s for m in motions], index,
                           progress=lambda done, total: calls.append((done, total)))
    for k, (block, j) in enumerate(zip(blocks, index)):
        single = simulate(block, motions[j].accel_g, motions[j].dt_s)
        assert peaks.solver[k] == single.solver
        assert peaks.mode[k] == single.mode
        assert peaks.sliding_max_m[k] == pytest.approx(single.sliding_max_m, rel=1e-12, abs=1e-15)
        assert peaks.theta_max_over_alpha[k] == pytest.approx(single.theta_max_over_alpha, rel=1e-12)
        assert peaks.overturned[k] == single.overturned
    assert calls[-1] == (5, 5) and all(a <= b for (a, _), (b, _) in zip(calls, calls[1:]))


def test_unknown_solver_is_refused():
    with pytest.raises(ValueError, match="solver"):
        simulate(prototype("ASP", 0.2), [0.1, 0.1], 0.01, solver="fast")


def test_results_do_not_depend_on_the_number_of_threads():
    import numba

    blocks = [Block(half_width_m=w, cg_height_m=1.0, height_m=2.0, mu=mu)
              for w in (0.2, 0.3, 0.5) for mu in (0.1, 0.25, 0.6)]
    motions = [pulse_record("A", 0.5, 0.8), pulse_record("B", 0.4, 1.2)]
    index = [k % 2 for k in range(len(blocks))]
    accel, dts = [m.accel_g for m in motions], [m.dt_s for m in motions]
    default = numba.get_num_threads()
    try:
        numba.set_num_threads(1)
        serial = simulate_cases(blocks, accel, dts, index)
    finally:
        numba.set_num_threads(default)
    parallel = simulate_cases(blocks, accel, dts, index)
    for field in ("sliding_max_m", "sliding_residual_m", "theta_max_over_alpha", "overturned", "mode", "solver"):
        assert np.array_equal(getattr(serial, field), getattr(parallel, field)), field


def test_feet_inset_rock_about_the_feet_with_the_whole_box_inertia():
    """A box 2b wide standing on feet inset by d rocks as a block of slenderness atan((b-d)/h)
    and p = sqrt(m g R / I_O), with R to the foot and I_O = m(4b^2 + H^2)/12 + m R^2 (parallel axes)."""
    from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2 as g

    b, h, height, inset = 0.3, 0.9, 1.8, 0.06
    footed = Block(half_width_m=b, cg_height_m=h, height_m=height, mu=0.8, foot_inset_m=inset)
    radius = np.hypot(b - inset, h)
    inertia_pivot = (4 * b**2 + height**2) / 12 + radius**2
    assert footed.alpha_rad == pytest.approx(np.arctan((b - inset) / h), rel=1e-12)
    assert footed.p_rad_s == pytest.approx(np.sqrt(g * radius / inertia_pivot), rel=1e-12)
    assert footed.inertia_ratio == pytest.approx(inertia_pivot / radius**2, rel=1e-12)
    motion = pulse_record("A", 0.35, 0.8)  # above tan(alpha) of the feet (0.267) and of the box (0.333)
    kernel = rocking_response(motion.accel_g, motion.dt_s, np.arctan((b - inset) / h),
                              np.sqrt(g * radius / inertia_pivot), inertia_ratio_value=inertia_pivot / radius**2,
                              tail_s=4.0)
    from assess.mechanics.timestepping import simulate_time_stepping
    from assess.mechanics.event_driven import simulate_event_driven
    stepped = simulate_time_stepping(footed, motion.accel_g, motion.dt_s, tail_s=4.0)
    event = simulate_event_driven(footed, motion.accel_g, motion.dt_s, tail_s=4.0)
    assert kernel.uplift and not kernel.overturned
    assert stepped.theta_max_over_alpha == pytest.approx(kernel.theta_max_over_alpha, rel=0.01)
    assert event.theta_max_over_alpha == pytest.approx(kernel.theta_max_over_alpha, rel=0.005)
    # the feet make it more slender than the box: it rocks where the box on its edges would not rock as far
    box = simulate(Block(half_width_m=b, cg_height_m=h, height_m=height, mu=0.8), motion.accel_g, motion.dt_s)
    assert stepped.theta_max_over_alpha * footed.alpha_rad > box.theta_max_over_alpha * box_alpha(b, h)


def box_alpha(b, h):
    return float(np.arctan(b / h))
