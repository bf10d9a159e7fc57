"""Acceleration records: read a file into floor accelerations [g] at a constant step.

Formats (docs/workbook.md, "Record files"):

* CSV with a header naming time and acceleration with their units,
  ``time_s,accel_g`` (also ``accel_m_s2``, ``accel_cm_s2`` and ``accel_gal``,
  1 gal = 1 cm/s²); lines starting with ``#`` are comments (pyslammer's sample
  records give no header line: ``Time (s),Acceleration (g's)`` in a comment is
  read as that header);
* a single column of accelerations whose header gives the unit and the step,
  e.g. ``accel_g,dt_s=0.005``;
* PEER NGA ``.AT2``: four header lines, the fourth giving ``NPTS=`` and ``DT=``
  (or, in the older format, ``7998  .0050  NPTS, DT``), then accelerations in
  g, several per line.

Units are read from the header, never guessed. A byte-order mark (UTF-8 or
UTF-16) and CRLF or CR line ends are accepted. Every problem raises
:class:`~assess.errors.InputError` naming the file and the line, what is wrong
and how to fix it; a message never quotes the file's text (it may not be a
record at all), only its numbers and, where they are plain names such as
``time_ms``, its header cells.

What is read is bounded: at most :data:`MAX_RECORD_BYTES` bytes and
:data:`MAX_RECORD_SAMPLES` samples, text only (a NUL byte outside UTF-16 is
binary data), at a step between :data:`MIN_STEP_S` and :data:`MAX_STEP_S`.
:func:`check_record_location` keeps the records a workbook names inside its
folder.
"""
from __future__ import annotations

import errno
import os
import re
import stat
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from assess.errors import InputError, Problem
from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2

#: Factor from each accepted acceleration unit (header suffix) to g.
ACCELERATION_UNITS_TO_G = {"g": 1.0, "m_s2": 1.0 / STANDARD_GRAVITY_M_S2,
                           "cm_s2": 0.01 / STANDARD_GRAVITY_M_S2, "gal": 0.01 / STANDARD_GRAVITY_M_S2}
#: How each unit is written in messages.
_UNIT_TEXT = {"g": "g", "m_s2": "m/s²", "cm_s2": "cm/s²", "gal": "gal (cm/s²)"}
#: Relative spread of the time steps accepted as "constant".
DT_TOLERANCE = 1e-3
#: Above this peak acceleration [g] a record is refused as a probable unit mistake.
MAX_PLAUSIBLE_PGA_G = 5.0
#: Shortest record [s] a caller asking for a duration check should demand
#: (``read_record(path, min_duration_s=MIN_DURATION_S)``).
MIN_DURATION_S = 2.0
#: Most samples a record may hold: 16 minutes at 1 kHz, 2.8 hours at 100 Hz, far
#: longer than a floor motion. The simulation's time and memory grow with the
#: sample count.
MAX_RECORD_SAMPLES = 1_000_000
#: Largest record file [bytes]: MAX_RECORD_SAMPLES samples written as
#: ``time,acceleration`` lines of up to ~30 characters, with room for comments.
#: Reading is bounded by it, whatever the file claims to be (``/proc`` files
#: report a size of 0).
MAX_RECORD_BYTES = 32 * 1024 * 1024
#: Finest and coarsest time step [s] accepted. Above 0.1 s a record holds
#: nothing above 5 Hz (its Nyquist frequency), where floor motions carry much of
#: their energy, and the solvers, which read it as piecewise linear, would shake
#: the item with a coarse polygon; below 0.1 ms (10 kHz) no strong-motion or
#: shake-table instrument samples, and such a step is rather a time column in
#: another unit than seconds.
MIN_STEP_S, MAX_STEP_S = 1e-4, 0.1
#: A header cell is named in a message only when it is a plain name like this one.
_PLAIN_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,39}")
_NUMBER = r"[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?"  # ASCII digits only
#: A value of a record as written by a program: a decimal number in ASCII digits (or nan/inf, refused later,
#: located). Python's float() also reads "0.1_0" (underscores) and other scripts' digits ("０.１").
_PLAIN_NUMBER = re.compile(rf"\s*(?:{_NUMBER}|[-+]?(?:nan|inf|infinity))\s*", re.IGNORECASE)
_LINE_END = re.compile(r"\r\n|\r|\n")
_PYSLAMMER_HEADER = "time (s),acceleration (g"
_HEADER_FIX = ("head the columns time_s,accel_g (or accel_m_s2, accel_cm_s2, accel_gal), or give a "
               "single column headed accel_g,dt_s=0.01.")


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
        """Time [s] from the first to the last sample."""
        return (self.accel_g.size - 1) * self.dt_s

    @property
    def time_s(self) -> np.ndarray:
        """Times [s] of the samples, from 0."""
        return np.arange(self.accel_g.size) * self.dt_s

    @property
    def pta_g(self) -> float:
        """Peak absolute acceleration [g]."""
        return float(np.max(np.abs(self.accel_g)))

    def scaled(self, factor: float) -> "Record":
        return Record(self.accel_g * factor, self.dt_s, self.name)


