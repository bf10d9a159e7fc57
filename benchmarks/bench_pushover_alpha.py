"""Does a pushover tell a frame's α apart? The OpenSees frames rebuilt with their continuous column at several α.

Run: python benchmarks/bench_pushover_alpha.py [--buildings smf8,smf12] [--alphas 5,10,12,20]
     (needs openseespy; a few seconds)

The yielding route's answer on tall frames rests on α (``lateral_stiffness_ratio``), which the strength alone
leaves open (tests/verification/test_yielding_tall.py: the system's α 12 against the 12-storey frame's 10 slides
its items 0.66 times as far). A pushover, where the engineer's ``yield_base_shear_g`` comes from, also shows
how stiff the frame stays after its storeys yield: the continuous column, which α measures against the storeys,
carries that stiffness. For each frame of tests/peers/opensees_buildings.py (``smf8``, ``smf12``) rebuilt with
its column at each α (its storeys, springs and masses kept), a static pushover under the ELF pattern
(``peers.opensees_buildings.pushover``) to 3 % roof drift gives: the base shear over the weight at first yield
(``pushover_yield_base_shear_g``), the roof drift ratio there, the base shear at 2 % roof drift, and the tangent
stiffness at 2 % over the initial one.

Measured (2026-11-29): on ``smf12`` the tangent ratio is 0.171 / 0.065 / 0.051 / 0.032 at α 5 / 10 / 12 / 20 and
the base shear at 2 % 0.179 / 0.134 / 0.129 / 0.120 W, where the first yield moves 0.082-0.090 W and its roof
drift 0.0037-0.0039; on ``smf8`` 0.154 / 0.060 / 0.049 / 0.032 and 0.298 / 0.215 / 0.204 / 0.189 W. The
pushover's stiffness after yield separates α 10 from 12 by a quarter where the first yield does not. The product
takes it since 2026-11-30: the building sheet's ``pushover_slope_ratio`` (the tangent at 2 % over the initial one,
``peers.opensees_buildings.pushover_slope_ratio``) and the tool's own pushover of its stick
(assess/building/pushover.py) find the α that gives it (tests/verification/test_truth_pushover.py).
"""
from __future__ import annotations

import argparse
import dataclasses
import sys
from pathlib import Path

import numpy as np

sys.path[:0] = [str(Path(__file__).resolve().parents[1] / "tests")]

from peers.opensees_buildings import (BUILDINGS, TALL, pushover, pushover_slope_ratio,  # noqa: E402
                                     pushover_yield_base_shear_g)


def pushover_figures(truth, alpha: float) -> dict:
    """The pushover of ``truth`` with its column at ``alpha``: first yield, and what it does at 2 % roof drift."""
    building = dataclasses.replace(truth, column_alpha=alpha)
    shear, drifts = pushover(building, roof_drift_ratio=0.03, steps=600)
    roof = np.cumsum(drifts, axis=1)[:, -1] / (building.storeys * building.storey_height_m)
    initial = shear[5] / roof[5]
    at = int(np.searchsorted(roof, 0.02))
    first_yield = pushover_yield_base_shear_g(building)
    return {"alpha": alpha, "yield_base_shear_g": first_yield, "roof_drift_at_yield": first_yield / initial,
            "base_shear_at_2pct_g": float(shear[at]), "tangent_at_2pct_over_initial": pushover_slope_ratio(building)}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--buildings", default="smf8,smf12")
    parser.add_argument("--alphas", default="5,10,12,20")
    args = parser.parse_args(argv)
    print("| building | α | first yield [W] | roof drift at first yield | base shear at 2 % [W] "
          "| tangent at 2 % / initial |")
    print("|---|---|---|---|---|---|")
    for name in args.buildings.split(","):
        truth = {**BUILDINGS, **TALL}[name]
        for alpha in (float(a) for a in args.alphas.split(",")):
            f = pushover_figures(truth, alpha)
            print(f"| {name} | {alpha:g} | {f['yield_base_shear_g']:.4f} | {f['roof_drift_at_yield']:.5f} | "
                  f"{f['base_shear_at_2pct_g']:.4f} | {f['tangent_at_2pct_over_initial']:.3f} |")


if __name__ == "__main__":
    main()
