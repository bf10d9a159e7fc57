"""Where the engine's cases run: the seam between the assessment and the machine(s).

The assessment hands every batch of (block, motion) cases to a *runner*'s
``simulate_cases`` (same arguments and result as
:func:`assess.mechanics.engine.simulate_cases`). :class:`LocalRunner` runs
them on this machine's threads; other runners (a Dask cluster, a cache of
earlier results) keep the same signature, so the numbers never depend on
where, or whether again, a case ran.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Optional, Sequence

import numpy as np

from .block import Block
from .engine import DEFAULT_TAIL_S, CasePeaks, simulate_cases


@dataclass
class LocalRunner:
    """Run cases on this machine's threads (the compiled batch kernels).

    ``cases_simulated`` counts the cases this runner simulated, for the
    progress lines and the portfolio's account of what re-ran.
    """

    cases_simulated: int = field(default=0)

    def simulate_cases(self, blocks: Sequence[Block], records_g: Sequence[np.ndarray], dt_s: Sequence[float],
                       record_index, *, tail_s: float = DEFAULT_TAIL_S,
                       progress: Optional[Callable[[int, int], None]] = None) -> CasePeaks:
        peaks = simulate_cases(blocks, records_g, dt_s, record_index, tail_s=tail_s, progress=progress)
        self.cases_simulated += len(blocks)
        return peaks