@dataclass(frozen=True)
class _Samples:
    """What a format reader found: values in the declared unit and where each one was."""

    values: np.ndarray   # in the declared unit
    dt_s: float
    lines: np.ndarray    # file line (1-based) of each value
    unit: str            # key of ACCELERATION_UNITS_TO_G
    unit_source: str     # where the unit was declared, for messages
    step_source: str     # where the step was read, for messages
    step_line: int       # ... and on which line


def _named(cell: str, otherwise: str) -> str:
    """``'cell'`` when the header cell is a plain name, else ``otherwise`` (file text is never echoed)."""
    cell = cell.strip()
    return f"'{cell}'" if _PLAIN_NAME.fullmatch(cell) else otherwise


def _problem(path, message, fix, line=None):
    return InputError([Problem(file=str(path), message=message, fix=fix, row=line)])


def check_record_location(record_path, folder) -> str | None:
    """Why a workbook in ``folder`` may not name ``record_path`` as a record; None when it may.

    A workbook names its records relative to its own folder (docs/workbook.md); one
    that reaches outside it (``../../etc/passwd``, ``/proc/self/environ``, a
    link inside the folder that points elsewhere) would make assess read, and
    a message about it quote, a file the user never meant to hand over. So
    the record must lie in ``folder`` or below it once every symbolic link is
    followed. Nothing is opened here.

    >>> check_record_location("/data/site/records/lg.csv", "/data/site") is None
    True
    >>> check_record_location("/data/site/../secret.csv", "/data/site")[:40]
    "the record file is outside the workbook'"
    """
    real = os.path.realpath(record_path)
    base = os.path.realpath(folder)
    try:
        inside = os.path.commonpath([real, base]) == base
    except ValueError:  # different drives (Windows)
        inside = False
    if inside:
        return None
    return (f"the record file is outside the workbook's folder {base} (it is {real[:200]}); records are "
            "read only from that folder and its subfolders, so that a workbook cannot make assess read "
            "other files of this machine.")


