"""The yielding stick's elastic limit against the elastic modal route, printed as a table.

Run: python benchmarks/yielding_elastic_limit.py   (needs pyslammer for its record)

Strengths 100 W (nothing yields), Northridge PAC-175 at PGA 0.4 g, 3/6/12 storeys. Columns: the RMS
error (worst floor) against the modal route fed each mode's Rayleigh damping ratio (the same building:
what is left is Newmark's step), against today's route (building_modes as called today, 5 % in every
mode), and the roof's peak acceleration over today's. ``base hinge`` (a shear wall's default): the elastic
model on its base hinge (assess/building/wall_hinge.py), its elastic part damped, not the hinge.
"""
import os

import numpy as np
import pyslammer

from assess.building.modes import building_modes
from assess.building.nonlinear import elastic_periods, rayleigh_modal_damping, yielding_response, yielding_stick
from assess.building.response import floor_accelerations
from assess.building.wall_hinge import hinged_wall_response
from assess.hazard.records import read_record


def rms_error(ours, theirs):
    return np.sqrt(np.mean((ours - theirs) ** 2, axis=1)[1:] / np.mean(theirs ** 2, axis=1)[1:]).max()


def main():
    folder = os.path.join(os.path.dirname(pyslammer.__file__), "sample_ground_motions")
    record = read_record(os.path.join(folder, "Northridge_1994_PAC-175.csv"))
    ground, dt = np.asarray(record.accel_g) * 0.4 / np.abs(record.accel_g).max(), record.dt_s
    print("| storeys | stick | α | damping | vs modal route, same damping | vs today's route | roof PFA / today's |")
    cases = [("equivalent shear", np.inf, "rayleigh"), ("elastic column", 12.0, "rayleigh"),
             ("elastic column", 1.0, "rayleigh"), ("equivalent shear", 1.0, "rayleigh"),
             ("elastic column", 12.0, "modal"), ("elastic column", 1.0, "modal"), ("base hinge", 1.0, "rayleigh"),
             ("base hinge", 0.0, "rayleigh")]
    for storeys, period in [(3, 0.35), (6, 0.70), (12, 1.40)]:
        for flexure, alpha, damping in cases:
            stick = yielding_stick(storeys, 3.5, np.full(storeys, 100.0), system="other", period_s=period,
                                   alpha=alpha, flexure=flexure, damping_model=damping)
            ours = (hinged_wall_response if flexure == "base hinge" else yielding_response)(stick, ground,
                                                                                        dt).floor_accel_g
            today = floor_accelerations(building_modes(storeys, 3.5, period_s=period, alpha=alpha), ground, dt)
            same = "n/a (other model)"
            if flexure == "elastic column" or np.isinf(alpha):
                zeta = (rayleigh_modal_damping(elastic_periods(stick), *stick.rayleigh) if damping == "rayleigh"
                        else 0.05)
                modes = building_modes(storeys, 3.5, period_s=period, alpha=alpha, damping=zeta)
                same = f"{rms_error(ours, floor_accelerations(modes, ground, dt)):.4f}"
            ratio = np.abs(ours[-1]).max() / np.abs(today[-1]).max()
            print(f"| {storeys} | {flexure} | {alpha:g} | {damping} | {same} | {rms_error(ours, today):.3f} | "
                  f"{ratio:.3f} |")


if __name__ == "__main__":
    main()
