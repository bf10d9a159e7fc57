"""A cache of engine results, keyed by the content of everything a result depends on.

:class:`CachingRunner` is a runner (:mod:`assess.mechanics.gateway`): it takes
a batch of cases of any kind (the level's peaks, planar sliding, full
responses with or without histories), answers those it has seen before from a
folder of stored results, and hands only the others to the runner it wraps
(this machine's threads, a Dask cluster), in one batch. A case's key is a
hash of

* what is asked of the run (:meth:`~assess.mechanics.gateway.Cases.options`):
  its kind, the seconds followed after the record (``tail_s``) and, for a
  full response, whether it carries the histories and which solver was asked;

* the block: its class and every dataclass field (nested dataclasses such as a
  sliding interface included), floats by their exact ``repr``;
* the motion: the bytes of the record's samples (float64) and its time step
  ``dt_s`` (hashed once per record, not once per case), and of the second
  component of a planar run; synthetic histories enter through their
  samples, so their seed is part of the key;
* :func:`engine_version`: a hash of the source of every ``assess/mechanics``
  module, the package version, and the numpy and numba versions, so that a
  change of the engine invalidates every stored result.

The engine is deterministic (the same case gives the same peaks whatever else
is in its batch), so a stored result is the result; the tests check that the
numbers are identical with and without the cache.

Storage: a folder of *packs*, compressed ``.npz`` files each holding the
cases one call simulated (keys and peaks, or keys and responses with their
histories as flat arrays; no pickled objects). A pack is
written to a temporary file and renamed into place, so a reader never sees
half a pack and two processes writing at once lose nothing; packs are never
modified, only merged (when there are more than :data:`MAX_PACKS`) or
deleted, least recently used first, when the folder passes ``max_bytes``. A
pack that cannot be read (damaged, truncated, of another format) is treated
as missing and removed: its cases are simulated again.
"""
from __future__ import annotations

import contextlib
import dataclasses
import hashlib
import math
import os
import stat
import tempfile
import time
import zipfile
from pathlib import Path
from typing import Optional

import numpy as np

import numba

import assess
from assess.mechanics.block import MODES, BlockResponse
from assess.mechanics.gateway import (ENGINE_SOLVERS, PEAKS, RESPONSE, CasePeaks, Cases, LocalRunner, Progress, Result,
                                      RunnerBase)

#: Bump when the pack layout changes: packs of another format are not read.
PACK_FORMAT = 1
#: Format of a pack of full responses (:class:`~assess.mechanics.block.BlockResponse`).
RESPONSE_PACK_FORMAT = 2
#: Largest cache folder [bytes] before the least recently used packs are deleted.
DEFAULT_MAX_BYTES = 1 << 30
#: Packs in the folder before they are merged into one.
MAX_PACKS = 64
#: Bytes of a case key (BLAKE2b digest size): collisions are out of reach at any realistic number of cases.
KEY_BYTES = 16
#: Leftover temporary files (a writer killed mid-write) older than this are removed [s].
STALE_TEMPORARY_S = 3600.0
_MECHANICS = Path(__file__).resolve().parents[1] / "mechanics"
_FLOATS = ("sliding_max_m", "sliding_residual_m", "theta_max_over_alpha")
_BOOLS = ("uplift", "overturned")
_TEXTS = ("mode", "solver")
_RESPONSE_FLOATS = ("sliding_max_m", "sliding_residual_m", "theta_max_over_alpha", "overturn_time_s")
_HISTORIES = ("time_s", "sliding_m", "theta_rad")
#: Largest pack read [bytes], as a file and inflated (all its arrays together; about 1.5 million cases):
#: a pack past it is not read (its cases are simulated again), so a pack cannot make assess use more memory.
MAX_PACK_BYTES = 256 << 20
#: Arrays of a pack of each format.
_PACK_ARRAYS = {
    PACK_FORMAT: ("format", "keys") + _FLOATS + _BOOLS + _TEXTS,
    RESPONSE_PACK_FORMAT: ("format", "keys") + _RESPONSE_FLOATS + _BOOLS + _HISTORIES
    + ("solver", "mode_count", "mode_time", "mode_name", "history_length"),
}