def read_record(path, *, min_duration_s: float = 0.0, max_pga_g: float = MAX_PLAUSIBLE_PGA_G,
                scale: float = 1.0) -> Record:
    """Read an acceleration record (CSV, one column with ``dt_s``, or PEER ``.AT2``).

    Parameters
    ----------
    path : str or Path
        The record file; ``.AT2`` (any case) is read as PEER NGA, anything
        else as CSV.
    min_duration_s : float, default 0
        Refuse a record shorter than this [s]. No check by default, as short
        synthetic histories are valid input to the engine; callers reading a
        user's earthquake record should pass :data:`MIN_DURATION_S` (2 s).
    max_pga_g : float, default :data:`MAX_PLAUSIBLE_PGA_G`
        Refuse a record whose peak acceleration exceeds this [g]: such a
        value is almost always a unit mistake (m/s² or cm/s² read as g).
    scale : float, default 1
        Factor applied to the record (the workbook's ``scale``); the scaled
        record must still peak below ``max_pga_g`` and above zero.

    Returns
    -------
    Record
        Accelerations [g] at a constant step, named after the file.

    Raises
    ------
    InputError
        The file is missing or cannot be read as a record; the message names
        the file and the line, and says how to fix it.

    Examples
    --------
    >>> import tempfile, os
    >>> folder = tempfile.mkdtemp()
    >>> path = os.path.join(folder, "floor.csv")
    >>> _ = open(path, "w").write("time_s,accel_cm_s2\\n0,0\\n0.01,98.0665\\n0.02,-49.03325\\n")
    >>> r = read_record(path)
    >>> r.dt_s, [round(float(a), 12) for a in r.accel_g]
    (0.01, [0.0, 0.1, -0.05])
    """
    path = Path(path)
    raw = _read_bounded(path)
    text = _decode(path, raw)
    if max(text.count("\n"), text.count("\r")) > MAX_RECORD_SAMPLES + 10_000:
        raise _problem(path, f"the file has more than {MAX_RECORD_SAMPLES:,} lines; a record may hold at most "
                       f"{MAX_RECORD_SAMPLES:,} samples.", "give one floor motion per file, resampled to a "
                       "coarser step if it is sampled more finely than needed (0.005 s is usual).")
    lines = _LINE_END.split(text)
    if not any(line.strip() for line in lines):
        raise _problem(path, "the file is empty.",
                       "give a header (e.g. time_s,accel_g) and one row per sample.")
    if path.suffix.lower() == ".at2":
        samples = _read_at2(path, lines)
    else:
        samples = _read_csv(path, lines)
    accel_g = samples.values * ACCELERATION_UNITS_TO_G[samples.unit]
    _check_samples(path, samples, accel_g, min_duration_s, max_pga_g)
    if scale != 1.0:
        accel_g = _scaled(path, samples, accel_g, scale, max_pga_g)
    return Record(accel_g=accel_g, dt_s=samples.dt_s, name=path.name)


#: What an operating-system error opening a record means, and what to do.
#: Where a relative record path starts: a workbook's folder, or for ``assess simulate --record`` the current one.
_WHERE_PATHS_START = ("check the path (a workbook's record paths start from its folder, assess simulate's --record "
                      "from the current folder).")
_OPEN_ERRORS = {
    errno.ENOENT: ("the record file does not exist.", _WHERE_PATHS_START),
    errno.ENOTDIR: ("the record file does not exist (a part of its path is not a folder).", _WHERE_PATHS_START),
    errno.ELOOP: ("the path is a loop of symbolic links: it leads back to itself and names no file.",
                  "point the record path (or the link) at the record file itself."),
    errno.ENAMETOOLONG: ("the path is too long for the file system (a file or folder name over 255 "
                         "characters, or the whole path over 4096).", "check the path; shorten the names."),
    errno.EACCES: ("the record file cannot be read (permission denied).",
                   "make the file readable by the user running assess."),
}


def record_file_problem(path) -> str | None:
    """What is wrong with ``path`` as a record file before it is read (None: it is a regular file).

    Never raises: a loop of links, a name too long for the file system or a
    missing file is said in words (``Path.is_file`` raises on a name over 255
    characters; ``Path.resolve`` on a loop). For readers of the workbook,
    which check the path of every record before anything is read.

    >>> record_file_problem("/nowhere/at/all.csv")
    'the record file does not exist.'
    """
    try:
        mode = os.stat(path).st_mode
    except OSError as error:
        return _OPEN_ERRORS.get(error.errno, (f"the record file cannot be opened ({error.strerror}).",))[0]
    except ValueError:  # a NUL character in the path
        return "the path holds a NUL character."
    if stat.S_ISDIR(mode):
        return "this is a folder, not a record file."
    if not stat.S_ISREG(mode):
        return "this is not a regular file (a device, a pipe or a socket)."
    return None


