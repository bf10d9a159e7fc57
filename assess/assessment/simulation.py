"""One item under one motion (``assess simulate``): the engine's answer beside the regression's.

Runs the item through the engine's gateway (a ``response`` run,
:func:`assess.mechanics.gateway.run_responses`) and, where the motion is a
pulse of known period, the paper's regression (eqs. 7, 8 and 21) for the same
item, and returns both in one :class:`ItemSimulation`.
"""
from __future__ import annotations

import io
from dataclasses import dataclass
from pathlib import Path
from typing import Optional

import numpy as np

from assess.inventory.settings import Settings
from assess.fragility import RegressionConstants, intensity_measure, sliding_quantile
from assess.hazard.records import MIN_DURATION_S, Record, pulse_record, read_record
from assess.inventory.units import CM_PER_M
from assess.mechanics.block import Block, BlockResponse
from assess.mechanics.gateway import DEFAULT_TAIL_S, run_responses



@dataclass(frozen=True)
class ItemSimulation:
    """What ``assess simulate`` reports (docs/commands.md, "What assess simulate prints").

    Attributes
    ----------
    block : Block
    motion : Record
        The floor motion as simulated (record after scaling, or sampled pulse).
    response : BlockResponse
    pulse_period_s : float or None
        Tp of the motion when it is a pulse; then ``im`` and
        ``regression_sliding_median_m`` are the regression's prediction.
    im : float or None
        PTA/(μg) − 1 [-] (eq. 7), with PTA of the motion.
    regression_sliding_median_m : float or None
        Median Umax of eq. 21 [m]; 0 when IM ≤ 0.
    """

    block: Block
    motion: Record
    response: BlockResponse
    pulse_period_s: Optional[float] = None
    im: Optional[float] = None
    regression_sliding_median_m: Optional[float] = None

    def as_dict(self) -> dict:
        """The JSON object of ``assess simulate --json`` (docs/commands.md; lengths in cm), plus what the run was."""
        r = self.response
        out = {
            "alpha_rad": self.block.alpha_rad,
            "p_rad_s": self.block.p_rad_s,
            "b_over_h": self.block.b_over_h,
            "mu": self.block.mu,
            "mu_static": self.block.mu_static,
            "restitution": self.block.restitution_effective,
            "mode": r.mode,
            "sliding_max_cm": r.sliding_max_m * CM_PER_M,
            "sliding_residual_cm": r.sliding_residual_m * CM_PER_M,
            "theta_max_over_alpha": r.theta_max_over_alpha,
            "uplift": bool(r.uplift),
            "overturned": bool(r.overturned),
            "overturn_time_s": None if np.isnan(r.overturn_time_s) else r.overturn_time_s,
            "mode_sequence": [[round(float(t), 6), mode] for t, mode in r.mode_sequence],
            "solver": r.solver,
            "motion": {"name": self.motion.name, "pta_g": self.motion.pta_g, "dt_s": self.motion.dt_s,
                       "duration_s": self.motion.duration_s},
        }
        if self.pulse_period_s is not None:
            out["regression"] = {"tp_s": self.pulse_period_s, "im": self.im,
                                 "sliding_median_cm": self.regression_sliding_median_m * CM_PER_M}
        return out

    def as_text(self) -> str:
        """What ``assess simulate`` prints without ``--json``: :meth:`as_dict` in five or six lines."""
        result = self.as_dict()
        lines = [
            f"item: alpha {result['alpha_rad']:.4f} rad, p {result['p_rad_s']:.3f} rad/s, b/h "
            f"{result['b_over_h']:.3f}, mu {result['mu']:g} (static {result['mu_static']:g}), "
            f"restitution {result['restitution']:.4f}",
            f"motion: {result['motion']['name']}, PTA {result['motion']['pta_g']:.3f} g, "
            f"{result['motion']['duration_s']:.2f} s at dt {result['motion']['dt_s']:g} s",
            f"mode: {result['mode']} ({' -> '.join(m for _, m in result['mode_sequence'])}; "
            f"solved by the {result['solver']})",
            f"sliding: peak {result['sliding_max_cm']:.2f} cm, residual {result['sliding_residual_cm']:.2f} cm",
            f"rocking: theta_max/alpha {result['theta_max_over_alpha']:.3f}, uplift "
            f"{'yes' if result['uplift'] else 'no'}, overturned {'yes' if result['overturned'] else 'no'}"
            + (f" at {result['overturn_time_s']:.2f} s" if result["overturned"] else ""),
        ]
        if "regression" in result:
            reg = result["regression"]
            lines.append(f"regression (eq. 21): IM {reg['im']:.3f}, median sliding "
                         f"{reg['sliding_median_cm']:.2f} cm")
        return "\n".join(lines)

    def history_csv(self) -> bytes:
        """``--history``: time_s, floor_accel_g, sliding_cm, theta_over_alpha (needs ``return_history``)."""
        r = self.response
        floor = np.zeros(r.time_s.size)
        floor[:min(self.motion.accel_g.size, floor.size)] = self.motion.accel_g[:floor.size]
        table = np.column_stack([r.time_s, floor, r.sliding_m * CM_PER_M, r.theta_rad / self.block.alpha_rad])
        buffer = io.StringIO()
        np.savetxt(buffer, table, delimiter=",", fmt="%.9g",
                   header="time_s,floor_accel_g,sliding_cm,theta_over_alpha", comments="")
        return buffer.getvalue().encode()


def item_motion(record_path: Optional[Path], scale: float, pulse: Optional[str], ap_g: Optional[float],
                tp_s: Optional[float], dt_s: Optional[float]) -> tuple[Record, Optional[float]]:
    """The motion of ``assess simulate`` and its pulse period: the record at ``record_path`` times ``scale``
    (period None), else the ``pulse`` of amplitude ``ap_g`` and period ``tp_s`` sampled at ``dt_s``."""
    if record_path is not None:
        return read_record(record_path, min_duration_s=MIN_DURATION_S, scale=scale), None
    return pulse_record(pulse, ap_g, tp_s, dt_s), tp_s


def simulate_item(block: Block, motion: Record, *, pulse_period_s: Optional[float] = None,
                  tail_s: float = DEFAULT_TAIL_S, solver: str = "auto", return_history: bool = False,
                  constants: Optional[RegressionConstants] = None, runner=None) -> ItemSimulation:
    """Simulate ``block`` under ``motion``; with a pulse period, add the regression's median.

    ``runner`` runs the engine's case (:mod:`assess.mechanics.gateway`; default this machine).

    Examples
    --------
    >>> from assess.hazard.records import pulse_record
    >>> forma = Block(half_width_m=0.311, cg_height_m=1.143, height_m=2.286, mu=0.13)
    >>> run = simulate_item(forma, pulse_record("B", 0.54, 2.1), pulse_period_s=2.1)
    >>> run.response.mode, round(run.im, 2)
    ('slide', 3.15)
    """
    response, = run_responses([(block, motion.accel_g, motion.dt_s)], runner, tail_s=tail_s, solver=solver,
                              history=return_history)
    im = median_m = None
    if pulse_period_s is not None:
        constants = constants or RegressionConstants.from_settings(Settings())
        im = float(intensity_measure(motion.pta_g, block.mu))
        median_m = float(sliding_quantile(im, motion.pta_g, pulse_period_s, constants)) if im > 0 else 0.0
    return ItemSimulation(block=block, motion=motion, response=response, pulse_period_s=pulse_period_s,
                          im=im, regression_sliding_median_m=median_m)
