"""μ as a range (mu_low, mu_high): its nodes and weights, whether the engine is monotone in μ, its
propagation through the assessment, and the class at each end of the range."""
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from scipy import integrate, stats

from assessed import run_assessment
from assess.inventory.settings import Settings
from assess.fragility.friction_range import friction_nodes, items_whose_class_changes
from assess.inventory import Inventory
from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2 as G
from assess.mechanics.sliding import sliding_response


# ----------------------------------------------------------------------------- nodes and weights
@pytest.mark.parametrize("low, mode, high", [(0.13, 0.13, 0.23), (0.17, 0.2, 0.28), (0.2, 0.31, 0.31),
                                             (0.4, 0.45, 0.7)])
@pytest.mark.parametrize("per_side", [1, 2, 4])
def test_node_weights_integrate_piecewise_linear_functions_exactly_against_scipys_triangular(
        low, mode, high, per_side):
    """Σ w f(μ) equals ∫ f p dμ (scipy's triangular density, adaptive quadrature) for every f linear
    between the nodes: 1, μ, and hinge functions with their kink at a node."""
    nodes, weights = friction_nodes(low, mode, high, per_side)
    assert low in nodes and high in nodes and np.isclose(nodes, mode).any()
    density = stats.triang((mode - low) / (high - low), loc=low, scale=high - low).pdf
    functions = [lambda x: 1.0, lambda x: x] + [lambda x, k=k: max(x - k, 0.0) for k in nodes[1:-1]]
    for f in functions:
        expected, _ = integrate.quad(lambda x: f(x) * density(x), low, high, points=list(nodes), limit=200)
        assert np.dot(weights, [f(x) for x in nodes]) == pytest.approx(expected, rel=1e-9, abs=1e-12)
    assert np.dot(weights, nodes) == pytest.approx((low + mode + high) / 3.0, rel=1e-12)  # the mean


def test_a_range_of_zero_width_is_one_node():
    nodes, weights = friction_nodes(0.3, 0.3, 0.3)
    assert nodes.tolist() == [0.3] and weights.tolist() == [1.0]
    with pytest.raises(ValueError):
        friction_nodes(0.3, 0.2, 0.4)


# ----------------------------------------------------------------------------- monotone in μ?
def test_newmark_rectangular_pulse_sliding_decreases_with_mu():
    """Closed form U = ap (ap − μ) g T² / (2μ) [Newmark 1965]: decreasing in μ; the kernel follows it."""
    ap, duration = 0.5, 0.5
    mus = np.linspace(0.1, 0.45, 8)
    peaks = [sliding_response([ap, ap], duration, mu).sliding_max_m for mu in mus]
    closed = ap * (ap - mus) * G * duration ** 2 / (2.0 * mus)
    np.testing.assert_allclose(peaks, closed, rtol=1e-12)
    assert np.all(np.diff(peaks) < 0.0)


def test_two_way_sliding_on_a_real_record_is_not_monotone_in_mu():
    """Why the range keeps several μ values: under Loma Prieta HSP-000 scaled to 1 g, a block sliding at
    μ = 0.138 slides about 4.7 cm farther than at μ = 0.12 (LN2-6-01's range, 0.12-0.192). An independent
    implicit (Moreau) time stepping on dt/200 gives the same growth."""
    pyslammer = pytest.importorskip("pyslammer")
    from peers.moreau import moreau_reference

    motion = pyslammer.sample_ground_motions()["Loma_Prieta_1989_HSP-000"]
    accel = np.asarray(motion.accel, dtype=float)
    accel = accel / np.abs(accel).max()
    dt = float(motion.dt)
    low, inside = 0.12, 0.138
    exact = [sliding_response(accel, dt, mu).sliding_max_m for mu in (low, inside)]
    zero = np.zeros_like(accel)
    reference = [moreau_reference(accel, zero, dt, mu, 200)[0] for mu in (low, inside)]
    assert exact[1] - exact[0] > 0.03  # grows by more than 3 cm with μ
    assert reference[1] - reference[0] == pytest.approx(exact[1] - exact[0], abs=0.005)


# ----------------------------------------------------------------------------- through the assessment
RECT_G, RECT_S, RAMP_S = 0.5, 0.5, 0.01  # 0.5 g for 0.5 s, then down to 0 over one 0.01 s sample step