def _read_bounded(path: Path) -> bytes:
    """The bytes of the regular file ``path``: at most :data:`MAX_RECORD_BYTES`, else refused.

    Opened without blocking (a FIFO named as a record must not hang the run)
    and checked to be a regular file on the open descriptor itself.
    """
    try:
        descriptor = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_BINARY", 0))
    except OSError as error:
        message, fix = _OPEN_ERRORS.get(error.errno, (
            f"the record file cannot be opened ({error.strerror}).",
            "check that the file exists, is readable and not locked by another program."))
        raise _problem(path, message, fix) from None
    except ValueError:
        raise _problem(path, "the path holds a NUL character.", "check the path.") from None
    try:
        mode = os.fstat(descriptor).st_mode
        if stat.S_ISDIR(mode):
            raise _problem(path, "this is a folder, not a record file.", "name the record file in the folder.")
        if not stat.S_ISREG(mode):
            raise _problem(path, "this is not a regular file (a device, a pipe or a socket).",
                           "save the record as a CSV or .AT2 file and name that file.")
        with os.fdopen(descriptor, "rb", closefd=False) as stream:
            raw = stream.read(MAX_RECORD_BYTES + 1)
    except OSError as error:
        raise _problem(path, f"the record file cannot be read ({error.strerror}).",
                       "check that the file is readable and not locked by another program.") from None
    finally:
        os.close(descriptor)
    if len(raw) > MAX_RECORD_BYTES:
        raise _problem(path, f"the file is larger than {MAX_RECORD_BYTES // 2**20} MB, more than a record of "
                       f"{MAX_RECORD_SAMPLES:,} samples needs.", "give one floor motion per file, resampled to "
                       "a coarser step if it is sampled more finely than needed (0.005 s is usual).")
    return raw


def _decode(path: Path, raw: bytes) -> str:
    """Text of a file: UTF-16 when it starts with a UTF-16 byte-order mark, else UTF-8 (mark dropped).

    A NUL byte elsewhere means binary data (a spreadsheet, an archive, a
    device dump), not a record: refused, naming the line it is on.
    """
    if raw.startswith((b"\xff\xfe", b"\xfe\xff")):
        return raw.decode("utf-16", errors="replace")
    nul = raw.find(b"\x00")
    if nul >= 0:
        line = raw.count(b"\n", 0, nul) + 1
        raise _problem(path, f"the file holds binary data (a NUL byte on line {line}), not the text of a "
                       "record.", "give the record as a CSV or PEER .AT2 text file (a spreadsheet must be "
                       "saved as CSV; UTF-16 text needs its byte-order mark).", line=line)
    return raw.decode("utf-8-sig", errors="replace")


def _scaled(path, samples: _Samples, accel_g, scale: float, max_pga_g: float):
    """``accel_g`` times the workbook's ``scale``, refused when the product is no usable motion."""
    scaled = accel_g * scale
    pga_g = float(np.max(np.abs(scaled))) if np.isfinite(scale) else float("nan")
    if not np.isfinite(pga_g) or pga_g > max_pga_g:
        raise _problem(path, f"the record times its scale {scale:g} peaks at {pga_g:.3g} g, more than "
                       f"{max_pga_g:g} g.", "check the scale: it multiplies the record as read (in g).")
    if pga_g < np.finfo(float).tiny:
        raise _problem(path, f"the record times its scale {scale:g} is zero (its peak "
                       f"{float(np.max(np.abs(accel_g))):.3g} g times the scale is below the smallest "
                       "normal floating-point number).", "check the scale: it multiplies the record as read.")
    return scaled


