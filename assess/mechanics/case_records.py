"""Floor acceleration records as the kernels take them, checked once for every solver."""
from __future__ import annotations

import numpy as np


def checked_record(floor_accel_g, dt_s, *, min_samples: int = 0):
    """A floor acceleration record [g] as a contiguous float array, and its sample interval [s] as a float.

    Raises ValueError unless the record is one-dimensional with at least
    ``min_samples`` samples, all finite, and ``dt_s`` is finite and positive.

    >>> accel, dt = checked_record([0.1, 0.2], 0.01)
    >>> accel.flags.c_contiguous, accel.dtype.name, dt
    (True, 'float64', 0.01)
    """
    accel = np.ascontiguousarray(floor_accel_g, dtype=float)
    if accel.ndim != 1 or accel.size < min_samples:
        raise ValueError(f"floor_accel_g must be a one-dimensional array of at least {min_samples} samples")
    if not np.all(np.isfinite(accel)):
        raise ValueError("floor_accel_g contains NaN or infinite values")
    dt = float(dt_s)
    if not (np.isfinite(dt) and dt > 0.0):
        raise ValueError("dt_s must be finite and > 0")
    return accel, dt


def checked_records(records_g, dt_s, *, min_samples: int = 0):
    """Checked records (:func:`checked_record`) and their sample intervals.

    ``records_g`` is one record or a sequence of them; ``dt_s`` one interval or one per record.

    >>> records, dts = checked_records([0.1, 0.2], 0.01)
    >>> len(records), dts.tolist()
    (1, [0.01])
    """
    first = np.asarray(records_g[0]) if len(records_g) else np.asarray([])
    records = [records_g] if first.ndim == 0 else list(records_g)
    dts = np.broadcast_to(np.asarray(dt_s, dtype=float), (len(records),))
    checked = [checked_record(r, d, min_samples=min_samples) for r, d in zip(records, dts)]
    return [c[0] for c in checked], np.array([c[1] for c in checked])