def engine_version(folder: Path = _MECHANICS) -> str:
    """Hex digest of what the engine's numbers depend on besides the case itself.

    The source of every ``*.py`` module of ``folder`` (default: ``assess/mechanics``),
    by name and content, plus the versions of assess, numpy and numba.
    """
    digest = hashlib.blake2b(digest_size=KEY_BYTES)
    for path in sorted(Path(folder).glob("*.py")):
        digest.update(path.name.encode() + b"\0" + path.read_bytes() + b"\0")
    for version in (assess.__version__, np.__version__, numba.__version__):
        digest.update(str(version).encode() + b"\0")
    return digest.hexdigest()


def _canonical(value) -> str:
    """A field's value as exact text: floats by ``repr`` (round-trips exactly), dataclasses field by field."""
    if value is None or isinstance(value, (bool, str)):
        return repr(value)
    if isinstance(value, (int, np.integer)):
        return repr(int(value))
    if isinstance(value, (float, np.floating)):
        return repr(float(value))
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return block_fingerprint(value)
    if isinstance(value, (tuple, list)):
        return "(" + ",".join(_canonical(v) for v in value) + ")"
    if isinstance(value, np.ndarray):
        array = np.ascontiguousarray(value)
        return f"array({array.dtype.str},{array.shape},{hashlib.blake2b(array.tobytes()).hexdigest()})"
    raise TypeError(f"no exact text for a {type(value).__name__}")


def block_fingerprint(block) -> str:
    """The block's class and every dataclass field with its exact value, as text.

    >>> from assess.mechanics.block import Block
    >>> print(block_fingerprint(Block(half_width_m=0.3, cg_height_m=1.0, height_m=2.0, mu=0.2)))
    assess.mechanics.block.Block(half_width_m=0.3,cg_height_m=1.0,height_m=2.0,mu=0.2,mu_static=0.2,restitution=None,foot_inset_m=0.0)
    """
    kind = type(block)
    fields = ",".join(f"{f.name}={_canonical(getattr(block, f.name))}" for f in dataclasses.fields(block))
    return f"{kind.__module__}.{kind.__qualname__}({fields})"


def record_digest(record_g, dt_s: float) -> bytes:
    """Hash of a record's samples (as float64) and its time step."""
    samples = np.ascontiguousarray(record_g, dtype=np.float64)
    digest = hashlib.blake2b(digest_size=KEY_BYTES)
    digest.update(f"{samples.shape}|{float(dt_s)!r}|".encode())
    digest.update(samples.tobytes())
    return digest.digest()


def case_keys(cases: Cases, version: str) -> list[Optional[bytes]]:
    """One key per case (None for a block whose fields have no exact text: never cached)."""
    records = [record_digest(r, d) for r, d in zip(cases.records_g, cases.dt_s)]
    prefix = f"{version}|{cases.options()}|".encode()
    second = cases.record_index_2.tolist() if cases.record_index_2 is not None else [None] * len(cases)
    by_block: dict[int, Optional[bytes]] = {}
    keys = []
    for block, j, j2 in zip(cases.blocks, cases.record_index.tolist(), second):
        digest = by_block.get(id(block), b"")
        if digest == b"":
            try:
                digest = hashlib.blake2b(block_fingerprint(block).encode(), digest_size=KEY_BYTES).digest()
            except TypeError:
                digest = None
            by_block[id(block)] = digest
        motion = records[j] + (b"" if j2 is None else records[j2])
        keys.append(None if digest is None
                    else hashlib.blake2b(prefix + digest + motion, digest_size=KEY_BYTES).digest())
    return keys