def _check_samples(path, samples: _Samples, accel_g, min_duration_s, max_pga_g):
    """Checks common to every format: enough samples, finite values, a plausible peak, the duration."""
    if accel_g.size < 2:
        raise _problem(path, f"the record has {accel_g.size} sample(s).", "give at least two samples.")
    if accel_g.size > MAX_RECORD_SAMPLES:
        raise _problem(path, f"the record has {accel_g.size:,} samples, more than {MAX_RECORD_SAMPLES:,}.",
                       "give one floor motion per file, resampled to a coarser step if it is sampled more "
                       "finely than needed (0.005 s is usual).")
    if not MIN_STEP_S <= samples.dt_s <= MAX_STEP_S:
        why = (f"a step over {MAX_STEP_S:g} s cannot carry the frequencies (up to 10-25 Hz) of a floor motion"
               if samples.dt_s > MAX_STEP_S else
               f"no accelerograph samples finer than {MIN_STEP_S:g} s (10 kHz), and the simulation's cost "
               "grows with the number of samples")
        raise _problem(path, f"the time step is {samples.dt_s:g} s ({samples.step_source}); a record's step "
                       f"must be between {MIN_STEP_S:g} s and {MAX_STEP_S:g} s: {why}.",
                       "check that the step is in seconds; resample the record to 0.005-0.02 s if needed.",
                       line=samples.step_line)
    bad = np.flatnonzero(~np.isfinite(accel_g))
    if bad.size:
        line = int(samples.lines[bad[0]])
        raise _problem(path, f"the record contains NaN or infinite accelerations ({bad.size} value(s), "
                       f"the first on line {line}).", "remove or fill the missing samples: a record "
                       "needs a number at every step.", line=line)
    peak = int(np.argmax(np.abs(accel_g)))
    pga_g = float(abs(accel_g[peak]))
    if pga_g > max_pga_g:
        line = int(samples.lines[peak])
        raise _problem(path, f"the peak acceleration is {pga_g:.3g} g (line {line}, value "
                       f"{samples.values[peak]:g} read as {_UNIT_TEXT[samples.unit]} from "
                       f"{samples.unit_source}), more than {max_pga_g:g} g: this is probably a unit "
                       "mistake.", _unit_fix(samples, pga_g, max_pga_g), line=line)
    duration_s = (accel_g.size - 1) * samples.dt_s
    if duration_s < min_duration_s:
        raise _problem(path, f"the record lasts {duration_s:.4g} s ({accel_g.size} samples at "
                       f"{samples.dt_s:g} s), less than {min_duration_s:g} s.",
                       "give the whole record; if it is complete, check that the step (dt_s or the "
                       "time column) is in seconds.", line=int(samples.lines[-1]))
    if not np.any(accel_g):
        raise _problem(path, f"the acceleration is zero at every one of the {accel_g.size} samples: there is "
                       "no motion to simulate.", "check that the file is the record meant and that its "
                       "acceleration column holds the values.")


def _unit_fix(samples: _Samples, pga_g: float, max_pga_g: float) -> str:
    """Which declared unit would make the peak plausible, as advice."""
    raw_peak = pga_g / ACCELERATION_UNITS_TO_G[samples.unit]
    plausible = [unit for unit in ("m_s2", "cm_s2")
                 if ACCELERATION_UNITS_TO_G[unit] < ACCELERATION_UNITS_TO_G[samples.unit]
                 and 0.01 <= raw_peak * ACCELERATION_UNITS_TO_G[unit] <= max_pga_g]
    if samples.unit_source.startswith("the .AT2"):
        if plausible:
            unit = plausible[0]
            return (f"PEER .AT2 files are in g; these values look like {_UNIT_TEXT[unit]} (peak "
                    f"{raw_peak * ACCELERATION_UNITS_TO_G[unit]:.3g} g): save the record as a CSV with "
                    f"the header time_s,accel_{unit}, or check it is an acceleration file.")
        return "PEER .AT2 files are in g: check that this is an acceleration file and in g."
    if plausible:
        unit = plausible[0]
        return (f"if the values are in {_UNIT_TEXT[unit]} (peak "
                f"{raw_peak * ACCELERATION_UNITS_TO_G[unit]:.3g} g), head the column accel_{unit}"
                + (" (or accel_gal)" if unit == "cm_s2" else "") + "; otherwise check the values.")
    return "check the values and the unit suffix of the acceleration column (accel_g, accel_m_s2, accel_cm_s2)."


# ------------------------------------------------------------------ PEER .AT2