def newmark_sliding_m(mu):
    """Newmark's rectangular pulse, with the record's last step down taken linear (as the record is read):
    u = g ∫0^ts (A(t) − μt) dt, A the floor velocity / g, ts = A_end/μ when the block stops."""
    a, T, d = RECT_G, RECT_S, RAMP_S
    stop_s = a * (T + d / 2.0) / mu
    area = a * T ** 2 / 2.0 + a * T * d + a * d ** 2 / 3.0 + a * (T + d / 2.0) * (stop_s - T - d)
    return G * (area - mu * stop_s ** 2 / 2.0)


def rect_record(folder: Path) -> Path:
    """0.5 g held for 0.5 s (samples every 0.01 s), then the floor at rest: 3 s in all."""
    time_s = np.round(np.arange(0.0, 3.0 + 1e-9, 0.01), 2)
    accel = np.where(time_s <= RECT_S + 1e-9, RECT_G, 0.0)
    accel[-1] = 0.0
    path = folder / "rect.csv"
    pd.DataFrame({"time_s": time_s, "accel_g": accel}).to_csv(path, index=False)
    return path


def rect_inventory(folder, mu_range, clearance_cm=60.0, mu=0.25):
    item = {"id": "BOX", "name": "box", "room": "", "floor": 0, "height_m": 1.0, "width_m": 1.0,
            "depth_m": 1.2, "mass_kg": 100.0, "mu": mu, "mu_static": mu, "clearance_m": clearance_cm / 100,
            "cg_height_m": 0.5, "anchored": False, "quantity": 1, "row": 2,
            "mu_low": mu_range[0], "mu_high": mu_range[1]}
    hazard = pd.DataFrame([{"level": "test", "level_label": "test", "motion": "rect", "all_floors": False,
                            "floor": 0, "pta_g": np.nan, "tp_s": np.nan, "vp_m_s": np.nan, "pulse": "",
                            "record_path": str(rect_record(folder)), "scale": 1.0, "row": 2,
                            "record_2_path": "", "azimuth_deg": 0.0}])
    hazard["floor"] = hazard["floor"].astype("Int64")
    return Inventory(path=Path(folder) / "test.xlsx", equipment=pd.DataFrame([item]), hazard=hazard,
                     settings=Settings())


def test_every_run_at_each_mu_node_is_newmarks_closed_form_and_the_probability_weighs_the_nodes(tmp_path):
    """b/h = 1 > μs: pure sliding. Under the rectangular pulse each μ node's run is Newmark's closed form;
    P(sliding > 60 cm) is the weight of the nodes whose closed-form sliding exceeds 60 cm (μ < 0.255)."""
    result = run_assessment(rect_inventory(tmp_path, (0.2, 0.3)), "test")
    runs = result.suite_runs
    nodes, weights = friction_nodes(0.2, 0.25, 0.3, per_side=4)
    assert sorted(runs["mu"].round(12)) == sorted(np.round(nodes, 12))
    np.testing.assert_allclose(runs.sort_values("mu")["sliding_cm"], newmark_sliding_m(np.sort(nodes)) * 100,
                               rtol=1e-9)
    np.testing.assert_allclose(runs.sort_values("mu")["mu_weight"], weights, rtol=1e-12)
    row = result.summary.iloc[0]
    beyond = newmark_sliding_m(nodes) > 0.60
    assert 0.0 < beyond.mean() < 1.0
    assert row["p_beyond_clearance"] == pytest.approx(weights[beyond].sum(), rel=1e-12)
    # the μ values are a quadrature, not draws: the interval still counts one history (one record)
    from assess.fragility.suite import binomial_interval
    assert row["suite_histories"] == 1
    assert (row["p_beyond_clearance_low"], row["p_beyond_clearance_high"]) == pytest.approx(
        binomial_interval(weights[beyond].sum(), 1))
    # the ends: every run at mu_low slides past 60 cm (92 cm), none at mu_high (41 cm)
    assert row["p_beyond_clearance_mu_low"] == 1.0 and row["p_beyond_clearance_mu_high"] == 0.0
    assert (row["risk_mu_low"], row["risk_mu_high"]) == ("high", "low")
    assert items_whose_class_changes(result.summary) == ["BOX"]
    assert "depends on where mu lies in 0.20-0.30" in row["mu_range_note"]
    assert row["mu_range_note"] in row["demand_note"]
    # motions.csv stays one row per item x motion x direction, at the nominal mu
    assert len(result.motions) == 2
    assert result.motions["sim_sliding_max_cm"].iloc[0] == pytest.approx(newmark_sliding_m(0.25) * 100, rel=1e-9)


