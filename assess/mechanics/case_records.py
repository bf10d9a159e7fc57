"""Records as the parallel case kernels take them (rocking and time-stepping), written once."""
from __future__ import annotations

import numpy as np

#: Cases a thread takes at a time in the parallel kernels (small: run times differ by orders of magnitude).
CASES_PER_CHUNK = 4


def checked_records(records_g, dt_s, check_record):
    """Checked records (contiguous float arrays) and their sample intervals.

    ``records_g`` is one record or a sequence of them; ``dt_s`` one interval or one per record;
    ``check_record(accel, dt)`` is the solver's own check, returning ``(accel, dt)``.

    >>> records, dts = checked_records([0.1, 0.2], 0.01, lambda a, d: (np.asarray(a, float), float(d)))
    >>> len(records), dts.tolist()
    (1, [0.01])
    """
    first = np.asarray(records_g[0]) if len(records_g) else np.asarray([])
    records = [records_g] if first.ndim == 0 else list(records_g)
    dts = np.broadcast_to(np.asarray(dt_s, dtype=float), (len(records),))
    checked = [check_record(r, d) for r, d in zip(records, dts)]
    return [c[0] for c in checked], np.array([c[1] for c in checked])