def _read_at2(path, lines) -> _Samples:
    if len(lines) < 5:
        raise _problem(path, "a PEER .AT2 file needs four header lines and then data.",
                       "give the file as downloaded from the PEER NGA database.")
    _check_at2_quantity(path, lines[2])
    npts, dt = _at2_npts_dt(path, lines[3])
    values, where = [], []
    for number, line in enumerate(lines[4:], start=5):
        numbers = _numbers_of(line)
        if numbers is None:
            raise _problem(path, f"line {number} is not a row of numbers (it holds other text).",
                           "remove the stray text.", line=number)
        values.extend(numbers)
        where.extend([number] * len(numbers))
        if len(values) > MAX_RECORD_SAMPLES:
            raise _problem(path, f"the file holds more than {MAX_RECORD_SAMPLES:,} samples (line {number}).",
                           "give one floor motion per file.", line=number)
    if len(values) != npts:
        span = "" if not where else f" (line {where[0]})" if where[-1] == where[0] else \
            f" (lines {where[0]} to {where[-1]})"
        raise _problem(path, f"line 4 says NPTS={npts} but {len(values)} values follow{span}.",
                       "the file may be truncated or edited: download it again from the PEER NGA "
                       "database, or correct NPTS on line 4.", line=4)
    return _Samples(np.array(values, dtype=float), dt, np.array(where), "g", "the .AT2 format (always g)",
                    "DT on line 4", 4)


def _check_at2_quantity(path, line):
    """Line 3 of an AT2 says what the file holds; refuse velocity, displacement and non-g units."""
    text = line.upper()
    for quantity, kind in (("VELOCITY", ".VT2"), ("DISPLACEMENT", ".DT2")):
        if quantity in text and "ACCELERATION" not in text:
            raise _problem(path, f"line 3 says this file holds a {quantity.lower()} history.",
                           f"give the acceleration file (.AT2) of the record, "
                           f"not the {kind} one.", line=3)
    unit = re.search(r"UNITS\s+OF\s+([A-Z/0-9*^.]+)", text)
    if unit and unit.group(1).rstrip(".") != "G":
        raise _problem(path, f"line 3 gives the units as {unit.group(1)[:12]}; a .AT2 file is read in g.",
                       "save the record as a CSV whose header names its unit "
                       "(time_s,accel_cm_s2 or accel_m_s2).", line=3)


def _at2_npts_dt(path, line) -> tuple[int, float]:
    """NPTS and DT from line 4: ``NPTS= 7998, DT= .0050 SEC`` or the older ``7998  .0050  NPTS, DT``."""
    npts = re.search(r"NPTS\s*=\s*(\d+)", line, re.I)
    dt = re.search(rf"DT\s*=\s*({_NUMBER})", line, re.I)
    if not (npts and dt):
        old = re.match(rf"\s*(\d+)\s*,?\s+({_NUMBER})\s+NPTS\s*,\s*DT", line, re.I)
        if not old:
            raise _problem(path, "line 4 should give NPTS= and DT= (e.g. NPTS= 7998, DT= .0050 SEC).",
                           "give the file as downloaded from the PEER NGA database.", line=4)
        count, step = int(old.group(1)), float(old.group(2))
    else:
        count, step = int(npts.group(1)), float(dt.group(1))
    if not (np.isfinite(step) and step > 0.0):
        raise _problem(path, f"line 4 gives the step DT={step:g}; it must be a positive number of seconds.",
                       "correct DT on line 4.", line=4)
    return count, step


def _numbers_of(line) -> list[float] | None:
    """The numbers on a data line of an AT2 (None when it holds anything else).

    Fortran-written files may run two numbers together (``-.1234E-02-.5678E-03``).
    """
    text = line.replace(",", " ").strip()
    if not text:
        return []
    try:
        return [plain_number(v) for v in text.split()]
    except ValueError:
        pass
    found = re.findall(_NUMBER, text)
    if re.sub(_NUMBER, "", text).strip():
        return None
    return [float(v) for v in found]


# ------------------------------------------------------------------ CSV

@dataclass(frozen=True)
class _Layout:
    """What a CSV header declares."""

    time_col: int | None
    accel_col: int
    unit: str
    dt_s: float | None
    n_columns: int
    accel_name: str