@dataclasses.dataclass
class _Index:
    """Every stored case, keys sorted for a binary search, and the packs they came from."""

    keys: np.ndarray = dataclasses.field(default_factory=lambda: np.zeros(0, dtype=f"S{KEY_BYTES}"))
    values: dict = dataclasses.field(default_factory=dict)
    packs: set = dataclasses.field(default_factory=set)

    def add(self, keys: np.ndarray, values: dict) -> None:
        keys = np.concatenate([self.keys, keys])
        merged = {name: np.concatenate([self.values[name], values[name]]) if name in self.values
                  else values[name] for name in values}
        keys, first = np.unique(keys, return_index=True)  # sorted, one entry per key
        self.keys = keys
        self.values = {name: column[first] for name, column in merged.items()}

    def find(self, keys: np.ndarray) -> np.ndarray:
        """Row of each key in the index, -1 where it is not stored."""
        if not self.keys.size or not keys.size:
            return np.full(keys.size, -1, dtype=np.int64)
        position = np.searchsorted(self.keys, keys)
        clipped = np.minimum(position, self.keys.size - 1)
        return np.where(self.keys[clipped] == keys, clipped, -1)


class CachingRunner(RunnerBase):
    """A runner that reuses stored results and simulates only the cases it has not seen.

    Parameters
    ----------
    inner : runner
        What simulates the cases not in the cache (a runner of
        :mod:`assess.mechanics.gateway`; default
        :class:`~assess.mechanics.gateway.LocalRunner`).
    folder : path
        The cache folder (created on the first write).
    max_bytes : int
        Size of the folder beyond which the least recently used packs are deleted.
    version : str, optional
        The engine version the keys carry (default :func:`engine_version`).

    ``cases_simulated`` counts the ``peaks`` cases handed to ``inner`` (one per
    distinct key: the level's item × motion × direction runs and the stripes,
    the portfolio's account), ``cases_reused`` those answered from the cache or
    by an identical case of the same batch; the two add up to the ``peaks``
    cases asked for. ``runs_simulated`` and ``runs_reused`` count every run the
    same way, by kind (``peaks``, ``planar``, ``response``). ``write_errors``
    holds why a pack could not be stored (the run goes on without storing it).
    ``asked``, when set to a list, receives ``(kind, keys)`` of every batch
    run (the portfolio's account of a building assessed on a worker,
    :func:`assess.portfolio.spread.sequential_account`).
    """

    def __init__(self, inner=None, folder=".cache", *, max_bytes: int = DEFAULT_MAX_BYTES,
                 version: str | None = None):
        self.inner = inner if inner is not None else LocalRunner()
        self.folder = Path(folder)
        self.max_bytes = int(max_bytes)
        self.version = version if version is not None else engine_version()
        self.cases_simulated = 0
        self.cases_reused = 0
        self.runs_simulated: dict = {}
        self.runs_reused: dict = {}
        self.write_errors: list[str] = []
        self.asked: Optional[list] = None
        self._index = _Index()
        self._responses: dict = {}

    # ------------------------------------------------------------ the runner seam
    def run(self, cases: Cases, *, progress: Progress = None) -> Result:
        n = len(cases)
        keys = case_keys(cases, self.version)
        if self.asked is not None:
            self.asked.append((cases.kind, keys))
        cacheable = np.array([k is not None for k in keys], dtype=bool)
        key_array = np.array([k if k is not None else b"" for k in keys], dtype=f"S{KEY_BYTES}")
        self._load_new_packs()
        names = key_array.tolist()  # as the packs hold them (a fixed-width bytes array drops trailing zeros)
        if cases.kind == RESPONSE:
            row = np.array([0 if ok and name in self._responses else -1 for ok, name in zip(cacheable, names)],
                           dtype=np.int64)
        else:
            row = np.full(n, -1, dtype=np.int64)
            row[cacheable] = self._index.find(key_array[cacheable])
        missing = np.flatnonzero(row < 0)
        # one simulation per distinct key; uncacheable cases each run
        send, first_of = [], {}
        source = np.empty(missing.size, dtype=np.int64)  # position in `send` of each missing case
        for m, k in enumerate(missing):
            key = keys[k]
            if key is not None and key in first_of:
                source[m] = first_of[key]
                continue
            if key is not None:
                first_of[key] = len(send)
            source[m] = len(send)
            send.append(k)
        send = np.asarray(send, dtype=np.int64)
        hits = n - send.size
        fresh = None
        if send.size:
            def report(done, total):
                if progress is not None:
                    progress(hits + done, n)

            fresh = self.inner.run(cases.subset(send), progress=report)
        elif progress is not None:
            progress(n, n)
        stored = cacheable[send]
        if cases.kind == RESPONSE:
            result = [self._responses[name] if row[i] >= 0 else None for i, name in enumerate(names)]
            for m, k in enumerate(missing):
                result[k] = fresh[source[m]]
            if stored.any():
                self._store_responses(key_array[send][stored], [r for r, s in zip(fresh, stored) if s])
        else:
            result = self._peaks(n, row, missing, source, fresh)
            if stored.any():
                self._store(key_array[send][stored],
                            {name: np.asarray(getattr(fresh, name))[stored] for name in _FLOATS + _BOOLS}
                            | {name: np.asarray(getattr(fresh, name)).astype(str)[stored] for name in _TEXTS})
        self._count(cases, int(send.size))
        if cases.kind == PEAKS:
            self.cases_reused += int(hits)
        self.runs_reused[cases.kind] = self.runs_reused.get(cases.kind, 0) + int(hits)
        return result

    def _peaks(self, n, row, missing, source, fresh) -> CasePeaks:
        """Peaks of every case: stored ones from the index, the others from ``fresh`` (of the sent cases)."""
        values = {name: np.zeros(n, dtype=float) for name in _FLOATS}
        values.update({name: np.zeros(n, dtype=bool) for name in _BOOLS})
        texts = {name: np.full(n, "", dtype=object) for name in _TEXTS}
        found = np.flatnonzero(row >= 0)
        if found.size:
            for name in _FLOATS + _BOOLS:
                values[name][found] = self._index.values[name][row[found]]
            for name in _TEXTS:
                texts[name][found] = self._index.values[name][row[found]]
        if fresh is not None:
            for name in _FLOATS + _BOOLS:
                values[name][missing] = np.asarray(getattr(fresh, name))[source]
            for name in _TEXTS:
                texts[name][missing] = np.asarray(getattr(fresh, name)).astype(str)[source]
        return CasePeaks(sliding_max_m=values["sliding_max_m"], sliding_residual_m=values["sliding_residual_m"],
                         theta_max_over_alpha=values["theta_max_over_alpha"], uplift=values["uplift"],
                         overturned=values["overturned"], mode=texts["mode"].astype(str),
                         solver=texts["solver"].astype(str))

    def known_keys(self) -> list[bytes]:
        """The keys of every stored peaks and planar case read so far, as :func:`case_keys` gives them."""
        return [key.ljust(KEY_BYTES, b"\0") for key in self._index.keys.tolist()]  # numpy drops trailing zeros

    # ------------------------------------------------------------ the folder
    def _pack_paths(self) -> list[Path]:
        try:
            return sorted(p for p in self.folder.glob("*.npz") if not p.name.startswith("."))
        except OSError:
            return []

    def _load_new_packs(self) -> None:
        """Add to the index every pack of the folder not read yet (another process may have written some)."""
        for path in self._pack_paths():
            if path.name in self._index.packs:
                continue
            pack = _read_pack(path)
            if pack is None:
                with contextlib.suppress(OSError):
                    path.unlink()  # damaged: its cases are simulated again
                continue
            if isinstance(pack, dict):
                self._responses.update(pack)
            else:
                self._index.add(*pack)
            self._index.packs.add(path.name)
            with contextlib.suppress(OSError):
                os.utime(path)  # recently used: deleted last when the folder is trimmed

    def _store(self, keys: np.ndarray, values: dict) -> None:
        self._index.add(keys, values)
        self._write(lambda: _write_pack(self.folder, keys, values))

    def _store_responses(self, keys: np.ndarray, responses: list) -> None:
        self._responses.update(zip(keys.tolist(), responses))
        self._write(lambda: _write_response_pack(self.folder, keys, responses))

    def _write(self, write) -> None:
        try:
            self.folder.mkdir(parents=True, exist_ok=True)
            self._index.packs.add(write())
            self._tidy()
        except OSError as error:
            self.write_errors.append(f"{self.folder}: {error.strerror or type(error).__name__}")

    def _tidy(self) -> None:
        """Remove stale temporaries, merge packs past :data:`MAX_PACKS`, trim to ``max_bytes``."""
        now = time.time()
        for leftover in self.folder.glob(".tmp-*"):
            with contextlib.suppress(OSError):
                if now - leftover.stat().st_mtime > STALE_TEMPORARY_S:
                    leftover.unlink()
        packs = self._pack_paths()
        if len(packs) > MAX_PACKS:
            merged = [p for p in packs if p.name in self._index.packs]
            names = set()  # everything this process knows, in one pack of each layout
            if self._index.keys.size:
                names.add(_write_pack(self.folder, self._index.keys, self._index.values))
            if self._responses:
                keys = np.array(list(self._responses), dtype=f"S{KEY_BYTES}")
                names.add(_write_response_pack(self.folder, keys, list(self._responses.values())))
            for path in merged:
                if path.name not in names:
                    with contextlib.suppress(OSError):
                        path.unlink()
            self._index.packs = names | (self._index.packs - {p.name for p in merged})
            packs = self._pack_paths()
        sizes = []
        for path in packs:
            with contextlib.suppress(OSError):
                stat = path.stat()
                sizes.append((stat.st_mtime, stat.st_size, path))
        total = sum(size for _, size, _ in sizes)
        for _, size, path in sorted(sizes, key=lambda s: s[0]):
            if total <= self.max_bytes:
                break
            with contextlib.suppress(OSError):
                path.unlink()
                total -= size


