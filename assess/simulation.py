"""One item under one motion (``assess simulate``): the engine's answer beside the regression's.

Runs the item through the engine's gateway (a ``response`` run,
:func:`assess.mechanics.gateway.run_responses`) and, where the motion is a
pulse of known period, the paper's regression (eqs. 7, 8 and 21) for the same
item, and returns both in one :class:`ItemSimulation`.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

import numpy as np

from assess.data import default_settings
from assess.fragility import RegressionConstants, intensity_measure, sliding_quantile
from assess.hazard.records import Record
from assess.mechanics.block import Block, BlockResponse
from assess.mechanics.gateway import DEFAULT_TAIL_S, run_responses

M_TO_CM = 100.0


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
            "sliding_max_cm": r.sliding_max_m * M_TO_CM,
            "sliding_residual_cm": r.sliding_residual_m * M_TO_CM,
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
                                 "sliding_median_cm": self.regression_sliding_median_m * M_TO_CM}
        return out


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
        constants = constants or RegressionConstants.from_settings(default_settings())
        im = float(intensity_measure(motion.pta_g, block.mu))
        median_m = float(sliding_quantile(im, motion.pta_g, pulse_period_s, constants)) if im > 0 else 0.0
    return ItemSimulation(block=block, motion=motion, response=response, pulse_period_s=pulse_period_s,
                          im=im, regression_sliding_median_m=median_m)
