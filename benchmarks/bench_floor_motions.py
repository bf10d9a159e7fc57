"""Equipment demand under floor motions from the modal route, against demand under OpenSees' floor histories.

Run: python benchmarks/bench_floor_motions.py [--pga 0.4] [--cache DIR]   (needs openseespy and pyslammer)

Buildings: linear shear buildings in OpenSeesPy (tests/peers/opensees_shear.py), 3 storeys
T_1 0.35 s, 6 storeys 0.70 s, 12 storeys 1.40 s, storeys 3.5 m, equal floor masses, 5 %
damping in every mode (OpenSees' ``modalDamping``), stepped at ≤ 1 ms. Two stiffness
distributions: **uniform** (what a shear building assumes), **falling linearly to a
quarter at the roof** (what it does not: a code-designed frame's storey stiffness follows
its storey shear), and a **wall-frame** building (an Euler-Bernoulli column beside the
uniform storey springs, α = 2), each scaled to the same T_1.

Ground: pyslammer's 18 records, each scaled to PGA ``--pga``.

Items (one base direction, the more slender one; dimensions from inventories/lab.xlsx):
the FORMA, KELVINATOR and ASP prototypes of Konstantinidis & Makris (2010) at their
best-fit μ (Table 3, p. 1467: 0.13, 0.17, 0.20), a 42U server rack, tall wire shelving
loaded high, a chest freezer; on the ground floor, at mid-height (floor n//2) and on the roof.

Routes, each through ``assess.mechanics.engine.simulate_cases`` as the truth is:

* ``shear building``: the user gives storeys, storey height, T_1 and damping; the modal
  route with the uniform shear building (α = ∞), every mode;
* ``steel moment frame``: the same with the shape ``system = steel moment frame`` implies
  (α = 12, shear-flexural), with uniform storeys;
* ``steel moment frame, design profile``: the same with the storey stiffness a building sheet of that
  system now takes by default (in proportion to the ASCE 7-22 design storey shear,
  ``assess.building.design.design_storey_stiffness``);
* ``shear wall``: the shape ``system = shear wall`` implies (α = 1);
* ``ground x (1 + 2z/h)``: the ground record scaled by ASCE 7-16's floor factor (the
  former ``--derive-floors``), for context.

Printed per table (one per OpenSees building): over item × floor × record cases,
the geometric mean and σ ln of the route's peak sliding over the truth's (cases where the
truth slides at least 1 cm and neither overturns), the share within a factor 2, the
overturn verdicts that agree (and the counts), and a risk proxy per item-floor over the
suite: high where P(sliding past the clearance or overturning) ≥ 0.5, moderate ≥ 0.1, else
low (the default thresholds of assess's settings). Then the floor histories' RMS error
against OpenSees, and mean PFA/PGA per floor against ASCE 7-22's H_f for T_1.
Not a test: numbers for the issue.
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))

from assess.anchorage.equations import height_factor  # noqa: E402
from assess.building import building_modes, floor_accelerations  # noqa: E402
from assess.building.design import design_storey_stiffness  # noqa: E402
from assess.hazard.records import read_record  # noqa: E402
from assess.mechanics.block import Block  # noqa: E402
from assess.mechanics.engine import simulate_cases  # noqa: E402
from peers.opensees_shear import (load_opensees, shear_building_floor_accelerations,  # noqa: E402
                                  shear_building_periods, shear_flexural_periods)

BUILDINGS = [(3, 0.35), (6, 0.70), (12, 1.40)]
STOREY_HEIGHT_M = 3.5
DAMPING = 0.05
FLOOR_MASS_KG = 2.0e5
#: name, height [m], half base width [m], centre-of-mass height [m], μ, μ_s, clearance [m]
ITEMS = [
    ("FORMA", 2.286, 0.311, 1.143, 0.13, 0.13, 0.25),
    ("KELVINATOR", 2.134, 0.330, 1.067, 0.17, 0.17, 0.30),
    ("ASP", 1.803, 0.292, 0.9015, 0.20, 0.20, 0.20),
    ("server rack", 2.00, 0.30, 0.85, 0.35, 0.35, 0.15),
    ("tall shelving", 1.88, 0.23, 1.10, 0.45, 0.45, 0.05),
    ("chest freezer", 0.90, 0.35, 0.45, 0.70, 0.75, 0.10),
]
PROFILES = {"uniform": lambda n: np.ones(n), "quarter at the roof": lambda n: np.linspace(1.0, 0.25, n),
            "wall-frame": lambda n: np.ones(n)}
#: Lateral stiffness ratio α of each OpenSees building (inf: storey springs only; 2: a column of
#: EI = k h H²/α² beside them, a wall-frame building near the walls' end of the range).
ALPHAS = {"uniform": np.inf, "quarter at the roof": np.inf, "wall-frame": 2.0}
SLIDING_FLOOR_M = 0.01


def ground_suite(pga_g):
    import pyslammer
    folder = Path(pyslammer.__file__).parent / "sample_ground_motions"
    suite = []
    for path in sorted(folder.glob("*.csv")):
        record = read_record(path)
        suite.append((path.stem, record.accel_g * (pga_g / record.pta_g), record.dt_s))
    return suite


def opensees_floors(storeys, period_s, profile, suite, cache):
    """Floor histories of OpenSees' building for every record: list over records of (n+1, samples)."""
    key = cache / f"opensees-{storeys}-{period_s}-{profile.replace(' ', '_')}.npz" if cache else None
    if key is not None and key.exists():
        data = np.load(key)
        return [data[f"r{i}"] for i in range(len(suite))]
    shape = PROFILES[profile](storeys)
    masses = np.full(storeys, FLOOR_MASS_KG)
    alpha = ALPHAS[profile]
    if np.isinf(alpha):
        periods = shear_building_periods(shape, masses)
        factor, bending = (periods[0] / period_s) ** 2, None
    else:
        bending = STOREY_HEIGHT_M * (storeys * STOREY_HEIGHT_M) ** 2 / alpha ** 2  # k = 1
        periods = shear_flexural_periods(storeys, STOREY_HEIGHT_M, 1.0, bending, FLOOR_MASS_KG)
        factor = (periods[0] / period_s) ** 2
        bending = bending * factor
    out = [shear_building_floor_accelerations(shape * factor, masses, ground, dt, damping=DAMPING,
                                              bending_rigidity_n_m2=bending, storey_height_m=STOREY_HEIGHT_M)[0]
           for _, ground, dt in suite]
    if key is not None:
        key.parent.mkdir(parents=True, exist_ok=True)
        np.savez(key, **{f"r{i}": a for i, a in enumerate(out)})
    return out