def _write_pack(folder: Path, keys: np.ndarray, values: dict) -> str:
    """Write one pack of peaks atomically (temporary file, then rename); returns its file name."""
    return _write_arrays(folder, format=np.array(PACK_FORMAT), keys=keys,
                         **{f: np.asarray(values[f], dtype=float) for f in _FLOATS},
                         **{f: np.asarray(values[f], dtype=bool) for f in _BOOLS},
                         **{f: np.asarray(values[f], dtype=str) for f in _TEXTS})


def _write_response_pack(folder: Path, keys: np.ndarray, responses: list) -> str:
    """Write one pack of full responses: their fields per row, mode sequences and histories as flat arrays."""
    histories = [r.time_s is not None for r in responses]
    flat = {name: [np.asarray(getattr(r, name), dtype=float) for r, kept in zip(responses, histories) if kept]
            for name in _HISTORIES}
    return _write_arrays(
        folder, format=np.array(RESPONSE_PACK_FORMAT), keys=keys,
        **{f: np.array([float(getattr(r, f)) for r in responses], dtype=float) for f in _RESPONSE_FLOATS},
        **{f: np.array([bool(getattr(r, f)) for r in responses], dtype=bool) for f in _BOOLS},
        solver=np.array([str(r.solver) for r in responses], dtype=str),
        mode_count=np.array([len(r.mode_sequence) for r in responses], dtype=np.int64),
        mode_time=np.array([float(t) for r in responses for t, _ in r.mode_sequence], dtype=float),
        mode_name=np.array([str(m) for r in responses for _, m in r.mode_sequence], dtype=str),
        history_length=np.array([r.time_s.size if kept else -1 for r, kept in zip(responses, histories)],
                                dtype=np.int64),
        **{name: np.concatenate(arrays) if arrays else np.zeros(0) for name, arrays in flat.items()})


