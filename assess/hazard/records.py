"""Acceleration records: read a file into floor accelerations [g] at a constant step.

Formats (SPEC §1):

* CSV with a header naming time and acceleration with their units,
  ``time_s,accel_g`` (also ``accel_m_s2``, ``accel_cm_s2``); lines starting with
  ``#`` are comments (pyslammer's sample records start with two such lines and
  give no header: ``Time (s),Acceleration (g's)`` in a comment is read as that
  header);
* a single column of accelerations whose header gives the unit and the step,
  e.g. ``accel_g,dt_s=0.005``;
* PEER NGA ``.AT2``: four header lines, the fourth giving ``NPTS`` and ``DT``,
  then accelerations in g, several per line.

Units are read from the header, never guessed. Every problem raises
:class:`~assess.errors.InputError` naming the file and the line.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from assess.errors import InputError, Problem
from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2

#: Factor from each accepted acceleration unit to g.
ACCELERATION_UNITS_TO_G = {"g": 1.0, "m_s2": 1.0 / STANDARD_GRAVITY_M_S2,
                           "cm_s2": 0.01 / STANDARD_GRAVITY_M_S2}
#: Relative spread of the time steps accepted as "constant".
DT_TOLERANCE = 1e-3
_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"


@dataclass(frozen=True)
class Record:
    """A floor acceleration history at a constant step.

    Attributes
    ----------
    accel_g : ndarray
        Acceleration [g] at 0, dt, 2dt, ...
    dt_s : float
        Step [s].
    name : str
        Where it came from (file name).
    """

    accel_g: np.ndarray
    dt_s: float
    name: str

    @property
    def duration_s(self) -> float:
        return (self.accel_g.size - 1) * self.dt_s

    @property
    def pta_g(self) -> float:
        """Peak absolute acceleration [g]."""
        return float(np.max(np.abs(self.accel_g)))

    def scaled(self, factor: float) -> "Record":
        return Record(self.accel_g * factor, self.dt_s, self.name)


def _problem(path, message, fix, line=None):
    return InputError([Problem(file=str(path), message=message, fix=fix, row=line)])


def read_record(path) -> Record:
    """Read an acceleration record (CSV, one column with ``dt_s``, or PEER ``.AT2``).

    Raises
    ------
    InputError
        The file is missing or cannot be read as a record; the message names
        the file and the line.
    """
    path = Path(path)
    if not path.is_file():
        raise _problem(path, "the record file does not exist.",
                       "check the path (relative paths are taken from the workbook's folder).")
    text = path.read_text(encoding="utf-8-sig", errors="replace")
    lines = text.splitlines()
    if path.suffix.lower() == ".at2":
        accel, dt = _read_at2(path, lines)
    else:
        accel, dt = _read_csv(path, lines)
    if accel.size < 2:
        raise _problem(path, f"the record has {accel.size} sample(s).", "give at least two samples.")
    if not np.all(np.isfinite(accel)):
        raise _problem(path, "the record contains NaN or infinite accelerations.",
                       "remove or fill the missing samples.")
    return Record(accel_g=accel, dt_s=dt, name=path.name)


def _read_at2(path, lines):
    if len(lines) < 5:
        raise _problem(path, "a PEER .AT2 file needs four header lines and then data.",
                       "give the file as downloaded from the PEER NGA database.")
    npts = re.search(r"NPTS\s*=\s*(\d+)", lines[3], re.I)
    dt = re.search(rf"DT\s*=\s*({_NUMBER})", lines[3], re.I)
    if not (npts and dt):
        raise _problem(path, f"line 4 should give NPTS= and DT=, found '{lines[3].strip()}'.",
                       "give the file as downloaded from the PEER NGA database.", line=4)
    values = []
    for number, line in enumerate(lines[4:], start=5):
        try:
            values.extend(float(v) for v in line.replace(",", " ").split())
        except ValueError:
            raise _problem(path, f"line {number} is not a row of numbers: '{line.strip()[:60]}'.",
                           "remove the stray text.", line=number) from None
    if len(values) != int(npts.group(1)):
        raise _problem(path, f"the header says NPTS={npts.group(1)} but {len(values)} values follow.",
                       "check that the file is complete.")
    return np.array(values), float(dt.group(1))


def _header_units(path, header, number):
    names = [h.strip().lower() for h in header.split(",")]
    accel_unit = None
    for name in names:
        match = re.fullmatch(r"accel(?:eration)?_(g|m_s2|cm_s2)", name)
        if match:
            accel_unit = match.group(1)
    if header.lower().startswith("time (s),acceleration (g"):  # pyslammer's comment header
        return 0, 1, "g", None
    if accel_unit is None:
        raise _problem(path, f"the header '{header.strip()}' does not name the acceleration with its "
                       "unit.", "name the columns time_s,accel_g (or accel_m_s2, accel_cm_s2), or give "
                       "a single column headed accel_g,dt_s=0.01.", line=number)
    accel_col = next(i for i, n in enumerate(names) if n.startswith("accel"))
    dt = re.search(rf"dt_s\s*=\s*({_NUMBER})", header, re.I)
    time_col = names.index("time_s") if "time_s" in names else None
    if time_col is None and dt is None:
        raise _problem(path, "the header gives neither a time_s column nor dt_s=.",
                       "add a time_s column, or write the step in the header: accel_g,dt_s=0.01.",
                       line=number)
    return time_col, accel_col, accel_unit, (float(dt.group(1)) if dt else None)


def _read_csv(path, lines):
    header, header_line, rows = None, None, []
    for number, line in enumerate(lines, start=1):
        stripped = line.strip()
        if not stripped:
            continue
        if stripped.startswith("#"):
            comment = stripped.lstrip("#").strip()
            if header is None and comment.lower().startswith("time (s),acceleration (g"):
                header, header_line = comment, number
            continue
        if header is None:
            header, header_line = stripped, number
            continue
        rows.append((number, stripped))
    if header is None:
        raise _problem(path, "the file is empty.", "give a header and one row per sample.")
    time_col, accel_col, unit, dt = _header_units(path, header, header_line)
    times, accel = [], []
    for number, row in rows:
        cells = row.split(",")
        try:
            accel.append(float(cells[accel_col]))
            if time_col is not None:
                times.append(float(cells[time_col]))
        except (ValueError, IndexError):
            raise _problem(path, f"line {number} is not a row of numbers: '{row[:60]}'.",
                           "remove the stray text or comment it out with #.", line=number) from None
    accel = np.array(accel) * ACCELERATION_UNITS_TO_G[unit]
    if time_col is not None and len(times) >= 2:
        steps = np.diff(times)
        dt = float(f"{np.mean(steps):.12g}")  # 0.019999999999999997 -> 0.02
        if dt <= 0 or np.max(np.abs(steps - dt)) > DT_TOLERANCE * dt:
            k = int(np.argmax(np.abs(steps - dt)))
            raise _problem(path, f"the time step is not constant: {steps[k]:g} s between lines of times "
                           f"{times[k]:g} and {times[k + 1]:g} s (mean {dt:g} s).",
                           "resample the record to a constant step.", line=rows[k + 1][0])
    return accel, (dt if dt is not None else 0.0)


def pulse_record(pulse: str, ap_g: float, tp_s: float, dt_s: float | None = None) -> Record:
    """The pulse of SPEC §4 sampled from 0 to its end (zero after), as a :class:`Record`.

    The default step is min(Tp/400, 5 ms): 400 samples per pulse period, over
    which the piecewise-linear input the engine reads follows the smooth pulse.

    >>> r = pulse_record("rect", 0.5, 1.0)
    >>> r.accel_g.size, r.dt_s, r.pta_g
    (401, 0.0025, 0.5)
    """
    from assess.hazard.pulses import pulse_acceleration, pulse_duration
    if not (np.isfinite(tp_s) and tp_s > 0.0):
        raise ValueError(f"tp_s must be positive, got {tp_s!r}")
    dt = min(tp_s / 400.0, 0.005) if dt_s is None else float(dt_s)
    n = int(np.ceil(pulse_duration(pulse, tp_s) / dt - 1e-9)) + 1
    time_s = np.arange(n) * dt
    accel = pulse_acceleration(pulse, ap_g, tp_s, np.minimum(time_s, pulse_duration(pulse, tp_s)))
    return Record(accel_g=accel, dt_s=dt, name=f"Type-{pulse} pulse, ap {ap_g:g} g, Tp {tp_s:g} s"
                  if pulse != "rect" else f"rectangular pulse, ap {ap_g:g} g, Tp {tp_s:g} s")