def route_floors(route, storeys, period_s, suite):
    if route == "ground x (1 + 2z/h)":
        factors = 1.0 + 2.0 * np.arange(storeys + 1) / storeys
        return [np.outer(factors, ground) for _, ground, _ in suite]
    alpha = np.inf if route == "shear building" else None
    system = "shear wall" if route == "shear wall" else "steel moment frame"
    stiffness = None
    if route == "steel moment frame, design profile":
        stiffness = design_storey_stiffness(system, np.ones(storeys), STOREY_HEIGHT_M * np.arange(1, storeys + 1),
                                            period_s)
    modes = building_modes(storeys, STOREY_HEIGHT_M, system=system, period_s=period_s, damping=DAMPING, alpha=alpha,
                           storey_stiffness=stiffness)
    return [floor_accelerations(modes, ground, dt) for _, ground, dt in suite]


def run_engine(floor_histories, suite):
    """Peak sliding [m] and overturned, shape (buildings, floors 3, items, records)."""
    blocks, records, dts, index = [], [], [], []
    for b, (storeys, _) in enumerate(BUILDINGS):
        for f, floor in enumerate((0, storeys // 2, storeys)):
            for r, (_, _, dt) in enumerate(suite):
                records.append(np.ascontiguousarray(floor_histories[b][r][floor]))
                dts.append(dt)
                for item in ITEMS:
                    _, height, half, cg, mu, mu_s, _ = item
                    blocks.append(Block(half_width_m=half, cg_height_m=cg, height_m=height, mu=mu, mu_static=mu_s))
                    index.append(len(records) - 1)
    peaks = simulate_cases(blocks, records, dts, np.array(index))
    shape = (len(BUILDINGS), 3, len(suite), len(ITEMS))
    sliding = peaks.sliding_max_m.reshape(shape).transpose(0, 1, 3, 2)
    overturned = peaks.overturned.reshape(shape).transpose(0, 1, 3, 2)
    return sliding, overturned


def risk_class(sliding, overturned):
    clearance = np.array([item[6] for item in ITEMS])[None, None, :, None]
    p = np.mean((sliding > clearance) | overturned, axis=-1)
    return np.where(p >= 0.5, 2, np.where(p >= 0.1, 1, 0))


def compare(truth, route, floors=slice(None)):
    """Route against truth over the floor positions ``floors`` (0 ground, 1 mid-height, 2 roof)."""
    (ts, to), (rs, ro) = [(s[:, floors], o[:, floors]) for s, o in (truth, route)]
    use = (ts >= SLIDING_FLOOR_M) & ~to & ~ro
    ratio = np.log(np.maximum(rs[use], 1e-4) / ts[use])
    return dict(cases=int(use.sum()), gm=float(np.exp(ratio.mean())), sigma=float(ratio.std(ddof=1)),
                within2=float(np.mean(np.abs(ratio) <= np.log(2))),
                overturn_agree=float(np.mean(to == ro)), overturn_true=int(to.sum()), overturn_route=int(ro.sum()),
                risk_agree=float(np.mean(risk_class(ts, to) == risk_class(rs, ro))))


def print_table(title, truth, routes):
    print(f"\n### {title}")
    print("| route | sliding gm | σ ln | within ×2 | overturn verdicts agree (true, predicted) | risk proxy agrees |")
    print("|---|---|---|---|---|---|")
    for floors, where in ((slice(None), "ground, mid, roof"), (slice(1, 3), "mid, roof"), (slice(1, 2), "mid"),
                          (slice(2, 3), "roof")):
        for name, result in routes.items():
            c = compare(truth, result, floors)
            print(f"| {name} ({where}; {c['cases']} sliding cases) | {c['gm']:.3f} | {c['sigma']:.3f} | "
                  f"{100 * c['within2']:.0f} % | "
                  f"{100 * c['overturn_agree']:.1f} % ({c['overturn_true']}, {c['overturn_route']}) | "
                  f"{100 * c['risk_agree']:.0f} % |")
    print(f"(sliding cases: item-floor-record cases where the truth slides ≥ 1 cm and neither overturns; "
          f"overturn verdicts over every item-floor-record case, {len(BUILDINGS) * 3 * len(ITEMS) * 18} with "
          f"all three floors; risk proxy per item-floor, {len(BUILDINGS) * 3 * len(ITEMS)} with all three floors)")
    # the items at the roof, per building
    ts, to = truth
    for b, (storeys, period) in enumerate(BUILDINGS):
        parts = []
        for name, (rs, ro) in [("OpenSees", truth)] + list(routes.items())[:1]:
            parts.append(f"{name}: FORMA roof median {100 * np.median(rs[b, 2, 0]):.1f} cm, "
                         f"shelving roof overturns {int(ro[b, 2, 4].sum())}/{ro.shape[-1]}")
        print(f"  {storeys} storeys: " + "; ".join(parts))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pga", type=float, default=0.4)
    parser.add_argument("--cache", type=Path, default=None, help="folder keeping OpenSees' histories between runs")
    args = parser.parse_args()
    ops, why = load_opensees()
    if ops is None:
        sys.exit(f"needs openseespy: {why}")
    suite = ground_suite(args.pga)
    print(f"{len(suite)} pyslammer records at PGA {args.pga} g; buildings {BUILDINGS} (storeys, T1 s), "
          f"{STOREY_HEIGHT_M} m storeys, {DAMPING:.0%} modal damping")
    start = time.perf_counter()
    truth_floors = {p: [opensees_floors(n, t, p, suite, args.cache) for n, t in BUILDINGS] for p in PROFILES}
    print(f"OpenSees floor histories: {time.perf_counter() - start:.0f} s")
    start = time.perf_counter()
    routes = ("shear building", "steel moment frame", "steel moment frame, design profile", "shear wall",
              "ground x (1 + 2z/h)")
    route_floors_ = {r: [route_floors(r, n, t, suite) for n, t in BUILDINGS] for r in routes}
    print(f"modal floor histories, {len(routes)} routes x 3 buildings x {len(suite)} records: "
          f"{time.perf_counter() - start:.2f} s")
    # floor histories: the modal solver with OpenSees' own stiffness against OpenSees, every floor and record
    for profile in PROFILES:
        for b, (storeys, period) in enumerate(BUILDINGS):
            modes = building_modes(storeys, STOREY_HEIGHT_M, period_s=period, damping=DAMPING, alpha=ALPHAS[profile],
                                   storey_stiffness=PROFILES[profile](storeys))
            errors = []
            for truth, (_, ground, dt) in zip(truth_floors[profile][b], suite):
                ours = floor_accelerations(modes, ground, dt)
                errors.append(np.sqrt(np.mean((ours[1:] - truth[1:]) ** 2, axis=1) / np.mean(truth[1:] ** 2, axis=1)))
            errors = np.array(errors)
            print(f"  {profile}, {storeys} storeys: floor-history RMS error of the modal solver against OpenSees, "
                  f"{errors.size} floor-records: median {100 * np.median(errors):.3f} %, max {100 * errors.max():.3f} %")
    start = time.perf_counter()
    demand = {f"OpenSees {p}": run_engine(truth_floors[p], suite) for p in PROFILES}
    demand.update({r: run_engine(route_floors_[r], suite) for r in routes})
    print(f"engine: {len(demand)} x {len(BUILDINGS) * 3 * len(ITEMS) * len(suite)} cases: "
          f"{time.perf_counter() - start:.0f} s")
    print_table("OpenSees building with uniform storey stiffness (what a shear building assumes)",
                demand["OpenSees uniform"], {r: demand[r] for r in routes})
    print_table("OpenSees building with storey stiffness falling to 1/4 at the roof (what `system` does not assume)",
                demand["OpenSees quarter at the roof"], {r: demand[r] for r in routes})
    print_table("OpenSees wall-frame building, a column beside the storey springs, α = 2 (what a frame does not assume)",
                demand["OpenSees wall-frame"], {r: demand[r] for r in routes})
    # PFA/PGA per floor against H_f
    print("\n### Mean PFA/PGA over the suite per floor (z/h), against ASCE 7-22 H_f for T_1")
    for b, (storeys, period) in enumerate(BUILDINGS):
        pga = np.array([np.abs(h[0]).max() for h in truth_floors["uniform"][b]])
        print(f"{storeys} storeys, T1 {period} s:")
        print("| floor | z/h | OpenSees uniform | OpenSees 1/4 at roof | OpenSees wall-frame | shear building | "
              "steel moment frame | steel moment frame, design profile | shear wall | H_f |")
        print("|---|---|---|---|---|---|---|---|---|---|")
        for k in range(storeys + 1):
            means = [np.mean([np.abs(h[k]).max() for h in source[b]] / pga) for source in
                     (truth_floors["uniform"], truth_floors["quarter at the roof"], truth_floors["wall-frame"],
                      route_floors_["shear building"], route_floors_["steel moment frame"],
                      route_floors_["steel moment frame, design profile"],
                      route_floors_["shear wall"])]
            print(f"| {k} | {k / storeys:.2f} | " + " | ".join(f"{m:.2f}" for m in means)
                  + f" | {float(height_factor(k / storeys, period)):.2f} |")


if __name__ == "__main__":
    main()