def test_without_a_range_nothing_changes(tmp_path):
    """A zero-width range (mu_low = mu = mu_high) and no range give the same numbers as each other."""
    none = run_assessment(rect_inventory(tmp_path, (np.nan, np.nan)), "test").summary.iloc[0]
    zero = run_assessment(rect_inventory(tmp_path, (0.25, 0.25)), "test").summary.iloc[0]
    for column in ("p_beyond_clearance", "demand_median_cm", "demand_p84_cm", "risk", "p_overturn"):
        assert none[column] == zero[column]
    assert none["demand_median_cm"] == pytest.approx(newmark_sliding_m(0.25) * 100, rel=1e-9)
    assert none["risk_mu_low"] == "" and none["mu_range_note"] == ""


def test_a_class_that_does_not_change_says_so(tmp_path):
    """Clearance 200 cm: no μ of 0.2-0.3 slides that far (at most 92 cm)."""
    row = run_assessment(rect_inventory(tmp_path, (0.2, 0.3), clearance_cm=200.0), "test").summary.iloc[0]
    assert row["risk_mu_low"] == row["risk_mu_high"] == row["risk"] == "low"
    assert row["mu_range_note"] == "Its risk class is low wherever mu lies in 0.20-0.30."


# ----------------------------------------------------------------------------- units of the step
def cases_frame(mu, mu_static, mu_low, mu_high, b_over_h):
    return pd.DataFrame({"id": ["A", "A"], "direction": [1, 2], "mu": mu, "mu_static": mu_static,
                         "mu_low": mu_low, "mu_high": mu_high, "b_over_h": [b_over_h, 2 * b_over_h]})


def test_items_that_may_uplift_get_more_mu_values_and_mu_static_keeps_its_ratio():
    from assess.fragility.friction_range import NODES_PER_SIDE_SLIDING, NODES_PER_SIDE_UPLIFT, expand_cases

    sliding = expand_cases(cases_frame(0.2, 0.24, 0.15, 0.25, b_over_h=0.5))  # μs at mu_high 0.30 < 0.5
    rocking = expand_cases(cases_frame(0.2, 0.24, 0.15, 0.25, b_over_h=0.28))  # 0.30 > 0.28: may uplift
    assert sliding["mu_node"].nunique() == 2 * NODES_PER_SIDE_SLIDING + 1
    assert rocking["mu_node"].nunique() == 2 * NODES_PER_SIDE_UPLIFT + 1
    np.testing.assert_allclose(rocking["mu_static"] / rocking["mu"], 1.2, rtol=1e-12)
    nominal = rocking[rocking["mu_nominal"]]
    assert len(nominal) == 2 and (nominal["mu"] == 0.2).all()  # the first rows: the cases as given
    assert rocking.groupby("direction")["mu_weight"].sum().tolist() == pytest.approx([1.0, 1.0], rel=1e-12)


def test_the_method_text_names_exactly_the_items_whose_class_changes():
    from assess.fragility.friction_range import method_text

    summary = pd.DataFrame({"id": ["A", "B", "C", "D"], "mu_low": [0.1, 0.2, np.nan, 0.3],
                            "risk_mu_low": ["high", "low", "", "moderate"],
                            "risk_mu_high": ["low", "low", "", "high"]})
    assert items_whose_class_changes(summary) == ["A", "D"]
    text = method_text(summary)
    assert "3 items give a range" in text and "changes for 2 items (A, D)" in text
    assert method_text(summary.assign(mu_low=np.nan)) == ""


def test_an_overturning_share_weighted_over_mu_is_not_read_as_a_count_of_motions():
    from assess.report.advice import suite_share_text as _suite_share_text

    assert _suite_share_text(1 / 3, {"suite_motions": 3, "suite_histories": 3}) == "1 of its 3 motions"
    assert _suite_share_text(0.1, {"suite_motions": 3, "suite_histories": 3}) == \
        "a weighted 10% of its 3 motions over its range of mu"