def _write_arrays(folder: Path, **arrays) -> str:
    """Write ``arrays`` as one pack atomically (temporary file, then rename); returns its file name (a hash
    of its ``keys``)."""
    name = hashlib.blake2b(np.ascontiguousarray(arrays["keys"]).tobytes(), digest_size=KEY_BYTES).hexdigest() + ".npz"
    handle, temporary = tempfile.mkstemp(prefix=".tmp-", suffix=".npz", dir=folder)
    try:
        with os.fdopen(handle, "wb") as stream:
            np.savez_compressed(stream, **arrays)
            stream.flush()
            os.fsync(stream.fileno())
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(temporary, 0o666 & ~umask)  # as any file this user writes, not mkstemp's 0600
        os.replace(temporary, folder / name)
        temporary = None
    finally:
        if temporary is not None:
            with contextlib.suppress(OSError):
                os.unlink(temporary)
    return name


def _read_pack(path: Path):
    """``(keys, values)`` of a pack of peaks, ``{key: BlockResponse}`` of a pack of responses, or None when
    it cannot be read or is of neither format.

    Nothing in a pack is trusted (a copied output folder brings its ``.cache``
    along): only a regular file of at most :data:`MAX_PACK_BYTES` is opened
    (:func:`_open_regular`), its arrays are checked against their declared
    sizes before any is inflated (:func:`_pack_arrays`), and every row is
    checked (:func:`_plausible_rows`); a row that fails is left out, a miss.
    """
    stream = _open_regular(path)
    if stream is None:
        return None
    try:
        with stream, zipfile.ZipFile(stream) as archive:
            head = _pack_arrays(archive, ("format",))
            if head is None or head["format"].shape != () or head["format"].dtype.kind not in "iu" \
                    or int(head["format"]) not in _PACK_ARRAYS:
                return None
            form = int(head["format"])
            arrays = _pack_arrays(archive, _PACK_ARRAYS[form])
    except Exception:  # noqa: BLE001 - a damaged file raises many kinds (zip, zlib, value, key errors)
        return None
    if arrays is None:
        return None
    if form == RESPONSE_PACK_FORMAT:
        try:
            return _responses_of(arrays)
        except (ValueError, TypeError, IndexError):  # inconsistent columns: not a pack this code wrote
            return None
    keys = arrays["keys"]
    values = {name: arrays[name] for name in _FLOATS + _BOOLS + _TEXTS}
    n = keys.shape
    if keys.dtype != np.dtype(f"S{KEY_BYTES}") or keys.ndim != 1 or any(v.shape != n for v in values.values()):
        return None
    if any(values[f].dtype.kind != "f" for f in _FLOATS) or any(values[f].dtype.kind != "b" for f in _BOOLS) \
            or any(values[f].dtype.kind != "U" for f in _TEXTS):
        return None
    kept = _plausible_rows(values)
    return keys[kept], {name: column[kept] for name, column in values.items()}


