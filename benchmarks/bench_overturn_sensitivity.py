"""Whether a rocking item overturns turns on a fraction of a per cent of its floor motion: the tool's three
solvers and MuJoCo's rigid box under the OpenSees buildings' floor histories, each times a few amplitudes.

Run: python benchmarks/bench_overturn_sensitivity.py [--cases smf4:DE,smf8:DE,rcf5:DE,smf4:MCE_R]
     [--amplitudes 0.99,0.995,0.9975,1,1.0025,1.005,1.01] [--mujoco 10]
     (needs openseespy and pyslammer, and mujoco for --mujoco; about 4 minutes)

The item is the loaded shelving of the yielding-building checks (tests/peers/yielding_equipment.py: 2.18 m
high, 0.61 m deep, μ 0.35) about its narrow side, the only item that overturns in those checks. For every
(building, level, motion) of the 11 records and the mid-height and roof floors, the OpenSees floor history
(tests/peers/opensees_buildings.py) times each amplitude runs through the tool's engine three ways
(``solver`` ``auto``, the engine's own choice; ``general``, the Moreau-Jean solver; ``event-driven``), and,
for the first ``--mujoco`` rows whose verdict the tool changes over the amplitudes (then the steady ones),
through MuJoCo's box (tests/peers/mujoco_box.py). Printed: each row where any run overturns, as a string of
verdicts over the amplitudes (X overturns), then the counts: rows whose verdict changes within the
amplitudes, rows out of order (neither rising nor falling with the amplitude), runs where the three solvers
differ, and the same for MuJoCo. Measured (``--mujoco 10``, 262 s): 47 rows, 19 change (13 out of order), 4 of
329 runs differ between the solvers; MuJoCo on the first 10 rows that change in the tool: 8 change, 5 out of
order (on one, both read ".XX..X."). Nothing is fitted here.
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(REPO / "tests")]

from assess.mechanics.block import Block  # noqa: E402
from assess.mechanics.gateway import run_responses  # noqa: E402
from peers.opensees_buildings import BUILDINGS, truth_response  # noqa: E402
from peers.yielding_equipment import LEVELS, ground_suite, narrow_box  # noqa: E402

SOLVERS = ("auto", "general", "event-driven")


def verdicts(flags) -> str:
    return "".join("X" if f else "." for f in flags)


def changes(text: str) -> bool:
    return "X" in text and "." in text


def out_of_order(text: str) -> bool:
    return text not in ("".join(sorted(text)), "".join(sorted(text, reverse=True)))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", default="smf4:DE,smf8:DE,rcf5:DE,smf4:MCE_R")
    parser.add_argument("--amplitudes", default="0.99,0.995,0.9975,1,1.0025,1.005,1.01")
    parser.add_argument("--mujoco", type=int, default=0, help="rows to run through MuJoCo's box as well")
    args = parser.parse_args(argv)
    amplitudes = [float(a) for a in args.amplitudes.split(",")]
    item = narrow_box("SHELVING")
    block = Block(half_width_m=item["half_width_m"], cg_height_m=item["height_m"] / 2, height_m=item["height_m"],
                  mu=item["mu"])
    start = time.perf_counter()
    rows = []
    for case in args.cases.split(","):
        name, level = case.split(":")
        truth = BUILDINGS[name]
        for motion, accel, dt in ground_suite(11, truth.period_s, LEVELS[level]):
            floors = truth_response(truth, accel, dt)[0]
            for floor in (truth.storeys // 2, truth.storeys):
                runs = {solver: verdicts(r.overturned for r in run_responses(
                    [(block, floors[floor] * a, dt) for a in amplitudes], solver=solver)) for solver in SOLVERS}
                if any("X" in v for v in runs.values()):
                    rows.append((name, level, motion, floor, floors[floor], dt, runs))
                    print(f"{name} {level} {motion} floor {floor}: " + " ".join(f"{s} {v}" for s, v in runs.items()),
                          flush=True)
    differ = sum(len({runs[s][k] for s in SOLVERS}) > 1 for *_, runs in rows for k in range(len(amplitudes)))
    tool = [runs["auto"] for *_, runs in rows]
    print(f"\n{len(rows)} rows where any run overturns; the verdict changes within the amplitudes on "
          f"{sum(map(changes, tool))}, out of order on {sum(map(out_of_order, tool))}; "
          f"the three solvers differ on {differ} of {len(rows) * len(amplitudes)} runs")
    if args.mujoco:
        import mujoco
        from peers.mujoco_box import box_model, overturns

        model = box_model(mujoco, **item)
        chosen = sorted(rows, key=lambda r: not changes(r[-1]["auto"]))[:args.mujoco]
        texts = []
        for name, level, motion, floor, history, dt, runs in chosen:
            texts.append(verdicts(overturns(mujoco, model, history * a, dt, item["height_m"]) for a in amplitudes))
            print(f"{name} {level} {motion} floor {floor}: tool {runs['auto']} mujoco {texts[-1]}", flush=True)
        print(f"\nMuJoCo on {len(chosen)} rows ({sum(changes(r[-1]['auto']) for r in chosen)} where the tool's verdict "
              f"changes): changes on {sum(map(changes, texts))}, out of order on {sum(map(out_of_order, texts))}")
    print(f"total {time.perf_counter() - start:.0f} s")


if __name__ == "__main__":
    main()
