"""Ground suites for a design-earthquake target: records selected and scaled, synthetic motions matched,
and the equipment demand under each.

Run: python benchmarks/bench_ground_suite.py [--synthetic 11]

Prints, for the ASCE 7 design spectrum SDS 1.0 g, SD1 0.6 g, TL 8 s (the DE level) and the
periods that matter 0.35, 0.7 and 1.4 s (range 0.07-2.8 s, ASCE 7-22 §16.2.3.1):

1. the suite of 11 selected from pyslammer's 18 records and scaled (assess.site.suite.select_and_scale):
   each motion's file, scale factor, PGA and log misfit, and per period the target, the suite's mean
   and their ratio: the checks of ASCE 7-22 §16.2.2-16.2.3.2;
2. synthetic spectrum-compatible motions (assess.site.suite.synthetic_suite): per motion the smallest
   and largest ratio of its spectrum to the target over the range (on 1500 periods), attempts, seconds;
3. equipment demand under the suites (and, as a control, under the same 11 records each spectrally matched
   to the target by the synthetics' own Fourier matching, so that records and synthetics differ only in
   their phases and envelopes, not in their spectra), through the engine (assess.mechanics.engine.simulate_cases):
   the paper's three prototypes (Konstantinidis & Makris 2010 Table 1, μ slow-pull, as in
   inventories/km2010-prototypes.xlsx), a slender shelf and a squat chest freezer: geometric mean of
   the peak sliding under the synthetic motions over that under the records (peaks below 0.1 mm taken
   as 0.1 mm), σ ln of the peak sliding in each suite, and the share of motions that overturn the item.

Not a test: the figures go into the report of the work.
"""
from __future__ import annotations

import argparse
import time
from importlib import resources

import numpy as np

from assess.hazard.processing import peak_velocity_m_s
from assess.mechanics.block import Block
from assess.mechanics.engine import simulate_cases
from assess.hazard.records import Record
from assess.site import asce7, suite
from assess.site.spectrum import pseudo_acceleration_spectrum

PERIODS_THAT_MATTER_S = [0.35, 0.7, 1.4]
FLOOR_M = 1e-4

#: (name, height [m], base width 2b [m], μ): the prototypes of Konstantinidis & Makris (2010) Table 1 with
#: their slow-pull μ (Table 3), as in inventories/km2010-prototypes.xlsx; a slender shelf and a chest freezer.
ITEMS = [
    ("FORMA", 2.286, 0.622, 0.23),
    ("KELVINATOR", 2.134, 0.660, 0.28),
    ("ASP", 1.803, 0.584, 0.31),
    ("slender shelf", 2.000, 0.400, 0.40),
    ("squat freezer", 0.850, 0.700, 0.30),
]