def _open_regular(path):
    """``path`` opened for reading if it is a regular file of at most :data:`MAX_PACK_BYTES`; else None.

    Opened without following a final link and without blocking (a FIFO named
    ``*.npz`` would wait for a writer forever), then checked with ``fstat``,
    so what is read is what was checked.
    """
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_BINARY", 0)
    try:
        handle = os.open(path, flags)
    except OSError:
        return None
    try:
        status = os.fstat(handle)
        if stat.S_ISREG(status.st_mode) and status.st_size <= MAX_PACK_BYTES:
            return os.fdopen(handle, "rb")
    except OSError:
        pass
    os.close(handle)
    return None


def _pack_arrays(archive: zipfile.ZipFile, names) -> dict | None:
    """The pack's arrays ``names``, or None if one is missing, not a plain array, or too large.

    The members' inflated sizes (from the zip directory) must add up to at
    most :data:`MAX_PACK_BYTES`, and each array's shape and type (from its
    ``.npy`` header) must fit its member's size, before a byte is inflated;
    the zip reader stops a member at its declared size.
    """
    members = archive.infolist()
    if len(members) > 64 or sum(m.file_size for m in members) > MAX_PACK_BYTES:
        return None
    by_name = {m.filename: m for m in members}
    arrays = {}
    for name in names:
        member = by_name.get(name + ".npy")
        if member is None:
            return None
        with archive.open(member) as stream:
            version = np.lib.format.read_magic(stream)
            if version == (1, 0):
                shape, _, dtype = np.lib.format.read_array_header_1_0(stream)
            elif version == (2, 0):
                shape, _, dtype = np.lib.format.read_array_header_2_0(stream)
            else:
                return None
        if dtype.hasobject or math.prod(shape) * dtype.itemsize > member.file_size:
            return None
        with archive.open(member) as stream:
            arrays[name] = np.lib.format.read_array(stream, allow_pickle=False)
    return arrays


