"""Is the engine's answer monotone in the friction coefficient μ? On lab.xlsx's items and pyslammer's records.

Run: python benchmarks/bench_mu_monotone.py [--values 9] [--pga 0.5,1.0]

Each freestanding item of ``inventories/lab.xlsx``, in both base directions,
runs under pyslammer's 18 sample records, each scaled to the PGAs given, at
``--values`` μ values evenly spaced over its range: ``mu_low``-``mu_high``
where the workbook gives one, else ``mu`` to 1.6 ``mu`` (the paper's slow-pull
over best-fit ratio is 1.55-1.77); ``mu_static`` scaled with μ. A sequence
(item, direction, record, PGA) is

* ``sliding`` when the item cannot uplift at the top of its range
  (μs < b/h, :func:`assess.mechanics.engine.pure_sliding_proved`): the exact
  sliding kernel answers at every μ;
* ``may uplift`` otherwise.

Prints, per class, how many sequences have a peak sliding that ever grows
with μ (by more than 1 µm), the largest such growth, how often a μ inside the
range slides farther than both ends (the ends then do not bracket the range),
and, for ``may uplift``,
how many change mode, how many overturn at some μ and not at a larger one
(or the reverse). Not a test: numbers for the docs (the test of the claim is
tests/fragility/test_friction_range.py).
"""
from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from assess.inventory import read_workbook
from assess.mechanics.block import Block
from assess.mechanics.engine import pure_sliding_proved, simulate_cases

LAB = Path(__file__).resolve().parent.parent / "inventories" / "lab.xlsx"
#: Growth of the peak sliding with μ below this [m] is round-off, not a trend.
TOLERANCE_M = 1e-6


def records():
    import pyslammer

    return [(name, np.asarray(m.accel, dtype=float), float(m.dt))
            for name, m in sorted(pyslammer.sample_ground_motions().items())]


def sequences(values: int):
    """[(id, direction, b/h, μ values, μs values, blocks)] for lab.xlsx's freestanding items."""
    equipment = read_workbook(LAB).equipment
    out = []
    for item in equipment[~equipment["anchored"]].itertuples(index=False):
        low, high = (item.mu_low, item.mu_high) if np.isfinite(item.mu_low) else (item.mu, 1.6 * item.mu)
        mus = np.linspace(low, high, values)
        ratio = item.mu_static / item.mu
        for direction, base_m in ((1, item.width_m), (2, item.depth_m)):
            blocks = [Block(half_width_m=base_m / 2.0, cg_height_m=item.cg_height_m, height_m=item.height_m,
                            mu=float(mu), mu_static=float(mu * ratio)) for mu in mus]
            out.append((item.id, direction, base_m / 2.0 / item.cg_height_m, mus, mus * ratio, blocks))
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--values", type=int, default=9)
    parser.add_argument("--pga", default="0.5,1.0")
    args = parser.parse_args()
    pgas = [float(x) for x in args.pga.split(",")]
    motions = records()
    seqs = sequences(args.values)
    blocks = [b for s in seqs for b in s[5]]
    stats = {"sliding": [], "may uplift": []}
    for pga in pgas:
        scaled = [accel * pga / np.max(np.abs(accel)) for _, accel, _ in motions]
        for j, (name, _, dt) in enumerate(motions):
            peaks = simulate_cases(blocks, [scaled[j]], [dt], np.zeros(len(blocks), dtype=np.int64))
            start = 0
            for item_id, direction, b_over_h, mus, statics, seq_blocks in seqs:
                n = len(seq_blocks)
                sliding = peaks.sliding_max_m[start:start + n]
                over = peaks.overturned[start:start + n]
                modes = peaks.mode[start:start + n]
                start += n
                kind = "sliding" if bool(pure_sliding_proved(statics[-1], b_over_h)) else "may uplift"
                growth = np.diff(sliding)
                stats[kind].append({
                    "id": item_id, "direction": direction, "record": name, "pga": pga,
                    "grows": bool(np.any(growth > TOLERANCE_M)),
                    "growth_m": float(max(growth.max(initial=0.0), 0.0)),
                    "growth_rel": float(max((growth / np.maximum(sliding[:-1], 1e-12)).max(initial=0.0), 0.0))
                    if np.any(growth > TOLERANCE_M) else 0.0,
                    "slides": bool(sliding.max() > 0.0),
                    # does a μ inside the range slide farther than both ends (the ends do not bracket it)?
                    "beyond_ends_m": float(max(sliding[1:-1].max(initial=0.0) - max(sliding[0], sliding[-1]), 0.0)),
                    "beyond_ends_rel": float(max(sliding[1:-1].max(initial=0.0) / max(sliding[0], sliding[-1], 1e-12)
                                                 - 1.0, 0.0)),
                    "modes": len(set(modes)), "overturn_flips": int(np.sum(np.diff(over.astype(int)) != 0)),
                    "overturn_non_monotone": bool(np.any(np.diff(over.astype(int)) > 0)),
                })
    print(f"lab.xlsx freestanding items x 2 directions x {len(motions)} pyslammer records x PGA {pgas} g, "
          f"{args.values} mu values per range")
    for kind, rows in stats.items():
        if not rows:
            continue
        grows = [r for r in rows if r["grows"]]
        slide = [r for r in rows if r["slides"]]
        print(f"\n{kind}: {len(rows)} sequences ({len(slide)} slide at some mu); peak sliding grows with mu in "
              f"{len(grows)}")
        if grows:
            worst = max(grows, key=lambda r: r["growth_m"])
            print(f"  largest growth {worst['growth_m'] * 100:.3f} cm ({worst['growth_rel']:.1%} of the smaller), "
                  f"{worst['id']} dir {worst['direction']} {worst['record']} at {worst['pga']} g")
            print(f"  items: {sorted(set(r['id'] for r in grows))}")
        beyond = [r for r in rows if r["beyond_ends_m"] > TOLERANCE_M]
        print(f"  a mu inside the range slides farther than both ends in {len(beyond)}", end="")
        if beyond:
            worst = max(beyond, key=lambda r: r["beyond_ends_rel"])
            print(f"; by at most {max(r['beyond_ends_m'] for r in beyond) * 100:.3f} cm, "
                  f"{worst['beyond_ends_rel']:.1%} of the larger end ({worst['id']} dir {worst['direction']} "
                  f"{worst['record']} at {worst['pga']} g); over 5 %: "
                  f"{sum(r['beyond_ends_rel'] > 0.05 for r in beyond)}")
        else:
            print()
        growth = np.array([r["growth_rel"] for r in grows])
        if len(growth):
            print(f"  growth over 1 % of the smaller peak: {np.sum(growth > 0.01)}, over 5 %: {np.sum(growth > 0.05)}")
        if kind == "may uplift":
            print(f"  change mode within the range: {sum(r['modes'] > 1 for r in rows)}; overturn at a mu and not "
                  f"at a smaller one: {sum(r['overturn_non_monotone'] for r in rows)}; overturn flips more than once: "
                  f"{sum(r['overturn_flips'] > 1 for r in rows)}")


if __name__ == "__main__":
    main()
