"""Each sliding estimator for a motion given by parameters, against the sliding under the real record.

Run: python benchmarks/estimators_vs_records.py [--realizations 10] [--csv cases.csv] [--markdown]

A motion given only by PTA, Tp and vp (the workbook's parameters) has to be
turned into a sliding demand by a model. This measures each model the tool
has against what the engine gives under the real record those parameters
were identified from (exact for the rigid-block model, the sliding kernel's
exactness is tested elsewhere):

* **pyslammer's 18 records** (test-only peer data), scaled to PGA 0.4 and
  0.7 g, on a stocky block (b/h = 2: it cannot uplift) with μ = 0.1, 0.2,
  0.3; cases that slide more than 5 mm under the record. The parameters in:
  PTA = the record's PGA, Tp and vp of the Type-B pulse
  :func:`~assess.hazard.pulse_identification.identify_pulse` fits (what the
  main job does for a record given without Tp);
* **the paper's Table 3**: the 27 Working Model simulations (three
  prototypes with their best-fit μ under the recorded Loma Prieta motions),
  described by the Table's PTA, Tp and vp.

Estimators:

* ``regression`` — the paper's median (eq. 21) with the identified Tp;
* ``pulse`` — the engine under a Type-B pulse of amplitude PTA and period Tp;
* ``synthetic (vp as peak)`` — the engine under synthetic near-fault histories
  whose pulse peaks at vp (the model before the Type-B reading);
* ``synthetic`` — the same with the pulse whose Type-B approximation is
  (Tp, vp) (:func:`~assess.hazard.near_fault_pulse.type_b_reading`);
* ``governing`` — what the main job uses for a motion given by parameters:
  the regression where :func:`~assess.fragility.suite.regression_applies`,
  the synthetic model elsewhere.

Columns: n, geometric mean of predicted/actual, σ of ln(predicted/actual),
share within a factor 2. Nothing is fitted on these records:
``PULSE_SHARE_MIN`` is the smallest pulse share of the paper's own Table 3.
"""
from __future__ import annotations

import argparse
import time
import warnings

import numpy as np
import pandas as pd

from assess.data import default_settings, km2010_table3
from assess.fragility import RegressionConstants, intensity_measure, sliding_quantile
from assess.fragility.suite import PULSE_SHARE_MIN, pulse_acceleration_share, regression_applies
from assess.hazard.pulse_identification import identify_pulse
from assess.hazard.records import pulse_record
from assess.hazard.synthesis import synthesize_motion
from assess.mechanics.block import Block
from assess.mechanics.engine import simulate

PROTOTYPES = {"FORMA": (2.286, 0.622), "KELVINATOR": (2.134, 0.660), "ASP": (1.803, 0.584)}  # Table 1
PGAS_G = (0.4, 0.7)
MUS = (0.1, 0.2, 0.3)
MIN_SLIDING_M = 0.005
ESTIMATORS = ("regression", "pulse", "synthetic (vp as peak)", "synthetic", "governing")


def _synthetic_m(block, pta_g, tp_s, vp_m_s, realizations, seed, vp_reading):
    histories = synthesize_motion(pta_g, tp_s, vp_m_s, n_realizations=realizations, seed=seed,
                                  vp_reading=vp_reading)
    return float(np.median([simulate(block, h.accel_g, h.dt_s).sliding_max_m for h in histories]))


def _estimates(block, pta_g, tp_s, vp_m_s, mu, constants, realizations, seed):
    im = float(intensity_measure(pta_g, mu))
    pulse = pulse_record("B", pta_g, tp_s)
    out = {
        "im": im, "pulse_share": float(pulse_acceleration_share(pta_g, tp_s, vp_m_s)),
        "regression": float(sliding_quantile(im, pta_g, tp_s, constants)) if im > 0 else 0.0,
        "pulse": simulate(block, pulse.accel_g, pulse.dt_s).sliding_max_m,
        "synthetic (vp as peak)": _synthetic_m(block, pta_g, tp_s, vp_m_s, realizations, seed, "peak"),
        "synthetic": _synthetic_m(block, pta_g, tp_s, vp_m_s, realizations, seed, "type-b"),
    }
    applies = bool(regression_applies(out["pulse_share"], im, constants.im_min, constants.im_max, False))
    out["governing"] = out["regression"] if applies else out["synthetic"]
    return out


