"""A pelicun damage assessment of the items an assess run exports (``fragility/``): the test-only peer of
:mod:`assess.fragility.pelicun_export`.

It does what a FEMA P-58 user does with the export, and nothing else: the asset model from
``fragility/cmp_marginals.csv`` as written (each item at the story pelicun counts), the damage model from
``fragility/fragility.csv``, and a demand sample with a different peak floor acceleration at every level
(``PFA-<level>-<dir>``, level 0 the ground), so that an item reading any floor but its own gets another
probability. pelicun's defaults are kept (``DemandOffset`` ``{"PFA": -1}``).

Run as a script on a run's folder, it prints per item what pelicun computes and what the exported
fragility gives at the PFA of the item's own floor::

    python tests/peers/pelicun_dl.py reports/lab-2in50/fragility [--pfa-by-floor 0.55,0.63,...]
"""
from __future__ import annotations

import argparse
import csv
from pathlib import Path

import numpy as np
import pandas as pd
from scipy import stats

#: pelicun's default offset of a PFA demand (its settings/default_config.json): story s reads PFA-(s-1).
PFA_OFFSET = -1


def demand_levels(pfa_by_level_g, factors=(0.6, 1.0, 1.5)) -> np.ndarray:
    """Rows of PFA by level [g]: the given floor accelerations times each factor (one row per factor)."""
    base = np.asarray(pfa_by_level_g, dtype=float)
    return np.array([base * f for f in factors])


def run_pelicun(folder, rows_g: np.ndarray, repeats: int = 4000, seed: int = 7, work=None) -> pd.DataFrame:
    """Damage states pelicun computes for every exported item, per row of ``rows_g`` (PFA by level [g]).

    Returns one row per item and demand row: ``id``, ``location`` (pelicun story), ``row``, ``p_ds1_or_more``,
    ``p_ds2`` (shares of the ``repeats`` realisations of that row). Incomplete items are left out (pelicun
    drops them); ``missing`` in ``attrs`` names them.
    """
    from pelicun.assessment import Assessment

    folder = Path(folder)
    work = Path(work) if work is not None else folder
    marginals = pd.read_csv(folder / "cmp_marginals.csv", index_col=0)
    levels = rows_g.shape[1]
    stories = int(marginals["Location"].max())
    if stories > levels:
        raise ValueError(f"the demand gives {levels} levels; story {stories} needs PFA-{stories - 1}")
    demand_csv = work / "pelicun_demand.csv"
    n = rows_g.shape[0] * repeats
    which = np.tile(np.arange(rows_g.shape[0]), repeats)  # interleaved rows
    with demand_csv.open("w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        columns = [f"1-PFA-{k}-{d}" for k in range(levels) for d in (1, 2)]
        writer.writerow([""] + columns)
        writer.writerow(["Units"] + ["g"] * len(columns))
        for i, r in enumerate(which):
            writer.writerow([i] + [f"{rows_g[r, k]:.6g}" for k in range(levels) for _ in (1, 2)])
    asmnt = Assessment({"PrintLog": False, "Seed": seed})
    asmnt.stories = max(stories, levels - 1)
    asmnt.demand.load_sample(str(demand_csv))
    asmnt.asset.load_cmp_model({"marginals": str(folder / "cmp_marginals.csv")})
    asmnt.asset.generate_cmp_sample(n)
    asmnt.damage.load_model_parameters([str(folder / "fragility.csv")],
                                       set(asmnt.asset.list_unique_component_ids()), warn_missing=True)
    asmnt.damage.calculate()
    sample = asmnt.damage.ds_model.sample
    out = []
    for (cmp, loc), block in sample.T.groupby(level=["cmp", "loc"]):
        per_state = block.groupby(level="ds").sum().T  # quantity in each damage state, per realisation
        quantity = per_state.sum(axis=1).to_numpy()
        damaged = per_state.drop(columns="0", errors="ignore").sum(axis=1).to_numpy() / quantity
        ds2 = (per_state["2"].to_numpy() / quantity) if "2" in per_state else np.zeros(n)
        for r in range(rows_g.shape[0]):
            out.append({"id": cmp, "location": int(loc), "row": r, "p_ds1_or_more": damaged[which == r].mean(),
                        "p_ds2": ds2[which == r].mean()})
    table = pd.DataFrame(out)
    table.attrs["missing"] = list(asmnt.damage.missing_components)
    return table


def exported_probabilities(folder, rows_g: np.ndarray, floor_offset: int = 0) -> pd.DataFrame:
    """P(DS ≥ 1) = max(Φ₁, Φ₂) and P(DS2) = Φ₂ of the exported lognormals, at the PFA of each item's own floor
    (the story in cmp_marginals.csv − 1 = its assess floor, + ``floor_offset``: −1 gives the floor below)."""
    folder = Path(folder)
    marginals = pd.read_csv(folder / "cmp_marginals.csv", index_col=0)
    fragility = pd.read_csv(folder / "fragility.csv", index_col=0)
    out = []
    for cmp, m in marginals.iterrows():
        f = fragility.loc[cmp]
        if f["Incomplete"] == 1:
            continue
        level = int(m["Location"]) + PFA_OFFSET + floor_offset
        for r in range(rows_g.shape[0]):
            a = rows_g[r, level] if 0 <= level < rows_g.shape[1] else np.nan
            p1 = stats.norm.cdf(np.log(a / f["LS1-Theta_0"]) / f["LS1-Theta_1"])
            p2 = (stats.norm.cdf(np.log(a / f["LS2-Theta_0"]) / f["LS2-Theta_1"])
                  if pd.notna(f["LS2-Theta_0"]) else 0.0)
            out.append({"id": cmp, "floor_read": level, "row": r, "pfa_g": a, "p_ds1_or_more": max(p1, p2),
                        "p_ds2": p2})
    return pd.DataFrame(out)


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder", type=Path)
    parser.add_argument("--pfa-by-floor", help="PFA [g] of floors 0, 1, ...: default 0.5 + 0.1 per floor")
    parser.add_argument("--repeats", type=int, default=4000)
    args = parser.parse_args(argv)
    marginals = pd.read_csv(args.folder / "cmp_marginals.csv", index_col=0)
    levels = int(marginals["Location"].max())
    pfa = ([float(v) for v in args.pfa_by_floor.split(",")] if args.pfa_by_floor
           else [0.5 + 0.1 * k for k in range(levels)])
    rows = demand_levels(pfa)
    got = run_pelicun(args.folder, rows, repeats=args.repeats)
    want = exported_probabilities(args.folder, rows)
    below = exported_probabilities(args.folder, rows, floor_offset=-1)
    table = got.merge(want, on=["id", "row"], suffixes=("_pelicun", "_fragility")).merge(
        below[["id", "row", "p_ds1_or_more"]].rename(columns={"p_ds1_or_more": "p_ds1_or_more_floor_below"}),
        on=["id", "row"])
    pd.set_option("display.width", 200)
    pd.set_option("display.max_rows", 500)
    print(f"PFA by floor (row 1; rows 0 and 2 are x0.6 and x1.5): {', '.join(f'{v:.3g}' for v in rows[1])} g")
    print(table.round(3).to_string(index=False))
    print("pelicun left out (Incomplete):", ", ".join(got.attrs["missing"]) or "none")
    print("largest |pelicun - fragility at its own floor|:",
          f"{(table['p_ds1_or_more_pelicun'] - table['p_ds1_or_more_fragility']).abs().max():.4f}")


if __name__ == "__main__":
    main()