def _read_csv(path, lines) -> _Samples:
    header, header_line, rows = None, None, []
    for number, line in enumerate(lines, start=1):
        stripped = line.strip()
        if not stripped:
            continue
        if stripped.startswith("#"):
            comment = stripped.lstrip("#").strip()
            if header is None and comment.lower().startswith(_PYSLAMMER_HEADER):
                header, header_line = comment, number
            continue
        if header is None:
            header, header_line = stripped, number
            continue
        rows.append((number, stripped))
    if header is None:
        raise _problem(path, "the file holds only comments: no header and no samples.",
                       "give a header (e.g. time_s,accel_g) and one row per sample.")
    layout = _header_layout(path, header, header_line)
    if not rows:
        raise _problem(path, f"the file has a header (line {header_line}) but no samples.",
                       "give one row per sample below the header.", line=header_line)
    header_cells = [c.lower() for c in _cells(header)]
    times, accel, where = [], [], []
    for number, row in rows:
        cells = _cells(row)
        if [c.lower() for c in cells] == header_cells or layout.accel_name in (c.lower() for c in cells):
            raise _problem(path, f"line {number} repeats the header of line {header_line}: two records "
                           "in one file?", "keep one record per file (one header, then the samples).",
                           line=number)
        if len(cells) != layout.n_columns and all(_is_number(c) for c in cells):
            raise _problem(path, f"line {number} has {len(cells)} value(s) where the header (line "
                           f"{header_line}) names {layout.n_columns} column(s).",
                           "give one value per column on every row.", line=number)
        if len(where) >= MAX_RECORD_SAMPLES:
            raise _problem(path, f"the file holds more than {MAX_RECORD_SAMPLES:,} samples (line {number}).",
                           "give one floor motion per file.", line=number)
        try:
            accel.append(plain_number(cells[layout.accel_col]))
            if layout.time_col is not None:
                times.append(plain_number(cells[layout.time_col]))
        except (ValueError, IndexError):
            if any(_looks_numeric(c) for c in cells):
                raise _problem(path, f"line {number} holds a value that is not a plain decimal number "
                               "(underscores, or digits other than 0-9).",
                               "write the values with the digits 0-9, a point and an exponent only "
                               "(e.g. 0.10 or 1.0e-1).", line=number) from None
            raise _problem(path, f"line {number} is not a row of numbers (it holds other text).",
                           "remove the stray text or comment it out with #.", line=number) from None
        where.append(number)
    dt = layout.dt_s if layout.time_col is None else _step_of_times(path, times, where, layout.dt_s)
    source = f"the header '{layout.accel_name}' (line {header_line})"  # a name the header layout accepted
    if layout.time_col is None or len(where) < 2:
        step_source, step_line = f"dt_s in the header, line {header_line}", header_line
    else:
        step_source, step_line = f"the time column, lines {where[0]} and {where[1]}", where[1]
    return _Samples(np.array(accel, dtype=float), dt, np.array(where), layout.unit, source,
                    step_source, step_line)


def _is_number(text) -> bool:
    return _PLAIN_NUMBER.fullmatch(text) is not None


def plain_number(text: str) -> float:
    """The number ``text`` writes in plain decimal (ASCII digits, a point, an exponent); ValueError otherwise.

    >>> plain_number(" -1.5e-3"), plain_number("nan") != plain_number("nan")
    (-0.0015, True)
    >>> for text in ("0.1_0", "\uff10.\uff11", "0x10"):
    ...     try:
    ...         plain_number(text)
    ...     except ValueError:
    ...         print("refused")
    refused
    refused
    refused
    """
    if _PLAIN_NUMBER.fullmatch(text) is None:
        raise ValueError("not a plain decimal number")
    return float(text)


def _looks_numeric(text: str) -> bool:
    """Whether Python's float() reads ``text`` although it is no plain number (``0.1_0``, ``０.１``)."""
    try:
        float(text)
    except ValueError:
        return False
    return _PLAIN_NUMBER.fullmatch(text) is None


def _cells(row) -> list[str]:
    """Comma-separated cells, stripped, without the empty cells a trailing comma leaves."""
    cells = [c.strip() for c in row.split(",")]
    while len(cells) > 1 and not cells[-1]:
        cells.pop()
    return cells


