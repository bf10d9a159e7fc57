"""Predominant pulse (Tp, vp) of pyslammer's 18 sample records: the table of docs/records.md.

Run: python benchmarks/identify_pulses.py [--markdown]

For every record, :func:`assess.hazard.pulse_identification.identify_pulse`
with all four pulse models; prints the selected pulse (type, Tp, signed vp,
arrival, fit_r2, residual PGV ratio, pulse-like or not), the Type-B fit alone
(the pulse Table 3 of Konstantinidis & Makris 2010 lists), the record's PGA and
PGV, and the seconds the identification took. ``--markdown`` prints the rows
as the Markdown table of docs/records.md.

pyslammer (GPL) is only called for its records; it is a test dependency. Not a test.
"""
from __future__ import annotations

import argparse
import time

import numpy as np
import pyslammer

from assess.hazard.pulse_identification import identify_pulse


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--markdown", action="store_true", help="print the Markdown table of docs/records.md")
    args = parser.parse_args()
    records = pyslammer.sample_ground_motions()
    if args.markdown:
        print("| record | dt [s] | PGA [g] | PGV [cm/s] | type | Tp [s] | vp [cm/s] | arrival [s] "
              "| fit r² | resid. PGV ratio | pulse-like | Type-B Tp [s] | Type-B vp [cm/s] | Type-B r² |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name, motion in records.items():
        start = time.perf_counter()
        fit = identify_pulse(np.asarray(motion.accel, dtype=float), float(motion.dt))
        seconds = time.perf_counter() - start
        b = fit.fit_for("B")
        kind = fit.pulse_type + (f" (γ {fit.gamma:.1f})" if fit.pulse_type == "MP" else "")
        if args.markdown:
            print(f"| {name} | {float(motion.dt):g} | {fit.pga_g:.2f} | {100 * fit.pgv_m_s:.0f} | {kind} "
                  f"| {fit.tp_s:.2f} | {100 * fit.vp_m_s:+.0f} | {fit.arrival_time_s:.1f} | {fit.fit_r2:.2f} "
                  f"| {fit.residual_pgv_ratio:.2f} | {'yes' if fit.is_pulse_like else 'no'} "
                  f"| {b.tp_s:.2f} | {100 * b.vp_m_s:+.0f} | {b.fit_r2:.2f} |")
        else:
            print(f"{name:30s} {kind:11s} Tp {fit.tp_s:6.2f} s  vp {100 * fit.vp_m_s:+6.0f} cm/s  "
                  f"r2 {fit.fit_r2:.2f}  resid.PGV {fit.residual_pgv_ratio:.2f}  "
                  f"{'pulse-like' if fit.is_pulse_like else 'no clear pulse':14s} | B: Tp {b.tp_s:5.2f} "
                  f"vp {100 * b.vp_m_s:+5.0f} r2 {b.fit_r2:.2f} | PGA {fit.pga_g:.2f} g "
                  f"PGV {100 * fit.pgv_m_s:4.0f} cm/s | {seconds:.1f} s")


if __name__ == "__main__":
    main()
