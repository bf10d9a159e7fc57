"""How the engine's sliding under the tool's motions compares with the paper's Table 3.

Run: python benchmarks/motions_vs_table3.py [--realizations 10]

For each of the 27 rows of Konstantinidis & Makris (2010) Table 3 (the three
prototypes with their best-fit μ, under Loma Prieta motions described by PTA,
Tp and vp), the peak sliding the engine gives under

* the synthetic near-fault histories of ``assess.hazard.synthesis`` (median of
  N seeded realisations), and
* the Type-B pulse of amplitude PTA and period Tp,

beside the Umax the paper's Working Model simulations gave under the recorded
motions (Table 3). Prints each row and the median ratio of each to Table 3.
Not a test: the motions are descriptions of the records, not the records.
"""
from __future__ import annotations

import argparse
import warnings

import numpy as np

from assess.data import km2010_table3
from assess.hazard.records import pulse_record
from assess.hazard.synthesis import synthesize_motion
from assess.mechanics.block import Block
from assess.mechanics.engine import simulate

PROTOTYPES = {"FORMA": (2.286, 0.622), "KELVINATOR": (2.134, 0.660), "ASP": (1.803, 0.584)}  # Table 1


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--realizations", type=int, default=10)
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    ratios_synthetic, ratios_pulse = [], []
    print(f"{'equipment':11s} {'motion':28s} {'PTA':>5s} {'Table 3':>8s} {'synthetic':>10s} {'Type-B':>8s}  [cm]")
    for k, row in enumerate(km2010_table3().itertuples(index=False)):
        height, width = PROTOTYPES[row.equipment]
        block = Block(half_width_m=width / 2, cg_height_m=height / 2, height_m=height, mu=row.mu_best_fit)
        histories = synthesize_motion(row.pta_g, row.tp_s, row.vp_cm_s / 100, n_realizations=args.realizations,
                                      seed=np.random.default_rng([2010, k]))
        synthetic_cm = np.median([simulate(block, h.accel_g, h.dt_s).sliding_max_m * 100 for h in histories])
        pulse = pulse_record("B", row.pta_g, row.tp_s)
        pulse_cm = simulate(block, pulse.accel_g, pulse.dt_s).sliding_max_m * 100
        ratios_synthetic.append(synthetic_cm / row.umax_cm)
        ratios_pulse.append(pulse_cm / row.umax_cm)
        print(f"{row.equipment:11s} {row.motion:28s} {row.pta_g:5.2f} {row.umax_cm:8.1f} {synthetic_cm:10.1f} "
              f"{pulse_cm:8.1f}")
    for label, ratios in (("synthetic (median of realisations)", ratios_synthetic),
                          ("Type-B pulse of amplitude PTA", ratios_pulse)):
        r = np.array(ratios)
        print(f"{label}: median ratio to Table 3 {np.median(r):.2f} (range {r.min():.2f}-{r.max():.2f})")


if __name__ == "__main__":
    main()