def _header_layout(path, header, number) -> _Layout:
    if header.lower().startswith(_PYSLAMMER_HEADER):  # pyslammer's comment header
        return _Layout(0, 1, "g", None, 2, "acceleration (g's)")
    if "," not in header and len(re.split(r"[;\t ]+", header.strip())) > 1:
        raise _problem(path, f"the header (line {number}) has no commas; columns must be separated by "
                       "commas.", "save the file as CSV (comma-separated), e.g. time_s,accel_g.", line=number)
    cells = _cells(header)
    try:
        float(cells[0])
    except ValueError:
        pass
    else:
        raise _problem(path, f"line {number} holds numbers where the header should be: the file does not "
                       "say which column is what, nor in which unit.", "add a first line " + _HEADER_FIX,
                       line=number)
    time_cols, accel_cols, dt_s, columns = [], [], None, []
    for cell in cells:
        name = cell.lower()
        step = re.fullmatch(rf"dt_s\s*=\s*({_NUMBER})", name)
        if step:
            dt_s = float(step.group(1))
            continue
        index = len(columns)
        columns.append(name)
        if name == "time_s":
            time_cols.append(index)
        elif name.startswith("accel"):
            unit = re.fullmatch(r"accel(?:eration)?_(g|m_s2|cm_s2|gal)", name)
            if unit is None:
                raise _problem(path, f"the header (line {number}) does not name the acceleration with its "
                               f"unit ({_named(cell, 'column ' + str(index + 1))}).", _HEADER_FIX, line=number)
            accel_cols.append((index, unit.group(1), name))
        elif name.startswith("time"):
            raise _problem(path, f"the header names the time {_named(cell, 'in column ' + str(index + 1))}; "
                           "only seconds are read (time_s).",
                           "give the times in seconds under the header time_s.", line=number)
    for kind, found in (("time", [columns[i] for i in time_cols]), ("acceleration", [a[2] for a in accel_cols])):
        if len(found) > 1:
            raise _problem(path, f"the header names the {kind} {len(found)} times "
                           f"({', '.join(found)}).",
                           f"keep one {kind} column per file.", line=number)
    if not accel_cols:
        raise _problem(path, f"the header (line {number}) does not name the acceleration with its unit.",
                       _HEADER_FIX, line=number)
    if dt_s is not None and not (np.isfinite(dt_s) and dt_s > 0.0):
        raise _problem(path, f"the header gives dt_s={dt_s:g}; the step must be a positive number of seconds.",
                       "correct dt_s in the header.", line=number)
    if not time_cols and dt_s is None:
        raise _problem(path, "the header gives neither a time_s column nor dt_s=.",
                       "add a time_s column, or write the step in the header: accel_g,dt_s=0.01.",
                       line=number)
    index, unit, name = accel_cols[0]
    return _Layout(time_cols[0] if time_cols else None, index, unit, dt_s, len(columns), name)


def _step_of_times(path, times, where, header_dt) -> float:
    """The constant step [s] of a time column; refuses times that do not increase or steps that vary."""
    if len(times) < 2:
        return header_dt if header_dt is not None else 0.0
    steps = np.diff(times)
    if np.any(steps <= 0.0):
        k = int(np.argmax(steps <= 0.0))
        raise _problem(path, f"the time does not increase at line {where[k + 1]}: {times[k + 1]:g} s after "
                       f"{times[k]:g} s on line {where[k]}.",
                       "sort the rows by time and remove repeated rows.", line=where[k + 1])
    dt = float(f"{np.mean(steps):.12g}")  # 0.019999999999999997 -> 0.02
    usual = float(f"{np.median(steps):.12g}")
    if np.max(np.abs(steps - dt)) > DT_TOLERANCE * dt:
        k = int(np.argmax(np.abs(steps - usual)))
        raise _problem(path, f"the time step is not constant: {steps[k]:.6g} s between lines {where[k]} and "
                       f"{where[k + 1]} (times {times[k]:g} and {times[k + 1]:g} s), where the usual step "
                       f"is {usual:g} s.", "resample the record to a constant step, or fill the missing "
                       "samples.", line=where[k + 1])
    if header_dt is not None and abs(header_dt - dt) > DT_TOLERANCE * dt:
        raise _problem(path, f"the header says dt_s={header_dt:g} but the time column steps by {dt:g} s.",
                       "remove dt_s= from the header, or correct it.", line=where[0])
    return dt


def pulse_record(pulse: str, ap_g: float, tp_s: float, dt_s: float | None = None) -> Record:
    """A pulse (docs/commands.md, ``--pulse``) sampled from 0 to its end (zero after), as a :class:`Record`.

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
