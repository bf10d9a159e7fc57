"""How much sliding under both horizontal components differs from the one-way answers, and its cost.

Run: python benchmarks/bench_sliding_2d.py [--blocks 3] [--repeat 5]

Record pairs: pyslammer's 18 sample records, each with the next one in name order
(the last with the first); the second is resampled linearly onto the first's steps
and both are cut to the shorter duration. Each pair is scaled by one factor so that
the larger of its two component PGAs is 0.4 g, then 0.7 g.

Prints, for μ 0.1, 0.2, 0.3 (μs = μ) and each PGA:

* the ratio of the peak distance from rest under both components at once
  (assess.mechanics.sliding_2d) to the larger of the two one-way peaks, each
  component alone (assess.mechanics.sliding, the tool's present answer):
  median, range and how many pairs exceed 1 (also over all cases, and over those
  whose one-way peak is at least 1 cm);
* the cost per block-step of the two kernels (peaks only, serial batch of
  ``--blocks`` blocks over the 18 pairs), with the 2-D kernel's default 1 ms substep
  and a 0.25 ms one.

Not a test: numbers for the lead and the docs.
"""
from __future__ import annotations

import argparse
import os

import numpy as np

from assess.mechanics.sliding import sliding_peaks_batch
from assess.mechanics.sliding_2d import DEFAULT_MAX_SUBSTEP_S, sliding_2d_peaks_batch
from timing import best_of

PGAS_G = (0.4, 0.7)
MUS = (0.1, 0.2, 0.3)


def record_pairs():
    """[(name_x, name_y, accel_x_g, accel_y_g, dt_s)] for the 18 pairs (unscaled)."""
    import pyslammer

    motions = sorted(pyslammer.sample_ground_motions().items())
    pairs = []
    for (name_x, first), (name_y, second) in zip(motions, motions[1:] + motions[:1]):
        ax, dt = np.asarray(first.accel, dtype=float), float(first.dt)
        b = np.asarray(second.accel, dtype=float)
        t_b = np.arange(b.size) * float(second.dt)
        t = np.arange(0.0, min(ax.size * dt, t_b[-1]), dt)
        n = min(t.size, ax.size)
        pairs.append((name_x, name_y, ax[:n], np.interp(t[:n], t_b, b), dt))
    return pairs


def padded(rows):
    lengths = np.array([r.size for r in rows], dtype=np.int64)
    out = np.zeros((len(rows), lengths.max()))
    for i, r in enumerate(rows):
        out[i, :r.size] = r
    return out, lengths


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--blocks", type=int, default=3)
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()

    pairs = record_pairs()
    dt = np.array([p[4] for p in pairs])
    print(f"{len(pairs)} record pairs; load average {os.getloadavg()[0]:.2f} at start")
    print("\nratio = 2-D peak distance from rest / max(1-D peak under x alone, 1-D peak under y alone)")
    print(f"{'PGA g':>6} {'mu':>5} {'median':>7} {'min':>6} {'max':>6} {'>1':>6}   pair with the largest ratio")
    all_ratios, all_one_way = [], []
    for pga in PGAS_G:
        xs, ys = [], []
        for _, _, ax, ay, _ in pairs:
            scale = pga / max(np.abs(ax).max(), np.abs(ay).max())
            xs.append(ax * scale)
            ys.append(ay * scale)
        ax_2d, lengths = padded(xs)
        ay_2d, _ = padded(ys)
        mus = np.array(MUS)
        peak_2d, _ = sliding_2d_peaks_batch(ax_2d, ay_2d, dt, mus, record_lengths=lengths)
        peak_x, _ = sliding_peaks_batch(ax_2d, dt, mus, record_lengths=lengths)
        peak_y, _ = sliding_peaks_batch(ay_2d, dt, mus, record_lengths=lengths)
        for i, mu in enumerate(MUS):
            one_way = np.maximum(peak_x[i], peak_y[i])
            slides = one_way > 0.0
            ratio = peak_2d[i, slides] / one_way[slides]
            all_ratios.extend(ratio)
            all_one_way.extend(one_way[slides])
            worst = np.flatnonzero(slides)[np.argmax(ratio)]
            print(f"{pga:>6.1f} {mu:>5.2f} {np.median(ratio):>7.3f} {ratio.min():>6.3f} {ratio.max():>6.3f} "
                  f"{np.sum(ratio > 1.0):>3}/{ratio.size:<2}   {pairs[worst][0]} + {pairs[worst][1]}"
                  f" ({peak_2d[i, worst] * 100:.1f} cm vs {one_way[worst] * 100:.1f} cm)")
    all_ratios = np.array(all_ratios)
    print(f"{'all':>6} {'':>5} {np.median(all_ratios):>7.3f} {all_ratios.min():>6.3f} {all_ratios.max():>6.3f} "
          f"{np.sum(all_ratios > 1.0):>3}/{all_ratios.size}")
    big = np.array(all_one_way) >= 0.01
    print(f"{'1-D >= 1 cm':>12} {np.median(all_ratios[big]):>7.3f} {all_ratios[big].min():>6.3f} "
          f"{all_ratios[big].max():>6.3f} {np.sum(all_ratios[big] > 1.0):>3}/{big.sum()}"
          f"   (cases where the one-way answer is at least 1 cm)")

    # cost per block-step, peaks only, serial (fewer blocks than 2 x threads), PGA 0.7 g
    xs = [ax * 0.7 / max(np.abs(ax).max(), np.abs(ay).max()) for _, _, ax, ay, _ in pairs]
    ys = [ay * 0.7 / max(np.abs(ax).max(), np.abs(ay).max()) for _, _, ax, ay, _ in pairs]
    ax_2d, lengths = padded(xs)
    ay_2d, _ = padded(ys)
    mu = np.random.default_rng(2010).uniform(0.1, 0.3, args.blocks)
    block_steps = args.blocks * int((lengths - 1).sum())
    sliding_peaks_batch(ax_2d, dt, mu[:1], record_lengths=lengths)  # compile / load the caches
    sliding_2d_peaks_batch(ax_2d, ay_2d, dt, mu[:1], record_lengths=lengths)
    t_1d, _ = best_of(args.repeat, lambda: sliding_peaks_batch(ax_2d, dt, mu, record_lengths=lengths))
    print(f"\ncost per block-step, {args.blocks} blocks (μ uniform 0.1-0.3) x {len(pairs)} pairs at PGA 0.7 g, "
          f"{block_steps} block-steps, best of {args.repeat}:")
    print(f"  1-D exact kernel, one component:        {t_1d / block_steps * 1e9:8.1f} ns")
    for substep in (DEFAULT_MAX_SUBSTEP_S, 2.5e-4):
        t_2d, _ = best_of(args.repeat, lambda: sliding_2d_peaks_batch(ax_2d, ay_2d, dt, mu, record_lengths=lengths,
                                                                      max_substep_s=substep))
        print(f"  2-D kernel, substep {substep * 1e3:.2f} ms:             {t_2d / block_steps * 1e9:8.1f} ns"
              f"   ({t_2d / t_1d:.1f} x the 1-D kernel; vs two 1-D runs {t_2d / (2 * t_1d):.1f} x)")


if __name__ == "__main__":
    main()
