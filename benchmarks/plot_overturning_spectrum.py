"""Overturning spectrum of a rigid block under a one-sine (Type-A) pulse, as Fig. 6 of
Konstantinidis & Makris (2010): α = 0.16 rad, p = 1.25 rad/s, Housner restitution.

Run: python benchmarks/plot_overturning_spectrum.py
Writes docs/figures/overturning_spectrum.png and .svg. Each pulse is followed by
15/p s of free rocking, so overturning after the pulse ends is caught. Not a test.
"""
from __future__ import annotations

import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from assess.hazard.pulses import pulse_acceleration  # noqa: E402
from assess.mechanics.rocking import rocking_peaks_batch  # noqa: E402

ALPHA, P = 0.16, 1.25
OMEGA_RATIOS = np.arange(0.5, 14.01, 0.25)  # ωp/p
AMPLITUDES = np.arange(0.5, 40.01, 0.1)      # ap/(αg)
OUT = Path(__file__).resolve().parents[1] / "docs" / "figures"


def overturned_column(omega_ratio):
    tp_s = 2 * np.pi / (omega_ratio * P)
    dt_s = min(tp_s / 200.0, 0.01)
    time_s = np.arange(0.0, tp_s + 15.0 / P, dt_s)
    shape = pulse_acceleration("A", 1.0, tp_s, time_s)
    records = [a * ALPHA * shape for a in AMPLITUDES]
    return rocking_peaks_batch(records, dt_s, ALPHA, P).overturned[0]


def main() -> None:
    start = time.perf_counter()
    unsafe = np.array([overturned_column(w) for w in OMEGA_RATIOS]).T  # (amplitude, frequency)
    minimum = np.array([AMPLITUDES[np.argmax(c)] if c.any() else np.nan for c in unsafe.T])
    print(f"{unsafe.size} pulses in {time.perf_counter() - start:.1f} s")
    for w, m in zip(OMEGA_RATIOS, minimum):
        if float(w).is_integer():
            print(f"  omega_p/p = {w:4.1f}: minimum overturning ap/(alpha g) = {m:.1f}")

    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    ax.contourf(OMEGA_RATIOS, AMPLITUDES, unsafe.astype(float), levels=[0.5, 1.5], colors=["0.75"])
    ax.plot(OMEGA_RATIOS, minimum, "k-", lw=1.5, label="minimum overturning acceleration")
    ax.axhline(np.tan(ALPHA) / ALPHA, color="k", ls=":", lw=1, label=r"uplift, $a_p = g\tan\alpha$")
    ax.text(3.0, 30.0, "unsafe\n(overturns)", ha="center")
    ax.text(10.0, 6.0, "safe", ha="center")
    ax.set_xlabel(r"$\omega_p/p$")
    ax.set_ylabel(r"$a_p/(\alpha g)$")
    ax.set_xlim(0, 14)
    ax.set_ylim(0, 40)
    ax.set_title(r"Overturning spectrum, Type-A pulse ($\alpha$ = 0.16 rad, $p$ = 1.25 rad/s)", fontsize=10)
    ax.legend(loc="upper left", fontsize=8)
    OUT.mkdir(parents=True, exist_ok=True)
    for suffix in ("png", "svg"):
        fig.savefig(OUT / f"overturning_spectrum.{suffix}", dpi=150, bbox_inches="tight")
    print(f"wrote {OUT / 'overturning_spectrum.png'} and .svg")


if __name__ == "__main__":
    main()