def demand(blocks, motions):
    records = [m.first.accel_g for m in motions]
    dts = [m.first.dt_s for m in motions]
    n_b, n_m = len(blocks), len(motions)
    case_blocks = [b for b in blocks for _ in range(n_m)]
    index = np.tile(np.arange(n_m), n_b)
    peaks = simulate_cases(case_blocks, records, dts, index)
    return (peaks.sliding_max_m.reshape(n_b, n_m), peaks.overturned.reshape(n_b, n_m))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--synthetic", type=int, default=11, help="synthetic motions (default 11)")
    args = parser.parse_args()
    target = asce7.from_design_values(1.0, 0.6, 8.0)
    folder = resources.files("pyslammer") / "sample_ground_motions"

    start = time.perf_counter()
    candidates = suite.read_records_folder(folder)
    selected = suite.select_and_scale(candidates, target.design_g, PERIODS_THAT_MATTER_S, level="DE")
    seconds = time.perf_counter() - start
    print(f"DE target: SDS 1.0 g, SD1 0.6 g, TL 8 s; periods that matter {PERIODS_THAT_MATTER_S} s -> range "
          f"{selected.lower_s:.3g}-{selected.upper_s:.3g} s\n")
    print(f"1. Suite selected from pyslammer's {len(candidates)} records ({seconds:.1f} s):")
    for note in selected.notes:
        print(f"   {note}")
    table = selected.ground_motions[["motion", "scale_factor", "pga_g", "misfit_ln"]]
    print(table.to_string(index=False, float_format=lambda x: f"{x:.3f}"))
    inside = selected.spectrum[selected.spectrum.in_range]
    print(inside[["period_s", "target_g", "suite_mean_g", "ratio"]].to_string(index=False,
                                                                                 float_format=lambda x: f"{x:.3f}"))
    grid = np.geomspace(selected.lower_s, selected.upper_s, 1500)
    mean = np.mean([pseudo_acceleration_spectrum(m.first.accel_g, m.first.dt_s, grid) for m in selected.motions],
                   axis=0) / target.design_g(grid)
    print(f"   §16.2.2 suite size {len(selected.motions)} (>= 11); scale factors "
          f"{selected.scale_factors.min():.3f}-{selected.scale_factors.max():.3f} (bounds 0.25-4); "
          f"§16.2.3.2 suite mean / target over the range (1500 periods): min {mean.min():.3f}, max {mean.max():.3f}\n")

    print(f"2. {args.synthetic} synthetic motions matched to the same target:")
    motions = []
    worst_low, worst_high = np.inf, 0.0
    total = time.perf_counter()
    for index in range(args.synthetic):
        tick = time.perf_counter()
        seed = suite.motion_seed(index)
        record, error = suite.synthetic_motion(target.design_g, selected.lower_s, selected.upper_s, seed,
                                                         name=f"DE synthetic {index + 1}")
        ratio = pseudo_acceleration_spectrum(record.accel_g, record.dt_s, grid) / target.design_g(grid)
        worst_low, worst_high = min(worst_low, ratio.min()), max(worst_high, ratio.max())
        motions.append(suite.Motion(record.name, record, None, "synthetic", seed))
        print(f"   motion {index + 1:2d}: Sa/target {ratio.min():.3f}-{ratio.max():.3f}, PGA {record.pta_g:.3f} g, "
              f"largest deviation {error:.3f}, {time.perf_counter() - tick:.1f} s")
    print(f"   all: Sa/target {worst_low:.3f}-{worst_high:.3f} over {selected.lower_s:.3g}-{selected.upper_s:.3g} s; "
          f"{time.perf_counter() - total:.0f} s in all\n")

    for label, suite_motions in (("records (scaled)", selected.motions), ("synthetic", motions)):
        pga = np.array([m.first.pta_g for m in suite_motions])
        pgv = np.array([peak_velocity_m_s(m.first.accel_g, m.first.dt_s) for m in suite_motions])
        print(f"   {label:17s}: PGA median {np.median(pga):.3f} g (range {pga.min():.3f}-{pga.max():.3f}), "
              f"PGV median {100 * np.median(pgv):.1f} cm/s (range {100 * pgv.min():.1f}-{100 * pgv.max():.1f})")
    print()

    tick = time.perf_counter()
    matched = []
    for m in selected.motions:
        accel, error = suite.match_spectrum(m.first.accel_g, m.first.dt_s, target.design_g, selected.lower_s,
                                            selected.upper_s)
        matched.append(suite.Motion(m.name + " matched", Record(accel, m.first.dt_s, m.name), None, m.source))
        worst = float(np.max(np.abs(pseudo_acceleration_spectrum(accel, m.first.dt_s, grid) / target.design_g(grid) - 1)))
        print(f"   record {m.name:32s} matched: largest |Sa/target - 1| {worst:.3f}, PGA {np.abs(accel).max():.3f} g")
    print(f"   ({time.perf_counter() - tick:.0f} s)\n")

    blocks = [Block(half_width_m=w / 2, cg_height_m=h / 2, height_m=h, mu=mu) for _, h, w, mu in ITEMS]
    tick = time.perf_counter()
    sliding_records, over_records = demand(blocks, selected.motions)
    sliding_synthetic, over_synthetic = demand(blocks, motions)
    sliding_matched, over_matched = demand(blocks, matched)
    print(f"3. Equipment demand (engine, {len(blocks)} items x {len(selected.motions)} + {len(motions)} + {len(matched)} motions, "
          f"{time.perf_counter() - tick:.1f} s); peak sliding floored at {FLOOR_M * 1000:g} mm:")
    print(f"   {'item':14s} {'b/h':>5s} {'mu':>5s} {'gm rec cm':>9s} {'gm syn cm':>9s} {'syn/rec':>7s} "
          f"{'sln rec':>7s} {'sln syn':>7s} {'over rec':>8s} {'over syn':>8s}")
    ratios = []
    for k, (name, h, w, mu) in enumerate(ITEMS):
        rec = np.log(np.maximum(sliding_records[k], FLOOR_M))
        syn = np.log(np.maximum(sliding_synthetic[k], FLOOR_M))
        ratio = float(np.exp(syn.mean() - rec.mean()))
        ratios.append(ratio)
        print(f"   {name:14s} {w / h:5.2f} {mu:5.2f} {100 * np.exp(rec.mean()):9.2f} {100 * np.exp(syn.mean()):9.2f} "
              f"{ratio:7.2f} {rec.std(ddof=1):7.2f} {syn.std(ddof=1):7.2f} "
              f"{over_records[k].mean():8.0%} {over_synthetic[k].mean():8.0%}")
    print(f"   geometric mean over the items of syn/rec: {np.exp(np.mean(np.log(ratios))):.2f}")
    print("   control: records matched to the target (each within the range as printed above):")
    print(f"   {'item':14s} {'gm mat cm':>9s} {'syn/mat':>7s} {'mat/rec':>7s} {'sln mat':>7s} {'over mat':>8s}")
    for k, (name, h, w, mu) in enumerate(ITEMS):
        rec = np.log(np.maximum(sliding_records[k], FLOOR_M))
        syn = np.log(np.maximum(sliding_synthetic[k], FLOOR_M))
        mat = np.log(np.maximum(sliding_matched[k], FLOOR_M))
        print(f"   {name:14s} {100 * np.exp(mat.mean()):9.2f} {np.exp(syn.mean() - mat.mean()):7.2f} "
              f"{np.exp(mat.mean() - rec.mean()):7.2f} {mat.std(ddof=1):7.2f} {over_matched[k].mean():8.0%}")


if __name__ == "__main__":
    main()