def pyslammer_cases(constants, realizations):
    import pyslammer

    rows = []
    for name, motion in pyslammer.sample_ground_motions().items():
        accel = np.asarray(motion.accel, dtype=float)
        dt_s = float(motion.dt)
        for pga_g in PGAS_G:
            scaled = accel * pga_g / np.max(np.abs(accel))
            fit = identify_pulse(scaled, dt_s, models=("B",))
            for mu in MUS:
                block = Block(half_width_m=1.0, cg_height_m=0.5, height_m=1.0, mu=mu)
                actual = simulate(block, scaled, dt_s).sliding_max_m
                if actual <= MIN_SLIDING_M:
                    continue
                seed = np.random.default_rng([7, len(rows)])
                rows.append({"set": "pyslammer", "motion": name, "pta_g": pga_g, "mu": mu, "tp_s": fit.tp_s,
                             "vp_m_s": fit.vp_m_s, "actual": actual,
                             **_estimates(block, pga_g, fit.tp_s, fit.vp_m_s, mu, constants, realizations, seed)})
    return rows


def table3_cases(constants, realizations):
    rows = []
    for k, row in enumerate(km2010_table3().itertuples(index=False)):
        height, width = PROTOTYPES[row.equipment]
        block = Block(half_width_m=width / 2, cg_height_m=height / 2, height_m=height, mu=row.mu_best_fit)
        seed = np.random.default_rng([2010, k])
        rows.append({"set": "Table 3", "motion": f"{row.equipment} / {row.motion}", "pta_g": row.pta_g,
                     "mu": row.mu_best_fit, "tp_s": row.tp_s, "vp_m_s": row.vp_cm_s / 100.0,
                     "actual": row.umax_cm / 100.0,
                     **_estimates(block, row.pta_g, row.tp_s, row.vp_cm_s / 100.0, row.mu_best_fit, constants,
                                  realizations, seed)})
    return rows


def scores(predicted, actual) -> dict:
    log_ratio = np.log(np.maximum(np.asarray(predicted), 1e-6) / np.asarray(actual))
    return {"n": log_ratio.size, "gm": float(np.exp(log_ratio.mean())), "sd": float(log_ratio.std(ddof=1)),
            "median": float(np.exp(np.median(log_ratio))), "within2": float(np.mean(np.abs(log_ratio) < np.log(2)))}


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--realizations", type=int, default=10)
    parser.add_argument("--csv", help="write every case here")
    parser.add_argument("--markdown", action="store_true")
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    constants = RegressionConstants.from_settings(default_settings())
    start = time.perf_counter()
    cases = pd.DataFrame(pyslammer_cases(constants, args.realizations) + table3_cases(constants, args.realizations))
    if args.csv:
        cases.to_csv(args.csv, index=False)
    bar = "|" if args.markdown else " "
    print(f"{bar} data set {bar} estimator {bar} n {bar} geometric mean {bar} median {bar} σ ln {bar} within ×2 {bar}")
    if args.markdown:
        print("|---|---|---|---|---|---|---|")
    for data_set, frame in cases.groupby("set", sort=False):
        for estimator in ESTIMATORS:
            s = scores(frame[estimator], frame["actual"])
            print(f"{bar} {data_set} {bar} {estimator} {bar} {s['n']} {bar} {s['gm']:.2f} {bar} {s['median']:.2f} {bar} "
                  f"{s['sd']:.2f} {bar} {s['within2']:.0%} {bar}")
    slammer = cases[cases["set"] == "pyslammer"].reset_index(drop=True)
    inside = slammer["pulse_share"] >= PULSE_SHARE_MIN
    for label, frame in (("pulse share >= %.2f" % PULSE_SHARE_MIN, slammer[inside]),
                         ("pulse share < %.2f" % PULSE_SHARE_MIN, slammer[~inside])):
        for estimator in ("regression", "synthetic"):
            s = scores(frame[estimator], frame["actual"])
            print(f"{bar} pyslammer, {label} {bar} {estimator} {bar} {s['n']} {bar} {s['gm']:.2f} {bar} "
                  f"{s['median']:.2f} {bar} {s['sd']:.2f} {bar} {s['within2']:.0%} {bar}")
    print(f"({time.perf_counter() - start:.0f} s, {args.realizations} synthetic histories per case)")


if __name__ == "__main__":
    main()
