"""Build ``inventories/lab-hazard-curve.csv``: an illustrative PGA hazard curve for the sample lab.

**Illustrative, not a hazard study.** It is written in the layout of an
OpenQuake engine hazard-curve export (``hazard_curve-mean-PGA_*.csv``: a
comment line with ``kind`` and ``investigation_time``, then ``lon, lat,
depth, poe-<level>...``) so that the sample runs exactly as a user's curve
would, but it was not computed by OpenQuake: it is the second-order
(quadratic in log) hazard-curve form of Vamvatsikos (2013)

    λ(a) = k0 · exp(−k1 ln a − k2 (ln a)²)          [1/yr]

with k2 = 0.4 and k0, k1 chosen so that the curve passes through the lab
workbook's two anchors: 0.40 g at 10 % in 50 years (λ = 1/475) and 0.62 g at
2 % in 50 years (λ = 1/2475; the workbook's ground motions at 2in50 have a
median PTA of 0.59 g). Probabilities of exceedance are for an investigation
time of 1 year, P = 1 − e^(−λ) (Poisson), at 20 levels from 0.005 to 3 g.
For a real building, export the site's curve from an OpenQuake run
(``oq export hazard_curves``) and give that file instead.

The same curve is also written in the layout of a USGS nshmp-haz hazard curve,
``inventories/lab-hazard-usgs/PGA/curves.csv`` (header ``name,lon,lat`` and
the levels; one row of annual rates λ, ``%.8e``, as nshmp-haz writes them), for
a US user's run; a real one is the ``hazout/PGA/curves.csv`` of an nshmp-haz
run for the site.

Vamvatsikos, D. (2013). Derivation of new SAC/FEMA performance evaluation
solutions with second-order hazard approximation. Earthquake Eng. Struct.
Dyn. 42(8):1171-1188. doi:10.1002/eqe.2265

Run: python inventories/build_lab_hazard_curve.py
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

K2 = 0.4
ANCHORS = ((0.40, 1.0 / 475.0), (0.62, 1.0 / 2475.0))  # (PGA [g], annual rate [1/yr])
LEVELS_G = np.geomspace(0.005, 3.0, 20)
SITE = (-121.89, 37.34, 0.0)  # lon, lat, depth: an illustrative Bay Area site


def curve_constants(anchors=ANCHORS, k2=K2) -> tuple[float, float]:
    """(ln k0, k1) of λ = k0 exp(−k1 ln a − k2 ln²a) through the two anchors."""
    (a1, r1), (a2, r2) = anchors
    x1, x2 = math.log(a1), math.log(a2)
    # ln r = ln k0 − k1 x − k2 x²: two equations in ln k0, k1
    k1 = -((math.log(r2) + k2 * x2 * x2) - (math.log(r1) + k2 * x1 * x1)) / (x2 - x1)
    ln_k0 = math.log(r1) + k1 * x1 + k2 * x1 * x1
    return ln_k0, k1


def annual_rate(level_g, ln_k0, k1, k2=K2):
    x = np.log(level_g)
    return np.exp(ln_k0 - k1 * x - k2 * x * x)


def write_nshmp(path, rates, site_name="Lab (illustrative)"):
    """The curve in nshmp-haz's layout: the levels as the OpenQuake file writes them (7 decimals), annual rates."""
    header = ["name", "lon", "lat"] + [repr(float(f"{level:.7f}")) for level in LEVELS_G]
    row = [site_name, f"{SITE[0]:.5f}", f"{SITE[1]:.5f}"] + [f"{rate:.8e}" for rate in rates]
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(",".join(header) + "\n" + ",".join(row) + "\n", encoding="utf-8")


def main(path=Path(__file__).with_name("lab-hazard-curve.csv"),
         usgs_path=Path(__file__).with_name("lab-hazard-usgs") / "PGA" / "curves.csv"):
    ln_k0, k1 = curve_constants()
    write_nshmp(usgs_path, annual_rate(LEVELS_G, ln_k0, k1))
    poes = -np.expm1(-annual_rate(LEVELS_G, ln_k0, k1))
    header = ["lon", "lat", "depth"] + [f"poe-{level:.7f}" for level in LEVELS_G]
    comment = ("#" + "," * (len(header) - 1) + "\"generated_by='assess inventories/build_lab_hazard_curve.py "
               "(illustrative second-order curve, not an OpenQuake run)', kind='mean', "
               "investigation_time=1.0, imt='PGA'\"")
    row = [f"{SITE[0]:.5f}", f"{SITE[1]:.5f}", f"{SITE[2]:.5f}"] + [f"{p:.6E}" for p in poes]
    path.write_text("\n".join([comment, ",".join(header), ",".join(row)]) + "\n", encoding="utf-8")
    print(f"wrote {path} and {usgs_path}: k0 = {math.exp(ln_k0):.4g}, k1 = {k1:.4f}, k2 = {K2}")


if __name__ == "__main__":
    main()