def _plausible_rows(values: dict) -> np.ndarray:
    """Which stored rows could be the engine's: finite peaks in their ranges, known modes and solvers.

    ``sliding_max_m`` and ``theta_max_over_alpha`` are finite and not
    negative; the residual sliding is finite and no larger than the peak; the
    mode (where stored) is one of :data:`assess.mechanics.block.MODES` and the
    solver one of the engine's. A row that fails is not used (its case is simulated again).
    """
    sliding = values["sliding_max_m"]
    residual = values["sliding_residual_m"]
    theta = values["theta_max_over_alpha"]
    with np.errstate(invalid="ignore"):
        kept = (np.isfinite(sliding) & (sliding >= 0.0) & np.isfinite(theta) & (theta >= 0.0)
                & np.isfinite(residual) & (np.abs(residual) <= sliding * (1.0 + 1e-9) + 1e-12))
    if "mode" in values:
        kept &= np.isin(values["mode"], np.array(MODES, dtype=str))
    kept &= np.isin(values["solver"], np.array(ENGINE_SOLVERS, dtype=str))
    return kept


def _responses_of(pack) -> dict | None:
    """The responses of an open pack of :data:`RESPONSE_PACK_FORMAT`, by key; None if inconsistent."""
    keys = pack["keys"]
    n = keys.shape
    columns = {name: pack[name] for name in _RESPONSE_FLOATS + _BOOLS + ("solver", "mode_count", "history_length")}
    mode_time, mode_name = pack["mode_time"], pack["mode_name"]
    flat = {name: pack[name] for name in _HISTORIES}
    if keys.dtype != np.dtype(f"S{KEY_BYTES}") or keys.ndim != 1 or any(v.shape != n for v in columns.values()):
        return None
    counts, lengths = columns["mode_count"], np.maximum(columns["history_length"], 0)
    if counts.sum() != mode_time.size or mode_time.size != mode_name.size or \
            any(v.size != lengths.sum() for v in flat.values()):
        return None
    mode_start = np.concatenate([[0], np.cumsum(counts)])
    history_start = np.concatenate([[0], np.cumsum(lengths)])
    kept = _plausible_rows(columns) & np.all(np.isin(mode_name, np.array(MODES, dtype=str)))
    out = {}
    for i, key in enumerate(keys.tolist()):
        if not kept[i]:
            continue  # not a response the engine gives: simulated again
        sequence = tuple((float(t), str(m)) for t, m in zip(mode_time[mode_start[i]:mode_start[i + 1]],
                                                             mode_name[mode_start[i]:mode_start[i + 1]]))
        history = {}
        if columns["history_length"][i] >= 0:
            history = {name: flat[name][history_start[i]:history_start[i + 1]].copy() for name in _HISTORIES}
        out[key] = BlockResponse(**{f: float(columns[f][i]) for f in _RESPONSE_FLOATS},
                                 **{f: bool(columns[f][i]) for f in _BOOLS}, mode_sequence=sequence,
                                 solver=str(columns["solver"][i]), **history)
    return out
